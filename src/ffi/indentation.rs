//! C ABI for `crate::rescaling` and `crate::indentation`: the rescaling
//! relations, the Galanov radii, slopes ⇄ (κ, d), hardness numbers, and the
//! fit of a measured load–depth curve from plain arrays into a result struct.

use super::{guard, input, output, Failure};
use crate::error::{Error, Result};
use crate::indentation::{
    self, Anchor, AreaFunction, Curve, IndentationOptions, Indenter, Segment, FLAG_CODES,
};
use crate::rescaling::{self, KnownSolution, Rescaling};
use std::ffi::c_char;

/// Segment label: not assigned.
pub const ASPERITY_SEGMENT_UNKNOWN: i32 = 0;
/// Segment label: approach (before contact).
pub const ASPERITY_SEGMENT_APPROACH: i32 = 1;
/// Segment label: loading.
pub const ASPERITY_SEGMENT_LOADING: i32 = 2;
/// Segment label: hold at peak.
pub const ASPERITY_SEGMENT_HOLD: i32 = 3;
/// Segment label: unloading from the peak.
pub const ASPERITY_SEGMENT_UNLOADING: i32 = 4;
/// Segment label: thermal-drift hold.
pub const ASPERITY_SEGMENT_DRIFT_HOLD: i32 = 5;
/// Segment label: final unloading after the drift hold.
pub const ASPERITY_SEGMENT_FINAL_UNLOADING: i32 = 6;

/// Indenter: Berkovich pyramid (ideal area 24.5 h_c², β = 1.034).
pub const ASPERITY_INDENTER_BERKOVICH: i32 = 1;
/// Indenter: Vickers pyramid (ideal area 24.5 h_c², β = 1.012).
pub const ASPERITY_INDENTER_VICKERS: i32 = 2;
/// Indenter: cube corner (ideal area 2.598 h_c², β = 1.034).
pub const ASPERITY_INDENTER_CUBE_CORNER: i32 = 3;
/// Indenter: cone of half-angle `cone_half_angle` (rad), β = 1.
pub const ASPERITY_INDENTER_CONE: i32 = 4;
/// Indenter: sphere of radius `sphere_radius` (m), d = 2, β = 1.
pub const ASPERITY_INDENTER_SPHERE: i32 = 5;
/// Indenter: not documented (Berkovich area and β assumed, flagged).
pub const ASPERITY_INDENTER_UNKNOWN: i32 = 6;

/// Loading-fit anchor: the maximum point of loading (thesis §3.6.1).
pub const ASPERITY_ANCHOR_MAX_POINT: i32 = 0;
/// Loading-fit anchor: the point `anchor_index`.
pub const ASPERITY_ANCHOR_INDEX: i32 = 1;
/// Loading-fit anchor: none (two-parameter regression).
pub const ASPERITY_ANCHOR_FREE: i32 = 2;

