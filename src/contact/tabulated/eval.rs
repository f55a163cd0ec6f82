//! Evaluation: the branch rules of the module documentation's hysteresis,
//! the segments and tails of a branch, and the [`NormalContact`]
//! implementation (displacement and load control, pull-off, reach).

use super::data::FarData;
use super::segment::Segment;
use super::TabulatedLaw;
use crate::contact::{
    below_pull_off, check_delta, check_force, finite_response, overflow, BatchError, ContactState,
    Control, NormalContact, NormalResponse, RawBatch,
};
use crate::error::{Error, Result};

impl TabulatedLaw {
    /// Whether overlap δ (m) lies on branch j.
    #[inline]
    pub(super) fn contains(&self, j: usize, delta: f64) -> bool {
        let b = &self.branches[j];
        delta >= b.lo_delta && delta <= b.hi_delta
    }

    /// The first branch after k that contains δ (m), else the last: the
    /// last needs no test, so a two-branch table jumps without one.
    #[inline]
    fn jump_forward(&self, k: usize, delta: f64) -> usize {
        let n = self.branches.len();
        (k + 1..n - 1)
            .find(|&j| self.contains(j, delta))
            .unwrap_or(n - 1)
    }

    /// The last branch before k that contains δ (m), else branch 0.
    #[inline]
    fn jump_back(&self, k: usize, delta: f64) -> usize {
        (1..k).rev().find(|&j| self.contains(j, delta)).unwrap_or(0)
    }

    /// Overlap δ (m) at reduced approach Δ.
    pub(super) fn overlap(&self, x: f64) -> f64 {
        self.data.approach_origin + x * self.data.approach_scale
    }

    /// Reduced approach Δ at overlap δ (m).
    #[inline]
    fn reduced(&self, delta: f64) -> f64 {
        (delta - self.data.approach_origin) / self.data.approach_scale
    }

    /// Reduced (F, radius, dF/dΔ) on branch k at overlap δ (m).
    ///
    /// The segments are scanned from the last, where most of a branch's
    /// range lies: the first segment that starts at or below δ (the
    /// `start_delta` are increasing, so this is the first whose range ends
    /// at or above δ).
    #[inline(always)]
    pub(super) fn on_branch(&self, k: usize, delta: f64) -> (f64, f64, f64) {
        let segs = &self.branches[k].segments;
        if let Some(last) = segs.last() {
            if delta > last.hi_delta {
                return self.beyond(k, delta);
            }
            for s in segs.iter().rev() {
                if delta >= s.start_delta {
                    return s.eval(delta);
                }
            }
        }
        self.far(self.reduced(delta))
    }

    #[cold]
    fn beyond(&self, k: usize, delta: f64) -> (f64, f64, f64) {
        match self.branches[k].segments.last() {
            Some(s) if k + 1 < self.branches.len() => s.eval(delta),
            _ => self.deep(self.reduced(delta)),
        }
    }

    fn far(&self, x: f64) -> (f64, f64, f64) {
        match self.data.far {
            FarData::Zero => (0.0, 0.0, 0.0),
            FarData::RigidLennardJones { k } => {
                let (g, dg) = rigid_lj(x);
                (k * g, 0.0, k * dg)
            }
        }
    }

    fn deep(&self, x: f64) -> (f64, f64, f64) {
        let d = &self.data.deep;
        let z = x - d.delta_zero;
        // One logarithm and two exponentials instead of three `powf`: the
        // tail is where deep-contact calls land, and `powf` cost 3× the
        // whole table lookup there.
        let (sz, lz) = (z.sqrt(), z.ln());
        let (zf1, za) = (((d.qf - 1.0) * lz).exp(), (d.qa * lz).exp());
        let f = d.h * z * sz + d.bf * z * zf1;
        let a = d.g * sz + d.ba * za;
        let k = 1.5 * d.h * sz + d.qf * d.bf * zf1;
        (f, a.max(0.0), k)
    }

    /// The last segment of the last branch (validated to exist).
    fn last_segment(&self) -> &Segment {
        let segs = &self.branches[self.branches.len() - 1].segments;
        &segs[segs.len() - 1]
    }

