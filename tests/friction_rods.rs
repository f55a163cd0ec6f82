//! The micro-rod equilibrium of `asperity::friction::rods`: hand cases,
//! exact sweep against the thesis's dense formulation (6-12)/(6-16), limits,
//! volume conservation (6.2.3), energies (4-15, 4-16), argument errors, and
//! the substrate-coupled model.

use asperity::friction::{
    square_influence, CoupledRodBed, Loading, PlasticUpdate, RodBed, RodOptions, RodSolver,
    RodState,
};
use asperity::Error;
use faer::linalg::solvers::Llt;
use faer::Side;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Hand-case bed: w = 1 mm (A = 1e-6 m²), E = 1 GPa, σ_y = 10 MPa
/// (F_y = 10 N, ε_y = 0.01), root depth 1 mm, all H_i = 0, so L = 1 mm and
/// k = E A / L = 1e9 · 1e-6 / 1e-3 = 1e6 N/m for every rod.
fn hand_bed(n: usize) -> RodBed {
    let centers = (0..n).map(|i| (i as f64 + 0.5) * 1e-3).collect();
    RodBed::new(1e-3, centers, vec![0.0; n], 1e-3, 1e9, 1e7).unwrap()
}

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

fn load(
    bed: &RodBed,
    state: &RodState,
    counter: &[f64],
    p: f64,
    opts: &RodOptions,
) -> (
    asperity::friction::RodReport,
    asperity::friction::RodSolution,
    RodState,
) {
    let mut out = bed.solution();
    let mut new = state.clone();
    let r = bed
        .solve(
            state,
            &mut new,
            counter,
            Loading::FixedLoad { load: p },
            opts,
            &mut out,
        )
        .unwrap();
    (r, out, new)
}

#[test]
fn hand_two_rods_fixed_load() {
    // g = [1 µm, 0] → contact onsets a = [1e-6, 0]; yield onsets
    // y = a − F_y/k = a − 1e-5.
    let bed = hand_bed(2);
    let s = bed.state();
    let g = [1e-6, 0.0];
    let o = RodOptions::default();

    // P = 0.5 N: rod 0 alone, δ = P/k = 5e-7 < 1e-6, so b = 1e-6 − 5e-7 =
    // 5e-7 > a_1 = 0 (rod 1 clear).
    let (r, out, _) = load(&bed, &s, &g, 0.5, &o);
    assert!(close(r.position, 5e-7, 1e-18), "{}", r.position);
    assert!(close(out.forces()[0], 0.5, 1e-12) && out.forces()[1] == 0.0);
    assert_eq!(r.in_contact, 1);

    // P = 3 N: both rods, k(1e-6 − b) + k(0 − b) = 3 → b = −1e-6,
    // f = [2, 1] N.
    let (r, out, _) = load(&bed, &s, &g, 3.0, &o);
    assert!(close(r.position, -1e-6, 1e-18), "{}", r.position);
    assert!(close(out.forces()[0], 2.0, 1e-9) && close(out.forces()[1], 1.0, 1e-9));
    assert_eq!((r.in_contact, r.yielded), (2, 0));
    // Stored energy (4-15): ½(2²+1²)/1e6 = 2.5e-6 J.
    assert!(close(r.elastic_energy, 2.5e-6, 1e-15));

    // P = 19.5 N: rod 0 yields (10 N) once b ≤ −9e-6; rod 1 carries 9.5 N,
    // b = −9.5e-6. Rod 0 overlap 1.05e-5 m; plastic shortening (6.2.3)
    // s = (o − ε_y L)/(1 − ε_y) = (1.05e-5 − 1e-5)/0.99 = 5.050505e-7 m;
    // plastic work (4-16) F_y s = 5.050505e-6 J. Nearest non-yielded rod is
    // rod 1 (only side): H_1 += s.
    let (r, out, new) = load(&bed, &s, &g, 19.5, &o);
    assert!(close(r.position, -9.5e-6, 1e-17), "{}", r.position);
    assert!(out.yielded()[0] && !out.yielded()[1]);
    assert!(close(out.forces()[0], 10.0, 0.0) && close(out.forces()[1], 9.5, 1e-9));
    let s_expected = 0.5e-6 / 0.99;
    assert!(close(out.plastic_shortening()[0], s_expected, 1e-17));
    assert!(close(r.plastic_work, 10.0 * s_expected, 1e-16));
    assert!(close(new.heights[0], -s_expected, 1e-17));
    assert!(close(new.heights[1], s_expected, 1e-17));
    assert!(close(new.heights[0] + new.heights[1], 0.0, 1e-21));
    // After shortening the rod still carries exactly F_y at b:
    // k' (o − s) with k' = E A/(L − s).
    let k_new = bed.stiffness(new.heights[0]);
    assert!(close(k_new * (1.05e-5 - s_expected), 10.0, 1e-9));
}

