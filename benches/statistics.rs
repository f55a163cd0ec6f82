//! Greenwood–Williamson load at one separation, Gaussian heights (thesis
//! (1-29)): time per evaluation of the library's `load` (the exponentially
//! convergent trapezoidal sum for F_{3/2}, accurate to 1e-12), against a
//! naive fine trapezoid in the height variable with enough points for 1e-8,
//! and the general-order tanh–sinh path. Separations sweep d/σ ∈ [−3, 6].
//!
//! Bush–Gibson–Thomas (thesis §5.3.3): time per response (load, area,
//! contacts, stiffness) at 16 separations d/σ ∈ [−2, 6] for Nayak's α = 5 and
//! 100, against a brute-force double trapezoid over the mean curvature and
//! the curvature difference (4000 × 4000 nodes, exact elliptic Hertz at every
//! node) of the same integrals. Bora et al. (§5.3.9): one equilibrium on
//! 16 × 16 and 32 × 32 maps.
//!
//! `cargo bench --bench statistics`

use asperity::statistics::gaussian::{f0, f1, f1_2};
use asperity::statistics::gaussian::{f3_2, tail_moment_quadrature};
use asperity::statistics::{
    BoraTopography, BushGibsonThomas, EllipticHertz, GreenwoodWilliamson, HeightDistribution,
};
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use std::hint::black_box;

const N: usize = 64;
const NAIVE_POINTS: usize = 25_000;

/// F_{3/2}(h) by the plain trapezoidal rule on s ∈ [h, h + 12] with `n`
/// intervals: the "obvious" implementation. The `(s − h)^{3/2}` endpoint
/// makes its error O(Δ^{5/2}).
fn naive_f3_2(h: f64, n: usize) -> f64 {
    let span = 12.0;
    let step = span / n as f64;
    let mut sum = 0.0;
    for k in 1..=n {
        let t = k as f64 * step;
        let w = if k == n { 0.5 } else { 1.0 };
        let s = h + t;
        sum += w * t * t.sqrt() * (-0.5 * s * s).exp();
    }
    sum * step / (2.0 * core::f64::consts::PI).sqrt()
}

fn bench(c: &mut Criterion) {
    let sigma = 1e-6;
    let gw = GreenwoodWilliamson::new(
        1e4,
        100e-6,
        100e9,
        HeightDistribution::gaussian(sigma).unwrap(),
    )
    .unwrap();
    let h: Vec<f64> = (0..N)
        .map(|i| -3.0 + 9.0 * i as f64 / (N - 1) as f64)
        .collect();
    let d: Vec<f64> = h.iter().map(|h| h * sigma).collect();

    // Accuracy of each method against the library (itself checked to 1e-12
    // against 40-digit values in tests/statistics_gaussian.rs).
    let mut naive_err: f64 = 0.0;
    let mut quad_err: f64 = 0.0;
    for &h in &h {
        let exact = f3_2(h).unwrap();
        naive_err = naive_err.max((naive_f3_2(h, NAIVE_POINTS) / exact - 1.0).abs());
        quad_err =
            quad_err.max((tail_moment_quadrature(1.5, h).unwrap().value / exact - 1.0).abs());
    }
    eprintln!(
        "h in [-3, 6]: naive trapezoid ({NAIVE_POINTS} points) max rel. error {naive_err:.1e}; \
         tanh-sinh {quad_err:.1e}"
    );

    let mut g = c.benchmark_group("gw_gaussian_load");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("library_load", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for &d in &d {
                acc += gw.load(black_box(d)).unwrap();
            }
            acc
        })
    });
    g.bench_function("tanh_sinh_f3_2", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for &h in &h {
                acc += tail_moment_quadrature(1.5, black_box(h)).unwrap().value;
            }
            acc
        })
    });
    g.sample_size(10);
    g.bench_function("naive_trapezoid_f3_2", |b| {
        b.iter(|| {
            let mut acc = 0.0;
            for &h in &h {
                acc += naive_f3_2(black_box(h), NAIVE_POINTS);
            }
            acc
        })
    });
    g.finish();
}

