//! The surface and statistics C ABI (`src/ffi/surface.rs`,
//! `src/ffi/statistics/`) called from Rust: analytic values of a sine
//! profile, equality with the Rust API, the generators, Greenwood–Williamson
//! and Zhuravlev, and the error paths (NULL pointers, lengths, selectors,
//! non-finite input, the failing index of a batch).

mod common;
use common::c_errors::{expect_error, last_message};

use asperity::ffi::statistics::*;
use asperity::ffi::surface::*;
use asperity::ffi::*;
use asperity::statistics::{EmpiricalHeights, GreenwoodWilliamson, HeightDistribution, Zhuravlev};
use asperity::surface::{
    gaussian_filter, hurst_fit, psd_windowed, remove_form, roughness_parameters, CantorBorodich,
    Convention, FilterEnds, Form, MaterialRatioCurve, ParameterOptions, PeakStatistics, Profile,
    SelfAffine, WeierstrassMandelbrot, Window,
};
use std::f64::consts::PI;
use std::ffi::c_void;
use std::ptr::{null, null_mut};

#[track_caller]
fn ok(status: i32) {
    assert_eq!(status, ASPERITY_OK, "{}", last_message());
}

/// `periods` whole periods of A sin(2πx/Λ + φ), `per_period` samples each.
fn sine(amplitude: f64, wavelength: f64, periods: usize, per_period: usize) -> (Vec<f64>, f64) {
    let dx = wavelength / per_period as f64;
    let z = (0..periods * per_period)
        .map(|j| amplitude * (2.0 * PI * j as f64 / per_period as f64 + 0.3).sin())
        .collect();
    (z, dx)
}

fn parameters(z: &[f64], dx: f64, form: i32, cutoff: f64, sl: f64) -> AsperityRoughness {
    let mut r = AsperityRoughness::default();
    ok(unsafe { asperity_roughness_parameters(z.len(), z.as_ptr(), dx, form, cutoff, sl, &mut r) });
    r
}

fn self_affine(n: usize, dx: f64, seed: u64) -> Vec<f64> {
    let mut z = vec![0.0; n];
    ok(unsafe { asperity_generate_self_affine(0.7, 1e-6, 0.0, 0.0, dx, seed, n, z.as_mut_ptr()) });
    z
}

// --- Profiles ------------------------------------------------------------------

#[test]
fn sine_profile_parameters_are_analytic() {
    let (a, lambda) = (1e-6, 100e-6);
    let (z, dx) = sine(a, lambda, 10, 200);
    let r = parameters(&z, dx, ASPERITY_FORM_NONE, 0.0, 0.0);
    let rel = |got: f64, want: f64| (got / want - 1.0).abs();
    assert!(rel(r.ra, 2.0 * a / PI) < 1e-4, "Ra {}", r.ra);
    assert!(rel(r.rq, a / 2f64.sqrt()) < 1e-12, "Rq {}", r.rq);
    assert!(r.rsk.abs() < 1e-12, "Rsk {}", r.rsk);
    assert!((r.rku - 1.5).abs() < 1e-12, "Rku {}", r.rku);
    assert!(
        rel(r.rdq, 2f64.sqrt() * PI * a / lambda) < 1e-3,
        "RΔq {}",
        r.rdq
    );
    assert_eq!(r.has_rsm, 1);
    assert!(rel(r.rsm, lambda) < 1e-3, "RSm {}", r.rsm);
    assert_eq!(r.has_rc, 1);
    assert!(rel(r.rc, 2.0 * a) < 1e-3, "Rc {}", r.rc);
    assert!(rel(r.rp, a) < 1e-3 && rel(r.rv, a) < 1e-3);
    assert!(rel(r.rz, r.rp + r.rv) < 1e-15 && r.rz <= r.rt);
    // From the derivatives: m0 = Rq²; a single line at q = 2π/Λ: m2 = q² m0,
    // m4 = q⁴ m0, α = 1, to the stencils' errors ((q dx)²/12 = 8e-5 for the
    // curvature at 200 samples a period) and the end samples (the one-sided
    // slopes at the ends, the two samples the second difference leaves out:
    // ~ 2/2000).
    let q = 2.0 * PI / lambda;
    assert!(rel(r.m0, a * a / 2.0) < 1e-12, "m0 {}", r.m0);
    assert!(rel(r.m2, q * q * r.m0) < 3e-3, "m2 {}", r.m2);
    assert!(rel(r.m4, q.powi(4) * r.m0) < 3e-3, "m4 {}", r.m4);
    assert!(rel(r.nayak_alpha, 1.0) < 6e-3, "α {}", r.nayak_alpha);
    assert_eq!(
        (r.n_evaluated, r.first_index, r.sampling_lengths),
        (2000, 0, 1)
    );
    assert!(rel(r.sampling_length, 10.0 * lambda) < 1e-12);
    // Sampling lengths of two periods: the same values for a sine.
    let s = parameters(&z, dx, ASPERITY_FORM_MEAN, 0.0, 2.0 * lambda);
    assert_eq!(s.sampling_lengths, 5);
    assert!(rel(s.rq, r.rq) < 1e-12 && rel(s.ra, r.ra) < 1e-12);
    // Too short for a Hurst fit: the flag says so and the value is 0.
    let (short, dx_short) = sine(a, lambda, 2, 50);
    let r = parameters(&short, dx_short, ASPERITY_FORM_NONE, 0.0, 0.0);
    assert_eq!((r.has_psd_hurst_exponent, r.psd_hurst_exponent), (0, 0.0));
}

