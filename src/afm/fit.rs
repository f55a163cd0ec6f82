//! Fitting the library's adhesive-sphere laws to the retract curve.
//!
//! The data are points (F_i, y_i): the baseline-corrected force and the tip
//! position `y = u − F/k` (u the piezo travel towards the sample, k the
//! spring constant). A law with contact modulus E*, work of adhesion w and
//! radius R gives, on its load-controlled (stable) branch, the overlap
//! δ(F) ([`NormalContact::eval_at_load`]); the model of the data is
//! `y = u_c + δ(F)`, u_c the tip position at zero overlap. The residual is
//! the position misfit `g = u_c + δ(F) − y` weighted by the effective-variance
//! rule (Orear 1982) for noise in the force: `r = g·S`, `S = k s/(k + s)` the
//! stiffness of lever and contact in series (s = dF/dδ of the law), which is
//! a force (N) and stays well conditioned both for a stiff sample under a
//! soft lever (S → k) and near the pull-off (s → 0). Points below the
//! model's pull-off p_c have the residual `F − p_c`. When the curve has a
//! significant pull-off F_po, one more residual `F_po − p_c` asks the law's
//! load-controlled pull-off to match it: the lever separates where the
//! combined stiffness vanishes, at the minimum force for a lever much
//! softer than the contact, so a law whose own pull-off lies far beyond the
//! measured one contradicts the curve even where its branch fits.
//!
//! The parameters are `K = E*√R` and `W = wR` (and u_c): δ(F) depends on R,
//! E* and w only through these two for Hertz, DMT, JKR and Maugis–Dugdale
//! with the Lennard-Jones stress (λ = 1.157 μ, μ³ = W²/(K²z₀³)), so with an
//! unknown radius the fit still gives K, W and μ, and E*, w follow for a
//! given R. Levenberg–Marquardt on (ln K, ln W, u_c) with a
//! central-difference Jacobian; standard errors from
//! `s²(JᵀJ)⁻¹`, `s² = SSR/(n − p)`.
//!
//! # References
//!
//! * K. Levenberg (1944), Q. Appl. Math. 2, 164–168; D. W. Marquardt (1963),
//!   J. SIAM 11, 431–441.
//! * J. Orear (1982), Least squares when both variables have uncertainties,
//!   Am. J. Phys. 50, 912–916, [doi:10.1119/1.12972](https://doi.org/10.1119/1.12972).
//! * H.-J. Butt, B. Cappella, M. Kappl (2005), Force measurements with the
//!   atomic force microscope, Surf. Sci. Rep. 59, 1–152,
//!   [doi:10.1016/j.surfrep.2005.08.003](https://doi.org/10.1016/j.surfrep.2005.08.003)
//!   (tip–sample separation from piezo travel and deflection, §2.2).

use super::lj::ScaledTable;
use crate::contact::{Control, Dmt, Hertz, Jkr, MaugisDugdale, NormalContact, TabulatedLaw};
use crate::error::{Error, Result};
use serde::Serialize;
use std::f64::consts::PI;
use std::sync::Arc;

/// A contact law the analysis fits, cheapest first.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AfmModel {
    /// [`Hertz`]: no adhesion; parameter E*.
    Hertz,
    /// [`Dmt`]: Hertz plus the constant force 2πwR.
    Dmt,
    /// [`Jkr`]: Johnson–Kendall–Roberts.
    Jkr,
    /// [`MaugisDugdale`] with the Lennard-Jones theoretical stress
    /// (λ = 1.157 μ, [`MaugisDugdale::from_tabor`]).
    MaugisDugdale,
    /// The numerical Lennard-Jones sphere ([`crate::contact::lj_sphere`])
    /// through its [`TabulatedLaw`] (module `afm::lj`): one table per
    /// Tabor parameter, the dearest fit.
    #[serde(rename = "lj")]
    LennardJones,
}

impl AfmModel {
    /// Every model, cheapest first (the advisor's order).
    pub const ALL: [AfmModel; 5] = [
        AfmModel::Hertz,
        AfmModel::Dmt,
        AfmModel::Jkr,
        AfmModel::MaugisDugdale,
        AfmModel::LennardJones,
    ];

