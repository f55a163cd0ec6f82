//! The C ABI of the homogenised friction law (its table,
//! `AsperityHomogenisedFriction`, and the law stepped through the one
//! friction handle, `asperity_friction_from_homogenised`), called from
//! Rust: NULL pointers, bad input (status and the message of
//! `asperity_last_error_message`), the state size and layout, and equality
//! of the scalar and block steps with the Rust API (bit for bit), including
//! old/new aliasing, in place, NULL work, overlapping and overflowing
//! blocks, and the JSON path.

mod common;
#[path = "common/laws.rs"]
mod laws;
use common::c_errors::{expect_error, last_message};

use asperity::ffi::friction_law::*;
use asperity::ffi::homogenised::*;
use asperity::ffi::slider::{
    ASPERITY_HOMOGENISED_STATE_FORCE, ASPERITY_HOMOGENISED_STATE_MECHANISMS,
    ASPERITY_HOMOGENISED_STATE_PLASTIC_SLIP_PATH,
};
use asperity::ffi::*;
use asperity::friction::*;
use std::ffi::c_char;
use std::ptr::{null, null_mut};

const MPA: f64 = 1e6;
const AREA: f64 = 1e-6;
const K: f64 = 1e8;

fn samples() -> Vec<HomogenisedSample> {
    [
        (10.0, 1.10, 0.9, 0.01),
        (50.0, 1.02, 4.5, 0.05),
        (100.0, 0.97, 9.0, 0.10),
        (200.0, 0.90, 18.0, 0.20),
    ]
    .iter()
    .map(|&(p, mu, pa, fr)| HomogenisedSample {
        pressure: p * MPA,
        cof: mu,
        adhesion_pressure: pa * MPA,
        contact_fraction: fr,
        shares: Dissipation {
            chemical: 0.93,
            van_der_waals: 0.06,
            elastic: 0.008,
            plastic: 0.002,
        },
    })
    .collect()
}

struct Handle(*mut AsperityHomogenisedFriction);

impl Drop for Handle {
    fn drop(&mut self) {
        unsafe { asperity_homogenised_friction_free(self.0) }
    }
}

fn handle(s: &[HomogenisedSample]) -> Handle {
    let mut h = null_mut();
    let st = unsafe { asperity_homogenised_friction_new(s.as_ptr(), s.len(), &mut h) };
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    assert!(!h.is_null());
    Handle(h)
}

/// The friction law of the table `h` with the stick stiffness `k`.
struct Law(*mut AsperityFriction);

impl Drop for Law {
    fn drop(&mut self) {
        unsafe { asperity_friction_free(self.0) }
    }
}

fn law(h: &Handle, k: f64) -> Law {
    let mut l = null_mut();
    let st = unsafe { asperity_friction_from_homogenised(h.0, k, &mut l) };
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    assert!(!l.is_null());
    Law(l)
}

/// The Rust law of `s` with the stick stiffness `k`.
fn rust_law(s: &[HomogenisedSample], k: f64) -> HomogenisedFriction {
    HomogenisedFriction::from_samples(s, CofForm::Derjaguin)
        .unwrap()
        .with_stick_stiffness(k)
        .unwrap()
}

const M: usize = HomogenisedFriction::STATE_LEN;

fn inc(n: f64, sx: f64, sy: f64) -> FrictionIncrement {
    FrictionIncrement {
        normal_force: n,
        area: AREA,
        slip: [sx, sy],
        dt: 1e-6,
        ..Default::default()
    }
}

