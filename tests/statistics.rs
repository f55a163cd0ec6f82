//! Statistical multi-asperity models (thesis §1.7, §3.7, §5.3.4; REFERENCE.md
//! §3): Greenwood–Williamson (1-29)..(1-31), Zhuravlev (1-23)..(1-28),
//! Kragelsky's rods (5-7) and the power-law extensions (3-27), (3-28).

use approx::assert_relative_eq;
use asperity::contact::power_punch::{galin_c, galin_d};
use asperity::rescaling::{KnownSolution, Rescaling};
use asperity::statistics::gaussian::{f0, f1, f3_2};
use asperity::statistics::zhuravlev::{AREA_EXPONENT, FRICTION_LOAD_EXPONENT, LOAD_EXPONENT};
use asperity::statistics::{
    plasticity_index, BearingCurveRods, DeformationRegime, EmpiricalHeights, GreenwoodWilliamson,
    HeightDistribution, KragelskyRods, PowerLawAsperities, Zhuravlev,
};
use asperity::Error;
use core::f64::consts::PI;

const N: f64 = 1.0e4;
const R: f64 = 100e-6;
const E_STAR: f64 = 100e9;
const SIGMA: f64 = 1e-6;

fn gaussian_gw() -> GreenwoodWilliamson {
    GreenwoodWilliamson::new(N, R, E_STAR, HeightDistribution::gaussian(SIGMA).unwrap()).unwrap()
}

/// Standard normal quantile by Newton on `Q(z) = erfc(z/√2)/2` (for building
/// deterministic samples).
fn normal_quantile(p: f64) -> f64 {
    let mut z = 0.0;
    for _ in 0..100 {
        let q = 0.5 * libm::erfc(z / 2f64.sqrt());
        let phi = (-0.5 * z * z).exp() / (2.0 * PI).sqrt();
        let dz = ((1.0 - q) - p) / phi;
        z -= dz;
        if dz.abs() < 1e-15 {
            break;
        }
    }
    z
}

// ---------------------------------------------------------------------------
// Greenwood–Williamson

/// (1-29), (1-30) with the REFERENCE §3 values at d/σ = 1:
/// F₀ = 0.1586552539, F₁ = 0.08331547059, F_{3/2} = 0.07566817739.
#[test]
fn gw_gaussian_matches_reference_integrals() {
    let gw = gaussian_gw();
    let r = gw.response(SIGMA).unwrap();
    let load = 4.0 / 3.0 * N * E_STAR * R.sqrt() * SIGMA.powf(1.5) * 0.07566817739;
    let area = PI * N * R * SIGMA * 0.08331547059;
    assert_relative_eq!(r.load, load, max_relative = 1e-10);
    assert_relative_eq!(r.area, area, max_relative = 1e-10);
    assert_relative_eq!(r.contacts, N * 0.1586552539, max_relative = 1e-9);
    assert_relative_eq!(gw.load(SIGMA).unwrap(), r.load, max_relative = 1e-15);
    assert_relative_eq!(gw.area(SIGMA).unwrap(), r.area, max_relative = 1e-15);
    assert_relative_eq!(
        gw.contacts(SIGMA).unwrap(),
        r.contacts,
        max_relative = 1e-15
    );
    // Nothing touches far away; everything touches deep down.
    let far = gw.response(50.0 * SIGMA).unwrap();
    assert_eq!((far.load, far.area, far.contacts), (0.0, 0.0, 0.0));
    assert_eq!(far.mean_pressure(), 0.0);
    assert_relative_eq!(gw.contacts(-40.0 * SIGMA).unwrap(), N, max_relative = 1e-15);
}

