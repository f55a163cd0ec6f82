//! The power-law (Hurst) fit of a profile's PSD, G(q) ∝ q^{−(1+2H)}, with its
//! uncertainty and a fitting band chosen from the data (thesis 1.5.3).
//!
//! ## Estimator
//!
//! 1. **Bridge detrending** (end matching): the line through the first and
//!    the last height is subtracted, which removes the bulk of a tilt and
//!    the jump between the ends of a measured (non-periodic) scan.
//! 2. **Hann-windowed periodogram** G_k (normalised by ⟨w²⟩ = 3/8, as
//!    [`super::spectral`]): the taper brings both ends to zero with zero
//!    slope, so whatever jump or kink is left leaks ∝ q⁻⁶, below any
//!    self-affine spectrum; on a periodic profile the sawtooth the bridge
//!    adds is tapered away the same way. The ordinates k = 1, 2 (shaped by
//!    the form removal and the taper) and the Nyquist ordinate are left out.
//! 3. **The taper's smoothing is modelled**, not ignored: the Hann window
//!    averages neighbouring harmonics, E\[G_k\] = ⅔G(q_k) + ⅙(G(q_{k−1}) +
//!    G(q_{k+1})), which lifts a steep spectrum at its lowest harmonics (by
//!    e(e+1)/(6k²) for G ∝ q^{−e}: 11 % at k = 4 for H = 0.8) and would
//!    flatten the fit. The fit subtracts log₁₀ of that factor for the
//!    current slope from every bin and refits (three passes).
//! 4. **Log bins**, 10 per decade: each bin holds the mean of log₁₀ q and of
//!    log₁₀ G over its n_b ordinates. A periodogram ordinate of a Gaussian
//!    profile is G·χ²₂/2, whose log₁₀ has the variance
//!    σ₁² = (π²/6)/ln²10 ≈ 0.310 and the mean log₁₀ G − γ_E/ln 10 whatever
//!    the bin size (a constant that moves the prefactor, corrected by
//!    e^{γ_E}, never the slope). Neighbouring Hann ordinates are correlated
//!    (their log-ordinates by Li₂(4/9)/ζ(2) ≈ 0.31 at lag 1, 0.017 at lag
//!    2), so a bin's mean has the variance σ₁² f(n_b)/n_b with
//!    f = 1 + 2(1 − 1/n_b)·0.31 + 2(1 − 2/n_b)·0.017.
//! 5. **Weighted least squares** of the bin points with the variance
//!    σ_b² = σ₁² f(n_b)/n_b + σ_m², where σ_m = 0.02 decade (5 % in G) is a
//!    floor for the departures of real spectra from a pure power law that
//!    are no reason to reject a band.
//! 6. **Band from the data** ([`hurst_fit`] without a band): every run of
//!    consecutive bins spanning at least one decade of q is fitted; a run is
//!    a power law when χ² = Σ r_b²/σ_b² ≤ ν + 3√(2ν) (ν = bins − 2: the
//!    residuals are within three standard deviations of the χ²_ν they would
//!    follow for a power law) and 0 ≤ H ≤ 1. The widest such run is the
//!    band (ties: the smaller χ²/ν). Instrument roll-off (the stylus tip),
//!    a noise floor or a roll-off to a flat spectrum end the band; a line
//!    spectrum (a sine) leaks ∝ q⁻⁶ (H = 2.5) and has none.
//!
//! The uncertainty is the standard error of the WLS slope,
//! s_s = (Σ_b w_b (x_b − x̄)²)^{−1/2}, times √(χ²/ν) when that exceeds 1 (the
//! residuals then show more scatter than the weights assume); H = −(s+1)/2
//! so s_H = s_s/2. It is the statistical error of the fit in that band, not
//! the systematic one of the band choice.
//!
//! On generated self-affine profiles (the library's Fourier-filtered
//! generator, 2¹⁶ points) the fitted H is within 0.02 of the input for
//! H = 0.3 … 0.9, and so is it on non-periodic segments of them
//! (tests/surface_topography.rs).
//!
//! # References
//!
//! * Thesis §1.5.3 (self-affine profiles, D = 2 − H).
//! * A. Eke et al. (2000), "Physiological time series: distinguishing fractal
//!   noises from motions", Pflügers Arch. 439, 403–415 (bridge detrending
//!   before the spectral fit).
//! * J. Geweke, S. Porter-Hudak (1983), "The estimation and application of
//!   long memory time series models", J. Time Ser. Anal. 4, 221–238
//!   (regression of the log periodogram; its χ² statistics).
//! * T. D. B. Jacobs, T. Junge, L. Pastewka (2017), "Quantitative
//!   characterization of surface topography using spectral analysis", Surf.
//!   Topogr.: Metrol. Prop. 5, 013001 (windowing, fitting ranges).

