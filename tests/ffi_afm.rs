//! The AFM C ABI (`src/ffi/afm.rs`) called from Rust: a synthetic JKR curve
//! (known E*, w) through `asperity_afm_analyze`, equality with the Rust API,
//! deflection input, the flag names, the measured SiN curve when present,
//! and the error paths.

mod common;
use common::c_errors::last_message;

use asperity::afm::{analyze, AfmCurve, AfmOptions};
use asperity::contact::{Control, Jkr, NormalContact};
use asperity::ffi::afm::*;
use asperity::ffi::*;
use std::ffi::CStr;
use std::path::PathBuf;
use std::ptr::{null, null_mut};

/// A JKR retract/approach curve: R = 50 nm, E* = 0.5 GPa, w = 0.5 J/m²,
/// k = 40 N/m, position decreasing towards the sample, tilted baseline and
/// deterministic noise of 0.2 nN.
fn jkr_curve() -> (Vec<f64>, Vec<f64>, usize) {
    let law = Jkr::new(50e-9, 0.5e9, 0.5).unwrap();
    let pc = law.pull_off_force(Control::Load).unwrap();
    let k = 40.0;
    let branch = |f: f64| {
        let f = if f <= pc { pc * (1.0 - 1e-9) } else { f };
        1e-6 + law.eval_at_load(f).unwrap().delta + f / k
    };
    let (mut u, mut f) = (Vec::new(), Vec::new());
    let u0 = branch(0.0);
    for i in 0..400 {
        u.push(u0 - 200e-9 + 200e-9 * i as f64 / 400.0);
        f.push(0.0);
    }
    for i in 0..150 {
        let fi = 200e-9 * i as f64 / 149.0;
        u.push(branch(fi));
        f.push(fi);
    }
    let rs = u.len();
    for i in 0..300 {
        let fi = 200e-9 + (pc - 200e-9) * i as f64 / 299.0;
        u.push(branch(fi));
        f.push(fi);
    }
    let upo = *u.last().unwrap();
    for i in 1..=400 {
        u.push(upo - 200e-9 * i as f64 / 400.0);
        f.push(0.0);
    }
    let z: Vec<f64> = u.iter().map(|u| -u).collect();
    let raw = z
        .iter()
        .zip(&f)
        .enumerate()
        .map(|(i, (z, f))| {
            let x = ((i as f64 * 12.9898).sin() * 43758.5453).fract();
            f + 0.2e-9 * (2.0 * x - 1.0) * 3f64.sqrt() - 20e-9 - 0.01 * z
        })
        .collect();
    (z, raw, rs)
}

/// `asperity_afm_analyze` of the JKR curve's forces (k = 40 N/m, R = 50
/// nm) with `model`; asserts success.
fn analyze_jkr_force(z: &[f64], f: &[f64], rs: usize, model: i32) -> AsperityAfmResult {
    let mut r = AsperityAfmResult::default();
    let st = unsafe {
        asperity_afm_analyze(
            z.len(),
            z.as_ptr(),
            f.as_ptr(),
            ASPERITY_AFM_INPUT_FORCE,
            rs,
            40.0,
            50e-9,
            model,
            &mut r,
        )
    };
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    r
}

