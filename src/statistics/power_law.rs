//! Power-law asperities and nonlinear materials through Borodich's rescaling
//! (thesis §3.7, (3-27), (3-28)).
//!
//! # Formulas
//!
//! An asperity `B r^d` pressed by w into a material `σ ∝ ε^κ` carries, by the
//! rescaling of one known solution `(P₁, δ₁, a₁)` at shape scale `B₁`
//! ((3-13), (3-14), (3-24); [`crate::rescaling`]), with
//! $q = (2 + \kappa(d-1))/d$ and $\lambda = B/B_1$, the load and (eliminating
//! P between (3-13) and (3-14)) the contact radius
//!
//! $$P(w) = \lambda^{(\kappa-2)/d} P_1 \Bigl(\frac{w}{\delta_1}\Bigr)^q, \qquad a(w) = a_1\lambda^{-1/d}\Bigl(\frac{w}{\delta_1}\Bigr)^{1/d} .$$
//!
//! Summing over summit heights:
//!
//! * Greenwood–Williamson type (against a flat):
//!
//!   $$P = N\lambda^{(\kappa-2)/d}\frac{P_1}{\delta_1^q}\int_d^\infty (z-d)^q\varphi\\,dz, \qquad A = N\pi a_1^2\lambda^{-2/d}\delta_1^{-2/d}\int_d^\infty (z-d)^{2/d}\varphi\\,dz ;$$
//!
//! * Zhuravlev type (two rough surfaces, pair interference
//!   `x − (ξ₁ + ξ₂)`): `P = λ^{(κ−2)/d} (P₁/δ₁^q) (1/N) ∫∫ [x − (ξ₁+ξ₂)]^q n n`
//!   — (3-27) for κ = 1 (exponent `(d+1)/d`, prefactor `λ^{−1/d}`) and (3-28)
//!   for any κ. For two power-law summits of the same d the gap is a power
//!   law of coefficient `B_upper + B_lower`, which λ then refers to; (3-28)
//!   holds when both materials share κ or one is rigid (thesis §3.7).
//!
//! κ = 1, d = 2 with a Hertz solution is Greenwood–Williamson, resp.
//! Zhuravlev: `q = 3/2`, area exponent 1 (tested in `tests/statistics.rs`).
//!
//! # References
//!
//! * Thesis §3.7, (3-13), (3-14), (3-24), (3-27), (3-28).
//! * F. M. Borodich (1983), "Similarity in the problem of contact between
//!   elastic bodies", J. Appl. Math. Mech. (PMM) 47, 440–442; F. M. Borodich
//!   (1993), "The Hertz frictional contact between nonlinear elastic
//!   anisotropic bodies (the similarity approach)", Int. J. Solids Struct. 30,
//!   1513–1526.
//! * J. A. Greenwood, J. B. P. Williamson (1966), Proc. R. Soc. Lond. A 295,
//!   300–319, [doi:10.1098/rspa.1966.0242](https://doi.org/10.1098/rspa.1966.0242).

use super::heights::HeightDistribution;
use super::MultiAsperityResponse;
use crate::contact::power_punch::{check_shape, galin_c, galin_d};
use crate::error::{check, Error, Result};
use crate::rescaling::{
    zhuravlev_integral, zhuravlev_integral_linear, zhuravlev_prefactor, KnownSolution, Rescaling,
};

/// Identical power-law asperities on a power-law material, described by one
/// known solution and the rescaling exponents.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct PowerLawAsperities {
    rescaling: Rescaling,
    lambda: f64,
    known: KnownSolution,
    load_coefficient: f64,
    radius_coefficient: f64,
}

impl PowerLawAsperities {
    /// Asperities of shape scale `lambda` = B/B₁ (> 0) relative to the punch
    /// of the `known` solution `(P₁, δ₁, a₁)`, on the material and shape
    /// exponents of `rescaling` (κ ∈ [0, 10], d ∈ [1, 100]).
    pub fn new(rescaling: Rescaling, lambda: f64, known: KnownSolution) -> Result<Self> {
        let rescaling = Rescaling::new(rescaling.kappa, rescaling.d)?;
        let known = KnownSolution::new(known.load, known.depth, known.radius)?;
        let lambda = check::positive("lambda", lambda)?;
        let load_coefficient = zhuravlev_prefactor(&rescaling, lambda, &known)?;
        // a(w) = c_a w^{1/d}: rescale the known point to λ and read c_a there.
        let p = rescaling.load(lambda, known.depth, &known)?;
        let a = rescaling.radius(lambda, p, &known)?;
        let radius_coefficient = a / known.depth.powf(1.0 / rescaling.d);
        if !(load_coefficient.is_finite() && radius_coefficient.is_finite())
            || load_coefficient <= 0.0
            || radius_coefficient <= 0.0
        {
            return Err(Error::OutOfDomain {
                name: "known",
                value: known.depth,
                reason: "the rescaled asperity law is not representable in f64",
            });
        }
        Ok(Self {
            rescaling,
            lambda,
            known,
            load_coefficient,
            radius_coefficient,
        })
    }

    /// Linear-elastic (κ = 1) asperities `b r^d` (b in m^{1−d}, > 0;
    /// 1 ≤ d ≤ 100) on contact modulus `e_star` (Pa, > 0): the known solution
    /// is Galin's (1-19)..(1-22) at a₁ = 1 m, `P₁ = C(d) b E*`,
    /// `δ₁ = D(d) b`, and λ = 1.
    pub fn elastic(b: f64, d: f64, e_star: f64) -> Result<Self> {
        let (b, d) = check_shape(b, d)?;
        let e = check::positive("e_star", e_star)?;
        let known = KnownSolution::new(galin_c(d) * b * e, galin_d(d) * b, 1.0)?;
        Self::new(Rescaling::new(1.0, d)?, 1.0, known)
    }