/// Flag bit: κ < 0 (outside the rescaling assumptions).
pub const ASPERITY_INDENT_FLAG_KAPPA_NEGATIVE: u32 = 1 << 0;
/// Flag bit: κ > 1 (only densifying or hardening materials).
pub const ASPERITY_INDENT_FLAG_KAPPA_ABOVE_ONE: u32 = 1 << 1;
/// Flag bit: d > 3 (implausibly blunt).
pub const ASPERITY_INDENT_FLAG_D_ABOVE_THREE: u32 = 1 << 2;
/// Flag bit: d < 1 (sharper than a cone).
pub const ASPERITY_INDENT_FLAG_D_BELOW_ONE: u32 = 1 << 3;
/// Flag bit: indenter and specimen both deformable with different κ.
pub const ASPERITY_INDENT_FLAG_BOTH_DEFORMABLE: u32 = 1 << 4;
/// Flag bit: sharp indenter, outside the Hertz assumptions.
pub const ASPERITY_INDENT_FLAG_SHARP_INDENTER: u32 = 1 << 5;
/// Flag bit: no usable unloading branch (no modulus, no hardness).
pub const ASPERITY_INDENT_FLAG_NO_UNLOADING: u32 = 1 << 6;
/// Flag bit: few points in the fits.
pub const ASPERITY_INDENT_FLAG_FEW_POINTS: u32 = 1 << 7;
/// Flag bit: loading branch not a power law (R² < 0.99).
pub const ASPERITY_INDENT_FLAG_POOR_LOADING_FIT: u32 = 1 << 8;
/// Flag bit: unloading branch not a power law (R² < 0.99).
pub const ASPERITY_INDENT_FLAG_POOR_UNLOADING_FIT: u32 = 1 << 9;
/// Flag bit: indenter undocumented, ideal Berkovich area assumed.
pub const ASPERITY_INDENT_FLAG_AREA_FUNCTION_ASSUMED: u32 = 1 << 10;
/// Flag bit: se(κ) > 0.25.
pub const ASPERITY_INDENT_FLAG_KAPPA_POORLY_CONSTRAINED: u32 = 1 << 11;
/// Flag bit: se(d) > d/4.
pub const ASPERITY_INDENT_FLAG_D_POORLY_CONSTRAINED: u32 = 1 << 12;
/// Flag bit: E_r not below the indenter's modulus (no sample modulus).
pub const ASPERITY_INDENT_FLAG_MODULUS_EXCEEDS_INDENTER: u32 = 1 << 13;
/// Flag bit: the unloading stiffness moves by more than its standard error as the fit
/// window's lower bound moves from 0.2 to 0.8 of P_max.
pub const ASPERITY_INDENT_FLAG_WINDOW_DEPENDENT_STIFFNESS: u32 = 1 << 14;

const _: () = assert!(FLAG_CODES.len() == 15);

/// Options of `asperity_indentation_fit`. Fill with
/// `asperity_indentation_default_options` and change what you need.
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct AsperityIndentationOptions {
    /// One of `ASPERITY_INDENTER_*`.
    pub indenter: i32,
    /// One of `ASPERITY_ANCHOR_*`.
    pub anchor: i32,
    /// Nonzero: use the segment labels when given (default 1).
    pub use_labels: i32,
    /// Number of NanoSuite area coefficients in `area_coefficients` (0: the
    /// indenter's ideal area function).
    pub n_area_coefficients: i32,
    /// NanoSuite area coefficients, `A = C0 h_c² + C1 h_c + C2 h_c^{1/2} + …`
    /// with h_c in nm and A in nm².
    pub area_coefficients: [f64; 8],
    /// Sphere radius (m), for `ASPERITY_INDENTER_SPHERE`.
    pub sphere_radius: f64,
    /// Cone half-angle (rad), for `ASPERITY_INDENTER_CONE`.
    pub cone_half_angle: f64,
    /// Nonzero: `known_d` is given (otherwise d is fitted; a sphere's d = 2).
    pub has_known_d: i32,
    /// Nonzero: `known_kappa` is given.
    pub has_known_kappa: i32,
    /// Known bluntness index d.
    pub known_d: f64,
    /// Known hardening index κ.
    pub known_kappa: f64,
    /// Anchor index, for `ASPERITY_ANCHOR_INDEX`.
    pub anchor_index: usize,
    /// Indenter Young's modulus (Pa; default 1141e9, INFINITY for rigid).
    pub e_indenter: f64,
    /// Indenter Poisson's ratio (default 0.07).
    pub nu_indenter: f64,
    /// Sample Poisson's ratio (default 0.3).
    pub nu_sample: f64,
    /// β (0: the indenter's, King 1987: 1.034 Berkovich and cube corner, 1.012 Vickers, 1 axisymmetric).
    pub beta: f64,
    /// ε of the contact depth (default 0.75).
    pub epsilon: f64,
    /// Loading-fit load window, fractions of the anchor load (default 0.1, 1).
    pub loading_window: [f64; 2],
    /// Unloading-fit load window, fractions of P_max (default 0.2, 0.98).
    pub unloading_window: [f64; 2],
}

