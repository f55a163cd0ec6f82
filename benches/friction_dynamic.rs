//! Time per call of the dynamic friction steps (issue 9 §3: a LuGre or
//! Maxwell-slip (N ≤ 10) step ≤ 50 ns), next to what a host code would
//! write itself: LuGre integrated by explicit Euler with sub-steps (the
//! usual scheme), at the sub-step counts that reach 1e-3 and 1e-6 relative
//! force error against the exact increment, and an inline 1-D Maxwell-slip
//! loop without validation. Then the integrated models, per increment of a
//! stick-slip run: Prandtl–Tomlinson with one and two springs, and the
//! Burridge–Knopoff chain of 1, 10 and 100 blocks.
//!
//! `cargo bench --bench friction_dynamic`. A calibrated timing loop, median
//! over rounds, paths interleaved round by round. Tunables:
//! `ASPERITY_BENCH_ROUNDS` (default 11), `ASPERITY_BENCH_RUN_MS` (default
//! 40).

use asperity::friction::dynamic::{
    Bristles, BurridgeKnopoff, FrictionIncrement, FrictionLaw, GeneralizedMaxwellSlip, LuGre,
    MaxwellSlip, PrandtlTomlinson,
};
use std::hint::black_box;
use std::time::{Duration, Instant};

const N: usize = 1024;