use super::fft::RealFft;
use super::spectral::HurstFit;
use super::{check_heights, mean};
use crate::error::{check, Error, Result};
use serde::Serialize;

/// Euler–Mascheroni constant γ_E.
const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;
/// Log bins per decade.
pub(crate) const PER_DECADE: f64 = 10.0;
/// Variance of log₁₀ of one χ²₂/2 ordinate: (π²/6)/ln²10.
const VAR_LOG10_ORDINATE: f64 = core::f64::consts::PI * core::f64::consts::PI
    / 6.0
    / (core::f64::consts::LN_10 * core::f64::consts::LN_10);
/// Model floor σ_m (decades of G).
const MODEL_FLOOR: f64 = 0.02;
/// Shortest band the data-chosen fit accepts (decades of q).
const MIN_DECADES: f64 = 1.0;
/// Lowest harmonic used.
const FIRST_HARMONIC: usize = 3;
/// Correlation of the logs of neighbouring Hann periodogram ordinates at lags
/// 1 and 2: Li₂(ρ)/ζ(2) with the ordinates' correlations ρ = 4/9, 1/36.
const LOG_CORRELATION: [f64; 2] = [0.308, 0.017];
/// Passes of the window-smoothing correction.
const PASSES: usize = 3;
/// Shortest profile for [`psd_hurst_exponent`] and [`hurst_estimate`].
const MIN_POINTS: usize = 128;

/// A log bin of periodogram ordinates.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Bin {
    /// Mean log₁₀ q over the ordinates.
    pub lq: f64,
    /// Mean log₁₀ G over the ordinates.
    pub lg: f64,
    /// Number of ordinates.
    pub n: usize,
    /// Lowest and highest q of the ordinates (rad/m).
    pub q_lo: f64,
    pub q_hi: f64,
}

/// Accumulates ordinates (q, G) into log bins (10 per decade from `q0`).
pub(crate) struct Binner {
    l0: f64,
    bins: Vec<Bin>,
}

impl Binner {
    pub(crate) fn new(q0: f64) -> Self {
        Self {
            l0: q0.log10(),
            bins: Vec::new(),
        }
    }

    /// Adds one ordinate; q must not decrease between calls; G ≤ 0 skipped.
    pub(crate) fn add(&mut self, q: f64, g: f64) {
        if g <= 0.0 || q <= 0.0 {
            return;
        }
        let lq = q.log10();
        let b = ((lq - self.l0) * PER_DECADE + 1e-9).floor().max(0.0) as usize;
        if self.bins.len() <= b {
            self.bins.resize(
                b + 1,
                Bin {
                    lq: 0.0,
                    lg: 0.0,
                    n: 0,
                    q_lo: f64::INFINITY,
                    q_hi: 0.0,
                },
            );
        }
        let e = &mut self.bins[b];
        e.lq += lq;
        e.lg += g.log10();
        e.n += 1;
        e.q_lo = e.q_lo.min(q);
        e.q_hi = e.q_hi.max(q);
    }

    /// The populated bins with their means.
    pub(crate) fn finish(self) -> Vec<Bin> {
        self.bins
            .into_iter()
            .filter(|b| b.n > 0)
            .map(|b| Bin {
                lq: b.lq / b.n as f64,
                lg: b.lg / b.n as f64,
                ..b
            })
            .collect()
    }
}