/// Result of `asperity_indentation_fit` (SI units). Fields that need the
/// unloading branch are 0 when `has_unloading` is 0; `sample_modulus` is 0
/// when `has_sample_modulus` is 0. Never NaN.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct AsperityIndentationResult {
    /// Hardening index κ.
    pub kappa: f64,
    /// Standard error of κ.
    pub kappa_stderr: f64,
    /// Bluntness index d.
    pub d: f64,
    /// Standard error of d.
    pub d_stderr: f64,
    /// Loading log–log slope m_l.
    pub loading_slope: f64,
    /// Standard error of m_l.
    pub loading_slope_stderr: f64,
    /// R² of the loading fit (in ln P).
    pub loading_r_squared: f64,
    /// Unloading exponent m of `P = α(h − h_f)^m`.
    pub unloading_exponent: f64,
    /// Standard error of m.
    pub unloading_exponent_stderr: f64,
    /// Final depth h_f (m).
    pub final_depth: f64,
    /// Standard error of h_f (m).
    pub final_depth_stderr: f64,
    /// R² of the unloading fit (in P).
    pub unloading_r_squared: f64,
    /// Peak load at the start of unloading (N).
    pub peak_load: f64,
    /// Depth at the start of unloading (m).
    pub peak_depth: f64,
    /// Unloading stiffness S (N/m).
    pub stiffness: f64,
    /// Standard error of S (N/m).
    pub stiffness_stderr: f64,
    /// Contact depth h_c (m).
    pub contact_depth: f64,
    /// Projected contact area (m²).
    pub contact_area: f64,
    /// Reduced modulus E_r (Pa), Oliver–Pharr with β.
    pub reduced_modulus: f64,
    /// Standard error of E_r (Pa).
    pub reduced_modulus_stderr: f64,
    /// BASh reduced modulus (β = 1) (Pa).
    pub reduced_modulus_bash: f64,
    /// Sample Young's modulus (Pa).
    pub sample_modulus: f64,
    /// Standard error of the sample modulus (Pa).
    pub sample_modulus_stderr: f64,
    /// Hardness P_max/A (Pa).
    pub hardness: f64,
    /// Standard error of H (Pa).
    pub hardness_stderr: f64,
    /// Points in the loading fit.
    pub n_loading_points: usize,
    /// Points in the unloading fit.
    pub n_unloading_points: usize,
    /// Loading segment `[start, end)`.
    pub loading_range: [usize; 2],
    /// Unloading segment `[start, end)`.
    pub unloading_range: [usize; 2],
    /// `ASPERITY_INDENT_FLAG_*` bits.
    pub flags: u32,
    /// 1 when the unloading branch was analysed.
    pub has_unloading: i32,
    /// 1 when a sample modulus could be computed.
    pub has_sample_modulus: i32,
    /// 1 when the segments came from the labels.
    pub segments_from_labels: i32,
}

/// Fill `options` with the defaults: Berkovich, ideal area, anchor at the
/// maximum point, labels used, diamond indenter (1141 GPa, 0.07), sample
/// ν = 0.3, β by indenter, ε = 0.75, windows 0.1–1 (loading) and 0.2–0.98
/// (unloading).
#[no_mangle]
pub unsafe extern "C" fn asperity_indentation_default_options(
    options: *mut AsperityIndentationOptions,
) -> i32 {
    guard(|| {
        let d = IndentationOptions::default();
        *output(options, "options")? = AsperityIndentationOptions {
            indenter: ASPERITY_INDENTER_BERKOVICH,
            anchor: ASPERITY_ANCHOR_MAX_POINT,
            use_labels: 1,
            n_area_coefficients: 0,
            area_coefficients: [0.0; 8],
            sphere_radius: 0.0,
            cone_half_angle: 0.0,
            has_known_d: 0,
            has_known_kappa: 0,
            known_d: 0.0,
            known_kappa: 0.0,
            anchor_index: 0,
            e_indenter: d.e_indenter,
            nu_indenter: d.nu_indenter,
            nu_sample: d.nu_sample,
            beta: 0.0,
            epsilon: d.epsilon,
            loading_window: d.loading_window,
            unloading_window: d.unloading_window,
        };
        Ok(())
    })
}