/// GW 1966: area and load nearly proportional for Gaussian heights. Over
/// three decades of load (d/σ from 1 to 3.3296640, P falling 1000-fold) the
/// mean pressure `P/A` falls by the factor 1.3642446 (±15.4 % about its mid
/// value), and the local exponent d ln A/d ln P rises from 0.9223085 to
/// 0.9723357 (values from the 30-digit parabolic-cylinder forms).
#[test]
fn gw_area_nearly_proportional_to_load() {
    let gw = gaussian_gw();
    let (h1, h2) = (1.0, 3.329_663_997_459_623);
    let p1 = gw.response(h1 * SIGMA).unwrap();
    let p2 = gw.response(h2 * SIGMA).unwrap();
    assert_relative_eq!(p1.load / p2.load, 1000.0, max_relative = 1e-10);
    let scale = 4.0 / (3.0 * PI) * E_STAR * (SIGMA / R).sqrt();
    assert_relative_eq!(
        p1.mean_pressure() / scale,
        0.908_212_806_784_032_4,
        max_relative = 1e-11
    );
    assert_relative_eq!(
        p2.mean_pressure() / scale,
        0.665_725_806_010_168_7,
        max_relative = 1e-11
    );
    let ratio = p1.mean_pressure() / p2.mean_pressure();
    assert_relative_eq!(ratio, 1.364_244_556_219_231, max_relative = 1e-10);
    // Local exponent d ln A / d ln P = (dA/dd · P)/(dP/dd · A) by central
    // differences, and the whole sweep in between stays between the ends.
    let slope = |h: f64| {
        let e = 1e-4 * SIGMA;
        let (a, b) = (
            gw.response(h * SIGMA - e).unwrap(),
            gw.response(h * SIGMA + e).unwrap(),
        );
        (b.area / a.area).ln() / (b.load / a.load).ln()
    };
    assert!((slope(h1) - 0.9223085).abs() < 1e-6, "{}", slope(h1));
    assert!((slope(h2) - 0.9723357).abs() < 1e-6, "{}", slope(h2));
    let mut previous = f64::INFINITY;
    for i in 0..=100 {
        let h = h1 + (h2 - h1) * i as f64 / 100.0;
        let m = gw.mean_pressure(h * SIGMA).unwrap();
        assert!(m < previous && m <= p1.mean_pressure() * (1.0 + 1e-12));
        assert!(m >= p2.mean_pressure() * (1.0 - 1e-12));
        previous = m;
    }
}

/// GW 1966's exponential tail gives exact proportionality:
/// `P/A = E* √(σ/(πR))` for every `d ≥ −σ`, and `P = (4/3)NE*R^{1/2}σ^{3/2}
/// Γ(5/2) e^{−(d+σ)/σ}`; below −σ the upper incomplete Γ, here in closed
/// form `e^x Γ(5/2, x) = (3/4)√π e^x erfc(√x) + (3/2)√x + x^{3/2}`.
#[test]
fn gw_exponential_closed_forms() {
    let gw = GreenwoodWilliamson::new(
        N,
        R,
        E_STAR,
        HeightDistribution::exponential(SIGMA).unwrap(),
    )
    .unwrap();
    let k = 4.0 / 3.0 * N * E_STAR * R.sqrt() * SIGMA.powf(1.5);
    let gamma_5_2 = 0.75 * PI.sqrt();
    for &h in &[-1.0, -0.5, 0.0, 1.0, 3.0, 10.0] {
        let r = gw.response(h * SIGMA).unwrap();
        let e = (-(h + 1.0)).exp();
        assert_relative_eq!(r.load, k * gamma_5_2 * e, max_relative = 1e-13);
        assert_relative_eq!(r.area, PI * N * R * SIGMA * e, max_relative = 1e-13);
        assert_relative_eq!(r.contacts, N * e, max_relative = 1e-13);
        assert_relative_eq!(
            r.mean_pressure(),
            E_STAR * (SIGMA / (PI * R)).sqrt(),
            max_relative = 1e-13
        );
    }
    for &h in &[-1.5, -2.0, -4.0, -11.0, -60.0] {
        let x: f64 = -(h + 1.0);
        let upper =
            0.75 * PI.sqrt() * x.exp() * libm::erfc(x.sqrt()) + 1.5 * x.sqrt() + x.powf(1.5);
        let r = gw.response(h * SIGMA).unwrap();
        assert_relative_eq!(r.load, k * upper, max_relative = 1e-12);
        assert_relative_eq!(r.area, PI * N * R * SIGMA * (1.0 + x), max_relative = 1e-13);
        assert_relative_eq!(r.contacts, N, max_relative = 1e-15);
    }
}

