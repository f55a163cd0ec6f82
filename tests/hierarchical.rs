//! Hierarchical roughness (thesis 5.4): Archard's exponent sequences
//! (Archard 1957: 2/3, 8/9, 26/27 and 4/5, 14/15, 44/45, → 1), his
//! load–area law against explicit sums over discrete spheres, and the
//! Cantor profiles' contact against an explicit profile, with the
//! self-similar power law P ∝ δ^{1+β}, β = ln(pr)/ln q, of Cantor–Borodich
//! and the proportional load–area law of Cantor–Liu.

use asperity::ffi::hierarchical::*;
use asperity::ffi::ASPERITY_OK;
use asperity::hierarchical::{
    archard_exponent, Archard, ArchardModel, CantorContact, CantorProfile,
};
use asperity::Error;
use std::f64::consts::PI;

fn name(e: Error) -> &'static str {
    match e {
        Error::InvalidArgument { name, .. }
        | Error::UnknownSelector { name, .. }
        | Error::NullPointer { name } => name,
        other => panic!("unexpected {other:?}"),
    }
}

const E: f64 = 1e11;

#[test]
fn archard_exponents_are_his_sequences_and_tend_to_one() {
    // Archard (1957), Fig. 3: equal heights 2/3, 8/9, 26/27; protuberances
    // at distributed heights 4/5, 14/15, 44/45.
    let uniform = [2.0 / 3.0, 8.0 / 9.0, 26.0 / 27.0, 80.0 / 81.0];
    let non_uniform = [4.0 / 5.0, 14.0 / 15.0, 44.0 / 45.0, 134.0 / 135.0];
    let radii = [1e-2, 1e-4, 1e-6, 1e-8, 1e-10];
    let dens = [1e9, 1e13, 1e17, 1e21];
    for (model, want, first) in [
        (ArchardModel::Uniform, &uniform, 1),
        (ArchardModel::NonUniform, &non_uniform, 2),
    ] {
        let mut last_gap = 1.0;
        for (i, &a) in want.iter().enumerate() {
            let n = first + i;
            assert!((archard_exponent(model, n).unwrap() - a).abs() < 1e-15);
            let m = Archard::new(model, &radii[..n], &dens[..n - 1], E).unwrap();
            assert!((m.exponent() - a).abs() < 1e-15);
            // The slope of the computed area over six decades of load.
            let (w1, w2) = (1e-3, 1e3);
            let slope = (m.area(w2).unwrap() / m.area(w1).unwrap()).ln() / (w2 / w1).ln();
            assert!(
                (slope - a).abs() < 1e-12,
                "{model:?} n = {n}: slope {slope} vs {a}"
            );
            // Each generation divides 1 − a by 3.
            let gap = 1.0 - a;
            assert!(gap < last_gap);
            if i > 0 {
                assert!((last_gap / gap - 3.0).abs() < 1e-9);
            }
            last_gap = gap;
        }
        let deep = archard_exponent(model, 30).unwrap();
        assert!(1.0 - deep < 1e-13, "{model:?}: {deep}");
    }
}

#[test]
fn archard_single_sphere_is_hertz() {
    let r = 5e-3;
    let m = Archard::new(ArchardModel::Uniform, &[r], &[], E).unwrap();
    for w in [1e-6, 1e-3, 1.0, 1e3] {
        let a = (3.0 * w * r / (4.0 * E)).cbrt();
        let want = PI * a * a;
        assert!((m.area(w).unwrap() - want).abs() <= 1e-13 * want);
    }
}

/// Points of a square lattice of density `eta` (1/m²) within radius `a`.
fn lattice(eta: f64, a: f64) -> Vec<f64> {
    let s = 1.0 / eta.sqrt();
    let m = (a / s).ceil() as i64;
    let mut r2 = vec![];
    for i in -m..=m {
        for j in -m..=m {
            // Cell centres, so the lattice is unbiased.
            let (x, y) = ((i as f64 + 0.5) * s, (j as f64 + 0.5) * s);
            if x * x + y * y < a * a {
                r2.push(x * x + y * y);
            }
        }
    }
    r2
}