fn to_options(c: &AsperityIndentationOptions) -> Result<IndentationOptions> {
    let indenter = match c.indenter {
        ASPERITY_INDENTER_BERKOVICH => Indenter::Berkovich,
        ASPERITY_INDENTER_VICKERS => Indenter::Vickers,
        ASPERITY_INDENTER_CUBE_CORNER => Indenter::CubeCorner,
        ASPERITY_INDENTER_CONE => Indenter::Cone {
            half_angle: c.cone_half_angle,
        },
        ASPERITY_INDENTER_SPHERE => Indenter::Sphere {
            radius: c.sphere_radius,
        },
        ASPERITY_INDENTER_UNKNOWN => Indenter::Unknown,
        k => {
            return Err(Error::UnknownSelector {
                name: "options.indenter",
                value: k as i64,
            })
        }
    };
    let anchor = match c.anchor {
        ASPERITY_ANCHOR_MAX_POINT => Anchor::MaxPoint,
        ASPERITY_ANCHOR_INDEX => Anchor::Index {
            index: c.anchor_index,
        },
        ASPERITY_ANCHOR_FREE => Anchor::Free,
        k => {
            return Err(Error::UnknownSelector {
                name: "options.anchor",
                value: k as i64,
            })
        }
    };
    let area = match c.n_area_coefficients {
        0 => None,
        k @ 1..=8 => Some(AreaFunction::NanoSuite {
            coefficients: c.area_coefficients[..k as usize].to_vec(),
        }),
        k => {
            return Err(Error::InvalidArgument {
                name: "options.n_area_coefficients",
                value: k as f64,
                bound: "in [0, 8]",
            })
        }
    };
    Ok(IndentationOptions {
        indenter,
        area,
        known_d: (c.has_known_d != 0).then_some(c.known_d),
        known_kappa: (c.has_known_kappa != 0).then_some(c.known_kappa),
        e_indenter: c.e_indenter,
        nu_indenter: c.nu_indenter,
        nu_sample: c.nu_sample,
        beta: (c.beta != 0.0).then_some(c.beta),
        epsilon: c.epsilon,
        loading_window: c.loading_window,
        unloading_window: c.unloading_window,
        anchor,
        use_labels: c.use_labels != 0,
    })
}

unsafe fn slice<'a, T>(p: *const T, n: usize, name: &'static str) -> Result<&'a [T]> {
    if p.is_null() {
        return Err(Error::NullPointer { name });
    }
    // SAFETY: the caller provides `n` readable elements at `p`.
    Ok(std::slice::from_raw_parts(p, n))
}

