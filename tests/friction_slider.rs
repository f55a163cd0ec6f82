//! The sliding hierarchical slider (issue 6 §2 sliding, §3, §8): the
//! chapter-6 findings on seeded synthetic profiles (and a measured profile
//! when `../shared/data/profiles/` is present), bad input, extremes, no
//! allocation per step, and the slider as the friction law of a surface
//! patch (`FrictionLaw`: flat states, `SliderWork::record`, tangents,
//! blocks) reproducing `Slider::slide` bit for bit.
//!
//! The chapter-6 scenes spread the volume of yielded rods with Gaussian
//! weights of width 20 µm (the project's extension: thesis 6.2.3 announces
//! a weighting function for future versions without giving one); the
//! thesis's nearest-neighbour rule makes the COF grow with load, which
//! `nearest_neighbour_pile_up_re_yields_with_load` pins down. See
//! `examples/chapter6.rs` for the full study and README "Reproducing the
//! thesis" for the comparison with Tables 6-1 to 6-3.

mod common;

use asperity::friction::{
    apparent_friction, BlockStates, CofForm, CounterHeight, FrictionBlock, FrictionIncrement,
    FrictionLaw, FrictionResponse, Loading, SlideStep, Slider, SliderOptions, SliderWork, TrackEnd,
};
use asperity::scene::{LoadingSpec, PlasticSpec, Scene, SurfaceSpec};
use asperity::Error;
use std::path::Path;

// ------------------------------------------------- counting allocator

#[global_allocator]
static GLOBAL: common::counting::Counting = common::counting::Counting;

use common::counting::allocations;

// ------------------------------------------------------------ helpers

fn scene() -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/chapter6_copper.json");
    Scene::from_file(path).expect("chapter-6 scene")
}

fn with_fraction(fraction: f64) -> Scene {
    let mut s = scene();
    s.loading = LoadingSpec::FixedLoadFraction { fraction };
    s
}

fn check_step(r: &SlideStep) {
    r.dissipation
        .validate()
        .expect("every dissipation entry >= 0");
    assert!(r.cof.is_finite() && r.friction_force.is_finite());
    assert!(r.true_contact_area >= 0.0 && (0.0..=1.0).contains(&r.adhesion_area_share));
}

fn r_squared(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len() as f64;
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let (mut sxy, mut sxx, mut syy) = (0.0, 0.0, 0.0);
    for (a, b) in x.iter().zip(y) {
        sxy += (a - mx) * (b - my);
        sxx += (a - mx) * (a - mx);
        syy += (b - my) * (b - my);
    }
    sxy * sxy / (sxx * syy)
}

// -------------------------------------------------------- chapter 6

#[test]
fn chapter6_scene_runs_and_chemical_bonds_dominate() {
    let s = scene();
    let slider = s.build().unwrap();
    assert_eq!(slider.rods(), 90);
    assert_eq!(slider.nano_per_rod(), 10);
    let run = slider.slide(s.sliding.distance, s.sliding.step).unwrap();
    assert_eq!(run.summary.steps, 100);
    for r in &run.steps {
        check_step(r);
        assert!(!r.no_contact);
    }
    let d = run.summary.dissipation;
    println!("chapter-6 scene: {:?}", run.summary);
    // Chemical bonds the dominant mechanism (thesis 6.5.2, Figure 6-58).
    assert!(d.chemical > d.van_der_waals + d.elastic + d.plastic);
    assert!(d.chemical / d.total() > 0.5);
    // Friction force = total dissipation / distance, (4-1).
    let f = d.total() / s.sliding.distance;
    assert!((run.summary.mean_friction_force - f).abs() <= 1e-12 * f);
    // Adhesion makes a part of the true contact area (Figure 6-59).
    assert!(run.summary.mean_adhesion_area_share > 0.0);
}

/// Thesis 6.5.1: average COF 0.9, Cu–Cu literature 0.8–1.2 at 0.18 N.
/// We get 1.05 (chemical bonds 89 %, plastic work 4 %).
#[test]
fn chapter6_average_cof_in_literature_range() {
    let s = scene();
    let run = s
        .build()
        .unwrap()
        .slide(s.sliding.distance, s.sliding.step)
        .unwrap();
    println!("0.18 N: mean COF {}", run.summary.mean_cof);
    assert!(
        (0.8..=1.2).contains(&run.summary.mean_cof),
        "{}",
        run.summary.mean_cof
    );
}

#[test]
fn low_load_cof_in_literature_range() {
    // At the lowest loads of Table 6-1 the model gives Cu–Cu values.
    let s = with_fraction(0.095);
    let run = s
        .build()
        .unwrap()
        .slide(s.sliding.distance, s.sliding.step)
        .unwrap();
    println!("P = 0.095 sigma_y A_n: mean COF {}", run.summary.mean_cof);
    assert!((0.8..=1.2).contains(&run.summary.mean_cof));
}

#[test]
fn true_contact_area_linear_in_load() {
    // Thesis 6.5.3, Figure 6-60; loads of Table 6-1.
    let (mut p, mut a) = (vec![], vec![]);
    for f in [0.05, 0.11, 0.25, 0.45] {
        let s = with_fraction(f);
        let run = s
            .build()
            .unwrap()
            .slide(s.sliding.distance, s.sliding.step)
            .unwrap();
        p.push(run.summary.normal_load);
        a.push(run.summary.mean_true_contact_area);
    }
    let r2 = r_squared(&p, &a);
    println!("A_r(P): {p:?} {a:?} R^2 = {r2}");
    assert!(r2 >= 0.95);
}

/// The loads of thesis Table 6-1, as fractions of σ_y A_n.
const TABLE_6_1: [f64; 9] = [0.05, 0.095, 0.11, 0.19, 0.25, 0.35, 0.45, 0.55, 0.65];

fn mean_cof_and_plastic_share(s: &Scene) -> (f64, f64) {
    let run = s
        .build()
        .unwrap()
        .slide(s.sliding.distance, s.sliding.step)
        .unwrap();
    let d = run.summary.dissipation;
    (run.summary.mean_cof, d.plastic / d.total())
}

/// Table 6-1: COF 1.08 … 0.92 over 0.05 … 0.65 σ_y A_n, independent of load.
/// We get 1.05 … 1.19, every load within ±15 % of the mean and in 0.8–1.2.
#[test]
fn cof_independent_of_load() {
    let mu: Vec<f64> = TABLE_6_1
        .iter()
        .map(|&f| mean_cof_and_plastic_share(&with_fraction(f)).0)
        .collect();
    let m = mu.iter().sum::<f64>() / mu.len() as f64;
    println!("COF(P), Table 6-1 loads: {mu:?}, mean {m}");
    assert!(mu.iter().all(|x| (x / m - 1.0).abs() <= 0.15), "{mu:?}");
    assert!(mu.iter().all(|x| (0.8..=1.2).contains(x)), "{mu:?}");
}

