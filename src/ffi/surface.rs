//! C ABI for `crate::surface`: ISO 4287 parameters of a profile given as an
//! array (with form removal and the Gaussian filter on the way), the
//! material-ratio curve, the PSD, the Hurst fit, peak statistics, the
//! generators writing into caller arrays, and of maps (row-major arrays)
//! the areal Gaussian filter and the radially averaged 2-D PSD.
//!
//! Profiles are plain arrays: `n` heights (m) at a uniform spacing `dx` (m).
//! Input arrays are never written. Functions that write arrays write exactly
//! the number of elements their documentation states, and refuse a length
//! that does not match with `ASPERITY_ERR_INVALID_ARGUMENT` naming it.

use super::{guard, output};
use crate::error::{Error, Result};
use crate::surface::{
    gaussian_filter, hurst_fit, psd_windowed, remove_form, roughness_parameters, CantorBorodich,
    FilterEnds, Form, HurstFit, MaterialRatioCurve, ParameterOptions, PeakStatistics, Profile,
    SelfAffine, WeierstrassMandelbrot, Window,
};

/// Form removal before analysis: none (the heights as given; the mean line
/// is still their mean).
pub const ASPERITY_FORM_NONE: i32 = 0;
/// Form removal: the mean height.
pub const ASPERITY_FORM_MEAN: i32 = 1;
/// Form removal: the least-squares straight line (tilt).
pub const ASPERITY_FORM_LINEAR: i32 = 2;
/// Form removal: the least-squares parabola (tilt and curvature).
pub const ASPERITY_FORM_QUADRATIC: i32 = 3;

/// Gaussian filter ends: drop λc/2 at each end (ISO 4288 run-in/run-out).
pub const ASPERITY_FILTER_ENDS_DISCARD: i32 = 0;
/// Gaussian filter ends: keep every sample, kernel renormalised at the ends
/// (ISO 16610-28).
pub const ASPERITY_FILTER_ENDS_KEEP: i32 = 1;

/// PSD data window: none (rectangular; Parseval exact, m₀ = Rq²).
pub const ASPERITY_WINDOW_RECTANGULAR: i32 = 0;
/// PSD data window: periodic Hann, normalised by its mean square.
pub const ASPERITY_WINDOW_HANN: i32 = 1;

/// ISO 4287 parameters of a profile, its spectral moments and its Hurst
/// exponent, from `asperity_roughness_parameters`. Heights are measured from
/// the mean line of the evaluated profile (after form removal and filtering).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityRoughness {
    /// Maximum profile peak height Rp (m), averaged over sampling lengths.
    pub rp: f64,
    /// Maximum profile valley depth Rv (m).
    pub rv: f64,
    /// Maximum height Rz = Rp + Rv within a sampling length (m).
    pub rz: f64,
    /// Mean height of profile elements Rc (m); meaningful only when `has_rc`
    /// is 1 (0 otherwise).
    pub rc: f64,
    /// Total height Rt over the evaluation length (m); Rt ≥ Rz.
    pub rt: f64,
    /// Arithmetic mean deviation Ra (m).
    pub ra: f64,
    /// Root-mean-square deviation Rq (m), thesis (1-5).
    pub rq: f64,
    /// Skewness Rsk (dimensionless).
    pub rsk: f64,
    /// Kurtosis Rku (dimensionless; 3 for a Gaussian, 1.5 for a sine).
    pub rku: f64,
    /// Mean width of profile elements RSm (m); meaningful only when `has_rsm`
    /// is 1 (0 otherwise).
    pub rsm: f64,
    /// Root-mean-square slope RΔq (dimensionless), seven-point slopes.
    pub rdq: f64,
    /// Hurst exponent H of the power-law fit PSD ∝ q^{−(1+2H)} over the band
    /// chosen from the data; meaningful only when `has_psd_hurst_exponent` is
    /// 1 (0 otherwise: fewer than 128 samples, or no band of one decade where
    /// the spectrum is a power law with 0 ≤ H ≤ 1).
    pub psd_hurst_exponent: f64,
    /// Spectral moment m₀ (m²) of the evaluated profile: the height
    /// variance, Rq² when there is one sampling length.
    pub m0: f64,
    /// Spectral moment m₂ (dimensionless): the slope variance, mean square of
    /// the seven-point slopes of RΔq (from the derivatives, not from a
    /// rectangular-window PSD, whose m₂ measures the jump between the ends).
    pub m2: f64,
    /// Spectral moment m₄ (m⁻²): the curvature variance, mean square of the
    /// three-point second differences.
    pub m4: f64,
    /// Nayak's bandwidth parameter α = m₀m₄/m₂² (dimensionless).
    pub nayak_alpha: f64,
    /// Sampling length used (m).
    pub sampling_length: f64,
    /// Number of sampling lengths averaged.
    pub sampling_lengths: usize,
    /// Number of samples of the evaluated profile (fewer than `n` when the
    /// Gaussian filter discarded its ends).
    pub n_evaluated: usize,
    /// Index in the input of the first evaluated sample.
    pub first_index: usize,
    /// 1 when `rc` holds a value (a complete profile element was found).
    pub has_rc: i32,
    /// 1 when `rsm` holds a value.
    pub has_rsm: i32,
    /// 1 when `psd_hurst_exponent` holds a value.
    pub has_psd_hurst_exponent: i32,
    /// Reserved, 0.
    pub reserved: i32,
}

