//! C ABI for `crate::contact::tabulated`: the opaque `AsperityTable` handle
//! (a boxed [`TabulatedLaw`]), its constructors, scalar and batch evaluation
//! with the same old/new-state convention as `asperity_normal_eval`, pull-off,
//! accuracy and JSON storage.
//!
//! A table is immutable after construction: one handle may be used by any
//! number of threads at once (per-contact states stay with the caller).
//! `asperity_table_new_lj` tabulates the numerical Lennard-Jones sphere.

use super::{copy_text, guard, input, output, read_text, Failure};
use crate::contact::{
    ContactState, LjSphere, MaugisDugdale, NormalContact, NormalResponse, TabulatedLaw,
};
use std::ffi::c_char;

/// An immutable tabulated contact law (opaque). Create it with
/// `asperity_table_new_*` or `asperity_table_from_json`, release it with
/// `asperity_table_free`. Safe to share between threads.
pub struct AsperityTable(TabulatedLaw);

unsafe fn emit(
    out: *mut *mut AsperityTable,
    make: impl FnOnce() -> crate::error::Result<TabulatedLaw>,
) -> i32 {
    guard(|| {
        let out = output(out, "out")?;
        *out = core::ptr::null_mut();
        *out = Box::into_raw(Box::new(AsperityTable(make()?)));
        Ok(())
    })
}

/// Build the table of a Maugis–Dugdale sphere: radius (m), E* (Pa), work of
/// adhesion (J/m²), Dugdale stress σ₀ (Pa), relative `tolerance` in
/// [1e-10, 0.1] (1e-4 is the default of the Rust API) in the error measure of
/// the documentation (relative to max(|P|, 1e-3·|pull-off|)). Writes a new
/// handle to `*out` (NULL on failure).
#[no_mangle]
pub unsafe extern "C" fn asperity_table_new_maugis_dugdale(
    radius: f64,
    e_star: f64,
    work_of_adhesion: f64,
    sigma0: f64,
    tolerance: f64,
    out: *mut *mut AsperityTable,
) -> i32 {
    emit(out, || {
        let md = MaugisDugdale::new(radius, e_star, work_of_adhesion, sigma0)
            .map_err(|e| e.renamed("cohesive_stress", "sigma0"))?;
        TabulatedLaw::from_maugis_dugdale(&md, tolerance)
    })
}

/// Build the table of a Lennard-Jones sphere (the numerical solver with
/// `n_grid` cells; 0 = the converged default grid): radius R (m), E* (Pa),
/// work of adhesion Δγ (J/m²), equilibrium separation z₀ (m), all finite and
/// positive with Tabor parameter μ in (0, 100], relative `tolerance` in
/// [1e-10, 0.1] (1e-4 is the default of the Rust API) in the error measure
/// of the documentation (relative to max(|P|, 1e-3·|pull-off|)) against the
/// solver on the same grid. The overlap δ of the table is the rigid approach
/// α (0 where the undeformed apex sits at z₀). Build time in an optimised
/// build at tolerance 1e-4: 0.1–0.5 s at `n_grid` = 128 (μ ≤ 1), about 2 s
/// at μ = 3 and 10 (`n_grid` = 256), 17 s at μ = 10 with `n_grid` = 0 (512
/// cells). Tighter tolerances take longer and may not be reached: at 1e-10,
/// μ = 0.1 takes 8 s (N = 64) and 23 s (N = 128), μ = 1 returns
/// `ASPERITY_ERR_NOT_CONVERGED` ("the curve is too coarse for the
/// tolerance", residual 3e-8) after 40–60 s. Writes a new handle to `*out`
/// (NULL on failure).
#[no_mangle]
pub unsafe extern "C" fn asperity_table_new_lj(
    radius: f64,
    e_star: f64,
    work_of_adhesion: f64,
    z0: f64,
    n_grid: usize,
    tolerance: f64,
    out: *mut *mut AsperityTable,
) -> i32 {
    emit(out, || {
        let lj = LjSphere::new(radius, e_star, work_of_adhesion, z0)?;
        TabulatedLaw::from_lj_sphere(&lj, n_grid, tolerance)
    })
}

/// Release a table; NULL is accepted and ignored.
#[no_mangle]
pub unsafe extern "C" fn asperity_table_free(table: *mut AsperityTable) {
    if !table.is_null() {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            drop(Box::from_raw(table));
        }));
    }
}

/// Evaluate `table` at the overlap `delta` (m) from the history `old_state`
/// (NULL: fresh), writing the history after the step to `new_state` (may be
/// NULL, may equal `old_state`) and the response to `out`.
#[no_mangle]
pub unsafe extern "C" fn asperity_table_eval(
    table: *const AsperityTable,
    delta: f64,
    old_state: *const ContactState,
    new_state: *mut ContactState,
    out: *mut NormalResponse,
) -> i32 {
    guard(|| {
        let t = &input(table, "table")?.0;
        let out = output(out, "out")?;
        let old = super::contact::read_state(old_state);
        super::contact::eval_one(t, delta, &old, new_state, out)
    })
}

