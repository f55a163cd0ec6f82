//! Tabulated law against the closed-form Maugis–Dugdale law it tabulates:
//! time per call of `eval` (scalar, with per-contact states) and of
//! `eval_batch` (per element), over a mixed set of overlaps that visits the
//! far field, the adhesive region and deep contact.
//!
//! `cargo bench --bench tabulated`

use asperity::contact::tabulated::DEFAULT_TOLERANCE;
use asperity::contact::{eval_batch, ContactState, MaugisDugdale, NormalContact, TabulatedLaw};
use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use std::hint::black_box;

const N: usize = 4096;

fn inputs(md: &MaugisDugdale) -> (Vec<f64>, Vec<ContactState>) {
    let ds = md.length_scale();
    let mut x = 0x2545F4914F6CDD1Du64;
    let mut d = Vec::with_capacity(N);
    let mut s = Vec::with_capacity(N);
    for i in 0..N {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        let r = (x >> 11) as f64 / (1u64 << 53) as f64;
        d.push((-2.0 + 12.0 * r) * ds);
        let branch = (i % 2) as i32;
        s.push(ContactState {
            branch,
            in_contact: branch,
            ..Default::default()
        });
    }
    (d, s)
}

fn bench(c: &mut Criterion) {
    for lam in [0.1, 2.0] {
        let md = MaugisDugdale::from_maugis_parameter(1e-6, 1e9, 0.05, lam).unwrap();
        let t = TabulatedLaw::from_maugis_dugdale(&md, DEFAULT_TOLERANCE).unwrap();
        eprintln!(
            "λ = {lam}: {} knots, {} index entries, {} bytes, measured error {:.2e}",
            t.knot_count(),
            t.index_len(),
            t.memory_bytes(),
            t.measured_error()
        );
        let (d, s) = inputs(&md);
        let mut g = c.benchmark_group(format!("lambda_{lam}"));
        g.throughput(Throughput::Elements(N as u64));
        g.bench_function("table_eval", |b| {
            b.iter(|| {
                let mut acc = 0.0;
                for i in 0..N {
                    let (r, _) = t.eval(black_box(d[i]), &s[i]).unwrap();
                    acc += r.force;
                }
                acc
            })
        });
        let mut f = vec![0.0; N];
        let mut a = vec![0.0; N];
        let mut ns = vec![ContactState::default(); N];
        g.bench_function("table_batch", |b| {
            b.iter(|| {
                eval_batch(
                    &t,
                    black_box(&d),
                    Some(&s),
                    Some(&mut ns),
                    &mut f,
                    Some(&mut a),
                    None,
                )
                .unwrap();
                f[0]
            })
        });
        g.bench_function("maugis_dugdale_eval", |b| {
            b.iter(|| {
                let mut acc = 0.0;
                for i in 0..N {
                    let (r, _) = md.eval(black_box(d[i]), &s[i]).unwrap();
                    acc += r.force;
                }
                acc
            })
        });
        g.finish();
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).measurement_time(std::time::Duration::from_secs(2)).warm_up_time(std::time::Duration::from_millis(500));
    targets = bench
}
criterion_main!(benches);