#[test]
fn archard_two_generations_equal_the_sum_over_discrete_spheres() {
    // Uniform: small Hertz spheres on a square lattice under the large
    // sphere's Hertz pressure, each carrying p(r)/η; many spheres in the
    // contact (η π a² ≈ 3e5), so the sum converges to Archard's integral.
    let (r1, r2, eta) = (1e-2, 1e-5, 1e12);
    let m = Archard::new(ArchardModel::Uniform, &[r1, r2], &[eta], E).unwrap();
    for w in [10.0, 1e3] {
        let a = (3.0 * w * r1 / (4.0 * E)).cbrt();
        let p0 = 3.0 * w / (2.0 * PI * a * a);
        let sum: f64 = lattice(eta, a)
            .iter()
            .map(|&q| {
                let wi = p0 * (1.0 - q / (a * a)).sqrt() / eta;
                PI * (3.0 * wi * r2 / (4.0 * E)).powf(2.0 / 3.0)
            })
            .sum();
        let got = m.area(w).unwrap();
        assert!(
            (got - sum).abs() <= 2e-3 * sum,
            "W = {w}: {got} vs sum {sum}"
        );
    }
    // Non-uniform: protuberances on the rigid sphere, compressed by
    // δ₀ − r²/2R₁ each; W and A summed, then compared through A(W).
    let (r1, r2, eta) = (1e-2, 1e-6, 1e14);
    let m = Archard::new(ArchardModel::NonUniform, &[r1, r2], &[eta], E).unwrap();
    for d0 in [1e-9, 1e-8] {
        let reach = (2.0 * r1 * d0).sqrt();
        let (mut w, mut area) = (0.0, 0.0);
        for q in lattice(eta, reach) {
            let d = d0 - q / (2.0 * r1);
            w += 4.0 / 3.0 * E * r2.sqrt() * d.powf(1.5);
            area += PI * r2 * d;
        }
        let got = m.area(w).unwrap();
        assert!(
            (got - area).abs() <= 2e-3 * area,
            "δ₀ = {d0}: {got} vs sum {area}"
        );
    }
}

#[test]
fn archard_bad_input_names_the_argument() {
    let a = |m, r: &[f64], d: &[f64], e| Archard::new(m, r, d, e).map(|_| ());
    use ArchardModel::*;
    assert_eq!(name(a(Uniform, &[], &[], E).unwrap_err()), "radii.len()");
    assert_eq!(
        name(a(NonUniform, &[1.0], &[], E).unwrap_err()),
        "radii.len()"
    );
    assert_eq!(
        name(a(Uniform, &[1.0, 0.1], &[], E).unwrap_err()),
        "densities.len()"
    );
    assert_eq!(
        name(a(Uniform, &[1.0, 2.0], &[1.0], E).unwrap_err()),
        "radii"
    );
    assert_eq!(
        name(a(Uniform, &[1.0, 0.1], &[-1.0], E).unwrap_err()),
        "densities"
    );
    assert_eq!(
        name(a(Uniform, &[1.0], &[], 0.0).unwrap_err()),
        "contact_modulus"
    );
    let m = Archard::new(Uniform, &[1.0], &[], E).unwrap();
    assert_eq!(name(m.area(-1.0).unwrap_err()), "load");
    assert_eq!(m.area(0.0).unwrap(), 0.0);
    assert_eq!(name(ArchardModel::from_i32(2).unwrap_err()), "model");
}

fn borodich(p: u32, r: f64, q: f64, n: u32) -> CantorProfile {
    CantorProfile {
        descendants: p,
        generations: n,
        width_ratio: r,
        height_ratio: q,
        base_width: 1e-3,
        base_height: 1e-5,
    }
}

