//! Stick-slip detection, and the static and kinetic friction of a run, from
//! a friction force history (thesis 5.3.1: the Prandtl–Tomlinson model
//! "reflects the distinction between static and kinetic friction").
//!
//! # Definition
//!
//! The history is a sequence of samples i (one per increment): the friction
//! force F_i resisting the motion (N; for a [`super::FrictionResponse`] along
//! +x, `-force[0]`) and the slip increment s_i that led to it (m). The slip
//! path is p_i = Σ_{j≤i} |s_j|.
//!
//! The force's turning points are found with a hysteresis `min_drop`: a
//! maximum is a peak once the force has fallen `min_drop` below it, a
//! minimum is a trough once the force has risen `min_drop` above it (so
//! ringing and noise smaller than `min_drop` are ignored). A descent from a
//! peak to the next trough is a **slip event** when it is sudden: at least
//! half of its drop happens within a slip of [`SHARPNESS`] times the path
//! of the loading before it (from the previous trough, or the start, to the
//! peak). A stick-slip drop happens within the slip of one event, far
//! shorter than the stick that loaded it (in the Prandtl–Tomlinson model
//! with η > 1 the force first falls smoothly from its peak, the lattice
//! force, and then jumps). Smooth sliding in a periodic potential
//! (Prandtl–Tomlinson with η < 1) falls over a(½ − η/π) of the period a in
//! the quasi-static limit and rises over the rest; at η = 0.5 a tenth of
//! the rise holds about 40 % of the fall, and only close to η = 1, where
//! the transition is continuous, does smooth sliding count as stick-slip. A
//! descent still open at the end of the record is not counted.
//!
//! The **static friction force** is the mean of the events' peak forces
//! (the break-away forces), or the largest force of the run when there is
//! no event; the **kinetic friction force** is the mean force over the
//! slip, Σ F_i |s_i| / Σ |s_i| (the work per unit slip; the plain mean when
//! nothing slipped).

use crate::error::{check, Error, Result};

/// A descent is a slip event when half its drop happens within this
/// fraction of its loading path (module docs).
pub const SHARPNESS: f64 = 0.1;

/// One slip event of a force history.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlipEvent {
    /// The sample of the peak (the last before the drop).
    pub peak_index: usize,
    /// The sample of the trough (the end of the drop).
    pub trough_index: usize,
    /// The force at the peak (N): the break-away force of the event.
    pub peak_force: f64,
    /// The force drop, peak less trough (N), ≥ `min_drop`.
    pub drop: f64,
    /// The largest part of the drop within a slip of [`SHARPNESS`] times
    /// the loading path (N), ≥ half the drop.
    pub jump: f64,
    /// The slip path of the drop (m).
    pub slip: f64,
    /// The slip path of the loading before it (m), from the previous trough
    /// or the start of the run.
    pub loading: f64,
    /// The slip path at the peak (m), from the start of the run.
    pub position: f64,
}

/// Stick-slip in a force history ([`stick_slip()`]).
#[derive(Debug, Clone, PartialEq)]
pub struct StickSlip {
    /// The slip events, in order.
    pub events: Vec<SlipEvent>,
    /// Mean peak force of the events (N); the largest force when there is
    /// none.
    pub static_force: f64,
    /// Mean force over the slip, Σ F_i |s_i| / Σ |s_i| (N).
    pub kinetic_force: f64,
    /// The largest force of the run (N).
    pub max_force: f64,
}

impl StickSlip {
    /// Whether the run stuck and slipped (at least one event).
    pub fn is_stick_slip(&self) -> bool {
        !self.events.is_empty()
    }

    /// The mean slip path from one event to the next (m); `None` with fewer
    /// than two events.
    pub fn mean_spacing(&self) -> Option<f64> {
        let (first, last) = (self.events.first()?, self.events.last()?);
        let n = self.events.len();
        (n >= 2).then(|| (last.position - first.position) / (n - 1) as f64)
    }
}

