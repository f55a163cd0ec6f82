//! The Sergienko–Bukharov C ABI (`asperity_sergienko_bukharov_run`) called
//! from Rust: equality with the Rust API for a list and a Gaussian, the
//! friction drop and lift with the amplitude through C, and the error paths
//! naming the argument.

mod common;
use common::c_errors::{expect_error, last_message};

use asperity::ffi::statistics::*;
use asperity::ffi::*;
use asperity::statistics::{
    Excitation, HeightDistribution, Integration, KragelskyRods, SergienkoBukharov,
};
use std::ptr::{null, null_mut};

#[track_caller]
fn ok(status: i32) {
    assert_eq!(status, ASPERITY_OK, "{}", last_message());
}

fn params() -> AsperitySergienkoBukharovParams {
    AsperitySergienkoBukharovParams {
        distribution: ASPERITY_HEIGHTS_LIST,
        transient_periods: 10,
        average_periods: 4,
        steps_per_natural_period: 64,
        rod_count: 0.0,
        sigma: 0.0,
        rod_stiffness: 1e4,
        rod_area: 1e-12,
        mass: 1e-3,
        load: 1.0,
        damping_ratio: 0.2,
        friction_coefficient: 0.2,
        attractive_pressure: 1e9,
        force_amplitude: 0.5,
        frequency: 0.0, // set from ω₀ below
        tangential_impulse: 1e-6,
        slope: 0.1,
        initial_offset: 0.0,
        max_steps: 0,
    }
}

fn heights() -> Vec<f64> {
    (0..2000).map(|j| (j as f64 + 0.5) * 5e-9).collect()
}

#[test]
fn sergienko_bukharov_c_matches_rust() {
    let h = heights();
    let rods = KragelskyRods::new(
        h.len() as f64,
        1e-12,
        1e4,
        HeightDistribution::empirical(h.clone()).unwrap(),
    )
    .unwrap();
    let model = SergienkoBukharov::new(rods, 1e-3, 1.0, 0.2, 0.2, 1e9).unwrap();
    let mut p = params();
    p.frequency = 0.3 * model.natural_frequency();
    let want = model
        .run(
            &Excitation {
                force_amplitude: p.force_amplitude,
                frequency: p.frequency,
                tangential_impulse: p.tangential_impulse,
                slope: p.slope,
                initial_offset: 0.0,
            },
            &Integration {
                transient_periods: 10,
                average_periods: 4,
                steps_per_natural_period: 64,
                record_every: 0,
                max_steps: 0,
            },
        )
        .unwrap();
    let mut r = AsperitySergienkoBukharovResult::default();
    unsafe {
        ok(asperity_sergienko_bukharov_run(
            &p,
            h.as_ptr(),
            h.len(),
            &mut r,
        ));
    }
    assert_eq!(r, (&want).into());
    assert_eq!(r.steps, want.steps);
    assert!(r.friction_ratio < 1.0 && r.lift > 0.0, "{r:?}");
    // Larger amplitude: less friction, more lift.
    let mut q = p;
    q.force_amplitude = 0.9;
    let mut s = AsperitySergienkoBukharovResult::default();
    unsafe {
        ok(asperity_sergienko_bukharov_run(
            &q,
            h.as_ptr(),
            h.len(),
            &mut s,
        ));
    }
    assert!(s.friction_ratio < r.friction_ratio && s.lift > r.lift);
    // Gaussian heights: no array needed.
    let g = AsperitySergienkoBukharovParams {
        distribution: ASPERITY_HEIGHTS_GAUSSIAN,
        rod_count: 1e4,
        sigma: 1e-6,
        ..p
    };
    let rods =
        KragelskyRods::new(1e4, 1e-12, 1e4, HeightDistribution::gaussian(1e-6).unwrap()).unwrap();
    let model = SergienkoBukharov::new(rods, 1e-3, 1.0, 0.2, 0.2, 1e9).unwrap();
    let (_, exc, int) = g.to_model(&[]).unwrap();
    let want = model.run(&exc, &int).unwrap();
    unsafe {
        ok(asperity_sergienko_bukharov_run(&g, null(), 0, &mut r));
    }
    assert_eq!(r, (&want).into());
}

#[test]
fn sergienko_bukharov_c_errors_name_the_argument() {
    let h = heights();
    let mut p = params();
    p.frequency = 1e4;
    let mut r = AsperitySergienkoBukharovResult::default();
    unsafe {
        expect_error(
            asperity_sergienko_bukharov_run(null(), h.as_ptr(), h.len(), &mut r),
            ASPERITY_ERR_NULL_POINTER,
            "`params`",
        );
        expect_error(
            asperity_sergienko_bukharov_run(&p, h.as_ptr(), h.len(), null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_sergienko_bukharov_run(&p, null(), 3, &mut r),
            ASPERITY_ERR_NULL_POINTER,
            "`heights`",
        );
        expect_error(
            asperity_sergienko_bukharov_run(&p, h.as_ptr(), 0, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`heights`",
        );
        let all_zero = AsperitySergienkoBukharovParams::default();
        expect_error(
            asperity_sergienko_bukharov_run(&all_zero, h.as_ptr(), h.len(), &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`rod_area`",
        );
        let bad = AsperitySergienkoBukharovParams {
            distribution: 7,
            ..p
        };
        expect_error(
            asperity_sergienko_bukharov_run(&bad, h.as_ptr(), h.len(), &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`distribution`",
        );
        for (q, name) in [
            (
                AsperitySergienkoBukharovParams { mass: -1.0, ..p },
                "`mass`",
            ),
            (AsperitySergienkoBukharovParams { load: 0.0, ..p }, "`load`"),
            (
                AsperitySergienkoBukharovParams {
                    frequency: 0.0,
                    ..p
                },
                "`frequency`",
            ),
            (
                AsperitySergienkoBukharovParams {
                    average_periods: 0,
                    ..p
                },
                "`average_periods`",
            ),
            (
                AsperitySergienkoBukharovParams {
                    distribution: ASPERITY_HEIGHTS_GAUSSIAN,
                    rod_count: 1e3,
                    ..p
                },
                "`sigma`",
            ),
        ] {
            expect_error(
                asperity_sergienko_bukharov_run(&q, h.as_ptr(), h.len(), &mut r),
                ASPERITY_ERR_INVALID_ARGUMENT,
                name,
            );
        }
    }
}
