//! Kragelsky's rod assembly (Kragelsky 1948; Kragelsky, Dobychin & Kombalov
//! 1982; thesis §5.3.4, (5-7)): the asperities are elastic rods of constant
//! cross-section and random height, each compressed independently by the
//! counter-surface, so a rod of height z carries `k (z − d)` at the separation
//! d (k its axial stiffness `E A_rod/L`).
//!
//! # Formulas
//!
//! [`KragelskyRods`]: any height distribution ([`HeightDistribution`]), rods
//! of stiffness $k$ and section $A_\mathrm{rod}$:
//!
//! $$P = Nk\int_d^\infty (z-d)\\,\varphi(z)\\,dz, \qquad A = N A_\mathrm{rod}\int_d^\infty \varphi(z)\\,dz, \qquad n = N\int_d^\infty \varphi(z)\\,dz .$$
//!
//! Load and area are exactly proportional for exponential heights and nearly
//! so for Gaussian ones.
//!
//! [`BearingCurveRods`]: Kragelsky's own closed form, with the top of the
//! roughness described by the bearing-area curve
//! $\eta(\varepsilon) = b\\,\varepsilon^\nu$ (the fraction of the contour area
//! A_c cut at the relative approach $\varepsilon = a/R_\mathrm{max}$), the
//! real area, the load, and K the rod stiffness per unit area (`E/L`, Pa/m):
//!
//! $$A_r = A_c\\, b\\,\varepsilon^\nu, \qquad N = \frac{K A_c\\, b\\, R_\mathrm{max}\\,\varepsilon^{\nu+1}}{\nu+1} = \gamma_1\gamma_2 A_c K a^{\nu+1}, \qquad \gamma_1 = \frac{b}{R_\mathrm{max}^\nu}, \ \ \gamma_2 = \frac{1}{\nu+1} .$$
//!
//! The thesis's (5-7) is unreadable in the extracted text; the form above is
//! the rod model's own integral with the thesis's names (N the load, A_c the
//! contour area, a the approach, γ₁, γ₂ factors of the distribution, K the
//! stiffness), and it is checked against [`KragelskyRods`] on a sampled
//! bearing curve in `tests/statistics.rs`.
//!
//! # References
//!
//! * Thesis §5.3.4, (5-7).
//! * I. V. Kragelsky (1948), the rod model of rough contact (in Russian; as
//!   cited by the thesis, §5.3.4).
//! * I. V. Kragelsky, M. N. Dobychin, V. S. Kombalov (1982), *Friction and Wear:
//!   Calculation Methods*, Pergamon Press, Oxford.

use super::heights::HeightDistribution;
use super::{solve_separation, MultiAsperityResponse, SeparationSolution};
use crate::error::{check, Error, Result};

/// An assembly of N elastic rods with random heights.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct KragelskyRods {
    rod_count: f64,
    rod_area: f64,
    rod_stiffness: f64,
    heights: HeightDistribution,
}

impl KragelskyRods {
    /// `rod_count` N (> 0), cross-section `rod_area` (m², > 0), axial
    /// `rod_stiffness` k (N/m, > 0) and the rod-top `heights`.
    pub fn new(
        rod_count: f64,
        rod_area: f64,
        rod_stiffness: f64,
        heights: HeightDistribution,
    ) -> Result<Self> {
        heights.validate()?;
        Ok(Self {
            rod_count: check::positive("rod_count", rod_count)?,
            rod_area: check::positive("rod_area", rod_area)?,
            rod_stiffness: check::positive("rod_stiffness", rod_stiffness)?,
            heights,
        })
    }

    /// Rods of Young's modulus `youngs_modulus` (Pa, > 0) and length
    /// `rod_length` (m, > 0): `k = E A_rod/L`.
    pub fn from_material(
        rod_count: f64,
        rod_area: f64,
        rod_length: f64,
        youngs_modulus: f64,
        heights: HeightDistribution,
    ) -> Result<Self> {
        let a = check::positive("rod_area", rod_area)?;
        let l = check::positive("rod_length", rod_length)?;
        let e = check::positive("youngs_modulus", youngs_modulus)?;
        Self::new(rod_count, a, e * a / l, heights)
    }

    /// Number of rods N.
    pub fn rod_count(&self) -> f64 {
        self.rod_count
    }

    /// Cross-section A_rod of one rod (m²).
    pub fn rod_area(&self) -> f64 {
        self.rod_area
    }

    /// Axial stiffness k of one rod (N/m).
    pub fn rod_stiffness(&self) -> f64 {
        self.rod_stiffness
    }

    /// The rod-top height distribution.
    pub fn heights(&self) -> &HeightDistribution {
        &self.heights
    }

