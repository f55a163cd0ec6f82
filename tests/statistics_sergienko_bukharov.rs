//! Sergienko & Bukharov (2015), thesis §5.3.5, in the library's formulation
//! (module docs of `asperity::statistics::sergienko_bukharov`): a rigid body
//! oscillating normally on Kragelsky's independent springs.
//!
//! Closed forms: without excitation the body settles on Kragelsky's static
//! equilibrium (solved independently by `KragelskyRods::separation_at_load`);
//! a small tangential impulse gives the linear oscillation of amplitude
//! v₀/ω₀; in the quasi-static limit on uniformly spread springs the mean
//! penetration is the quadrature ⟨√(2(N + F₀ sin φ)/(kρ))⟩ (Jensen: below the
//! static one); with exponential heights n ∝ P exactly, so the friction keeps
//! its static value at any amplitude. Then the thesis's statement as
//! monotone sweeps (friction falls, lift grows with the amplitude), lift-off
//! for F₀ > N, step halving, finiteness over decades, and named errors.

use asperity::statistics::{
    Excitation, HeightDistribution, Integration, KragelskyRods, SergienkoBukharov,
};
use asperity::Error;
use core::f64::consts::TAU;

const K: f64 = 1e4; // N/m per spring
const AREA: f64 = 1e-12; // m² per spring
const LOAD: f64 = 1.0; // N
const MU: f64 = 0.2;
const P0: f64 = 1e9; // Pa: the molecular term is ~ half the mechanical one

/// `count` springs with tops spread uniformly over `span` (m): ρ = count/span.
fn uniform(count: usize, span: f64) -> KragelskyRods {
    let dz = span / count as f64;
    let h: Vec<f64> = (0..count).map(|j| (j as f64 + 0.5) * dz).collect();
    KragelskyRods::new(
        count as f64,
        AREA,
        K,
        HeightDistribution::empirical(h).unwrap(),
    )
    .unwrap()
}

fn gaussian() -> KragelskyRods {
    KragelskyRods::new(1e4, AREA, K, HeightDistribution::gaussian(1e-6).unwrap()).unwrap()
}

fn body(rods: KragelskyRods, mass: f64, zeta: f64) -> SergienkoBukharov {
    SergienkoBukharov::new(rods, mass, LOAD, zeta, MU, P0).unwrap()
}

fn driven(f0: f64, omega: f64) -> Excitation {
    Excitation {
        force_amplitude: f0,
        frequency: omega,
        ..Default::default()
    }
}

fn periods(transient: u32, average: u32) -> Integration {
    Integration {
        transient_periods: transient,
        average_periods: average,
        ..Default::default()
    }
}

#[test]
fn settles_on_the_kragelsky_equilibrium() {
    // Dropped from above the springs' tops and from below the equilibrium,
    // and kicked sideways on sloped flanks: all settle where Kragelsky's
    // P(d) = N puts the body.
    for (rods, y_scale) in [(uniform(20_000, 1e-5), 3.2e-7), (gaussian(), 1e-6)] {
        let d_s = rods.separation_at_load(LOAD).unwrap().separation;
        let n_s = rods.response(d_s).unwrap().contacts;
        let m = body(rods, 1e-2, 0.3);
        assert_eq!(m.static_separation(), d_s);
        for exc in [
            Excitation {
                initial_offset: 2.0 * y_scale,
                ..Default::default()
            },
            Excitation {
                initial_offset: -0.5 * y_scale,
                ..Default::default()
            },
            Excitation {
                tangential_impulse: 1e-4,
                slope: 0.1,
                ..Default::default()
            },
        ] {
            let r = m.run(&exc, &periods(60, 5)).unwrap();
            assert!(
                (r.mean_separation - d_s).abs() < 1e-6 * y_scale,
                "{exc:?}: {} vs {d_s}",
                r.mean_separation
            );
            assert!(r.separation_amplitude < 1e-6 * y_scale);
            assert!((r.mean_contacts / n_s - 1.0).abs() < 1e-6);
            assert!((r.mean_load / LOAD - 1.0).abs() < 1e-6);
            assert!((r.friction_ratio - 1.0).abs() < 1e-6);
            let f_s = MU * (LOAD + P0 * AREA * n_s);
            assert!((r.static_friction / f_s - 1.0).abs() < 1e-12);
            assert_eq!(r.lift_off_fraction, 0.0);
        }
    }
}

