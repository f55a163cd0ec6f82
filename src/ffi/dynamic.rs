//! C ABI for `crate::friction::dynamic`: the dynamic friction models of
//! thesis chapter 5 (LuGre, Maxwell-slip, Prandtl–Tomlinson with one or two
//! springs, the Burridge–Knopoff chain) as per-increment friction steps.
//!
//! Each constructor (`asperity_friction_lugre_new`,
//! `asperity_friction_maxwell_slip_new`,
//! `asperity_friction_generalized_maxwell_slip_new`,
//! `asperity_friction_bristles_new`,
//! `asperity_friction_prandtl_tomlinson_new`,
//! `asperity_friction_prandtl_tomlinson_two_spring_new`,
//! `asperity_friction_burridge_knopoff_new`) validates its parameter struct
//! and writes an `AsperityFriction` handle, stepped through the one friction
//! handle (`ffi::friction_law`).

use super::friction_law::{emit_law, AsperityFriction};
use super::input;

/// `ctor(p.a, p.b, …)` for a constructor whose arguments are the C
/// parameter struct's fields, in order and under the same names, with its
/// errors renamed to the fields (`params.a`, …).
macro_rules! from_params {
    ($ctor:path, $p:expr, $($field:ident),+ $(,)?) => {{
        let p = $p;
        $ctor($(p.$field),+).map_err(|e| {
            $(let e = e.renamed(stringify!($field), concat!("params.", stringify!($field)));)+
            e
        })
    }};
}
use crate::error::Result;
use crate::friction::dynamic::burridge_knopoff::MAX_BLOCKS;
use crate::friction::dynamic::{
    Bristles, BurridgeKnopoff, DynamicModel, GeneralizedMaxwellSlip, LuGre, MaxwellSlip,
    PrandtlTomlinson,
};

/// The largest Burridge-Knopoff chain (blocks).
pub const ASPERITY_DYNAMIC_MAX_BLOCKS: usize = 256;

const _: () = assert!(ASPERITY_DYNAMIC_MAX_BLOCKS == MAX_BLOCKS);

/// The LuGre model's parameters (see `LuGre::new`). SI units.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityLugreParams {
    /// Coulomb coefficient mu_c, finite and >= 0.
    pub mu_coulomb: f64,
    /// Static coefficient mu_s, finite and >= 0 (mu_c or mu_s > 0).
    pub mu_static: f64,
    /// Stribeck velocity v_s (m/s), finite and > 0.
    pub stribeck_velocity: f64,
    /// Stribeck exponent delta, finite and > 0 (2: Gaussian).
    pub stribeck_exponent: f64,
    /// Bristle stiffness per unit normal force sigma_0 (1/m), finite, > 0.
    pub sigma0: f64,
    /// Bristle damping per unit normal force sigma_1 (s/m), finite, >= 0,
    /// with sigma_1 v_d / sqrt(2e) <= 4 min(mu_c, mu_s) (passivity).
    pub sigma1: f64,
    /// Velocity v_d (m/s) of the damping's decay sigma_1 exp(-(v/v_d)^2),
    /// > 0; +infinity only when sigma_1 = 0.
    pub damping_velocity: f64,
    /// Viscous coefficient sigma_2 (N s/m), finite and >= 0.
    pub sigma2: f64,
}

/// The generalised Maxwell-slip model's Stribeck curve and rates (see
/// `GeneralizedMaxwellSlip::new`; the elements come as arrays). SI units.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityGeneralizedMaxwellSlipParams {
    /// Coulomb coefficient mu_c of the Stribeck curve, finite and > 0.
    pub mu_coulomb: f64,
    /// Static coefficient mu_s of the Stribeck curve, finite and > 0.
    pub mu_static: f64,
    /// Stribeck velocity v_s (m/s), finite and > 0.
    pub stribeck_velocity: f64,
    /// Stribeck exponent delta, finite and > 0 (2: Gaussian).
    pub stribeck_exponent: f64,
    /// Attraction rate C of the slip law per unit normal force (1/s), > 0;
    /// +infinity for the instantaneous limit.
    pub attraction: f64,
    /// Viscous coefficient sigma_2 (N s/m), finite and >= 0.
    pub sigma2: f64,
}

/// The two-spring (tip-cantilever) Prandtl-Tomlinson model's parameters
/// (see `PrandtlTomlinson::two_spring`). SI units.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityPrandtlTomlinsonTwoSpringParams {
    /// Lattice potential amplitude U0 (J), finite and > 0.
    pub amplitude: f64,
    /// Lattice period a (m), finite and > 0.
    pub period: f64,
    /// Tip (contact) spring k_t between the tip and the cantilever body
    /// (N/m), finite and > 0.
    pub tip_stiffness: f64,
    /// Tip mass m_t (kg), finite and > 0.
    pub tip_mass: f64,
    /// Tip damping gamma_t (kg/s), finite and >= 0.
    pub tip_damping: f64,
    /// Cantilever lateral spring k_c between the body and the support
    /// (N/m), finite and > 0.
    pub cantilever_stiffness: f64,
    /// Cantilever body mass m_c (kg), finite and > 0.
    pub cantilever_mass: f64,
    /// Cantilever damping gamma_c (kg/s), finite and >= 0.
    pub cantilever_damping: f64,
    /// Relative tolerance of the integration, in [1e-13, 1e-2].
    pub tolerance: f64,
}