/// Why the chapter-6 scenes do not use the thesis's nearest-neighbour
/// pile-up ([`asperity::friction::PlasticUpdate`]): the volume of a yielded
/// rod goes to the rods next to the contact spot, which the counter-surface
/// reaches next, so it yields again, and the plastic share of the
/// dissipation (and the COF) grows with load. The Gaussian spread of the
/// scene keeps it small at every load.
#[test]
fn nearest_neighbour_pile_up_re_yields_with_load() {
    let nearest = |f: f64| {
        let mut s = with_fraction(f);
        s.rods.plastic = PlasticSpec::NearestNeighbours;
        mean_cof_and_plastic_share(&s)
    };
    let (low, high) = (nearest(0.05), nearest(0.65));
    println!("nearest neighbours: (COF, plastic share) {low:?} at 0.05, {high:?} at 0.65");
    assert!(low.1 < 0.05 && high.1 > 0.3, "{low:?} {high:?}");
    assert!(high.0 > 1.3 * low.0, "{low:?} {high:?}");
    for f in [0.05, 0.65] {
        let (_, share) = mean_cof_and_plastic_share(&with_fraction(f));
        assert!(
            share < 0.1,
            "Gaussian pile-up at {f}: plastic share {share}"
        );
    }
}

/// Thesis Table 6-1, "average dissipated energy" per step (J) at the
/// loads of [`TABLE_6_1`].
const TABLE_6_1_ENERGY: [f64; 9] = [
    0.50e-7, 0.84e-7, 0.91e-7, 1.57e-7, 2.01e-7, 2.80e-7, 3.56e-7, 4.39e-7, 5.23e-7,
];

/// The energy the slider dissipates per 1.5 µm step is the thesis's (Table
/// 6-1) within 10 % at every load (−1 … +9 % measured), on the synthetic
/// copper-like profiles.
#[test]
fn energy_per_step_matches_table_6_1() {
    for (f, e) in TABLE_6_1.iter().zip(TABLE_6_1_ENERGY) {
        let s = with_fraction(*f);
        let run = s
            .build()
            .unwrap()
            .slide(s.sliding.distance, s.sliding.step)
            .unwrap();
        let ratio = run.summary.mean_step_dissipation / e;
        println!("{f} σ_y A_n: energy per step / thesis = {ratio:.4}");
        assert!((ratio - 1.0).abs() <= 0.10, "{f}: {ratio}");
    }
}

/// The yielded-rod bound (README "Reproducing the thesis"): with the
/// counter height at the rod centre and one column of nano-asperities per
/// 1.5 µm rod, every rod in contact has all its m = 10 nano-asperities in
/// contact and carries at most σ_y A, so no step has μ below thesis 4.4
/// applied to one yielded rod, μ_y = m f/(σ_y A + m F_adh,1) = 0.9214.
/// Thesis Table 6-1 reports 0.90–0.92 at 0.25–0.65 σ_y A_n, at or below it.
#[test]
fn no_step_falls_below_the_yielded_rod_bound() {
    let slider = scene().build().unwrap();
    let m = slider.material();
    let force = m.yield_stress * slider.rod_width() * slider.depth();
    let bound = apparent_friction(m, slider.geometry().nano(), slider.nano_per_rod(), force)
        .unwrap()
        .cof;
    assert!((bound - 0.9214).abs() < 5e-4, "{bound}");
    for f in TABLE_6_1 {
        let s = with_fraction(f);
        let run = s
            .build()
            .unwrap()
            .slide(s.sliding.distance, s.sliding.step)
            .unwrap();
        let low = run
            .steps
            .iter()
            .map(|r| r.cof)
            .fold(f64::INFINITY, f64::min);
        assert!(
            low >= bound * (1.0 - 1e-12),
            "{f}: a step at μ = {low} < {bound}"
        );
    }
}

/// [`CounterHeight::HighestPoint`] (not the thesis's reading): on a flat
/// counter it is the rod-centre rule exactly; on the synthetic copper
/// profiles a rod touches at its highest counter point, so wider rods have
/// a smaller share of their nano-asperities in contact and the COF falls
/// with the rod width (the sign of thesis Table 6-3), while with the
/// rod-centre rule it does not.
#[test]
fn highest_point_counter_height() {
    let base = scene().build().unwrap();
    let flat = |h: CounterHeight| {
        let mut o = *base.options();
        o.track_end = TrackEnd::Periodic;
        o.counter_height = h;
        let s = Slider::new(
            base.geometry().clone(),
            *base.material(),
            vec![0.0; 64],
            1.5e-6,
            o,
        )
        .unwrap();
        s.slide(60e-6, 1.5e-6).unwrap().summary
    };
    assert_eq!(
        flat(CounterHeight::RodCentre),
        flat(CounterHeight::HighestPoint)
    );
    let cof = |k: f64, h: CounterHeight| {
        let mut s = with_fraction(0.25);
        s.rods.widths = vec![1.5e-6 * k];
        s.rods.counter_height = h;
        mean_cof_and_plastic_share(&s).0
    };
    let (fine, coarse) = (
        cof(1.0, CounterHeight::HighestPoint),
        cof(6.0, CounterHeight::HighestPoint),
    );
    println!("highest point: COF {fine} at 1.5 µm, {coarse} at 9 µm");
    assert!(coarse < 0.9 * fine, "{fine} {coarse}");
    let (fine, coarse) = (
        cof(1.0, CounterHeight::RodCentre),
        cof(6.0, CounterHeight::RodCentre),
    );
    assert!(coarse > 0.95 * fine, "{fine} {coarse}");
}

/// Thesis Tables 6-1 and 6-2 print COFs that are F/(N + 2A) of their own
/// energy columns (THESIS.md); with that form
/// ([`CofForm::DerjaguinDoubleAdhesion`], the per-step mean of
/// F/(N + 2A)) the slider is within 10 % of the printed COF at every load
/// of both tables (−0.3 … +8.6 % measured).
#[test]
fn double_adhesion_form_matches_tables_6_1_and_6_2() {
    let thesis_1 = [1.08, 0.98, 0.97, 0.93, 0.91, 0.91, 0.90, 0.91, 0.92];
    let mean = |s: &Scene| {
        let mut s = s.clone();
        s.cof_form = CofForm::DerjaguinDoubleAdhesion;
        let run = s
            .build()
            .unwrap()
            .slide(s.sliding.distance, s.sliding.step)
            .unwrap();
        let by_hand = run
            .steps
            .iter()
            .map(|r| r.friction_force / (r.normal_load + 2.0 * r.adhesion))
            .sum::<f64>()
            / run.steps.len() as f64;
        assert!((run.summary.mean_cof / by_hand - 1.0).abs() < 1e-12);
        run.summary.mean_cof
    };
    for (f, t) in TABLE_6_1.iter().zip(thesis_1) {
        let mu = mean(&with_fraction(*f));
        println!("Table 6-1 {f}: {mu:.4} against {t}");
        assert!((mu / t - 1.0).abs() <= 0.10, "{f}: {mu} against {t}");
    }
    let thesis_2 = [0.99, 0.94, 0.97, 0.96, 0.93, 0.94, 0.96];
    for (m, t) in [40usize, 80, 120, 160, 200, 240, 280].iter().zip(thesis_2) {
        let mut s = with_fraction(0.1);
        if let SurfaceSpec::SelfAffine { points, .. } = &mut s.surfaces.slider {
            *points = m + 1;
        }
        if let SurfaceSpec::SelfAffine { points, .. } = &mut s.surfaces.counter {
            *points = m + 151;
        }
        let mu = mean(&s);
        println!("Table 6-2 {m} rods: {mu:.4} against {t}");
        assert!((mu / t - 1.0).abs() <= 0.10, "{m}: {mu} against {t}");
    }
}