#[test]
fn hand_three_rods_fixed_load() {
    // g = [2, 1, 0] µm, P = 4 N: all three in contact,
    // k(3e-6 − 3b) = 4 → b = −1/3 µm; f = k(a − b) = [7/3, 4/3, 1/3] N.
    let bed = hand_bed(3);
    let (r, out, _) = load(
        &bed,
        &bed.state(),
        &[2e-6, 1e-6, 0.0],
        4.0,
        &RodOptions::default(),
    );
    assert!(close(r.position, -1e-6 / 3.0, 1e-18));
    for (f, e) in out.forces().iter().zip([7.0 / 3.0, 4.0 / 3.0, 1.0 / 3.0]) {
        assert!(close(*f, e, 1e-9), "{f} vs {e}");
    }
    assert!(r.residual < 1e-12);
}

#[test]
fn hand_fixed_gap() {
    let g = [1e-6, 0.0];
    let o = RodOptions::default();
    // Rigid bulk, b₀ = −2 µm: f = k(a − b₀) = [3, 2] N.
    let bed = hand_bed(2);
    let s = bed.state();
    let mut out = bed.solution();
    let mut new = s.clone();
    let r = bed
        .solve(
            &s,
            &mut new,
            &g,
            Loading::FixedGap { position: -2e-6 },
            &o,
            &mut out,
        )
        .unwrap();
    assert_eq!(r.position, -2e-6);
    assert!(close(out.forces()[0], 3.0, 1e-9) && close(out.forces()[1], 2.0, 1e-9));
    // Elastic bulk k_B = 1e6 N/m (E_B A_B/H_B = 1e9·1e-6/1e-3), b₀ = 0:
    // rod 0 only, k_B (b − 0) = k (1e-6 − b) → b = 5e-7, F = 0.5 N,
    // δ_B = 5e-7.
    let bed = hand_bed(2).with_bulk(1e9, 1e-6, 1e-3).unwrap();
    for solver in [RodSolver::Sweep, RodSolver::Dense] {
        let o = RodOptions { solver, ..o };
        let r = bed
            .solve(
                &s,
                &mut new,
                &g,
                Loading::FixedGap { position: 0.0 },
                &o,
                &mut out,
            )
            .unwrap();
        assert!(close(r.position, 5e-7, 1e-18), "{solver:?} {}", r.position);
        assert!(close(r.bulk_compression, 5e-7, 1e-18));
        assert!(close(r.total_force, 0.5, 1e-9));
        assert!(r.residual < 1e-9);
    }
    // No contact: b₀ above every rod: no force, b = b₀.
    let r = bed
        .solve(
            &s,
            &mut new,
            &g,
            Loading::FixedGap { position: 1e-5 },
            &o,
            &mut out,
        )
        .unwrap();
    assert!(close(r.position, 1e-5, 1e-20));
    assert_eq!((r.total_force, r.in_contact), (0.0, 0));
}

