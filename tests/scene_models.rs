//! Scenes choosing dynamic friction models (issue 9 §3): parsing (defaults,
//! round trip, unknown keys, parameter errors named by their field path, the
//! sliding velocity), and the run of each model along the energy-dissipation
//! slider's track against direct steps of the same model (bit-identical),
//! closed forms (LuGre's Stribeck curve at the scene's velocity, the
//! Maxwell-slip virgin curve, Prandtl–Tomlinson stick-slip once a lattice
//! period), and no allocation per step.

mod common;

use asperity::contact::BatchError;
use asperity::friction::dynamic::{
    BurridgeKnopoff, DynamicModel, FrictionIncrement, FrictionLaw, GeneralizedMaxwellSlip, LuGre,
    MaxwellSlip, PrandtlTomlinson, STATE_DISSIPATION,
};
use asperity::friction::{SlideRun, SlideStep, SlideSummary};
use asperity::scene::{
    run_along, DynamicModelSpec, LuGreSpec, Scene, SceneError, TrackRun, TrackSummary,
};
use asperity::Error;
use std::path::Path;
use std::sync::OnceLock;

#[global_allocator]
static GLOBAL: common::counting::Counting = common::counting::Counting;

// ------------------------------------------------------------ helpers

fn example_text() -> String {
    std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/dynamic_models.json"),
    )
    .unwrap()
}

fn example() -> Scene {
    Scene::from_json(&example_text(), ".").expect("the example scene")
}

/// The example scene with its `friction_models` list replaced by `models`
/// (JSON text of the list's entries).
fn with_models(models: &str) -> String {
    let text = example_text();
    let start = text.find("\"friction_models\"").unwrap();
    format!("{}\"friction_models\": [{models}]\n}}", &text[..start])
}

fn parse(text: &str) -> Result<Scene, SceneError> {
    Scene::from_json(text, ".")
}

/// The field and argument of a value error.
fn invalid(e: SceneError) -> (String, &'static str) {
    match e {
        SceneError::Invalid { field, error } => {
            let name = match error {
                Error::InvalidArgument { name, .. } => name,
                other => panic!("{field}: not an argument error: {other}"),
            };
            (field.into_owned(), name)
        }
        other => panic!("not a value error: {other}"),
    }
}

fn json_error(e: SceneError) -> String {
    match e {
        SceneError::Json { message, line, .. } => {
            assert!(line > 0, "{message}: a line number");
            message
        }
        other => panic!("not a JSON error: {other}"),
    }
}

const LUGRE: &str = r#"{ "name": "L", "lugre": { "mu_coulomb": 0.3, "mu_static": 0.5,
    "stribeck_velocity": 1e-3, "sigma0": 1e5 } }"#;

/// The energy-dissipation run of the example scene (computed once).
fn slide() -> &'static (Scene, SlideRun) {
    static RUN: OnceLock<(Scene, SlideRun)> = OnceLock::new();
    RUN.get_or_init(|| {
        let s = example();
        let run = s
            .build()
            .unwrap()
            .slide(s.sliding.distance, s.sliding.step)
            .unwrap();
        (s, run)
    })
}

/// A made-up run of `n` increments over `distance` with normal loads
/// `load(k)`.
fn track(n: usize, distance: f64, load: impl Fn(usize) -> f64) -> SlideRun {
    SlideRun {
        steps: (0..n)
            .map(|k| SlideStep {
                position: (k + 1) as f64 * distance / n as f64,
                normal_load: load(k),
                ..SlideStep::default()
            })
            .collect(),
        summary: SlideSummary {
            steps: n,
            distance,
            ..SlideSummary::default()
        },
    }
}

// ------------------------------------------------------------ parsing

