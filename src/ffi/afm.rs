//! C ABI for `crate::afm`: the analysis of a measured AFM force–distance
//! curve from plain arrays into a result struct, flags as bits.

use super::{guard, output};
use crate::afm::{self, AfmCurve, AfmModel, AfmOptions, ModelFit, FLAG_CODES};
use crate::error::{Error, Result};
use std::ffi::c_char;

/// Model selector: fit every model and recommend one.
pub const ASPERITY_AFM_MODEL_AUTO: i32 = 0;
/// Model selector: Hertz.
pub const ASPERITY_AFM_MODEL_HERTZ: i32 = 1;
/// Model selector: DMT.
pub const ASPERITY_AFM_MODEL_DMT: i32 = 2;
/// Model selector: JKR.
pub const ASPERITY_AFM_MODEL_JKR: i32 = 3;
/// Model selector: Maugis–Dugdale with the Lennard-Jones stress.
pub const ASPERITY_AFM_MODEL_MAUGIS_DUGDALE: i32 = 4;
/// Model selector: the numerical Lennard-Jones sphere (tabulated; about
/// 1–4 s a fit). AUTO fits it only when the Maugis–Dugdale fit's
/// λ = 1.157 μ lies between 0.1 and 5.
pub const ASPERITY_AFM_MODEL_LJ: i32 = 5;

/// Input signal: the array holds the cantilever force (N, positive repulsive).
pub const ASPERITY_AFM_INPUT_FORCE: i32 = 0;
/// Input signal: the array holds the deflection (m); force = k · deflection.
pub const ASPERITY_AFM_INPUT_DEFLECTION: i32 = 1;

/// Flag bit: no tip radius; the fits give E*·√R and w·R.
pub const ASPERITY_AFM_FLAG_RADIUS_UNKNOWN: u32 = 1 << 0;
/// Flag bit: no jump-in on the approach.
pub const ASPERITY_AFM_FLAG_NO_JUMP_IN: u32 = 1 << 1;
/// Flag bit: the pull-off is within the noise of the baseline.
pub const ASPERITY_AFM_FLAG_NO_ADHESION: u32 = 1 << 2;
/// Flag bit: a free part shorter than 20 points.
pub const ASPERITY_AFM_FLAG_SHORT_BASELINE: u32 = 1 << 3;
/// Flag bit: approach and retract baselines differ (drag, drift).
pub const ASPERITY_AFM_FLAG_BASELINE_MISMATCH: u32 = 1 << 4;
/// Flag bit: E* of the recommended fit is undetermined (relative standard
/// error above 0.5).
pub const ASPERITY_AFM_FLAG_E_STAR_UNRESOLVED: u32 = 1 << 5;
/// Flag bit: a model could not be fitted or did not converge.
pub const ASPERITY_AFM_FLAG_FIT_FAILED: u32 = 1 << 6;
/// Flag bit: the recommended model lies outside its Tabor range.
pub const ASPERITY_AFM_FLAG_MODEL_OUTSIDE_TABOR_RANGE: u32 = 1 << 7;
/// Flag bit: fewer than 10 retract points fitted.
pub const ASPERITY_AFM_FLAG_FEW_FIT_POINTS: u32 = 1 << 8;

const _: () = assert!(FLAG_CODES.len() == 9);

/// One fitted model (SI units). A quantity that is not determined (E* and
/// w without a radius, w for Hertz, a standard error of a singular fit) is 0.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct AsperityAfmFit {
    /// One of `ASPERITY_AFM_MODEL_*` (never AUTO).
    pub model: i32,
    /// 1 when the least-squares iteration converged.
    pub converged: i32,
    /// Contact modulus E* (Pa), for the given tip radius.
    pub e_star: f64,
    /// Standard error of E* (Pa).
    pub e_star_stderr: f64,
    /// E*·√R (Pa·m^½).
    pub e_star_times_sqrt_radius: f64,
    /// Standard error of E*·√R.
    pub e_star_times_sqrt_radius_stderr: f64,
    /// Work of adhesion w (J/m²), for the given tip radius.
    pub work_of_adhesion: f64,
    /// Standard error of w (J/m²).
    pub work_of_adhesion_stderr: f64,
    /// w·R (J/m).
    pub work_of_adhesion_times_radius: f64,
    /// Standard error of w·R (J/m).
    pub work_of_adhesion_times_radius_stderr: f64,
    /// Tabor parameter μ of the fit (z₀ = 0.3 nm).
    pub tabor_parameter: f64,
    /// The law's load-controlled pull-off force (N).
    pub pull_off_force: f64,
    /// Position of zero overlap (m, on the input's position axis).
    pub zero_overlap_position: f64,
    /// Root-mean-square effective-variance residual (N).
    pub rms_residual: f64,
    /// Points fitted.
    pub points: usize,
}

