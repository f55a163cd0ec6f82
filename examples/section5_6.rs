//! Thesis 5.6: the multi-scale, single-level hierarchical slider (5.6.1:
//! micro-asperities as flat rods all at one height, nano-asperities on
//! their tops, 98 of them) sliding over a rigid counter-profile, reported
//! beside the thesis's figures (5.6.2: Figures 5-23 to 5-25).
//!
//! The slider is the chapter-6 model's with `SliderGeometry::uniform` (the
//! single level the thesis gives up in chapter 6), copper, the nano-
//! asperities and counter-surface of `examples/scenes/chapter6_copper.json`
//! (a seeded copper-like self-affine profile: the measured copper profile of
//! 5.6 is not in the project's data).
//!
//! `cargo run --release --example section5_6`

use asperity::friction::{
    CofForm, Loading, PlasticUpdate, RodOptions, RodSolver, Slider, SliderGeometry, SliderOptions,
};
use asperity::scene::Scene;
use std::path::Path;

fn main() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/chapter6_copper.json");
    let scene = Scene::from_file(path).expect("chapter-6 scene");
    let copper = scene.build().expect("chapter-6 slider");
    let material = scene.material();
    let nano = *copper.geometry().nano();
    let counter = copper.counter().to_vec();
    let dx = copper.counter_dx();
    // 7 slabs of 4 nano-spacings, 14 nano-asperities each: 98 in all.
    let (rods, per_rod) = (7usize, 14usize);
    let width = 4.0 * nano.spacing;
    let geometry = SliderGeometry::uniform(width, rods, nano, per_rod).expect("uniform slider");
    println!(
        "## Thesis 5.6: single-level slider, {rods} slabs of {:.2} µm, {} nano-asperities\n",
        width * 1e6,
        rods * per_rod
    );
    println!("| load (fraction of σ_y A_n) | max apparent COF | mean COF | max / mean nano in contact (of 98) | chemical / vdW / elastic / plastic share of dissipation | max elastic dissipation in a step (J) |");
    println!("|---:|---:|---:|---|---|---:|");
    for fraction in [0.05, 0.2, 0.5] {
        let mut options = SliderOptions::new(Loading::FixedLoad { load: 0.0 });
        options.cof_form = CofForm::Amontons;
        options.rod = RodOptions {
            solver: RodSolver::Sweep,
            warm_start: true,
            plastic: PlasticUpdate::ShortenOnly,
        };
        let capacity = material.yield_stress * rods as f64 * width * width;
        options.loading = Loading::FixedLoad {
            load: fraction * capacity,
        };
        let slider =
            Slider::new(geometry.clone(), material, counter.clone(), dx, options).expect("slider");
        let run = slider.slide(1.5e-4, 1.5e-6).expect("slide");
        let max_cof = run.steps.iter().map(|s| s.cof).fold(f64::MIN, f64::max);
        let max_nano = run.steps.iter().map(|s| s.nano_contacts).max().unwrap_or(0);
        let max_elastic = run
            .steps
            .iter()
            .map(|s| s.dissipation.elastic)
            .fold(0.0, f64::max);
        let d = run.summary.dissipation;
        let t = d.total();
        println!(
            "| {fraction} | {max_cof:.3} | {:.3} | {max_nano} / {:.1} | {:.1} / {:.1} / {:.2} / {:.2} % | {max_elastic:.2e} |",
            run.summary.mean_cof,
            run.summary.mean_nano_contacts,
            100.0 * d.chemical / t,
            100.0 * d.van_der_waals / t,
            100.0 * d.elastic / t,
            100.0 * d.plastic / t,
        );
    }
    println!("\nThesis 5.6.2: apparent COF jumping between discrete values, at most about 0.6 (Fig. 5-23); a fraction of the 98 nano-asperities in contact (Fig. 5-24); chemical bonds the largest dissipation, van der Waals second, elastic insignificant, at most 3e-17 J at the start (Fig. 5-25).");
}
