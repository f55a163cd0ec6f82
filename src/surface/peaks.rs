//! Peaks of profiles and summits of maps, with heights and curvatures from
//! finite differences — the asperity statistics that Greenwood–Williamson and
//! Zhuravlev-type models take as input (thesis 1.5, 1.7).
//!
//! * **Peak** (profile, 3-point definition): z_j > z_{j−1} and z_j > z_{j+1}
//!   (a flat top of equal samples counts once, at its middle sample).
//!   Curvature κ_peak from the second difference (1/m, > 0 at a peak).
//! * **Summit** (map, 8-neighbour definition; Greenwood 1984): z_{ij} higher
//!   than all 8 neighbours. Curvature κ_summit, the mean of the principal
//!   curvatures, from central second differences.
//!
//! Heights are measured from the mean line (mean plane).
//!
//! # Formulas
//!
//! $$\kappa_\mathrm{peak} = -\frac{z_{j+1} - 2z_j + z_{j-1}}{dx^2}, \qquad \kappa_\mathrm{summit} = -\frac{z_{xx} + z_{yy}}{2} .$$
//!
//! # References
//!
//! * Thesis §1.5, §1.7.
//! * J. A. Greenwood (1984), "A unified theory of surface roughness", Proc. R.
//!   Soc. Lond. A 393, 133–157 (summits on a sampled map).
//! * J. A. Greenwood, J. B. P. Williamson (1966), Proc. R. Soc. Lond. A 295,
//!   300–319, [doi:10.1098/rspa.1966.0242](https://doi.org/10.1098/rspa.1966.0242).

use super::{check_heights, mean, Topography};
use crate::error::{check, Result};
use serde::Serialize;

/// A profile peak.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Peak {
    /// Sample index.
    pub index: usize,
    /// Position j·dx from the first sample (m).
    pub x: f64,
    /// Height above the mean line (m).
    pub height: f64,
    /// Curvature −z″ (1/m), three-point second difference.
    pub curvature: f64,
}

/// A summit of a map.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Summit {
    /// Index along x.
    pub i: usize,
    /// Index along y.
    pub j: usize,
    /// Position i·dx (m).
    pub x: f64,
    /// Position j·dy (m).
    pub y: f64,
    /// Height above the mean plane (m).
    pub height: f64,
    /// Mean curvature −(z_xx + z_yy)/2 (1/m).
    pub curvature: f64,
}

/// Summary of detected peaks or summits.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PeakStatistics {
    /// Number found.
    pub count: usize,
    /// Density: per metre of profile, or per square metre of map.
    pub density: f64,
    /// Mean height above the mean line (m).
    pub mean_height: f64,
    /// Standard deviation of the heights (m).
    pub height_std: f64,
    /// Mean curvature (1/m); mean radius ≈ 1/this.
    pub mean_curvature: f64,
}

impl PeakStatistics {
    /// Statistics of `(height, curvature)` pairs over `extent` (m or m²).
    fn from_pairs(pairs: impl Iterator<Item = (f64, f64)>, extent: f64) -> Self {
        let (mut n, mut sh, mut sh2, mut sk) = (0usize, 0.0, 0.0, 0.0);
        for (h, k) in pairs {
            n += 1;
            sh += h;
            sh2 += h * h;
            sk += k;
        }
        let nf = n.max(1) as f64;
        let mh = sh / nf;
        PeakStatistics {
            count: n,
            density: n as f64 / extent,
            mean_height: mh,
            height_std: (sh2 / nf - mh * mh).max(0.0).sqrt(),
            mean_curvature: sk / nf,
        }
    }

    /// Statistics of profile peaks over a profile of length `length` (m).
    pub fn of_peaks(peaks: &[Peak], length: f64) -> Self {
        Self::from_pairs(peaks.iter().map(|p| (p.height, p.curvature)), length)
    }

    /// Statistics of summits over a map of area `area` (m²).
    pub fn of_summits(summits: &[Summit], area: f64) -> Self {
        Self::from_pairs(summits.iter().map(|s| (s.height, s.curvature)), area)
    }
}