/// Result of `asperity_afm_analyze` (SI units, never NaN).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct AsperityAfmResult {
    /// Pull-off force (N, negative), from the retract baseline.
    pub pull_off_force: f64,
    /// Position of the pull-off (m).
    pub pull_off_position: f64,
    /// Jump-in distance (m), 0 without jump-in.
    pub jump_in_distance: f64,
    /// Force at the bottom of the jump-in dip (N), 0 without jump-in.
    pub jump_in_force: f64,
    /// Adhesion energy (J): the area of the attractive retract part.
    pub adhesion_energy: f64,
    /// Retract baseline: force (N) at the contact point.
    pub baseline_offset: f64,
    /// Retract baseline: tilt dF/dz (N/m).
    pub baseline_slope: f64,
    /// Retract baseline: noise (N, standard deviation).
    pub baseline_noise: f64,
    /// Approach baseline: force (N) at the contact point.
    pub approach_baseline_offset: f64,
    /// Approach baseline: tilt (N/m).
    pub approach_baseline_slope: f64,
    /// Contact point (m, on the input's position axis).
    pub contact_point: f64,
    /// Spring constant used (N/m).
    pub spring_constant: f64,
    /// +1 when the position grows towards the sample, −1 otherwise.
    pub direction: f64,
    /// Tabor parameter of the recommended fit (0 when none).
    pub tabor_parameter: f64,
    /// First and last index fitted (retract, maximum force to pull-off).
    pub fit_range: [usize; 2],
    /// 1 when a tip radius was given (E*, w filled).
    pub radius_known: i32,
    /// The recommended model (`ASPERITY_AFM_MODEL_*`), 0 when none.
    pub recommended_model: i32,
    /// Its index in `fits`, −1 when none.
    pub recommended_index: i32,
    /// Number of entries of `fits` in use (cheapest model first).
    pub n_fits: i32,
    /// `ASPERITY_AFM_FLAG_*` bits.
    pub flags: u32,
    /// Reserved, 0.
    pub reserved: u32,
    /// The fitted models, cheapest first; `n_fits` are valid. Of five fits
    /// (AUTO with the Lennard-Jones sphere) the four cheapest are kept,
    /// the recommended one always among them.
    pub fits: [AsperityAfmFit; 4],
}

unsafe fn slice<'a>(p: *const f64, n: usize, name: &'static str) -> Result<&'a [f64]> {
    if p.is_null() {
        return Err(Error::NullPointer { name });
    }
    // SAFETY: the caller provides `n` readable doubles at `p`.
    Ok(std::slice::from_raw_parts(p, n))
}

fn fit_of(f: &ModelFit) -> AsperityAfmFit {
    let z = |v: Option<f64>| v.unwrap_or(0.0);
    AsperityAfmFit {
        model: f.kind.map_or(0, AfmModel::code),
        converged: i32::from(f.converged),
        e_star: z(f.e_star),
        e_star_stderr: z(f.e_star_stderr),
        e_star_times_sqrt_radius: f.e_star_times_sqrt_radius,
        e_star_times_sqrt_radius_stderr: z(f.e_star_times_sqrt_radius_stderr),
        work_of_adhesion: z(f.work_of_adhesion),
        work_of_adhesion_stderr: z(f.work_of_adhesion_stderr),
        work_of_adhesion_times_radius: z(f.work_of_adhesion_times_radius),
        work_of_adhesion_times_radius_stderr: z(f.work_of_adhesion_times_radius_stderr),
        tabor_parameter: z(f.tabor_parameter),
        pull_off_force: f.pull_off_force,
        zero_overlap_position: f.zero_overlap_position,
        rms_residual: f.rms_residual,
        points: f.points,
    }
}