#[test]
fn roughness_equals_the_rust_api() {
    let dx = 1e-6;
    let mut z = self_affine(4096, dx, 7);
    for (j, v) in z.iter_mut().enumerate() {
        *v += 1e-9 * j as f64 + 3e-6; // tilt and offset
    }
    let opts = ParameterOptions {
        convention: Convention::Iso4287,
        ..ParameterOptions::default()
    };
    for (code, form) in [
        (ASPERITY_FORM_NONE, None),
        (ASPERITY_FORM_MEAN, Some(Form::Mean)),
        (ASPERITY_FORM_LINEAR, Some(Form::Linear)),
        (ASPERITY_FORM_QUADRATIC, Some(Form::Quadratic)),
    ] {
        let levelled = match form {
            Some(f) => remove_form(&z, f).unwrap(),
            None => z.clone(),
        };
        // Without a filter.
        let r = parameters(&z, dx, code, 0.0, 0.0);
        let p = roughness_parameters(&levelled, dx, &opts).unwrap();
        let m = asperity::surface::spectral_moments(&levelled, dx).unwrap();
        assert_eq!(r.rq, p.rq);
        assert_eq!(r.ra, p.ra);
        assert_eq!(r.rz, p.rz);
        assert_eq!(r.rt, p.rt);
        assert_eq!(r.rsk, p.rsk);
        assert_eq!(r.rku, p.rku);
        assert_eq!(r.rdq, p.rdq);
        assert_eq!(r.rsm, p.rsm.unwrap_or(0.0));
        assert_eq!(r.rc, p.rc.unwrap_or(0.0));
        assert_eq!(r.has_rsm, i32::from(p.rsm.is_some()));
        assert_eq!(
            r.psd_hurst_exponent,
            p.psd_hurst_exponent.unwrap_or(0.0),
            "form {code}"
        );
        assert_eq!((r.m0, r.m2, r.m4), (m.m0, m.m2, m.m4));
        assert_eq!(r.nayak_alpha, m.nayak_alpha());
        // With the Gaussian filter and sampling lengths of λc (ISO 4288).
        let cutoff = 400e-6;
        let r = parameters(&z, dx, code, cutoff, cutoff);
        let f = gaussian_filter(
            &Profile::new(dx, levelled.clone()).unwrap(),
            cutoff,
            FilterEnds::Discard,
        )
        .unwrap();
        let o = ParameterOptions {
            sampling_length: Some(cutoff),
            ..opts
        };
        let p = roughness_parameters(f.roughness.heights(), dx, &o).unwrap();
        assert_eq!((r.rq, r.rz, r.rdq, r.rku), (p.rq, p.rz, p.rdq, p.rku));
        assert_eq!(r.first_index, f.first_index);
        assert_eq!(r.n_evaluated, f.roughness.len());
        assert_eq!(r.sampling_lengths, p.sampling_lengths);
        assert_eq!(r.first_index, 200);
    }
}

#[test]
fn arrays_equal_the_rust_api() {
    let dx = 1e-6;
    let n = 1000;
    let z = self_affine(n, dx, 3);
    unsafe {
        // Form removal, in place.
        let mut w = z.clone();
        ok(asperity_profile_remove_form(
            n,
            w.as_ptr(),
            ASPERITY_FORM_QUADRATIC,
            w.as_mut_ptr(),
        ));
        assert_eq!(w, remove_form(&z, Form::Quadratic).unwrap());
        let mut w = vec![0.0; n];
        ok(asperity_profile_remove_form(
            n,
            z.as_ptr(),
            ASPERITY_FORM_NONE,
            w.as_mut_ptr(),
        ));
        assert_eq!(w, z);

        // Gaussian filter, both end treatments.
        for (code, ends) in [
            (ASPERITY_FILTER_ENDS_DISCARD, FilterEnds::Discard),
            (ASPERITY_FILTER_ENDS_KEEP, FilterEnds::Keep),
        ] {
            let (mut rough, mut line) = (vec![f64::NAN; n], vec![f64::NAN; n]);
            let (mut n_out, mut first) = (0usize, 0usize);
            ok(asperity_profile_gaussian_filter(
                n,
                z.as_ptr(),
                dx,
                80e-6,
                code,
                rough.as_mut_ptr(),
                line.as_mut_ptr(),
                &mut n_out,
                &mut first,
            ));
            let f = gaussian_filter(&Profile::new(dx, z.clone()).unwrap(), 80e-6, ends).unwrap();
            assert_eq!(n_out, f.roughness.len());
            assert_eq!(first, f.first_index);
            assert_eq!(&rough[..n_out], f.roughness.heights());
            assert_eq!(&line[..n_out], f.mean_line.heights());
            assert!(
                rough[n_out..].iter().all(|v| v.is_nan()),
                "wrote past n_out"
            );
        }

        // PSD, both windows: n/2 + 1 values, odd and even n.
        for m in [n, n - 1] {
            for (code, window) in [
                (ASPERITY_WINDOW_RECTANGULAR, Window::Rectangular),
                (ASPERITY_WINDOW_HANN, Window::Hann),
            ] {
                let n_q = m / 2 + 1;
                let (mut q, mut g) = (vec![0.0; n_q], vec![0.0; n_q]);
                ok(asperity_profile_psd(
                    m,
                    z.as_ptr(),
                    dx,
                    code,
                    n_q,
                    q.as_mut_ptr(),
                    g.as_mut_ptr(),
                ));
                let p = psd_windowed(&z[..m], dx, window).unwrap();
                assert_eq!((q, g), (p.q, p.c));
            }
        }
        // q may be NULL.
        let mut g = vec![0.0; n / 2 + 1];
        ok(asperity_profile_psd(
            n,
            z.as_ptr(),
            dx,
            ASPERITY_WINDOW_RECTANGULAR,
            n / 2 + 1,
            null_mut(),
            g.as_mut_ptr(),
        ));

        // Hurst fit: default and explicit band.
        let mut f = AsperityHurstFit::default();
        ok(asperity_profile_hurst_fit(
            n,
            z.as_ptr(),
            dx,
            0.0,
            0.0,
            &mut f,
        ));
        let h = hurst_fit(&z, dx, None).unwrap();
        assert_eq!(
            (f.hurst, f.r_squared, f.bins),
            (h.hurst, h.r_squared, h.bins)
        );
        ok(asperity_profile_hurst_fit(
            n,
            z.as_ptr(),
            dx,
            2e4,
            5e5,
            &mut f,
        ));
        let h = hurst_fit(&z, dx, Some((2e4, 5e5))).unwrap();
        assert_eq!(
            (f.hurst, f.prefactor, f.q_min, f.q_max),
            (h.hurst, h.prefactor, h.q_min, h.q_max)
        );
        // The ordinates fitted lie in the band given.
        assert!(f.q_min >= 2e4 && f.q_max <= 5e5, "{f:?}");

        // Peaks.
        let mut s = AsperityPeakStatistics::default();
        ok(asperity_profile_peak_statistics(n, z.as_ptr(), dx, &mut s));
        let p = Profile::new(dx, z.clone()).unwrap();
        let want = PeakStatistics::of_peaks(&p.peaks().unwrap(), p.length());
        assert_eq!(s.count, want.count);
        assert_eq!(
            (s.density, s.mean_height, s.height_std, s.mean_curvature),
            (
                want.density,
                want.mean_height,
                want.height_std,
                want.mean_curvature
            )
        );

        // Material-ratio curve: Rmr from 0 to 1, levels from the highest peak
        // down to the deepest valley.
        let k = 11;
        let (mut ratio, mut level) = (vec![0.0; k], vec![0.0; k]);
        ok(asperity_material_ratio_curve(
            n,
            z.as_ptr(),
            k,
            ratio.as_mut_ptr(),
            level.as_mut_ptr(),
        ));
        let c = MaterialRatioCurve::new(&z).unwrap().curve(k);
        assert_eq!(ratio, c.iter().map(|p| p.0).collect::<Vec<_>>());
        assert_eq!(level, c.iter().map(|p| p.1).collect::<Vec<_>>());
        assert_eq!((ratio[0], ratio[k - 1]), (0.0, 1.0));
        assert!(level.windows(2).all(|w| w[1] <= w[0]));
        ok(asperity_material_ratio_curve(
            n,
            z.as_ptr(),
            k,
            null_mut(),
            level.as_mut_ptr(),
        ));
    }
}