/// Weighted least-squares line through bins (see the module docs).
#[derive(Debug, Clone, Copy)]
struct Wls {
    slope: f64,
    intercept: f64,
    slope_se: f64,
    chi2: f64,
    dof: f64,
    r_squared: f64,
}

/// Variance of a bin's mean log₁₀ G (module docs, items 4 and 5).
fn bin_variance(b: &Bin, correlated: bool) -> f64 {
    let n = b.n as f64;
    let f = if correlated {
        1.0 + 2.0 * (1.0 - 1.0 / n) * LOG_CORRELATION[0]
            + 2.0 * (1.0 - 2.0 / n).max(0.0) * LOG_CORRELATION[1]
    } else {
        1.0
    };
    VAR_LOG10_ORDINATE * f / n + MODEL_FLOOR * MODEL_FLOOR
}

/// log₁₀ of the Hann smoothing factor ⅔ + ⅙((1 − 1/k)^s + (1 + 1/k)^s) at
/// harmonic k for G ∝ q^s.
fn hann_lift(k: f64, s: f64) -> f64 {
    let u = 1.0 / k;
    (2.0 / 3.0 + ((1.0 - u).powf(s) + (1.0 + u).powf(s)) / 6.0).log10()
}

fn wls_once(bins: &[Bin], shift: &[f64], correlated: bool) -> Wls {
    let w = |b: &Bin| 1.0 / bin_variance(b, correlated);
    let y = |i: usize| bins[i].lg - shift[i];
    let (mut sw, mut sx, mut sy) = (0.0, 0.0, 0.0);
    for (i, b) in bins.iter().enumerate() {
        let wb = w(b);
        sw += wb;
        sx += wb * b.lq;
        sy += wb * y(i);
    }
    let (mx, my) = (sx / sw, sy / sw);
    let (mut sxx, mut sxy, mut syy) = (0.0, 0.0, 0.0);
    for (i, b) in bins.iter().enumerate() {
        let wb = w(b);
        let (dx, dy) = (b.lq - mx, y(i) - my);
        sxx += wb * dx * dx;
        sxy += wb * dx * dy;
        syy += wb * dy * dy;
    }
    let slope = sxy / sxx;
    let intercept = my - slope * mx;
    let chi2: f64 = bins
        .iter()
        .enumerate()
        .map(|(i, b)| {
            let r = y(i) - intercept - slope * b.lq;
            w(b) * r * r
        })
        .sum();
    let dof = (bins.len() as f64 - 2.0).max(1.0);
    let inflation = (chi2 / dof).max(1.0).sqrt();
    Wls {
        slope,
        intercept,
        slope_se: inflation / sxx.sqrt(),
        chi2,
        dof,
        r_squared: if syy > 0.0 {
            sxy * sxy / (sxx * syy)
        } else {
            1.0
        },
    }
}

/// The WLS fit of `bins`; with `hann_dq = Some(Δq)` the bins are Hann
/// ordinates at q = kΔq and the window's smoothing is modelled (module docs,
/// item 3).
fn wls(bins: &[Bin], hann_dq: Option<f64>) -> Wls {
    let mut shift = vec![0.0; bins.len()];
    let mut f = wls_once(bins, &shift, hann_dq.is_some());
    if let Some(dq) = hann_dq {
        for _ in 0..PASSES {
            for (sh, b) in shift.iter_mut().zip(bins) {
                *sh = hann_lift(10f64.powf(b.lq) / dq, f.slope);
            }
            f = wls_once(bins, &shift, true);
        }
    }
    f
}