/// Analyse an AFM force–distance curve of `n` points: `position` (m, piezo
/// or height sensor, either direction), `signal` (force in N or deflection
/// in m, as `input_kind` says: `ASPERITY_AFM_INPUT_*`), approach first and
/// retract from index `retract_start` (0: split at the turning point);
/// `spring_constant` k (N/m, > 0), `tip_radius` R (m, 0 = unknown: the fits
/// then give E*·√R and w·R), `model` (`ASPERITY_AFM_MODEL_*`, AUTO fits all
/// and recommends one). Writes baselines, contact point, jump-in, pull-off,
/// adhesion energy, the fits and the flags into `result` (see
/// `afm::analyze`). Errors: NULL pointers, n too small (8 points a side),
/// non-finite values, non-positive k, negative radius, unknown selectors.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn asperity_afm_analyze(
    n: usize,
    position: *const f64,
    signal: *const f64,
    input_kind: i32,
    retract_start: usize,
    spring_constant: f64,
    tip_radius: f64,
    model: i32,
    result: *mut AsperityAfmResult,
) -> i32 {
    guard(|| {
        let out = output(result, "result")?;
        let z = slice(position, n, "position")?;
        let s = slice(signal, n, "signal")?;
        let k = crate::error::check::positive("spring_constant", spring_constant)?;
        let force: Vec<f64> = match input_kind {
            ASPERITY_AFM_INPUT_FORCE => s.to_vec(),
            ASPERITY_AFM_INPUT_DEFLECTION => s.iter().map(|d| d * k).collect(),
            other => {
                return Err(Error::UnknownSelector {
                    name: "input_kind",
                    value: other as i64,
                }
                .into())
            }
        };
        let radius = crate::error::check::non_negative("tip_radius", tip_radius)?;
        let models = match model {
            ASPERITY_AFM_MODEL_AUTO => Vec::new(),
            c => vec![AfmModel::from_code(c).ok_or(Error::UnknownSelector {
                name: "model",
                value: c as i64,
            })?],
        };
        let curve = AfmCurve::new(
            z.to_vec(),
            force,
            (retract_start > 0).then_some(retract_start),
            Some(k),
        )?;
        let options = AfmOptions {
            tip_radius: (radius > 0.0).then_some(radius),
            models,
            ..AfmOptions::default()
        };
        let a = afm::analyze(&curve, &options)?;
        let mut o = AsperityAfmResult {
            pull_off_force: a.pull_off_force,
            pull_off_position: a.pull_off_position,
            jump_in_distance: a.jump_in_distance,
            jump_in_force: a.jump_in_force,
            adhesion_energy: a.adhesion_energy,
            baseline_offset: a.baseline.offset,
            baseline_slope: a.baseline.slope,
            baseline_noise: a.baseline.noise,
            approach_baseline_offset: a.approach_baseline.offset,
            approach_baseline_slope: a.approach_baseline.slope,
            contact_point: a.contact_point,
            spring_constant: a.spring_constant,
            direction: a.direction,
            tabor_parameter: a.tabor_parameter.unwrap_or(0.0),
            fit_range: a.fit_range,
            radius_known: i32::from(a.radius_known),
            recommended_model: a
                .recommended()
                .and_then(|f| f.kind)
                .map_or(0, AfmModel::code),
            recommended_index: -1,
            n_fits: a.fits.len().min(4) as i32,
            flags: a.flag_mask(),
            ..Default::default()
        };
        // The four cheapest, the recommended one always kept.
        let mut kept: Vec<&ModelFit> = a.fits.iter().collect();
        while kept.len() > 4 {
            let drop = kept
                .iter()
                .rposition(|f| Some(f.model) != a.recommended_model)
                .unwrap_or(kept.len() - 1);
            kept.remove(drop);
        }
        for (i, f) in kept.into_iter().enumerate() {
            o.fits[i] = fit_of(f);
            if Some(f.model) == a.recommended_model {
                o.recommended_index = i as i32;
            }
        }
        *out = o;
        Ok(())
    })
}

/// The code of AFM flag bit `bit` (0-based, e.g. `"no_jump_in"` for bit 1)
/// as a static NUL-terminated string; NULL for a bit without a flag. Do not
/// free.
#[no_mangle]
pub extern "C" fn asperity_afm_flag_name(bit: u32) -> *const c_char {
    static NAMES: [&str; 9] = [
        "radius_unknown\0",
        "no_jump_in\0",
        "no_adhesion\0",
        "short_baseline\0",
        "baseline_mismatch\0",
        "e_star_unresolved\0",
        "fit_failed\0",
        "model_outside_tabor_range\0",
        "few_fit_points\0",
    ];
    NAMES
        .get(bit as usize)
        .map_or(std::ptr::null(), |s| s.as_ptr().cast())
}
