//! AFM force–distance analysis: synthetic curves made from each law (noise,
//! offset, tilt) recover their parameters within the stated standard errors;
//! the measured curves of `../shared/data/afm` give finite, flagged results
//! and the README's pull-off (skipped with a reason when absent, a failure
//! under `ASPERITY_REQUIRE_ALL=1`).

use asperity::afm::*;
use asperity::contact::{
    Control, Dmt, Hertz, Jkr, LjSphere, MaugisDugdale, NormalContact, TabulatedLaw,
};
use asperity::Error;
use std::path::PathBuf;

#[allow(dead_code)]
mod common;

fn data(name: &str) -> Option<AfmCurve> {
    let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../shared/data/afm")
        .join(name);
    if !p.exists() {
        common::skip(format_args!(
            "{} is not present (the measured data live outside the project, in \
             ../shared/data next to the crate)",
            p.display()
        ));
        return None;
    }
    Some(AfmCurve::read(&p, None).unwrap_or_else(|e| panic!("{}: {e}", p.display())))
}

/// Deterministic pseudo-random noise, uniform in [−√3, √3] (unit variance).
fn noise(i: usize, seed: u64) -> f64 {
    let mut x = (i as u64).wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ seed;
    x ^= x >> 33;
    x = x.wrapping_mul(0xff51_afd7_ed55_8ccd);
    x ^= x >> 33;
    ((x as f64 / u64::MAX as f64) * 2.0 - 1.0) * 3f64.sqrt()
}

/// A synthetic sphere on a sample.
#[derive(Clone, Copy)]
struct Synth {
    model: AfmModel,
    radius: f64,
    e_star: f64,
    w: f64,
    z0: f64,
    k: f64,
    f_max: f64,
    sigma: f64,
    offset: f64,
    slope: f64,
    /// +1: position grows towards the sample; −1: it decreases.
    direction: f64,
    seed: u64,
}

impl Synth {
    fn law(&self) -> Box<dyn NormalContact> {
        let (r, e, w) = (self.radius, self.e_star, self.w);
        match self.model {
            AfmModel::Hertz => Box::new(Hertz::new(r, e).unwrap()),
            AfmModel::Dmt => Box::new(Dmt::new(r, e, w).unwrap()),
            AfmModel::Jkr => Box::new(Jkr::new(r, e, w).unwrap()),
            AfmModel::MaugisDugdale => {
                Box::new(MaugisDugdale::from_tabor(r, e, w, self.z0).unwrap())
            }
            // The dimensional sphere on finer grids (from 256 cells, 1e-4)
            // than the fit's unit tables (128 cells, 1e-3).
            AfmModel::LennardJones => {
                let lj = LjSphere::new(r, e, w, self.z0).unwrap();
                let t = [256, 320, 384, 192, 128]
                    .into_iter()
                    .find_map(|n| TabulatedLaw::from_lj_sphere(&lj, n, 1e-4).ok());
                Box::new(t.expect("an LJ table on 128–384 cells"))
            }
        }
    }

    /// Approach: 400 free points over 200 nm, then the stable branch from
    /// F = 0 to f_max (150 points); retract: the branch from f_max to the
    /// law's pull-off (300 points), then 400 free points. Travel u towards
    /// the sample, contact at u_c = 1 µm; position z = u/direction; raw
    /// force = F + noise + offset + slope·z.
    fn curve(&self) -> AfmCurve {
        let law = self.law();
        let pc = law.pull_off_force(Control::Load).unwrap();
        let uc = 1e-6;
        let branch = |f: f64| {
            let f = if f <= pc { pc * (1.0 - 1e-9) } else { f };
            uc + law.eval_at_load(f).unwrap().delta + f / self.k
        };
        let mut u = Vec::new();
        let mut f = Vec::new();
        let u0 = branch(0.0_f64.max(pc * (1.0 - 1e-9)));
        for i in 0..400 {
            u.push(u0 - 200e-9 + 200e-9 * i as f64 / 400.0);
            f.push(0.0);
        }
        for i in 0..150 {
            let fi = self.f_max * i as f64 / 149.0;
            u.push(branch(fi.max(pc)));
            f.push(fi.max(pc));
        }
        let rs = u.len();
        for i in 0..300 {
            let fi = self.f_max + (pc - self.f_max) * i as f64 / 299.0;
            u.push(branch(fi));
            f.push(fi);
        }
        let upo = *u.last().unwrap();
        for i in 1..=400 {
            u.push(upo - 200e-9 * i as f64 / 400.0);
            f.push(0.0);
        }
        let z: Vec<f64> = u.iter().map(|u| u / self.direction).collect();
        let raw: Vec<f64> = z
            .iter()
            .zip(&f)
            .enumerate()
            .map(|(i, (z, f))| f + self.sigma * noise(i, self.seed) + self.offset + self.slope * z)
            .collect();
        AfmCurve::new(z, raw, Some(rs), Some(self.k)).unwrap()
    }
}