/// The Burridge-Knopoff chain's parameters (see `BurridgeKnopoff::new`).
/// SI units.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityBurridgeKnopoffParams {
    /// Number of blocks M, in [1, `ASPERITY_DYNAMIC_MAX_BLOCKS`]; each
    /// carries N/M of the normal force.
    pub blocks: usize,
    /// Mass of each block m (kg), finite and > 0.
    pub mass: f64,
    /// Coupling spring k_c between neighbours (N/m), finite and >= 0.
    pub coupling_stiffness: f64,
    /// Leaf spring k_p from the driver to each block (N/m), finite, > 0.
    pub pulling_stiffness: f64,
    /// Static coefficient mu_s, finite and >= 0.
    pub mu_static: f64,
    /// Kinetic coefficient mu_k at the onset of slip, in [0, mu_s].
    pub mu_kinetic: f64,
    /// Weakening velocity v_c (m/s) of mu_k / (1 + v/v_c), > 0;
    /// +infinity for constant kinetic friction.
    pub weakening_velocity: f64,
    /// Viscous damping of each block against the substrate (kg/s),
    /// finite and >= 0.
    pub damping: f64,
    /// Relative tolerance of the integration, in [1e-13, 1e-2].
    pub tolerance: f64,
}

unsafe fn emit(
    out: *mut *mut AsperityFriction,
    make: impl FnOnce() -> Result<DynamicModel>,
) -> i32 {
    emit_law(out, make)
}

/// Build a LuGre model from `*params` (Canudas de Wit et al. 1995, scaled
/// by the normal force, integrated exactly per increment). Writes a new
/// handle to `*out` (NULL on failure). Errors name the field and its bound
/// (`params.sigma1` for the passivity bound).
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_lugre_new(
    params: *const AsperityLugreParams,
    out: *mut *mut AsperityFriction,
) -> i32 {
    emit(out, || {
        from_params!(
            LuGre::new,
            input(params, "params")?,
            mu_coulomb,
            mu_static,
            stribeck_velocity,
            stribeck_exponent,
            sigma0,
            sigma1,
            damping_velocity,
            sigma2,
        )
        .map(DynamicModel::LuGre)
    })
}

/// Build `n` >= 1 Maxwell-slip elements in parallel: stiffnesses
/// `stiffness[i]` (1/m per unit normal force, > 0), break-away
/// coefficients `capacity[i]` (>= 0), viscous coefficient `sigma2`
/// (N s/m, >= 0). Writes a new handle to `*out` (NULL on failure).
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_maxwell_slip_new(
    stiffness: *const f64,
    capacity: *const f64,
    n: usize,
    sigma2: f64,
    out: *mut *mut AsperityFriction,
) -> i32 {
    emit(out, || {
        let k = input(stiffness, "stiffness")?;
        let m = input(capacity, "capacity")?;
        // SAFETY: the caller provides `n` readable values at each pointer.
        let (k, m) = (
            core::slice::from_raw_parts(k, n),
            core::slice::from_raw_parts(m, n),
        );
        MaxwellSlip::new(k, m, sigma2).map(DynamicModel::MaxwellSlip)
    })
}

/// Build the generalised Maxwell-slip model (Al-Bender, Lampaert and
/// Swevers 2005): `n` >= 1 elements of stiffnesses `stiffness[i]` (1/m per
/// unit normal force, > 0) and weights `weight[i]` (>= 0) whose slip is
/// attracted to their share weight\[i\] s(v) of the Stribeck curve of
/// `*params`. One-dimensional: increments need `slip[1]` = 0, and dt > 0
/// with a non-zero slip. Writes a new handle to `*out` (NULL on failure);
/// errors name the array or the field (`params.attraction`, ...).
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_generalized_maxwell_slip_new(
    stiffness: *const f64,
    weight: *const f64,
    n: usize,
    params: *const AsperityGeneralizedMaxwellSlipParams,
    out: *mut *mut AsperityFriction,
) -> i32 {
    emit(out, || {
        let k = input(stiffness, "stiffness")?;
        let a = input(weight, "weight")?;
        let p = *input(params, "params")?;
        // SAFETY: the caller provides `n` readable values at each pointer.
        let (k, a) = (
            core::slice::from_raw_parts(k, n),
            core::slice::from_raw_parts(a, n),
        );
        GeneralizedMaxwellSlip::new(
            k,
            a,
            p.mu_coulomb,
            p.mu_static,
            p.stribeck_velocity,
            p.stribeck_exponent,
            p.attraction,
            p.sigma2,
        )
        .map_err(|e| {
            let mut e = e.renamed("weight.len()", "n");
            for (from, to) in [
                ("mu_coulomb", "params.mu_coulomb"),
                ("mu_static", "params.mu_static"),
                ("stribeck_velocity", "params.stribeck_velocity"),
                ("stribeck_exponent", "params.stribeck_exponent"),
                ("attraction", "params.attraction"),
                ("sigma2", "params.sigma2"),
            ] {
                e = e.renamed(from, to);
            }
            e
        })
        .map(DynamicModel::GeneralizedMaxwellSlip)
    })
}

