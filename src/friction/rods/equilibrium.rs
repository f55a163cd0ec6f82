//! The position of a bed of independent rods (module docs: *Fixed gap*,
//! *Fixed load*): the scalar equilibrium R(b) = F(b) − P − c·(b − b₀) = 0
//! with F the piecewise-linear total rod force. Three ways to the root, all
//! finished by the same exact evaluation on the identified linear piece, so
//! they agree to rounding: the cold breakpoint sweep (O(n log n)), the warm
//! walk from the previous position (O(n) per breakpoint crossed) and the
//! thesis's dense system (6-12)/(6-16) iterated over active sets (the
//! reference).

// Rod arrays (onsets, yields, stiffnesses, forces) are indexed in lockstep.
#![allow(clippy::needless_range_loop)]

use super::{Loading, ACTIVE_SET_MAX_ITERATIONS};
use crate::error::{Error, Result};
use faer::linalg::solvers::{PartialPivLu, Solve};
use faer::{MatMut, MatRef};

/// Force of one rod at position `b` (m), with contact onset `a` and yield
/// onset `y` (m, y = a − F_y/k): F_y for b ≤ y, k·(a − b) between, 0 for
/// b ≥ a (N). The regime is decided on the breakpoints, not on the computed
/// force: at b = y the overlap a − y misses F_y/k by the rounding of the
/// subtraction, and such a rod has yielded (at the capacity load, b = min y,
/// every rod has).
#[inline]
pub(super) fn rod_force(b: f64, a: f64, y: f64, k: f64, fy: f64) -> f64 {
    if b <= y {
        fy
    } else if b < a {
        (k * (a - b)).min(fy)
    } else {
        0.0
    }
}

/// The scalar equilibrium a [`Loading`] asks of a rod bed:
/// R(b) = F(b) − P − c·(b − b₀) = 0, F(b) the total rod force at position b.
/// Fixed load (6-13): P the load, c = 0. Fixed gap (6-9), (6-10): P = 0,
/// c = k_B (the bulk in series, δ_B = b − b₀), b₀ the prescribed position;
/// c = +∞ (rigid bulk) means b = b₀.
#[derive(Debug, Clone, Copy)]
pub(super) struct Balance {
    pub(super) p: f64,
    pub(super) c: f64,
    pub(super) b0: f64,
}

impl Balance {
    /// The equilibrium of `loading` for a bulk of stiffness `bulk_stiffness`
    /// k_B (N/m; +∞ rigid).
    pub(super) fn new(loading: Loading, bulk_stiffness: f64) -> Self {
        match loading {
            Loading::FixedGap { position } => Self {
                p: 0.0,
                c: bulk_stiffness,
                b0: position,
            },
            Loading::FixedLoad { load } => Self {
                p: load,
                c: 0.0,
                b0: 0.0,
            },
        }
    }

    /// R(b) for total rod force `f` (N) at position `b` (m).
    pub(super) fn residual(&self, b: f64, f: f64) -> f64 {
        if self.c > 0.0 {
            f - self.p - self.c * (b - self.b0)
        } else {
            f - self.p
        }
    }
}

/// The equilibrium [`Balance`] of a bed of independent rods, whose total
/// force F is piecewise linear in b: rod i has contact onset `a[i]`, yield
/// onset `y[i]` (m) and stiffness `k[i]` (N/m), all with yield force `fy` (N).
pub(super) struct Problem<'a> {
    pub(super) a: &'a [f64],
    pub(super) y: &'a [f64],
    pub(super) k: &'a [f64],
    pub(super) fy: f64,
    pub(super) eq: Balance,
}

/// A distance well away from `b` (for a point inside an unbounded piece).
#[inline]
fn span(b: f64) -> f64 {
    b.abs().max(1.0)
}