/// A power-law fit of a PSD, `G = A q^s`, from `asperity_profile_hurst_fit`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityHurstFit {
    /// Hurst exponent H = −(s + 1)/2 (dimensionless).
    pub hurst: f64,
    /// Fitted log–log slope s (dimensionless).
    pub slope: f64,
    /// Prefactor A (m³·(rad/m)^{−s}).
    pub prefactor: f64,
    /// Coefficient of determination r² of the weighted log–log fit.
    pub r_squared: f64,
    /// Lowest wavenumber fitted (rad/m).
    pub q_min: f64,
    /// Highest wavenumber fitted (rad/m).
    pub q_max: f64,
    /// Number of populated log bins fitted (10 per decade).
    pub bins: usize,
}

impl From<HurstFit> for AsperityHurstFit {
    fn from(f: HurstFit) -> Self {
        Self {
            hurst: f.hurst,
            slope: f.slope,
            prefactor: f.prefactor,
            r_squared: f.r_squared,
            q_min: f.q_min,
            q_max: f.q_max,
            bins: f.bins,
        }
    }
}

/// The power-law fit of a PSD with its uncertainty and band, from
/// `asperity_profile_hurst_estimate` (the fit of `AsperityHurstFit` with
/// the fields that struct, frozen at ABI 0.2, lacks).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityHurstEstimate {
    /// Hurst exponent H = −(s + 1)/2 (dimensionless).
    pub hurst: f64,
    /// Standard error of H (dimensionless, one standard deviation; the
    /// statistical error of the fit in the band, inflated by √(χ²/ν) when
    /// the residuals exceed the periodogram's scatter; not the systematic
    /// error of the band choice).
    pub hurst_uncertainty: f64,
    /// Fitted log–log slope s (dimensionless).
    pub slope: f64,
    /// Standard error of s (dimensionless, 2 × `hurst_uncertainty`).
    pub slope_uncertainty: f64,
    /// Prefactor A of G = A q^s (m³·(rad/m)^{−s}).
    pub prefactor: f64,
    /// Coefficient of determination r² of the weighted log–log fit.
    pub r_squared: f64,
    /// χ²/ν of the fit (dimensionless; about 1 for a power law).
    pub chi2_per_dof: f64,
    /// Lowest wavenumber fitted (rad/m).
    pub q_min: f64,
    /// Highest wavenumber fitted (rad/m).
    pub q_max: f64,
    /// Shortest wavelength of the band, 2π/q_max (m).
    pub wavelength_min: f64,
    /// Longest wavelength of the band, 2π/q_min (m).
    pub wavelength_max: f64,
    /// Number of populated log bins fitted (10 per decade).
    pub bins: u64,
}