#[test]
fn small_impulse_gives_the_linear_oscillation() {
    // Undamped, a small upward velocity v₀ = tanθ J/m: amplitude v₀/ω₀,
    // period 2π/ω₀, mean level unchanged to first order.
    let m = body(gaussian(), 1e-2, 0.0);
    let omega0 = m.natural_frequency();
    let mass = 1e-2;
    let (j, slope) = (1e-9, 0.2);
    let v0 = slope * j / mass;
    let amp = v0 / omega0;
    assert!(amp < 1e-3 * 1e-6, "small against σ: {amp}");
    let r = m
        .run(
            &Excitation {
                tangential_impulse: j,
                slope,
                ..Default::default()
            },
            &Integration {
                transient_periods: 0,
                average_periods: 4,
                steps_per_natural_period: 256,
                record_every: 1,
                max_steps: 0,
            },
        )
        .unwrap();
    assert!(
        (r.separation_amplitude / amp - 1.0).abs() < 2e-3,
        "{}",
        r.separation_amplitude / amp
    );
    assert!(r.lift.abs() < 2e-3 * amp);
    assert!((r.period * omega0 / TAU - 1.0).abs() < 1e-12);
    // The record starts at the equilibrium going up, and after one
    // natural period is back there.
    let s = &r.samples;
    assert_eq!(s[0].separation, m.static_separation());
    assert!((s[0].velocity / v0 - 1.0).abs() < 1e-15);
    let per = (r.period / r.time_step).round() as usize;
    assert!((s[per].separation - m.static_separation()).abs() < 1e-2 * amp);
}

/// `(1/2π) ∫ √(1 + a sin φ) dφ` by the rectangle rule (spectral for a < 1).
fn mean_sqrt(a: f64) -> f64 {
    let n = 4096;
    (0..n)
        .map(|i| {
            (1.0 + a * (TAU * i as f64 / n as f64).sin())
                .max(0.0)
                .sqrt()
        })
        .sum::<f64>()
        / n as f64
}

#[test]
fn quasi_static_uniform_springs_follow_the_quadrature() {
    let (count, span) = (20_000, 1e-5);
    let rho = count as f64 / span;
    let top = (count as f64 - 0.5) * span / count as f64;
    let y_s = (2.0 * LOAD / (K * rho)).sqrt();
    let m = body(uniform(count, span), 1.0, 0.5);
    let omega0 = m.natural_frequency();
    // y_s and n_s of the continuum within the discreteness Δ/y ≈ 2e-3.
    assert!(((top - m.static_separation()) / y_s - 1.0).abs() < 3e-3);
    assert!((m.static_contacts() / (rho * y_s) - 1.0).abs() < 3e-3);
    let mut last = 1.0;
    for a in [0.3, 0.6, 0.9, 0.99] {
        let r = m
            .run(&driven(a * LOAD, 0.01 * omega0), &periods(2, 2))
            .unwrap();
        let want_y = y_s * mean_sqrt(a);
        let y = top - r.mean_separation;
        assert!((y / want_y - 1.0).abs() < 1e-2, "a {a}: {y} vs {want_y}");
        assert!((r.mean_contacts / (rho * want_y) - 1.0).abs() < 1e-2);
        // Jensen: below the static level, and more so for larger a.
        assert!(r.contact_ratio < last, "a {a}");
        last = r.contact_ratio;
        assert!((r.mean_load / LOAD - 1.0).abs() < 1e-3);
        // Friction: the mechanical term keeps its mean, the molecular falls.
        let f_s = MU * (LOAD + P0 * AREA * m.static_contacts());
        let want_f = MU * (LOAD + P0 * AREA * rho * want_y);
        assert!((r.mean_friction / want_f - 1.0).abs() < 1e-2);
        assert!((r.static_friction / f_s - 1.0).abs() < 1e-12);
        assert_eq!(r.lift_off_fraction, 0.0);
    }
    // At a = 0.9 the closed form gives 0.9328 y_s.
    assert!((mean_sqrt(0.9) - 0.9328).abs() < 1e-4, "{}", mean_sqrt(0.9));
}

