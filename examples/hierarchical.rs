//! Hierarchical roughness (thesis 5.4) and the generalised Maxwell-slip
//! model (5.3.8): the load–area exponents of Archard's hierarchies and of
//! the Cantor profiles, their cost per evaluation, and the GMS Stribeck
//! curve against its steady sliding (BENCHMARKS.md §11).
//!
//! ```sh
//! cargo run --release --example hierarchical
//! ```

use asperity::friction::dynamic::GeneralizedMaxwellSlip;
use asperity::friction::{FrictionIncrement, FrictionLaw};
use asperity::hierarchical::{archard_exponent, Archard, ArchardModel, CantorProfile};
use std::hint::black_box;
use std::time::Instant;

/// Median ns per call of `f` over 11 rounds of `n` calls.
fn ns(n: usize, mut f: impl FnMut(usize)) -> f64 {
    let mut t: Vec<f64> = (0..11)
        .map(|_| {
            let s = Instant::now();
            for i in 0..n {
                f(i);
            }
            s.elapsed().as_secs_f64() * 1e9 / n as f64
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[5]
}

fn main() -> Result<(), asperity::Error> {
    let e = 1e11;
    let radii = [1e-2, 1e-4, 1e-6, 1e-8, 1e-10];
    let dens = [1e9, 1e13, 1e17, 1e21];
    println!("| Archard model | generations | exponent a (A ∝ W^a) | Archard 1957 | fitted slope, W = 1e-3..1e3 N | ns per area |");
    println!("|---|---:|---:|---|---:|---:|");
    for (model, label, first, fractions) in [
        (
            ArchardModel::Uniform,
            "equal heights",
            1,
            ["2/3", "8/9", "26/27", "80/81"],
        ),
        (
            ArchardModel::NonUniform,
            "distributed heights",
            2,
            ["4/5", "14/15", "44/45", "134/135"],
        ),
    ] {
        for (i, frac) in fractions.iter().enumerate() {
            let n = first + i;
            let m = Archard::new(model, &radii[..n], &dens[..n - 1], e)?;
            let slope = (m.area(1e3)? / m.area(1e-3)?).ln() / 1e6f64.ln();
            let t = ns(1 << 16, |i| {
                black_box(m.area(black_box(1.0 + i as f64)).unwrap());
            });
            println!(
                "| {label} | {n} | {:.12} | {frac} | {slope:.12} | {t:.1} |",
                archard_exponent(model, n)?
            );
        }
    }
    println!();
    println!("| Cantor profile | p | r | q | D | β (A ∝ δ^β) | A ∝ P^x, x | fitted dlnP/dlnδ, 6 decades | ns per contact |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    for (label, p, r, q) in [
        ("Cantor–Borodich", 2, 1.0 / 3.0, 0.5),
        ("Cantor–Borodich", 2, 1.0 / 3.0, 0.8),
        ("Warren–Krajcinovic", 3, 0.2, 0.6),
        ("Cantor–Liu", 2, 1.0 / 3.0, 1.0),
    ] {
        let prof = CantorProfile {
            descendants: p,
            generations: 200,
            width_ratio: r,
            height_ratio: q,
            base_width: 1e-3,
            base_height: 1e-5,
        };
        let fit = if q < 1.0 {
            let pts: Vec<(f64, f64)> = (0..200)
                .map(|i| {
                    let d = 1e-12 * 10f64.powf(6.0 * i as f64 / 199.0);
                    (
                        d.ln(),
                        prof.contact(d, 1e10, 0.0).unwrap().winkler_load.ln(),
                    )
                })
                .collect();
            let n = pts.len() as f64;
            let mx = pts.iter().map(|p| p.0).sum::<f64>() / n;
            let my = pts.iter().map(|p| p.1).sum::<f64>() / n;
            let sxy: f64 = pts.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
            let sxx: f64 = pts.iter().map(|p| (p.0 - mx) * (p.0 - mx)).sum();
            format!("{:.4}", sxy / sxx)
        } else {
            "–".into()
        };
        let t = ns(1 << 12, |i| {
            black_box(
                prof.contact(black_box(1e-9 * (1.0 + i as f64)), 1e10, 1e9)
                    .unwrap(),
            );
        });
        println!(
            "| {label} | {p} | {r:.4} | {q} | {:.4} | {:.4} | {:.4} | {fit} | {t:.0} |",
            prof.fractal_dimension(),
            prof.width_exponent(),
            prof.load_area_exponent()
        );
    }
    println!();
    // GMS: steady sliding against F_ss(v) = N s(v) Σα + σ₂ v.
    let g = GeneralizedMaxwellSlip::new(
        &[2e5, 1e5, 5e4, 2.5e4],
        &[0.25; 4],
        0.3,
        0.5,
        1e-3,
        2.0,
        50.0,
        0.1,
    )?;
    println!("| v (m/s) | F_ss = N s(v) + σ₂v (N) | GMS after 1 mm of sliding (N) | relative difference |");
    println!("|---:|---:|---:|---:|");
    for v in [1e-6, 1e-4, 5e-4, 1e-3, 2e-3, 1e-2, 1e-1] {
        let mut s = vec![0.0; g.state_len()];
        let mut f = 0.0;
        for _ in 0..1000 {
            let inc = FrictionIncrement {
                normal_force: 10.0,
                slip: [1e-6, 0.0],
                dt: 1e-6 / v,
                ..Default::default()
            };
            f = -g.step_in_place(&mut s, &inc, &mut g.work())?.force[0];
        }
        let want = g.steady_force(10.0, v);
        println!(
            "| {v:e} | {want:.10} | {f:.10} | {:.1e} |",
            (f - want).abs() / want
        );
    }
    Ok(())
}
