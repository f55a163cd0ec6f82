//! The real nano-topography model of Bora et al. (2013), thesis §5.3.9:
//! springs with the measured heights on an elastic half-space. Checked
//! against Kragelsky's independent springs (no substrate), one and two
//! loaded springs in closed form with Love's square compliance, a dense
//! solve of the linear complementarity problem on a pseudo-random map, the
//! stiffness as the load's derivative, the inverse, and named errors.

// Forces, gaps and heights are indexed in lockstep.
#![allow(clippy::needless_range_loop)]

use asperity::friction::square_influence;
use asperity::statistics::BoraTopography;
use asperity::Error;

const K: f64 = 50.0; // N/m per spring
const E_STAR: f64 = 1e9;
const DX: f64 = 10e-9;

/// Deterministic pseudo-random heights in ±amp (a linear congruential
/// generator; no dependency).
fn heights(n: usize, amp: f64, seed: u64) -> Vec<f64> {
    let mut x = seed;
    (0..n)
        .map(|_| {
            x = x
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            amp * (2.0 * ((x >> 11) as f64 / (1u64 << 53) as f64) - 1.0)
        })
        .collect()
}

#[test]
fn without_substrate_it_is_kragelskys_springs() {
    let h = heights(64, 5e-9, 1);
    let m = BoraTopography::new(8, 8, DX, h.clone(), K, None).unwrap();
    for &d in &[-6e-9, -1e-9, 0.0, 2e-9, 4.5e-9, 5e-9] {
        let s = m.solve(d).unwrap();
        let want: f64 = h.iter().map(|x| K * (x - d).max(0.0)).sum();
        let count = h.iter().filter(|&&x| x > d).count();
        assert!(
            (s.load - want).abs() <= 1e-14 * want,
            "d {d}: {} vs {want}",
            s.load
        );
        assert_eq!(s.contacts, count);
        assert_eq!(s.stiffness, K * count as f64);
        assert!((s.area - count as f64 * DX * DX).abs() < 1e-30);
    }
}

#[test]
fn one_and_two_loaded_springs_in_closed_form() {
    // One spring 2 nm above the rest: f = δ/(1/k + C₀₀).
    let mut h = vec![0.0; 25];
    h[12] = 2e-9;
    let m = BoraTopography::new(5, 5, DX, h.clone(), K, Some(E_STAR)).unwrap();
    let c00 = square_influence(0.0, 0.0, DX, E_STAR).unwrap();
    let d = 1e-9;
    let s = m.solve(d).unwrap();
    let want = (h[12] - d) / (1.0 / K + c00);
    assert_eq!(s.contacts, 1);
    assert!((s.load / want - 1.0).abs() < 1e-9, "{} vs {want}", s.load);
    assert!((s.stiffness * (1.0 / K + c00) - 1.0).abs() < 1e-9);
    // Two neighbours at the same height: f = δ/(1/k + C₀₀ + C₀₁) each.
    h[13] = 2e-9;
    let m = BoraTopography::new(5, 5, DX, h, K, Some(E_STAR)).unwrap();
    let c01 = square_influence(DX, 0.0, DX, E_STAR).unwrap();
    let s = m.solve(d).unwrap();
    let want = (2e-9 - d) / (1.0 / K + c00 + c01);
    assert_eq!(s.contacts, 2);
    assert!((s.forces[12] / want - 1.0).abs() < 1e-9 && (s.forces[13] / want - 1.0).abs() < 1e-9);
    // The substrate couples them: each carries less than alone.
    assert!(want < (2e-9 - d) / (1.0 / K + c00));
}

/// Solve `a x = b` (dense, row-major, n × n) by Gaussian elimination with
/// partial pivoting.
fn dense_solve(mut a: Vec<f64>, mut b: Vec<f64>, n: usize) -> Vec<f64> {
    for c in 0..n {
        let p = (c..n)
            .max_by(|&i, &j| a[i * n + c].abs().total_cmp(&a[j * n + c].abs()))
            .unwrap();
        for k in 0..n {
            a.swap(c * n + k, p * n + k);
        }
        b.swap(c, p);
        for r in c + 1..n {
            let f = a[r * n + c] / a[c * n + c];
            for k in c..n {
                a[r * n + k] -= f * a[c * n + k];
            }
            b[r] -= f * b[c];
        }
    }
    let mut x = vec![0.0; n];
    for r in (0..n).rev() {
        let s: f64 = (r + 1..n).map(|k| a[r * n + k] * x[k]).sum();
        x[r] = (b[r] - s) / a[r * n + r];
    }
    x
}

