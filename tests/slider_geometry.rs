//! Slider geometry (thesis 5.6.1, 6.2.1): rods by (6-1) on a piecewise-linear
//! profile, nested levels, the nano-asperities of a square-wave profile
//! (exact) and of a sine (closed forms), the hand calculation of thesis 4.4
//! built from numbers, serde, every bad input, and the measured profiles of
//! `../shared/data/profiles` (skipped, through `common::skip`, when absent: a
//! printed reason, and a failure under `ASPERITY_REQUIRE_ALL=1`; print with
//! `cargo test --test slider_geometry -- --nocapture`).
//!
//! Expected values are computed by hand in the comments, never taken from
//! the code.

use asperity::error::Error;
use asperity::friction::*;
use asperity::surface::{Form, MapForm, Profile, Spacing, Topography};
use std::f64::consts::{PI, SQRT_2};
use std::path::PathBuf;

#[allow(dead_code)]
mod common;

const NM: f64 = 1e-9;
const UM: f64 = 1e-6;

fn rel(a: f64, b: f64) -> f64 {
    if b == 0.0 {
        a.abs()
    } else {
        ((a - b) / b).abs()
    }
}

#[track_caller]
fn close(a: f64, b: f64, tol: f64) {
    assert!(
        rel(a, b) <= tol,
        "{a:e} vs expected {b:e} (rel {:e})",
        rel(a, b)
    );
}

#[track_caller]
fn all_close(a: &[f64], b: &[f64], abs: f64) {
    assert_eq!(a.len(), b.len(), "{a:?} vs {b:?}");
    for (x, y) in a.iter().zip(b) {
        assert!((x - y).abs() <= abs, "{a:?} vs expected {b:?}");
    }
}

#[track_caller]
fn invalid<T: std::fmt::Debug>(r: asperity::Result<T>, expect: &str) {
    match r {
        Err(Error::InvalidArgument { name, .. }) if name == expect => {
            let msg = r.unwrap_err().to_string();
            assert!(msg.contains(expect), "{msg}");
        }
        other => panic!("expected InvalidArgument `{expect}`, got {other:?}"),
    }
}

#[track_caller]
fn out_of_domain<T: std::fmt::Debug>(r: asperity::Result<T>, expect: &str) {
    match r {
        Err(Error::OutOfDomain { name, .. }) if name == expect => {}
        other => panic!("expected OutOfDomain `{expect}`, got {other:?}"),
    }
}

/// Piecewise-linear micro profile, dx = 1 µm, extent 9 µm, heights (nm)
/// 1, 3, −1, 5, 0, 2, 4, −2, 1, 3: sum 16, mean line 1.6 nm.
fn micro() -> Vec<f64> {
    [1.0, 3.0, -1.0, 5.0, 0.0, 2.0, 4.0, -2.0, 1.0, 3.0]
        .iter()
        .map(|h| h * NM)
        .collect()
}

/// Square-ish nano profile: 4 periods of (3, 3, 1, 1, −2, −2, −2, −2) nm at
/// dx = 10 nm (mean 0, Rq = √(36/8) = √4.5 nm).
fn square() -> Vec<f64> {
    let period = [3.0, 3.0, 1.0, 1.0, -2.0, -2.0, -2.0, -2.0];
    (0..32).map(|j| period[j % 8] * NM).collect()
}
const SQ_DX: f64 = 10.0 * NM;

/// A sine of amplitude 5 nm, 8 periods of 256 samples at dx = 1.25 nm
/// (Λ = 320 nm), sampled half a step off the zeros.
fn sine() -> (Vec<f64>, f64, f64, f64) {
    let (a, p, dx) = (5.0 * NM, 256usize, 1.25 * NM);
    let h = (0..8 * p)
        .map(|j| a * (2.0 * PI * (j as f64 + 0.5) / p as f64).sin())
        .collect();
    (h, dx, a, p as f64 * dx)
}

// ------------------------------------------------------------------ (6-1)

#[test]
fn rod_heights_are_the_mean_of_their_two_sides() {
    // w = 2.5 µm: ⌊9/2.5⌋ = 3 rods, sides at 0, 2.5, 5, 7.5 µm.
    // z(0) = 1; z(2.5) = −1 + 0.5·(5 − (−1)) = 2; z(5) = 2;
    // z(7.5) = −2 + 0.5·(1 − (−2)) = −0.5.
    // h = (1+2)/2, (2+2)/2, (2−0.5)/2 = 1.5, 2, 0.75; minus 1.6.
    let h = rod_heights(&micro(), UM, 2.5 * UM).unwrap();
    all_close(&h, &[-0.1 * NM, 0.4 * NM, -0.85 * NM], 1e-15 * NM);
    // One rod over the whole extent: (z(0) + z(9))/2 − 1.6 = 2 − 1.6.
    let h = rod_heights(&micro(), UM, 9.0 * UM).unwrap();
    all_close(&h, &[0.4 * NM], 1e-15 * NM);
    // Rods narrower than dx: w = 0.25 µm, 36 rods; rod 1 spans 0.25–0.5 µm:
    // z = 1 + 0.25·2 = 1.5 and 1 + 0.5·2 = 2 → 1.75 − 1.6 = 0.15.
    let h = rod_heights(&micro(), UM, 0.25 * UM).unwrap();
    assert_eq!(h.len(), 36);
    assert!((h[1] - 0.15 * NM).abs() < 1e-15 * NM);
    // The rods of a constant profile are at the mean line.
    let h = rod_heights(&[7.0; 5], 1.0, 1.0).unwrap();
    assert_eq!(h, vec![0.0; 4]);
}

