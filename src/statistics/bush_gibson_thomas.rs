//! Bush, Gibson & Thomas (1975): an isotropic Gaussian rough surface whose
//! summits are elliptic paraboloids with the heights and principal curvatures
//! of Nayak's random-process model, each a Hertz contact against a rigid (or
//! equivalent) flat (thesis §5.3.3).
//!
//! The surface is given by its spectral moments (Nayak 1971), the moments of
//! a profile through it in any direction: `m₀ = σ²` (mean-square height),
//! `m₂` (mean-square profile slope) and `m₄` (mean-square profile
//! curvature), with Nayak's bandwidth parameter `α = m₀m₄/m₂² > 3/2`. The
//! separation d is the height of the flat above the mean plane of the surface
//! (not of the summits).
//!
//! # Formulas
//!
//! *Summits* (Longuet-Higgins 1957, Nayak 1971). At a point of an isotropic
//! Gaussian surface the height z, the mean curvature `k̄ = −(h_xx + h_yy)/2`
//! and the half-difference `ρ = (k₁ − k₂)/2` of the principal curvatures are
//! distributed as: (z, k̄) bivariate normal with variances m₀, `2m₄/3` and
//! covariance m₂; ρ independent, Rayleigh with parameter `s² = m₄/3`. The
//! Kac–Rice formula (the gradient, of density `1/(2πm₂)` at zero, is
//! independent of z and the Hessian) gives the summit density per unit area
//!
//! $$n(z,\bar k,\rho) = \frac{1}{2\pi m_2}\\,\phi_2(z,\bar k)\\,\frac{\rho}{s^2}e^{-\rho^2/2s^2}\\,(\bar k^2-\rho^2), \qquad 0\le\rho<\bar k,$$
//!
//! (`k̄² − ρ² = k₁k₂`, the Hessian determinant), whose integral is Nayak's
//! summit density `D = m₄/(6π√3 m₂)` (tested).
//!
//! *Contacts*. A summit of height z > d is pressed by `δ = z − d`; Hertz for
//! the elliptic paraboloid ([`super::elliptic_hertz`]) gives the area
//! `πδ F_A(λ)/√(k₁k₂)` and the load `(4/3)E* δ^{3/2} F_P(λ)/(k₁k₂)^{1/4}`
//! with `λ = k₁/k₂`. Per unit nominal area
//!
//! $$\frac{N}{A_0} = \int n, \qquad \frac{A}{A_0} = \int n\\,\frac{\pi\delta F_A}{\sqrt{k_1k_2}}, \qquad \frac{P}{A_0} = \int n\\,\frac43E^\ast\frac{\delta^{3/2}F_P}{(k_1k_2)^{1/4}},\qquad -\frac{1}{A_0}\frac{dP}{dd} = \int n\\,2E^\ast\frac{\delta^{1/2}F_P}{(k_1k_2)^{1/4}},$$
//!
//! over z > d, k̄ > 0, 0 ≤ ρ < k̄. Evaluation: the height integral given k̄
//! is a Gaussian tail moment, `s_z^q F_q((d − μ)/s_z)` with
//! `μ = 3m₂k̄/(2m₄)`, `s_z² = m₀(1 − 3/(2α))` ([`super::gaussian`]); with
//! `ρ = k̄t` the curvature-difference integral is a universal function of
//! `β = k̄/s`, `J_X(β) = ∫₀¹ t e^{−β²t²/2} w_X(t) dt`, `w_A = √(1−t²) F_A`,
//! `w_P = (1−t²)^{3/4} F_P`, `w_N = 1 − t²` (closed form), summed on a fixed
//! 205-node tanh–sinh rule whose Hertz factors are computed once per
//! process; the remaining integral over k̄ is adaptive tanh–sinh to 1e-10.
//!
//! *Small loads* (large d/σ). The summits that touch are the highest, whose
//! curvature concentrates at `k₁ ≈ k₂ ≈ m₂z/m₀` (spheres); their density
//! falls like `(m₂/m₀)(2π)^{−3/2} u² e^{−u²/2}` per unit u = z/σ. Then
//! `A/P → √π/(E*√m₂)`: with the rms gradient `√⟨|∇h|²⟩ = √(2m₂)` of the
//! isotropic surface,
//!
//! $$A = \kappa\\,\frac{P}{E^\ast\sqrt{\langle|\nabla h|^2\rangle}}, \qquad \kappa = \sqrt{2\pi} .$$
//!
//! So κ = √(2π) holds with the mean-square *gradient* of the surface
//! (`m₂` of the issue text read as ⟨|∇h|²⟩ = 2 m₂ of Nayak); with Nayak's
//! profile moment m₂ the constant is √π. This is the BGT asymptote as
//! Carbone & Bottiglione (2008) and Persson quote it (π/2 times Persson's
//! `√(8/π)`); the tests check it as d/σ grows. It is reached only at loads
//! where the touching summits are far above √α standard deviations, so for
//! broad spectra (large α) the area–load curve is not linear at practical
//! loads, Carbone & Bottiglione's point.
//!
//! # References
//!
//! * Thesis §5.3.3.
//! * A. W. Bush, R. D. Gibson, T. R. Thomas (1975), "The elastic contact of a
//!   rough surface", Wear 35, 87–111,
//!   [doi:10.1016/0043-1648(75)90145-3](https://doi.org/10.1016/0043-1648(75)90145-3).
//! * P. R. Nayak (1971), "Random process model of rough surfaces", J. Lubr.
//!   Technol. 93, 398–407,
//!   [doi:10.1115/1.3451608](https://doi.org/10.1115/1.3451608).
//! * M. S. Longuet-Higgins (1957), "The statistical analysis of a random,
//!   moving surface", Phil. Trans. R. Soc. A 249, 321–387.
//! * G. Carbone, F. Bottiglione (2008), "Asperity contact theories: Do they
//!   predict linearity between contact area and load?", J. Mech. Phys. Solids
//!   56, 2555–2572,
//!   [doi:10.1016/j.jmps.2008.03.011](https://doi.org/10.1016/j.jmps.2008.03.011).

