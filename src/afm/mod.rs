//! AFM force–distance curves: baseline, contact point, jump-in, pull-off,
//! adhesion energy, and the library's contact laws fitted to the retract
//! curve.
//!
//! [`analyze`] takes a measured curve ([`AfmCurve`]: piezo position and
//! cantilever force, approach then retract) and
//!
//! 1. fits the **baseline** of each branch, `F_b(z) = offset + slope·(z − z_c)`,
//!    on its free (far) part: a straight line on the farthest 30 % of the
//!    points, extended towards the sample up to the first run of three
//!    points more than 6 noise deviations off it, minus a 5 % margin, and
//!    refitted (the tilt is the slope; z_c the contact point). The retract
//!    baseline is the reported one: the pull-off is measured from it;
//! 2. corrects the forces, `F = F_raw − F_b(z)`, and converts piezo travel u
//!    (towards the sample) and deflection `d = F/k` into the tip position
//!    `y = u − F/k`; the overlap is `δ = y − u_c` and the tip–sample
//!    separation `D = −δ` (Butt, Cappella & Kappl 2005, §2.2);
//! 3. finds the **contact point** on the approach: the first point off the
//!    baseline after a jump-in when there is one (a dip more than 6 noise
//!    deviations below it), otherwise where the approach force crosses the
//!    baseline before rising;
//! 4. measures the **jump-in distance**, the tip's jump `y(after) − y(before)`
//!    from the last free point to the bottom of the dip (m, 0 without
//!    jump-in), the **pull-off force** (the retract minimum, N, negative) and
//!    the **adhesion energy**, the area between the retract curve and its
//!    baseline where the force is attractive around the pull-off,
//!    `U = ∫(−F) du` over the piezo travel (J);
//! 5. fits Hertz, DMT, JKR and Maugis–Dugdale (Lennard-Jones stress) to the
//!    retract curve from its maximum force to the pull-off ([`fit`]: E* and w
//!    with standard errors for a given tip radius, `E*√R` and `wR` without
//!    it), with the Tabor parameter `μ = (Rw²/(E*²z₀³))^{1/3}` that follows;
//!    and the numerical Lennard-Jones sphere through its tabulated law
//!    (module `lj`: a search in μ from the Maugis–Dugdale fit's, one table
//!    per μ, 1–4 s optimised). `auto` (no models given) fits the
//!    Lennard-Jones sphere only when the Maugis–Dugdale fit's λ = 1.157 μ
//!    lies in the transition range 0.1 < λ < 5, where the two laws differ;
//!    elsewhere it lists it in [`AfmAnalysis::skipped_fits`] with the reason;
//! 6. recommends a model the way [`crate::fidelity::advise`] does: among the
//!    fits whose rms residual is within the tolerance (default 10 %) of the
//!    best one's, the cheapest (Hertz, DMT, JKR, Maugis–Dugdale, Lennard-Jones
//!    sphere) that is
//!    consistent with its own Tabor parameter (Johnson & Greenwood 1997: DMT
//!    for λ ≤ 0.1, JKR for λ ≥ 5, λ = 1.157 μ; Maugis–Dugdale and the
//!    Lennard-Jones sphere throughout),
//!    else the cheapest within the tolerance (flagged);
//! 7. raises flags ([`FLAG_CODES`]) for what the data do not support.
//!
//! # Measured curves (`../shared/data/afm`)
//!
//! No tip radius is recorded in either file (the fits give E*√R and wR; E*
//! below is for an assumed R = 20 nm):
//!
//! | file | k (N/m) | baseline at contact (nN) | pull-off (nN) | jump-in (nm) | adhesion energy (J) | recommended |
//! |---|---|---|---|---|---|---|
//! | MFP-3D SiN | 1.1841 | −3.96 | −12.77 | 3.8 | 1.76e-16 | DMT (flagged: μ ≈ 24 favours JKR) |
//! | JPK QI | 35.028 | −180.9 (tilt 7.4e-3 N/m) | −4.6 (within noise) | none | 1.5e-16 | Hertz, E* = 78.6 ± 0.6 MPa |
//!
//! (`asperity afm FILE --json` prints them; README, "`asperity afm FILE`".)
//!
//! # References
//!
//! * H.-J. Butt, B. Cappella, M. Kappl (2005), Surf. Sci. Rep. 59, 1–152,
//!   [doi:10.1016/j.surfrep.2005.08.003](https://doi.org/10.1016/j.surfrep.2005.08.003).
//! * K. L. Johnson, J. A. Greenwood (1997), An adhesion map for the contact
//!   of elastic spheres, J. Colloid Interface Sci. 192, 326–333,
//!   [doi:10.1006/jcis.1997.4984](https://doi.org/10.1006/jcis.1997.4984)
//!   (the ranges of the models in λ).
//! * D. Maugis (1992), J. Colloid Interface Sci. 150, 243–269.
//! * Thesis chapter 1 (1-41)–(1-44) (the adhesive-sphere laws).

