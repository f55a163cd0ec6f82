//! The in-module tests: overlap thresholds, and the stay range against the
//! full choice of branch and segment.

use super::threshold::{next_up, overlap_threshold};
use super::TabulatedLaw;
use crate::contact::{ContactState, LjSphere, MaugisDugdale, NormalContact};

fn next_down(v: f64) -> f64 {
    -next_up(-v)
}

#[test]
fn next_up_steps_one_ulp() {
    assert_eq!(next_up(0.0), f64::from_bits(1));
    assert_eq!(next_up(-0.0), f64::from_bits(1));
    assert_eq!(next_up(1.0), 1.0 + f64::EPSILON);
    assert_eq!(next_up(-f64::from_bits(1)), -0.0);
    assert_eq!(next_up(f64::MAX), f64::INFINITY);
    assert_eq!(next_up(f64::NEG_INFINITY), -f64::MAX);
    assert_eq!(next_up(f64::INFINITY), f64::INFINITY);
    assert_eq!(next_down(1.0), 1.0 - f64::EPSILON / 2.0);
}

/// The overlap thresholds decide exactly as the reduced approach
/// `(δ − origin)/scale` compared with the bound: true at the threshold,
/// false one double beyond it.
#[test]
fn overlap_thresholds_reproduce_the_reduced_comparisons() {
    let reduced = |o: f64, s: f64, d: f64| (d - o) / s;
    let mut checked = 0;
    for o in [0.0, -3.7e-9, 1e-6, -2.5] {
        for s in [3e-10, 1.7320508075688772e-8, 1.0, 7.3, 1e10] {
            for x in [
                -28.90788462585297,
                -1.6294154310638171,
                -1.7438050853496148,
                0.0,
                1e-300,
                0.1 + 0.2,
                8.902789206157527,
                7.868170735204815e6,
                1e300,
            ] {
                let lo = overlap_threshold(o, s, x, true);
                let hi = overlap_threshold(o, s, x, false);
                if lo.is_finite() {
                    assert!(reduced(o, s, lo) >= x, "{o} {s} {x}");
                    assert!(reduced(o, s, next_down(lo)) < x, "{o} {s} {x}");
                    checked += 1;
                } else {
                    // No finite δ reaches x (x beyond the range).
                    assert_eq!(lo, f64::INFINITY);
                    assert!(reduced(o, s, f64::MAX) < x, "{o} {s} {x}");
                }
                if hi.is_finite() {
                    assert!(reduced(o, s, hi) <= x, "{o} {s} {x}");
                    assert!(reduced(o, s, next_up(hi)) > x, "{o} {s} {x}");
                } else {
                    assert_eq!(hi, f64::INFINITY);
                    assert!(reduced(o, s, f64::MAX) <= x, "{o} {s} {x}");
                }
            }
        }
    }
    assert!(checked > 150);
    assert_eq!(
        overlap_threshold(0.0, 1.0, f64::INFINITY, false),
        f64::INFINITY
    );
    assert_eq!(
        overlap_threshold(0.0, 1.0, f64::NEG_INFINITY, true),
        f64::NEG_INFINITY
    );
}

/// The choice `eval` makes by the rules of the module documentation,
/// without the stay range: the branch after the jumps, and the reduced
/// response on it.
fn full_choice(t: &TabulatedLaw, k: usize, delta: f64) -> (usize, (f64, f64, f64)) {
    let n = t.branches.len();
    let b = &t.branches[k];
    let k = if delta > b.hi_delta {
        (k + 1..n).find(|&j| t.contains(j, delta)).unwrap_or(n - 1)
    } else if delta < b.lo_delta {
        (0..k).rev().find(|&j| t.contains(j, delta)).unwrap_or(0)
    } else {
        k
    };
    (k, t.on_branch(k, delta))
}

/// The stay range is a shortcut only: from every branch, at every
/// threshold of the table and the doubles beside it, and over a sweep,
/// `eval` gives bit for bit the response and the branch of the full
/// choice. The tables cover a widest segment that is not the last
/// (μ = 0.1: linear, then square root), two segments on the contact
/// branch (μ = 1) and a far branch without segments (Maugis–Dugdale).
#[test]
fn stay_range_is_the_full_choice() {
    let (r, w, z0) = (1e-6f64, 0.05f64, 0.3e-9f64);
    let lj = |mu: f64| {
        let e_star = (r * w * w / (mu * mu * mu * z0 * z0 * z0)).sqrt();
        let lj = LjSphere::new(r, e_star, w, z0).unwrap();
        TabulatedLaw::from_lj_sphere(&lj, 128, 1e-4).unwrap()
    };
    let md = MaugisDugdale::from_maugis_parameter(1e-6, 1e9, 0.05, 2.0).unwrap();
    let tables = [
        lj(0.1),
        lj(1.0),
        TabulatedLaw::from_maugis_dugdale(&md, 1e-4).unwrap(),
    ];
    assert_ne!(
        tables[0].branches[0].stay,
        tables[0].branches[0].segments.len() - 1
    );
    let mut checked = 0;
    for t in &tables {
        let mut points = Vec::new();
        for b in &t.branches {
            points.extend([b.lo_delta, b.hi_delta, b.stay_lo, b.stay_hi]);
            for s in &b.segments {
                points.extend([s.start_delta, s.hi_delta]);
            }
        }
        let (lo, hi) = (t.overlap(-30.0), t.overlap(30.0));
        points.extend((0..=3000).map(|i| lo + (hi - lo) * i as f64 / 3000.0));
        let mut all = Vec::new();
        for p in points.into_iter().filter(|p| p.is_finite()) {
            all.extend([next_down(p), p, next_up(p)]);
        }
        for k in 0..t.branches.len() {
            let old = ContactState {
                branch: k as i32,
                ..Default::default()
            };
            for &delta in &all {
                let (kk, (f, a, kbar)) = full_choice(t, k, delta);
                let (resp, state) = t.eval(delta, &old).unwrap();
                let d = &t.data;
                assert_eq!(state.branch, kk as i32, "{} {k} {delta:e}", t.source());
                assert_eq!(resp.force.to_bits(), (f * d.force_scale).to_bits());
                assert_eq!(
                    resp.contact_radius.to_bits(),
                    (a * d.radius_scale).to_bits()
                );
                assert_eq!(
                    resp.stiffness.to_bits(),
                    (kbar * t.stiffness_scale).to_bits()
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 30_000, "{checked}");
}