impl From<HurstFit> for AsperityHurstEstimate {
    fn from(f: HurstFit) -> Self {
        let tau = core::f64::consts::TAU;
        Self {
            hurst: f.hurst,
            hurst_uncertainty: f.hurst_uncertainty,
            slope: f.slope,
            slope_uncertainty: f.slope_uncertainty,
            prefactor: f.prefactor,
            r_squared: f.r_squared,
            chi2_per_dof: f.chi2_per_dof,
            q_min: f.q_min,
            q_max: f.q_max,
            wavelength_min: tau / f.q_max,
            wavelength_max: tau / f.q_min,
            bins: f.bins as u64,
        }
    }
}

/// Statistics of the peaks of a profile (3-point maxima), from
/// `asperity_profile_peak_statistics`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityPeakStatistics {
    /// Number of peaks found.
    pub count: usize,
    /// Peaks per metre of profile (1/m).
    pub density: f64,
    /// Mean peak height above the mean line (m).
    pub mean_height: f64,
    /// Standard deviation of the peak heights (m).
    pub height_std: f64,
    /// Mean peak curvature (1/m); a mean radius is about 1/this.
    pub mean_curvature: f64,
}

impl From<PeakStatistics> for AsperityPeakStatistics {
    fn from(s: PeakStatistics) -> Self {
        Self {
            count: s.count,
            density: s.density,
            mean_height: s.mean_height,
            height_std: s.height_std,
            mean_curvature: s.mean_curvature,
        }
    }
}

/// Borrow a required input array of `n` doubles.
#[inline]
pub(crate) unsafe fn array<'a>(p: *const f64, n: usize, name: &'static str) -> Result<&'a [f64]> {
    if p.is_null() {
        return Err(Error::NullPointer { name });
    }
    // SAFETY: the caller provides `n` readable doubles at `p`.
    Ok(core::slice::from_raw_parts(p, n))
}

/// Check a required output array.
#[inline]
pub(crate) fn out_array(p: *mut f64, name: &'static str) -> Result<*mut f64> {
    if p.is_null() {
        Err(Error::NullPointer { name })
    } else {
        Ok(p)
    }
}

/// Copy `values` to the caller's array `out` (checked non-NULL, at least
/// `values.len()` long). `out` may overlap an input that is no longer read.
#[inline]
unsafe fn write(out: *mut f64, values: &[f64]) {
    core::ptr::copy_nonoverlapping(values.as_ptr(), out, values.len());
}

fn form_of(form: i32) -> Result<Option<Form>> {
    match form {
        ASPERITY_FORM_NONE => Ok(None),
        ASPERITY_FORM_MEAN => Ok(Some(Form::Mean)),
        ASPERITY_FORM_LINEAR => Ok(Some(Form::Linear)),
        ASPERITY_FORM_QUADRATIC => Ok(Some(Form::Quadratic)),
        v => Err(Error::UnknownSelector {
            name: "form",
            value: v as i64,
        }),
    }
}

fn ends_of(ends: i32) -> Result<FilterEnds> {
    match ends {
        ASPERITY_FILTER_ENDS_DISCARD => Ok(FilterEnds::Discard),
        ASPERITY_FILTER_ENDS_KEEP => Ok(FilterEnds::Keep),
        v => Err(Error::UnknownSelector {
            name: "ends",
            value: v as i64,
        }),
    }
}

fn window_of(window: i32) -> Result<Window> {
    match window {
        ASPERITY_WINDOW_RECTANGULAR => Ok(Window::Rectangular),
        ASPERITY_WINDOW_HANN => Ok(Window::Hann),
        v => Err(Error::UnknownSelector {
            name: "window",
            value: v as i64,
        }),
    }
}

