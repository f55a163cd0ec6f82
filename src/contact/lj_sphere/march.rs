//! The pseudo-arclength march along the path: predictor, step control in
//! the scaled `(ᾱ, P̄, h̄₀)` plane and refreshing of the factorisation.

use super::numeric::hermite01;
use super::observe::is_unresolved;
use super::path::{BWork, State};
use super::{LjPoint, LjSolver};
use crate::error::{Error, Result};
use core::f64::consts::PI;

/// GMRES iterations per Newton solve above which the continuation refactors
/// the Jacobian before the next step.
pub(super) const KRYLOV_REFRESH: usize = 3;

/// Target of the largest log-gap change per continuation step.
const DY_STEP: f64 = 0.1;

impl LjSolver {
    /// Step control of the marches: the distance between two points in the
    /// scaled `(ᾱ, P̄, h̄₀)` space and the target distance per step for about
    /// `target` points up to `P̄ = max_force`.
    pub(super) fn step_metric(&self, max_force: f64, target: usize) -> StepMetric {
        let o = &self.opts;
        let al_end = (0.75 * PI * (max_force.max(0.0) + 2.0)).powf(2.0 / 3.0) * self.mu.max(0.05);
        StepMetric {
            sa: o.start_gap + al_end,
            sp: max_force.max(0.0) + 2.5,
            target: 2.2 / target.max(10) as f64,
        }
    }

    /// Pseudo-arclength march from the start gap until `P̄ ≥ max_force` or
    /// `stop(states)`, with steps adapted to about `target` points along the
    /// scaled `(ᾱ, P̄, h̄₀)` path (inexact Newton, factorisations reused).
    pub(super) fn path_march(
        &self,
        max_force: f64,
        target: usize,
        stop: &dyn Fn(&[State]) -> bool,
    ) -> Result<(Vec<State>, BWork)> {
        let o = self.opts;
        let mut bw = BWork::new(self.n());
        let st0 = self.path_start(o.start_gap, &mut bw, false)?;
        let mut states = vec![st0];
        self.march_on(
            &mut states,
            &mut bw,
            max_force,
            target,
            0.01 * o.start_gap,
            stop,
        )?;
        Ok((states, bw))
    }

    /// The march of [`LjSolver::path_march`] continued from the last of
    /// `states`, with first step `sigma`.
    pub(super) fn march_on(
        &self,
        states: &mut Vec<State>,
        bw: &mut BWork,
        max_force: f64,
        target: usize,
        mut sigma: f64,
        stop: &dyn Fn(&[State]) -> bool,
    ) -> Result<()> {
        let metric = self.step_metric(max_force, target);
        let mut guard = 0usize;
        let mut fails = 0u32;
        loop {
            guard += 1;
            let last = states.last().unwrap();
            if last.pt.force >= max_force || stop(states) {
                break;
            }
            if guard > 50 * target.max(10) {
                return Err(Error::NotConverged {
                    what: "LJ sphere curve continuation (too many steps)",
                    iterations: bw.w.iterations.min(u32::MAX as u64) as u32,
                    residual: bw.w.max_residual,
                });
            }
            if last.h0 < 0.05 {
                return Err(Error::OutOfDomain {
                    name: "max_force",
                    value: max_force,
                    reason: "not reached before the central gap fell below 0.05 z0",
                });
            }
            let k = states.len();
            // Cubic Hermite extrapolation through the last two states with
            // their tangents (refined to the true Jacobian, see
            // `LjSolver::tangent`) as the predictor; the tangent alone at
            // first and after a failure.
            let guess = if k >= 2 && fails == 0 {
                let (b, c) = (&states[k - 2], &states[k - 1]);
                let d = c.s - b.s;
                let th = 1.0 + sigma / d;
                if th.is_finite() && d > 0.0 {
                    let n = self.n();
                    let y = (0..n)
                        .map(|i| hermite01(b.y[i], d * b.t[i], c.y[i], d * c.t[i], th))
                        .collect();
                    Some((y, hermite01(b.al, d * b.t[n], c.al, d * c.t[n], th)))
                } else {
                    None
                }
            } else {
                None
            };
            // Refresh the factorisation when it has become a poor
            // preconditioner (cheaper than the extra GMRES iterations).
            if bw.krylov > KRYLOV_REFRESH {
                bw.invalidate();
            }
            match self.path_step(last, sigma, guess, bw, false) {
                Err(e) => {
                    if is_unresolved(&e) {
                        // Smaller steps cannot help an under-resolved grid.
                        return Err(e);
                    }
                    bw.invalidate();
                    sigma *= 0.5;
                    fails += 1;
                    if fails > 40 || sigma < 1e-12 {
                        return Err(e);
                    }
                }
                Ok(st) => {
                    // Distance in the scaled (ᾱ, P̄, h̄₀) plane, and the
                    // largest change of a log-gap (the profile must not
                    // move by more than ~DY_STEP per step, or Newton leaves
                    // its basin where the contact forms).
                    let ds = metric.dist(&last.pt, &st.pt);
                    let dy =
                        st.y.iter()
                            .zip(&last.y)
                            .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
                    let ratio = (ds / metric.target).max(dy / DY_STEP);
                    if ratio > 3.0 {
                        sigma *= (0.8 / ratio).max(0.05);
                        continue;
                    }
                    fails = 0;
                    let f = if ratio > 0.0 { 1.0 / ratio } else { 2.0 };
                    sigma *= f.clamp(0.5, 2.0);
                    states.push(st);
                }
            }
        }
        Ok(())
    }
}

/// Scaled distance between path points, and the target per step.
pub(super) struct StepMetric {
    pub(super) sa: f64,
    pub(super) sp: f64,
    pub(super) target: f64,
}

impl StepMetric {
    pub(super) fn dist(&self, a: &LjPoint, b: &LjPoint) -> f64 {
        (((a.approach - b.approach) / self.sa).powi(2)
            + ((a.force - b.force) / self.sp).powi(2)
            + ((a.central_gap - b.central_gap) / self.sa).powi(2))
        .sqrt()
    }
}