pub mod fit;
mod lj;
pub mod read;

pub use fit::{AfmModel, ModelFit};
pub use read::AfmCurve;

use crate::contact::Control;
use crate::error::{check, Error, Result};
use fit::{extremes, FitData};
use serde::Serialize;

/// Options of [`analyze`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AfmOptions {
    /// Tip radius R (m); `None` when unknown (the fits then give E*√R and wR).
    pub tip_radius: Option<f64>,
    /// Spring constant k (N/m), overriding the curve's. When the curve has
    /// one, its forces are rescaled by k/k_curve (same deflection).
    pub spring_constant: Option<f64>,
    /// The models to fit; empty means all of [`AfmModel::ALL`] ("auto").
    pub models: Vec<AfmModel>,
    /// Equilibrium separation z₀ (m) of the Lennard-Jones law behind the
    /// Maugis–Dugdale stress and the Tabor parameter; default 0.3 nm.
    pub equilibrium_separation: f64,
    /// Relative tolerance on the rms residual for the recommendation
    /// (default 0.1: within 10 % of the best fit).
    pub tolerance: f64,
}

impl Default for AfmOptions {
    fn default() -> Self {
        Self {
            tip_radius: None,
            spring_constant: None,
            models: Vec::new(),
            equilibrium_separation: 0.3e-9,
            tolerance: 0.1,
        }
    }
}

/// A baseline `F_b(z) = offset + slope·(z − reference_position)`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Baseline {
    /// Force of the free cantilever at the reference position (N).
    pub offset: f64,
    /// Tilt dF/dz (N/m) along the file's position axis.
    pub slope: f64,
    /// The reference position (m): the contact point.
    pub reference_position: f64,
    /// Standard deviation of the free part about the line (N).
    pub noise: f64,
    /// Points of the free part.
    pub points: usize,
}

impl Baseline {
    /// The baseline force (N) at position `z` (m).
    pub fn at(&self, z: f64) -> f64 {
        self.offset + self.slope * (z - self.reference_position)
    }
}

/// A validity diagnostic: a stable code and an explanation with numbers.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Flag {
    /// Stable code (see [`FLAG_CODES`]).
    pub code: &'static str,
    /// Explanation.
    pub message: String,
}

/// Every flag code, in the order of the C ABI's bit mask (bit i is
/// `FLAG_CODES[i]`).
pub static FLAG_CODES: [&str; 9] = [
    "radius_unknown",
    "no_jump_in",
    "no_adhesion",
    "short_baseline",
    "baseline_mismatch",
    "e_star_unresolved",
    "fit_failed",
    "model_outside_tabor_range",
    "few_fit_points",
];

/// The result of [`analyze`]. Serialises with the names `asperity afm
/// --json` promises: `pull_off_force`, `jump_in_distance`,
/// `adhesion_energy`, `baseline` (`offset`, `slope`), `contact_point`,
/// `fits` and `recommended_model`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct AfmAnalysis {
    /// Pull-off force (N, negative): the retract minimum below its baseline.
    pub pull_off_force: f64,
    /// Position (m, file axis) of the pull-off.
    pub pull_off_position: f64,
    /// Jump-in distance (m): how far the tip jumps to contact; 0 without one.
    pub jump_in_distance: f64,
    /// Force at the bottom of the jump-in dip (N, below the approach
    /// baseline); 0 without jump-in.
    pub jump_in_force: f64,
    /// Adhesion energy (J): ∫(−F) du over the attractive part of the retract.
    pub adhesion_energy: f64,
    /// The retract baseline (the reference of the pull-off).
    pub baseline: Baseline,
    /// The approach baseline.
    pub approach_baseline: Baseline,
    /// Contact point (m, file axis) on the approach.
    pub contact_point: f64,
    /// Spring constant used (N/m).
    pub spring_constant: f64,
    /// Tip radius used (m), `None` when unknown.
    pub tip_radius: Option<f64>,
    /// Whether E* and w are given (the radius is known); otherwise the
    /// fits give E*√R and wR.
    pub radius_known: bool,
    /// Sign s of the file's position axis: the travel towards the sample
    /// is u = s·z.
    pub direction: f64,
    /// Retract indices fitted: from the maximum force to the pull-off.
    pub fit_range: [usize; 2],
    /// Every fitted model, cheapest first.
    pub fits: Vec<ModelFit>,
    /// The recommended model ([`AfmModel::name`]), `None` when no fit worked.
    pub recommended_model: Option<&'static str>,
    /// Tabor parameter of the recommended fit.
    pub tabor_parameter: Option<f64>,
    /// Flag codes (see [`FLAG_CODES`]).
    pub flags: Vec<&'static str>,
    /// The flags with their explanations.
    pub flag_details: Vec<Flag>,
    /// Models that could not be fitted, with the reason.
    pub failed_fits: Vec<(String, String)>,
    /// Models `auto` did not fit, with the reason (the Lennard-Jones sphere
    /// outside the DMT–JKR transition range).
    pub skipped_fits: Vec<(String, String)>,
    /// The options used.
    pub options: AfmOptions,
}