/// Brute-force BGT `[contacts, area, load, stiffness]` at separation `d`:
/// the integrals of the module docs in κ = k̄/σ_k (trapezoid on [0, κ_c + 14],
/// `nk` intervals) and t = sin θ (trapezoid on θ ∈ [0, π/2], `nt` intervals).
fn bgt_reference(s: &BushGibsonThomas, d: f64, nk: usize, nt: usize) -> [f64; 4] {
    let (m0, m2, m4, e) = (s.m0(), s.m2(), s.m4(), s.e_star());
    // The curvature-difference rule, θ nodes with exact Hertz factors.
    let ht = core::f64::consts::FRAC_PI_2 / nt as f64;
    let rule: Vec<(f64, f64, f64, f64)> = (0..=nt)
        .map(|i| {
            let th = i as f64 * ht;
            let (t, c) = (th.sin(), th.cos());
            let w = if i == 0 || i == nt { 0.5 * ht } else { ht } * c; // dt = cos θ dθ
            let lambda = if c > 0.0 {
                (1.0 + t) / ((1.0 - t).max(1e-300))
            } else {
                f64::INFINITY
            };
            let (fa, fp) = if lambda.is_finite() && lambda < 1e300 {
                let h = EllipticHertz::new(lambda).unwrap();
                (h.area_factor, h.load_factor)
            } else {
                (0.0, 0.0)
            };
            (
                t,
                w * t * (1.0 - t * t),
                w * t * c * fa,
                w * t * c.powf(1.5) * fp,
            )
        })
        .collect();
    let sigma_k = (2.0 * m4 / 3.0).sqrt();
    let s_z = (m0 - 1.5 * m2 * m2 / m4).sqrt();
    let base = 1.0 / (2.0 * core::f64::consts::PI * m2 * m4 / 3.0);
    let hi = (m2 * d / m0 / sigma_k).max(0.0) + 14.0;
    let hk = hi / nk as f64;
    let mut acc = [0.0; 4];
    for i in 1..=nk {
        let kappa = i as f64 * hk;
        let w = if i == nk { 0.5 * hk } else { hk };
        let phi = (-0.5 * kappa * kappa).exp() / (2.0 * core::f64::consts::PI).sqrt();
        let beta2 = 2.0 * kappa * kappa;
        let (mut jn, mut ja, mut jp) = (0.0, 0.0, 0.0);
        for &(t, cn, ca, cp) in &rule {
            let x = (-0.5 * beta2 * t * t).exp();
            jn += cn * x;
            ja += ca * x;
            jp += cp * x;
        }
        let h = (d - m2 / sigma_k * kappa) / s_z;
        let k35 = kappa.powf(3.5);
        acc[0] += w * phi * kappa.powi(4) * jn * f0(h).unwrap();
        acc[1] += w * phi * kappa.powi(3) * ja * f1(h).unwrap();
        acc[2] += w * phi * k35 * jp * f3_2(h).unwrap();
        acc[3] += w * phi * k35 * jp * f1_2(h).unwrap();
    }
    let a0 = s.nominal_area();
    [
        a0 * base * sigma_k.powi(4) * acc[0],
        a0 * base * sigma_k.powi(3) * core::f64::consts::PI * s_z * acc[1],
        a0 * base * sigma_k.powf(3.5) * (4.0 / 3.0) * e * s_z.powf(1.5) * acc[2],
        a0 * base * sigma_k.powf(3.5) * 2.0 * e * s_z.sqrt() * acc[3],
    ]
}

fn bench_bgt(c: &mut Criterion) {
    let sigma = 1e-6;
    let d: Vec<f64> = (0..16)
        .map(|i| (-2.0 + 8.0 * i as f64 / 15.0) * sigma)
        .collect();
    let mut g = c.benchmark_group("bgt_response");
    g.throughput(Throughput::Elements(d.len() as u64));
    g.sample_size(10);
    for &alpha in &[5.0, 100.0] {
        let s = BushGibsonThomas::from_alpha(sigma, 0.1, alpha, 1e9, 1e-4).unwrap();
        let mut worst: f64 = 0.0;
        let t0 = std::time::Instant::now();
        for &x in d.iter().step_by(3) {
            let r = s.evaluate(x).unwrap();
            let got = [
                r.response.contacts,
                r.response.area,
                r.response.load,
                r.stiffness,
            ];
            let want = bgt_reference(&s, x, 4000, 4000);
            for j in 0..4 {
                worst = worst.max((got[j] / want[j] - 1.0).abs());
            }
        }
        eprintln!(
            "BGT alpha {alpha}: max rel. difference to the 4000x4000 trapezoid {worst:.1e} \
             (reference {:.2} s per separation)",
            t0.elapsed().as_secs_f64() / 6.0
        );
        g.bench_function(format!("library_response_alpha_{alpha}"), |b| {
            b.iter(|| {
                let mut acc = 0.0;
                for &x in &d {
                    acc += s.evaluate(black_box(x)).unwrap().response.load;
                }
                acc
            })
        });
    }
    g.finish();
}

/// Bora et al.: one equilibrium (Polonsky–Keer CG) on pseudo-random maps of
/// 16 × 16 and 32 × 32 springs, half of them loaded, with the largest gap
/// residual of the loaded springs relative to the height range.
#[allow(clippy::needless_range_loop)] // forces and heights in lockstep
fn bench_bora(c: &mut Criterion) {
    let mut g = c.benchmark_group("bora_solve");
    g.sample_size(10);
    for &side in &[16usize, 32] {
        let n = side * side;
        let mut x = 12345u64;
        let h: Vec<f64> = (0..n)
            .map(|_| {
                x = x
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                5e-9 * (2.0 * ((x >> 11) as f64 / (1u64 << 53) as f64) - 1.0)
            })
            .collect();
        let m = BoraTopography::new(side, side, 10e-9, h.clone(), 50.0, Some(1e9)).unwrap();
        let s = m.solve(0.0).unwrap();
        let mut worst: f64 = 0.0;
        for i in 0..n {
            if s.forces[i] > 0.0 {
                let u: f64 = (0..n).map(|j| m.influence(i, j) * s.forces[j]).sum();
                worst = worst.max((0.0 - h[i] + s.forces[i] / 50.0 + u).abs() / 1e-8);
            }
        }
        eprintln!(
            "Bora {side}x{side}: {} of {n} springs loaded, {} CG iterations, max gap residual {worst:.1e} of the height range",
            s.contacts, s.iterations
        );
        g.bench_function(format!("solve_{side}x{side}"), |b| {
            b.iter(|| m.solve(black_box(0.0)).unwrap().load)
        });
    }
    g.finish();
}

criterion_group!(benches, bench, bench_bgt, bench_bora);
criterion_main!(benches);
