//! C ABI of `crate::statistics::bush_gibson_thomas`: the Bush–Gibson–Thomas
//! surface (thesis §5.3.3) by its spectral moments, by value.

use super::*;

/// A Bush–Gibson–Thomas rough surface (thesis §5.3.3), by value: an
/// isotropic Gaussian surface of spectral moments m₀, m₂, m₄ (Nayak 1971)
/// whose summits are elliptic paraboloids in Hertz contact with a flat.
/// Nayak's α = m₀m₄/m₂² must exceed 3/2. An all-zero value is invalid.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityBgtParams {
    /// Mean-square height m₀ = σ² (m², > 0).
    pub m0: f64,
    /// Mean-square profile slope m₂ (dimensionless, > 0); the mean-square
    /// gradient of the isotropic surface is 2m₂.
    pub m2: f64,
    /// Mean-square profile curvature m₄ (m⁻², > 0).
    pub m4: f64,
    /// Contact modulus E* (Pa, > 0).
    pub e_star: f64,
    /// Nominal contact area A₀ (m², > 0).
    pub nominal_area: f64,
}

/// Response of a Bush–Gibson–Thomas surface at one separation.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperityBgtResponse {
    /// Total normal load P (N), ≥ 0.
    pub load: f64,
    /// Real contact area A (m²), ≥ 0.
    pub area: f64,
    /// Expected number of summits in contact (dimensionless).
    pub contacts: f64,
    /// Normal stiffness −dP/dd (N/m), ≥ 0.
    pub stiffness: f64,
}

impl AsperityBgtParams {
    /// The validated Rust model.
    pub fn to_model(&self) -> Result<BushGibsonThomas> {
        BushGibsonThomas::new(self.m0, self.m2, self.m4, self.e_star, self.nominal_area)
    }
}

fn bgt_eval(bgt: &BushGibsonThomas, separation: f64) -> Result<AsperityBgtResponse> {
    let r = bgt.evaluate(separation)?;
    Ok(AsperityBgtResponse {
        load: r.response.load,
        area: r.response.area,
        contacts: r.response.contacts,
        stiffness: r.stiffness,
    })
}

/// Bush–Gibson–Thomas load, real area, number of contacts and stiffness at
/// `separation` d (m, finite; the flat's height above the mean plane of the
/// surface).
#[no_mangle]
pub unsafe extern "C" fn asperity_bgt_eval(
    bgt: *const AsperityBgtParams,
    separation: f64,
    out: *mut AsperityBgtResponse,
) -> i32 {
    guard(|| {
        let bgt = input(bgt, "bgt")?.to_model()?;
        let out = output(out, "out")?;
        *out = bgt_eval(&bgt, separation)?;
        Ok(())
    })
}

/// `asperity_bgt_eval` for `n` separations `separation[i]` (m), writing
/// `load[i]` (N) and, where the array is not NULL, `area[i]` (m²),
/// `contacts[i]` and `stiffness[i]` (N/m). `separation` and `load` are
/// required (unless n = 0); inputs and outputs may be the same memory. On an
/// error at element i, elements before i are written, those from i on are
/// untouched, and the message names i.
#[no_mangle]
pub unsafe extern "C" fn asperity_bgt_eval_batch(
    bgt: *const AsperityBgtParams,
    n: usize,
    separation: *const f64,
    load: *mut f64,
    area: *mut f64,
    contacts: *mut f64,
    stiffness: *mut f64,
) -> i32 {
    guard(|| {
        let bgt = input(bgt, "bgt")?.to_model()?;
        response_batch(n, separation, [load, area, contacts, stiffness], |d, _| {
            let r = bgt_eval(&bgt, d)?;
            Ok([r.load, r.area, r.contacts, r.stiffness])
        })
    })
}

/// The separation (m) at which the surface carries `load` (N, finite, > 0),
/// by safeguarded Newton iteration.
#[no_mangle]
pub unsafe extern "C" fn asperity_bgt_separation_at_load(
    bgt: *const AsperityBgtParams,
    load: f64,
    out: *mut AsperitySeparation,
) -> i32 {
    guard(|| {
        let bgt = input(bgt, "bgt")?.to_model()?;
        let out = output(out, "out")?;
        *out = bgt.separation_at_load(load)?.into();
        Ok(())
    })
}

/// Nayak's summit density D = m₄/(6π√3 m₂) (m⁻², to `*summit_density`) and
/// the small-load limit of A/P, √π/(E*√m₂) = √(2π)/(E*√(2m₂)) (m²/N, to
/// `*area_per_load`) of the surface `bgt`; either output may be NULL.
#[no_mangle]
pub unsafe extern "C" fn asperity_bgt_properties(
    bgt: *const AsperityBgtParams,
    summit_density: *mut f64,
    area_per_load: *mut f64,
) -> i32 {
    guard(|| {
        let bgt = input(bgt, "bgt")?.to_model()?;
        if !summit_density.is_null() {
            *summit_density = bgt.summit_density();
        }
        if !area_per_load.is_null() {
            *area_per_load = bgt.small_load_area_per_load();
        }
        Ok(())
    })
}
