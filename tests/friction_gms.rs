//! The generalised Maxwell-slip model (Al-Bender, Lampaert and Swevers
//! 2005; thesis 5.3.8): its limits (Maxwell-slip for a flat Stribeck curve,
//! for every attraction rate), the presliding hysteresis with non-local
//! memory (Masing rules at speeds far below v_s), the Stribeck steady state
//! F_ss(v) = N s(v) Σα + σ₂v over decades of v, the frictional lag (the
//! closed-form attraction after a velocity step), exactness of a split
//! increment, passivity (dissipation ≥ 0, work = dissipation + stored
//! energy) and the tangents against finite differences.

use asperity::friction::dynamic::{GeneralizedMaxwellSlip, MaxwellSlip};
use asperity::friction::{FrictionIncrement, FrictionLaw, FrictionRegime};
use asperity::Error;

#[path = "common/tangents.rs"]
mod tangents;

const K: [f64; 5] = [2e5, 1e5, 5e4, 2.5e4, 1.25e4];
/// Maxwell-slip capacities μᵢ (Σ = 0.8).
const MU: [f64; 5] = [0.2, 0.2, 0.2, 0.1, 0.1];
/// GMS weights αᵢ = μᵢ/Σμ.
const ALPHA: [f64; 5] = [0.25, 0.25, 0.25, 0.125, 0.125];

fn inc(n: f64, ds: f64, dt: f64) -> FrictionIncrement {
    FrictionIncrement {
        normal_force: n,
        slip: [ds, 0.0],
        dt,
        ..Default::default()
    }
}

/// μ_c = 0.5, μ_s = 0.8, v_s = 1 mm/s, δ = 2, C = `c`, σ₂ = `sigma2`.
fn gms(c: f64, sigma2: f64) -> GeneralizedMaxwellSlip {
    GeneralizedMaxwellSlip::new(&K, &ALPHA, 0.5, 0.8, 1e-3, 2.0, c, sigma2).unwrap()
}

fn rng(seed: &mut u64) -> f64 {
    *seed ^= *seed << 13;
    *seed ^= *seed >> 7;
    *seed ^= *seed << 17;
    (*seed >> 11) as f64 / (1u64 << 53) as f64
}

fn name(e: Error) -> &'static str {
    match e {
        Error::InvalidArgument { name, .. } | Error::NullPointer { name } => name,
        other => panic!("unexpected {other:?}"),
    }
}

#[test]
fn flat_stribeck_curve_is_maxwell_slip_for_every_attraction_rate() {
    let ms = MaxwellSlip::new(&K, &MU, 0.3).unwrap();
    for c in [1e-3, 1.0, 1e4, f64::INFINITY] {
        let g = GeneralizedMaxwellSlip::new(&K, &ALPHA, 0.8, 0.8, 1e-3, 2.0, c, 0.3).unwrap();
        let (mut sm, mut sg) = (vec![0.0; ms.state_len()], vec![0.0; g.state_len()]);
        let mut seed = 17;
        for step in 0..3000 {
            let ds = 8e-6 * (rng(&mut seed) - 0.5) * if step % 100 < 50 { 1.0 } else { 3.0 };
            let dt = 1e-4 * (0.1 + rng(&mut seed));
            let n = 1.0 + rng(&mut seed);
            let i = inc(n, ds, dt);
            let rm = ms.step_in_place(&mut sm, &i, &mut ms.work()).unwrap();
            let rg = g.step_in_place(&mut sg, &i, &mut g.work()).unwrap();
            let scale = n * 0.8 + 0.3 * ds.abs() / dt;
            assert!(
                (rm.force[0] - rg.force[0]).abs() <= 1e-12 * scale,
                "C = {c}, step {step}: {} vs {}",
                rm.force[0],
                rg.force[0]
            );
            assert!(
                (rm.dissipated - rg.dissipated).abs() <= 1e-9 * rm.dissipated.max(1e-18),
                "C = {c}, step {step}: dissipation {} vs {}",
                rm.dissipated,
                rg.dissipated
            );
            assert_eq!(rm.regime, rg.regime, "C = {c}, step {step}");
        }
    }
}

/// Walks a 1-D path of positions at speed `v` in increments of at most
/// `h`, returning the force −F_x at each target.
fn walk(m: &GeneralizedMaxwellSlip, n: f64, path: &[f64], h: f64, v: f64) -> Vec<f64> {
    let mut s = vec![0.0; m.state_len()];
    let mut x = 0.0;
    let mut out = vec![];
    for &target in path {
        let steps = ((target - x).abs() / h).ceil().max(1.0) as usize;
        let d = (target - x) / steps as f64;
        let mut f = 0.0;
        for _ in 0..steps {
            let r = m
                .step_in_place(&mut s, &inc(n, d, d.abs() / v), &mut m.work())
                .unwrap();
            f = -r.force[0];
        }
        x = target;
        out.push(f);
    }
    out
}

