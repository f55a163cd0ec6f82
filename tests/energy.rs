//! `NormalContact::energy` and `asperity_normal_energy`: the energy of the
//! equilibrium reached by `eval` is the integral of its force along the
//! branch (central differences dU/dδ = P to 1e-6), Hertz's closed form,
//! continuity at δ = 0, zero when separated, finiteness over decades, and
//! an error naming `law` for laws without a closed form.

mod common;
use common::c_errors::expect_error;

use asperity::contact::{
    ContactState, Control, Derjaguin, Dmt, FlatPunch, Hertz, Jkr, Kendall, MaugisDugdale,
    NormalContact, NormalLaw, PowerPunch, SurfaceLaw,
};
use asperity::ffi::contact::*;
use asperity::ffi::*;
use core::f64::consts::PI;
use std::ptr::{null, null_mut};

const R: f64 = 1e-5;
const E: f64 = 1e9;
const W: f64 = 0.05;

fn in_contact() -> ContactState {
    ContactState {
        in_contact: 1,
        branch: 1,
        ..Default::default()
    }
}

/// dU/dδ by central differences at δ from `state` against the force there,
/// relative to max(|P|, `floor`).
fn check_derivative(law: &dyn NormalContact, delta: f64, st: &ContactState, h: f64, floor: f64) {
    let (r, _) = law.eval(delta, st).unwrap();
    let up = law.energy(delta + h, st).unwrap();
    let dn = law.energy(delta - h, st).unwrap();
    let du = (up - dn) / (2.0 * h);
    let err = (du - r.force).abs() / r.force.abs().max(floor);
    assert!(
        err < 1e-6,
        "{law:?}: dU/dδ = {du:e}, P = {:e} at δ = {delta:e} (error {err:e})",
        r.force,
        law = std::any::type_name_of_val(law)
    );
}

#[test]
fn hertz_closed_form_and_continuity() {
    let h = Hertz::new(R, E).unwrap();
    for d in [1e-12, 1e-9, 1e-7, 1e-6] {
        let u = h.energy(d, &ContactState::default()).unwrap();
        let closed = 8.0 / 15.0 * E * R.sqrt() * d.powf(2.5);
        assert!(((u - closed) / closed).abs() < 1e-14, "{u:e} vs {closed:e}");
        check_derivative(&h, d, &ContactState::default(), 1e-6 * d, 0.0);
    }
    for d in [-1e-6, -1e-300, 0.0] {
        assert_eq!(h.energy(d, &ContactState::default()).unwrap(), 0.0);
    }
    // Continuous at δ = 0 from above.
    assert!(h.energy(1e-300, &ContactState::default()).unwrap() < 1e-300);
}

#[test]
fn dmt_energy_integrates_its_force() {
    let d = Dmt::new(R, E, W).unwrap();
    let fresh = ContactState::default();
    for x in [1e-11, 1e-10, 1e-9, 1e-8, 1e-7] {
        check_derivative(&d, x, &fresh, 1e-6 * x, 1e-3 * d.adhesive_force());
    }
    assert_eq!(d.energy(-1e-9, &fresh).unwrap(), 0.0);
    assert_eq!(d.energy(0.0, &fresh).unwrap(), 0.0);
    assert!(d.energy(1e-300, &fresh).unwrap().abs() < 1e-290);
}

#[test]
fn punches_and_kendall_integrate_their_force() {
    let fresh = ContactState::default();
    let laws: Vec<NormalLaw> = vec![
        FlatPunch::new(R, E).unwrap().into(),
        FlatPunch::no_slip(R, E, 0.3).unwrap().into(),
        PowerPunch::cone(1.2, E).unwrap().into(),
        PowerPunch::new(1e8, 3.0, E).unwrap().into(),
        PowerPunch::new(0.5 / R, 2.0, E).unwrap().into(),
    ];
    for l in &laws {
        for x in [1e-10, 1e-9, 1e-8] {
            check_derivative(l, x, &fresh, 1e-6 * x, 0.0);
        }
        assert_eq!(l.energy(-1e-9, &fresh).unwrap(), 0.0);
    }
    // d = 2, B = 1/(2R) is Hertz.
    let (p, h) = (laws[4], Hertz::new(R, E).unwrap());
    let (a, b) = (
        p.energy(1e-8, &fresh).unwrap(),
        h.energy(1e-8, &fresh).unwrap(),
    );
    assert!(((a - b) / b).abs() < 1e-12, "{a:e} vs {b:e}");
    let k = Kendall::new(R, E, W).unwrap();
    let pc = k.pull_off_force(Control::Load).unwrap().abs();
    let st = in_contact();
    for x in lin(k.critical_delta() * 0.99, 1e-8, 50) {
        check_derivative(&k, x, &st, 1e-7 * k.critical_delta().abs(), pc);
    }
    assert_eq!(k.energy(-1e-12, &fresh).unwrap(), 0.0);
    assert!(k.energy(-1e-12, &st).unwrap() < 0.0);
}

fn lin(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect()
}

