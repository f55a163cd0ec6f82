//! The slider-geometry C ABI called from Rust: NULL pointers, short caller
//! arrays, bad values (negative status and a message naming the argument),
//! NULL accepted by `_free`, and results equal to the Rust API.

mod common;
use common::c_errors::{expect_error, last_message};

use asperity::ffi::friction::*;
use asperity::ffi::*;
use asperity::friction::{NanoAsperities, SliderGeometry};
use std::ptr::{null, null_mut};

const NM: f64 = 1e-9;
const UM: f64 = 1e-6;

/// Piecewise-linear micro profile (dx = 1 µm) and a square-wave nano
/// profile (dx = 10 nm), as in tests/slider_geometry.rs.
fn profiles() -> (Vec<f64>, Vec<f64>) {
    let micro = [1.0, 3.0, -1.0, 5.0, 0.0, 2.0, 4.0, -2.0, 1.0, 3.0]
        .iter()
        .map(|h| h * NM)
        .collect();
    let period = [3.0, 3.0, 1.0, 1.0, -2.0, -2.0, -2.0, -2.0];
    let nano = (0..32).map(|j| period[j % 8] * NM).collect();
    (micro, nano)
}

unsafe fn build(
    micro: &[f64],
    nano: &[f64],
    widths: &[f64],
    out: *mut *mut AsperitySliderGeometry,
) -> i32 {
    asperity_slider_geometry_new(
        micro.as_ptr(),
        micro.len(),
        UM,
        nano.as_ptr(),
        nano.len(),
        10.0 * NM,
        widths.as_ptr(),
        widths.len(),
        out,
    )
}

#[test]
fn geometry_from_two_arrays_equals_the_rust_api() {
    let (micro, nano) = profiles();
    let widths = [5.0 * UM, 2.5 * UM, 1.25 * UM];
    let rust = SliderGeometry::from_slices(&micro, UM, &widths, &nano, 10.0 * NM).unwrap();
    unsafe {
        let mut g = null_mut();
        assert_eq!(build(&micro, &nano, &widths, &mut g), ASPERITY_OK);
        assert!(!g.is_null());
        let mut levels = 0usize;
        assert_eq!(
            asperity_slider_geometry_level_count(g, &mut levels),
            ASPERITY_OK
        );
        assert_eq!(levels, 3);
        for (l, level) in rust.levels().iter().enumerate() {
            let mut count = 0usize;
            assert_eq!(
                asperity_slider_geometry_rod_count(g, l, &mut count),
                ASPERITY_OK
            );
            assert_eq!(count, level.len());
            let (mut width, mut origin) = (0.0, f64::NAN);
            assert_eq!(
                asperity_slider_geometry_rod_width(g, l, &mut width, &mut origin),
                ASPERITY_OK
            );
            assert_eq!((width, origin), (level.width(), level.origin()));
            assert_eq!(
                asperity_slider_geometry_rod_width(g, l, &mut width, null_mut()),
                ASPERITY_OK
            );
            // A longer caller array: only `count` values are written.
            let mut heights = vec![f64::NAN; count + 2];
            assert_eq!(
                asperity_slider_geometry_rod_heights(g, l, heights.as_mut_ptr(), heights.len()),
                ASPERITY_OK
            );
            assert_eq!(&heights[..count], level.heights());
            assert!(heights[count..].iter().all(|h| h.is_nan()));
        }
        // Hand value of the finest level (see tests/slider_geometry.rs):
        // −0.1, 0.4, 0.025, 0.025 nm.
        let mut h = [0.0; 4];
        assert_eq!(
            asperity_slider_geometry_rod_heights(g, 2, h.as_mut_ptr(), 4),
            ASPERITY_OK
        );
        for (a, b) in h.iter().zip([-0.1, 0.4, 0.025, 0.025]) {
            assert!((a - b * NM).abs() < 1e-15 * NM, "{h:?}");
        }
        let mut n = AsperityNanoAsperities::default();
        assert_eq!(asperity_slider_geometry_nano(g, &mut n), ASPERITY_OK);
        let r = rust.nano();
        assert_eq!(
            (n.h_vdw, n.w_vdw, n.h_chem, n.w_chem, n.spacing, n.per_rod),
            (
                r.h_vdw,
                r.w_vdw,
                r.h_chem,
                r.w_chem,
                r.spacing,
                rust.nano_per_rod()
            )
        );
        // λ = 80 nm on a 1.25 µm tip: ⌊15.625⌋ = 15 per side.
        assert_eq!(n.per_rod, 225);
        asperity_slider_geometry_free(g);
    }
}