use super::elliptic_hertz::EllipticHertz;
use super::gaussian;
use super::quadrature::tanh_sinh_n;
use super::{solve_separation, MultiAsperityResponse, SeparationSolution};
use crate::error::{check, Error, Result};
use std::sync::OnceLock;

/// κ of the small-load asymptote `A = κ P/(E* √⟨|∇h|²⟩)` (module docs):
/// √(2π). (Private: cbindgen would export a public constant to the C header.)
const KAPPA: f64 = 2.506_628_274_631_000_2;

/// Nayak's α must exceed 3/2 (at 3/2 the height and the mean curvature of a
/// summit are fully correlated and the summit distribution is degenerate).
const MIN_ALPHA: f64 = 1.5;

const FRAC_1_SQRT_2PI: f64 = 0.398_942_280_401_432_7;
/// Relative tolerance of the curvature quadrature.
const TOLERANCE: f64 = 1e-10;
/// Half-width of the mean-curvature range, in standard deviations.
const RANGE: f64 = 14.0;

/// The Bush–Gibson–Thomas rough surface.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct BushGibsonThomas {
    m0: f64,
    m2: f64,
    m4: f64,
    e_star: f64,
    nominal_area: f64,
}

/// Load, real area and contact count, with the stiffness, at one separation.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct BgtResponse {
    /// Load, real area (m²) and expected number of summits in contact.
    pub response: MultiAsperityResponse,
    /// Normal stiffness −dP/dd (N/m).
    pub stiffness: f64,
}

/// One node of the fixed rule for `J_X(β)`: `t²/2`, and the weights times
/// `t w_X(t)` for the area and the load.
struct Node {
    half_t2: f64,
    area: f64,
    load: f64,
}

