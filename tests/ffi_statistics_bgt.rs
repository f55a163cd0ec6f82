//! The Bush–Gibson–Thomas C ABI (`asperity_bgt_*`) called from Rust:
//! equality with the Rust API, the batch (with NULL optional outputs, in-place
//! use and the failing element), the inverse, the properties, and the error
//! paths naming the argument.

mod common;
use common::c_errors::{expect_error, last_message};

use asperity::ffi::statistics::*;
use asperity::ffi::*;
use asperity::statistics::BushGibsonThomas;
use std::ptr::{null, null_mut};

#[track_caller]
fn ok(status: i32) {
    assert_eq!(status, ASPERITY_OK, "{}", last_message());
}

fn params() -> AsperityBgtParams {
    // σ = 1 µm, √m₂ = 0.1, α = 5.
    AsperityBgtParams {
        m0: 1e-12,
        m2: 1e-2,
        m4: 5.0 * 1e-4 / 1e-12,
        e_star: 1e9,
        nominal_area: 1e-4,
    }
}

#[test]
fn bgt_c_matches_rust() {
    let p = params();
    let model = BushGibsonThomas::new(p.m0, p.m2, p.m4, p.e_star, p.nominal_area).unwrap();
    let d: Vec<f64> = (0..7).map(|i| (-1.0 + 0.75 * i as f64) * 1e-6).collect();
    let n = d.len();
    let (mut load, mut area, mut count, mut k) =
        (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    unsafe {
        ok(asperity_bgt_eval_batch(
            &p,
            n,
            d.as_ptr(),
            load.as_mut_ptr(),
            area.as_mut_ptr(),
            count.as_mut_ptr(),
            k.as_mut_ptr(),
        ));
        for i in 0..n {
            let mut r = AsperityBgtResponse::default();
            ok(asperity_bgt_eval(&p, d[i], &mut r));
            let want = model.evaluate(d[i]).unwrap();
            assert_eq!(
                (r.load, r.area, r.contacts, r.stiffness),
                (
                    want.response.load,
                    want.response.area,
                    want.response.contacts,
                    want.stiffness
                )
            );
            assert_eq!(
                (load[i], area[i], count[i], k[i]),
                (r.load, r.area, r.contacts, r.stiffness)
            );
            if i > 0 {
                assert!(load[i] < load[i - 1] && area[i] < area[i - 1]);
            }
        }
        // In place, optional outputs NULL.
        let mut inout = d.clone();
        ok(asperity_bgt_eval_batch(
            &p,
            n,
            inout.as_ptr(),
            inout.as_mut_ptr(),
            null_mut(),
            null_mut(),
            null_mut(),
        ));
        assert_eq!(inout, load);
        // The inverse.
        let mut s = AsperitySeparation::default();
        ok(asperity_bgt_separation_at_load(&p, load[2], &mut s));
        assert!((s.separation - d[2]).abs() < 1e-15, "{s:?}");
        // Properties: Nayak's density and √(2π)/(E*√(2m₂)).
        let (mut dens, mut ratio) = (0.0, 0.0);
        ok(asperity_bgt_properties(&p, &mut dens, &mut ratio));
        let want = p.m4 / (6.0 * std::f64::consts::PI * 3f64.sqrt() * p.m2);
        assert!((dens / want - 1.0).abs() < 1e-15);
        let want = (2.0 * std::f64::consts::PI).sqrt() / (p.e_star * (2.0 * p.m2).sqrt());
        assert!((ratio / want - 1.0).abs() < 1e-15);
        ok(asperity_bgt_properties(&p, null_mut(), null_mut()));
    }
}

#[test]
fn bgt_c_errors_name_the_argument() {
    let p = params();
    let mut r = AsperityBgtResponse::default();
    let mut s = AsperitySeparation::default();
    unsafe {
        expect_error(
            asperity_bgt_eval(null(), 0.0, &mut r),
            ASPERITY_ERR_NULL_POINTER,
            "`bgt`",
        );
        expect_error(
            asperity_bgt_eval(&p, 0.0, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_bgt_eval(&p, f64::NAN, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`separation`",
        );
        let all_zero = AsperityBgtParams::default();
        expect_error(
            asperity_bgt_eval(&all_zero, 0.0, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`m0`",
        );
        // α = m₀m₄/m₂² = 1 < 3/2.
        let narrow = AsperityBgtParams {
            m4: 1e-4 / 1e-12,
            ..p
        };
        expect_error(
            asperity_bgt_eval(&narrow, 0.0, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`m4`",
        );
        expect_error(
            asperity_bgt_separation_at_load(&p, -1.0, &mut s),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`load`",
        );
        // A batch: NaN at element 2, earlier elements written, later untouched.
        let d = [0.0, 1e-6, f64::NAN, 2e-6];
        let mut load = [-1.0; 4];
        expect_error(
            asperity_bgt_eval_batch(
                &p,
                4,
                d.as_ptr(),
                load.as_mut_ptr(),
                null_mut(),
                null_mut(),
                null_mut(),
            ),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "element 2",
        );
        assert!(load[0] > 0.0 && load[1] > 0.0 && load[2] == -1.0 && load[3] == -1.0);
        expect_error(
            asperity_bgt_eval_batch(
                &p,
                1,
                null(),
                load.as_mut_ptr(),
                null_mut(),
                null_mut(),
                null_mut(),
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`separation`",
        );
        ok(asperity_bgt_eval_batch(
            &p,
            0,
            null(),
            null_mut(),
            null_mut(),
            null_mut(),
            null_mut(),
        ));
    }
}

#[test]
fn bora_c_matches_rust_and_names_errors() {
    use asperity::statistics::BoraTopography;
    let mut h = vec![0.0; 25];
    h[12] = 2e-9;
    h[13] = 1.5e-9;
    let rust = BoraTopography::new(5, 5, 10e-9, h.clone(), 50.0, Some(1e9)).unwrap();
    unsafe {
        let mut m: *mut AsperityBora = null_mut();
        ok(asperity_bora_new(
            5,
            5,
            10e-9,
            h.as_ptr(),
            50.0,
            1e9,
            &mut m,
        ));
        let mut r = AsperityBoraResponse::default();
        let mut forces = vec![0.0; 25];
        ok(asperity_bora_solve(m, 1e-9, &mut r, forces.as_mut_ptr()));
        let want = rust.solve(1e-9).unwrap();
        assert_eq!(
            (r.load, r.area, r.stiffness, r.contacts),
            (want.load, want.area, want.stiffness, want.contacts as u64)
        );
        assert_eq!(forces, want.forces);
        ok(asperity_bora_solve(m, 1e-9, &mut r, null_mut()));
        let mut s = AsperitySeparation::default();
        ok(asperity_bora_separation_at_load(m, r.load, &mut s));
        assert!((s.separation - 1e-9).abs() < 1e-15, "{s:?}");
        expect_error(
            asperity_bora_solve(m, f64::NAN, &mut r, null_mut()),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`separation`",
        );
        expect_error(
            asperity_bora_solve(null(), 0.0, &mut r, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`bora`",
        );
        asperity_bora_free(m);
        asperity_bora_free(null_mut());
        // Rigid substrate (contact_modulus 0): independent springs.
        ok(asperity_bora_new(
            5,
            5,
            10e-9,
            h.as_ptr(),
            50.0,
            0.0,
            &mut m,
        ));
        ok(asperity_bora_solve(m, 1e-9, &mut r, null_mut()));
        assert!((r.load - 50.0 * (1e-9 + 0.5e-9)).abs() < 1e-20);
        asperity_bora_free(m);
        let mut m: *mut AsperityBora = 8 as *mut AsperityBora;
        expect_error(
            asperity_bora_new(5, 5, 10e-9, h.as_ptr(), -50.0, 1e9, &mut m),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`spring_stiffness`",
        );
        assert!(m.is_null());
        expect_error(
            asperity_bora_new(5, 5, 10e-9, null(), 50.0, 1e9, &mut m),
            ASPERITY_ERR_NULL_POINTER,
            "`heights`",
        );
    }
}