    /// Hertzian asperities of radius `radius` (m, > 0): `elastic(1/(2R), 2, E*)`.
    pub fn sphere(radius: f64, e_star: f64) -> Result<Self> {
        let r = check::positive("radius", radius)?;
        Self::elastic(0.5 / r, 2.0, e_star)
    }

    /// The rescaling exponents (κ, d).
    pub fn rescaling(&self) -> Rescaling {
        self.rescaling
    }

    /// Load exponent `q = (2 + κ(d−1))/d` of one asperity, the integrand
    /// exponent of (3-27), (3-28).
    pub fn exponent(&self) -> f64 {
        self.rescaling.load_depth_exponent()
    }

    /// Area exponent `2/d` of one asperity (`πa² ∝ w^{2/d}`).
    pub fn area_exponent(&self) -> f64 {
        2.0 / self.rescaling.d
    }

    /// Load of one asperity at overlap `depth` (m, ≥ 0), (3-24):
    /// `λ^{(κ−2)/d} (w/δ₁)^q P₁`.
    pub fn asperity_load(&self, depth: f64) -> Result<f64> {
        self.rescaling.load(self.lambda, depth, &self.known)
    }

    /// Contact radius of one asperity at overlap `depth` (m, ≥ 0),
    /// `a₁ λ^{−1/d} (w/δ₁)^{1/d}` ((3-13) with (3-14)).
    pub fn asperity_contact_radius(&self, depth: f64) -> Result<f64> {
        let w = check::non_negative("depth", depth)?;
        Ok(self.radius_coefficient * w.powf(1.0 / self.rescaling.d))
    }

    /// Greenwood–Williamson-type sum over `summit_count` N (> 0) asperities
    /// with summit `heights` against a flat at `separation` d (m, finite):
    /// `P = N λ^{(κ−2)/d}(P₁/δ₁^q) M_q(d)`, `A = N π c_a² M_{2/d}(d)`,
    /// `n = N M_0(d)` with the tail moments `M_q` of
    /// [`HeightDistribution::tail_moment`] (per-summit radii of an empirical
    /// list do not apply: the shape is `B r^d`).
    pub fn greenwood_williamson(
        &self,
        summit_count: f64,
        heights: &HeightDistribution,
        separation: f64,
    ) -> Result<MultiAsperityResponse> {
        let n = check::positive("summit_count", summit_count)?;
        let d = check::finite("separation", separation)?;
        heights.validate()?;
        let ca = self.radius_coefficient;
        Ok(MultiAsperityResponse {
            load: n * self.load_coefficient * heights.tail_moment_unchecked(self.exponent(), d)?,
            area: n
                * core::f64::consts::PI
                * ca
                * ca
                * heights.tail_moment_unchecked(self.area_exponent(), d)?,
            contacts: n * heights.tail_moment_unchecked(0.0, d)?,
        })
    }

    /// Zhuravlev-type sum (3-27), (3-28) for the linear summit densities
    /// `n_i(ξ) = α_i ξ` (m⁻², > 0) at approach x (m, ≥ 0), in closed form:
    /// `P = λ^{(κ−2)/d}(P₁/δ₁^q) α₁α₂ Γ(q+1)/(N Γ(q+5)) x^{q+4}`, so
    /// `P ∝ x^{q+4}`, `A ∝ x^{2/d+4}` and `F = τA ∝ P^{(2/d+4)/(q+4)}`.
    pub fn zhuravlev_linear(
        &self,
        summit_count: f64,
        alpha1: f64,
        alpha2: f64,
        approach: f64,
    ) -> Result<MultiAsperityResponse> {
        let n = check::positive("summit_count", summit_count)?;
        let a1 = check::positive("alpha1", alpha1)?;
        let a2 = check::positive("alpha2", alpha2)?;
        let x = check::non_negative("approach", approach)?;
        let ca = self.radius_coefficient;
        Ok(MultiAsperityResponse {
            load: self.load_coefficient / n
                * zhuravlev_integral_linear(self.exponent(), x, a1, a2)?,
            area: core::f64::consts::PI * ca * ca / n
                * zhuravlev_integral_linear(self.area_exponent(), x, a1, a2)?,
            contacts: zhuravlev_integral_linear(0.0, x, a1, a2)? / n,
        })
    }

    /// Zhuravlev-type sum (3-27), (3-28) for arbitrary summit densities `n1`,
    /// `n2` (m⁻¹, ≥ 0) at approach x (m, ≥ 0), by Gauss–Legendre quadrature of
    /// `order` (4..=64) points per dimension ([`zhuravlev_integral`]).
    pub fn zhuravlev(
        &self,
        summit_count: f64,
        approach: f64,
        n1: impl Fn(f64) -> f64,
        n2: impl Fn(f64) -> f64,
        order: usize,
    ) -> Result<MultiAsperityResponse> {
        let n = check::positive("summit_count", summit_count)?;
        let x = check::non_negative("approach", approach)?;
        let ca = self.radius_coefficient;
        let load = zhuravlev_integral(self.exponent(), x, &n1, &n2, order)?;
        let area = zhuravlev_integral(self.area_exponent(), x, &n1, &n2, order)?;
        let count = zhuravlev_integral(0.0, x, &n1, &n2, order)?;
        if load < 0.0 || area < 0.0 || count < 0.0 {
            return Err(Error::OutOfDomain {
                name: "n1",
                value: count,
                reason: "the summit densities must be non-negative",
            });
        }
        Ok(MultiAsperityResponse {
            load: self.load_coefficient / n * load,
            area: core::f64::consts::PI * ca * ca / n * area,
            contacts: count / n,
        })
    }
}