    /// The name used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            AfmModel::Hertz => "hertz",
            AfmModel::Dmt => "dmt",
            AfmModel::Jkr => "jkr",
            AfmModel::MaugisDugdale => "maugis_dugdale",
            AfmModel::LennardJones => "lj",
        }
    }

    /// The model named `name` (as [`AfmModel::name`]).
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.name() == name)
    }

    /// Integer code of the C ABI (`ASPERITY_AFM_MODEL_*`, 1-based; 0 is auto).
    pub fn code(self) -> i32 {
        match self {
            AfmModel::Hertz => 1,
            AfmModel::Dmt => 2,
            AfmModel::Jkr => 3,
            AfmModel::MaugisDugdale => 4,
            AfmModel::LennardJones => 5,
        }
    }

    /// The model of a C code (1..=5).
    pub fn from_code(code: i32) -> Option<Self> {
        Self::ALL.into_iter().find(|m| m.code() == code)
    }

    fn adhesive(self) -> bool {
        self != AfmModel::Hertz
    }

    /// The law for `K = E*√R` (Pa·m^½) and `W = wR` (J/m), built with
    /// radius `r` (m). The Lennard-Jones sphere builds its table (about
    /// 0.1–0.35 s optimised).
    pub(crate) fn law(self, r: f64, k: f64, w: f64, z0: f64) -> Result<Box<dyn NormalContact>> {
        let e = k / r.sqrt();
        let wa = w / r;
        Ok(match self {
            AfmModel::Hertz => Box::new(Hertz::new(r, e)?),
            AfmModel::Dmt => Box::new(Dmt::new(r, e, wa)?),
            AfmModel::Jkr => Box::new(Jkr::new(r, e, wa)?),
            AfmModel::MaugisDugdale => Box::new(MaugisDugdale::from_tabor(r, e, wa, z0)?),
            AfmModel::LennardJones => {
                let mu = (w * w / (k * k * z0.powi(3))).cbrt();
                let mu = crate::error::check::in_range(
                    "tabor_parameter",
                    mu,
                    0.0,
                    100.0,
                    "in [0, 100] (the Lennard-Jones sphere's range)",
                )?;
                Box::new(ScaledTable {
                    table: super::lj::unit_table(mu)?,
                    force: w,
                    length: z0,
                    radius: (r * z0).sqrt(),
                })
            }
        })
    }
}

/// Overlap δ (m) of `law` at force `f` (N) on its stable branch, the
/// pull-off overlap below its load-controlled pull-off `p_c`.
pub(crate) fn overlap_at(law: &dyn NormalContact, p_c: f64, f: f64) -> Result<f64> {
    let f = if f <= p_c { p_c * (1.0 - 1e-9) } else { f };
    Ok(law.eval_at_load(f)?.delta)
}

/// The effective-variance residual (N) of one point (module docs): the
/// position misfit `g = u_c + δ(F) − y` times the stiffness of lever and
/// contact in series, `S = k s/(k + s)` (s = dF/dδ of the law at F);
/// `F − p_c` below the law's pull-off `p_c`.
pub(crate) fn residual_at(
    law: &dyn NormalContact,
    p_c: f64,
    k: f64,
    u_c: f64,
    f: f64,
    y: f64,
) -> Option<f64> {
    if f <= p_c {
        return Some(f - p_c);
    }
    let r = law.eval_at_load(f).ok()?;
    let s = r.stiffness.max(0.0);
    let series = if s.is_finite() { k * s / (k + s) } else { k };
    Some((u_c + r.delta - y) * series)
}