/// The [`HurstFit`] of `bins` (at least 3, with 2 distinct q); `hann_dq` as
/// in [`wls`].
pub(crate) fn fit_bins(bins: &[Bin], hann_dq: Option<f64>) -> HurstFit {
    let f = wls(bins, hann_dq);
    HurstFit {
        hurst: -(f.slope + 1.0) / 2.0,
        hurst_uncertainty: f.slope_se / 2.0,
        slope: f.slope,
        slope_uncertainty: f.slope_se,
        // e^{γ_E}: the mean of ln(χ²₂/2) is −γ_E.
        prefactor: 10f64.powf(f.intercept) * EULER_GAMMA.exp(),
        r_squared: f.r_squared,
        chi2_per_dof: f.chi2 / f.dof,
        q_min: bins[0].q_lo,
        q_max: bins[bins.len() - 1].q_hi,
        bins: bins.len(),
    }
}

/// Is χ² within three standard deviations of its expectation ν?
fn acceptable(f: &Wls) -> bool {
    f.chi2 <= f.dof + 3.0 * (2.0 * f.dof).sqrt()
}

/// The line through the first and the last height subtracted (end matching).
pub fn bridge_detrend(heights: &[f64]) -> Vec<f64> {
    let n = heights.len();
    if n < 2 {
        return heights.to_vec();
    }
    let (a, b) = (heights[0], heights[n - 1]);
    let s = (b - a) / (n - 1) as f64;
    heights
        .iter()
        .enumerate()
        .map(|(j, z)| z - a - s * j as f64)
        .collect()
}

/// Log bins of the bridge-detrended Hann periodogram for
/// `FIRST_HARMONIC ≤ k < n/2`, restricted to `band` when given; and Δq.
fn binned_periodogram(heights: &[f64], dx: f64, band: Option<(f64, f64)>) -> (Vec<Bin>, f64) {
    let n = heights.len();
    let z = bridge_detrend(heights);
    let dq = 2.0 * core::f64::consts::PI / (n as f64 * dx);
    let scale = dx / (core::f64::consts::PI * n as f64 * 0.375);
    let (lo, hi) = band.unwrap_or((FIRST_HARMONIC as f64 * dq * (1.0 - 1e-12), f64::INFINITY));
    let mut binner = Binner::new(lo);
    RealFft::new(n).forward_with(&z, mean(&z), true, |k, x| {
        let q = k as f64 * dq;
        if k == 0 || 2 * k >= n || q < lo || q > hi {
            return;
        }
        binner.add(q, x.norm_sqr() * scale);
    });
    (binner.finish(), dq)
}

pub(crate) fn check_fit_band(q_min: f64, q_max: f64) -> Result<()> {
    check::positive("q_min", q_min)?;
    check::positive("q_max", q_max)?;
    if q_max <= q_min {
        return Err(Error::InvalidArgument {
            name: "q_max",
            value: q_max,
            bound: "> q_min",
        });
    }
    // A band wider than f64 can express (q_max / q_min = inf, e.g. a
    // subnormal q_min) has no finite bin count.
    if !(q_max / q_min).log10().is_finite() {
        return Err(Error::InvalidArgument {
            name: "q_max",
            value: q_max,
            bound: "q_max / q_min finite (a band of at most about 308 decades)",
        });
    }
    Ok(())
}

/// The widest run of bins that is a power law with 0 ≤ H ≤ 1 (module docs).
fn search_band(bins: &[Bin], dq: f64) -> Option<HurstFit> {
    // (width, χ²/ν, a, b): wider wins, then smaller χ²/ν.
    let mut best: Option<(f64, f64, usize, usize)> = None;
    for a in 0..bins.len() {
        for b in a + 2..bins.len() {
            let width = (bins[b].q_hi / bins[a].q_lo).log10();
            if width < MIN_DECADES {
                continue;
            }
            if best.is_some_and(|(bw, ..)| width < bw - 1e-12) {
                continue;
            }
            let run = &bins[a..=b];
            let f = wls(run, Some(dq));
            let h = -(f.slope + 1.0) / 2.0;
            if !acceptable(&f) || !(0.0..=1.0).contains(&h) {
                continue;
            }
            let c = f.chi2 / f.dof;
            let better = match best {
                None => true,
                Some((bw, bc, _, _)) => width > bw + 1e-12 || c < bc,
            };
            if better {
                best = Some((width, c, a, b));
            }
        }
    }
    best.map(|(_, _, a, b)| fit_bins(&bins[a..=b], Some(dq)))
}