#[test]
fn levels_nest_inside_their_parents() {
    // Widths 5, 2.5, 1.25 µm: ⌊9/5⌋ = 1 rod, then 2, then 4 (not ⌊9/2.5⌋ = 3:
    // the finer levels tile the coarse rods only).
    // Level 2 sides at 0, 1.25, 2.5, 3.75, 5: z = 1, 3 + 0.25·(−4) = 2, 2,
    // 5 + 0.75·(0 − 5) = 1.25, 2 → h = 1.5, 2, 1.625, 1.625, minus 1.6.
    let levels = rod_levels(&micro(), UM, &[5.0 * UM, 2.5 * UM, 1.25 * UM]).unwrap();
    assert_eq!(levels.len(), 3);
    all_close(levels[0].heights(), &[-0.1 * NM], 1e-15 * NM);
    all_close(levels[1].heights(), &[-0.1 * NM, 0.4 * NM], 1e-15 * NM);
    all_close(
        levels[2].heights(),
        &[-0.1 * NM, 0.4 * NM, 0.025 * NM, 0.025 * NM],
        1e-15 * NM,
    );
    assert_eq!(levels[2].width(), 1.25 * UM);
    assert_eq!(levels[2].left(3), 3.75 * UM);
    assert_eq!(levels[1].center(1), 3.75 * UM);
    // The thesis's two discretisations nest: 13.5 µm = 9 × 1.5 µm.
    let long: Vec<f64> = (0..400).map(|j| (j as f64 * 0.37).sin() * NM).collect();
    let l = rod_levels(&long, 0.5 * UM, &[13.5 * UM, 1.5 * UM]).unwrap();
    // ⌊199.5/13.5⌋ = 14 rods, 14·9 = 126.
    assert_eq!((l[0].len(), l[1].len()), (14, 126));
}

