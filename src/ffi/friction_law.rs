//! C ABI for `crate::friction::law`: every friction law behind one handle.
//!
//! * `AsperityFriction` (opaque, a boxed [`FrictionLaw`]) is built from a
//!   homogenised table (`asperity_friction_from_homogenised`), a slider
//!   (`asperity_friction_from_slider`) or a chapter-5 dynamic model's
//!   parameters (`asperity_friction_lugre_new`, …, in `ffi::dynamic`);
//!   immutable, one handle may be used by any number of threads at once.
//! * Per-point states are caller-owned arrays of
//!   `asperity_friction_state_size` doubles (all-zero = fresh; the
//!   accumulated dissipation at `ASPERITY_FRICTION_STATE_DISSIPATION` and slip
//!   path at `ASPERITY_FRICTION_STATE_SLIP_PATH` for every law, then the
//!   law's own variables).
//! * `AsperityFrictionWork` (opaque) is a step's scratch: one per thread,
//!   built once by `asperity_friction_work_new`. Every step accepts NULL
//!   instead, at the price of building a scratch per call (an allocation
//!   for the slider; nothing for the other laws).
//! * `asperity_friction_step` (old and new states separate) and
//!   `asperity_friction_step_in_place` step one point with every output and
//!   optional tangents; `asperity_friction_step_block` and
//!   `asperity_friction_step_block_in_place` step n points in the shape of
//!   Abaqus/Explicit VFRIC (forces and dissipations), and
//!   `asperity_friction_step_block_responses` steps n points with every
//!   point's full response and tangents (implicit hosts).
//!
//! Sign convention (as VFRIC): the slip increment is the motion of the
//! point relative to the counter-surface, the tangential force is the force
//! on the point and opposes slip.

use super::homogenised::AsperityHomogenisedFriction;
use super::slider::AsperitySlider;
use super::{guard, input, output, partial_overlap, Failure};
use crate::error::{Error, Result};
use crate::friction::law::{
    check_tangents, BlockStates, FrictionBlock, FrictionIncrement, FrictionLaw, FrictionRegime,
    FrictionResponse, FrictionWork, STATE_DISSIPATION, STATE_MODEL, STATE_SLIP_PATH,
    TANGENT_NORMAL, TANGENT_SLIP,
};

/// `AsperityFrictionIncrement.tangents` bit: compute dF/dN.
pub const ASPERITY_FRICTION_TANGENT_NORMAL: i32 = 1;
/// `AsperityFrictionIncrement.tangents` bit: compute dF/d(slip).
pub const ASPERITY_FRICTION_TANGENT_SLIP: i32 = 2;
/// Index in a friction state of the accumulated dissipation (J).
pub const ASPERITY_FRICTION_STATE_DISSIPATION: usize = 0;
/// Index in a friction state of the accumulated slip path sum |ds| (m).
pub const ASPERITY_FRICTION_STATE_SLIP_PATH: usize = 1;
/// Index in a friction state of the law's first own variable. Homogenised
/// law: the stick force (x, y; N), the plastic slip path (m), the
/// dissipation by mechanism (chemical, van der Waals, elastic, plastic; J).
/// Slider: a flag (0 fresh, 1 stepped), the position X (m), the rod-bed
/// position b (m, NaN: none), the dissipation by mechanism (J), the n rod
/// heights (m), the n rods' stored energies (J). LuGre: the bristle
/// deflection z (x, y; m). Maxwell-slip: the element deflections (x, y per
/// element; m). Generalised Maxwell-slip: per element the force per unit
/// normal force and the mode (0 sticking, +-1 slipping). Bristles: the bristle deflections (m). Prandtl-Tomlinson:
/// x - x_s (m), tip velocity (m/s), support position x_s (m), then with two
/// springs the cantilever body's x_c - x_s (m) and velocity (m/s).
/// Burridge-Knopoff: x_i - x_d (m) and v_i (m/s) per block, then the driver
/// position x_d (m).
pub const ASPERITY_FRICTION_STATE_MODEL: usize = 2;
/// `AsperityFrictionResponse.regime`: no slip (inside the slip cone, zero
/// slip, every element stuck).
pub const ASPERITY_FRICTION_STICK: i32 = 0;
/// `AsperityFrictionResponse.regime`: partial slip (pre-sliding: some
/// elements or bristles slipping).
pub const ASPERITY_FRICTION_PARTIAL_SLIP: i32 = 1;
/// `AsperityFrictionResponse.regime`: gross sliding.
pub const ASPERITY_FRICTION_SLIP: i32 = 2;
/// `AsperityFrictionResponse.regime`: no normal force and no adhesion; no
/// friction.
pub const ASPERITY_FRICTION_NO_CONTACT: i32 = 3;