#[test]
fn zero_load_capacity_and_overload() {
    let bed = hand_bed(2);
    let s = bed.state();
    let g = [1e-6, 0.0];
    for solver in [RodSolver::Sweep, RodSolver::Dense] {
        let o = RodOptions {
            solver,
            ..RodOptions::default()
        };
        // Zero load: the highest rod just touches, b = max a = 1 µm.
        let (r, out, _) = load(&bed, &s, &g, 0.0, &o);
        assert_eq!(r.position, 1e-6);
        assert_eq!(r.in_contact, 0);
        assert!(out.forces().iter().all(|&f| f == 0.0));
        // Load = capacity 20 N: b = min y = 0 − 1e-5, all rods yielded.
        let (r, _, _) = load(&bed, &s, &g, 20.0, &o);
        assert!(close(r.position, -1e-5, 1e-20));
        assert_eq!(r.yielded, 2);
        // Above capacity: a named error.
        let mut out = bed.solution();
        let mut new = s.clone();
        let e = bed
            .solve(
                &s,
                &mut new,
                &g,
                Loading::FixedLoad { load: 20.1 },
                &o,
                &mut out,
            )
            .unwrap_err();
        assert!(
            matches!(e, Error::OutOfDomain { name: "load", .. }),
            "{e:?}"
        );
    }
}

#[test]
fn flat_profile() {
    // All rods equal, flat counter-surface: every rod carries P/n.
    let n = 50;
    let bed = hand_bed(n);
    let g = vec![3e-7; n];
    let p = 123.0;
    let (r, out, _) = load(&bed, &bed.state(), &g, p, &RodOptions::default());
    // b = a − P/(n k).
    assert!(close(r.position, 3e-7 - p / (n as f64 * 1e6), 1e-18));
    for &f in out.forces() {
        assert!(close(f, p / n as f64, 1e-9));
    }
    assert_eq!(r.in_contact, n);
    // Dense agrees; zero load and capacity are the flat's two corners.
    let o = RodOptions {
        solver: RodSolver::Dense,
        ..RodOptions::default()
    };
    let (rd, _, _) = load(&bed, &bed.state(), &g, p, &o);
    assert!(close(rd.position, r.position, 1e-18));
    let (r0, _, _) = load(&bed, &bed.state(), &g, 0.0, &RodOptions::default());
    assert_eq!(r0.position, 3e-7);
    let (rc, _, _) = load(
        &bed,
        &bed.state(),
        &g,
        bed.capacity(),
        &RodOptions::default(),
    );
    assert_eq!(rc.yielded, n);
}

/// A random bed in the thesis's regime: copper-like rods 1.5 µm wide,
/// heights ± 0.5 µm, root depth 10 µm, counter-surface ± 0.5 µm.
fn random_bed(rng: &mut ChaCha8Rng, n: usize) -> (RodBed, Vec<f64>) {
    let w = 1.5e-6;
    let centers = (0..n).map(|i| (i as f64 + 0.5) * w).collect();
    let heights = (0..n).map(|_| rng.random_range(-0.5e-6..0.5e-6)).collect();
    let counter = (0..n).map(|_| rng.random_range(-0.5e-6..0.5e-6)).collect();
    let bed = RodBed::new(w, centers, heights, 10e-6, 68.65e9, 276e6).unwrap();
    (bed, counter)
}