#[test]
fn presliding_hysteresis_obeys_the_masing_rules_with_non_local_memory() {
    // At v = 1e-9 m/s ≪ v_s the Stribeck curve is μ_s to 1e-12: the
    // presliding loop of the GMS paper (its Fig. 2) is Maxwell-slip's.
    let m = gms(1e3, 0.0);
    let (n, v) = (3.0, 1e-9);
    let xs: Vec<f64> = (1..=40).map(|i| i as f64 * 0.7e-6).collect();
    let f = walk(&m, n, &xs, 0.3e-6, v);
    for (x, f) in xs.iter().zip(&f) {
        let want = m.virgin_force(n, *x, v);
        assert!(
            (f - want).abs() <= 1e-12 * want,
            "virgin at {x}: {f} vs {want}"
        );
    }
    // Reversal at x_r: F(x) = F(x_r) − 2 F_v((x_r − x)/2).
    let xr = 9e-6;
    let mut path = vec![xr];
    let back: Vec<f64> = (1..=50).map(|i| xr - i as f64 * 0.6e-6).collect();
    path.extend(&back);
    let f = walk(&m, n, &path, 0.25e-6, v);
    let fr = m.virgin_force(n, xr, v);
    for (x, got) in back.iter().zip(&f[1..]) {
        let want = fr - 2.0 * m.virgin_force(n, (xr - x) / 2.0, v);
        assert!(
            (got - want).abs() <= 1e-12 * fr,
            "reversal at {x}: {got} vs {want}"
        );
    }
    // A closed inner loop is forgotten; an open one is remembered.
    let f = walk(&m, n, &[6e-6, 2e-6, 6e-6, 8e-6, 10e-6], 0.2e-6, v);
    for (x, got) in [(6e-6, f[2]), (8e-6, f[3]), (10e-6, f[4])] {
        let want = m.virgin_force(n, x, v);
        assert!((got - want).abs() <= 1e-12 * want, "{x}: {got} vs {want}");
    }
    let f = walk(&m, n, &[6e-6, 2e-6, 5e-6], 0.2e-6, v);
    assert!(f[2] < m.virgin_force(n, 5e-6, v) - 1e-3 * n);
}

#[test]
fn steady_sliding_follows_the_stribeck_curve_over_decades_of_speed() {
    let (n, sigma2) = (2.0, 0.5);
    let m = gms(50.0, sigma2);
    let mut last = f64::INFINITY;
    for e in -8..=1 {
        let v = 10f64.powi(e);
        // Slide 1 mm at v in 1 µm increments: every element slips, and the
        // attraction (time constant α s/C ≤ 16 ms) has long converged.
        let mut s = vec![0.0; m.state_len()];
        let ds = 1e-6;
        let mut r = None;
        for _ in 0..1000 {
            r = Some(
                m.step_in_place(&mut s, &inc(n, ds, ds / v), &mut m.work())
                    .unwrap(),
            );
        }
        let r = r.unwrap();
        // Σα = 1: F_ss = N s(v) + σ₂v.
        let want = n * (0.5 + 0.3 * (-(v / 1e-3) * (v / 1e-3)).exp()) + sigma2 * v;
        assert!(
            (-r.force[0] - want).abs() <= 1e-12 * want,
            "v = {v}: {} vs F_ss {want}",
            -r.force[0]
        );
        assert!((m.steady_force(n, v) - want).abs() <= 1e-14 * want);
        assert_eq!(r.regime(), FrictionRegime::Slip);
        // The Stribeck curve weakens monotonically.
        let s = m.stribeck(v);
        assert!(s <= last, "not weakening at {v}");
        last = s;
    }
}