    /// Reduced approach on the load-controlled stable branch at reduced
    /// force `target` (≥ the load pull-off).
    fn x_at_load(&self, target: f64) -> f64 {
        let s = self.last_segment();
        let ivs = &s.intervals[self.load_interval..];
        let end = ivs[ivs.len() - 1].force_at(1.0).0;
        if target > end {
            // Deep tail: Newton on z, F increasing and convex.
            let d = &self.data.deep;
            let x_last = s.x_of(ivs[ivs.len() - 1].hi);
            let mut z = (x_last - d.delta_zero).max((target / d.h).powf(2.0 / 3.0));
            for _ in 0..100 {
                let f = d.h * z * z.sqrt() + d.bf * z.powf(d.qf) - target;
                let k = 1.5 * d.h * z.sqrt() + d.qf * d.bf * z.powf(d.qf - 1.0);
                let step = f / k;
                let zn = (z - step).max(0.5 * z);
                if !(zn.is_finite()) || (zn - z).abs() <= 1e-15 * z {
                    z = if zn.is_finite() { zn } else { z };
                    break;
                }
                z = zn;
            }
            return d.delta_zero + z;
        }
        // Interval whose force range contains the target.
        let i = ivs
            .partition_point(|iv| iv.force_at(1.0).0 < target)
            .min(ivs.len() - 1);
        let iv = &ivs[i];
        // Safeguarded Newton on t ∈ [0, 1] (monotone cubic).
        let (mut lo, mut hi) = (0.0f64, 1.0f64);
        let mut t = 0.5;
        for _ in 0..100 {
            let (f, df) = iv.force_at(t);
            let f = f - target;
            if f == 0.0 {
                break;
            }
            if f < 0.0 {
                lo = t;
            } else {
                hi = t;
            }
            let mut tn = t - f / df;
            if !(tn > lo && tn < hi) {
                tn = 0.5 * (lo + hi);
            }
            if (tn - t).abs() <= 1e-16 || hi - lo <= 1e-16 {
                t = tn;
                break;
            }
            t = tn;
        }
        s.x_of(iv.lo + t * (iv.hi - iv.lo))
    }
}

/// Rigid Lennard-Jones sphere (Derjaguin), reduced: `g = −(8/3)[h⁻² − h⁻⁸/4]`,
/// `h = 1 − x`, and dg/dx.
pub(super) fn rigid_lj(x: f64) -> (f64, f64) {
    let ih = 1.0 / (1.0 - x);
    let h2 = ih * ih;
    let h8 = h2 * h2 * h2 * h2;
    let g = -(8.0 / 3.0) * (h2 - 0.25 * h8);
    let dg = -(16.0 / 3.0) * (h2 - h8) * ih;
    (g, dg)
}

impl NormalContact for TabulatedLaw {
    /// Equilibrium at overlap δ (m) under displacement control, following the
    /// history in `old` (see the module documentation).
    ///
    /// Errors: [`Error::InvalidArgument`] for a non-finite δ or a branch
    /// outside `0..branch_count()`; [`Error::OutOfDomain`] when the response
    /// overflows.
    #[inline(always)]
    fn eval(&self, delta: f64, old: &ContactState) -> Result<(NormalResponse, ContactState)> {
        let br = old.branch;
        let mut k = br as u32 as usize;
        if !(delta.is_finite() && k < self.branches.len()) {
            return Err(bad_input(delta, br));
        }
        let d = &self.data;
        // Branches and segments are chosen on δ against thresholds
        // equivalent to the reduced ones, so that no division precedes the
        // choice. Most calls stay on their branch and land on its widest
        // segment: one range test; otherwise the jumps and the full choice.
        let b = &self.branches[k];
        let (f, a, kbar) = if b.stays(delta) {
            b.stay_segment().eval(delta)
        } else {
            if !(delta <= b.hi_delta) {
                k = self.jump_forward(k, delta);
            } else if delta < b.lo_delta {
                k = self.jump_back(k, delta);
            }
            self.on_branch(k, delta)
        };
        let radius = a * d.radius_scale;
        let r = NormalResponse {
            force: f * d.force_scale,
            delta,
            contact_radius: radius,
            stiffness: kbar * self.stiffness_scale,
            in_contact: (a > 0.0) as i32,
            reserved: 0,
        };
        let s = ContactState {
            contact_radius: radius,
            cohesive_radius: 0.0,
            in_contact: (k > 0 || a > 0.0) as i32,
            branch: k as i32,
        };
        // One test for the three computed values (δ is finite): x·0 is 0
        // exactly when x is finite, NaN otherwise.
        if r.force * 0.0 + radius * 0.0 + r.stiffness * 0.0 == 0.0 {
            Ok((r, s))
        } else {
            Err(overflow(delta))
        }
    }

    /// The element loop without a second finiteness test: `eval` already
    /// returns an error for a non-finite response.
    #[inline]
    unsafe fn eval_batch_raw(&self, b: &RawBatch) -> core::result::Result<(), BatchError> {
        crate::contact::batch::eval_elementwise_finite(self, b)
    }