/// A compliant sample under a stiff lever: R = 20 nm, k = 40 N/m, 200 nN.
fn base(model: AfmModel, e_star: f64, w: f64) -> Synth {
    Synth {
        model,
        radius: 20e-9,
        e_star,
        w,
        z0: 0.3e-9,
        k: 40.0,
        f_max: 200e-9,
        sigma: 0.2e-9,
        offset: -50e-9,
        slope: 0.02,
        direction: 1.0,
        seed: 7,
    }
}

fn options(s: &Synth, radius: Option<f64>) -> AfmOptions {
    AfmOptions {
        tip_radius: radius,
        equilibrium_separation: s.z0,
        ..AfmOptions::default()
    }
}

/// |x − truth| ≤ 3 standard errors, and the error is a stated, small one.
fn within(what: &str, x: f64, se: Option<f64>, truth: f64) {
    let se = se.unwrap_or_else(|| panic!("{what}: no standard error"));
    assert!(se.is_finite() && se > 0.0, "{what}: se {se}");
    assert!(se < 0.2 * truth.abs(), "{what}: se {se} vs value {truth}");
    assert!(
        (x - truth).abs() <= 3.0 * se,
        "{what}: fitted {x:.6e}, truth {truth:.6e}, se {se:.3e}"
    );
}

fn check_recovery(s: Synth) {
    let c = s.curve();
    let a = analyze(&c, &options(&s, Some(s.radius))).unwrap();
    let fit = a
        .fits
        .iter()
        .find(|f| f.model == s.model.name())
        .unwrap_or_else(|| panic!("no {} fit: {:?}", s.model.name(), a.failed_fits));
    let m = s.model.name();
    within(
        &format!("{m} E*"),
        fit.e_star.unwrap(),
        fit.e_star_stderr,
        s.e_star,
    );
    if s.model != AfmModel::Hertz {
        within(
            &format!("{m} w"),
            fit.work_of_adhesion.unwrap(),
            fit.work_of_adhesion_stderr,
            s.w,
        );
    }
    // The residual (N) is the force noise σ.
    let expected = s.sigma;
    assert!(
        fit.rms_residual < 1.3 * expected && fit.rms_residual > 0.7 * expected,
        "{m}: rms {:.3e} N, noise {expected:.3e} N",
        fit.rms_residual
    );
    // Baseline offset and tilt.
    // Standard error of a line's slope: σ/(√n·std z), n ≥ 300 free points
    // over 150 nm or more (std z ≥ 150 nm/√12).
    let slope_se = s.sigma / (300f64.sqrt() * 150e-9 / 12f64.sqrt());
    assert!(
        (a.baseline.slope - s.slope).abs() < 4.0 * slope_se,
        "{m}: slope {} vs {}, se {slope_se}",
        a.baseline.slope,
        s.slope
    );
    let b_at = s.offset + s.slope * a.baseline.reference_position;
    assert!((a.baseline.offset - b_at).abs() < s.sigma, "{m}: offset");
    // Pull-off against the law's.
    let pc = s.law().pull_off_force(Control::Load).unwrap();
    assert!(
        (a.pull_off_force - pc).abs() < 4.0 * s.sigma,
        "{m}: pull-off {:.4e} N, law {pc:.4e} N",
        a.pull_off_force
    );
    assert!(a.adhesion_energy.is_finite() && a.adhesion_energy >= 0.0);
    assert_eq!(a.recommended_model, Some(m), "{m}: {}", a.to_json());

    // Unknown radius: the products, the same numbers.
    let b = analyze(&c, &options(&s, None)).unwrap();
    let fb = b.fits.iter().find(|f| f.model == m).unwrap();
    assert!(fb.e_star.is_none() && fb.work_of_adhesion.is_none());
    assert!(b.flags.contains(&"radius_unknown"));
    within(
        &format!("{m} E*√R"),
        fb.e_star_times_sqrt_radius,
        fb.e_star_times_sqrt_radius_stderr,
        s.e_star * s.radius.sqrt(),
    );
    if s.model != AfmModel::Hertz {
        within(
            &format!("{m} wR"),
            fb.work_of_adhesion_times_radius.unwrap(),
            fb.work_of_adhesion_times_radius_stderr,
            s.w * s.radius,
        );
        let mu_fit = fb.tabor_parameter.unwrap();
        let mu = (s.radius * s.w * s.w / (s.e_star * s.e_star * s.z0.powi(3))).cbrt();
        assert!((mu_fit / mu - 1.0).abs() < 0.2, "{m}: μ {mu_fit} vs {mu}");
    }
}

