//! Autocorrelation function, power spectral density and spectral moments of a
//! profile (thesis 1.5.2–1.5.3); the power-law (Hurst) fit is in
//! [`super::power_law`].
//!
//! ## Normalisation
//!
//! The PSD G follows the thesis's (1-7) (*Formulas*): a **one-sided**
//! density in angular wavenumber q = ω (rad/m), whose integral is the
//! variance, **Rq² = R(0)**. For n samples z_j at spacing dx (length
//! L = n·dx), with Z_j = z_j − z̄ and its DFT X_k = Σ_j Z_j e^{−2πijk/n}, the
//! estimate G_k at the wavenumbers q_k of *Formulas* holds for 0 < k < n/2,
//! and half that at k = 0 and (n even) k = n/2. Then Σ_k G_k Δq, with
//! Δq = 2π/L, equals (1/n) Σ_j Z_j² exactly (Parseval): m₀ = Rq² to rounding.
//! Units: m² per rad/m = m³.
//!
//! ## Spectral moments
//!
//! m₀, m₂, m₄ are the variances of the height, the slope and the curvature
//! (Nayak 1971), m_p = ∫ q^p G dq. [`spectral_moments`] computes them **from
//! the derivatives** of the profile, the definition the library reports for
//! measured profiles:
//!
//! * m₀ = ⟨Z²⟩, Z = z − z̄ (= Rq²);
//! * m₂ = ⟨Z′²⟩ with the seven-point slopes of ISO 4287 (those of RΔq, so
//!   √m₂ = RΔq over one sampling length);
//! * m₄ = ⟨Z″²⟩ with the three-point second difference
//!   (z_{j+1} − 2z_j + z_{j−1})/dx² on the n − 2 interior samples.
//!
//! By Parseval these are ∫ |D_p(q)|² G dq with the stencils' transfer
//! functions D₁ ≈ q (error O((q dx)⁶)), D₂ = (2/dx) sin(q dx/2) squared
//! (error (q dx)²/12), so they equal the q^p moments for a profile resolved
//! by its sampling. They need no periodic extension: a measured scan is not
//! periodic, and [`Psd::moments`] of its rectangular-window PSD measures the
//! jump between its two ends — the step's leakage ∝ q⁻² makes ∫ q² G dq grow
//! with the number of samples (on the Dektak scan √m₂ is 87 × RΔq without
//! detrending). Those values are kept, under names that say so
//! (`m2_rectangular_window`, …), in the CLI and the Python package; they are
//! right for a periodic profile (a generated one, whole periods of a sine).
//!
//! Nayak's bandwidth parameter α = m₀m₄/m₂² is ≥ 1 for the q^p moments of
//! any spectrum (Cauchy–Schwarz), 1.5 for a Gaussian ideal low-pass, → ∞
//! broadband; with the stencils it is ≥ 1 up to the stencil error.
//!
//! The ACF (1-6, 1-8) is the biased estimator R_k, R_0 = Rq², computed by
//! zero-padded FFT. Both ACF and PSD are even in Z:
//! the inverted profile −z has the same ones (1-9).
//!
//! Windowed PSDs (Hann) divide by the window's mean square, so ∫ G dq still
//! estimates the variance; Parseval is then no longer exact.
//!
//! # Formulas
//!
//! $$G(\omega) = \frac2\pi\int_0^\infty R(\delta)\cos(\omega\delta)\\,d\delta, \qquad R(\delta) = \int_0^\infty G(q)\cos(q\delta)\\,dq, \qquad R_q^2 = R(0) = \int_0^\infty G(q)\\,dq,$$
//!
//! $$q_k = \frac{2\pi k}{L}, \qquad G_k = \frac{dx}{\pi n}\lvert X_k\rvert^2, \qquad R_k = \frac1n\sum_{j<n-k} Z_j Z_{j+k}, \qquad m_p = \int q^p G(q)\\,dq, \qquad \alpha = \frac{m_0 m_4}{m_2^2} .$$
//!
//! # References
//!
//! * Thesis §1.5.2–1.5.3, (1-6)–(1-9).
//! * P. R. Nayak (1971), "Random process model of rough surfaces", J. Lubr.
//!   Technol. 93, 398–407 (spectral moments and the bandwidth parameter).
//! * J. S. Bendat, A. G. Piersol (2010), *Random Data: Analysis and Measurement
//!   Procedures*, 4th ed., Wiley (periodogram and the Hann window).