/// Empirical heights: the straight sums of (1-29), (1-30) over the summits
/// above d, with and without per-summit radii, from unsorted input.
#[test]
fn gw_empirical_sums() {
    let z = vec![0.3e-6, -1.0e-6, 1.2e-6, 0.0, 2.0e-6];
    let m = z.len() as f64;
    let gw = GreenwoodWilliamson::new(
        N,
        R,
        E_STAR,
        HeightDistribution::empirical(z.clone()).unwrap(),
    )
    .unwrap();
    let d = 0.1e-6;
    let over: Vec<f64> = z.iter().filter(|&&x| x > d).map(|x| x - d).collect();
    let load: f64 = over.iter().map(|w| w.powf(1.5)).sum::<f64>() * 4.0 / 3.0 * E_STAR * R.sqrt();
    let area: f64 = over.iter().sum::<f64>() * PI * R;
    let r = gw.response(d).unwrap();
    assert_relative_eq!(r.load, N / m * load, max_relative = 1e-14);
    assert_relative_eq!(r.area, N / m * area, max_relative = 1e-14);
    assert_relative_eq!(r.contacts, N * 3.0 / m, max_relative = 1e-15);
    // At or above the highest summit nothing touches.
    assert_eq!(gw.load(2.0e-6).unwrap(), 0.0);
    assert_eq!(gw.contacts(2.5e-6).unwrap(), 0.0);

    // Per-summit radii replace R.
    let radii = vec![50e-6, 80e-6, 200e-6, 120e-6, 10e-6];
    let e = EmpiricalHeights::with_radii(z.clone(), radii.clone()).unwrap();
    assert_eq!(e.heights(), &[-1.0e-6, 0.0, 0.3e-6, 1.2e-6, 2.0e-6]);
    assert_eq!(e.radii().unwrap(), &[80e-6, 120e-6, 50e-6, 200e-6, 10e-6]);
    let gw = GreenwoodWilliamson::new(N, R, E_STAR, HeightDistribution::Empirical(e)).unwrap();
    let (mut load, mut area) = (0.0, 0.0);
    for (zi, ri) in z.iter().zip(&radii) {
        if *zi > d {
            load += 4.0 / 3.0 * E_STAR * ri.sqrt() * (zi - d).powf(1.5);
            area += PI * ri * (zi - d);
        }
    }
    let r = gw.response(d).unwrap();
    assert_relative_eq!(r.load, N / m * load, max_relative = 1e-14);
    assert_relative_eq!(r.area, N / m * area, max_relative = 1e-14);
}

/// A large deterministic sample of normal quantiles behaves like the Gaussian
/// model (to the sampling error of M = 20 000 summits).
#[test]
fn gw_empirical_sample_approaches_gaussian() {
    let m = 20_000;
    let z: Vec<f64> = (0..m)
        .map(|i| SIGMA * normal_quantile((i as f64 + 0.5) / m as f64))
        .collect();
    let e =
        GreenwoodWilliamson::new(N, R, E_STAR, HeightDistribution::empirical(z).unwrap()).unwrap();
    let g = gaussian_gw();
    for &h in &[-1.0, 0.0, 0.5, 1.0, 2.0] {
        let (a, b) = (
            e.response(h * SIGMA).unwrap(),
            g.response(h * SIGMA).unwrap(),
        );
        let tol = 2e-3 * (1.0 + h.max(0.0).powi(3));
        assert_relative_eq!(a.load, b.load, max_relative = tol);
        assert_relative_eq!(a.area, b.area, max_relative = tol);
        assert_relative_eq!(a.contacts, b.contacts, max_relative = tol);
    }
    assert_relative_eq!(e.heights().std_dev(), SIGMA, max_relative = 2e-3);
}

/// The inverse of (1-29): separation at a given load, over nine decades of
/// load, for the three distributions.
#[test]
fn gw_separation_at_load_round_trip() {
    let exp = GreenwoodWilliamson::new(
        N,
        R,
        E_STAR,
        HeightDistribution::exponential(SIGMA).unwrap(),
    )
    .unwrap();
    let sample: Vec<f64> = (0..500)
        .map(|i| SIGMA * normal_quantile((i as f64 + 0.5) / 500.0))
        .collect();
    let emp =
        GreenwoodWilliamson::new(N, R, E_STAR, HeightDistribution::empirical(sample).unwrap())
            .unwrap();
    let gauss = gaussian_gw();
    let p_ref = gauss.load(0.0).unwrap();
    for (name, model) in [
        ("gaussian", &gauss),
        ("exponential", &exp),
        ("empirical", &emp),
    ] {
        let mut most = 0;
        for k in -6..=3 {
            let target = p_ref * 10f64.powi(k);
            let s = model.separation_at_load(target).unwrap();
            let p = model.load(s.separation).unwrap();
            assert_relative_eq!(p, target, max_relative = 1e-11);
            assert!(s.relative_residual <= 1e-11, "{s:?}");
            assert!(s.iterations <= 60, "{s:?}");
            most = most.max(s.iterations);
        }
        eprintln!("{name}: at most {most} iterations over ten decades of load");
    }
    // Exponential heights invert in closed form above d = −σ.
    let target = exp.load(2.0 * SIGMA).unwrap();
    assert_relative_eq!(
        exp.separation_at_load(target).unwrap().separation,
        2.0 * SIGMA,
        max_relative = 1e-12
    );
    assert!(matches!(
        gauss.separation_at_load(0.0),
        Err(Error::InvalidArgument { name: "load", .. })
    ));
    // A load no finite separation reaches within the bracketing budget.
    assert!(matches!(
        gauss.separation_at_load(1e300),
        Err(Error::OutOfDomain { name: "load", .. })
    ));
}

