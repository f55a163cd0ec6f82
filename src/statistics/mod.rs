//! Statistical multi-asperity models: Zhuravlev, Greenwood–Williamson,
//! Bush–Gibson–Thomas, Kragelsky's rod assembly and the power-law asperity
//! extensions through rescaling (thesis sections 1.6–1.7, 3.7, 5.3–5.4).
//!
//! All of them sum independent single-asperity responses over a distribution
//! of summit heights:
//!
//! * [`zhuravlev`]: two rough surfaces of Hertzian caps, summit density
//!   linear in depth (closed forms (1-25)..(1-28): $P \propto x^{11/2}$,
//!   $S \propto x^5$, $\mu \propto P^{-1/11}$) or any density by quadrature
//!   ((1-23), (1-24)).
//! * [`greenwood_williamson`]: a rough surface of equal-radius Hertzian
//!   summits against a flat, Gaussian, exponential or empirical heights
//!   ((1-29), (1-30)), its inverse (separation at a load) and the plasticity
//!   index (1-31).
//! * [`bush_gibson_thomas`]: Bush, Gibson & Thomas (1975), §5.3.3: an
//!   isotropic Gaussian surface given by its spectral moments, whose summits
//!   (Nayak's random-process model) are elliptic paraboloids in Hertz
//!   contact ([`elliptic_hertz`]); small-load limit
//!   `A = √(2π) P/(E*√⟨|∇h|²⟩)`.
//! * [`bora`]: the real nano-topography model of Bora et al. (2013), §5.3.9:
//!   one spring per point of a measured height map on an elastic half-space
//!   (Love's square loads), solved as a complementarity problem.
//! * [`borodich_kryukova`]: Borodich & Kryukova (1997), §5.3.7: a block on a
//!   moving belt, both faces covered with elastic rough layers, integrated
//!   in time.
//! * [`kragelsky`]: Kragelsky's assembly of elastic rods (5-7).
//! * [`sergienko_bukharov`]: Sergienko & Bukharov (2015), §5.3.5: a rigid
//!   body oscillating normally on Kragelsky's rods; the dynamic lift and the
//!   drop of the friction with the amplitude (formulated from the thesis's
//!   description).
//! * [`power_law`]: asperities `B r^d` on a material `σ ∝ ε^κ`, through
//!   Borodich's rescaling of one known solution ((3-27), (3-28)).
//!
//! The height integrals live in [`heights`] (distributions and their tail
//! moments) and [`gaussian`] (the Gaussian `F_q(h)`, accurate to 1e-12 and
//! cheap: one short trapezoidal sum per evaluation; timings in
//! BENCHMARKS.md §6).
//!
//! Units: SI. Separations d (m) are heights of the counter-surface's
//! reference plane in the frame of the summit heights (zero-mean for the
//! parametric distributions); approaches x (m) are measured downwards from the
//! first touch. Every result is a [`MultiAsperityResponse`].
//!
//! # Formulas
//!
//! Every model is a sum of single-asperity responses over the summit heights,
//!
//! $$P(d) = N\int_d^\infty f(z-d)\\,\varphi(z)\\,dz,$$
//!
//! with $f(w) = \tfrac43 E^\ast R^{1/2} w^{3/2}$ (Greenwood–Williamson), $f(w) = kw$
//! (Kragelsky), $f(w) \propto w^{(2+\kappa(d-1))/d}$ (power-law asperities), or
//! the pair double integral of Zhuravlev.
//!
//! # References
//!
//! * Thesis §§1.6–1.7, 3.7, 5.3–5.4.
//! * V. A. Zhuravlev (1940), "On the question of theoretical justification of
//!   the Amontons–Coulomb law for friction of unlubricated surfaces",
//!   Zh. Tekh. Fiz. 10 (in Russian).
//! * J. A. Greenwood, J. B. P. Williamson (1966), Proc. R. Soc. Lond. A 295,
//!   300–319, [doi:10.1098/rspa.1966.0242](https://doi.org/10.1098/rspa.1966.0242).
//! * I. V. Kragelsky, M. N. Dobychin, V. S. Kombalov (1982), *Friction and Wear:
//!   Calculation Methods*, Pergamon Press, Oxford.
//! * The single modules cite the details.

pub mod bora;
pub mod borodich_kryukova;
pub mod bush_gibson_thomas;
pub mod elliptic_hertz;
pub mod gaussian;
pub mod greenwood_williamson;
pub mod heights;
pub mod kragelsky;
pub mod power_law;
mod quadrature;
pub mod sergienko_bukharov;
pub mod zhuravlev;

pub use bora::{BoraSolution, BoraTopography};
pub use borodich_kryukova::{BorodichKryukova, Sinusoid, SliderSample, SliderState};
pub use bush_gibson_thomas::{BgtResponse, BushGibsonThomas};
pub use elliptic_hertz::EllipticHertz;
pub use greenwood_williamson::GreenwoodWilliamson;
pub use heights::{EmpiricalHeights, HeightDistribution};
pub use kragelsky::{BearingCurveRods, KragelskyRods};
pub use power_law::PowerLawAsperities;
pub use quadrature::Quadrature;
pub use sergienko_bukharov::{
    Excitation, Integration, SergienkoBukharov, SergienkoBukharovRun, SergienkoBukharovSample,
};
pub use zhuravlev::{Zhuravlev, ZhuravlevFriction};

use crate::error::{check, Error, Result};

/// The response of an assembly of asperities at one separation (or approach).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct MultiAsperityResponse {
    /// Total normal load P (N), ≥ 0, compressive.
    pub load: f64,
    /// Real (true) contact area A (m²), ≥ 0.
    pub area: f64,
    /// Expected number of asperities (or asperity pairs) in contact
    /// (dimensionless, not necessarily an integer).
    pub contacts: f64,
}