/// One fitted model. With an unknown radius, `e_star` and
/// `work_of_adhesion` are `None` and the products are the result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ModelFit {
    /// The model name ([`AfmModel::name`]).
    pub model: &'static str,
    /// Contact modulus E* (Pa) for the given tip radius.
    pub e_star: Option<f64>,
    /// Standard error of E* (Pa).
    pub e_star_stderr: Option<f64>,
    /// E*√R (Pa·m^½), known without the radius.
    pub e_star_times_sqrt_radius: f64,
    /// Standard error of E*√R.
    pub e_star_times_sqrt_radius_stderr: Option<f64>,
    /// Work of adhesion w (J/m²) for the given tip radius (adhesive models).
    pub work_of_adhesion: Option<f64>,
    /// Standard error of w (J/m²).
    pub work_of_adhesion_stderr: Option<f64>,
    /// w·R (J/m), known without the radius (adhesive models).
    pub work_of_adhesion_times_radius: Option<f64>,
    /// Standard error of w·R (J/m).
    pub work_of_adhesion_times_radius_stderr: Option<f64>,
    /// Tabor parameter μ = (Rw²/(E*²z₀³))^{1/3} of the fit (adhesive models).
    pub tabor_parameter: Option<f64>,
    /// The model's load-controlled pull-off force (N).
    pub pull_off_force: f64,
    /// Position (m, the file's coordinate) of zero overlap, u_c.
    pub zero_overlap_position: f64,
    /// Standard error of that position (m).
    pub zero_overlap_position_stderr: Option<f64>,
    /// Root-mean-square effective-variance residual (N): the misfit along
    /// the position axis times the stiffness of lever and contact in series.
    pub rms_residual: f64,
    /// Points fitted.
    pub points: usize,
    /// Levenberg–Marquardt iterations of the best start.
    pub iterations: usize,
    /// Whether the iteration met its tolerance.
    pub converged: bool,
    /// The model.
    #[serde(skip)]
    pub kind: Option<AfmModel>,
    /// K = E*√R of the fit with radius `fit_radius` (internal units).
    #[serde(skip)]
    pub(crate) k: f64,
    /// W = wR.
    #[serde(skip)]
    pub(crate) w: f64,
    /// u_c in travel coordinates.
    #[serde(skip)]
    pub(crate) u_c: f64,
    /// The Lennard-Jones fit's unit table (at its μ).
    #[serde(skip)]
    pub(crate) table: Option<SharedTable>,
}

/// A shared table; equal when it is the same table.
#[derive(Debug, Clone)]
pub(crate) struct SharedTable(pub Arc<TabulatedLaw>);

impl PartialEq for SharedTable {
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

impl ModelFit {
    /// The fitted law, built with radius `r` (m; 1 when unknown: only
    /// forces and overlaps are meaningful then) and z₀ (m).
    pub(crate) fn law(&self, r: f64, z0: f64) -> Result<Box<dyn NormalContact>> {
        match (&self.table, self.kind) {
            (Some(t), _) => Ok(Box::new(ScaledTable {
                table: t.0.clone(),
                force: self.w,
                length: z0,
                radius: (r * z0).sqrt(),
            })),
            (None, Some(m)) => m.law(r, self.k, self.w, z0),
            (None, None) => Err(Error::InvalidArgument {
                name: "fit",
                value: 0.0,
                bound: "a fit made by analyze",
            }),
        }
    }
}

/// Reference scales of a fit's data (θ is O(1) in them).
pub(crate) struct Scales {
    /// Tip position at the pull-off (the last point), m.
    pub y_ref: f64,
    /// Span of the tip positions, m.
    pub len: f64,
    /// Force span, N (the residuals' unit).
    pub df: f64,
    /// Position span from the pull-off to the maximum, m.
    pub dy: f64,
    /// The smallest force (N).
    pub f_po: f64,
}

impl Scales {
    pub(crate) fn of(d: &FitData) -> Self {
        let (i_min, i_max) = extremes(d.force);
        let y_ref = d.tip[i_min];
        let (ylo, yhi) = d
            .tip
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &y| {
                (a.min(y), b.max(y))
            });
        let len = (yhi - ylo).max(1e-13);
        let f_po = d.force[i_min];
        let df = (d.force[i_max] - f_po).max(1e-300);
        let dy = (d.tip[i_max] - y_ref).max(0.05 * len);
        Self {
            y_ref,
            len,
            df,
            dy,
            f_po,
        }
    }
}

/// The data of a fit: corrected force (N) and tip position y = u − F/k (m).
pub(crate) struct FitData<'a> {
    pub force: &'a [f64],
    pub tip: &'a [f64],
    /// z₀ of the Maugis–Dugdale stress and the Tabor parameter (m).
    pub z0: f64,
    /// Tip radius (m), or `None`.
    pub radius: Option<f64>,
    /// Sign s with u = s·position.
    pub direction: f64,
    /// Spring constant k (N/m).
    pub spring_constant: f64,
    /// The measured pull-off force (N) when it is significant: one more
    /// residual, `F_po − p_c`, ties the law's load-controlled pull-off to it
    /// (a soft lever separates at the minimum force).
    pub pull_off: Option<f64>,
}

