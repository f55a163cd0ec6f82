//! Borodich rescaling (thesis chapter 3): REFERENCE.md §2 and §8 numbers,
//! Hertz/Galin limits, the table of cases, Galanov radii, Zhuravlev integrals.

use approx::assert_relative_eq;
use asperity::contact::power_punch::{galin_c, galin_d};
use asperity::rescaling::*;
use asperity::Error;

/// Taljat A533-B steel (case A): slope 1.056 → κ = 0.112 (3-21).
#[test]
fn taljat_kappa_from_slope() {
    let k = kappa_from_loading_slope(1.056, 2.0).unwrap();
    assert_relative_eq!(k, 0.112, epsilon = 1e-12);
}

/// REFERENCE §8: from (P₁, δ₁) = (2.31 kN, 0.224 mm), κ = 0.112 →
/// P(0.1 mm) = 985.71 N (3-19).
#[test]
fn taljat_rescaled_load() {
    let r = Rescaling::sphere(0.112).unwrap();
    let known = KnownSolution::new(2310.0, 0.224e-3, 1.0).unwrap();
    let p = r.load(1.0, 0.1e-3, &known).unwrap();
    assert!((p - 985.71).abs() < 0.01, "P(0.1 mm) = {p}");
    // Round trip through (3-13).
    let d = r.depth(1.0, p, &known).unwrap();
    assert_relative_eq!(d, 0.1e-3, max_relative = 1e-13);
}

/// Gadelrab fused silica (case M): slopes 1.24 and 1.43 → d = 4.17 (the
/// thesis prints 4.24 from an unrounded slope) and κ = 1.25 either way.
#[test]
fn gadelrab_fused_silica() {
    let d = d_from_unloading_slope(1.24).unwrap();
    assert_relative_eq!(d, 1.0 / 0.24, epsilon = 1e-12);
    assert!((d - 4.17).abs() < 0.005);
    let k = kappa_from_loading_slope(1.43, d).unwrap();
    assert!((k - 1.25).abs() < 0.005, "κ = {k}");
    let k_printed = kappa_from_loading_slope(1.43, 4.24).unwrap();
    assert!((k_printed - 1.25).abs() < 0.005, "κ = {k_printed}");
    // The printed d = 4.24 corresponds to an unloading slope of 1.2358.
    assert_relative_eq!(unloading_slope(4.24).unwrap(), 1.0 + 1.0 / 4.24);
}

/// Goldsmith–Lyman Al1100F (case F): slope 0.766 → κ = 2·0.766 − 2 = −0.468
/// (the thesis prints −0.467): outside validity.
#[test]
fn goldsmith_lyman_negative_kappa() {
    let k = kappa_from_loading_slope(0.766, 2.0).unwrap();
    assert_relative_eq!(k, -0.468, epsilon = 1e-12);
    assert!(k < 0.0);
}

/// The tabulated (κ, d) pairs imply slopes; the slopes give back κ and d.
#[test]
fn table_of_cases_round_trip() {
    // (case, κ, d)
    let cases = [
        ("N Krier Si 9 nm", 0.024, 1.4),
        ("O Lichinchi TiN", 1.73, 4.11),
        ("P Taylor GaAs cube corner", 0.96, 1.43),
        ("Q Jayaraman Si3N4", 0.82, 1.51),
        ("Q Jayaraman Si3N4, kappa given", 0.22, 1.3),
        ("S Jayaraman 1070 steel", 1.53, 3.91),
        ("S Jayaraman 1070 steel, kappa given", 0.12, 1.23),
        ("M Gadelrab fused silica", 1.25, 4.24),
    ];
    for (name, k, d) in cases {
        let ml = loading_slope(k, d).unwrap();
        let mu = unloading_slope(d).unwrap();
        let d2 = d_from_unloading_slope(mu).unwrap();
        let k2 = kappa_from_loading_slope(ml, d2).unwrap();
        assert_relative_eq!(d2, d, max_relative = 1e-12);
        assert_relative_eq!(k2, k, epsilon = 1e-12);
        // With κ given, d from the loading slope alone.
        let d3 = d_from_loading_slope(ml, k).unwrap();
        assert_relative_eq!(d3, d, max_relative = 1e-12);
        // The validity flags of the thesis: κ > 1 (M, O, S), d > 3 (M, O, S).
        let flagged = k > 1.0 || d > 3.0;
        assert_eq!(
            flagged,
            name.starts_with('M') || name.starts_with('O') || name == "S Jayaraman 1070 steel",
            "{name}"
        );
    }
    // Krier's 77 nm defect tip, d = 4.89: unloading slope 1.2045.
    assert_relative_eq!(unloading_slope(4.89).unwrap(), 1.0 + 1.0 / 4.89);
}