/// Fit a measured load–depth curve: `n` points of `depth` (m) and `load` (N),
/// optional `segments` (`ASPERITY_SEGMENT_*` per point, NULL to detect them),
/// `options` (NULL for the defaults). Writes κ, d with standard errors, the
/// Oliver–Pharr modulus and hardness and the validity flags into `result`
/// (see `indentation::analyze`). Errors: NULL pointers, n < 3, non-finite
/// values, unknown labels or selectors, no loading branch, d or κ not
/// identifiable (`ASPERITY_ERR_OUT_OF_DOMAIN`, with a message).
#[no_mangle]
pub unsafe extern "C" fn asperity_indentation_fit(
    n: usize,
    depth: *const f64,
    load: *const f64,
    segments: *const i32,
    options: *const AsperityIndentationOptions,
    result: *mut AsperityIndentationResult,
) -> i32 {
    guard(|| {
        let out = output(result, "result")?;
        let h = slice(depth, n, "depth")?;
        let p = slice(load, n, "load")?;
        if n < 3 {
            return Err(Error::InvalidArgument {
                name: "n",
                value: n as f64,
                bound: ">= 3",
            }
            .into());
        }
        let mut curve = Curve::new(h.to_vec(), p.to_vec())?;
        if !segments.is_null() {
            let s = slice(segments, n, "segments")?;
            let mut labels = Vec::with_capacity(n);
            for (i, &code) in s.iter().enumerate() {
                labels.push(Segment::from_code(code).ok_or_else(|| {
                    Failure::at(
                        i,
                        Error::UnknownSelector {
                            name: "segments",
                            value: code as i64,
                        },
                    )
                })?);
            }
            curve = curve.with_segments(labels)?;
        }
        let opts = if options.is_null() {
            IndentationOptions::default()
        } else {
            to_options(input(options, "options")?)?
        };
        let r = indentation::analyze(&curve, &opts)?;
        let mut o = AsperityIndentationResult {
            kappa: r.kappa,
            kappa_stderr: r.kappa_stderr,
            d: r.d,
            d_stderr: r.d_stderr,
            loading_slope: r.loading.slope,
            loading_slope_stderr: r.loading.slope_stderr,
            loading_r_squared: r.loading.r_squared,
            n_loading_points: r.loading.n_points,
            loading_range: r.segmentation.loading,
            unloading_range: r.segmentation.unloading,
            flags: r.flag_mask(),
            segments_from_labels: i32::from(r.segmentation.from_labels),
            ..Default::default()
        };
        if let Some(u) = &r.unloading {
            o.has_unloading = 1;
            o.unloading_exponent = u.fit.exponent;
            o.unloading_exponent_stderr = u.fit.exponent_stderr;
            o.final_depth = u.fit.final_depth;
            o.final_depth_stderr = u.fit.final_depth_stderr;
            o.unloading_r_squared = u.fit.r_squared;
            o.n_unloading_points = u.fit.n_points;
            o.peak_load = u.peak_load;
            o.peak_depth = u.peak_depth;
            o.stiffness = u.stiffness;
            o.stiffness_stderr = u.stiffness_stderr;
            o.contact_depth = u.contact_depth;
            o.contact_area = u.contact_area;
            o.reduced_modulus = u.reduced_modulus;
            o.reduced_modulus_stderr = u.reduced_modulus_stderr;
            o.reduced_modulus_bash = u.reduced_modulus_bash;
            o.hardness = u.hardness;
            o.hardness_stderr = u.hardness_stderr;
        }
        if let (Some(e), Some(se)) = (r.sample_modulus, r.sample_modulus_stderr) {
            o.has_sample_modulus = 1;
            o.sample_modulus = e;
            o.sample_modulus_stderr = se;
        }
        *out = o;
        Ok(())
    })
}

/// The code of flag bit `bit` (0-based, e.g. `"kappa_above_one"` for bit 1) as
/// a static NUL-terminated string; NULL for a bit without a flag. Do not free.
#[no_mangle]
pub extern "C" fn asperity_indentation_flag_name(bit: u32) -> *const c_char {
    static NAMES: [&str; 15] = [
        "kappa_negative\0",
        "kappa_above_one\0",
        "d_above_three\0",
        "d_below_one\0",
        "both_deformable\0",
        "sharp_indenter\0",
        "no_unloading\0",
        "few_points\0",
        "poor_loading_fit\0",
        "poor_unloading_fit\0",
        "area_function_assumed\0",
        "kappa_poorly_constrained\0",
        "d_poorly_constrained\0",
        "modulus_exceeds_indenter\0",
        "window_dependent_stiffness\0",
    ];
    NAMES
        .get(bit as usize)
        .map_or(std::ptr::null(), |s| s.as_ptr().cast())
}

// ---------------------------------------------------------------------------
// Rescaling

/// The C names of the Rust API's `known.*` in a rescaling error.
fn known_names(e: Error) -> Error {
    let e = e.renamed("known.load", "known_load");
    let e = e.renamed("known.depth", "known_depth");
    e.renamed("known.radius", "known_radius")
}