const _: () = {
    assert!(ASPERITY_FRICTION_TANGENT_NORMAL == TANGENT_NORMAL);
    assert!(ASPERITY_FRICTION_TANGENT_SLIP == TANGENT_SLIP);
    assert!(ASPERITY_FRICTION_STATE_DISSIPATION == STATE_DISSIPATION);
    assert!(ASPERITY_FRICTION_STATE_SLIP_PATH == STATE_SLIP_PATH);
    assert!(ASPERITY_FRICTION_STATE_MODEL == STATE_MODEL);
    assert!(ASPERITY_FRICTION_STICK == FrictionRegime::Stick as i32);
    assert!(ASPERITY_FRICTION_PARTIAL_SLIP == FrictionRegime::PartialSlip as i32);
    assert!(ASPERITY_FRICTION_SLIP == FrictionRegime::Slip as i32);
    assert!(ASPERITY_FRICTION_NO_CONTACT == FrictionRegime::NoContact as i32);
};

/// A friction law stepped once per increment (opaque): the homogenised
/// law, the slider as a patch law, or a chapter-5 dynamic model. Release it
/// with `asperity_friction_free`. Immutable; safe to share between threads.
pub struct AsperityFriction(pub(crate) Box<dyn FrictionLaw>);

/// The scratch of a friction step (opaque): one per thread. Release it with
/// `asperity_friction_work_free`.
pub struct AsperityFrictionWork(pub(crate) FrictionWork);

/// Writes a new handle of the law `make()` builds to `*out` (NULL on
/// failure).
pub(crate) unsafe fn emit_law<L: FrictionLaw + 'static>(
    out: *mut *mut AsperityFriction,
    make: impl FnOnce() -> Result<L>,
) -> i32 {
    guard(|| {
        let out = output(out, "out")?;
        *out = core::ptr::null_mut();
        *out = Box::into_raw(Box::new(AsperityFriction(Box::new(make()?))));
        Ok(())
    })
}

/// The homogenised law of `table` with the stick stiffness
/// `stick_stiffness` (N/m, finite and >= 0; 0: rigid-plastic) of its
/// regularised stick. The law copies the table. Writes a new handle to
/// `*out` (NULL on failure).
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_from_homogenised(
    table: *const AsperityHomogenisedFriction,
    stick_stiffness: f64,
    out: *mut *mut AsperityFriction,
) -> i32 {
    emit_law(out, || {
        let t = &input(table, "table")?.0;
        t.clone().with_stick_stiffness(stick_stiffness)
    })
}

/// The hierarchical slider as the friction law of a surface patch (the
/// increment's normal force is the fixed load, at most the slider's
/// capacity; its area is unused). The law copies the slider. Writes a new
/// handle to `*out` (NULL on failure).
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_from_slider(
    slider: *const AsperitySlider,
    out: *mut *mut AsperityFriction,
) -> i32 {
    emit_law(out, || Ok(input(slider, "slider")?.0.clone()))
}

/// Release a law; NULL is accepted and ignored.
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_free(law: *mut AsperityFriction) {
    if !law.is_null() {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            drop(Box::from_raw(law));
        }));
    }
}

/// Write the number of doubles of one point's state to `*n` (homogenised:
/// 9; slider: 9 + 2 x rods; LuGre: 4; Maxwell-slip and generalised
/// Maxwell-slip: 2 + 2 x elements;
/// bristles: 2 + bristles; Prandtl-Tomlinson: 5, with two springs 7;
/// Burridge-Knopoff: 3 + 2 x blocks).
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_state_size(
    law: *const AsperityFriction,
    n: *mut usize,
) -> i32 {
    guard(|| {
        let l = &input(law, "law")?.0;
        *output(n, "n")? = l.state_len();
        Ok(())
    })
}

