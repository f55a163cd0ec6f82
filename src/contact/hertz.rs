//! Hertz: elastic sphere (paraboloid) on a flat, no adhesion.
//!
//! With the Galanov effective radius ([`Hertz::sphere_in_crater`], thesis
//! (2-19)) the same law describes a sphere unloading from its own plastic
//! crater.
//!
//! # Formulas
//!
//! Thesis (1-15)..(1-17); Hertz 1882; Johnson 1985 §4.2. Under an overlap
//! δ, and under a load P with the peak pressure:
//!
//! $$a = \sqrt{R\delta}, \qquad P = \tfrac{4}{3} E^\ast R^{1/2} \delta^{3/2}, \qquad \frac{dP}{d\delta} = 2E^\ast a,$$
//!
//! $$a = \left(\frac{3PR}{4E^\ast}\right)^{1/3}, \qquad p_0 = \frac{3P}{2\pi a^2},$$
//!
//! with $E^\ast$ the contact modulus and, for a sphere in its crater,
//! $1/R_\mathrm{eff} = 1/R - 1/R_\mathrm{medium}$ (2-19).
//!
//! # References
//!
//! * Thesis (1-15)–(1-17) (Hertz), (2-19) (Galanov's sphere in a crater); the
//!   thesis is the seed PhD thesis on multi-scale dry friction (see the crate
//!   docs, *Sources*).
//! * H. Hertz (1882), "Über die Berührung fester elastischer Körper",
//!   J. reine angew. Math. 92, 156–171,
//!   [doi:10.1515/crll.1882.92.156](https://doi.org/10.1515/crll.1882.92.156).
//! * K. L. Johnson (1985), *Contact Mechanics*, Cambridge University Press,
//!   §4.2, [doi:10.1017/CBO9781139171731](https://doi.org/10.1017/CBO9781139171731).

use super::batch::{eval_pointwise, Pointwise};
use super::{
    check_delta, check_force, stateless, BatchError, ContactState, Control, NormalContact,
    NormalResponse, RawBatch,
};
use crate::error::{check, Result};

/// Inputs of a Hertz sphere, as [`Hertz::from_params`] and C's
/// `asperity_law_from_params` take them.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HertzParams {
    /// Radius of curvature R of the sphere, or the effective radius
    /// `1/R = 1/R₁ + 1/R₂` of two spheres (m, > 0).
    pub radius: f64,
    /// Contact modulus E* (Pa, > 0).
    pub e_star: f64,
}

/// Hertz sphere. Its inputs are [`HertzParams`]; it derives nothing from
/// them.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Hertz {
    /// R (m).
    pub(crate) radius: f64,
    /// E* (Pa).
    pub(crate) e_star: f64,
}

law_inputs!(Hertz, HertzParams { radius, e_star });

impl Hertz {
    /// A sphere of radius `radius` (m) with contact modulus `e_star` (Pa).
    pub fn new(radius: f64, e_star: f64) -> Result<Self> {
        Ok(Self {
            radius: check::positive("radius", radius)?,
            e_star: check::positive("e_star", e_star)?,
        })
    }

    /// The sphere of the inputs `p`, validated as by [`Hertz::new`].
    pub fn from_params(p: &HertzParams) -> Result<Self> {
        Self::new(p.radius, p.e_star)
    }

    /// Galanov's effective shape for a sphere of radius `radius` pressed into a
    /// spherical crater (the deformed medium) of radius `medium_radius` (m)
    /// (thesis (2-19), (3-23)): `1/R_eff = 1/R − 1/R_medium`, computed by
    /// [`crate::rescaling::unloading_radius`]. `medium_radius = +∞` is a flat;
    /// the crater must be flatter than the sphere (`medium_radius > radius`).
    pub fn sphere_in_crater(radius: f64, medium_radius: f64, e_star: f64) -> Result<Self> {
        Self::new(
            crate::rescaling::unloading_radius(radius, medium_radius)?,
            e_star,
        )
    }

    /// Contact radius under load `force` ≥ 0 (N): `a = (3PR/(4E*))^{1/3}` (1-15).
    #[inline]
    pub fn contact_radius_at_load(&self, force: f64) -> f64 {
        (3.0 * force * self.radius / (4.0 * self.e_star)).cbrt()
    }

    /// Maximum (central) pressure `p₀ = 3P/(2πa²)` (Pa) at load `force` > 0 (1-17).
    pub fn peak_pressure(&self, force: f64) -> Result<f64> {
        let p = check::positive("force", force)?;
        let a = self.contact_radius_at_load(p);
        Ok(3.0 * p / (2.0 * core::f64::consts::PI * a * a))
    }

    /// Force, contact radius and stiffness at overlap δ ≥ 0 (no checks).
    #[inline]
    pub(crate) fn at_overlap(&self, delta: f64) -> (f64, f64, f64) {
        let a = (self.radius * delta).sqrt();
        let force = 4.0 / 3.0 * self.e_star * a * delta;
        (force, a, 2.0 * self.e_star * a)
    }
}

impl Pointwise for Hertz {
    /// Zero out of contact (δ ≤ 0), selected rather than branched on.
    #[inline]
    fn point(&self, delta: f64) -> (f64, f64, f64) {
        self.at_overlap(if delta > 0.0 { delta } else { 0.0 })
    }
}

impl NormalContact for Hertz {
    #[inline]
    fn eval(&self, delta: f64, _old: &ContactState) -> Result<(NormalResponse, ContactState)> {
        let delta = check_delta(delta)?;
        let (f, a, k) = self.point(delta);
        Ok(stateless(f, delta, a, k))
    }

    #[inline]
    unsafe fn eval_batch_raw(&self, b: &RawBatch) -> core::result::Result<(), BatchError> {
        eval_pointwise(self, b)
    }

    fn eval_at_load(&self, force: f64) -> Result<NormalResponse> {
        let force = check_force(force)?;
        if force < 0.0 {
            return Err(super::below_pull_off(force));
        }
        let a = self.contact_radius_at_load(force);
        let delta = a * a / self.radius;
        Ok(stateless(force, delta, a, 2.0 * self.e_star * a).0)
    }

    fn pull_off_force(&self, _control: Control) -> Result<f64> {
        Ok(0.0)
    }

    fn length_scale(&self) -> f64 {
        self.radius
    }

    /// 0: no adhesion, the force vanishes for δ ≤ 0 (`rel_force` is checked,
    /// then ignored).
    fn reach(&self, _control: Control, rel_force: f64) -> Result<f64> {
        super::check_rel_force(rel_force)?;
        Ok(0.0)
    }

    /// `U = (8/15) E* R^{1/2} δ^{5/2}` for δ ≥ 0, 0 otherwise (∫P dδ;
    /// Johnson 1985 §4.2).
    fn energy(&self, delta: f64, _old: &ContactState) -> Result<f64> {
        let delta = check_delta(delta)?;
        Ok(super::hertz_energy(self.radius, self.e_star, delta))
    }
}
