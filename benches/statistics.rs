//! Greenwood–Williamson load at one separation, Gaussian heights (thesis
//! (1-29)): time per evaluation of the library's `load` (the exponentially
//! convergent trapezoidal sum for F_{3/2}, accurate to 1e-12), against a
//! naive fine trapezoid in the height variable with enough points for 1e-8,
//! and the general-order tanh–sinh path. Separations sweep d/σ ∈ [−3, 6].
//!
//! `cargo bench --bench statistics`

use asperity::statistics::gaussian::{f3_2, tail_moment_quadrature};
use asperity::statistics::{GreenwoodWilliamson, HeightDistribution};
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

criterion_group!(benches, bench);
criterion_main!(benches);
