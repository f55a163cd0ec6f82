//! The validity flags of an analysis (thesis §3.6): stable codes, each with
//! an explanation that gives the numbers.

use super::branches::UnloadingBranch;
use super::fit::PowerLawFit;
use super::indenter::Indenter;
use super::indices::Indices;
use super::oliver_pharr::Moduli;
use super::options::IndentationOptions;
use serde::Serialize;

/// A validity diagnostic (thesis §3.6): a stable code and an explanation.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Flag {
    /// Stable code (see [`FLAG_CODES`]).
    pub code: &'static str,
    /// Explanation with the numbers.
    pub message: String,
}

/// Every flag code [`analyze`](super::analyze) can raise, in the order of the
/// C ABI's bit mask (bit i is `FLAG_CODES[i]`).
pub static FLAG_CODES: [&str; 15] = [
    "kappa_negative",
    "kappa_above_one",
    "d_above_three",
    "d_below_one",
    "both_deformable",
    "sharp_indenter",
    "no_unloading",
    "few_points",
    "poor_loading_fit",
    "poor_unloading_fit",
    "area_function_assumed",
    "kappa_poorly_constrained",
    "d_poorly_constrained",
    "modulus_exceeds_indenter",
    "window_dependent_stiffness",
];

/// The flags of an analysis, in the order of [`FLAG_CODES`].
pub(super) fn raise(
    indices: &Indices,
    moduli: &Moduli,
    loading: &PowerLawFit,
    unloading: &UnloadingBranch,
    o: &IndentationOptions,
) -> Vec<Flag> {
    let Indices {
        kappa,
        kappa_stderr: kappa_se,
        d,
        d_stderr: d_se,
        ..
    } = *indices;
    let er = moduli.reduced_modulus;
    let es = moduli.sample_modulus;
    let unloading_error = unloading.error;
    let unloading_points = unloading.segment_points;
    let sensitivity = &unloading.sensitivity;
    let unloading = &unloading.evaluation;
    let mut flags: Vec<Flag> = Vec::new();
    let mut flag = |code: &'static str, message: String| flags.push(Flag { code, message });
    if kappa < 0.0 {
        flag("kappa_negative", format!("kappa = {kappa:.3} < 0: the loading branch is flatter than any power-law hardening material gives (thesis 3.5, Goldsmith-Lyman); the rescaling assumptions do not hold"));
    }
    if kappa > 1.0 {
        flag("kappa_above_one", format!("kappa = {kappa:.3} > 1: only materials that densify or harden under pressure (fused silica, TiN) behave so (thesis 3.6.2); for others the indenter shape or the assumptions are at fault"));
    }
    if d > 3.0 {
        flag("d_above_three", format!("d = {d:.3} > 3: an implausibly blunt indenter (thesis 3.6.2); the effective unloading shape includes the imprint (Galanov effect)"));
    }
    if d < 1.0 {
        flag(
            "d_below_one",
            format!("d = {d:.3} < 1: sharper than a cone, outside Galin's solution"),
        );
    }
    if let Some(er) = er {
        if o.e_indenter.is_finite() {
            let share = (1.0 - o.nu_indenter.powi(2)) / o.e_indenter * er;
            if share > 0.1 && (kappa - 1.0).abs() > (2.0 * kappa_se).max(0.05) {
                flag("both_deformable", format!("the indenter carries {:.0} % of the contact compliance while the sample has kappa = {kappa:.3} != 1 (the indenter is linear elastic): the rescaling needs identical materials or a rigid indenter (thesis 3.5)", share * 100.0));
            }
        }
    }
    if o.indenter.is_sharp() {
        flag("sharp_indenter", "a pyramid or cone: a sharp indenter is outside the Hertz assumptions of the rescaling theory (thesis 3.6.2); kappa and d from its curve are not reliable without the real tip shape or the hardening index".to_string());
    }
    if unloading.is_none() {
        let why = match unloading_error {
            Some(e) => format!("no usable unloading branch ({e}): no modulus or hardness"),
            None => format!(
                "no unloading branch ({} points): no modulus or hardness",
                unloading_points
            ),
        };
        flag("no_unloading", why);
    }
    let nu_pts = unloading.as_ref().map(|u| u.fit.n_points);
    if loading.n_points < 10 || nu_pts.is_some_and(|k| k < 8) {
        flag(
            "few_points",
            format!(
                "few points in the fits (loading {}, unloading {}): the standard errors are rough",
                loading.n_points,
                nu_pts.unwrap_or(0)
            ),
        );
    }
    if loading.r_squared < 0.99 {
        flag(
            "poor_loading_fit",
            format!(
                "the loading branch is not a power law (R^2 = {:.4})",
                loading.r_squared
            ),
        );
    }
    if let Some(u) = unloading {
        if u.fit.r_squared < 0.99 {
            flag(
                "poor_unloading_fit",
                format!(
                    "the unloading branch is not a power law (R^2 = {:.4})",
                    u.fit.r_squared
                ),
            );
        }
    }
    if o.indenter == Indenter::Unknown && o.area.is_none() {
        flag("area_function_assumed", "indenter not documented: the ideal Berkovich area 24.5 h_c^2 and beta = 1.034 were assumed".to_string());
    }
    if kappa_se > 0.25 {
        flag(
            "kappa_poorly_constrained",
            format!("se(kappa) = {kappa_se:.3}: kappa is not determined by this curve"),
        );
    }
    if d_se > 0.25 * d.abs() {
        flag(
            "d_poorly_constrained",
            format!("se(d) = {d_se:.3} for d = {d:.3}"),
        );
    }
    if unloading.is_some() && es.is_none() {
        flag("modulus_exceeds_indenter", "the reduced modulus is not below the indenter's plane-strain modulus: no sample modulus".to_string());
    }
    if let Some(w) = sensitivity {
        if w.stiffness_spread_in_stderr > 1.0 {
            flag(
                "window_dependent_stiffness",
                format!(
                    "the unloading stiffness moves by {:.1} % ({:.1} of its standard errors) as the fit window's lower bound moves over {}; the modulus by {:.1} %: the window, not the statistics, limits the result",
                    100.0 * w.stiffness_relative_spread,
                    w.stiffness_spread_in_stderr,
                    window_bounds(w),
                    100.0 * w.modulus_relative_spread
                ),
            );
        }
    }
    flags
}

/// "0.2–0.8 of P_max": the range of lower bounds that gave a fit.
fn window_bounds(w: &super::window::WindowSensitivity) -> String {
    match (w.points.first(), w.points.last()) {
        (Some(a), Some(b)) => format!("{}–{} of P_max", a.window[0], b.window[0]),
        _ => "no other window".to_string(),
    }
}