/// Stiffness is −dP/dd.
#[test]
fn gw_stiffness_is_the_load_derivative() {
    let gw = gaussian_gw();
    for &h in &[-2.0, 0.0, 1.0, 3.0] {
        let e = 1e-6 * SIGMA;
        let d = h * SIGMA;
        let fd = -(gw.load(d + e).unwrap() - gw.load(d - e).unwrap()) / (2.0 * e);
        assert_relative_eq!(gw.stiffness(d).unwrap(), fd, max_relative = 1e-7);
    }
}

/// (1-31): ψ = (E*/H)√(σ/R), and GW's reading (< 0.6 elastic, > 1 plastic).
#[test]
fn plasticity_index_and_regimes() {
    // E* = 100 GPa, H = 2 GPa, σ = 1 µm, R = 100 µm: ψ = 50 · 0.1 = 5.
    assert_relative_eq!(
        plasticity_index(E_STAR, 2e9, SIGMA, R).unwrap(),
        5.0,
        max_relative = 1e-15
    );
    assert_relative_eq!(
        gaussian_gw().plasticity_index(2e9).unwrap(),
        5.0,
        max_relative = 1e-15
    );
    // Polished: σ = 1 nm, R = 1 mm, E*/H = 10 → ψ = 0.01.
    let psi = plasticity_index(10.0, 1.0, 1e-9, 1e-3).unwrap();
    assert_relative_eq!(psi, 0.01, max_relative = 1e-14);
    assert_eq!(
        DeformationRegime::of(psi).unwrap(),
        DeformationRegime::Elastic
    );
    assert_eq!(
        DeformationRegime::of(0.8).unwrap(),
        DeformationRegime::Transitional
    );
    assert_eq!(
        DeformationRegime::of(5.0).unwrap(),
        DeformationRegime::Plastic
    );
    assert!(matches!(
        plasticity_index(E_STAR, -1.0, SIGMA, R),
        Err(Error::InvalidArgument {
            name: "hardness",
            ..
        })
    ));
    // All-equal empirical heights have σ = 0.
    let flat = GreenwoodWilliamson::new(
        N,
        R,
        E_STAR,
        HeightDistribution::empirical(vec![1e-6; 3]).unwrap(),
    )
    .unwrap();
    assert!(matches!(
        flat.plasticity_index(2e9),
        Err(Error::InvalidArgument { name: "sigma", .. })
    ));
}

#[test]
fn gw_invalid_arguments_are_named() {
    let g = HeightDistribution::gaussian(SIGMA).unwrap();
    let named = |r: Result<GreenwoodWilliamson, Error>, want: &str| match r {
        Err(Error::InvalidArgument { name, .. }) => assert_eq!(name, want),
        other => panic!("expected {want}: {other:?}"),
    };
    named(
        GreenwoodWilliamson::new(-1.0, R, E_STAR, g.clone()),
        "summit_count",
    );
    named(
        GreenwoodWilliamson::new(N, 0.0, E_STAR, g.clone()),
        "radius",
    );
    named(
        GreenwoodWilliamson::new(N, R, f64::NAN, g.clone()),
        "e_star",
    );
    named(
        GreenwoodWilliamson::new(N, R, E_STAR, HeightDistribution::Gaussian { sigma: -1.0 }),
        "sigma",
    );
    assert!(matches!(
        HeightDistribution::empirical(vec![]),
        Err(Error::InvalidArgument {
            name: "heights",
            ..
        })
    ));
    assert!(matches!(
        HeightDistribution::empirical(vec![0.0, f64::NAN]),
        Err(Error::InvalidArgument {
            name: "heights",
            ..
        })
    ));
    assert!(matches!(
        EmpiricalHeights::with_radii(vec![0.0, 1.0], vec![1.0]),
        Err(Error::InvalidArgument { name: "radii", .. })
    ));
    assert!(matches!(
        gaussian_gw().load(f64::INFINITY),
        Err(Error::InvalidArgument {
            name: "separation",
            ..
        })
    ));
}

// ---------------------------------------------------------------------------
// Zhuravlev

const ALPHA: f64 = 1e16; // summits per m² of depth: n(ξ) = αξ
const NU: f64 = 0.3;
const E: f64 = 200e9;

fn zhuravlev() -> Zhuravlev {
    Zhuravlev::new(R, E / (2.0 * (1.0 - NU * NU)), N).unwrap()
}

/// (1-25), (1-26) in the thesis's own form: `P = √2 R^{1/2} E α² x^{11/2}
/// Γ(5/2)/(3(1−ν²) N Γ(13/2))` with `Γ(13/2)/Γ(5/2) = 216.5625`, and
/// `S = π (R/2) α² x⁵/(120 N)`; contacting pairs `α² x⁴/(24 N)`.
#[test]
fn zhuravlev_linear_closed_forms() {
    let z = zhuravlev();
    let x = 0.4e-6;
    let r = z.linear(ALPHA, ALPHA, x).unwrap();
    let load = 2f64.sqrt() * R.sqrt() * E * ALPHA * ALPHA * x.powf(5.5)
        / (3.0 * (1.0 - NU * NU) * N * 216.5625);
    assert_relative_eq!(r.load, load, max_relative = 1e-13);
    assert_relative_eq!(
        r.area,
        PI * R / 2.0 * ALPHA * ALPHA * x.powi(5) / (120.0 * N),
        max_relative = 1e-13
    );
    assert_relative_eq!(
        r.contacts,
        ALPHA * ALPHA * x.powi(4) / (24.0 * N),
        max_relative = 1e-13
    );
}