#[test]
fn the_example_scene_parses_into_its_five_models() {
    let s = example();
    assert_eq!(s.sliding.velocity, Some(1e-3));
    let names: Vec<&str> = s.friction_models.iter().map(|m| m.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "LuGre",
            "Maxwell-slip 4",
            "Prandtl-Tomlinson",
            "Prandtl-Tomlinson two-spring",
            "Burridge-Knopoff 8 blocks"
        ]
    );
    let keys: Vec<&str> = s.friction_models.iter().map(|m| m.model.key()).collect();
    assert_eq!(
        keys,
        [
            "lugre",
            "maxwell_slip",
            "prandtl_tomlinson",
            "prandtl_tomlinson_two_spring",
            "burridge_knopoff"
        ]
    );
    // The built models are the constructors' with the scene's numbers.
    let built = s.friction_models().unwrap();
    assert_eq!(
        built,
        vec![
            DynamicModel::LuGre(LuGre::new(0.9, 1.2, 1e-3, 2.0, 3e5, 100.0, 1e-2, 0.0).unwrap()),
            DynamicModel::MaxwellSlip(
                MaxwellSlip::new(&[4e5, 2e5, 1e5, 5e4], &[0.3, 0.3, 0.25, 0.2], 0.0).unwrap()
            ),
            DynamicModel::PrandtlTomlinson(
                PrandtlTomlinson::new(1.8e-6, 3e-5, 2.5e4, 1e-3, 5.0, 1e-8).unwrap()
            ),
            DynamicModel::PrandtlTomlinson(
                PrandtlTomlinson::two_spring(1.8e-6, 3e-5, 5e4, 1e-4, 2.0, 5e4, 1e-3, 5.0, 1e-8)
                    .unwrap()
            ),
            DynamicModel::BurridgeKnopoff(
                BurridgeKnopoff::new(8, 1e-4, 1e3, 1e3, 1.2, 1.05, f64::INFINITY, 0.0, 1e-8)
                    .unwrap()
            ),
        ]
    );
}

#[test]
fn defaults_fill_the_optional_parameters() {
    let s = parse(&with_models(&format!(
        r#"{LUGRE}, {{ "name": "M", "maxwell_slip": {{ "stiffness": [1e5], "capacity": [0.4] }} }},
           {{ "name": "P", "prandtl_tomlinson": {{ "amplitude": 1e-19, "period": 3e-10,
              "stiffness": 10, "mass": 1e-12 }} }}"#
    )))
    .unwrap();
    assert_eq!(
        s.friction_models().unwrap(),
        vec![
            DynamicModel::LuGre(
                LuGre::new(0.3, 0.5, 1e-3, 2.0, 1e5, 0.0, f64::INFINITY, 0.0).unwrap()
            ),
            DynamicModel::MaxwellSlip(MaxwellSlip::new(&[1e5], &[0.4], 0.0).unwrap()),
            DynamicModel::PrandtlTomlinson(
                PrandtlTomlinson::new(1e-19, 3e-10, 10.0, 1e-12, 0.0, 1e-8).unwrap()
            ),
        ]
    );
}

