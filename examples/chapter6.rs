//! The chapter-6 study (thesis 6.5): Cu–Cu hierarchical slider, fixed load,
//! on seeded synthetic self-affine profiles with copper-like statistics and
//! on the measured line scans of `../shared/data/profiles/` when present.
//! Prints Markdown tables next to the thesis's numbers, and the study of the
//! plastic pile-up rule (thesis 6.2.3) that sets how the COF depends on load.
//!
//! `cargo run --release --example chapter6`

use asperity::friction::{SlideSummary, Slider};
use asperity::scene::{FormSpec, LoadingSpec, PlasticSpec, Scene, SurfaceSpec};
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

    // The pile-up rule (thesis 6.2.3): where the volume of a yielded rod goes.
    println!(
        "\n## The pile-up rule: COF (plastic share of the dissipation) at the loads of Table 6-1\n"
    );
    let loads = [0.05, 0.11, 0.25, 0.45, 0.65];
    let mut head = String::from("| rule |");
    for f in loads {
        head += &format!(" {f} σ_y A_n |");
    }
    println!("{head}\n|---|{}", "---|".repeat(loads.len()));
    let rules = [
        (
            "nearest neighbours (thesis)",
            PlasticSpec::NearestNeighbours,
        ),
        ("Gaussian ℓ = 5 µm", PlasticSpec::Gaussian { width: 5e-6 }),
        ("Gaussian ℓ = 10 µm", PlasticSpec::Gaussian { width: 1e-5 }),
        (
            "Gaussian ℓ = 20 µm (scene)",
            PlasticSpec::Gaussian { width: 2e-5 },
        ),
        ("Gaussian ℓ = 40 µm", PlasticSpec::Gaussian { width: 4e-5 }),
        ("shorten only (no pile-up)", PlasticSpec::ShortenOnly),
    ];
    let mut failure = None;
    for (name, rule) in rules {
        let mut row = format!("| {name} |");
        for f in loads {
            let mut sc = base.clone();
            sc.rods.plastic = rule;
            sc.loading = LoadingSpec::FixedLoadFraction { fraction: f };
            row += &match try_run(&sc) {
                Ok((_, s)) => format!(
                    " {:.3} ({:.0} %) |",
                    s.mean_cof,
                    100.0 * s.dissipation.plastic / s.dissipation.total()
                ),
                Err(e) => {
                    failure.get_or_insert(e);
                    " fails¹ |".to_string()
                }
            };
        }
        println!("{row}");
    }
    if let Some(e) = failure {
        println!("\n¹ {e}");
    }

    // The measured line scans (material undocumented, see the data README).
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/data/profiles");
    println!("\n## Measured profiles (slider: the first 135 µm; counter: 300 µm from 1 mm; quadratic form removed)\n");
    let files = [
        "hommel_hfm1_stylus_linescan.csv",
        "dektak1_stylus_linescan.csv",
    ];
    if !dir.join(files[0]).exists() {
        println!("skipped: {} absent", dir.display());
        return;
    }
    println!("| profile | counter Rq (nm) | rms slope | P/(σ_y A_n) | COF | adhesion share of true area | plastic share |\n|---|---|---|---|---|---|---|");
    for file in files {
        for f in [0.05, 0.25, 0.45, 0.65] {
            let mut sc = base.clone();
            sc.base = dir.clone();
            sc.loading = LoadingSpec::FixedLoadFraction { fraction: f };
            let spec = |start: f64, length: f64| SurfaceSpec::File {
                path: file.into(),
                form: FormSpec::Quadratic,
                start,
                length: Some(length),
            };
            sc.surfaces.slider = spec(0.0, 135e-6);
            sc.surfaces.counter = spec(1e-3, 300e-6);
            let (sl, s) = match try_run(&sc) {
                Ok(r) => r,
                Err(e) => {
                    println!("| {file} | | | {f} | error: {e} | | |");
                    continue;
                }
            };
            let c = sl.counter();
            let rq = (c.iter().map(|z| z * z).sum::<f64>() / c.len() as f64).sqrt();
            let dx = sl.counter_dx();
            let slope = (c
                .windows(2)
                .map(|w| ((w[1] - w[0]) / dx).powi(2))
                .sum::<f64>()
                / (c.len() - 1) as f64)
                .sqrt();
            println!(
                "| {file} | {:.1} | {slope:.3} | {f} | {:.3} | {:.0} % | {:.1} % |",
                rq * 1e9,
                s.mean_cof,
                100.0 * s.mean_adhesion_area_share,
                100.0 * s.dissipation.plastic / s.dissipation.total()
            );
        }
    }
}
