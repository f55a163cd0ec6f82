//! Rods on an elastic substrate, [`CoupledRodBed`] (module docs: *Rods on an
//! elastic substrate*): the rod bases sink by u = C f, C the influence
//! matrix of Love's square loads (`influence.rs`), so the rod forces solve
//! the box-constrained problem (diag(1/k) + C) f = o on the elastic rods,
//! 0 ≤ f ≤ F_y. An active-set iteration with dense LU solves it at a fixed
//! position (`Inner`); a bracketed Newton iteration on the position gives
//! the fixed load or the fixed gap with an elastic bulk.

// Rod arrays and the column-major influence matrix are indexed in lockstep.
#![allow(clippy::needless_range_loop)]

use super::bed::{check_loading, RodBed};
use super::equilibrium::{Balance, Problem};
use super::influence::influence_unchecked;
use super::{Loading, RodOptions, RodReport, RodSolution, RodState, ACTIVE_SET_MAX_ITERATIONS};
use crate::error::{check, Error, Result};
use faer::linalg::solvers::{PartialPivLu, Solve};
use faer::{MatMut, MatRef};

/// Rods standing on an elastic half-space (see the module docs): the rod bed
/// of a [`RodBed`] (its rigid-bulk stiffness k_B is kept as a series spring
/// at fixed gap) plus the dense influence matrix C (m/N) between the rod
/// sites, rods in a row along x at y = 0. Immutable.
#[derive(Debug, Clone, PartialEq)]
pub struct CoupledRodBed {
    bed: RodBed,
    contact_modulus: f64,
    influence: Vec<f64>,
}

impl CoupledRodBed {
    /// Couples the rods of `bed` through a half-space of contact modulus
    /// `contact_modulus` E* (Pa): C_ij =
    /// [`square_influence`](super::square_influence)(x_i − x_j, 0, w, E*),
    /// symmetric. Errors: `contact_modulus` not finite and > 0.
    pub fn new(bed: RodBed, contact_modulus: f64) -> Result<Self> {
        check::positive("contact_modulus", contact_modulus)?;
        let n = bed.len();
        let w = bed.width();
        let centers = bed.centers();
        let mut influence = vec![0.0; n * n];
        for j in 0..n {
            for i in 0..=j {
                let c = influence_unchecked(centers[i] - centers[j], 0.0, w, contact_modulus);
                influence[i + j * n] = c;
                influence[j + i * n] = c;
            }
        }
        Ok(Self {
            bed,
            contact_modulus,
            influence,
        })
    }

