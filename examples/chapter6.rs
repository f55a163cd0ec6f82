//! The chapter-6 study (thesis 6.5): Cu–Cu hierarchical slider, fixed load,
//! on seeded synthetic self-affine profiles (and on a measured profile from
//! `../shared/data/profiles/` when present). Prints Markdown tables next to
//! the thesis's numbers.
//!
//! `cargo run --release --example chapter6`

use asperity::friction::{SlideSummary, Slider};
use asperity::scene::{LoadingSpec, Scene, SurfaceSpec};
use std::path::Path;

fn scene() -> Scene {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/chapter6_copper.json");
    Scene::from_file(path).expect("chapter-6 scene")
}

fn run(s: &Scene) -> (Slider, SlideSummary) {
    try_run(s).unwrap_or_else(|e| panic!("{e}"))
}

fn try_run(s: &Scene) -> Result<(Slider, SlideSummary), String> {
    let slider = s.build().map_err(|e| e.to_string())?;
    let run = slider
        .slide(s.sliding.distance, s.sliding.step)
        .map_err(|e| e.to_string())?;
    Ok((slider, run.summary))
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

fn main() {
    let base = scene();
    let (slider, s) = run(&base);
    println!("## Chapter 6, Cu–Cu, fixed load 0.18 N, {} rods of {:.1} µm × {:.1} µm, {} nano-asperities per rod, 150 µm\n",
        slider.rods(), slider.rod_width() * 1e6, slider.depth() * 1e6, slider.nano_per_rod());
    println!("| quantity | here | thesis |\n|---|---|---|");
    println!("| average COF | {:.3} | 0.9 (6.5.1) |", s.mean_cof);
    let d = s.dissipation;
    println!(
        "| chemical share of dissipation | {:.1} % | dominant (Fig. 6-58) |",
        100.0 * d.chemical / d.total()
    );
    println!(
        "| vdW / elastic / plastic share | {:.2} / {:.2} / {:.2} % | small |",
        100.0 * d.van_der_waals / d.total(),
        100.0 * d.elastic / d.total(),
        100.0 * d.plastic / d.total()
    );
    println!(
        "| adhesion share of true contact area | {:.1} % | ≈ 10 % (Fig. 6-59) |",
        100.0 * s.mean_adhesion_area_share
    );
    println!("| max yielded rods | {} | 3 (coarse) |", s.max_yielded_rods);

    // Table 6-1.
    let fractions = [0.05, 0.095, 0.11, 0.19, 0.25, 0.35, 0.45, 0.55, 0.65];
    let thesis_cof = [1.08, 0.98, 0.97, 0.93, 0.91, 0.91, 0.90, 0.91, 0.92];
    let thesis_e = [0.50, 0.84, 0.91, 1.57, 2.01, 2.80, 3.56, 4.39, 5.23];
    println!("\n## Table 6-1: load (90 rods of 1.5 µm)\n");
    println!("| P/(σ_y A_n) | P (mN) | COF | thesis COF | energy per step (1e-7 J) | thesis | true area (µm²) | adhesion share | yielded |\n|---|---|---|---|---|---|---|---|---|");
    let (mut loads, mut areas) = (vec![], vec![]);
    for (k, f) in fractions.iter().enumerate() {
        let mut sc = base.clone();
        sc.loading = LoadingSpec::FixedLoadFraction { fraction: *f };
        let s = match try_run(&sc) {
            Ok((_, s)) => s,
            Err(e) => {
                println!(
                    "| {f} | – | error: {e} | {} | | {} | | | |",
                    thesis_cof[k], thesis_e[k]
                );
                continue;
            }
        };
        loads.push(s.normal_load);
        areas.push(s.mean_true_contact_area);
        println!(
            "| {f} | {:.0} | {:.3} | {} | {:.3} | {} | {:.1} | {:.1} % | {} |",
            s.normal_load * 1e3,
            s.mean_cof,
            thesis_cof[k],
            s.mean_step_dissipation * 1e7,
            thesis_e[k],
            s.mean_true_contact_area * 1e12,
            100.0 * s.mean_adhesion_area_share,
            s.max_yielded_rods
        );
    }
    println!(
        "\nTrue contact area against load: R² = {:.4}",
        r_squared(&loads, &areas)
    );

    // Table 6-2.
    println!("\n## Table 6-2: nominal area (P = 0.1 σ_y A_n)\n");
    println!("| rods | A_n (µm²) | COF | thesis |\n|---|---|---|---|");
    let thesis2 = [
        "0.99",
        "0.94",
        "0.97",
        "0.96",
        "0.93–0.99",
        "0.93–0.99",
        "0.93–0.99",
    ];
    for (k, m) in [40usize, 80, 120, 160, 200, 240, 280].iter().enumerate() {
        let mut sc = base.clone();
        sc.loading = LoadingSpec::FixedLoadFraction { fraction: 0.1 };
        if let SurfaceSpec::SelfAffine { points, .. } = &mut sc.surfaces.slider {
            *points = m + 1;
        }
        if let SurfaceSpec::SelfAffine { points, .. } = &mut sc.surfaces.counter {
            *points = m + 151;
        }
        let (sl, s) = run(&sc);
        println!(
            "| {m} | {:.0} | {:.3} | {} |",
            sl.nominal_area() * 1e12,
            s.mean_cof,
            thesis2[k]
        );
    }

    // Table 6-3.
    println!("\n## Table 6-3: rod width (P = 0.25 σ_y A_n, slider 135 µm × 13.5 µm)\n");
    println!("| width | rods | COF | thesis |\n|---|---|---|---|");
    let thesis3 = [0.90, 0.91, 0.89, 0.83, 0.84, 0.79, 0.87, 0.79, 0.82];
    for k in 1..=9usize {
        let mut sc = base.clone();
        sc.loading = LoadingSpec::FixedLoadFraction { fraction: 0.25 };
        sc.rods.widths = vec![1.5e-6 * k as f64];
        let (sl, s) = run(&sc);
        println!(
            "| {k}d = {:.1} µm | {} | {:.3} | {} |",
            1.5 * k as f64,
            sl.rods(),
            s.mean_cof,
            thesis3[k - 1]
        );
    }
}