fn env(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// μ_c 0.3, μ_s 0.5, v_s 1 mm/s, σ₀ 1e5 /m, σ₁ at half its passivity bound
/// for the damping velocity `vd` (m/s), σ₂ 0.4 N s/m.
fn lugre(vd: f64) -> LuGre {
    let s1 = 0.5 * 4.0 * 0.3 * (2.0 * std::f64::consts::E).sqrt() / vd;
    LuGre::new(0.3, 0.5, 1e-3, 2.0, 1e5, s1, vd, 0.4).unwrap()
}

/// The increments turned by 30° in the tangent plane (a 2-D slip).
fn turned(incs: &[FrictionIncrement]) -> Vec<FrictionIncrement> {
    let (c, s) = (30f64.to_radians().cos(), 30f64.to_radians().sin());
    incs.iter()
        .map(|i| FrictionIncrement {
            slip: [c * i.slip[0], s * i.slip[0]],
            ..*i
        })
        .collect()
}

/// Increments of an explicit dynamics host: dt = 1 µs, speeds 0.1–10 mm/s
/// with reversals, N around 10 N.
fn increments() -> Vec<FrictionIncrement> {
    (0..N)
        .map(|i| {
            let t = i as f64;
            let v = 1e-3 * (0.1 + 9.9 * (0.5 + 0.5 * (0.37 * t).sin())) * (0.05 * t).cos().signum();
            FrictionIncrement {
                normal_force: 10.0 + (0.11 * t).cos(),
                slip: [v * 1e-6, 0.0],
                dt: 1e-6,
                ..Default::default()
            }
        })
        .collect()
}

/// The hand-written explicit-Euler LuGre of a host code (1-D, same
/// parameters, Amontons-scaled), `m` sub-steps per increment; returns the
/// friction force along the motion.
#[inline(never)]
fn euler(z: &mut f64, n: f64, ds: f64, dt: f64, m: usize) -> f64 {
    let (mu_c, mu_s, vs, s0, vd, s2) = (0.3, 0.5, 1e-3, 1e5, 1e-3, 0.4);
    let s1 = 0.5 * 4.0 * 0.3 * (2.0 * std::f64::consts::E).sqrt() / vd;
    let v = ds / dt;
    let g = mu_c + (mu_s - mu_c) * (-(v / vs) * (v / vs)).exp();
    let a = s0 * v.abs() / g;
    let h = dt / m as f64;
    for _ in 0..m {
        *z += h * (v - a * *z);
    }
    n * (s0 * *z + s1 * (-(v / vd) * (v / vd)).exp() * (v - a * *z)) + s2 * v
}

/// Median time per call (ns) of `f` (which makes `N` calls).
fn time(rounds: u64, run_ms: u64, mut f: impl FnMut()) -> f64 {
    let start = Instant::now();
    let mut reps = 0u64;
    while start.elapsed() < Duration::from_millis(run_ms) {
        f();
        reps += 1;
    }
    let mut best = vec![];
    for _ in 0..rounds {
        let t = Instant::now();
        for _ in 0..reps {
            f();
        }
        best.push(t.elapsed().as_nanos() as f64 / (reps * N as u64) as f64);
    }
    best.sort_by(|a, b| a.total_cmp(b));
    best[best.len() / 2]
}

fn main() {
    let rounds = env("ASPERITY_BENCH_ROUNDS", 11);
    let run_ms = env("ASPERITY_BENCH_RUN_MS", 40);
    let incs = increments();
    let incs_2d = turned(&incs);
    let m = lugre(1e-3);
    let len = m.state_len();

    // Exact reference forces along the sequence.
    let mut state = vec![0.0; len];
    let mut next = state.clone();
    let mut w = m.work();
    let exact: Vec<f64> = incs
        .iter()
        .map(|i| {
            let r = m.step(&state, &mut next, i, &mut w).unwrap();
            state.copy_from_slice(&next);
            -r.force[0]
        })
        .collect();
    // Euler's error at m sub-steps, and the counts that reach 1e-3, 1e-6.
    let error = |sub: usize| {
        let mut z = 0.0;
        incs.iter()
            .zip(&exact)
            .map(|(i, f)| ((euler(&mut z, i.normal_force, i.slip[0], i.dt, sub) - f) / f).abs())
            .fold(0.0, f64::max)
    };
    let reach = |tol: f64| (0..24).map(|p| 1usize << p).find(|&s| error(s) <= tol);
    println!("# Dynamic friction steps, time per call (median of {rounds} rounds)\n");
    println!("| path | sub-steps | max relative force error | ns per call |");
    println!("|---|---:|---:|---:|");
    let lugre_time = |m: &LuGre, incs: &[FrictionIncrement]| {
        time(rounds, run_ms, || {
            let mut s = [0.0; 4];
            let mut n = [0.0; 4];
            let mut w = m.work();
            for i in incs {
                black_box(m.step(&s, &mut n, black_box(i), &mut w).unwrap());
                s = n;
            }
        })
    };
    let t = lugre_time(&m, &incs);
    println!(
        "| LuGre, exact increment (`LuGre::step`), track, v_d = v_s | – | 0 (reference) | {t:.1} |"
    );
    let t2 = lugre_time(&lugre(3e-3), &incs);
    println!("| LuGre, exact increment, track, v_d = 3 v_s (two exponentials) | – | 0 | {t2:.1} |");
    let t2 = lugre_time(&m, &incs_2d);
    println!("| LuGre, exact increment, 2-D slip (30°), v_d = v_s | – | 0 | {t2:.1} |");
    for tol in [1e-3, 1e-6] {
        match reach(tol) {
            Some(sub) => {
                let e = error(sub);
                // A million sub-steps per call: one short round is enough.
                let (r, ms) = if sub > 1 << 16 {
                    (1, 1)
                } else {
                    (rounds, run_ms)
                };
                let te = time(r, ms, || {
                    let mut z = 0.0;
                    for i in &incs {
                        black_box(euler(&mut z, i.normal_force, i.slip[0], i.dt, sub));
                    }
                });
                println!(
                    "| LuGre, hand-written explicit Euler | {sub} | {e:.1e} | {te:.1} ({:.1}× the exact step) |",
                    te / t
                );
            }
            None => println!("| LuGre, explicit Euler | > 8e6 | not reached {tol:e} | – |"),
        }
    }

    for elements in [1usize, 4, 10] {
        let k: Vec<f64> = (0..elements).map(|i| 2e5 / (1 << i) as f64).collect();
        let mu: Vec<f64> = (0..elements).map(|_| 0.5 / elements as f64).collect();
        let ms = MaxwellSlip::new(&k, &mu, 0.0).unwrap();
        let len = ms.state_len();
        let maxwell_time = |incs: &[FrictionIncrement]| {
            time(rounds, run_ms, || {
                let mut s = vec![0.0; len];
                let mut n = vec![0.0; len];
                let mut w = ms.work();
                for i in incs {
                    black_box(ms.step(&s, &mut n, black_box(i), &mut w).unwrap());
                    std::mem::swap(&mut s, &mut n);
                }
            })
        };
        let t = maxwell_time(&incs);
        let t2 = maxwell_time(&incs_2d);
        let reach: Vec<f64> = k.iter().zip(&mu).map(|(k, m)| m / k).collect();
        let ti = time(rounds, run_ms, || {
            let mut d = vec![0.0; elements];
            for i in &incs {
                let mut f = 0.0;
                for ((d, r), k) in d.iter_mut().zip(&reach).zip(&k) {
                    *d = (*d + i.slip[0]).clamp(-r, *r);
                    f += k * *d;
                }
                black_box(i.normal_force * f);
            }
        });
        println!(
            "| Maxwell-slip, {elements} elements (`MaxwellSlip::step`), track | – | – | {t:.1} (inline 1-D loop without checks: {ti:.1}) |"
        );
        println!("| Maxwell-slip, {elements} elements, 2-D slip (30°) | – | – | {t2:.1} |");
    }
    // The generalised Maxwell-slip model on the same elements (weights
    // equal, μ_c = 0.3, μ_s = 0.5, v_s = 1 mm/s, C = 50/s): exact per
    // increment, one exponential a slipping element.
    for elements in [1usize, 4, 10] {
        let k: Vec<f64> = (0..elements).map(|i| 2e5 / (1 << i) as f64).collect();
        let a: Vec<f64> = (0..elements).map(|_| 1.0 / elements as f64).collect();
        let g = GeneralizedMaxwellSlip::new(&k, &a, 0.3, 0.5, 1e-3, 2.0, 50.0, 0.0).unwrap();
        let len = g.state_len();
        let t = time(rounds, run_ms, || {
            let mut s = vec![0.0; len];
            let mut n = vec![0.0; len];
            let mut w = g.work();
            for i in &incs {
                black_box(g.step(&s, &mut n, black_box(i), &mut w).unwrap());
                std::mem::swap(&mut s, &mut n);
            }
        });
        println!(
            "| generalised Maxwell-slip, {elements} elements (`GeneralizedMaxwellSlip::step`), track | – | 0 (exact increment) | {t:.1} |"
        );
    }
    // Ten bristles of break deflections 1–10 µm (snaps counted exactly).
    let d: Vec<f64> = (1..=10).map(|i| 1e-6 * i as f64).collect();
    let brush = Bristles::new(&[1e5; 10], &d, 0.0).unwrap();
    let tb = time(rounds, run_ms, || {
        let mut s = vec![0.0; brush.state_len()];
        let mut n = s.clone();
        let mut w = brush.work();
        for i in &incs {
            black_box(brush.step(&s, &mut n, black_box(i), &mut w).unwrap());
            std::mem::swap(&mut s, &mut n);
        }
    });
    println!("| Bristles, 10 (`Bristles::step`), track | – | – | {tb:.1} |");

    // The integrated models over N increments of a stick-slip run (from the
    // state after a first stretch of the run), mean time per increment.
    let run = |m: &dyn FrictionLaw, inc: FrictionIncrement, start: &[f64]| {
        let mut s = start.to_vec();
        let t = time(rounds.min(5), run_ms, || {
            s.copy_from_slice(start);
            let mut w = m.work();
            for _ in 0..N {
                black_box(m.step_in_place(&mut s, black_box(&inc), &mut w).unwrap());
            }
        });
        s.copy_from_slice(start);
        let (mut events, mut d) = (0, 0.0);
        let mut w = m.work();
        for _ in 0..N {
            let r = m.step_in_place(&mut s, &inc, &mut w).unwrap();
            events += usize::from(r.regime != 0);
            d += r.dissipated;
        }
        (t, events, d)
    };
    let warm = |m: &dyn FrictionLaw, inc: &FrictionIncrement, s: &mut [f64]| {
        let mut w = m.work();
        for _ in 0..N {
            m.step_in_place(s, inc, &mut w).unwrap();
        }
    };
    println!("\n| integrated model, stick-slip run | increment | ns per increment |");
    println!("|---|---|---:|");
    // Prandtl–Tomlinson at η = 3 on a 0.3 nm lattice, 1 µm/s, 1 µs
    // increments (300 per lattice period; ω = 1e6 /s).
    let (a, k, mass) = (3e-10, 1.0, 1e-12);
    let u0 = 3.0 * k * a * a / (4.0 * std::f64::consts::PI.powi(2));
    let g = (k * mass).sqrt();
    let pt = PrandtlTomlinson::new(u0, a, k, mass, g, 1e-9).unwrap();
    let pt2 =
        PrandtlTomlinson::two_spring(u0, a, 2.0 * k, mass, g, 2.0 * k, mass, g, 1e-9).unwrap();
    let inc = FrictionIncrement {
        normal_force: 1.0,
        slip: [1e-12, 0.0],
        dt: 1e-6,
        ..Default::default()
    };
    for (label, m) in [("one spring", &pt), ("two springs", &pt2)] {
        let mut start = vec![0.0; m.state_len()];
        warm(m, &inc, &mut start);
        let (t, _, _) = run(m, inc, &start);
        println!(
            "| Prandtl-Tomlinson, {label}, η = 3 | 1 µs (1/300 of a lattice period) | {t:.0} |"
        );
    }
    // Burridge–Knopoff: 10 mg blocks on 1000 N/m leaf springs, coupled by
    // 1e4 N/m, μ_s 0.5, μ_k 0.3 weakening on 5 cm/s, 1 N per block, driven
    // at 1 cm/s in 0.1 ms increments (a stick-slip period of ~40 ms), one
    // block displaced by 1 µm at the start.
    for blocks in [1usize, 10, 100] {
        let m = BurridgeKnopoff::new(blocks, 1e-5, 1e4, 1e3, 0.5, 0.3, 0.05, 0.01, 1e-9).unwrap();
        let inc = FrictionIncrement {
            normal_force: blocks as f64,
            slip: [1e-6, 0.0],
            dt: 1e-4,
            ..Default::default()
        };
        let mut start = vec![0.0; m.state_len()];
        start[asperity::friction::dynamic::burridge_knopoff::state_block(blocks / 3)] = -1e-6;
        warm(&m, &inc, &mut start);
        let (t, slipping, d) = run(&m, inc, &start);
        println!(
            "| Burridge-Knopoff, {blocks} block{} | 0.1 ms ({slipping} of {N} increments with slip, {d:.2e} J) | {t:.0} |",
            if blocks == 1 { "" } else { "s" }
        );
    }
}
