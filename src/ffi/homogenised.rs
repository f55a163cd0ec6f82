//! C ABI for `crate::friction::homogenised`: the opaque
//! `AsperityHomogenisedFriction` handle (a boxed [`HomogenisedFriction`]),
//! built from an array of samples or from JSON, the state size, the step per
//! point and the VFRIC-shaped block step.
//!
//! A law is immutable after construction: one handle may be used by any
//! number of threads at once (per-point states stay with the caller). Sign
//! convention (as Abaqus VFRIC): the slip increment is the motion of the
//! point relative to the counter-surface, the tangential force is the force
//! on the point and opposes slip.

use super::{copy_text, guard, input, output, read_text, Failure};
use crate::error::Result;
use crate::friction::{
    CofForm, FrictionIncrement, FrictionPointState, FrictionResponse, HomogenisedFriction,
    HomogenisedSample, RawFrictionBlock,
};
use std::ffi::c_char;

/// `AsperityFrictionResponse.regime`: the trial force is inside the cone, no
/// plastic slip.
pub const ASPERITY_FRICTION_STICK: i32 = 0;
/// `AsperityFrictionResponse.regime`: the force is on the cone, plastic slip
/// and dissipation.
pub const ASPERITY_FRICTION_SLIP: i32 = 1;
/// `AsperityFrictionResponse.regime`: no normal force and no adhesion; no
/// friction (force 0).
pub const ASPERITY_FRICTION_NO_CONTACT: i32 = 2;

const _: () = {
    use crate::friction::FrictionRegime as R;
    assert!(ASPERITY_FRICTION_STICK == R::Stick as i32);
    assert!(ASPERITY_FRICTION_SLIP == R::Slip as i32);
    assert!(ASPERITY_FRICTION_NO_CONTACT == R::NoContact as i32);
};

/// The homogenised friction law of FE integration points (opaque): μ(p),
/// adhesion, contact fraction and dissipation shares over the nominal
/// pressure. Create it with `asperity_homogenised_friction_new` or
/// `asperity_homogenised_friction_from_json`, release it with
/// `asperity_homogenised_friction_free`. Immutable; safe to share between
/// threads.
pub struct AsperityHomogenisedFriction(HomogenisedFriction);

unsafe fn emit(
    out: *mut *mut AsperityHomogenisedFriction,
    make: impl FnOnce() -> Result<HomogenisedFriction>,
) -> i32 {
    guard(|| {
        let out = output(out, "out")?;
        *out = core::ptr::null_mut();
        *out = Box::into_raw(Box::new(AsperityHomogenisedFriction(make()?)));
        Ok(())
    })
}

/// Build the law from `n` >= 1 samples at strictly increasing nominal
/// pressures (Pa), their `cof` read as the Derjaguin coefficient
/// F/(N + A) (thesis (4-3); other forms through JSON). Writes a new handle
/// to `*out` (NULL on failure). Errors: NULL `samples` or `out`, `n` = 0,
/// non-finite or negative values, fractions outside [0, 1], shares not
/// summing to 1, pressures not increasing.
#[no_mangle]
pub unsafe extern "C" fn asperity_homogenised_friction_new(
    samples: *const HomogenisedSample,
    n: usize,
    out: *mut *mut AsperityHomogenisedFriction,
) -> i32 {
    emit(out, || {
        let p = input(samples, "samples")?;
        // SAFETY: the caller provides `n` readable samples at `samples`.
        let s = core::slice::from_raw_parts(p as *const HomogenisedSample, n);
        HomogenisedFriction::from_samples(s, CofForm::Derjaguin)
    })
}

/// Load a law from `len` bytes of JSON text at `json` (from
/// `asperity_homogenised_friction_to_json`, or written by hand; no NUL
/// needed). The law is validated; a corrupted text gives
/// `ASPERITY_ERR_INVALID_ARGUMENT`. Writes a new handle to `*out` (NULL on
/// failure).
#[no_mangle]
pub unsafe extern "C" fn asperity_homogenised_friction_from_json(
    json: *const c_char,
    len: usize,
    out: *mut *mut AsperityHomogenisedFriction,
) -> i32 {
    emit(out, || {
        let text = read_text(json, len, "json")?;
        HomogenisedFriction::from_json(text)
    })
}

