//! Zhuravlev's model (1940; thesis §1.7, (1-23)..(1-28)): two statistically
//! identical rough surfaces of spherical caps of radius R, summit density
//! `n(ξ)` per unit depth ξ below the highest summit (N summits in all).
//!
//! # Formulas
//!
//! At the approach x of the two highest-summit planes, the caps at depths
//! ξ₁, ξ₂ overlap by `x − (ξ₁ + ξ₂)`, and the Hertz law of a pair (effective
//! radius `R_eff = R/2`, contact modulus E*) gives the load (1-23) and the
//! real area (1-24)
//!
//! $$P = \tfrac43 E^\ast R_\mathrm{eff}^{1/2}\\,\frac1N\iint_{\xi_1+\xi_2 \le x}\bigl(x - (\xi_1+\xi_2)\bigr)^{3/2} n(\xi_1)\\,n(\xi_2)\\,d\xi_1\\,d\xi_2, \qquad S = \pi R_\mathrm{eff}\\,\frac1N\iint \bigl(x - (\xi_1+\xi_2)\bigr)\\,n\\,n\\,d\xi_1\\,d\xi_2 ,$$
//!
//! and the number of contacting pairs $\frac1N\iint n\\,n\\,d\xi_1\\,d\xi_2$,
//! where `n(ξ₂)dξ₂/N` is the probability that a summit of one surface meets
//! one of the other in the layer dξ₂. With `E* = E/(2(1−ν²))` the prefactor
//! of the load is the thesis's `√2 R^{1/2} E/(3(1−ν²))`. Zhuravlev's linear
//! density $n(\xi) = \alpha\xi$ gives the double integrals in closed form,
//! hence the load (1-25) and the area (1-26) and, with the friction force
//! proportional to the area (1-27), the friction law (1-28):
//!
//! $$\alpha^2\int_0^x (x-s)^q\\,\frac{s^3}{6}\\,ds = \alpha^2 x^{q+4}\\,\frac{\Gamma(q+1)}{\Gamma(q+5)}, \qquad P = C_1 x^{11/2}, \quad S = C_2 x^5, \quad F = \tau S \propto P^{10/11}, \quad \mu \propto P^{-1/11} .$$
//!
//! The coefficient of friction is nearly independent of the load, as
//! Zhuravlev argued.
//!
//! The double integrals are those of [`crate::rescaling`]
//! ([`zhuravlev_integral_linear`] in closed form, [`zhuravlev_integral`] by
//! Gauss–Legendre quadrature for any density); this module adds the Hertz
//! prefactors, the inversion at a given load and the friction law. The
//! power-law asperity version (3-27), (3-28) is
//! [`super::PowerLawAsperities::zhuravlev_linear`].
//!
//! # References
//!
//! * Thesis §1.7, (1-23)–(1-28).
//! * V. A. Zhuravlev (1940), "On the question of theoretical justification of
//!   the Amontons–Coulomb law for friction of unlubricated surfaces",
//!   Zh. Tekh. Fiz. 10 (in Russian); English translation with a commentary by
//!   F. M. Borodich in Proc. Inst. Mech. Eng. J 221 (2007).
//! * H. Hertz (1882), J. reine angew. Math. 92, 156–171,
//!   [doi:10.1515/crll.1882.92.156](https://doi.org/10.1515/crll.1882.92.156).

use super::MultiAsperityResponse;
use crate::error::{check, Error, Result};
use crate::rescaling::{zhuravlev_exponent, zhuravlev_integral, zhuravlev_integral_linear};

/// Exponent of the approach in the load for Zhuravlev's linear density,
/// `P ∝ x^{11/2}` (1-25).
pub const LOAD_EXPONENT: f64 = 5.5;
/// Exponent of the approach in the real area, `S ∝ x⁵` (1-26).
pub const AREA_EXPONENT: f64 = 5.0;
/// Exponent of the load in the friction force, `F ∝ P^{10/11}` (1-28).
pub const FRICTION_LOAD_EXPONENT: f64 = 10.0 / 11.0;

/// Zhuravlev's pair of rough surfaces: the Hertz law of two caps and the
/// summit count that normalises the meeting probability.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Zhuravlev {
    effective_radius: f64,
    e_star: f64,
    summit_count: f64,
}

/// Friction of Zhuravlev's model at one load ((1-27), (1-28)).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ZhuravlevFriction {
    /// Approach x (m) that carries the load.
    pub approach: f64,
    /// The load P (N).
    pub load: f64,
    /// Real contact area S (m²).
    pub area: f64,
    /// Friction force `F = τ S` (N), (1-27).
    pub friction_force: f64,
    /// Coefficient of friction `μ = F/P` (dimensionless).
    pub coefficient: f64,
}

impl Zhuravlev {
    /// Zhuravlev's setting: both surfaces carry caps of radius `cap_radius`
    /// (m, > 0), so a pair has `R_eff = R/2`; contact modulus `e_star`
    /// (Pa, > 0; `E/(2(1−ν²))` for identical materials); `summit_count` N
    /// (> 0).
    pub fn new(cap_radius: f64, e_star: f64, summit_count: f64) -> Result<Self> {
        let r = check::positive("cap_radius", cap_radius)?;
        Self::with_effective_radius(0.5 * r, e_star, summit_count)
    }

    /// The same with the pair's effective radius `1/R_eff = 1/R₁ + 1/R₂`
    /// (m, > 0) given directly.
    pub fn with_effective_radius(
        effective_radius: f64,
        e_star: f64,
        summit_count: f64,
    ) -> Result<Self> {
        Ok(Self {
            effective_radius: check::positive("effective_radius", effective_radius)?,
            e_star: check::positive("e_star", e_star)?,
            summit_count: check::positive("summit_count", summit_count)?,
        })
    }

