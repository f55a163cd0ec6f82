//! C ABI for `crate::fidelity`.

use super::{guard, output};
use crate::fidelity::{self, Assessment, Fidelity};

/// Fidelity: DMT.
pub const ASPERITY_FIDELITY_DMT: i32 = 0;
/// Fidelity: tabulated Maugis–Dugdale.
pub const ASPERITY_FIDELITY_TABULATED_MAUGIS_DUGDALE: i32 = 1;
/// Fidelity: tabulated Lennard-Jones sphere.
pub const ASPERITY_FIDELITY_TABULATED_LENNARD_JONES: i32 = 2;
/// Fidelity: JKR.
pub const ASPERITY_FIDELITY_JKR: i32 = 3;
/// Fidelity: Maugis–Dugdale (λ = 1.157 μ).
pub const ASPERITY_FIDELITY_MAUGIS_DUGDALE: i32 = 4;
/// Fidelity: the full numerical Lennard-Jones sphere.
pub const ASPERITY_FIDELITY_LENNARD_JONES: i32 = 5;

/// One model measured against the converged Lennard-Jones sphere.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct AsperityFidelityAssessment {
    /// One of `ASPERITY_FIDELITY_*`.
    pub law: i32,
    /// Reserved, 0.
    pub reserved: i32,
    /// |P_c,model − P_c,LJ| (N), load-controlled pull-off.
    pub pull_off_error: f64,
    /// Largest force difference over a displacement-controlled approach and
    /// retraction (N).
    pub curve_error: f64,
    /// Time per evaluation on this machine (s).
    pub cost_per_call: f64,
    /// One-time construction time (s).
    pub build_time: f64,
}

/// The advisor's answer.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct AsperityFidelityAdvice {
    /// The cheapest model within the tolerance (`ASPERITY_FIDELITY_*`).
    pub choice: i32,
    /// Reference grid size of the Lennard-Jones solution.
    pub reference_grid: i32,
    /// Tabor parameter μ.
    pub tabor: f64,
    /// Load-controlled pull-off of the reference (N, negative).
    pub reference_pull_off: f64,
    /// Every model, cheapest first (index = `ASPERITY_FIDELITY_*`).
    pub assessments: [AsperityFidelityAssessment; 6],
}

fn code(f: Fidelity) -> i32 {
    match f {
        Fidelity::Dmt => ASPERITY_FIDELITY_DMT,
        Fidelity::TabulatedMaugisDugdale => ASPERITY_FIDELITY_TABULATED_MAUGIS_DUGDALE,
        Fidelity::TabulatedLennardJones => ASPERITY_FIDELITY_TABULATED_LENNARD_JONES,
        Fidelity::Jkr => ASPERITY_FIDELITY_JKR,
        Fidelity::MaugisDugdale => ASPERITY_FIDELITY_MAUGIS_DUGDALE,
        Fidelity::LennardJones => ASPERITY_FIDELITY_LENNARD_JONES,
    }
}

fn to_c(a: &Assessment) -> AsperityFidelityAssessment {
    AsperityFidelityAssessment {
        law: code(a.law),
        reserved: 0,
        pull_off_error: a.pull_off_error,
        curve_error: a.curve_error,
        cost_per_call: a.cost_per_call,
        build_time: a.build_time,
    }
}

/// The cheapest adhesive-sphere model whose pull-off and force–approach
/// errors against the converged Lennard-Jones sphere are within
/// `force_tolerance` (N): radius R (m), contact modulus E* (Pa), work of
/// adhesion w (J/m²), equilibrium separation z₀ (m). Runs the Lennard-Jones
/// solver (milliseconds to seconds); not for a hot path.
#[no_mangle]
pub unsafe extern "C" fn asperity_fidelity_advise(
    radius: f64,
    e_star: f64,
    work_of_adhesion: f64,
    z0: f64,
    force_tolerance: f64,
    out: *mut AsperityFidelityAdvice,
) -> i32 {
    guard(|| {
        let out = output(out, "out")?;
        let a = fidelity::advise(radius, e_star, work_of_adhesion, z0, force_tolerance)?;
        let mut c = AsperityFidelityAdvice {
            choice: code(a.choice),
            reference_grid: a.reference_grid as i32,
            tabor: a.tabor,
            reference_pull_off: a.reference_pull_off,
            ..Default::default()
        };
        for (slot, x) in c.assessments.iter_mut().zip(&a.assessments) {
            *slot = to_c(x);
        }
        *out = c;
        Ok(())
    })
}