#[test]
fn hertz_curve_recovers_modulus() {
    check_recovery(base(AfmModel::Hertz, 1e9, 0.0));
}

#[test]
fn dmt_curve_recovers_parameters() {
    // Stiff sample, weak adhesion: μ ≈ 0.07 (λ ≈ 0.08).
    let mut s = base(AfmModel::Dmt, 50e9, 0.05);
    s.radius = 10e-9;
    s.sigma = 0.05e-9;
    check_recovery(s);
}

#[test]
fn jkr_curve_recovers_parameters() {
    // Compliant, strongly adhering: μ ≈ 12 (λ ≈ 14).
    let mut s = base(AfmModel::Jkr, 0.5e9, 0.5);
    s.radius = 50e-9;
    s.direction = -1.0;
    s.slope = -0.01;
    check_recovery(s);
}

#[test]
fn maugis_dugdale_curve_recovers_parameters() {
    // μ ≈ 1 (λ ≈ 1.2), between DMT and JKR.
    let mut s = base(AfmModel::MaugisDugdale, 5e9, 0.2);
    s.radius = 20e-9;
    s.sigma = 0.05e-9;
    check_recovery(s);
}

#[test]
fn sweep_over_decades_is_finite() {
    for &e in &[1e7, 1e8, 1e9, 1e10] {
        for &w in &[0.01, 0.1, 1.0] {
            let mut s = base(AfmModel::Jkr, e, w);
            s.f_max = 50.0 * std::f64::consts::PI * w * s.radius;
            s.sigma = 1e-3 * s.f_max;
            let a = analyze(&s.curve(), &options(&s, Some(s.radius))).unwrap();
            assert!(a.pull_off_force < 0.0 && a.pull_off_force.is_finite());
            assert!(a.adhesion_energy.is_finite() && a.contact_point.is_finite());
            assert!(a.recommended_model.is_some(), "{}", a.to_json());
            for f in &a.fits {
                assert!(f.rms_residual.is_finite() && f.e_star_times_sqrt_radius > 0.0);
            }
        }
    }
}

#[test]
fn bad_input_is_an_error() {
    let s = base(AfmModel::Jkr, 1e9, 0.1);
    let c = s.curve();
    let mut o = options(&s, Some(-1.0));
    assert!(matches!(
        analyze(&c, &o),
        Err(Error::InvalidArgument {
            name: "tip_radius",
            ..
        })
    ));
    o.tip_radius = None;
    o.spring_constant = Some(0.0);
    assert!(matches!(
        analyze(&c, &o),
        Err(Error::InvalidArgument {
            name: "spring_constant",
            ..
        })
    ));
    let mut no_k = c.clone();
    no_k.spring_constant = None;
    assert!(matches!(
        analyze(&no_k, &AfmOptions::default()),
        Err(Error::InvalidArgument {
            name: "spring_constant",
            ..
        })
    ));
    assert!(AfmCurve::new(vec![0.0; 5], vec![0.0; 5], None, None).is_err());
    assert!(AfmCurve::new(vec![0.0; 20], vec![f64::NAN; 20], None, None).is_err());
    assert!(AfmCurve::from_csv_str("a,b\n1,2\n", None).is_err());
}

