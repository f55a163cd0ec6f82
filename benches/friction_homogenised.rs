//! Time per point of the homogenised friction step (issue 6 §4 (b), §7: ≤ 1 µs
//! per point, no allocation), single step and VFRIC-shaped block, through the
//! Rust API and the C ABI, next to a hand-written inline 2-D Coulomb return
//! mapping with a constant μ (no table lookup, no validation, no tangents):
//! the floor a host code would write itself.
//!
//! `cargo bench --bench friction_homogenised`. A plain calibrated timing loop
//! (median over rounds, paths interleaved round by round so machine noise
//! hits them alike). Tunables: `ASPERITY_BENCH_ROUNDS` (default 11),
//! `ASPERITY_BENCH_RUN_MS` (target length of one timed run, default 40).

use asperity::ffi::friction_law::{
    asperity_friction_free, asperity_friction_from_homogenised, asperity_friction_step_block,
    asperity_friction_work_free, asperity_friction_work_new,
};
use asperity::ffi::homogenised::{
    asperity_homogenised_friction_free, asperity_homogenised_friction_new,
};
use asperity::friction::{
    BlockStates, CofForm, Dissipation, FrictionBlock, FrictionIncrement, FrictionLaw,
    HomogenisedFriction, HomogenisedSample,
};
use std::hint::black_box;
use std::time::{Duration, Instant};

/// Points per block, and per timed pass of the single-step paths.
const N: usize = 1024;
const AREA: f64 = 1e-6;
const K: f64 = 1e8;
const DT: f64 = 1e-6;
/// Doubles of a point's state.
const M: usize = HomogenisedFriction::STATE_LEN;