#[test]
fn hand_calculation_from_numbers() {
    let nano = AsperityNanoAsperities {
        h_vdw: 4.1 * NM,
        w_vdw: 430.0 * NM,
        h_chem: 4.1 * NM,
        w_chem: 161.0 * NM,
        spacing: 1.35 * UM,
        per_rod: 100,
    };
    let rust = SliderGeometry::uniform(
        13.5 * UM,
        10,
        NanoAsperities {
            h_vdw: 4.1 * NM,
            w_vdw: 430.0 * NM,
            h_chem: 4.1 * NM,
            w_chem: 161.0 * NM,
            spacing: 1.35 * UM,
        },
        100,
    )
    .unwrap();
    unsafe {
        let mut g = null_mut();
        assert_eq!(
            asperity_slider_geometry_new_uniform(13.5 * UM, 10, &nano, &mut g),
            ASPERITY_OK
        );
        let mut back = AsperityNanoAsperities::default();
        assert_eq!(asperity_slider_geometry_nano(g, &mut back), ASPERITY_OK);
        assert_eq!(back, nano);
        let mut count = 0;
        assert_eq!(
            asperity_slider_geometry_rod_count(g, 0, &mut count),
            ASPERITY_OK
        );
        assert_eq!(count, rust.tips().len());
        let mut h = [1.0; 10];
        assert_eq!(
            asperity_slider_geometry_rod_heights(g, 0, h.as_mut_ptr(), 10),
            ASPERITY_OK
        );
        assert_eq!(&h[..], rust.tips().heights());
        asperity_slider_geometry_free(g);

        // Bad numbers: 101 per tip do not fit; w_chem > w_vdW; no rods.
        let mut g = null_mut();
        let bad = AsperityNanoAsperities {
            per_rod: 101,
            ..nano
        };
        let s = asperity_slider_geometry_new_uniform(13.5 * UM, 1, &bad, &mut g);
        expect_error(s, ASPERITY_ERR_INVALID_ARGUMENT, "`nano_per_rod`");
        assert!(g.is_null());
        let bad = AsperityNanoAsperities {
            w_chem: 500.0 * NM,
            ..nano
        };
        let s = asperity_slider_geometry_new_uniform(13.5 * UM, 1, &bad, &mut g);
        expect_error(s, ASPERITY_ERR_INVALID_ARGUMENT, "`w_chem`");
        let s = asperity_slider_geometry_new_uniform(13.5 * UM, 0, &nano, &mut g);
        expect_error(s, ASPERITY_ERR_INVALID_ARGUMENT, "`rods`");
        let s = asperity_slider_geometry_new_uniform(-1.0, 1, &nano, &mut g);
        expect_error(s, ASPERITY_ERR_INVALID_ARGUMENT, "`rod_width`");
        let s = asperity_slider_geometry_new_uniform(13.5 * UM, 1, null(), &mut g);
        expect_error(s, ASPERITY_ERR_NULL_POINTER, "`nano`");
        let s = asperity_slider_geometry_new_uniform(13.5 * UM, 1, &nano, null_mut());
        expect_error(s, ASPERITY_ERR_NULL_POINTER, "`out`");
    }
}

