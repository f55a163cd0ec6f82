//! The ISO 16610-21 Gaussian profile filter (formerly ISO 11562): mean line
//! and roughness profile for a cut-off wavelength λc.
//!
//! The weighting function s(x) is that of ISO 16610-21, eq. 1, and its
//! amplitude transmission a₁/a₀ for the mean line is 50 % at λ = λc (both
//! under *Formulas*). The roughness profile is the profile minus the mean
//! line (transmission 1 − a₁/a₀).
//!
//! Discretisation: weights s(k·dx)·dx, truncated at |x| ≤ λc (the neglected
//! tail is exp(−π/α²) ≈ 7·10⁻⁷ of the peak) and normalised to unit sum. The
//! convolution runs by FFT (rustfft), so λc may span thousands of samples.
//!
//! Ends ([`FilterEnds`]): near the ends the kernel is cut by the profile
//! boundary; the mean line there uses the remaining weights renormalised to
//! unit sum (the zero-order moment criterion of ISO 16610-28). By default
//! ([`FilterEnds::Discard`]) the first and last λc/2 — the run-in and run-out
//! of ISO 4288 — are then dropped: on the part kept, at most
//! erfc(√π/(2α)) ≈ 0.8 % of the kernel weight was cut off.
//!
//! # Formulas
//!
//! $$s(x) = \frac{1}{\alpha\lambda_c}\exp\Bigl(-\pi\Bigl(\frac{x}{\alpha\lambda_c}\Bigr)^2\Bigr), \qquad \alpha = \sqrt{\frac{\ln 2}{\pi}} \approx 0.4697, \qquad \frac{a_1}{a_0} = \exp\Bigl(-\pi\Bigl(\frac{\alpha\lambda_c}{\lambda}\Bigr)^2\Bigr).$$
//!
//! # References
//!
//! * ISO 16610-21:2011, *Geometrical product specifications (GPS) — Filtration —
//!   Part 21: Linear profile filters: Gaussian filters* (formerly ISO 11562:1996).
//! * ISO 16610-28:2016 (end effects); ISO 4288:1996 (run-in and run-out).
//! * Thesis §1.5.

use super::check_heights;
use super::fft::{fast_len, fft1};
use super::Profile;
use crate::error::{check, Error, Result};
use rustfft::num_complex::Complex64;

/// α = √(ln 2 / π) of ISO 16610-21.
fn alpha() -> f64 {
    (core::f64::consts::LN_2 / core::f64::consts::PI).sqrt()
}

/// Analytic amplitude transmission of the Gaussian mean line at wavelength
/// `wavelength` (m) for cut-off `cutoff` (m): exp(−π (αλc/λ)²), α = √(ln2/π)
/// (ISO 16610-21). Equals 0.5 at λ = λc. The roughness profile transmits
/// 1 − this.
pub fn gaussian_transmission(wavelength: f64, cutoff: f64) -> f64 {
    let r = alpha() * cutoff / wavelength;
    (-core::f64::consts::PI * r * r).exp()
}

/// What to do with the ends of the profile, where the filter kernel reaches
/// beyond the data.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FilterEnds {
    /// Drop λc/2 at each end (ISO 4288 run-in/run-out); the mean line on the
    /// rest is within 0.8 % kernel weight of the untruncated filter.
    #[default]
    Discard,
    /// Keep every point; at the ends the kernel is truncated and renormalised
    /// to unit sum (ISO 16610-28 zero-order moment criterion). The mean line
    /// there follows a tilt or curvature less closely.
    Keep,
}

/// Mean line and roughness profile from [`gaussian_filter`], both on the
/// retained samples (the origin `x0` moves with the discarded run-in).
#[derive(Debug, Clone, PartialEq)]
pub struct FilteredProfile {
    /// Index of the first retained sample in the input profile.
    pub first_index: usize,
    /// The Gaussian mean line (waviness) w(x) (m).
    pub mean_line: Profile,
    /// The roughness profile r(x) = z(x) − w(x) (m).
    pub roughness: Profile,
}