/// REFERENCE §3: P ∝ x^{11/2}, S ∝ x⁵, F ∝ P^{10/11}, μ ∝ P^{−1/11}.
#[test]
fn zhuravlev_exponents() {
    assert_eq!((LOAD_EXPONENT, AREA_EXPONENT), (5.5, 5.0));
    assert_relative_eq!(FRICTION_LOAD_EXPONENT, 10.0 / 11.0);
    let z = zhuravlev();
    let (a, b) = (
        z.linear(ALPHA, ALPHA, 0.3e-6).unwrap(),
        z.linear(ALPHA, ALPHA, 0.6e-6).unwrap(),
    );
    assert_relative_eq!((b.load / a.load).log2(), 5.5, max_relative = 1e-13);
    assert_relative_eq!((b.area / a.area).log2(), 5.0, max_relative = 1e-13);
    assert_relative_eq!((b.contacts / a.contacts).log2(), 4.0, max_relative = 1e-13);
    let tau = 50e6;
    let f1 = z.friction_linear(ALPHA, ALPHA, 1.0, tau).unwrap();
    let f2 = z.friction_linear(ALPHA, ALPHA, 1000.0, tau).unwrap();
    assert_relative_eq!(
        (f2.friction_force / f1.friction_force).log10(),
        3.0 * 10.0 / 11.0,
        max_relative = 1e-12
    );
    assert_relative_eq!(
        (f2.coefficient / f1.coefficient).log10(),
        -3.0 / 11.0,
        max_relative = 1e-12
    );
    // (1-28): F = τ C₂ (P/C₁)^{10/11} with C₁, C₂ the x-coefficients.
    let c1 = z.linear(ALPHA, ALPHA, 1.0).unwrap();
    assert_relative_eq!(
        f1.friction_force,
        tau * c1.area * (1.0 / c1.load).powf(10.0 / 11.0),
        max_relative = 1e-12
    );
    assert_relative_eq!(
        f1.coefficient,
        f1.friction_force / f1.load,
        max_relative = 1e-15
    );
    // The approach carries the load.
    assert_relative_eq!(
        z.linear(ALPHA, ALPHA, f2.approach).unwrap().load,
        1000.0,
        max_relative = 1e-12
    );
}

/// (1-23), (1-24) by quadrature against closed forms: the linear density, and
/// `n(ξ) = βξ²`, whose convolution is `β² s⁵/30` so that
/// `I_q(x) = 4 β² x^{q+6} Γ(q+1)/Γ(q+7)`.
#[test]
fn zhuravlev_quadrature_matches_closed_forms() {
    let z = zhuravlev();
    let x = 0.5e-6;
    let lin = |s: f64| ALPHA * s;
    let q = z.response(x, lin, lin, 24).unwrap();
    let c = z.linear(ALPHA, ALPHA, x).unwrap();
    assert_relative_eq!(q.load, c.load, max_relative = 1e-9);
    assert_relative_eq!(q.area, c.area, max_relative = 1e-12);
    assert_relative_eq!(q.contacts, c.contacts, max_relative = 1e-12);

    let beta = 1e22;
    let quad = |s: f64| beta * s * s;
    let r = z.response(x, quad, quad, 32).unwrap();
    let gamma = |v: f64| libm::tgamma(v);
    let i = |q: f64| 4.0 * beta * beta * x.powf(q + 6.0) * gamma(q + 1.0) / gamma(q + 7.0);
    let reff = R / 2.0;
    let e_star = E / (2.0 * (1.0 - NU * NU));
    assert_relative_eq!(
        r.load,
        4.0 / 3.0 * e_star * reff.sqrt() / N * i(1.5),
        max_relative = 1e-9
    );
    assert_relative_eq!(r.area, PI * reff / N * i(1.0), max_relative = 1e-12);
    assert_relative_eq!(r.contacts, i(0.0) / N, max_relative = 1e-12);
    // A negative density is refused.
    assert!(matches!(
        z.response(x, |s| -s, lin, 16),
        Err(Error::OutOfDomain { .. })
    ));
}