    /// The rod bed.
    pub fn bed(&self) -> &RodBed {
        &self.bed
    }
    /// Contact modulus E* of the substrate (Pa).
    pub fn contact_modulus(&self) -> f64 {
        self.contact_modulus
    }
    /// The influence matrix C (m/N), n × n, column-major.
    pub fn influence(&self) -> MatRef<'_, f64> {
        let n = self.bed.len();
        MatRef::from_column_major_slice(&self.influence, n, n)
    }

    /// The equilibrium under `loading`: as [`RodBed::solve`], with
    /// substrate coupling. Errors as [`RodBed::solve`];
    /// [`Error::NotConverged`] when the active-set iteration fails.
    pub fn solve(
        &self,
        old: &RodState,
        new: &mut RodState,
        counter: &[f64],
        loading: Loading,
        options: &RodOptions,
        out: &mut RodSolution,
    ) -> Result<RodReport> {
        check_loading(loading)?;
        self.solve_checked(old, new, counter, loading, options, out)
    }

    fn solve_checked(
        &self,
        old: &RodState,
        new: &mut RodState,
        counter: &[f64],
        loading: Loading,
        options: &RodOptions,
        out: &mut RodSolution,
    ) -> Result<RodReport> {
        let bed = &self.bed;
        bed.check_all(old, counter, options, out)?;
        bed.check_capacity(loading)?;
        bed.prepare(old, counter, out);
        let n = bed.len();
        let fy = bed.yield_force();
        let eq = Balance::new(loading, bed.bulk_stiffness());
        let mut inner = Inner::new(n);
        // M·1·F_y per rod: the all-yielded limit.
        let mut all_yield = f64::INFINITY;
        for i in 0..n {
            let row: f64 = (0..n).map(|j| self.influence[i + j * n]).sum();
            let u = fy * (1.0 / out.stiffness[i] + row);
            all_yield = all_yield.min(out.contact_at[i] - u);
        }
        let (closed, start, max_a) = {
            let problem = Problem {
                a: &out.contact_at,
                y: &out.yield_at,
                k: &out.stiffness,
                fy,
                eq,
            };
            let max_a = problem.max_a();
            let closed = match loading {
                Loading::FixedGap { position } if eq.c == f64::INFINITY => Some(position),
                Loading::FixedLoad { load: 0.0 } => Some(max_a),
                Loading::FixedLoad { load } if load >= bed.capacity() => Some(all_yield),
                _ => None,
            };
            // Start from the old position, or from the uncoupled bed's
            // equilibrium (a close guess when the substrate is stiff).
            let start = match (closed, options.warm_start, old.position) {
                (Some(b), _, _) => b,
                (None, true, Some(p)) => p,
                (None, _, _) => problem.finish(problem.sweep(&mut out.events).0),
            };
            (closed, start, max_a)
        };
        let (b, iterations) = match closed {
            Some(b) => (b, 0),
            None => {
                let (mut lo, mut hi) = (all_yield, max_a);
                if let Loading::FixedGap { position: b0 } = loading {
                    lo = lo.min(b0);
                    hi = hi.max(b0);
                }
                self.outer(&mut inner, out, &eq, fy, start, (lo, hi))?
            }
        };
        inner.solve(self, out, b, fy)?;
        for i in 0..n {
            let u: f64 = (0..n)
                .map(|j| self.influence[i + j * n] * out.force[j])
                .sum();
            out.displacement[i] = u;
            out.overlap[i] = out.contact_at[i] - b - u;
            out.yielded[i] = out.force[i] >= fy;
        }
        let total: f64 = out.force.iter().sum();
        let mut report = RodReport {
            position: b,
            total_force: total,
            iterations: iterations + inner.iterations,
            ..RodReport::default()
        };
        bed.balance_report(loading, &mut report);
        bed.check_crush(out, old, loading)?;
        bed.commit(old, new, options, out, &mut report);
        new.position = Some(b);
        Ok(report)
    }

    /// Bracketed Newton iteration on b for R(b) = F(b) − P − c (b − b₀)
    /// (`eq`) from `start` inside the bracket (lo, hi) (m), F(b) from the
    /// inner box-constrained solve with yield force `fy` (N); slope
    /// −(1ᵀM_EE⁻¹1 + c).
    fn outer(
        &self,
        inner: &mut Inner,
        out: &mut RodSolution,
        eq: &Balance,
        fy: f64,
        start: f64,
        (mut lo, mut hi): (f64, f64),
    ) -> Result<(f64, u32)> {
        let scale = eq.p + fy;
        let mut b = start.max(lo).min(hi);
        let mut prev_set: Vec<u8> = Vec::new();
        let mut prev_newton = false;
        for it in 1..=ACTIVE_SET_MAX_ITERATIONS {
            let (f, kk) = inner.solve(self, out, b, fy)?;
            let r = eq.residual(b, f);
            if prev_newton && inner.set == prev_set {
                return Ok((b, it));
            }
            if r.abs() <= 1e-15 * scale * (self.bed.len() as f64) {
                return Ok((b, it));
            }
            if r >= 0.0 {
                lo = lo.max(b);
            } else {
                hi = hi.min(b);
            }
            let slope = kk + eq.c;
            let newton = if slope > 0.0 { b + r / slope } else { f64::NAN };
            prev_set.clone_from(&inner.set);
            if lo < newton && newton < hi && it % 5 != 0 {
                b = newton;
                prev_newton = true;
            } else {
                b = 0.5 * (lo + hi);
                prev_newton = false;
            }
            if hi - lo <= 4.0 * f64::EPSILON * hi.abs().max(lo.abs()) {
                return Ok((0.5 * (lo + hi), it));
            }
        }
        Err(Error::NotConverged {
            what: "coupled rods: position",
            iterations: ACTIVE_SET_MAX_ITERATIONS,
            residual: hi - lo,
        })
    }
}