#[test]
fn frictional_lag_is_the_closed_form_attraction() {
    // One element (k, α = 1) sliding at v₁ = 0.1 mm/s, then at v₂ = 2 mm/s:
    // s falls from s(v₁) to s(v₂) and f follows
    // f(t) = s₂ + (s₁ − s₂) e^{−C t/s₂} (no rate limit when falling).
    let (k, c) = (1e5, 20.0);
    let m = GeneralizedMaxwellSlip::new(&[k], &[1.0], 0.5, 0.8, 1e-3, 2.0, c, 0.0).unwrap();
    let n = 1.0;
    let mut s = vec![0.0; m.state_len()];
    let (v1, v2) = (1e-4, 2e-3);
    for _ in 0..200 {
        m.step_in_place(&mut s, &inc(n, 1e-6, 1e-6 / v1), &mut m.work())
            .unwrap();
    }
    let (s1, s2) = (m.stribeck(v1), m.stribeck(v2));
    assert!((s[2] - s1).abs() <= 1e-14);
    let dt = 1e-3;
    for j in 1..=200 {
        let r = m
            .step_in_place(&mut s, &inc(n, v2 * dt, dt), &mut m.work())
            .unwrap();
        let t = j as f64 * dt;
        let want = s2 + (s1 - s2) * (-c * t / s2).exp();
        assert!(
            (-r.force[0] - want).abs() <= 1e-12,
            "t = {t}: {} vs {want}",
            -r.force[0]
        );
    }
    // The rising branch (v₂ → v₁) is attracted as fast as the spring
    // allows at most: f never rises faster than k per metre of slip.
    let mut f_old = s[2];
    for _ in 0..200 {
        let r = m
            .step_in_place(&mut s, &inc(n, 1e-8, 1e-8 / v1), &mut m.work())
            .unwrap();
        let f = -r.force[0];
        assert!(f - f_old <= k * 1e-8 * (1.0 + 1e-12));
        assert!(f <= s1 * (1.0 + 1e-14));
        f_old = f;
    }
}

#[test]
fn an_increment_split_in_two_at_the_same_speed_is_the_whole() {
    // Exact integration: stepping Δs in one or in two halves (same v) agrees
    // to rounding, through every phase (stick, rate-limited loading,
    // attraction).
    let m = gms(30.0, 0.2);
    let mut seed = 3;
    let mut s = vec![0.0; m.state_len()];
    for step in 0..2000 {
        let v =
            10f64.powf(-6.0 + 4.0 * rng(&mut seed)) * if rng(&mut seed) < 0.4 { -1.0 } else { 1.0 };
        let ds = v.signum() * 6e-6 * rng(&mut seed);
        let dt = ds / v;
        let n = 1.0 + rng(&mut seed);
        let mut whole = s.clone();
        let rw = m
            .step_in_place(&mut whole, &inc(n, ds, dt), &mut m.work())
            .unwrap();
        let mut half = s.clone();
        let r1 = m
            .step_in_place(&mut half, &inc(n, ds / 2.0, dt / 2.0), &mut m.work())
            .unwrap();
        let r2 = m
            .step_in_place(&mut half, &inc(n, ds / 2.0, dt / 2.0), &mut m.work())
            .unwrap();
        let scale = n * 0.8;
        assert!(
            (rw.force[0] - r2.force[0]).abs() <= 1e-10 * scale,
            "step {step}: {} vs {}",
            rw.force[0],
            r2.force[0]
        );
        let d = rw.dissipated.max(r1.dissipated + r2.dissipated).max(1e-300);
        assert!(
            (rw.dissipated - r1.dissipated - r2.dissipated).abs() <= 1e-8 * d + 1e-22,
            "step {step}: dissipation {} vs {}",
            rw.dissipated,
            r1.dissipated + r2.dissipated
        );
        s = whole;
    }
}

#[test]
fn every_increment_dissipates_and_work_is_dissipation_plus_stored_energy() {
    // A random walk of speeds over five decades and both directions, each
    // leg cut into 200 sub-increments: every dissipation ≥ 0 and the
    // trapezoidal work of the force converges to ΣΔD + E_stored.
    for c in [0.5, 50.0, 5e3, f64::INFINITY] {
        let m = gms(c, 0.0);
        let n = 2.0;
        let mut seed = 11;
        let mut s = vec![0.0; m.state_len()];
        let (mut work, mut dissipated, mut f_old, mut stored) = (0.0, 0.0, 0.0, 0.0);
        for _ in 0..150 {
            let v = 10f64.powf(-7.0 + 5.0 * rng(&mut seed));
            let leg = 20e-6 * (rng(&mut seed) - 0.5);
            let ds = leg / 200.0;
            for _ in 0..200 {
                let r = m
                    .step_in_place(&mut s, &inc(n, ds, ds.abs() / v), &mut m.work())
                    .unwrap();
                assert!(r.dissipated >= 0.0, "C = {c}: dissipation {}", r.dissipated);
                let f = -r.force[0];
                work += 0.5 * (f_old + f) * ds;
                dissipated += r.dissipated;
                f_old = f;
                stored = r.stored_energy;
            }
        }
        let total = dissipated + stored;
        assert!(
            (work - total).abs() <= 3e-3 * total,
            "C = {c}: work {work} vs dissipation + stored {total}"
        );
    }
}