impl AfmAnalysis {
    /// One JSON object.
    pub fn to_json(&self) -> String {
        crate::report::to_json(self)
    }

    /// The flags as a bit mask, bit i for `FLAG_CODES[i]`.
    pub fn flag_mask(&self) -> u32 {
        crate::report::flag_mask(&self.flags, &FLAG_CODES)
    }

    /// The recommended fit.
    pub fn recommended(&self) -> Option<&ModelFit> {
        let name = self.recommended_model?;
        self.fits.iter().find(|f| f.model == name)
    }

    /// The fitted model's retract curve as raw data would show it: `n`
    /// points (position in m on the file's axis, force in N including the
    /// retract baseline) from the maximum corrected force `f_max` (N) down to
    /// the model's pull-off.
    pub fn model_curve(&self, fit: &ModelFit, f_max: f64, n: usize) -> Result<Vec<(f64, f64)>> {
        let r = self.tip_radius.unwrap_or(1.0);
        let law = fit.law(r, self.options.equilibrium_separation)?;
        let pc = law.pull_off_force(Control::Load)?;
        let n = n.max(2);
        let mut out = Vec::with_capacity(n);
        for i in 0..n {
            let f = f_max + (pc - f_max) * i as f64 / (n - 1) as f64;
            let delta = fit::overlap_at(law.as_ref(), pc, f)?;
            let u = fit.u_c + delta + f / self.spring_constant;
            let z = self.direction * u;
            out.push((z, f + self.baseline.at(z)));
        }
        Ok(out)
    }
}

/// Maugis parameter below which DMT holds and above which JKR holds
/// (Johnson & Greenwood 1997).
const DMT_LAMBDA_MAX: f64 = 0.1;
/// See `DMT_LAMBDA_MAX`.
const JKR_LAMBDA_MIN: f64 = 5.0;

/// Whether a fit's own Maugis parameter λ = 1.157 μ lies in its model's
/// range: DMT for λ ≤ 0.1, JKR for λ ≥ 5, Maugis–Dugdale, the Lennard-Jones
/// sphere and Hertz always
/// (Hertz comes within the tolerance only when adhesion is negligible).
fn in_tabor_range(f: &ModelFit) -> bool {
    let lambda = f
        .tabor_parameter
        .map(|mu| crate::material::maugis_over_tabor() * mu);
    match (f.kind, lambda) {
        (Some(AfmModel::Dmt), Some(l)) => l <= DMT_LAMBDA_MAX,
        (Some(AfmModel::Jkr), Some(l)) => l >= JKR_LAMBDA_MIN,
        (Some(AfmModel::Dmt | AfmModel::Jkr), None) => false,
        _ => true,
    }
}

/// Noise deviations that mark a point off the baseline.
const THRESHOLD: f64 = 6.0;

/// A straight-line fit `f = a + b z`: (a, b, standard deviation).
fn line(z: &[f64], f: &[f64]) -> (f64, f64, f64) {
    let n = z.len() as f64;
    let zm = z.iter().sum::<f64>() / n;
    let fm = f.iter().sum::<f64>() / n;
    let (mut szz, mut szf) = (0.0, 0.0);
    for (&x, &y) in z.iter().zip(f) {
        szz += (x - zm) * (x - zm);
        szf += (x - zm) * (y - fm);
    }
    let b = if szz > 0.0 { szf / szz } else { 0.0 };
    let a = fm - b * zm;
    let ss: f64 = z
        .iter()
        .zip(f)
        .map(|(&x, &y)| (y - a - b * x).powi(2))
        .sum();
    (a, b, (ss / (n - 2.0).max(1.0)).sqrt())
}