/// Active-set solver of the box-constrained problem at a fixed position.
struct Inner {
    /// 0 off, 1 elastic, 2 yielded.
    set: Vec<u8>,
    idx: Vec<usize>,
    mat: Vec<f64>,
    rhs: Vec<f64>,
    ones: Vec<f64>,
    iterations: u32,
    started: bool,
}

impl Inner {
    fn new(n: usize) -> Self {
        Self {
            set: vec![0; n],
            idx: Vec::with_capacity(n),
            mat: Vec::new(),
            rhs: Vec::new(),
            ones: Vec::new(),
            iterations: 0,
            started: false,
        }
    }

    /// Forces at position `b` into `out.force`; returns (Σ f, 1ᵀ M_EE⁻¹ 1).
    fn solve(
        &mut self,
        bed: &CoupledRodBed,
        out: &mut RodSolution,
        b: f64,
        fy: f64,
    ) -> Result<(f64, f64)> {
        let n = bed.bed.len();
        let c = &bed.influence;
        if !self.started {
            for i in 0..n {
                let o = out.contact_at[i] - b;
                self.set[i] = if o <= 0.0 {
                    0
                } else if b <= out.yield_at[i] {
                    2
                } else {
                    1
                };
            }
            self.started = true;
        }
        for _ in 0..ACTIVE_SET_MAX_ITERATIONS {
            self.iterations += 1;
            self.idx.clear();
            self.idx.extend((0..n).filter(|&i| self.set[i] == 1));
            let m = self.idx.len();
            self.mat.clear();
            self.mat.resize(m * m, 0.0);
            self.rhs.clear();
            self.rhs.resize(m, 0.0);
            self.ones.clear();
            self.ones.resize(m, 1.0);
            for (q, &i) in self.idx.iter().enumerate() {
                for (p, &j) in self.idx.iter().enumerate() {
                    self.mat[p + q * m] = c[j + i * n];
                }
                self.mat[q + q * m] += 1.0 / out.stiffness[i];
                let mut r = out.contact_at[i] - b;
                for j in 0..n {
                    if self.set[j] == 2 {
                        r -= c[i + j * n] * fy;
                    }
                }
                self.rhs[q] = r;
            }
            let mut slope = 0.0;
            if m > 0 {
                let lu = PartialPivLu::new(MatRef::from_column_major_slice(&self.mat, m, m));
                lu.solve_in_place(MatMut::from_column_major_slice_mut(&mut self.rhs, m, 1));
                lu.solve_in_place(MatMut::from_column_major_slice_mut(&mut self.ones, m, 1));
                slope = self.ones.iter().sum();
            }
            for i in 0..n {
                out.force[i] = match self.set[i] {
                    2 => fy,
                    _ => 0.0,
                };
            }
            for (q, &i) in self.idx.iter().enumerate() {
                out.force[i] = self.rhs[q];
            }
            // Check and update the sets.
            let mut changed = false;
            for i in 0..n {
                let f = out.force[i];
                let next = match self.set[i] {
                    1 => {
                        if f < 0.0 {
                            0
                        } else if f > fy {
                            2
                        } else {
                            1
                        }
                    }
                    s => {
                        // Remaining interference r_i = o_i − (M f)_i.
                        let mut mf = f / out.stiffness[i];
                        for j in 0..n {
                            mf += c[i + j * n] * out.force[j];
                        }
                        let r = out.contact_at[i] - b - mf;
                        match s {
                            0 if r > 0.0 => 1,
                            2 if r < 0.0 => 1,
                            _ => s,
                        }
                    }
                };
                if next != self.set[i] {
                    self.set[i] = next;
                    changed = true;
                }
            }
            if !changed {
                let total: f64 = out.force.iter().sum();
                return Ok((total, slope));
            }
        }
        Err(Error::NotConverged {
            what: "coupled rods: active set at fixed position",
            iterations: ACTIVE_SET_MAX_ITERATIONS,
            residual: f64::NAN,
        })
    }
}
