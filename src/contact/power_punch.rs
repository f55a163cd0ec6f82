//! Galin's axisymmetric power-law punch `f(r) = B r^d`, d ≥ 1, no adhesion.
//!
//! The stiffness `dP/dδ = 2E*a` holds for every d (the BASh relation).
//! `d = 2, B = 1/(2R)` is Hertz; `d = 1, B = cot γ` the cone of half-angle γ
//! (`P = (π/2) E* a² cot γ`, `δ = (π/2) a cot γ`). Pyramids enter through the
//! cone of equal projected area ([`BERKOVICH_EQUIVALENT_HALF_ANGLE`], …). A cone
//! unloading from its own imprint uses Galanov's effective cone
//! ([`PowerPunch::cone_in_imprint`], thesis (2-18)).
//!
//! # Formulas
//!
//! Thesis (1-19)..(1-22); Galin 1946; Borodich 1983; Sneddon 1965:
//!
//! $$\delta(a) = D(d)\\,B\\,a^d, \qquad P(a) = C(d)\\,B\\,E^\ast a^{d+1}, \qquad \frac{dP}{d\delta} = 2E^\ast a,$$
//!
//! $$D(d) = \frac{\sqrt{\pi}\\,\Gamma(d/2 + 1)}{\Gamma(d/2 + 1/2)}, \qquad C(d) = \frac{2d}{d+1}\\,D(d).$$
//!
//! # References
//!
//! * Thesis (1-19)–(1-22) (Galin's solution), §3.6.2 (equivalent cones), (2-18)
//!   (Galanov's cone in its imprint).
//! * L. A. Galin (1946), "Spatial contact problems of the theory of elasticity
//!   for punches of circular shape in planar projection", J. Appl. Math. Mech.
//!   (PMM) 10, 425–448 (in Russian); L. A. Galin (1953/1961), *Contact Problems
//!   in the Theory of Elasticity*.
//! * F. M. Borodich (1983), "Similarity in the problem of contact between elastic
//!   bodies", J. Appl. Math. Mech. (PMM) 47, 440–442.
//! * I. N. Sneddon (1965), "The relation between load and penetration in the
//!   axisymmetric Boussinesq problem for a punch of arbitrary profile",
//!   Int. J. Eng. Sci. 3, 47–57.

use super::{
    check_delta, check_force, stateless, ContactState, Control, NormalContact, NormalResponse,
};
use crate::error::{check, Error, Result};

/// Half-angle (rad) of the cone with the projected area of a Berkovich pyramid
/// at equal depth: 70.3° (thesis §3.6.2).
pub const BERKOVICH_EQUIVALENT_HALF_ANGLE: f64 = 70.3 * core::f64::consts::PI / 180.0;
/// Half-angle (rad) of the cone equivalent to a Vickers pyramid: 70.3°
/// (thesis §3.6.2).
pub const VICKERS_EQUIVALENT_HALF_ANGLE: f64 = 70.3 * core::f64::consts::PI / 180.0;
/// Half-angle (rad) of the cone equivalent to a cube-corner pyramid: 42.3°
/// (thesis §3.6.2).
pub const CUBE_CORNER_EQUIVALENT_HALF_ANGLE: f64 = 42.3 * core::f64::consts::PI / 180.0;

/// Largest accepted exponent d. Beyond it `a^d` leaves the range of `f64` for
/// any physically sized punch; use [`super::FlatPunch`] for the limit d → ∞.
pub const MAX_EXPONENT: f64 = 100.0;

/// Galin's `D(d) = √π Γ(d/2+1)/Γ(d/2+1/2)` (dimensionless), `δ = D B a^d`.
/// D(1) = π/2, D(2) = 2, D(3) = 3π/4.
pub fn galin_d(d: f64) -> f64 {
    let x = 0.5 * d;
    core::f64::consts::PI.sqrt() * (libm::lgamma(x + 1.0) - libm::lgamma(x + 0.5)).exp()
}