/// The profile's height at x (m) in [0, w₀), built block by block: an
/// explicit construction independent of the contact sums.
fn height(p: &CantorProfile, x: f64) -> Option<f64> {
    let (mut left, mut width, mut step, mut h) = (0.0, p.base_width, p.base_height, 0.0);
    if !(0.0..width).contains(&x) {
        return None;
    }
    h += step;
    for _ in 0..p.generations {
        // p children of width r w, spread evenly (equal gaps between them
        // and at the ends).
        let cw = width * p.width_ratio;
        let gap = (width - p.descendants as f64 * cw) / (p.descendants as f64 + 1.0);
        let mut inside = None;
        for c in 0..p.descendants {
            let l = left + gap + c as f64 * (cw + gap);
            if (l..l + cw).contains(&x) {
                inside = Some(l);
            }
        }
        match inside {
            Some(l) => {
                left = l;
                width = cw;
                step *= p.height_ratio;
                h += step;
            }
            None => break,
        }
    }
    Some(h)
}

#[test]
fn cantor_contact_equals_the_explicit_profile() {
    // Warren–Krajcinovic's three descendants, five generations: the
    // Winkler load κ ∫ (δ − depth(x))⁺ dx and the contact width by
    // quadrature over the explicit profile.
    let p = CantorProfile {
        descendants: 3,
        generations: 5,
        width_ratio: 0.2,
        height_ratio: 0.6,
        base_width: 1.0,
        base_height: 1.0,
    };
    // Every block edge on a cell boundary: edges at multiples of
    // 0.1 × 5⁻⁵ (the gaps are a tenth of the parent's width).
    let m = 8 * 5usize.pow(7);
    let dx = p.base_width / m as f64;
    let hs: Vec<f64> = (0..m)
        .map(|i| height(&p, (i as f64 + 0.5) * dx).unwrap())
        .collect();
    let top = hs.iter().cloned().fold(0.0, f64::max);
    let kappa = 2e9;
    for d in [0.01, 0.05, 0.2, 0.5, 1.0, 1.7, 2.5] {
        let c = p.contact(d, kappa, 3e8).unwrap();
        let (mut load, mut width) = (0.0, 0.0);
        for &h in &hs {
            let pen = d - (top - h);
            if pen >= 0.0 {
                load += kappa * pen * dx;
                width += dx;
            }
        }
        assert!(
            (c.winkler_load - load).abs() <= 1e-9 * load,
            "δ = {d}: {} vs {load}",
            c.winkler_load
        );
        assert!(
            (c.width - width).abs() <= 1e-9 * width,
            "δ = {d}: {} vs {width}",
            c.width
        );
        assert!((c.plastic_load - 3e8 * c.width).abs() <= 1e-15 * c.plastic_load);
    }
}