#[test]
fn cof_independent_of_nominal_area() {
    // Table 6-2: 40 … 280 rods of 1.5 µm at P = 0.1 sigma_y A_n.
    let mut mu = vec![];
    for m in [40usize, 120, 280] {
        let mut s = with_fraction(0.1);
        if let SurfaceSpec::SelfAffine { points, .. } = &mut s.surfaces.slider {
            *points = m + 1;
        }
        if let SurfaceSpec::SelfAffine { points, .. } = &mut s.surfaces.counter {
            *points = m + 151;
        }
        let run = s
            .build()
            .unwrap()
            .slide(s.sliding.distance, s.sliding.step)
            .unwrap();
        mu.push(run.summary.mean_cof);
    }
    let m = mu.iter().sum::<f64>() / mu.len() as f64;
    println!("COF(A_n): {mu:?}");
    assert!(mu.iter().all(|x| (x / m - 1.0).abs() <= 0.15));
}

/// The chapter-6 copper scene at 0.1 σ_y A_n with both surfaces cut from the
/// measured Hommel stylus profile. No independent COF exists for it: the
/// profile's material is not documented (profiles README) and its texture is
/// not the thesis's (rms 0.14 µm after a quadratic detrend against the
/// scene's 0.5 µm), and the model gives 1.9 here, outside both the thesis's
/// chapter-6 figures (0.79–1.08, Tables 6-1 to 6-3) and the Cu–Cu literature
/// range (0.8–1.2, thesis 6.5.1). So no COF is claimed. What is claimed: every
/// step's ledger is valid, the friction force is the dissipation over the
/// distance ((4-1)), and chemical bonds dominate the dissipation as thesis
/// 6.5.2 finds for copper (93 % here).
#[test]
fn measured_profile_slides() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/data/profiles");
    let file = dir.join("hommel_hfm1_stylus_linescan.csv");
    if !file.exists() {
        common::skip(format_args!(
            "{} is not present (the measured data live outside the project, in \
             ../shared/data next to the crate)",
            file.display()
        ));
        return;
    }
    let mut s = with_fraction(0.1);
    s.base = dir.clone();
    let spec = |start: f64, length: f64| SurfaceSpec::File {
        path: "hommel_hfm1_stylus_linescan.csv".into(),
        form: asperity::scene::FormSpec::Quadratic,
        start,
        length: Some(length),
    };
    s.surfaces.slider = spec(0.0, 135e-6);
    s.surfaces.counter = spec(1e-3, 300e-6);
    let run = s
        .build()
        .unwrap()
        .slide(s.sliding.distance, s.sliding.step)
        .unwrap();
    println!("measured (Hommel) profile: {:?}", run.summary);
    for r in &run.steps {
        check_step(r);
    }
    let d = run.summary.dissipation;
    let f = d.total() / s.sliding.distance;
    assert!((run.summary.mean_friction_force - f).abs() <= 1e-12 * f);
    assert!(
        d.chemical > d.van_der_waals + d.elastic + d.plastic && d.chemical / d.total() > 0.5,
        "{d:?}"
    );
}

// ----------------------------------------------------- no allocation

#[test]
fn step_does_not_allocate() {
    let slider = scene().build().unwrap();
    let m = slider.state_len();
    let mut work = slider.work();
    let mut a = vec![0.0; m];
    // Seated and stepped once: the work is at capacity.
    slider
        .step_in_place(&mut a, &along(1.5e-6), &mut work)
        .unwrap();
    let mut b = a.clone();
    let before = allocations();
    for _ in 0..50 {
        slider.step(&a, &mut b, &along(1.5e-6), &mut work).unwrap();
        check_step(record(&work));
        core::mem::swap(&mut a, &mut b);
    }
    assert_eq!(allocations() - before, 0, "the slider's step allocated");
}

// --------------------------------------------------- extremes, errors

fn rebuilt(loading: Loading) -> asperity::Result<Slider> {
    let base = scene().build().unwrap();
    let mut o: SliderOptions = *base.options();
    o.loading = loading;
    Slider::new(
        base.geometry().clone(),
        *base.material(),
        base.counter().to_vec(),
        base.counter_dx(),
        o,
    )
}

#[test]
fn zero_load_and_no_contact_give_zero_friction_and_a_flag() {
    let s = rebuilt(Loading::FixedLoad { load: 0.0 }).unwrap();
    let run = s.slide(15e-6, 1.5e-6).unwrap();
    for r in &run.steps {
        check_step(r);
        assert_eq!(r.normal_load, 0.0);
    }
    // Far away at fixed gap: nothing touches.
    let s = rebuilt(Loading::FixedGap { position: 1e-3 }).unwrap();
    let run = s.slide(15e-6, 1.5e-6).unwrap();
    for r in &run.steps {
        check_step(r);
        assert!(r.no_contact);
        assert_eq!((r.cof, r.friction_force, r.nano_contacts), (0.0, 0.0, 0));
    }
    assert_eq!(run.summary.no_contact_steps, run.summary.steps);
    assert_eq!(run.summary.mean_cof, 0.0);
}

#[test]
fn load_above_capacity_is_a_named_error() {
    let cap = scene().build().unwrap().capacity();
    match rebuilt(Loading::FixedLoad { load: 1.01 * cap }) {
        Err(Error::OutOfDomain { name: "load", .. }) => {}
        other => panic!("{other:?}"),
    }
}

#[test]
fn bad_arguments_are_named() {
    let s = scene().build().unwrap();
    let name = |e: Error| match e {
        Error::InvalidArgument { name, .. } | Error::OutOfDomain { name, .. } => name,
        other => panic!("{other:?}"),
    };
    assert_eq!(name(s.slide(f64::NAN, 1e-6).unwrap_err()), "distance");
    assert_eq!(name(s.slide(1e-5, 0.0).unwrap_err()), "step");
    let mut w = s.work();
    let a = vec![0.0; s.state_len()];
    let mut b = a.clone();
    assert_eq!(
        name(s.step(&a, &mut b, &along(f64::NAN), &mut w).unwrap_err()),
        "slip"
    );
    // Past the counter profile's end.
    assert_eq!(name(s.slide(1e-3, 1.5e-6).unwrap_err()), "position");
    let base = s.options();
    let mk = |counter: Vec<f64>, dx: f64| {
        Slider::new(s.geometry().clone(), *s.material(), counter, dx, *base)
    };
    assert_eq!(name(mk(vec![0.0; 10], -1.0).unwrap_err()), "counter_dx");
    assert_eq!(name(mk(vec![0.0], 1e-6).unwrap_err()), "counter.len()");
    assert_eq!(
        name(mk(vec![0.0, f64::INFINITY, 0.0], 1e-6).unwrap_err()),
        "counter"
    );
    assert_eq!(
        name(rebuilt(Loading::FixedGap { position: f64::NAN }).unwrap_err()),
        "position"
    );
    assert_eq!(
        name(rebuilt(Loading::FixedLoad { load: -1.0 }).unwrap_err()),
        "load"
    );
}

