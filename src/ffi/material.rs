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

/// Weir surface energy prefactor `K = 1/((m−2)(n−2))` (the default).
pub const ASPERITY_WEIR_PLANE_SUM: i32 = 0;
/// Weir surface energy prefactor `K = 3/(mn)` (reproduces seed 001's 8.6 nN).
pub const ASPERITY_WEIR_THREE_OVER_MN: i32 = 1;
/// Pair rule: Dupré with geometric-mean interfacial energy, `w = 2√(γ₁γ₂)`.
pub const ASPERITY_PAIR_GEOMETRIC_MEAN: i32 = 0;
/// Pair rule of seed 001: `Δγ = (√γ₁ − √γ₂)²`.
pub const ASPERITY_PAIR_SEED001_DIFFERENCE: i32 = 1;

/// Weir's surface energy `γ = a·B/((m−2)(n−2))` (J/m²), `a = (M/ρ)^{1/3}`,
/// `B = E/(3(1−2ν))`: `atomic_mass` in kg per atom, `density` kg/m³,
/// `youngs_modulus` Pa, `poisson_ratio` in [0, 0.5), exponents 2 < m < n.
#[no_mangle]
pub unsafe extern "C" fn asperity_weir_surface_energy(
    atomic_mass: f64,
    density: f64,
    youngs_modulus: f64,
    poisson_ratio: f64,
    m: f64,
    n: f64,
    gamma: *mut f64,
) -> i32 {
    asperity_weir_surface_energy_with(
        atomic_mass,
        density,
        youngs_modulus,
        poisson_ratio,
        m,
        n,
        ASPERITY_WEIR_PLANE_SUM,
        gamma,
    )
}

/// [`asperity_weir_surface_energy`] with the prefactor chosen by `prefactor`
/// (`ASPERITY_WEIR_PLANE_SUM` or `ASPERITY_WEIR_THREE_OVER_MN`).
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn asperity_weir_surface_energy_with(
    atomic_mass: f64,
    density: f64,
    youngs_modulus: f64,
    poisson_ratio: f64,
    m: f64,
    n: f64,
    prefactor: i32,
    gamma: *mut f64,
) -> i32 {
    guard(|| {
        let out = output(gamma, "gamma")?;
        let k = match prefactor {
            ASPERITY_WEIR_PLANE_SUM => material::WeirPrefactor::PlaneSum,
            ASPERITY_WEIR_THREE_OVER_MN => material::WeirPrefactor::ThreeOverMn,
            v => {
                return Err(crate::Error::UnknownSelector {
                    name: "prefactor",
                    value: v as i64,
                }
                .into())
            }
        };
        *out = material::weir_surface_energy(
            atomic_mass,
            density,
            youngs_modulus,
            poisson_ratio,
            m,
            n,
            k,
        )?;
        Ok(())
    })
}

/// Work of adhesion (J/m²) of a pair of surface energies (J/m²) under `rule`
/// (`ASPERITY_PAIR_GEOMETRIC_MEAN` or `ASPERITY_PAIR_SEED001_DIFFERENCE`).
#[no_mangle]
pub unsafe extern "C" fn asperity_pair_work_of_adhesion(
    gamma1: f64,
    gamma2: f64,
    rule: i32,
    work_of_adhesion: *mut f64,
) -> i32 {
    guard(|| {
        let out = output(work_of_adhesion, "work_of_adhesion")?;
        let rule = match rule {
            ASPERITY_PAIR_GEOMETRIC_MEAN => material::PairRule::GeometricMean,
            ASPERITY_PAIR_SEED001_DIFFERENCE => material::PairRule::Seed001Difference,
            v => {
                return Err(crate::Error::UnknownSelector {
                    name: "rule",
                    value: v as i64,
                }
                .into())
            }
        };
        *out = material::pair_work_of_adhesion(gamma1, gamma2, rule)?;
        Ok(())
    })
}

/// Work of adhesion `A/(12πD₀²)` (J/m²) from a Hamaker constant (J) and a
/// separation D₀ (m).
#[no_mangle]
pub unsafe extern "C" fn asperity_hamaker_work_of_adhesion(
    hamaker: f64,
    separation: f64,
    work_of_adhesion: *mut f64,
) -> i32 {
    guard(|| {
        *output(work_of_adhesion, "work_of_adhesion")? =
            material::hamaker_work_of_adhesion(hamaker, separation)?;
        Ok(())
    })
}
