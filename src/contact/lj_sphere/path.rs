//! Pseudo-arclength continuation of the Lennard-Jones sphere: the unknowns
//! are the log-gaps `y` and the approach `ᾱ`, the extra equation a
//! constraint (a hyperplane normal to the tangent, a prescribed approach or a
//! prescribed central gap), and the bordered `(N+1)×(N+1)` Newton system is
//! factored by faer's LU. The border row changes from step to step; a
//! rank-one (Sherman–Morrison) correction applies the current row to the
//! stored factorisation, so its solves stay exact in the constraint. A stale
//! factorisation preconditions GMRES on the true Jacobian.
//!
//! Mixed precision. The factorisation is a preconditioner only, so it is
//! computed and applied in single precision (half the memory traffic of the
//! triangular solves, twice the SIMD width of the factorisation); every
//! linear solve is GMRES on the double-precision bordered Jacobian, checked
//! by its recomputed residual. Solves to a relative residual of 1e-6 or
//! looser (Newton corrections, predictor tangents) apply the Jacobian with a
//! single-precision copy of the influence matrix, whose rounding (≈ 6e-8
//! relative) is far below their tolerance; tighter solves (exact tangents)
//! use the double-precision matrix. The Newton residual itself is always
//! double precision, so the converged states are unchanged.

// Index loops mirror the matrix algebra.
#![allow(clippy::needless_range_loop)]

use super::kernels;
use super::lu32::Lu32;
use super::newton::{Mode, Work};
use super::numeric::{dot, norm2};
use super::observe::unresolved;
use super::{LjPoint, LjSolver};
use crate::error::{Error, Result};

/// The extra equation of the bordered system.
#[derive(Debug, Clone)]
pub(super) enum Con {
    /// `row · (y, ᾱ) = c`.
    Plane { row: Vec<f64>, c: f64 },
    /// `ᾱ = value`.
    Approach(f64),
    /// `h̄₀ = value`.
    Gap(f64),
}

/// Relative residual to which a tangent is refined for the Hermite
/// predictor of the march: its error only costs Newton iterations.
pub(super) const PREDICTOR_RTOL: f64 = 1e-4;
/// Relative residual of the tangents of special points and exact states,
/// whose derivatives along the tangent locate extrema.
pub(super) const EXACT_RTOL: f64 = 1e-12;

/// [`LjSolver::path_root`] for a force minimum (the curve's pull-off) stops
/// once `|dP̄/ds|` is this fraction of its larger value at the ends of the
/// bracket: the minimum is then located to about 1e-6 of the bracket, and
/// the force there is off by the square of that. Below it the iterations
/// chase the rounding of `dP̄/ds` (central differences, scattered by
/// ~1e-9): at μ = 1, N = 256 the pull-off took 18 evaluations, 14 of them
/// at that noise, until the bracket closed to 1e-12 of its width.
pub(super) const ROOT_RTOL: f64 = 1e-6;

/// Largest Krylov dimension of [`LjSolver::bgmres`] before the caller
/// refactors instead.
const GMRES_MAX: usize = 12;

/// GMRES cycles of [`LjSolver::bgmres`] in a tight solve (each checked by
/// the true residual; a loose solve runs one).
const GMRES_CYCLES: usize = 3;

/// Forcing term of the inexact Newton steps: relative residual of the
/// GMRES solves of a Newton correction.
const NEWTON_ETA: f64 = 1e-3;

/// GMRES solves to a relative residual at or above this apply the Jacobian
/// with the single-precision influence matrix (module docs).
const SINGLE_PRECISION_RTOL: f64 = 1e-6;

/// Scratch of the single-precision influence products.
#[derive(Default)]
struct Single {
    q: Vec<f32>,
    out: Vec<f32>,
}