#[test]
fn periodic_track_and_flat_counter() {
    let base = scene().build().unwrap();
    let mut o = *base.options();
    o.track_end = TrackEnd::Periodic;
    // A flat counter-surface: a defined result, no NaN.
    let s = Slider::new(
        base.geometry().clone(),
        *base.material(),
        vec![0.0; 64],
        1.5e-6,
        o,
    )
    .unwrap();
    let run = s.slide(300e-6, 1.5e-6).unwrap();
    for r in &run.steps {
        check_step(r);
    }
    assert!(run.summary.mean_cof > 0.0);
}

/// The homogenised law built from slider runs reproduces, at each sampled
/// pressure, what a separate run of the slider at that load gives: the slip
/// force F = μ(N + A) equals the run's mean friction force (total
/// dissipation / distance), the dissipation split and the true contact area
/// are the run's.
#[test]
fn homogenised_law_from_slider_runs_reproduces_the_runs() {
    let base = scene().build().unwrap();
    let area = base.nominal_area();
    let (distance, step) = (30e-6, 1.5e-6);
    let pressures: Vec<f64> = [0.05, 0.2, 0.4]
        .iter()
        .map(|f| f * base.capacity() / area)
        .collect();
    let law = base.homogenise(&pressures, distance, step).unwrap();
    for &p in &pressures {
        let run = rebuilt(Loading::FixedLoad { load: p * area })
            .unwrap()
            .slide(distance, step)
            .unwrap();
        let inc = FrictionIncrement {
            normal_force: p * area,
            area,
            slip: [1e-7, 0.0],
            dt: 1e-3,
            ..Default::default()
        };
        let fresh = vec![0.0; law.state_len()];
        let mut new = fresh.clone();
        let out = law.step(&fresh, &mut new, &inc, &mut law.work()).unwrap();
        let f = run.summary.mean_friction_force;
        assert!(
            (out.force_magnitude - f).abs() <= 1e-12 * f,
            "p = {p:e} Pa: homogenised {} N, slider {f} N",
            out.force_magnitude
        );
        assert!(out.force[0] < 0.0, "the force opposes the slip");
        let d = run.summary.dissipation;
        let share = out.dissipation.chemical / out.dissipated;
        assert!((share - d.chemical / d.total()).abs() < 1e-12);
        let a = run.summary.mean_true_contact_area;
        assert!((out.true_contact_area - a).abs() <= 1e-12 * a);
    }
}

// ------------------------------------- the slider as a patch friction law

use asperity::friction::FrictionRegime;

/// The chapter-6 scene's fixed load (N).
const SCENE_LOAD: f64 = 0.18;

/// A slip `dx` along the track at the scene's load.
fn along(dx: f64) -> FrictionIncrement {
    loaded(SCENE_LOAD, [dx, 0.0])
}

fn loaded(load: f64, slip: [f64; 2]) -> FrictionIncrement {
    FrictionIncrement {
        normal_force: load,
        slip,
        dt: 1e-3,
        ..Default::default()
    }
}

/// The full record of the last step made with `work`.
fn record(work: &asperity::friction::FrictionWork) -> &SlideStep {
    work.get::<SliderWork>().expect("a slider's work").record()
}