#[test]
fn zhuravlev_inverse_and_arguments() {
    let z = zhuravlev();
    for &x in &[1e-9, 0.2e-6, 3e-6] {
        let p = z.linear(ALPHA, ALPHA, x).unwrap().load;
        assert_relative_eq!(
            z.approach_at_load_linear(ALPHA, ALPHA, p).unwrap(),
            x,
            max_relative = 1e-13
        );
    }
    assert_eq!(z.approach_at_load_linear(ALPHA, ALPHA, 0.0).unwrap(), 0.0);
    assert!(matches!(
        Zhuravlev::new(-R, E, N),
        Err(Error::InvalidArgument {
            name: "cap_radius",
            ..
        })
    ));
    assert!(matches!(
        z.linear(0.0, ALPHA, 1e-6),
        Err(Error::InvalidArgument { name: "alpha1", .. })
    ));
    assert!(matches!(
        z.linear(ALPHA, ALPHA, -1e-6),
        Err(Error::InvalidArgument {
            name: "approach",
            ..
        })
    ));
    assert!(matches!(
        z.friction_linear(ALPHA, ALPHA, 1.0, -1.0),
        Err(Error::InvalidArgument {
            name: "shear_strength",
            ..
        })
    ));
}

// ---------------------------------------------------------------------------
// Kragelsky

/// Rods on Gaussian heights: `P = N k σ F₁(d/σ)`, `A = N A_rod F₀(d/σ)`; on
/// exponential heights the area is exactly proportional to the load,
/// `P/A = kσ/A_rod` for d ≥ −σ.
#[test]
fn kragelsky_rods_gaussian_and_exponential() {
    let (n, a_rod, len, e) = (1e4, 1e-10, 5e-6, 120e9);
    let k = e * a_rod / len;
    let g = KragelskyRods::from_material(
        n,
        a_rod,
        len,
        e,
        HeightDistribution::gaussian(SIGMA).unwrap(),
    )
    .unwrap();
    assert_relative_eq!(g.rod_stiffness(), k, max_relative = 1e-15);
    for &h in &[-2.0, 0.0, 1.0, 3.0] {
        let r = g.response(h * SIGMA).unwrap();
        assert_relative_eq!(r.load, n * k * SIGMA * f1(h).unwrap(), max_relative = 1e-14);
        assert_relative_eq!(r.area, n * a_rod * f0(h).unwrap(), max_relative = 1e-14);
        assert_relative_eq!(r.contacts, n * f0(h).unwrap(), max_relative = 1e-14);
    }
    // REFERENCE §3 at d = σ: F₁ = 0.08331547059.
    assert_relative_eq!(
        g.load(SIGMA).unwrap(),
        n * k * SIGMA * 0.08331547059,
        max_relative = 1e-10
    );
    let x =
        KragelskyRods::new(n, a_rod, k, HeightDistribution::exponential(SIGMA).unwrap()).unwrap();
    for &h in &[-1.0, 0.0, 2.0, 5.0] {
        let r = x.response(h * SIGMA).unwrap();
        assert_relative_eq!(r.mean_pressure(), k * SIGMA / a_rod, max_relative = 1e-13);
    }
    for &frac in &[1e-3, 0.1, 0.5] {
        let target = n * k * SIGMA * frac;
        for model in [&g, &x] {
            let s = model.separation_at_load(target).unwrap();
            assert_relative_eq!(
                model.load(s.separation).unwrap(),
                target,
                max_relative = 1e-11
            );
        }
    }
}

/// The bearing-curve closed form (5-7), `A_r = A_c b ε^ν`,
/// `N = K A_c b R_max ε^{ν+1}/(ν+1)`, against a direct sum over rods whose
/// depths below the top are the quantiles of the curve
/// (ξ_i = R_max((i + ½)/M)^{1/ν}).
#[test]
fn kragelsky_bearing_curve_matches_rod_sum() {
    let (ac, kk, nu, rmax, a_rod) = (1e-6, 2.4e16, 2.0, 2e-6, 1e-12);
    let bc = BearingCurveRods::new(ac, kk, 1.0, nu, rmax, a_rod).unwrap();
    let m = 100_000;
    let z: Vec<f64> = (0..m)
        .map(|i| -rmax * ((i as f64 + 0.5) / m as f64).powf(1.0 / nu))
        .collect();
    let rods = KragelskyRods::new(
        ac / a_rod,
        a_rod,
        kk * a_rod,
        HeightDistribution::empirical(z).unwrap(),
    )
    .unwrap();
    for &eps in &[0.1, 0.3, 0.6] {
        let a = eps * rmax;
        let closed = bc.response(a).unwrap();
        assert_relative_eq!(closed.area, ac * eps.powf(nu), max_relative = 1e-14);
        assert_relative_eq!(
            closed.load,
            kk * ac * rmax * eps.powf(nu + 1.0) / (nu + 1.0),
            max_relative = 1e-14
        );
        let sum = rods.response(-a).unwrap();
        assert_relative_eq!(sum.load, closed.load, max_relative = 2e-3);
        assert_relative_eq!(sum.area, closed.area, max_relative = 2e-3);
        assert_relative_eq!(sum.contacts, closed.contacts, max_relative = 2e-3);
        assert_relative_eq!(
            bc.approach_at_load(closed.load).unwrap(),
            a,
            max_relative = 1e-13
        );
    }
    // Beyond the curve (b ε^ν > 1) the model does not apply.
    let half = BearingCurveRods::new(ac, kk, 4.0, nu, rmax, a_rod).unwrap();
    assert!(matches!(
        half.response(0.6 * rmax),
        Err(Error::OutOfDomain {
            name: "approach",
            ..
        })
    ));
    assert!(matches!(
        BearingCurveRods::new(ac, kk, 1.0, 0.0, rmax, a_rod),
        Err(Error::InvalidArgument { name: "nu", .. })
    ));
}