/// Scratch of the bordered Newton iteration.
pub(super) struct BWork {
    pub(super) w: Work,
    /// The bordered Jacobian's single-precision factorisation (a
    /// preconditioner), assembled and factored in place.
    lu: Lu32,
    /// Scratch of the single-precision triangular solves, `N+1`.
    s32: Vec<f32>,
    single: Single,
    row_lu: Vec<f64>,
    z: Vec<f64>,
    x: Vec<f64>,
    row: Vec<f64>,
    yt: Vec<f64>,
    /// Initial guess of a tangent solve, `N+1`.
    t0: Vec<f64>,
    g: f64,
    /// Most GMRES iterations of one linear solve in the last Newton solve
    /// (a measure of how stale the factorisation is).
    pub(super) krylov: usize,
    /// GMRES Krylov basis, `(GMRES_MAX+1)×(N+1)`.
    kv: Vec<f64>,
    /// GMRES preconditioned directions, `GMRES_MAX×(N+1)`.
    kz: Vec<f64>,
    /// Scratch of the Jacobian–vector product, `N`.
    kq: Vec<f64>,
    /// GMRES right-hand side, solution and true residual, `N+1` each.
    kb: Vec<f64>,
    kx: Vec<f64>,
    kr: Vec<f64>,
}

impl BWork {
    /// Forget the factorisation (after a failed solve).
    pub(super) fn invalidate(&mut self) {
        self.lu.invalidate();
    }

    pub(super) fn new(n: usize) -> Self {
        Self {
            w: Work::new_small(n),
            lu: Lu32::default(),
            s32: vec![0.0; n + 1],
            single: Single {
                q: vec![0.0; n],
                out: vec![0.0; n],
            },
            row_lu: vec![0.0; n + 1],
            z: vec![0.0; n + 1],
            x: vec![0.0; n + 1],
            row: vec![0.0; n + 1],
            yt: vec![0.0; n],
            t0: vec![0.0; n + 1],
            g: 0.0,
            krylov: 0,
            kv: vec![0.0; (GMRES_MAX + 1) * (n + 1)],
            kz: vec![0.0; GMRES_MAX * (n + 1)],
            kq: vec![0.0; n],
            kb: vec![0.0; n + 1],
            kx: vec![0.0; n + 1],
            kr: vec![0.0; n + 1],
        }
    }
}

/// A converged state on the path with its tangent.
#[derive(Debug, Clone)]
pub(super) struct State {
    pub(super) y: Vec<f64>,
    pub(super) al: f64,
    /// Unit tangent (metric [`LjSolver::metric_y`] on y, 1 on ᾱ), `N+1`.
    pub(super) t: Vec<f64>,
    /// Path parameter (cumulative arclength in the metric).
    pub(super) s: f64,
    pub(super) pt: LjPoint,
    /// dP̄/ds along `t` (NaN unless computed).
    pub(super) df: f64,
    /// h̄₀ of the state.
    pub(super) h0: f64,
}

impl LjSolver {
    /// Metric weight of one log-gap in the arclength (ᾱ has weight 1).
    pub(super) fn metric_y(&self) -> f64 {
        1.0 / self.n() as f64
    }

    /// Distance between the states `(y, ᾱ)` and `(y', ᾱ')` in the
    /// arclength metric ([`LjSolver::metric_y`]): the chord of the path
    /// between neighbouring states.
    pub(super) fn chord(&self, y: &[f64], al: f64, y2: &[f64], al2: f64) -> f64 {
        let dy: f64 = y.iter().zip(y2).map(|(a, b)| (a - b).powi(2)).sum();
        (self.metric_y() * dy + (al - al2).powi(2)).sqrt()
    }

    fn con_value(&self, con: &Con, y: &[f64], al: f64, w: &Work) -> f64 {
        let n = self.n();
        match con {
            Con::Plane { row, c } => dot(&row[..n], y) + row[n] * al - c,
            Con::Approach(a) => al - a,
            Con::Gap(h) => 1.0 - self.k * (dot(&self.a0, &w.p) + self.tail0) - al - h,
        }
    }

    fn con_row(&self, con: &Con, w: &Work, out: &mut [f64]) {
        let n = self.n();
        match con {
            Con::Plane { row, .. } => out.copy_from_slice(row),
            Con::Approach(_) => {
                out.iter_mut().for_each(|v| *v = 0.0);
                out[n] = 1.0;
            }
            Con::Gap(_) => {
                for j in 0..n {
                    out[j] = -self.k * self.a0[j] * w.dp[j] * w.h[j];
                }
                out[n] = -1.0;
            }
        }
    }

    /// Residual of the bordered system; max-norm of (F, g).
    fn bres(&self, con: &Con, y: &[f64], al: f64, bw: &mut BWork) -> f64 {
        let r = self.residual(Mode::Approach(al), y, &mut bw.w);
        let g = self.con_value(con, y, al, &bw.w);
        bw.g = g;
        let m = r.max(g.abs());
        if m.is_finite() {
            m
        } else {
            f64::INFINITY
        }
    }