/// The fixed tanh–sinh rule on t ∈ [0, 1] with the Hertz factors, built once.
fn nodes() -> &'static [Node] {
    static NODES: OnceLock<Vec<Node>> = OnceLock::new();
    NODES.get_or_init(|| {
        let step = 1.0 / 32.0;
        let mut out = Vec::new();
        let mut k = -((3.2f64 / step) as i64);
        while (k as f64) * step <= 3.2 {
            let tau = k as f64 * step;
            let u = core::f64::consts::FRAC_PI_2 * tau.sinh();
            let cosh_u = u.cosh();
            let w = 0.5 * step * core::f64::consts::FRAC_PI_2 * tau.cosh() / (cosh_u * cosh_u);
            // t = (1 + tanh u)/2, 1 − t = 1/(1 + e^{2u}) without cancellation.
            let one_minus_t = 1.0 / (1.0 + (2.0 * u).exp());
            let t = 1.0 / (1.0 + (-2.0 * u).exp());
            k += 1;
            if one_minus_t <= 0.0 || t <= 0.0 {
                continue;
            }
            let one_minus_t2 = one_minus_t * (1.0 + t);
            let lambda = (1.0 + t) / one_minus_t;
            // λ ≤ 2/(1−t) < 1e300 on this rule: the solve cannot fail; a
            // failure would only drop a node of negligible weight.
            let Ok(h) = EllipticHertz::new(lambda) else {
                continue;
            };
            out.push(Node {
                half_t2: 0.5 * t * t,
                area: w * t * one_minus_t2.sqrt() * h.area_factor,
                load: w * t * one_minus_t2.powf(0.75) * h.load_factor,
            });
        }
        out
    })
}

/// `(J_A(β), J_P(β))` on the fixed rule.
fn j_area_load(beta: f64) -> (f64, f64) {
    let b2 = beta * beta;
    let mut area = 0.0;
    let mut load = 0.0;
    for n in nodes() {
        let e = (-b2 * n.half_t2).exp();
        area += n.area * e;
        load += n.load * e;
    }
    (area, load)
}

/// `J_N(β) = ∫₀¹ t(1 − t²) e^{−β²t²/2} dt = ½(1/c − (1 − e^{−c})/c²)`,
/// `c = β²/2`, by its series `½ Σ (−c)^k/(k+2)!` for small c.
pub(crate) fn j_count(beta: f64) -> f64 {
    let c = 0.5 * beta * beta;
    if c < 0.5 {
        let mut term = 0.5; // 1/2!
        let mut sum = term;
        for k in 1..30 {
            term *= -c / (k as f64 + 2.0);
            sum += term;
            if term.abs() < 1e-18 {
                break;
            }
        }
        0.5 * sum
    } else {
        0.5 * (1.0 / c + (-c).exp_m1() / (c * c))
    }
}

impl BushGibsonThomas {
    /// The surface of spectral moments `m0` (m², the mean-square height σ²),
    /// `m2` (the mean-square profile slope, dimensionless) and `m4` (the
    /// mean-square profile curvature, m⁻²), all finite and > 0 with Nayak's
    /// `α = m0·m4/m2² > 3/2`, against a flat with the contact modulus `e_star`
    /// (Pa, > 0), over the nominal area `nominal_area` (m², > 0).
    pub fn new(m0: f64, m2: f64, m4: f64, e_star: f64, nominal_area: f64) -> Result<Self> {
        let m0 = check::positive("m0", m0)?;
        let m2 = check::positive("m2", m2)?;
        let m4 = check::positive("m4", m4)?;
        let alpha = m0 * m4 / (m2 * m2);
        if alpha.is_nan() || alpha <= MIN_ALPHA || !alpha.is_finite() {
            return Err(Error::InvalidArgument {
                name: "m4",
                value: m4,
                bound: "Nayak's alpha = m0*m4/m2^2 finite and > 1.5",
            });
        }
        Ok(Self {
            m0,
            m2,
            m4,
            e_star: check::positive("e_star", e_star)?,
            nominal_area: check::positive("nominal_area", nominal_area)?,
        })
    }