#[test]
fn tangents_match_finite_differences() {
    let mut compared = 0;
    for c in [2.0, 200.0, f64::INFINITY] {
        let m = gms(c, 0.3);
        let mut seed = 5;
        let mut s = vec![0.0; m.state_len()];
        for step in 0..400 {
            let v = 10f64.powf(-6.0 + 4.0 * rng(&mut seed));
            let ds = 5e-6 * (rng(&mut seed) - 0.45);
            let n = 1.0 + rng(&mut seed);
            let i = inc(n, ds, ds.abs() / v);
            let label = format!("C = {c}, step {step}");
            // In gross sliding the slope is N α s'(v)/Δt, small beside the
            // force: the step is a fraction of Δs large enough that rounding
            // stays below 1e-7 and small enough for the truncation.
            let h = (1e-4 * ds.abs()).max(1e-13);
            let fd = tangents::fd_check_track(&m, &s, &i, 1e-7 * n, h, &label);
            compared += fd.slip.is_some() as usize;
            m.step_in_place(&mut s, &i, &mut m.work()).unwrap();
        }
    }
    assert!(compared > 600, "only {compared} slip tangents compared");
}

#[test]
fn bad_input_names_the_argument() {
    let g = |k: &[f64], a: &[f64], mc, ms, vs, d, c, s2| {
        GeneralizedMaxwellSlip::new(k, a, mc, ms, vs, d, c, s2).map(|_| ())
    };
    assert_eq!(
        name(g(&[], &[], 0.5, 0.8, 1e-3, 2.0, 1.0, 0.0).unwrap_err()),
        "weight.len()"
    );
    assert_eq!(
        name(g(&[1.0], &[1.0, 1.0], 0.5, 0.8, 1e-3, 2.0, 1.0, 0.0).unwrap_err()),
        "weight.len()"
    );
    assert_eq!(
        name(g(&[-1.0], &[1.0], 0.5, 0.8, 1e-3, 2.0, 1.0, 0.0).unwrap_err()),
        "stiffness"
    );
    assert_eq!(
        name(g(&[1.0], &[-1.0], 0.5, 0.8, 1e-3, 2.0, 1.0, 0.0).unwrap_err()),
        "weight"
    );
    assert_eq!(
        name(g(&[1.0], &[1.0], 0.0, 0.8, 1e-3, 2.0, 1.0, 0.0).unwrap_err()),
        "mu_coulomb"
    );
    assert_eq!(
        name(g(&[1.0], &[1.0], 0.5, f64::NAN, 1e-3, 2.0, 1.0, 0.0).unwrap_err()),
        "mu_static"
    );
    assert_eq!(
        name(g(&[1.0], &[1.0], 0.5, 0.8, 0.0, 2.0, 1.0, 0.0).unwrap_err()),
        "stribeck_velocity"
    );
    assert_eq!(
        name(g(&[1.0], &[1.0], 0.5, 0.8, 1e-3, -2.0, 1.0, 0.0).unwrap_err()),
        "stribeck_exponent"
    );
    assert_eq!(
        name(g(&[1.0], &[1.0], 0.5, 0.8, 1e-3, 2.0, 0.0, 0.0).unwrap_err()),
        "attraction"
    );
    assert_eq!(
        name(g(&[1.0], &[1.0], 0.5, 0.8, 1e-3, 2.0, f64::NAN, 0.0).unwrap_err()),
        "attraction"
    );
    assert_eq!(
        name(g(&[1.0], &[1.0], 0.5, 0.8, 1e-3, 2.0, 1.0, -1.0).unwrap_err()),
        "sigma2"
    );
    let m = gms(1.0, 0.0);
    let mut new = vec![0.0; m.state_len()];
    let old = vec![0.0; m.state_len()];
    // Rate dependent, one-dimensional, a valid mode.
    assert_eq!(
        name(
            m.step(&old, &mut new, &inc(1.0, 1e-6, 0.0), &mut m.work())
                .unwrap_err()
        ),
        "dt"
    );
    let across = FrictionIncrement {
        slip: [0.0, 1e-9],
        dt: 1.0,
        normal_force: 1.0,
        ..Default::default()
    };
    assert_eq!(
        name(m.step(&old, &mut new, &across, &mut m.work()).unwrap_err()),
        "slip"
    );
    let mut bad = old.clone();
    bad[3] = 0.5;
    assert_eq!(
        name(
            m.step(&bad, &mut new, &inc(1.0, 1e-6, 1.0), &mut m.work())
                .unwrap_err()
        ),
        "old"
    );
    assert!(new.iter().all(|&x| x == 0.0));
}
