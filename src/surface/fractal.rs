//! Box-counting dimension of a profile's graph (thesis 1.5.3).
//!
//! # Formulas
//!
//! With boxes of side $\varepsilon = 2^s\\,dx$ and $N(\varepsilon)$ boxes needed to
//! cover the graph,
//!
//! $$D = -\frac{d\ln N(\varepsilon)}{d\ln\varepsilon},$$
//!
//! fitted by least squares; for a self-affine profile the spectral estimate
//! is $D = 2 - H$.
//!
//! # References
//!
//! * Thesis §1.5.3.
//! * K. Falconer (2014), *Fractal Geometry: Mathematical Foundations and
//!   Applications*, 3rd ed., Wiley (box-counting dimension).

use super::check_heights;
use crate::error::{check, Error, Result};
use serde::Serialize;

/// Result of [`box_counting_dimension`].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BoxCounting {
    /// Fitted dimension D = −d ln N / d ln ε.
    pub dimension: f64,
    /// Coefficient of determination of the log–log fit.
    pub r_squared: f64,
    /// Box sizes ε (m).
    pub sizes: Vec<f64>,
    /// Box counts N(ε).
    pub counts: Vec<f64>,
}

/// Box-counting dimension of the graph of `heights` (m) sampled at `dx` (m),
/// with square boxes of side ε = 2^s·dx (s = 0, 1, … while ε ≤ L/8) in the
/// (x, z) plane in metres.
///
/// For each ε the profile is cut into columns of width ε; a column whose
/// samples (with the first sample of the next column, so that the graph
/// stays connected) span [z_min, z_max] needs ⌊z_max/ε⌋ − ⌊z_min/ε⌋ + 1
/// boxes. D is the least-squares slope of ln N against ln(1/ε).
///
/// The graph of a self-affine profile is not self-similar: its box count
/// depends on the height scale, and tends to D = 1 when heights are much
/// smaller than the box sizes. The estimate is meaningful when the height
/// range is comparable to or larger than the lengths examined (the
/// Cantor–Borodich profile with h ≳ L, or heights rescaled on purpose); for
/// measured profiles prefer the spectral estimate D = 2 − H
/// ([`super::psd_hurst_exponent`]).
///
/// Errors: fewer than 16 or non-finite heights; dx not finite and > 0.
pub fn box_counting_dimension(heights: &[f64], dx: f64) -> Result<BoxCounting> {
    check::positive("dx", dx)?;
    check_heights(heights, 16, ">= 16 points")?;
    let n = heights.len();
    let (mut sizes, mut counts) = (Vec::new(), Vec::new());
    let mut w = 1usize;
    while w * 8 <= n {
        let eps = w as f64 * dx;
        let mut count = 0.0;
        let mut start = 0;
        while start < n {
            let end = (start + w + 1).min(n);
            let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
            for &z in &heights[start..end] {
                lo = lo.min(z);
                hi = hi.max(z);
            }
            count += (hi / eps).floor() - (lo / eps).floor() + 1.0;
            start += w;
        }
        sizes.push(eps);
        counts.push(count);
        w *= 2;
    }
    if sizes.len() < 2 {
        return Err(Error::InvalidArgument {
            name: "heights.len()",
            value: n as f64,
            bound: ">= 16 points",
        });
    }
    let pts: Vec<(f64, f64)> = sizes
        .iter()
        .zip(&counts)
        .map(|(e, c)| (-e.ln(), c.ln()))
        .collect();
    let (dimension, _, r_squared) = super::spectral::line_fit(&pts);
    Ok(BoxCounting {
        dimension,
        r_squared,
        sizes,
        counts,
    })
}
