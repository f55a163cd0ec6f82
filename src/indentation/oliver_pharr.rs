//! The Oliver & Pharr (1992) method: unloading stiffness, contact depth, area,
//! reduced modulus and hardness from the unloading branch, and the sample
//! modulus that follows (2-15).

use super::fit::{fit_unloading, UnloadingFit};
use super::hardness::sample_modulus;
use super::indenter::AreaFunction;
use super::options::IndentationOptions;
use crate::error::{check, Error, Result};
use serde::Serialize;

/// Options of the Oliver–Pharr evaluation.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OliverPharrOptions {
    /// Area function A(h_c).
    pub area: AreaFunction,
    /// ε of `h_c = h_max − ε P_max/S` (0.75 for a paraboloid of revolution,
    /// the usual choice for Berkovich tips).
    pub epsilon: f64,
    /// β of `E_r = (√π/2) S/(β√A)`.
    pub beta: f64,
    /// Load window of the unloading fit, as fractions of P_max.
    pub window: [f64; 2],
}

/// The Oliver–Pharr evaluation of one unloading branch.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct OliverPharr {
    /// The power-law fit of the unloading branch.
    pub fit: UnloadingFit,
    /// Peak load P_max (N) at the start of unloading.
    pub peak_load: f64,
    /// Depth h_max (m) at the start of unloading.
    pub peak_depth: f64,
    /// Unloading stiffness S = dP/dh at h_max (N/m).
    pub stiffness: f64,
    /// Standard error of S (N/m).
    pub stiffness_stderr: f64,
    /// Contact depth h_c (m).
    pub contact_depth: f64,
    /// Standard error of h_c (m).
    pub contact_depth_stderr: f64,
    /// Projected contact area A(h_c) (m²).
    pub contact_area: f64,
    /// Reduced modulus E_r = (√π/2) S/(β√A) (Pa).
    pub reduced_modulus: f64,
    /// Standard error of E_r (Pa).
    pub reduced_modulus_stderr: f64,
    /// The BASh value (β = 1), (2-14) (Pa).
    pub reduced_modulus_bash: f64,
    /// Hardness H = P_max/A (Pa).
    pub hardness: f64,
    /// Standard error of H (Pa).
    pub hardness_stderr: f64,
    /// Bluntness index of the effective (Galanov) unloading shape,
    /// d = 1/(m − 1) (κ = 1 in (3-26)).
    pub d_unloading: f64,
    /// Standard error of d_unloading, `se(m)/(m − 1)²`.
    pub d_unloading_stderr: f64,
    /// ε used.
    pub epsilon: f64,
    /// β used.
    pub beta: f64,
}

/// The Oliver & Pharr (1992) method on the unloading branch `(depth, load)`,
/// starting at `(peak_depth, peak_load)`: power-law fit ([`fit_unloading`]),
/// `S = α m (h_max − h_f)^{m−1}`, `h_c = h_max − ε P_max/S`, `A = A(h_c)`,
/// `E_r = (√π/2) S/(β√A)`, `H = P_max/A`, with statistical standard errors.
pub fn oliver_pharr(
    depth: &[f64],
    load: &[f64],
    peak_depth: f64,
    peak_load: f64,
    options: &OliverPharrOptions,
) -> Result<OliverPharr> {
    options.area.validate()?;
    let eps = check::positive("epsilon", options.epsilon)?;
    let beta = check::positive("beta", options.beta)?;
    let fit = fit_unloading(depth, load, peak_depth, peak_load, options.window)?;
    let (hmax, pmax) = fit.scales;
    let derived = |t: &[f64; 3]| -> Option<[f64; 4]> {
        let u = 1.0 - t[1];
        if !(u > 0.0) {
            return None;
        }
        // S in scaled units: α′ m u^{m−1}, times P_max/h_max.
        let s = (t[0]).exp() * t[2] * u.powf(t[2] - 1.0) * pmax / hmax;
        let hc = hmax - eps * pmax / s;
        let a = options.area.area(hc).ok()?;
        let er = core::f64::consts::PI.sqrt() / 2.0 * s / (beta * a.sqrt());
        let hard = pmax / a;
        Some([s, hc, er, hard])
    };
    let v = derived(&fit.theta).ok_or(Error::OutOfDomain {
        name: "contact_depth",
        value: hmax,
        reason: "h_c = h_max - eps P_max/S is not positive or outside the area function",
    })?;
    let se = |k: usize| fit.propagate(|t| derived(t).map(|v| v[k])).unwrap_or(0.0);
    let a = options.area.area(v[1])?;
    let m = fit.exponent;
    let d_unl = if m > 1.0 { 1.0 / (m - 1.0) } else { f64::MAX };
    let d_unl_se = if m > 1.0 {
        fit.exponent_stderr / (m - 1.0).powi(2)
    } else {
        f64::MAX
    };
    Ok(OliverPharr {
        peak_load: pmax,
        peak_depth: hmax,
        stiffness: v[0],
        stiffness_stderr: se(0),
        contact_depth: v[1],
        contact_depth_stderr: se(1),
        contact_area: a,
        reduced_modulus: v[2],
        reduced_modulus_stderr: se(2),
        reduced_modulus_bash: v[2] * beta,
        hardness: v[3],
        hardness_stderr: se(3),
        d_unloading: d_unl,
        d_unloading_stderr: d_unl_se,
        epsilon: eps,
        beta,
        fit,
    })
}

/// The moduli and the hardness of an analysis, all `None` without an
/// Oliver–Pharr evaluation of the unloading branch.
#[derive(Debug, Default)]
pub(super) struct Moduli {
    /// Reduced modulus E_r (Pa).
    pub(super) reduced_modulus: Option<f64>,
    /// Standard error of E_r (Pa).
    pub(super) reduced_modulus_stderr: Option<f64>,
    /// Sample modulus E (Pa), `None` too when E_r is not below the indenter's
    /// plane-strain modulus.
    pub(super) sample_modulus: Option<f64>,
    /// Standard error of E (Pa).
    pub(super) sample_modulus_stderr: Option<f64>,
    /// Hardness H = P_max/A(h_c) (Pa).
    pub(super) hardness: Option<f64>,
    /// Standard error of H (Pa).
    pub(super) hardness_stderr: Option<f64>,
}

impl Moduli {
    /// E_r and H of the evaluation, and the sample modulus from E_r with the
    /// indenter's constants (2-15), its standard error by first-order
    /// propagation.
    pub(super) fn new(unloading: Option<&OliverPharr>, o: &IndentationOptions) -> Self {
        let Some(op) = unloading else {
            return Self::default();
        };
        let es = sample_modulus(op.reduced_modulus, o.nu_sample, o.e_indenter, o.nu_indenter).ok();
        let es_se = es.map(|e| {
            // dE/dE_r = (1 − ν²)/(E_r² den²) = E²/((1 − ν²) E_r²).
            let nu2 = 1.0 - o.nu_sample * o.nu_sample;
            e * e / (nu2 * op.reduced_modulus.powi(2)) * op.reduced_modulus_stderr
        });
        Self {
            reduced_modulus: Some(op.reduced_modulus),
            reduced_modulus_stderr: Some(op.reduced_modulus_stderr),
            sample_modulus: es,
            sample_modulus_stderr: es_se,
            hardness: Some(op.hardness),
            hardness_stderr: Some(op.hardness_stderr),
        }
    }
}
