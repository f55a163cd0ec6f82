//! The C ABI of the homogenised friction law, called from Rust: NULL
//! pointers, bad input (status and the message of
//! `asperity_last_error_message`), the state size, and equality of the
//! scalar and block steps with the Rust API (bit for bit), including
//! old/new aliasing and the JSON path.

mod common;
use common::c_errors::{expect_error, last_message};

use asperity::ffi::homogenised::*;
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

fn inc(n: f64, sx: f64, sy: f64) -> FrictionIncrement {
    FrictionIncrement {
        normal_force: n,
        area: AREA,
        slip: [sx, sy],
        dt: 1e-6,
        stick_stiffness: K,
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
    }
}

#[test]
fn state_size() {
    let n = asperity_homogenised_friction_state_size();
    assert_eq!(n, std::mem::size_of::<FrictionPointState>());
    // force[2], slip_path, 4 dissipation entries, steps.
    assert_eq!(n, 8 * 8);
}

#[test]
fn step_equals_the_rust_api() {
    let s = samples();
    let h = handle(&s);
    let rust = HomogenisedFriction::from_samples(&s, CofForm::Derjaguin).unwrap();
    let mut old = FrictionPointState::default();
    for i in 0..300 {
        let x = i as f64;
        let incr = inc(
            5.0 + (7.0 * x) % 230.0,
            2e-7 * (0.1 * x).cos(),
            2e-7 * (0.1 * x).sin(),
        );
        let (rs, rr) = rust.step_value(&old, &incr).unwrap();
        let mut cs = FrictionPointState::default();
        let mut cr = FrictionResponse::default();
        let st = unsafe { asperity_homogenised_friction_step(h.0, &incr, &old, &mut cs, &mut cr) };
        assert_eq!(st, ASPERITY_OK, "{}", last_message());
        assert_eq!(format!("{rs:?}{rr:?}"), format!("{cs:?}{cr:?}"));
        // In place (old == new) gives the same.
        let mut inplace = old;
        let mut cr2 = FrictionResponse::default();
        let p: *mut FrictionPointState = &mut inplace;
        let st = unsafe { asperity_homogenised_friction_step(h.0, &incr, p, p, &mut cr2) };
        assert_eq!(st, ASPERITY_OK);
        assert_eq!(inplace, cs);
        assert_eq!(cr2, cr);
        old = cs;
    }
    // NULL old state = fresh; NULL new state = not wanted.
    let mut r1 = FrictionResponse::default();
    let mut r2 = FrictionResponse::default();
    let fresh = FrictionPointState::default();
    unsafe {
        assert_eq!(
            asperity_homogenised_friction_step(
                h.0,
                &inc(50.0, 1e-6, 0.0),
                null(),
                null_mut(),
                &mut r1
            ),
            ASPERITY_OK
        );
        asperity_homogenised_friction_step(h.0, &inc(50.0, 1e-6, 0.0), &fresh, null_mut(), &mut r2);
    }
    assert_eq!(r1, r2);
    assert_eq!(r1.regime, ASPERITY_FRICTION_SLIP);
}

