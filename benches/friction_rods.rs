//! Speed of the micro-rod equilibrium at fixed load (thesis (6-13)..(6-16)):
//! the exact breakpoint sweep (cold, O(n log n)), the warm start from the
//! previous step's position (O(n) per breakpoint crossed), and the thesis's
//! dense formulation iterated over active sets (faer LU, the reference), for
//! n = 90 and 900 rods. Plus the substrate-coupled model for reference.
//! `cargo bench --bench friction_rods`.
//!
//! Each timed solve includes validation, the plastic update with
//! nearest-neighbour pile-up (6.2.3) and the energies, so the figures are
//! those a sliding loop pays per increment. The warm start is timed from a
//! state whose position is the equilibrium at a load 0.1 % different — a
//! typical sliding step. Median over repetitions. Two regimes at P = 0.3 n F_y:
//! rough (±0.5 µm, most rods in contact have yielded: small dense systems)
//! and smooth (±20 nm, most rods elastic: the dense system is n × n).

use asperity::friction::{CoupledRodBed, Loading, RodBed, RodOptions, RodSolver, RodState};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use std::time::Instant;

/// Copper-like rods 1.5 µm wide, root depth 10 µm (yield overlap
/// ε_y L ≈ 40 nm), heights and counter-surface uniform in ±`amplitude`.
fn bed(n: usize, amplitude: f64) -> (RodBed, Vec<f64>) {
    let mut rng = ChaCha8Rng::seed_from_u64(2024);
    let w = 1.5e-6;
    let centers = (0..n).map(|i| (i as f64 + 0.5) * w).collect();
    let heights = (0..n)
        .map(|_| rng.random_range(-amplitude..amplitude))
        .collect();
    let counter = (0..n)
        .map(|_| rng.random_range(-amplitude..amplitude))
        .collect();
    (
        RodBed::new(w, centers, heights, 10e-6, 68.65e9, 276e6).unwrap(),
        counter,
    )
}

/// Median time (s) of `reps` calls of `f`.
fn median(reps: usize, mut f: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..reps)
        .map(|_| {
            let s = Instant::now();
            f();
            s.elapsed().as_secs_f64()
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}

fn main() {
    println!(
        "| regime | n | path | time per solve | ratio to cold sweep | iterations | elastic / yielded |"
    );
    println!("|---|---|---|---|---|---|---|");
    for (regime, amplitude, n) in [
        ("rough", 0.5e-6, 90),
        ("rough", 0.5e-6, 900),
        ("smooth", 20e-9, 90),
        ("smooth", 20e-9, 900),
    ] {
        let (bed, g) = bed(n, amplitude);
        let p = 0.3 * bed.capacity();
        let fresh = bed.state();
        let mut out = bed.solution();
        let mut new = bed.state();
        let cold = RodOptions {
            warm_start: false,
            ..RodOptions::default()
        };
        let warm = RodOptions::default();
        let dense = RodOptions {
            solver: RodSolver::Dense,
            ..cold
        };
        // Warm state: the equilibrium at P(1 + 1e-3).
        let mut warm_state: RodState = fresh.clone();
        bed.solve(
            &fresh,
            &mut new,
            &g,
            Loading::FixedLoad { load: p * 1.001 },
            &cold,
            &mut out,
        )
        .unwrap();
        warm_state.position = new.position;

        let mut rc = Default::default();
        let t_cold = median(201, || {
            rc = bed
                .solve(
                    &fresh,
                    &mut new,
                    &g,
                    Loading::FixedLoad { load: p },
                    &cold,
                    &mut out,
                )
                .unwrap();
        });
        let mut rw = Default::default();
        let t_warm = median(201, || {
            rw = bed
                .solve(
                    &warm_state,
                    &mut new,
                    &g,
                    Loading::FixedLoad { load: p },
                    &warm,
                    &mut out,
                )
                .unwrap();
        });
        let mut rd = Default::default();
        let reps = if n > 200 { 3 } else { 21 };
        let t_dense = median(reps, || {
            rd = bed
                .solve(
                    &fresh,
                    &mut new,
                    &g,
                    Loading::FixedLoad { load: p },
                    &dense,
                    &mut out,
                )
                .unwrap();
        });
        let coupled = CoupledRodBed::new(bed.clone(), 68.65e9 / (1.0 - 0.355f64.powi(2))).unwrap();
        let mut rk = Default::default();
        let t_coupled = median(reps, || {
            rk = coupled
                .solve(
                    &fresh,
                    &mut new,
                    &g,
                    Loading::FixedLoad { load: p },
                    &cold,
                    &mut out,
                )
                .unwrap();
        });
        let row = |name: &str, t: f64, r: &asperity::friction::RodReport| {
            println!(
                "| {regime} | {n} | {name} | {:.3} µs | {:.2} | {} | {} / {} |",
                t * 1e6,
                t / t_cold,
                r.iterations,
                r.in_contact - r.yielded,
                r.yielded
            );
        };
        row("exact sweep (cold)", t_cold, &rc);
        row(
            if rw.warm_started {
                "warm start"
            } else {
                "warm start (fell back)"
            },
            t_warm,
            &rw,
        );
        row("dense (6-16), faer LU", t_dense, &rd);
        row("coupled substrate (Love/Boussinesq)", t_coupled, &rk);
        println!(
            "{regime}, n = {n}: dense / sweep = {:.0}×, sweep / warm = {:.2}×, |b_sweep − b_dense| = {:.1e} m",
            t_dense / t_cold,
            t_cold / t_warm,
            (rc.position - rd.position).abs()
        );
    }
}