use super::fft::{fast_even_len, RealFft};
use super::{check_heights, mean};
use crate::error::{check, Error, Result};
use serde::Serialize;

/// Data window applied before the FFT.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Window {
    /// No window: exact Parseval, but leakage ∝ q⁻² from the mismatch of the
    /// ends biases spectra steeper than q⁻² (H > 0.5).
    #[default]
    Rectangular,
    /// Periodic Hann window w_j = sin²(πj/n), normalised by mean(w²) = 3/8;
    /// side lobes fall as q⁻⁶ in power, so power laws down to q⁻⁵ are fitted
    /// without leakage bias.
    Hann,
}

/// One-sided PSD G(q) at q_k = k·Δq, k = 0..=n/2 (see the module docs).
#[derive(Debug, Clone, PartialEq, Default, Serialize)]
pub struct Psd {
    /// Wavenumber step Δq = 2π/(n·dx) (rad/m).
    pub dq: f64,
    /// Angular wavenumbers q_k = k·Δq (rad/m).
    pub q: Vec<f64>,
    /// Power spectral density G(q_k) (m³ = m²/(rad/m)).
    pub c: Vec<f64>,
}

/// Spectral moments m_p = ∫ q^p G(q) dq (Nayak 1971): from the derivatives
/// ([`spectral_moments`]) or of a given PSD ([`Psd::moments`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SpectralMoments {
    /// m₀ = height variance (m²); equals Rq² for the rectangular window.
    pub m0: f64,
    /// m₂ = slope variance (dimensionless).
    pub m2: f64,
    /// m₄ = curvature variance (m⁻²).
    pub m4: f64,
}

/// Spectral moments of a profile from its derivatives (see the module docs):
/// m₀ = ⟨Z²⟩ (Z = z − z̄), m₂ = ⟨Z′²⟩ with the ISO 4287 seven-point slopes
/// (five- and three-point near the ends, one-sided at the end points: the
/// slopes of RΔq), m₄ = ⟨Z″²⟩ with the three-point second difference on the
/// n − 2 interior samples.
///
/// Errors: fewer than 3 or non-finite heights; `dx` not finite and > 0.
pub fn spectral_moments(heights: &[f64], dx: f64) -> Result<SpectralMoments> {
    check::positive("dx", dx)?;
    check_heights(heights, 3, ">= 3 points")?;
    let n = heights.len();
    let zbar = mean(heights);
    let m0 = heights.iter().map(|z| (z - zbar) * (z - zbar)).sum::<f64>() / n as f64;
    let m2 = (0..n)
        .map(|i| super::iso::slope_at(heights, i, dx).powi(2))
        .sum::<f64>()
        / n as f64;
    let m4 = heights
        .windows(3)
        .map(|w| ((w[2] - 2.0 * w[1] + w[0]) / (dx * dx)).powi(2))
        .sum::<f64>()
        / (n - 2) as f64;
    Ok(SpectralMoments { m0, m2, m4 })
}

impl SpectralMoments {
    /// Nayak's bandwidth parameter α = m₀ m₄ / m₂² (Nayak 1971).
    pub fn nayak_alpha(&self) -> f64 {
        self.m0 * self.m4 / (self.m2 * self.m2)
    }

    /// Expected density of peaks of a Gaussian profile, (1/2π)√(m₄/m₂)
    /// (1/m; Rice, Longuet-Higgins, Nayak 1971).
    pub fn peak_density(&self) -> f64 {
        (self.m4 / self.m2).sqrt() / (2.0 * core::f64::consts::PI)
    }
}

