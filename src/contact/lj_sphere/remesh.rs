//! Moving edge band for large μ: the continuation of [`LjSolver::curve`]
//! and [`LjSolver::pull_off_with`] concentrates half the cells in a band of
//! half-width `w` around the contact edge and moves the band with the edge.
//!
//! The edge (cohesive) zone has width `~μ^{-3/2}` (units of `√(Rz₀)`), while
//! the contact radius travels from 0 (neck formation) to `~μ^{1/2}` along the
//! curve: a fixed mesh that resolves the zone everywhere it goes needs
//! `O(μ²)` cells. Instead, when the edge marker (first crossing of the peak-attraction gap
//! `h̄ = 3^{1/6}`, [`LjSolver::edge_marker`]) leaves the
//! inner half of the band, the continuation **remeshes**: a new band centred
//! ahead of the edge (in the direction it moves), the influence matrix
//! rebuilt (`O(N²)` closed-form elliptic integrals), the last state
//! transferred (linear interpolation of `w̄ = h̄ − r̄²/2` and of its path
//! derivative `dw̄/ds = h̄ dy/ds` to the new nodes), re-converged on the
//! hyperplane through the transferred point normal to the transferred
//! tangent, and the factorisation renewed. The path parameter continues.
//! The band half-width is `w = clamp(N μ^{-3/2}/16, 0.05, 2)`: about 20
//! cells per edge-zone width in the band core; the number of remeshes along
//! a curve is about `a_max/(0.5 w)` (μ = 10, N = 512: ≈ 25).
//!
//! The resolution guard (cell-sum vs Gauss force) stays on; in the moving
//! band a guard failure makes the step shorter instead of ending the curve.

use super::path::{BWork, Con, State};
use super::*;

/// The moving band of one continuation: its plan and, for every state, the
/// band centre (segment) of the mesh it lives on.
pub(super) struct Track {
    /// `(w, fraction)` of the band; `None` = the solver's own fixed mesh.
    pub(super) plan: Option<(f64, f64)>,
    /// Band centre of each segment.
    pub(super) bands: Vec<f64>,
    /// Segment of each state.
    pub(super) seg: Vec<usize>,
    /// Remeshes performed.
    pub(super) remeshes: usize,
}

impl Track {
    /// Whether states `i` and `i + 1` live on the same mesh.
    pub(super) fn same(&self, i: usize) -> bool {
        self.seg[i] == self.seg[i + 1]
    }
}

/// Cache of the solver of one segment (rebuilt on demand).
pub(super) type SegCache = Option<(usize, LjSolver)>;

impl LjSolver {
    /// The moving-band plan `(w, fraction)` for this solver: `None` for
    /// μ ≤ 1 (the fixed mesh resolves the edge zone at N ≥ 64) or when the
    /// options fix a band.
    pub(super) fn band_plan(&self) -> Option<(f64, f64)> {
        if self.mu <= 1.0 || self.opts.edge_fraction > 0.0 {
            return None;
        }
        let e = self.mu.powf(-1.5);
        let w = (self.n() as f64 * e / 16.0).clamp(0.05, 2.0);
        Some((w, 0.5))
    }

    /// The radius the band follows: the first crossing of `h̄ = 3^{1/6}`
    /// (the peak of the attraction, inside the edge zone) from the centre,
    /// by linear interpolation between nodes; 0 when `h̄₀` is above it. It
    /// also follows the edge of the flat neck that forms at `h̄ ≈ 1.01`
    /// before contact at large μ, where the contact radius is still 0.
    pub(super) fn edge_marker(&self, y: &[f64]) -> f64 {
        let th = 3f64.ln() / 6.0;
        let x = &self.mesh.x;
        if y[0] >= th {
            return 0.0;
        }
        for i in 1..y.len() {
            if y[i] >= th {
                let t = (th - y[i - 1]) / (y[i] - y[i - 1]);
                return x[i - 1] + t * (x[i] - x[i - 1]);
            }
        }
        x[x.len() - 1]
    }

    /// This solver with its band moved to `a_e` (same N, L, r_f).
    pub(super) fn rebanded(&self, a_e: f64, plan: (f64, f64)) -> Result<LjSolver> {
        let mut o = self.opts;
        o.edge_radius = a_e.max(0.0);
        o.edge_width = plan.0;
        o.edge_fraction = plan.1;
        LjSolver::new(&LjSphere::from_tabor(self.mu)?, o)
    }

    /// The solver of segment `k` of `track` (`self` without a plan), cached.
    pub(super) fn seg_solver<'a>(
        &'a self,
        track: &Track,
        k: usize,
        cache: &'a mut SegCache,
    ) -> Result<&'a LjSolver> {
        let Some(plan) = track.plan else {
            return Ok(self);
        };
        if !matches!(cache, Some((kk, _)) if *kk == k) {
            *cache = Some((k, self.rebanded(track.bands[k], plan)?));
        }
        Ok(&cache.as_ref().unwrap().1)
    }

    /// Linear interpolation of node values `v` of this mesh at the nodes of
    /// `to` (constant beyond the end nodes).
    fn interp_nodes(&self, v: &[f64], to: &LjSolver) -> Vec<f64> {
        let x = &self.mesh.x;
        let n = x.len();
        let mut j = 0usize;
        to.mesh
            .x
            .iter()
            .map(|&r| {
                if r <= x[0] {
                    return v[0];
                }
                if r >= x[n - 1] {
                    return v[n - 1];
                }
                while j + 1 < n - 1 && x[j + 1] < r {
                    j += 1;
                }
                while j > 0 && x[j] > r {
                    j -= 1;
                }
                let t = (r - x[j]) / (x[j + 1] - x[j]);
                v[j] + t * (v[j + 1] - v[j])
            })
            .collect()
    }

    /// The state `st` of this mesh transferred to the mesh of `to` and
    /// re-converged there (see the module documentation); `bw` is reset.
    pub(super) fn transfer(&self, st: &State, to: &LjSolver, bw: &mut BWork) -> Result<State> {
        let n = self.n();
        let x = &self.mesh.x;
        let wb: Vec<f64> = (0..n).map(|i| st.y[i].exp() - 0.5 * x[i] * x[i]).collect();
        let dw: Vec<f64> = (0..n).map(|i| st.y[i].exp() * st.t[i]).collect();
        let wb2 = self.interp_nodes(&wb, to);
        let dw2 = self.interp_nodes(&dw, to);
        let x2 = &to.mesh.x;
        let mut y = vec![0.0; n];
        let mut t = vec![0.0; n + 1];
        for i in 0..n {
            let h = (wb2[i] + 0.5 * x2[i] * x2[i]).max(1e-3);
            y[i] = h.ln();
            t[i] = dw2[i] / h;
        }
        t[n] = st.t[n];
        let my = to.metric_y();
        let nn = (my * t[..n].iter().map(|v| v * v).sum::<f64>() + t[n] * t[n]).sqrt();
        t.iter_mut().for_each(|v| *v /= nn);
        let mut row = vec![0.0; n + 1];
        for i in 0..n {
            row[i] = my * t[i];
        }
        row[n] = t[n];
        let mut al = st.al;
        let c = dot(&row[..n], &y) + row[n] * al;
        bw.invalidate();
        to.bnewton(&Con::Plane { row, c }, &mut y, &mut al, bw, false)?;
        let tt = to.tangent(bw, &t, true)?;
        to.make_state(&y, al, tt, st.s, bw, false)
    }
}