#[test]
fn exponential_heights_keep_the_static_friction() {
    // n = P/(kσ) exactly: ⟨n⟩ = ⟨P⟩/(kσ) = n_s at any amplitude, while the
    // body still lifts (d = −σ ln P + const is convex in P).
    let sigma = 1e-6;
    let rods = KragelskyRods::new(
        1e4,
        AREA,
        K,
        HeightDistribution::exponential(sigma).unwrap(),
    )
    .unwrap();
    let m = body(rods, 1e-2, 0.3);
    let omega0 = m.natural_frequency();
    assert!((m.static_contacts() - LOAD / (K * sigma)).abs() < 1e-9 * m.static_contacts());
    let mut last_lift = 0.0;
    for a in [0.2, 0.5, 0.9] {
        let r = m
            .run(&driven(a * LOAD, 0.5 * omega0), &periods(40, 10))
            .unwrap();
        assert!(
            (r.contact_ratio - 1.0).abs() < 1e-4,
            "a {a}: {}",
            r.contact_ratio
        );
        assert!(
            (r.friction_ratio - 1.0).abs() < 1e-4,
            "a {a}: {}",
            r.friction_ratio
        );
        assert!(r.lift > last_lift, "a {a}");
        last_lift = r.lift;
    }
}

#[test]
fn friction_falls_and_lift_grows_with_the_amplitude() {
    for (name, rods, mass) in [
        ("uniform", uniform(5_000, 1e-5), 1e-3),
        ("gaussian", gaussian(), 1e-3),
    ] {
        let m = body(rods, mass, 0.2);
        let omega0 = m.natural_frequency();
        for ratio in [0.03, 0.3] {
            let (mut last_f, mut last_lift) = (1.0 + 1e-12, -1e-300);
            // A list's n(d) is a staircase: below a ≈ 0.3 the Jensen drop
            // (≈ a² n_s/16) is smaller than one spring.
            let start = if name == "uniform" { 0.3 } else { 0.1 };
            for a in [start, 0.5, 0.7, 0.9, 1.2, 1.6, 2.0] {
                let r = m
                    .run(&driven(a * LOAD, ratio * omega0), &periods(20, 4))
                    .unwrap();
                assert!(r.friction_ratio < last_f, "{name} ω/ω₀ {ratio} a {a}");
                assert!(r.lift > last_lift, "{name} ω/ω₀ {ratio} a {a}");
                assert!((r.mean_load / LOAD - 1.0).abs() < 2e-3, "{name} {a}");
                (last_f, last_lift) = (r.friction_ratio, r.lift);
                if name == "uniform" && a > 1.0 {
                    // F₀ > N pulls the body off every spring part of the time.
                    assert!(r.lift_off_fraction > 0.0, "{name} a {a}");
                } else if a < 0.5 {
                    assert_eq!(r.lift_off_fraction, 0.0);
                }
            }
        }
    }
}

#[test]
fn halving_the_step_changes_little() {
    let m = body(gaussian(), 1e-3, 0.2);
    let omega0 = m.natural_frequency();
    let run = |spp: u32| {
        m.run(
            &driven(0.7 * LOAD, 0.4 * omega0),
            &Integration {
                transient_periods: 20,
                average_periods: 4,
                steps_per_natural_period: spp,
                record_every: 0,
                max_steps: 0,
            },
        )
        .unwrap()
    };
    let (a, b) = (run(32), run(64));
    assert!(b.time_step < 0.6 * a.time_step);
    assert!(a.resolution >= 0.8 * 32.0 && b.resolution >= 0.8 * 64.0);
    assert!(
        (a.lift / b.lift - 1.0).abs() < 1e-4,
        "{} {}",
        a.lift,
        b.lift
    );
    assert!((a.friction_ratio - b.friction_ratio).abs() < 1e-6);
    // The amplitude is read from the step ends: its sampling error is
    // (2π/steps per period)²/8 ≈ 3e-4 for the coarser run.
    assert!((a.separation_amplitude / b.separation_amplitude - 1.0).abs() < 1e-3);
    assert!((b.mean_load / LOAD - 1.0).abs() < 1e-6);
}