#[test]
fn exact_sweep_matches_dense_reference() {
    let mut rng = ChaCha8Rng::seed_from_u64(6);
    let mut worst_b: f64 = 0.0;
    let mut worst_f: f64 = 0.0;
    for case in 0..40 {
        let n = 5 + case % 50;
        let (bed, g) = random_bed(&mut rng, n);
        let s = bed.state();
        let cap = bed.capacity();
        let p = cap * rng.random_range(0.001..0.999);
        let sweep = RodOptions {
            warm_start: false,
            ..RodOptions::default()
        };
        let dense = RodOptions {
            solver: RodSolver::Dense,
            ..sweep
        };
        let (r1, o1, n1) = load(&bed, &s, &g, p, &sweep);
        let (r2, o2, n2) = load(&bed, &s, &g, p, &dense);
        // Lengths relative to the height range (1 µm), forces to F_y.
        let db = (r1.position - r2.position).abs() / 1e-6;
        assert!(
            db < 1e-12,
            "case {case}: b {} vs {}",
            r1.position,
            r2.position
        );
        worst_b = worst_b.max(db);
        for i in 0..n {
            let df = (o1.forces()[i] - o2.forces()[i]).abs() / bed.yield_force();
            assert!(df < 1e-12, "case {case} rod {i}");
            worst_f = worst_f.max(df);
            assert!((n1.heights[i] - n2.heights[i]).abs() < 1e-12 * 1e-6);
        }
        assert!(r1.residual <= 1e-12 * p && r2.residual <= 1e-12 * p);
        assert!((r1.total_force - p).abs() <= 1e-12 * p);

        // Fixed gap with an elastic bulk, (6-12): b₀ anywhere in the range.
        let bed = bed
            .with_bulk_stiffness(1e5 * rng.random_range(0.1..10.0))
            .unwrap();
        let b0 = rng.random_range(-2e-6..1e-6);
        let mut out = bed.solution();
        let mut new = s.clone();
        let r1 = bed
            .solve(
                &s,
                &mut new,
                &g,
                Loading::FixedGap { position: b0 },
                &sweep,
                &mut out,
            )
            .unwrap();
        let r2 = bed
            .solve(
                &s,
                &mut new,
                &g,
                Loading::FixedGap { position: b0 },
                &dense,
                &mut out,
            )
            .unwrap();
        assert!(
            (r1.position - r2.position).abs() < 1e-12 * 1e-6,
            "gap case {case}"
        );
        assert!((r1.total_force - r2.total_force).abs() < 1e-12 * bed.capacity());
    }
    eprintln!("sweep vs dense: worst |Δb|/1µm = {worst_b:.2e}, |Δf|/F_y = {worst_f:.2e}");
}

#[test]
fn total_force_monotone_in_position() {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let (bed, g) = random_bed(&mut rng, 60);
    let s = bed.state();
    let mut prev = -1.0;
    for j in 0..=4000 {
        let b = 1.5e-6 - j as f64 * 1e-9;
        let f = bed.total_force(&s, &g, b).unwrap();
        assert!(f >= prev, "F not nondecreasing as b falls at b = {b}");
        assert!(f <= bed.capacity() * (1.0 + 1e-15));
        prev = f;
    }
    assert!((prev / bed.capacity() - 1.0).abs() < 1e-15);
}

fn volume_check(rule: PlasticUpdate) {
    let mut rng = ChaCha8Rng::seed_from_u64(8);
    for _ in 0..10 {
        let (bed, g) = random_bed(&mut rng, 90);
        let o = RodOptions {
            plastic: rule,
            ..RodOptions::default()
        };
        let mut s = bed.state();
        let mut yielded = 0;
        // Slide a few steps under a high load: yields accumulate.
        for step in 0..5 {
            let gs: Vec<f64> = g.iter().cycle().skip(step).take(g.len()).copied().collect();
            let before: f64 = s.heights.iter().sum();
            let (r, out, new) = load(&bed, &s, &gs, 0.6 * bed.capacity(), &o);
            let after: f64 = new.heights.iter().sum();
            let scale: f64 = s.heights.iter().map(|h| h.abs()).sum::<f64>() + r.plastic_volume;
            assert!(
                (after - before).abs() <= 1e-14 * scale,
                "{rule:?}: volume change {:e} (moved {:e})",
                after - before,
                r.plastic_volume / bed.area()
            );
            // Yielded rods got shorter; plastic work = F_y Σ s.
            let sum_s: f64 = out.plastic_shortening().iter().sum();
            assert!((r.plastic_work - bed.yield_force() * sum_s).abs() <= 1e-12 * r.plastic_work);
            yielded += r.yielded;
            s = new;
        }
        assert!(yielded > 0);
    }
}

#[test]
fn volume_conserved_nearest_neighbours() {
    volume_check(PlasticUpdate::NearestNeighbours);
}