#[test]
fn cantor_borodich_contact_is_a_power_law_set_by_the_height_ratio() {
    // Borodich's two descendants, many generations: P(qδ) = prq P(δ),
    // A(qδ) = pr A(δ), so P ∝ δ^{1+β} and A ∝ P^{β/(1+β)} over every
    // period of the log-periodic oscillation.
    for (r, q) in [(1.0 / 3.0, 0.5), (0.3, 0.7), (0.45, 0.25)] {
        let p = borodich(2, r, q, 120);
        let beta = (2.0 * r).ln() / q.ln();
        assert!((p.width_exponent() - beta).abs() < 1e-15);
        let c = |d: f64| p.contact(d, 1e10, 1e9).unwrap();
        let h0 = p.base_height;
        for k in 4..30 {
            let d = h0 * q.powi(k) * 1.37;
            let (a, b) = (c(d), c(q * d));
            let lp = (a.winkler_load / b.winkler_load).ln() / (1.0 / q).ln();
            let la = (a.width / b.width).ln() / (1.0 / q).ln();
            assert!(
                (lp - (1.0 + beta)).abs() < 1e-9,
                "r = {r}, q = {q}, k = {k}: {lp} vs {}",
                1.0 + beta
            );
            assert!((la - beta).abs() < 1e-9, "{la} vs {beta}");
            let lap = (a.width / b.width).ln() / (a.winkler_load / b.winkler_load).ln();
            assert!((lap - p.load_area_exponent()).abs() < 1e-9);
        }
        // A least-squares fit over six decades of depth finds the exponent
        // to within the log-periodic wobble.
        let pts: Vec<(f64, f64)> = (0..200)
            .map(|i| {
                let d = h0 * 1e-7 * 10f64.powf(6.0 * i as f64 / 199.0);
                (d.ln(), c(d).winkler_load.ln())
            })
            .collect();
        let n = pts.len() as f64;
        let (sx, sy) = pts.iter().fold((0.0, 0.0), |(a, b), (x, y)| (a + x, b + y));
        let (mx, my) = (sx / n, sy / n);
        let (sxy, sxx) = pts.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
            (a + (x - mx) * (y - my), b + (x - mx) * (x - mx))
        });
        let slope = sxy / sxx;
        assert!(
            (slope - (1.0 + beta)).abs() < 0.03 * (1.0 + beta),
            "fit {slope} vs {}",
            1.0 + beta
        );
    }
    // Borodich and Onishchenko: the same fractal dimension (p = 2, r = 1/3)
    // with another height ratio contacts with another exponent.
    let (a, b) = (
        borodich(2, 1.0 / 3.0, 0.5, 80),
        borodich(2, 1.0 / 3.0, 0.8, 80),
    );
    assert_eq!(a.fractal_dimension(), b.fractal_dimension());
    assert!((a.load_area_exponent() - b.load_area_exponent()).abs() > 0.1);
}

#[test]
fn cantor_liu_load_tends_to_proportional_to_area() {
    // Equal height steps (q = 1): A grows by 1/(pr) per h₀ of depth and
    // P/A → κ h₀ (pr/(1 − pr) + 1/2) at depths (m + 1/2) h₀ (the tops of
    // the shallowest generation in contact half a step above the depth).
    let p = borodich(3, 0.25, 1.0, 40);
    let (kappa, h0, pr) = (1e9, p.base_height, 0.75);
    let want = kappa * h0 * (pr / (1.0 - pr) + 0.5);
    let mut last = f64::INFINITY;
    for m in [5.5, 10.5, 20.5, 30.5] {
        let c = p.contact(m * h0, kappa, 0.0).unwrap();
        let ratio = c.winkler_load / c.width;
        let err = (ratio - want).abs() / want;
        assert!(err < last, "not converging at {m}: {ratio} vs {want}");
        last = err;
    }
    assert!(last < 1e-3, "{last}");
    assert_eq!(p.load_area_exponent(), 1.0);
}

#[test]
fn plesha_ni_layers_in_series() {
    // q = pr: every layer has the same h_k/A_k, so Δ/P = (n + 1) h₀/(E w₀).
    let p = borodich(2, 0.3, 0.6, 7);
    let e = 7e10;
    let c = p.series_compliance(e).unwrap();
    let want = 8.0 * p.base_height / (e * p.base_width);
    assert!((c - want).abs() <= 1e-14 * want);
    assert_eq!(name(p.series_compliance(0.0).unwrap_err()), "modulus");
}

