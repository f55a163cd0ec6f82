//! STUB — to be implemented (Maugis–Dugdale sphere).
use super::{Control, ContactState, NormalContact, NormalResponse};
use crate::error::{check, Error, Result};

/// Maugis–Dugdale sphere.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MaugisDugdale {
    /// Sphere radius R (m).
    pub radius: f64,
    /// Contact modulus E* (Pa).
    pub e_star: f64,
    /// Work of adhesion w (J/m²).
    pub work_of_adhesion: f64,
    /// Dugdale cohesive stress σ₀ (Pa).
    pub cohesive_stress: f64,
}

const TODO: Error = Error::OutOfDomain { name: "law", value: 0.0, reason: "not implemented" };

impl MaugisDugdale {
    /// A Maugis–Dugdale sphere.
    pub fn new(radius: f64, e_star: f64, work_of_adhesion: f64, cohesive_stress: f64) -> Result<Self> {
        Ok(Self { radius: check::positive("radius", radius)?, e_star: check::positive("e_star", e_star)?, work_of_adhesion: check::positive("work_of_adhesion", work_of_adhesion)?, cohesive_stress: check::positive("cohesive_stress", cohesive_stress)? })
    }
}

impl NormalContact for MaugisDugdale {
    fn eval(&self, _delta: f64, _old: &ContactState) -> Result<(NormalResponse, ContactState)> { Err(TODO) }
    fn eval_at_load(&self, _force: f64) -> Result<NormalResponse> { Err(TODO) }
    fn pull_off_force(&self, _control: Control) -> Result<f64> { Err(TODO) }
    fn length_scale(&self) -> f64 { self.radius }
}
