//! Functional parameters of the material-ratio (Abbott–Firestone) curve:
//! the ISO 13565-2 profile parameters Rk, Rpk, Rvk, Mr1, Mr2 and the
//! ISO 25178-2 areal ones Sk, Spk, Svk, Smr1, Smr2, Vmp, Vmc, Vvc, Vvv. The
//! construction is the same for a profile and a map: only the set of heights
//! matters.
//!
//! Conventions:
//!
//! * Heights Z = z − z̄ from the mean line or plane (remove form and filter
//!   first, as for [`super::iso`]). Each of the n samples stands for an
//!   equal share 1/n of the length or area.
//! * The curve c(Mr) through the heights sorted in decreasing order,
//!   Z₍₁₎ ≥ … ≥ Z₍ₙ₎, placed at Mr_k = (k − ½)/n and interpolated linearly
//!   (constant beyond the first and last points).
//! * The equivalent straight line (ISO 13565-2 §4.1): among the secants of
//!   c(Mr) between Mr_a and Mr_a + 40 %, Mr_a stepping through the points
//!   Mr_k ≤ 60 %, the one of least gradient (least |slope|; the first on a
//!   tie). It meets Mr = 0 at c₁ and Mr = 100 % at c₂.
//! * Rk = c₁ − c₂; Mr1 = Rmr(c₁), Mr2 = Rmr(c₂), the fractions of samples at
//!   or above these levels.
//! * Rpk and Rvk are the heights of the triangles of the same areas as the
//!   peaks above c₁ and the valleys below c₂: the areas are the sample means
//!   A₁ = mean(max(Z − c₁, 0)), A₂ = mean(max(c₂ − Z, 0)) (the exact areas
//!   under the step curve), Rpk = 2A₁/Mr1, Rvk = 2A₂/(1 − Mr2) (0 when
//!   Mr1 = 0 or Mr2 = 1).
//! * Volumes (ISO 25178-2 §4.4, per unit area, m³/m² = m): with the level
//!   c(mr) of ratio mr, Vm(mr) = mean(max(Z − c(mr), 0)) and
//!   Vv(mr) = mean(max(c(mr) − Z, 0)); Vmp = Vm(p), Vmc = Vm(q) − Vm(p),
//!   Vvv = Vv(q), Vvc = Vv(p) − Vv(q), p = 10 %, q = 80 % by default.
//!
//! Ratios are fractions in [0, 1] in the Rust values (ISO prints them in %).
//!
//! # Formulas
//!
//! $$R_k = c_1 - c_2,\qquad R_{pk} = \frac{2A_1}{M_{r1}},\qquad R_{vk} = \frac{2A_2}{1 - M_{r2}},\qquad A_1 = \int_0^{M_{r1}} \bigl(c(M_r) - c_1\bigr)\\,dM_r,\quad A_2 = \int_{M_{r2}}^1 \bigl(c_2 - c(M_r)\bigr)\\,dM_r,$$
//!
//! $$V_m(m_r) = \int_0^{m_r} \bigl(c(M_r) - c(m_r)\bigr)\\,dM_r,\qquad V_v(m_r) = \int_{m_r}^1 \bigl(c(m_r) - c(M_r)\bigr)\\,dM_r .$$
//!
//! For a curve that is linear with slope −s over the core (the 40 % secant
//! inside it) and linear over the peak and valley zones, Rk = s, Rpk =
//! c(0) − c₁ and Rvk = c₂ − c(1) exactly.
//!
//! # References
//!
//! * ISO 13565-2:1996, *Geometrical Product Specifications (GPS) — Surface
//!   texture: Profile method; Surfaces having stratified functional
//!   properties — Part 2: Height characterization using the linear material
//!   ratio curve*.
//! * ISO 25178-2:2012, *Geometrical product specifications (GPS) — Surface
//!   texture: Areal — Part 2: Terms, definitions and surface texture
//!   parameters*, §4.4 (functional parameters Sk, Spk, Svk, Smr1, Smr2; Vmp,
//!   Vmc, Vvc, Vvv).

use super::{check_heights, mean, Topography};
use crate::error::{check, Result};
use serde::{Deserialize, Serialize};

