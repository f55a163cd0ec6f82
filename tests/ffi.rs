//! The C ABI called directly from Rust: status codes, error messages, the
//! message buffer protocol, status strings, the version, batch evaluation and
//! caller-owned state. Only laws that do not depend on the adhesive solvers
//! (Hertz, DMT, power punch, flat punch) are used where a working law is
//! needed, except in the round trip of every constructor through
//! `asperity_law_from_params`.

mod common;
use common::c_errors::{expect_error, last_message};

use asperity::contact::{ContactState, NormalResponse};
use asperity::ffi::contact::*;
use asperity::ffi::material::*;
use asperity::ffi::*;
use std::ffi::CStr;
use std::ptr::{null, null_mut};

const R: f64 = 1e-6;
const E: f64 = 1e9;
const W: f64 = 0.05;

fn law(f: impl FnOnce(*mut AsperityNormalLaw) -> i32) -> AsperityNormalLaw {
    let mut out = std::mem::MaybeUninit::<AsperityNormalLaw>::zeroed();
    let s = f(out.as_mut_ptr());
    assert_eq!(s, ASPERITY_OK, "constructor failed: {}", last_message());
    unsafe { out.assume_init() }
}

fn hertz() -> AsperityNormalLaw {
    law(|o| unsafe { asperity_law_hertz(R, E, o) })
}
fn dmt() -> AsperityNormalLaw {
    law(|o| unsafe { asperity_law_dmt(R, E, W, o) })
}
fn power_punch() -> AsperityNormalLaw {
    law(|o| unsafe { asperity_law_power_punch(1e3, 1.5, E, o) })
}
fn flat_punch() -> AsperityNormalLaw {
    law(|o| unsafe { asperity_law_flat_punch_no_slip(R, E, 0.3, o) })
}

fn eval(
    l: &AsperityNormalLaw,
    delta: f64,
    old: &ContactState,
) -> (i32, NormalResponse, ContactState) {
    let mut r = NormalResponse::default();
    let mut s = ContactState::default();
    let st = unsafe { asperity_normal_eval(l, delta, old, &mut s, &mut r) };
    (st, r, s)
}

// --- NULL pointers -----------------------------------------------------------