// ---------------------------------------------------------------------------
// Power-law asperities through rescaling (3-27), (3-28)

/// κ = 1, d = 2 is Hertz: the power-law extension equals Greenwood–Williamson
/// (from Galin's sphere and from a Hertz known solution rescaled to R) and
/// Zhuravlev (with the pair's effective radius).
#[test]
fn power_law_sphere_reduces_to_gw_and_zhuravlev() {
    let from_galin = PowerLawAsperities::sphere(R, E_STAR).unwrap();
    // Hertz solution on R₁ = 1 mm at δ₁ = 1 µm, rescaled by λ = R₁/R (3-15).
    let r1: f64 = 1e-3;
    let delta1: f64 = 1e-6;
    let known = KnownSolution::new(
        4.0 / 3.0 * E_STAR * r1.sqrt() * delta1.powf(1.5),
        delta1,
        (r1 * delta1).sqrt(),
    )
    .unwrap();
    let from_hertz =
        PowerLawAsperities::new(Rescaling::sphere(1.0).unwrap(), r1 / R, known).unwrap();
    assert_eq!(from_galin.exponent(), 1.5);
    assert_eq!(from_galin.area_exponent(), 1.0);
    let sample: Vec<f64> = (0..200)
        .map(|i| SIGMA * ((i as f64) * 0.37).sin())
        .collect();
    for heights in [
        HeightDistribution::gaussian(SIGMA).unwrap(),
        HeightDistribution::exponential(SIGMA).unwrap(),
        HeightDistribution::empirical(sample).unwrap(),
    ] {
        let gw = GreenwoodWilliamson::new(N, R, E_STAR, heights.clone()).unwrap();
        for &h in &[-1.5, 0.0, 0.8, 2.5] {
            let want = gw.response(h * SIGMA).unwrap();
            for model in [&from_galin, &from_hertz] {
                let got = model.greenwood_williamson(N, &heights, h * SIGMA).unwrap();
                assert_relative_eq!(got.load, want.load, max_relative = 1e-12);
                assert_relative_eq!(got.area, want.area, max_relative = 1e-12);
                assert_relative_eq!(got.contacts, want.contacts, max_relative = 1e-15);
            }
        }
    }
    // Zhuravlev: a pair of caps R is the power-law asperity with R_eff = R/2.
    let pair = PowerLawAsperities::sphere(R / 2.0, E_STAR).unwrap();
    let z = Zhuravlev::new(R, E_STAR, N).unwrap();
    let x = 0.7e-6;
    let want = z.linear(ALPHA, ALPHA, x).unwrap();
    let got = pair.zhuravlev_linear(N, ALPHA, ALPHA, x).unwrap();
    assert_relative_eq!(got.load, want.load, max_relative = 1e-12);
    assert_relative_eq!(got.area, want.area, max_relative = 1e-12);
    assert_relative_eq!(got.contacts, want.contacts, max_relative = 1e-14);
    let lin = |s: f64| ALPHA * s;
    let quad = pair.zhuravlev(N, x, lin, lin, 24).unwrap();
    assert_relative_eq!(quad.load, want.load, max_relative = 1e-9);
}