/// κ = 1, d = 2 is Hertz; κ = 1, any d is Galin (REFERENCE §1, §2).
#[test]
fn linear_elastic_limits_are_hertz_and_galin() {
    let e_star = 1e9;
    for d in [1.0, 1.5, 2.0, 3.0, 7.5] {
        let b1 = 1e3;
        let a1: f64 = 1e-6;
        let p1 = galin_c(d) * b1 * e_star * a1.powf(d + 1.0);
        let delta1 = galin_d(d) * b1 * a1.powf(d);
        let known = KnownSolution::new(p1, delta1, a1).unwrap();
        let r = Rescaling::new(1.0, d).unwrap();
        for lambda in [0.3, 1.0, 4.0] {
            for p in [0.1 * p1, p1, 17.0 * p1] {
                let b = lambda * b1;
                let a = (p / (galin_c(d) * b * e_star)).powf(1.0 / (d + 1.0));
                let delta = galin_d(d) * b * a.powf(d);
                assert_relative_eq!(
                    r.radius(lambda, p, &known).unwrap(),
                    a,
                    max_relative = 1e-12
                );
                assert_relative_eq!(
                    r.depth(lambda, p, &known).unwrap(),
                    delta,
                    max_relative = 1e-12
                );
                assert_relative_eq!(
                    r.load(lambda, delta, &known).unwrap(),
                    p,
                    max_relative = 1e-12
                );
            }
        }
    }
    // Sphere, (3-17)/(3-18) with λ = R₁/R: Hertz for a new radius.
    let (r1, r2) = (1e-3, 2.5e-3);
    let hertz = |r: f64, p: f64| {
        let a = (3.0 * p * r / (4.0 * e_star)).cbrt();
        (a, a * a / r)
    };
    let (a1, d1) = hertz(r1, 1.0);
    let known = KnownSolution::new(1.0, d1, a1).unwrap();
    let lambda = lambda_spheres(r1, r2).unwrap();
    let (a2, d2) = hertz(r2, 3.0);
    let s = Rescaling::sphere(1.0).unwrap();
    assert_relative_eq!(
        s.depth(lambda, 3.0, &known).unwrap(),
        d2,
        max_relative = 1e-12
    );
    assert_relative_eq!(
        s.radius(lambda, 3.0, &known).unwrap(),
        a2,
        max_relative = 1e-12
    );
    // Cones (3-16): λ = tan γ₁/tan γ = cot γ / cot γ₁.
    let l = lambda_cones(60f64.to_radians(), 70.3f64.to_radians()).unwrap();
    assert_relative_eq!(
        l,
        (70.3f64.to_radians().tan().recip()) / (60f64.to_radians().tan().recip()),
        max_relative = 1e-12
    );
}

