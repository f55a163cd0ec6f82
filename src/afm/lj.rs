//! The numerical Lennard-Jones sphere fitted to the retract curve.
//!
//! The sphere of [`crate::contact::lj_sphere`] (Greenwood 1997; Feng 2000)
//! has, in reduced units (force `P̄ = P/(πRw)`, approach `ᾱ = α/z₀`), a
//! force–approach law that depends on the Tabor parameter
//! `μ = (Rw²/(E*²z₀³))^{1/3} = (W²/(K²z₀³))^{1/3}` only (K = E*√R, W = wR).
//! At a fixed μ the dimensional law is therefore one reduced table scaled,
//!
//! $$P(\delta) = W\\,\tilde P(\delta/z_0;\ \mu), \qquad s = \frac{dP}{d\delta} = \frac{W}{z_0}\\,\tilde s,$$
//!
//! with `P̃` the force of the unit sphere [`LjSphere::from_tabor`] (R = w =
//! z₀ = 1, force unit π), evaluated through its [`TabulatedLaw`] (N = 128
//! cells, relative tolerance 10⁻³ against that grid: the law's pull-off
//! is within 0.2 % of the N = 256 solver's for μ = 0.05…30). K follows
//! from W and μ: `K = W μ^{-3/2} z₀^{-3/2}`.
//!
//! The fit ([`fit`]) is a profile least-squares problem:
//!
//! 1. **inner**: at fixed μ, Levenberg–Marquardt on `(ln W, u_c)` with the
//!    effective-variance residual and the pull-off residual of
//!    [`super::fit`] (one table, cheap evaluations);
//! 2. **outer**: a 1-D minimisation of the inner sum of squares over
//!    `x = ln μ` in `[ln 0.01, ln 50]`, from the Maugis–Dugdale fit's μ: a
//!    bracket by steps of 0.5, 1, 2 in x, then successive parabolic
//!    interpolation (golden-section steps where the parabola is unusable)
//!    until the bracket is narrower than 0.05 in x. Every μ builds one
//!    table (0.1–0.35 s optimised), cached for the fit;
//! 3. **standard errors** from the Jacobian in `(ln W, ln μ, u_c)` at the
//!    optimum, `s²(JᵀJ)⁻¹`, `s² = SSR/(m − 3)`; the ln μ column by the
//!    central difference between tables at `x ± 0.1`, the others by central
//!    differences on the optimum's table. `ln K = ln W − 1.5 ln μ − 1.5 ln z₀`
//!    gives `var ln K = var ln W + 2.25 var ln μ − 3 cov(ln W, ln μ)`.
//!
//! A minimum on a bound of the μ range is reported as not converged.
//!
//! # References
//!
//! * J. A. Greenwood (1997), Proc. R. Soc. Lond. A 453, 1277–1297,
//!   [doi:10.1098/rspa.1997.0070](https://doi.org/10.1098/rspa.1997.0070).
//! * J. Q. Feng (2000), Colloids Surf. A 172, 175–198.
//! * R. P. Brent (1973), *Algorithms for Minimization without Derivatives*,
//!   Prentice-Hall, ch. 5 (parabolic interpolation with golden-section
//!   safeguard).

use super::fit::{levenberg_marquardt, residual_at, FitData, Scales};
use crate::contact::lj_sphere::LjSphere;
use crate::contact::tabulated::TabulatedLaw;
use crate::contact::{ContactState, Control, NormalContact, NormalResponse};
use crate::error::{Error, Result};
use std::collections::HashMap;
use std::sync::Arc;

/// Grid sizes tried for a table, first that builds wins.
const GRIDS: [usize; 3] = [128, 192, 256];
/// Relative tolerance of a table against its grid's solver.
const TABLE_TOLERANCE: f64 = 1e-3;
/// The μ range of the outer search.
pub(crate) const MU_RANGE: (f64, f64) = (0.01, 50.0);
/// Step in ln μ of the finite difference of the standard errors.
const FD_STEP: f64 = 0.1;
/// Width in ln μ of the final bracket.
const X_TOL: f64 = 0.05;

