//! The C ABI of the models that were Rust-only (issue 33 §1) and the
//! additive Hurst estimate (issue 34 §3), called from Rust: equality with
//! the Rust API, the closed forms the modules give (the flat layer's spring
//! 2aε, the elastic-continuum rescaling, the Coulomb fixed point, H of a
//! generated self-affine profile), capacities, NULL outputs and errors that
//! name the argument.

mod common;
use common::c_errors::{expect_error, last_message};

use asperity::ffi::hierarchical::*;
use asperity::ffi::statistics::*;
use asperity::ffi::surface::*;
use asperity::ffi::*;
use asperity::hierarchical::Schmittbuhl;
use asperity::statistics::SliderState;
use asperity::surface::{hurst_fit, SelfAffine};
use core::f64::consts::TAU;
use std::ptr::{null, null_mut};

#[track_caller]
fn ok(status: i32) {
    assert_eq!(status, ASPERITY_OK, "{}", last_message());
}

fn flat() -> AsperityBorodichKryukova {
    AsperityBorodichKryukova {
        half_length: 0.01,
        mass: 1.0,
        belt_speed: 0.1,
        spring_stiffness: 1e3,
        layer_stiffness: 5e8,
        friction_coefficient: 0.3,
        gravity: 9.81,
        sign_speed: 1e-4,
        slider_amplitude: 0.0,
        slider_wavelength: 1e-3,
        belt_amplitude: 0.0,
        belt_wavelength: 1e-3,
        nodes: 200,
        reserved: 0,
    }
}

#[test]
fn borodich_kryukova_c_matches_rust_and_the_flat_closed_forms() {
    let p = flat();
    let (m, g) = (p.mass, p.gravity);
    let y_rest = -m * g / (2.0 * p.half_length * p.layer_stiffness);
    let x_star = p.friction_coefficient * m * g / p.spring_stiffness;
    let wx = (p.spring_stiffness / m).sqrt();
    unsafe {
        let mut f = 0.0;
        ok(asperity_borodich_kryukova_normal_force(
            &p, 0.0, y_rest, 0.0, &mut f,
        ));
        assert!((f / (m * g) - 1.0).abs() < 1e-12, "{f}");
        let start = AsperityBorodichKryukovaState {
            y: y_rest,
            ..Default::default()
        };
        let (steps, every) = (30_000, 100);
        let mut out = vec![AsperityBorodichKryukovaSample::default(); 302];
        let mut written = 0usize;
        ok(asperity_borodich_kryukova_run(
            &p,
            &start,
            1e-5,
            steps,
            every,
            out.len(),
            out.as_mut_ptr(),
            &mut written,
        ));
        assert_eq!(written, 301);
        // The slot past the samples is untouched.
        assert_eq!(out[301], AsperityBorodichKryukovaSample::default());
        let rust = p
            .to_model()
            .run(
                SliderState {
                    y: y_rest,
                    ..Default::default()
                },
                1e-5,
                steps,
                every,
            )
            .unwrap();
        for (c, r) in out.iter().zip(&rust) {
            assert_eq!(
                (c.state.time, c.state.x, c.state.vx, c.state.y, c.state.vy),
                (r.state.time, r.state.x, r.state.vx, r.state.y, r.state.vy)
            );
            assert_eq!(
                (c.normal_force, c.friction_force),
                (r.normal_force, r.friction_force)
            );
            // x = x*(1 − cos ω_x t) while sliding (x* ω_x < U).
            let want = x_star * (1.0 - (wx * c.state.time).cos());
            assert!((c.state.x - want).abs() < 1e-9, "t {}", c.state.time);
        }
        // Exactly enough room, `written` NULL.
        let mut two = [AsperityBorodichKryukovaSample::default(); 2];
        ok(asperity_borodich_kryukova_run(
            &p,
            &start,
            1e-5,
            3,
            2,
            2,
            two.as_mut_ptr(),
            null_mut(),
        ));
        assert_eq!(two[1].state.time, 2e-5);
    }
}