    fn load_unchecked(&self, d: f64) -> Result<f64> {
        Ok(self.rod_count * self.rod_stiffness * self.heights.tail_moment_unchecked(1.0, d)?)
    }

    /// Load `P = N k ∫_d^∞ (z − d) φ dz` (N) at `separation` d (m, finite).
    pub fn load(&self, separation: f64) -> Result<f64> {
        self.load_unchecked(check::finite("separation", separation)?)
    }

    /// Load, real area `N A_rod ∫_d^∞ φ dz` and rods in contact at
    /// `separation` (m, finite).
    pub fn response(&self, separation: f64) -> Result<MultiAsperityResponse> {
        let d = check::finite("separation", separation)?;
        let contacts = self.rod_count * self.heights.tail_moment_unchecked(0.0, d)?;
        Ok(MultiAsperityResponse {
            load: self.load_unchecked(d)?,
            area: contacts * self.rod_area,
            contacts,
        })
    }

    /// The separation (m) that carries `load` (N, > 0), by Newton's method
    /// (slope `−N k ∫_d^∞ φ dz`) with bisection safeguard.
    pub fn separation_at_load(&self, load: f64) -> Result<SeparationSolution> {
        let target = check::positive("load", load)?;
        let zero_above = match &self.heights {
            HeightDistribution::Empirical(e) => Some(e.max()),
            _ => None,
        };
        let nk = self.rod_count * self.rod_stiffness;
        solve_separation(target, 0.0, self.heights.scale(), zero_above, |d| {
            Ok((
                nk * self.heights.tail_moment_unchecked(1.0, d)?,
                -nk * self.heights.tail_moment_unchecked(0.0, d)?,
            ))
        })
    }
}

/// Kragelsky's rods with a power-law bearing-area curve `η(ε) = b ε^ν`.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct BearingCurveRods {
    contour_area: f64,
    stiffness_per_area: f64,
    b: f64,
    nu: f64,
    max_height: f64,
    rod_area: f64,
}

impl BearingCurveRods {
    /// Contour (nominal) area `contour_area` A_c (m², > 0), rod stiffness per
    /// unit area `stiffness_per_area` K = E/L (Pa/m, > 0), bearing-curve
    /// coefficient `b` (> 0; the fraction `b ε^ν` must stay ≤ 1 at the
    /// approaches used) and exponent `nu` ν (> 0; typically 1–3), the
    /// maximum roughness height `max_height` R_max (m, > 0) and the rod
    /// cross-section `rod_area` (m², > 0; only for the number of contacts).
    pub fn new(
        contour_area: f64,
        stiffness_per_area: f64,
        b: f64,
        nu: f64,
        max_height: f64,
        rod_area: f64,
    ) -> Result<Self> {
        Ok(Self {
            contour_area: check::positive("contour_area", contour_area)?,
            stiffness_per_area: check::positive("stiffness_per_area", stiffness_per_area)?,
            b: check::positive("b", b)?,
            nu: check::positive("nu", nu)?,
            max_height: check::positive("max_height", max_height)?,
            rod_area: check::positive("rod_area", rod_area)?,
        })
    }

    fn check_approach(&self, approach: f64) -> Result<f64> {
        let a = check::non_negative("approach", approach)?;
        if self.b * (a / self.max_height).powf(self.nu) > 1.0 {
            return Err(Error::OutOfDomain {
                name: "approach",
                value: a,
                reason: "the bearing-area fraction b (a/R_max)^nu exceeds 1",
            });
        }
        Ok(a)
    }

    /// Load `N = K A_c b R_max ε^{ν+1}/(ν+1)`, real area `A_c b ε^ν` and
    /// rods in contact `A_r/A_rod` at `approach` a (m, ≥ 0, with
    /// `b ε^ν ≤ 1`), ε = a/R_max ((5-7)).
    pub fn response(&self, approach: f64) -> Result<MultiAsperityResponse> {
        let a = self.check_approach(approach)?;
        let eps = a / self.max_height;
        let area = self.contour_area * self.b * eps.powf(self.nu);
        let load = self.stiffness_per_area * area * a / (self.nu + 1.0);
        Ok(MultiAsperityResponse {
            load,
            area,
            contacts: area / self.rod_area,
        })
    }

    /// The approach (m) carrying `load` (N, ≥ 0): inverting (5-7),
    /// `a = [(ν+1) N R_max^ν/(K A_c b)]^{1/(ν+1)}`.
    pub fn approach_at_load(&self, load: f64) -> Result<f64> {
        let p = check::non_negative("load", load)?;
        let a = ((self.nu + 1.0) * p * self.max_height.powf(self.nu)
            / (self.stiffness_per_area * self.contour_area * self.b))
            .powf(1.0 / (self.nu + 1.0));
        self.check_approach(a)
    }
}
