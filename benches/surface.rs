//! Profile analysis speed: ISO 4287 parameters and the PSD of a 10⁶-point
//! profile (target: both together ≤ 50 ms, single-threaded), and the FFT PSD
//! against a naive O(n²) DFT at n = 4096 to show what the FFT buys.
//!
//! `cargo bench --bench surface`

use asperity::surface::{roughness_parameters, ParameterOptions, Psd, PsdPlan, SelfAffine, Window};
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use std::hint::black_box;
use std::time::Instant;

const N: usize = 1_000_000;
const DX: f64 = 1e-7;

fn profile(n: usize) -> Vec<f64> {
    SelfAffine::new(0.8, 1e-6)
        .unwrap()
        .with_roll_off(n as f64 * DX / 20.0)
        .unwrap()
        .profile(n, DX, 2024)
        .unwrap()
        .into_heights()
}

/// One-sided power spectrum by the textbook O(n²) DFT (twiddles tabulated),
/// normalised like `surface::psd`.
fn naive_psd(z: &[f64], dx: f64, out: &mut [f64], cos: &[f64], sin: &[f64]) {
    let n = z.len();
    let m = z.iter().sum::<f64>() / n as f64;
    for (k, o) in out.iter_mut().enumerate() {
        let (mut re, mut im) = (0.0, 0.0);
        let mut idx = 0usize;
        for &v in z {
            re += (v - m) * cos[idx];
            im -= (v - m) * sin[idx];
            idx += k;
            if idx >= n {
                idx -= n;
            }
        }
        let f = if k == 0 || 2 * k == n { 0.5 } else { 1.0 };
        *o = f * (re * re + im * im) * dx / (std::f64::consts::PI * n as f64);
    }
}

fn bench(c: &mut Criterion) {
    let z = profile(N);
    let no_hurst = ParameterOptions {
        hurst: false,
        ..Default::default()
    };
    let with_hurst = ParameterOptions::default();
    let mut plan = PsdPlan::new(N).unwrap();
    let mut g = Psd::default();

    // A first wall-clock figure, printed for the record.
    let t0 = Instant::now();
    let r = roughness_parameters(&z, DX, &with_hurst).unwrap();
    plan.compute(&z, DX, Window::Rectangular, &mut g).unwrap();
    let once = t0.elapsed();
    eprintln!(
        "10^6 points: parameters (with Hurst fit) + PSD, first call incl. planning: {:.1} ms; Rq = {:.4e} m, H = {:?}, m0/Rq² - 1 = {:.1e}",
        once.as_secs_f64() * 1e3,
        r.rq,
        r.psd_hurst_exponent,
        g.moments().m0 / (r.rq * r.rq) - 1.0
    );

    let mut grp = c.benchmark_group("profile_1e6");
    grp.throughput(Throughput::Elements(N as u64));
    grp.bench_function("iso_parameters", |b| {
        b.iter(|| roughness_parameters(black_box(&z), DX, &no_hurst).unwrap())
    });
    grp.bench_function("iso_parameters_with_hurst_fit", |b| {
        b.iter(|| roughness_parameters(black_box(&z), DX, &with_hurst).unwrap())
    });
    grp.bench_function("psd_planned", |b| {
        b.iter(|| {
            plan.compute(black_box(&z), DX, Window::Rectangular, &mut g)
                .unwrap();
            g.c[1]
        })
    });
    grp.bench_function("psd_one_shot", |b| {
        b.iter(|| asperity::surface::psd(black_box(&z), DX).unwrap().c[1])
    });
    grp.bench_function("iso_parameters_plus_psd", |b| {
        b.iter(|| {
            let r = roughness_parameters(black_box(&z), DX, &no_hurst).unwrap();
            plan.compute(&z, DX, Window::Rectangular, &mut g).unwrap();
            r.rq + g.c[1]
        })
    });
    grp.bench_function("iso_parameters_with_hurst_plus_psd", |b| {
        b.iter(|| {
            let r = roughness_parameters(black_box(&z), DX, &with_hurst).unwrap();
            plan.compute(&z, DX, Window::Rectangular, &mut g).unwrap();
            r.rq + g.c[1]
        })
    });
    grp.finish();

    // FFT against the O(n²) DFT on a short profile; both give the same PSD.
    let n = 4096;
    let zs = profile(n);
    let cos: Vec<f64> = (0..n)
        .map(|j| (2.0 * std::f64::consts::PI * j as f64 / n as f64).cos())
        .collect();
    let sin: Vec<f64> = (0..n)
        .map(|j| (2.0 * std::f64::consts::PI * j as f64 / n as f64).sin())
        .collect();
    let mut naive = vec![0.0; n / 2 + 1];
    naive_psd(&zs, DX, &mut naive, &cos, &sin);
    let fft = asperity::surface::psd(&zs, DX).unwrap();
    let peak = naive.iter().cloned().fold(0.0, f64::max);
    let err = naive
        .iter()
        .zip(&fft.c)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    eprintln!(
        "n = {n}: max |naive DFT − FFT| PSD difference = {:.1e} of the peak",
        err / peak
    );
    let mut small = PsdPlan::new(n).unwrap();
    let mut gs = Psd::default();
    let mut grp = c.benchmark_group("psd_4096");
    grp.bench_function("fft", |b| {
        b.iter(|| {
            small
                .compute(black_box(&zs), DX, Window::Rectangular, &mut gs)
                .unwrap();
            gs.c[1]
        })
    });
    grp.bench_function("naive_dft", |b| {
        b.iter(|| {
            naive_psd(black_box(&zs), DX, &mut naive, &cos, &sin);
            naive[1]
        })
    });
    grp.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).measurement_time(std::time::Duration::from_secs(3)).warm_up_time(std::time::Duration::from_millis(500));
    targets = bench
}
criterion_main!(benches);
