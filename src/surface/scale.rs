//! Scale-dependent rms slope and curvature of profiles and maps, by finite
//! differences at increasing step h (Sanner et al. 2022).
//!
//! At scale h = k·dx (k = 1, 2, 3, 4, 6, 8, 11, 16, …: about √2 apart, up to
//! a quarter of the profile),
//!
//! * slope: rms of (z(x + h) − z(x))/h over all pairs in the profile;
//! * curvature: rms of (z(x + h) − 2z(x) + z(x − h))/h² over all triples.
//!
//! For a sinusoid A sin(2πx/λ) these are √2·A|sin(πh/λ)|/h and
//! 2√2·A sin²(πh/λ)/h² (both → the rms slope and curvature as h → 0, zero
//! at h = λ). For a self-affine profile both follow power laws of h, the
//! slope ∝ h^{H−1} and the curvature ∝ h^{H−2}: a rough surface has no
//! single slope, and the scale says which one a contact model sees. A map
//! gives the same along x (rows) and along y (columns).
//!
//! # References
//!
//! * A. Sanner, W. G. Nöhring, L. A. Thimons, T. D. B. Jacobs, L. Pastewka
//!   (2022), "Scale-dependent roughness parameters for topography analysis",
//!   Appl. Surf. Sci. Adv. 7, 100190.
//! * Thesis §1.5.3 (self-affine profiles).

use super::{check_heights, Topography};
use crate::error::{check, Result};
use serde::Serialize;

/// rms slope and curvature at increasing scale.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ScaleDependent {
    /// Scales h (m), increasing.
    pub scale: Vec<f64>,
    /// rms slope at each scale (dimensionless).
    pub slope_rms: Vec<f64>,
    /// rms curvature at each scale (m⁻¹).
    pub curvature_rms: Vec<f64>,
}

/// Scale-dependent slope and curvature of a map along x and along y.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ScaleDependentMap {
    /// Along x (every row).
    pub along_x: ScaleDependent,
    /// Along y (every column).
    pub along_y: ScaleDependent,
}

/// Steps k ≥ 1, about √2 apart, with k ≤ max(1, (n − 1)/4).
fn steps(n: usize) -> Vec<usize> {
    let k_max = ((n - 1) / 4).max(1);
    let mut out = Vec::new();
    let mut x = 1.0f64;
    while (x.round() as usize) <= k_max {
        let k = x.round() as usize;
        if out.last() != Some(&k) {
            out.push(k);
        }
        x *= core::f64::consts::SQRT_2;
    }
    out
}

/// Sums of squared differences at step k over `lines` (each a slice).
fn sums<'a>(lines: impl Iterator<Item = &'a [f64]> + Clone, k: usize) -> (f64, usize, f64, usize) {
    let (mut s1, mut n1, mut s2, mut n2) = (0.0, 0, 0.0, 0);
    for z in lines {
        let n = z.len();
        for j in 0..n.saturating_sub(k) {
            let d = z[j + k] - z[j];
            s1 += d * d;
            n1 += 1;
        }
        for j in k..n.saturating_sub(k) {
            let d = z[j + k] - 2.0 * z[j] + z[j - k];
            s2 += d * d;
            n2 += 1;
        }
    }
    (s1, n1, s2, n2)
}

fn compute<'a>(lines: impl Iterator<Item = &'a [f64]> + Clone, n: usize, d: f64) -> ScaleDependent {
    let mut out = ScaleDependent {
        scale: Vec::new(),
        slope_rms: Vec::new(),
        curvature_rms: Vec::new(),
    };
    for k in steps(n) {
        let (s1, n1, s2, n2) = sums(lines.clone(), k);
        if n1 == 0 || n2 == 0 {
            continue;
        }
        let h = k as f64 * d;
        out.scale.push(h);
        out.slope_rms.push((s1 / n1 as f64).sqrt() / h);
        out.curvature_rms.push((s2 / n2 as f64).sqrt() / (h * h));
    }
    out
}

/// Scale-dependent rms slope and curvature of `heights` (m) at spacing `dx`
/// (m); see the module docs.
///
/// Errors: fewer than 3 or non-finite heights; `dx` not finite and > 0.
pub fn scale_dependent(heights: &[f64], dx: f64) -> Result<ScaleDependent> {
    check::positive("dx", dx)?;
    check_heights(heights, 3, ">= 3 points")?;
    Ok(compute(std::iter::once(heights), heights.len(), dx))
}

/// Scale-dependent rms slope and curvature of a map along x (rows) and y
/// (columns); see the module docs. Errors: a side of fewer than 3 points.
pub fn scale_dependent_map(map: &Topography) -> Result<ScaleDependentMap> {
    let (nx, ny) = (map.nx(), map.ny());
    if nx < 3 || ny < 3 {
        return Err(crate::error::Error::InvalidArgument {
            name: "map",
            value: nx.min(ny) as f64,
            bound: "nx, ny >= 3",
        });
    }
    let z = map.heights();
    let mut t = vec![0.0; nx * ny];
    for j in 0..ny {
        for i in 0..nx {
            t[i * ny + j] = z[j * nx + i];
        }
    }
    Ok(ScaleDependentMap {
        along_x: compute(z.chunks_exact(nx), nx, map.dx()),
        along_y: compute(t.chunks_exact(ny), ny, map.dy()),
    })
}
