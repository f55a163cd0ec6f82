//! Hertz contact of an elastic elliptic paraboloid (principal curvatures
//! k₁ ≥ k₂ > 0) pressed by a depth δ against a flat: the single-asperity law
//! of the Bush–Gibson–Thomas model ([`super::bush_gibson_thomas`]).
//!
//! # Formulas
//!
//! The gap before loading is `½k₂x² + ½k₁y²`, so `A = k₂/2`, `B = k₁/2`
//! (Johnson 1985, §4.2). The contact is an ellipse of semi-axes a ≥ b along x
//! and y, eccentricity `e² = m = 1 − b²/a²`, under the pressure
//! `p₀√(1 − x²/a² − y²/b²)`, with complete elliptic integrals K(m), E(m)
//! (Johnson 1985, §4.2: the surface displacement of an ellipsoidal
//! pressure):
//!
//! $$\frac{B}{A} = \lambda = \frac{k_1}{k_2} = \frac{E/(1-m) - K}{K - E}, \qquad \delta = \frac{p_0 b K}{E^\ast}, \qquad \frac{k_2}{2} = \frac{p_0 b\\,(K - E)}{E^\ast m a^2},\qquad P = \tfrac23\pi a b p_0 .$$
//!
//! Eliminating p₀ gives `a² = 2δ q/(K k₂)` with `q = (K − E)/m` (→ π/4 for a
//! sphere), the area `πab` and the load. Written against the sphere of the
//! geometric-mean radius `1/√(k₁k₂)`:
//!
//! $$A = \frac{\pi\delta}{\sqrt{k_1k_2}}\\,F_A(\lambda), \quad F_A = \frac{2q\sqrt{(1-m)\lambda}}{K}, \qquad P = \frac43 E^\ast \frac{\delta^{3/2}}{(k_1k_2)^{1/4}}\\,F_P(\lambda), \quad F_P = \frac{\pi}{\sqrt2}\\,\frac{q^{1/2}\lambda^{1/4}}{K^{3/2}},$$
//!
//! both exactly 1 for a sphere (λ = 1); the stiffness is `dP/dδ = 3P/(2δ)`.
//! K and E come from the arithmetic–geometric mean in the complementary
//! parameter `1 − m` (no loss of accuracy for flat ellipses); m is found from
//! λ by safeguarded secant iteration in `ln(m/(1 − m))` started from
//! `b/a ≈ λ^{−2/3}` (Johnson 1985, §4.2), to `|Δ ln λ| ≤ 1e-14`.
//!
//! # References
//!
//! * K. L. Johnson (1985), *Contact Mechanics*, Cambridge University Press,
//!   §4.2 (Hertz theory, non-circular contact).
//! * B. J. Hamrock, D. E. Brewe (1983), "Simplified solution for stresses and
//!   deformations", J. Lubr. Technol. 105, 171–177 (the curve fits
//!   `a/b ≈ 1.0339 λ^{0.636}`, `E ≈ 1.0003 + 0.5968/λ` used as a check).

use crate::error::{check, Error, Result};
use core::f64::consts::FRAC_PI_2;

/// Contact ellipse of an elliptic paraboloid against a flat, in the form of
/// the module documentation.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct EllipticHertz {
    /// Curvature ratio λ = k₁/k₂ ≥ 1 (dimensionless).
    pub curvature_ratio: f64,
    /// Axis ratio b/a ≤ 1 of the contact ellipse (dimensionless).
    pub axis_ratio: f64,
    /// Area factor F_A (dimensionless; 1 for a sphere).
    pub area_factor: f64,
    /// Load factor F_P (dimensionless; 1 for a sphere).
    pub load_factor: f64,
    /// Complete elliptic integral of the first kind K(m), m = 1 − (b/a)².
    pub k: f64,
    /// Complete elliptic integral of the second kind E(m).
    pub e: f64,
}

/// Below this λ − 1 the contact is a sphere to within 1e-7 (F − 1 ≈ O(λ − 1)).
const SPHERE_BELOW: f64 = 1e-9;

/// `(K, E, q)` for the parameter `m` with complement `m1 = 1 − m` (both
/// given, so that either may be tiny), `q = (K − E)/m`, by the
/// arithmetic–geometric mean: `K = π/(2 AGM(1, √m1))`,
/// `K − E = K Σ 2^{n−1} c_n²` with `c₀² = m` and `c_{n+1} = c_n²/(4a_{n+1})`
/// (no difference of nearly equal numbers, so q keeps full accuracy as
/// m → 0).
fn complete_integrals(m: f64, m1: f64) -> (f64, f64, f64) {
    let mut a = 1.0;
    let mut b = m1.sqrt();
    // c_n²/m, starting from c₀²/m = 1.
    let mut c2_over_m = 1.0;
    let mut sum = 0.5;
    let mut power = 0.5;
    for _ in 0..60 {
        let next = 0.5 * (a + b);
        // c_{n+1}² = c_n⁴/(16 a_{n+1}²), divided by m.
        c2_over_m = c2_over_m * c2_over_m * m / (16.0 * next * next);
        b = (a * b).sqrt();
        a = next;
        power *= 2.0;
        let term = power * c2_over_m;
        sum += term;
        if term <= 1e-17 * sum {
            break;
        }
    }
    let k = FRAC_PI_2 / a;
    let q = k * sum;
    (k, k - m * q, q)
}

