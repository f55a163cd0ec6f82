//! Convergence study of the numerical Lennard-Jones sphere (issue §3).
//!
//! `cargo run --release --example lj_convergence [NMAX] [MU,MU,...]` (default
//! NMAX = 1024 and μ ∈ {0.1, 1, 3}; 2048 and 4096 take minutes: dense LU of
//! order N for the pull-off; the whole-curve norm at N = 4096 takes 20–50 s
//! per μ). `lj_convergence whole MU NMIN NMAX` runs the whole-curve norm
//! alone, for N = NMIN … NMAX.
//!
//! For each μ and N = 32, 64, …, NMAX it prints the load-controlled pull-off
//! `P̄_c` (edge-concentrated mesh, [`LjSphere::pull_off`]), the successive
//! difference, the observed order `log2(e_N/e_2N)`, and the Richardson
//! estimate `P̄_∞ ≈ P̄_2N + (P̄_2N − P̄_N)/(2^p − 1)` with the observed order p;
//! then a whole-curve error norm: the max over 40 central gaps spanning the
//! curve of |P̄_N(h̄₀) − P̄_2N(h̄₀)|, with its order. Finally the S-curve
//! onset μ by bisection on the sign of the largest dᾱ/dh̄₀.

// Options are built by changing a default, field by field, for readability.
#![allow(clippy::field_reassign_with_default)]
use asperity::contact::lj_sphere::{LjOptions, LjSolver, LjSphere};
use asperity::contact::MaugisDugdale;
use std::time::Instant;

/// `lj_convergence curve MU N` / `lj_convergence pulloff MU N`: one run,
/// timed (for quick checks of a single case).
fn single(kind: &str, mu: f64, n: usize) {
    let sp = LjSphere::from_tabor(mu).unwrap();
    let t = Instant::now();
    if kind == "curve" {
        let mut o = LjOptions::default();
        o.n_grid = n;
        let c = LjSolver::new(&sp, o).and_then(|s| s.curve());
        let dt = t.elapsed();
        match c {
            Ok(c) => println!(
                "curve μ = {mu}, N = {n}: {:.1?}, {} points, {} iterations, {} LU, max residual {:.1e}, pull-off {:.7} (a = {:.4}), jump-in {:?}, jump-out {:?}, hysteresis {:.5}",
                dt,
                c.points.len(),
                c.iterations,
                c.factorizations,
                c.max_residual,
                c.pull_off_load.force,
                c.pull_off_load.contact_radius,
                c.jump_in.map(|p| (p.approach, p.force)),
                c.jump_out.map(|p| (p.approach, p.force)),
                c.hysteresis_energy
            ),
            Err(e) => println!("curve μ = {mu}, N = {n}: {dt:.1?} error: {e}"),
        }
    } else {
        match sp.pull_off(n) {
            Ok(po) => println!(
                "pull-off μ = {mu}, N = {n}: {:.1?}, P̄ = {:.8}, a = {:.5}, {} iterations",
                t.elapsed(),
                po.force,
                po.contact_radius,
                po.iterations
            ),
            Err(e) => println!("pull-off μ = {mu}, N = {n}: {:.1?} error: {e}", t.elapsed()),
        }
    }
}

