//! STUB — to be implemented (JKR for power-law punches, frictionless and no-slip).
use super::{Control, ContactState, NormalContact, NormalResponse};
use crate::error::{check, Error, Result};

/// JKR power-law punch.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JkrPowerPunch {
    /// Shape coefficient B (m^{1−d}).
    pub b: f64,
    /// Shape exponent d.
    pub d: f64,
    /// Contact modulus E* (Pa).
    pub e_star: f64,
    /// Work of adhesion w (J/m²).
    pub work_of_adhesion: f64,
}

const TODO: Error = Error::OutOfDomain { name: "law", value: 0.0, reason: "not implemented" };

impl JkrPowerPunch {
    /// Frictionless adhesive power-law punch.
    pub fn new(b: f64, d: f64, e_star: f64, work_of_adhesion: f64) -> Result<Self> {
        let (b, d) = super::power_punch::check_shape(b, d)?;
        Ok(Self { b, d, e_star: check::positive("e_star", e_star)?, work_of_adhesion: check::non_negative("work_of_adhesion", work_of_adhesion)? })
    }
    /// No-slip adhesive power-law punch on a half-space of Poisson's ratio `nu`.
    pub fn no_slip(b: f64, d: f64, e_star: f64, work_of_adhesion: f64, nu: f64) -> Result<Self> {
        check::poisson("nu", nu)?;
        Self::new(b, d, e_star, work_of_adhesion)
    }
}

impl NormalContact for JkrPowerPunch {
    fn eval(&self, _delta: f64, _old: &ContactState) -> Result<(NormalResponse, ContactState)> { Err(TODO) }
    fn eval_at_load(&self, _force: f64) -> Result<NormalResponse> { Err(TODO) }
    fn pull_off_force(&self, _control: Control) -> Result<f64> { Err(TODO) }
    fn length_scale(&self) -> f64 { 1.0 }
}
