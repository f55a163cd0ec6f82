//! STUB — to be implemented (Kendall adhesive flat punch).
use super::{Control, ContactState, NormalContact, NormalResponse};
use crate::error::{check, Error, Result};

/// Kendall adhesive flat punch.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kendall {
    /// Punch radius a (m).
    pub radius: f64,
    /// Contact modulus E* (Pa).
    pub e_star: f64,
    /// Work of adhesion w (J/m²).
    pub work_of_adhesion: f64,
    /// No-slip factor C_NS (1 when frictionless).
    pub no_slip_factor: f64,
}

const TODO: Error = Error::OutOfDomain { name: "law", value: 0.0, reason: "not implemented" };

impl Kendall {
    /// Frictionless adhesive flat punch.
    pub fn new(radius: f64, e_star: f64, work_of_adhesion: f64) -> Result<Self> {
        Ok(Self { radius: check::positive("radius", radius)?, e_star: check::positive("e_star", e_star)?, work_of_adhesion: check::non_negative("work_of_adhesion", work_of_adhesion)?, no_slip_factor: 1.0 })
    }
    /// Bonded (no-slip) adhesive flat punch on a half-space of Poisson's ratio `nu`.
    pub fn no_slip(radius: f64, e_star: f64, work_of_adhesion: f64, nu: f64) -> Result<Self> {
        let mut k = Self::new(radius, e_star, work_of_adhesion)?;
        k.no_slip_factor = crate::material::no_slip_factor(nu)?;
        Ok(k)
    }
}

impl NormalContact for Kendall {
    fn eval(&self, _delta: f64, _old: &ContactState) -> Result<(NormalResponse, ContactState)> { Err(TODO) }
    fn eval_at_load(&self, _force: f64) -> Result<NormalResponse> { Err(TODO) }
    fn pull_off_force(&self, _control: Control) -> Result<f64> { Err(TODO) }
    fn length_scale(&self) -> f64 { self.radius }
}
