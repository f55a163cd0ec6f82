//! What an equilibrium is: central gap, approach, force (with the check
//! that the grid resolves the edge zone) and contact radius of a state.

use super::newton::{Mode, Work};
use super::numeric::{deriv3, dot, hermite01};
use super::{lj_pressure, LjSolver};
use crate::error::Error;

impl LjSolver {
    /// Central gap, approach, force and contact radius of the state in `w`
    /// (after a converged `residual`).
    pub(super) fn observe(&self, mode: Mode, w: &Work) -> (f64, f64, f64, f64) {
        let u0 = -self.k * (dot(&self.a0, &w.p) + self.tail0);
        let (h0, al) = match mode {
            Mode::Gap(h0) => (h0, 1.0 + u0 - h0),
            Mode::Approach(al) => (1.0 + u0 - al, al),
        };
        let (force, a) = self.force_radius(&w.h, &w.p, h0);
        (h0, al, force, a)
    }

    /// Central gap, force and contact radius at log-gaps `y` and approach
    /// `al` (not necessarily an equilibrium; for derivatives along a path).
    pub(super) fn observe_y(&self, y: &[f64], al: f64) -> (f64, f64, f64) {
        let h: Vec<f64> = y.iter().map(|v| v.exp()).collect();
        let p: Vec<f64> = h.iter().map(|&v| lj_pressure(v).0).collect();
        let h0 = 1.0 - self.k * (dot(&self.a0, &p) + self.tail0) - al;
        let (f, a) = self.force_radius(&h, &p, h0);
        (h0, f, a)
    }

    /// Force (NaN where the grid does not resolve the edge zone) and contact
    /// radius of the gaps `h`, pressures `p` at the nodes and central gap `h0`.
    fn force_radius(&self, h: &[f64], p: &[f64], h0: f64) -> (f64, f64) {
        let n = self.n();
        // Force: Gauss on cells with quadratic w̄ = h − r²/2, plus the tail.
        let x = &self.mesh.x;
        let wb = |i: usize| h[i] - 0.5 * x[i] * x[i];
        // One partial sum per Gauss point of the cells: three independent
        // chains of additions instead of one.
        let mut acc = [0.0f64; 3];
        for cell in self.quad.chunks_exact(3) {
            let i0 = cell[0].2;
            let (w0, w1, w2) = (wb(i0), wb(i0 + 1), wb(i0 + 2));
            let (lo, hi) = (w0.min(w1).min(w2), w0.max(w1).max(w2));
            for (a, &(r2, wr, _, l)) in acc.iter_mut().zip(cell) {
                // Quadratic, limited to the range of its nodes (no
                // overshoot where an unresolved edge zone makes the
                // profile jump).
                let wv = (l[0] * w0 + l[1] * w1 + l[2] * w2).clamp(lo, hi);
                *a += lj_pressure(wv + r2).0 * wr;
            }
        }
        let s = acc[0] + acc[1] + acc[2];
        let l = self.opts.outer_radius;
        let xl = self.mesh.x[n - 1];
        let hl = 0.5 * l * l + (h[n - 1] - 0.5 * xl * xl);
        let tail = -(16.0 / 3.0) * (0.5 * hl.powi(-2) - 0.125 * hl.powi(-8));
        let mut force = -2.0 * s + tail;
        // Resolution check: the cell-sum force of the piecewise-constant
        // pressure must agree with the Gauss force (they differ by O(N⁻²) on
        // a resolved grid; by O(1) when the edge zone, of width ~μ^{-3/2},
        // falls between nodes; 10 % flags the latter).
        let cells: f64 = (0..n)
            .map(|j| p[j] * (self.mesh.c[j + 1].powi(2) - self.mesh.c[j].powi(2)))
            .sum();
        if (-cells + tail - force).abs() > 0.1 * force.abs().max(1.0) {
            force = f64::NAN;
        }
        (force, self.contact_radius_of(h, h0))
    }

    /// Contact radius: the first root of `h̄(r) = 1` from the centre, on the
    /// C¹ piecewise-cubic Hermite interpolant of `w̄ = h̄ − r²/2` through the
    /// centre (`h̄₀`, slope 0) and the nodes (slopes of the local parabolas),
    /// so that it varies continuously differentiably along the path (also
    /// when the root crosses a node); 0 when `h̄₀ ≥ 1`.
    fn contact_radius_of(&self, h: &[f64], h0: f64) -> f64 {
        if !(h0 < 1.0) {
            return 0.0;
        }
        let n = self.n();
        let x = &self.mesh.x;
        // Node k: k = 0 is the centre, k ≥ 1 is node k − 1.
        let r = |k: usize| if k == 0 { 0.0 } else { x[k - 1] };
        let wv = |k: usize| {
            if k == 0 {
                h0
            } else {
                h[k - 1] - 0.5 * x[k - 1] * x[k - 1]
            }
        };
        let slope = |k: usize| {
            if k == 0 {
                return 0.0;
            }
            let km = k - 1;
            let kp = (k + 1).min(n);
            if kp == k {
                return (wv(k) - wv(km)) / (r(k) - r(km));
            }
            deriv3([r(km), r(k), r(kp)], [wv(km), wv(k), wv(kp)], r(k))
        };
        for k in 0..n {
            let (ra, rb) = (r(k), r(k + 1));
            let (ha, hb) = (wv(k) + 0.5 * ra * ra - 1.0, wv(k + 1) + 0.5 * rb * rb - 1.0);
            if ha < 0.0 && hb >= 0.0 {
                let (ma, mb) = (slope(k), slope(k + 1));
                let (wa, wb) = (wv(k), wv(k + 1));
                let d = rb - ra;
                let f = |t: f64| {
                    let rr = ra + t * d;
                    hermite01(wa, ma * d, wb, mb * d, t) + 0.5 * rr * rr - 1.0
                };
                // Bisection to full precision (the cubic is cheap).
                let (mut lo, mut hi) = (0.0f64, 1.0f64);
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if f(mid) < 0.0 {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                // One secant polish.
                let (flo, fhi) = (f(lo), f(hi));
                let t = if fhi != flo {
                    (lo - flo * (hi - lo) / (fhi - flo)).clamp(lo, hi)
                } else {
                    0.5 * (lo + hi)
                };
                return ra + t * d;
            }
        }
        0.0
    }
}

/// Whether `e` is the error of [`unresolved`].
pub(super) fn is_unresolved(e: &Error) -> bool {
    matches!(e, Error::NotConverged { what, .. } if what.starts_with("LJ sphere: the grid"))
}

/// The error of a state whose edge zone the grid does not resolve.
#[cold]
pub(super) fn unresolved(iterations: u32, residual: f64) -> Error {
    Error::NotConverged {
        what: "LJ sphere: the grid does not resolve the edge zone (Gauss and cell-sum forces differ by > 10 %; raise n_grid or concentrate the mesh)",
        iterations,
        residual,
    }
}
