//! The fidelity advisor: errors against the Lennard-Jones reference, the
//! choice for loose and tight tolerances, and the C ABI.

use asperity::ffi::fidelity::*;
use asperity::ffi::ASPERITY_OK;
use asperity::fidelity::{advise, Fidelity};
use std::f64::consts::PI;

// μ = 0.1 with R = 1 µm, w = 0.05 J/m², z0 = 0.3 nm.
const R: f64 = 1e-6;
const W: f64 = 0.05;
const Z0: f64 = 0.3e-9;

fn e_star(mu: f64) -> f64 {
    (R * W * W / (mu * mu * mu * Z0 * Z0 * Z0)).sqrt()
}

#[test]
fn tight_tolerance_needs_the_lennard_jones_table_loose_allows_dmt() {
    let scale = PI * R * W;
    let tight = advise(R, e_star(0.1), W, Z0, 0.01 * scale).unwrap();
    assert!((tight.tabor - 0.1).abs() < 1e-12);
    // The reference pull-off at μ = 0.1 (Richardson 1.9689564 πRw).
    assert!(
        (tight.reference_pull_off / scale + 1.9689564).abs() < 1e-3,
        "{}",
        tight.reference_pull_off / scale
    );
    // The pull-off yardstick is the solver on the converged grid, not the
    // coarser table, whose own pull-off error is therefore measured.
    let lj = asperity::contact::LjSphere::new(R, e_star(0.1), W, Z0).unwrap();
    assert_eq!(tight.reference_grid, lj.converged_default_grid());
    assert_eq!(tight.reference_pull_off, lj.pull_off_force(0).unwrap());
    let table = tight.assessments[2];
    assert_eq!(table.law, Fidelity::TabulatedLennardJones);
    assert!(
        table.pull_off_error > 0.0 && table.pull_off_error / scale < 1e-4,
        "{}",
        table.pull_off_error / scale
    );
    assert_eq!(tight.choice, Fidelity::TabulatedLennardJones);
    assert_eq!(tight.assessments.len(), 6);
    for (a, f) in tight.assessments.iter().zip(Fidelity::ALL) {
        assert_eq!(a.law, f);
        assert!(a.pull_off_error.is_finite() && a.curve_error.is_finite() && a.cost_per_call > 0.0);
    }
    // DMT's pull-off at μ = 0.1 is within 2 % of the LJ value, but its
    // force–approach curve is not: it ignores the range of the surface forces.
    let dmt = tight.assessments[0];
    assert!(
        dmt.pull_off_error / scale < 0.05,
        "{}",
        dmt.pull_off_error / scale
    );
    assert!(dmt.curve_error / scale > 0.5, "{}", dmt.curve_error / scale);
    // A tolerance above DMT's errors picks DMT, the cheapest.
    let loose = advise(
        R,
        e_star(0.1),
        W,
        Z0,
        1.01 * dmt.curve_error.max(dmt.pull_off_error),
    )
    .unwrap();
    assert_eq!(loose.choice, Fidelity::Dmt);
}

#[test]
fn c_abi_advice() {
    let mut out = AsperityFidelityAdvice::default();
    let scale = PI * R * W;
    let s = unsafe { asperity_fidelity_advise(R, e_star(0.1), W, Z0, 0.01 * scale, &mut out) };
    assert_eq!(s, ASPERITY_OK);
    assert_eq!(out.choice, ASPERITY_FIDELITY_TABULATED_LENNARD_JONES);
    assert_eq!(
        out.assessments[ASPERITY_FIDELITY_DMT as usize].law,
        ASPERITY_FIDELITY_DMT
    );
    assert_ne!(
        unsafe { asperity_fidelity_advise(R, e_star(0.1), W, Z0, -1.0, &mut out) },
        ASPERITY_OK
    );
    assert_ne!(
        unsafe { asperity_fidelity_advise(R, e_star(0.1), W, Z0, 1.0, std::ptr::null_mut()) },
        ASPERITY_OK
    );
}