    /// Factor the bordered Jacobian at the state in `bw.w` with border row
    /// `bw.row`, in single precision (a preconditioner, module docs).
    fn bfactor(&self, bw: &mut BWork) -> bool {
        let n = self.n();
        let m = n + 1;
        let k = self.k;
        let jac = bw.lu.matrix_mut(m);
        for j in 0..n {
            let qj = k * self.scale * bw.w.dp[j] * bw.w.h[j];
            let col = &self.a[j * n..(j + 1) * n];
            let jc = &mut jac[j * m..(j + 1) * m];
            for i in 0..n {
                jc[i] = (col[i] * qj) as f32;
            }
            jc[j] = (col[j] * qj + bw.w.h[j]) as f32;
            jc[n] = bw.row[j] as f32;
        }
        {
            let jc = &mut jac[n * m..];
            jc[..n].iter_mut().for_each(|v| *v = 1.0);
            jc[n] = bw.row[n] as f32;
        }
        // Without short-circuit: a branch-free fold vectorises (the
        // short-circuiting `any` took half of the assembly's time).
        if jac.iter().fold(false, |bad, v| bad | !v.is_finite()) {
            return false;
        }
        bw.lu.factor();
        bw.s32.iter_mut().for_each(|v| *v = 0.0);
        bw.s32[n] = 1.0;
        bw.lu.solve_in_place(&mut bw.s32);
        for (z, s) in bw.z.iter_mut().zip(&bw.s32) {
            *z = f64::from(*s);
        }
        bw.row_lu.copy_from_slice(&bw.row);
        bw.w.factorizations += 1;
        true
    }

    /// Solve the bordered system with the stored factorisation and the
    /// current border row `bw.row` (rank-one correction), in place in `bw.x`.
    fn bsolve(&self, bw: &mut BWork) -> bool {
        let m = self.n() + 1;
        if !bw.lu.is_valid() {
            return false;
        }
        for (s, x) in bw.s32.iter_mut().zip(&bw.x) {
            *s = *x as f32;
        }
        bw.lu.solve_in_place(&mut bw.s32);
        for (x, s) in bw.x.iter_mut().zip(&bw.s32) {
            *x = f64::from(*s);
        }
        let mut dz = 0.0;
        let mut dx = 0.0;
        for i in 0..m {
            let d = bw.row[i] - bw.row_lu[i];
            dz += d * bw.z[i];
            dx += d * bw.x[i];
        }
        if dx != 0.0 {
            let f = dx / (1.0 + dz);
            if !f.is_finite() {
                return false;
            }
            for i in 0..m {
                bw.x[i] -= f * bw.z[i];
            }
        }
        bw.x.iter().all(|v| v.is_finite())
    }

    /// `out = J_b v`: the bordered Jacobian at the state in `bw.w` with
    /// border row `bw.row`, applied to `v` (`N+1`); the influence product in
    /// single precision when `single` is given (module docs).
    fn bjac_apply(
        &self,
        w: &Work,
        row: &[f64],
        q: &mut [f64],
        single: Option<&mut Single>,
        v: &[f64],
        out: &mut [f64],
    ) {
        let n = self.n();
        for j in 0..n {
            q[j] = self.k * w.dp[j] * w.h[j] * v[j];
        }
        match single {
            None => self.matvec(q, &mut out[..n]),
            Some(sp) => {
                for (s, x) in sp.q.iter_mut().zip(q.iter()) {
                    *s = *x as f32;
                }
                kernels::matvec(&self.a32, &sp.q, self.scale as f32, &mut sp.out);
                for (o, s) in out[..n].iter_mut().zip(&sp.out) {
                    *o = f64::from(*s);
                }
            }
        }
        for i in 0..n {
            out[i] += w.h[i] * v[i] + v[n];
        }
        out[n] = dot(row, v);
    }