/// λ(x) for `x = m/(1 − m)` as `(K − q)/((1 − m) q)` (module docs: the
/// numerator `E/(1−m) − K = m(K − q)/(1 − m)` written without cancellation),
/// with m, 1 − m, K, E and q.
fn ratio_of(x: f64) -> (f64, f64, f64, f64, f64, f64) {
    let m = x / (1.0 + x);
    let m1 = 1.0 / (1.0 + x);
    let (k, e, q) = complete_integrals(m, m1);
    ((k - q) / (m1 * q), m, m1, k, e, q)
}

impl EllipticHertz {
    /// The contact ellipse for the curvature ratio `curvature_ratio`
    /// λ = k₁/k₂ (finite, ≥ 1).
    pub fn new(curvature_ratio: f64) -> Result<Self> {
        let lambda = check::finite("curvature_ratio", curvature_ratio)?;
        if lambda < 1.0 {
            return Err(Error::InvalidArgument {
                name: "curvature_ratio",
                value: lambda,
                bound: "finite and >= 1 (the larger curvature over the smaller)",
            });
        }
        if lambda - 1.0 < SPHERE_BELOW {
            return Ok(Self {
                curvature_ratio: lambda,
                axis_ratio: 1.0,
                area_factor: 1.0,
                load_factor: 1.0,
                k: FRAC_PI_2,
                e: FRAC_PI_2,
            });
        }
        let target = lambda.ln();
        let f = |y: f64| -> f64 { ratio_of(y.exp()).0.ln() - target };
        // Start: b/a ≈ λ^{−2/3}, i.e. x = a²/b² − 1 ≈ λ^{4/3} − 1.
        let y0 = ((4.0 / 3.0) * target).exp_m1().ln();
        let (mut lo, mut hi) = (y0 - 0.5, y0 + 0.5);
        let (mut f_lo, mut f_hi) = (f(lo), f(hi));
        let mut n = 0;
        while f_lo > 0.0 {
            lo -= 2.0;
            f_lo = f(lo);
            n += 1;
            if n > 400 {
                return Err(not_converged(f_lo));
            }
        }
        while f_hi < 0.0 {
            hi += 2.0;
            f_hi = f(hi);
            n += 1;
            if n > 400 {
                return Err(not_converged(f_hi));
            }
        }
        // Illinois regula falsi on the bracket [lo, hi].
        let mut y = lo;
        let mut fy = f_lo;
        let mut side = 0i8;
        for _ in 0..200 {
            y = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
            if !(y > lo && y < hi) {
                y = 0.5 * (lo + hi);
            }
            fy = f(y);
            if fy.abs() <= 1e-14 || (hi - lo) <= 1e-15 * (1.0 + y.abs()) {
                break;
            }
            if fy < 0.0 {
                lo = y;
                f_lo = fy;
                if side == -1 {
                    f_hi *= 0.5;
                }
                side = -1;
            } else {
                hi = y;
                f_hi = fy;
                if side == 1 {
                    f_lo *= 0.5;
                }
                side = 1;
            }
        }
        if fy.abs() > 1e-13 {
            return Err(not_converged(fy));
        }
        let (_, _, m1, k, e, q) = ratio_of(y.exp());
        let area_factor = 2.0 * q * (m1 * lambda).sqrt() / k;
        let load_factor =
            core::f64::consts::PI / core::f64::consts::SQRT_2 * q.sqrt() * lambda.powf(0.25)
                / (k * k.sqrt());
        Ok(Self {
            curvature_ratio: lambda,
            axis_ratio: m1.sqrt(),
            area_factor,
            load_factor,
            k,
            e,
        })
    }
}

fn not_converged(residual: f64) -> Error {
    Error::NotConverged {
        what: "elliptic Hertz eccentricity",
        iterations: 200,
        residual: residual.abs(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sphere_and_round_trip() {
        let s = EllipticHertz::new(1.0).unwrap();
        assert_eq!((s.area_factor, s.load_factor), (1.0, 1.0));
        // Just off the sphere the factors are continuous.
        let s = EllipticHertz::new(1.0 + 1e-6).unwrap();
        assert!((s.area_factor - 1.0).abs() < 1e-6 && (s.load_factor - 1.0).abs() < 1e-6);
        // Forward from e: λ(x) then back.
        for &x in &[1e-6, 1e-3, 0.1, 1.0, 10.0, 1e3, 1e8, 1e15] {
            let (lambda, _, m1, _, _, _) = ratio_of(x);
            let h = EllipticHertz::new(lambda).unwrap();
            let rel = (h.axis_ratio * h.axis_ratio / m1 - 1.0).abs();
            assert!(rel < 1e-12, "x {x} λ {lambda} rel {rel}");
        }
    }
}