/// The reduced table of the unit sphere with Tabor parameter `mu`.
pub(crate) fn unit_table(mu: f64) -> Result<Arc<TabulatedLaw>> {
    let lj = LjSphere::from_tabor(mu)?;
    let mut last = None;
    for n in GRIDS {
        match TabulatedLaw::from_lj_sphere(&lj, n, TABLE_TOLERANCE) {
            Ok(t) => return Ok(Arc::new(t)),
            Err(e) => last = Some(e),
        }
    }
    Err(last.unwrap_or(Error::NotConverged {
        what: "Lennard-Jones table",
        iterations: 0,
        residual: f64::NAN,
    }))
}

/// A unit table scaled to the dimensional law (module docs): forces by W
/// (J/m), overlaps by z₀ (m), contact radii by √(R z₀).
#[derive(Debug, Clone)]
pub(crate) struct ScaledTable {
    pub table: Arc<TabulatedLaw>,
    /// W = wR (J/m): the force unit over the table's π.
    pub force: f64,
    /// z₀ (m).
    pub length: f64,
    /// √(R z₀) (m).
    pub radius: f64,
}

impl ScaledTable {
    fn scale(&self, r: NormalResponse) -> NormalResponse {
        NormalResponse {
            force: r.force * self.force,
            delta: r.delta * self.length,
            contact_radius: r.contact_radius * self.radius,
            stiffness: r.stiffness * self.force / self.length,
            ..r
        }
    }
}

impl NormalContact for ScaledTable {
    fn eval(&self, delta: f64, old: &ContactState) -> Result<(NormalResponse, ContactState)> {
        let mut o = *old;
        o.contact_radius /= self.radius;
        let (r, mut s) = self.table.eval(delta / self.length, &o)?;
        s.contact_radius *= self.radius;
        Ok((self.scale(r), s))
    }

    fn eval_at_load(&self, force: f64) -> Result<NormalResponse> {
        Ok(self.scale(self.table.eval_at_load(force / self.force)?))
    }

    fn pull_off_force(&self, control: Control) -> Result<f64> {
        Ok(self.table.pull_off_force(control)? * self.force)
    }

    fn length_scale(&self) -> f64 {
        self.table.length_scale() * self.length
    }

    fn reach(&self, control: Control, rel_force: f64) -> Result<f64> {
        Ok(self.table.reach(control, rel_force)? * self.length)
    }
}

/// The result of [`fit`], in the units of [`super::fit::fit`]'s.
pub(crate) struct LjFit {
    pub mu: f64,
    pub w: f64,
    pub u_c: f64,
    pub ssr: f64,
    /// Standard errors of ln K, ln W and u_c (m), `None` where singular.
    pub se_ln_k: Option<f64>,
    pub se_ln_w: Option<f64>,
    pub se_uc: Option<f64>,
    pub iterations: usize,
    pub converged: bool,
    pub table: Arc<TabulatedLaw>,
}

/// An inner solution at one μ.
#[derive(Clone)]
struct Inner {
    ssr: f64,
    /// (ln(W/W₀), (u_c − y_ref)/L).
    theta: [f64; 2],
    iterations: usize,
    converged: bool,
}