#[test]
fn generators_equal_the_rust_api() {
    let (n, dx) = (2048, 1e-7);
    unsafe {
        // Self-affine, with roll-off and cut-off: seeded, Rq matched.
        let mut z = vec![0.0; n];
        ok(asperity_generate_self_affine(
            0.6,
            2e-7,
            n as f64 * dx / 8.0,
            10.0 * dx,
            dx,
            11,
            n,
            z.as_mut_ptr(),
        ));
        let p = SelfAffine::new(0.6, 2e-7)
            .unwrap()
            .with_roll_off(n as f64 * dx / 8.0)
            .unwrap()
            .with_cutoff(10.0 * dx)
            .unwrap()
            .profile(n, dx, 11)
            .unwrap();
        assert_eq!(z, p.heights());
        let r = parameters(&z, dx, ASPERITY_FORM_NONE, 0.0, 0.0);
        assert!((r.rq / 2e-7 - 1.0).abs() < 1e-12, "Rq {}", r.rq);
        // Another seed, another profile; the same seed, the same profile.
        let (a, b) = (self_affine(n, dx, 1), self_affine(n, dx, 2));
        assert_ne!(a, b);
        assert_eq!(a, self_affine(n, dx, 1));

        // Weierstrass–Mandelbrot.
        ok(asperity_generate_weierstrass_mandelbrot(
            1.4,
            1.5,
            1e-6,
            dx,
            5,
            n,
            z.as_mut_ptr(),
        ));
        let p = WeierstrassMandelbrot::new(1.4, 1.5, 1e-6)
            .unwrap()
            .profile(n, dx, 5)
            .unwrap();
        assert_eq!(z, p.heights());

        // Cantor–Borodich, two and three descendants. The sample at x = 0
        // carries every generation: h (1 − β^levels)/(1 − β).
        for (m, alpha, beta) in [(2u32, 0.25, 0.8), (3u32, 0.2, 0.5)] {
            let (levels, h, length) = (6u32, 1e-6, 1e-3);
            let k = 4usize.pow(5).max(5usize.pow(5));
            let mut z = vec![0.0; k];
            ok(asperity_generate_cantor_borodich(
                m,
                alpha,
                beta,
                h,
                levels,
                length,
                k,
                z.as_mut_ptr(),
            ));
            let p = CantorBorodich::new(m as usize, alpha, beta, h, levels)
                .unwrap()
                .profile(length, k)
                .unwrap();
            assert_eq!(z, p.heights(), "m = {m}");
            let top = h * (1.0 - beta.powi(levels as i32)) / (1.0 - beta);
            assert!(
                (z[0] / top - 1.0).abs() < 1e-14,
                "m = {m}: {} vs {top}",
                z[0]
            );
            assert!(z.iter().all(|&v| (0.0..=top * (1.0 + 1e-14)).contains(&v)));
        }
    }
}