/// ISO 13565-2 parameters of a profile's material-ratio curve (lengths in
/// m, ratios as fractions in [0, 1]). Serialised as `Rk`, `Rpk`, `Rvk`,
/// `Mr1`, `Mr2`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct MaterialRatioParameters {
    /// Core roughness depth Rk = c₁ − c₂ (m).
    #[serde(rename = "Rk")]
    pub rk: f64,
    /// Reduced peak height Rpk (m).
    #[serde(rename = "Rpk")]
    pub rpk: f64,
    /// Reduced valley depth Rvk (m).
    #[serde(rename = "Rvk")]
    pub rvk: f64,
    /// Material ratio Mr1 at the top of the core, c₁ (fraction).
    #[serde(rename = "Mr1")]
    pub mr1: f64,
    /// Material ratio Mr2 at the bottom of the core, c₂ (fraction).
    #[serde(rename = "Mr2")]
    pub mr2: f64,
}

/// ISO 25178-2 functional parameters of a map (heights in m, volumes in
/// m³/m² = m, ratios as fractions in [0, 1]). Serialised with the ISO
/// symbols (`Sk`, …, `Vvv`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct FunctionalParameters {
    /// Core height Sk (m).
    #[serde(rename = "Sk")]
    pub sk: f64,
    /// Reduced peak height Spk (m).
    #[serde(rename = "Spk")]
    pub spk: f64,
    /// Reduced dale height Svk (m).
    #[serde(rename = "Svk")]
    pub svk: f64,
    /// Areal material ratio Smr1 at the top of the core (fraction).
    #[serde(rename = "Smr1")]
    pub smr1: f64,
    /// Areal material ratio Smr2 at the bottom of the core (fraction).
    #[serde(rename = "Smr2")]
    pub smr2: f64,
    /// Peak material volume Vmp = Vm(p) (m³/m²).
    #[serde(rename = "Vmp")]
    pub vmp: f64,
    /// Core material volume Vmc = Vm(q) − Vm(p) (m³/m²).
    #[serde(rename = "Vmc")]
    pub vmc: f64,
    /// Core void volume Vvc = Vv(p) − Vv(q) (m³/m²).
    #[serde(rename = "Vvc")]
    pub vvc: f64,
    /// Dale void volume Vvv = Vv(q) (m³/m²).
    #[serde(rename = "Vvv")]
    pub vvv: f64,
}

/// Heights from the mean, sorted in decreasing order.
fn sorted_from_mean(heights: &[f64]) -> Result<Vec<f64>> {
    check_heights(heights, 2, ">= 2 points")?;
    let zbar = mean(heights);
    let mut z: Vec<f64> = heights.iter().map(|h| h - zbar).collect();
    z.sort_unstable_by(|a, b| b.total_cmp(a));
    Ok(z)
}

/// c(Mr) of the sorted heights `z` (decreasing): linear between the points
/// Mr_k = (k + ½)/n (0-based k), constant outside.
fn level(z: &[f64], mr: f64) -> f64 {
    let n = z.len();
    let t = mr * n as f64 - 0.5;
    if t <= 0.0 {
        return z[0];
    }
    let k = t.floor() as usize;
    if k + 1 >= n {
        return z[n - 1];
    }
    let f = t - k as f64;
    z[k] + f * (z[k + 1] - z[k])
}

/// Fraction of the samples at or above `c`.
fn ratio_at(z: &[f64], c: f64) -> f64 {
    z.partition_point(|&v| v >= c) as f64 / z.len() as f64
}

/// mean(max(Z − c, 0)): the material volume above level c per unit length
/// or area.
fn material_above(z: &[f64], c: f64) -> f64 {
    let k = z.partition_point(|&v| v > c);
    z[..k].iter().map(|v| v - c).sum::<f64>() / z.len() as f64
}

/// mean(max(c − Z, 0)): the void volume below level c.
fn void_below(z: &[f64], c: f64) -> f64 {
    let k = z.partition_point(|&v| v >= c);
    z[k..].iter().map(|v| c - v).sum::<f64>() / z.len() as f64
}