/// JKR: on loading (fresh, jump-in at δ = 0) and on the retraction branch
/// down to δ_c, dU/dδ = P; zero out of contact; w → 0 is Hertz.
#[test]
fn jkr_energy_along_both_branches() {
    let j = Jkr::new(R, E, W).unwrap();
    let dc = j.critical_delta();
    let l = -dc;
    let pc = 1.5 * PI * W * R;
    let st = in_contact();
    // Loading: from δ = 0 (jump-in) to deep contact.
    for x in lin(1e-3 * l, 30.0 * l, 200) {
        check_derivative(&j, x, &ContactState::default(), 1e-6 * l, 1e-3 * pc);
    }
    // Retraction: the stable branch below zero overlap, down to near δ_c.
    for x in lin(0.0, dc * (1.0 - 1e-2), 200) {
        check_derivative(&j, x, &st, 1e-7 * l, 1e-3 * pc);
    }
    // Out of contact: zero; in contact at δ_c: the branch's energy.
    assert_eq!(j.energy(0.5 * dc, &ContactState::default()).unwrap(), 0.0);
    assert_eq!(j.energy(dc * 1.001, &st).unwrap(), 0.0);
    assert!(j.energy(dc, &st).unwrap().is_finite());
    // Closed form in the contact radius.
    let x = 2.0 * l;
    let (r, _) = j.eval(x, &st).unwrap();
    let a = r.contact_radius;
    let k = (2.0 * PI * W / E).sqrt();
    let closed =
        8.0 / 15.0 * E * a.powi(5) / (R * R) - 4.0 / 3.0 * E * k * a.powf(3.5) / R + PI * W * a * a;
    let u = j.energy(x, &st).unwrap();
    assert!(((u - closed) / closed).abs() < 1e-10, "{u:e} vs {closed:e}");
    // No adhesion: Hertz.
    let j0 = Jkr::new(R, E, 0.0).unwrap();
    let h = Hertz::new(R, E).unwrap();
    assert_eq!(j0.energy(1e-8, &st).unwrap(), h.energy(1e-8, &st).unwrap());
}

#[test]
fn derjaguin_energy_integrates_its_force() {
    let z = 3e-10;
    for law in [
        SurfaceLaw::LennardJones {
            work_of_adhesion: W,
            equilibrium_separation: z,
        },
        SurfaceLaw::Dugdale {
            work_of_adhesion: W,
            cohesive_stress: W / z,
        },
        SurfaceLaw::Exponential {
            work_of_adhesion: W,
            decay_length: z,
        },
    ] {
        let d = Derjaguin::new(R, law).unwrap();
        let f = d.adhesive_force();
        for x in lin(-5.0 * z, -0.05 * z, 40) {
            check_derivative(&d, x, &ContactState::default(), 1e-6 * z, 1e-3 * f);
        }
    }
}

#[test]
fn energies_stay_finite_over_decades() {
    for w in [1e-4, 1e-1, 10.0] {
        for r in [1e-9, 1e-6, 1e-3, 1.0] {
            for e in [1e6, 1e9, 1e12] {
                let laws: Vec<NormalLaw> = vec![
                    Hertz::new(r, e).unwrap().into(),
                    Dmt::new(r, e, w).unwrap().into(),
                    Jkr::new(r, e, w).unwrap().into(),
                    Kendall::new(r, e, w).unwrap().into(),
                    FlatPunch::new(r, e).unwrap().into(),
                ];
                for l in &laws {
                    let s = l.length_scale();
                    for f in [-10.0, -0.5, 0.0, 1e-6, 0.3, 1.0, 100.0] {
                        for st in [ContactState::default(), in_contact()] {
                            let u = l.energy(f * s, &st).unwrap();
                            assert!(u.is_finite(), "{l:?} at {f}: {u}");
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn laws_without_a_closed_form_say_so() {
    let m: NormalLaw = MaugisDugdale::from_maugis_parameter(R, E, W, 1.0)
        .unwrap()
        .into();
    let e = m.energy(1e-9, &ContactState::default()).unwrap_err();
    assert!(e.to_string().contains("`law`"), "{e}");
    let h: NormalLaw = Hertz::new(R, E).unwrap().into();
    assert!(h.energy(f64::NAN, &ContactState::default()).is_err());
}

#[test]
fn c_abi_energy() {
    let mut law = std::mem::MaybeUninit::<AsperityNormalLaw>::zeroed();
    assert_eq!(
        unsafe { asperity_law_jkr(R, E, W, law.as_mut_ptr()) },
        ASPERITY_OK
    );
    let law = unsafe { law.assume_init() };
    let j = Jkr::new(R, E, W).unwrap();
    let st = in_contact();
    let mut u = 0.0;
    let x = j.critical_delta() * 0.5;
    assert_eq!(
        unsafe { asperity_normal_energy(&law, x, &st, &mut u) },
        ASPERITY_OK
    );
    assert_eq!(u, j.energy(x, &st).unwrap());
    // NULL old state: fresh, out of contact below zero overlap.
    assert_eq!(
        unsafe { asperity_normal_energy(&law, x, null(), &mut u) },
        ASPERITY_OK
    );
    assert_eq!(u, 0.0);
    let s = unsafe { asperity_normal_energy(null(), x, null(), &mut u) };
    expect_error(s, ASPERITY_ERR_NULL_POINTER, "`law`");
    let s = unsafe { asperity_normal_energy(&law, x, null(), null_mut()) };
    expect_error(s, ASPERITY_ERR_NULL_POINTER, "`energy`");
    let s = unsafe { asperity_normal_energy(&law, f64::NAN, null(), &mut u) };
    expect_error(s, ASPERITY_ERR_INVALID_ARGUMENT, "`delta`");
    let mut md = std::mem::MaybeUninit::<AsperityNormalLaw>::zeroed();
    assert_eq!(
        unsafe { asperity_law_maugis_dugdale(R, E, W, 3e7, md.as_mut_ptr()) },
        ASPERITY_OK
    );
    let md = unsafe { md.assume_init() };
    let s = unsafe { asperity_normal_energy(&md, 1e-9, null(), &mut u) };
    expect_error(s, ASPERITY_ERR_OUT_OF_DOMAIN, "`law`");
}
