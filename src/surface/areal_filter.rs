//! The ISO 16610-61 areal Gaussian filter: mean surface and roughness
//! (S-L) surface of a height map for a nesting index (cut-off) λc.
//!
//! The weighting function s(x, y) of ISO 16610-61 (*Formulas*) is the
//! product s₁(x)·s₁(y) of the ISO 16610-21 profile weighting functions, so
//! the filter runs as the profile filter ([`super::filter`]) along every row,
//! then along every column. Its amplitude transmission for a sinusoid of
//! wavelength λ, in any direction, is exp(−π(αλc/λ)²): 50 % at λ = λc, the
//! same in every direction (the Gaussian is isotropic).
//!
//! Discretisation and ends as in [`super::filter`]: sampled weights truncated
//! at |x|, |y| ≤ λc; near the edges the weights inside the map are
//! renormalised to unit sum (ISO 16610-28's zero-order criterion; separable
//! because the map is a rectangle). With [`FilterEnds::Discard`] a border of
//! λc/2 is then dropped on every side.
//!
//! # Formulas
//!
//! $$s(x,y) = \frac{1}{\alpha^2\lambda_c^2}\exp\Bigl(-\pi\frac{x^2+y^2}{(\alpha\lambda_c)^2}\Bigr), \qquad \alpha = \sqrt{\frac{\ln 2}{\pi}}, \qquad \frac{a_1}{a_0} = \exp\Bigl(-\pi\Bigl(\frac{\alpha\lambda_c}{\lambda}\Bigr)^2\Bigr).$$
//!
//! # References
//!
//! * ISO 16610-61:2015, *Geometrical product specification (GPS) —
//!   Filtration — Part 61: Linear areal filters — Gaussian filters*.
//! * ISO 16610-21:2011 (the profile filter), ISO 16610-28:2016 (end effects),
//!   ISO 25178-3:2012 (S-L surface, nesting index).

use super::filter::{gaussian_mean_line, gaussian_transmission, FilterEnds};
use super::Topography;
use crate::error::{Error, Result};

/// Amplitude transmission of the areal Gaussian mean surface for a sinusoid
/// of wavelength `wavelength` (m), any direction, cut-off `cutoff` (m):
/// exp(−π(αλc/λ)²), 0.5 at λ = λc (ISO 16610-61). The roughness surface
/// transmits 1 − this.
pub fn areal_gaussian_transmission(wavelength: f64, cutoff: f64) -> f64 {
    gaussian_transmission(wavelength, cutoff)
}

/// Mean surface and roughness surface from [`areal_gaussian_filter`], on the
/// retained grid.
#[derive(Debug, Clone, PartialEq)]
pub struct FilteredMap {
    /// Index (i, j) in the input map of the first retained point.
    pub first_index: (usize, usize),
    /// The Gaussian mean surface (m).
    pub mean_surface: Topography,
    /// The roughness surface z − mean surface (m).
    pub roughness: Topography,
}

/// ISO 16610-61 areal Gaussian filter of `map` with cut-off (nesting index)
/// `cutoff` (m); see the module docs.
///
/// Errors: `cutoff` not finite and > 0, shorter than 5 spacings or not
/// shorter than the map along x or y; with [`FilterEnds::Discard`], fewer
/// than 2 points left along x or y.
pub fn areal_gaussian_filter(
    map: &Topography,
    cutoff: f64,
    ends: FilterEnds,
) -> Result<FilteredMap> {
    let (nx, ny) = (map.nx(), map.ny());
    let z = map.heights();
    let mut rows = vec![0.0; nx * ny];
    for j in 0..ny {
        let (_, w) =
            gaussian_mean_line(&z[j * nx..(j + 1) * nx], map.dx(), cutoff, FilterEnds::Keep)?;
        rows[j * nx..(j + 1) * nx].copy_from_slice(&w);
    }
    let mut mean = vec![0.0; nx * ny];
    let mut col = vec![0.0; ny];
    for i in 0..nx {
        for j in 0..ny {
            col[j] = rows[j * nx + i];
        }
        let (_, w) = gaussian_mean_line(&col, map.dy(), cutoff, FilterEnds::Keep)?;
        for j in 0..ny {
            mean[j * nx + i] = w[j];
        }
    }
    let (sx, sy) = match ends {
        FilterEnds::Keep => (0, 0),
        FilterEnds::Discard => (
            ((cutoff / (2.0 * map.dx())) - 1e-9).ceil() as usize,
            ((cutoff / (2.0 * map.dy())) - 1e-9).ceil() as usize,
        ),
    };
    if nx < 2 * sx + 2 || ny < 2 * sy + 2 {
        return Err(Error::InvalidArgument {
            name: "cutoff",
            value: cutoff,
            bound: "short enough to leave >= 2 points along x and y after discarding cutoff/2 at each edge",
        });
    }
    let (mx, my) = (nx - 2 * sx, ny - 2 * sy);
    let mut m = Vec::with_capacity(mx * my);
    let mut r = Vec::with_capacity(mx * my);
    for j in sy..ny - sy {
        for i in sx..nx - sx {
            let k = j * nx + i;
            m.push(mean[k]);
            r.push(z[k] - mean[k]);
        }
    }
    Ok(FilteredMap {
        first_index: (sx, sy),
        mean_surface: Topography::new(mx, my, map.dx(), map.dy(), m)?,
        roughness: Topography::new(mx, my, map.dx(), map.dy(), r)?,
    })
}