/// `KnownSolution::new`, its errors naming the C arguments `known_load`,
/// `known_depth`, `known_radius` (the Rust fields are `load`, `depth`,
/// `radius`, which are other arguments of the C calls).
fn known(load: f64, depth: f64, radius: f64) -> Result<KnownSolution> {
    KnownSolution::new(load, depth, radius).map_err(|e| {
        let e = e.renamed("load", "known_load");
        let e = e.renamed("depth", "known_depth");
        e.renamed("radius", "known_radius")
    })
}

/// Depth (m) at load `load` (N) by Borodich rescaling (3-13):
/// `δ = λ^{(2−κ)/s} (P/P₁)^{d/s} δ₁`, `s = 2 + κ(d − 1)`, from the known point
/// (P₁, δ₁); λ = B/B₁ (spheres R₁/R, cones tan γ₁/tan γ).
#[no_mangle]
pub unsafe extern "C" fn asperity_rescaling_depth(
    kappa: f64,
    d: f64,
    lambda: f64,
    load: f64,
    known_load: f64,
    known_depth: f64,
    depth: *mut f64,
) -> i32 {
    guard(|| {
        let out = output(depth, "depth")?;
        let k = known(known_load, known_depth, 1.0)?;
        *out = Rescaling::new(kappa, d)?
            .depth(lambda, load, &k)
            .map_err(known_names)?;
        Ok(())
    })
}

/// Contact radius (m) at load `load` (N) by rescaling (3-14):
/// `a = λ^{−κ/s} (P/P₁)^{1/s} a₁`.
#[no_mangle]
pub unsafe extern "C" fn asperity_rescaling_radius(
    kappa: f64,
    d: f64,
    lambda: f64,
    load: f64,
    known_load: f64,
    known_radius: f64,
    radius: *mut f64,
) -> i32 {
    guard(|| {
        let out = output(radius, "radius")?;
        let k = known(known_load, 1.0, known_radius)?;
        *out = Rescaling::new(kappa, d)?
            .radius(lambda, load, &k)
            .map_err(known_names)?;
        Ok(())
    })
}

/// Load (N) at depth `depth` (m) by rescaling (3-24):
/// `P = λ^{(κ−2)/d} (δ/δ₁)^{s/d} P₁`.
#[no_mangle]
pub unsafe extern "C" fn asperity_rescaling_load(
    kappa: f64,
    d: f64,
    lambda: f64,
    depth: f64,
    known_load: f64,
    known_depth: f64,
    load: *mut f64,
) -> i32 {
    guard(|| {
        let out = output(load, "load")?;
        let k = known(known_load, known_depth, 1.0)?;
        *out = Rescaling::new(kappa, d)?
            .load(lambda, depth, &k)
            .map_err(known_names)?;
        Ok(())
    })
}

/// λ for spheres, `R₁/R` (3-15).
#[no_mangle]
pub unsafe extern "C" fn asperity_rescaling_lambda_spheres(
    known_radius: f64,
    radius: f64,
    lambda: *mut f64,
) -> i32 {
    guard(|| {
        *output(lambda, "lambda")? = rescaling::lambda_spheres(known_radius, radius)?;
        Ok(())
    })
}

/// λ for cones, `tan γ₁/tan γ` (3-16), half-angles in rad.
#[no_mangle]
pub unsafe extern "C" fn asperity_rescaling_lambda_cones(
    known_half_angle: f64,
    half_angle: f64,
    lambda: *mut f64,
) -> i32 {
    guard(|| {
        *output(lambda, "lambda")? = rescaling::lambda_cones(known_half_angle, half_angle)?;
        Ok(())
    })
}

/// κ from the loading log–log slope and d: `κ = (d m_l − 2)/(d − 1)`
/// ((3-20), (3-26)); out of domain for a cone (d = 1).
#[no_mangle]
pub unsafe extern "C" fn asperity_rescaling_kappa_from_slope(
    loading_slope: f64,
    d: f64,
    kappa: *mut f64,
) -> i32 {
    guard(|| {
        *output(kappa, "kappa")? = rescaling::kappa_from_loading_slope(loading_slope, d)?;
        Ok(())
    })
}