    /// The surface from the rms height `sigma` σ (m), Nayak's `alpha`
    /// (finite, > 3/2) and the rms profile slope `rms_slope` √m₂ (> 0):
    /// `m₀ = σ²`, `m₂ = rms_slope²`, `m₄ = α m₂²/m₀`.
    pub fn from_alpha(
        sigma: f64,
        rms_slope: f64,
        alpha: f64,
        e_star: f64,
        nominal_area: f64,
    ) -> Result<Self> {
        let s = check::positive("sigma", sigma)?;
        let g = check::positive("rms_slope", rms_slope)?;
        let a = check::positive("alpha", alpha)?;
        if a <= MIN_ALPHA {
            return Err(Error::InvalidArgument {
                name: "alpha",
                value: a,
                bound: "finite and > 1.5",
            });
        }
        let m2 = g * g;
        Self::new(s * s, m2, a * m2 * m2 / (s * s), e_star, nominal_area)
    }

    /// m₀ (m²).
    pub fn m0(&self) -> f64 {
        self.m0
    }
    /// m₂ (dimensionless).
    pub fn m2(&self) -> f64 {
        self.m2
    }
    /// m₄ (m⁻²).
    pub fn m4(&self) -> f64 {
        self.m4
    }
    /// Contact modulus E* (Pa).
    pub fn e_star(&self) -> f64 {
        self.e_star
    }
    /// Nominal area A₀ (m²).
    pub fn nominal_area(&self) -> f64 {
        self.nominal_area
    }
    /// Nayak's bandwidth parameter `α = m₀m₄/m₂²`.
    pub fn alpha(&self) -> f64 {
        self.m0 * self.m4 / (self.m2 * self.m2)
    }

    /// Nayak's summit density `D = m₄/(6π√3 m₂)` (m⁻²).
    pub fn summit_density(&self) -> f64 {
        self.m4 / (6.0 * core::f64::consts::PI * 3f64.sqrt() * self.m2)
    }

    /// The small-load limit of A/P (m²/N): `√π/(E*√m₂) = κ/(E*√(2m₂))`
    /// with κ = √(2π).
    pub fn small_load_area_per_load(&self) -> f64 {
        KAPPA / (self.e_star * (2.0 * self.m2).sqrt())
    }

    /// `[contacts, area, load, stiffness]` at separation d.
    fn integrals(&self, d: f64) -> Result<[f64; 4]> {
        let sigma_k = (2.0 * self.m4 / 3.0).sqrt();
        let s_z = (self.m0 - 1.5 * self.m2 * self.m2 / self.m4).sqrt();
        // μ(k̄) = (m₂/v_k) k̄ = (m₂/σ_k) κ with κ = k̄/σ_k.
        let mu_per_kappa = self.m2 / sigma_k;
        // Prefactor σ_k^p/(2π m₂ s²) with s² = m₄/3, per power p of k̄.
        let base = 1.0 / (2.0 * core::f64::consts::PI * self.m2 * self.m4 / 3.0);
        let c_count = base * sigma_k.powi(4);
        let c_area = base * sigma_k.powi(3) * core::f64::consts::PI * s_z;
        let c_load = base * sigma_k.powf(3.5) * (4.0 / 3.0) * self.e_star * s_z * s_z.sqrt();
        let c_stiff = base * sigma_k.powf(3.5) * 2.0 * self.e_star * s_z.sqrt();
        let centre = (self.m2 * d / self.m0 / sigma_k).max(0.0);
        let lo = (centre - RANGE).max(0.0);
        let hi = centre + RANGE;
        let integrand = |kappa: f64| -> [f64; 4] {
            let phi = FRAC_1_SQRT_2PI * (-0.5 * kappa * kappa).exp();
            if phi == 0.0 {
                return [0.0; 4];
            }
            let h = (d - mu_per_kappa * kappa) / s_z;
            let beta = core::f64::consts::SQRT_2 * kappa;
            let (ja, jp) = j_area_load(beta);
            let k2 = kappa * kappa;
            let k3 = k2 * kappa;
            let k35 = k3 * kappa.sqrt();
            [
                phi * k2 * k2 * j_count(beta) * gaussian::f0_unchecked(h),
                phi * k3 * ja * gaussian::f1_unchecked(h),
                phi * k35 * jp * gaussian::half_integer(2, h),
                phi * k35 * jp * gaussian::half_integer(1, h),
            ]
        };
        let v = tanh_sinh_n(integrand, lo, hi, TOLERANCE, 0.0)?;
        let a0 = self.nominal_area;
        Ok([
            a0 * c_count * v[0],
            a0 * c_area * v[1],
            a0 * c_load * v[2],
            a0 * c_stiff * v[3],
        ])
    }