#[test]
fn borodich_kryukova_c_full_contact_of_whole_wavelengths() {
    // a a multiple of both wavelengths and y below −(A_s + A_b): the
    // cosines sum to zero on the midpoint cells, F = −2aε y at any x, t.
    let p = AsperityBorodichKryukova {
        slider_amplitude: 2e-7,
        belt_amplitude: 3e-7,
        belt_wavelength: 0.5e-3,
        ..flat()
    };
    for eps in [1e6, 1e8, 1e10] {
        let p = AsperityBorodichKryukova {
            layer_stiffness: eps,
            ..p
        };
        for y in [-6e-7, -1e-6, -1e-5] {
            for (x, t) in [(0.0, 0.0), (1.3e-4, 0.7), (-2e-3, 5.0)] {
                let mut f = 0.0;
                unsafe {
                    ok(asperity_borodich_kryukova_normal_force(&p, x, y, t, &mut f));
                }
                let want = -2.0 * p.half_length * eps * y;
                assert!((f / want - 1.0).abs() < 1e-10, "{f} vs {want}");
            }
        }
    }
}

#[test]
fn borodich_kryukova_c_errors_name_the_argument() {
    let p = flat();
    let s = AsperityBorodichKryukovaState::default();
    let mut f = 0.0;
    let mut out = [AsperityBorodichKryukovaSample::default(); 4];
    let mut written = 7usize;
    unsafe {
        expect_error(
            asperity_borodich_kryukova_normal_force(null(), 0.0, 0.0, 0.0, &mut f),
            ASPERITY_ERR_NULL_POINTER,
            "`bk`",
        );
        expect_error(
            asperity_borodich_kryukova_normal_force(&p, 0.0, 0.0, 0.0, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_borodich_kryukova_normal_force(&p, 0.0, f64::NAN, 0.0, &mut f),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`y`",
        );
        expect_error(
            asperity_borodich_kryukova_normal_force(
                &AsperityBorodichKryukova::default(),
                0.0,
                0.0,
                0.0,
                &mut f,
            ),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`half_length`",
        );
        let bad = AsperityBorodichKryukova { nodes: 0, ..p };
        expect_error(
            asperity_borodich_kryukova_run(&bad, &s, 1e-5, 1, 1, 4, out.as_mut_ptr(), null_mut()),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`nodes`",
        );
        expect_error(
            asperity_borodich_kryukova_run(&p, null(), 1e-5, 1, 1, 4, out.as_mut_ptr(), null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`start`",
        );
        expect_error(
            asperity_borodich_kryukova_run(&p, &s, 1e-5, 1, 0, 4, out.as_mut_ptr(), null_mut()),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`every`",
        );
        // 4 steps recorded every step: 5 samples, room for 4.
        expect_error(
            asperity_borodich_kryukova_run(&p, &s, 1e-5, 4, 1, 4, out.as_mut_ptr(), &mut written),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`capacity`",
        );
        assert_eq!(written, 7, "a failed call leaves its outputs");
        expect_error(
            asperity_borodich_kryukova_run(&p, &s, 1e-5, 1, 1, 4, null_mut(), null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`samples`",
        );
        expect_error(
            asperity_borodich_kryukova_run(&p, &s, 0.0, 1, 1, 4, out.as_mut_ptr(), null_mut()),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`dt`",
        );
        let nan = AsperityBorodichKryukovaState { vx: f64::NAN, ..s };
        expect_error(
            asperity_borodich_kryukova_run(&p, &nan, 1e-5, 1, 1, 4, out.as_mut_ptr(), null_mut()),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`start.vx`",
        );
    }
    assert_eq!(out, [AsperityBorodichKryukovaSample::default(); 4]);
}

#[test]
fn schmittbuhl_c_matches_rust_and_rescales_as_a_continuum() {
    let mut d = AsperitySchmittbuhl::default();
    unsafe {
        ok(asperity_schmittbuhl_default(&mut d));
    }
    assert_eq!(d.to_model(), Schmittbuhl::default());
    assert_eq!(
        (d.ratio, d.generations, d.dimension, d.reserved),
        (3, 3, 3, 0)
    );
    let mut out = [AsperitySchmittbuhlGeneration::default(); 5];
    let mut written = 0usize;
    unsafe {
        ok(asperity_schmittbuhl_run(
            &d,
            out.len(),
            out.as_mut_ptr(),
            &mut written,
        ));
    }
    assert_eq!(written, 4);
    assert_eq!(out[4], AsperitySchmittbuhlGeneration::default());
    let rust = Schmittbuhl::default().run().unwrap();
    for (c, r) in out.iter().zip(&rust) {
        assert_eq!(c, &AsperitySchmittbuhlGeneration::from(*r));
        assert_eq!((c.index as usize, c.events as usize), (r.index, r.events));
        // L_g = 3ᵍ L₀ in d = 3: springs ∝ L, masses ∝ L³, n ∝ L.
        let s = 3f64.powi(c.index as i32);
        assert_eq!(c.size, s);
        assert!((c.mass / (d.mass * s.powi(3)) - 1.0).abs() < 1e-12);
        assert!((c.pulling_stiffness / (d.pulling_stiffness * s) - 1.0).abs() < 1e-12);
        assert!((c.coupling_stiffness / (d.coupling_stiffness * s) - 1.0).abs() < 1e-12);
        assert!((c.normal_force / (d.normal_force * s) - 1.0).abs() < 1e-12);
        assert!(c.mu_kinetic <= c.mu_static);
    }
    assert_eq!((out[0].mu_static, out[0].mu_kinetic), (0.5, 0.3));
}

#[test]
fn schmittbuhl_c_coulomb_law_is_a_fixed_point() {
    // μ_s = μ_k, no weakening, in d = 2 with N = 2: every generation keeps
    // μ up to the quasi-static overshoot (≤ 2.5e-3, module docs).
    for mu in [0.1, 1.2] {
        let m = AsperitySchmittbuhl {
            mu_static: mu,
            mu_kinetic: mu,
            weakening_velocity: f64::INFINITY,
            ratio: 2,
            dimension: 2,
            ..Schmittbuhl::default().into()
        };
        let mut out = [AsperitySchmittbuhlGeneration::default(); 4];
        unsafe {
            ok(asperity_schmittbuhl_run(
                &m,
                4,
                out.as_mut_ptr(),
                null_mut(),
            ));
        }
        for g in &out {
            assert!((g.mu_static / mu - 1.0).abs() < 2.5e-3, "{g:?}");
            assert!((g.mu_kinetic / mu - 1.0).abs() < 2.5e-3, "{g:?}");
        }
    }
}

#[test]
fn schmittbuhl_c_errors_name_the_field() {
    let d: AsperitySchmittbuhl = Schmittbuhl::default().into();
    let mut out = [AsperitySchmittbuhlGeneration::default(); 4];
    let mut written = 9usize;
    unsafe {
        expect_error(
            asperity_schmittbuhl_default(null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_schmittbuhl_run(null(), 4, out.as_mut_ptr(), null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`model`",
        );
        expect_error(
            asperity_schmittbuhl_run(&d, 3, out.as_mut_ptr(), &mut written),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`capacity`",
        );
        expect_error(
            asperity_schmittbuhl_run(&d, 4, null_mut(), &mut written),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        for (bad, name) in [
            (AsperitySchmittbuhl { ratio: 1, ..d }, "`ratio`"),
            (AsperitySchmittbuhl { ratio: 65, ..d }, "`ratio`"),
            (
                AsperitySchmittbuhl {
                    generations: 0,
                    ..d
                },
                "`generations`",
            ),
            (AsperitySchmittbuhl { dimension: 4, ..d }, "`dimension`"),
            (AsperitySchmittbuhl { disorder: 1.0, ..d }, "`disorder`"),
            (
                AsperitySchmittbuhl {
                    mu_kinetic: 0.6,
                    ..d
                },
                "`mu_kinetic`",
            ),
            (
                AsperitySchmittbuhl {
                    weakening_velocity: f64::NAN,
                    ..d
                },
                "`weakening_velocity`",
            ),
            (AsperitySchmittbuhl { mass: 0.0, ..d }, "`mass`"),
            (AsperitySchmittbuhl::default(), "`weakening_velocity`"),
        ] {
            expect_error(
                asperity_schmittbuhl_run(&bad, 64, out.as_mut_ptr(), &mut written),
                ASPERITY_ERR_INVALID_ARGUMENT,
                name,
            );
        }
    }
    assert_eq!(written, 9);
    assert_eq!(out, [AsperitySchmittbuhlGeneration::default(); 4]);
}

#[test]
fn hurst_estimate_reports_the_uncertainty_and_the_band() {
    // A generated self-affine profile (H = 0.7, 2¹⁶ points): the fit
    // recovers H within 0.02 (src/surface/power_law.rs), and the C struct
    // carries every field of the Rust fit, the band also as wavelengths.
    let (n, dx) = (1usize << 16, 1e-7);
    let z = SelfAffine::new(0.7, 1e-7)
        .unwrap()
        .profile(n, dx, 11)
        .unwrap()
        .heights()
        .to_vec();
    let mut e = AsperityHurstEstimate::default();
    let mut old = AsperityHurstFit::default();
    unsafe {
        ok(asperity_profile_hurst_estimate(
            n,
            z.as_ptr(),
            dx,
            0.0,
            0.0,
            &mut e,
        ));
        ok(asperity_profile_hurst_fit(
            n,
            z.as_ptr(),
            dx,
            0.0,
            0.0,
            &mut old,
        ));
    }
    let h = hurst_fit(&z, dx, None).unwrap();
    assert_eq!(
        (
            e.hurst,
            e.hurst_uncertainty,
            e.slope,
            e.slope_uncertainty,
            e.prefactor,
            e.r_squared,
            e.chi2_per_dof,
            e.q_min,
            e.q_max,
            e.bins as usize
        ),
        (
            h.hurst,
            h.hurst_uncertainty,
            h.slope,
            h.slope_uncertainty,
            h.prefactor,
            h.r_squared,
            h.chi2_per_dof,
            h.q_min,
            h.q_max,
            h.bins
        )
    );
    assert_eq!((old.hurst, old.q_min, old.bins), (e.hurst, e.q_min, h.bins));
    assert!((e.hurst - 0.7).abs() < 0.02, "{e:?}");
    assert!(
        e.hurst_uncertainty > 0.0 && e.hurst_uncertainty < 0.02,
        "{e:?}"
    );
    assert_eq!(e.slope_uncertainty, 2.0 * e.hurst_uncertainty);
    assert_eq!(
        (e.wavelength_min, e.wavelength_max),
        (TAU / e.q_max, TAU / e.q_min)
    );
    // The band spans at least a decade and lies between 2 dx and the length.
    assert!(e.q_max / e.q_min >= 10.0 * (1.0 - 1e-12), "{e:?}");
    assert!(e.wavelength_min >= 2.0 * dx && e.wavelength_max <= n as f64 * dx);
    // An explicit band.
    unsafe {
        ok(asperity_profile_hurst_estimate(
            n,
            z.as_ptr(),
            dx,
            2e5,
            2e7,
            &mut e,
        ));
    }
    assert!(e.q_min >= 2e5 && e.q_max <= 2e7, "{e:?}");
    assert!((e.hurst - 0.7).abs() < 0.03, "{e:?}");
    // Errors: NULL output, a bad band, a profile without a power-law band.
    let before = e;
    unsafe {
        expect_error(
            asperity_profile_hurst_estimate(n, z.as_ptr(), dx, 0.0, 0.0, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_profile_hurst_estimate(n, z.as_ptr(), dx, 2e7, 2e5, &mut e),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`q_max`",
        );
        let sine: Vec<f64> = (0..4096)
            .map(|i| (TAU * i as f64 / 256.0).sin() * 1e-6)
            .collect();
        expect_error(
            asperity_profile_hurst_estimate(sine.len(), sine.as_ptr(), dx, 0.0, 0.0, &mut e),
            ASPERITY_ERR_OUT_OF_DOMAIN,
            "`heights`",
        );
    }
    assert_eq!(e, before);
}