/// The 40 % secant of least gradient: (c₁, c₂), its levels at Mr = 0 and 1.
fn equivalent_line(z: &[f64]) -> (f64, f64) {
    const WIDTH: f64 = 0.4;
    let n = z.len();
    let mut best: Option<(f64, f64)> = None; // (slope, intercept)
    for k in 0..n {
        let a = (k as f64 + 0.5) / n as f64;
        if a > 1.0 - WIDTH + 1e-12 {
            break;
        }
        let slope = (level(z, a + WIDTH) - z[k]) / WIDTH;
        // Slopes are ≤ 0: the least gradient is the largest slope; strict
        // comparison keeps the first of equal ones.
        if best.map_or(true, |(s, _)| slope > s) {
            best = Some((slope, z[k] - slope * a));
        }
    }
    let (slope, c1) = best.unwrap_or((z[n - 1] - z[0], z[0]));
    (c1, c1 + slope)
}

/// The ISO 13565-2 core: (c₁, c₂, Mr1, Mr2, Rpk, Rvk).
fn core(z: &[f64]) -> (f64, f64, f64, f64, f64, f64) {
    let (c1, c2) = equivalent_line(z);
    let mr1 = ratio_at(z, c1);
    let mr2 = ratio_at(z, c2);
    let a1 = material_above(z, c1);
    let a2 = void_below(z, c2);
    let rpk = if mr1 > 0.0 { 2.0 * a1 / mr1 } else { 0.0 };
    let rvk = if mr2 < 1.0 {
        2.0 * a2 / (1.0 - mr2)
    } else {
        0.0
    };
    (c1, c2, mr1, mr2, rpk, rvk)
}

/// ISO 13565-2 parameters of a profile's heights (m); see the module docs.
/// Use the roughness profile (ISO 13565-1 specifies a robust filter; the
/// Gaussian one is the common substitute).
///
/// Errors: fewer than 2 heights or non-finite ones.
pub fn material_ratio_parameters(heights: &[f64]) -> Result<MaterialRatioParameters> {
    let z = sorted_from_mean(heights)?;
    let (c1, c2, mr1, mr2, rpk, rvk) = core(&z);
    Ok(MaterialRatioParameters {
        rk: c1 - c2,
        rpk,
        rvk,
        mr1,
        mr2,
    })
}

/// ISO 25178-2 functional parameters of heights (m) with the volume ratios
/// `p`, `q` (fractions, 0 ≤ p < q ≤ 1; ISO defaults 0.1 and 0.8). The slice
/// form of [`functional_parameters`].
///
/// Errors: fewer than 2 heights or non-finite ones; `p`, `q` outside
/// 0 ≤ p < q ≤ 1 (named `p` or `q`).
pub fn functional_parameters_of(heights: &[f64], p: f64, q: f64) -> Result<FunctionalParameters> {
    check::in_range("p", p, 0.0, 1.0, "in [0, 1]")?;
    check::in_range("q", q, p, 1.0, "in (p, 1]")?;
    if q <= p {
        return Err(crate::error::Error::InvalidArgument {
            name: "q",
            value: q,
            bound: "> p",
        });
    }
    let z = sorted_from_mean(heights)?;
    let (c1, c2, mr1, mr2, spk, svk) = core(&z);
    let (cp, cq) = (level(&z, p), level(&z, q));
    let (vm_p, vm_q) = (material_above(&z, cp), material_above(&z, cq));
    let (vv_p, vv_q) = (void_below(&z, cp), void_below(&z, cq));
    Ok(FunctionalParameters {
        sk: c1 - c2,
        spk,
        svk,
        smr1: mr1,
        smr2: mr2,
        vmp: vm_p,
        vmc: vm_q - vm_p,
        vvc: vv_p - vv_q,
        vvv: vv_q,
    })
}

/// ISO 25178-2 functional parameters of a map with the default ratios
/// p = 10 %, q = 80 %; see [`functional_parameters_of`].
pub fn functional_parameters(t: &Topography) -> Result<FunctionalParameters> {
    functional_parameters_of(t.heights(), 0.1, 0.8)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolated_curve() {
        let z = [3.0, 1.0, 0.0, -4.0];
        assert_eq!(level(&z, 0.0), 3.0);
        assert_eq!(level(&z, 0.125), 3.0);
        assert_eq!(level(&z, 0.25), 2.0);
        assert_eq!(level(&z, 1.0), -4.0);
        assert_eq!(ratio_at(&z, 1.0), 0.5);
        assert_eq!(material_above(&z, 1.0), 0.5);
        assert_eq!(void_below(&z, 0.0), 1.0);
    }
}