/// Fit `model` to the data.
pub(crate) fn fit(model: AfmModel, d: &FitData) -> Result<ModelFit> {
    let n = d.force.len();
    let p = if model.adhesive() { 3 } else { 2 };
    if n < p + 2 {
        return Err(Error::InvalidArgument {
            name: "retract curve",
            value: n as f64,
            bound: "at least p + 2 points between the maximum force and the pull-off",
        });
    }
    let r = d.radius.unwrap_or(1.0);
    // Reference: the last point (the pull-off), the length unit L.
    let Scales {
        y_ref,
        len,
        df,
        dy,
        f_po,
    } = Scales::of(d);
    let k0 = 0.75 * df / dy.powf(1.5);
    let w0 = match model {
        AfmModel::Hertz => 0.0,
        AfmModel::Dmt => (-f_po / (2.0 * PI)).max(1e-6 * df / PI),
        AfmModel::Jkr => (-f_po / (1.5 * PI)).max(1e-6 * df / PI),
        AfmModel::MaugisDugdale => (-f_po / (1.75 * PI)).max(1e-6 * df / PI),
        AfmModel::LennardJones => {
            return Err(Error::InvalidArgument {
                name: "model",
                value: model.code() as f64,
                bound: "a closed-form law (the Lennard-Jones sphere is fitted by fit_lj)",
            })
        }
    };
    let fs = df;
    let kl = d.spring_constant;
    let residual = |th: &[f64], out: &mut [f64]| -> Option<()> {
        let k = k0 * th[0].exp();
        let w = if p == 3 { w0 * th[1].exp() } else { 0.0 };
        let uc = y_ref + len * th[p - 1];
        let law = model.law(r, k, w, d.z0).ok()?;
        let pc = law.pull_off_force(Control::Load).ok()?;
        for ((o, &f), &y) in out.iter_mut().zip(d.force).zip(d.tip) {
            let v = residual_at(law.as_ref(), pc, kl, uc, f, y)? / fs;
            if !v.is_finite() {
                return None;
            }
            *o = v;
        }
        if let Some(po) = d.pull_off {
            out[n] = (po - pc) / fs;
        }
        Some(())
    };
    let m = n + usize::from(d.pull_off.is_some());
    let mut best: Option<Lm> = None;
    for s in [0.0, -2.3, 2.3] {
        let mut th0 = vec![s; p];
        if p == 3 {
            th0[1] = 0.0;
        }
        th0[p - 1] = 0.0;
        if let Some(res) = levenberg_marquardt(&residual, th0, m) {
            if best.as_ref().map_or(true, |b| res.ssr < b.ssr) {
                best = Some(res);
            }
        }
    }
    let b = best.ok_or(Error::NotConverged {
        what: "AFM contact-law fit",
        iterations: 0,
        residual: f64::NAN,
    })?;
    let th = &b.theta;
    let k = k0 * th[0].exp();
    let w = if p == 3 { w0 * th[1].exp() } else { 0.0 };
    let uc = y_ref + len * th[p - 1];
    let dof = (m - p) as f64;
    let s2 = b.ssr / dof;
    let se = |i: usize| -> Option<f64> {
        b.cov
            .as_ref()
            .map(|c| (s2 * c[i * p + i]).sqrt())
            .filter(|v| v.is_finite())
    };
    let se_k = se(0).map(|s| s * k);
    let se_w = if p == 3 { se(1).map(|s| s * w) } else { None };
    let se_uc = se(p - 1).map(|s| s * len);
    let law = model.law(r, k, w, d.z0)?;
    finish(
        model,
        d,
        Solved {
            k,
            w,
            u_c: uc,
            se_k,
            se_w,
            se_uc,
            rms: fs * (b.ssr / m as f64).sqrt(),
            iterations: b.iterations,
            converged: b.converged,
            law,
            table: None,
        },
    )
}

/// Fit the numerical Lennard-Jones sphere (module [`super::lj`]), its
/// search in μ starting at `mu_start` (the Maugis–Dugdale fit's).
pub(crate) fn fit_lj(d: &FitData, mu_start: f64) -> Result<ModelFit> {
    let f = super::lj::fit(d, mu_start)?;
    let m = d.force.len() + usize::from(d.pull_off.is_some());
    let df = Scales::of(d).df;
    let k = f.w / (f.mu.powf(1.5) * d.z0.powf(1.5));
    let r = d.radius.unwrap_or(1.0);
    let law = Box::new(ScaledTable {
        table: f.table.clone(),
        force: f.w,
        length: d.z0,
        radius: (r * d.z0).sqrt(),
    });
    finish(
        AfmModel::LennardJones,
        d,
        Solved {
            k,
            w: f.w,
            u_c: f.u_c,
            se_k: f.se_ln_k.map(|s| s * k),
            se_w: f.se_ln_w.map(|s| s * f.w),
            se_uc: f.se_uc,
            rms: df * (f.ssr / m as f64).sqrt(),
            iterations: f.iterations,
            converged: f.converged,
            law,
            table: Some(SharedTable(f.table)),
        },
    )
}

