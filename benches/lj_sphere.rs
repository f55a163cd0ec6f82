//! Speed of the numerical Lennard-Jones sphere against the seed's own scheme
//! (issue §4), in the same run. `cargo bench --bench lj_sphere`.
//!
//! Baseline (seed 001, Lee & Chong 2015, §3 and Eq. 6; implemented here only):
//! 128 uniform elements on `[0, r̄_max]`, the gap `H` at the element centres,
//! the deformation integral by 4-point Gaussian quadrature per element (the
//! pressure interpolated linearly between centres, the kernel in its Landen
//! form `(s/r)K(s/r)`, `K(r/s)`), the residual `ψ = RHS(H) − H` and the
//! relaxation `H ← H + 0.001ψ` until `max|ψ| < 1e-3`. Its quadrature matrix
//! is built once outside the timing (favourable to the baseline).
//!
//! Ours: [`LjSolver::solve_at_approach`] (full Newton) on the default curve
//! mesh with N chosen so that its force error is below the baseline's (both
//! against a N = 1024 reference); the influence matrix is built once outside
//! the timing as well. Then a full approach–retract curve at N = 256.

// Options are built by changing a default, field by field, for readability.
#![allow(clippy::field_reassign_with_default)]
// The seed's scheme is written index by index, as in the paper.
#![allow(clippy::needless_range_loop)]
use asperity::contact::lj_sphere::{lj_pressure, LjOptions, LjSolver, LjSphere};
use core::f64::consts::PI;
use std::time::Instant;

struct Seed {
    r: Vec<f64>,
    dr: f64,
    g: Vec<f64>, // n×n, row-major: W_i = Σ_j g_ij p_j
    k: f64,
}

impl Seed {
    fn new(mu: f64, n: usize, rmax: f64) -> Seed {
        let dr = rmax / n as f64;
        let r: Vec<f64> = (0..n).map(|i| (i as f64 + 0.5) * dr).collect();
        let gx = [
            -0.861136311594053,
            -0.339981043584856,
            0.339981043584856,
            0.861136311594053,
        ];
        let gw = [
            0.347854845137454,
            0.652145154862546,
            0.652145154862546,
            0.347854845137454,
        ];
        let mut g = vec![0.0; n * n];
        for i in 0..n {
            for e in 0..n {
                let (a, b) = (e as f64 * dr, (e + 1) as f64 * dr);
                for q in 0..4 {
                    let s = 0.5 * (a + b) + 0.5 * dr * gx[q];
                    let (f, kk) = if s < r[i] {
                        (s / r[i], s / r[i])
                    } else {
                        (1.0, r[i] / s)
                    };
                    let ker = f * ellip::ellipk(kk * kk).unwrap() * 0.5 * dr * gw[q];
                    // Linear interpolation of p between element centres.
                    let t = (s / dr - 0.5).clamp(0.0, (n - 1) as f64);
                    let j = (t.floor() as usize).min(n - 2);
                    let w = t - j as f64;
                    g[i * n + j] += ker * (1.0 - w);
                    g[i * n + j + 1] += ker * w;
                }
            }
        }
        Seed {
            r,
            dr,
            g,
            k: 4.0 * mu.powf(1.5) / PI,
        }
    }

    /// Returns (force, iterations).
    fn solve(&self, alpha: f64) -> (f64, usize) {
        let n = self.r.len();
        let mut h: Vec<f64> = self
            .r
            .iter()
            .map(|&r| (1.0 - alpha + 0.5 * r * r).max(0.95))
            .collect();
        let mut p = vec![0.0; n];
        let mut it = 0;
        loop {
            it += 1;
            for j in 0..n {
                p[j] = lj_pressure(h[j]).0;
            }
            let mut m = 0.0f64;
            for i in 0..n {
                let row = &self.g[i * n..(i + 1) * n];
                let w: f64 = row.iter().zip(&p).map(|(a, b)| a * b).sum();
                let rhs = -alpha + 0.5 * self.r[i] * self.r[i] + 1.0 - self.k * w;
                let psi = rhs - h[i];
                m = m.max(psi.abs());
                h[i] += 0.001 * psi;
            }
            if m < 1e-3 || it > 2_000_000 {
                break;
            }
        }
        let f: f64 = (0..n)
            .map(|j| lj_pressure(h[j]).0 * self.r[j] * self.dr)
            .sum();
        (-2.0 * f, it)
    }
}

fn main() {
    let mu = 0.5;
    let sp = LjSphere::from_tabor(mu).unwrap();
    let alphas = [-1.0, 0.0, 0.5];
    let reference = sp.solver(1024).unwrap();
    let refs: Vec<f64> = alphas
        .iter()
        .map(|&a| reference.solve_at_approach(a, None).unwrap().force)
        .collect();
    let seed = Seed::new(mu, 128, 5.0);
    let t = Instant::now();
    let mut seed_err = 0.0f64;
    let mut seed_it = 0;
    for (i, &a) in alphas.iter().enumerate() {
        let (f, it) = seed.solve(a);
        seed_err = seed_err.max((f - refs[i]).abs());
        seed_it += it;
    }
    let t_seed = t.elapsed().as_secs_f64();
    println!("μ = {mu}, ᾱ ∈ {alphas:?}");
    println!("| scheme | N | max |P̄ − P̄_ref| | iterations | time (s) | ratio |");
    println!("|---|---|---|---|---|---|");
    println!(
        "| seed (relaxation 0.001, Gauss) | 128 | {seed_err:.2e} | {seed_it} | {t_seed:.4} | 1 |"
    );
    for n in [32, 64, 128] {
        let s = sp.solver(n).unwrap();
        let reps = 20;
        let t = Instant::now();
        let mut err = 0.0f64;
        let mut its = 0;
        for _ in 0..reps {
            for (i, &a) in alphas.iter().enumerate() {
                let r = s.solve_at_approach(a, None).unwrap();
                err = err.max((r.force - refs[i]).abs());
                its += r.iterations;
            }
        }
        let dt = t.elapsed().as_secs_f64() / reps as f64;
        println!(
            "| ours (Newton, faer LU) | {n} | {err:.2e} | {} | {dt:.6} | {:.0} |",
            its / reps,
            t_seed / dt
        );
    }
    // Full approach–retract curve at N = 256 (pseudo-arclength continuation).
    for mu in [0.1, 0.5, 1.0, 3.0, 10.0] {
        let sp = LjSphere::from_tabor(mu).unwrap();
        let mut o = LjOptions::default();
        o.n_grid = 256;
        let mut best = f64::INFINITY;
        let mut info = String::new();
        for _ in 0..5 {
            let t = Instant::now();
            let s = LjSolver::new(&sp, o).unwrap();
            let c = s.curve();
            let dt = t.elapsed().as_secs_f64();
            match c {
                Ok(c) => {
                    if dt < best {
                        best = dt;
                        info = format!(
                            "{} points, {} iterations, {} LU, max residual {:.1e}, pull-off {:.6}, hysteresis {:.5}",
                            c.points.len(),
                            c.iterations,
                            c.factorizations,
                            c.max_residual,
                            c.pull_off_load.force,
                            c.hysteresis_energy
                        );
                    }
                }
                Err(e) => {
                    best = dt;
                    info = format!("error: {e}");
                    break;
                }
            }
        }
        println!(
            "curve μ = {mu}, N = 256 (incl. influence matrix): {:.1} ms — {info} (bar: ≤ 100 ms)",
            best * 1e3
        );
    }
}
