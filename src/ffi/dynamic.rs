//! C ABI for `crate::friction::dynamic`: the dynamic friction models of
//! thesis chapter 5 (LuGre, Maxwell-slip, Prandtl–Tomlinson with one or two
//! springs, the Burridge–Knopoff chain) as per-increment friction steps.
//!
//! * `AsperityDynamicFriction` (opaque, a boxed [`DynamicModel`]) is built by
//!   `asperity_dynamic_lugre_new`, `asperity_dynamic_maxwell_slip_new`,
//!   `asperity_dynamic_prandtl_tomlinson_new`,
//!   `asperity_dynamic_prandtl_tomlinson_two_spring_new` or
//!   `asperity_dynamic_burridge_knopoff_new`;
//!   immutable, one handle may be used by any number of threads at once.
//! * Per-point states are caller-owned arrays of
//!   `asperity_dynamic_friction_state_size` doubles (all-zero = fresh;
//!   layout: `ASPERITY_DYNAMIC_STATE_*`, then the model's variables).
//! * `asperity_dynamic_friction_step` steps one point with every output and
//!   optional tangents; `asperity_dynamic_friction_step_block` steps n points
//!   in the shape of Abaqus/Explicit VFRIC.
//!
//! Sign convention (as VFRIC and the other friction steps): the slip
//! increment is the motion of the point relative to the counter-surface, the
//! tangential force is the force on the point and opposes slip.

use super::{guard, input, output, partial_overlap, Failure};

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
use crate::error::{Error, Result};
use crate::friction::dynamic::burridge_knopoff::MAX_BLOCKS;
use crate::friction::dynamic::{
    Bristles, BurridgeKnopoff, DynamicFriction, DynamicIncrement, DynamicModel, DynamicResponse,
    LuGre, MaxwellSlip, PrandtlTomlinson, STATE_DISSIPATION, STATE_MODEL, STATE_SLIP_PATH,
    TANGENT_NORMAL, TANGENT_SLIP,
};

/// `AsperityDynamicIncrement.tangents` bit: compute dF/dN.
pub const ASPERITY_DYNAMIC_TANGENT_NORMAL: i32 = 1;
/// `AsperityDynamicIncrement.tangents` bit: compute dF/d(slip).
pub const ASPERITY_DYNAMIC_TANGENT_SLIP: i32 = 2;
/// Index in a dynamic-friction state of the accumulated dissipation (J).
pub const ASPERITY_DYNAMIC_STATE_DISSIPATION: usize = 0;
/// Index in a dynamic-friction state of the accumulated slip path (m).
pub const ASPERITY_DYNAMIC_STATE_SLIP_PATH: usize = 1;
/// Index in a dynamic-friction state of the model's first variable: LuGre's
/// bristle deflection z (x, y; m); Maxwell-slip's element deflections
/// (x, y per element; m); Prandtl-Tomlinson's x - x_s (m), tip velocity
/// (m/s), support position x_s (m), then with two springs the cantilever
/// body's x_c - x_s (m) and velocity (m/s); Burridge-Knopoff's x_i - x_d (m)
/// and v_i (m/s) per block, then the driver position x_d (m).
pub const ASPERITY_DYNAMIC_STATE_MODEL: usize = 2;
/// The largest Burridge-Knopoff chain (blocks).
pub const ASPERITY_DYNAMIC_MAX_BLOCKS: usize = 256;

const _: () = {
    assert!(ASPERITY_DYNAMIC_TANGENT_NORMAL == TANGENT_NORMAL);
    assert!(ASPERITY_DYNAMIC_TANGENT_SLIP == TANGENT_SLIP);
    assert!(ASPERITY_DYNAMIC_STATE_DISSIPATION == STATE_DISSIPATION);
    assert!(ASPERITY_DYNAMIC_STATE_SLIP_PATH == STATE_SLIP_PATH);
    assert!(ASPERITY_DYNAMIC_STATE_MODEL == STATE_MODEL);
    assert!(ASPERITY_DYNAMIC_MAX_BLOCKS == MAX_BLOCKS);
};

/// A dynamic friction model (opaque): LuGre, Maxwell-slip,
/// Prandtl-Tomlinson (one or two springs) or Burridge-Knopoff. Create it
/// with `asperity_dynamic_*_new`, release it with
/// `asperity_dynamic_friction_free`. Immutable; safe to share between
/// threads.
pub struct AsperityDynamicFriction(DynamicModel);

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
    out: *mut *mut AsperityDynamicFriction,
    make: impl FnOnce() -> Result<DynamicModel>,
) -> i32 {
    guard(|| {
        let out = output(out, "out")?;
        *out = core::ptr::null_mut();
        *out = Box::into_raw(Box::new(AsperityDynamicFriction(make()?)));
        Ok(())
    })
}