/// A power-law fit G = A q^s of a PSD over a band (see
/// [`super::power_law`] for the estimator and the band choice).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct HurstFit {
    /// Hurst exponent H = −(s + 1)/2, from G ∝ q^{−(1+2H)} for a self-affine
    /// profile (fractal dimension D = 2 − H).
    pub hurst: f64,
    /// Standard error of H (one standard deviation, statistical: the scatter
    /// of the periodogram in the band, inflated by √(χ²/ν) when the
    /// residuals exceed it).
    pub hurst_uncertainty: f64,
    /// Fitted log–log slope s.
    pub slope: f64,
    /// Standard error of s (= 2 × `hurst_uncertainty`).
    pub slope_uncertainty: f64,
    /// Prefactor A of G = A q^s (m³·(rad/m)^{−s}), corrected for the log bias
    /// of χ²₂ ordinates.
    pub prefactor: f64,
    /// Coefficient of determination of the weighted log–log fit.
    pub r_squared: f64,
    /// χ²/ν of the fit with the weights of [`super::power_law`] (about 1 for
    /// a power law).
    pub chi2_per_dof: f64,
    /// Lowest wavenumber fitted (rad/m).
    pub q_min: f64,
    /// Highest wavenumber fitted (rad/m).
    pub q_max: f64,
    /// Number of populated log bins fitted (10 per decade).
    pub bins: usize,
}

impl Psd {
    /// Number of wavenumbers.
    pub fn len(&self) -> usize {
        self.c.len()
    }

    /// True when there are no wavenumbers.
    pub fn is_empty(&self) -> bool {
        self.c.is_empty()
    }

    /// ∫ G dq = Σ_k G_k Δq (m²): the height variance (Parseval).
    pub fn integral(&self) -> f64 {
        self.c.iter().sum::<f64>() * self.dq
    }

    /// Spectral moments m_p = Σ q_k^p G_k Δq of this PSD. Of a
    /// rectangular-window PSD of a non-periodic profile, m₂ and m₄ measure
    /// the jump between its ends, not its slopes (module docs); use
    /// [`spectral_moments`] for a measured profile.
    pub fn moments(&self) -> SpectralMoments {
        let (mut m0, mut m2, mut m4) = (0.0, 0.0, 0.0);
        for (q, c) in self.q.iter().zip(&self.c) {
            let q2 = q * q;
            m0 += c;
            m2 += q2 * c;
            m4 += q2 * q2 * c;
        }
        SpectralMoments {
            m0: m0 * self.dq,
            m2: m2 * self.dq,
            m4: m4 * self.dq,
        }
    }

    /// Power-law fit of this PSD over `q_min ≤ q ≤ q_max` (rad/m): the
    /// ordinates are grouped in log bins (10 per decade, from `q_min`), each
    /// bin represented by the mean of log₁₀ G and of log₁₀ q over its
    /// ordinates, and the bins fitted by weighted least squares as in
    /// [`super::power_law`], without its window-smoothing correction (the
    /// uncertainty assumes independent χ²₂ ordinates: a rectangular
    /// periodogram of a periodic profile; a Hann one's neighbours are
    /// correlated and its uncertainty is about 1.3 times larger). Ordinates
    /// without power (≤ 0) are skipped, so line spectra (a sine, the
    /// Weierstrass–Mandelbrot comb) are not fitted meaningfully.
    ///
    /// Errors: band not finite, `q_min` ≤ 0 or ≥ `q_max`; fewer than 3 bins
    /// with power in the band ([`Error::OutOfDomain`]).
    pub fn power_law_fit(&self, q_min: f64, q_max: f64) -> Result<HurstFit> {
        super::power_law::check_fit_band(q_min, q_max)?;
        let mut bins = super::power_law::Binner::new(q_min);
        // q ascending, as produced by the PSD functions.
        let k_lo = self.q.partition_point(|&q| q < q_min);
        for (&q, &c) in self.q[k_lo..].iter().zip(&self.c[k_lo..]) {
            if q > q_max {
                break;
            }
            bins.add(q, c);
        }
        let bins = bins.finish();
        if bins.len() < 3 {
            return Err(Error::OutOfDomain {
                name: "q_min",
                value: q_min,
                reason: "fewer than 3 log bins with power between q_min and q_max",
            });
        }
        Ok(super::power_law::fit_bins(&bins, None))
    }
}

/// Reusable PSD computation for profiles of one length: the FFT is planned
/// and the buffers allocated once, so repeated calls do not allocate (the
/// output [`Psd`] is reused too).
pub struct PsdPlan {
    fft: RealFft,
}

impl PsdPlan {
    /// A plan for profiles of `n` samples. Errors: `n < 4`.
    pub fn new(n: usize) -> Result<Self> {
        if n < 4 {
            return Err(Error::InvalidArgument {
                name: "n",
                value: n as f64,
                bound: ">= 4 points",
            });
        }
        Ok(Self {
            fft: RealFft::new(n),
        })
    }