/// The Gaussian mean line (m) of `heights` sampled at `dx` (m) for cut-off
/// `cutoff` (m), and the index of its first sample in `heights` (slice form of
/// [`gaussian_filter`]).
///
/// Errors: `dx`, `cutoff` not finite and > 0; `cutoff` < 5·dx (the discrete
/// kernel would not resolve the Gaussian); `cutoff` ≥ the profile length n·dx;
/// with [`FilterEnds::Discard`], fewer than two samples left after dropping
/// λc/2 at each end; fewer than 2 or non-finite heights.
pub fn gaussian_mean_line(
    heights: &[f64],
    dx: f64,
    cutoff: f64,
    ends: FilterEnds,
) -> Result<(usize, Vec<f64>)> {
    check::positive("dx", dx)?;
    check::positive("cutoff", cutoff)?;
    check_heights(heights, 2, ">= 2 points")?;
    let n = heights.len();
    if cutoff < 5.0 * dx {
        return Err(Error::InvalidArgument {
            name: "cutoff",
            value: cutoff,
            bound: ">= 5 * dx (the sampled Gaussian must resolve the cut-off)",
        });
    }
    if cutoff >= n as f64 * dx {
        return Err(Error::InvalidArgument {
            name: "cutoff",
            value: cutoff,
            bound: "< profile length n*dx",
        });
    }
    let (start, end) = match ends {
        FilterEnds::Keep => (0, n),
        FilterEnds::Discard => {
            let s = ((cutoff / (2.0 * dx)) - 1e-9).ceil() as usize;
            (s, n.saturating_sub(s))
        }
    };
    if end < start + 2 {
        return Err(Error::InvalidArgument {
            name: "cutoff",
            value: cutoff,
            bound: "short enough to leave >= 2 samples after discarding cutoff/2 at each end",
        });
    }
    // Kernel, truncated at |x| <= λc, unnormalised (normalised per point).
    let h = alpha() * cutoff / dx;
    let m = ((cutoff / dx).floor() as usize).min(n - 1);
    let w: Vec<f64> = (0..=m)
        .map(|k| {
            let r = k as f64 / h;
            (-core::f64::consts::PI * r * r).exp()
        })
        .collect();
    // cum[k + m] = Σ_{l=-m}^{k} w_|l|, for the weights that fall inside the
    // profile near the ends.
    let mut cum = Vec::with_capacity(2 * m + 1);
    let mut acc = 0.0;
    for l in -(m as isize)..=(m as isize) {
        acc += w[l.unsigned_abs()];
        cum.push(acc);
    }
    let weight_inside = |i: usize| -> f64 {
        // Offsets k with 0 <= i + k < n and |k| <= m.
        let lo = -(m.min(i) as isize);
        let hi = (m.min(n - 1 - i)) as isize;
        let upper = cum[(hi + m as isize) as usize];
        let lower = if lo + m as isize > 0 {
            cum[(lo + m as isize - 1) as usize]
        } else {
            0.0
        };
        upper - lower
    };
    let mut out = Vec::with_capacity(end - start);
    if (2 * m + 1) * (end - start) <= 1 << 16 {
        // Direct convolution for short kernels or outputs.
        for i in start..end {
            let lo = i.saturating_sub(m);
            let hi = (i + m).min(n - 1);
            let s: f64 = (lo..=hi).map(|j| w[j.abs_diff(i)] * heights[j]).sum();
            out.push(s / weight_inside(i));
        }
    } else {
        // FFT convolution: zero-padded to S >= n + m, so the circular
        // convolution equals the linear one on 0..n.
        let s_len = fast_len(n + m + 1);
        let mut zf: Vec<Complex64> = heights
            .iter()
            .map(|&z| Complex64::new(z, 0.0))
            .chain(std::iter::repeat(Complex64::default()))
            .take(s_len)
            .collect();
        let mut kf = vec![Complex64::default(); s_len];
        kf[0] = Complex64::new(w[0], 0.0);
        for k in 1..=m {
            kf[k] = Complex64::new(w[k], 0.0);
            kf[s_len - k] = Complex64::new(w[k], 0.0);
        }
        fft1(&mut zf, false);
        fft1(&mut kf, false);
        for (a, b) in zf.iter_mut().zip(&kf) {
            *a *= *b;
        }
        fft1(&mut zf, true);
        let scale = 1.0 / s_len as f64;
        for (i, v) in zf.iter().enumerate().take(end).skip(start) {
            out.push(v.re * scale / weight_inside(i));
        }
    }
    Ok((start, out))
}

/// Gaussian filtering of `profile` with cut-off `cutoff` (m): mean line and
/// roughness profile r = z − w (ISO 16610-21; see the module docs for the
/// weighting function, its discretisation and `ends`).
///
/// Errors: as [`gaussian_mean_line`].
pub fn gaussian_filter(
    profile: &Profile,
    cutoff: f64,
    ends: FilterEnds,
) -> Result<FilteredProfile> {
    let (start, mean_line) = gaussian_mean_line(profile.heights(), profile.dx(), cutoff, ends)?;
    let roughness: Vec<f64> = profile.heights()[start..start + mean_line.len()]
        .iter()
        .zip(&mean_line)
        .map(|(z, w)| z - w)
        .collect();
    let x0 = profile.x(start);
    Ok(FilteredProfile {
        first_index: start,
        mean_line: Profile::new(profile.dx(), mean_line)?.with_origin(x0)?,
        roughness: Profile::new(profile.dx(), roughness)?.with_origin(x0)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fft_and_direct_convolution_agree() {
        // Same profile through both branches: a long one forces the FFT.
        let n = 3000;
        let z: Vec<f64> = (0..n)
            .map(|j| ((j as f64) * 0.05).sin() + 0.3 * ((j as f64) * 0.31).cos() + 1e-4 * j as f64)
            .collect();
        let (s1, fast) = gaussian_mean_line(&z, 1.0, 200.0, FilterEnds::Keep).unwrap();
        assert_eq!(s1, 0);
        // Direct reference.
        let h = alpha() * 200.0;
        for &i in &[0usize, 1, 57, 1500, 2999] {
            let (mut s, mut ws) = (0.0, 0.0);
            let (lo, hi) = (i.saturating_sub(200), (i + 200).min(n - 1));
            for (j, zj) in z.iter().enumerate().take(hi + 1).skip(lo) {
                let r = (j as f64 - i as f64) / h;
                let w = (-core::f64::consts::PI * r * r).exp();
                s += w * zj;
                ws += w;
            }
            assert!((fast[i] - s / ws).abs() < 1e-12, "i = {i}");
        }
    }

    #[test]
    fn discard_drops_half_a_cutoff() {
        let z = vec![1.0; 1000];
        let (s, w) = gaussian_mean_line(&z, 1e-6, 100e-6, FilterEnds::Discard).unwrap();
        assert_eq!(s, 50);
        assert_eq!(w.len(), 900);
        assert!(w.iter().all(|v| (v - 1.0).abs() < 1e-12));
    }
}