/// Fit the Lennard-Jones sphere (module docs), starting at `mu_start`.
pub(crate) fn fit(d: &FitData, mu_start: f64) -> Result<LjFit> {
    let n = d.force.len();
    let m = n + usize::from(d.pull_off.is_some());
    if n < 5 {
        return Err(Error::InvalidArgument {
            name: "retract curve",
            value: n as f64,
            bound: "at least p + 2 points between the maximum force and the pull-off",
        });
    }
    let sc = Scales::of(d);
    // W₀ from the pull-off of the unit sphere at μ ≈ 1 (−5.25 π⁻¹·π).
    let w0 = (-sc.f_po / 5.25).max(1e-6 * sc.df / std::f64::consts::PI);
    let r = d.radius.unwrap_or(1.0);
    let rad = (r * d.z0).sqrt();
    let mut tables: HashMap<u64, Option<Arc<TabulatedLaw>>> = HashMap::new();
    let mut table = |x: f64| -> Option<Arc<TabulatedLaw>> {
        tables
            .entry(x.to_bits())
            .or_insert_with(|| unit_table(x.exp()).ok())
            .clone()
    };
    let law = |t: &Arc<TabulatedLaw>, th: &[f64]| ScaledTable {
        table: t.clone(),
        force: w0 * th[0].exp(),
        length: d.z0,
        radius: rad,
    };
    let residual = |t: &Arc<TabulatedLaw>, th: &[f64], out: &mut [f64]| -> Option<()> {
        let l = law(t, th);
        let uc = sc.y_ref + sc.len * th[1];
        let pc = l.pull_off_force(Control::Load).ok()?;
        for ((o, &f), &y) in out.iter_mut().zip(d.force).zip(d.tip) {
            let v = residual_at(&l, pc, d.spring_constant, uc, f, y)? / sc.df;
            if !v.is_finite() {
                return None;
            }
            *o = v;
        }
        if let Some(po) = d.pull_off {
            out[n] = (po - pc) / sc.df;
        }
        Some(())
    };
    // Inner fit at one x = ln μ, from the pull-off start and the warm start.
    let inner = |t: &Arc<TabulatedLaw>, warm: Option<[f64; 2]>| -> Option<Inner> {
        let pc_t = t.pull_off_force(Control::Load).ok()?;
        let mut starts = Vec::new();
        let tw = if sc.f_po < 0.0 && pc_t < 0.0 {
            ((sc.f_po / pc_t) / w0).ln()
        } else {
            0.0
        };
        // u_c so that the model's pull-off sits at the measured one.
        let d_po = t.eval_at_load(pc_t * (1.0 - 1e-9)).ok()?.delta * d.z0;
        starts.push([tw, -d_po / sc.len]);
        starts.extend(warm);
        let mut best: Option<Inner> = None;
        for s in starts {
            let f = |th: &[f64], out: &mut [f64]| residual(t, th, out);
            if let Some(res) = levenberg_marquardt(&f, s.to_vec(), m) {
                if best.as_ref().map_or(true, |b| res.ssr < b.ssr) {
                    best = Some(Inner {
                        ssr: res.ssr,
                        theta: [res.theta[0], res.theta[1]],
                        iterations: res.iterations,
                        converged: res.converged,
                    });
                }
            }
        }
        best
    };
    let (xlo, xhi) = (MU_RANGE.0.ln(), MU_RANGE.1.ln());
    let mut evals: Vec<(f64, Inner)> = Vec::new();
    let mut profile = |x: f64, evals: &mut Vec<(f64, Inner)>| -> f64 {
        if let Some((_, i)) = evals.iter().find(|(y, _)| *y == x) {
            return i.ssr;
        }
        let warm = evals
            .iter()
            .min_by(|a, b| (a.0 - x).abs().total_cmp(&(b.0 - x).abs()))
            .map(|(_, i)| i.theta);
        let res = table(x).and_then(|t| inner(&t, warm));
        let s = res.as_ref().map_or(f64::INFINITY, |i| i.ssr);
        if let Some(i) = res {
            evals.push((x, i));
        }
        s
    };
    // Bracket.
    let x0 = mu_start
        .clamp(MU_RANGE.0, MU_RANGE.1)
        .ln()
        .clamp(xlo + 0.5, xhi - 0.5);
    let mut a = (x0 - 0.5, profile(x0 - 0.5, &mut evals));
    let mut b = (x0, profile(x0, &mut evals));
    let mut c = (x0 + 0.5, profile(x0 + 0.5, &mut evals));
    let mut step = 1.0;
    let mut at_bound = false;
    while !(b.1 <= a.1 && b.1 <= c.1) {
        if a.1 < c.1 {
            if a.0 <= xlo {
                at_bound = true;
                break;
            }
            let x = (a.0 - step).max(xlo);
            (c, b) = (b, a);
            a = (x, profile(x, &mut evals));
        } else {
            if c.0 >= xhi {
                at_bound = true;
                break;
            }
            let x = (c.0 + step).min(xhi);
            (a, b) = (b, c);
            c = (x, profile(x, &mut evals));
        }
        step *= 2.0;
    }
    if !b.1.is_finite() && !a.1.is_finite() && !c.1.is_finite() {
        return Err(Error::NotConverged {
            what: "Lennard-Jones sphere fit",
            iterations: evals.len() as u32,
            residual: f64::NAN,
        });
    }
    // Parabolic refinement with a golden-section safeguard.
    if !at_bound {
        for _ in 0..8 {
            if c.0 - a.0 < X_TOL {
                break;
            }
            let (p, q) = ((b.0 - a.0) * (b.1 - c.1), (b.0 - c.0) * (b.1 - a.1));
            let den = 2.0 * (p - q);
            let mut x = b.0 - ((b.0 - a.0) * p - (b.0 - c.0) * q) / den;
            let lo = a.0 + 0.1 * (b.0 - a.0);
            let hi = c.0 - 0.1 * (c.0 - b.0);
            if !(x.is_finite() && x > lo && x < hi) || (x - b.0).abs() < 0.2 * X_TOL {
                x = if c.0 - b.0 > b.0 - a.0 {
                    b.0 + 0.382 * (c.0 - b.0)
                } else {
                    b.0 - 0.382 * (b.0 - a.0)
                };
            }
            let fx = profile(x, &mut evals);
            if fx <= b.1 {
                if x > b.0 {
                    a = b;
                } else {
                    c = b;
                }
                b = (x, fx);
            } else if x > b.0 {
                c = (x, fx);
            } else {
                a = (x, fx);
            }
        }
    }
    let (xb, best) = evals
        .iter()
        .min_by(|p, q| p.1.ssr.total_cmp(&q.1.ssr))
        .cloned()
        .ok_or(Error::NotConverged {
            what: "Lennard-Jones sphere fit",
            iterations: 0,
            residual: f64::NAN,
        })?;
    let at_bound = at_bound || xb <= xlo + 1e-12 || xb >= xhi - 1e-12;
    let t = table(xb).ok_or(Error::NotConverged {
        what: "Lennard-Jones table",
        iterations: 0,
        residual: f64::NAN,
    })?;
    // Jacobian in (ln W, ln μ, u_c).
    let th = best.theta;
    let mut jac = vec![0.0; m * 3];
    let mut rp = vec![0.0; m];
    let mut rm = vec![0.0; m];
    let mut ok = true;
    for (j, col) in [(0usize, 0usize), (1, 2)] {
        let h = 1e-6;
        let mut p = th;
        p[j] += h;
        let mut q = th;
        q[j] -= h;
        ok &= residual(&t, &p, &mut rp).is_some() && residual(&t, &q, &mut rm).is_some();
        for i in 0..m {
            jac[i * 3 + col] = (rp[i] - rm[i]) / (2.0 * h);
        }
    }
    let (tp, tm) = (table(xb + FD_STEP), table(xb - FD_STEP));
    match (tp, tm) {
        (Some(tp), Some(tm)) => {
            ok &= residual(&tp, &th, &mut rp).is_some() && residual(&tm, &th, &mut rm).is_some();
            for i in 0..m {
                jac[i * 3 + 1] = (rp[i] - rm[i]) / (2.0 * FD_STEP);
            }
        }
        _ => ok = false,
    }
    let cov = if ok {
        let (jtj, _) = super::fit::normal_equations(&jac, &rp, m, 3);
        super::fit::invert(&jtj, 3)
    } else {
        None
    };
    let s2 = best.ssr / (m as f64 - 3.0).max(1.0);
    let var = |i: usize, j: usize| cov.as_ref().map(|c| s2 * c[i * 3 + j]);
    let pos = |v: Option<f64>| v.filter(|v| v.is_finite() && *v >= 0.0).map(f64::sqrt);
    let se_ln_w = pos(var(0, 0));
    let se_ln_k = pos(var(0, 0)
        .zip(var(1, 1))
        .zip(var(0, 1))
        .map(|((ww, mm), wm)| ww + 2.25 * mm - 3.0 * wm));
    let se_uc = pos(var(2, 2)).map(|s| s * sc.len);
    Ok(LjFit {
        mu: xb.exp(),
        w: w0 * th[0].exp(),
        u_c: sc.y_ref + sc.len * th[1],
        ssr: best.ssr,
        se_ln_k,
        se_ln_w,
        se_uc,
        iterations: best.iterations,
        converged: best.converged && !at_bound,
        table: t,
    })
}