    /// Profile length the plan was made for.
    pub fn len(&self) -> usize {
        self.fft.len()
    }

    /// Always false (a plan has at least 4 points).
    pub fn is_empty(&self) -> bool {
        self.fft.len() == 0
    }

    /// Writes the PSD of `heights` (m, spacing `dx` m) with `window` into
    /// `out` (resized as needed); see the module docs for the normalisation.
    ///
    /// Errors: `heights.len()` ≠ the plan's length; `dx` not finite and > 0;
    /// non-finite heights.
    pub fn compute(
        &mut self,
        heights: &[f64],
        dx: f64,
        window: Window,
        out: &mut Psd,
    ) -> Result<()> {
        let n = self.fft.len();
        if heights.len() != n {
            return Err(Error::InvalidArgument {
                name: "heights.len()",
                value: heights.len() as f64,
                bound: "== the length the PsdPlan was made for",
            });
        }
        check::positive("dx", dx)?;
        check_heights(heights, 4, ">= 4 points")?;
        let zbar = mean(heights);
        let hann = window == Window::Hann;
        let nq = n / 2 + 1;
        let dq = 2.0 * core::f64::consts::PI / (n as f64 * dx);
        let scale = psd_scale(n, dx, window);
        out.dq = dq;
        out.q.resize(nq, 0.0);
        out.c.resize(nq, 0.0);
        let (q, c) = (&mut out.q, &mut out.c);
        self.fft.forward_with(heights, zbar, hann, |k, x| {
            q[k] = k as f64 * dq;
            c[k] = x.norm_sqr() * scale(k);
        });
        Ok(())
    }

    /// As [`Self::compute`], returning a new [`Psd`].
    pub fn psd(&mut self, heights: &[f64], dx: f64, window: Window) -> Result<Psd> {
        let mut out = Psd::default();
        self.compute(heights, dx, window, &mut out)?;
        Ok(out)
    }
}

/// G_k / |X_k|² for n samples at spacing dx: dx/(πn·mean(w²)), halved at
/// k = 0 and (n even) k = n/2. Mean square of the periodic Hann window:
/// Σ sin⁴(πj/n) = 3n/8 for n ≥ 3.
fn psd_scale(n: usize, dx: f64, window: Window) -> impl Fn(usize) -> f64 {
    let w2 = if window == Window::Hann { 0.375 } else { 1.0 };
    let full = dx / (core::f64::consts::PI * n as f64 * w2);
    move |k| {
        if k == 0 || 2 * k == n {
            0.5 * full
        } else {
            full
        }
    }
}

/// One-sided PSD of `heights` (m) at spacing `dx` (m), mean removed,
/// rectangular window: ∫ G dq = Rq² exactly (see the module docs).
///
/// Errors: fewer than 4 or non-finite heights; `dx` not finite and > 0.
pub fn psd(heights: &[f64], dx: f64) -> Result<Psd> {
    psd_windowed(heights, dx, Window::Rectangular)
}

/// One-sided PSD with a data window; see [`psd`] and [`Window`].
pub fn psd_windowed(heights: &[f64], dx: f64, window: Window) -> Result<Psd> {
    check_heights(heights, 4, ">= 4 points")?;
    PsdPlan::new(heights.len())?.psd(heights, dx, window)
}

/// Autocorrelation function R(δ_k), δ_k = k·dx, k = 0..n (biased estimator,
/// mean removed; thesis 1-6/1-8).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Acf {
    /// Lag step = sampling interval dx (m).
    pub dx: f64,
    /// R_k (m²); R_0 = Rq².
    pub r: Vec<f64>,
}

impl Acf {
    /// Lag δ_k = k·dx (m).
    pub fn lag(&self, k: usize) -> f64 {
        k as f64 * self.dx
    }

    /// The normalised ACF ρ_k = R_k / R_0 (ρ_0 = 1); all zero when R_0 = 0.
    pub fn normalized(&self) -> Vec<f64> {
        let r0 = self.r.first().copied().unwrap_or(0.0);
        if r0 > 0.0 {
            self.r.iter().map(|r| r / r0).collect()
        } else {
            vec![0.0; self.r.len()]
        }
    }