#[test]
fn jkr_curve_through_the_c_abi() {
    let (z, f, rs) = jkr_curve();
    let r = analyze_jkr_force(&z, &f, rs, ASPERITY_AFM_MODEL_AUTO);
    assert_eq!(r.n_fits, 4);
    assert_eq!(r.recommended_model, ASPERITY_AFM_MODEL_JKR);
    let fit = r.fits[r.recommended_index as usize];
    assert_eq!(fit.model, ASPERITY_AFM_MODEL_JKR);
    // Within three standard errors of the truth.
    assert!(
        (fit.e_star - 0.5e9).abs() <= 3.0 * fit.e_star_stderr,
        "{fit:?}"
    );
    assert!((fit.work_of_adhesion - 0.5).abs() <= 3.0 * fit.work_of_adhesion_stderr);
    assert!(fit.e_star_stderr > 0.0 && fit.e_star_stderr < 0.1 * fit.e_star);
    // JKR pull-off −(3/2)πwR = −117.8 nN.
    let pc = -1.5 * std::f64::consts::PI * 0.5 * 50e-9;
    assert!((r.pull_off_force - pc).abs() < 1e-9, "{}", r.pull_off_force);
    assert_eq!(r.direction, -1.0);
    assert_eq!(r.radius_known, 1);
    assert_eq!(r.flags & ASPERITY_AFM_FLAG_RADIUS_UNKNOWN, 0);
    assert_ne!(r.flags & ASPERITY_AFM_FLAG_NO_JUMP_IN, 0);

    // The same numbers as the Rust API.
    let c = AfmCurve::new(z.clone(), f.clone(), Some(rs), Some(40.0)).unwrap();
    let a = analyze(
        &c,
        &AfmOptions {
            tip_radius: Some(50e-9),
            ..AfmOptions::default()
        },
    )
    .unwrap();
    assert_eq!(a.pull_off_force, r.pull_off_force);
    assert_eq!(a.adhesion_energy, r.adhesion_energy);
    assert_eq!(a.baseline.slope, r.baseline_slope);
    assert_eq!(a.flag_mask(), r.flags);
    assert_eq!(a.recommended().unwrap().e_star, Some(fit.e_star));

    // Deflection input, one model, unknown radius.
    let d: Vec<f64> = f.iter().map(|f| f / 40.0).collect();
    let mut r2 = AsperityAfmResult::default();
    let st = unsafe {
        asperity_afm_analyze(
            z.len(),
            z.as_ptr(),
            d.as_ptr(),
            ASPERITY_AFM_INPUT_DEFLECTION,
            0,
            40.0,
            0.0,
            ASPERITY_AFM_MODEL_JKR,
            &mut r2,
        )
    };
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    assert_eq!(r2.n_fits, 1);
    assert_eq!(r2.radius_known, 0);
    assert_eq!(r2.fits[0].e_star, 0.0);
    assert_ne!(r2.flags & ASPERITY_AFM_FLAG_RADIUS_UNKNOWN, 0);
    let k_sqrt_r = 0.5e9 * 50e-9f64.sqrt();
    let f0 = r2.fits[0];
    assert!(
        (f0.e_star_times_sqrt_radius - k_sqrt_r).abs() <= 3.0 * f0.e_star_times_sqrt_radius_stderr
    );
    assert!((r2.pull_off_force - r.pull_off_force).abs() < 1e-12);
}

#[test]
fn lennard_jones_model_code_through_the_c_abi() {
    // The JKR curve (μ ≈ 12) fitted with the Lennard-Jones sphere, code 5:
    // the same numbers as the Rust API, close to JKR's E*, w.
    let (z, f, rs) = jkr_curve();
    let r = analyze_jkr_force(&z, &f, rs, ASPERITY_AFM_MODEL_LJ);
    assert_eq!(r.n_fits, 1);
    assert_eq!(r.recommended_model, ASPERITY_AFM_MODEL_LJ);
    let fit = r.fits[0];
    assert_eq!(fit.model, ASPERITY_AFM_MODEL_LJ);
    assert!((fit.e_star / 0.5e9 - 1.0).abs() < 0.1, "E* {}", fit.e_star);
    assert!(
        (fit.work_of_adhesion / 0.5 - 1.0).abs() < 0.1,
        "w {}",
        fit.work_of_adhesion
    );
    assert!(fit.e_star_stderr > 0.0 && fit.tabor_parameter > 5.0);
    let curve = AfmCurve::new(z, f, Some(rs), Some(40.0)).unwrap();
    let a = analyze(
        &curve,
        &AfmOptions {
            tip_radius: Some(50e-9),
            models: vec![asperity::afm::AfmModel::LennardJones],
            ..AfmOptions::default()
        },
    )
    .unwrap();
    assert_eq!(a.fits[0].e_star, Some(fit.e_star));
    assert_eq!(a.fits[0].tabor_parameter, Some(fit.tabor_parameter));
}