fn main() {
    let a1 = std::env::args().nth(1).unwrap_or_default();
    if a1 == "curve" || a1 == "pulloff" {
        let mu: f64 = std::env::args().nth(2).unwrap().parse().unwrap();
        let n: usize = std::env::args().nth(3).unwrap().parse().unwrap();
        single(&a1, mu, n);
        return;
    }
    if a1 == "whole" {
        let arg = |i: usize| std::env::args().nth(i).unwrap();
        let mu: f64 = arg(2).parse().unwrap();
        let (nmin, nmax): (usize, usize) = (arg(3).parse().unwrap(), arg(4).parse().unwrap());
        let ns: Vec<usize> = (0..)
            .map(|k| nmin << k)
            .take_while(|&n| n <= nmax)
            .collect();
        println!("## μ = {mu}");
        whole_curve(&LjSphere::from_tabor(mu).unwrap(), &ns);
        return;
    }
    let nmax: usize = std::env::args()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1024);
    let mus: Vec<f64> = std::env::args()
        .nth(2)
        .map(|s| s.split(',').filter_map(|v| v.parse().ok()).collect())
        .unwrap_or_else(|| vec![0.1, 1.0, 3.0]);
    let mut ns = vec![];
    let mut n = 32;
    while n <= nmax {
        ns.push(n);
        n *= 2;
    }
    for &mu in &mus {
        let sp = LjSphere::from_tabor(mu).unwrap();
        let lam = asperity::material::maugis_over_tabor() * mu;
        let md = -MaugisDugdale::from_maugis_parameter(1.0, 1.0, 1.0, lam)
            .unwrap()
            .load_pull_off_point()
            .p_bar;
        println!("\n## μ = {mu}  (Maugis–Dugdale at λ = {lam:.4}: P̄_c = {md:.6})");
        println!("| N | P̄_c | |P̄_N − P̄_N/2| | order | Richardson | iterations | time |");
        println!("|---|---|---|---|---|---|---|");
        let mut vals: Vec<f64> = vec![];
        for &n in &ns {
            let t = Instant::now();
            match sp.pull_off(n) {
                Ok(po) => {
                    let p = -po.force;
                    let (mut d, mut ord, mut rich) = (String::new(), String::new(), String::new());
                    if let Some(&p1) = vals.last() {
                        d = format!("{:.2e}", (p - p1).abs());
                        if vals.len() >= 2 {
                            let p0 = vals[vals.len() - 2];
                            let o = ((p1 - p0).abs() / (p - p1).abs()).log2();
                            ord = format!("{o:.2}");
                            let r = p + (p - p1) / (2f64.powf(o) - 1.0);
                            rich = format!("{r:.7} ({:+.2} % vs MD)", 100.0 * (r - md) / md);
                        }
                    }
                    println!(
                        "| {n} | {p:.7} | {d} | {ord} | {rich} | {} | {:.2?} |",
                        po.iterations,
                        t.elapsed()
                    );
                    vals.push(p);
                }
                Err(e) => println!("| {n} | error: {e} | | | | | {:.2?} |", t.elapsed()),
            }
        }
        whole_curve(&sp, &ns);
    }
    // S-curve onset by bisection on the largest dᾱ/dh̄₀.
    let slope = |mu: f64| -> f64 {
        let mut o = LjOptions::default();
        o.n_grid = 128;
        LjSolver::new(&LjSphere::from_tabor(mu).unwrap(), o)
            .unwrap()
            .max_turning_slope()
            .unwrap()
    };
    let (mut lo, mut hi) = (0.5, 1.0);
    println!(
        "\nslope(0.5) = {:.4e}, slope(1.0) = {:.4e}",
        slope(lo),
        slope(hi)
    );
    for _ in 0..14 {
        let m = 0.5 * (lo + hi);
        if slope(m) > 0.0 {
            hi = m;
        } else {
            lo = m;
        }
    }
    println!("S-curve onset (N = 128): μ_c = {:.4}", 0.5 * (lo + hi));
}

/// The whole-curve norm: the max over 40 central gaps spanning the curve of
/// `|P̄_N(h̄₀) − P̄_{N/2}(h̄₀)|` for successive `ns`, with its order and the
/// Richardson error estimate of the finer curve, `|ΔP̄|/(2^p − 1)` (the
/// observed order, or the scheme's 2 before one is observed).
fn whole_curve(sp: &LjSphere, ns: &[usize]) {
    let h0s: Vec<f64> = (0..40)
        .map(|i| {
            let t = i as f64 / 39.0;
            6.0 * (1.0 - t) + 0.965 * t
        })
        .collect();
    let mut prev: Option<Vec<f64>> = None;
    let mut prev_e: Option<f64> = None;
    println!("\n| N | whole-curve max |ΔP̄| vs N/2 | order | Richardson error of P̄_N | time |");
    println!("|---|---|---|---|---|");
    for &n in ns {
        let t = Instant::now();
        let mut o = LjOptions::default();
        o.n_grid = n;
        o.max_force = 2.0;
        let s = LjSolver::new(sp, o).unwrap();
        match s.sweep(&h0s) {
            Ok(pts) => {
                let f: Vec<f64> = pts.iter().map(|p| p.force).collect();
                if let Some(pf) = &prev {
                    let e = f
                        .iter()
                        .zip(pf)
                        .map(|(a, b)| (a - b).abs())
                        .fold(0.0, f64::max);
                    let p = prev_e.map(|pe| (pe / e).log2());
                    let ord = p.map(|p| format!("{p:.2}")).unwrap_or_default();
                    let rich = e / (2f64.powf(p.unwrap_or(2.0)) - 1.0);
                    println!(
                        "| {n} | {e:.3e} | {ord} | {rich:.2e} | {:.1?} |",
                        t.elapsed()
                    );
                    prev_e = Some(e);
                }
                prev = Some(f);
            }
            Err(e) => {
                println!("| {n} | error: {e} | | | {:.1?} |", t.elapsed());
                prev = None;
            }
        }
    }
}
