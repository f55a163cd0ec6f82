//! Load-controlled pull-off: on the edge continuation's meshes (μ > 1) or on
//! a mesh banded at the pull-off radius of a coarse curve, marched to just
//! past the force minimum, which is then refined.

use super::path::State;
use super::special::Special;
use super::{LjOptions, LjPullOff, LjSolver, LjSphere};
use crate::error::{Error, Result};

impl LjSolver {
    /// Load-controlled pull-off. For μ ≤ 1 (or a band given in `options`)
    /// on the edge-concentrated mesh: the contact radius at pull-off is
    /// located on a coarse (N = 64) curve; the mesh concentrates half the
    /// cells within `±w` of that radius (`w = clamp(2μ^{-3/2}, 0.1, 1)`,
    /// about the width of the edge zone); the pseudo-arclength continuation
    /// runs from far to just past the minimum of P̄, which is then refined
    /// as the zero of dP̄/ds (Illinois method, exact tangents). For μ > 1
    /// the edge continuation (module `edge`) on the meshes of
    /// [`LjSolver::curve`] with the same options, up to just past the
    /// minimum: the pull-off is the curve's, at a fraction of its cost.
    pub fn pull_off_with(sphere: &LjSphere, options: LjOptions) -> Result<LjPullOff> {
        let mu = sphere.mu;
        let mut o = options;
        o.max_force = 1.0;
        if mu > 1.0 && options.edge_fraction == 0.0 {
            // The edge continuation (module `edge`) follows the edge from
            // the neck to the pull-off, on the curve's meshes (sized by the
            // caller's `max_force`, not the 1 of the banded mesh below).
            let s = LjSolver::new(sphere, options)?;
            if let Some(plan) = s.band_plan() {
                return s.edge_pull_off(plan);
            }
        }
        if options.edge_fraction == 0.0 {
            // A fixed band at the pull-off radius of a coarse curve.
            let mut co = options;
            co.n_grid = 64;
            co.target_points = 60;
            co.max_force = 1.0;
            let coarse = LjSolver::new(sphere, co)?;
            o.edge_fraction = 0.5;
            o.edge_radius = coarse.curve()?.pull_off_load.contact_radius;
            o.edge_width = (2.0 * mu.powf(-1.5)).clamp(0.1, 1.0);
        }
        let s = LjSolver::new(sphere, o)?;
        let stop = |st: &[State]| {
            let n = st.len();
            if n < 4 {
                return false;
            }
            let imin = (0..n)
                .min_by(|&a, &b| st[a].pt.force.total_cmp(&st[b].pt.force))
                .unwrap();
            // Past the minimum on the contact branch: the last point in
            // contact and stable, the minimum in contact, a rise after it.
            let last = &st[n - 1];
            imin + 2 < n
                && st[imin].pt.contact_radius > 0.0
                && last.pt.contact_radius > 0.0
                && last.t[last.t.len() - 1] > 0.0
                && last.pt.force > st[imin].pt.force + 0.02
        };
        let (states, mut bw) = s.path_march(1.0, 80, &stop)?;
        let best = match Self::min_interval(&states) {
            Some(i) => s.refine_between(&states, i, &mut bw, Special::ForceMin)?,
            None => {
                return Err(Error::NotConverged {
                    what: "LJ sphere pull-off: no force minimum along the continuation",
                    iterations: bw.w.iterations.min(u32::MAX as u64) as u32,
                    residual: bw.w.max_residual,
                })
            }
        };
        let p = best.pt;
        Ok(LjPullOff {
            force: p.force,
            approach: p.approach,
            central_gap: p.central_gap,
            contact_radius: p.contact_radius,
            iterations: bw.w.iterations,
            max_residual: bw.w.max_residual,
            n_grid: s.n(),
        })
    }
}
