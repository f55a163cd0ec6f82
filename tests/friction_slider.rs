//! The sliding hierarchical slider (issue 6 §2 sliding, §3, §8): the
//! chapter-6 findings on seeded synthetic profiles (and a measured profile
//! when `../shared/data/profiles/` is present), bad input, extremes, and no
//! allocation per step.
//!
//! Targets the model as written does not meet on our profiles are kept as
//! `#[ignore]`d tests stating the figure we get (run them with
//! `--ignored`); see `examples/chapter6.rs` for the full study.

use asperity::friction::{Loading, SlideStep, Slider, SliderOptions, SliderState, TrackEnd};
use asperity::scene::{LoadingSpec, Scene, SurfaceSpec};
use asperity::Error;
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;
use std::path::Path;

// ------------------------------------------------- counting allocator

struct Counting;
thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}
#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocations() -> usize {
    ALLOCATIONS.with(|c| c.get())
}

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
/// We get ≈ 1.3 at 0.18 N with the synthetic copper-like profiles: the
/// plastic work of rods re-yielding as they slide over new counter
/// asperities is ≈ 25 % of the dissipation (the thesis's smoother measured
/// profiles yield 3 coarse rods only).
#[test]
#[ignore = "not met: mean COF ≈ 1.3 at 0.18 N (target 0.8–1.2), plastic work ≈ 25 %"]
fn chapter6_average_cof_in_literature_range() {
    let s = scene();
    let run = s
        .build()
        .unwrap()
        .slide(s.sliding.distance, s.sliding.step)
        .unwrap();
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

/// Table 6-1: COF 1.08 … 0.92, independent of load. We get COF rising from
/// ≈ 1.10 (0.095 σ_y A_n) to ≈ 1.69 (0.65 σ_y A_n): the plastic share grows
/// with the number of yielded rods.
#[test]
#[ignore = "not met: COF rises with load (≈ 1.1 → 1.45 over 0.05–0.45 sigma_y A_n)"]
fn cof_independent_of_load() {
    let mut mu = vec![];
    for f in [0.05, 0.11, 0.25, 0.45] {
        let s = with_fraction(f);
        mu.push(
            s.build()
                .unwrap()
                .slide(s.sliding.distance, s.sliding.step)
                .unwrap()
                .summary
                .mean_cof,
        );
    }
    let m = mu.iter().sum::<f64>() / mu.len() as f64;
    assert!(mu.iter().all(|x| (x / m - 1.0).abs() <= 0.15), "{mu:?}");
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

#[test]
fn measured_profile_slides() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/data/profiles");
    let file = dir.join("hommel_hfm1_stylus_linescan.csv");
    if !file.exists() {
        println!("skipped: {} absent", file.display());
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
    assert!(run.summary.mean_cof > 0.0 && run.summary.mean_cof.is_finite());
}

// ----------------------------------------------------- no allocation

#[test]
fn step_does_not_allocate() {
    let slider = scene().build().unwrap();
    let mut work = slider.work();
    let fresh = slider.fresh_state();
    let mut a = fresh.clone();
    slider.seat(&fresh, &mut a, &mut work).unwrap();
    let mut b: SliderState = a.clone();
    let before = allocations();
    for _ in 0..50 {
        let r = slider.step(&a, &mut b, 1.5e-6, &mut work).unwrap();
        check_step(&r);
        core::mem::swap(&mut a, &mut b);
    }
    assert_eq!(allocations() - before, 0, "Slider::step allocated");
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
    let a = s.fresh_state();
    let mut b = a.clone();
    assert_eq!(name(s.step(&a, &mut b, -1.0, &mut w).unwrap_err()), "slip");
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
    use asperity::friction::{FrictionIncrement, FrictionPointState, FrictionResponse};
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
            stick_stiffness: 0.0,
        };
        let mut new = FrictionPointState::default();
        let mut out = FrictionResponse::default();
        law.step(&FrictionPointState::default(), &inc, &mut new, &mut out)
            .unwrap();
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