    /// Solve `J_b x = b` (`b` in `bw.x` on entry, `x` there on success) by
    /// GMRES right-preconditioned with the stored, possibly stale,
    /// factorisation, to a *true* residual `‖b − J_b x‖₂ ≤ rtol‖b‖₂`: below
    /// [`SINGLE_PRECISION_RTOL`] each cycle's result is checked against the
    /// recomputed residual (rounding makes GMRES's own estimate optimistic
    /// near 1e-12) and corrected by another cycle, at most
    /// [`GMRES_CYCLES`]; looser solves take GMRES's estimate. Returns the
    /// total iterations, or `None` when that does not suffice (the caller
    /// refactors).
    pub(super) fn bgmres(&self, bw: &mut BWork, rtol: f64) -> Option<usize> {
        let m1 = self.n() + 1;
        let single = rtol >= SINGLE_PRECISION_RTOL;
        let mut b = core::mem::take(&mut bw.kb);
        let mut x = core::mem::take(&mut bw.kx);
        let mut r = core::mem::take(&mut bw.kr);
        b.copy_from_slice(&bw.x);
        x.iter_mut().for_each(|v| *v = 0.0);
        r.copy_from_slice(&b);
        let bn = norm2(&b);
        let mut total = 0;
        let mut ok = None;
        for _ in 0..GMRES_CYCLES {
            let rn = norm2(&r);
            if !rn.is_finite() {
                break;
            }
            if rn <= rtol * bn {
                ok = Some(total);
                break;
            }
            bw.x.copy_from_slice(&r);
            let Some(k) = self.gmres_cycle(bw, rtol * bn / rn, single) else {
                break;
            };
            total += k;
            for (xi, di) in x.iter_mut().zip(&bw.x) {
                *xi += di;
            }
            if single {
                // At a relative residual of 1e-6 or looser GMRES's own
                // estimate is reliable (its optimism is a rounding effect
                // near 1e-12), and the caller checks the result: the next
                // Newton residual, or a predictor's own Newton solve. The
                // check would cost one more Jacobian product per solve (5 %
                // of a μ = 10 curve's instructions).
                ok = Some(total);
                break;
            }
            // True residual r = b − J_b x.
            let mut q = core::mem::take(&mut bw.kq);
            let mut sp = core::mem::take(&mut bw.single);
            self.bjac_apply(
                &bw.w,
                &bw.row,
                &mut q,
                single.then_some(&mut sp),
                &x,
                &mut r,
            );
            bw.kq = q;
            bw.single = sp;
            for (ri, bi) in r.iter_mut().zip(&b) {
                *ri = bi - *ri;
            }
        }
        if ok.is_some() {
            bw.x.copy_from_slice(&x);
        }
        debug_assert_eq!(x.len(), m1);
        bw.kb = b;
        bw.kx = x;
        bw.kr = r;
        ok
    }

