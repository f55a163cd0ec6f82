//! Greenwood–Williamson (1966): a rough surface of N summits of equal radius
//! R and random heights against a rigid (or equivalent) flat, each summit a
//! Hertz contact with the overlap `z − d` (thesis §1.7, (1-29), (1-30)).
//!
//! # Formulas
//!
//! The load (1-29), the real area (1-30), the number of contacts, the
//! stiffness, and the plasticity index (1-31), which says whether the
//! summits stay elastic:
//!
//! $$P = \tfrac43 N E^\ast R^{1/2}\int_d^\infty (z-d)^{3/2}\varphi(z)\\,dz, \qquad A = \pi N R\int_d^\infty (z-d)\\,\varphi(z)\\,dz, \qquad n = N\int_d^\infty \varphi(z)\\,dz,$$
//!
//! $$-\frac{dP}{dd} = 2NE^\ast R^{1/2}\int_d^\infty (z-d)^{1/2}\varphi(z)\\,dz, \qquad \psi = \frac{E^\ast}{H}\sqrt{\frac{\sigma}{R}} .$$
//!
//! with d the separation of the flat from the mean summit height and φ the
//! summit-height density ([`HeightDistribution`]). Two rough surfaces reduce
//! to one against a flat with `1/R = 1/R₁ + 1/R₂`, `σ² = σ₁² + σ₂²`
//! (GW 1966; Greenwood & Tripp 1970).
//!
//! For Gaussian heights of standard deviation $\sigma$ the integrals are
//! $\sigma^q F_q(d/\sigma)$ ([`super::gaussian`]): an evaluation of the load
//! costs one trapezoidal sum of at most 61 exponentials (relative accuracy
//! 1e-12; timings in BENCHMARKS.md §6) and allocates nothing.
//!
//! Area and load are nearly proportional (GW 1966): for Gaussian heights the
//! mean real pressure `P/A = (4/(3π)) E* (σ/R)^{1/2} F_{3/2}/F₁` falls by a
//! factor 1.364 (±15 % about its mid value) while the load falls by three
//! decades (d/σ from 1 to 3.33), the local exponent d ln A / d ln P rising
//! from 0.922 to 0.972; for exponential heights it is exactly constant,
//! `E* √(σ/(πR))`.
//!
//! # References
//!
//! * Thesis §1.7, (1-29)–(1-31).
//! * J. A. Greenwood, J. B. P. Williamson (1966), "Contact of nominally flat
//!   surfaces", Proc. R. Soc. Lond. A 295, 300–319,
//!   [doi:10.1098/rspa.1966.0242](https://doi.org/10.1098/rspa.1966.0242).
//! * J. A. Greenwood, J. H. Tripp (1970), "The contact of two nominally flat
//!   rough surfaces", Proc. Inst. Mech. Eng. 185, 625–633,
//!   [doi:10.1243/PIME_PROC_1970_185_069_02](https://doi.org/10.1243/PIME_PROC_1970_185_069_02).

use super::gaussian;
use super::heights::HeightDistribution;
use super::{solve_separation, MultiAsperityResponse, SeparationSolution};
use crate::error::{check, Result};

/// A Greenwood–Williamson rough surface.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct GreenwoodWilliamson {
    summit_count: f64,
    radius: f64,
    e_star: f64,
    heights: HeightDistribution,
}

const FOUR_THIRDS: f64 = 4.0 / 3.0;

impl GreenwoodWilliamson {
    /// `summit_count` N (summits on the nominal area, `η A_n`; finite, > 0),
    /// summit `radius` R (m, > 0; per-summit radii of an empirical list take
    /// its place in the load and area), contact modulus `e_star` E* (Pa, > 0)
    /// and the summit `heights`.
    pub fn new(
        summit_count: f64,
        radius: f64,
        e_star: f64,
        heights: HeightDistribution,
    ) -> Result<Self> {
        heights.validate()?;
        Ok(Self {
            summit_count: check::positive("summit_count", summit_count)?,
            radius: check::positive("radius", radius)?,
            e_star: check::positive("e_star", e_star)?,
            heights,
        })
    }

    /// Number of summits N.
    pub fn summit_count(&self) -> f64 {
        self.summit_count
    }

    /// Summit radius R (m).
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// Contact modulus E* (Pa).
    pub fn e_star(&self) -> f64 {
        self.e_star
    }

    /// The summit-height distribution.
    pub fn heights(&self) -> &HeightDistribution {
        &self.heights
    }

    /// `(4/3) N E* R^{1/2}` (N·m^{−3/2}), the factor of (1-29).
    #[inline]
    fn load_factor(&self) -> f64 {
        FOUR_THIRDS * self.summit_count * self.e_star * self.radius.sqrt()
    }

    /// Load P (N) at separation `separation` (m, finite), (1-29).
    ///
    /// Errors with [`crate::Error::OutOfDomain`] naming `separation` when the
    /// result overflows `f64` (so do [`Self::area`], [`Self::contacts`],
    /// [`Self::response`] and [`Self::stiffness`]): a separation or
    /// parameters near the ends of `f64`, e.g. d = −4e211 m.
    pub fn load(&self, separation: f64) -> Result<f64> {
        let d = check::finite("separation", separation)?;
        overflow(self.load_unchecked(d)?, d)
    }