impl Problem<'_> {
    fn n(&self) -> usize {
        self.a.len()
    }

    fn force(&self, b: f64) -> f64 {
        let mut f = 0.0;
        for i in 0..self.n() {
            f += rod_force(b, self.a[i], self.y[i], self.k[i], self.fy);
        }
        f
    }

    fn residual(&self, b: f64, f: f64) -> f64 {
        self.eq.residual(b, f)
    }

    pub(super) fn max_a(&self) -> f64 {
        self.a.iter().copied().fold(f64::NEG_INFINITY, f64::max)
    }

    fn min_y(&self) -> f64 {
        self.y.iter().copied().fold(f64::INFINITY, f64::min)
    }

    /// The cases with a closed answer: rigid bulk at fixed gap; zero load;
    /// load equal to the capacity.
    pub(super) fn special(&self) -> Option<f64> {
        if self.eq.c == f64::INFINITY {
            return Some(self.eq.b0);
        }
        if self.eq.c == 0.0 {
            if self.eq.p == 0.0 {
                return Some(self.max_a());
            }
            if self.eq.p >= self.n() as f64 * self.fy {
                return Some(self.min_y());
            }
        }
        None
    }

    /// Exact root on the linear piece containing the interior point `m`:
    /// classification at m, anchored at the piece's upper breakpoint (its
    /// lower one when unbounded above), clamped to the piece.
    pub(super) fn finish(&self, m: f64) -> f64 {
        let mut kk = 0.0;
        let mut hi = f64::INFINITY;
        let mut lo = f64::NEG_INFINITY;
        for i in 0..self.n() {
            let (a, y) = (self.a[i], self.y[i]);
            if y < m && m < a {
                kk += self.k[i];
            }
            for bp in [a, y] {
                if bp > m {
                    hi = hi.min(bp);
                } else if bp < m {
                    lo = lo.max(bp);
                }
            }
        }
        let anchor = if hi.is_finite() { hi } else { lo };
        let r = self.residual(anchor, self.force(anchor));
        let slope = kk + self.eq.c;
        let b = if slope > 0.0 {
            anchor + r / slope
        } else {
            anchor
        };
        b.max(lo).min(hi)
    }

    /// Cold O(n log n) sweep of the sorted breakpoints from the top. Returns
    /// a point inside the piece holding the root and the breakpoints crossed.
    pub(super) fn sweep(&self, events: &mut [(f64, u32)]) -> (f64, u32) {
        let n = self.n();
        for i in 0..n {
            events[2 * i] = (self.a[i], (2 * i) as u32);
            events[2 * i + 1] = (self.y[i], (2 * i + 1) as u32);
        }
        events.sort_unstable_by(|p, q| q.0.total_cmp(&p.0).then((p.1 & 1).cmp(&(q.1 & 1))));
        let top = events[0].0;
        let mut r = self.residual(top, 0.0);
        if r >= 0.0 {
            return (top + span(top), 0);
        }
        let mut kk = 0.0;
        let mut prev = top;
        for (j, &(e, code)) in events.iter().enumerate() {
            if e < prev {
                r += (kk + self.eq.c) * (prev - e);
                if r >= 0.0 {
                    return (0.5 * (prev + e), j as u32);
                }
                prev = e;
            }
            let i = (code >> 1) as usize;
            if code & 1 == 0 {
                kk += self.k[i];
            } else {
                kk = (kk - self.k[i]).max(0.0);
            }
        }
        (prev - span(prev), (2 * n) as u32)
    }

    /// Warm start: walk from `start` across at most `limit` breakpoints,
    /// O(n) per step. Returns a point inside the piece holding the root, or
    /// `None` (fall back to the sweep).
    pub(super) fn walk(&self, start: f64, limit: u32) -> Option<(f64, u32)> {
        let mut b = start;
        for step in 0..=limit {
            let mut f = 0.0;
            let mut k_below = 0.0;
            let mut k_above = 0.0;
            let mut bu = f64::INFINITY;
            let mut bl = f64::NEG_INFINITY;
            for i in 0..self.n() {
                let (a, y, k) = (self.a[i], self.y[i], self.k[i]);
                f += rod_force(b, a, y, k, self.fy);
                if y < b && b <= a {
                    k_below += k;
                }
                if y <= b && b < a {
                    k_above += k;
                }
                for bp in [a, y] {
                    if bp > b {
                        bu = bu.min(bp);
                    } else if bp < b {
                        bl = bl.max(bp);
                    }
                }
            }
            let r = self.residual(b, f);
            if r >= 0.0 {
                let slope = k_above + self.eq.c;
                if (slope > 0.0 && b + r / slope <= bu) || !bu.is_finite() {
                    let m = if bu.is_finite() {
                        0.5 * (b + bu)
                    } else {
                        b + span(b)
                    };
                    return Some((m, step));
                }
                b = bu;
            } else {
                let slope = k_below + self.eq.c;
                if slope > 0.0 && b + r / slope >= bl {
                    let m = if bl.is_finite() {
                        0.5 * (bl + b)
                    } else {
                        b - span(b)
                    };
                    return Some((m, step));
                }
                if !bl.is_finite() {
                    return None;
                }
                b = bl;
            }
        }
        None
    }

    /// The thesis's dense formulation, (6-16) at fixed load and (6-12) at
    /// fixed gap with an elastic bulk, iterated over active sets with a
    /// bracket safeguard. Writes the forces of the elastic rods (k_i δ_i from
    /// the LU solution) into `forces`. Returns b and the iterations.
    pub(super) fn dense(&self, forces: &mut [f64]) -> Result<(f64, u32)> {
        let n = self.n();
        let gap = self.eq.c > 0.0;
        let (mut lo, mut hi) = (self.min_y(), self.max_a());
        if gap {
            lo = lo.min(self.eq.b0);
            hi = hi.max(self.eq.b0);
        }
        let kmax = self.k.iter().copied().fold(0.0, f64::max);
        let mut m = 0.5 * (lo + hi);
        let mut active: Vec<usize> = Vec::with_capacity(n);
        let mut mat: Vec<f64> = Vec::new();
        let mut rhs: Vec<f64> = Vec::new();
        for it in 1..=ACTIVE_SET_MAX_ITERATIONS {
            active.clear();
            let mut n_yield = 0usize;
            for i in 0..n {
                if self.y[i] < m && m < self.a[i] {
                    active.push(i);
                } else if m <= self.y[i] {
                    n_yield += 1;
                }
            }
            let yielded_force = n_yield as f64 * self.fy;
            // The classification point itself narrows the bracket, so that
            // the midpoint fallback always makes progress.
            if self.residual(m, self.force(m)) >= 0.0 {
                lo = lo.max(m);
            } else {
                hi = hi.min(m);
            }
            let na = active.len();
            let candidate = if na == 0 && !gap {
                None
            } else {
                // Unknowns x = (δ_B or b, δ_1..δ_na); row 0 equilibrium
                // scaled by 1/k_max (row equilibration), rows 1.. compatibility.
                let dim = na + 1;
                mat.clear();
                mat.resize(dim * dim, 0.0);
                rhs.clear();
                rhs.resize(dim, 0.0);
                let at = |r: usize, c: usize| r + c * dim;
                if gap {
                    mat[at(0, 0)] = self.eq.c / kmax.max(self.eq.c);
                    rhs[0] = yielded_force / kmax.max(self.eq.c);
                } else {
                    mat[at(0, 0)] = 0.0;
                    rhs[0] = (self.eq.p - yielded_force) / kmax;
                }
                for (j, &i) in active.iter().enumerate() {
                    let scale = if gap { kmax.max(self.eq.c) } else { kmax };
                    mat[at(0, j + 1)] = if gap { -self.k[i] } else { self.k[i] } / scale;
                    mat[at(j + 1, 0)] = 1.0;
                    mat[at(j + 1, j + 1)] = 1.0;
                    rhs[j + 1] = if gap {
                        self.a[i] - self.eq.b0
                    } else {
                        self.a[i]
                    };
                }
                let lu = PartialPivLu::new(MatRef::from_column_major_slice(&mat, dim, dim));
                lu.solve_in_place(MatMut::from_column_major_slice_mut(&mut rhs, dim, 1));
                let b = if gap { self.eq.b0 + rhs[0] } else { rhs[0] };
                if b.is_finite() {
                    Some(b)
                } else {
                    None
                }
            };
            if let Some(b) = candidate {
                // Consistent with the active set (closed pieces)?
                let mut consistent = true;
                let mut q = 0;
                for i in 0..n {
                    let is_active = q < na && active[q] == i;
                    if is_active {
                        q += 1;
                        if !(self.y[i] <= b && b <= self.a[i]) {
                            consistent = false;
                        }
                    } else if m <= self.y[i] {
                        if b > self.y[i] {
                            consistent = false;
                        }
                    } else if b < self.a[i] {
                        consistent = false;
                    }
                }
                if consistent {
                    for (j, &i) in active.iter().enumerate() {
                        forces[i] = (self.k[i] * rhs[j + 1]).clamp(0.0, self.fy);
                    }
                    return Ok((b, it));
                }
                let inside = lo < b && b < hi;
                let r = self.residual(b, self.force(b));
                if r >= 0.0 {
                    lo = lo.max(b);
                } else {
                    hi = hi.min(b);
                }
                m = if inside && it % 4 != 0 {
                    b
                } else {
                    0.5 * (lo + hi)
                };
            } else {
                m = 0.5 * (lo + hi);
            }
        }
        Err(Error::NotConverged {
            what: "dense rod active set (6-12)/(6-16)",
            iterations: ACTIVE_SET_MAX_ITERATIONS,
            residual: hi - lo,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::{Balance, Problem};

    fn problem<'a>(a: &'a [f64], y: &'a [f64], k: &'a [f64], p: f64, c: f64) -> Problem<'a> {
        Problem {
            a,
            y,
            k,
            fy: 1.0,
            eq: Balance { p, c, b0: 0.0 },
        }
    }

    #[test]
    fn sweep_walk_and_bisection_agree() {
        // Three rods, F_y = 1: onsets a, yields y = a − 1/k.
        let a = [0.3, -0.2, 0.05];
        let k = [2.0, 5.0, 1.0];
        let y: Vec<f64> = a.iter().zip(&k).map(|(a, k)| a - 1.0 / k).collect();
        let mut events = vec![(0.0, 0); 6];
        for (p, c) in [(0.4, 0.0), (1.7, 0.0), (2.9, 0.0), (0.0, 3.0), (0.0, 0.5)] {
            let pr = problem(&a, &y, &k, p, c);
            let (m, _) = pr.sweep(&mut events);
            let b = pr.finish(m);
            // Bisection on the monotone residual.
            let (mut lo, mut hi) = (-10.0, 10.0);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if pr.residual(mid, pr.force(mid)) >= 0.0 {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            assert!((b - lo).abs() < 1e-14, "p {p} c {c}: {b} vs {lo}");
            for start in [-3.0, -0.5, 0.0, 0.1, 2.0] {
                if let Some((m, _)) = pr.walk(start, 8) {
                    assert!((pr.finish(m) - b).abs() < 1e-14);
                }
            }
        }
    }
}