    /// One GMRES cycle (Saad & Schultz 1986; modified Gram–Schmidt, Givens
    /// rotations) for `J_b x = b`, `b` in `bw.x`, right-preconditioned by the
    /// stored factorisation, to the estimated residual `rtol‖b‖₂`. Each
    /// iteration costs one Jacobian–vector product and one triangular solve;
    /// the first is the chord step itself. Returns the iterations, or
    /// `None` when [`GMRES_MAX`] do not suffice.
    fn gmres_cycle(&self, bw: &mut BWork, rtol: f64, single: bool) -> Option<usize> {
        let m1 = self.n() + 1;
        let beta = norm2(&bw.x);
        if !beta.is_finite() {
            return None;
        }
        if beta == 0.0 {
            return Some(0);
        }
        let mut kv = core::mem::take(&mut bw.kv);
        let mut kz = core::mem::take(&mut bw.kz);
        let mut q = core::mem::take(&mut bw.kq);
        let mut sp = core::mem::take(&mut bw.single);
        for (v, b) in kv[..m1].iter_mut().zip(&bw.x) {
            *v = b / beta;
        }
        let mut hh = [[0.0f64; GMRES_MAX]; GMRES_MAX + 1];
        let mut cs = [0.0f64; GMRES_MAX];
        let mut sn = [0.0f64; GMRES_MAX];
        let mut g = [0.0f64; GMRES_MAX + 1];
        g[0] = beta;
        let mut done = None;
        for j in 0..GMRES_MAX {
            bw.x.copy_from_slice(&kv[j * m1..(j + 1) * m1]);
            if !self.bsolve(bw) {
                break;
            }
            kz[j * m1..(j + 1) * m1].copy_from_slice(&bw.x);
            let (head, tail) = kv.split_at_mut((j + 1) * m1);
            let wv = &mut tail[..m1];
            self.bjac_apply(&bw.w, &bw.row, &mut q, single.then_some(&mut sp), &bw.x, wv);
            for i in 0..=j {
                let vi = &head[i * m1..(i + 1) * m1];
                let hij = dot(wv, vi);
                hh[i][j] = hij;
                for (a, b) in wv.iter_mut().zip(vi) {
                    *a -= hij * b;
                }
            }
            let hn = norm2(wv);
            hh[j + 1][j] = hn;
            if hn > 0.0 {
                wv.iter_mut().for_each(|a| *a /= hn);
            }
            for i in 0..j {
                let t = cs[i] * hh[i][j] + sn[i] * hh[i + 1][j];
                hh[i + 1][j] = -sn[i] * hh[i][j] + cs[i] * hh[i + 1][j];
                hh[i][j] = t;
            }
            let d = hh[j][j].hypot(hh[j + 1][j]);
            if !(d > 0.0) || !d.is_finite() {
                break;
            }
            cs[j] = hh[j][j] / d;
            sn[j] = hh[j + 1][j] / d;
            hh[j][j] = d;
            hh[j + 1][j] = 0.0;
            g[j + 1] = -sn[j] * g[j];
            g[j] *= cs[j];
            if g[j + 1].abs() <= rtol * beta || hn == 0.0 {
                done = Some(j + 1);
                break;
            }
        }
        let ok = if let Some(k) = done {
            let mut yk = [0.0f64; GMRES_MAX];
            for i in (0..k).rev() {
                let mut s = g[i];
                for l in i + 1..k {
                    s -= hh[i][l] * yk[l];
                }
                yk[i] = s / hh[i][i];
            }
            bw.x.iter_mut().for_each(|v| *v = 0.0);
            for (i, &c) in yk[..k].iter().enumerate() {
                for (x, z) in bw.x.iter_mut().zip(&kz[i * m1..(i + 1) * m1]) {
                    *x += c * z;
                }
            }
            bw.x.iter().all(|v| v.is_finite())
        } else {
            false
        };
        bw.kv = kv;
        bw.kz = kz;
        bw.kq = q;
        bw.single = sp;
        if ok {
            done
        } else {
            None
        }
    }

    /// Bordered Newton (full: refactor every iteration; else inexact Newton
    /// by GMRES preconditioned with the stored factorisation, refreshed
    /// when GMRES fails or a step needs a line search).
    pub(super) fn bnewton(
        &self,
        con: &Con,
        y: &mut [f64],
        al: &mut f64,
        bw: &mut BWork,
        full: bool,
    ) -> Result<(u32, f64)> {
        let n = self.n();
        let tol = self.opts.tolerance;
        let maxit = self.opts.max_iterations;
        let what = "LJ sphere continuation (bordered Newton)";
        let mut r = self.bres(con, y, *al, bw);
        let mut it = 0u32;
        let mut fresh = false;
        let mut need = full || !bw.lu.is_valid();
        bw.krylov = 0;
        let fail = |bw: &mut BWork, it: u32, r: f64| {
            bw.w.iterations += it as u64;
            Err(Error::NotConverged {
                what,
                iterations: it,
                residual: r,
            })
        };
        while r > tol {
            if it >= maxit || !r.is_finite() {
                return fail(bw, it, r);
            }
            it += 1;
            let mut row = core::mem::take(&mut bw.row);
            self.con_row(con, &bw.w, &mut row);
            bw.row = row;
            if need {
                if !self.bfactor(bw) {
                    return fail(bw, it, r);
                }
                fresh = true;
                need = full;
            }
            for i in 0..n {
                bw.x[i] = -bw.w.f[i];
            }
            bw.x[n] = -bw.g;
            // The factorisation, fresh or stale, preconditions GMRES on the
            // true Jacobian (inexact Newton with forcing term NEWTON_ETA); a
            // fresh one needs a single iteration.
            let solved = match self.bgmres(bw, NEWTON_ETA) {
                Some(k) => {
                    if !fresh {
                        bw.krylov = bw.krylov.max(k);
                    }
                    true
                }
                None => false,
            };
            if !solved {
                bw.lu.invalidate();
                if fresh {
                    return fail(bw, it, r);
                }
                need = true;
                continue;
            }
            let dmax = bw.x[..n].iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let mut lam = if dmax > 0.5 { 0.5 / dmax } else { 1.0 };
            let r2 = (norm2(&bw.w.f).powi(2) + bw.g * bw.g).sqrt();
            let mut yt = core::mem::take(&mut bw.yt);
            let mut accepted = false;
            let mut rt = r;
            let mut alt = *al;
            for _ in 0..12 {
                for i in 0..n {
                    yt[i] = y[i] + lam * bw.x[i];
                }
                alt = *al + lam * bw.x[n];
                rt = self.bres(con, &yt, alt, bw);
                let rt2 = (norm2(&bw.w.f).powi(2) + bw.g * bw.g).sqrt();
                if rt.is_finite() && rt2 <= (1.0 - 1e-4 * lam) * r2 {
                    accepted = true;
                    break;
                }
                lam *= 0.5;
            }
            if accepted {
                y.copy_from_slice(&yt);
                *al = alt;
                bw.yt = yt;
                if !full && lam < 1.0 {
                    need = true;
                }
                fresh = false;
                r = rt;
            } else {
                bw.yt = yt;
                r = self.bres(con, y, *al, bw);
                if fresh && r <= 1e2 * tol {
                    break;
                }
                if fresh {
                    return fail(bw, it, r);
                }
                need = true;
            }
        }
        bw.w.iterations += it as u64;
        bw.w.max_residual = bw.w.max_residual.max(r);
        Ok((it, r))
    }

