//! C ABI for `crate::friction::homogenised`: the opaque
//! `AsperityHomogenisedFriction` handle (a boxed [`HomogenisedFriction`]),
//! the table built from an array of samples or from JSON.
//! `asperity_friction_from_homogenised` makes it a friction law with a stick
//! stiffness, stepped per increment through the one friction handle
//! (`ffi::friction_law`).
//!
//! A table is immutable after construction: one handle may be used by any
//! number of threads at once.

use super::{copy_text, guard, input, output, read_text};
use crate::error::Result;
use crate::friction::{CofForm, HomogenisedFriction, HomogenisedSample};
use std::ffi::c_char;

/// The homogenised friction law of FE integration points (opaque): μ(p),
/// adhesion, contact fraction and dissipation shares over the nominal
/// pressure. Create it with `asperity_homogenised_friction_new` or
/// `asperity_homogenised_friction_from_json`, release it with
/// `asperity_homogenised_friction_free`. Immutable; safe to share between
/// threads.
pub struct AsperityHomogenisedFriction(pub(crate) HomogenisedFriction);

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