#[test]
fn widths_that_do_not_nest_are_rejected() {
    let m = micro();
    invalid(rod_levels(&m, UM, &[5.0 * UM, 2.0 * UM]), "rod_widths");
    invalid(rod_levels(&m, UM, &[5.0 * UM, 5.0 * UM]), "rod_widths");
    invalid(rod_levels(&m, UM, &[2.5 * UM, 5.0 * UM]), "rod_widths");
    invalid(
        rod_levels(&m, UM, &[4.0 * UM, 2.0 * UM, 0.3 * UM]),
        "rod_widths",
    );
    match rod_levels(&m, UM, &[5.0 * UM, 2.0 * UM]) {
        Err(Error::InvalidArgument { value, bound, .. }) => {
            assert_eq!(value, 2.0 * UM);
            assert!(bound.contains("nested"), "{bound}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn bad_rod_widths_and_profiles() {
    let m = micro();
    invalid(rod_levels(&m, UM, &[]), "rod_widths.len()");
    for w in [0.0, -UM, f64::NAN, f64::INFINITY] {
        invalid(rod_levels(&m, UM, &[w]), "rod_widths");
        invalid(rod_levels(&m, UM, &[5.0 * UM, w]), "rod_widths");
    }
    // Longer than the sampled extent (n − 1)·dx = 9 µm.
    invalid(rod_levels(&m, UM, &[9.01 * UM]), "rod_widths");
    invalid(rod_heights(&[], UM, UM), "heights.len()");
    invalid(rod_heights(&[1.0], UM, UM), "heights.len()");
    invalid(rod_heights(&[1.0, f64::NAN, 2.0], UM, UM), "heights");
    for dx in [0.0, -1.0, f64::NAN] {
        invalid(rod_heights(&m, dx, UM), "dx");
    }
}

// ------------------------------------------------- nano-asperities, exact

#[test]
fn square_profile_nano_asperities_by_hand() {
    let a = nano_analysis(&square(), SQ_DX).unwrap();
    let h = 4.5f64.sqrt(); // nm
                           // (5-15): Rq = √((4·9 + 4·1 + 16·4... per period 9+9+1+1+4·4 = 36)/8).
    close(a.asperities.h_vdw, h * NM, 1e-12);
    // Crossings: 4 down (1 → −2) and 3 up (−2 → 3): c = 7, n_mean = 4.
    assert_eq!(a.n_mean, 4);
    // A_vdW per period: 2·h (the 3s, clamped) + 2·1 (the 1s), times dx.
    close(a.area_vdw, 4.0 * (2.0 * h + 2.0) * NM * SQ_DX, 1e-12);
    // (6-2): w_vdW = A_vdW/(h·4) = dx·(2 + 2/h).
    close(a.asperities.w_vdw, SQ_DX * (2.0 + 2.0 / h), 1e-12);
    // h_chem: mean of 3 − h over the eight samples above h.
    close(a.asperities.h_chem, (3.0 - h) * NM, 1e-12);
    close(a.area_chem, 8.0 * (3.0 - h) * NM * SQ_DX, 1e-12);
    // w_chem = A_chem/(h_chem·4) = 8·dx/4.
    close(a.asperities.w_chem, 2.0 * SQ_DX, 1e-12);
    // (6-3): λ = 32·dx/4.
    close(a.asperities.spacing, 8.0 * SQ_DX, 1e-12);
    close(a.length, 32.0 * SQ_DX, 1e-15);
    close(a.length_above_rms, 8.0 * SQ_DX, 1e-15);
    close(a.asperities.height(), 3.0 * NM, 1e-12);
    // (5-16, 5-17): runs above h; the first is cut by the start, so 3.
    // Up-crossing between −2 and 3 at (h + 2)/5 of the step, down-crossing
    // between 3 and 1 at (3 − h)/2: d = dx·(2 + (3 − h)/2 − (h + 2)/5).
    let s = a.statistics;
    assert_eq!(s.asperities_at_rq, 3);
    close(
        s.mean_width.unwrap(),
        SQ_DX * (2.0 + (3.0 - h) / 2.0 - (h + 2.0) / 5.0),
        1e-12,
    );
    close(s.rq, h * NM, 1e-12);
}

#[test]
fn sine_nano_asperities_and_5_6_1_statistics() {
    let (h, dx, a, lambda) = sine();
    let r = nano_analysis(&h, dx).unwrap();
    let s = r.statistics;
    // Rq = A/√2 (exact for whole periods), Δq = √2·πA/Λ, so λ_a = Λ (5-18).
    close(s.rq, a / SQRT_2, 1e-12);
    close(s.rdq, SQRT_2 * PI * a / lambda, 2e-3);
    close(s.spacing, lambda, 2e-3);
    // Width at the Rq level: sin θ > 1/√2 on (π/4, 3π/4), Λ/4; 8 of them.
    assert_eq!(s.asperities_at_rq, 8);
    close(s.mean_width.unwrap(), lambda / 4.0, 1e-3);
    // Mean-line crossings: n_mean = 8 periods, λ = L/8 = Λ (6-3).
    assert_eq!(r.n_mean, 8);
    close(r.asperities.spacing, lambda, 1e-12);
    // (6-2): A_vdW per period = (Λ/2π)·A·(2(1 − 1/√2) + π/(2√2)), so
    // w_vdW = (Λ/2π)(2√2 − 2 + π/2).
    close(
        r.asperities.w_vdw,
        lambda / (2.0 * PI) * (2.0 * SQRT_2 - 2.0 + PI / 2.0),
        1e-3,
    );
    // h_chem = (2/π)∫_{π/4}^{3π/4} sin θ dθ − 1/√2 = (2√2/π − 1/√2)·A.
    close(
        r.asperities.h_chem,
        (2.0 * SQRT_2 / PI - 1.0 / SQRT_2) * a,
        2e-3,
    );
    // w_chem = (length above Rq)/n_mean: samples j + 0.5 ∈ (32, 96) of each
    // 256, i.e. 64 per period: exactly Λ/4.
    close(r.asperities.w_chem, lambda / 4.0, 1e-12);
    assert!(r.asperities.w_chem <= r.asperities.w_vdw);
    assert!(r.asperities.w_vdw <= r.asperities.spacing);
    // The plain statistics function agrees with the record.
    assert_eq!(asperity_statistics(&h, dx).unwrap(), s);
}

#[test]
fn valleys_only_profile_has_no_chemical_tip() {
    // Mean 0: seven samples at +1, one at −7 per period; Rq = √((7 + 49)/8)
    // = √7 > 1, so nothing lies above the van der Waals slab.
    let p: Vec<f64> = (0..32)
        .map(|j| if j % 8 == 7 { -7.0 * NM } else { NM })
        .collect();
    let r = nano_analysis(&p, SQ_DX).unwrap();
    close(r.asperities.h_vdw, 7f64.sqrt() * NM, 1e-12);
    assert_eq!(r.asperities.h_chem, 0.0);
    assert_eq!(r.asperities.w_chem, 0.0);
    // A_vdW = 28 samples at 1 nm; 7 crossings → n_mean 4.
    assert_eq!(r.n_mean, 4);
    close(
        r.asperities.w_vdw,
        28.0 * NM * SQ_DX / (7f64.sqrt() * NM * 4.0),
        1e-12,
    );
    assert_eq!(r.statistics.mean_width, None);
    assert_eq!(r.statistics.asperities_at_rq, 0);
}

#[test]
fn nano_asperities_per_rod_tip() {
    // Thesis 4.4: 100 on a 13.5 µm tip ↔ 10 × 10 at 1.35 µm.
    assert_eq!(nano_per_rod(13.5 * UM, 1.35 * UM).unwrap(), 100);
    // ⌊13.5/1.4⌋ = 9 → 81.
    assert_eq!(nano_per_rod(13.5 * UM, 1.4 * UM).unwrap(), 81);
    assert_eq!(nano_per_rod(1.5 * UM, 1.5 * UM).unwrap(), 1);
    out_of_domain(nano_per_rod(1.0 * UM, 1.35 * UM), "tip_width");
    invalid(nano_per_rod(0.0, 1.0), "tip_width");
    invalid(nano_per_rod(1.0, f64::NAN), "spacing");
}

// ------------------------------------------------------------- the slider

#[test]
fn slider_from_synthetic_profiles() {
    let g =
        SliderGeometry::from_slices(&micro(), UM, &[5.0 * UM, 2.5 * UM], &square(), SQ_DX).unwrap();
    assert_eq!(g.levels().len(), 2);
    all_close(g.levels()[0].heights(), &[-0.1 * NM], 1e-15 * NM);
    all_close(g.tips().heights(), &[-0.1 * NM, 0.4 * NM], 1e-15 * NM);
    assert_eq!(g.branching(0), Some(2));
    assert_eq!(g.branching(1), None);
    // λ = 80 nm: ⌊2.5 µm / 80 nm⌋ = 31 per side, 961 per tip, 2 tips.
    assert_eq!(g.nano_per_rod(), 961);
    assert_eq!(g.nano_total(), 2 * 961);
    close(g.nano().spacing, 80.0 * NM, 1e-12);
    close(g.nano().w_chem, 20.0 * NM, 1e-12);
    // Micro statistics: Z = h − 1.6, Σ Z² = 44.4 nm² over 10 samples.
    close(g.micro_statistics().unwrap().rq, 4.44f64.sqrt() * NM, 1e-12);
    assert_eq!(g.nano_analysis().unwrap().n_mean, 4);
    // The same through Profiles, with the micro profile's origin.
    let x0 = 8.6722e-3;
    let mp = Profile::new(UM, micro()).unwrap().with_origin(x0).unwrap();
    let np = Profile::new(SQ_DX, square()).unwrap();
    let gp = SliderGeometry::from_profiles(&mp, &[5.0 * UM, 2.5 * UM], &np).unwrap();
    assert_eq!(gp.tips().heights(), g.tips().heights());
    assert_eq!(gp.nano(), g.nano());
    assert_eq!(gp.tips().origin(), x0);
    assert_eq!(gp.tips().left(1), x0 + 2.5 * UM);
}

/// The hand calculation of thesis 4.4 (REFERENCE.md §5): one 13.5 µm square
/// micro-asperity carrying N = 100 nano-asperities with w_vdW = 430 nm and
/// w_chem = 161 nm. The thesis does not give the spacing (1.35 µm puts 10 × 10
/// on the tip) nor the split of the 8.2 nm nano-asperity height of its Figure
/// 6-12 into body and tip (4.1 + 4.1 nm here, for illustration).
fn hand_calculation_nano() -> NanoAsperities {
    NanoAsperities {
        h_vdw: 4.1 * NM,
        w_vdw: 430.0 * NM,
        h_chem: 4.1 * NM,
        w_chem: 161.0 * NM,
        spacing: 1.35 * UM,
    }
}

#[test]
fn slider_from_numbers_hand_calculation() {
    let nano = hand_calculation_nano();
    let g = SliderGeometry::uniform(13.5 * UM, 1, nano, 100).unwrap();
    assert_eq!(g.nano_total(), 100);
    assert_eq!(g.tips().width(), 13.5 * UM);
    assert_eq!(g.tips().heights(), &[0.0]);
    assert_eq!(g.nano().w_chem, 161.0 * NM);
    assert_eq!(g.nano().w_vdw, 430.0 * NM);
    close(g.nano().height(), 8.2 * NM, 1e-12);
    assert!(g.micro_statistics().is_none() && g.nano_analysis().is_none());
    // Chapter 6: 10 rods of 13.5 µm, or the same split into 90 rods of 1.5 µm.
    let g10 = SliderGeometry::uniform(13.5 * UM, 10, nano, 100).unwrap();
    assert_eq!(g10.nano_total(), 1000);
    let fine = NanoAsperities {
        spacing: 1.5 * UM,
        ..nano
    };
    let coarse = RodLevel::new(13.5 * UM, 0.0, vec![0.0; 10]).unwrap();
    let g2 = SliderGeometry::new(
        vec![
            coarse.clone(),
            RodLevel::new(1.5 * UM, 0.0, vec![0.0; 90]).unwrap(),
        ],
        fine,
        1,
    )
    .unwrap();
    assert_eq!(g2.branching(0), Some(9));
    // Too many per tip: 101·1.35² > 13.5²; 100 at 1.4 µm does not fit either.
    invalid(
        SliderGeometry::uniform(13.5 * UM, 1, nano, 101),
        "nano_per_rod",
    );
    invalid(
        SliderGeometry::uniform(13.5 * UM, 1, nano, 0),
        "nano_per_rod",
    );
    invalid(
        SliderGeometry::uniform(
            13.5 * UM,
            1,
            NanoAsperities {
                spacing: 1.4 * UM,
                ..nano
            },
            100,
        ),
        "nano_per_rod",
    );
    invalid(SliderGeometry::uniform(0.0, 1, nano, 1), "rod_width");
    invalid(SliderGeometry::uniform(f64::NAN, 1, nano, 1), "rod_width");
    invalid(SliderGeometry::uniform(13.5 * UM, 0, nano, 1), "rods");
    // Invalid nano-asperities, one field at a time.
    let bad = |f: fn(&mut NanoAsperities)| {
        let mut n = nano;
        f(&mut n);
        SliderGeometry::uniform(13.5 * UM, 1, n, 100)
    };
    invalid(bad(|n| n.h_vdw = 0.0), "h_vdw");
    invalid(bad(|n| n.w_vdw = -1.0), "w_vdw");
    invalid(bad(|n| n.h_chem = -1e-9), "h_chem");
    invalid(bad(|n| n.h_chem = f64::INFINITY), "h_chem");
    invalid(bad(|n| n.w_chem = 431e-9), "w_chem");
    invalid(bad(|n| n.w_chem = f64::NAN), "w_chem");
    invalid(bad(|n| n.spacing = 429e-9), "spacing");
    // Levels that do not nest: wrong count, wrong ratio, shifted origin.
    let lv = |w: f64, o: f64, n: usize| RodLevel::new(w, o, vec![0.0; n]).unwrap();
    invalid(
        SliderGeometry::new(vec![coarse.clone(), lv(1.5 * UM, 0.0, 89)], fine, 1),
        "levels",
    );
    invalid(
        SliderGeometry::new(vec![coarse.clone(), lv(2.0 * UM, 0.0, 67)], fine, 1),
        "levels",
    );
    invalid(
        SliderGeometry::new(vec![coarse, lv(1.5 * UM, 0.1 * UM, 90)], fine, 1),
        "levels",
    );
    invalid(SliderGeometry::new(vec![], fine, 1), "levels.len()");
    invalid(RodLevel::new(1.0, f64::NAN, vec![0.0]), "origin");
    invalid(RodLevel::new(1.0, 0.0, vec![f64::NAN]), "heights");
}

#[test]
fn bad_profiles_name_their_argument() {
    let (m, n, w) = (micro(), square(), [5.0 * UM]);
    let build = SliderGeometry::from_slices;
    invalid(build(&[], UM, &w, &n, SQ_DX), "micro_heights.len()");
    invalid(build(&m[..7], UM, &w, &n, SQ_DX), "micro_heights.len()");
    invalid(build(&m, UM, &w, &[], SQ_DX), "nano_heights.len()");
    invalid(build(&m, UM, &w, &n[..7], SQ_DX), "nano_heights.len()");
    let mut bad = m.clone();
    bad[3] = f64::NAN;
    invalid(build(&bad, UM, &w, &n, SQ_DX), "micro_heights");
    let mut bad = n.clone();
    bad[30] = f64::NEG_INFINITY;
    invalid(build(&m, UM, &w, &bad, SQ_DX), "nano_heights");
    for dx in [0.0, -UM, f64::NAN, f64::INFINITY] {
        invalid(build(&m, dx, &w, &n, SQ_DX), "micro_dx");
        invalid(build(&m, UM, &w, &n, dx), "nano_dx");
    }
    invalid(build(&m, UM, &[], &n, SQ_DX), "rod_widths.len()");
    invalid(build(&m, UM, &[0.0], &n, SQ_DX), "rod_widths");
    invalid(build(&m, UM, &[10.0 * UM], &n, SQ_DX), "rod_widths");
    invalid(
        build(&m, UM, &[5.0 * UM, 3.0 * UM], &n, SQ_DX),
        "rod_widths",
    );
    // Constant profiles have no asperities (Rq = 0).
    out_of_domain(build(&[1.0; 10], UM, &w, &n, SQ_DX), "micro_heights");
    out_of_domain(build(&m, UM, &w, &[2.0 * NM; 16], SQ_DX), "nano_heights");
    // Finest rods (50 nm) narrower than the nano spacing (80 nm).
    out_of_domain(build(&m, UM, &[50.0 * NM], &n, SQ_DX), "rod_widths");
    // The standalone functions use the plain names.
    invalid(nano_analysis(&n[..7], SQ_DX), "heights.len()");
    invalid(asperity_statistics(&n, -1.0), "dx");
    out_of_domain(asperity_statistics(&[0.0; 8], 1.0), "heights");
}

#[test]
fn serde_round_trip_and_validation_on_load() {
    let g =
        SliderGeometry::from_slices(&micro(), UM, &[5.0 * UM, 2.5 * UM], &square(), SQ_DX).unwrap();
    let json = g.to_json();
    assert_eq!(SliderGeometry::from_json(&json).unwrap(), g);
    let via_serde: SliderGeometry = serde_json::from_str(&json).unwrap();
    assert_eq!(via_serde, g);
    let h = SliderGeometry::uniform(13.5 * UM, 1, hand_calculation_nano(), 100).unwrap();
    assert_eq!(SliderGeometry::from_json(&h.to_json()).unwrap(), h);
    // Tampered records are rejected with the field's error.
    let v: serde_json::Value = serde_json::from_str(&h.to_json()).unwrap();
    let mut t = v.clone();
    t["nano"]["w_chem"] = serde_json::json!(500e-9);
    invalid(SliderGeometry::from_json(&t.to_string()), "w_chem");
    assert!(serde_json::from_str::<SliderGeometry>(&t.to_string()).is_err());
    let mut t = v.clone();
    t["nano_per_rod"] = serde_json::json!(101);
    invalid(SliderGeometry::from_json(&t.to_string()), "nano_per_rod");
    let mut t: serde_json::Value = serde_json::from_str(&json).unwrap();
    t["levels"][1]["width"] = serde_json::json!(2.0e-6);
    invalid(SliderGeometry::from_json(&t.to_string()), "levels");
    let mut t: serde_json::Value = serde_json::from_str(&json).unwrap();
    t["levels"][0]["width"] = serde_json::json!(-1.0);
    invalid(SliderGeometry::from_json(&t.to_string()), "json");
    let mut t: serde_json::Value = serde_json::from_str(&json).unwrap();
    t["nano_analysis"]["asperities"]["spacing"] = serde_json::json!(1.0);
    invalid(SliderGeometry::from_json(&t.to_string()), "nano_analysis");
    invalid(SliderGeometry::from_json("{"), "json");
    // A hand-written file may use plain numbers.
    let text = r#"{"levels": [{"width": 13.5e-6, "origin": 0, "heights": [0, 1e-9]}],
        "nano": {"h_vdw": 4.1e-9, "w_vdw": 430e-9, "h_chem": 4.1e-9,
                 "w_chem": 161e-9, "spacing": 1.35e-6},
        "nano_per_rod": 100, "micro_statistics": null, "nano_analysis": null}"#;
    let g = SliderGeometry::from_json(text).unwrap();
    assert_eq!(g.tips().heights(), &[0.0, 1e-9]);
    assert_eq!(g.nano_total(), 200);
    close(g.nano().w_chem, 161.0 * NM, 1e-15);
    invalid(
        SliderGeometry::from_json(&text.replace("[0, 1e-9]", "[0, \"x\"]")),
        "json",
    );
}

#[test]
fn geometry_is_send_and_sync() {
    fn shared<T: Send + Sync + 'static>() {}
    shared::<SliderGeometry>();
    shared::<RodLevel>();
    let g = std::sync::Arc::new(
        SliderGeometry::uniform(13.5 * UM, 2, hand_calculation_nano(), 100).unwrap(),
    );
    let h = {
        let g = g.clone();
        std::thread::spawn(move || g.nano_total())
    };
    assert_eq!(h.join().unwrap(), 200);
}

// --------------------------------------------------------- measured data

fn data_dir() -> Option<PathBuf> {
    let d = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../shared/data/profiles");
    if d.join("README.md").is_file() {
        Some(d)
    } else {
        common::skip(format_args!(
            "measured data not found at {} (the project does not copy them: they live \
             outside it, in ../shared/data next to the crate)",
            d.display()
        ));
        None
    }
}

fn check_invariants(g: &SliderGeometry, micro: &Profile) {
    let n = g.nano();
    assert!(n.h_vdw > 0.0 && n.h_chem >= 0.0);
    assert!(0.0 <= n.w_chem && n.w_chem <= n.w_vdw && n.w_vdw <= n.spacing);
    let a = g.nano_analysis().unwrap();
    // w_chem is the length above the slab shared among n_mean asperities,
    // λ the whole length.
    close(n.w_chem, a.length_above_rms / a.n_mean as f64, 1e-12);
    close(n.spacing, a.length / a.n_mean as f64, 1e-12);
    // Rod counts: ⌊(n − 1)dx/w₀⌋, then × each ratio.
    let w0 = g.levels()[0].width();
    let n0 = ((micro.len() - 1) as f64 * micro.dx() / w0).floor() as usize;
    assert_eq!(g.levels()[0].len(), n0);
    for l in 1..g.levels().len() {
        let m = (g.levels()[l - 1].width() / g.levels()[l].width()).round() as usize;
        assert_eq!(g.levels()[l].len(), g.levels()[l - 1].len() * m);
        assert_eq!(g.branching(l - 1), Some(m));
    }
    let side = (g.tips().width() / n.spacing).floor() as usize;
    assert_eq!(g.nano_per_rod(), side * side);
    assert_eq!(g.nano_total(), g.tips().len() * side * side);
    // Rod heights are finite and within the profile's range about its mean.
    let zbar = micro.heights().iter().sum::<f64>() / micro.len() as f64;
    let (lo, hi) = micro
        .heights()
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), z| {
            (a.min(z - zbar), b.max(z - zbar))
        });
    for level in g.levels() {
        assert!(level
            .heights()
            .iter()
            .all(|h| h.is_finite() && *h >= lo && *h <= hi));
        // The rods average the profile: their mean is near the mean line.
        let mean = level.heights().iter().sum::<f64>() / level.len() as f64;
        assert!(mean.abs() < 0.5 * g.micro_statistics().unwrap().rq);
    }
    assert!(SliderGeometry::from_json(&g.to_json()).unwrap() == *g);
}