#[test]
fn null_out_pointers_are_reported() {
    unsafe {
        expect_error(
            asperity_law_hertz(R, E, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_law_dmt(R, E, W, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_law_power_punch(1.0, 2.0, E, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_law_flat_punch(R, E, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        let h = hertz();
        expect_error(
            asperity_normal_eval(&h, 1e-9, null(), null_mut(), null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_normal_eval_at_load(&h, 1e-6, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_pull_off_force(&h, ASPERITY_CONTROL_LOAD, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`force`",
        );
        expect_error(
            asperity_law_length_scale(&h, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`length`",
        );
        expect_error(
            asperity_effective_modulus(1e9, 0.3, 1e9, 0.3, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`e_star`",
        );
        expect_error(
            asperity_no_slip_factor(0.3, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`c_ns`",
        );
    }
}

#[test]
fn null_law_pointer_is_reported() {
    unsafe {
        let mut r = NormalResponse::default();
        let mut f = 0.0;
        expect_error(
            asperity_normal_eval(null(), 1e-9, null(), null_mut(), &mut r),
            ASPERITY_ERR_NULL_POINTER,
            "`law`",
        );
        expect_error(
            asperity_normal_eval_at_load(null(), 1e-6, &mut r),
            ASPERITY_ERR_NULL_POINTER,
            "`law`",
        );
        expect_error(
            asperity_pull_off_force(null(), ASPERITY_CONTROL_LOAD, &mut f),
            ASPERITY_ERR_NULL_POINTER,
            "`law`",
        );
        expect_error(
            asperity_law_length_scale(null(), &mut f),
            ASPERITY_ERR_NULL_POINTER,
            "`law`",
        );
        let d = [1e-9];
        expect_error(
            asperity_normal_eval_batch(
                null(),
                1,
                d.as_ptr(),
                null(),
                null_mut(),
                &mut f,
                null_mut(),
                null_mut(),
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`law`",
        );
        // Required batch arrays.
        let h = hertz();
        expect_error(
            asperity_normal_eval_batch(
                &h,
                1,
                null(),
                null(),
                null_mut(),
                &mut f,
                null_mut(),
                null_mut(),
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`delta`",
        );
        expect_error(
            asperity_normal_eval_batch(
                &h,
                1,
                d.as_ptr(),
                null(),
                null_mut(),
                null_mut(),
                null_mut(),
                null_mut(),
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`force`",
        );
        // n = 0 touches no array.
        assert_eq!(
            asperity_normal_eval_batch(
                &h,
                0,
                null(),
                null(),
                null_mut(),
                null_mut(),
                null_mut(),
                null_mut()
            ),
            ASPERITY_OK
        );
    }
}

// --- invalid arguments -------------------------------------------------------

#[test]
fn bad_numbers_are_invalid_arguments_naming_the_argument() {
    let mut out = std::mem::MaybeUninit::<AsperityNormalLaw>::zeroed();
    let o = out.as_mut_ptr();
    let inv = ASPERITY_ERR_INVALID_ARGUMENT;
    unsafe {
        for bad in [-1e-6, 0.0, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            expect_error(asperity_law_hertz(bad, E, o), inv, "`radius`");
            expect_error(asperity_law_dmt(bad, E, W, o), inv, "`radius`");
            expect_error(asperity_law_flat_punch(bad, E, o), inv, "`radius`");
            expect_error(asperity_law_hertz(R, bad, o), inv, "`e_star`");
            expect_error(asperity_law_power_punch(1.0, 2.0, bad, o), inv, "`e_star`");
        }
        for bad in [-0.01, f64::NAN, f64::INFINITY] {
            expect_error(asperity_law_dmt(R, E, bad, o), inv, "`work_of_adhesion`");
        }
        // ν outside [0, 0.5].
        for nu in [0.5000001, 0.6, -0.1, f64::NAN, f64::INFINITY] {
            expect_error(asperity_law_flat_punch_no_slip(R, E, nu, o), inv, "`nu`");
            let mut c = 0.0;
            expect_error(asperity_no_slip_factor(nu, &mut c), inv, "`nu`");
        }
        // A negative radius message says the bound.
        asperity_law_hertz(-1.0, E, o);
        let m = last_message();
        assert!(m.contains("> 0"), "message `{m}` should state the bound");
        // Non-finite overlaps and loads.
        let h = hertz();
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let (s, _, _) = eval(&h, bad, &ContactState::default());
            expect_error(s, inv, "`delta`");
            let mut r = NormalResponse::default();
            expect_error(
                asperity_normal_eval_at_load(&h, bad, &mut r),
                inv,
                "`force`",
            );
        }
    }
}

#[test]
fn unknown_law_kind_and_control_are_invalid_arguments() {
    let mut zeroed: AsperityNormalLaw = unsafe { std::mem::zeroed() };
    assert_eq!(zeroed.kind, ASPERITY_LAW_NONE);
    let mut r = NormalResponse::default();
    let mut f = 0.0;
    unsafe {
        // The first kind past the last law, and far-off values.
        let next = asperity::NormalLaw::NAMES.len() as i32 + 1;
        for kind in [ASPERITY_LAW_NONE, next, 99, -1, i32::MAX] {
            zeroed.kind = kind;
            expect_error(
                asperity_normal_eval(&zeroed, 1e-9, null(), null_mut(), &mut r),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "`law.kind`",
            );
            assert!(last_message().contains(&kind.to_string()));
            expect_error(
                asperity_pull_off_force(&zeroed, ASPERITY_CONTROL_LOAD, &mut f),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "`law.kind`",
            );
            expect_error(
                asperity_normal_eval_at_load(&zeroed, 0.0, &mut r),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "`law.kind`",
            );
            expect_error(
                asperity_law_length_scale(&zeroed, &mut f),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "`law.kind`",
            );
            let d = [1e-9];
            expect_error(
                asperity_normal_eval_batch(
                    &zeroed,
                    1,
                    d.as_ptr(),
                    null(),
                    null_mut(),
                    &mut f,
                    null_mut(),
                    null_mut(),
                ),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "`law.kind`",
            );
        }
        let h = hertz();
        for control in [2, -1, 99] {
            expect_error(
                asperity_pull_off_force(&h, control, &mut f),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "`control`",
            );
        }
        // Other selectors.
        let mut out = std::mem::MaybeUninit::<AsperityNormalLaw>::zeroed();
        expect_error(
            asperity_law_kendall(R, E, W, 0.3, 2, out.as_mut_ptr()),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`no_slip`",
        );
        expect_error(
            asperity_law_derjaguin(R, W, 99, 3e-10, out.as_mut_ptr()),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`surface_law`",
        );
    }
}

#[test]
fn successful_calls_leave_the_message_unchanged() {
    unsafe {
        asperity_law_hertz(-1.0, E, null_mut());
        let before = last_message();
        let _ = hertz();
        let (s, _, _) = eval(&hertz(), 1e-9, &ContactState::default());
        assert_eq!(s, ASPERITY_OK);
        assert_eq!(last_message(), before);
    }
}

#[test]
fn messages_are_thread_local() {
    unsafe {
        asperity_law_hertz(-1.0, E, null_mut());
    }
    let mine = last_message();
    let other = std::thread::spawn(|| {
        let fresh = last_message();
        unsafe {
            asperity_law_dmt(R, E, -1.0, null_mut());
        }
        (fresh, last_message())
    })
    .join()
    .unwrap();
    assert_eq!(other.0, "", "empty before the first failure on a thread");
    assert!(other.1.contains("out"), "{}", other.1);
    assert_eq!(last_message(), mine);
}

// --- the message buffer protocol -------------------------------------------

#[test]
fn message_buffer_protocol() {
    unsafe {
        let mut o = std::mem::MaybeUninit::<AsperityNormalLaw>::zeroed();
        assert_eq!(
            asperity_law_hertz(-2.5, E, o.as_mut_ptr()),
            ASPERITY_ERR_INVALID_ARGUMENT
        );
        let full = last_message();
        let n = full.len();
        assert!(n > 10);
        // (NULL, 0) and (NULL, anything) return the length and write nothing.
        assert_eq!(asperity_last_error_message(null_mut(), 0), n);
        assert_eq!(asperity_last_error_message(null_mut(), 100), n);
        // A buffer of length 0 is not written.
        let mut one = [0x55u8; 1];
        assert_eq!(asperity_last_error_message(one.as_mut_ptr().cast(), 0), n);
        assert_eq!(one[0], 0x55);
        // Length 1: just the NUL.
        assert_eq!(asperity_last_error_message(one.as_mut_ptr().cast(), 1), n);
        assert_eq!(one[0], 0);
        // Truncation: len − 1 bytes and a NUL, nothing written past len.
        for len in [2usize, 8, n, n + 1, n + 10] {
            let mut buf = vec![0x55u8; len + 4];
            assert_eq!(asperity_last_error_message(buf.as_mut_ptr().cast(), len), n);
            let k = (len - 1).min(n);
            assert_eq!(&buf[..k], &full.as_bytes()[..k], "len {len}");
            assert_eq!(buf[k], 0, "NUL after {k} bytes (len {len})");
            assert!(
                buf[len..].iter().all(|&b| b == 0x55),
                "wrote past len {len}"
            );
            let s = CStr::from_ptr(buf.as_ptr().cast()).to_str().unwrap();
            assert_eq!(s, &full[..k]);
        }
    }
}

// --- status strings and version ---------------------------------------------

#[test]
fn status_strings() {
    let cases = [
        (ASPERITY_OK, "ok"),
        (ASPERITY_ERR_NULL_POINTER, "null pointer"),
        (ASPERITY_ERR_INVALID_ARGUMENT, "invalid argument"),
        (ASPERITY_ERR_NOT_CONVERGED, "not converged"),
        (ASPERITY_ERR_OUT_OF_DOMAIN, "out of domain"),
        (ASPERITY_ERR_INTERNAL, "internal error"),
        (1, "unknown status"),
        (-8, "unknown status"),
        (i32::MIN, "unknown status"),
        (i32::MAX, "unknown status"),
    ];
    for (code, text) in cases {
        let p = asperity_status_string(code);
        assert!(!p.is_null());
        let s = unsafe { CStr::from_ptr(p) }.to_str().unwrap();
        assert_eq!(s, text, "status {code}");
        // Static storage: the same pointer every time.
        assert_eq!(p, asperity_status_string(code));
    }
    // The codes are distinct and negative for errors.
    let codes = [
        ASPERITY_ERR_NULL_POINTER,
        ASPERITY_ERR_INVALID_ARGUMENT,
        ASPERITY_ERR_NOT_CONVERGED,
        ASPERITY_ERR_OUT_OF_DOMAIN,
        ASPERITY_ERR_INTERNAL,
    ];
    for (i, a) in codes.iter().enumerate() {
        assert!(*a < 0);
        assert!(codes[i + 1..].iter().all(|b| b != a));
    }
}

#[test]
fn version_is_the_package_version() {
    let v = unsafe { CStr::from_ptr(asperity_version()) }
        .to_str()
        .unwrap();
    assert_eq!(v, env!("CARGO_PKG_VERSION"));
    let header =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/include/asperity.h"))
            .unwrap();
    for (macro_name, value) in [
        ("ASPERITY_VERSION_MAJOR", env!("CARGO_PKG_VERSION_MAJOR")),
        ("ASPERITY_VERSION_MINOR", env!("CARGO_PKG_VERSION_MINOR")),
        ("ASPERITY_VERSION_PATCH", env!("CARGO_PKG_VERSION_PATCH")),
    ] {
        assert!(
            header.contains(&format!("#define {macro_name} {value}\n")),
            "{macro_name}"
        );
    }
}

// --- batch ---------------------------------------------------------------------

fn deltas() -> Vec<f64> {
    // Out of contact, touching, and well into contact, for each law's scale.
    (0..40).map(|i| (i as f64 - 8.0) * 2.5e-10).collect()
}

#[test]
fn batch_matches_scalar_element_by_element() {
    for l in [hertz(), dmt(), power_punch(), flat_punch()] {
        let d = deltas();
        let n = d.len();
        let old: Vec<ContactState> = (0..n)
            .map(|i| ContactState {
                contact_radius: if i % 3 == 0 { 1e-8 } else { 0.0 },
                cohesive_radius: 0.0,
                in_contact: (i % 3 == 0) as i32,
                branch: 0,
            })
            .collect();
        let mut new = vec![ContactState::default(); n];
        let (mut f, mut a, mut k) = (vec![f64::NAN; n], vec![f64::NAN; n], vec![f64::NAN; n]);
        let s = unsafe {
            asperity_normal_eval_batch(
                &l,
                n,
                d.as_ptr(),
                old.as_ptr(),
                new.as_mut_ptr(),
                f.as_mut_ptr(),
                a.as_mut_ptr(),
                k.as_mut_ptr(),
            )
        };
        assert_eq!(s, ASPERITY_OK, "{}", last_message());
        for i in 0..n {
            let (s, r, st) = eval(&l, d[i], &old[i]);
            assert_eq!(s, ASPERITY_OK);
            assert_eq!(
                f[i].to_bits(),
                r.force.to_bits(),
                "kind {} element {i}",
                l.kind
            );
            assert_eq!(a[i].to_bits(), r.contact_radius.to_bits());
            assert_eq!(k[i].to_bits(), r.stiffness.to_bits());
            assert_eq!(new[i], st, "kind {} element {i}", l.kind);
            assert!(f[i].is_finite() && a[i].is_finite() && k[i].is_finite());
        }
    }
}

#[test]
fn batch_closed_forms() {
    // Hertz P = (4/3)E*√R δ^{3/2}; DMT the same minus 2πwR in contact.
    let d = deltas();
    let n = d.len();
    let mut f = vec![0.0; n];
    for (l, offset) in [(hertz(), 0.0), (dmt(), 2.0 * std::f64::consts::PI * W * R)] {
        let s = unsafe {
            asperity_normal_eval_batch(
                &l,
                n,
                d.as_ptr(),
                null(),
                null_mut(),
                f.as_mut_ptr(),
                null_mut(),
                null_mut(),
            )
        };
        assert_eq!(s, ASPERITY_OK);
        for i in 0..n {
            let want = if d[i] >= 0.0 {
                4.0 / 3.0 * E * R.sqrt() * d[i].powf(1.5) - offset
            } else {
                0.0
            };
            approx::assert_relative_eq!(f[i], want, max_relative = 1e-12, epsilon = 1e-20);
        }
    }
}

#[test]
fn batch_null_optional_arrays() {
    let l = dmt();
    let d = deltas();
    let n = d.len();
    let mut f_all = vec![0.0; n];
    let mut a_all = vec![0.0; n];
    let mut k_all = vec![0.0; n];
    let mut new_all = vec![ContactState::default(); n];
    let zeros = vec![ContactState::default(); n];
    unsafe {
        assert_eq!(
            asperity_normal_eval_batch(
                &l,
                n,
                d.as_ptr(),
                zeros.as_ptr(),
                new_all.as_mut_ptr(),
                f_all.as_mut_ptr(),
                a_all.as_mut_ptr(),
                k_all.as_mut_ptr()
            ),
            ASPERITY_OK
        );
        // NULL old_state = fresh states; NULL outputs not written.
        let mut f = vec![0.0; n];
        assert_eq!(
            asperity_normal_eval_batch(
                &l,
                n,
                d.as_ptr(),
                null(),
                null_mut(),
                f.as_mut_ptr(),
                null_mut(),
                null_mut()
            ),
            ASPERITY_OK
        );
        assert_eq!(f, f_all);
        let mut a = vec![0.0; n];
        assert_eq!(
            asperity_normal_eval_batch(
                &l,
                n,
                d.as_ptr(),
                null(),
                null_mut(),
                f.as_mut_ptr(),
                a.as_mut_ptr(),
                null_mut()
            ),
            ASPERITY_OK
        );
        assert_eq!(a, a_all);
        let mut k = vec![0.0; n];
        let mut new = vec![ContactState::default(); n];
        assert_eq!(
            asperity_normal_eval_batch(
                &l,
                n,
                d.as_ptr(),
                null(),
                new.as_mut_ptr(),
                f.as_mut_ptr(),
                null_mut(),
                k.as_mut_ptr()
            ),
            ASPERITY_OK
        );
        assert_eq!(k, k_all);
        assert_eq!(new, new_all);
    }
}

#[test]
fn batch_aliasing_input_and_output() {
    let l = hertz();
    let d = deltas();
    let n = d.len();
    let mut f_ref = vec![0.0; n];
    let mut a_ref = vec![0.0; n];
    let mut s_ref = vec![ContactState::default(); n];
    let old: Vec<ContactState> = (0..n)
        .map(|i| ContactState {
            contact_radius: i as f64 * 1e-9,
            cohesive_radius: 0.0,
            in_contact: 1,
            branch: 0,
        })
        .collect();
    unsafe {
        assert_eq!(
            asperity_normal_eval_batch(
                &l,
                n,
                d.as_ptr(),
                old.as_ptr(),
                s_ref.as_mut_ptr(),
                f_ref.as_mut_ptr(),
                a_ref.as_mut_ptr(),
                null_mut()
            ),
            ASPERITY_OK
        );
        // force written over delta, contact radius too (same array), states in place.
        let mut buf = d.clone();
        let mut states = old.clone();
        let p = buf.as_mut_ptr();
        let sp = states.as_mut_ptr();
        assert_eq!(
            asperity_normal_eval_batch(&l, n, p, sp, sp, p, null_mut(), null_mut()),
            ASPERITY_OK
        );
        assert_eq!(buf, f_ref);
        assert_eq!(states, s_ref);
        // delta, force and stiffness all the same memory: stiffness is written last.
        let mut buf = d.clone();
        let p = buf.as_mut_ptr();
        assert_eq!(
            asperity_normal_eval_batch(&l, n, p, null(), null_mut(), p, null_mut(), p),
            ASPERITY_OK
        );
        for i in 0..n {
            let (_, r, _) = eval(&l, d[i], &ContactState::default());
            assert_eq!(buf[i], r.stiffness);
        }
    }
}

#[test]
fn batch_error_names_the_element_and_keeps_earlier_outputs() {
    let l = hertz();
    for bad_index in [0usize, 3, 9] {
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let mut d = deltas()[..10].to_vec();
            d[bad_index] = bad;
            let mut f = vec![-7.0; 10];
            let mut a = vec![-7.0; 10];
            let s = unsafe {
                asperity_normal_eval_batch(
                    &l,
                    10,
                    d.as_ptr(),
                    null(),
                    null_mut(),
                    f.as_mut_ptr(),
                    a.as_mut_ptr(),
                    null_mut(),
                )
            };
            expect_error(
                s,
                ASPERITY_ERR_INVALID_ARGUMENT,
                &format!("element {bad_index}"),
            );
            assert!(last_message().contains("`delta`"), "{}", last_message());
            for i in 0..bad_index {
                let (_, r, _) = eval(&l, d[i], &ContactState::default());
                assert_eq!(f[i], r.force, "element {i} before the error is written");
                assert_eq!(a[i], r.contact_radius);
            }
            assert!(
                f[bad_index..].iter().all(|&x| x == -7.0),
                "nothing written from the bad element on"
            );
        }
    }
}

// --- state ---------------------------------------------------------------------

#[test]
fn eval_does_not_modify_old_state_and_is_repeatable() {
    for l in [hertz(), dmt(), power_punch(), flat_punch()] {
        let scale = {
            let mut s = 0.0;
            assert_eq!(
                unsafe { asperity_law_length_scale(&l, &mut s) },
                ASPERITY_OK
            );
            assert!(s.is_finite() && s > 0.0);
            s
        };
        let mut old = ContactState::default();
        for step in 0..20 {
            let delta = (step as f64 - 5.0) * 1e-10;
            let before = old;
            let (s1, r1, n1) = eval(&l, delta, &old);
            assert_eq!(s1, ASPERITY_OK, "{}", last_message());
            assert_eq!(old, before, "old_state modified (kind {})", l.kind);
            // Re-evaluate the same increment from the same old state.
            let (s2, r2, n2) = eval(&l, delta, &old);
            assert_eq!(s2, ASPERITY_OK);
            assert_eq!(r1, r2);
            assert_eq!(n1, n2);
            assert!(r1.force.is_finite() && r1.stiffness.is_finite());
            assert_eq!(r1.delta, delta);
            assert_eq!(r1.reserved, 0);
            let _ = scale;
            old = n1;
        }
    }
}

#[test]
fn state_pointers_may_be_null_or_the_same() {
    let l = dmt();
    let mut r1 = NormalResponse::default();
    let mut r2 = NormalResponse::default();
    let mut st = ContactState::default();
    unsafe {
        // NULL old (fresh) and NULL new (discarded).
        assert_eq!(
            asperity_normal_eval(&l, 1e-9, null(), null_mut(), &mut r1),
            ASPERITY_OK
        );
        // old and new the same struct.
        let p: *mut ContactState = &mut st;
        assert_eq!(asperity_normal_eval(&l, 1e-9, p, p, &mut r2), ASPERITY_OK);
    }
    assert_eq!(r1, r2);
    assert_eq!(st.in_contact, 1);
    assert!(st.contact_radius > 0.0);
}

#[test]
fn pull_off_and_load_through_the_abi() {
    let mut f = 0.0;
    unsafe {
        for control in [ASPERITY_CONTROL_LOAD, ASPERITY_CONTROL_DISPLACEMENT] {
            assert_eq!(
                asperity_pull_off_force(&hertz(), control, &mut f),
                ASPERITY_OK
            );
            assert_eq!(f, 0.0);
            assert_eq!(
                asperity_pull_off_force(&dmt(), control, &mut f),
                ASPERITY_OK
            );
            approx::assert_relative_eq!(
                f,
                -2.0 * std::f64::consts::PI * W * R,
                max_relative = 1e-14
            );
        }
        // Below the pull-off force there is no equilibrium.
        let mut r = NormalResponse::default();
        expect_error(
            asperity_normal_eval_at_load(&hertz(), -1e-9, &mut r),
            ASPERITY_ERR_OUT_OF_DOMAIN,
            "`force`",
        );
        expect_error(
            asperity_normal_eval_at_load(&dmt(), -4e-7, &mut r),
            ASPERITY_ERR_OUT_OF_DOMAIN,
            "`force`",
        );
        // At a load, then back through eval at the returned overlap.
        assert_eq!(
            asperity_normal_eval_at_load(&hertz(), 1e-6, &mut r),
            ASPERITY_OK
        );
        let (_, back, _) = eval(&hertz(), r.delta, &ContactState::default());
        approx::assert_relative_eq!(back.force, 1e-6, max_relative = 1e-12);
    }
}

#[test]
fn law_values_are_plain_data() {
    // Copies evaluate identically.
    let l = power_punch();
    let copy = l;
    let (_, a, _) = eval(&l, 1e-9, &ContactState::default());
    let (_, b, _) = eval(&copy, 1e-9, &ContactState::default());
    assert_eq!(a, b);
    let h = hertz();
    // Only the active member is read: the bytes past it are not guaranteed
    // to be initialised (see the report on `From<NormalLaw>`).
    let p = unsafe { h.params.hertz };
    assert_eq!((p.radius, p.e_star), (R, E));
    assert_eq!((h.kind, h.reserved), (ASPERITY_LAW_HERTZ, 0));
}

#[test]
fn law_storage_past_the_active_member_is_zero() {
    let mut law = std::mem::MaybeUninit::<AsperityNormalLaw>::uninit();
    // SAFETY: the constructor writes the whole value.
    let law = unsafe {
        assert_eq!(asperity_law_hertz(1e-6, 1e9, law.as_mut_ptr()), ASPERITY_OK);
        law.assume_init()
    };
    // SAFETY: every byte of the union is initialised by the constructor.
    let raw = unsafe { law.params.raw };
    assert_eq!((raw[0], raw[1]), (1e-6, 1e9));
    assert!(raw[2..].iter().all(|&x| x.to_bits() == 0));
}

// --- Laws from their inputs --------------------------------------------------

/// A law built from the inputs a constructor stored (the member of its kind)
/// is the constructor's law, bit for bit: the inputs read back as given and
/// the derived values follow from them alone.
#[test]
fn law_from_params_rebuilds_every_constructor() {
    let s = ASPERITY_SURFACE_LAW_DUGDALE;
    let laws = [
        hertz(),
        law(|o| unsafe { asperity_law_sphere_in_crater(R, 4.0 * R, E, o) }),
        power_punch(),
        law(|o| unsafe { asperity_law_cone(1.2, E, o) }),
        law(|o| unsafe { asperity_law_flat_punch(R, E, o) }),
        flat_punch(),
        dmt(),
        law(|o| unsafe { asperity_law_jkr(R, E, W, o) }),
        law(|o| unsafe { asperity_law_jkr_power_punch(1e3, 1.5, E, W, 0.3, 0, o) }),
        law(|o| unsafe { asperity_law_jkr_power_punch(1e3, 1.5, E, W, 0.3, 1, o) }),
        law(|o| unsafe { asperity_law_kendall(R, E, W, 0.2, 0, o) }),
        law(|o| unsafe { asperity_law_kendall(R, E, W, 0.2, 1, o) }),
        law(|o| unsafe { asperity_law_maugis_dugdale(R, E, W, 3e7, o) }),
        law(|o| unsafe { asperity_law_derjaguin(R, W, 1, 0.3e-9, o) }),
        law(|o| unsafe { asperity_law_derjaguin(R, W, s, 3e7, o) }),
        law(|o| unsafe { asperity_law_derjaguin(R, W, 3, 1e-9, o) }),
    ];
    for l in laws {
        let again = law(|o| unsafe { asperity_law_from_params(l.kind, &l.params, o) });
        assert_eq!(again.kind, l.kind);
        // Kind k is the law NormalLaw::NAMES[k - 1].
        let name = l.to_law().unwrap().name();
        assert_eq!(asperity::NormalLaw::NAMES[l.kind as usize - 1], name);
        let bits = |l: &AsperityNormalLaw| unsafe { l.params.raw }.map(f64::to_bits);
        assert_eq!(bits(&again), bits(&l), "kind {}", l.kind);
    }
    // Inputs as given, for a law with a selector and a renamed argument.
    let d = law(|o| unsafe { asperity_law_derjaguin(R, W, s, 3e7, o) });
    let p = unsafe { d.params.derjaguin };
    assert_eq!((p.radius, p.work_of_adhesion, p.parameter), (R, W, 3e7));
    assert_eq!((p.surface_law, p.reserved), (s, 0));
    let k = law(|o| unsafe { asperity_law_kendall(R, E, W, 0.2, 0, o) });
    let p = unsafe { k.params.kendall };
    assert_eq!((p.nu, p.no_slip), (0.2, 0));
}

#[test]
fn law_from_params_errors_name_the_input() {
    use asperity::contact::{DerjaguinParams, KendallParams, MaugisDugdaleParams};
    let next = asperity::NormalLaw::NAMES.len() as i32 + 1;
    let mut out = hertz();
    let before = unsafe { out.params.raw };
    let zero = AsperityLawParams { raw: [0.0; 16] };
    let kendall = |nu, no_slip| AsperityLawParams {
        kendall: KendallParams {
            radius: R,
            e_star: E,
            work_of_adhesion: W,
            nu,
            no_slip,
            reserved: 0,
        },
    };
    let derjaguin = AsperityLawParams {
        derjaguin: DerjaguinParams {
            radius: R,
            work_of_adhesion: W,
            parameter: -1.0,
            surface_law: ASPERITY_SURFACE_LAW_EXPONENTIAL,
            reserved: 0,
        },
    };
    let md = AsperityLawParams {
        maugis_dugdale: MaugisDugdaleParams {
            radius: R,
            e_star: E,
            work_of_adhesion: W,
            cohesive_stress: 0.0,
        },
    };
    // (kind, inputs, the name the message gives)
    let cases = [
        (ASPERITY_LAW_NONE, zero, "`kind`"),
        (next, zero, "`kind`"),
        (-1, zero, "`kind`"),
        (ASPERITY_LAW_KENDALL, kendall(0.3, 2), "`no_slip`"),
        (ASPERITY_LAW_KENDALL, kendall(0.7, 0), "`nu`"),
        (ASPERITY_LAW_DERJAGUIN, derjaguin, "`parameter`"),
        (ASPERITY_LAW_MAUGIS_DUGDALE, md, "`cohesive_stress`"),
    ];
    unsafe {
        for (kind, p, name) in cases {
            expect_error(
                asperity_law_from_params(kind, &p, &mut out),
                ASPERITY_ERR_INVALID_ARGUMENT,
                name,
            );
        }
        expect_error(
            asperity_law_from_params(ASPERITY_LAW_HERTZ, null(), &mut out),
            ASPERITY_ERR_NULL_POINTER,
            "`params`",
        );
        expect_error(
            asperity_law_from_params(ASPERITY_LAW_HERTZ, &zero, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
    }
    // A failed constructor leaves its output as it was.
    assert_eq!(out.kind, ASPERITY_LAW_HERTZ);
    assert_eq!(
        unsafe { out.params.raw }.map(f64::to_bits),
        before.map(f64::to_bits)
    );
}