    /// Equilibrium at force P (N) on the load-controlled stable branch (beyond
    /// the minimum of the force on the last branch), by inverting the
    /// interpolant.
    ///
    /// Errors: [`Error::OutOfDomain`] below the load-controlled pull-off.
    fn eval_at_load(&self, force: f64) -> Result<NormalResponse> {
        let force = check_force(force)?;
        let d = &self.data;
        let target = force / d.force_scale;
        if target < d.load_pull_off {
            return Err(below_pull_off(force));
        }
        let x = self.x_at_load(target);
        let k = self.branches.len() - 1;
        let delta = self.overlap(x);
        let (_, a, kbar) = self.on_branch(k, delta);
        let r = NormalResponse {
            force,
            delta,
            contact_radius: a * d.radius_scale,
            stiffness: kbar * self.stiffness_scale,
            in_contact: 1,
            reserved: 0,
        };
        finite_response((r, ContactState::default())).map(|rs| rs.0)
    }

    /// Load control: the minimum of the force on the last branch, the first
    /// met lowering the load from deep contact (the curve's point, unless
    /// the grid leaves the contact branch several minima: see
    /// [`crate::contact::lj_sphere::LjCurve::pull_off_load`]). Displacement
    /// control: the force where contact is lost
    /// on retraction, at the point where the radius reaches zero or at the
    /// jump-out turning point (exactly the curve's point).
    fn pull_off_force(&self, control: Control) -> Result<f64> {
        let bar = match control {
            Control::Load => self.data.load_pull_off,
            Control::Displacement => self.data.displacement_pull_off,
        };
        Ok(bar * self.data.force_scale)
    }

    /// The curve's approach unit (m).
    fn length_scale(&self) -> f64 {
        self.data.approach_scale
    }

    /// The reach from the table's branches and far tail (see
    /// [`NormalContact::reach`]); `rel_force` is checked always and used
    /// only with a Lennard-Jones far tail.
    ///
    /// * Approach: a fresh contact (branch 0) feels the far tail up to the
    ///   first knot of branch 0 (the first stable piece of a path that starts
    ///   stable, as the Lennard-Jones sphere's does) or, without one, up to
    ///   branch 0's upper end, where it jumps in. A Maugis–Dugdale table's
    ///   far tail is zero (up to `−h₀`). The Lennard-Jones sphere's far tail
    ///   is the rigid sphere's (Derjaguin; REFERENCE §6), in reduced units
    ///   `F = k·g(Δ)`, `g = −(8/3)[h⁻² − h⁻⁸/4]`, `h = 1 − Δ`; with
    ///   `y = h⁻² < 1`, `|F| = (8/3)|k|(y − y⁴/4)` increases with y, so
    ///   `|F| < rel_force·|P_c|` below the root of
    ///   `y − y⁴/4 = 3 rel_force |P_c|/(8|k|)` (Δ = 1 − 1/√y; the whole tail
    ///   Δ ≤ 0 when the right side is ≥ 3/4). The approach bound is the
    ///   lowest of these points: where the tail bound falls inside the
    ///   tabulated path, the path's first knot is taken instead
    ///   (conservative: the force there may already be below the bound).
    /// * Displacement control: also below the jump-out point (the lower end)
    ///   of every branch after the first, so that every history jumps back
    ///   to branch 0 below δ_r.
    /// * Load control: also below the overlap of the load-controlled
    ///   pull-off knot.
    fn reach(&self, control: Control, rel_force: f64) -> Result<f64> {
        let rel = crate::contact::check_rel_force(rel_force)?;
        let d = &self.data;
        let first = &self.branches[0];
        let mut onset = f64::INFINITY;
        if self.branches.len() > 1 {
            onset = onset.min(first.hi_delta);
        }
        if let Some(s) = first.segments.first() {
            onset = onset.min(s.start_delta);
        }
        if let FarData::RigidLennardJones { k } = d.far {
            if k != 0.0 {
                let c = 3.0 * rel * d.load_pull_off.abs() / (8.0 * k.abs());
                let x = if c < 0.75 {
                    let y = crate::contact::derjaguin::lj_tail_inverse(c);
                    1.0 - 1.0 / y.sqrt()
                } else {
                    0.0
                };
                onset = onset.min(self.overlap(x));
            }
        }
        let r = match control {
            Control::Displacement => self.branches[1..]
                .iter()
                .fold(onset, |m, b| m.min(b.lo_delta)),
            Control::Load => {
                let x = self.last_segment().x_of(d.load_pull_off_u);
                onset.min(self.overlap(x))
            }
        };
        crate::error::check::finite_result(r, "table", r, "its reach is not finite")
    }
}

/// The error for a non-finite δ or a branch outside the table.
#[cold]
fn bad_input(delta: f64, b: i32) -> Error {
    match check_delta(delta) {
        Err(e) => e,
        Ok(_) => bad_branch(b),
    }
}

fn bad_branch(b: i32) -> Error {
    Error::InvalidArgument {
        name: "old.branch",
        value: b as f64,
        bound: "a branch of the table: 0 (far) to branch_count() - 1",
    }
}