#[test]
fn profile_errors_name_the_argument() {
    let (z, dx) = sine(1e-6, 1e-4, 4, 50);
    let n = z.len();
    let mut r = AsperityRoughness::default();
    let mut w = vec![0.0; n];
    unsafe {
        let p = z.as_ptr();
        expect_error(
            asperity_roughness_parameters(n, null(), dx, 0, 0.0, 0.0, &mut r),
            ASPERITY_ERR_NULL_POINTER,
            "`heights`",
        );
        expect_error(
            asperity_roughness_parameters(n, p, dx, 0, 0.0, 0.0, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_roughness_parameters(0, p, dx, 0, 0.0, 0.0, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`heights.len()`",
        );
        expect_error(
            asperity_roughness_parameters(5, p, dx, 0, 0.0, 0.0, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            ">= 8 points",
        );
        expect_error(
            asperity_roughness_parameters(n, p, dx, 4, 0.0, 0.0, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`form`",
        );
        expect_error(
            asperity_roughness_parameters(n, p, 0.0, 0, 0.0, 0.0, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`dx`",
        );
        expect_error(
            asperity_roughness_parameters(n, p, f64::NAN, 2, 0.0, 0.0, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`dx`",
        );
        expect_error(
            asperity_roughness_parameters(n, p, dx, 0, -1e-4, 0.0, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`cutoff`",
        );
        expect_error(
            asperity_roughness_parameters(n, p, dx, 0, f64::INFINITY, 0.0, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`cutoff`",
        );
        expect_error(
            asperity_roughness_parameters(n, p, dx, 0, 0.0, 1.0, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`sampling_length`",
        );
        let mut bad = z.clone();
        bad[17] = f64::NAN;
        for form in [ASPERITY_FORM_NONE, ASPERITY_FORM_LINEAR] {
            expect_error(
                asperity_roughness_parameters(n, bad.as_ptr(), dx, form, 0.0, 0.0, &mut r),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "`heights`",
            );
            expect_error(
                asperity_profile_remove_form(n, bad.as_ptr(), form, w.as_mut_ptr()),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "`heights`",
            );
        }
        bad[17] = f64::INFINITY;
        expect_error(
            asperity_profile_peak_statistics(
                n,
                bad.as_ptr(),
                dx,
                &mut AsperityPeakStatistics::default(),
            ),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`heights`",
        );
        let flat = vec![2e-6; 64];
        expect_error(
            asperity_roughness_parameters(64, flat.as_ptr(), dx, 0, 0.0, 0.0, &mut r),
            ASPERITY_ERR_OUT_OF_DOMAIN,
            "constant heights",
        );
        // The failed call did not touch `out`.
        assert_eq!(r, AsperityRoughness::default());

        expect_error(
            asperity_profile_remove_form(n, p, ASPERITY_FORM_LINEAR, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_profile_remove_form(n, p, -1, w.as_mut_ptr()),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`form`",
        );
        expect_error(
            asperity_profile_remove_form(0, p, ASPERITY_FORM_NONE, w.as_mut_ptr()),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`heights.len()`",
        );

        let mut k = 0usize;
        let mut rough = vec![0.0; n];
        expect_error(
            asperity_profile_gaussian_filter(
                n,
                p,
                dx,
                5e-5,
                2,
                rough.as_mut_ptr(),
                null_mut(),
                &mut k,
                null_mut(),
            ),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`ends`",
        );
        expect_error(
            asperity_profile_gaussian_filter(
                n,
                p,
                dx,
                5e-5,
                0,
                null_mut(),
                null_mut(),
                &mut k,
                null_mut(),
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`roughness`",
        );
        expect_error(
            asperity_profile_gaussian_filter(
                n,
                p,
                dx,
                5e-5,
                0,
                rough.as_mut_ptr(),
                null_mut(),
                null_mut(),
                null_mut(),
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`n_out`",
        );
        expect_error(
            asperity_profile_gaussian_filter(
                n,
                p,
                dx,
                1.0,
                0,
                rough.as_mut_ptr(),
                null_mut(),
                &mut k,
                null_mut(),
            ),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`cutoff`",
        );

        // PSD length rule.
        let mut g = vec![0.0; n];
        for n_q in [0, n / 2, n / 2 + 2, n] {
            expect_error(
                asperity_profile_psd(n, p, dx, 0, n_q, null_mut(), g.as_mut_ptr()),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "`n_q`",
            );
        }
        expect_error(
            asperity_profile_psd(n, p, dx, 2, n / 2 + 1, null_mut(), g.as_mut_ptr()),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`window`",
        );
        expect_error(
            asperity_profile_psd(n, p, dx, 0, n / 2 + 1, null_mut(), null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`g`",
        );
        expect_error(
            asperity_profile_psd(3, p, dx, 0, 2, null_mut(), g.as_mut_ptr()),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`heights.len()`",
        );

        let mut f = AsperityHurstFit::default();
        expect_error(
            asperity_profile_hurst_fit(n, p, dx, 0.0, 1e5, &mut f),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`q_min`",
        );
        expect_error(
            asperity_profile_hurst_fit(n, null(), dx, 0.0, 0.0, &mut f),
            ASPERITY_ERR_NULL_POINTER,
            "`heights`",
        );

        let mut level = vec![0.0; 4];
        for bad_points in [0usize, 1] {
            expect_error(
                asperity_material_ratio_curve(n, p, bad_points, null_mut(), level.as_mut_ptr()),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "`n_points`",
            );
        }
        expect_error(
            asperity_material_ratio_curve(n, p, 4, null_mut(), null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`level`",
        );
        expect_error(
            asperity_material_ratio_curve(0, p, 4, null_mut(), level.as_mut_ptr()),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`heights.len()`",
        );
    }
}

#[test]
fn generator_errors_name_the_argument() {
    let mut z = vec![0.0; 64];
    let o = z.as_mut_ptr();
    unsafe {
        expect_error(
            asperity_generate_self_affine(0.5, 1e-6, 0.0, 0.0, 1e-6, 1, 64, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`heights`",
        );
        for n in [0, 3] {
            expect_error(
                asperity_generate_self_affine(0.5, 1e-6, 0.0, 0.0, 1e-6, 1, n, o),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "`n`",
            );
        }
        expect_error(
            asperity_generate_self_affine(1.5, 1e-6, 0.0, 0.0, 1e-6, 1, 64, o),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`hurst`",
        );
        expect_error(
            asperity_generate_self_affine(0.5, f64::NAN, 0.0, 0.0, 1e-6, 1, 64, o),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`rq`",
        );
        expect_error(
            asperity_generate_self_affine(0.5, 1e-6, -1.0, 0.0, 1e-6, 1, 64, o),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`roll_off_wavelength`",
        );
        expect_error(
            asperity_generate_self_affine(0.5, 1e-6, 1e-5, 2e-5, 1e-6, 1, 64, o),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`cutoff_wavelength`",
        );
        expect_error(
            asperity_generate_self_affine(0.5, 1e-6, 0.0, 0.0, 0.0, 1, 64, o),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`dx`",
        );
        expect_error(
            asperity_generate_weierstrass_mandelbrot(2.0, 1.5, 1e-6, 1e-6, 1, 64, o),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`fractal_dimension`",
        );
        expect_error(
            asperity_generate_weierstrass_mandelbrot(1.5, 1.0, 1e-6, 1e-6, 1, 64, o),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`gamma`",
        );
        expect_error(
            asperity_generate_weierstrass_mandelbrot(1.5, 1.5, 1e-6, 1e-6, 1, 2, o),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`n`",
        );
        expect_error(
            asperity_generate_weierstrass_mandelbrot(1.5, 1.5, 1e-6, 1e-6, 1, 64, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`heights`",
        );
        expect_error(
            asperity_generate_cantor_borodich(1, 0.25, 0.8, 1e-6, 5, 1e-3, 64, o),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`descendants`",
        );
        expect_error(
            asperity_generate_cantor_borodich(3, 0.4, 0.8, 1e-6, 5, 1e-3, 64, o),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`alpha`",
        );
        expect_error(
            asperity_generate_cantor_borodich(2, 0.25, 0.4, 1e-6, 5, 1e-3, 64, o),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`beta`",
        );
        expect_error(
            asperity_generate_cantor_borodich(2, 0.25, 0.8, 1e-6, 0, 1e-3, 64, o),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`levels`",
        );
        expect_error(
            asperity_generate_cantor_borodich(2, 0.25, 0.8, 1e-6, 5, 1e-3, 1, o),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`n`",
        );
    }
    assert!(z.iter().all(|&v| v == 0.0), "a failed call wrote heights");
}

// --- Greenwood–Williamson ------------------------------------------------------

const E_STAR: f64 = 1e11;

fn gw_params(distribution: i32) -> AsperityGwParams {
    AsperityGwParams {
        distribution,
        reserved: 0,
        summit_count: 1e4,
        radius: 50e-6,
        sigma: 1e-6,
        e_star: E_STAR,
    }
}

#[test]
fn greenwood_williamson_equals_the_rust_api() {
    for (code, heights) in [
        (
            ASPERITY_HEIGHTS_GAUSSIAN,
            HeightDistribution::gaussian(1e-6).unwrap(),
        ),
        (
            ASPERITY_HEIGHTS_EXPONENTIAL,
            HeightDistribution::exponential(1e-6).unwrap(),
        ),
    ] {
        let p = gw_params(code);
        let gw = GreenwoodWilliamson::new(1e4, 50e-6, E_STAR, heights).unwrap();
        let d: Vec<f64> = (0..9).map(|i| (-1.0 + 0.5 * i as f64) * 1e-6).collect();
        let n = d.len();
        let (mut load, mut area, mut count, mut k) =
            (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        unsafe {
            ok(asperity_gw_eval_batch(
                &p,
                n,
                d.as_ptr(),
                load.as_mut_ptr(),
                area.as_mut_ptr(),
                count.as_mut_ptr(),
                k.as_mut_ptr(),
            ));
            for i in 0..n {
                let mut r = AsperityGwResponse::default();
                ok(asperity_gw_eval(&p, d[i], &mut r));
                let want = gw.response(d[i]).unwrap();
                assert_eq!(
                    (r.load, r.area, r.contacts, r.stiffness),
                    (
                        want.load,
                        want.area,
                        want.contacts,
                        gw.stiffness(d[i]).unwrap()
                    )
                );
                assert_eq!(
                    (load[i], area[i], count[i], k[i]),
                    (r.load, r.area, r.contacts, r.stiffness)
                );
                if i > 0 {
                    assert!(
                        load[i] < load[i - 1] && area[i] < area[i - 1],
                        "code {code}"
                    );
                }
            }
            // In place: the separations are overwritten by the loads.
            let mut inout = d.clone();
            ok(asperity_gw_eval_batch(
                &p,
                n,
                inout.as_ptr(),
                inout.as_mut_ptr(),
                null_mut(),
                null_mut(),
                null_mut(),
            ));
            assert_eq!(inout, load);
            // n = 0 needs no arrays.
            ok(asperity_gw_eval_batch(
                &p,
                0,
                null(),
                null_mut(),
                null_mut(),
                null_mut(),
                null_mut(),
            ));

            let mut s = AsperitySeparation::default();
            ok(asperity_gw_separation_at_load(&p, load[3], &mut s));
            let want = gw.separation_at_load(load[3]).unwrap();
            assert_eq!(
                (s.separation, s.iterations),
                (want.separation, want.iterations)
            );
            assert!((s.separation - d[3]).abs() < 1e-9 * 1e-6, "code {code}");

            let mut psi = 0.0;
            ok(asperity_gw_plasticity_index(&p, 2e9, &mut psi));
            assert_eq!(psi, gw.plasticity_index(2e9).unwrap());
            let mut psi2 = 0.0;
            ok(asperity_plasticity_index(
                E_STAR, 2e9, 1e-6, 50e-6, &mut psi2,
            ));
            assert_eq!(psi, psi2);
            assert!((psi - 50.0 * (1.0 / 50.0f64).sqrt()).abs() < 1e-12);
        }
    }
    let mut regime = -1;
    for (psi, want) in [
        (0.3, ASPERITY_REGIME_ELASTIC),
        (0.8, ASPERITY_REGIME_TRANSITIONAL),
        (7.0, ASPERITY_REGIME_PLASTIC),
    ] {
        ok(unsafe { asperity_deformation_regime(psi, &mut regime) });
        assert_eq!(regime, want);
    }
}

#[test]
fn empirical_greenwood_williamson_equals_the_rust_api() {
    let heights: Vec<f64> = (0..200)
        .map(|i| 1e-6 * ((i * 37 % 101) as f64 / 50.0 - 1.0))
        .collect();
    let radii: Vec<f64> = (0..200).map(|i| 40e-6 + 1e-7 * i as f64).collect();
    for with_radii in [false, true] {
        let e = if with_radii {
            EmpiricalHeights::with_radii(heights.clone(), radii.clone()).unwrap()
        } else {
            EmpiricalHeights::new(heights.clone()).unwrap()
        };
        let gw =
            GreenwoodWilliamson::new(5e3, 50e-6, E_STAR, HeightDistribution::Empirical(e)).unwrap();
        let mut h: *mut AsperityGwEmpirical = null_mut();
        unsafe {
            ok(asperity_gw_empirical_new(
                5e3,
                50e-6,
                E_STAR,
                heights.len(),
                heights.as_ptr(),
                if with_radii { radii.as_ptr() } else { null() },
                &mut h,
            ));
            assert!(!h.is_null());
            let d = [-0.5e-6, 0.0, 0.3e-6, 0.9e-6, 2e-6];
            let mut load = [0.0; 5];
            ok(asperity_gw_empirical_eval_batch(
                h,
                5,
                d.as_ptr(),
                load.as_mut_ptr(),
                null_mut(),
                null_mut(),
                null_mut(),
            ));
            for (i, &di) in d.iter().enumerate() {
                let mut r = AsperityGwResponse::default();
                ok(asperity_gw_empirical_eval(h, di, &mut r));
                let want = gw.response(di).unwrap();
                assert_eq!(
                    (r.load, r.area, r.contacts),
                    (want.load, want.area, want.contacts)
                );
                assert_eq!(r.stiffness, gw.stiffness(di).unwrap());
                assert_eq!(load[i], r.load);
            }
            assert_eq!(load[4], 0.0, "above the highest summit");
            let mut s = AsperitySeparation::default();
            ok(asperity_gw_empirical_separation_at_load(h, load[1], &mut s));
            assert_eq!(
                s.separation,
                gw.separation_at_load(load[1]).unwrap().separation
            );
            let mut psi = 0.0;
            ok(asperity_gw_empirical_plasticity_index(h, 2e9, &mut psi));
            assert_eq!(psi, gw.plasticity_index(2e9).unwrap());
            asperity_gw_empirical_free(h);
        }
    }
    unsafe { asperity_gw_empirical_free(null_mut()) };
}

#[test]
fn greenwood_williamson_errors_name_the_argument() {
    let p = gw_params(ASPERITY_HEIGHTS_GAUSSIAN);
    let mut r = AsperityGwResponse::default();
    let mut s = AsperitySeparation::default();
    let mut psi = 0.0;
    unsafe {
        expect_error(
            asperity_gw_eval(null(), 0.0, &mut r),
            ASPERITY_ERR_NULL_POINTER,
            "`gw`",
        );
        expect_error(
            asperity_gw_eval(&p, 0.0, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_gw_eval(&p, f64::NAN, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`separation`",
        );
        for bad in [0, 3, -1] {
            expect_error(
                asperity_gw_eval(&gw_params(bad), 0.0, &mut r),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "`gw.distribution`",
            );
        }
        expect_error(
            asperity_gw_eval(&AsperityGwParams::default(), 0.0, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`gw.distribution`",
        );
        for (field, q) in [
            ("`sigma`", AsperityGwParams { sigma: -1e-6, ..p }),
            ("`radius`", AsperityGwParams { radius: 0.0, ..p }),
            (
                "`summit_count`",
                AsperityGwParams {
                    summit_count: f64::INFINITY,
                    ..p
                },
            ),
            (
                "`e_star`",
                AsperityGwParams {
                    e_star: f64::NAN,
                    ..p
                },
            ),
        ] {
            expect_error(
                asperity_gw_eval(&q, 0.0, &mut r),
                ASPERITY_ERR_INVALID_ARGUMENT,
                field,
            );
            expect_error(
                asperity_gw_eval_batch(
                    &q,
                    0,
                    null(),
                    null_mut(),
                    null_mut(),
                    null_mut(),
                    null_mut(),
                ),
                ASPERITY_ERR_INVALID_ARGUMENT,
                field,
            );
        }
        // A batch: NaN at element 2, earlier elements written, later untouched.
        let d = [0.0, 1e-6, f64::NAN, 2e-6];
        let mut load = [-1.0; 4];
        let mut k = [-1.0; 4];
        expect_error(
            asperity_gw_eval_batch(
                &p,
                4,
                d.as_ptr(),
                load.as_mut_ptr(),
                null_mut(),
                null_mut(),
                k.as_mut_ptr(),
            ),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "element 2",
        );
        assert!(last_message().contains("`separation`"));
        assert!(load[0] > 0.0 && load[1] > 0.0 && k[1] > 0.0);
        assert_eq!((load[2], load[3], k[2]), (-1.0, -1.0, -1.0));
        expect_error(
            asperity_gw_eval_batch(
                &p,
                4,
                null(),
                load.as_mut_ptr(),
                null_mut(),
                null_mut(),
                null_mut(),
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`separation`",
        );
        expect_error(
            asperity_gw_eval_batch(
                &p,
                4,
                d.as_ptr(),
                null_mut(),
                null_mut(),
                null_mut(),
                null_mut(),
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`load`",
        );
        for bad in [0.0, -1.0, f64::NAN] {
            expect_error(
                asperity_gw_separation_at_load(&p, bad, &mut s),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "`load`",
            );
        }
        expect_error(
            asperity_gw_plasticity_index(&p, 0.0, &mut psi),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`hardness`",
        );
        expect_error(
            asperity_gw_plasticity_index(&p, 1e9, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`psi`",
        );
        expect_error(
            asperity_plasticity_index(E_STAR, 1e9, -1.0, 1e-5, &mut psi),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`sigma`",
        );
        let mut regime = 0;
        expect_error(
            asperity_deformation_regime(-0.1, &mut regime),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`plasticity_index`",
        );

        // Empirical: arrays and handle.
        let heights = [1e-6, 0.0, -1e-6];
        let mut h: *mut AsperityGwEmpirical = std::ptr::NonNull::dangling().as_ptr();
        expect_error(
            asperity_gw_empirical_new(10.0, 1e-5, E_STAR, 3, null(), null(), &mut h),
            ASPERITY_ERR_NULL_POINTER,
            "`heights`",
        );
        assert!(h.is_null(), "*out is NULL after a failure");
        expect_error(
            asperity_gw_empirical_new(10.0, 1e-5, E_STAR, 0, heights.as_ptr(), null(), &mut h),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`heights`",
        );
        let radii = [1e-5, -1e-5, 1e-5];
        expect_error(
            asperity_gw_empirical_new(
                10.0,
                1e-5,
                E_STAR,
                3,
                heights.as_ptr(),
                radii.as_ptr(),
                &mut h,
            ),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`radii`",
        );
        let nan_heights = [1e-6, f64::NAN, 0.0];
        expect_error(
            asperity_gw_empirical_new(10.0, 1e-5, E_STAR, 3, nan_heights.as_ptr(), null(), &mut h),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`heights`",
        );
        expect_error(
            asperity_gw_empirical_new(10.0, 1e-5, E_STAR, 3, heights.as_ptr(), null(), null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_gw_empirical_eval(null(), 0.0, &mut r),
            ASPERITY_ERR_NULL_POINTER,
            "`gw`",
        );
        ok(asperity_gw_empirical_new(
            10.0,
            1e-5,
            E_STAR,
            3,
            heights.as_ptr(),
            null(),
            &mut h,
        ));
        expect_error(
            asperity_gw_empirical_eval_batch(
                h,
                3,
                d.as_ptr(),
                load.as_mut_ptr(),
                null_mut(),
                null_mut(),
                null_mut(),
            ),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "element 2",
        );
        asperity_gw_empirical_free(h);
    }
}

// --- Zhuravlev -----------------------------------------------------------------

const ZH: AsperityZhuravlev = AsperityZhuravlev {
    cap_radius: 100e-6,
    effective_radius: 0.0,
    e_star: 5e10,
    summit_count: 1e3,
};

unsafe extern "C" fn linear_density(xi: f64, data: *mut c_void) -> f64 {
    *(data as *const f64) * xi
}

unsafe extern "C" fn nan_density(_xi: f64, _data: *mut c_void) -> f64 {
    f64::NAN
}

#[test]
fn zhuravlev_equals_the_rust_api() {
    let z = Zhuravlev::new(100e-6, 5e10, 1e3).unwrap();
    let (a1, a2) = (2e12, 3e12);
    unsafe {
        let mut r = AsperityZhuravlevResponse::default();
        ok(asperity_zhuravlev_linear(&ZH, a1, a2, 2e-6, &mut r));
        let want = z.linear(a1, a2, 2e-6).unwrap();
        assert_eq!(
            (r.load, r.area, r.contacts),
            (want.load, want.area, want.contacts)
        );
        // P ∝ x^{11/2}, S ∝ x⁵.
        let mut r2 = AsperityZhuravlevResponse::default();
        ok(asperity_zhuravlev_linear(&ZH, a1, a2, 4e-6, &mut r2));
        assert!((r2.load / r.load / 2f64.powf(5.5) - 1.0).abs() < 1e-12);
        assert!((r2.area / r.area / 32.0 - 1.0).abs() < 1e-12);

        let mut x = 0.0;
        ok(asperity_zhuravlev_approach_at_load_linear(
            &ZH, a1, a2, r.load, &mut x,
        ));
        assert!((x / 2e-6 - 1.0).abs() < 1e-12, "{x}");

        let mut f = AsperityZhuravlevFriction::default();
        ok(asperity_zhuravlev_friction_linear(
            &ZH, a1, a2, r.load, 1e8, &mut f,
        ));
        let want = z.friction_linear(a1, a2, r.load, 1e8).unwrap();
        assert_eq!(
            (f.approach, f.area, f.friction_force, f.coefficient),
            (
                want.approach,
                want.area,
                want.friction_force,
                want.coefficient
            )
        );

        // The same pair given by its effective radius.
        let eff = AsperityZhuravlev {
            cap_radius: 0.0,
            effective_radius: 50e-6,
            ..ZH
        };
        let mut r3 = AsperityZhuravlevResponse::default();
        ok(asperity_zhuravlev_linear(&eff, a1, a2, 2e-6, &mut r3));
        assert_eq!(r3, r);

        // Quadrature with linear callbacks: the closed form, and the Rust
        // API with the same densities.
        let (mut d1, mut d2) = (a1, a2);
        let mut q = AsperityZhuravlevResponse::default();
        ok(asperity_zhuravlev_eval(
            &ZH,
            2e-6,
            Some(linear_density),
            (&mut d1 as *mut f64).cast(),
            Some(linear_density),
            (&mut d2 as *mut f64).cast(),
            24,
            &mut q,
        ));
        let want = z.response(2e-6, |s| a1 * s, |s| a2 * s, 24).unwrap();
        assert_eq!(q.load, want.load);
        assert!(
            (q.load / r.load - 1.0).abs() < 1e-9,
            "{} vs {}",
            q.load,
            r.load
        );
        assert!((q.area / r.area - 1.0).abs() < 1e-9);
        assert!((q.contacts / r.contacts - 1.0).abs() < 1e-9);
    }
}

#[test]
fn zhuravlev_errors_name_the_argument() {
    let mut r = AsperityZhuravlevResponse::default();
    let mut a = 1e12;
    let data: *mut c_void = (&mut a as *mut f64).cast();
    unsafe {
        expect_error(
            asperity_zhuravlev_linear(null(), 1e12, 1e12, 1e-6, &mut r),
            ASPERITY_ERR_NULL_POINTER,
            "`model`",
        );
        expect_error(
            asperity_zhuravlev_linear(&ZH, 1e12, 1e12, 1e-6, null_mut()),
            ASPERITY_ERR_NULL_POINTER,
            "`out`",
        );
        expect_error(
            asperity_zhuravlev_linear(&ZH, -1e12, 1e12, 1e-6, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`alpha1`",
        );
        expect_error(
            asperity_zhuravlev_linear(&ZH, 1e12, 1e12, f64::NAN, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`approach`",
        );
        let both = AsperityZhuravlev {
            effective_radius: 50e-6,
            ..ZH
        };
        expect_error(
            asperity_zhuravlev_linear(&both, 1e12, 1e12, 1e-6, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`effective_radius`",
        );
        expect_error(
            asperity_zhuravlev_linear(&AsperityZhuravlev::default(), 1e12, 1e12, 1e-6, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`cap_radius`",
        );
        let mut x = 0.0;
        expect_error(
            asperity_zhuravlev_approach_at_load_linear(&ZH, 1e12, 1e12, -1.0, &mut x),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`load`",
        );
        let mut f = AsperityZhuravlevFriction::default();
        expect_error(
            asperity_zhuravlev_friction_linear(&ZH, 1e12, 1e12, 1.0, -1.0, &mut f),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`shear_strength`",
        );
        expect_error(
            asperity_zhuravlev_eval(
                &ZH,
                1e-6,
                None,
                data,
                Some(linear_density),
                data,
                24,
                &mut r,
            ),
            ASPERITY_ERR_NULL_POINTER,
            "`n1`",
        );
        expect_error(
            asperity_zhuravlev_eval(
                &ZH,
                1e-6,
                Some(linear_density),
                data,
                Some(nan_density),
                null_mut(),
                24,
                &mut r,
            ),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`n2`",
        );
        expect_error(
            asperity_zhuravlev_eval(
                &ZH,
                1e-6,
                Some(linear_density),
                data,
                Some(linear_density),
                data,
                3,
                &mut r,
            ),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "`order`",
        );
    }
}

/// At the ends of `f64` the Greenwood–Williamson evaluation either answers
/// with finite numbers or returns an error: never `ASPERITY_OK` with a NaN
/// or infinite output (RELIABILITY.md open point, session 8: a Gaussian
/// surface with σ = 2.2e-308 m and E* near f64::MAX).
#[test]
fn gw_eval_never_returns_ok_with_a_non_finite_output() {
    let vals = [
        1e-308, 1e-300, 1e-200, 1e-100, 1e-10, 1e-6, 1.0, 1e6, 1e100, 1e200, 1e300, 1.79e308,
    ];
    let (mut ok, mut total) = (0usize, 0usize);
    for distribution in [ASPERITY_HEIGHTS_GAUSSIAN, ASPERITY_HEIGHTS_EXPONENTIAL] {
        for &summit_count in &vals {
            for &radius in &vals {
                for &sigma in &[2.2e-308, 1e-300, 1e-100, 1e-6, 1.0, 1e100, 1e300] {
                    for &e_star in &[1e-300, 1.0, 1e9, 1e300, 1.79e308] {
                        let p = AsperityGwParams {
                            distribution,
                            reserved: 0,
                            summit_count,
                            radius,
                            sigma,
                            e_star,
                        };
                        for d in [
                            25.7,
                            0.0,
                            -1e-307,
                            1e-308,
                            -25.7,
                            1e300,
                            -1e300,
                            3.0 * sigma,
                            -3.0 * sigma,
                        ] {
                            let mut out = AsperityGwResponse::default();
                            let s = unsafe { asperity_gw_eval(&p, d, &mut out) };
                            total += 1;
                            if s == ASPERITY_OK {
                                ok += 1;
                                assert!(
                                    [out.load, out.area, out.contacts, out.stiffness]
                                        .iter()
                                        .all(|v| v.is_finite()),
                                    "{p:?} at d = {d:e}: {out:?}"
                                );
                            }
                        }
                    }
                }
            }
        }
    }
    // Both outcomes occur on this grid.
    assert!(ok > 1000 && ok < total, "{ok} of {total} answered");
}
