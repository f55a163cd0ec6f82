//! Love's compliance of an elastic half-space under a uniformly loaded
//! square (Johnson 1985, §3.2; Love 1929): the influence coefficients that
//! couple the rods of a [`super::CoupledRodBed`] through their substrate.

use crate::error::{check, Result};

/// Gauss–Legendre nodes and weights on [−1, 1], 8 points.
const GL8: [(f64, f64); 8] = [
    (-0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
    (-0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (-0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (-0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.183_434_642_495_649_8, 0.362_683_783_378_362),
    (0.525_532_409_916_329, 0.313_706_645_877_887_3),
    (0.796_666_477_413_626_7, 0.222_381_034_453_374_47),
    (0.960_289_856_497_536_3, 0.101_228_536_290_376_26),
];

/// Centre distance (in rod widths) beyond which [`square_influence`] uses
/// quadrature instead of Love's closed form.
pub const INFLUENCE_QUADRATURE_SWITCH: f64 = 6.0;

/// G(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|): the mixed antiderivative of
/// 1/√(X² + Y²) (zero terms at X = 0 or Y = 0).
fn love_g(x: f64, y: f64) -> f64 {
    let t1 = if x != 0.0 {
        x * (y / x.abs()).asinh()
    } else {
        0.0
    };
    let t2 = if y != 0.0 {
        y * (x / y.abs()).asinh()
    } else {
        0.0
    };
    t1 + t2
}

/// Compliance of an elastic half-space (m/N): the normal displacement at
/// offset (`dx`, `dy`) (m) from the centre of a square of side `width` (m)
/// carrying a unit force spread uniformly over it, for contact modulus
/// `contact_modulus` E* (Pa) (Boussinesq: a point force f displaces the
/// surface by f/(π E* r) at distance r; E* = E/(1 − ν²) against a rigid
/// counter-surface).
///
/// u = (1/(π E* w²)) ∬_square dA/r: uniform pressure on a rectangle, Love
/// (1929), "The stress produced in a semi-infinite solid by pressure on part
/// of the boundary", Phil. Trans. R. Soc. A 228, 377; Johnson, *Contact
/// Mechanics* (1985), ch. 3 (Boussinesq's point-force solution). In closed
/// form, with G(X, Y) = X asinh(Y/|X|) + Y asinh(X/|Y|), X± = dx ± w/2,
/// Y± = dy ± w/2:
///
/// u = (G(X₊,Y₊) − G(X₋,Y₊) − G(X₊,Y₋) + G(X₋,Y₋)) / (π E* w²).
///
/// At the centre u = 4 ln(1 + √2)/(π E* w) ≈ 1.1222/(E* w); far away
/// u → 1/(π E* r). Beyond [`INFLUENCE_QUADRATURE_SWITCH`] widths the closed
/// form loses digits to cancellation, so the integral is taken by 8 × 8
/// Gauss–Legendre points (relative error < 1e-15 there).
///
/// Errors: `width`, `contact_modulus` not finite and > 0; `dx`, `dy` not
/// finite.
pub fn square_influence(dx: f64, dy: f64, width: f64, contact_modulus: f64) -> Result<f64> {
    check::finite("dx", dx)?;
    check::finite("dy", dy)?;
    check::positive("width", width)?;
    check::positive("contact_modulus", contact_modulus)?;
    Ok(influence_unchecked(dx, dy, width, contact_modulus))
}

/// [`square_influence`] without the argument checks.
pub(super) fn influence_unchecked(dx: f64, dy: f64, w: f64, e_star: f64) -> f64 {
    let h = 0.5 * w;
    let r = (dx * dx + dy * dy).sqrt();
    let integral = if r <= INFLUENCE_QUADRATURE_SWITCH * w {
        love_g(dx + h, dy + h) - love_g(dx - h, dy + h) - love_g(dx + h, dy - h)
            + love_g(dx - h, dy - h)
    } else {
        let mut s = 0.0;
        for &(xi, wi) in &GL8 {
            for &(eta, wj) in &GL8 {
                let x = dx - h * xi;
                let y = dy - h * eta;
                s += wi * wj / (x * x + y * y).sqrt();
            }
        }
        s * h * h
    };
    integral / (core::f64::consts::PI * e_star * w * w)
}