/// Build the scratch of a step with `law` and write the handle to `*out`
/// (NULL on failure). Use one per thread; a scratch made for another law is
/// rebuilt on first use.
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_work_new(
    law: *const AsperityFriction,
    out: *mut *mut AsperityFrictionWork,
) -> i32 {
    guard(|| {
        let out = output(out, "out")?;
        *out = core::ptr::null_mut();
        let l = &input(law, "law")?.0;
        *out = Box::into_raw(Box::new(AsperityFrictionWork(l.work())));
        Ok(())
    })
}

/// Release a scratch; NULL is accepted and ignored.
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_work_free(work: *mut AsperityFrictionWork) {
    if !work.is_null() {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            drop(Box::from_raw(work));
        }));
    }
}

/// Runs `f` with the caller's scratch, or a fresh one when `work` is NULL.
unsafe fn with_work<T>(
    law: &dyn FrictionLaw,
    work: *mut AsperityFrictionWork,
    f: impl FnOnce(&mut FrictionWork) -> T,
) -> T {
    match work.as_mut() {
        Some(w) => f(&mut w.0),
        None => f(&mut law.work()),
    }
}

fn overlap_error(name: &'static str, with: &'static str) -> Error {
    Error::InvalidArgument {
        name,
        value: 0.0,
        bound: with,
    }
}

/// One increment of one point: `*increment` from the state `old_state`
/// (`asperity_friction_state_size` doubles; all-zero = fresh) into
/// `new_state` (same size; may equal `old_state`, must not partially
/// overlap it) and the response into `*out`. The same old state and
/// increment give bit-identical results (cut-backs). `work` may be NULL.
/// No allocation with a `work`. On failure `new_state` and `*out` are
/// untouched; the message names the argument and its bound.
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_step(
    law: *const AsperityFriction,
    increment: *const FrictionIncrement,
    old_state: *const f64,
    new_state: *mut f64,
    work: *mut AsperityFrictionWork,
    out: *mut FrictionResponse,
) -> i32 {
    guard(|| {
        let l = &*input(law, "law")?.0;
        let inc = input(increment, "increment")?;
        input(old_state, "old_state")?;
        output(new_state, "new_state")?;
        let out = output(out, "out")?;
        let len = l.state_len();
        let r = if core::ptr::eq(old_state, new_state) {
            // SAFETY: the caller provides `len` writable values.
            let state = core::slice::from_raw_parts_mut(new_state, len);
            with_work(l, work, |w| l.step_in_place(state, inc, w))
        } else {
            if partial_overlap(old_state, new_state, len) {
                return Err(
                    overlap_error("new_state", "equal to old_state or not overlapping it").into(),
                );
            }
            // SAFETY: distinct, non-overlapping arrays of `len` values.
            let old = core::slice::from_raw_parts(old_state, len);
            let new = core::slice::from_raw_parts_mut(new_state, len);
            with_work(l, work, |w| l.step(old, new, inc, w))
        }?;
        *out = r;
        Ok(())
    })
}

/// `asperity_friction_step` with the state `state` updated in place (on
/// failure it is untouched).
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_step_in_place(
    law: *const AsperityFriction,
    increment: *const FrictionIncrement,
    state: *mut f64,
    work: *mut AsperityFrictionWork,
    out: *mut FrictionResponse,
) -> i32 {
    guard(|| {
        let l = &*input(law, "law")?.0;
        let inc = input(increment, "increment")?;
        output(state, "state")?;
        let out = output(out, "out")?;
        // SAFETY: the caller provides `state_size` writable values.
        let state = core::slice::from_raw_parts_mut(state, l.state_len());
        *out = with_work(l, work, |w| l.step_in_place(state, inc, w))?;
        Ok(())
    })
}

/// What a block call writes per point: the tangential forces (2n doubles)
/// and the dissipations (n, or NULL), or the full responses (n).
enum BlockOut {
    Forces {
        tangential_forces: *mut f64,
        dissipation: *mut f64,
    },
    Responses(*mut FrictionResponse),
}

