//! Schmittbuhl's hierarchical model (thesis 5.4.3): the renormalisation of
//! a friction law by Burridge–Knopoff chains.
//!
//! Tolerances: the chain runs are quasi-static to V√(k_p m)/F_s (the
//! inertial overshoot of a sliding block, 2e-5 at generation 0 of the
//! default model, growing as Nᵍ with d = 3) and sampled at
//! [`SAMPLES_PER_REACH`] increments per static reach F_s/k_p: a peak is
//! sampled up to one increment's load rise k_p Δs = F_s/400 low.
//! The kinetic friction is the friction work per unit slip of the blocks,
//! exact for Coulomb friction up to the integration tolerance.

use asperity::hierarchical::schmittbuhl::SAMPLES_PER_REACH;
use asperity::hierarchical::Schmittbuhl;
use asperity::Error;

/// One increment's relative load rise, 1/[`SAMPLES_PER_REACH`].
const SAMPLE: f64 = 1.0 / SAMPLES_PER_REACH;

#[test]
fn coulomb_law_is_a_fixed_point_of_the_renormalisation() {
    // Static = kinetic, no weakening: every sliding block resists with
    // μ n, so the chain does with μ N n at every generation, with or
    // without pre-stress; only the quasi-static overshoot V√(k m)/F_s
    // (≤ 2e-5 N^{2g}... ≤ 2.5e-3 here) separates the peak from μ.
    for ratio in [2, 3, 5] {
        for dimension in [2, 3] {
            for disorder in [0.0, 0.5, 0.9] {
                for mu in [0.1, 0.5, 1.2] {
                    let model = Schmittbuhl {
                        mu_static: mu,
                        mu_kinetic: mu,
                        weakening_velocity: f64::INFINITY,
                        ratio,
                        generations: if ratio == 5 { 2 } else { 3 },
                        dimension,
                        disorder,
                        ..Default::default()
                    };
                    let law = model.run().unwrap();
                    assert_eq!(law.len(), model.generations + 1);
                    for g in &law {
                        let what = format!("N {ratio} d {dimension} δ {disorder} μ {mu}: {g:?}");
                        assert!((g.mu_static / mu - 1.0).abs() < 2.5e-3, "{what}");
                        assert!((g.mu_kinetic / mu - 1.0).abs() < 2.5e-3, "{what}");
                    }
                }
            }
        }
    }
}

#[test]
fn identical_blocks_keep_a_stick_slip_law() {
    // No pre-stress: the chain's blocks switch together and move as one
    // block, whose stick-slip breaks loose at F_s and whose work per unit
    // slip is F_k: the law (μ_s, μ_k) is a fixed point, up to the
    // sampling of the peaks (one increment's rise per generation).
    for (mu_s, mu_k) in [(0.5, 0.3), (0.8, 0.2), (0.3, 0.25)] {
        for ratio in [2, 3, 4] {
            let model = Schmittbuhl {
                mu_static: mu_s,
                mu_kinetic: mu_k,
                weakening_velocity: f64::INFINITY,
                ratio,
                disorder: 0.0,
                ..Default::default()
            };
            let law = model.run().unwrap();
            for g in &law[1..] {
                let what = format!("μ {mu_s}/{mu_k} N {ratio}: {g:?}");
                assert!(g.events >= 2, "{what}");
                assert!(g.mu_static <= mu_s * (1.0 + 1e-6), "{what}");
                assert!(
                    g.mu_static >= mu_s * (1.0 - 1.5 * SAMPLE * g.index as f64),
                    "{what}"
                );
                // The friction work per unit slip of the blocks: F_k, up to
                // the kinetic energy booked at stops (integration tolerance).
                assert!((g.mu_kinetic / mu_k - 1.0).abs() < 1e-4, "{what}");
            }
        }
    }
}

