//! Archard's hierarchical model (1957; thesis 1.6.2, 5.4.1): a sphere of
//! radius R₁ covered with spheres of radius R₂ ≪ R₁, each covered with
//! spheres of radius R₃, …, all elastic (contact modulus E*), the load of
//! each generation spread over the next by the Hertz pressure.
//!
//! # Formulas
//!
//! A single sphere under load w has the Hertz contact radius
//! a = (3wR/4E*)^{1/3} and area πa² ∝ w^{2/3}. If the spheres of generation
//! k+1 sit at the areal density η_{k+1} on a sphere of generation k whose
//! contact carries the Hertz pressure p(r) = (3w/2πa²)√(1 − r²/a²), each
//! carries p(r)/η_{k+1}; when they obey A = c w^α,
//!
//! $$A_k(w) = \int_0^{a} \eta\, c \Big(\frac{p(r)}{\eta}\Big)^{\alpha} 2\pi r\,dr
//!   = c\,\eta^{1-\alpha}\Big(\frac{3w}{2\pi a^2}\Big)^{\alpha}\frac{2\pi a^2}{\alpha + 2}
//!   \ \propto\ w^{(2+\alpha)/3},$$
//!
//! so each generation maps the exponent α to (2 + α)/3 and the model stays
//! a power law A = c W^a, built exactly from the finest generation up.
//!
//! * [`ArchardModel::Uniform`]: the finest spheres are Hertzian (α = 2/3):
//!   a = 2/3, 8/9, 26/27, 80/81, … = 1 − 3⁻ⁿ for n generations (Archard's
//!   models with protuberances of equal height).
//! * [`ArchardModel::NonUniform`]: the finest protuberances (radius Rₙ,
//!   density ηₙ) stand at heights that follow the rigid surface of
//!   generation n−1 (Archard's protuberances at different heights: the
//!   number in contact grows with the load). Under a compression δ₀ of that
//!   surface the protuberance at r is compressed by δ₀ − r²/2R_{n−1}, and
//!   W = η 2πR_{n−1} (8/15) E* √Rₙ δ₀^{5/2}, A = η π² R_{n−1} Rₙ δ₀², so
//!   α = 4/5 and a = 4/5, 14/15, 44/45, … = 1 − 1/(5·3ⁿ⁻²).
//!
//! Either way a → 1 as generations are added: the area becomes proportional
//! to the load (Amontons) although every contact is elastic.
//!
//! **Validity.** The integral replaces the sum over the spheres of the next
//! generation: it holds while many of them touch within each contact
//! (η πa² ≫ 1), and the model ignores the coupling of neighbouring contacts
//! (Greenwood and Tripp 1967), as the thesis notes.
//!
//! # References
//!
//! * J. F. Archard, "Elastic deformation and the laws of friction", Proc.
//!   R. Soc. Lond. A 243 (1957) 190–205.
//! * J. A. Greenwood, J. H. Tripp, "The elastic contact of rough spheres",
//!   J. Appl. Mech. 34 (1967) 153–159.

use crate::error::{check, Error, Result};
use core::f64::consts::PI;

/// Which finest generation Archard's hierarchy ends with.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(i32)]
pub enum ArchardModel {
    /// Hertzian spheres of equal height at every generation (2/3, 8/9, …).
    Uniform = 0,
    /// The finest protuberances at heights following the surface under them
    /// (4/5, 14/15, 44/45, …).
    NonUniform = 1,
}

impl ArchardModel {
    /// The model of a C selector (0 uniform, 1 non-uniform); the error
    /// names `model`.
    pub fn from_i32(model: i32) -> Result<Self> {
        match model {
            0 => Ok(Self::Uniform),
            1 => Ok(Self::NonUniform),
            other => Err(Error::UnknownSelector {
                name: "model",
                value: other as i64,
            }),
        }
    }
}

/// The exponent a of A ∝ W^a for `generations` ≥ 1 sphere radii (≥ 2 for
/// the non-uniform model): 1 − 3⁻ⁿ, or 1 − 1/(5·3ⁿ⁻²). Errors name
/// `generations`.
pub fn archard_exponent(model: ArchardModel, generations: usize) -> Result<f64> {
    let min = match model {
        ArchardModel::Uniform => 1,
        ArchardModel::NonUniform => 2,
    };
    if generations < min || generations > 64 {
        return Err(Error::InvalidArgument {
            name: "generations",
            value: generations as f64,
            bound: "in [1, 64] (uniform) or [2, 64] (non-uniform)",
        });
    }
    Ok(match model {
        ArchardModel::Uniform => 1.0 - 3f64.powi(-(generations as i32)),
        ArchardModel::NonUniform => 1.0 - 1.0 / (5.0 * 3f64.powi(generations as i32 - 2)),
    })
}