#[test]
fn constructors_and_nulls() {
    let s = samples();
    unsafe {
        expect_error(
            asperity_homogenised_friction_new(s.as_ptr(), s.len(), null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        let mut h = 1usize as *mut AsperityHomogenisedFriction;
        expect_error(
            asperity_homogenised_friction_new(null(), 3, &mut h),
            ASPERITY_ERR_NULL_POINTER,
            "`samples`",
        );
        assert!(h.is_null(), "out is NULL on failure");
        expect_error(
            asperity_homogenised_friction_new(s.as_ptr(), 0, &mut h),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`samples`",
        );
        let mut bad = s.clone();
        bad[2].contact_fraction = 1.5;
        expect_error(
            asperity_homogenised_friction_new(bad.as_ptr(), bad.len(), &mut h),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`contact_fraction`",
        );
        assert!(h.is_null());
        let mut bad = s.clone();
        bad[3].pressure = 10.0 * MPA;
        expect_error(
            asperity_homogenised_friction_new(bad.as_ptr(), bad.len(), &mut h),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`pressure`",
        );
        let mut bad = s.clone();
        bad[0].shares.chemical = 0.5;
        expect_error(
            asperity_homogenised_friction_new(bad.as_ptr(), bad.len(), &mut h),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`shares`",
        );
        expect_error(
            asperity_homogenised_friction_from_json(null(), 3, &mut h),
            ASPERITY_ERR_NULL_POINTER,
            "`json`",
        );
        let junk = b"{\"format\":";
        expect_error(
            asperity_homogenised_friction_from_json(junk.as_ptr().cast(), junk.len(), &mut h),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`json`",
        );
        assert!(h.is_null());
        let not_utf8 = [0xffu8, 0xfe];
        expect_error(
            asperity_homogenised_friction_from_json(not_utf8.as_ptr().cast(), 2, &mut h),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "UTF-8",
        );
        asperity_homogenised_friction_free(null_mut());
        // The law of a table: the stick stiffness is checked and named.
        let table = handle(&s);
        let mut l = 1usize as *mut AsperityFriction;
        for k in [-1.0, f64::NAN, f64::INFINITY] {
            expect_error(
                asperity_friction_from_homogenised(table.0, k, &mut l),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "`stick_stiffness`",
            );
            assert!(l.is_null(), "out is NULL on failure");
        }
        expect_error(
            asperity_friction_from_homogenised(null(), K, &mut l),
            ASPERITY_ERR_NULL_POINTER,
            "`table`",
        );
        expect_error(
            asperity_friction_from_homogenised(table.0, K, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        asperity_friction_free(null_mut());
        asperity_friction_work_free(null_mut());
    }
}

#[test]
fn state_size_and_layout() {
    let h = handle(&samples());
    let l = law(&h, K);
    let mut n = 0usize;
    assert_eq!(
        unsafe { asperity_friction_state_size(l.0, &mut n) },
        ASPERITY_OK
    );
    // D, S, force[2], plastic slip path, 4 dissipation entries.
    assert_eq!(n, 9);
    assert_eq!(n, HomogenisedFriction::STATE_LEN);
    assert_eq!(
        (
            ASPERITY_FRICTION_STATE_DISSIPATION,
            ASPERITY_FRICTION_STATE_SLIP_PATH,
            ASPERITY_HOMOGENISED_STATE_FORCE,
            ASPERITY_HOMOGENISED_STATE_PLASTIC_SLIP_PATH,
            ASPERITY_HOMOGENISED_STATE_MECHANISMS
        ),
        (
            0,
            1,
            HomogenisedFriction::STATE_FORCE,
            HomogenisedFriction::STATE_PLASTIC_SLIP_PATH,
            HomogenisedFriction::STATE_MECHANISMS
        )
    );
    unsafe {
        expect_error(
            asperity_friction_state_size(null(), &mut n),
            ASPERITY_ERR_NULL_POINTER,
            "`law`",
        );
        expect_error(
            asperity_friction_state_size(l.0, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`n`",
        );
        let mut w = 1usize as *mut AsperityFrictionWork;
        expect_error(
            asperity_friction_work_new(null(), &mut w),
            ASPERITY_ERR_NULL_POINTER,
            "`law`",
        );
        assert!(w.is_null());
    }
}

#[test]
fn step_equals_the_rust_api() {
    let s = samples();
    let h = handle(&s);
    let l = law(&h, K);
    let rust = rust_law(&s, K);
    let mut rw = rust.work();
    let mut old = vec![0.0; M];
    for i in 0..300 {
        let x = i as f64;
        let incr = inc(
            5.0 + (7.0 * x) % 230.0,
            2e-7 * (0.1 * x).cos(),
            2e-7 * (0.1 * x).sin(),
        );
        let mut rs = vec![0.0; M];
        let rr = rust.step(&old, &mut rs, &incr, &mut rw).unwrap();
        let mut cs = vec![0.0; M];
        let mut cr = FrictionResponse::default();
        let st = unsafe {
            asperity_friction_step(
                l.0,
                &incr,
                old.as_ptr(),
                cs.as_mut_ptr(),
                null_mut(),
                &mut cr,
            )
        };
        assert_eq!(st, ASPERITY_OK, "{}", last_message());
        assert_eq!(format!("{rs:?}{rr:?}"), format!("{cs:?}{cr:?}"));
        // In place (old == new) gives the same.
        let mut inplace = old.clone();
        let mut cr2 = FrictionResponse::default();
        let p = inplace.as_mut_ptr();
        let st = unsafe { asperity_friction_step(l.0, &incr, p, p, null_mut(), &mut cr2) };
        assert_eq!(st, ASPERITY_OK);
        assert_eq!(inplace, cs);
        assert_eq!(cr2, cr);
        old = cs;
    }
    // All-zero old state = fresh; the old and new states are required.
    let mut r1 = FrictionResponse::default();
    let fresh = [0.0; M];
    let mut new = vec![0.0; M];
    unsafe {
        assert_eq!(
            asperity_friction_step(
                l.0,
                &inc(50.0, 1e-6, 0.0),
                fresh.as_ptr(),
                new.as_mut_ptr(),
                null_mut(),
                &mut r1
            ),
            ASPERITY_OK
        );
        expect_error(
            asperity_friction_step(
                l.0,
                &inc(50.0, 1e-6, 0.0),
                null(),
                new.as_mut_ptr(),
                null_mut(),
                &mut r1,
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`old_state`",
        );
        expect_error(
            asperity_friction_step(
                l.0,
                &inc(50.0, 1e-6, 0.0),
                fresh.as_ptr(),
                null_mut(),
                null_mut(),
                &mut r1,
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`new_state`",
        );
    }
    assert_eq!(r1.regime, ASPERITY_FRICTION_SLIP);
    assert_eq!(r1.regime, 2);
}

/// The contract of the one friction handle (issue 30 §1): old == new, NULL
/// work, `asperity_friction_step_in_place`, the blocks separate, old ==
/// new and in place, a partially overlapping block (`new_states`) and a
/// point count whose states overflow `size_t` (`n`), bit for bit against
/// the Rust law.
#[test]
fn the_friction_handle_keeps_the_contract() {
    let case = laws::homogenised_case();
    let h = handle(&laws::homogenised_samples());
    let l = law(&h, 1e8);
    unsafe { laws::c_contract(l.0, &case, 24) };
}

#[test]
fn step_errors() {
    let h = handle(&samples());
    let l = law(&h, K);
    let old = vec![0.0; M];
    let mut s = vec![0.0; M];
    let mut r = FrictionResponse::default();
    let i = inc(50.0, 1e-7, 0.0);
    unsafe {
        expect_error(
            asperity_friction_step(null(), &i, old.as_ptr(), s.as_mut_ptr(), null_mut(), &mut r),
            ASPERITY_ERR_NULL_POINTER,
            "`law`",
        );
        expect_error(
            asperity_friction_step(
                l.0,
                null(),
                old.as_ptr(),
                s.as_mut_ptr(),
                null_mut(),
                &mut r,
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`increment`",
        );
        expect_error(
            asperity_friction_step(
                l.0,
                &i,
                old.as_ptr(),
                s.as_mut_ptr(),
                null_mut(),
                null_mut(),
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        let sentinel = vec![99.0; M];
        s.copy_from_slice(&sentinel);
        let out_sentinel = FrictionResponse {
            cof: -9.0,
            ..Default::default()
        };
        r = out_sentinel;
        for (bad, name) in [
            (FrictionIncrement { area: -1e-6, ..i }, "`area`"),
            (FrictionIncrement { area: 0.0, ..i }, "`area`"),
            (
                FrictionIncrement {
                    normal_force: f64::NAN,
                    ..i
                },
                "`normal_force`",
            ),
            (
                FrictionIncrement {
                    slip: [0.0, f64::NAN],
                    ..i
                },
                "`slip`",
            ),
            (FrictionIncrement { dt: -1.0, ..i }, "`dt`"),
        ] {
            expect_error(
                asperity_friction_step(l.0, &bad, old.as_ptr(), s.as_mut_ptr(), null_mut(), &mut r),
                ASPERITY_ERR_INVALID_ARGUMENT,
                name,
            );
            assert_eq!(s, sentinel, "new state untouched on failure");
            assert_eq!(r, out_sentinel, "out untouched on failure");
            let mut st = old.clone();
            expect_error(
                asperity_friction_step_in_place(l.0, &bad, st.as_mut_ptr(), null_mut(), &mut r),
                ASPERITY_ERR_INVALID_ARGUMENT,
                name,
            );
            assert_eq!(st, old, "state untouched on failure");
        }
        let mut bad_old = [0.0; M];
        bad_old[ASPERITY_HOMOGENISED_STATE_FORCE] = f64::INFINITY;
        expect_error(
            asperity_friction_step(
                l.0,
                &i,
                bad_old.as_ptr(),
                s.as_mut_ptr(),
                null_mut(),
                &mut r,
            ),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`old.force`",
        );
        let mut bad_old = vec![0.0; M];
        bad_old[ASPERITY_HOMOGENISED_STATE_MECHANISMS + 1] = -1.0;
        expect_error(
            asperity_friction_step_in_place(l.0, &i, bad_old.as_mut_ptr(), null_mut(), &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`state.mechanisms`",
        );
        assert_eq!(s, sentinel);
    }
}

#[test]
fn block_equals_the_rust_api_and_reports_the_element() {
    let s = samples();
    let h = handle(&s);
    let l = law(&h, K);
    let rust = rust_law(&s, K);
    let mut rw = rust.work();
    let n = 32;
    let nf: Vec<f64> = (0..n).map(|i| 10.0 + 6.0 * i as f64).collect();
    let a = vec![AREA; n];
    let sl: Vec<f64> = (0..2 * n).map(|j| 3e-7 * (0.3 * j as f64).cos()).collect();
    let mut rold = vec![0.0; n * M];
    let mut rnew = rold.clone();
    let (mut rf, mut rd) = (vec![0.0; 2 * n], vec![0.0; n]);
    // The C side steps its states in place (old == new).
    let mut cstate = vec![0.0; n * M];
    let (mut cf, mut cd) = (vec![0.0; 2 * n], vec![0.0; n]);
    for round in 0..20 {
        rust.step_block(
            FrictionBlock {
                normal_force: &nf,
                area: Some(&a),
                slip: &sl,
                dt: 1e-6,
                tangents: 0,
                states: BlockStates::Separate {
                    old: &rold,
                    new: &mut rnew,
                },
                tangential_force: Some(&mut rf),
                dissipation: Some(&mut rd),
                responses: None,
            },
            &mut rw,
        )
        .unwrap();
        let p = cstate.as_mut_ptr();
        let st = unsafe {
            asperity_friction_step_block(
                l.0,
                n,
                nf.as_ptr(),
                a.as_ptr(),
                sl.as_ptr(),
                1e-6,
                p,
                p,
                cf.as_mut_ptr(),
                cd.as_mut_ptr(),
                null_mut(),
            )
        };
        assert_eq!(st, ASPERITY_OK, "{}", last_message());
        assert_eq!(cstate, rnew, "round {round}");
        assert_eq!(
            cf.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
            rf.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
        );
        assert_eq!(cd, rd);
        std::mem::swap(&mut rold, &mut rnew);
    }
    unsafe {
        // Fresh (all-zero) old states, no dissipation wanted.
        let fresh = vec![0.0; n * M];
        let mut new = vec![0.0; n * M];
        let mut f = vec![0.0; 2 * n];
        // The block from these states into `new` and the forces into `f`,
        // no dissipation, no work; the law, the areas and Δt as each check
        // has them.
        let new_p = new.as_mut_ptr();
        let block = |law: *const AsperityFriction, areas: *const f64, dt: f64, f: &mut [f64]| {
            asperity_friction_step_block(
                law,
                n,
                nf.as_ptr(),
                areas,
                sl.as_ptr(),
                dt,
                fresh.as_ptr(),
                new_p,
                f.as_mut_ptr(),
                null_mut(),
                null_mut(),
            )
        };
        let st = block(l.0, a.as_ptr(), 1e-6, &mut f);
        assert_eq!(st, ASPERITY_OK);
        let mut s2 = fresh.clone();
        let mut f2 = vec![0.0; 2 * n];
        rust.step_block(
            FrictionBlock {
                normal_force: &nf,
                area: Some(&a),
                slip: &sl,
                dt: 1e-6,
                tangents: 0,
                states: BlockStates::InPlace(&mut s2),
                tangential_force: Some(&mut f2),
                dissipation: None,
                responses: None,
            },
            &mut rw,
        )
        .unwrap();
        assert_eq!(f, f2);
        assert_eq!(new, s2);
        // n = 0 needs no arrays.
        assert_eq!(
            asperity_friction_step_block(
                l.0,
                0,
                null(),
                null(),
                null(),
                0.0,
                null(),
                null_mut(),
                null_mut(),
                null_mut(),
                null_mut()
            ),
            ASPERITY_OK
        );
        // Required arrays.
        for which in 0..5 {
            let ptr = |k: usize, p: *const f64| if k == which { null() } else { p };
            let mut_ptr = |k: usize, p: *mut f64| if k == which { null_mut() } else { p };
            let st = asperity_friction_step_block(
                l.0,
                n,
                ptr(0, nf.as_ptr()),
                a.as_ptr(),
                ptr(1, sl.as_ptr()),
                1e-6,
                ptr(2, fresh.as_ptr()),
                mut_ptr(3, new.as_mut_ptr()),
                mut_ptr(4, f.as_mut_ptr()),
                null_mut(),
                null_mut(),
            );
            let name = [
                "`normal_forces`",
                "`slip_increments`",
                "`old_states`",
                "`new_states`",
                "`tangential_forces`",
            ][which];
            expect_error(st, ASPERITY_ERR_NULL_POINTER, name);
        }
        // NULL areas: 0 for every point, which this law refuses (element 0).
        let st = block(l.0, null(), 1e-6, &mut f);
        expect_error(st, ASPERITY_ERR_INVALID_ARGUMENT, "element 0");
        expect_error(st, ASPERITY_ERR_INVALID_ARGUMENT, "`area`");
        // A bad element: the message names it, earlier ones are written.
        let mut a_bad = a.clone();
        a_bad[7] = -1.0;
        let mut f = vec![-99.0; 2 * n];
        let st = block(l.0, a_bad.as_ptr(), 1e-6, &mut f);
        expect_error(st, ASPERITY_ERR_INVALID_ARGUMENT, "element 7");
        expect_error(st, ASPERITY_ERR_INVALID_ARGUMENT, "`area`");
        assert!(f[..14].iter().all(|&x| x != -99.0) && f[14..].iter().all(|&x| x == -99.0));
        let st = block(l.0, a.as_ptr(), f64::NAN, &mut f);
        expect_error(st, ASPERITY_ERR_INVALID_ARGUMENT, "`dt`");
        let st = block(null(), a.as_ptr(), 0.0, &mut f);
        expect_error(st, ASPERITY_ERR_NULL_POINTER, "`law`");
    }
}

#[test]
fn json_through_the_c_abi() {
    let s = samples();
    let h = handle(&s);
    unsafe {
        let mut needed = 0usize;
        assert_eq!(
            asperity_homogenised_friction_to_json(h.0, null_mut(), 0, &mut needed),
            ASPERITY_OK
        );
        expect_error(
            asperity_homogenised_friction_to_json(h.0, null_mut(), 0, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`needed`",
        );
        let mut buf = vec![0u8; needed + 1];
        let mut n2 = 0usize;
        asperity_homogenised_friction_to_json(
            h.0,
            buf.as_mut_ptr().cast::<c_char>(),
            buf.len(),
            &mut n2,
        );
        assert_eq!(n2, needed);
        let text = std::str::from_utf8(&buf[..needed]).unwrap();
        let rust = HomogenisedFriction::from_samples(&s, CofForm::Derjaguin).unwrap();
        assert_eq!(text, rust.to_json());
        let mut g = null_mut();
        assert_eq!(
            asperity_homogenised_friction_from_json(buf.as_ptr().cast(), needed, &mut g),
            ASPERITY_OK
        );
        let g = Handle(g);
        let i = inc(123.0, 1e-6, -4e-7);
        let mut r1 = FrictionResponse::default();
        let mut r2 = FrictionResponse::default();
        let fresh = [0.0; M];
        let mut new = [0.0; M];
        let (lh, lg) = (law(&h, K), law(&g, K));
        for (l, r) in [(&lh, &mut r1), (&lg, &mut r2)] {
            assert_eq!(
                asperity_friction_step(l.0, &i, fresh.as_ptr(), new.as_mut_ptr(), null_mut(), r),
                ASPERITY_OK
            );
        }
        assert_eq!(format!("{r1:?}"), format!("{r2:?}"));
        // A JSON law in another form.
        let amontons = HomogenisedFriction::from_samples(&s, CofForm::Amontons)
            .unwrap()
            .to_json();
        let mut a = null_mut();
        assert_eq!(
            asperity_homogenised_friction_from_json(
                amontons.as_ptr().cast(),
                amontons.len(),
                &mut a
            ),
            ASPERITY_OK
        );
        let a = Handle(a);
        let la = law(&a, K);
        assert_eq!(
            asperity_friction_step(
                la.0,
                &inc(100.0, 1e-3, 0.0),
                fresh.as_ptr(),
                new.as_mut_ptr(),
                null_mut(),
                &mut r1,
            ),
            ASPERITY_OK
        );
        assert_eq!(r1.force, [-0.97 * 100.0, 0.0]);
    }
}
