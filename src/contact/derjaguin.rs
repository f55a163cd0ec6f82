//! STUB — to be implemented (Derjaguin approximation, rigid sphere with a surface law).
use super::{Control, ContactState, NormalContact, NormalResponse};
use crate::error::{check, Error, Result};

/// The surface-force law between two flats, attraction positive.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SurfaceLaw {
    /// Lennard-Jones 3-9.
    LennardJones {
        /// Work of adhesion w (J/m²).
        work_of_adhesion: f64,
        /// Equilibrium separation z₀ (m).
        equilibrium_separation: f64,
    },
    /// Dugdale step.
    Dugdale {
        /// Work of adhesion w (J/m²).
        work_of_adhesion: f64,
        /// Cohesive stress σ₀ (Pa).
        cohesive_stress: f64,
    },
    /// Exponential.
    Exponential {
        /// Work of adhesion w (J/m²).
        work_of_adhesion: f64,
        /// Decay length ℓ (m).
        decay_length: f64,
    },
}

/// Rigid sphere with a surface-force law.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Derjaguin {
    /// Sphere radius R (m).
    pub radius: f64,
    /// Work of adhesion w (J/m²).
    pub work_of_adhesion: f64,
    /// The law's length (m): z₀, h₀ = w/σ₀ or ℓ.
    pub range: f64,
    /// Surface law selector (`ASPERITY_SURFACE_LAW_*`).
    pub surface_law: i32,
    /// Reserved, 0.
    pub reserved: i32,
}

const TODO: Error = Error::OutOfDomain { name: "law", value: 0.0, reason: "not implemented" };

impl Derjaguin {
    /// A rigid sphere of radius `radius` (m) with the surface law `law`.
    pub fn new(radius: f64, law: SurfaceLaw) -> Result<Self> {
        let _ = law;
        Ok(Self { radius: check::positive("radius", radius)?, work_of_adhesion: 0.0, range: 1.0, surface_law: 0, reserved: 0 })
    }
}

impl NormalContact for Derjaguin {
    fn eval(&self, _delta: f64, _old: &ContactState) -> Result<(NormalResponse, ContactState)> { Err(TODO) }
    fn eval_at_load(&self, _force: f64) -> Result<NormalResponse> { Err(TODO) }
    fn pull_off_force(&self, _control: Control) -> Result<f64> { Err(TODO) }
    fn length_scale(&self) -> f64 { self.range }
}