/// The exponents of (3-13), (3-14), (3-24) for a nonlinear material: the
/// rescaled solutions are self-consistent and λ is recovered from two points.
#[test]
fn nonlinear_rescaling_consistency() {
    let known = KnownSolution::new(2.0, 3e-6, 1e-5).unwrap();
    for kappa in [0.0, 1e-9, 0.112, 0.5, 1.0, 1.7] {
        for d in [1.0, 1.0 + 1e-9, 1.5, 2.0, 4.24, 50.0] {
            let r = Rescaling::new(kappa, d).unwrap();
            for lambda in [0.5, 1.0, 3.0] {
                let p = 5.0;
                let delta = r.depth(lambda, p, &known).unwrap();
                assert!(delta.is_finite() && delta > 0.0);
                assert_relative_eq!(
                    r.load(lambda, delta, &known).unwrap(),
                    p,
                    max_relative = 1e-11
                );
                let l = shape_scale_from_points(&r, &known, p, delta).unwrap();
                assert_relative_eq!(l, lambda, max_relative = 1e-9);
                // Load grows with depth, depth with load: monotone.
                assert!(r.depth(lambda, 2.0 * p, &known).unwrap() > delta);
            }
        }
    }
    // Continuity at κ → 0 and d → 1.
    let a = Rescaling::new(0.0, 1.0)
        .unwrap()
        .load(2.0, 1e-6, &known)
        .unwrap();
    let b = Rescaling::new(1e-12, 1.0 + 1e-12)
        .unwrap()
        .load(2.0, 1e-6, &known)
        .unwrap();
    assert_relative_eq!(a, b, max_relative = 1e-9);
}

/// REFERENCE §2: R = 0.788 mm with R_medium = 0.798 mm ⇒ unloading R₂ =
/// 62.882 mm by (3-23); (3-22) reproduces R₂ from Hertz points.
#[test]
fn galanov_radii() {
    let r2 = unloading_radius(0.788e-3, 0.798e-3).unwrap();
    assert!((r2 - 62.882e-3).abs() < 1e-6, "R₂ = {r2}");
    assert_relative_eq!(
        medium_radius(0.788e-3, r2).unwrap(),
        0.798e-3,
        max_relative = 1e-12
    );
    // The other tabulated R_medium values round-trip as well.
    for (r, rm) in [
        (0.788e-3, 0.794e-3),
        (0.788e-3, 1.27e-3),
        (0.788e-3, 1.282e-3),
    ] {
        let r2 = unloading_radius(r, rm).unwrap();
        assert_relative_eq!(medium_radius(r, r2).unwrap(), rm, max_relative = 1e-12);
    }
    // (3-22): a Hertz point on R₁ and a Hertz point on R₂ give R₂ back.
    let e_star = 150e9;
    let hertz_delta = |r: f64, p: f64| (9.0 * p * p / (16.0 * e_star * e_star * r)).cbrt();
    let (r1, r2) = (0.788e-3, 62.882e-3);
    let (p1, p2) = (1000.0, 2310.0);
    let got =
        galanov_unloading_radius(r1, p1, hertz_delta(r1, p1), p2, hertz_delta(r2, p2)).unwrap();
    assert_relative_eq!(got, r2, max_relative = 1e-12);
    assert_relative_eq!(
        hertz_effective_radius(e_star, p2, hertz_delta(r2, p2)).unwrap(),
        r2,
        max_relative = 1e-12
    );
    // Infinite unloading radius: crater fits the sphere; bad order rejected.
    assert_eq!(medium_radius(1.0, f64::INFINITY).unwrap(), 1.0);
    assert!(matches!(
        medium_radius(1.0, 0.5),
        Err(Error::InvalidArgument { .. })
    ));
    // Cone analogue (2-18).
    let gi = 70.3f64.to_radians();
    let gf = 80f64.to_radians();
    let b = galanov_cone_coefficient(gi, gf).unwrap();
    assert_relative_eq!(b, 1.0 / gi.tan() - 1.0 / gf.tan(), max_relative = 1e-12);
    assert_relative_eq!(
        galanov_imprint_half_angle(gi, b).unwrap(),
        gf,
        max_relative = 1e-12
    );
}