#[test]
fn step_errors() {
    let h = handle(&samples());
    let mut s = FrictionPointState::default();
    let mut r = FrictionResponse::default();
    let i = inc(50.0, 1e-7, 0.0);
    unsafe {
        expect_error(
            asperity_homogenised_friction_step(null(), &i, null(), &mut s, &mut r),
            ASPERITY_ERR_NULL_POINTER,
            "`friction`",
        );
        expect_error(
            asperity_homogenised_friction_step(h.0, null(), null(), &mut s, &mut r),
            ASPERITY_ERR_NULL_POINTER,
            "`increment`",
        );
        expect_error(
            asperity_homogenised_friction_step(h.0, &i, null(), &mut s, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        let sentinel = FrictionPointState {
            steps: 99,
            ..Default::default()
        };
        s = sentinel;
        for (bad, name) in [
            (FrictionIncrement { area: -1e-6, ..i }, "`area`"),
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
            (
                FrictionIncrement {
                    stick_stiffness: -1.0,
                    ..i
                },
                "`stick_stiffness`",
            ),
        ] {
            expect_error(
                asperity_homogenised_friction_step(h.0, &bad, null(), &mut s, &mut r),
                ASPERITY_ERR_INVALID_ARGUMENT,
                name,
            );
            assert_eq!(s, sentinel, "new state untouched on failure");
        }
        let bad_old = FrictionPointState {
            force: [f64::INFINITY, 0.0],
            ..Default::default()
        };
        expect_error(
            asperity_homogenised_friction_step(h.0, &i, &bad_old, &mut s, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`old.force`",
        );
    }
}

#[test]
fn block_equals_the_rust_api_and_reports_the_element() {
    let s = samples();
    let h = handle(&s);
    let rust = HomogenisedFriction::from_samples(&s, CofForm::Derjaguin).unwrap();
    let n = 32;
    let nf: Vec<f64> = (0..n).map(|i| 10.0 + 6.0 * i as f64).collect();
    let a = vec![AREA; n];
    let sl: Vec<f64> = (0..2 * n).map(|j| 3e-7 * (0.3 * j as f64).cos()).collect();
    let mut rold = vec![FrictionPointState::default(); n];
    let mut rnew = rold.clone();
    let (mut rf, mut rd) = (vec![0.0; 2 * n], vec![0.0; n]);
    // The C side steps its states in place (old == new).
    let mut cstate = vec![FrictionPointState::default(); n];
    let (mut cf, mut cd) = (vec![0.0; 2 * n], vec![0.0; n]);
    for round in 0..20 {
        rust.step_block(&nf, &a, &sl, 1e-6, K, &rold, &mut rnew, &mut rf, &mut rd)
            .unwrap();
        let p = cstate.as_mut_ptr();
        let st = unsafe {
            asperity_homogenised_friction_step_block(
                h.0,
                n,
                nf.as_ptr(),
                a.as_ptr(),
                sl.as_ptr(),
                1e-6,
                K,
                p,
                p,
                cf.as_mut_ptr(),
                cd.as_mut_ptr(),
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
        // NULL old (fresh), NULL new and dissipation (not wanted).
        let mut f = vec![0.0; 2 * n];
        let st = asperity_homogenised_friction_step_block(
            h.0,
            n,
            nf.as_ptr(),
            a.as_ptr(),
            sl.as_ptr(),
            1e-6,
            K,
            null(),
            null_mut(),
            f.as_mut_ptr(),
            null_mut(),
        );
        assert_eq!(st, ASPERITY_OK);
        let fresh = vec![FrictionPointState::default(); n];
        let mut s2 = fresh.clone();
        let mut f2 = vec![0.0; 2 * n];
        let mut d2 = vec![0.0; n];
        rust.step_block(&nf, &a, &sl, 1e-6, K, &fresh, &mut s2, &mut f2, &mut d2)
            .unwrap();
        assert_eq!(f, f2);
        // n = 0 needs no arrays.
        assert_eq!(
            asperity_homogenised_friction_step_block(
                h.0,
                0,
                null(),
                null(),
                null(),
                0.0,
                0.0,
                null(),
                null_mut(),
                null_mut(),
                null_mut()
            ),
            ASPERITY_OK
        );
        // Required arrays.
        for which in 0..4 {
            let ptr = |k: usize, p: *const f64| if k == which { null() } else { p };
            let st = asperity_homogenised_friction_step_block(
                h.0,
                n,
                ptr(0, nf.as_ptr()),
                ptr(1, a.as_ptr()),
                ptr(2, sl.as_ptr()),
                1e-6,
                K,
                null(),
                null_mut(),
                if which == 3 {
                    null_mut()
                } else {
                    f.as_mut_ptr()
                },
                null_mut(),
            );
            let name = [
                "`normal_forces`",
                "`areas`",
                "`slip_increments`",
                "`tangential_forces`",
            ][which];
            expect_error(st, ASPERITY_ERR_NULL_POINTER, name);
        }
        // A bad element: the message names it, earlier ones are written.
        let mut a_bad = a.clone();
        a_bad[7] = -1.0;
        let mut f = vec![-99.0; 2 * n];
        let st = asperity_homogenised_friction_step_block(
            h.0,
            n,
            nf.as_ptr(),
            a_bad.as_ptr(),
            sl.as_ptr(),
            1e-6,
            K,
            null(),
            null_mut(),
            f.as_mut_ptr(),
            null_mut(),
        );
        expect_error(st, ASPERITY_ERR_INVALID_ARGUMENT, "element 7");
        expect_error(st, ASPERITY_ERR_INVALID_ARGUMENT, "`area`");
        assert!(f[..14].iter().all(|&x| x != -99.0) && f[14..].iter().all(|&x| x == -99.0));
        let st = asperity_homogenised_friction_step_block(
            h.0,
            n,
            nf.as_ptr(),
            a.as_ptr(),
            sl.as_ptr(),
            f64::NAN,
            K,
            null(),
            null_mut(),
            f.as_mut_ptr(),
            null_mut(),
        );
        expect_error(st, ASPERITY_ERR_INVALID_ARGUMENT, "`dt`");
        let st = asperity_homogenised_friction_step_block(
            null(),
            n,
            nf.as_ptr(),
            a.as_ptr(),
            sl.as_ptr(),
            0.0,
            K,
            null(),
            null_mut(),
            f.as_mut_ptr(),
            null_mut(),
        );
        expect_error(st, ASPERITY_ERR_NULL_POINTER, "`friction`");
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
        asperity_homogenised_friction_step(h.0, &i, null(), null_mut(), &mut r1);
        asperity_homogenised_friction_step(g.0, &i, null(), null_mut(), &mut r2);
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
        asperity_homogenised_friction_step(
            a.0,
            &inc(100.0, 1e-3, 0.0),
            null(),
            null_mut(),
            &mut r1,
        );
        assert_eq!(r1.force, [-0.97 * 100.0, 0.0]);
    }
}