/// The pointers of a block call, before they become slices.
struct RawBlock {
    n: usize,
    normal_forces: *const f64,
    areas: *const f64,
    slip_increments: *const f64,
    dt: f64,
    tangents: i32,
    out: BlockOut,
}

/// Steps a block: checks the tangent bits, the pointers and sizes, makes
/// the slices (the states by `states(total)`) and calls the law.
unsafe fn step_block(
    law: *const AsperityFriction,
    b: RawBlock,
    work: *mut AsperityFrictionWork,
    states: impl FnOnce(usize) -> core::result::Result<BlockStates<'static>, Failure>,
) -> i32 {
    guard(|| {
        let l = &*input(law, "law")?.0;
        check_tangents(b.tangents)?;
        let n = b.n;
        if n == 0 {
            return Ok(());
        }
        input(b.normal_forces, "normal_forces")?;
        input(b.slip_increments, "slip_increments")?;
        match b.out {
            BlockOut::Forces {
                tangential_forces, ..
            } => {
                output(tangential_forces, "tangential_forces")?;
            }
            BlockOut::Responses(r) => {
                output(r, "responses")?;
            }
        }
        let too_many = || Error::InvalidArgument {
            name: "n",
            value: n as f64,
            bound: "such that n * state size and 2n fit in size_t",
        };
        let total = n.checked_mul(l.state_len()).ok_or_else(too_many)?;
        let twice = n.checked_mul(2).ok_or_else(too_many)?;
        let states = states(total)?;
        // SAFETY: the caller provides n normal forces, n areas (or NULL),
        // 2n slips, and either 2n tangential forces and n dissipations (or
        // NULL), or n responses.
        let (tangential_force, dissipation, responses) = match b.out {
            BlockOut::Forces {
                tangential_forces,
                dissipation,
            } => (
                Some(core::slice::from_raw_parts_mut(tangential_forces, twice)),
                (!dissipation.is_null()).then(|| core::slice::from_raw_parts_mut(dissipation, n)),
                None,
            ),
            BlockOut::Responses(r) => (None, None, Some(core::slice::from_raw_parts_mut(r, n))),
        };
        let block = FrictionBlock {
            normal_force: core::slice::from_raw_parts(b.normal_forces, n),
            area: (!b.areas.is_null()).then(|| core::slice::from_raw_parts(b.areas, n)),
            slip: core::slice::from_raw_parts(b.slip_increments, twice),
            dt: b.dt,
            tangents: b.tangents,
            states,
            tangential_force,
            dissipation,
            responses,
        };
        with_work(l, work, |w| l.step_block(block, w)).map_err(|e| Failure::at(e.index, e.error))
    })
}

/// The states of `asperity_friction_step_block` and
/// `asperity_friction_step_block_responses`: `total` doubles at `old_states`
/// into `new_states`, in place when they are equal.
unsafe fn separate_or_in_place(
    old_states: *const f64,
    new_states: *mut f64,
    total: usize,
) -> core::result::Result<BlockStates<'static>, Failure> {
    input(old_states, "old_states")?;
    output(new_states, "new_states")?;
    // SAFETY: the caller provides `total` doubles at each pointer; equal
    // pointers are one mutable slice, otherwise they do not overlap.
    if core::ptr::eq(old_states, new_states) {
        return Ok(BlockStates::InPlace(core::slice::from_raw_parts_mut(
            new_states, total,
        )));
    }
    if partial_overlap(old_states, new_states, total) {
        return Err(overlap_error(
            "new_states",
            "equal to old_states (in place) or not overlapping it",
        )
        .into());
    }
    Ok(BlockStates::Separate {
        old: core::slice::from_raw_parts(old_states, total),
        new: core::slice::from_raw_parts_mut(new_states, total),
    })
}