/// Zhuravlev (REFERENCE §3): linear densities give ∫₀^x (x−s)^q s³/6 ds ∝
/// x^{q+4}; q = 3/2 gives P ∝ x^{11/2}. Quadrature against the closed form.
#[test]
fn zhuravlev_integrals() {
    assert_relative_eq!(zhuravlev_exponent(1.0, 2.0).unwrap(), 1.5);
    assert_relative_eq!(zhuravlev_exponent(1.0, 3.0).unwrap(), 4.0 / 3.0);
    assert_relative_eq!(zhuravlev_exponent(0.5, 2.0).unwrap(), 1.25);
    for q in [1.0, 1.25, 1.5, 2.0, 4.0 / 3.0] {
        let closed = zhuravlev_integral_linear(q, 2.0, 3.0, 0.5).unwrap();
        let quad = zhuravlev_integral(q, 2.0, |x| 3.0 * x, |x| 0.5 * x, 24).unwrap();
        assert_relative_eq!(quad, closed, max_relative = 1e-9);
        // Scaling exponent q + 4 (11/2 for Hertz).
        let ratio = zhuravlev_integral_linear(q, 4.0, 1.0, 1.0).unwrap()
            / zhuravlev_integral_linear(q, 2.0, 1.0, 1.0).unwrap();
        assert_relative_eq!(ratio.log2(), q + 4.0, epsilon = 1e-12);
    }
    // Gaussian-like density: converged in the order.
    let g = |x: f64| (-x * x).exp();
    let a = zhuravlev_integral(1.5, 1.3, g, g, 32).unwrap();
    let b = zhuravlev_integral(1.5, 1.3, g, g, 64).unwrap();
    assert_relative_eq!(a, b, max_relative = 1e-10);
    // Prefactor: λ^{(κ−2)/d} P₁/δ₁^q; one pair at interference w recovers (3-24).
    let r = Rescaling::new(0.4, 2.5).unwrap();
    let known = KnownSolution::new(2.0, 1e-6, 1.0).unwrap();
    let c = zhuravlev_prefactor(&r, 1.7, &known).unwrap();
    let w: f64 = 3e-7;
    assert_relative_eq!(
        c * w.powf(r.load_depth_exponent()),
        r.load(1.7, w, &known).unwrap(),
        max_relative = 1e-12
    );
}

#[test]
fn bad_arguments_are_errors_not_nan() {
    let known = KnownSolution {
        load: 1.0,
        depth: 1.0,
        radius: 1.0,
    };
    assert!(Rescaling::new(-0.1, 2.0).is_err());
    assert!(Rescaling::new(0.5, 0.9).is_err());
    assert!(Rescaling::new(f64::NAN, 2.0).is_err());
    let r = Rescaling::sphere(0.3).unwrap();
    assert!(r.depth(-1.0, 1.0, &known).is_err());
    assert!(r.load(1.0, f64::NAN, &known).is_err());
    let bad = KnownSolution {
        load: 0.0,
        depth: 1.0,
        radius: 1.0,
    };
    assert!(r.depth(1.0, 1.0, &bad).is_err());
    assert!(matches!(
        kappa_from_loading_slope(2.0, 1.0),
        Err(Error::OutOfDomain { .. })
    ));
    assert!(matches!(
        d_from_unloading_slope(1.0),
        Err(Error::OutOfDomain { .. })
    ));
    assert!(d_from_unloading_slope(f64::INFINITY).is_err());
    assert!(shape_scale_from_points(&Rescaling::new(2.0, 2.0).unwrap(), &known, 1.0, 1.0).is_err());
    assert!(zhuravlev_integral(1.5, 1.0, |x| x, |x| x, 2).is_err());
    // Near d = 1 κ is finite but ill-conditioned, never NaN.
    let k = kappa_from_loading_slope(1.999, 1.001).unwrap();
    assert!(k.is_finite());
}