#[test]
fn measured_profiles_slider() {
    let Some(d) = data_dir() else { return };
    // Micro: the Hommel stylus profile (0.5 µm sampling, 4.8 mm), bow removed
    // (README: quadratic detrend, Rq 0.138 µm).
    let micro = Profile::read(d.join("hommel_hfm1_stylus_linescan.csv"), Spacing::Tolerant)
        .unwrap()
        .remove_form(Form::Quadratic)
        .unwrap();
    // Nano: the AFM map (39 nm sampling, 10 µm), plane-levelled, each row
    // then freed of its own tilt and offset (scan-line drift).
    let map = Topography::read(
        d.join("afm_dimension_icon_di3_zsensor_map.csv"),
        Spacing::Tolerant,
    )
    .unwrap()
    .remove_form(MapForm::Plane)
    .unwrap();
    let row = |j: usize| map.row(j).unwrap().remove_form(Form::Linear).unwrap();
    let nano = row(map.ny() / 2);

    let ms = asperity_statistics(micro.heights(), micro.dx()).unwrap();
    eprintln!(
        "micro (hommel, quadratic form removed): Rq = {:.4e} m, d̄(Rq) = {:.4e} m over {} asperities, Δq = {:.4e}, λ_a = 2πRq/Δq = {:.4e} m",
        ms.rq,
        ms.mean_width.unwrap_or(f64::NAN),
        ms.asperities_at_rq,
        ms.rdq,
        ms.spacing
    );

    // Nano statistics of every row, for the spread.
    let mut rows: Vec<NanoAnalysis> = (0..map.ny())
        .map(|j| {
            let p = row(j);
            nano_analysis(p.heights(), p.dx()).unwrap()
        })
        .collect();
    let median = |f: &dyn Fn(&NanoAnalysis) -> f64, rows: &mut Vec<NanoAnalysis>| {
        rows.sort_by(|a, b| f(a).total_cmp(&f(b)));
        (
            f(&rows[0]),
            f(&rows[rows.len() / 2]),
            f(&rows[rows.len() - 1]),
        )
    };
    for (name, f) in [
        (
            "h_vdW",
            (|a: &NanoAnalysis| a.asperities.h_vdw) as fn(&NanoAnalysis) -> f64,
        ),
        ("h_chem", |a| a.asperities.h_chem),
        ("w_vdW", |a| a.asperities.w_vdw),
        ("w_chem", |a| a.asperities.w_chem),
        ("λ (6-3)", |a| a.asperities.spacing),
        ("n_mean", |a| a.n_mean as f64),
    ] {
        let (lo, med, hi) = median(&f, &mut rows);
        eprintln!("AFM rows: {name}: min {lo:.4e}, median {med:.4e}, max {hi:.4e}");
    }
    for r in &rows {
        let n = r.asperities;
        assert!(n.w_chem <= n.w_vdw && n.w_vdw <= n.spacing && n.h_vdw > 0.0);
    }

    // The thesis's discretisations: 13.5 µm rods, and 13.5 µm split into
    // 9 × 1.5 µm (when the nano spacing fits on a 1.5 µm tip).
    let a = nano_analysis(nano.heights(), nano.dx()).unwrap();
    let mut widths: Vec<&[f64]> = vec![&[13.5 * UM]];
    if a.asperities.spacing <= 1.5 * UM {
        widths.push(&[13.5 * UM, 1.5 * UM]);
    } else {
        eprintln!(
            "not building 13.5/1.5 µm levels: nano spacing {:.3e} m exceeds a 1.5 µm tip",
            a.asperities.spacing
        );
        out_of_domain(
            SliderGeometry::from_profiles(&micro, &[13.5 * UM, 1.5 * UM], &nano),
            "rod_widths",
        );
    }
    for w in widths {
        let g = SliderGeometry::from_profiles(&micro, w, &nano).unwrap();
        check_invariants(&g, &micro);
        let n = g.nano();
        let an = g.nano_analysis().unwrap();
        eprintln!("rod widths {w:?} m:");
        for l in g.levels() {
            let (lo, hi) = l
                .heights()
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), h| {
                    (a.min(*h), b.max(*h))
                });
            let rms = (l.heights().iter().map(|h| h * h).sum::<f64>() / l.len() as f64).sqrt();
            eprintln!(
                "  level w = {:.3e} m: {} rods, heights {:.3e} .. {:.3e} m, rms {:.3e} m",
                l.width(),
                l.len(),
                lo,
                hi,
                rms
            );
        }
        eprintln!(
            "  nano (AFM row {}): h_vdW = {:.3e} m, h_chem = {:.3e} m (total {:.3e} m), w_vdW = {:.3e} m, w_chem = {:.3e} m, λ = {:.3e} m, n_mean = {}, A_vdW = {:.3e} m², A_chem = {:.3e} m²",
            map.ny() / 2,
            n.h_vdw,
            n.h_chem,
            n.height(),
            n.w_vdw,
            n.w_chem,
            n.spacing,
            an.n_mean,
            an.area_vdw,
            an.area_chem
        );
        eprintln!(
            "  per tip: {} nano-asperities (thesis: 100 on 13.5 µm), total {}",
            g.nano_per_rod(),
            g.nano_total()
        );
        eprintln!(
            "  side by side with the thesis's copper: w_vdW {:.0} nm vs 430 nm, w_chem {:.0} nm vs 161 nm, height {:.1} nm vs 8.2 nm, per 13.5 µm rod {} vs 100",
            n.w_vdw / NM,
            n.w_chem / NM,
            n.height() / NM,
            nano_per_rod(13.5 * UM, n.spacing).unwrap()
        );
    }
}