/// `heights` with `form` removed (`None`: unchanged).
fn without_form(heights: &[f64], form: Option<Form>) -> Result<Vec<f64>> {
    match form {
        Some(f) => remove_form(heights, f),
        None => Ok(heights.to_vec()),
    }
}

/// ISO 4287 parameters of the profile `heights` (`n` values, m) sampled at
/// `dx` (m):
///
/// 1. `form` (one of `ASPERITY_FORM_*`) is removed by least squares;
/// 2. when `cutoff` λc (m) is not 0, the ISO 16610-21 Gaussian filter keeps
///    the roughness profile and drops λc/2 at each end (λc ≥ 5·dx and
///    shorter than the profile);
/// 3. the parameters are computed over sampling lengths of
///    `sampling_length` (m; 0 = the whole evaluated profile is one; ISO 4288
///    takes λc), with the ISO 4287 default discriminations (10 % of Rz, 1 %
///    of the sampling length); m₀, m₂, m₄ and α over the whole evaluated
///    profile; the Hurst exponent where a power law applies.
///
/// Errors: NULL `heights` or `out`; fewer than 8 evaluated samples,
/// non-finite heights, `dx` not finite and > 0 (`ASPERITY_ERR_INVALID_ARGUMENT`,
/// the message names the argument); an unknown `form`; a bad `cutoff` or
/// `sampling_length`; constant heights (`ASPERITY_ERR_OUT_OF_DOMAIN`).
#[no_mangle]
pub unsafe extern "C" fn asperity_roughness_parameters(
    n: usize,
    heights: *const f64,
    dx: f64,
    form: i32,
    cutoff: f64,
    sampling_length: f64,
    out: *mut AsperityRoughness,
) -> i32 {
    guard(|| {
        let h = array(heights, n, "heights")?;
        let out = output(out, "out")?;
        let form = form_of(form)?;
        let z = without_form(h, form)?;
        let (first_index, z) = if cutoff != 0.0 {
            let f = gaussian_filter(&Profile::new(dx, z)?, cutoff, FilterEnds::Discard)?;
            (f.first_index, f.roughness.into_heights())
        } else {
            (0, z)
        };
        let options = ParameterOptions {
            sampling_length: (sampling_length != 0.0).then_some(sampling_length),
            // The C entry point documents the ISO 4287 rules (section means).
            convention: crate::surface::Convention::Iso4287,
            ..ParameterOptions::default()
        };
        let p = roughness_parameters(&z, dx, &options)?;
        let m = crate::surface::spectral_moments(&z, dx)?;
        *out = AsperityRoughness {
            rp: p.rp,
            rv: p.rv,
            rz: p.rz,
            rc: p.rc.unwrap_or(0.0),
            rt: p.rt,
            ra: p.ra,
            rq: p.rq,
            rsk: p.rsk,
            rku: p.rku,
            rsm: p.rsm.unwrap_or(0.0),
            rdq: p.rdq,
            psd_hurst_exponent: p.psd_hurst_exponent.unwrap_or(0.0),
            m0: m.m0,
            m2: m.m2,
            m4: m.m4,
            nayak_alpha: m.nayak_alpha(),
            sampling_length: p.sampling_length,
            sampling_lengths: p.sampling_lengths,
            n_evaluated: z.len(),
            first_index,
            has_rc: i32::from(p.rc.is_some()),
            has_rsm: i32::from(p.rsm.is_some()),
            has_psd_hurst_exponent: i32::from(p.psd_hurst_exponent.is_some()),
            reserved: 0,
        };
        Ok(())
    })
}