    /// Correlation length (m): the first lag at which R/R₀ falls to
    /// `threshold` (e.g. 1/e, 0.1, 0.2), interpolated linearly; `None` if it
    /// never does. Errors: `threshold` outside (0, 1).
    pub fn correlation_length(&self, threshold: f64) -> Result<Option<f64>> {
        if !(threshold > 0.0 && threshold < 1.0) {
            return Err(Error::InvalidArgument {
                name: "threshold",
                value: threshold,
                bound: "in (0, 1)",
            });
        }
        let r0 = self.r.first().copied().unwrap_or(0.0);
        if r0 <= 0.0 {
            return Ok(None);
        }
        for k in 1..self.r.len() {
            let (a, b) = (self.r[k - 1] / r0, self.r[k] / r0);
            if b <= threshold {
                let t = (a - threshold) / (a - b);
                return Ok(Some((k as f64 - 1.0 + t) * self.dx));
            }
        }
        Ok(None)
    }
}

/// Autocorrelation function of `heights` (m) at spacing `dx` (m): biased
/// estimator R_k = (1/n) Σ_{j<n−k} Z_j Z_{j+k}, Z = z − z̄, by zero-padded FFT
/// (Wiener–Khinchin), O(n log n).
///
/// Errors: fewer than 2 or non-finite heights; `dx` not finite and > 0.
pub fn acf(heights: &[f64], dx: f64) -> Result<Acf> {
    check::positive("dx", dx)?;
    check_heights(heights, 2, ">= 2 points")?;
    let n = heights.len();
    let s = fast_even_len(2 * n);
    let mut fft = RealFft::new(s);
    // |X_k|² is real and even in k: its DFT is real and gives the circular
    // autocorrelation of the zero-padded sequence, i.e. the linear one.
    let mut p = vec![0.0; s];
    fft.forward_with(heights, mean(heights), false, |k, x| {
        let v = x.norm_sqr();
        p[k] = v;
        if k > 0 && k < s - k {
            p[s - k] = v;
        }
    });
    let scale = 1.0 / (s as f64 * n as f64);
    let mut r = vec![0.0; n];
    fft.forward_with(&p, 0.0, false, |k, x| {
        if k < n {
            r[k] = x.re * scale;
        }
    });
    Ok(Acf { dx, r })
}

/// Least-squares straight line through `(x, y)` points: `(slope, intercept,
/// r²)` (r² = 1 when the y are constant). Callers guarantee ≥ 2 distinct x.
pub(crate) fn line_fit(pts: &[(f64, f64)]) -> (f64, f64, f64) {
    let k = pts.len() as f64;
    let mx = pts.iter().map(|p| p.0).sum::<f64>() / k;
    let my = pts.iter().map(|p| p.1).sum::<f64>() / k;
    let (mut sxx, mut sxy, mut syy) = (0.0, 0.0, 0.0);
    for &(x, y) in pts {
        sxx += (x - mx) * (x - mx);
        sxy += (x - mx) * (y - my);
        syy += (y - my) * (y - my);
    }
    let slope = sxy / sxx;
    let r_squared = if syy > 0.0 {
        sxy * sxy / (sxx * syy)
    } else {
        1.0
    };
    (slope, my - slope * mx, r_squared)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn acf_matches_the_direct_sum() {
        let z: Vec<f64> = (0..37).map(|j| ((j * 13 + 5) % 17) as f64 * 0.1).collect();
        let a = acf(&z, 1.0).unwrap();
        let m = mean(&z);
        for k in [0usize, 1, 5, 36] {
            let d: f64 = (0..37 - k)
                .map(|j| (z[j] - m) * (z[j + k] - m))
                .sum::<f64>()
                / 37.0;
            assert!((a.r[k] - d).abs() < 1e-12, "k = {k}");
        }
    }

    #[test]
    fn parseval_odd_and_even_lengths() {
        for n in [64usize, 65, 1000, 1001] {
            let z: Vec<f64> = (0..n).map(|j| ((j * 7919) % 101) as f64 * 1e-9).collect();
            let g = psd(&z, 1e-6).unwrap();
            let m = mean(&z);
            let var = z.iter().map(|v| (v - m) * (v - m)).sum::<f64>() / n as f64;
            assert!((g.integral() / var - 1.0).abs() < 1e-12, "n = {n}");
        }
    }
}