#[test]
fn pre_stress_closes_the_static_kinetic_gap() {
    // With a pre-stress the blocks break loose at different driver
    // positions: the chain never carries N F_s at once, so the static
    // friction falls towards the kinetic one (Coulomb kinetic friction:
    // the sliding blocks resist with F_k whatever the order of their
    // slips). Static never grows above its child's (stuck blocks hold at
    // most F_s each); the ratio μ_k/μ_s grows towards 1.
    for disorder in [0.3, 0.5, 0.8] {
        for ratio in [2, 3, 4] {
            let model = Schmittbuhl {
                weakening_velocity: f64::INFINITY,
                ratio,
                disorder,
                ..Default::default()
            };
            let law = model.run().unwrap();
            for w in law.windows(2) {
                let what = format!("δ {disorder} N {ratio}: {w:?}");
                assert!(w[1].mu_static <= w[0].mu_static * (1.0 + SAMPLE), "{what}");
                assert!(w[1].mu_kinetic <= w[1].mu_static, "{what}");
                // Coulomb kinetic friction: the friction work per unit
                // slip is F_k whatever the order of the slips (taken no
                // larger than the static friction, the mean break-away peak,
                // which many partial events can put just below F_k).
                let k = w[1].mu_kinetic;
                assert!(
                    (k / 0.3 - 1.0).abs() < 1e-4 || k == w[1].mu_static,
                    "{what}"
                );
                assert!(w[1].mu_static > 0.3 * 0.98, "{what}");
            }
            let (first, last) = (law[0].ratio, law.last().unwrap().ratio);
            assert!(last > first + 0.2, "δ {disorder} N {ratio}: {law:?}");
            assert!(last <= 1.0);
        }
    }
}

#[test]
fn velocity_weakening_flows_down_and_stays_finite() {
    // F_k(v) = μ_k n/(1 + v/v_c) ≤ μ_k n: the work per unit slip of a
    // chain is at most μ_k N n (up to the sampling), and its peaks at most
    // N F_s; the static stays positive, the kinetic non-negative (with
    // v_c = 1e-3 m/s against slips near 1 m/s the friction all but
    // vanishes and the work per unit slip rounds to 0). Swept over the weakening velocity (four
    // decades), the pre-stress, the ratio and the dimension.
    for vc in [1e-3, 1e-2, 1e-1, 1.0, 10.0] {
        for disorder in [0.0, 0.5] {
            for (ratio, dimension) in [(2, 3), (3, 3), (3, 2), (4, 2)] {
                let model = Schmittbuhl {
                    weakening_velocity: vc,
                    ratio,
                    dimension,
                    disorder,
                    ..Default::default()
                };
                let law = model.run().unwrap();
                for w in law.windows(2) {
                    let what = format!("v_c {vc} δ {disorder} N {ratio} d {dimension}: {w:?}");
                    let (a, b) = (&w[0], &w[1]);
                    assert!(
                        b.mu_static.is_finite() && b.mu_kinetic.is_finite(),
                        "{what}"
                    );
                    assert!(b.mu_static > 0.0 && b.mu_kinetic >= 0.0, "{what}");
                    assert!(b.mu_static <= a.mu_static * (1.0 + SAMPLE), "{what}");
                    // The window's ends are sampled: up to one increment's rise,
                    // F_s/400 a block, off a whole number of cycles.
                    assert!(
                        b.mu_kinetic <= a.mu_kinetic + SAMPLE * a.mu_static,
                        "{what}"
                    );
                    assert!(b.mu_kinetic <= b.mu_static, "{what}");
                }
            }
        }
    }
    // Weakening makes the chain slide at a lower mean force than Coulomb's
    // kinetic friction: at generation 1 the kinetic coefficient is below
    // μ_k, far below it when v_c is small against the slip velocity
    // (F_s − F_k)/√(k_p m) ≈ 1 m/s of the default blocks.
    let one = |vc: f64| {
        Schmittbuhl {
            weakening_velocity: vc,
            generations: 1,
            disorder: 0.0,
            ..Default::default()
        }
        .run()
        .unwrap()[1]
            .mu_kinetic
    };
    assert!(one(1e-3) < 0.1 * 0.3, "{}", one(1e-3));
    assert!(one(100.0) < 0.3 && one(100.0) > 0.9 * 0.3, "{}", one(100.0));
}