#[test]
fn cantor_bad_input_names_the_field() {
    let ok = borodich(2, 0.3, 0.5, 10);
    for (bad, field) in [
        (
            CantorProfile {
                descendants: 1,
                ..ok
            },
            "descendants",
        ),
        (
            CantorProfile {
                generations: 0,
                ..ok
            },
            "generations",
        ),
        (
            CantorProfile {
                width_ratio: 0.5,
                ..ok
            },
            "width_ratio",
        ),
        (
            CantorProfile {
                height_ratio: 1.5,
                ..ok
            },
            "height_ratio",
        ),
        (
            CantorProfile {
                height_ratio: 0.0,
                ..ok
            },
            "height_ratio",
        ),
        (
            CantorProfile {
                base_width: f64::NAN,
                ..ok
            },
            "base_width",
        ),
        (
            CantorProfile {
                base_height: -1.0,
                ..ok
            },
            "base_height",
        ),
    ] {
        assert_eq!(name(bad.contact(1e-6, 1.0, 1.0).unwrap_err()), field);
    }
    assert_eq!(name(ok.contact(-1e-6, 1.0, 1.0).unwrap_err()), "depth");
    assert_eq!(name(ok.contact(1e-6, -1.0, 1.0).unwrap_err()), "stiffness");
}

#[test]
fn the_c_functions_equal_the_rust_api() {
    let radii = [1e-2, 1e-5, 1e-8];
    let dens = [1e12, 1e16];
    let loads = [0.0, 1e-3, 1.0, 1e3];
    let mut areas = [0.0; 4];
    let st = unsafe {
        asperity_archard_area_batch(
            ASPERITY_ARCHARD_NON_UNIFORM,
            radii.as_ptr(),
            dens.as_ptr(),
            3,
            E,
            4,
            loads.as_ptr(),
            areas.as_mut_ptr(),
        )
    };
    assert_eq!(st, ASPERITY_OK);
    let m = Archard::new(ArchardModel::NonUniform, &radii, &dens, E).unwrap();
    for (w, a) in loads.iter().zip(&areas) {
        assert_eq!(a.to_bits(), m.area(*w).unwrap().to_bits());
    }
    let mut x = 0.0;
    assert_eq!(
        unsafe { asperity_archard_exponent(ASPERITY_ARCHARD_UNIFORM, 3, &mut x) },
        ASPERITY_OK
    );
    assert!((x - 26.0 / 27.0).abs() < 1e-15);
    assert_ne!(
        unsafe { asperity_archard_exponent(7, 3, &mut x) },
        ASPERITY_OK
    );
    // A bad load at element 2: elements 0, 1 written, the rest untouched.
    let bad = [1.0, 2.0, -1.0, 3.0];
    let mut out = [-5.0; 4];
    let st = unsafe {
        asperity_archard_area_batch(
            0,
            radii.as_ptr(),
            dens.as_ptr(),
            3,
            E,
            4,
            bad.as_ptr(),
            out.as_mut_ptr(),
        )
    };
    assert_ne!(st, ASPERITY_OK);
    assert!(out[0] > 0.0 && out[1] > 0.0 && out[2] == -5.0 && out[3] == -5.0);

    let p = borodich(2, 1.0 / 3.0, 0.5, 30);
    let depths = [0.0, 1e-8, 1e-7, 1e-6];
    let mut c = [CantorContact::default(); 4];
    let st =
        unsafe { asperity_cantor_contact_batch(&p, 1e10, 1e9, 4, depths.as_ptr(), c.as_mut_ptr()) };
    assert_eq!(st, ASPERITY_OK);
    for (d, got) in depths.iter().zip(&c) {
        assert_eq!(*got, p.contact(*d, 1e10, 1e9).unwrap());
    }
    let (mut dim, mut beta, mut la) = (0.0, 0.0, 0.0);
    assert_eq!(
        unsafe { asperity_cantor_exponents(&p, &mut dim, &mut beta, &mut la) },
        ASPERITY_OK
    );
    assert_eq!(
        (dim, beta, la),
        (
            p.fractal_dimension(),
            p.width_exponent(),
            p.load_area_exponent()
        )
    );
    assert_ne!(
        unsafe { asperity_cantor_exponents(std::ptr::null(), &mut dim, &mut beta, &mut la) },
        ASPERITY_OK
    );
}
