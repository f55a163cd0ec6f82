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

/// A cosine along x of wavenumber `k` (rad/m) on `nx` × `ny` points.
fn wave_map(nx: usize, ny: usize, d: f64, k: f64, amplitude: f64) -> Vec<f64> {
    let mut h = Vec::with_capacity(nx * ny);
    for _j in 0..ny {
        for i in 0..nx {
            h.push(amplitude * (k * i as f64 * d).cos());
        }
    }
    h
}

#[test]
fn map_gaussian_filter_c_transmits_half_at_the_cutoff() {
    // ISO 16610-61: a sinusoid of wavelength λc keeps half its amplitude in
    // the mean surface (to 0.01 on this grid, as tests/surface_topography.rs).
    let (nx, ny, d, lc) = (256usize, 96usize, 1e-6, 32e-6);
    let h = wave_map(nx, ny, d, TAU / lc, 1e-6);
    let (mut r, mut m) = (vec![0.0; nx * ny], vec![0.0; nx * ny]);
    let (mut mx, mut my, mut fx, mut fy) = (0usize, 0usize, 9usize, 9usize);
    unsafe {
        ok(asperity_map_gaussian_filter(
            nx,
            ny,
            d,
            d,
            h.as_ptr(),
            lc,
            ASPERITY_FILTER_ENDS_DISCARD,
            r.as_mut_ptr(),
            m.as_mut_ptr(),
            &mut mx,
            &mut my,
            &mut fx,
            &mut fy,
        ));
    }
    assert_eq!((mx, my, fx, fy), (nx - 32, ny - 32, 16, 16));
    let map = asperity::surface::Topography::new(nx, ny, d, d, h.clone()).unwrap();
    let want =
        asperity::surface::areal_gaussian_filter(&map, lc, asperity::surface::FilterEnds::Discard)
            .unwrap();
    assert_eq!(&r[..mx * my], want.roughness.heights());
    assert_eq!(&m[..mx * my], want.mean_surface.heights());
    let rms = (m[..mx * my].iter().map(|v| v * v).sum::<f64>() / (mx * my) as f64).sqrt();
    let got = rms * 2f64.sqrt() / 1e-6;
    assert!((got - 0.5).abs() < 0.01, "{got}");
    for k in 0..mx * my {
        let (i, j) = (k % mx + fx, k / mx + fy);
        // r = z − mean, to rounding of the 1 µm heights.
        assert!((r[k] + m[k] - h[i + nx * j]).abs() < 1e-21);
    }
    // Keep: the whole grid, in place, optional outputs NULL.
    let mut inout = h.clone();
    unsafe {
        ok(asperity_map_gaussian_filter(
            nx,
            ny,
            d,
            d,
            inout.as_ptr(),
            lc,
            ASPERITY_FILTER_ENDS_KEEP,
            inout.as_mut_ptr(),
            null_mut(),
            &mut mx,
            &mut my,
            null_mut(),
            null_mut(),
        ));
    }
    assert_eq!((mx, my), (nx, ny));
    let keep =
        asperity::surface::areal_gaussian_filter(&map, lc, asperity::surface::FilterEnds::Keep)
            .unwrap();
    assert_eq!(inout, keep.roughness.heights());
    // Errors name the argument.
    unsafe {
        for (cutoff, ends, name) in [
            (2e-6, ASPERITY_FILTER_ENDS_KEEP, "`cutoff`"),
            (f64::NAN, ASPERITY_FILTER_ENDS_KEEP, "`cutoff`"),
            (lc, 7, "`ends`"),
        ] {
            expect_error(
                asperity_map_gaussian_filter(
                    nx,
                    ny,
                    d,
                    d,
                    h.as_ptr(),
                    cutoff,
                    ends,
                    r.as_mut_ptr(),
                    null_mut(),
                    &mut mx,
                    &mut my,
                    null_mut(),
                    null_mut(),
                ),
                ASPERITY_ERR_INVALID_ARGUMENT,
                name,
            );
        }
        expect_error(
            asperity_map_gaussian_filter(
                1,
                ny,
                d,
                d,
                h.as_ptr(),
                lc,
                ASPERITY_FILTER_ENDS_KEEP,
                r.as_mut_ptr(),
                null_mut(),
                &mut mx,
                &mut my,
                null_mut(),
                null_mut(),
            ),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`nx`",
        );
        expect_error(
            asperity_map_gaussian_filter(
                nx,
                ny,
                d,
                d,
                h.as_ptr(),
                lc,
                ASPERITY_FILTER_ENDS_KEEP,
                null_mut(),
                null_mut(),
                &mut mx,
                &mut my,
                null_mut(),
                null_mut(),
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`roughness`",
        );
        expect_error(
            asperity_map_gaussian_filter(
                nx,
                ny,
                d,
                d,
                null(),
                lc,
                ASPERITY_FILTER_ENDS_KEEP,
                r.as_mut_ptr(),
                null_mut(),
                &mut mx,
                &mut my,
                null_mut(),
                null_mut(),
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`heights`",
        );
    }
}

#[test]
fn map_psd_radial_c_peaks_at_the_wave_and_matches_rust() {
    // A cosine of k periods along x of a periodic map: with the
    // rectangular window all power sits at |q| = 2πk/L, the annulus m = k.
    for (nx, ny, k) in [(64usize, 64usize, 5usize), (128, 48, 9), (40, 100, 3)] {
        let d = 1e-6;
        let q0 = TAU * k as f64 / (nx as f64 * d);
        let h = wave_map(nx, ny, d, q0, 1e-7);
        let cap = nx.min(ny) / 2 + 1;
        let (mut q, mut g, mut c) = (vec![0.0; cap], vec![0.0; cap], vec![0usize; cap]);
        let mut m = 0usize;
        unsafe {
            ok(asperity_map_psd_radial(
                nx,
                ny,
                d,
                d,
                h.as_ptr(),
                ASPERITY_WINDOW_RECTANGULAR,
                cap,
                q.as_mut_ptr(),
                g.as_mut_ptr(),
                c.as_mut_ptr(),
                &mut m,
            ));
        }
        assert!(m >= 2 && m <= cap);
        let map = asperity::surface::Topography::new(nx, ny, d, d, h.clone()).unwrap();
        let want = asperity::surface::psd_2d(&map, asperity::surface::Window::Rectangular)
            .unwrap()
            .radial();
        assert_eq!(&q[..m], want.r);
        assert_eq!(&g[..m], want.value);
        assert_eq!(&c[..m], want.count);
        let top = (0..m).max_by(|&a, &b| g[a].total_cmp(&g[b])).unwrap();
        let dq = (TAU / (nx as f64 * d)).max(TAU / (ny as f64 * d));
        assert!((q[top] - q0).abs() <= 0.5 * dq, "{} vs {q0}", q[top]);
        // One annulus too few is refused, naming the capacity.
        let before = g.clone();
        unsafe {
            expect_error(
                asperity_map_psd_radial(
                    nx,
                    ny,
                    d,
                    d,
                    h.as_ptr(),
                    ASPERITY_WINDOW_HANN,
                    m - 1,
                    null_mut(),
                    g.as_mut_ptr(),
                    null_mut(),
                    &mut m,
                ),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "`capacity`",
            );
        }
        assert_eq!(g, before);
    }
    let h = [0.0; 16];
    let mut g = [0.0; 8];
    let mut m = 0usize;
    unsafe {
        expect_error(
            asperity_map_psd_radial(
                4,
                4,
                1e-6,
                1e-6,
                h.as_ptr(),
                9,
                8,
                null_mut(),
                g.as_mut_ptr(),
                null_mut(),
                &mut m,
            ),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`window`",
        );
        expect_error(
            asperity_map_psd_radial(
                4,
                4,
                1e-6,
                1e-6,
                h.as_ptr(),
                0,
                8,
                null_mut(),
                g.as_mut_ptr(),
                null_mut(),
                null_mut(),
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`written`",
        );
        expect_error(
            asperity_map_psd_radial(
                4,
                4,
                -1e-6,
                1e-6,
                h.as_ptr(),
                0,
                8,
                null_mut(),
                g.as_mut_ptr(),
                null_mut(),
                &mut m,
            ),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`dx`",
        );
    }
}