/// `heights` (`n` values, m) minus their least-squares `form`
/// (`ASPERITY_FORM_*`; NONE copies), written to `out` (`n` values, m; may be
/// `heights` itself). Errors: NULL arrays, too few points for the form,
/// non-finite heights, an unknown `form`.
#[no_mangle]
pub unsafe extern "C" fn asperity_profile_remove_form(
    n: usize,
    heights: *const f64,
    form: i32,
    out: *mut f64,
) -> i32 {
    guard(|| {
        let h = array(heights, n, "heights")?;
        let out = out_array(out, "out")?;
        let form = form_of(form)?;
        if form.is_none() {
            crate::surface::check_heights(h, 1, ">= 1 point")?;
        }
        let z = without_form(h, form)?;
        write(out, &z);
        Ok(())
    })
}

/// ISO 16610-21 Gaussian filter of `heights` (`n` values, m, spacing `dx` m)
/// with cut-off `cutoff` λc (m): writes the roughness profile to `roughness`
/// and, if not NULL, the mean line to `mean_line` (each needs room for `n`
/// values; either may be `heights` itself), the number of samples written to
/// `*n_out` and the index of the first one in the input to `*first_index`
/// (may be NULL). `ends` is `ASPERITY_FILTER_ENDS_DISCARD` (λc/2 dropped at
/// each end: `*n_out` is about n − λc/dx) or `ASPERITY_FILTER_ENDS_KEEP`
/// (`*n_out` = n). Errors: as `asperity_roughness_parameters` for `cutoff`.
#[no_mangle]
pub unsafe extern "C" fn asperity_profile_gaussian_filter(
    n: usize,
    heights: *const f64,
    dx: f64,
    cutoff: f64,
    ends: i32,
    roughness: *mut f64,
    mean_line: *mut f64,
    n_out: *mut usize,
    first_index: *mut usize,
) -> i32 {
    guard(|| {
        let h = array(heights, n, "heights")?;
        let r = out_array(roughness, "roughness")?;
        let n_out = output(n_out, "n_out")?;
        let ends = ends_of(ends)?;
        let f = gaussian_filter(&Profile::new(dx, h.to_vec())?, cutoff, ends)?;
        write(r, f.roughness.heights());
        if !mean_line.is_null() {
            write(mean_line, f.mean_line.heights());
        }
        *n_out = f.roughness.len();
        if !first_index.is_null() {
            *first_index = f.first_index;
        }
        Ok(())
    })
}

/// The material-ratio (Abbott–Firestone) curve of `heights` (`n` values, m)
/// at `n_points` ≥ 2 equally spaced ratios Rmr = i/(n_points − 1):
/// `ratio[i]` (dimensionless, 0 … 1; may be NULL) and `level[i]`, the height
/// c(Rmr) above the mean line (m; the highest peak at 0, the deepest valley
/// at 1). Errors: NULL `heights` or `level`, `n_points` < 2, no or non-finite
/// heights.
#[no_mangle]
pub unsafe extern "C" fn asperity_material_ratio_curve(
    n: usize,
    heights: *const f64,
    n_points: usize,
    ratio: *mut f64,
    level: *mut f64,
) -> i32 {
    guard(|| {
        let h = array(heights, n, "heights")?;
        let level = out_array(level, "level")?;
        if n_points < 2 {
            return Err(Error::InvalidArgument {
                name: "n_points",
                value: n_points as f64,
                bound: ">= 2",
            }
            .into());
        }
        let curve = MaterialRatioCurve::new(h)?.curve(n_points);
        for (i, (r, c)) in curve.into_iter().enumerate() {
            *level.add(i) = c;
            if !ratio.is_null() {
                *ratio.add(i) = r;
            }
        }
        Ok(())
    })
}