#[test]
fn volume_conserved_gaussian() {
    volume_check(PlasticUpdate::Gaussian { width: 3e-6 });
    // A width far below the pitch degenerates to the nearest rod(s).
    volume_check(PlasticUpdate::Gaussian { width: 1e-9 });
}

#[test]
fn shorten_only_loses_volume() {
    let bed = hand_bed(2);
    let o = RodOptions {
        plastic: PlasticUpdate::ShortenOnly,
        ..RodOptions::default()
    };
    let (r, _, new) = load(&bed, &bed.state(), &[1e-6, 0.0], 19.5, &o);
    assert!(r.plastic_volume > 0.0);
    assert_eq!(new.heights[1], 0.0);
    assert!(new.heights[0] < 0.0);
}

#[test]
fn nearest_neighbours_split_halves() {
    // Five rods, middle one highest: it yields, its neighbours get s/2 each.
    let bed = hand_bed(5);
    let g = [0.0, 0.0, 2e-5, 0.0, 0.0];
    let (r, out, new) = load(&bed, &bed.state(), &g, 10.0 + 4.0, &RodOptions::default());
    assert_eq!(r.yielded, 1);
    let s = out.plastic_shortening()[2];
    assert!(s > 0.0);
    assert!(close(new.heights[1], s / 2.0, 1e-22) && close(new.heights[3], s / 2.0, 1e-22));
    assert_eq!((new.heights[0], new.heights[4]), (0.0, 0.0));
}

#[test]
fn warm_start_matches_cold() {
    let mut rng = ChaCha8Rng::seed_from_u64(9);
    let (bed, g) = random_bed(&mut rng, 200);
    let cold = RodOptions {
        warm_start: false,
        ..RodOptions::default()
    };
    let warm = RodOptions::default();
    let mut s_cold = bed.state();
    let mut s_warm = bed.state();
    let mut out = bed.solution();
    let mut tmp = bed.state();
    let mut warm_hits = 0;
    for step in 0..40 {
        // The counter-surface slides by one rod every 10 steps and the load
        // wanders: small changes, as in a sliding simulation.
        let shift = step / 10;
        let gs: Vec<f64> = g
            .iter()
            .cycle()
            .skip(shift)
            .take(g.len())
            .copied()
            .collect();
        let p = bed.capacity() * (0.3 + 0.05 * ((step as f64) * 0.7).sin());
        let rc = bed
            .solve(
                &s_cold,
                &mut tmp,
                &gs,
                Loading::FixedLoad { load: p },
                &cold,
                &mut out,
            )
            .unwrap();
        std::mem::swap(&mut s_cold, &mut tmp);
        let fc = out.forces().to_vec();
        let rw = bed
            .solve(
                &s_warm,
                &mut tmp,
                &gs,
                Loading::FixedLoad { load: p },
                &warm,
                &mut out,
            )
            .unwrap();
        std::mem::swap(&mut s_warm, &mut tmp);
        if rw.warm_started {
            warm_hits += 1;
        }
        assert!(
            (rc.position - rw.position).abs() <= 1e-12 * 1e-6,
            "step {step}: {} vs {}",
            rc.position,
            rw.position
        );
        for (a, b) in fc.iter().zip(out.forces()) {
            assert!((a - b).abs() <= 1e-12 * bed.yield_force());
        }
        for (a, b) in s_cold.heights.iter().zip(&s_warm.heights) {
            assert!((a - b).abs() <= 1e-12 * 1e-6);
        }
    }
    assert!(warm_hits >= 30, "warm start used in {warm_hits}/40 steps");
}