    /// Tangent at the converged state in `bw.w`, oriented along `prev`
    /// (`N+1`, unit in the metric); `exact` refactors the Jacobian first,
    /// otherwise the stale factorisation's tangent is refined against the
    /// true Jacobian to relative residual `rtol` (refactoring if that fails),
    /// starting from `guess` when one is given (a direction, any length).
    pub(super) fn tangent(
        &self,
        bw: &mut BWork,
        prev: &[f64],
        exact: bool,
        rtol: f64,
        guess: Option<&[f64]>,
    ) -> Result<Vec<f64>> {
        let n = self.n();
        let my = self.metric_y();
        for i in 0..n {
            bw.row[i] = my * prev[i];
        }
        bw.row[n] = prev[n];
        if (exact || !bw.lu.is_valid()) && !self.bfactor(bw) {
            return Err(unresolved(0, f64::NAN));
        }
        let rtol = if exact { EXACT_RTOL } else { rtol };
        let guessed = match guess {
            Some(g) if !exact => self.tangent_from_guess(bw, g, rtol),
            _ => false,
        };
        if !guessed {
            bw.x.iter_mut().for_each(|v| *v = 0.0);
            bw.x[n] = 1.0;
            if self.bgmres(bw, rtol).is_none() {
                // The stale factorisation is too poor a preconditioner:
                // refactor.
                if !self.bfactor(bw) {
                    return Err(unresolved(0, f64::NAN));
                }
                bw.x.iter_mut().for_each(|v| *v = 0.0);
                bw.x[n] = 1.0;
                if self.bgmres(bw, rtol).is_none() {
                    return Err(unresolved(0, f64::NAN));
                }
            }
        }
        let mut t = bw.x.clone();
        let nn = (my * t[..n].iter().map(|v| v * v).sum::<f64>() + t[n] * t[n]).sqrt();
        let sgn = if my * dot(&t[..n], &prev[..n]) + t[n] * prev[n] >= 0.0 {
            1.0
        } else {
            -1.0
        };
        t.iter_mut().for_each(|v| *v *= sgn / nn);
        Ok(t)
    }

    /// The tangent at the state `(y, ᾱ)` a chord `dist` from `from`, to
    /// second order in the step: the secant is the tangent at the midpoint,
    /// so `t ≈ 2·secant − t_from` (the initial guess of
    /// [`LjSolver::tangent`]).
    pub(super) fn tangent_guess(from: &State, y: &[f64], al: f64, dist: f64) -> Vec<f64> {
        let n = y.len();
        (0..=n)
            .map(|i| {
                let d = if i < n {
                    y[i] - from.y[i]
                } else {
                    al - from.al
                };
                2.0 * d / dist - from.t[i]
            })
            .collect()
    }