/// Build a LuGre model from `*params` (Canudas de Wit et al. 1995, scaled
/// by the normal force, integrated exactly per increment). Writes a new
/// handle to `*out` (NULL on failure). Errors name the field and its bound
/// (`params.sigma1` for the passivity bound).
#[no_mangle]
pub unsafe extern "C" fn asperity_dynamic_lugre_new(
    params: *const AsperityLugreParams,
    out: *mut *mut AsperityDynamicFriction,
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
pub unsafe extern "C" fn asperity_dynamic_maxwell_slip_new(
    stiffness: *const f64,
    capacity: *const f64,
    n: usize,
    sigma2: f64,
    out: *mut *mut AsperityDynamicFriction,
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

/// Build `n` >= 1 bristles (Haessig and Friedland 1991): stiffnesses
/// `stiffness[i]` (1/m per unit normal force, > 0) and break deflections
/// `break_deflection[i]` (m, > 0), viscous coefficient `sigma2`
/// (N s/m, >= 0). A bristle that reaches its break deflection snaps and
/// bonds again undeflected. One-dimensional: increments need `slip[1]` = 0.
/// Writes a new handle to `*out` (NULL on failure).
#[no_mangle]
pub unsafe extern "C" fn asperity_dynamic_bristles_new(
    stiffness: *const f64,
    break_deflection: *const f64,
    n: usize,
    sigma2: f64,
    out: *mut *mut AsperityDynamicFriction,
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
pub unsafe extern "C" fn asperity_dynamic_prandtl_tomlinson_new(
    amplitude: f64,
    period: f64,
    stiffness: f64,
    mass: f64,
    damping: f64,
    tolerance: f64,
    out: *mut *mut AsperityDynamicFriction,
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
pub unsafe extern "C" fn asperity_dynamic_prandtl_tomlinson_two_spring_new(
    params: *const AsperityPrandtlTomlinsonTwoSpringParams,
    out: *mut *mut AsperityDynamicFriction,
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
pub unsafe extern "C" fn asperity_dynamic_burridge_knopoff_new(
    params: *const AsperityBurridgeKnopoffParams,
    out: *mut *mut AsperityDynamicFriction,
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

/// Release a model; NULL is accepted and ignored.
#[no_mangle]
pub unsafe extern "C" fn asperity_dynamic_friction_free(model: *mut AsperityDynamicFriction) {
    if !model.is_null() {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            drop(Box::from_raw(model));
        }));
    }
}

/// Write the number of doubles of one point's state to `*n` (LuGre: 4;
/// Maxwell-slip: 2 + 2 x elements; Prandtl-Tomlinson: 5, with two springs
/// 7; Burridge-Knopoff: 3 + 2 x blocks).
#[no_mangle]
pub unsafe extern "C" fn asperity_dynamic_friction_state_size(
    model: *const AsperityDynamicFriction,
    n: *mut usize,
) -> i32 {
    guard(|| {
        let m = &input(model, "model")?.0;
        *output(n, "n")? = m.state_len();
        Ok(())
    })
}

/// One increment of one point: `*increment` from the state `old_state`
/// (`asperity_dynamic_friction_state_size` doubles; all-zero = fresh) into
/// `new_state` (same size; may equal `old_state` to step in place, must not
/// partially overlap it) and the response into `*out`. The same old state
/// and increment give bit-identical results (cut-backs). No allocation. On
/// failure `new_state` and `*out` are untouched; the message names the
/// argument and its bound.
#[no_mangle]
pub unsafe extern "C" fn asperity_dynamic_friction_step(
    model: *const AsperityDynamicFriction,
    increment: *const DynamicIncrement,
    old_state: *const f64,
    new_state: *mut f64,
    out: *mut DynamicResponse,
) -> i32 {
    guard(|| {
        let m = &input(model, "model")?.0;
        let inc = input(increment, "increment")?;
        input(old_state, "old_state")?;
        output(new_state, "new_state")?;
        let out = output(out, "out")?;
        let len = m.state_len();
        let r = if core::ptr::eq(old_state, new_state) {
            // SAFETY: the caller provides `len` writable values.
            m.step_in_place(core::slice::from_raw_parts_mut(new_state, len), inc)
        } else {
            if partial_overlap(old_state, new_state, len) {
                return Err(Error::InvalidArgument {
                    name: "new_state",
                    value: len as f64,
                    bound: "equal to old_state or not overlapping it",
                }
                .into());
            }
            // SAFETY: distinct, non-overlapping arrays of `len` values.
            m.step(
                core::slice::from_raw_parts(old_state, len),
                core::slice::from_raw_parts_mut(new_state, len),
                inc,
            )
        }?;
        *out = r;
        Ok(())
    })
}

/// Step `n` points at once, in the shape of Abaqus/Explicit VFRIC: normal
/// forces `normal_forces[i]` (N), slip increments `slip_increments[2i]`,
/// `[2i+1]` (m, interleaved), one `dt` (s), the states
/// `states[i*m .. (i+1)*m]` (m = `asperity_dynamic_friction_state_size`)
/// stepped in place, tangential forces out in `tangential_forces[2i]`,
/// `[2i+1]` (N) and the dissipated energy of the increment in
/// `dissipation[i]` (J; may be NULL). No tangents. On an error at point i,
/// the points before i are written and the message names i.
#[no_mangle]
pub unsafe extern "C" fn asperity_dynamic_friction_step_block(
    model: *const AsperityDynamicFriction,
    n: usize,
    normal_forces: *const f64,
    slip_increments: *const f64,
    dt: f64,
    states: *mut f64,
    tangential_forces: *mut f64,
    dissipation: *mut f64,
) -> i32 {
    guard(|| {
        let m = &input(model, "model")?.0;
        if n == 0 {
            return Ok(());
        }
        let len = m.state_len();
        // SAFETY: the caller provides arrays of the documented lengths.
        let normal = core::slice::from_raw_parts(input(normal_forces, "normal_forces")?, n);
        let slip = core::slice::from_raw_parts(input(slip_increments, "slip_increments")?, 2 * n);
        let states = core::slice::from_raw_parts_mut(output(states, "states")?, n * len);
        let forces =
            core::slice::from_raw_parts_mut(output(tangential_forces, "tangential_forces")?, 2 * n);
        let diss = if dissipation.is_null() {
            None
        } else {
            Some(core::slice::from_raw_parts_mut(dissipation, n))
        };
        m.step_block(normal, slip, dt, states, forces, diss)
            .map_err(|e| Failure::at(e.index, e.error))
    })
}