#[test]
fn energies_non_negative_and_release_on_unloading() {
    let mut rng = ChaCha8Rng::seed_from_u64(10);
    let (bed, g) = random_bed(&mut rng, 90);
    let mut s = bed.state();
    let mut out = bed.solution();
    let mut new = bed.state();
    let loads = [0.2, 0.5, 0.1, 0.0, 0.4];
    let mut released_any = false;
    for &f in &loads {
        let r = bed
            .solve(
                &s,
                &mut new,
                &g,
                Loading::FixedLoad {
                    load: f * bed.capacity(),
                },
                &RodOptions::default(),
                &mut out,
            )
            .unwrap();
        assert!(r.plastic_work >= 0.0 && r.elastic_energy >= 0.0 && r.released_energy >= 0.0);
        if r.released_energy > 0.0 {
            released_any = true;
        }
        if f == 0.0 {
            // Full unloading releases everything that was stored.
            let stored_before: f64 = s.energy.iter().sum();
            assert!((r.released_energy - stored_before).abs() <= 1e-12 * stored_before);
            assert_eq!(r.elastic_energy, 0.0);
        }
        std::mem::swap(&mut s, &mut new);
    }
    assert!(released_any);
}

#[test]
fn named_errors() {
    let c = vec![0.0, 1e-3];
    let h = vec![0.0, 0.0];
    let name = |e: Error| match e {
        Error::InvalidArgument { name, .. } => name,
        Error::OutOfDomain { name, .. } => name,
        other => panic!("{other:?}"),
    };
    let new = |w: f64, c: Vec<f64>, h: Vec<f64>, d: f64, e: f64, s: f64| {
        name(RodBed::new(w, c, h, d, e, s).unwrap_err())
    };
    assert_eq!(new(f64::NAN, c.clone(), h.clone(), 1e-3, 1e9, 1e7), "width");
    assert_eq!(new(-1.0, c.clone(), h.clone(), 1e-3, 1e9, 1e7), "width");
    assert_eq!(new(1e-3, c.clone(), h.clone(), 1e-3, -1e9, 1e7), "modulus");
    assert_eq!(
        new(1e-3, c.clone(), h.clone(), 1e-3, 1e9, f64::NAN),
        "yield_stress"
    );
    assert_eq!(
        new(1e-3, c.clone(), h.clone(), 1e-3, 1e9, 2e9),
        "yield_stress"
    );
    assert_eq!(
        new(1e-3, c.clone(), h.clone(), f64::INFINITY, 1e9, 1e7),
        "root_depth"
    );
    assert_eq!(
        new(1e-3, vec![0.0], h.clone(), 1e-3, 1e9, 1e7),
        "centers.len()"
    );
    assert_eq!(new(1e-3, vec![], vec![], 1e-3, 1e9, 1e7), "heights.len()");
    assert_eq!(
        new(1e-3, vec![1.0, 0.0], h.clone(), 1e-3, 1e9, 1e7),
        "centers"
    );
    assert_eq!(
        new(1e-3, c.clone(), vec![0.0, f64::NAN], 1e-3, 1e9, 1e7),
        "heights"
    );
    assert_eq!(
        new(1e-3, c.clone(), vec![0.0, -2e-3], 1e-3, 1e9, 1e7),
        "heights"
    );
    assert_eq!(
        name(hand_bed(2).with_bulk(1e9, -1.0, 1.0).unwrap_err()),
        "bulk_area"
    );
    assert_eq!(
        name(hand_bed(2).with_bulk_stiffness(f64::NAN).unwrap_err()),
        "bulk_stiffness"
    );

    let bed = hand_bed(2);
    let s = bed.state();
    let o = RodOptions::default();
    let mut out = bed.solution();
    let mut nw = s.clone();
    let g = [0.0, 0.0];
    let mut err = |s: &RodState, g: &[f64], p: f64, o: &RodOptions| {
        name(
            bed.solve(s, &mut nw, g, Loading::FixedLoad { load: p }, o, &mut out)
                .unwrap_err(),
        )
    };
    assert_eq!(err(&s, &g, -1.0, &o), "load");
    assert_eq!(err(&s, &g, f64::NAN, &o), "load");
    assert_eq!(err(&s, &[0.0], 1.0, &o), "counter.len()");
    assert_eq!(err(&s, &[0.0, f64::INFINITY], 1.0, &o), "counter");
    let mut bad = s.clone();
    bad.heights.pop();
    assert_eq!(err(&bad, &g, 1.0, &o), "state.heights.len()");
    let mut bad = s.clone();
    bad.heights[0] = f64::NAN;
    assert_eq!(err(&bad, &g, 1.0, &o), "state.heights");
    let mut bad = s.clone();
    bad.energy[1] = -1.0;
    assert_eq!(err(&bad, &g, 1.0, &o), "state.energy");
    let mut bad = s.clone();
    bad.position = Some(f64::NAN);
    assert_eq!(err(&bad, &g, 1.0, &o), "state.position");
    let go = RodOptions {
        plastic: PlasticUpdate::Gaussian { width: 0.0 },
        ..o
    };
    assert_eq!(err(&s, &g, 1.0, &go), "width");
    let mut small = hand_bed(3).solution();
    assert_eq!(
        name(
            bed.solve(
                &s,
                &mut nw,
                &g,
                Loading::FixedLoad { load: 1.0 },
                &o,
                &mut small
            )
            .unwrap_err()
        ),
        "solution.len()"
    );
    assert_eq!(
        name(
            bed.solve(
                &s,
                &mut nw,
                &g,
                Loading::FixedGap { position: f64::NAN },
                &o,
                &mut out
            )
            .unwrap_err()
        ),
        "position"
    );
    // A fixed gap that would crush a rod through its root.
    assert_eq!(
        name(
            bed.solve(
                &s,
                &mut nw,
                &g,
                Loading::FixedGap { position: -2e-3 },
                &o,
                &mut out
            )
            .unwrap_err()
        ),
        "position"
    );
    assert_eq!(
        name(square_influence(f64::NAN, 0.0, 1.0, 1.0).unwrap_err()),
        "dx"
    );
    assert_eq!(
        name(square_influence(0.0, 0.0, 0.0, 1.0).unwrap_err()),
        "width"
    );
    assert_eq!(
        name(CoupledRodBed::new(hand_bed(2), -1.0).unwrap_err()),
        "contact_modulus"
    );
}