#[test]
fn spring_constant_option_rescales_forces() {
    let s = base(AfmModel::Jkr, 0.5e9, 0.5);
    let c = s.curve();
    let a = analyze(&c, &options(&s, None)).unwrap();
    let mut o = options(&s, None);
    o.spring_constant = Some(2.0 * s.k);
    let b = analyze(&c, &o).unwrap();
    assert!((b.pull_off_force / a.pull_off_force - 2.0).abs() < 1e-9);
    assert_eq!(b.spring_constant, 2.0 * s.k);
}

#[test]
fn sin_curve_pull_off_matches_readme() {
    let Some(c) = data("afm_force_curve_asylum_mfp3d_SiN.csv") else {
        return;
    };
    assert_eq!(c.retract_start, 1009);
    assert_eq!(c.spring_constant, Some(1.1841));
    let a = analyze(&c, &AfmOptions::default()).unwrap();
    println!("{}", a.to_json());
    // README: minimum −16.73 nN, baseline ≈ −3.88 nN: adhesion ≈ 12.9 nN.
    assert!(
        (a.pull_off_force / -12.9e-9 - 1.0).abs() < 0.02,
        "pull-off {:.4e} N",
        a.pull_off_force
    );
    // README: the jump-to-contact dip reaches −6.9 nN from −3.88 nN.
    assert!(a.jump_in_force < -2.5e-9 && a.jump_in_force > -3.5e-9);
    assert!(a.jump_in_distance > 0.0 && a.jump_in_distance < 10e-9);
    assert!(a.adhesion_energy > 0.0 && a.adhesion_energy.is_finite());
    assert!((a.baseline.offset + 3.9e-9).abs() < 0.2e-9);
    assert!(a.flags.contains(&"radius_unknown"));
    assert!(!a.flags.contains(&"no_jump_in"));
    assert!(a.recommended_model.is_some());
    for f in &a.fits {
        assert!(f.rms_residual.is_finite() && f.e_star_times_sqrt_radius.is_finite());
    }
}

#[test]
fn jpk_curve_is_finite_and_flagged() {
    let Some(c) = data("afm_force_curve_jpk_qi_stiff_cantilever.csv") else {
        return;
    };
    assert_eq!(c.spring_constant, Some(35.028));
    let a = analyze(
        &c,
        &AfmOptions {
            tip_radius: Some(20e-9),
            ..AfmOptions::default()
        },
    )
    .unwrap();
    println!("{}", a.to_json());
    assert_eq!(a.direction, -1.0);
    assert!(a.pull_off_force < 0.0 && a.pull_off_force > -20e-9);
    assert!(a.contact_point.is_finite() && a.adhesion_energy.is_finite());
    assert!(a.flags.contains(&"no_jump_in"));
    assert!(!a.flags.is_empty());
    for f in &a.fits {
        assert!(f.rms_residual.is_finite());
        assert!(f.e_star.unwrap().is_finite());
    }
}

#[test]
fn arbitrary_curves_never_panic_and_ok_results_are_finite() {
    // Pure noise, steps, ramps, constant curves, lengths 16…400.
    for seed in 0..40u64 {
        let n = 16 + (seed as usize * 37) % 385;
        let z: Vec<f64> = (0..n)
            .map(|i| {
                let t = i as f64 / n as f64;
                1e-6 * if t < 0.5 { t } else { 1.0 - t } + 1e-10 * noise(i, seed)
            })
            .collect();
        let f: Vec<f64> = (0..n)
            .map(|i| match seed % 4 {
                0 => 1e-9 * noise(i, seed + 100),
                1 => {
                    if i % 7 == 0 {
                        5e-9
                    } else {
                        -2e-9
                    }
                }
                2 => 1e-8 * (i as f64 / n as f64),
                _ => 0.0,
            })
            .collect();
        // A noisy turning point can leave fewer than 8 points a side: an error.
        let Ok(c) = AfmCurve::new(z, f, None, Some(0.5 + seed as f64)) else {
            continue;
        };
        let opts = AfmOptions {
            tip_radius: (seed % 2 == 0).then_some(10e-9),
            ..AfmOptions::default()
        };
        if let Ok(a) = analyze(&c, &opts) {
            assert!(a.pull_off_force.is_finite() && a.adhesion_energy.is_finite());
            assert!(a.contact_point.is_finite() && a.jump_in_distance.is_finite());
            for f in &a.fits {
                assert!(f.rms_residual.is_finite() && f.e_star_times_sqrt_radius.is_finite());
            }
            assert!(serde_json::from_str::<serde_json::Value>(&a.to_json()).is_ok());
        }
    }
}