/// One-sided PSD G(q) (thesis 1-7; ∫G dq = Rq² for the rectangular window) of
/// `heights` (`n` ≥ 4 values, m, spacing `dx` m, mean removed) with `window`
/// (`ASPERITY_WINDOW_*`). Length rule: `n_q` must equal n/2 + 1 (integer
/// division); `q[k]` = k·2π/(n·dx) (rad/m; may be NULL) and `g[k]` (m³).
#[no_mangle]
pub unsafe extern "C" fn asperity_profile_psd(
    n: usize,
    heights: *const f64,
    dx: f64,
    window: i32,
    n_q: usize,
    q: *mut f64,
    g: *mut f64,
) -> i32 {
    guard(|| {
        let h = array(heights, n, "heights")?;
        let g = out_array(g, "g")?;
        let window = window_of(window)?;
        if n_q != n / 2 + 1 {
            return Err(Error::InvalidArgument {
                name: "n_q",
                value: n_q as f64,
                bound: "== n/2 + 1 (the number of wavenumbers 0..=n/2)",
            }
            .into());
        }
        let psd = psd_windowed(h, dx, window)?;
        write(g, &psd.c);
        if !q.is_null() {
            write(q, &psd.q);
        }
        Ok(())
    })
}

/// Power-law fit of the PSD of `heights` (`n` values, m, spacing `dx` m;
/// bridge-detrended Hann periodogram, weighted log-bin fit) over
/// `q_min ≤ q ≤ q_max` (rad/m); `q_min` = `q_max` = 0 chooses the band from
/// the data (the widest run of at least one decade that is a power law with
/// 0 ≤ H ≤ 1). Errors: as `asperity_profile_psd`, a bad band, fewer than 3
/// populated bins, no power-law band (`ASPERITY_ERR_OUT_OF_DOMAIN`).
#[no_mangle]
pub unsafe extern "C" fn asperity_profile_hurst_fit(
    n: usize,
    heights: *const f64,
    dx: f64,
    q_min: f64,
    q_max: f64,
    out: *mut AsperityHurstFit,
) -> i32 {
    guard(|| {
        let h = array(heights, n, "heights")?;
        let out = output(out, "out")?;
        let band = (q_min != 0.0 || q_max != 0.0).then_some((q_min, q_max));
        *out = hurst_fit(h, dx, band)?.into();
        Ok(())
    })
}

/// `asperity_profile_hurst_fit` reporting H with its standard error, the
/// fit's χ²/ν and the band in wavenumbers (rad/m) and wavelengths (m):
/// the power-law fit of the PSD of `heights` (`n` values, m, spacing `dx`
/// m) over `q_min ≤ q ≤ q_max` (rad/m), or, with `q_min` = `q_max` = 0, over
/// the band chosen from the data (the widest run of at least one decade
/// that is a power law with 0 ≤ H ≤ 1). Errors: as
/// `asperity_profile_hurst_fit`.
#[no_mangle]
pub unsafe extern "C" fn asperity_profile_hurst_estimate(
    n: usize,
    heights: *const f64,
    dx: f64,
    q_min: f64,
    q_max: f64,
    out: *mut AsperityHurstEstimate,
) -> i32 {
    guard(|| {
        let h = array(heights, n, "heights")?;
        let out = output(out, "out")?;
        let band = (q_min != 0.0 || q_max != 0.0).then_some((q_min, q_max));
        *out = hurst_fit(h, dx, band)?.into();
        Ok(())
    })
}

/// Statistics of the peaks (3-point maxima, heights from the mean line,
/// curvature −z″) of `heights` (`n` ≥ 3 values, m, spacing `dx` m); the
/// density is per profile length n·dx.
#[no_mangle]
pub unsafe extern "C" fn asperity_profile_peak_statistics(
    n: usize,
    heights: *const f64,
    dx: f64,
    out: *mut AsperityPeakStatistics,
) -> i32 {
    guard(|| {
        let h = array(heights, n, "heights")?;
        let out = output(out, "out")?;
        let p = Profile::new(dx, h.to_vec())?;
        *out = PeakStatistics::of_peaks(&p.peaks()?, p.length()).into();
        Ok(())
    })
}