    /// Effective radius of a pair of caps (m).
    pub fn effective_radius(&self) -> f64 {
        self.effective_radius
    }

    /// Contact modulus E* (Pa).
    pub fn e_star(&self) -> f64 {
        self.e_star
    }

    /// Summit count N.
    pub fn summit_count(&self) -> f64 {
        self.summit_count
    }

    /// `(4/3) E* R_eff^{1/2} / N`, the factor of (1-23).
    fn load_factor(&self) -> f64 {
        4.0 / 3.0 * self.e_star * self.effective_radius.sqrt() / self.summit_count
    }

    /// `π R_eff / N`, the factor of (1-24).
    fn area_factor(&self) -> f64 {
        core::f64::consts::PI * self.effective_radius / self.summit_count
    }

    /// Hertz exponent 3/2 of a pair, from the rescaling exponent with κ = 1,
    /// d = 2.
    fn hertz_exponent() -> Result<f64> {
        zhuravlev_exponent(1.0, 2.0)
    }

    /// Load, real area and contacting pairs at approach `approach` x (m, ≥ 0)
    /// for the linear densities `n_i(ξ) = α_i ξ` (`alpha1`, `alpha2` in m⁻²,
    /// finite and > 0): the closed forms (1-25), (1-26),
    /// `P = (4/3)E*R_eff^{1/2} α₁α₂ Γ(5/2)/(N Γ(13/2)) x^{11/2}`,
    /// `S = π R_eff α₁α₂ x⁵/(120 N)`, pairs `α₁α₂ x⁴/(24 N)`.
    pub fn linear(&self, alpha1: f64, alpha2: f64, approach: f64) -> Result<MultiAsperityResponse> {
        let a1 = check::positive("alpha1", alpha1)?;
        let a2 = check::positive("alpha2", alpha2)?;
        let x = check::non_negative("approach", approach)?;
        let q = Self::hertz_exponent()?;
        Ok(MultiAsperityResponse {
            load: self.load_factor() * zhuravlev_integral_linear(q, x, a1, a2)?,
            area: self.area_factor() * zhuravlev_integral_linear(1.0, x, a1, a2)?,
            contacts: zhuravlev_integral_linear(0.0, x, a1, a2)? / self.summit_count,
        })
    }

    /// Load, real area and contacting pairs at approach `approach` (m, ≥ 0)
    /// for arbitrary summit densities `n1`, `n2` (m⁻¹, ≥ 0 on ξ ≥ 0) by
    /// Gauss–Legendre quadrature of `order` (4..=64) points per dimension
    /// ((1-23), (1-24); [`zhuravlev_integral`]). A density that makes a
    /// negative integral is reported as [`Error::OutOfDomain`].
    pub fn response(
        &self,
        approach: f64,
        n1: impl Fn(f64) -> f64,
        n2: impl Fn(f64) -> f64,
        order: usize,
    ) -> Result<MultiAsperityResponse> {
        let x = check::non_negative("approach", approach)?;
        let q = Self::hertz_exponent()?;
        let i_load = zhuravlev_integral(q, x, &n1, &n2, order)?;
        let i_area = zhuravlev_integral(1.0, x, &n1, &n2, order)?;
        let i_count = zhuravlev_integral(0.0, x, &n1, &n2, order)?;
        if i_load < 0.0 || i_area < 0.0 || i_count < 0.0 {
            return Err(Error::OutOfDomain {
                name: "n1",
                value: i_count,
                reason: "the summit densities must be non-negative",
            });
        }
        Ok(MultiAsperityResponse {
            load: self.load_factor() * i_load,
            area: self.area_factor() * i_area,
            contacts: i_count / self.summit_count,
        })
    }

    /// The approach x (m) that carries `load` (N, ≥ 0) with linear densities,
    /// inverting (1-25): `x = (P/C₁)^{2/11}`.
    pub fn approach_at_load_linear(&self, alpha1: f64, alpha2: f64, load: f64) -> Result<f64> {
        let a1 = check::positive("alpha1", alpha1)?;
        let a2 = check::positive("alpha2", alpha2)?;
        let p = check::non_negative("load", load)?;
        let q = Self::hertz_exponent()?;
        let c1 = self.load_factor() * zhuravlev_integral_linear(q, 1.0, a1, a2)?;
        Ok((p / c1).powf(1.0 / (q + 4.0)))
    }

    /// Friction at `load` (N, > 0) for linear densities and the interfacial
    /// shear strength `shear_strength` τ (Pa, ≥ 0; Zhuravlev's α of (1-27),
    /// "a coefficient depending on the cohesive forces"): `F = τ S` (1-27),
    /// which is `F = τ C₂ (P/C₁)^{10/11}` (1-28), and `μ = F/P ∝ P^{−1/11}`.
    pub fn friction_linear(
        &self,
        alpha1: f64,
        alpha2: f64,
        load: f64,
        shear_strength: f64,
    ) -> Result<ZhuravlevFriction> {
        let p = check::positive("load", load)?;
        let tau = check::non_negative("shear_strength", shear_strength)?;
        let x = self.approach_at_load_linear(alpha1, alpha2, p)?;
        let r = self.linear(alpha1, alpha2, x)?;
        let f = tau * r.area;
        Ok(ZhuravlevFriction {
            approach: x,
            load: p,
            area: r.area,
            friction_force: f,
            coefficient: f / p,
        })
    }
}