/// The free part of a branch whose points run from far to near: the line
/// (a, b, σ) and the number of free points (module docs, step 1).
fn free_part(z: &[f64], f: &[f64]) -> (f64, f64, f64, usize) {
    let n = z.len();
    let (fl, fh) = f
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let floor = 1e-9 * (fh - fl).max(f64::MIN_POSITIVE);
    let mut end = (n * 3 / 10).max(5).min(n);
    let mut fitted = line(&z[..end], &f[..end]);
    for _ in 0..2 {
        let (a, b, s) = fitted;
        let thr = THRESHOLD * s.max(floor);
        let off = |i: usize| (f[i] - a - b * z[i]).abs() > thr;
        let departure = (0..n).find(|&i| (i..(i + 3).min(n)).all(off)).unwrap_or(n);
        let margin = (departure / 20).max(2);
        end = departure.saturating_sub(margin).max(5).min(n);
        fitted = line(&z[..end], &f[..end]);
    }
    (fitted.0, fitted.1, fitted.2, end)
}

/// Analyse a measured force–distance curve (module docs). Errors: invalid
/// curve or options, no spring constant (neither in the curve nor in the
/// options), fewer than 8 points on a side.
pub fn analyze(curve: &AfmCurve, options: &AfmOptions) -> Result<AfmAnalysis> {
    curve.validate()?;
    if let Some(r) = options.tip_radius {
        check::positive("tip_radius", r)?;
    }
    check::positive("equilibrium_separation", options.equilibrium_separation)?;
    check::positive("tolerance", options.tolerance)?;
    let k = match (options.spring_constant, curve.spring_constant) {
        (Some(k), _) => check::positive("spring_constant", k)?,
        (None, Some(k)) => k,
        (None, None) => {
            return Err(Error::InvalidArgument {
                name: "spring_constant",
                value: f64::NAN,
                bound: "given (the curve carries none)",
            })
        }
    };
    let scale = match (options.spring_constant, curve.spring_constant) {
        (Some(k), Some(kc)) => k / kc,
        _ => 1.0,
    };
    let rs = curve.retract_start;
    let z = &curve.position;
    let raw: Vec<f64> = curve.force.iter().map(|f| f * scale).collect();
    let direction = if z[rs - 1] >= z[0] { 1.0 } else { -1.0 };

    // 1. Baselines: approach far→near as stored, retract reversed.
    let (za, fa) = (&z[..rs], &raw[..rs]);
    let zr: Vec<f64> = z[rs..].iter().rev().copied().collect();
    let fr_rev: Vec<f64> = raw[rs..].iter().rev().copied().collect();
    let (aa, ba, sa, na) = free_part(za, fa);
    let (ar, br, sr, nr) = free_part(&zr, &fr_rev);
    let fa: Vec<f64> = za.iter().zip(fa).map(|(&z, &f)| f - aa - ba * z).collect();
    let fr: Vec<f64> = z[rs..]
        .iter()
        .zip(&raw[rs..])
        .map(|(&z, &f)| f - ar - br * z)
        .collect();
    let ua: Vec<f64> = za.iter().map(|&v| direction * v).collect();
    let ur: Vec<f64> = z[rs..].iter().map(|&v| direction * v).collect();

    // 3. Contact point and jump-in on the approach.
    let (_, i_max_a) = extremes(&fa);
    let floor_a = sa.max(1e-12 * fa[i_max_a].abs());
    let dip = (0..=i_max_a)
        .filter(|&i| i + 1 >= na)
        .min_by(|&i, &j| fa[i].total_cmp(&fa[j]));
    let jump = dip.filter(|&i| fa[i] < -THRESHOLD * floor_a && i < i_max_a);
    let (contact_point, jump_in_distance, jump_in_force) = match jump {
        Some(i_min) => {
            let j = (0..i_min)
                .rev()
                .find(|&j| fa[j].abs() <= THRESHOLD * floor_a)
                .unwrap_or(0);
            let y = |i: usize| ua[i] - fa[i] / k;
            (za[(j + 1).min(i_min)], y(i_min) - y(j), fa[i_min])
        }
        None => {
            let c = (0..i_max_a).rev().find(|&i| fa[i] <= 0.0).unwrap_or(0);
            let zc = if c < i_max_a && fa[c + 1] != fa[c] {
                let t = (0.0 - fa[c]) / (fa[c + 1] - fa[c]);
                za[c] + t.clamp(0.0, 1.0) * (za[c + 1] - za[c])
            } else {
                za[c]
            };
            (zc, 0.0, 0.0)
        }
    };

    // 4. Pull-off and adhesion energy on the retract.
    // The contact part: from the start to the free part (nr points at the end).
    let contact_end = (fr.len() - nr.min(fr.len() - 1)).max(1);
    let (i_po, i_max_r) = extremes(&fr[..contact_end]);
    let pull_off_force = fr[i_po];
    let floor_r = sr.max(1e-12 * fr[i_max_r].abs());
    let mut lo = i_po;
    while lo > 0 && fr[lo - 1] < 0.0 {
        lo -= 1;
    }
    let mut hi = i_po;
    while hi + 1 < fr.len() && fr[hi + 1] < 0.0 {
        hi += 1;
    }
    let adhesion_energy = if pull_off_force < 0.0 {
        (lo..hi)
            .map(|i| -0.5 * (fr[i] + fr[i + 1]) * (ur[i] - ur[i + 1]).abs())
            .sum::<f64>()
            .max(0.0)
    } else {
        0.0
    };

    let baseline = Baseline {
        offset: ar + br * contact_point,
        slope: br,
        reference_position: contact_point,
        noise: sr,
        points: nr,
    };
    let approach_baseline = Baseline {
        offset: aa + ba * contact_point,
        slope: ba,
        reference_position: contact_point,
        noise: sa,
        points: na,
    };

    // 5. Fits on the retract from its maximum to the pull-off.
    // Without a significant pull-off, up to the last point above the noise.
    let a0 = i_max_r;
    let a1 = if pull_off_force < -THRESHOLD * floor_r && i_po > a0 {
        i_po
    } else {
        (a0..contact_end)
            .find(|&i| fr[i] <= THRESHOLD * floor_r)
            .unwrap_or(contact_end - 1)
            .max(a0)
    };
    let ff: Vec<f64> = fr[a0..=a1].to_vec();
    let tip: Vec<f64> = (a0..=a1).map(|i| ur[i] - fr[i] / k).collect();
    let data = FitData {
        force: &ff,
        tip: &tip,
        z0: options.equilibrium_separation,
        radius: options.tip_radius,
        direction,
        spring_constant: k,
        pull_off: (pull_off_force < -THRESHOLD * floor_r).then_some(pull_off_force),
    };
    let auto = options.models.is_empty();
    let models: Vec<AfmModel> = AfmModel::ALL
        .into_iter()
        .filter(|m| auto || options.models.contains(m))
        .collect();
    let mut fits: Vec<ModelFit> = Vec::new();
    let mut failed_fits = Vec::new();
    let mut skipped_fits = Vec::new();
    for m in models {
        let result = if m == AfmModel::LennardJones {
            // The search in μ starts at the Maugis–Dugdale fit's μ.
            let md = fits
                .iter()
                .find(|f| f.kind == Some(AfmModel::MaugisDugdale))
                .cloned()
                .or_else(|| fit::fit(AfmModel::MaugisDugdale, &data).ok());
            let mu = md.as_ref().and_then(|f| f.tabor_parameter);
            let lambda = mu.map(|mu| crate::material::maugis_over_tabor() * mu);
            match lambda {
                Some(l) if auto && !(l > DMT_LAMBDA_MAX && l < JKR_LAMBDA_MIN) => {
                    skipped_fits.push((
                        m.name().to_string(),
                        format!(
                            "not fitted by auto: the Maugis–Dugdale fit's λ = {l:.3} lies outside the transition range {DMT_LAMBDA_MAX} < λ < {JKR_LAMBDA_MIN}, where the Lennard-Jones sphere and Maugis–Dugdale agree (ask for --model lj to fit it)"
                        ),
                    ));
                    continue;
                }
                _ => fit::fit_lj(&data, mu.unwrap_or(1.0)),
            }
        } else {
            fit::fit(m, &data)
        };
        match result {
            Ok(f) => fits.push(f),
            Err(e) => failed_fits.push((m.name().to_string(), e.to_string())),
        }
    }
    // 6. The cheapest model within the tolerance of the best residual.
    let best = fits
        .iter()
        .map(|f| f.rms_residual)
        .fold(f64::INFINITY, f64::min);
    let within: Vec<&ModelFit> = fits
        .iter()
        .filter(|f| f.rms_residual <= (1.0 + options.tolerance) * best)
        .collect();
    let chosen = within
        .iter()
        .find(|f| in_tabor_range(f))
        .or(within.first())
        .copied();
    let recommended_model = chosen.map(|f| f.model);
    let tabor_parameter = chosen.and_then(|f| f.tabor_parameter);

    // 7. Flags.
    let mut flag_details = Vec::new();
    let mut raise = |code: &'static str, message: String| flag_details.push(Flag { code, message });
    if options.tip_radius.is_none() {
        raise(
            "radius_unknown",
            "no tip radius: the fits give E*·√R (Pa·m^½) and w·R (J/m), not E* and w".into(),
        );
    }
    if jump.is_none() {
        raise(
            "no_jump_in",
            format!(
                "no dip below the approach baseline by more than {THRESHOLD} noise deviations ({:.3e} N)",
                THRESHOLD * floor_a
            ),
        );
    }
    if pull_off_force > -THRESHOLD * floor_r {
        raise(
            "no_adhesion",
            format!(
                "the retract minimum {pull_off_force:.3e} N is within {THRESHOLD} noise deviations ({:.3e} N) of the baseline",
                THRESHOLD * floor_r
            ),
        );
    }
    if na < 20 || nr < 20 {
        raise(
            "short_baseline",
            format!("free parts of {na} (approach) and {nr} (retract) points; 20 or more expected"),
        );
    }
    let mismatch = approach_baseline.offset - baseline.offset;
    if mismatch.abs() > THRESHOLD * sa.max(sr).max(f64::MIN_POSITIVE) {
        raise(
            "baseline_mismatch",
            format!(
                "approach and retract baselines differ by {mismatch:.3e} N at the contact point (noise {:.3e} N): drag or drift; each branch is corrected by its own",
                sa.max(sr)
            ),
        );
    }
    if let Some(c) = chosen {
        let rel = c
            .e_star_times_sqrt_radius_stderr
            .map(|s| s / c.e_star_times_sqrt_radius);
        if rel.map_or(true, |r| r.is_nan() || r > 0.5) {
            raise(
                "e_star_unresolved",
                format!(
                    "the {} fit leaves E* undetermined (relative standard error {}): the sample's indentation is not resolved against the lever's deflection",
                    c.model,
                    rel.map_or("unknown".into(), |r| format!("{r:.2}"))
                ),
            );
        }
        if let Some(mu) = c.tabor_parameter {
            let lambda = crate::material::maugis_over_tabor() * mu;
            if !in_tabor_range(c) {
                raise(
                    "model_outside_tabor_range",
                    format!(
                        "{} recommended with λ = {lambda:.3} (μ = {mu:.3}, z₀ = {:.2e} m); Johnson & Greenwood (1997) place DMT below λ ≈ 0.1 and JKR above λ ≈ 5",
                        c.model, options.equilibrium_separation
                    ),
                );
            }
        }
    }
    if !failed_fits.is_empty() || fits.iter().any(|f| !f.converged) {
        let names: Vec<String> = failed_fits
            .iter()
            .map(|(m, e)| format!("{m}: {e}"))
            .chain(
                fits.iter()
                    .filter(|f| !f.converged)
                    .map(|f| format!("{}: not converged", f.model)),
            )
            .collect();
        raise("fit_failed", names.join("; "));
    }
    if ff.len() < 10 {
        raise(
            "few_fit_points",
            format!(
                "{} retract points between the maximum and the pull-off",
                ff.len()
            ),
        );
    }
    let flags = flag_details.iter().map(|f| f.code).collect();
    Ok(AfmAnalysis {
        pull_off_force,
        pull_off_position: z[rs + i_po],
        jump_in_distance,
        jump_in_force,
        adhesion_energy,
        baseline,
        approach_baseline,
        contact_point,
        spring_constant: k,
        tip_radius: options.tip_radius,
        radius_known: options.tip_radius.is_some(),
        direction,
        fit_range: [rs + a0, rs + a1],
        fits,
        recommended_model,
        tabor_parameter,
        flags,
        flag_details,
        failed_fits,
        skipped_fits,
        options: options.clone(),
    })
}