/// d from the elastic unloading slope: `d = 1/(m_u − 1)`, m_u > 1.
#[no_mangle]
pub unsafe extern "C" fn asperity_rescaling_d_from_unloading_slope(
    unloading_slope: f64,
    d: *mut f64,
) -> i32 {
    guard(|| {
        *output(d, "d")? = rescaling::d_from_unloading_slope(unloading_slope)?;
        Ok(())
    })
}

/// d from the loading slope and a known κ: `d = (2 − κ)/(m_l − κ)`.
#[no_mangle]
pub unsafe extern "C" fn asperity_rescaling_d_from_loading_slope(
    loading_slope: f64,
    kappa: f64,
    d: *mut f64,
) -> i32 {
    guard(|| {
        *output(d, "d")? = rescaling::d_from_loading_slope(loading_slope, kappa)?;
        Ok(())
    })
}

/// Galanov effective unloading radius (3-22): `R₂ = R₁ (P₂/P₁)² (δ₁/δ₂)³`.
#[no_mangle]
pub unsafe extern "C" fn asperity_galanov_unloading_radius(
    r1: f64,
    p1: f64,
    delta1: f64,
    p2: f64,
    delta2: f64,
    r2: *mut f64,
) -> i32 {
    guard(|| {
        *output(r2, "r2")? = rescaling::galanov_unloading_radius(r1, p1, delta1, p2, delta2)?;
        Ok(())
    })
}

/// Radius of the deformed medium (3-23): `R_medium = R R₂/(R₂ − R)`, R₂ > R.
#[no_mangle]
pub unsafe extern "C" fn asperity_galanov_medium_radius(
    radius: f64,
    unloading_radius: f64,
    medium_radius: *mut f64,
) -> i32 {
    guard(|| {
        *output(medium_radius, "medium_radius")? =
            rescaling::medium_radius(radius, unloading_radius)?;
        Ok(())
    })
}

// ---------------------------------------------------------------------------
// Hardness numbers

/// Brinell hardness (2-7), `2P/(πD(D − √(D² − d²)))` (Pa).
#[no_mangle]
pub unsafe extern "C" fn asperity_hardness_brinell(
    load: f64,
    ball_diameter: f64,
    imprint_diameter: f64,
    hardness: *mut f64,
) -> i32 {
    guard(|| {
        *output(hardness, "hardness")? =
            indentation::brinell_hardness(load, ball_diameter, imprint_diameter)?;
        Ok(())
    })
}

/// Meyer hardness (2-8), `4P/(πd²)` (Pa).
#[no_mangle]
pub unsafe extern "C" fn asperity_hardness_meyer(
    load: f64,
    imprint_diameter: f64,
    hardness: *mut f64,
) -> i32 {
    guard(|| {
        *output(hardness, "hardness")? = indentation::meyer_hardness(load, imprint_diameter)?;
        Ok(())
    })
}

/// Ludwik hardness (2-10), `4P/(√2 π d²)` (Pa).
#[no_mangle]
pub unsafe extern "C" fn asperity_hardness_ludwik(
    load: f64,
    imprint_diameter: f64,
    hardness: *mut f64,
) -> i32 {
    guard(|| {
        *output(hardness, "hardness")? = indentation::ludwik_hardness(load, imprint_diameter)?;
        Ok(())
    })
}

/// Vickers hardness (2-12), `2P sin 68°/d²` (Pa), mean diagonal d.
#[no_mangle]
pub unsafe extern "C" fn asperity_hardness_vickers(
    load: f64,
    mean_diagonal: f64,
    hardness: *mut f64,
) -> i32 {
    guard(|| {
        *output(hardness, "hardness")? = indentation::vickers_hardness(load, mean_diagonal)?;
        Ok(())
    })
}