/// Whether the last step made with `work` seated a fresh state.
fn seated(work: &asperity::friction::FrictionWork) -> bool {
    work.get::<SliderWork>().expect("a slider's work").seated()
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

fn same(a: &FrictionResponse, b: &FrictionResponse) -> bool {
    // Bit for bit (NaN-safe through the debug text of every field).
    format!("{a:?}") == format!("{b:?}")
}

/// `Slider::slide` runs the friction step: its records are, bit for bit,
/// the records (`SliderWork::record`) of a fresh flat state stepped in
/// place along the track at the scene's load, and the responses carry
/// them.
#[test]
fn flat_steps_reproduce_slide_bit_for_bit() {
    let s = scene();
    let slider = s.build().unwrap();
    let Loading::FixedLoad { load } = slider.options().loading else {
        panic!("the chapter-6 scene is load-controlled");
    };
    assert_eq!(load, SCENE_LOAD);
    let (d, dx) = (30e-6, 1.5e-6);
    let run = slider.slide(d, dx).unwrap();
    let m = slider.state_len();
    assert_eq!(m, 9 + 2 * slider.rods());
    let mut work = slider.work();
    let mut a = vec![0.0; m]; // all-zero: fresh
    let (mut path, mut total) = (0.0, 0.0);
    for (k, want) in run.steps.iter().enumerate() {
        let r = slider
            .step_in_place(&mut a, &loaded(load, [dx, 0.0]), &mut work)
            .unwrap();
        let rec = record(&work);
        assert_eq!(format!("{rec:?}"), format!("{want:?}"), "{k}");
        assert_eq!(seated(&work), k == 0, "only the first step seats");
        assert_eq!(
            r.force_magnitude.to_bits(),
            want.friction_force.to_bits(),
            "{k}"
        );
        assert_eq!(r.force[0], -want.friction_force, "opposes the slip");
        assert_eq!(r.force[1], 0.0);
        assert_eq!(r.dissipation, want.dissipation, "{k}");
        assert_eq!(r.dissipated, want.dissipation.total(), "{k}");
        assert_eq!(r.true_contact_area, want.true_contact_area, "{k}");
        assert_eq!(r.adhesion, want.adhesion, "{k}");
        assert_eq!(r.cof, want.cof, "{k}");
        assert_eq!(r.normal_force, want.normal_load, "{k}");
        assert_eq!(a[Slider::STATE_POSITION], want.position, "{k}");
        assert_eq!(a[Slider::STATE_ROD_POSITION], want.rod_position, "{k}");
        assert_eq!(r.regime(), FrictionRegime::Slip);
        assert_eq!(r.regime, 2);
        assert_eq!(r.tangents, 0, "no tangent unless asked");
        assert_eq!(r.dforce_dslip, [[0.0; 2]; 2]);
        // The stored energy is the rods'.
        let energies = &a[Slider::STATE_HEIGHTS + slider.rods()..];
        assert_eq!(r.stored_energy, energies.iter().sum::<f64>());
        // Dissipation >= 0 on every increment, by mechanism.
        r.dissipation.validate().unwrap();
        assert!(r.dissipated >= 0.0);
        path += dx;
        total += want.dissipation.total();
    }
    // The state's ledger: slip path and the summed dissipation.
    assert_eq!(a[Slider::STATE_FLAG], 1.0);
    assert!((a[1] - path).abs() <= 1e-12 * path);
    assert!((a[0] - total).abs() <= 1e-12 * total);
    let acc: f64 = a[Slider::STATE_MECHANISMS..Slider::STATE_HEIGHTS]
        .iter()
        .sum();
    assert!((acc - total).abs() <= 1e-12 * total);
    assert!((acc - run.summary.dissipation.total()).abs() <= 1e-12 * total);
}

#[test]
fn flat_step_is_a_pure_function_of_old_state_and_increment() {
    let slider = scene().build().unwrap();
    let m = slider.state_len();
    let mut work = slider.work();
    let mut st = vec![0.0; m];
    for _ in 0..7 {
        slider
            .step_in_place(&mut st, &along(1.5e-6), &mut work)
            .unwrap();
    }
    let old = st.clone();
    let mut inc = loaded(0.1, [1.2e-6, -0.7e-6]);
    inc.tangents = 3;
    let mut n1 = vec![0.0; m];
    let mut n2 = vec![1.0; m];
    let r1 = slider.step(&old, &mut n1, &inc, &mut work).unwrap();
    let rec1 = *record(&work);
    // A cut-back: a different increment in between, then the same again,
    // and with fresh work buffers.
    let mut scratch = vec![0.0; m];
    slider
        .step(&old, &mut scratch, &loaded(0.2, [3e-6, 0.0]), &mut work)
        .unwrap();
    let r2 = slider.step(&old, &mut n2, &inc, &mut work).unwrap();
    assert!(same(&r1, &r2), "{r1:?}\n{r2:?}");
    assert_eq!(bits(&n1), bits(&n2));
    assert_eq!(*record(&work), rec1);
    let mut other = slider.work();
    let r3 = slider.step(&old, &mut n2, &inc, &mut other).unwrap();
    assert!(same(&r1, &r3));
    assert_eq!(bits(&n1), bits(&n2));
    // In place gives the same.
    let mut inplace = old.clone();
    let r4 = slider.step_in_place(&mut inplace, &inc, &mut work).unwrap();
    assert!(same(&r1, &r4));
    assert_eq!(bits(&n1), bits(&inplace));
    assert_eq!(old, st, "old is only read");
    // Any work will do: one made for another law is rebuilt.
    let mut foreign = asperity::friction::FrictionWork::default();
    let r5 = slider.step(&old, &mut n2, &inc, &mut foreign).unwrap();
    assert!(same(&r1, &r5));
    assert_eq!(*record(&foreign), rec1);
}

#[test]
fn flat_step_with_the_hosts_load_matches_a_slider_built_for_that_load() {
    let base = scene().build().unwrap();
    let dx = 1.5e-6;
    let m = base.state_len();
    let mut work = base.work();
    for f in [0.0, 0.07, 0.3] {
        let load = f * base.capacity();
        let run = rebuilt(Loading::FixedLoad { load })
            .unwrap()
            .slide(12e-6, dx)
            .unwrap();
        let mut st = vec![0.0; m];
        for (k, want) in run.steps.iter().enumerate() {
            let r = base
                .step_in_place(&mut st, &loaded(load, [dx, 0.0]), &mut work)
                .unwrap();
            assert_eq!(r.force_magnitude, want.friction_force, "f = {f}, step {k}");
            assert_eq!(r.dissipation, want.dissipation);
            assert_eq!(r.true_contact_area, want.true_contact_area);
            assert_eq!(r.normal_force, load);
            assert_eq!(record(&work), want);
        }
    }
}

#[test]
fn slip_direction_sets_the_force_direction_not_its_size() {
    let slider = scene().build().unwrap();
    let m = slider.state_len();
    let mut work = slider.work();
    let mut st = vec![0.0; m];
    for _ in 0..3 {
        slider
            .step_in_place(&mut st, &along(1.5e-6), &mut work)
            .unwrap();
    }
    let s = 1.5e-6;
    let mut n = vec![0.0; m];
    let r0 = slider
        .step(&st, &mut n, &loaded(0.18, [s, 0.0]), &mut work)
        .unwrap();
    for (sx, sy) in [(0.0, s), (-s, 0.0), (0.0, -s)] {
        let r = slider
            .step(&st, &mut n, &loaded(0.18, [sx, sy]), &mut work)
            .unwrap();
        // Same path length, same track advance, same friction force ...
        assert_eq!(r.force_magnitude, r0.force_magnitude);
        assert_eq!(r.dissipation, r0.dissipation);
        // ... opposing the slip.
        assert_eq!(
            r.force,
            [-r0.force_magnitude * sx / s, -r0.force_magnitude * sy / s]
        );
    }
    // An oblique slip: |F| = F_t, F antiparallel to the slip.
    let (sx, sy) = (0.9e-6, -1.3e-6);
    let r = slider
        .step(&st, &mut n, &loaded(0.18, [sx, sy]), &mut work)
        .unwrap();
    let fm = r.force[0].hypot(r.force[1]);
    assert!((fm - r.force_magnitude).abs() <= 1e-14 * fm);
    let cross = r.force[0] * sy - r.force[1] * sx;
    assert!(cross.abs() <= 1e-14 * fm * sx.hypot(sy));
    assert!(r.force[0] * sx + r.force[1] * sy < 0.0);
    // F·Δs = −ΔU: the work of the friction force is the dissipation.
    let work_done = -(r.force[0] * sx + r.force[1] * sy);
    assert!((work_done - r.dissipated).abs() <= 1e-12 * r.dissipated);
}

#[test]
fn zero_slip_is_stick_with_nothing_dissipated() {
    let slider = scene().build().unwrap();
    let m = slider.state_len();
    let mut work = slider.work();
    // An all-zero state and an all-zero increment: seated, nothing else.
    let zero = vec![0.0; m];
    let mut st = vec![0.0; m];
    let r = slider
        .step(&zero, &mut st, &FrictionIncrement::default(), &mut work)
        .unwrap();
    assert!(seated(&work));
    assert_eq!(r.regime(), FrictionRegime::Stick);
    assert_eq!(
        (r.force, r.force_magnitude, r.dissipated, r.cof),
        ([0.0; 2], 0.0, 0.0, 0.0)
    );
    assert_eq!(record(&work).position, 0.0);
    assert!(r.true_contact_area > 0.0);
    assert_eq!(st[Slider::STATE_FLAG], 1.0);
    assert_eq!(st[1], 0.0);
    // Seating is what a fresh state's first step does before it moves: a
    // step from the seated state equals the same step from the fresh one,
    // bit for bit.
    let mut seated_state = vec![0.0; m];
    slider
        .step(
            &zero,
            &mut seated_state,
            &loaded(SCENE_LOAD, [0.0; 2]),
            &mut work,
        )
        .unwrap();
    let (mut a, mut b) = (vec![0.0; m], vec![0.0; m]);
    let ra = slider
        .step(&seated_state, &mut a, &along(1.5e-6), &mut work)
        .unwrap();
    assert!(!seated(&work));
    let rec_a = *record(&work);
    let rb = slider
        .step(&zero, &mut b, &along(1.5e-6), &mut work)
        .unwrap();
    assert!(seated(&work));
    assert!(same(&ra, &rb), "{ra:?}\n{rb:?}");
    assert_eq!(bits(&a), bits(&b));
    assert_eq!(*record(&work), rec_a);
    // Zero slip under a heavier load: a normal loading step, stick, nothing
    // booked, the track position kept; tangents asked are 0.
    let mut inc = loaded(0.5 * slider.capacity(), [0.0, 0.0]);
    inc.tangents = 3;
    let before = st.clone();
    let r = slider.step_in_place(&mut st, &inc, &mut work).unwrap();
    assert_eq!(r.regime(), FrictionRegime::Stick);
    assert_eq!((r.force_magnitude, r.dissipated), (0.0, 0.0));
    assert_eq!(r.dforce_dslip, [[0.0; 2]; 2]);
    assert_eq!(r.dforce_dnormal, [0.0; 2]);
    assert_eq!(r.tangents, 0);
    assert_eq!(r.normal_force, 0.5 * slider.capacity());
    assert_eq!(st[Slider::STATE_POSITION], before[Slider::STATE_POSITION]);
    assert_eq!(st[..2], before[..2]);
    assert_eq!(
        st[Slider::STATE_MECHANISMS..Slider::STATE_HEIGHTS],
        before[Slider::STATE_MECHANISMS..Slider::STATE_HEIGHTS]
    );
    // More rods now yield: heights changed (plastic indentation, not
    // friction).
    assert_ne!(st[Slider::STATE_HEIGHTS..], before[Slider::STATE_HEIGHTS..]);
}

#[test]
fn fresh_state_starts_at_its_position() {
    let slider = scene().build().unwrap();
    let m = slider.state_len();
    let mut work = slider.work();
    let x0 = 45e-6;
    let dx = 1.5e-6;
    let mut clean = vec![0.0; m];
    clean[Slider::STATE_POSITION] = x0;
    // Of a fresh state only the position is read (and the accumulators,
    // the mechanisms' among them, carried): the rest is ignored.
    let mut st = clean.clone();
    st[Slider::STATE_ROD_POSITION] = 7.0;
    st[Slider::STATE_HEIGHTS] = 123.0;
    st[Slider::STATE_HEIGHTS + slider.rods()] = -1.0;
    let mut at_zero = vec![0.0; m];
    let mut w = slider.work();
    for k in 0..5 {
        let want = slider
            .step_in_place(&mut clean, &along(dx), &mut w)
            .unwrap();
        let r = slider
            .step_in_place(&mut st, &along(dx), &mut work)
            .unwrap();
        assert!(same(&r, &want), "{k}");
        assert_eq!(bits(&st), bits(&clean), "{k}");
        let p = record(&work).position;
        assert!((p - (x0 + (k + 1) as f64 * dx)).abs() < 1e-18);
        // Elsewhere on the counter-surface, another history.
        slider
            .step_in_place(&mut at_zero, &along(dx), &mut w)
            .unwrap();
    }
    assert_ne!(
        st[Slider::STATE_HEIGHTS..],
        at_zero[Slider::STATE_HEIGHTS..]
    );
}

#[test]
fn tangents_are_the_documented_secants() {
    let slider = scene().build().unwrap();
    let m = slider.state_len();
    let mut work = slider.work();
    let mut st = vec![0.0; m];
    for _ in 0..5 {
        slider
            .step_in_place(&mut st, &along(1.5e-6), &mut work)
            .unwrap();
    }
    let (load, s) = (0.12, 1.5e-6);
    let mut n = vec![0.0; m];
    let only = |tangents: i32| FrictionIncrement {
        tangents,
        ..loaded(load, [s, 0.0])
    };
    let r0 = slider.step(&st, &mut n, &only(0), &mut work).unwrap();
    let rn = slider.step(&st, &mut n, &only(1), &mut work).unwrap();
    let rs = slider.step(&st, &mut n, &only(2), &mut work).unwrap();
    let r = slider.step(&st, &mut n, &only(3), &mut work).unwrap();
    // Only what is asked is computed; the step itself is unchanged.
    assert_eq!((rn.tangents, rs.tangents, r.tangents), (1, 2, 3));
    assert_eq!(rn.dforce_dslip, [[0.0; 2]; 2]);
    assert_eq!(rs.dforce_dnormal, [0.0; 2]);
    for x in [&rn, &rs, &r] {
        assert_eq!(x.force_magnitude, r0.force_magnitude);
        assert_eq!(x.dissipation, r0.dissipation);
    }
    assert_eq!(r.dforce_dnormal, rn.dforce_dnormal);
    assert_eq!(r.dforce_dslip, rs.dforce_dslip);
    // The secants, recomputed from the same old state by steps without
    // tangents at the documented perturbed loads and slips.
    let mut w = slider.work();
    let mut tmp = vec![0.0; m];
    let mut ft = |slip: f64, load: f64| {
        slider
            .step(&st, &mut tmp, &loaded(load, [slip, 0.0]), &mut w)
            .unwrap()
            .force_magnitude
    };
    let h = Slider::TANGENT_STEP;
    let dn = h * load.max(h * slider.capacity());
    let dfdn = (ft(s, load + dn) - ft(s, load - dn)) / (2.0 * dn);
    let dfds = (ft(s + h * s, load) - ft(s - h * s, load)) / (2.0 * h * s);
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * b.abs().max(1e-300);
    assert!(
        close(r.dforce_dnormal[0], -dfdn),
        "{:?} vs {}",
        r.dforce_dnormal,
        -dfdn
    );
    assert_eq!(r.dforce_dnormal[1], 0.0);
    assert!(
        close(r.dforce_dslip[0][0], -dfds),
        "{:?} vs {}",
        r.dforce_dslip,
        -dfds
    );
    // Across the slip the force turns with it: −F_t/s, closed form.
    let turn = -r0.force_magnitude / s;
    assert!(close(r.dforce_dslip[1][1], turn));
    assert_eq!(r.dforce_dslip[0][1], 0.0);
    assert_eq!(r.dforce_dslip[1][0], 0.0);
    // The friction force grows with the load: dF_t/dN > 0 (more contacts).
    assert!(dfdn > 0.0);
    // A rotated slip rotates the tangent: R diag(a, b) Rᵀ.
    let th: f64 = 0.6;
    let (c, sn) = (th.cos(), th.sin());
    let mut inc = only(3);
    inc.slip = [s * c, s * sn];
    let q = slider.step(&st, &mut n, &inc, &mut work).unwrap();
    let (a, b) = (r.dforce_dslip[0][0], r.dforce_dslip[1][1]);
    let want = [
        [a * c * c + b * sn * sn, (a - b) * c * sn],
        [(a - b) * c * sn, a * sn * sn + b * c * c],
    ];
    for i in 0..2 {
        for j in 0..2 {
            assert!(
                (q.dforce_dslip[i][j] - want[i][j]).abs() <= 1e-6 * a.abs().max(b.abs()),
                "{:?} vs {want:?}",
                q.dforce_dslip
            );
        }
    }
    assert!((q.dforce_dnormal[0] - r.dforce_dnormal[0] * c).abs() <= 1e-6 * dfdn.abs());
}

#[test]
fn flat_step_limits_and_bad_input() {
    let slider = scene().build().unwrap();
    let m = slider.state_len();
    let mut work = slider.work();
    let name = |e: Error| match e {
        Error::InvalidArgument { name, .. }
        | Error::OutOfDomain { name, .. }
        | Error::UnknownSelector { name, .. } => name,
        other => panic!("{other:?}"),
    };
    let mut st = vec![0.0; m];
    slider
        .step_in_place(&mut st, &along(1.5e-6), &mut work)
        .unwrap();
    let sentinel = vec![-7.0; m];
    let mut new = sentinel.clone();
    let mut err = |old: &[f64], inc: FrictionIncrement| {
        let e = slider.step(old, &mut new, &inc, &mut work).unwrap_err();
        assert_eq!(new, sentinel, "new untouched on error");
        name(e)
    };
    let cap = slider.capacity();
    // Non-finite input.
    assert_eq!(err(&st, along(f64::NAN)), "slip");
    assert_eq!(err(&st, loaded(0.1, [0.0, f64::INFINITY])), "slip");
    assert_eq!(err(&st, loaded(0.1, [f64::MAX, f64::MAX])), "slip");
    assert_eq!(
        err(
            &st,
            FrictionIncrement {
                dt: -1.0,
                ..along(1e-6)
            }
        ),
        "dt"
    );
    assert_eq!(
        err(
            &st,
            FrictionIncrement {
                dt: f64::NAN,
                ..along(1e-6)
            }
        ),
        "dt"
    );
    assert_eq!(err(&st, loaded(f64::NAN, [1e-6, 0.0])), "normal_force");
    assert_eq!(err(&st, loaded(-1e-3, [1e-6, 0.0])), "normal_force");
    // Load above the total yield capacity: no equilibrium.
    assert_eq!(err(&st, loaded(1.001 * cap, [1e-6, 0.0])), "normal_force");
    assert_eq!(
        err(
            &st,
            FrictionIncrement {
                tangents: 4,
                ..along(1e-6)
            }
        ),
        "tangents"
    );
    // Bad states.
    assert_eq!(err(&st[1..], along(1e-6)), "old.len()");
    let mut bad = st.clone();
    bad[Slider::STATE_FLAG] = 2.0;
    assert_eq!(err(&bad, along(1e-6)), "old.flag");
    let mut bad = st.clone();
    bad[Slider::STATE_POSITION] = f64::NAN;
    assert_eq!(err(&bad, along(1e-6)), "old.position");
    let mut bad = st.clone();
    bad[Slider::STATE_ROD_POSITION] = f64::INFINITY;
    assert_eq!(err(&bad, along(1e-6)), "old.rod_position");
    let mut bad = st.clone();
    bad[Slider::STATE_MECHANISMS + 2] = -1.0;
    assert_eq!(err(&bad, along(1e-6)), "old.mechanisms");
    let mut bad = st.clone();
    bad[0] = -1.0;
    assert_eq!(err(&bad, along(1e-6)), "old.dissipation");
    let mut bad = st.clone();
    bad[1] = f64::NAN;
    assert_eq!(err(&bad, along(1e-6)), "old.slip_path");
    let mut bad = st.clone();
    bad[Slider::STATE_HEIGHTS + 3] = f64::NAN;
    assert_eq!(err(&bad, along(1e-6)), "state.heights");
    let mut bad = st.clone();
    bad[Slider::STATE_HEIGHTS + slider.rods()] = -1.0;
    assert_eq!(err(&bad, along(1e-6)), "state.energy");
    // Past the counter profile's end.
    assert_eq!(err(&st, along(1e-3)), "position");
    let e = slider
        .step(&st, &mut vec![0.0; m + 1], &along(1e-6), &mut work)
        .unwrap_err();
    assert_eq!(name(e), "new.len()");
    // A rod-bed position NaN is "none": no warm start, same equilibrium.
    let mut cold = st.clone();
    cold[Slider::STATE_ROD_POSITION] = f64::NAN;
    let mut a = vec![0.0; m];
    let mut b = vec![0.0; m];
    slider.step(&st, &mut a, &along(1.5e-6), &mut work).unwrap();
    let ra = *record(&work);
    slider
        .step(&cold, &mut b, &along(1.5e-6), &mut work)
        .unwrap();
    let rb = *record(&work);
    assert!((ra.rod_position - rb.rod_position).abs() <= 1e-15);
    assert_eq!(ra.nano_contacts, rb.nano_contacts);

    // Zero load: a defined result (the slider just touches; adhesive
    // contacts may still give friction), finite, dissipation >= 0.
    let r = slider
        .step(&st, &mut a, &loaded(0.0, [1.5e-6, 0.0]), &mut work)
        .unwrap();
    assert_eq!(r.normal_force, 0.0);
    assert!(r.force_magnitude.is_finite() && r.cof.is_finite() && r.dissipated >= 0.0);
    // Load at the capacity: every rod yields, still defined.
    let r = slider
        .step(&st, &mut a, &loaded(cap, [1.5e-6, 0.0]), &mut work)
        .unwrap();
    assert_eq!(record(&work).yielded_rods, slider.rods());
    assert!(r.force_magnitude.is_finite() && r.force_magnitude > 0.0);
}

#[test]
fn mismatched_profile_lengths() {
    let base = scene().build().unwrap();
    let o = *base.options();
    let length = base.rods() as f64 * base.rod_width();
    let mk = |counter: Vec<f64>, dx: f64, track_end: TrackEnd| {
        let mut o = o;
        o.track_end = track_end;
        Slider::new(base.geometry().clone(), *base.material(), counter, dx, o)
    };
    let wave = |n: usize, dx: f64| -> Vec<f64> {
        (0..n)
            .map(|j| 3e-7 * (j as f64 * dx * 2.0 * std::f64::consts::PI / 20e-6).sin())
            .collect()
    };
    // A counter-surface shorter than the slider: a named error at
    // construction (not a failure at the first step) ...
    let short = wave(40, 1.5e-6);
    assert!(39.0 * 1.5e-6 < length);
    match mk(short.clone(), 1.5e-6, TrackEnd::Error) {
        Err(Error::InvalidArgument {
            name: "counter.len()",
            value,
            ..
        }) => assert_eq!(value, 40.0),
        other => panic!("{other:?}"),
    }
    // ... and a defined slide when it repeats.
    let s = mk(short, 1.5e-6, TrackEnd::Periodic).unwrap();
    let run = s.slide(60e-6, 1.5e-6).unwrap();
    for r in &run.steps {
        check_step(r);
        assert!(r.friction_force > 0.0);
    }
    // Just long enough: accepted, and one more increment runs off the end.
    let n = (length / 1.5e-6).round() as usize + 1;
    let s = mk(wave(n, 1.5e-6), 1.5e-6, TrackEnd::Error).unwrap();
    let mut st = vec![0.0; s.state_len()];
    let mut w = s.work();
    s.step_in_place(&mut st, &FrictionIncrement::default(), &mut w)
        .unwrap();
    let e = s
        .step_in_place(&mut st, &along(1.5e-6), &mut w)
        .unwrap_err();
    assert!(
        matches!(
            e,
            Error::OutOfDomain {
                name: "position",
                ..
            }
        ),
        "{e:?}"
    );
    // A counter sampled at another spacing than the rods: interpolated, and
    // a finer sampling of the same sine gives nearly the same contacts.
    let coarse = mk(wave(200, 1.5e-6), 1.5e-6, TrackEnd::Error).unwrap();
    let fine = mk(wave(600, 0.5e-6), 0.5e-6, TrackEnd::Error).unwrap();
    let a = coarse.slide(30e-6, 1.5e-6).unwrap().summary;
    let b = fine.slide(30e-6, 1.5e-6).unwrap().summary;
    assert!(
        (a.mean_true_contact_area / b.mean_true_contact_area - 1.0).abs() < 0.05,
        "{} vs {}",
        a.mean_true_contact_area,
        b.mean_true_contact_area
    );
}

#[test]
fn flat_step_on_a_flat_counter_surface() {
    let base = scene().build().unwrap();
    let mut o = *base.options();
    o.track_end = TrackEnd::Periodic;
    let s = Slider::new(
        base.geometry().clone(),
        *base.material(),
        vec![0.0; 8],
        1.5e-6,
        o,
    )
    .unwrap();
    let mut st = vec![0.0; s.state_len()];
    let mut w = s.work();
    for _ in 0..20 {
        let r = s
            .step_in_place(&mut st, &loaded(0.1, [1e-6, 1e-6]), &mut w)
            .unwrap();
        assert!(r.force_magnitude.is_finite() && r.force_magnitude > 0.0);
        r.dissipation.validate().unwrap();
    }
}

/// A block of the points `normal`, `slip` (no areas: the slider does not
/// use them) at Δt = 1 ms.
fn block<'a>(
    normal: &'a [f64],
    slip: &'a [f64],
    states: BlockStates<'a>,
    forces: &'a mut [f64],
    dissipation: Option<&'a mut [f64]>,
) -> FrictionBlock<'a> {
    FrictionBlock {
        normal_force: normal,
        area: None,
        slip,
        dt: 1e-3,
        tangents: 0,
        states,
        tangential_force: Some(forces),
        dissipation,
        responses: None,
    }
}