/// E* of the sphere with Tabor parameter `mu` (R, w, z₀ given).
fn e_for_tabor(s: &Synth, mu: f64) -> f64 {
    (s.radius * s.w * s.w / (mu.powi(3) * s.z0.powi(3))).sqrt()
}

/// An LJ-sphere curve, fitted with `--model lj` only (the fit of a known
/// model, as the C ABI and the CLI ask for it).
fn lj_synth(mu: f64) -> Synth {
    let mut s = base(AfmModel::LennardJones, 1e9, 0.2);
    s.radius = 20e-9;
    s.e_star = e_for_tabor(&s, mu);
    s.f_max = 20.0 * std::f64::consts::PI * s.w * s.radius;
    // 1.2e-3 of the maximum force, as the other synthetic curves (0.2 nN
    // in 200 nN): above the tables' 1e-3 error of the pull-off scale.
    s.sigma = 0.3e-9;
    s
}

fn lj_only(s: &Synth, radius: Option<f64>) -> AfmOptions {
    AfmOptions {
        models: vec![AfmModel::LennardJones, AfmModel::MaugisDugdale],
        ..options(s, radius)
    }
}

fn check_lj_recovery(s: Synth) {
    let c = s.curve();
    let a = analyze(&c, &lj_only(&s, Some(s.radius))).unwrap();
    let f = a
        .fits
        .iter()
        .find(|f| f.model == "lj")
        .unwrap_or_else(|| panic!("no lj fit: {:?}", a.failed_fits));
    println!("{}", a.to_json());
    assert!(f.converged, "lj not converged");
    within("lj E*", f.e_star.unwrap(), f.e_star_stderr, s.e_star);
    within(
        "lj w",
        f.work_of_adhesion.unwrap(),
        f.work_of_adhesion_stderr,
        s.w,
    );
    let mu = (s.radius * s.w * s.w / (s.e_star * s.e_star * s.z0.powi(3))).cbrt();
    let mu_fit = f.tabor_parameter.unwrap();
    assert!((mu_fit / mu - 1.0).abs() < 0.2, "lj: μ {mu_fit} vs {mu}");
    // The residual is the noise (σ), within the table's error.
    assert!(
        f.rms_residual < 1.5 * s.sigma && f.rms_residual > 0.7 * s.sigma,
        "lj: rms {:.3e} N, noise {:.3e} N",
        f.rms_residual,
        s.sigma
    );
    // The law's pull-off is the data's: the sphere's own, within the noise.
    let pc = s.law().pull_off_force(Control::Load).unwrap();
    assert!(
        (f.pull_off_force - pc).abs() < 3.0 * s.sigma,
        "lj pull-off {:.4e} N vs {pc:.4e} N",
        f.pull_off_force
    );
    // The model curve of the fit (the SVG's) is finite and ends at its pull-off.
    let pts = a.model_curve(f, 1e-9, 20).unwrap();
    assert!(pts.iter().all(|p| p.0.is_finite() && p.1.is_finite()));
}

#[test]
fn lj_curve_recovers_parameters_mu_half() {
    check_lj_recovery(lj_synth(0.5));
}

#[test]
fn lj_curve_recovers_parameters_mu_three() {
    let mut s = lj_synth(3.0);
    s.direction = -1.0;
    s.slope = -0.01;
    s.seed = 11;
    check_lj_recovery(s);
}