#[test]
fn scenes_round_trip_through_serde() {
    let s = example();
    let text = serde_json::to_string(&s).unwrap();
    assert!(text.contains(r#""name":"LuGre","lugre":{"#), "{text}");
    assert_eq!(parse(&text).unwrap(), s);
    // A model's absent damping velocity stays absent.
    let s = parse(&with_models(LUGRE)).unwrap();
    let text = serde_json::to_string(&s).unwrap();
    assert!(!text.contains("damping_velocity"), "{text}");
    assert_eq!(parse(&text).unwrap(), s);
    // Without models neither key is written: the scene is as before.
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/chapter6_copper.json");
    let s = Scene::from_file(path).unwrap();
    assert!(s.friction_models.is_empty() && s.sliding.velocity.is_none());
    let text = serde_json::to_string(&s).unwrap();
    assert!(
        !text.contains("friction_models") && !text.contains("velocity"),
        "{text}"
    );
    assert_eq!(s.friction_models().unwrap(), vec![]);
}

#[test]
fn unknown_keys_and_malformed_entries_are_rejected() {
    // An unknown model, listing the known ones.
    let m = json_error(
        parse(&with_models(
            r#"{ "name": "B", "bristle": { "sigma0": 1e5 } }"#,
        ))
        .unwrap_err(),
    );
    assert!(
        m.contains("bristle") && m.contains("lugre") && m.contains("maxwell_slip"),
        "{m}"
    );
    // An unknown parameter of a known model.
    let m = json_error(
        parse(&with_models(
            &LUGRE.replace("\"sigma0\"", "\"mu_kinetic\": 0.2, \"sigma0\""),
        ))
        .unwrap_err(),
    );
    assert!(m.contains("unknown field `mu_kinetic`"), "{m}");
    // A missing parameter.
    let m = json_error(parse(&with_models(&LUGRE.replace(", \"sigma0\": 1e5", ""))).unwrap_err());
    assert!(m.contains("missing field `sigma0`"), "{m}");
    // No name; no model; two models in one entry; not an object.
    let m = json_error(
        parse(&with_models(
            r#"{ "maxwell_slip": { "stiffness": [1], "capacity": [1] } }"#,
        ))
        .unwrap_err(),
    );
    assert!(m.contains("missing field `name`"), "{m}");
    let m = json_error(parse(&with_models(r#"{ "name": "x" }"#)).unwrap_err());
    assert!(m.contains("missing the model"), "{m}");
    let m = json_error(
        parse(&with_models(&LUGRE.replace(
            "\"lugre\"",
            "\"maxwell_slip\": { \"stiffness\": [1], \"capacity\": [1] }, \"lugre\"",
        )))
        .unwrap_err(),
    );
    assert!(m.contains("one model per entry"), "{m}");
    let m = json_error(parse(&with_models("\"LuGre\"")).unwrap_err());
    assert!(m.contains("a friction model"), "{m}");
}

#[test]
fn bad_parameters_are_named_with_their_field_path() {
    // σ₁ beyond the passivity bound, in the second entry.
    let bad = LUGRE
        .replace("\"L\"", "\"L2\"")
        .replace("1e5 }", "1e5, \"sigma1\": 1e4, \"damping_velocity\": 1 }");
    let e = parse(&with_models(&format!("{LUGRE}, {bad}"))).unwrap_err();
    let text = e.to_string();
    assert!(
        text.contains("friction_models[1].lugre") && text.contains("sigma1"),
        "{text}"
    );
    assert_eq!(invalid(e), ("friction_models[1].lugre".into(), "sigma1"));
    // σ₁ > 0 without a damping velocity (+∞): the passivity bound again.
    let e = parse(&with_models(
        &LUGRE.replace("1e5 }", "1e5, \"sigma1\": 1 }"),
    ))
    .unwrap_err();
    assert_eq!(invalid(e), ("friction_models[0].lugre".into(), "sigma1"));
    for (entry, field, name) in [
        (
            r#"{ "name": "M", "maxwell_slip": { "stiffness": [1e5, 2e5], "capacity": [0.4] } }"#,
            "friction_models[0].maxwell_slip",
            "capacity.len()",
        ),
        (
            r#"{ "name": "M", "maxwell_slip": { "stiffness": [-1e5], "capacity": [0.4] } }"#,
            "friction_models[0].maxwell_slip",
            "stiffness",
        ),
        (
            r#"{ "name": "P", "prandtl_tomlinson": { "amplitude": 1e-19, "period": 3e-10,
                "stiffness": 10, "mass": 1e-12, "tolerance": 0.5 } }"#,
            "friction_models[0].prandtl_tomlinson",
            "tolerance",
        ),
        (
            r#"{ "name": "P", "prandtl_tomlinson": { "amplitude": 1e-19, "period": 0,
                "stiffness": 10, "mass": 1e-12 } }"#,
            "friction_models[0].prandtl_tomlinson",
            "period",
        ),
    ] {
        let e = parse(&with_models(entry)).unwrap_err();
        assert_eq!(invalid(e), (field.to_string(), name), "{entry}");
    }
    // Names: empty, with a control character, twice.
    for (names, field) in [
        (["", "b"], "friction_models[0].name"),
        (["a\\n", "b"], "friction_models[0].name"),
        (["a", "a"], "friction_models[1].name"),
    ] {
        let e = parse(&with_models(&format!(
            "{}, {}",
            LUGRE.replace("\"L\"", &format!("\"{}\"", names[0])),
            LUGRE.replace("\"L\"", &format!("\"{}\"", names[1]))
        )))
        .unwrap_err();
        assert_eq!(invalid(e), (field.to_string(), "name"), "{names:?}");
    }
}

#[test]
fn models_need_a_positive_sliding_velocity() {
    let text = with_models(LUGRE);
    assert!(parse(&text).is_ok());
    // Missing: named at `sliding`.
    let missing = text.replace(", \"velocity\": 1e-3", "");
    assert_ne!(missing, text);
    let e = parse(&missing).unwrap_err();
    assert!(e.to_string().contains("velocity"), "{e}");
    assert_eq!(invalid(e), ("sliding".into(), "velocity"));
    for bad in ["0", "-1e-3"] {
        let e = parse(&text.replace("\"velocity\": 1e-3", &format!("\"velocity\": {bad}")))
            .unwrap_err();
        assert_eq!(invalid(e), ("sliding".into(), "velocity"), "{bad}");
    }
    // A velocity without models is fine (unused), and so is an empty list.
    assert!(parse(&with_models("")).is_ok());
    assert!(parse(&missing.replace(LUGRE, "")).is_ok());
    // Checked again when the models run (the scene's fields are public).
    let mut s = parse(&text).unwrap();
    s.sliding.velocity = Some(f64::NAN);
    let e = s.run_friction_models(&track(3, 3e-6, |_| 1.0)).unwrap_err();
    assert_eq!(invalid(e), ("sliding".into(), "velocity"));
}

// ------------------------------------------------------------ the run

/// The run of `model` by direct `step` calls (separate old and new states,
/// not the runner's in-place path) with the increments the runner
/// documents, compared bit for bit.
fn assert_direct(model: &DynamicModel, run: &SlideRun, velocity: f64, got: &TrackRun) {
    let n = run.steps.len();
    assert_eq!(got.steps.len(), n);
    let dx = run.summary.distance / n as f64;
    let mut old = vec![0.0; model.state_len()];
    let mut new = old.clone();
    let mut work = model.work();
    let mut total = 0.0;
    for (k, s) in run.steps.iter().enumerate() {
        let inc = FrictionIncrement {
            normal_force: s.normal_load,
            slip: [dx, 0.0],
            dt: dx / velocity,
            ..FrictionIncrement::default()
        };
        let r = model.step(&old, &mut new, &inc, &mut work).unwrap();
        let g = &got.steps[k];
        assert_eq!(r.force[1], 0.0, "{k}: a track along x");
        assert_eq!(g.friction_force.to_bits(), (-r.force[0]).to_bits(), "{k}");
        let mu = if inc.normal_force > 0.0 {
            -r.force[0] / inc.normal_force
        } else {
            0.0
        };
        assert_eq!(g.cof.to_bits(), mu.to_bits(), "{k}");
        assert_eq!(g.cof.abs().to_bits(), r.cof.to_bits(), "{k}");
        assert_eq!(g.dissipated.to_bits(), r.dissipated.to_bits(), "{k}");
        total += r.dissipated;
        assert_eq!(g.dissipation.to_bits(), total.to_bits(), "{k}");
        assert_eq!(g.dissipation.to_bits(), new[STATE_DISSIPATION].to_bits());
        std::mem::swap(&mut old, &mut new);
    }
    let s = &got.summary;
    assert_eq!(s.steps, n);
    assert_eq!(s.dissipation.to_bits(), total.to_bits());
    let cof: Vec<f64> = got.steps.iter().map(|r| r.cof).collect();
    assert_eq!(s.static_cof, cof.iter().copied().fold(f64::MIN, f64::max));
    let mean = cof.iter().sum::<f64>() / n as f64;
    assert!((s.mean_cof - mean).abs() <= 1e-15 * mean.abs().max(1.0));
}

#[test]
fn the_scene_models_along_the_slide_equal_direct_steps() {
    let (s, run) = slide();
    let runs = s.run_friction_models(run).unwrap();
    let models = s.friction_models().unwrap();
    assert_eq!(runs.len(), 5);
    for (m, r) in models.iter().zip(&runs) {
        assert_direct(m, run, 1e-3, r);
        assert_eq!(run_along(m, run, 1e-3).unwrap(), *r);
    }
    // Near the energy-dissipation model's COF (the example's purpose).
    let ed = run.summary.mean_cof;
    for r in &runs {
        assert!(
            (r.summary.mean_cof - ed).abs() < 0.1 * ed,
            "{:?}",
            r.summary
        );
    }
}

#[test]
fn a_varying_normal_load_reaches_each_model() {
    // Fixed-gap slides vary N; Amontons-scaled models follow it.
    let run = track(40, 6e-5, |k| 0.1 + 0.05 * (k as f64 * 0.7).sin());
    let (s, _) = slide();
    for m in s.friction_models().unwrap() {
        let got = run_along(&m, &run, 2e-3).unwrap();
        assert_direct(&m, &run, 2e-3, &got);
    }
    // A tensile load is given as 0: μ = 0, no force, no dissipation.
    let run = track(3, 3e-6, |k| if k == 1 { -0.2 } else { 0.1 });
    let m = DynamicModel::LuGre(LuGre::new(0.3, 0.5, 1e-3, 2.0, 1e5, 0.0, 1.0, 0.0).unwrap());
    let got = run_along(&m, &run, 1e-3).unwrap();
    assert_eq!(got.steps[1].cof, 0.0);
    assert_eq!(got.steps[1].friction_force, 0.0);
    assert_eq!(got.steps[1].dissipated, 0.0);
    assert!(got.steps[2].cof > 0.0);
}

#[test]
fn lugre_reaches_its_stribeck_curve_at_the_scene_velocity() {
    // Steady sliding at v: μ = μ_c + (μ_s − μ_c) e^{−(v/v_s)²}, so the
    // time increment must be step/velocity.
    let run = track(200, 4e-4, |_| 0.25);
    for v in [2e-4, 1e-3, 5e-3] {
        let m = LuGre::new(0.3, 0.5, 1e-3, 2.0, 1e6, 0.0, 1.0, 0.0).unwrap();
        let got = run_along(&m, &run, v).unwrap();
        let want = 0.3 + 0.2 * (-(v / 1e-3f64).powi(2)).exp();
        let last = got.steps.last().unwrap();
        assert!((last.cof - want).abs() < 1e-12, "v = {v}: {}", last.cof);
        assert!((last.friction_force - 0.25 * want).abs() < 1e-12);
        assert_eq!(got.summary.stick_slip_events, 0);
    }
}

#[test]
fn maxwell_slip_follows_its_virgin_curve_along_the_track() {
    let (k, mu) = ([4e5, 1e5], [0.3, 0.5]);
    let m = MaxwellSlip::new(&k, &mu, 0.0).unwrap();
    let run = track(30, 3e-5, |_| 0.2);
    let got = run_along(&m, &run, 1e-3).unwrap();
    for (j, r) in got.steps.iter().enumerate() {
        let x = (j + 1) as f64 * 1e-6;
        let want = (k[0] * x).min(mu[0]) + (k[1] * x).min(mu[1]);
        assert!((r.cof - want).abs() < 1e-12, "{j}: {} vs {want}", r.cof);
    }
    let s = got.summary;
    assert!((s.static_cof - 0.8).abs() < 1e-12);
    assert_eq!(s.stick_slip_events, 0);
    // Gross sliding from x = 5 µm: the slip blocks dissipate N Σμᵢ a metre.
    assert!((s.dissipation - 0.2 * (0.3 * (3e-5 - 0.75e-6) + 0.5 * (3e-5 - 5e-6))).abs() < 1e-15);
}

#[test]
fn prandtl_tomlinson_sticks_and_slips_once_a_lattice_period() {
    // Support at 1 mm/s, 100 increments of 1.5 µm; η = 4π²U₀/(k a²).
    let run = track(100, 1.5e-4, |_| 0.18);
    let (k, m) = (2.5e4, 1e-3);
    let pt = |eta: f64, a: f64, gamma: f64| {
        let u0 = eta * k * a * a / (4.0 * std::f64::consts::PI.powi(2));
        PrandtlTomlinson::new(u0, a, k, m, gamma, 1e-8).unwrap()
    };
    // Lattice periods of 10, 20 and 40 increments: one slip each (the
    // last period of 40 increments is cut short by the end of the run).
    for (a, periods) in [(1.5e-5, 10..=10), (3e-5, 5..=5), (6e-5, 2..=3)] {
        for gamma in [1.0, 5.0, 20.0] {
            for eta in [1.5, 2.8] {
                let s = run_along(&pt(eta, a, gamma), &run, 1e-3).unwrap().summary;
                assert!(
                    periods.contains(&s.stick_slip_events),
                    "a = {a}, gamma = {gamma}, eta = {eta}: {s:?}"
                );
            }
            // Below the threshold the tip follows the support smoothly.
            let s = run_along(&pt(0.5, a, gamma), &run, 1e-3).unwrap().summary;
            assert_eq!(s.stick_slip_events, 0, "a = {a}, gamma = {gamma}: {s:?}");
        }
    }
}

/// A uniform Burridge–Knopoff chain along the track slides as one block:
/// it first slips when every leaf spring reaches μ_s N/M, at
/// t₁ = μ_s N/(M k_p V), then once every closed-form period T
/// ([`BurridgeKnopoff::uniform_period`]); between slips the force returns
/// to its kinetic level, so after the first slip μ averages μ_k over whole
/// cycles.
#[test]
fn burridge_knopoff_along_the_track_slips_once_a_period() {
    let (n, v, steps, distance) = (0.18, 1e-3, 400, 6e-4);
    let run = track(steps, distance, |_| n);
    let dt = distance / steps as f64 / v;
    for (blocks, kp) in [(1, 800.0), (8, 100.0), (32, 25.0)] {
        let bk = BurridgeKnopoff::new(blocks, 1e-4, 1e3, kp, 1.2, 1.05, f64::INFINITY, 0.0, 1e-9)
            .unwrap();
        let t1 = 1.2 * n / (blocks as f64 * kp * v);
        let period = bk.uniform_period(n, v);
        let time = steps as f64 * dt;
        let want = 1 + ((time - t1) / period).floor() as usize;
        let got = run_along(&bk, &run, v).unwrap();
        assert_eq!(
            got.summary.stick_slip_events, want,
            "{blocks} blocks: {:?}",
            got.summary
        );
        // The mean μ over the whole cycles after the first slip is μ_k.
        let first = (t1 / dt).ceil() as usize;
        let cycles = ((time - t1) / period).floor();
        let end = first + (cycles * period / dt).round() as usize;
        let cof: Vec<f64> = got.steps[first..end].iter().map(|r| r.cof).collect();
        let mean = cof.iter().sum::<f64>() / cof.len() as f64;
        assert!((mean - 1.05).abs() < 0.02, "{blocks} blocks: mean μ {mean}");
    }
}

#[test]
fn stick_slip_events_are_bursts_of_dissipation() {
    let summary = |dissipated: &[f64]| {
        let steps: Vec<_> = dissipated
            .iter()
            .map(|&d| asperity::scene::TrackStep {
                dissipated: d,
                ..Default::default()
            })
            .collect();
        TrackSummary::of(&steps).stick_slip_events
    };
    // Median 1: increments above 10 are slips; two in a row are one slip.
    assert_eq!(
        summary(&[1.0, 1.0, 30.0, 1.0, 0.5, 12.0, 40.0, 1.0, 1.0]),
        2
    );
    // Up to ten times the median is steady sliding.
    assert_eq!(summary(&[1.0, 2.0, 10.0, 0.5, 1.0]), 0);
    // Sticking most of the time (median 0): any dissipation is a slip.
    assert_eq!(summary(&[0.0, 0.0, 1e-9, 0.0, 0.0, 0.0, 2e-9]), 2);
    // A slip in the last increment counts.
    assert_eq!(summary(&[1.0, 1.0, 1.0, 50.0]), 1);
    assert_eq!(summary(&[0.0; 4]), 0);
    assert_eq!(summary(&[]), 0);
    assert_eq!(TrackSummary::of(&[]), TrackSummary::default());
}

#[test]
fn the_run_allocates_per_run_not_per_step() {
    let m = DynamicModel::MaxwellSlip(MaxwellSlip::new(&[4e5, 1e5], &[0.3, 0.5], 0.0).unwrap());
    let count = |n: usize| {
        let run = track(n, n as f64 * 1e-6, |_| 0.2);
        let before = common::counting::allocations();
        let got = run_along(&m, &run, 1e-3).unwrap();
        let after = common::counting::allocations();
        assert_eq!(got.steps.len(), n);
        after - before
    };
    assert_eq!(count(10), count(1000));
}

#[test]
fn runner_errors_name_the_argument_and_increment() {
    let run = track(4, 4e-6, |k| if k == 2 { f64::INFINITY } else { 0.1 });
    let m = LuGre::new(0.3, 0.5, 1e-3, 2.0, 1e5, 0.0, 1.0, 0.0).unwrap();
    let e = run_along(&m, &run, 1e-3).unwrap_err();
    assert!(matches!(
        e,
        BatchError {
            index: 2,
            error: Error::InvalidArgument {
                name: "normal_force",
                ..
            }
        }
    ));
    for v in [0.0, -1.0, f64::NAN] {
        let e = run_along(&m, &run, v).unwrap_err();
        assert!(matches!(
            e.error,
            Error::InvalidArgument {
                name: "velocity",
                ..
            }
        ));
    }
    // Through a scene: the model's path and the increment.
    let s = parse(&with_models(LUGRE)).unwrap();
    let e = s.run_friction_models(&run).unwrap_err();
    assert_eq!(
        invalid(e),
        (
            "friction_models[0].lugre at increment 2".into(),
            "normal_force"
        )
    );
    // An empty run: no records, a zero summary.
    let got = run_along(&m, &track(0, 1e-6, |_| 0.1), 1e-3).unwrap();
    assert!(got.steps.is_empty() && got.summary == TrackSummary::default());
    let _ = DynamicModelSpec::KEYS;
    let _: Option<LuGreSpec> = None;
}

/// A scene's `bristles` entry builds the constructor's model; a bad value is
/// named with its path.
#[test]
fn bristles_in_a_scene_build_the_constructors_model() {
    let s = parse(&with_models(
        r#"{"name": "brush", "bristles": {"stiffness": [1e5, 2e5], "break_deflection": [1e-6, 3e-6]}}"#,
    ))
    .unwrap();
    assert_eq!(
        s.friction_models().unwrap(),
        vec![DynamicModel::Bristles(
            asperity::friction::dynamic::Bristles::new(&[1e5, 2e5], &[1e-6, 3e-6], 0.0).unwrap()
        )]
    );
    let e = parse(&with_models(
        r#"{"name": "brush", "bristles": {"stiffness": [1e5], "break_deflection": [0.0]}}"#,
    ))
    .unwrap_err();
    assert_eq!(
        invalid(e),
        ("friction_models[0].bristles".into(), "break_deflection")
    );
}

/// A nano-asperity spacing 10¹⁰ times below the tip width: (w/λ)² overflows
/// usize. The scene is refused with the count named, not a panic (debug)
/// or a wrapped count (release).
#[test]
fn a_nano_spacing_far_below_the_tip_width_is_an_error() {
    let text = example_text()
        .replace("\"spacing\": 1.35e-6", "\"spacing\": 1e-16")
        .replace("\"w_vdw\": 4.3e-7", "\"w_vdw\": 1e-17")
        .replace("\"w_chem\": 1.61e-7", "\"w_chem\": 1e-17");
    let err = parse(&text)
        .and_then(|s| s.build().map(|_| ()))
        .unwrap_err();
    let msg = err.to_string();
    assert!(msg.contains("nano_per_rod"), "{msg}");
}

#[test]
fn generalized_maxwell_slip_from_a_scene_reaches_its_stribeck_curve() {
    // The scene key with its defaults (δ = 2, C = +∞, σ₂ = 0), then steady
    // sliding along a track at v: μ = s(v) Σα, the time increment being
    // step/velocity.
    let s = parse(&with_models(
        r#"{ "name": "GMS", "generalized_maxwell_slip": { "stiffness": [1e6, 2e5],
             "weight": [0.5, 0.5], "mu_coulomb": 0.3, "mu_static": 0.5,
             "stribeck_velocity": 1e-3, "attraction": 40 } }"#,
    ))
    .unwrap();
    let want =
        GeneralizedMaxwellSlip::new(&[1e6, 2e5], &[0.5, 0.5], 0.3, 0.5, 1e-3, 2.0, 40.0, 0.0)
            .unwrap();
    let models = s.friction_models().unwrap();
    assert_eq!(
        models,
        vec![DynamicModel::GeneralizedMaxwellSlip(want.clone())]
    );
    let run = track(400, 4e-4, |_| 0.25);
    for v in [2e-4, 1e-3, 5e-3] {
        let got = run_along(&want, &run, v).unwrap();
        let mu = 0.3 + 0.2 * (-(v / 1e-3f64).powi(2)).exp();
        let last = got.steps.last().unwrap();
        assert!((last.cof - mu).abs() < 1e-12, "v = {v}: {}", last.cof);
        assert_direct(&models[0], &run, v, &got);
    }
    let (field, name) = invalid(
        parse(&with_models(
            r#"{ "name": "G", "generalized_maxwell_slip": { "stiffness": [1e6], "weight": [1],
                 "mu_coulomb": 0.3, "mu_static": 0.5, "stribeck_velocity": 1e-3, "attraction": -1 } }"#,
        ))
        .unwrap_err(),
    );
    assert_eq!(
        (field.as_str(), name),
        ("friction_models[0].generalized_maxwell_slip", "attraction")
    );
}