#[test]
fn square_influence_limits() {
    let (w, e) = (1e-6, 1e11);
    // Centre of the loaded square: 4 ln(1+√2)/(π E* w).
    let centre = square_influence(0.0, 0.0, w, e).unwrap();
    let expected = 4.0 * (1.0 + 2f64.sqrt()).ln() / (std::f64::consts::PI * e * w);
    assert!((centre / expected - 1.0).abs() < 1e-14);
    // Far field: 1/(π E* r) (1 + w²/(24 r²)) + O((w/r)⁴).
    for r in [20.0, 100.0, 1000.0] {
        let u = square_influence(r * w, 0.0, w, e).unwrap();
        let far = (1.0 + 1.0 / (24.0 * r * r)) / (std::f64::consts::PI * e * r * w);
        assert!((u / far - 1.0).abs() < 2.0 / r.powi(4), "r = {r}");
    }
    // Closed form and quadrature agree across the switch.
    let sw = asperity::friction::rods::INFLUENCE_QUADRATURE_SWITCH * w;
    // (the offsets differ by 4 ulp; u ∝ 1/r, so 1e-14 is the closed form's
    // own accuracy there).
    let a = square_influence(sw * (1.0 - 2.0 * f64::EPSILON), 0.0, w, e).unwrap();
    let b = square_influence(sw * (1.0 + 2.0 * f64::EPSILON), 0.0, w, e).unwrap();
    assert!((a / b - 1.0).abs() < 1e-14, "{a} {b}");
    // Symmetric in the offset.
    let p = square_influence(2.3 * w, -0.7 * w, w, e).unwrap();
    let q = square_influence(-2.3 * w, 0.7 * w, w, e).unwrap();
    assert!((p / q - 1.0).abs() < 1e-15);
}

