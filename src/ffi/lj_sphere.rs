//! C ABI for `crate::contact::lj_sphere`: the numerical Lennard-Jones sphere.

use super::{guard, output};
use crate::contact::lj_sphere::LjSphere;

/// Load-controlled pull-off force (N, negative: tensile) of an elastic sphere
/// of radius `radius` (m) and contact modulus `e_star` (Pa) under the
/// Lennard-Jones 3-9 surface law with work of adhesion `work_of_adhesion`
/// (J/m²) and equilibrium separation `z0` (m), from the full numerical
/// solution on `n_grid` radial cells (0 = the library's converged default).
/// Writes `*force`; returns `ASPERITY_ERR_NOT_CONVERGED` when the solver does
/// not converge or the grid does not resolve the edge zone.
#[no_mangle]
pub unsafe extern "C" fn asperity_lj_sphere_pull_off(
    radius: f64,
    e_star: f64,
    work_of_adhesion: f64,
    z0: f64,
    n_grid: usize,
    force: *mut f64,
) -> i32 {
    guard(|| {
        let out = output(force, "force")?;
        let sp = LjSphere::new(radius, e_star, work_of_adhesion, z0)?;
        *out = sp.pull_off_force(n_grid)?;
        Ok(())
    })
}