#[test]
fn block_step_equals_scalar_steps() {
    let slider = scene().build().unwrap();
    let m = slider.state_len();
    let n = 5;
    let cap = slider.capacity();
    let normal: Vec<f64> = (0..n).map(|i| (0.02 + 0.08 * i as f64) * cap).collect();
    let mut states = vec![0.0; n * m];
    for i in 0..n {
        states[i * m + Slider::STATE_POSITION] = 10e-6 * i as f64;
    }
    let mut work = slider.work();
    let mut scalar = states.clone();
    let mut sep_new = vec![0.0; n * m];
    for k in 0..6 {
        let slip: Vec<f64> = (0..n)
            .flat_map(|i| {
                let th = 0.9 * i as f64 + 0.3 * k as f64;
                [1.4e-6 * th.cos(), 1.4e-6 * th.sin()]
            })
            .collect();
        let mut f_block = vec![0.0; 2 * n];
        let mut d_block = vec![0.0; n];
        let mut f_sep = vec![0.0; 2 * n];
        let sep = BlockStates::Separate {
            old: &states,
            new: &mut sep_new,
        };
        slider
            .step_block(block(&normal, &slip, sep, &mut f_sep, None), &mut work)
            .unwrap();
        slider
            .step_block(
                block(
                    &normal,
                    &slip,
                    BlockStates::InPlace(&mut states),
                    &mut f_block,
                    Some(&mut d_block),
                ),
                &mut work,
            )
            .unwrap();
        assert_eq!(bits(&states), bits(&sep_new));
        assert_eq!(bits(&f_block), bits(&f_sep));
        for i in 0..n {
            let r = slider
                .step_in_place(
                    &mut scalar[i * m..(i + 1) * m],
                    &loaded(normal[i], [slip[2 * i], slip[2 * i + 1]]),
                    &mut work,
                )
                .unwrap();
            assert_eq!(r.force, [f_block[2 * i], f_block[2 * i + 1]]);
            assert_eq!(r.dissipated, d_block[i]);
            assert!(d_block[i] >= 0.0);
        }
        assert_eq!(bits(&states), bits(&scalar));
    }
    // An error at element 3: elements before written, from 3 on untouched.
    let mut bad = normal.clone();
    bad[3] = 2.0 * cap;
    let before = states.clone();
    let mut f = vec![9.0; 2 * n];
    let e = slider
        .step_block(
            block(
                &bad,
                &[1e-6; 10],
                BlockStates::InPlace(&mut states),
                &mut f,
                None,
            ),
            &mut work,
        )
        .unwrap_err();
    assert_eq!(e.index, 3);
    assert!(matches!(
        e.error,
        Error::OutOfDomain {
            name: "normal_force",
            ..
        }
    ));
    assert_ne!(states[..3 * m], before[..3 * m]);
    assert_eq!(states[3 * m..], before[3 * m..]);
    assert_eq!(f[6..], [9.0; 4]);
    // Mismatched lengths name the slice.
    let e = slider
        .step_block(
            block(
                &normal,
                &[0.0; 3],
                BlockStates::InPlace(&mut states),
                &mut f,
                None,
            ),
            &mut work,
        )
        .unwrap_err();
    assert!(matches!(
        e.error,
        Error::InvalidArgument {
            name: "slip.len()",
            ..
        }
    ));
}