/// A fit's solution in K, W, u_c with its standard errors.
struct Solved {
    k: f64,
    w: f64,
    u_c: f64,
    se_k: Option<f64>,
    se_w: Option<f64>,
    se_uc: Option<f64>,
    rms: f64,
    iterations: usize,
    converged: bool,
    law: Box<dyn NormalContact>,
    table: Option<SharedTable>,
}

/// The reported fit of a solution.
fn finish(model: AfmModel, d: &FitData, s: Solved) -> Result<ModelFit> {
    let Solved {
        k,
        w,
        u_c: uc,
        se_k,
        se_w,
        se_uc,
        ..
    } = s;
    let r = d.radius.unwrap_or(1.0);
    let pull_off = s.law.pull_off_force(Control::Load)?;
    let known = d.radius.is_some();
    let adhesive = model.adhesive();
    let tabor = if adhesive {
        let mu = (w * w / (k * k * d.z0.powi(3))).cbrt();
        mu.is_finite().then_some(mu)
    } else {
        None
    };
    Ok(ModelFit {
        model: model.name(),
        e_star: known.then(|| k / r.sqrt()),
        e_star_stderr: if known {
            se_k.map(|s| s / r.sqrt())
        } else {
            None
        },
        e_star_times_sqrt_radius: k,
        e_star_times_sqrt_radius_stderr: se_k,
        work_of_adhesion: (known && adhesive).then(|| w / r),
        work_of_adhesion_stderr: if known { se_w.map(|s| s / r) } else { None },
        work_of_adhesion_times_radius: adhesive.then_some(w),
        work_of_adhesion_times_radius_stderr: se_w,
        tabor_parameter: tabor,
        pull_off_force: pull_off,
        zero_overlap_position: d.direction * uc,
        zero_overlap_position_stderr: se_uc,
        rms_residual: s.rms,
        points: d.force.len(),
        iterations: s.iterations,
        converged: s.converged,
        kind: Some(model),
        k,
        w,
        u_c: uc,
        table: s.table,
    })
}

/// Indices of the smallest and largest value.
pub(crate) fn extremes(v: &[f64]) -> (usize, usize) {
    let mut lo = 0;
    let mut hi = 0;
    for (i, &x) in v.iter().enumerate() {
        if x < v[lo] {
            lo = i;
        }
        if x > v[hi] {
            hi = i;
        }
    }
    (lo, hi)
}

/// The result of a Levenberg–Marquardt run.
pub(super) struct Lm {
    pub theta: Vec<f64>,
    pub ssr: f64,
    /// (JᵀJ)⁻¹ at the solution, row-major, `None` when singular.
    pub cov: Option<Vec<f64>>,
    pub iterations: usize,
    pub converged: bool,
}

/// Levenberg–Marquardt with Marquardt's diagonal scaling on a residual
/// `r(θ)` of length `n` (`None` where the model is undefined); central
/// differences with step 1e-6 (θ is O(1) by construction).
/// A residual function: fills its second argument, `None` where undefined.
pub(super) type Residual<'a> = dyn Fn(&[f64], &mut [f64]) -> Option<()> + 'a;