/// Step `n` points at once, in the shape of Abaqus/Explicit VFRIC: normal
/// forces `normal_forces[i]` (N), nominal areas `areas[i]` (m^2; NULL: 0
/// for every point, refused by laws that need them), slip increments
/// `slip_increments[2i]`, `[2i+1]` (m, interleaved), one `dt` (s), the
/// states `old_states[i*m .. (i+1)*m]` -> `new_states[...]` (m =
/// `asperity_friction_state_size`; `new_states` may equal `old_states`,
/// must not partially overlap it), tangential forces out in
/// `tangential_forces[2i]`, `[2i+1]` (N) and the dissipated energy of the
/// increment in `dissipation[i]` (J; may be NULL). No tangents (see
/// `asperity_friction_step_block_responses`). `work` may be NULL. On an
/// error at point i, the points before i are written, those from i on
/// untouched, and the message names i.
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_step_block(
    law: *const AsperityFriction,
    n: usize,
    normal_forces: *const f64,
    areas: *const f64,
    slip_increments: *const f64,
    dt: f64,
    old_states: *const f64,
    new_states: *mut f64,
    tangential_forces: *mut f64,
    dissipation: *mut f64,
    work: *mut AsperityFrictionWork,
) -> i32 {
    let b = RawBlock {
        n,
        normal_forces,
        areas,
        slip_increments,
        dt,
        tangents: 0,
        out: BlockOut::Forces {
            tangential_forces,
            dissipation,
        },
    };
    step_block(law, b, work, |total| {
        separate_or_in_place(old_states, new_states, total)
    })
}

/// `asperity_friction_step_block` with the states `states` stepped in
/// place.
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_step_block_in_place(
    law: *const AsperityFriction,
    n: usize,
    normal_forces: *const f64,
    areas: *const f64,
    slip_increments: *const f64,
    dt: f64,
    states: *mut f64,
    tangential_forces: *mut f64,
    dissipation: *mut f64,
    work: *mut AsperityFrictionWork,
) -> i32 {
    let b = RawBlock {
        n,
        normal_forces,
        areas,
        slip_increments,
        dt,
        tangents: 0,
        out: BlockOut::Forces {
            tangential_forces,
            dissipation,
        },
    };
    step_block(law, b, work, |total| {
        output(states, "states")?;
        // SAFETY: the caller provides `total` writable doubles.
        Ok(BlockStates::InPlace(core::slice::from_raw_parts_mut(
            states, total,
        )))
    })
}

/// `asperity_friction_step_block` with each point's full response: the
/// states `old_states[i*m .. (i+1)*m]` -> `new_states[...]` (m =
/// `asperity_friction_state_size`; `new_states` may equal `old_states`,
/// must not partially overlap it) of the points with normal forces
/// `normal_forces[i]` (N), nominal areas `areas[i]` (m^2; NULL: 0 for every
/// point, refused by laws that need them), slip increments
/// `slip_increments[2i]`, `[2i+1]` (m, interleaved) and one `dt` (s), and
/// `responses[i]` (n, required) as `asperity_friction_step` gives it for
/// the increment of point i with `tangents` (0, or
/// `ASPERITY_FRICTION_TANGENT_NORMAL` | `ASPERITY_FRICTION_TANGENT_SLIP`,
/// for every point): the tangential force (N), the dissipated energy (J),
/// the stored energy (J), the regime, and the tangents dF/dN
/// (dimensionless) and dF/d(slip) (N/m) an implicit host needs for its
/// Jacobian. `work` may be NULL; n = 0 reads and writes nothing. Unknown
/// tangent bits are refused first (even with n = 0), NULL `responses`
/// with the other pointers. On an error at point i, the points before i
/// are written, those from i on untouched, and the message names i.
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_step_block_responses(
    law: *const AsperityFriction,
    n: usize,
    normal_forces: *const f64,
    areas: *const f64,
    slip_increments: *const f64,
    dt: f64,
    tangents: i32,
    old_states: *const f64,
    new_states: *mut f64,
    responses: *mut FrictionResponse,
    work: *mut AsperityFrictionWork,
) -> i32 {
    let b = RawBlock {
        n,
        normal_forces,
        areas,
        slip_increments,
        dt,
        tangents,
        out: BlockOut::Responses(responses),
    };
    step_block(law, b, work, |total| {
        separate_or_in_place(old_states, new_states, total)
    })
}
