//! Derjaguin–Muller–Toporov: Hertz deformation plus a constant adhesive force
//! acting while in contact.
//!
//! Out of contact (δ < 0) the force is zero: the range of the surface forces
//! is neglected. Pull-off is the same under both controls. The limit λ → 0
//! of [`super::MaugisDugdale`].
//!
//! # Formulas
//!
//! Thesis (1-41); Derjaguin, Muller & Toporov 1975:
//!
//! $$P(\delta) = \tfrac{4}{3} E^\ast R^{1/2} \delta^{3/2} - 2\pi w R \quad (\delta \ge 0), \qquad P = 0 \quad (\delta < 0),$$
//!
//! $$a = \sqrt{R\delta}, \qquad P_c = -2\pi w R .$$
//!
//! # References
//!
//! * Thesis (1-41).
//! * B. V. Derjaguin, V. M. Muller, Yu. P. Toporov (1975), "Effect of contact
//!   deformations on the adhesion of particles", J. Colloid Interface Sci. 53,
//!   314–326,
//!   [doi:10.1016/0021-9797(75)90018-1](https://doi.org/10.1016/0021-9797(75)90018-1).
//! * D. Maugis (1992), J. Colloid Interface Sci. 150, 243–269 (DMT as the
//!   λ → 0 limit; see [`super::maugis_dugdale`]).

use super::batch::{eval_pointwise, Pointwise};
use super::{
    check_delta, check_force, stateless, BatchError, ContactState, Control, Hertz, NormalContact,
    NormalResponse, RawBatch,
};
use crate::error::{check, Result};
use core::f64::consts::PI;

/// Inputs of a DMT sphere, as [`Dmt::from_params`] and C's
/// `asperity_law_from_params` take them.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DmtParams {
    /// Sphere radius R (m, > 0).
    pub radius: f64,
    /// Contact modulus E* (Pa, > 0).
    pub e_star: f64,
    /// Work of adhesion w (J/m², ≥ 0).
    pub work_of_adhesion: f64,
}

/// DMT sphere. Its inputs are [`DmtParams`]; it derives nothing from them.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dmt {
    /// R (m).
    pub(crate) radius: f64,
    /// E* (Pa).
    pub(crate) e_star: f64,
    /// w (J/m²).
    pub(crate) work_of_adhesion: f64,
}

law_inputs!(
    Dmt,
    DmtParams {
        radius,
        e_star,
        work_of_adhesion
    }
);

impl Dmt {
    /// A DMT sphere: radius (m), contact modulus (Pa), work of adhesion (J/m², ≥ 0).
    pub fn new(radius: f64, e_star: f64, work_of_adhesion: f64) -> Result<Self> {
        Ok(Self {
            radius: check::positive("radius", radius)?,
            e_star: check::positive("e_star", e_star)?,
            work_of_adhesion: check::non_negative("work_of_adhesion", work_of_adhesion)?,
        })
    }

    /// The sphere of the inputs `p`, validated as by [`Dmt::new`].
    pub fn from_params(p: &DmtParams) -> Result<Self> {
        Self::new(p.radius, p.e_star, p.work_of_adhesion)
    }

    /// The adhesive force magnitude `2πwR` (N).
    #[inline]
    pub fn adhesive_force(&self) -> f64 {
        2.0 * PI * self.work_of_adhesion * self.radius
    }

    #[inline]
    fn hertz(&self) -> Hertz {
        Hertz {
            radius: self.radius,
            e_star: self.e_star,
        }
    }
}

impl Pointwise for Dmt {
    /// Hertz minus `2πwR` for δ ≥ 0, zero below (selected, not branched).
    #[inline]
    fn point(&self, delta: f64) -> (f64, f64, f64) {
        let touching = delta >= 0.0;
        let (f, a, k) = self.hertz().at_overlap(if touching { delta } else { 0.0 });
        let f = if touching {
            f - self.adhesive_force()
        } else {
            0.0
        };
        (f, a, k)
    }
}

impl NormalContact for Dmt {
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
        let fa = self.adhesive_force();
        if force < -fa {
            return Err(super::below_pull_off(force));
        }
        let mut r = self.hertz().eval_at_load(force + fa)?;
        r.force = force;
        r.in_contact = 1;
        Ok(r)
    }

    fn pull_off_force(&self, _control: Control) -> Result<f64> {
        Ok(-self.adhesive_force())
    }

    /// The overlap at which the Hertz force equals the adhesive force,
    /// `(3πw√R/(2E*))^{2/3}`; the radius when w = 0, or when that power
    /// under- or overflows f64 (a tiny w such as 1e-300 J/m² would otherwise
    /// give a length scale of 0).
    fn length_scale(&self) -> f64 {
        if self.work_of_adhesion == 0.0 {
            return self.radius;
        }
        let l = (3.0 * PI * self.work_of_adhesion * self.radius.sqrt() / (2.0 * self.e_star))
            .powf(2.0 / 3.0);
        if l.is_normal() {
            l
        } else {
            self.radius
        }
    }

    /// 0 under both controls: the force is exactly zero for δ < 0 (the range
    /// of the surface forces is neglected). `rel_force` is checked, then
    /// ignored.
    fn reach(&self, _control: Control, rel_force: f64) -> Result<f64> {
        super::check_rel_force(rel_force)?;
        Ok(0.0)
    }

    /// `U = (8/15) E* R^{1/2} δ^{5/2} − 2πwRδ` for δ ≥ 0 and 0 for δ < 0,
    /// the integral of the force (continuous at δ = 0, `dU/dδ = P`).
    fn energy(&self, delta: f64, _old: &ContactState) -> Result<f64> {
        let delta = check_delta(delta)?;
        if delta < 0.0 {
            return Ok(0.0);
        }
        Ok(super::hertz_energy(self.radius, self.e_star, delta) - self.adhesive_force() * delta)
    }
}
