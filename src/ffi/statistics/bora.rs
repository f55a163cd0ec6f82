//! C ABI of `crate::statistics::bora`: the Bora et al. interface on a
//! measured map (thesis §5.3.9), an opaque handle.

use super::*;

/// The real nano-topography interface of Bora et al. (2013, thesis §5.3.9)
/// (opaque): springs with the heights of a measured map on an elastic
/// half-space. Create it with `asperity_bora_new`, release it with
/// `asperity_bora_free`. Immutable: safe to share between threads.
pub struct AsperityBora(BoraTopography);

/// The equilibrium of a Bora interface at one separation.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityBoraResponse {
    /// Total load P (N), ≥ 0.
    pub load: f64,
    /// Real contact area (m²): loaded springs times the cell area Δ².
    pub area: f64,
    /// Normal stiffness −dP/dd (N/m), ≥ 0.
    pub stiffness: f64,
    /// Number of loaded springs.
    pub contacts: u64,
    /// Conjugate-gradient iterations spent.
    pub iterations: u32,
    /// Reserved, 0.
    pub reserved: u32,
}

/// A Bora interface on `nx` × `ny` heights `heights` (m, finite, row-major:
/// `heights[i + nx*j]` at x = iΔ, y = jΔ; copied) with grid spacing `spacing`
/// Δ (m, > 0), springs of stiffness `spring_stiffness` (N/m, > 0) on a
/// substrate of contact modulus `contact_modulus` E* (Pa, > 0), or a rigid
/// substrate (independent springs) when `contact_modulus` is 0. At most
/// 16384 points. Writes a new handle to `*out` (NULL on failure).
#[no_mangle]
pub unsafe extern "C" fn asperity_bora_new(
    nx: usize,
    ny: usize,
    spacing: f64,
    heights: *const f64,
    spring_stiffness: f64,
    contact_modulus: f64,
    out: *mut *mut AsperityBora,
) -> i32 {
    guard(|| {
        let out = output(out, "out")?;
        *out = core::ptr::null_mut();
        let n = nx.checked_mul(ny).ok_or(Error::InvalidArgument {
            name: "nx",
            value: nx as f64,
            bound: "nx, ny >= 1 and nx*ny <= 16384",
        })?;
        let h = if n == 0 {
            Vec::new()
        } else {
            array(heights, n, "heights")?.to_vec()
        };
        let substrate = if contact_modulus == 0.0 {
            None
        } else {
            Some(contact_modulus)
        };
        let m = BoraTopography::new(nx, ny, spacing, h, spring_stiffness, substrate)?;
        *out = Box::into_raw(Box::new(AsperityBora(m)));
        Ok(())
    })
}

/// Release a Bora interface; NULL is accepted.
#[no_mangle]
pub unsafe extern "C" fn asperity_bora_free(bora: *mut AsperityBora) {
    if !bora.is_null() {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            drop(Box::from_raw(bora));
        }));
    }
}

/// The equilibrium with the flat at `separation` d (m, finite, in the frame
/// of the heights): load, area, stiffness, contacts to `*out`, and, unless
/// `forces` is NULL, the nx·ny spring forces (N) to `forces`.
#[no_mangle]
pub unsafe extern "C" fn asperity_bora_solve(
    bora: *const AsperityBora,
    separation: f64,
    out: *mut AsperityBoraResponse,
    forces: *mut f64,
) -> i32 {
    guard(|| {
        let m = &input(bora, "bora")?.0;
        let out = output(out, "out")?;
        let s = m.solve(separation)?;
        if !forces.is_null() {
            core::ptr::copy_nonoverlapping(s.forces.as_ptr(), forces, s.forces.len());
        }
        *out = AsperityBoraResponse {
            load: s.load,
            area: s.area,
            stiffness: s.stiffness,
            contacts: s.contacts as u64,
            iterations: s.iterations,
            reserved: 0,
        };
        Ok(())
    })
}

/// The separation (m) at which the interface carries `load` (N, finite
/// and > 0).
#[no_mangle]
pub unsafe extern "C" fn asperity_bora_separation_at_load(
    bora: *const AsperityBora,
    load: f64,
    out: *mut AsperitySeparation,
) -> i32 {
    guard(|| {
        let m = &input(bora, "bora")?.0;
        let out = output(out, "out")?;
        *out = m.separation_at_load(load)?.into();
        Ok(())
    })
}
