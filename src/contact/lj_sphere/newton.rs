//! One equilibrium: the residual of the discretised problem at prescribed
//! central gap or approach, its Jacobian factored by faer's LU, and the
//! damped (full or chord) Newton iteration behind the single solves.

use super::numeric::{dot, norm2};
use super::observe::unresolved;
use super::{lj_pressure, LjSolution, LjSolver};
use crate::error::{check, Error, Result};
use faer::linalg::solvers::{PartialPivLu, Solve};
use faer::{MatMut, MatRef};

/// Which quantity is prescribed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Mode {
    Gap(f64),
    Approach(f64),
}

impl Mode {
    fn is_gap(&self) -> bool {
        matches!(self, Mode::Gap(_))
    }
}

/// Scratch of the Newton iteration and the cached factorisation.
pub(super) struct Work {
    pub(super) h: Vec<f64>,
    pub(super) p: Vec<f64>,
    pub(super) dp: Vec<f64>,
    pub(super) ap: Vec<f64>,
    pub(super) f: Vec<f64>,
    pub(super) d: Vec<f64>,
    pub(super) yt: Vec<f64>,
    pub(super) jac: Vec<f64>,
    pub(super) lu: Option<(PartialPivLu<f64>, bool)>,
    pub(super) iterations: u64,
    pub(super) factorizations: u64,
    pub(super) max_residual: f64,
}

impl Work {
    /// Without the n×n Jacobian (allocated on first use).
    pub(super) fn new_small(n: usize) -> Self {
        let mut w = Self::new(0);
        for v in [
            &mut w.h, &mut w.p, &mut w.dp, &mut w.ap, &mut w.f, &mut w.d, &mut w.yt,
        ] {
            *v = vec![0.0; n];
        }
        w
    }

    pub(super) fn new(n: usize) -> Self {
        Self {
            h: vec![0.0; n],
            p: vec![0.0; n],
            dp: vec![0.0; n],
            ap: vec![0.0; n],
            f: vec![0.0; n],
            d: vec![0.0; n],
            yt: vec![0.0; n],
            jac: vec![0.0; n * n],
            lu: None,
            iterations: 0,
            factorizations: 0,
            max_residual: 0.0,
        }
    }
}

impl LjSolver {
    /// Residual at log-gaps `y`: fills h, p, dp, ap, f; returns the max-norm
    /// of `f_i / max(h̄_i, 1)` (see [`LjOptions::tolerance`]).
    pub(super) fn residual(&self, mode: Mode, y: &[f64], w: &mut Work) -> f64 {
        let n = self.n();
        for i in 0..n {
            let h = y[i].exp();
            let (p, dp) = lj_pressure(h);
            w.h[i] = h;
            w.p[i] = p;
            w.dp[i] = dp;
        }
        let mut ap = core::mem::take(&mut w.ap);
        self.matvec(&w.p, &mut ap);
        w.ap = ap;
        let k = self.k;
        let mut m = 0.0f64;
        match mode {
            Mode::Gap(h0) => {
                let a0p = dot(&self.a0, &w.p) + self.tail0;
                for i in 0..n {
                    let x = self.mesh.x[i];
                    let f = w.h[i] - h0 - 0.5 * x * x + k * (w.ap[i] + self.tail[i] - a0p);
                    w.f[i] = f;
                    m = m.max(f.abs() / w.h[i].max(1.0));
                }
            }
            Mode::Approach(al) => {
                for i in 0..n {
                    let x = self.mesh.x[i];
                    let f = w.h[i] + al - 0.5 * x * x - 1.0 + k * (w.ap[i] + self.tail[i]);
                    w.f[i] = f;
                    m = m.max(f.abs() / w.h[i].max(1.0));
                }
            }
        }
        if m.is_finite() {
            m
        } else {
            f64::INFINITY
        }
    }

    /// Factor the Jacobian at the state in `w` (after `residual`).
    pub(super) fn factor(&self, gap_mode: bool, w: &mut Work) -> bool {
        let n = self.n();
        let k = self.k;
        if w.jac.len() != n * n {
            w.jac = vec![0.0; n * n];
        }
        for j in 0..n {
            let qj = k * w.dp[j] * w.h[j];
            let col = &self.a[j * n..(j + 1) * n];
            let jc = &mut w.jac[j * n..(j + 1) * n];
            let sub = if gap_mode { self.a0[j] } else { 0.0 };
            for i in 0..n {
                jc[i] = (self.scale * col[i] - sub) * qj;
            }
            jc[j] += w.h[j];
        }
        if w.jac.iter().any(|v| !v.is_finite()) {
            return false;
        }
        let m = MatRef::from_column_major_slice(&w.jac, n, n);
        w.lu = Some((PartialPivLu::new(m), gap_mode));
        w.factorizations += 1;
        true
    }