#[test]
fn null_pointers_short_arrays_and_bad_values() {
    let (micro, nano) = profiles();
    let w = [5.0 * UM];
    unsafe {
        asperity_slider_geometry_free(null_mut());
        let mut g = null_mut();
        let s = asperity_slider_geometry_new(
            null(),
            10,
            UM,
            nano.as_ptr(),
            nano.len(),
            10.0 * NM,
            w.as_ptr(),
            1,
            &mut g,
        );
        expect_error(s, ASPERITY_ERR_NULL_POINTER, "`micro_heights`");
        assert!(g.is_null());
        let s = asperity_slider_geometry_new(
            micro.as_ptr(),
            micro.len(),
            UM,
            null(),
            0,
            10.0 * NM,
            w.as_ptr(),
            1,
            &mut g,
        );
        expect_error(s, ASPERITY_ERR_NULL_POINTER, "`nano_heights`");
        let s = asperity_slider_geometry_new(
            micro.as_ptr(),
            micro.len(),
            UM,
            nano.as_ptr(),
            nano.len(),
            10.0 * NM,
            null(),
            1,
            &mut g,
        );
        expect_error(s, ASPERITY_ERR_NULL_POINTER, "`rod_widths`");
        expect_error(
            build(&micro, &nano, &w, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        // Bad values.
        expect_error(
            build(&micro, &nano, &[0.0], &mut g),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`rod_widths`",
        );
        expect_error(
            build(&micro, &nano, &[5.0 * UM, 2.0 * UM], &mut g),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`rod_widths`",
        );
        expect_error(
            build(&micro, &nano, &[], &mut g),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`rod_widths.len()`",
        );
        expect_error(
            build(&micro[..5], &nano, &w, &mut g),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`micro_heights.len()`",
        );
        let mut bad = nano.clone();
        bad[0] = f64::NAN;
        expect_error(
            build(&micro, &bad, &w, &mut g),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`nano_heights`",
        );
        expect_error(
            build(&micro, &[1.0; 8], &w, &mut g),
            ASPERITY_ERR_OUT_OF_DOMAIN,
            "`nano_heights`",
        );
        expect_error(
            build(&micro, &nano, &[50.0 * NM], &mut g),
            ASPERITY_ERR_OUT_OF_DOMAIN,
            "`rod_widths`",
        );
        let s = asperity_slider_geometry_new(
            micro.as_ptr(),
            micro.len(),
            -UM,
            nano.as_ptr(),
            nano.len(),
            10.0 * NM,
            w.as_ptr(),
            1,
            &mut g,
        );
        expect_error(s, ASPERITY_ERR_INVALID_ARGUMENT, "`micro_dx`");
        assert!(g.is_null());

        // Queries on a valid geometry: one level of 2.5 µm rods, 3 of them.
        assert_eq!(build(&micro, &nano, &[2.5 * UM], &mut g), ASPERITY_OK);
        let mut count = 0usize;
        expect_error(
            asperity_slider_geometry_rod_count(null(), 0, &mut count),
            ASPERITY_ERR_NULL_POINTER,
            "`geometry`",
        );
        expect_error(
            asperity_slider_geometry_rod_count(g, 0, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`count`",
        );
        expect_error(
            asperity_slider_geometry_rod_count(g, 1, &mut count),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`level`",
        );
        expect_error(
            asperity_slider_geometry_level_count(g, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`count`",
        );
        let mut short = [0.0; 2];
        expect_error(
            asperity_slider_geometry_rod_heights(g, 0, short.as_mut_ptr(), short.len()),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`len`",
        );
        assert_eq!(short, [0.0; 2], "nothing written on failure");
        expect_error(
            asperity_slider_geometry_rod_heights(g, 0, null_mut(), 3),
            ASPERITY_ERR_NULL_POINTER,
            "`heights`",
        );
        expect_error(
            asperity_slider_geometry_rod_heights(g, 5, short.as_mut_ptr(), 2),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`level`",
        );
        let mut width = 0.0;
        expect_error(
            asperity_slider_geometry_rod_width(g, 0, null_mut(), null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`width`",
        );
        expect_error(
            asperity_slider_geometry_rod_width(g, 1, &mut width, null_mut()),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`level`",
        );
        expect_error(
            asperity_slider_geometry_nano(g, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_slider_geometry_nano(null(), &mut AsperityNanoAsperities::default()),
            ASPERITY_ERR_NULL_POINTER,
            "`geometry`",
        );
        let mut h = [0.0; 3];
        assert_eq!(
            asperity_slider_geometry_rod_heights(g, 0, h.as_mut_ptr(), 3),
            ASPERITY_OK
        );
        // −0.1, 0.4, −0.85 nm by (6-1).
        for (a, b) in h.iter().zip([-0.1, 0.4, -0.85]) {
            assert!((a - b * NM).abs() < 1e-15 * NM, "{h:?}");
        }
        asperity_slider_geometry_free(g);
    }
}

/// An AFM profile sampled at 10⁻²⁰ m gives a nano-asperity spacing ~10¹⁴
/// times below a 1 µm rod: the count per rod overflowed `usize` (the C
/// guard's `ASPERITY_ERR_INTERNAL`). Now an error naming `rod_widths` (more
/// than 2²⁴ nano-asperities per rod), the handle NULL.
#[test]
fn nano_spacing_far_below_the_rod_width_is_an_error() {
    let (micro, nano) = profiles();
    let widths = [UM];
    for nano_dx in [1e-20, 1e-300] {
        let mut g = 1usize as *mut AsperitySliderGeometry;
        let st = unsafe {
            asperity_slider_geometry_new(
                micro.as_ptr(),
                micro.len(),
                UM,
                nano.as_ptr(),
                nano.len(),
                nano_dx,
                widths.as_ptr(),
                widths.len(),
                &mut g,
            )
        };
        assert!(g.is_null());
        expect_error(st, ASPERITY_ERR_OUT_OF_DOMAIN, "rod_widths");
        assert!(last_message().contains("2^24"), "{}", last_message());
    }
}