fn env(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

fn samples() -> Vec<HomogenisedSample> {
    // Copper-like, 9 samples over 10..200 MPa.
    (0..9)
        .map(|i| {
            let p = 10e6 + 190e6 * i as f64 / 8.0;
            HomogenisedSample {
                pressure: p,
                cof: 1.1 - 0.2 * (p - 10e6) / 190e6 + 0.01 * (i as f64 * 0.7).sin(),
                adhesion_pressure: 0.09 * p,
                contact_fraction: p / 1e9,
                shares: Dissipation {
                    chemical: 0.93,
                    van_der_waals: 0.065,
                    elastic: 0.004,
                    plastic: 0.001,
                },
            }
        })
        .collect()
}

/// Inputs: normal forces across (and a little beyond) the table, 2-D slip
/// increments of which about half slide, and states from a previous step.
struct Inputs {
    normal: Vec<f64>,
    area: Vec<f64>,
    slip: Vec<f64>,
    /// The points' states, M doubles each.
    old: Vec<f64>,
}

fn inputs(law: &HomogenisedFriction) -> Inputs {
    let mut x = 0x2545_F491_4F6C_DD1Du64;
    let mut rnd = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut normal = Vec::with_capacity(N);
    let mut slip = Vec::with_capacity(2 * N);
    for _ in 0..N {
        normal.push((5.0 + 210.0 * rnd()) * 1e6 * AREA);
        let a = 2.0 * std::f64::consts::PI * rnd();
        let m = 2e-6 * rnd();
        slip.push(m * a.cos());
        slip.push(m * a.sin());
    }
    let area = vec![AREA; N];
    let fresh = vec![0.0; N * M];
    let mut old = fresh.clone();
    let mut f = vec![0.0; 2 * N];
    let mut d = vec![0.0; N];
    law.step_block(
        FrictionBlock {
            normal_force: &normal,
            area: Some(&area),
            slip: &slip,
            dt: DT,
            tangents: 0,
            states: BlockStates::Separate {
                old: &fresh,
                new: &mut old,
            },
            tangential_force: Some(&mut f),
            dissipation: Some(&mut d),
            responses: None,
        },
        &mut law.work(),
    )
    .unwrap();
    Inputs {
        normal,
        area,
        slip,
        old,
    }
}

/// The hand-written comparison: 2-D regularised Coulomb with constant μ.
#[inline(always)]
fn coulomb_inline(mu: f64, n: f64, old: [f64; 2], ds: [f64; 2], k: f64) -> ([f64; 2], f64) {
    let lim = mu * n;
    let tx = old[0] - k * ds[0];
    let ty = old[1] - k * ds[1];
    let t = (tx * tx + ty * ty).sqrt();
    if t <= lim {
        ([tx, ty], 0.0)
    } else {
        let s = lim / t;
        ([tx * s, ty * s], lim * (t - lim) / k)
    }
}

/// Median ns per point of `f` (which processes N points per call).
fn time(rounds: u64, run: Duration, paths: &mut [(&str, &mut dyn FnMut() -> f64)]) -> Vec<f64> {
    // Calibrate: calls per timed run.
    let mut reps = vec![1u64; paths.len()];
    for (j, (_, f)) in paths.iter_mut().enumerate() {
        loop {
            let t = Instant::now();
            for _ in 0..reps[j] {
                black_box(f());
            }
            if t.elapsed() >= run / 4 {
                break;
            }
            reps[j] *= 2;
        }
        reps[j] *= 4;
    }
    let mut samples = vec![Vec::new(); paths.len()];
    for _ in 0..rounds {
        for (j, (_, f)) in paths.iter_mut().enumerate() {
            let t = Instant::now();
            for _ in 0..reps[j] {
                black_box(f());
            }
            samples[j].push(t.elapsed().as_secs_f64() * 1e9 / (reps[j] as f64 * N as f64));
        }
    }
    samples
        .into_iter()
        .map(|mut v| {
            v.sort_by(|a, b| a.partial_cmp(b).unwrap());
            v[v.len() / 2]
        })
        .collect()
}

fn main() {
    // `cargo bench` passes `--bench`; `cargo test --benches` runs it once.
    let quick = !std::env::args().any(|a| a == "--bench");
    let rounds = if quick {
        1
    } else {
        env("ASPERITY_BENCH_ROUNDS", 11)
    };
    let run = Duration::from_millis(if quick {
        1
    } else {
        env("ASPERITY_BENCH_RUN_MS", 40)
    });

    let s = samples();
    let law = HomogenisedFriction::from_samples(&s, CofForm::Derjaguin)
        .unwrap()
        .with_stick_stiffness(K)
        .unwrap();
    let mut table = std::ptr::null_mut();
    assert_eq!(
        unsafe { asperity_homogenised_friction_new(s.as_ptr(), s.len(), &mut table) },
        0
    );
    let mut handle = std::ptr::null_mut();
    assert_eq!(
        unsafe { asperity_friction_from_homogenised(table, K, &mut handle) },
        0
    );
    let mut c_work = std::ptr::null_mut();
    assert_eq!(
        unsafe { asperity_friction_work_new(handle, &mut c_work) },
        0
    );
    let mut work = law.work();
    let mut block_work = law.work();
    let inp = inputs(&law);
    let mut new = inp.old.clone();
    let mut f = vec![0.0; 2 * N];
    let mut d = vec![0.0; N];
    let mut cnew = inp.old.clone();
    let mut cf = vec![0.0; 2 * N];
    let mut cd = vec![0.0; N];
    let mut inline_f = vec![0.0; 2 * N];

    let mut single = || {
        let mut acc = 0.0;
        let mut st = [0.0; M];
        for i in 0..N {
            let inc = FrictionIncrement {
                normal_force: black_box(inp.normal[i]),
                area: inp.area[i],
                slip: [inp.slip[2 * i], inp.slip[2 * i + 1]],
                dt: DT,
                ..Default::default()
            };
            let r = law
                .step(&inp.old[i * M..(i + 1) * M], &mut st, &inc, &mut work)
                .unwrap();
            acc += r.dissipated + st[HomogenisedFriction::STATE_FORCE];
        }
        acc
    };
    let mut block = || {
        law.step_block(
            FrictionBlock {
                normal_force: black_box(&inp.normal),
                area: Some(&inp.area),
                slip: &inp.slip,
                dt: DT,
                tangents: 0,
                states: BlockStates::Separate {
                    old: &inp.old,
                    new: &mut new,
                },
                tangential_force: Some(&mut f),
                dissipation: Some(&mut d),
                responses: None,
            },
            &mut block_work,
        )
        .unwrap();
        d[N - 1]
    };
    let mut c_block = || {
        let st = unsafe {
            asperity_friction_step_block(
                handle,
                N,
                black_box(inp.normal.as_ptr()),
                inp.area.as_ptr(),
                inp.slip.as_ptr(),
                DT,
                inp.old.as_ptr(),
                cnew.as_mut_ptr(),
                cf.as_mut_ptr(),
                cd.as_mut_ptr(),
                c_work,
            )
        };
        assert_eq!(st, 0);
        cd[N - 1]
    };
    let mut inline = || {
        let mut acc = 0.0;
        for i in 0..N {
            let (fo, di) = coulomb_inline(
                black_box(1.0),
                inp.normal[i],
                [
                    inp.old[i * M + HomogenisedFriction::STATE_FORCE],
                    inp.old[i * M + HomogenisedFriction::STATE_FORCE + 1],
                ],
                [inp.slip[2 * i], inp.slip[2 * i + 1]],
                K,
            );
            inline_f[2 * i] = fo[0];
            inline_f[2 * i + 1] = fo[1];
            acc += di;
        }
        acc
    };
    let mut paths: Vec<(&str, &mut dyn FnMut() -> f64)> = vec![
        ("step (Rust, one point per call)", &mut single),
        ("step_block (Rust)", &mut block),
        ("asperity_friction_step_block (C ABI)", &mut c_block),
        ("inline Coulomb return mapping, constant μ", &mut inline),
    ];
    let ns = time(rounds, run, &mut paths);
    let names: Vec<&str> = paths.iter().map(|p| p.0).collect();
    drop(paths);
    let slipping = d.iter().filter(|&&x| x > 0.0).count();
    println!(
        "homogenised friction step: {} samples, {N} points per pass, {slipping} sliding",
        s.len()
    );
    println!("| path | ns/point | ratio to inline Coulomb |");
    println!("|---|---:|---:|");
    let base = ns[3];
    for (name, t) in names.iter().zip(&ns) {
        println!("| {name} | {t:.1} | {:.2} |", t / base);
    }
    let worst = ns[..3].iter().cloned().fold(0.0, f64::max);
    println!(
        "bar: <= 1000 ns per point: {} (worst path {worst:.1} ns)",
        if worst <= 1000.0 { "PASS" } else { "FAIL" }
    );
    unsafe {
        asperity_friction_work_free(c_work);
        asperity_friction_free(handle);
        asperity_homogenised_friction_free(table);
    }
}
