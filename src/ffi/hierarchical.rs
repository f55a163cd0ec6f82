//! C ABI for `crate::hierarchical`: Archard's spheres on spheres (load–area
//! law and its exponent) and the contact of Cantor–Liu and Cantor–Borodich
//! profiles (thesis 5.4.1, 5.4.2).

use super::surface::array;
use super::{guard, input, output, Failure};
use crate::hierarchical::{archard_exponent, Archard, ArchardModel, CantorContact, CantorProfile};

/// Archard's hierarchy with Hertzian spheres of equal height at every
/// generation (A ~ W^(2/3, 8/9, 26/27, ...)).
pub const ASPERITY_ARCHARD_UNIFORM: i32 = 0;
/// Archard's hierarchy whose finest protuberances stand at heights
/// following the surface under them (A ~ W^(4/5, 14/15, 44/45, ...)).
pub const ASPERITY_ARCHARD_NON_UNIFORM: i32 = 1;

/// Write to `*out` the exponent a of Archard's A ~ W^a for `model`
/// (`ASPERITY_ARCHARD_UNIFORM` or `_NON_UNIFORM`) with `generations` sphere
/// radii (1..64, 2..64 non-uniform): 1 - 3^-n or 1 - 1/(5 3^(n-2)).
#[no_mangle]
pub unsafe extern "C" fn asperity_archard_exponent(
    model: i32,
    generations: usize,
    out: *mut f64,
) -> i32 {
    guard(|| {
        let m = ArchardModel::from_i32(model)?;
        let out = output(out, "out")?;
        *out = archard_exponent(m, generations)?;
        Ok(())
    })
}

/// Archard's real contact area `area[i]` (m^2) under `load[i]` (N, >= 0)
/// for `n` loads: `model` as `asperity_archard_exponent`, `generations`
/// sphere radii `radii` (m, decreasing), `generations - 1` densities
/// `densities` (spheres of generation k per unit area of generation k-1,
/// 1/m^2), contact modulus `contact_modulus` (Pa). `load` and `area` may be
/// the same memory; on an error at element i the elements before i are
/// written and the message names i.
#[no_mangle]
pub unsafe extern "C" fn asperity_archard_area_batch(
    model: i32,
    radii: *const f64,
    densities: *const f64,
    generations: usize,
    contact_modulus: f64,
    n: usize,
    load: *const f64,
    area: *mut f64,
) -> i32 {
    guard(|| {
        let m = ArchardModel::from_i32(model)?;
        let r = array(radii, generations, "radii")?;
        let d = array(densities, generations.saturating_sub(1), "densities")?;
        let a = Archard::new(m, r, d, contact_modulus)?;
        if n == 0 {
            return Ok(());
        }
        input(load, "load")?;
        output(area, "area")?;
        for i in 0..n {
            let w = *load.add(i);
            let v = a.area(w).map_err(|e| Failure::at(i, e))?;
            *area.add(i) = v;
        }
        Ok(())
    })
}

/// The contact of the Cantor profile `*profile` at `n` depths `depth[i]`
/// (m below its highest tips, >= 0) on a Winkler foundation of stiffness
/// `stiffness` (Pa/m, >= 0) and a rigid-plastic one of hardness `hardness`
/// (Pa, >= 0), written to `out[i]` (per unit length out of the plane). On
/// an error at element i the elements before i are written and the message
/// names i.
#[no_mangle]
pub unsafe extern "C" fn asperity_cantor_contact_batch(
    profile: *const CantorProfile,
    stiffness: f64,
    hardness: f64,
    n: usize,
    depth: *const f64,
    out: *mut CantorContact,
) -> i32 {
    guard(|| {
        let p = *input(profile, "profile")?;
        p.check()?;
        if n == 0 {
            return Ok(());
        }
        input(depth, "depth")?;
        output(out, "out")?;
        for i in 0..n {
            let d = *depth.add(i);
            let c = p
                .contact(d, stiffness, hardness)
                .map_err(|e| Failure::at(i, e))?;
            *out.add(i) = c;
        }
        Ok(())
    })
}

/// The exponents of the Cantor profile `*profile`: its tips' fractal
/// dimension D = ln p/ln(1/r), beta = ln(pr)/ln q of width ~ depth^beta
/// (+infinity for Cantor-Liu, q = 1) and beta/(1 + beta) of
/// width ~ load^(beta/(1+beta)) on a Winkler foundation (1 for Cantor-Liu).
/// Any output may be NULL.
#[no_mangle]
pub unsafe extern "C" fn asperity_cantor_exponents(
    profile: *const CantorProfile,
    fractal_dimension: *mut f64,
    width_exponent: *mut f64,
    load_area_exponent: *mut f64,
) -> i32 {
    guard(|| {
        let p = *input(profile, "profile")?;
        p.check()?;
        if !fractal_dimension.is_null() {
            *fractal_dimension = p.fractal_dimension();
        }
        if !width_exponent.is_null() {
            *width_exponent = p.width_exponent();
        }
        if !load_area_exponent.is_null() {
            *load_area_exponent = p.load_area_exponent();
        }
        Ok(())
    })
}