#[test]
fn flag_names_match_the_bits() {
    let name = |b: u32| {
        unsafe { CStr::from_ptr(asperity_afm_flag_name(b)) }
            .to_str()
            .unwrap()
    };
    assert_eq!(name(0), "radius_unknown");
    assert_eq!(name(1), "no_jump_in");
    assert_eq!(
        1u32 << 7,
        ASPERITY_AFM_FLAG_MODEL_OUTSIDE_TABOR_RANGE,
        "{}",
        name(7)
    );
    assert_eq!(name(7), "model_outside_tabor_range");
    assert_eq!(name(8), "few_fit_points");
    assert!(asperity_afm_flag_name(9).is_null());
}

#[test]
fn errors_name_the_argument() {
    let (z, f, rs) = jkr_curve();
    let mut r = AsperityAfmResult::default();
    let call = |pos: *const f64,
                sig: *const f64,
                kind: i32,
                k: f64,
                rad: f64,
                m: i32,
                out: *mut AsperityAfmResult| unsafe {
        asperity_afm_analyze(z.len(), pos, sig, kind, rs, k, rad, m, out)
    };
    assert_eq!(
        call(null(), f.as_ptr(), 0, 40.0, 0.0, 0, &mut r),
        ASPERITY_ERR_NULL_POINTER
    );
    assert!(last_message().contains("position"));
    assert_eq!(
        call(z.as_ptr(), f.as_ptr(), 0, 40.0, 0.0, 0, null_mut()),
        ASPERITY_ERR_NULL_POINTER
    );
    assert_eq!(
        call(z.as_ptr(), f.as_ptr(), 0, 0.0, 0.0, 0, &mut r),
        ASPERITY_ERR_INVALID_ARGUMENT
    );
    assert!(last_message().contains("spring_constant"));
    assert_eq!(
        call(z.as_ptr(), f.as_ptr(), 0, 40.0, -1.0, 0, &mut r),
        ASPERITY_ERR_INVALID_ARGUMENT
    );
    assert!(last_message().contains("tip_radius"));
    assert_eq!(
        call(z.as_ptr(), f.as_ptr(), 0, 40.0, 0.0, 9, &mut r),
        ASPERITY_ERR_INVALID_ARGUMENT
    );
    assert!(last_message().contains("model"));
    assert_eq!(
        call(z.as_ptr(), f.as_ptr(), 5, 40.0, 0.0, 0, &mut r),
        ASPERITY_ERR_INVALID_ARGUMENT
    );
    assert!(last_message().contains("input_kind"));
    let mut bad = f.clone();
    bad[3] = f64::NAN;
    assert_eq!(
        call(z.as_ptr(), bad.as_ptr(), 0, 40.0, 0.0, 0, &mut r),
        ASPERITY_ERR_INVALID_ARGUMENT
    );
    let st =
        unsafe { asperity_afm_analyze(10, z.as_ptr(), f.as_ptr(), 0, 0, 40.0, 0.0, 0, &mut r) };
    assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT, "{}", last_message());
}

#[test]
fn measured_sin_curve_through_the_c_abi() {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../shared/data/afm/afm_force_curve_asylum_mfp3d_SiN.csv");
    if !p.exists() {
        common::skip(format_args!("{} is not present", p.display()));
        return;
    }
    let c = AfmCurve::read(&p, None).unwrap();
    let mut r = AsperityAfmResult::default();
    let st = unsafe {
        asperity_afm_analyze(
            c.len(),
            c.position.as_ptr(),
            c.force.as_ptr(),
            ASPERITY_AFM_INPUT_FORCE,
            c.retract_start,
            c.spring_constant.unwrap(),
            0.0,
            ASPERITY_AFM_MODEL_AUTO,
            &mut r,
        )
    };
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    // README: adhesion ≈ 12.9 nN above the baseline.
    assert!((r.pull_off_force / -12.9e-9 - 1.0).abs() < 0.02);
    assert_ne!(r.flags & ASPERITY_AFM_FLAG_RADIUS_UNKNOWN, 0);
    assert!(r.jump_in_distance > 0.0);
}