/// The slip events and the static and kinetic friction of the force
/// history `forces` (N, the force resisting the motion, one per sample)
/// with the slip increments `slips` leading to each sample (m), counting
/// drops of at least `min_drop` (N, finite, > 0) (module docs). Errors
/// name `forces.len()` (≥ 1), `slips.len()` (equal to it), `forces` and
/// `slips` (finite values), `min_drop`.
pub fn stick_slip(forces: &[f64], slips: &[f64], min_drop: f64) -> Result<StickSlip> {
    if forces.is_empty() {
        return Err(Error::InvalidArgument {
            name: "forces.len()",
            value: 0.0,
            bound: ">= 1",
        });
    }
    if slips.len() != forces.len() {
        return Err(Error::InvalidArgument {
            name: "slips.len()",
            value: slips.len() as f64,
            bound: "equal to forces.len()",
        });
    }
    for (&f, &s) in forces.iter().zip(slips) {
        check::finite("forces", f)?;
        check::finite("slips", s)?;
    }
    check::positive("min_drop", min_drop)?;

    let mut path = 0.0;
    let paths: Vec<f64> = slips
        .iter()
        .map(|s| {
            path += s.abs();
            path
        })
        .collect();
    let mut events = vec![];
    // Rising: `hi` is the largest force since the last trough `trough`;
    // falling: `lo` is the smallest since the peak `hi`.
    let (mut trough, mut hi, mut lo) = (0usize, 0usize, 0usize);
    let mut rising = true;
    for (i, &f) in forces.iter().enumerate() {
        if rising {
            if f >= forces[hi] {
                hi = i;
            } else if f < forces[hi] - min_drop {
                rising = false;
                lo = i;
            }
        } else if f < forces[lo] {
            lo = i;
        } else if f > forces[lo] + min_drop {
            // A confirmed descent hi → lo.
            let loading = paths[hi] - paths[trough];
            let jump = steepest(&forces[hi..=lo], &paths[hi..=lo], SHARPNESS * loading);
            let drop = forces[hi] - forces[lo];
            if jump >= 0.5 * drop {
                events.push(SlipEvent {
                    peak_index: hi,
                    trough_index: lo,
                    peak_force: forces[hi],
                    drop,
                    jump,
                    slip: paths[lo] - paths[hi],
                    loading,
                    position: paths[hi],
                });
            }
            trough = lo;
            hi = i;
            rising = true;
        }
    }
    let max_force = forces.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let static_force = if events.is_empty() {
        max_force
    } else {
        events.iter().map(|e| e.peak_force).sum::<f64>() / events.len() as f64
    };
    let total: f64 = slips.iter().map(|s| s.abs()).sum();
    let kinetic_force = if total > 0.0 {
        forces
            .iter()
            .zip(slips)
            .map(|(f, s)| f * s.abs())
            .sum::<f64>()
            / total
    } else {
        forces.iter().sum::<f64>() / forces.len() as f64
    };
    Ok(StickSlip {
        events,
        static_force,
        kinetic_force,
        max_force,
    })
}

/// The largest fall F_i − F_j (i ≤ j) of `forces` within a path window
/// `paths[j] − paths[i] ≤ width` (a sliding-window maximum: linear time).
fn steepest(forces: &[f64], paths: &[f64], width: f64) -> f64 {
    let mut window = std::collections::VecDeque::new();
    let mut best = 0.0f64;
    for j in 0..forces.len() {
        while window
            .back()
            .is_some_and(|&i: &usize| forces[i] <= forces[j])
        {
            window.pop_back();
        }
        window.push_back(j);
        while window.front().is_some_and(|&i| paths[j] - paths[i] > width) {
            window.pop_front();
        }
        if let Some(&i) = window.front() {
            best = best.max(forces[i] - forces[j]);
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sawtooth_is_stick_slip_and_a_sine_is_not() {
        // Sawtooth: rises 1 → 2 over 100 samples, drops to 1 in one.
        let n = 1000;
        let f: Vec<f64> = (0..n).map(|i| 1.0 + (i % 101) as f64 / 100.0).collect();
        let s = vec![1e-9; n];
        let r = stick_slip(&f, &s, 0.1).unwrap();
        assert_eq!(r.events.len(), 9);
        assert!((r.static_force - 2.0).abs() < 1e-12);
        assert!((r.kinetic_force - 1.5).abs() < 0.01);
        assert!((r.events[0].drop - 1.0).abs() < 1e-12);
        assert!((r.mean_spacing().unwrap() - 101e-9).abs() < 1e-15);
        // A sine with the same range: no events, static = max.
        let g: Vec<f64> = (0..n)
            .map(|i| 1.5 + 0.5 * (i as f64 * 0.0622).sin())
            .collect();
        let r = stick_slip(&g, &s, 0.1).unwrap();
        assert!(!r.is_stick_slip(), "{:?}", r.events);
        assert_eq!(r.static_force, r.max_force);
        // Bad input names the argument.
        let name = |e: Error| match e {
            Error::InvalidArgument { name, .. } => name,
            e => panic!("{e:?}"),
        };
        assert_eq!(name(stick_slip(&[], &[], 0.1).unwrap_err()), "forces.len()");
        assert_eq!(
            name(stick_slip(&f, &s[1..], 0.1).unwrap_err()),
            "slips.len()"
        );
        assert_eq!(
            name(stick_slip(&[f64::NAN], &[0.0], 0.1).unwrap_err()),
            "forces"
        );
        assert_eq!(name(stick_slip(&f, &s, 0.0).unwrap_err()), "min_drop");
    }
}
