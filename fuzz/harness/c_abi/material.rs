//! Material scalars (`src/ffi/material.rs`): effective moduli, adhesion
//! parameters, surface energies.

use super::common::*;
use super::Op;
use asperity::ffi::material::*;

/// Runs one operation of this domain; `super::call` routes each variant
/// to the module of its `src/ffi/` file.
pub(super) unsafe fn call(op: &Op) {
    match op {
        Op::Material {
            which,
            a,
            sel,
            null,
        } => {
            let [a0, a1, a2, a3, a4, a5] = fs(*a);
            let mut out = 0.0;
            let o = mp(&mut out, *null);
            let s = match which % 9 {
                0 => asperity_effective_modulus(a0, a1, a2, a3, o),
                1 => asperity_rod_effective_modulus(a0, a1, o),
                2 => asperity_no_slip_factor(a0, o),
                3 => asperity_tabor_parameter(a0, a1, a2, a3, o),
                4 => asperity_maugis_parameter(a0, a1, a2, a3, o),
                5 => asperity_weir_surface_energy(a0, a1, a2, a3, a4, a5, o),
                6 => asperity_weir_surface_energy_with(a0, a1, a2, a3, a4, a5, sel.0, o),
                7 => asperity_pair_work_of_adhesion(a0, a1, sel.0, o),
                _ => asperity_hamaker_work_of_adhesion(a0, a1, o),
            };
            ok(s, "material");
        }
        _ => unreachable!("not a material operation: {op:?}"),
    }
}