/// Fuzzing regression (fuzz/regressions/c_abi/geometry_uniform_huge_rods):
/// a rod count the process cannot allocate is an error naming the argument,
/// not a capacity-overflow panic or an out-of-memory abort. Counts come from
/// `rods` directly ([`SliderGeometry::uniform`]) or from a rod width far
/// below the profile's spacing ([`rod_levels`], nested levels included).
#[test]
fn rod_counts_beyond_max_rods_are_errors() {
    let nano = hand_calculation_nano();
    for rods in [MAX_RODS + 1, 1 << 40, usize::MAX] {
        invalid(SliderGeometry::uniform(13.5 * UM, rods, nano, 1), "rods");
    }
    // The bound itself is accepted by the count check (the geometry is
    // built: 2^24 rods of 8 bytes).
    assert_eq!(
        SliderGeometry::uniform(13.5 * UM, MAX_RODS, nano, 1)
            .unwrap()
            .tips()
            .len(),
        MAX_RODS
    );
    // 9 µm of profile: 9e-6 / 1e-300 rods.
    invalid(rod_levels(&micro(), UM, &[1e-300]), "rod_widths");
    // Level 0 fits (9 rods), level 1 has 9 × 2^24 rods.
    invalid(
        rod_levels(&micro(), UM, &[UM, UM / (1u64 << 24) as f64]),
        "rod_widths",
    );
    assert_eq!(
        rod_levels(&micro(), UM, &[UM, UM / 4.0]).unwrap()[1].len(),
        36
    );
}