/// Archard's hierarchy of spheres (immutable).
#[derive(Debug, Clone, PartialEq)]
pub struct Archard {
    model: ArchardModel,
    /// ln c of A = c W^a (c overflows for deep hierarchies).
    ln_coefficient: f64,
    exponent: f64,
    generations: usize,
}

impl Archard {
    /// The hierarchy `model` of sphere radii `radii` R₁ > R₂ > … (m, finite
    /// and positive, decreasing; 1 to 64 of them, ≥ 2 for the non-uniform
    /// model),
    /// `densities` η₂, η₃, … (1/m², finite, > 0; one fewer than the radii):
    /// the number of spheres of generation k per unit area of generation
    /// k−1, and the contact modulus `contact_modulus` E* (Pa, finite, > 0).
    /// Errors name the argument.
    pub fn new(
        model: ArchardModel,
        radii: &[f64],
        densities: &[f64],
        contact_modulus: f64,
    ) -> Result<Self> {
        let n = radii.len();
        archard_exponent(model, n).map_err(|e| e.renamed("generations", "radii.len()"))?;
        if densities.len() + 1 != n {
            return Err(Error::InvalidArgument {
                name: "densities.len()",
                value: densities.len() as f64,
                bound: "radii.len() - 1",
            });
        }
        for (i, &r) in radii.iter().enumerate() {
            check::positive("radii", r)?;
            if i > 0 && r >= radii[i - 1] {
                return Err(Error::InvalidArgument {
                    name: "radii",
                    value: r,
                    bound: "decreasing: each generation's spheres smaller than the last",
                });
            }
        }
        for &d in densities {
            check::positive("densities", d)?;
        }
        let e = check::positive("contact_modulus", contact_modulus)?;
        // The finest law, in logs: A = exp(lc) w^alpha.
        let (mut lc, mut alpha, mut top) = match model {
            ArchardModel::Uniform => {
                // π (3R/4E*)^{2/3} w^{2/3}.
                (
                    PI.ln() + 2.0 / 3.0 * (0.75 * radii[n - 1] / e).ln(),
                    2.0 / 3.0,
                    n - 1,
                )
            }
            ArchardModel::NonUniform => {
                let (rb, rp, eta) = (radii[n - 2], radii[n - 1], densities[n - 2]);
                // W = K δ^{5/2}, A = B δ²: A = B (W/K)^{4/5}.
                let k = eta * 2.0 * PI * rb * (8.0 / 15.0) * e * rp.sqrt();
                let b = eta * PI * PI * rb * rp;
                (b.ln() - 0.8 * k.ln(), 0.8, n - 2)
            }
        };
        // Up the hierarchy: generation j carries generation j+1.
        while top > 0 {
            let j = top - 1;
            let eta = densities[j];
            // a_j² = κ w^{2/3}, κ = (3R_j/4E*)^{2/3}.
            let ln_kappa = 2.0 / 3.0 * (0.75 * radii[j] / e).ln();
            lc = lc + (1.0 - alpha) * eta.ln() + alpha * (1.5 / PI).ln() - alpha * ln_kappa
                + (2.0 * PI).ln()
                + ln_kappa
                - (alpha + 2.0).ln();
            alpha = (2.0 + alpha) / 3.0;
            top = j;
        }
        Ok(Self {
            model,
            ln_coefficient: lc,
            exponent: alpha,
            generations: n,
        })
    }

    /// The model.
    pub fn model(&self) -> ArchardModel {
        self.model
    }

    /// Number of sphere generations (radii).
    pub fn generations(&self) -> usize {
        self.generations
    }

    /// The exponent a of A = c W^a.
    pub fn exponent(&self) -> f64 {
        self.exponent
    }

    /// ln c of A = c W^a (c in m²/N^a).
    pub fn ln_coefficient(&self) -> f64 {
        self.ln_coefficient
    }

    /// The real contact area A (m²) under the load `load` W (N, finite,
    /// ≥ 0). Errors name `load`; an area that overflows is `OutOfDomain`.
    pub fn area(&self, load: f64) -> Result<f64> {
        let w = check::non_negative("load", load)?;
        if w == 0.0 {
            return Ok(0.0);
        }
        let a = (self.ln_coefficient + self.exponent * w.ln()).exp();
        if a.is_finite() {
            Ok(a)
        } else {
            Err(Error::OutOfDomain {
                name: "load",
                value: load,
                reason: "the contact area overflows",
            })
        }
    }
}