/// Build `n` >= 1 bristles (Haessig and Friedland 1991): stiffnesses
/// `stiffness[i]` (1/m per unit normal force, > 0) and break deflections
/// `break_deflection[i]` (m, > 0), viscous coefficient `sigma2`
/// (N s/m, >= 0). A bristle that reaches its break deflection snaps and
/// bonds again undeflected. One-dimensional: increments need `slip[1]` = 0.
/// Writes a new handle to `*out` (NULL on failure).
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_bristles_new(
    stiffness: *const f64,
    break_deflection: *const f64,
    n: usize,
    sigma2: f64,
    out: *mut *mut AsperityFriction,
) -> i32 {
    emit(out, || {
        let k = input(stiffness, "stiffness")?;
        let d = input(break_deflection, "break_deflection")?;
        // SAFETY: the caller provides `n` readable values at each pointer.
        let (k, d) = (
            core::slice::from_raw_parts(k, n),
            core::slice::from_raw_parts(d, n),
        );
        Bristles::new(k, d, sigma2)
            .map(DynamicModel::Bristles)
            .map_err(|e| e.renamed("break_deflection.len()", "n"))
    })
}

/// Build a Prandtl–Tomlinson tip: lattice potential amplitude `amplitude`
/// U0 (J, > 0) and period `period` a (m, > 0), spring stiffness `stiffness`
/// k (N/m, > 0), tip mass `mass` (kg, > 0), damping `damping` (kg/s, >= 0),
/// relative tolerance `tolerance` of the integration (in [1e-13, 1e-2]).
/// One-dimensional: increments need `slip[1]` = 0. Stick-slip when
/// 4 pi^2 U0/(k a^2) > 1. Writes a new handle to `*out` (NULL on failure).
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_prandtl_tomlinson_new(
    amplitude: f64,
    period: f64,
    stiffness: f64,
    mass: f64,
    damping: f64,
    tolerance: f64,
    out: *mut *mut AsperityFriction,
) -> i32 {
    emit(out, || {
        PrandtlTomlinson::new(amplitude, period, stiffness, mass, damping, tolerance)
            .map(DynamicModel::PrandtlTomlinson)
    })
}

/// Build a two-spring (tip-cantilever) Prandtl-Tomlinson model from
/// `*params`: the tip in the lattice potential joined by the tip spring to
/// the cantilever body, joined by the cantilever spring to the support
/// (Johnson and Woodhouse 1998). One-dimensional: increments need
/// `slip[1]` = 0. Stick-slip when 4 pi^2 U0/(k_eff a^2) > 1 with
/// 1/k_eff = 1/k_t + 1/k_c. Writes a new handle to `*out` (NULL on
/// failure); errors name the field (`params.tip_mass`, ...).
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_prandtl_tomlinson_two_spring_new(
    params: *const AsperityPrandtlTomlinsonTwoSpringParams,
    out: *mut *mut AsperityFriction,
) -> i32 {
    emit(out, || {
        from_params!(
            PrandtlTomlinson::two_spring,
            input(params, "params")?,
            amplitude,
            period,
            tip_stiffness,
            tip_mass,
            tip_damping,
            cantilever_stiffness,
            cantilever_mass,
            cantilever_damping,
            tolerance,
        )
        .map(DynamicModel::PrandtlTomlinson)
    })
}

/// Build a Burridge-Knopoff chain from `*params`: M blocks coupled by
/// springs, pulled by leaf springs from a driver that moves by the
/// increment's slip, with static friction mu_s N/M and velocity-weakening
/// kinetic friction mu_k (N/M)/(1 + v/v_c) on each (Burridge and Knopoff
/// 1967; Carlson and Langer 1989); free ends. One-dimensional: increments
/// need `slip[1]` = 0. The force is the leaf springs' pull on the driver.
/// Writes a new handle to `*out` (NULL on failure); errors name the field
/// (`params.blocks`, ...).
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_burridge_knopoff_new(
    params: *const AsperityBurridgeKnopoffParams,
    out: *mut *mut AsperityFriction,
) -> i32 {
    emit(out, || {
        from_params!(
            BurridgeKnopoff::new,
            input(params, "params")?,
            blocks,
            mass,
            coupling_stiffness,
            pulling_stiffness,
            mu_static,
            mu_kinetic,
            weakening_velocity,
            damping,
            tolerance,
        )
        .map(DynamicModel::BurridgeKnopoff)
    })
}