/// A nano-asperity spacing far below the rod width (a nano profile sampled
/// at 10⁻²⁰ m, a subnormal spacing) gave n = ⌊w/λ⌋ saturated to
/// `usize::MAX` and n² overflowed (a panic; with `asperity_slider_geometry_new`
/// the C guard's `ASPERITY_ERR_INTERNAL`), and a `per_rod` near `usize::MAX`
/// overflowed [`SliderGeometry::nano_total`]. Found reviewing the slider
/// constructors for the fuzz harness's `asperity_slider_new` operation. Now
/// at most [`MAX_NANO_PER_ROD`] = 2²⁴ = 4096² per rod, errors naming the
/// argument.
#[test]
fn nano_counts_beyond_max_nano_per_rod_are_errors() {
    assert_eq!(MAX_NANO_PER_ROD, 4096 * 4096);
    let s = 1.35 * UM;
    assert_eq!(nano_per_rod(4096.0 * s, s).unwrap(), 16_777_216);
    out_of_domain(nano_per_rod(4097.0 * s, s), "tip_width");
    for spacing in [1e-30, 5e-324] {
        out_of_domain(nano_per_rod(1.5 * UM, spacing), "tip_width");
    }
    // From profiles: the nano profile's spacing scales with its sampling
    // interval (the same heights at 10 nm and at 10 nm × 10⁻¹²).
    let coarse = nano_analysis(&square(), 10.0 * NM).unwrap().asperities;
    let fine = nano_analysis(&square(), 10.0 * NM * 1e-12)
        .unwrap()
        .asperities;
    close(fine.spacing, coarse.spacing * 1e-12, 1e-12);
    assert!(UM / fine.spacing > 4097.0);
    out_of_domain(
        SliderGeometry::from_slices(&micro(), UM, &[UM], &square(), 10.0 * NM * 1e-12),
        "rod_widths",
    );
    out_of_domain(
        SliderGeometry::from_slices(&micro(), UM, &[UM], &square(), 1e-300),
        "rod_widths",
    );
    // From numbers: `nano_per_rod` beyond the bound, though the cells fit.
    let tiny = NanoAsperities {
        h_vdw: 4.1 * NM,
        w_vdw: 1e-30,
        h_chem: 0.0,
        w_chem: 0.0,
        spacing: 1e-30,
    };
    for per_rod in [MAX_NANO_PER_ROD + 1, usize::MAX] {
        invalid(
            SliderGeometry::uniform(13.5 * UM, 2, tiny, per_rod),
            "nano_per_rod",
        );
    }
    let g = SliderGeometry::uniform(13.5 * UM, 2, tiny, MAX_NANO_PER_ROD).unwrap();
    assert_eq!(g.nano_total(), 2 * 16_777_216);
}