/// Linear elastic power-law asperities (3-27): one asperity follows Galin,
/// `P = C(d) B E* a^{d+1}`, `δ = D(d) B a^d`; the Zhuravlev sum goes as
/// `x^{(d+1)/d + 4}`; the λ exponent of the load is `−1/d`.
#[test]
fn power_law_elastic_3_27() {
    let (b, d) = (2e5, 3.0);
    let p = PowerLawAsperities::elastic(b, d, E_STAR).unwrap();
    assert_relative_eq!(p.exponent(), 4.0 / 3.0, max_relative = 1e-15);
    for &a in &[1e-8f64, 1e-7, 1e-6] {
        let delta = galin_d(d) * b * a.powf(d);
        assert_relative_eq!(
            p.asperity_load(delta).unwrap(),
            galin_c(d) * b * E_STAR * a.powf(d + 1.0),
            max_relative = 1e-12
        );
        assert_relative_eq!(
            p.asperity_contact_radius(delta).unwrap(),
            a,
            max_relative = 1e-12
        );
    }
    let (u, v) = (
        p.zhuravlev_linear(N, ALPHA, ALPHA, 0.2e-6).unwrap(),
        p.zhuravlev_linear(N, ALPHA, ALPHA, 0.4e-6).unwrap(),
    );
    assert_relative_eq!(
        (v.load / u.load).log2(),
        4.0 / 3.0 + 4.0,
        max_relative = 1e-12
    );
    assert_relative_eq!(
        (v.area / u.area).log2(),
        2.0 / 3.0 + 4.0,
        max_relative = 1e-12
    );
    // A blunter asperity (B twice as large, λ = 2) carries 2^{−1/d} less load
    // at the same depth, (3-24) with κ = 1 — equivalently Galin with 2B.
    let known = KnownSolution::new(galin_c(d) * b * E_STAR, galin_d(d) * b, 1.0).unwrap();
    let blunt = PowerLawAsperities::new(Rescaling::new(1.0, d).unwrap(), 2.0, known).unwrap();
    let direct = PowerLawAsperities::elastic(2.0 * b, d, E_STAR).unwrap();
    for &w in &[1e-9, 1e-7] {
        let (x, y) = (blunt.asperity_load(w).unwrap(), p.asperity_load(w).unwrap());
        assert_relative_eq!(x / y, 2f64.powf(-1.0 / d), max_relative = 1e-13);
        assert_relative_eq!(x, direct.asperity_load(w).unwrap(), max_relative = 1e-12);
        assert_relative_eq!(
            blunt.asperity_contact_radius(w).unwrap(),
            direct.asperity_contact_radius(w).unwrap(),
            max_relative = 1e-12
        );
    }
}

/// Nonlinear material (3-28): κ = 0.5 on spheres gives the integrand
/// exponent `(2 + κ(d−1))/d = 1.25`; the Greenwood–Williamson-type load is
/// `N λ^{(κ−2)/d}(P₁/δ₁^q) σ^q F_{1.25}(d/σ)` with F_{1.25} from the 40-digit
/// reference (F_{1.25}(0) = 0.40970482411012343, F_{1.25}(1) =
/// 0.07835825990143316), and the Zhuravlev-type load goes as x^{5.25}.
#[test]
fn power_law_nonlinear_3_28() {
    let known = KnownSolution::new(2310.0, 0.224e-3, 0.4e-3).unwrap();
    let r = Rescaling::sphere(0.5).unwrap();
    let lambda = 3.0;
    let p = PowerLawAsperities::new(r, lambda, known).unwrap();
    assert_relative_eq!(p.exponent(), 1.25, max_relative = 1e-15);
    let c = lambda.powf((0.5 - 2.0) / 2.0) * 2310.0 / 0.224e-3f64.powf(1.25);
    let g = HeightDistribution::gaussian(SIGMA).unwrap();
    for (h, f) in [(0.0, 0.40970482411012343), (1.0, 0.07835825990143316)] {
        let got = p.greenwood_williamson(N, &g, h * SIGMA).unwrap();
        assert_relative_eq!(got.load, N * c * SIGMA.powf(1.25) * f, max_relative = 1e-11);
        assert_relative_eq!(got.contacts, N * f0(h).unwrap(), max_relative = 1e-14);
    }
    let (u, v) = (
        p.zhuravlev_linear(N, ALPHA, ALPHA, 1e-6).unwrap(),
        p.zhuravlev_linear(N, ALPHA, ALPHA, 3e-6).unwrap(),
    );
    assert_relative_eq!(
        (v.load / u.load).ln() / 3f64.ln(),
        5.25,
        max_relative = 1e-12
    );
    // (3-24): P(w) = λ^{(κ−2)/d} P₁ (w/δ₁)^q.
    assert_relative_eq!(
        p.asperity_load(0.1e-3).unwrap(),
        c * 0.1e-3f64.powf(1.25),
        max_relative = 1e-13
    );
    // Load integrals stay those of the Gaussian: F_{3/2} for Hertz.
    let hertz = PowerLawAsperities::sphere(R, E_STAR).unwrap();
    let got = hertz.greenwood_williamson(N, &g, SIGMA).unwrap();
    assert_relative_eq!(
        got.load,
        4.0 / 3.0 * N * E_STAR * R.sqrt() * SIGMA.powf(1.5) * f3_2(1.0).unwrap(),
        max_relative = 1e-12
    );
}
