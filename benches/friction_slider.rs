//! The chapter-6 scene end to end (issue 6 §7): 90 rods of 1.5 µm, 150 µm of
//! sliding at the profile's resolution (100 increments), exact sweep against
//! the thesis's dense formulation (6-12)/(6-16). Bar: ≤ 50 ms end to end.
//!
//! `cargo bench --bench friction_slider`

use asperity::friction::{RodSolver, Slider};
use asperity::scene::{Scene, SolverSpec};
use std::hint::black_box;
use std::path::Path;
use std::time::Instant;

fn time(label: &str, reps: usize, mut f: impl FnMut()) -> f64 {
    f();
    let t = Instant::now();
    for _ in 0..reps {
        f();
    }
    let s = t.elapsed().as_secs_f64() / reps as f64;
    println!("{label:<58} {:>10.3} ms", s * 1e3);
    s
}

fn main() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/chapter6_copper.json");
    let scene = Scene::from_file(&path).expect("scene");
    let (d, dx) = (scene.sliding.distance, scene.sliding.step);
    let slider: Slider = scene.build().unwrap();
    println!(
        "chapter-6 scene: {} rods of {:.1} µm x {:.1} µm, {} nano-asperities per rod, {} steps",
        slider.rods(),
        slider.rod_width() * 1e6,
        slider.depth() * 1e6,
        slider.nano_per_rod(),
        (d / dx).round()
    );
    let end_to_end = time("end to end (scene build + slide), sweep", 20, || {
        let s = scene.build().unwrap();
        black_box(s.slide(d, dx).unwrap());
    });
    let sweep = time("slide only, sweep (warm start)", 20, || {
        black_box(slider.slide(d, dx).unwrap());
    });
    let mut dense_scene = scene.clone();
    dense_scene.rods.solver = SolverSpec::Dense;
    let dense = dense_scene.build().unwrap();
    assert_eq!(dense.options().rod.solver, RodSolver::Dense);
    let dense_t = time("slide only, dense (6-12)/(6-16), faer LU", 3, || {
        black_box(dense.slide(d, dx).unwrap());
    });
    let a = slider.slide(d, dx).unwrap().summary;
    let b = dense.slide(d, dx).unwrap().summary;
    println!(
        "dense / sweep = {:.1}; mean COF sweep {:.6}, dense {:.6}",
        dense_t / sweep,
        a.mean_cof,
        b.mean_cof
    );
    println!(
        "bar <= 50 ms end to end: {}",
        if end_to_end <= 0.05 { "met" } else { "NOT met" }
    );
}