/// A seeded Gaussian self-affine profile by Fourier filtering: `n` ≥ 4
/// samples at spacing `dx` (m) written to `heights`, Hurst exponent `hurst`
/// in [0, 1], root-mean-square height `rq` (m, matched to rounding),
/// `roll_off_wavelength` (m; 0 = none: a power law down to the lowest
/// harmonic) and `cutoff_wavelength` (m; 0 = none; shorter than the roll-off).
/// The same arguments and `seed` give the same heights (see
/// `surface::generate`).
#[no_mangle]
pub unsafe extern "C" fn asperity_generate_self_affine(
    hurst: f64,
    rq: f64,
    roll_off_wavelength: f64,
    cutoff_wavelength: f64,
    dx: f64,
    seed: u64,
    n: usize,
    heights: *mut f64,
) -> i32 {
    guard(|| {
        let out = out_array(heights, "heights")?;
        let mut s = SelfAffine::new(hurst, rq)?;
        if roll_off_wavelength != 0.0 {
            s = s.with_roll_off(roll_off_wavelength)?;
        }
        if cutoff_wavelength != 0.0 {
            s = s.with_cutoff(cutoff_wavelength)?;
        }
        write(out, s.profile(n, dx, seed)?.heights());
        Ok(())
    })
}

/// The Weierstrass–Mandelbrot profile with random phases from `seed`: `n` ≥ 4
/// samples at spacing `dx` (m) written to `heights`, fractal dimension
/// `fractal_dimension` in (1, 2), frequency ratio `gamma` > 1, amplitude of
/// the longest term `amplitude` (m).
#[no_mangle]
pub unsafe extern "C" fn asperity_generate_weierstrass_mandelbrot(
    fractal_dimension: f64,
    gamma: f64,
    amplitude: f64,
    dx: f64,
    seed: u64,
    n: usize,
    heights: *mut f64,
) -> i32 {
    guard(|| {
        let out = out_array(heights, "heights")?;
        let wm = WeierstrassMandelbrot::new(fractal_dimension, gamma, amplitude)?;
        write(out, wm.profile(n, dx, seed)?.heights());
        Ok(())
    })
}

/// The Cantor–Borodich profile: `descendants` m = 2 (Borodich) or 3
/// (Warren–Krajcinovic; any m ≥ 2 is accepted), horizontal ratio `alpha` in
/// (0, 1/m), vertical ratio `beta` in (1/m, 1), first step `height` (m),
/// `levels` generations in 1..=40, sampled at `n` ≥ 2 points
/// x_j = j·length/n over [0, `length`) (m), written to `heights`.
#[no_mangle]
pub unsafe extern "C" fn asperity_generate_cantor_borodich(
    descendants: u32,
    alpha: f64,
    beta: f64,
    height: f64,
    levels: u32,
    length: f64,
    n: usize,
    heights: *mut f64,
) -> i32 {
    guard(|| {
        let out = out_array(heights, "heights")?;
        let cb = CantorBorodich::new(descendants as usize, alpha, beta, height, levels)?;
        write(out, cb.profile(length, n)?.heights());
        Ok(())
    })
}

/// The map of `nx` × `ny` heights (m, row-major: `heights[i + nx*j]` at
/// x = i·dx, y = j·dy) as a `Topography` (copied).
unsafe fn map_of(
    nx: usize,
    ny: usize,
    dx: f64,
    dy: f64,
    heights: *const f64,
) -> Result<crate::surface::Topography> {
    let n = nx.checked_mul(ny).ok_or(Error::InvalidArgument {
        name: "ny",
        value: ny as f64,
        bound: "nx*ny within the address space",
    })?;
    let h = array(heights, n, "heights")?;
    crate::surface::Topography::new(nx, ny, dx, dy, h.to_vec())
}