    /// The loose tangent solve `J_b x = e_N` (border row in `bw.row`) from
    /// the initial guess `g` scaled to the border equation: GMRES only
    /// reduces the guess's residual `e_N − J_b x₀`, by `rtol/‖e_N − J_b
    /// x₀‖`. A tangent extrapolated along the path leaves a residual of
    /// 1e-3–1e-2, so a 1e-4 solve takes one or two iterations instead of
    /// four or five from zero. The solution in `bw.x`; false (nothing
    /// solved) when the guess or GMRES fails.
    fn tangent_from_guess(&self, bw: &mut BWork, g: &[f64], rtol: f64) -> bool {
        let n = self.n();
        let c = dot(&bw.row, g);
        if !(c.is_finite() && c > 0.0) || rtol < SINGLE_PRECISION_RTOL {
            return false;
        }
        let mut x0 = core::mem::take(&mut bw.t0);
        x0.iter_mut().zip(g).for_each(|(x, v)| *x = v / c);
        let mut q = core::mem::take(&mut bw.kq);
        let mut sp = core::mem::take(&mut bw.single);
        let mut r0 = core::mem::take(&mut bw.x);
        self.bjac_apply(&bw.w, &bw.row, &mut q, Some(&mut sp), &x0, &mut r0);
        bw.kq = q;
        bw.single = sp;
        r0.iter_mut().for_each(|v| *v = -*v);
        r0[n] += 1.0;
        let rn = norm2(&r0);
        bw.x = r0;
        let ok = if !rn.is_finite() {
            false
        } else if rn <= rtol {
            bw.x.copy_from_slice(&x0);
            true
        } else if self.bgmres(bw, (rtol / rn).min(0.5)).is_some() {
            bw.x.iter_mut().zip(&x0).for_each(|(x, v)| *x += v);
            true
        } else {
            false
        };
        bw.t0 = x0;
        ok
    }

    /// The state from a converged `bw.w` (after `bnewton`) with tangent `t`;
    /// `derivs` adds dP̄/ds and da/ds by central differences along `t`.
    pub(super) fn make_state(
        &self,
        y: &[f64],
        al: f64,
        t: Vec<f64>,
        s: f64,
        bw: &BWork,
        derivs: bool,
    ) -> Result<State> {
        let (h0, _, force, a) = self.observe(Mode::Approach(al), &bw.w);
        if !force.is_finite() {
            return Err(unresolved(
                bw.w.iterations.min(u32::MAX as u64) as u32,
                bw.w.max_residual,
            ));
        }
        let (mut df, mut da) = (f64::NAN, f64::NAN);
        if derivs {
            let n = self.n();
            let e = 1e-6;
            let mut yp = vec![0.0; n];
            let mut vals = [(0.0, 0.0); 2];
            for (q, sg) in [1.0, -1.0].into_iter().enumerate() {
                for i in 0..n {
                    yp[i] = y[i] + sg * e * t[i];
                }
                let (_, f, aa) = self.observe_y(&yp, al + sg * e * t[n]);
                vals[q] = (f, aa);
            }
            df = (vals[0].0 - vals[1].0) / (2.0 * e);
            da = (vals[0].1 - vals[1].1) / (2.0 * e);
            if a == 0.0 {
                da = 0.0;
            }
        }
        let d_al = t[self.n()];
        Ok(State {
            y: y.to_vec(),
            al,
            t,
            s,
            pt: LjPoint {
                central_gap: h0,
                approach: al,
                force,
                contact_radius: a,
                stiffness: f64::NAN,
                d_approach: d_al,
                d_force: df,
                d_radius: da,
            },
            df,
            h0,
        })
    }

    /// First state of a path: prescribed central gap `h0`, rigid guess,
    /// tangent towards increasing approach.
    pub(super) fn path_start(&self, h0: f64, bw: &mut BWork, derivs: bool) -> Result<State> {
        let mut y = self.rigid_guess(h0);
        let mut al = 1.0 - h0;
        self.bnewton(&Con::Gap(h0), &mut y, &mut al, bw, true)?;
        let n = self.n();
        // Border row e_ᾱ: the tangent has t_ᾱ = 1 before normalisation.
        let mut prev = vec![0.0; n + 1];
        prev[n] = 1.0;
        let t = self.tangent(bw, &prev, true, EXACT_RTOL, None)?;
        self.make_state(&y, al, t, 0.0, bw, derivs)
    }