/// Evaluate `table` for `n` contacts, as `asperity_normal_eval_batch`:
/// `delta[i]` (m), `old_state[i]` → `new_state[i]`, `force[i]` (N),
/// `contact_radius[i]` (m), `stiffness[i]` (N/m). `delta` and `force` are
/// required, the others may be NULL; inputs and outputs may alias. On an
/// error at element i, elements before i are written, those from i on are
/// untouched, and the message names i.
#[no_mangle]
pub unsafe extern "C" fn asperity_table_eval_batch(
    table: *const AsperityTable,
    n: usize,
    delta: *const f64,
    old_state: *const ContactState,
    new_state: *mut ContactState,
    force: *mut f64,
    contact_radius: *mut f64,
    stiffness: *mut f64,
) -> i32 {
    guard(|| {
        let t = &input(table, "table")?.0;
        if n == 0 {
            return Ok(());
        }
        let b = super::contact::raw_batch(
            n,
            delta,
            old_state,
            new_state,
            force,
            contact_radius,
            stiffness,
        )?;
        t.eval_batch_raw(&b)
            .map_err(|e| Failure::at(e.index, e.error))
    })
}

/// Equilibrium at the prescribed force `force` (N) on the load-controlled
/// stable branch; `out->delta` is the overlap.
#[no_mangle]
pub unsafe extern "C" fn asperity_table_eval_at_load(
    table: *const AsperityTable,
    force: f64,
    out: *mut NormalResponse,
) -> i32 {
    guard(|| {
        let t = &input(table, "table")?.0;
        let out = output(out, "out")?;
        *out = t.eval_at_load(force)?;
        Ok(())
    })
}

/// The pull-off force (N) of `table` under `control`
/// (`ASPERITY_CONTROL_LOAD` or `ASPERITY_CONTROL_DISPLACEMENT`).
#[no_mangle]
pub unsafe extern "C" fn asperity_table_pull_off_force(
    table: *const AsperityTable,
    control: i32,
    force: *mut f64,
) -> i32 {
    guard(|| {
        let t = &input(table, "table")?.0;
        let c = super::contact::control_of(control)?;
        *output(force, "force")? = t.pull_off_force(c)?;
        Ok(())
    })
}

/// The reach of `table` under `control` (`ASPERITY_CONTROL_LOAD` or
/// `ASPERITY_CONTROL_DISPLACEMENT`), as `asperity_normal_reach`: the overlap
/// (m) below which the force is zero from any history (displacement: the
/// table's jump-out points; load: the load-controlled pull-off), or, with a
/// Lennard-Jones far tail, below which |force| < `rel_force` ×
/// |load-controlled pull-off force| (`rel_force` finite and in (0, 1),
/// checked for every table).
#[no_mangle]
pub unsafe extern "C" fn asperity_table_reach(
    table: *const AsperityTable,
    control: i32,
    rel_force: f64,
    delta: *mut f64,
) -> i32 {
    guard(|| {
        let t = &input(table, "table")?.0;
        let c = super::contact::control_of(control)?;
        *output(delta, "delta")? = t.reach(c, rel_force)?;
        Ok(())
    })
}

/// The stated maximum relative error of `table` (its tolerance) and, if
/// `measured` is not NULL, the largest error measured at construction.
#[no_mangle]
pub unsafe extern "C" fn asperity_table_max_error(
    table: *const AsperityTable,
    max_error: *mut f64,
    measured: *mut f64,
) -> i32 {
    guard(|| {
        let t = &input(table, "table")?.0;
        *output(max_error, "max_error")? = t.tolerance();
        if !measured.is_null() {
            *measured = t.measured_error();
        }
        Ok(())
    })
}

/// Write the JSON text of `table` into `buf` (at most `len − 1` bytes and a
/// NUL) and its full length in bytes (without the NUL) to `*needed`, so
/// `asperity_table_to_json(t, NULL, 0, &n)` sizes the buffer. The text is
/// complete only when `*needed < len`; `needed` is required.
#[no_mangle]
pub unsafe extern "C" fn asperity_table_to_json(
    table: *const AsperityTable,
    buf: *mut c_char,
    len: usize,
    needed: *mut usize,
) -> i32 {
    guard(|| {
        let t = &input(table, "table")?.0;
        let needed = output(needed, "needed")?;
        *needed = copy_text(&t.to_json(), buf, len);
        Ok(())
    })
}

/// Load a table from `len` bytes of JSON text at `json` (from
/// `asperity_table_to_json`; no NUL needed). The table is validated; a
/// corrupted text gives `ASPERITY_ERR_INVALID_ARGUMENT`. Writes a new handle
/// to `*out` (NULL on failure).
#[no_mangle]
pub unsafe extern "C" fn asperity_table_from_json(
    json: *const c_char,
    len: usize,
    out: *mut *mut AsperityTable,
) -> i32 {
    emit(out, || {
        let text = read_text(json, len, "json")?;
        TabulatedLaw::from_json(text)
    })
}