/// Peaks of `heights` (m) at spacing `dx` (m); see the module docs. The end
/// samples are never peaks.
///
/// Errors: fewer than 3 or non-finite heights; `dx` not finite and > 0.
pub fn peaks(heights: &[f64], dx: f64) -> Result<Vec<Peak>> {
    check::positive("dx", dx)?;
    check_heights(heights, 3, ">= 3 points")?;
    let z = heights;
    let n = z.len();
    let zbar = mean(z);
    let mut out = Vec::new();
    let mut j = 1;
    while j + 1 < n {
        if z[j] > z[j - 1] {
            // Extend over a flat top.
            let mut e = j;
            while e + 1 < n && z[e + 1] == z[j] {
                e += 1;
            }
            if e + 1 < n && z[e + 1] < z[j] {
                let c = (j + e) / 2;
                out.push(Peak {
                    index: c,
                    x: c as f64 * dx,
                    height: z[c] - zbar,
                    curvature: -(z[c + 1] - 2.0 * z[c] + z[c - 1]) / (dx * dx),
                });
            }
            j = e + 1;
        } else {
            j += 1;
        }
    }
    Ok(out)
}

/// Summits of a map; see the module docs. Border points are never summits.
pub fn summits(t: &Topography) -> Vec<Summit> {
    summits_unchecked(t.heights(), t.nx(), t.ny(), t.dx(), t.dy())
}

/// Summits of a row-major `nx × ny` grid `heights` (m),
/// `heights[j*nx + i] = z(x_i, y_j)`, spacings `dx`, `dy` (m) — the slice form
/// of [`summits`].
///
/// Errors: `dx`, `dy` not finite and > 0; nx or ny < 2; `heights.len() !=
/// nx*ny`; non-finite heights.
pub fn summits_grid(
    heights: &[f64],
    nx: usize,
    ny: usize,
    dx: f64,
    dy: f64,
) -> Result<Vec<Summit>> {
    check::positive("dx", dx)?;
    check::positive("dy", dy)?;
    if nx < 2 || ny < 2 || heights.len() != nx * ny {
        return Err(crate::error::Error::InvalidArgument {
            name: "heights.len()",
            value: heights.len() as f64,
            bound: "== nx * ny with nx, ny >= 2",
        });
    }
    check_heights(heights, 4, ">= 4 points")?;
    Ok(summits_unchecked(heights, nx, ny, dx, dy))
}

fn summits_unchecked(z: &[f64], nx: usize, ny: usize, dx: f64, dy: f64) -> Vec<Summit> {
    let zbar = mean(z);
    let mut out = Vec::new();
    for j in 1..ny.saturating_sub(1) {
        for i in 1..nx - 1 {
            let c = z[j * nx + i];
            let mut top = true;
            'nb: for dj in [-1isize, 0, 1] {
                for di in [-1isize, 0, 1] {
                    if di == 0 && dj == 0 {
                        continue;
                    }
                    let k = ((j as isize + dj) as usize) * nx + (i as isize + di) as usize;
                    if z[k] >= c {
                        top = false;
                        break 'nb;
                    }
                }
            }
            if top {
                let zxx = (z[j * nx + i + 1] - 2.0 * c + z[j * nx + i - 1]) / (dx * dx);
                let zyy = (z[(j + 1) * nx + i] - 2.0 * c + z[(j - 1) * nx + i]) / (dy * dy);
                out.push(Summit {
                    i,
                    j,
                    x: i as f64 * dx,
                    y: j as f64 * dy,
                    height: c - zbar,
                    curvature: -(zxx + zyy) / 2.0,
                });
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_tops_count_once() {
        let z = [0.0, 1.0, 2.0, 2.0, 2.0, 1.0, 0.0, 1.0, 0.5, 0.5];
        let p = peaks(&z, 1.0).unwrap();
        assert_eq!(p.len(), 2);
        assert_eq!(p[0].index, 3);
        assert_eq!(p[1].index, 7);
        assert!((p[1].curvature - 1.5).abs() < 1e-12);
    }

    #[test]
    fn summits_of_a_bump_grid() {
        // z = cos x cos y: summits at (2πa, 2πb) and (π + 2πa, π + 2πb).
        let (nx, ny) = (64, 64);
        let d = 4.0 * core::f64::consts::PI / 64.0;
        let h: Vec<f64> = (0..nx * ny)
            .map(|k| {
                let (i, j) = (k % nx, k / nx);
                (i as f64 * d).cos() * (j as f64 * d).cos()
            })
            .collect();
        let t = Topography::new(nx, ny, d, d, h).unwrap();
        let s = summits(&t);
        // Interior maxima: (π, π), (π, 3π), (3π, π), (3π, 3π), (2π, 2π).
        assert_eq!(s.len(), 5, "{s:?}");
        for m in &s {
            assert!((m.curvature - 1.0).abs() < 0.01, "{}", m.curvature);
        }
    }
}