    /// Step of length `sigma` (projected on the tangent) from `from`, with the
    /// predictor `from + sigma·t` or the given guess.
    pub(super) fn path_step(
        &self,
        from: &State,
        sigma: f64,
        guess: Option<(Vec<f64>, f64)>,
        bw: &mut BWork,
        exact: bool,
    ) -> Result<State> {
        let n = self.n();
        let my = self.metric_y();
        let mut row = vec![0.0; n + 1];
        for i in 0..n {
            row[i] = my * from.t[i];
        }
        row[n] = from.t[n];
        let c = dot(&row[..n], &from.y) + row[n] * from.al + sigma;
        let (mut y, mut al) = guess.unwrap_or_else(|| {
            (
                from.y
                    .iter()
                    .zip(&from.t)
                    .map(|(a, b)| a + sigma * b)
                    .collect(),
                from.al + sigma * from.t[n],
            )
        });
        self.bnewton(&Con::Plane { row, c }, &mut y, &mut al, bw, exact)?;
        let dist = self.chord(&y, al, &from.y, from.al);
        let guess = Self::tangent_guess(from, &y, al, dist);
        let t = self.tangent(bw, &from.t, exact, PREDICTOR_RTOL, Some(&guess))?;
        self.make_state(&y, al, t, from.s + dist, bw, true)
    }

    /// As [`LjSolver::path_step`] with a chord solve from the current
    /// factorisation and an exact tangent and derivatives after it.
    fn path_step_exact_tangent(
        &self,
        from: &State,
        sigma: f64,
        guess: (Vec<f64>, f64),
        bw: &mut BWork,
    ) -> Result<State> {
        let n = self.n();
        let my = self.metric_y();
        let mut row = vec![0.0; n + 1];
        for i in 0..n {
            row[i] = my * from.t[i];
        }
        row[n] = from.t[n];
        let c = dot(&row[..n], &from.y) + row[n] * from.al + sigma;
        let (mut y, mut al) = guess;
        let con = Con::Plane { row, c };
        if self.bnewton(&con, &mut y, &mut al, bw, false).is_err() {
            bw.invalidate();
            let (y0, a0) = (from.y.clone(), from.al);
            y = y0;
            al = a0;
            self.bnewton(&con, &mut y, &mut al, bw, true)?;
        }
        let t = self.tangent(bw, &from.t, false, EXACT_RTOL, None)?;
        let dist = self.chord(&y, al, &from.y, from.al);
        self.make_state(&y, al, t, from.s + dist, bw, true)
    }

    /// The state between `l` and `r` (neighbours on the path) where
    /// `phi(state)` changes sign, by the Illinois method on the step length
    /// from `l`, until the bracket is 1e-12 of its width or `|phi|` is
    /// `rtol` of its larger value at `l` and `r` (0: the bracket only; see
    /// [`ROOT_RTOL`]). Tangents and derivatives are exact.
    pub(super) fn path_root(
        &self,
        l: &State,
        r: &State,
        bw: &mut BWork,
        phi: &dyn Fn(&State) -> f64,
        rtol: f64,
    ) -> Result<State> {
        let n = self.n();
        let my = self.metric_y();
        let proj = |x: &State| {
            my * dot(&l.t[..n], &x.y) + l.t[n] * x.al - my * dot(&l.t[..n], &l.y) - l.t[n] * l.al
        };
        let sr = proj(r);
        let (mut a, mut fa) = (0.0, phi(l));
        let (mut b, mut fb) = (sr, phi(r));
        if fa == 0.0 {
            return Ok(l.clone());
        }
        if fb == 0.0 {
            return Ok(r.clone());
        }
        let f_scale = fa.abs().max(fb.abs());
        let mut best: Option<State> = None;
        for _ in 0..60 {
            let sig = (a * fb - b * fa) / (fb - fa);
            let sig = if sig.is_finite() && (sig - a) * (sig - b) < 0.0 {
                sig
            } else {
                0.5 * (a + b)
            };
            let th = sig / sr;
            let guess = (
                l.y.iter()
                    .zip(&r.y)
                    .map(|(p, q)| p + th * (q - p))
                    .collect(),
                l.al + th * (r.al - l.al),
            );
            let st = self.path_step_exact_tangent(l, sig, guess, bw)?;
            let f = phi(&st);
            if f * fb < 0.0 {
                a = b;
                fa = fb;
            } else {
                fa *= 0.5;
            }
            b = sig;
            fb = f;
            best = Some(st);
            if f == 0.0 || f.abs() <= rtol * f_scale || (a - b).abs() < 1e-12 * sr.abs() {
                break;
            }
        }
        best.ok_or(Error::NotConverged {
            what: "LJ sphere special point",
            iterations: 0,
            residual: f64::NAN,
        })
    }
}