    /// Newton (full: refactor every iteration; else chord with refresh).
    pub(super) fn newton(
        &self,
        mode: Mode,
        y: &mut [f64],
        w: &mut Work,
        full: bool,
    ) -> Result<(u32, f64)> {
        let n = self.n();
        let tol = self.opts.tolerance;
        let maxit = self.opts.max_iterations;
        let what = if mode.is_gap() {
            "LJ sphere Newton solve at prescribed central gap"
        } else {
            "LJ sphere Newton solve at prescribed approach"
        };
        let mut r = self.residual(mode, y, w);
        let mut it = 0u32;
        let mut fresh = false;
        let mut need = full || !matches!(w.lu, Some((_, g)) if g == mode.is_gap());
        while r > tol {
            if it >= maxit || !r.is_finite() {
                w.iterations += it as u64;
                return Err(Error::NotConverged {
                    what,
                    iterations: it,
                    residual: r,
                });
            }
            it += 1;
            if need {
                if !self.factor(mode.is_gap(), w) {
                    w.iterations += it as u64;
                    return Err(Error::NotConverged {
                        what,
                        iterations: it,
                        residual: r,
                    });
                }
                fresh = true;
                need = full;
            }
            for i in 0..n {
                w.d[i] = -w.f[i];
            }
            if let Some((lu, _)) = &w.lu {
                lu.solve_in_place(MatMut::from_column_major_slice_mut(&mut w.d, n, 1));
            }
            let dmax = w.d.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            if !dmax.is_finite() {
                w.lu = None;
                if fresh {
                    w.iterations += it as u64;
                    return Err(Error::NotConverged {
                        what,
                        iterations: it,
                        residual: r,
                    });
                }
                need = true;
                continue;
            }
            let mut lam = if dmax > 0.5 { 0.5 / dmax } else { 1.0 };
            let r2 = norm2(&w.f);
            let d = core::mem::take(&mut w.d);
            let mut yt = core::mem::take(&mut w.yt);
            let mut accepted = false;
            let mut rt = r;
            for _ in 0..12 {
                for i in 0..n {
                    yt[i] = y[i] + lam * d[i];
                }
                rt = self.residual(mode, &yt, w);
                if rt.is_finite() && norm2(&w.f) <= (1.0 - 1e-4 * lam) * r2 {
                    accepted = true;
                    break;
                }
                lam *= 0.5;
            }
            w.d = d;
            if accepted {
                y.copy_from_slice(&yt);
                w.yt = yt;
                // Chord: refresh the Jacobian when the contraction is poor.
                if !full && (rt > 0.25 * r || lam < 1.0) {
                    need = true;
                }
                fresh = false;
                r = rt;
            } else {
                w.yt = yt;
                // Restore the residual state at y.
                r = self.residual(mode, y, w);
                if fresh && r <= 1e2 * tol {
                    // Stagnation at the rounding floor of an ill-conditioned
                    // Jacobian (near a fold of the prescribed variable): the
                    // state is converged to the reported residual.
                    break;
                }
                if fresh {
                    w.iterations += it as u64;
                    return Err(Error::NotConverged {
                        what,
                        iterations: it,
                        residual: r,
                    });
                }
                need = true;
            }
        }
        w.iterations += it as u64;
        w.max_residual = w.max_residual.max(r);
        Ok((it, r))
    }

    pub(super) fn rigid_guess(&self, h0: f64) -> Vec<f64> {
        self.mesh
            .x
            .iter()
            .map(|&x| (h0 + 0.5 * x * x).ln())
            .collect()
    }

    pub(super) fn solution(&self, mode: Mode, w: &Work, it: u32, res: f64) -> Result<LjSolution> {
        let (h0, al, force, a) = self.observe(mode, w);
        if !force.is_finite() {
            return Err(unresolved(it, res));
        }
        Ok(LjSolution {
            central_gap: h0,
            approach: al,
            force,
            contact_radius: a,
            gap: w.h.clone(),
            pressure: w.p.clone(),
            iterations: it,
            residual: res,
        })
    }

    fn check_guess(&self, guess: Option<&LjSolution>) -> Result<Option<Vec<f64>>> {
        match guess {
            None => Ok(None),
            Some(g) => {
                if g.gap.len() != self.n() || g.gap.iter().any(|&h| !(h > 0.0 && h.is_finite())) {
                    return Err(Error::InvalidArgument {
                        name: "initial_guess",
                        value: g.gap.len() as f64,
                        bound: "a solution of this solver (N positive gaps)",
                    });
                }
                Ok(Some(g.gap.iter().map(|h| h.ln()).collect()))
            }
        }
    }

    /// Equilibrium at the prescribed central gap `h0 = h(0)/z₀` (> 0), by
    /// full Newton from `initial_guess` (or the rigid profile). The
    /// equilibrium is unique in `h0` for moderate μ (Greenwood 1997), but a
    /// far guess can fail deep in contact: use [`LjSolver::sweep`] there.
    pub fn solve_at_central_gap(
        &self,
        h0: f64,
        initial_guess: Option<&LjSolution>,
    ) -> Result<LjSolution> {
        let h0 = check::positive("central_gap", h0)?;
        let mut y = self
            .check_guess(initial_guess)?
            .unwrap_or_else(|| self.rigid_guess(h0));
        let mut w = Work::new(self.n());
        let (it, res) = self.newton(Mode::Gap(h0), &mut y, &mut w, true)?;
        self.solution(Mode::Gap(h0), &w, it, res)
    }

    /// Equilibrium at the prescribed approach `alpha = α/z₀`, by full Newton
    /// from `initial_guess` (or the rigid profile at `h₀ = max(1 − ᾱ, 0.9)`).
    /// Several equilibria exist on S-shaped curves: the guess selects the
    /// branch.
    pub fn solve_at_approach(
        &self,
        alpha: f64,
        initial_guess: Option<&LjSolution>,
    ) -> Result<LjSolution> {
        let al = check::finite("approach", alpha)?;
        let guess = self.check_guess(initial_guess)?;
        let has_guess = guess.is_some();
        let mut y = guess.unwrap_or_else(|| {
            // Rigid profile, flattened where it would penetrate.
            self.mesh
                .x
                .iter()
                .map(|&x| (1.0 - al + 0.5 * x * x).max(0.97).ln())
                .collect()
        });
        let mut w = Work::new(self.n());
        match self.newton(Mode::Approach(al), &mut y, &mut w, true) {
            Ok((it, res)) => self.solution(Mode::Approach(al), &w, it, res),
            Err(e) if has_guess => Err(e),
            Err(_) => self.approach_by_continuation(al),
        }
    }
}