/// Write the JSON text of `friction` into `buf` (at most `len − 1` bytes and
/// a NUL) and its full length in bytes (without the NUL) to `*needed`, so
/// `asperity_homogenised_friction_to_json(f, NULL, 0, &n)` sizes the buffer.
/// The text is complete only when `*needed < len`; `needed` is required.
#[no_mangle]
pub unsafe extern "C" fn asperity_homogenised_friction_to_json(
    friction: *const AsperityHomogenisedFriction,
    buf: *mut c_char,
    len: usize,
    needed: *mut usize,
) -> i32 {
    guard(|| {
        let f = &input(friction, "friction")?.0;
        let needed = output(needed, "needed")?;
        *needed = copy_text(&f.to_json(), buf, len);
        Ok(())
    })
}

/// Release a law; NULL is accepted and ignored.
#[no_mangle]
pub unsafe extern "C" fn asperity_homogenised_friction_free(
    friction: *mut AsperityHomogenisedFriction,
) {
    if !friction.is_null() {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            drop(Box::from_raw(friction));
        }));
    }
}

/// Size in bytes of `AsperityFrictionPointState`, for hosts that allocate
/// per-point state arrays generically (an all-zero state is a fresh point).
#[no_mangle]
pub extern "C" fn asperity_homogenised_friction_state_size() -> usize {
    core::mem::size_of::<FrictionPointState>()
}

/// One friction step at one point: the increment `*increment` from the
/// history `*old_state` (NULL: fresh), the history after the step into
/// `*new_state` (may be NULL, may equal `old_state`) and the response into
/// `*out`. On failure `*new_state` and `*out` are untouched.
#[no_mangle]
pub unsafe extern "C" fn asperity_homogenised_friction_step(
    friction: *const AsperityHomogenisedFriction,
    increment: *const FrictionIncrement,
    old_state: *const FrictionPointState,
    new_state: *mut FrictionPointState,
    out: *mut FrictionResponse,
) -> i32 {
    guard(|| {
        let f = &input(friction, "friction")?.0;
        let inc = input(increment, "increment")?;
        let out = output(out, "out")?;
        let old = if old_state.is_null() {
            FrictionPointState::default()
        } else {
            old_state.read()
        };
        let (s, r) = f.step_value(&old, inc)?;
        *out = r;
        if !new_state.is_null() {
            new_state.write(s);
        }
        Ok(())
    })
}

/// Step `n` points at once, in the shape of Abaqus/Explicit VFRIC:
/// `normal_forces[i]` (N), `areas[i]` (m²), slip increments
/// `slip_increments[2i]`, `[2i+1]` (m, x and y interleaved), one `dt` (s) and
/// `stick_stiffness` (N/m) for all, `old_state[i]` → `new_state[i]`,
/// tangential forces out in `tangential_forces[2i]`, `[2i+1]` (N,
/// interleaved) and the dissipated energy of the increment in
/// `dissipation[i]` (J). `normal_forces`, `areas`, `slip_increments` and
/// `tangential_forces` are required; `old_state` may be NULL (all fresh),
/// `new_state` and `dissipation` may be NULL (not wanted); `old_state` may
/// equal `new_state`. On an error at element i, elements before i are written,
/// those from i on are untouched, and the message names i.
#[no_mangle]
pub unsafe extern "C" fn asperity_homogenised_friction_step_block(
    friction: *const AsperityHomogenisedFriction,
    n: usize,
    normal_forces: *const f64,
    areas: *const f64,
    slip_increments: *const f64,
    dt: f64,
    stick_stiffness: f64,
    old_state: *const FrictionPointState,
    new_state: *mut FrictionPointState,
    tangential_forces: *mut f64,
    dissipation: *mut f64,
) -> i32 {
    guard(|| {
        let f = &input(friction, "friction")?.0;
        if n == 0 {
            return Ok(());
        }
        input(normal_forces, "normal_forces")?;
        input(areas, "areas")?;
        input(slip_increments, "slip_increments")?;
        output(tangential_forces, "tangential_forces")?;
        f.step_block_raw(&RawFrictionBlock {
            n,
            normal_forces,
            areas,
            slip_increments,
            dt,
            stick_stiffness,
            old: old_state,
            new: new_state,
            tangential_forces,
            dissipation,
        })
        .map_err(|e| Failure::at(e.index, e.error))
    })
}