pub(super) fn levenberg_marquardt(r: &Residual, mut th: Vec<f64>, n: usize) -> Option<Lm> {
    let p = th.len();
    let mut res = vec![0.0; n];
    r(&th, &mut res)?;
    let mut ssr: f64 = res.iter().map(|v| v * v).sum();
    let mut lambda = 1e-3;
    let mut jac = vec![0.0; n * p];
    let mut rp = vec![0.0; n];
    let mut rm = vec![0.0; n];
    let mut trial = vec![0.0; n];
    let mut converged = false;
    let mut it = 0;
    let jacobian = |th: &[f64], jac: &mut [f64], rp: &mut [f64], rm: &mut [f64]| -> Option<()> {
        let h = 1e-6;
        for j in 0..p {
            let mut t = th.to_vec();
            t[j] += h;
            r(&t, rp)?;
            t[j] -= 2.0 * h;
            r(&t, rm)?;
            for i in 0..n {
                jac[i * p + j] = (rp[i] - rm[i]) / (2.0 * h);
            }
        }
        Some(())
    };
    while it < 200 {
        it += 1;
        jacobian(&th, &mut jac, &mut rp, &mut rm)?;
        let (jtj, g) = normal_equations(&jac, &res, n, p);
        let mut accepted = false;
        while lambda < 1e12 {
            let mut a = jtj.clone();
            for j in 0..p {
                a[j * p + j] += lambda * jtj[j * p + j].max(1e-12);
            }
            let Some(step) = solve(&a, &g.iter().map(|v| -v).collect::<Vec<_>>(), p) else {
                lambda *= 10.0;
                continue;
            };
            let t: Vec<f64> = th.iter().zip(&step).map(|(a, b)| a + b).collect();
            if t.iter().any(|v| !v.is_finite() || v.abs() > 60.0) {
                lambda *= 10.0;
                continue;
            }
            if r(&t, &mut trial).is_some() {
                let s: f64 = trial.iter().map(|v| v * v).sum();
                if s <= ssr {
                    let small =
                        step.iter().all(|v| v.abs() < 1e-9) || (ssr - s) <= 1e-12 * ssr.max(1e-300);
                    th = t;
                    res.copy_from_slice(&trial);
                    ssr = s;
                    lambda = (lambda / 10.0).max(1e-12);
                    accepted = true;
                    if small {
                        converged = true;
                    }
                    break;
                }
            }
            lambda *= 10.0;
        }
        if !accepted {
            // No step lowers the sum: a (local) minimum to rounding.
            converged = true;
            break;
        }
        if converged {
            break;
        }
    }
    let cov = jacobian(&th, &mut jac, &mut rp, &mut rm).and_then(|_| {
        let (jtj, _) = normal_equations(&jac, &res, n, p);
        invert(&jtj, p)
    });
    Some(Lm {
        theta: th,
        ssr,
        cov,
        iterations: it,
        converged,
    })
}

pub(super) fn normal_equations(
    jac: &[f64],
    res: &[f64],
    n: usize,
    p: usize,
) -> (Vec<f64>, Vec<f64>) {
    let mut jtj = vec![0.0; p * p];
    let mut g = vec![0.0; p];
    for i in 0..n {
        let row = &jac[i * p..(i + 1) * p];
        for a in 0..p {
            g[a] += row[a] * res[i];
            for b in 0..p {
                jtj[a * p + b] += row[a] * row[b];
            }
        }
    }
    (jtj, g)
}

/// Solve the p×p system `a x = b` (Gaussian elimination, partial pivoting);
/// `None` when singular to rounding.
fn solve(a: &[f64], b: &[f64], p: usize) -> Option<Vec<f64>> {
    let mut m = a.to_vec();
    let mut x = b.to_vec();
    let scale = (0..p).map(|i| a[i * p + i].abs()).fold(0.0, f64::max);
    if !(scale > 0.0 && scale.is_finite()) {
        return None;
    }
    for c in 0..p {
        let piv = (c..p).max_by(|&i, &j| m[i * p + c].abs().total_cmp(&m[j * p + c].abs()))?;
        if m[piv * p + c].abs() <= 1e-15 * scale {
            return None;
        }
        if piv != c {
            for k in 0..p {
                m.swap(piv * p + k, c * p + k);
            }
            x.swap(piv, c);
        }
        for i in c + 1..p {
            let f = m[i * p + c] / m[c * p + c];
            for k in c..p {
                m[i * p + k] -= f * m[c * p + k];
            }
            x[i] -= f * x[c];
        }
    }
    for c in (0..p).rev() {
        let mut s = x[c];
        for k in c + 1..p {
            s -= m[c * p + k] * x[k];
        }
        x[c] = s / m[c * p + c];
    }
    Some(x)
}

/// The inverse of a p×p matrix, column by column.
pub(super) fn invert(a: &[f64], p: usize) -> Option<Vec<f64>> {
    let mut inv = vec![0.0; p * p];
    for c in 0..p {
        let mut e = vec![0.0; p];
        e[c] = 1.0;
        let x = solve(a, &e, p)?;
        for r in 0..p {
            inv[r * p + c] = x[r];
        }
    }
    Some(inv)
}