#[test]
fn complementarity_and_the_dense_solution_on_a_random_map() {
    // Stiff springs against a compliant substrate and the reverse.
    for &(k, e) in &[(K, E_STAR), (1e4, 1e9), (1.0, 1e11)] {
        let (nx, ny) = (12, 10);
        let h = heights(nx * ny, 4e-9, 7);
        let m = BoraTopography::new(nx, ny, DX, h.clone(), k, Some(e)).unwrap();
        for &d in &[-2e-9, 0.0, 2e-9] {
            let s = m.solve(d).unwrap();
            let n = nx * ny;
            // Gaps g = d − h + f/k + C f.
            let g: Vec<f64> = (0..n)
                .map(|i| {
                    d - h[i]
                        + s.forces[i] / k
                        + (0..n).map(|j| m.influence(i, j) * s.forces[j]).sum::<f64>()
                })
                .collect();
            for i in 0..n {
                assert!(s.forces[i] >= 0.0);
                if s.forces[i] > 0.0 {
                    assert!(g[i].abs() < 1e-17, "k {k} d {d} i {i}: gap {}", g[i]);
                } else {
                    assert!(g[i] > -1e-17, "k {k} d {d} i {i}: overlap {}", g[i]);
                }
            }
            // The dense solve on the loaded set reproduces the forces.
            let act: Vec<usize> = (0..n).filter(|&i| s.forces[i] > 0.0).collect();
            let na = act.len();
            let mut a = vec![0.0; na * na];
            for (r, &i) in act.iter().enumerate() {
                for (c, &j) in act.iter().enumerate() {
                    a[r * na + c] = m.influence(i, j) + if i == j { 1.0 / k } else { 0.0 };
                }
            }
            let b: Vec<f64> = act.iter().map(|&i| h[i] - d).collect();
            let x = dense_solve(a, b, na);
            for (r, &i) in act.iter().enumerate() {
                assert!(
                    (x[r] / s.forces[i] - 1.0).abs() < 1e-7,
                    "k {k} d {d}: {} vs {}",
                    x[r],
                    s.forces[i]
                );
            }
        }
    }
}

#[test]
fn load_falls_with_separation_stiffness_and_inverse() {
    let h = heights(100, 5e-9, 3);
    let m = BoraTopography::new(10, 10, DX, h.clone(), K, Some(E_STAR)).unwrap();
    let rigid = BoraTopography::new(10, 10, DX, h, K, None).unwrap();
    let mut last = f64::INFINITY;
    for i in 0..=20 {
        let d = -5e-9 + 0.5e-9 * i as f64;
        let s = m.solve(d).unwrap();
        assert!(s.load.is_finite() && s.load <= last, "d {d}");
        // The substrate adds compliance in series: less load than rigid.
        assert!(s.load <= rigid.solve(d).unwrap().load * (1.0 + 1e-12));
        last = s.load;
    }
    for &d in &[-2e-9, 1e-9] {
        let s = m.solve(d).unwrap();
        let step = 1e-13;
        let fd =
            -(m.solve(d + step).unwrap().load - m.solve(d - step).unwrap().load) / (2.0 * step);
        assert!(
            (fd / s.stiffness - 1.0).abs() < 1e-5,
            "d {d}: {fd} vs {}",
            s.stiffness
        );
        let sol = m.separation_at_load(s.load).unwrap();
        assert!((sol.separation - d).abs() < 1e-6 * 5e-9, "{sol:?}");
    }
}

#[test]
fn errors_name_the_argument() {
    let name = |r: Result<BoraTopography, Error>| match r {
        Err(Error::InvalidArgument { name, .. }) => name,
        other => panic!("{other:?}"),
    };
    assert_eq!(name(BoraTopography::new(0, 3, DX, vec![], K, None)), "nx");
    assert_eq!(
        name(BoraTopography::new(2, 2, DX, vec![0.0; 3], K, None)),
        "heights"
    );
    assert_eq!(
        name(BoraTopography::new(2, 1, DX, vec![0.0, f64::NAN], K, None)),
        "heights"
    );
    assert_eq!(
        name(BoraTopography::new(2, 1, -DX, vec![0.0; 2], K, None)),
        "spacing"
    );
    assert_eq!(
        name(BoraTopography::new(2, 1, DX, vec![0.0; 2], 0.0, None)),
        "spring_stiffness"
    );
    assert_eq!(
        name(BoraTopography::new(2, 1, DX, vec![0.0; 2], K, Some(-1.0))),
        "contact_modulus"
    );
    let m = BoraTopography::new(2, 1, DX, vec![0.0, 1e-9], K, Some(E_STAR)).unwrap();
    assert!(matches!(
        m.solve(f64::INFINITY),
        Err(Error::InvalidArgument {
            name: "separation",
            ..
        })
    ));
    assert!(matches!(
        m.separation_at_load(-1.0),
        Err(Error::InvalidArgument { name: "load", .. })
    ));
    // Above every spring: nothing touches.
    let s = m.solve(2e-9).unwrap();
    assert_eq!((s.load, s.contacts, s.stiffness), (0.0, 0, 0.0));
}
