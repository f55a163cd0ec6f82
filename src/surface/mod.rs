//! Surface profiles and maps: readers, form removal and filtering, ISO 4287
//! parameters, autocorrelation and power spectral density, generators and the
//! representative elementary pattern (thesis sections 1.5, 1.7).
//!
//! ## Data
//!
//! * [`Profile`]: a line scan sampled at a uniform spacing `dx` (m), heights in
//!   m. [`Topography`]: a map on a uniform `dx` × `dy` grid.
//! * [`read`]: text readers for `x,z` line scans and `x,y,z` or gridded maps
//!   (comma, semicolon or whitespace separated, `#` comments), with an
//!   explicit policy for slightly irregular spacing ([`Spacing`]).
//! * [`instrument`]: instrument files — X3P (ISO 25178-72), Nanoscope `.di`,
//!   Dektak CSV, Hommel `.hfm` — and [`read_measurement`], which picks the
//!   reader by extension or content.
//! * [`Form`] / [`MapForm`]: least-squares form removal (mean, linear,
//!   quadratic; mean, plane, quadratic for maps).
//!
//! ## Analysis
//!
//! * [`filter`]: the ISO 16610-21 Gaussian mean-line filter;
//!   [`areal_filter`]: the ISO 16610-61 areal Gaussian filter of maps.
//! * [`iso`]: profile parameters (Rp, Rv, Rz, Rc, Rt, Ra, Rq, Rsk, Rku, RSm,
//!   RΔq) in the ISO 21920-2 (default) or ISO 4287 convention
//!   ([`Convention`]), the material-ratio (Abbott–Firestone) curve, and
//!   areal Sa, Sq, Ssk, Sku, Sp, Sv, Sz, Sdq.
//! * [`material_ratio`](mod@material_ratio): ISO 13565-2 Rk, Rpk, Rvk, Mr1,
//!   Mr2 and ISO 25178-2 Sk, Spk, Svk, Smr1, Smr2, Vmp, Vmc, Vvc, Vvv.
//! * [`spectral`]: autocorrelation (thesis 1-6, 1-8) and one-sided power
//!   spectral density (1-7) normalised so that Parseval holds exactly,
//!   spectral moments (from the derivatives) and Nayak's bandwidth.
//! * [`power_law`]: the PSD power-law (Hurst) fit with its uncertainty and a
//!   band chosen from the data.
//! * [`map_spectral`]: 2-D PSD and ACF of maps (full arrays, radial
//!   averages) and their isotropy (Str-like texture aspect ratio, slope
//!   anisotropy).
//! * [`scale`]: rms slope and curvature as functions of the scale (finite
//!   differences at increasing step), for profiles and maps.
//! * [`peaks`](mod@peaks): peaks of profiles (3-point) and summits of maps (8-neighbour)
//!   with finite-difference curvatures.
//! * [`pattern`]: Pepelyshev's representative elementary pattern (thesis
//!   1.5.4) by the two-sample Kolmogorov–Smirnov statistic, in O(n log n).
//!
//! ## Synthesis
//!
//! * [`generate`]: seeded Weierstrass–Mandelbrot profiles, self-affine Gaussian
//!   profiles and maps by Fourier filtering, and the Cantor–Borodich profile
//!   (two descendants) with the three-descendant Warren–Krajcinovic variant
//!   (thesis 1.5.3, 5.4.2).
//! * [`fractal`]: box-counting dimension of a profile's graph.
//!
//! Every function that works on a [`Profile`] has a slice form
//! (`heights: &[f64], dx: f64`) so that callers holding plain arrays (the C
//! ABI) need not build one.
//!
//! # Formulas
//!
//! The central quantities, detailed in the submodules:
//!
//! $$R_q = \sqrt{\frac1n\sum_j Z_j^2} = \sqrt{\int_0^\infty G(q)\\,dq}, \qquad G(\omega) = \frac2\pi\int_0^\infty R(\delta)\cos(\omega\delta)\\,d\delta, \qquad D = 2 - H .$$
//!
//! # References
//!
//! * Thesis §§1.5, 1.7.
//! * ISO 4287:1997 (profile parameters), ISO 16610-21:2011 (Gaussian filter),
//!   ISO 25178-2:2012 (areal parameters).
//! * P. R. Nayak (1971), "Random process model of rough surfaces", J. Lubr.
//!   Technol. 93, 398–407.
//! * The generators' and the pattern's sources are cited in [`generate`] and
//!   [`pattern`].

pub mod areal_filter;
mod fft;
pub mod filter;
pub mod fractal;
pub mod generate;
pub mod instrument;
pub mod iso;
pub mod map_spectral;
pub mod material_ratio;
pub mod pattern;
pub mod peaks;
pub mod power_law;
pub mod profile;
pub mod read;
pub mod scale;
pub mod spectral;

pub use areal_filter::{areal_gaussian_filter, areal_gaussian_transmission, FilteredMap};
pub use filter::{
    gaussian_filter, gaussian_mean_line, gaussian_transmission, FilterEnds, FilteredProfile,
};
pub use fractal::{box_counting_dimension, BoxCounting};
pub use generate::{CantorBorodich, SelfAffine, WeierstrassMandelbrot};
pub use instrument::{
    parse_dektak_csv, parse_hfm, parse_measurement, parse_nanoscope, parse_x3p, read_measurement,
    Measurement, Surface,
};
pub use iso::{
    areal_parameters, areal_parameters_grid, roughness_parameters, ArealParameters, Convention,
    MaterialRatioCurve, ParameterOptions, RoughnessParameters,
};
pub use map_spectral::{acf_2d, isotropy, psd_2d, Acf2d, Isotropy, Psd2d, Radial};
pub use material_ratio::{
    functional_parameters, functional_parameters_of, material_ratio_parameters,
    FunctionalParameters, MaterialRatioParameters,
};
pub use pattern::{ks_statistics, ks_two_sample, representative_pattern, RepresentativePattern};
pub use peaks::{peaks, summits, summits_grid, Peak, PeakStatistics, Summit};
pub use power_law::{
    bridge_detrend, default_fit_band, hurst_estimate, hurst_fit, psd_hurst_exponent, HurstEstimate,
};
pub use profile::{remove_form, Form, MapForm, Profile, Topography};
pub use read::{
    parse_profile, parse_topography, profile_from_positions, read_profile, read_topography, Spacing,
};
pub use scale::{scale_dependent, scale_dependent_map, ScaleDependent, ScaleDependentMap};
pub use spectral::{
    acf, psd, psd_windowed, spectral_moments, Acf, HurstFit, Psd, PsdPlan, SpectralMoments, Window,
};

use crate::error::{Error, Result};

/// Checks that `heights` has at least `min_len` values and that all are
/// finite. `bound` is the length condition as text, e.g. `">= 8 points"`.
pub(crate) fn check_heights(heights: &[f64], min_len: usize, bound: &'static str) -> Result<()> {
    if heights.len() < min_len {
        return Err(Error::InvalidArgument {
            name: "heights.len()",
            value: heights.len() as f64,
            bound,
        });
    }
    if let Some(&v) = heights.iter().find(|v| !v.is_finite()) {
        return Err(Error::InvalidArgument {
            name: "heights",
            value: v,
            bound: "finite",
        });
    }
    Ok(())
}

/// Arithmetic mean (callers guarantee a non-empty slice).
#[inline]
pub(crate) fn mean(h: &[f64]) -> f64 {
    h.iter().sum::<f64>() / h.len() as f64
}