    fn checked(&self, separation: f64) -> Result<[f64; 4]> {
        let d = check::finite("separation", separation)?;
        let v = self.integrals(d)?;
        for x in v {
            check::finite_result(
                x,
                "separation",
                d,
                "the response overflows f64 at this separation (separation or parameters near the ends of f64)",
            )?;
        }
        Ok(v)
    }

    /// Load, real area, contact count and stiffness at `separation` d (m,
    /// finite; height of the flat above the mean plane of the surface).
    pub fn evaluate(&self, separation: f64) -> Result<BgtResponse> {
        let [contacts, area, load, stiffness] = self.checked(separation)?;
        Ok(BgtResponse {
            response: MultiAsperityResponse {
                load,
                area,
                contacts,
            },
            stiffness,
        })
    }

    /// Load, real area and expected number of summits in contact at
    /// `separation` (m, finite).
    pub fn response(&self, separation: f64) -> Result<MultiAsperityResponse> {
        Ok(self.evaluate(separation)?.response)
    }

    /// Load P (N) at `separation` (m, finite).
    pub fn load(&self, separation: f64) -> Result<f64> {
        Ok(self.checked(separation)?[2])
    }

    /// Real contact area A (m²) at `separation` (m, finite).
    pub fn area(&self, separation: f64) -> Result<f64> {
        Ok(self.checked(separation)?[1])
    }

    /// Expected number of summits in contact at `separation` (m, finite).
    pub fn contacts(&self, separation: f64) -> Result<f64> {
        Ok(self.checked(separation)?[0])
    }

    /// Normal stiffness −dP/dd (N/m) at `separation` (m, finite).
    pub fn stiffness(&self, separation: f64) -> Result<f64> {
        Ok(self.checked(separation)?[3])
    }

    /// The separation (m) at which the surface carries `load` (N, finite
    /// and > 0), by safeguarded Newton iteration on ln P (as
    /// [`super::GreenwoodWilliamson::separation_at_load`]).
    pub fn separation_at_load(&self, load: f64) -> Result<SeparationSolution> {
        let target = check::positive("load", load)?;
        solve_separation(target, 0.0, self.m0.sqrt(), None, |d| {
            let v = self.integrals(d)?;
            Ok((v[2], -v[3]))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixed_rule_against_closed_form_count() {
        // The count weight 1 − t² on the same rule as the area and load.
        let rule: Vec<(f64, f64)> = {
            let step = 1.0 / 32.0;
            let mut v = Vec::new();
            let mut k = -((3.2f64 / step) as i64);
            while (k as f64) * step <= 3.2 {
                let tau = k as f64 * step;
                let u = core::f64::consts::FRAC_PI_2 * tau.sinh();
                let c = u.cosh();
                let w = 0.5 * step * core::f64::consts::FRAC_PI_2 * tau.cosh() / (c * c);
                let omt = 1.0 / (1.0 + (2.0 * u).exp());
                let t = 1.0 / (1.0 + (-2.0 * u).exp());
                v.push((t, w * t * omt * (1.0 + t)));
                k += 1;
            }
            v
        };
        for i in 0..=200 {
            let beta = i as f64 * 0.5;
            let sum: f64 = rule
                .iter()
                .map(|&(t, w)| w * (-0.5 * beta * beta * t * t).exp())
                .sum();
            let exact = j_count(beta);
            assert!(
                (sum / exact - 1.0).abs() < 1e-11,
                "β {beta}: {sum} vs {exact}"
            );
        }
        assert_eq!(nodes().len(), rule.len());
    }
}