/// Galin's `C(d) = (2d/(d+1)) D(d)` (dimensionless), `P = C B E* a^{d+1}`.
/// C(1) = π/2, C(2) = 8/3.
pub fn galin_c(d: f64) -> f64 {
    2.0 * d / (d + 1.0) * galin_d(d)
}

/// Validate the shape of a power-law punch, shared by the adhesive variant.
pub(crate) fn check_shape(b: f64, d: f64) -> Result<(f64, f64)> {
    let b = check::positive("b", b)?;
    let d = check::in_range("d", d, 1.0, MAX_EXPONENT, "in [1, 100]")?;
    Ok((b, d))
}

/// Inputs of a power-law punch, as [`PowerPunch::from_params`] and C's
/// `asperity_law_from_params` take them.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PowerPunchParams {
    /// Shape coefficient B (m^{1−d}, > 0) of the profile `f(r) = B r^d`.
    pub b: f64,
    /// Shape exponent d (1 ≤ d ≤ 100).
    pub d: f64,
    /// Contact modulus E* (Pa, > 0).
    pub e_star: f64,
}

/// A power-law punch `f(r) = B r^d`. Its inputs are [`PowerPunchParams`];
/// it caches Galin's coefficients.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerPunch {
    /// B (m^{1−d}).
    pub(crate) b: f64,
    /// d.
    pub(crate) d: f64,
    /// E* (Pa).
    pub(crate) e_star: f64,
    /// Cached `C(d) B E*` (Pa·m^{1−d}).
    force_coefficient: f64,
    /// Cached `D(d) B` (m^{1−d}).
    depth_coefficient: f64,
    /// Cached `1/(D(d) B)` (m^{d−1}).
    inverse_depth_coefficient: f64,
    /// Cached `1/d`.
    inverse_d: f64,
    /// Cached `(C(d)/D(d)) E* = 2d E*/(d+1)` (Pa), so that `P = this · a δ`.
    force_per_area: f64,
}

law_inputs!(PowerPunch, PowerPunchParams { b, d, e_star });

impl PowerPunch {
    /// The punch of the inputs `p`, validated as by [`PowerPunch::new`].
    pub fn from_params(p: &PowerPunchParams) -> Result<Self> {
        Self::new(p.b, p.d, p.e_star)
    }

    /// A punch `f(r) = b r^d` with contact modulus `e_star` (Pa).
    pub fn new(b: f64, d: f64, e_star: f64) -> Result<Self> {
        let (b, d) = check_shape(b, d)?;
        let e_star = check::positive("e_star", e_star)?;
        let depth_coefficient = galin_d(d) * b;
        Ok(Self {
            b,
            d,
            e_star,
            force_coefficient: galin_c(d) * b * e_star,
            depth_coefficient,
            inverse_depth_coefficient: 1.0 / depth_coefficient,
            inverse_d: 1.0 / d,
            force_per_area: 2.0 * d / (d + 1.0) * e_star,
        })
    }

    /// A cone of half-angle `half_angle` (rad, in (0, π/2)): `d = 1`, `B = cot γ`.
    ///
    /// A half-angle so small that `cot γ` overflows f64 (γ = 5e-324, say) is
    /// an error naming `half_angle`, the argument the caller gave, rather
    /// than `b`, which is not an argument of this function.
    pub fn cone(half_angle: f64, e_star: f64) -> Result<Self> {
        let g = check::half_angle("half_angle", half_angle)?;
        let b = 1.0 / g.tan();
        if !b.is_finite() {
            return Err(Error::InvalidArgument {
                name: "half_angle",
                value: g,
                bound: "in (0, pi/2) rad with cot(half_angle) finite",
            });
        }
        Self::new(b, 1.0, e_star)
    }