    fn load_unchecked(&self, d: f64) -> Result<f64> {
        match &self.heights {
            // The hot path: σ^{3/2} F_{3/2}(d/σ) without the general dispatch.
            HeightDistribution::Gaussian { sigma } => Ok(self.load_factor()
                * sigma
                * sigma.sqrt()
                * gaussian::half_integer(2, d / sigma)),
            HeightDistribution::Empirical(e) if e.radii().is_some() => {
                Ok(FOUR_THIRDS * self.summit_count * self.e_star * e.weighted_moment(1.5, d, 0.5))
            }
            h => Ok(self.load_factor() * h.tail_moment_unchecked(1.5, d)?),
        }
    }

    /// Real contact area A (m²) at `separation` (m, finite), (1-30).
    pub fn area(&self, separation: f64) -> Result<f64> {
        let d = check::finite("separation", separation)?;
        overflow(self.area_unchecked(d)?, d)
    }

    fn area_unchecked(&self, d: f64) -> Result<f64> {
        let pi_n = core::f64::consts::PI * self.summit_count;
        match &self.heights {
            HeightDistribution::Empirical(e) if e.radii().is_some() => {
                Ok(pi_n * e.weighted_moment(1.0, d, 1.0))
            }
            h => Ok(pi_n * self.radius * h.tail_moment_unchecked(1.0, d)?),
        }
    }

    /// Expected number of summits in contact `n = N ∫_d^∞ φ dz` at
    /// `separation` (m, finite).
    pub fn contacts(&self, separation: f64) -> Result<f64> {
        let d = check::finite("separation", separation)?;
        overflow(
            self.summit_count * self.heights.tail_moment_unchecked(0.0, d)?,
            d,
        )
    }

    /// Load, real area and number of contacts at `separation` (m, finite).
    pub fn response(&self, separation: f64) -> Result<MultiAsperityResponse> {
        let d = check::finite("separation", separation)?;
        Ok(MultiAsperityResponse {
            load: overflow(self.load_unchecked(d)?, d)?,
            area: overflow(self.area_unchecked(d)?, d)?,
            contacts: overflow(
                self.summit_count * self.heights.tail_moment_unchecked(0.0, d)?,
                d,
            )?,
        })
    }

    /// Normal contact stiffness `−dP/dd = 2 N E* R^{1/2} ∫_d^∞ (z−d)^{1/2} φ dz`
    /// (N/m) at `separation` (m, finite): the derivative of (1-29).
    pub fn stiffness(&self, separation: f64) -> Result<f64> {
        let d = check::finite("separation", separation)?;
        overflow(self.stiffness_unchecked(d)?, d)
    }

    fn stiffness_unchecked(&self, d: f64) -> Result<f64> {
        let two_n_e = 2.0 * self.summit_count * self.e_star;
        match &self.heights {
            HeightDistribution::Empirical(e) if e.radii().is_some() => {
                Ok(two_n_e * e.weighted_moment(0.5, d, 0.5))
            }
            h => Ok(two_n_e * self.radius.sqrt() * h.tail_moment_unchecked(0.5, d)?),
        }
    }

    /// Mean real contact pressure `P/A` (Pa) at `separation` (m); 0 when no
    /// summit touches.
    pub fn mean_pressure(&self, separation: f64) -> Result<f64> {
        Ok(self.response(separation)?.mean_pressure())
    }

    /// The separation (m) at which the surface carries `load` (N, finite,
    /// positive): the inverse of (1-29), by Newton's method on ln P (slope from
    /// [`Self::stiffness`]) safeguarded by bisection; converged to
    /// `|ln(P/P_target)| ≤ 1e-13` unless the bracket collapses to rounding
    /// first. At most 6 iterations for Gaussian and 4 for exponential heights
    /// over ten decades of load, 13 for a 500-summit empirical list (tests).
    pub fn separation_at_load(&self, load: f64) -> Result<SeparationSolution> {
        let target = check::positive("load", load)?;
        let zero_above = match &self.heights {
            HeightDistribution::Empirical(e) => Some(e.max()),
            _ => None,
        };
        solve_separation(target, 0.0, self.heights.scale(), zero_above, |d| {
            Ok((self.load_unchecked(d)?, -self.stiffness_unchecked(d)?))
        })
    }

    /// Plasticity index `ψ = (E*/H) √(σ/R)` (1-31) with the σ of the height
    /// distribution and the model's R; `hardness` H (Pa, > 0). An empirical
    /// list whose heights are all equal has σ = 0 and is rejected.
    pub fn plasticity_index(&self, hardness: f64) -> Result<f64> {
        super::plasticity_index(self.e_star, hardness, self.heights.std_dev(), self.radius)
    }
}

/// `value` when finite, else `OutOfDomain` naming `separation`.
#[inline]
fn overflow(value: f64, separation: f64) -> Result<f64> {
    check::finite_result(
        value,
        "separation",
        separation,
        "the response overflows f64 at this separation (separation or parameters near the ends of f64)",
    )
}