#[test]
fn finite_over_decades() {
    for mass in [1e-6, 1e-3, 1.0, 1e3] {
        for k in [1e2, 1e5, 1e8] {
            let rods =
                KragelskyRods::new(1e3, AREA, k, HeightDistribution::gaussian(1e-6).unwrap())
                    .unwrap();
            let m = SergienkoBukharov::new(rods, mass, LOAD, 0.1, MU, P0).unwrap();
            let omega0 = m.natural_frequency();
            for ratio in [0.03, 1.0, 10.0] {
                for a in [0.1, 3.0] {
                    let r = m
                        .run(&driven(a * LOAD, ratio * omega0), &periods(3, 2))
                        .unwrap();
                    for v in [
                        r.mean_separation,
                        r.lift,
                        r.separation_amplitude,
                        r.mean_contacts,
                        r.mean_friction,
                        r.friction_ratio,
                        r.mean_load,
                    ] {
                        assert!(v.is_finite(), "m {mass} k {k} ω/ω₀ {ratio} a {a}: {r:?}");
                    }
                    // (Three periods are not a steady state at ω ≫ ω₀, so
                    // ⟨P⟩ ≠ N there and the ratio may exceed 1.)
                    assert!(r.friction_ratio > 0.0 && r.resolution >= 0.8 * 64.0);
                }
            }
        }
    }
}

#[test]
fn bad_input_is_named() {
    let named = |e: Error, want: &str| match e {
        Error::InvalidArgument { name, .. } | Error::OutOfDomain { name, .. } => {
            assert_eq!(name, want)
        }
        other => panic!("{other:?}"),
    };
    let r = gaussian;
    named(
        SergienkoBukharov::new(r(), 0.0, 1.0, 0.1, MU, P0).unwrap_err(),
        "mass",
    );
    named(
        SergienkoBukharov::new(r(), 1.0, -1.0, 0.1, MU, P0).unwrap_err(),
        "load",
    );
    named(
        SergienkoBukharov::new(r(), 1.0, 1.0, f64::NAN, MU, P0).unwrap_err(),
        "damping_ratio",
    );
    named(
        SergienkoBukharov::new(r(), 1.0, 1.0, 0.1, 0.0, P0).unwrap_err(),
        "friction_coefficient",
    );
    named(
        SergienkoBukharov::new(r(), 1.0, 1.0, 0.1, MU, -1.0).unwrap_err(),
        "attractive_pressure",
    );
    let m = body(gaussian(), 1.0, 0.1);
    let w = m.natural_frequency();
    let ok = periods(2, 2);
    named(m.run(&driven(-1.0, w), &ok).unwrap_err(), "force_amplitude");
    named(m.run(&driven(1.0, 0.0), &ok).unwrap_err(), "frequency");
    named(
        m.run(&driven(1.0, f64::INFINITY), &ok).unwrap_err(),
        "frequency",
    );
    // An excitation far below the natural frequency needs too many steps.
    named(m.run(&driven(1.0, 1e-9 * w), &ok).unwrap_err(), "frequency");
    // So does a run over the caller's budget.
    let tight = Integration {
        max_steps: 100,
        ..ok
    };
    named(m.run(&driven(1.0, w), &tight).unwrap_err(), "frequency");
    named(
        m.run(&Excitation::default(), &tight).unwrap_err(),
        "average_periods",
    );
    let exc = |f: fn(&mut Excitation)| {
        let mut e = driven(0.5, w);
        f(&mut e);
        e
    };
    named(
        m.run(&exc(|e| e.tangential_impulse = -1.0), &ok)
            .unwrap_err(),
        "tangential_impulse",
    );
    named(
        m.run(&exc(|e| e.slope = f64::NAN), &ok).unwrap_err(),
        "slope",
    );
    named(
        m.run(&exc(|e| e.initial_offset = f64::INFINITY), &ok)
            .unwrap_err(),
        "initial_offset",
    );
    named(
        m.run(&driven(0.5, w), &periods(2, 0)).unwrap_err(),
        "average_periods",
    );
    let mut i = ok;
    i.steps_per_natural_period = 8;
    named(
        m.run(&driven(0.5, w), &i).unwrap_err(),
        "steps_per_natural_period",
    );
}
