//! C ABI for `crate::material`.

use super::{guard, output};
use crate::material;

/// Contact modulus `1/E* = (1−ν₁²)/E₁ + (1−ν₂²)/E₂` (Pa). `E = INFINITY`
/// marks a rigid body. See `material::effective_modulus`.
#[no_mangle]
pub unsafe extern "C" fn asperity_effective_modulus(
    e1: f64,
    nu1: f64,
    e2: f64,
    nu2: f64,
    e_star: *mut f64,
) -> i32 {
    guard(|| {
        let out = output(e_star, "e_star")?;
        *out = material::effective_modulus(e1, nu1, e2, nu2)?;
        Ok(())
    })
}

/// Effective modulus of two rods end to end, `1/E = 1/E₁ + 1/E₂` (Pa),
/// thesis (6-8).
#[no_mangle]
pub unsafe extern "C" fn asperity_rod_effective_modulus(e1: f64, e2: f64, e_eff: *mut f64) -> i32 {
    guard(|| {
        *output(e_eff, "e_eff")? = material::rod_effective_modulus(e1, e2)?;
        Ok(())
    })
}

/// No-slip factor `C_NS = (1−ν) ln(3−4ν)/(1−2ν)`, continuous to 1 at ν = 1/2.
#[no_mangle]
pub unsafe extern "C" fn asperity_no_slip_factor(nu: f64, c_ns: *mut f64) -> i32 {
    guard(|| {
        *output(c_ns, "c_ns")? = material::no_slip_factor(nu)?;
        Ok(())
    })
}

/// Tabor parameter `μ = (R w²/(E*² z₀³))^{1/3}`.
#[no_mangle]
pub unsafe extern "C" fn asperity_tabor_parameter(
    radius: f64,
    work_of_adhesion: f64,
    e_star: f64,
    equilibrium_separation: f64,
    mu: *mut f64,
) -> i32 {
    guard(|| {
        *output(mu, "mu")? =
            material::tabor_parameter(radius, work_of_adhesion, e_star, equilibrium_separation)?;
        Ok(())
    })
}

/// Maugis parameter `λ = 2σ₀ (R/(π w K²))^{1/3}`, `K = 4E*/3`.
#[no_mangle]
pub unsafe extern "C" fn asperity_maugis_parameter(
    radius: f64,
    work_of_adhesion: f64,
    e_star: f64,
    cohesive_stress: f64,
    lambda: *mut f64,
) -> i32 {
    guard(|| {
        *output(lambda, "lambda")? =
            material::maugis_parameter(radius, work_of_adhesion, e_star, cohesive_stress)?;
        Ok(())
    })
}