/// Power-law fit G = A q^s of a profile's PSD and its Hurst exponent
/// H = −(s + 1)/2 (see the module docs for the estimator).
///
/// `band` (rad/m): fit the ordinates in `[q_min, q_max]` as they are. `None`:
/// the band is chosen from the data, the widest run of at least one decade
/// that is a power law with 0 ≤ H ≤ 1.
///
/// Errors: `dx` not finite and > 0; fewer than 4 or non-finite heights; a
/// band not finite, `q_min` ≤ 0 or ≥ `q_max`, or a ratio beyond f64; fewer
/// than 3 bins with power in the band, or (without a band) no power-law band
/// ([`Error::OutOfDomain`]).
pub fn hurst_fit(heights: &[f64], dx: f64, band: Option<(f64, f64)>) -> Result<HurstFit> {
    check::positive("dx", dx)?;
    check_heights(heights, 4, ">= 4 points")?;
    if let Some((lo, hi)) = band {
        check_fit_band(lo, hi)?;
    }
    let (bins, dq) = binned_periodogram(heights, dx, band);
    match band {
        Some((lo, _)) => {
            if bins.len() < 3 {
                return Err(Error::OutOfDomain {
                    name: "q_min",
                    value: lo,
                    reason: "fewer than 3 log bins with power between q_min and q_max",
                });
            }
            Ok(fit_bins(&bins, Some(dq)))
        }
        None => search_band(&bins, dq).ok_or(Error::OutOfDomain {
            name: "heights",
            value: heights.len() as f64,
            reason: NO_BAND,
        }),
    }
}

const NO_BAND: &str = "no band of at least one decade in q where the PSD is a power law \
                       with 0 <= H <= 1 within the periodogram's scatter";

/// The power-law fit of [`hurst_fit`] with a band chosen from the data, or
/// why there is none.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HurstEstimate {
    /// The fit; `None` when no power-law band exists.
    pub fit: Option<HurstFit>,
    /// Why `fit` is `None` (fewer than 128 points, no spectral power, or no
    /// band of one decade that is a power law with 0 ≤ H ≤ 1).
    pub reason: Option<&'static str>,
}

/// [`hurst_fit`] with the band chosen from the data, or the reason there is
/// no power law (see [`HurstEstimate`]).
///
/// Errors: non-finite heights, `dx` not finite and > 0.
pub fn hurst_estimate(heights: &[f64], dx: f64) -> Result<HurstEstimate> {
    check::positive("dx", dx)?;
    check_heights(heights, 1, ">= 1 point")?;
    let none = |reason| {
        Ok(HurstEstimate {
            fit: None,
            reason: Some(reason),
        })
    };
    if heights.len() < MIN_POINTS {
        return none("fewer than 128 points");
    }
    let (bins, dq) = binned_periodogram(heights, dx, None);
    if bins.len() < 3 {
        return none("no spectral power (constant heights)");
    }
    match search_band(&bins, dq) {
        Some(f) => Ok(HurstEstimate {
            fit: Some(f),
            reason: None,
        }),
        None => none(NO_BAND),
    }
}

/// The Hurst exponent of [`hurst_estimate`]: `None` for fewer than 128
/// points or without a power-law band of at least one decade with
/// 0 ≤ H ≤ 1.
///
/// Errors: non-finite heights, `dx` not finite and > 0.
pub fn psd_hurst_exponent(heights: &[f64], dx: f64) -> Result<Option<f64>> {
    Ok(hurst_estimate(heights, dx)?.fit.map(|f| f.hurst))
}

/// Former default band of the Hann-window fit, kept for callers who want a
/// fixed band: wavelengths from L/4 down to 8·dx, i.e. q from 8π/L to
/// π/(4·dx) (rad/m).
pub fn default_fit_band(n: usize, dx: f64) -> (f64, f64) {
    let l = n as f64 * dx;
    (
        8.0 * core::f64::consts::PI / l,
        core::f64::consts::PI / (4.0 * dx),
    )
}