    /// Galanov's effective cone for a cone of half-angle `indenter_half_angle`
    /// unloading from a conical imprint of half-angle `imprint_half_angle`
    /// (rad) (thesis (2-18)): `B₁ = cot γ_i − cot γ_f`. The imprint must be
    /// blunter than the indenter (`imprint_half_angle > indenter_half_angle`);
    /// `π/2` is a flat.
    pub fn cone_in_imprint(
        indenter_half_angle: f64,
        imprint_half_angle: f64,
        e_star: f64,
    ) -> Result<Self> {
        let b =
            crate::rescaling::galanov_cone_coefficient(indenter_half_angle, imprint_half_angle)?;
        Self::new(b, 1.0, e_star)
    }

    /// Overlap at contact radius `a` (m): `δ = D(d) B a^d` (1-19).
    #[inline]
    pub fn delta_at_radius(&self, a: f64) -> f64 {
        self.depth_coefficient * a.powf(self.d)
    }

    /// Force at contact radius `a` (m): `P = C(d) B E* a^{d+1}` (1-20).
    #[inline]
    pub fn force_at_radius(&self, a: f64) -> f64 {
        self.force_coefficient * a.powf(self.d + 1.0)
    }

    /// Contact radius at overlap δ ≥ 0: `a = (δ/(D B))^{1/d}` (1-21).
    #[inline]
    pub fn radius_at_delta(&self, delta: f64) -> f64 {
        (delta * self.inverse_depth_coefficient).powf(self.inverse_d)
    }
}

impl NormalContact for PowerPunch {
    #[inline]
    fn eval(&self, delta: f64, _old: &ContactState) -> Result<(NormalResponse, ContactState)> {
        let delta = check_delta(delta)?;
        if delta <= 0.0 {
            return Ok(stateless(0.0, delta, 0.0, 0.0));
        }
        let a = self.radius_at_delta(delta);
        // P = C B E* a^{d+1} = (C/D) E* a δ: one powf per call.
        let force = self.force_per_area * a * delta;
        Ok(stateless(force, delta, a, 2.0 * self.e_star * a))
    }

    fn eval_at_load(&self, force: f64) -> Result<NormalResponse> {
        let force = check_force(force)?;
        if force < 0.0 {
            return Err(super::below_pull_off(force));
        }
        let a = (force / self.force_coefficient).powf(1.0 / (self.d + 1.0));
        Ok(stateless(force, self.delta_at_radius(a), a, 2.0 * self.e_star * a).0)
    }

    fn pull_off_force(&self, _control: Control) -> Result<f64> {
        Ok(0.0)
    }

    /// The contact radius at which the overlap equals the contact radius,
    /// `(D B)^{−1/(d−1)}` (m), for d > 1. A cone has no intrinsic length
    /// (`δ/a = D B` is constant); its scale is taken as 1 m, and so is that
    /// of a punch so close to a cone that `(D B)^{−1/(d−1)}` under- or
    /// overflows f64 (d = 1 + 2⁻⁵², B = 1477 would otherwise give 0).
    fn length_scale(&self) -> f64 {
        let l = if self.d > 1.0 {
            self.depth_coefficient.powf(-1.0 / (self.d - 1.0))
        } else {
            1.0
        };
        if l.is_normal() && l > 0.0 {
            l
        } else {
            1.0
        }
    }

    /// 0: no adhesion (`rel_force` is checked, then ignored).
    fn reach(&self, _control: Control, rel_force: f64) -> Result<f64> {
        super::check_rel_force(rel_force)?;
        Ok(0.0)
    }

    /// `U = ∫P dδ = C D B² E* d a^{2d+1}/(2d+1) = (d/(2d+1)) P δ` for δ > 0
    /// (with `dδ = D B d a^{d−1} da`; d = 2 gives Hertz's (8/15)E*√R δ^{5/2}),
    /// 0 otherwise.
    fn energy(&self, delta: f64, old: &ContactState) -> Result<f64> {
        let (r, _) = self.eval(delta, old)?;
        Ok(if delta > 0.0 {
            self.d / (2.0 * self.d + 1.0) * r.force * delta
        } else {
            0.0
        })
    }
}