impl MultiAsperityResponse {
    /// Mean real contact pressure `P/A` (Pa); 0 when nothing touches.
    pub fn mean_pressure(&self) -> f64 {
        if self.area > 0.0 {
            self.load / self.area
        } else {
            0.0
        }
    }
}

/// The separation that carries a given load, with the solver's report.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SeparationSolution {
    /// Separation d (m) at which the model carries the requested load.
    pub separation: f64,
    /// Newton/bisection iterations spent (after bracketing).
    pub iterations: u32,
    /// `|P(d)/P_target − 1|` at the returned separation.
    pub relative_residual: f64,
}

/// Plasticity index of Greenwood & Williamson (1966), thesis (1-31):
/// `ψ = (E*/H) √(σ/R)`, with the contact modulus E* (Pa), the hardness H
/// (Pa), the standard deviation σ of the summit heights (m) and the summit
/// radius R (m), all finite and > 0. It does not depend on the load: below
/// about 0.6 the contact stays elastic, above 1 it is plastic even at light
/// loads ([`DeformationRegime`]).
pub fn plasticity_index(e_star: f64, hardness: f64, sigma: f64, radius: f64) -> Result<f64> {
    let e = check::positive("e_star", e_star)?;
    let h = check::positive("hardness", hardness)?;
    let s = check::positive("sigma", sigma)?;
    let r = check::positive("radius", radius)?;
    Ok(e / h * (s / r).sqrt())
}

/// GW 1966's reading of the plasticity index (REFERENCE §8).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum DeformationRegime {
    /// ψ < 0.6: plastic flow only at impractically high nominal pressures.
    Elastic,
    /// 0.6 ≤ ψ ≤ 1.
    Transitional,
    /// ψ > 1: most contacts flow plastically even at light loads.
    Plastic,
}

impl DeformationRegime {
    /// The regime of a plasticity index ψ (finite, ≥ 0).
    pub fn of(plasticity_index: f64) -> Result<Self> {
        let psi = check::non_negative("plasticity_index", plasticity_index)?;
        Ok(if psi < 0.6 {
            Self::Elastic
        } else if psi <= 1.0 {
            Self::Transitional
        } else {
            Self::Plastic
        })
    }
}

/// Largest number of bracketing steps or iterations of [`solve_separation`].
const MAX_ITERATIONS: u32 = 200;

/// Solve `P(d) = target` for a load `P` that decreases with d, by Newton's
/// method on `ln P` safeguarded with bisection. `eval(d)` returns
/// `(P, dP/dd)`; `scale` (m, > 0) is a length for the bracketing steps from
/// `start`; `zero_above`, when given, is a separation at and above which
/// `P = 0` (the highest summit of an empirical list).
pub(crate) fn solve_separation(
    target: f64,
    start: f64,
    scale: f64,
    zero_above: Option<f64>,
    eval: impl Fn(f64) -> Result<(f64, f64)>,
) -> Result<SeparationSolution> {
    let not_bracketed = |_: f64| Error::OutOfDomain {
        name: "load",
        value: target,
        reason: "no finite separation carries this load (bracketing failed)",
    };
    // Bracket: P(lo) ≥ target ≥ P(hi).
    let (mut lo, mut hi);
    let mut step = scale;
    match zero_above {
        Some(top) => {
            hi = top;
            lo = top - scale;
        }
        None => {
            hi = start;
            let mut n = 0;
            while eval(hi)?.0 > target {
                hi += step;
                step *= 2.0;
                n += 1;
                if n > MAX_ITERATIONS || !hi.is_finite() {
                    return Err(not_bracketed(hi));
                }
            }
            lo = start;
            step = scale;
        }
    }
    let mut n = 0;
    let mut p_lo = eval(lo)?;
    while p_lo.0 < target {
        hi = hi.min(lo);
        lo -= step;
        step *= 2.0;
        n += 1;
        if n > MAX_ITERATIONS || !lo.is_finite() {
            return Err(not_bracketed(lo));
        }
        p_lo = eval(lo)?;
    }
    // Newton on g(d) = ln(P/target) from the loaded end of the bracket.
    let ln_target = target.ln();
    let mut d = lo;
    let (mut p, mut dp) = p_lo;
    for iteration in 1..=MAX_ITERATIONS {
        let g = p.ln() - ln_target;
        if p > 0.0 && g.abs() <= 1e-13 {
            return Ok(SeparationSolution {
                separation: d,
                iterations: iteration - 1,
                relative_residual: (p / target - 1.0).abs(),
            });
        }
        if p >= target {
            lo = d;
        } else {
            hi = d;
        }
        let newton = if p > 0.0 && dp < 0.0 {
            d - g * p / dp
        } else {
            f64::NAN
        };
        let next = if newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        if (hi - lo) <= 4.0 * f64::EPSILON * (lo.abs() + hi.abs()) || next == d {
            // The bracket has collapsed to rounding: accept if the load is
            // met (P is continuous), refuse a load below what f64 resolves.
            let residual = (p / target - 1.0).abs();
            if residual > 1e-9 {
                return Err(Error::NotConverged {
                    what: "separation at load",
                    iterations: iteration,
                    residual,
                });
            }
            return Ok(SeparationSolution {
                separation: d,
                iterations: iteration,
                relative_residual: residual,
            });
        }
        d = next;
        (p, dp) = eval(d)?;
    }
    Err(Error::NotConverged {
        what: "separation at load",
        iterations: MAX_ITERATIONS,
        residual: (p / target - 1.0).abs(),
    })
}