#[test]
fn generations_scale_as_an_elastic_continuum() {
    // L_g = Nᵍ L₀: springs ∝ L^{d−2}, masses ∝ L^d, normal force ∝ Nᵍ.
    for dimension in [2u32, 3] {
        let model = Schmittbuhl {
            mu_kinetic: 0.5,
            weakening_velocity: f64::INFINITY,
            dimension,
            ..Default::default()
        };
        let law = model.run().unwrap();
        for g in &law {
            let s = 3f64.powi(g.index as i32);
            assert_eq!(g.size, s);
            let d = dimension as i32;
            assert!((g.mass / (1e-5 * s.powi(d)) - 1.0).abs() < 1e-12);
            assert!((g.pulling_stiffness / (1e3 * s.powi(d - 2)) - 1.0).abs() < 1e-12);
            assert!((g.coupling_stiffness / (1e3 * s.powi(d - 2)) - 1.0).abs() < 1e-12);
            assert!((g.normal_force / s - 1.0).abs() < 1e-12);
        }
    }
    // Without friction there is nothing to renormalise.
    let free = Schmittbuhl {
        mu_static: 0.0,
        mu_kinetic: 0.0,
        ..Default::default()
    };
    for g in free.run().unwrap() {
        assert_eq!((g.mu_static, g.mu_kinetic, g.ratio), (0.0, 0.0, 1.0));
    }
}

#[test]
fn bad_inputs_are_named_errors() {
    let base = Schmittbuhl::default();
    let cases: Vec<(&str, Schmittbuhl)> = vec![
        (
            "mu_static",
            Schmittbuhl {
                mu_static: -0.1,
                ..base
            },
        ),
        (
            "mu_static",
            Schmittbuhl {
                mu_static: f64::NAN,
                ..base
            },
        ),
        (
            "mu_kinetic",
            Schmittbuhl {
                mu_kinetic: 0.6,
                ..base
            },
        ),
        (
            "mu_kinetic",
            Schmittbuhl {
                mu_kinetic: -1.0,
                ..base
            },
        ),
        (
            "weakening_velocity",
            Schmittbuhl {
                weakening_velocity: 0.0,
                ..base
            },
        ),
        (
            "weakening_velocity",
            Schmittbuhl {
                weakening_velocity: f64::NAN,
                ..base
            },
        ),
        ("ratio", Schmittbuhl { ratio: 1, ..base }),
        ("ratio", Schmittbuhl { ratio: 65, ..base }),
        (
            "generations",
            Schmittbuhl {
                generations: 0,
                ..base
            },
        ),
        (
            "generations",
            Schmittbuhl {
                generations: 13,
                ..base
            },
        ),
        (
            "dimension",
            Schmittbuhl {
                dimension: 1,
                ..base
            },
        ),
        (
            "dimension",
            Schmittbuhl {
                dimension: 4,
                ..base
            },
        ),
        ("mass", Schmittbuhl { mass: 0.0, ..base }),
        (
            "coupling_stiffness",
            Schmittbuhl {
                coupling_stiffness: -1.0,
                ..base
            },
        ),
        (
            "pulling_stiffness",
            Schmittbuhl {
                pulling_stiffness: f64::INFINITY,
                ..base
            },
        ),
        (
            "normal_force",
            Schmittbuhl {
                normal_force: 0.0,
                ..base
            },
        ),
        (
            "velocity",
            Schmittbuhl {
                velocity: -1e-4,
                ..base
            },
        ),
        (
            "disorder",
            Schmittbuhl {
                disorder: 1.0,
                ..base
            },
        ),
        (
            "disorder",
            Schmittbuhl {
                disorder: -0.1,
                ..base
            },
        ),
    ];
    for (name, model) in cases {
        match model.run() {
            Err(Error::InvalidArgument { name: n, .. }) => assert_eq!(n, name),
            other => panic!("{name}: {other:?}"),
        }
    }
}