#[test]
fn one_slider_many_threads_one_work_each() {
    let slider = scene().build().unwrap();
    let m = slider.state_len();
    let patch = |i: usize| -> Vec<u64> {
        let mut work = slider.work();
        let mut st = vec![0.0; m];
        st[Slider::STATE_POSITION] = 5e-6 * i as f64;
        let mut out = vec![];
        for k in 0..20 {
            let th = 0.3 * (i + k) as f64;
            let r = slider
                .step_in_place(
                    &mut st,
                    &loaded(
                        0.03 * (i + 1) as f64,
                        [1.2e-6 * th.cos(), 1.2e-6 * th.sin()],
                    ),
                    &mut work,
                )
                .unwrap();
            out.extend([
                r.force[0].to_bits(),
                r.force[1].to_bits(),
                r.dissipated.to_bits(),
            ]);
        }
        out.extend(bits(&st));
        out
    };
    let serial: Vec<Vec<u64>> = (0..4).map(patch).collect();
    let parallel: Vec<Vec<u64>> = std::thread::scope(|s| {
        let h: Vec<_> = (0..4).map(|i| s.spawn(move || patch(i))).collect();
        h.into_iter().map(|h| h.join().unwrap()).collect()
    });
    assert_eq!(serial, parallel);
}

/// A fresh state carries every accumulator it is given (the total, the
/// slip path and the four mechanisms), so the total stays the sum of the
/// mechanisms' after the seat and the first step.
#[test]
fn fresh_state_carries_its_accumulators() {
    let slider = scene().build().unwrap();
    let m = slider.state_len();
    let mut work = slider.work();
    let mut st = vec![0.0; m];
    st[0] = 10.0;
    st[1] = 2e-6;
    st[Slider::STATE_MECHANISMS..Slider::STATE_HEIGHTS].copy_from_slice(&[1.0, 2.0, 3.0, 4.0]);
    let r = slider
        .step_in_place(&mut st, &along(1.5e-6), &mut work)
        .unwrap();
    assert!(r.dissipated > 0.0);
    assert_eq!(st[0], 10.0 + r.dissipated);
    assert_eq!(st[1], 2e-6 + 1.5e-6);
    let d = r.dissipation;
    let want = [
        1.0 + d.chemical,
        2.0 + d.van_der_waals,
        3.0 + d.elastic,
        4.0 + d.plastic,
    ];
    assert_eq!(st[Slider::STATE_MECHANISMS..Slider::STATE_HEIGHTS], want);
}