/// ISO 16610-61 areal Gaussian filter of the map of `nx` × `ny` heights
/// `heights` (m, row-major: `heights[i + nx*j]` at x = i·dx, y = j·dy;
/// spacings `dx`, `dy` in m; nx, ny ≥ 2) with cut-off (nesting index)
/// `cutoff` λc (m): writes the roughness (S-L) surface to `roughness` and,
/// if not NULL, the Gaussian mean surface to `mean_surface` (row-major on
/// the retained grid; each needs room for nx·ny values; either may be
/// `heights` itself), the retained grid's size to `*nx_out`, `*ny_out`, and
/// the input indices of its first point to `*first_x`, `*first_y` (either
/// may be NULL). `ends` is `ASPERITY_FILTER_ENDS_DISCARD` (λc/2 dropped on
/// every side) or `ASPERITY_FILTER_ENDS_KEEP` (the whole grid, edge weights
/// renormalised). Errors: `cutoff` not finite and > 0, shorter than 5
/// spacings or not shorter than the map along x or y, fewer than 2 points
/// left after discarding.
#[no_mangle]
pub unsafe extern "C" fn asperity_map_gaussian_filter(
    nx: usize,
    ny: usize,
    dx: f64,
    dy: f64,
    heights: *const f64,
    cutoff: f64,
    ends: i32,
    roughness: *mut f64,
    mean_surface: *mut f64,
    nx_out: *mut usize,
    ny_out: *mut usize,
    first_x: *mut usize,
    first_y: *mut usize,
) -> i32 {
    guard(|| {
        let map = map_of(nx, ny, dx, dy, heights)?;
        let r = out_array(roughness, "roughness")?;
        output(nx_out, "nx_out")?;
        output(ny_out, "ny_out")?;
        let ends = ends_of(ends)?;
        let f = crate::surface::areal_gaussian_filter(&map, cutoff, ends)?;
        write(r, f.roughness.heights());
        if !mean_surface.is_null() {
            write(mean_surface, f.mean_surface.heights());
        }
        *nx_out = f.roughness.nx();
        *ny_out = f.roughness.ny();
        if !first_x.is_null() {
            *first_x = f.first_index.0;
        }
        if !first_y.is_null() {
            *first_y = f.first_index.1;
        }
        Ok(())
    })
}

/// The radially averaged 2-D PSD of the map of `nx` × `ny` heights
/// `heights` (m, row-major as `asperity_map_gaussian_filter`; spacings
/// `dx`, `dy` in m; mean removed) with `window` (`ASPERITY_WINDOW_*`):
/// annuli of width max(Δq_x, Δq_y) centred on m·Δq up to the smaller
/// Nyquist wavenumber, empty annuli skipped. Writes for each annulus its
/// mean |q| to `q` (rad/m; may be NULL), the mean PSD over it to `psd`
/// (m⁴) and its number of grid points to `count` (may be NULL), and the
/// number of annuli to `*written`. The arrays have room for `capacity`
/// values; min(nx, ny)/2 + 1 always suffices, and a smaller capacity than
/// the annuli found is an error naming `capacity`.
#[no_mangle]
pub unsafe extern "C" fn asperity_map_psd_radial(
    nx: usize,
    ny: usize,
    dx: f64,
    dy: f64,
    heights: *const f64,
    window: i32,
    capacity: usize,
    q: *mut f64,
    psd: *mut f64,
    count: *mut usize,
    written: *mut usize,
) -> i32 {
    guard(|| {
        let map = map_of(nx, ny, dx, dy, heights)?;
        let window = window_of(window)?;
        let g = out_array(psd, "psd")?;
        let written = output(written, "written")?;
        let radial = crate::surface::psd_2d(&map, window)?.radial();
        let m = radial.r.len();
        if capacity < m {
            return Err(Error::InvalidArgument {
                name: "capacity",
                value: capacity as f64,
                bound: ">= the number of annuli (min(nx, ny)/2 + 1 always suffices)",
            }
            .into());
        }
        write(g, &radial.value);
        if !q.is_null() {
            write(q, &radial.r);
        }
        if !count.is_null() {
            core::ptr::copy_nonoverlapping(radial.count.as_ptr(), count, m);
        }
        *written = m;
        Ok(())
    })
}