#[test]
fn lj_fit_of_a_maugis_dugdale_curve_is_as_good() {
    // μ ≈ 1: the two laws differ most, yet the LJ sphere fits an MD curve
    // nearly as well (its shape differs by a few % of the pull-off).
    let mut s = base(AfmModel::MaugisDugdale, 5e9, 0.2);
    s.sigma = 0.05e-9;
    let c = s.curve();
    let a = analyze(&c, &options(&s, Some(s.radius))).unwrap();
    let md = a.fits.iter().find(|f| f.model == "maugis_dugdale").unwrap();
    let lj = a
        .fits
        .iter()
        .find(|f| f.model == "lj")
        .unwrap_or_else(|| panic!("auto skipped lj at μ ≈ 1: {:?}", a.skipped_fits));
    assert!(
        lj.rms_residual < 2.0 * md.rms_residual,
        "lj rms {:.3e}, md rms {:.3e}",
        lj.rms_residual,
        md.rms_residual
    );
    assert!((lj.e_star.unwrap() / s.e_star - 1.0).abs() < 0.2);
    assert!((lj.work_of_adhesion.unwrap() / s.w - 1.0).abs() < 0.2);
    // Cheapest within tolerance: MD fits its own curve, LJ is not chosen.
    assert_eq!(a.recommended_model, Some("maugis_dugdale"));
}

#[test]
fn auto_skips_lj_outside_the_transition_range_and_says_so() {
    // JKR curve at μ ≈ 12: λ > 5.
    let mut s = base(AfmModel::Jkr, 0.5e9, 0.5);
    s.radius = 50e-9;
    let a = analyze(&s.curve(), &options(&s, Some(s.radius))).unwrap();
    assert!(a.fits.iter().all(|f| f.model != "lj"));
    assert_eq!(a.skipped_fits.len(), 1, "{:?}", a.skipped_fits);
    assert_eq!(a.skipped_fits[0].0, "lj");
    assert!(a.to_json().contains("\"skipped_fits\":[[\"lj\""));
}

#[test]
fn lj_fit_is_finite_over_tabor_parameters() {
    // μ from 0.05 to 20 (decades), fitted from curves of each.
    for &mu in &[0.05, 0.3, 2.0, 20.0] {
        let mut s = lj_synth(mu);
        s.sigma = 1e-3 * s.f_max;
        let a = analyze(&s.curve(), &lj_only(&s, Some(s.radius))).unwrap();
        let f = a
            .fits
            .iter()
            .find(|f| f.model == "lj")
            .unwrap_or_else(|| panic!("μ {mu}: no lj fit: {:?}", a.failed_fits));
        for v in [
            f.e_star.unwrap(),
            f.work_of_adhesion.unwrap(),
            f.rms_residual,
            f.pull_off_force,
            f.tabor_parameter.unwrap(),
        ] {
            assert!(v.is_finite(), "μ {mu}: {}", a.to_json());
        }
        assert!(f.pull_off_force < 0.0 && f.e_star.unwrap() > 0.0);
        let t = f.tabor_parameter.unwrap();
        assert!(t / mu > 0.5 && t / mu < 2.0, "μ {mu}: fitted {t}");
    }
}

#[test]
fn measured_curves_give_finite_lj_fits() {
    for name in [
        "afm_force_curve_asylum_mfp3d_SiN.csv",
        "afm_force_curve_jpk_qi_stiff_cantilever.csv",
    ] {
        let Some(c) = data(name) else {
            return;
        };
        let o = AfmOptions {
            tip_radius: Some(20e-9),
            models: vec![AfmModel::LennardJones],
            ..AfmOptions::default()
        };
        let a = analyze(&c, &o).unwrap();
        println!("{name}: {}", a.to_json());
        let f = a
            .fits
            .iter()
            .find(|f| f.model == "lj")
            .unwrap_or_else(|| panic!("{name}: {:?}", a.failed_fits));
        assert!(f.rms_residual.is_finite() && f.e_star.unwrap().is_finite());
        assert!(f.work_of_adhesion.unwrap().is_finite());
        assert!(f.tabor_parameter.unwrap().is_finite());
    }
}