#[test]
fn coupled_influence_symmetric_positive_definite() {
    let mut rng = ChaCha8Rng::seed_from_u64(11);
    let (bed, _) = random_bed(&mut rng, 90);
    let cb = CoupledRodBed::new(bed, 68.65e9).unwrap();
    let c = cb.influence();
    for i in 0..c.nrows() {
        for j in 0..c.ncols() {
            assert_eq!(c[(i, j)], c[(j, i)]);
        }
    }
    assert!(Llt::new(c, Side::Lower).is_ok(), "C not positive definite");
}

#[test]
fn coupled_reduces_to_uncoupled_when_stiff() {
    let mut rng = ChaCha8Rng::seed_from_u64(12);
    let (bed, g) = random_bed(&mut rng, 40);
    let s = bed.state();
    let p = 0.4 * bed.capacity();
    let (r0, o0, _) = load(&bed, &s, &g, p, &RodOptions::default());
    let cb = CoupledRodBed::new(bed.clone(), 1e25).unwrap();
    let mut out = bed.solution();
    let mut new = s.clone();
    let r1 = cb
        .solve(
            &s,
            &mut new,
            &g,
            Loading::FixedLoad { load: p },
            &RodOptions::default(),
            &mut out,
        )
        .unwrap();
    assert!((r1.position - r0.position).abs() < 1e-9 * 1e-6);
    for (a, b) in o0.forces().iter().zip(out.forces()) {
        assert!((a - b).abs() < 1e-9 * bed.yield_force());
    }
    assert!(r1.residual < 1e-10 * p);
}

#[test]
fn coupled_gap_and_load_consistent() {
    let mut rng = ChaCha8Rng::seed_from_u64(13);
    let (bed, g) = random_bed(&mut rng, 60);
    let s = bed.state();
    let cb = CoupledRodBed::new(bed.clone(), 68.65e9 / (1.0 - 0.355f64.powi(2))).unwrap();
    let mut out = bed.solution();
    let mut new = s.clone();
    let o = RodOptions::default();
    for frac in [0.05, 0.3, 0.7] {
        let p = frac * bed.capacity();
        let rl = cb
            .solve(
                &s,
                &mut new,
                &g,
                Loading::FixedLoad { load: p },
                &o,
                &mut out,
            )
            .unwrap();
        assert!(rl.residual <= 1e-11 * p, "residual {:e}", rl.residual);
        // Substrate compliance lowers the slider further than the rigid bed.
        let (r0, _, _) = load(&bed, &s, &g, p, &o);
        assert!(rl.position < r0.position);
        // The same position under fixed gap (rigid bulk) carries P.
        let rg = cb
            .solve(
                &s,
                &mut new,
                &g,
                Loading::FixedGap {
                    position: rl.position,
                },
                &o,
                &mut out,
            )
            .unwrap();
        assert!(
            (rg.total_force - p).abs() <= 1e-9 * p,
            "{} vs {p}",
            rg.total_force
        );
        // Box constraints and complementarity.
        let fy = bed.yield_force();
        for i in 0..bed.len() {
            let f = out.forces()[i];
            assert!((0.0..=fy).contains(&f));
            let o = out.overlaps()[i];
            if f == 0.0 {
                assert!(o <= 1e-12 * 1e-6);
            }
        }
        assert!(rl.elastic_energy > 0.0 && rl.released_energy >= 0.0);
    }
    // Zero load: first contact, no force.
    let r = cb
        .solve(
            &s,
            &mut new,
            &g,
            Loading::FixedLoad { load: 0.0 },
            &o,
            &mut out,
        )
        .unwrap();
    assert_eq!(r.total_force, 0.0);
    // Elastic bulk at fixed gap.
    let cbb = CoupledRodBed::new(bed.with_bulk_stiffness(1e6).unwrap(), 1e11).unwrap();
    let r = cbb
        .solve(
            &s,
            &mut new,
            &g,
            Loading::FixedGap { position: -0.5e-6 },
            &o,
            &mut out,
        )
        .unwrap();
    assert!(r.residual <= 1e-9 * r.total_force.max(1e-12));
    assert!(r.bulk_compression >= 0.0);
}
