//! The dynamic friction models of thesis chapter 5 (issue 9): LuGre against
//! its Stribeck curve and a fine Runge–Kutta integration, Maxwell-slip
//! against the Masing rules and non-local memory, Prandtl–Tomlinson (one and
//! two springs) against the stick-slip criterion η > 1 of the effective
//! stiffness and the quasi-static static and kinetic friction, the
//! Burridge–Knopoff chain against the closed-form period of a uniform chain,
//! its energy balance and events of many sizes; dissipation ≥ 0, tangents
//! against finite differences, cut-backs, extremes, bad input.

use asperity::friction::dynamic::{
    Bristles, FrictionIncrement, FrictionLaw, GeneralizedMaxwellSlip, LuGre, MaxwellSlip,
    STATE_DISSIPATION, STATE_MODEL, STATE_SLIP_PATH, TANGENT_NORMAL, TANGENT_SLIP,
};
use asperity::friction::{BlockStates, FrictionBlock};
use asperity::Error;

#[path = "common/tangents.rs"]
mod tangents;

fn name(e: Error) -> &'static str {
    match e {
        Error::InvalidArgument { name, .. }
        | Error::OutOfDomain { name, .. }
        | Error::UnknownSelector { name, .. } => name,
        other => panic!("{other:?}"),
    }
}

/// μ_c = 0.3, μ_s = 0.5, v_s = 1 mm/s, σ₀ = 1e5 /m (10 µm of pre-sliding
/// per unit μ), σ₁ at half its passivity bound with v_d = 1 mm/s, σ₂ = 0.4.
fn lugre() -> LuGre {
    let vd = 1e-3;
    let s1 = 0.5 * 4.0 * 0.3 * (2.0 * std::f64::consts::E).sqrt() / vd;
    LuGre::new(0.3, 0.5, 1e-3, 2.0, 1e5, s1, vd, 0.4).unwrap()
}

fn inc(n: f64, slip: [f64; 2], dt: f64) -> FrictionIncrement {
    FrictionIncrement {
        normal_force: n,
        slip,
        dt,
        ..Default::default()
    }
}

// ------------------------------------------------------------- LuGre

#[test]
fn lugre_steady_state_is_its_stribeck_curve() {
    let m = lugre();
    for n in [1e-3, 1.0, 250.0] {
        for k in -6..=2 {
            let v = 10f64.powi(k);
            // One long increment at constant speed: the exact solution is
            // at steady state (e^{-a dt} underflows).
            let dt = 1e3 / v * 1e-3;
            let mut s = vec![0.0; m.state_len()];
            let mut t = s.clone();
            let r = m
                .step(&s, &mut t, &inc(n, [v * dt, 0.0], dt), &mut m.work())
                .unwrap();
            let want = m.steady_force(n, v);
            assert!(
                (r.force_magnitude - want).abs() <= 1e-12 * want,
                "v = {v}: {} vs {want}",
                r.force_magnitude
            );
            assert!(r.force[0] < 0.0, "opposes slip");
            // Many small increments reach the same.
            s.fill(0.0);
            let steps = 400;
            let h = 2.0 * dt / steps as f64;
            let mut last = 0.0;
            for _ in 0..steps {
                let r = m
                    .step(&s, &mut t, &inc(n, [0.0, -v * h], h), &mut m.work())
                    .unwrap();
                s.copy_from_slice(&t);
                last = r.force[1];
            }
            assert!(
                (last - want).abs() <= 1e-9 * want,
                "v = {v}: {last} vs {want}"
            );
        }
    }
    // The Stribeck curve itself: μ_s at rest, μ_c fast.
    assert_eq!(m.stribeck(0.0), 0.5);
    assert!((m.stribeck(1e-1) - 0.3).abs() < 1e-15);
    assert!((m.stribeck(1e-3) - (0.3 + 0.2 / std::f64::consts::E)).abs() < 1e-15);
}

/// z(t) and the dissipated energy of one increment, by classical RK4 with
/// `k` sub-steps on ż = v − σ₀|v|z/μ(|v|) (1-D), and the work of
/// F = N(σ₀z + σ₁(v)ż) + σ₂v by Simpson's rule on the same steps, less ΔE.
fn rk4(p: &Params, z0: f64, n: f64, ds: f64, dt: f64, k: usize) -> (f64, f64) {
    let v = ds / dt;
    let mu = p.mu_c + (p.mu_s - p.mu_c) * (-(v.abs() / p.vs).powi(2)).exp();
    let a = p.s0 * v.abs() / mu;
    let s1 = p.s1 * (-(v / p.vd).powi(2)).exp();
    let zdot = |z: f64| v - a * z;
    let power = |z: f64| (n * (p.s0 * z + s1 * zdot(z)) + p.s2 * v) * v;
    let h = dt / k as f64;
    let (mut z, mut work) = (z0, 0.0);
    for _ in 0..k {
        let k1 = zdot(z);
        let k2 = zdot(z + 0.5 * h * k1);
        let k3 = zdot(z + 0.5 * h * k2);
        let k4 = zdot(z + h * k3);
        let zm = z + 0.5 * h * k2; // RK4 midpoint estimate for Simpson
        let zn = z + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
        work += h / 6.0 * (power(z) + 4.0 * power(zm) + power(zn));
        z = zn;
    }
    let de = 0.5 * n * p.s0 * (z * z - z0 * z0);
    (z, work - de)
}

struct Params {
    mu_c: f64,
    mu_s: f64,
    vs: f64,
    s0: f64,
    s1: f64,
    vd: f64,
    s2: f64,
}

#[test]
fn lugre_increment_is_exact_against_runge_kutta() {
    // v_d = v_s (one exponential serves the Stribeck and damping decays)
    // and v_d = 3 v_s (two), each with σ₁ at half its passivity bound.
    for vd in [1e-3, 3e-3] {
        let p = Params {
            mu_c: 0.3,
            mu_s: 0.5,
            vs: 1e-3,
            s0: 1e5,
            s1: 0.5 * 4.0 * 0.3 * (2.0 * std::f64::consts::E).sqrt() / vd,
            vd,
            s2: 0.4,
        };
        let m = LuGre::new(p.mu_c, p.mu_s, p.vs, 2.0, p.s0, p.s1, p.vd, p.s2).unwrap();
        // Start deflected either way (a reversal and a continuation), slow
        // and fast, short and long increments; the last three put the
        // relaxation exponent σ₀|Δs|/μ just below, near and above 1/32,
        // where 1 − e^{−x} switches from its series to `exp`.
        for (z0, ds, dt) in [
            (3e-6, 2e-6, 1e-3),
            (-4e-6, 5e-6, 2e-3),
            (4.9e-6, -1e-7, 1e-4),
            (0.0, 3e-5, 1e-2),
            (2e-6, 1e-9, 1e-6),
            (-1e-6, 1.2e-7, 1e-4),
            (1e-6, 1.45e-7, 1e-4),
            (1e-6, -2e-7, 1e-4),
        ] {
            let n = 7.0;
            let mut old = vec![0.0; m.state_len()];
            old[asperity::friction::dynamic::lugre::STATE_Z] = z0;
            let mut new = old.clone();
            let r = m
                .step(&old, &mut new, &inc(n, [ds, 0.0], dt), &mut m.work())
                .unwrap();
            let (z, d) = rk4(&p, z0, n, ds, dt, 200_000);
            let z1 = new[asperity::friction::dynamic::lugre::STATE_Z];
            assert!((z1 - z).abs() <= 1e-9 * z.abs().max(1e-9), "{z1} vs {z}");
            assert!(
                (r.dissipated - d).abs() <= 1e-7 * d.abs().max(1e-18),
                "dissipation {} vs RK4 {d} (z0 {z0}, ds {ds}, dt {dt}, vd {vd})",
                r.dissipated
            );
            assert!(r.dissipated >= 0.0);
            assert_eq!(new[STATE_DISSIPATION], r.dissipated);
            assert_eq!(new[STATE_SLIP_PATH], ds.abs());
        }
    }
}

/// μ_c = 0 far above v_s: μ(v) underflows to 0, the relaxation rate σ₀|v|/μ
/// is infinite and the bristles let go within the increment. The response
/// is the limit (z = 0, no bristle force, the stored energy dissipated), not
/// NaN (the step returned a NaN force with an Ok status before).
#[test]
fn lugre_without_coulomb_friction_lets_go_far_above_the_stribeck_speed() {
    let m = LuGre::new(0.0, 0.5, 1e-3, 2.0, 1e5, 0.0, f64::INFINITY, 0.2).unwrap();
    assert_eq!(m.stribeck(1.0), 0.0);
    let (n, z0, ds, dt) = (4.0, 3e-6, 1e-3, 1e-3);
    for slip in [[ds, 0.0], [0.6 * ds, 0.8 * ds]] {
        let mut old = vec![0.0; m.state_len()];
        old[asperity::friction::dynamic::lugre::STATE_Z] = z0;
        let mut new = old.clone();
        let r = m
            .step(&old, &mut new, &inc(n, slip, dt), &mut m.work())
            .unwrap();
        let z = asperity::friction::dynamic::lugre::STATE_Z;
        assert_eq!(&new[z..z + 2], &[0.0, 0.0]);
        // Only the viscous force σ₂v remains.
        let v = [slip[0] / dt, slip[1] / dt];
        for (f, v) in r.force.iter().zip(v) {
            assert!((f + 0.2 * v).abs() <= 1e-15 * 0.2, "{r:?}");
        }
        let want = 0.5 * n * 1e5 * z0 * z0 + 0.2 * (ds / dt) * ds;
        assert!(
            (r.dissipated - want).abs() <= 1e-13 * want,
            "{} vs {want}",
            r.dissipated
        );
        assert_eq!(r.stored_energy, 0.0);
    }
}

/// Deterministic pseudo-random numbers in [0, 1).
fn rng(seed: &mut u64) -> f64 {
    *seed = seed.wrapping_add(0x9E37_79B9_7F4A_7C15);
    let mut z = *seed;
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
}

/// Random host increments: loads over 4 decades and zero, slips with
/// reversals and zeros, time steps over 4 decades; dissipation ≥ 0, the
/// accumulators grow by it, a re-evaluation from the same old state is
/// bit-identical.
fn random_increments(m: &dyn FrictionLaw, seed: u64, rate_dependent: bool) {
    random_path(m, seed, rate_dependent, false)
}

/// [`random_increments`], along x only when `track`.
fn random_path(m: &dyn FrictionLaw, seed: u64, rate_dependent: bool, track: bool) {
    let mut seed = seed;
    let mut old = vec![0.0; m.state_len()];
    let mut new = old.clone();
    let mut again = old.clone();
    for k in 0..(if track { 500 } else { 3000 }) {
        let n = if k % 17 == 0 {
            0.0
        } else {
            10f64.powf(4.0 * rng(&mut seed) - 2.0)
        };
        let ang = 6.3 * rng(&mut seed);
        let len = if k % 11 == 0 {
            0.0
        } else {
            10f64.powf(3.0 * rng(&mut seed) - 8.0)
        };
        let dt = if !rate_dependent && k % 13 == 0 {
            0.0
        } else if track {
            // The inertial Prandtl–Tomlinson tip: up to one of its periods.
            10f64.powf(2.0 * rng(&mut seed) - 8.0)
        } else {
            10f64.powf(4.0 * rng(&mut seed) - 5.0)
        };
        let i = FrictionIncrement {
            normal_force: n,
            slip: if track {
                [len * ang.cos(), 0.0]
            } else {
                [len * ang.cos(), len * ang.sin()]
            },
            dt,
            tangents: k % 4,
            ..Default::default()
        };
        let r = m.step(&old, &mut new, &i, &mut m.work()).unwrap();
        assert!(r.dissipated >= 0.0, "{k}: {r:?}");
        assert!(r.force.iter().all(|f| f.is_finite()) && r.stored_energy >= 0.0);
        assert_eq!(
            new[STATE_DISSIPATION],
            old[STATE_DISSIPATION] + r.dissipated
        );
        let r2 = m.step(&old, &mut again, &i, &mut m.work()).unwrap();
        assert_eq!(format!("{r:?}"), format!("{r2:?}"));
        assert_eq!(
            new.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
            again.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
        );
        old.copy_from_slice(&new);
    }
}

#[test]
fn lugre_random_increments_dissipate_and_cut_back_exactly() {
    random_increments(&lugre(), 1, true);
    // At the passivity bound exactly, and with no damping.
    let vd = 2e-3;
    let bound = 4.0 * 0.2 * (2.0 * std::f64::consts::E).sqrt() / vd;
    let edge = LuGre::new(0.2, 0.35, 5e-4, 1.0, 3e4, bound, vd, 0.0).unwrap();
    random_increments(&edge, 2, true);
    let plain = LuGre::new(0.4, 0.4, 1e-2, 2.0, 1e6, 0.0, f64::INFINITY, 1.0).unwrap();
    random_increments(&plain, 3, true);
}

#[test]
fn lugre_sticks_at_zero_slip_and_pre_slides_elastically() {
    let m = lugre();
    let mut s = vec![0.0; m.state_len()];
    s[asperity::friction::dynamic::lugre::STATE_Z] = 2e-6;
    let mut t = s.clone();
    let r = m
        .step(&s, &mut t, &inc(3.0, [0.0, 0.0], 0.0), &mut m.work())
        .unwrap();
    assert_eq!(t, s);
    assert_eq!(r.dissipated, 0.0);
    assert_eq!(r.regime, 0);
    assert_eq!(r.force, [-3.0 * 1e5 * 2e-6, -0.0]);
    // A tiny slow displacement from rest: the bristles act as a spring of
    // stiffness N σ₀ (pre-sliding), force ≈ N σ₀ x.
    let s = vec![0.0; m.state_len()];
    let x = 1e-9;
    let r = m
        .step(&s, &mut t, &inc(2.0, [x, 0.0], 100.0), &mut m.work())
        .unwrap();
    assert!(
        (r.force_magnitude / (2.0 * 1e5 * x) - 1.0).abs() < 1e-3,
        "{r:?}"
    );
}

#[test]
fn lugre_tangents_match_finite_differences() {
    let m = lugre();
    let mut s = vec![0.0; m.state_len()];
    s[asperity::friction::dynamic::lugre::STATE_Z] = 1e-6;
    s[asperity::friction::dynamic::lugre::STATE_Z + 1] = -2e-6;
    let mut t = s.clone();
    let i = FrictionIncrement {
        normal_force: 5.0,
        slip: [3e-7, 1e-7],
        dt: 2e-4,
        tangents: TANGENT_NORMAL | TANGENT_SLIP,
        ..Default::default()
    };
    let r = m.step(&s, &mut t, &i, &mut m.work()).unwrap();
    assert_eq!(r.tangents, TANGENT_NORMAL | TANGENT_SLIP);
    let f = |n: f64, ds: [f64; 2]| {
        let mut t = s.clone();
        m.step(&s, &mut t, &inc(n, ds, 2e-4), &mut m.work())
            .unwrap()
            .force
    };
    let (fp, fm) = (f(5.0 + 1e-3, i.slip), f(5.0 - 1e-3, i.slip));
    for c in 0..2 {
        let d = (fp[c] - fm[c]) / 2e-3;
        assert!((r.dforce_dnormal[c] - d).abs() <= 1e-9 * d.abs().max(1e-3));
    }
    for j in 0..2 {
        let h = 1e-11;
        let (mut p, mut q) = (i.slip, i.slip);
        p[j] += h;
        q[j] -= h;
        let (fp, fq) = (f(5.0, p), f(5.0, q));
        for c in 0..2 {
            let d = (fp[c] - fq[c]) / (2.0 * h);
            assert!(
                (r.dforce_dslip[c][j] - d).abs() <= 1e-4 * d.abs().max(1.0),
                "[{c}][{j}]: {} vs {d}",
                r.dforce_dslip[c][j]
            );
        }
    }
}

#[test]
fn lugre_bad_input_names_the_argument() {
    let inf = f64::INFINITY;
    for (args, want) in [
        ((-0.1, 0.5, 1e-3, 2.0, 1e5, 0.0, inf, 0.0), "mu_coulomb"),
        ((0.0, 0.0, 1e-3, 2.0, 1e5, 0.0, inf, 0.0), "mu_static"),
        (
            (0.3, 0.5, 0.0, 2.0, 1e5, 0.0, inf, 0.0),
            "stribeck_velocity",
        ),
        (
            (0.3, 0.5, 1e-3, f64::NAN, 1e5, 0.0, inf, 0.0),
            "stribeck_exponent",
        ),
        ((0.3, 0.5, 1e-3, 2.0, 0.0, 0.0, inf, 0.0), "sigma0"),
        ((0.3, 0.5, 1e-3, 2.0, 1e5, -1.0, inf, 0.0), "sigma1"),
        ((0.3, 0.5, 1e-3, 2.0, 1e5, 10.0, inf, 0.0), "sigma1"),
        ((0.3, 0.5, 1e-3, 2.0, 1e5, 1e4, 1e-3, 0.0), "sigma1"),
        (
            (0.3, 0.5, 1e-3, 2.0, 1e5, 0.0, 0.0, 0.0),
            "damping_velocity",
        ),
        ((0.3, 0.5, 1e-3, 2.0, 1e5, 0.0, inf, -1.0), "sigma2"),
    ] {
        let (a, b, c, d, e, f, g, h) = args;
        assert_eq!(name(LuGre::new(a, b, c, d, e, f, g, h).unwrap_err()), want);
    }
    let m = lugre();
    let s = vec![0.0; m.state_len()];
    let mut t = vec![7.0; m.state_len()];
    for (i, want) in [
        (inc(-1.0, [0.0; 2], 1.0), "normal_force"),
        (inc(f64::NAN, [0.0; 2], 1.0), "normal_force"),
        (inc(1.0, [inf, 0.0], 1.0), "slip"),
        (inc(1.0, [1e-6, 0.0], 0.0), "dt"),
        (inc(1.0, [1e-6, 0.0], -1.0), "dt"),
        (
            FrictionIncrement {
                tangents: 4,
                ..inc(1.0, [0.0; 2], 1.0)
            },
            "tangents",
        ),
    ] {
        assert_eq!(
            name(m.step(&s, &mut t, &i, &mut m.work()).unwrap_err()),
            want
        );
        assert!(t.iter().all(|&x| x == 7.0), "new untouched on failure");
    }
    let mut bad = s.clone();
    bad[STATE_DISSIPATION] = -1.0;
    assert_eq!(
        name(
            m.step(&bad, &mut t, &inc(1.0, [0.0; 2], 1.0), &mut m.work())
                .unwrap_err()
        ),
        "old.dissipation"
    );
    bad[STATE_DISSIPATION] = 0.0;
    bad[asperity::friction::dynamic::lugre::STATE_Z] = f64::NAN;
    assert_eq!(
        name(
            m.step(&bad, &mut t, &inc(1.0, [0.0; 2], 1.0), &mut m.work())
                .unwrap_err()
        ),
        "old"
    );
    let mut short = vec![0.0; 3];
    assert_eq!(
        name(
            m.step(&s, &mut short, &inc(1.0, [0.0; 2], 1.0), &mut m.work())
                .unwrap_err()
        ),
        "new.len()"
    );
}

// -------------------------------------------------------- Maxwell-slip

fn maxwell() -> MaxwellSlip {
    // Five elements, reaches μᵢ/kᵢ = 1, 2, 4, 4, 8 µm.
    let k = [2e5, 1e5, 5e4, 2.5e4, 1.25e4];
    let mu = [0.2, 0.2, 0.2, 0.1, 0.1];
    MaxwellSlip::new(&k, &mu, 0.0).unwrap()
}

/// Walks a 1-D path of slip positions in increments of at most `h`,
/// returning the force (along +x, the force the counter-surface needs to
/// apply to drive the point: −F) at each target.
fn walk(m: &MaxwellSlip, n: f64, path: &[f64], h: f64) -> Vec<f64> {
    let mut s = vec![0.0; m.state_len()];
    let mut t = s.clone();
    let mut x = 0.0;
    let mut out = vec![];
    for &target in path {
        let steps = ((target - x).abs() / h).ceil().max(1.0) as usize;
        let d = (target - x) / steps as f64;
        let mut f = 0.0;
        for _ in 0..steps {
            let r = m
                .step(&s, &mut t, &inc(n, [d, 0.0], 1.0), &mut m.work())
                .unwrap();
            s.copy_from_slice(&t);
            f = -r.force[0];
        }
        x = target;
        out.push(f);
    }
    out
}

#[test]
fn maxwell_slip_obeys_the_masing_rules() {
    let m = maxwell();
    let n = 3.0;
    // Virgin loading from rest.
    let xs: Vec<f64> = (1..=40).map(|i| i as f64 * 0.7e-6).collect();
    let f = walk(&m, n, &xs, 0.3e-6);
    for (x, f) in xs.iter().zip(&f) {
        let want = m.virgin_force(n, *x);
        assert!(
            (f - want).abs() <= 1e-12 * want,
            "virgin at {x}: {f} vs {want}"
        );
    }
    // Load to x_r = 9 µm, reverse: F(x) = F(x_r) − 2 F_v((x_r − x)/2).
    let xr = 9e-6;
    let mut path = vec![xr];
    let back: Vec<f64> = (1..=50).map(|i| xr - i as f64 * 0.6e-6).collect();
    path.extend(&back);
    let f = walk(&m, n, &path, 0.25e-6);
    let fr = m.virgin_force(n, xr);
    for (x, got) in back.iter().zip(&f[1..]) {
        let want = fr - 2.0 * m.virgin_force(n, (xr - x) / 2.0);
        assert!(
            (got - want).abs() <= 1e-12 * fr,
            "unloading at {x}: {got} vs {want}"
        );
    }
    // Gross sliding: |F| = N Σμ.
    assert!((f.last().unwrap() + n * m.static_coefficient()).abs() <= 1e-12 * n);
}

#[test]
fn maxwell_slip_forgets_closed_inner_loops() {
    let m = maxwell();
    let n = 1.5;
    // Load to 6 µm, inner loop down to 2 µm and back to 6, then on to 10:
    // the force at 6 and beyond is the virgin curve's (non-local memory).
    let f = walk(&m, n, &[6e-6, 2e-6, 6e-6, 8e-6, 10e-6], 0.2e-6);
    for (x, got) in [(6e-6, f[2]), (8e-6, f[3]), (10e-6, f[4])] {
        let want = m.virgin_force(n, x);
        assert!((got - want).abs() <= 1e-12 * want, "{x}: {got} vs {want}");
    }
    // An open inner loop (reload to 5 µm only) is remembered: the force at
    // 5 µm lies below the virgin curve.
    let f = walk(&m, n, &[6e-6, 2e-6, 5e-6], 0.2e-6);
    assert!(f[2] < m.virgin_force(n, 5e-6) - 1e-3 * n);
}

#[test]
fn maxwell_slip_work_equals_dissipation_plus_stored_energy() {
    // A random 1-D path cut into fine sub-increments: the trapezoidal work
    // of the force converges to Σ dissipation + ΔE (exact for each
    // sub-increment in which no element changes regime).
    let m = maxwell();
    let n = 2.0;
    let mut seed = 9;
    let mut s = vec![0.0; m.state_len()];
    let mut t = s.clone();
    let (mut work, mut dissipated, mut f_old) = (0.0, 0.0, 0.0);
    let mut last_energy = 0.0;
    for _ in 0..200 {
        let target = 30e-6 * (rng(&mut seed) - 0.5);
        for _ in 0..100 {
            let d = target / 100.0 * (0.5 + rng(&mut seed));
            let r = m
                .step(&s, &mut t, &inc(n, [d, 0.0], 1.0), &mut m.work())
                .unwrap();
            let f_new = -r.force[0];
            work += 0.5 * (f_old + f_new) * d;
            dissipated += r.dissipated;
            f_old = f_new;
            last_energy = r.stored_energy;
            s.copy_from_slice(&t);
        }
    }
    let total = dissipated + last_energy;
    assert!(
        (work - total).abs() <= 2e-3 * total,
        "work {work} vs dissipation + stored {total}"
    );
    assert!(dissipated > 0.0);
}

#[test]
fn maxwell_slip_random_increments() {
    random_increments(&maxwell(), 4, false);
    let viscous = MaxwellSlip::new(&[1e5, 3e4], &[0.25, 0.35], 0.8).unwrap();
    random_increments(&viscous, 5, false);
}

/// The element deflections δᵢ (m, 2-D) of a Maxwell-slip state.
fn deflections(s: &[f64]) -> Vec<[f64; 2]> {
    s[STATE_MODEL..].chunks(2).map(|d| [d[0], d[1]]).collect()
}

/// The regime the trial deflections tᵢ = δᵢ + Δs predict (elements of
/// reach `reach`), and how close (relative to rᵢ) the nearest element is to
/// its stick–slip switch |tᵢ| = rᵢ.
fn maxwell_trial(old: &[f64], reach: &[f64], ds: [f64; 2]) -> (i32, f64) {
    let mut slipping = 0;
    let mut nearest = f64::INFINITY;
    for (d, &r) in deflections(old).iter().zip(reach) {
        let t = (d[0] + ds[0]).hypot(d[1] + ds[1]);
        slipping += (t > r) as usize;
        nearest = nearest.min((t - r).abs() / r);
    }
    let regime = match slipping {
        0 => 0,
        s if s == reach.len() => 2,
        _ => 1,
    };
    (regime, nearest)
}

/// Maxwell-slip's consistent tangents (the radial return of five elements
/// of reach 1–8 µm, σ₂ = 0 and 0.8 N·s/m) against central differences of
/// the step (`common/tangents.rs`), to 1e-6: stick, partial slip, gross
/// slip and either side of each element's stick–slip switch (1e-5 of its
/// reach away), in 2-D, from a fresh and a loaded state; N = 0 (no
/// contact: dF/dN from above, dF/dΔs = −σ₂/Δt I); elements without
/// break-away force (μᵢ = 0) neither slip nor stiffen.
#[test]
fn maxwell_slip_tangents_match_finite_differences() {
    let (k, mu) = ([2e5, 1e5, 5e4, 2.5e4, 1.25e4], [0.2, 0.2, 0.2, 0.1, 0.1]);
    let reach = [0, 1, 2, 3, 4].map(|e| mu[e] / k[e]);
    let dirs = [[1.0, 0.0], [0.6, -0.8], [-0.28, 0.96]];
    let dt = 0.5;
    let mut checked = 0;
    let mut seen = [false; 3];
    for sigma2 in [0.0, 0.8] {
        let m = MaxwellSlip::new(&k, &mu, sigma2).unwrap();
        let fresh = vec![0.0; m.state_len()];
        let mut loaded = fresh.clone();
        for ds in [[9e-6, 1e-6], [-3e-6, 5e-6], [5e-7, -2e-6]] {
            m.step_in_place(&mut loaded, &inc(1.0, ds, dt), &mut m.work())
                .unwrap();
        }
        for old in [&fresh, &loaded] {
            for n in [4.0, 0.5] {
                let mut points: Vec<(String, [f64; 2])> = vec![];
                for d in dirs {
                    for size in [1e-8, 2e-6, 6e-6, 4e-5] {
                        points.push((format!("{size:e}"), [size * d[0], size * d[1]]));
                    }
                    // Either side of element e's switch |δₑ + s u| = rₑ(1 ± 1e-5).
                    for (e, de) in deflections(old).into_iter().enumerate() {
                        for f in [1.0 - 1e-5, 1.0 + 1e-5] {
                            let du = de[0] * d[0] + de[1] * d[1];
                            let rr = reach[e] * f;
                            let s =
                                -du + (du * du - (de[0] * de[0] + de[1] * de[1]) + rr * rr).sqrt();
                            if s.is_finite() {
                                points.push((
                                    format!("element {e} at {f} of its reach"),
                                    [s * d[0], s * d[1]],
                                ));
                            }
                        }
                    }
                }
                for (what, ds) in points {
                    let i = inc(n, ds, dt);
                    let label = format!("σ₂ = {sigma2}, N = {n}, {what}, Δs = {ds:?}");
                    let fd = tangents::fd_check(&m, old, &i, 1e-7 * n, 1e-13, &label);
                    let (regime, nearest) = maxwell_trial(old, &reach, ds);
                    assert_eq!(fd.response.regime, regime, "{label}");
                    seen[regime as usize] = true;
                    if nearest > 1e-6 {
                        // No switch within the steps (1e-13 m ≤ 1e-7 of
                        // every reach).
                        assert!(fd.both(), "{label}: a kink within the steps? {fd:?}");
                    }
                    checked += fd.both() as usize;
                }
            }
        }
        // N = 0: no contact. F = σ₂Δs/Δt; dF/dN = −Σ kᵢδᵢ (from above, the
        // springs' pull per unit load), dF/dΔs = −σ₂/Δt I.
        for ds in [[2e-6, -1e-6], [0.0, 0.0], [-3e-5, 1e-5]] {
            let i = inc(0.0, ds, dt);
            let label = format!("σ₂ = {sigma2}, N = 0, Δs = {ds:?}");
            let fd = tangents::fd_check(&m, &loaded, &i, 1e-7, 1e-13, &label);
            let r = fd.response;
            assert_eq!(r.regime, 3, "{label}: no contact");
            assert_eq!(
                r.force,
                [-sigma2 * ds[0] / dt, -sigma2 * ds[1] / dt],
                "{label}"
            );
            assert_eq!(r.stored_energy, 0.0);
            let viscous = sigma2 * (ds[0] * ds[0] + ds[1] * ds[1]) / dt;
            assert!((r.dissipated - viscous).abs() <= 1e-15 * viscous, "{label}");
            let c = sigma2 / dt;
            assert_eq!(r.dforce_dslip, [[-c, 0.0], [0.0, -c]], "{label}");
            // No contact releases the elements; dF/dN is from above: the
            // deflections the same slip gives under load.
            let mut open = loaded.clone();
            m.step_in_place(&mut open, &i, &mut m.work()).unwrap();
            assert!(
                deflections(&open).iter().all(|d| *d == [0.0, 0.0]),
                "{label}"
            );
            let (mut t, mut spring) = (loaded.clone(), [0.0; 2]);
            m.step_in_place(&mut t, &inc(1.0, ds, dt), &mut m.work())
                .unwrap();
            for (e, d) in deflections(&t).into_iter().enumerate() {
                spring[0] += k[e] * d[0];
                spring[1] += k[e] * d[1];
            }
            assert!(spring[0] != 0.0 && spring[1] != 0.0);
            assert_eq!(r.dforce_dnormal, [-spring[0], -spring[1]], "{label}");
            assert!(fd.both(), "{label}: {fd:?}");
        }
    }
    assert_eq!(
        seen, [true; 3],
        "stick, partial slip and gross slip all met"
    );
    assert!(checked > 200, "{checked} points checked");
    // An element without break-away force (μ = 0) never deflects: no
    // stiffness, no slip (the other element's stick is stick), and alone
    // it slides freely (gross slip whenever Δs ≠ 0).
    let m = MaxwellSlip::new(&[2e5, 5e4], &[0.2, 0.0], 0.0).unwrap();
    let fresh = vec![0.0; m.state_len()];
    for ds in [[0.0, 0.0], [1e-8, -2e-8]] {
        let fd = tangents::fd_check(&m, &fresh, &inc(3.0, ds, dt), 3e-7, 1e-13, "μ = 0 element");
        let r = fd.response;
        assert_eq!(r.regime, 0, "{r:?}");
        assert_eq!(r.dforce_dslip, [[-3.0 * 2e5, 0.0], [0.0, -3.0 * 2e5]]);
        assert!(fd.both(), "{fd:?}");
    }
    let free = MaxwellSlip::new(&[1e5], &[0.0], 0.0).unwrap();
    let mut new = vec![0.0; free.state_len()];
    for (ds, regime) in [([0.0, 0.0], 0), ([1e-8, 0.0], 2)] {
        let r = free
            .step(
                &[0.0; 4],
                &mut new,
                &FrictionIncrement {
                    tangents: TANGENT_SLIP,
                    ..inc(3.0, ds, dt)
                },
                &mut free.work(),
            )
            .unwrap();
        assert_eq!(
            (r.regime, r.force, r.dforce_dslip),
            (regime, [-0.0, -0.0], [[-0.0; 2]; 2])
        );
        assert_eq!(new[STATE_MODEL..], [0.0; 2], "never deflects");
    }
}

#[test]
fn maxwell_slip_bad_input_names_the_argument() {
    assert_eq!(
        name(MaxwellSlip::new(&[], &[], 0.0).unwrap_err()),
        "capacity.len()"
    );
    assert_eq!(
        name(MaxwellSlip::new(&[1.0], &[0.1, 0.2], 0.0).unwrap_err()),
        "capacity.len()"
    );
    assert_eq!(
        name(MaxwellSlip::new(&[0.0], &[0.1], 0.0).unwrap_err()),
        "stiffness"
    );
    assert_eq!(
        name(MaxwellSlip::new(&[1.0], &[-0.1], 0.0).unwrap_err()),
        "capacity"
    );
    assert_eq!(
        name(MaxwellSlip::new(&[1.0], &[0.1], f64::NAN).unwrap_err()),
        "sigma2"
    );
    let m = maxwell();
    let s = vec![0.0; m.state_len()];
    let mut t = vec![7.0; m.state_len()];
    assert_eq!(
        name(
            m.step(&s, &mut t, &inc(-1.0, [0.0; 2], 1.0), &mut m.work())
                .unwrap_err()
        ),
        "normal_force"
    );
    assert!(t.iter().all(|&x| x == 7.0), "new untouched on failure");
    // A rate-independent model accepts dt = 0 with a slip.
    m.step(&s, &mut t, &inc(1.0, [1e-6, 0.0], 0.0), &mut m.work())
        .unwrap();
}

// ------------------------------------------- one interface, block calls

use asperity::friction::dynamic::DynamicModel;

/// A block of the points `normal`, `slip` at `dt` (no areas), the states
/// stepped in place.
fn in_place<'a>(
    normal: &'a [f64],
    slip: &'a [f64],
    dt: f64,
    states: &'a mut [f64],
    forces: &'a mut [f64],
    dissipation: Option<&'a mut [f64]>,
) -> FrictionBlock<'a> {
    FrictionBlock {
        normal_force: normal,
        area: None,
        slip,
        dt,
        tangents: 0,
        states: BlockStates::InPlace(states),
        tangential_force: Some(forces),
        dissipation,
        responses: None,
    }
}

#[test]
fn model_choice_in_place_and_block_equal_the_single_steps() {
    for model in [
        DynamicModel::LuGre(lugre()),
        DynamicModel::MaxwellSlip(maxwell()),
        DynamicModel::PrandtlTomlinson(tomlinson(3.0, 1e-3)),
        DynamicModel::PrandtlTomlinson(two_spring(3.0)),
        DynamicModel::BurridgeKnopoff(chain(5, 1e4, 0.05)),
        DynamicModel::Bristles(brush()),
        DynamicModel::GeneralizedMaxwellSlip(
            GeneralizedMaxwellSlip::new(&[2e5, 5e4], &[0.5, 0.5], 0.3, 0.5, 1e-3, 2.0, 30.0, 0.1)
                .unwrap(),
        ),
    ] {
        let direct: &dyn FrictionLaw = match &model {
            DynamicModel::LuGre(m) => m,
            DynamicModel::MaxwellSlip(m) => m,
            DynamicModel::GeneralizedMaxwellSlip(m) => m,
            DynamicModel::PrandtlTomlinson(m) => m,
            DynamicModel::BurridgeKnopoff(m) => m,
            DynamicModel::Bristles(m) => m,
        };
        let m = model.state_len();
        assert_eq!(m, direct.state_len());
        let points = 5;
        let normal: Vec<f64> = (0..points).map(|i| 1.0 + i as f64).collect();
        let track = matches!(
            model,
            DynamicModel::PrandtlTomlinson(_)
                | DynamicModel::BurridgeKnopoff(_)
                | DynamicModel::Bristles(_)
                | DynamicModel::GeneralizedMaxwellSlip(_)
        );
        let slip: Vec<f64> = (0..2 * points)
            .map(|i| {
                if track && i % 2 == 1 {
                    0.0
                } else {
                    1e-7 * (i as f64 - 4.5)
                }
            })
            .collect();
        let dt = 1e-4;
        let mut states = vec![0.0; points * m];
        let mut forces = vec![0.0; 2 * points];
        let mut diss = vec![0.0; points];
        let mut single = vec![vec![0.0; m]; points];
        for round in 0..4 {
            model
                .step_block(
                    in_place(
                        &normal,
                        &slip,
                        dt,
                        &mut states,
                        &mut forces,
                        Some(&mut diss),
                    ),
                    &mut model.work(),
                )
                .unwrap();
            for i in 0..points {
                let inc = inc(normal[i], [slip[2 * i], slip[2 * i + 1]], dt);
                let mut next = vec![0.0; m];
                let r = direct
                    .step(&single[i], &mut next, &inc, &mut direct.work())
                    .unwrap();
                let mut in_place = single[i].clone();
                let q = model
                    .step_in_place(&mut in_place, &inc, &mut model.work())
                    .unwrap();
                assert_eq!(format!("{r:?}"), format!("{q:?}"));
                assert_eq!(in_place, next);
                single[i] = next;
                assert_eq!([forces[2 * i], forces[2 * i + 1]], r.force, "{round} {i}");
                assert_eq!(diss[i], r.dissipated);
                assert_eq!(&states[i * m..(i + 1) * m], &single[i][..]);
            }
        }
        // An error at point 3 names it; points 0..3 are written.
        let mut bad = normal.clone();
        bad[3] = -1.0;
        let before = states.clone();
        let e = model
            .step_block(
                in_place(&bad, &slip, dt, &mut states, &mut forces, None),
                &mut model.work(),
            )
            .unwrap_err();
        assert_eq!((e.index, name(e.error)), (3, "normal_force"));
        assert_ne!(&states[..3 * m], &before[..3 * m]);
        assert_eq!(&states[3 * m..], &before[3 * m..]);
        let e = model
            .step_block(
                in_place(&normal, &slip[1..], dt, &mut states, &mut forces, None),
                &mut model.work(),
            )
            .unwrap_err();
        assert_eq!((e.index, name(e.error)), (0, "slip.len()"));
        // In place: a bad state is refused and left untouched.
        let mut s = vec![0.0; m];
        s[STATE_SLIP_PATH] = -1.0;
        let e = model
            .step_in_place(&mut s, &inc(1.0, [0.0; 2], 1.0), &mut model.work())
            .unwrap_err();
        assert_eq!(name(e), "state.slip_path");
        assert_eq!(s[STATE_SLIP_PATH], -1.0);
    }
}

// --------------------------------------------------- Prandtl–Tomlinson

use asperity::friction::dynamic::PrandtlTomlinson;

/// A tip on a lattice of period 0.3 nm, spring k = 1 N/m, mass 1e-12 kg
/// (ω = 1e6 /s), at Tomlinson parameter `eta`, damping ratio about `zeta`.
fn tomlinson(eta: f64, zeta: f64) -> PrandtlTomlinson {
    let (a, k, m) = (3e-10, 1.0, 1e-12);
    let u0 = eta * k * a * a / (4.0 * std::f64::consts::PI.powi(2));
    let gamma = 2.0 * zeta * (k * m).sqrt();
    PrandtlTomlinson::new(u0, a, k, m, gamma, 1e-9).unwrap()
}

/// Drives the support over `lattice` periods at speed `v` in increments
/// of `dt`; returns (max lateral force, mean lateral force, max tip speed,
/// total dissipation, the work of the end-of-increment force).
fn drive(m: &PrandtlTomlinson, v: f64, periods: f64, dt: f64) -> (f64, f64, f64, f64, f64) {
    let a = 3e-10;
    let steps = (periods * a / (v * dt)).round() as usize;
    let mut s = vec![0.0; m.state_len()];
    let (mut fmax, mut fsum, mut vmax, mut work) = (0.0f64, 0.0, 0.0f64, 0.0);
    let mut f_old = 0.0;
    let mut d = 0.0;
    for k in 0..steps {
        let r = m
            .step_in_place(&mut s, &inc(1.0, [v * dt, 0.0], dt), &mut m.work())
            .unwrap();
        let f = -r.force[0]; // resisting force felt along the motion
        if k > steps / 4 {
            fmax = fmax.max(f);
            fsum += f;
            vmax =
                vmax.max(s[asperity::friction::dynamic::prandtl_tomlinson::STATE_VELOCITY].abs());
        }
        work += 0.5 * (f + f_old) * v * dt;
        f_old = f;
        d += r.dissipated;
    }
    (fmax, fsum / (steps - steps / 4 - 1) as f64, vmax, d, work)
}

#[test]
fn prandtl_tomlinson_sticks_and_slips_only_above_eta_one() {
    let v = 1e-6; // 1 µm/s: quasi-static (a/v = 3e-4 s ≫ 1/ω = 1e-6 s)
    let dt = 1e-6;
    // η = 0.5: smooth sliding, the tip follows at about the support speed,
    // no friction in the quasi-static limit.
    let smooth = tomlinson(0.5, 0.5);
    assert!(smooth.eta() < 1.0);
    let (fmax, fmean, vmax, d, _) = drive(&smooth, v, 4.0, dt * 50.0);
    println!("eta 0.5: Fmax {fmax:e}, Fmean {fmean:e}, vmax {vmax:e}, D {d:e}");
    assert!(
        vmax < 5.0 * v,
        "no slip events: max tip speed {vmax} vs support {v}"
    );
    // Only the tip's viscous drag γv remains (1e-12 N here).
    assert!(fmean.abs() < 0.05 * smooth.lattice_force(), "{fmean}");
    // η = 3: stick-slip, slip events far faster than the support, a finite
    // mean friction force and dissipation per period.
    let sticky = tomlinson(3.0, 0.5);
    let (fmax, fmean, vmax, d, work) = drive(&sticky, v, 4.0, dt);
    println!("eta 3: Fmax {fmax:e}, Fmean {fmean:e}, vmax {vmax:e}, D {d:e}, W {work:e}");
    assert!(vmax > 30.0 * v, "slip events: max tip speed {vmax}");
    assert!(fmean > 0.1 * sticky.lattice_force() && fmax <= sticky.lattice_force() * 1.01);
    assert!(fmax > fmean, "static above kinetic");
    // The work of the support goes into dissipation (the stored energy is
    // bounded): over 4 periods they agree to a few per cent.
    assert!(
        (work - d).abs() < 0.05 * d,
        "work {work:e} vs dissipation {d:e}"
    );
}

#[test]
fn prandtl_tomlinson_energy_balance_and_bad_input() {
    // Random increments: dissipation ≥ 0, cut-backs exact.
    random_path(&tomlinson(2.0, 0.3), 7, true, true);
    let m = tomlinson(2.0, 0.3);
    let s = vec![0.0; m.state_len()];
    let mut t = vec![7.0; m.state_len()];
    assert_eq!(
        name(
            m.step(&s, &mut t, &inc(1.0, [1e-9, 1e-9], 1e-3), &mut m.work())
                .unwrap_err()
        ),
        "slip"
    );
    assert!(t.iter().all(|&x| x == 7.0));
    for (args, want) in [
        ((0.0, 3e-10, 1.0, 1e-12, 0.0, 1e-9), "amplitude"),
        ((1e-20, 0.0, 1.0, 1e-12, 0.0, 1e-9), "period"),
        ((1e-20, 3e-10, -1.0, 1e-12, 0.0, 1e-9), "stiffness"),
        ((1e-20, 3e-10, 1.0, 0.0, 0.0, 1e-9), "mass"),
        ((1e-20, 3e-10, 1.0, 1e-12, -1.0, 1e-9), "damping"),
        ((1e-20, 3e-10, 1.0, 1e-12, 0.0, 0.5), "tolerance"),
    ] {
        let (a, b, c, d, e, f) = args;
        assert_eq!(
            name(PrandtlTomlinson::new(a, b, c, d, e, f).unwrap_err()),
            want
        );
    }
}

// ------------------------------------------ Prandtl–Tomlinson, two springs

use asperity::friction::dynamic::{stick_slip, StickSlip};

/// Drives `m` (one or two springs) over `periods` lattice periods of
/// 0.3 nm at speed `v` in increments of `dt`; returns the history of the
/// resisting force on the support (N), its slip increments and the total
/// dissipation, every increment checked for dissipation ≥ 0.
fn history(m: &PrandtlTomlinson, v: f64, periods: f64, dt: f64) -> (Vec<f64>, Vec<f64>, f64) {
    let steps = (periods * 3e-10 / (v * dt)).round() as usize;
    let mut s = vec![0.0; m.state_len()];
    let (mut f, mut d) = (Vec::with_capacity(steps), 0.0);
    for _ in 0..steps {
        let r = m
            .step_in_place(&mut s, &inc(1.0, [v * dt, 0.0], dt), &mut m.work())
            .unwrap();
        assert!(r.dissipated >= 0.0 && r.force[0].is_finite());
        f.push(-r.force[0]);
        d += r.dissipated;
    }
    (f, vec![v * dt; steps], d)
}

/// The stick-slip analysis of a run, counting drops above 2 % of the
/// lattice force.
fn analyse(m: &PrandtlTomlinson, f: &[f64], s: &[f64]) -> StickSlip {
    stick_slip(f, s, 0.02 * m.lattice_force()).unwrap()
}

/// A tip and a cantilever body of equal springs k_t = k_c = 2 N/m in
/// series (k_eff = 1 N/m), masses 1e-12 kg, damping ratios about 0.5, on
/// the 0.3 nm lattice at Tomlinson parameter `eta` (of k_eff).
fn two_spring(eta: f64) -> PrandtlTomlinson {
    let (a, k, m) = (3e-10, 2.0, 1e-12);
    let u0 = eta * 1.0 * a * a / (4.0 * std::f64::consts::PI.powi(2));
    let gamma = f64::sqrt(k * m);
    PrandtlTomlinson::two_spring(u0, a, k, m, gamma, k, m, gamma, 1e-9).unwrap()
}

/// The quasi-static kinetic friction of the Prandtl–Tomlinson model at
/// η = 4π²U₀/(k a²) > 1 (k the effective stiffness): the energy lost in the
/// jump of each lattice period over the period, ΔE/a (N). The tip jumps
/// from x₁, where k + U''(x₁) = 0, to the equilibrium x₂ of the next stable
/// region (found by bisection) at the same support position.
fn quasi_static_kinetic(u0: f64, a: f64, k: f64) -> f64 {
    let w = 2.0 * std::f64::consts::PI / a;
    let eta = w * w * u0 / k;
    let x1 = (-1.0 / eta).acos() / w;
    let xs = x1 + u0 * w * (w * x1).sin() / k;
    let g = |x: f64| k * (x - xs) + u0 * w * (w * x).sin();
    let (mut lo, mut hi) = ((2.0 * std::f64::consts::PI - (-1.0 / eta).acos()) / w, 0.0);
    hi += lo + a / 2.0;
    assert!(g(lo) < 0.0 && g(hi) > 0.0);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if g(mid) < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let energy = |x: f64| 0.5 * k * (x - xs).powi(2) - u0 * (w * x).cos();
    (energy(x1) - energy(lo)) / a
}

#[test]
fn prandtl_tomlinson_stick_slip_follows_the_effective_stiffness() {
    // Quasi-static: a/V = 0.03 s against natural periods of ~1e-6 s (the
    // delay of the jumps, ~a (V/(aω))^{2/3}, is 0.1 % of a period).
    let (v, dt) = (1e-8, 1e-4);
    for eta in [0.5, 1.5, 3.0] {
        let one = tomlinson(eta, 0.5);
        let two = two_spring(eta);
        assert!((two.eta() - eta).abs() < 1e-12 * eta && two.is_two_spring());
        assert!((two.effective_stiffness() - 1.0).abs() < 1e-15);
        // Each spring alone would give η/2: on the smooth side for 1.5.
        assert_eq!(two.state_len(), one.state_len() + 2);
        for m in [&one, &two] {
            let (f, s, d) = history(m, v, 4.0, dt);
            // The first period loads from rest; analyse the last three.
            let q = f.len() / 4;
            let r = analyse(m, &f[q..], &s[q..]);
            println!(
                "eta {eta}, two springs {}: {} events, static {:e}, kinetic {:e}, D {d:e}",
                m.is_two_spring(),
                r.events.len(),
                r.static_force / m.lattice_force(),
                r.kinetic_force / m.lattice_force(),
            );
            if eta < 1.0 {
                assert!(!r.is_stick_slip(), "{:?}", r.events);
            } else {
                // One event per lattice period.
                assert!((2..=3).contains(&r.events.len()), "{:?}", r.events);
                let spacing = r.mean_spacing().unwrap();
                assert!((spacing / 3e-10 - 1.0).abs() < 0.02, "{spacing:e}");
                // Quasi-statically the force peaks at the lattice force (at
                // x = a/4, still stable for any η) and falls to
                // F_L √(1 − 1/η²) before the tip jumps.
                let fl = m.lattice_force();
                assert!((r.static_force / fl - 1.0).abs() < 0.005);
                let jump = fl * ((1.0 - 1.0 / (eta * eta)).sqrt() + 0.5);
                assert!(
                    r.events.iter().all(|e| e.jump > 0.5 * jump),
                    "{:?}",
                    r.events
                );
                // The kinetic friction is the energy of the jumps per period
                // (plus a little viscous drag).
                let want = quasi_static_kinetic(
                    m.lattice_force() * 3e-10 / (2.0 * std::f64::consts::PI),
                    3e-10,
                    m.effective_stiffness(),
                );
                assert!(
                    (r.kinetic_force / want - 1.0).abs() < 0.03,
                    "kinetic {:e} vs {want:e}",
                    r.kinetic_force
                );
            }
        }
    }
}

#[test]
fn two_spring_prandtl_tomlinson_tends_to_one_spring() {
    // k_t → ∞ and m_c → 0: the tip rides the cantilever. At k_t = 1e3 k
    // and m_c = 1e-4 m the forces on the support agree to the compliance
    // ratio, pointwise in smooth sliding and in the events of stick-slip.
    let (a, k, m) = (3e-10, 1.0, 1e-12);
    for eta in [0.5, 3.0] {
        let one = tomlinson(eta, 0.5);
        let u0 = eta * k * a * a / (4.0 * std::f64::consts::PI.powi(2));
        let gamma = 2.0 * 0.5 * (k * m).sqrt();
        let two =
            PrandtlTomlinson::two_spring(u0, a, 1e3 * k, m, gamma, k, 1e-4 * m, 0.0, 1e-9).unwrap();
        assert!((two.eta() / one.eta() - 1.0 - 1e-3).abs() < 1e-6);
        // Fast enough to keep the run short: 10 natural periods per
        // lattice period.
        let v = 3e-10 * 1e6 / 60.0;
        let (f1, s, _) = history(&one, v, 3.0, 1e-8);
        let (f2, _, _) = history(&two, v, 3.0, 1e-8);
        let fl = one.lattice_force();
        let worst = f1
            .iter()
            .zip(&f2)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        let (r1, r2) = (analyse(&one, &f1, &s), analyse(&two, &f2, &s));
        println!(
            "eta {eta}: worst {:.2e} F_L; events {} {}; static {:e} {:e}; kinetic {:e} {:e}",
            worst / fl,
            r1.events.len(),
            r2.events.len(),
            r1.static_force,
            r2.static_force,
            r1.kinetic_force,
            r2.kinetic_force
        );
        assert_eq!(r1.events.len(), r2.events.len());
        assert!((r1.static_force - r2.static_force).abs() < 3e-3 * fl);
        assert!((r1.kinetic_force - r2.kinetic_force).abs() < 3e-3 * fl);
        if eta < 1.0 {
            assert!(worst < 0.01 * fl, "{worst:e}");
        }
    }
}

#[test]
fn two_spring_prandtl_tomlinson_energy_balance_and_bad_input() {
    // Random increments: dissipation ≥ 0, cut-backs bit-identical.
    random_path(&two_spring(2.0), 9, true, true);
    // Stick-slip at η = 3 over two periods in 10 ns increments: the
    // support's work (trapezoidal) = stored energy + dissipation.
    let m = two_spring(3.0);
    let (v, dt) = (1e-5, 1e-8);
    let mut s = vec![0.0; m.state_len()];
    let (mut work, mut d, mut before) = (0.0, 0.0, 0.0);
    let mut stored = 0.0;
    for _ in 0..(6e-10 / (v * dt)) as usize {
        let r = m
            .step_in_place(&mut s, &inc(1.0, [v * dt, 0.0], dt), &mut m.work())
            .unwrap();
        let f = -r.force[0];
        work += 0.5 * (before + f) * v * dt;
        before = f;
        d += r.dissipated;
        stored = r.stored_energy;
    }
    assert!(d > 0.0 && stored >= 0.0);
    assert!(
        (work - d - stored).abs() < 1e-3 * work,
        "work {work:e}, dissipation {d:e}, stored {stored:e}"
    );
    assert_eq!(
        s[asperity::friction::dynamic::prandtl_tomlinson::STATE_SUPPORT],
        s[STATE_SLIP_PATH]
    );
    for (args, want) in [
        ((0.0, 1.0, 1.0, 1.0, 1.0, 1.0), "tip_stiffness"),
        ((1.0, 0.0, 1.0, 1.0, 1.0, 1.0), "tip_mass"),
        ((1.0, 1.0, -1.0, 1.0, 1.0, 1.0), "tip_damping"),
        (
            (1.0, 1.0, 1.0, f64::INFINITY, 1.0, 1.0),
            "cantilever_stiffness",
        ),
        ((1.0, 1.0, 1.0, 1.0, 0.0, 1.0), "cantilever_mass"),
        ((1.0, 1.0, 1.0, 1.0, 1.0, f64::NAN), "cantilever_damping"),
    ] {
        let (a, b, c, e, f, g) = args;
        let r = PrandtlTomlinson::two_spring(
            1e-20,
            3e-10,
            a,
            b * 1e-12,
            c * 1e-6,
            e,
            f * 1e-12,
            g * 1e-6,
            1e-9,
        );
        assert_eq!(name(r.unwrap_err()), want);
    }
    assert_eq!(
        name(
            PrandtlTomlinson::two_spring(1e-20, 3e-10, 1.0, 1e-12, 0.0, 1.0, 1e-12, 0.0, 0.1)
                .unwrap_err()
        ),
        "tolerance"
    );
}

// ------------------------------------------------------ Burridge–Knopoff

use asperity::friction::dynamic::burridge_knopoff::state_block;
use asperity::friction::dynamic::BurridgeKnopoff;

/// M blocks of 10 mg on leaf springs k_p = 1000 N/m (ω = 1e4 /s), coupled
/// by `coupling` (N/m), μ_s = 0.5, μ_k = 0.3, weakening velocity `vc`
/// (m/s), no damping.
fn chain(blocks: usize, coupling: f64, vc: f64) -> BurridgeKnopoff {
    BurridgeKnopoff::new(blocks, 1e-5, coupling, 1e3, 0.5, 0.3, vc, 0.0, 1e-10).unwrap()
}

/// A run of the driver at `v` over `steps` increments of `dt` with the
/// normal force `n` from `state`: the resisting force history, the work
/// of the driver (trapezoidal), the total dissipation; dissipation ≥ 0 and
/// finite forces on every increment.
fn pull(
    m: &BurridgeKnopoff,
    state: &mut [f64],
    n: f64,
    v: f64,
    dt: f64,
    steps: usize,
) -> (Vec<f64>, f64, f64) {
    let (mut f, mut work, mut d) = (Vec::with_capacity(steps), 0.0, 0.0);
    let mut before = -m
        .step_in_place(state, &inc(n, [0.0; 2], 0.0), &mut m.work())
        .unwrap()
        .force[0];
    for k in 0..steps {
        let r = m
            .step_in_place(state, &inc(n, [v * dt, 0.0], dt), &mut m.work())
            .unwrap();
        assert!(r.dissipated >= 0.0, "{k}: {r:?}");
        assert!(r.force[0].is_finite() && r.stored_energy.is_finite());
        let now = -r.force[0];
        work += 0.5 * (before + now) * v * dt;
        before = now;
        d += r.dissipated;
        f.push(now);
    }
    (f, work, d)
}

#[test]
fn burridge_knopoff_uniform_chain_sticks_and_slips_with_the_one_block_period() {
    // Every block alike and at rest: the chain moves as one block, whose
    // stick-slip cycle with Coulomb static and kinetic friction (v_c = ∞)
    // has a closed-form period (BurridgeKnopoff::uniform_period):
    // 2(F_s − F_k)/(k_p V) of stick, about π/ω of slip.
    let (v, dt) = (0.01, 2e-5);
    let one = chain(1, 0.0, f64::INFINITY);
    let many = chain(16, 1e3, f64::INFINITY);
    let period = one.uniform_period(1.0, v);
    assert_eq!(period, many.uniform_period(16.0, v));
    let stick = 2.0 * (0.5 - 0.3) / (1e3 * v);
    let slip = std::f64::consts::PI / 1e4;
    assert!((period / (stick + slip) - 1.0).abs() < 0.01, "{period}");
    let steps = (9.0 * period / dt) as usize;
    let mut s1 = vec![0.0; one.state_len()];
    let mut s16 = vec![0.0; many.state_len()];
    // 1 N per block.
    let (f1, w1, d1) = pull(&one, &mut s1, 1.0, v, dt, steps);
    let (f16, _, d16) = pull(&many, &mut s16, 16.0, v, dt, steps);
    for (k, (a, b)) in f1.iter().zip(&f16).enumerate() {
        assert!((b / 16.0 - a).abs() < 1e-7, "{k}: {a} vs {}", b / 16.0);
    }
    assert!((d16 / 16.0 - d1).abs() < 1e-7 * d1);
    let slips = vec![v * dt; steps];
    let r = stick_slip(&f1, &slips, 0.01).unwrap();
    assert!(r.events.len() >= 8, "{:?}", r.events);
    // The period, to the increment's resolution (2e-5 s over 8 periods).
    let measured = r.mean_spacing().unwrap() / v;
    assert!(
        (measured / period - 1.0).abs() < 1e-3,
        "period {measured} vs {period}"
    );
    // Each event breaks away at F_s and drops by 2(F_s − F_k): the block
    // swings symmetrically about the kinetic force.
    for e in &r.events {
        assert!((e.peak_force - 0.5).abs() < 1e-3, "{e:?}");
        assert!((e.drop - 0.4).abs() < 2e-3, "{e:?}");
    }
    // Over whole cycles the mean force is F_k: the friction work per cycle
    // is F_k times the block's advance, V times the period.
    let (a, b) = (r.events[0].peak_index, r.events.last().unwrap().peak_index);
    let whole = stick_slip(&f1[a..b], &slips[a..b], 0.01).unwrap();
    assert!(
        (whole.kinetic_force - 0.3).abs() < 1e-3,
        "{}",
        whole.kinetic_force
    );
    // The driver's work is the dissipation plus the energy left stored.
    let stored =
        0.5 * 1e3 * s1[state_block(0)].powi(2) + 0.5 * 1e-5 * s1[state_block(0) + 1].powi(2);
    assert!((w1 - d1 - stored).abs() < 1e-4 * w1, "{w1} {d1} {stored}");
}

#[test]
fn burridge_knopoff_perturbed_chain_has_events_of_many_sizes_and_balances_energy() {
    // Velocity weakening, damping, one block displaced by 1 µm: the
    // uniform motion breaks up into events of many sizes (Carlson and
    // Langer 1989).
    let blocks = 16;
    let m = BurridgeKnopoff::new(blocks, 1e-5, 1e4, 1e3, 0.5, 0.3, 0.05, 0.01, 1e-10).unwrap();
    let mut s = vec![0.0; m.state_len()];
    s[state_block(5)] = -1e-6;
    let e0 = m
        .step(&s.clone(), &mut s, &inc(16.0, [0.0; 2], 0.0), &mut m.work())
        .unwrap()
        .stored_energy;
    assert!((e0 - 0.5 * (1e3 + 2.0 * 1e4) * 1e-12).abs() < 1e-20);
    let (v, dt) = (0.01, 2e-5);
    let (f, work, d) = pull(&m, &mut s, blocks as f64, v, dt, 16000);
    let end = m
        .step(&s.clone(), &mut s, &inc(16.0, [0.0; 2], 0.0), &mut m.work())
        .unwrap();
    // Energy: the driver's work (trapezoidal, second order in the
    // increment) = the change of stored energy + the dissipation.
    let balance = work - (end.stored_energy - e0) - d;
    println!(
        "work {work:e}, stored {:e}, D {d:e}, balance {balance:e}",
        end.stored_energy
    );
    assert!(balance.abs() < 1e-4 * work, "{balance:e} of {work:e}");
    let r = stick_slip(&f, &vec![v * dt; f.len()], 1e-3).unwrap();
    let drops: Vec<f64> = r.events.iter().map(|e| e.drop).collect();
    let (lo, hi) = drops
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(a, b), &x| (a.min(x), b.max(x)));
    println!("{} events, drops {lo:e} .. {hi:e}", drops.len());
    assert!(drops.len() >= 20 && hi > 20.0 * lo, "{drops:?}");
    // Small events are far below the whole chain's breaking away (16 F_s
    // less 16 F_k: 3.2 N), large ones reach it.
    assert!(lo < 0.1 && hi > 3.0, "{drops:?}");
}

#[test]
fn burridge_knopoff_random_increments_tangents_and_bad_input() {
    // Random host increments: dissipation ≥ 0, cut-backs bit-identical.
    random_path(&chain(5, 1e4, 0.05), 11, true, true);
    random_path(&chain(1, 0.0, f64::INFINITY), 12, true, true);
    // Equal static and kinetic friction (no drop at the onset of slip).
    let flat = BurridgeKnopoff::new(3, 1e-5, 1e3, 1e3, 0.4, 0.4, f64::INFINITY, 0.0, 1e-9).unwrap();
    random_path(&flat, 13, true, true);
    // Stuck chain: F = k_p Σ(x_i − x_d), dF/dΔs = −M k_p, dF/dN = 0.
    let m = chain(4, 1e3, 0.05);
    let mut s = vec![0.0; m.state_len()];
    let r = m
        .step_in_place(
            &mut s,
            &FrictionIncrement {
                normal_force: 4.0,
                slip: [1e-5, 0.0],
                dt: 1e-3,
                tangents: 3,
                ..Default::default()
            },
            &mut m.work(),
        )
        .unwrap();
    assert_eq!(r.regime, 0);
    assert!((r.force[0] + 4.0 * 1e3 * 1e-5).abs() < 1e-15, "{r:?}");
    assert!((r.dforce_dslip[0][0] + 4e3).abs() < 1e-6 * 4e3, "{r:?}");
    assert!(r.dforce_dnormal[0].abs() < 1e-9, "{r:?}");
    // Past the static reach (F_s/k_p = 0.5 mm) every block slides; the
    // tangents equal differences of separate increments.
    let tangent = FrictionIncrement {
        normal_force: 4.0,
        slip: [1e-3, 0.0],
        dt: 1e-2,
        tangents: 3,
        ..Default::default()
    };
    let r = m
        .step(&s, &mut vec![0.0; s.len()], &tangent, &mut m.work())
        .unwrap();
    assert_eq!(r.regime, 2, "{r:?}");
    let force = |n: f64, ds: f64| {
        m.step(
            &s,
            &mut vec![0.0; s.len()],
            &inc(n, [ds, 0.0], 1e-2),
            &mut m.work(),
        )
        .unwrap()
        .force[0]
    };
    let h = 1e-7;
    let dn = (force(4.0 + h, 1e-3) - force(4.0 - h, 1e-3)) / (2.0 * h);
    let ds = (force(4.0, 1e-3 + h * 1e-3) - force(4.0, 1e-3 - h * 1e-3)) / (2e-3 * h);
    println!("{r:?} {dn} {ds}");
    assert!((r.dforce_dnormal[0] / dn - 1.0).abs() < 1e-4, "{dn}");
    assert!((r.dforce_dslip[0][0] / ds - 1.0).abs() < 1e-4, "{ds}");
    // Bad input names the argument, the state untouched.
    let old = vec![0.0; m.state_len()];
    let mut t = vec![7.0; m.state_len()];
    assert_eq!(
        name(
            m.step(&old, &mut t, &inc(1.0, [1e-6, 1e-9], 1e-3), &mut m.work())
                .unwrap_err()
        ),
        "slip"
    );
    assert_eq!(
        name(
            m.step(&old, &mut t, &inc(1.0, [1e-6, 0.0], 0.0), &mut m.work())
                .unwrap_err()
        ),
        "dt"
    );
    assert!(t.iter().all(|&x| x == 7.0));
    let inf = f64::INFINITY;
    for (args, want) in [
        ((0, 1e-5, 1e3, 1e3, 0.5, 0.3, 0.05, 0.0, 1e-9), "blocks"),
        ((257, 1e-5, 1e3, 1e3, 0.5, 0.3, 0.05, 0.0, 1e-9), "blocks"),
        ((2, 0.0, 1e3, 1e3, 0.5, 0.3, 0.05, 0.0, 1e-9), "mass"),
        (
            (2, 1e-5, -1.0, 1e3, 0.5, 0.3, 0.05, 0.0, 1e-9),
            "coupling_stiffness",
        ),
        (
            (2, 1e-5, 1e3, inf, 0.5, 0.3, 0.05, 0.0, 1e-9),
            "pulling_stiffness",
        ),
        (
            (2, 1e-5, 1e3, 1e3, f64::NAN, 0.3, 0.05, 0.0, 1e-9),
            "mu_static",
        ),
        ((2, 1e-5, 1e3, 1e3, 0.5, 0.6, 0.05, 0.0, 1e-9), "mu_kinetic"),
        (
            (2, 1e-5, 1e3, 1e3, 0.5, 0.3, 0.0, 0.0, 1e-9),
            "weakening_velocity",
        ),
        ((2, 1e-5, 1e3, 1e3, 0.5, 0.3, 0.05, -1.0, 1e-9), "damping"),
        ((2, 1e-5, 1e3, 1e3, 0.5, 0.3, 0.05, 0.0, 1.0), "tolerance"),
    ] {
        let (a, b, c, d, e, f, g, h, i) = args;
        assert_eq!(
            name(BurridgeKnopoff::new(a, b, c, d, e, f, g, h, i).unwrap_err()),
            want
        );
    }
}

#[test]
fn burridge_knopoff_extremes_are_finite_or_name_dt() {
    // Chains of 1 to 256 blocks, stiffness ratios k_c/k_p of 0 to 1e6,
    // increments from 1e-12 s to 10 s at 1 cm/s: finite, or the sub-step
    // budget error naming dt; never a hang (the budget bounds the work).
    let started = std::time::Instant::now();
    let mut failures = 0;
    for (blocks, ratio) in [
        (1, 0.0),
        (2, 1e6),
        (7, 1.0),
        (64, 100.0),
        (256, 1.0),
        (256, 1e6),
    ] {
        let m = BurridgeKnopoff::new(blocks, 1e-5, ratio * 1e3, 1e3, 0.5, 0.3, 0.05, 0.0, 1e-9)
            .unwrap();
        for dt in [1e-12, 1e-6, 1e-3, 10.0] {
            let mut s = vec![0.0; m.state_len()];
            s[state_block(blocks / 2)] = -1e-6;
            let t = std::time::Instant::now();
            match m.step_in_place(
                &mut s,
                &inc(blocks as f64, [0.01 * dt, 0.0], dt),
                &mut m.work(),
            ) {
                Ok(r) => {
                    assert!(r.force[0].is_finite() && r.dissipated >= 0.0, "{r:?}");
                    assert!(s.iter().all(|x| x.is_finite()));
                }
                Err(Error::NotConverged { what, .. }) => {
                    assert!(what.contains("dt"), "{what}");
                    failures += 1;
                }
                Err(e) => panic!("M {blocks}, ratio {ratio}, dt {dt}: {e:?}"),
            }
            println!("M {blocks} ratio {ratio:e} dt {dt:e}: {:?}", t.elapsed());
        }
    }
    println!("{failures} budget errors in {:?}", started.elapsed());
    assert!(
        failures > 0,
        "the 10 s increments of stiff chains exceed the budget"
    );
}

/// Prandtl–Tomlinson pulled by a constant force (thesis (5-5)): the static
/// friction is the lattice force F_L = 2πU₀/a. Below it the tip settles at
/// x* = (a/2π) asin(F/F_L); above it, overdamped, it slides at the mean
/// velocity √(F² − F_L²)/γ. The work F·x equals the lattice, kinetic and
/// dissipated energy.
#[test]
fn prandtl_tomlinson_under_a_constant_force_depins_at_the_lattice_force() {
    use std::f64::consts::PI;
    // a = 1 nm, F_L = 1 nN, γ = 1e-3 N s/m; m/γ = 1e-6 s against the
    // lattice's relaxation time γa/(2πF_L) = 1.6e-4 s: overdamped.
    let (a, fl, gamma, mass) = (1e-9, 1e-9, 1e-3, 1e-9);
    let m = PrandtlTomlinson::new(fl * a / (2.0 * PI), a, 1.0, mass, gamma, 1e-9).unwrap();
    assert!((m.lattice_force() - fl).abs() <= 1e-15 * fl);
    let balance = |f: f64, p: &asperity::friction::dynamic::ForcePull| {
        let lattice = fl * a / (2.0 * PI) * (1.0 - (2.0 * PI * p.displacement / a).cos());
        let work = f * p.displacement;
        let rest = lattice + 0.5 * mass * p.velocity * p.velocity + p.dissipated;
        assert!((work - rest).abs() <= 1e-6 * work, "work {work} vs {rest}");
    };
    for ratio in [1.5, 2.0, 4.0] {
        let f = ratio * fl;
        let want = (f * f - fl * fl).sqrt() / gamma;
        let p = m.pull_by_force(f, 200.0 * a / want).unwrap();
        assert!(
            (p.mean_velocity / want - 1.0).abs() < 0.02,
            "F = {ratio} F_L: {} vs {want}",
            p.mean_velocity
        );
        balance(f, &p);
    }
    for ratio in [0.5, 0.9, 0.99] {
        let f = ratio * fl;
        let p = m.pull_by_force(f, 0.05).unwrap();
        let settled = a / (2.0 * PI) * ratio.asin();
        assert!(
            (p.displacement - settled).abs() <= 1e-4 * a,
            "F = {ratio} F_L: {} vs {settled}",
            p.displacement
        );
        assert!(p.velocity.abs() <= 1e-6 * fl / gamma, "{p:?}");
        balance(f, &p);
    }
    assert_eq!(m.pull_by_force(fl, 0.0).unwrap().displacement, 0.0);
    assert_eq!(name(m.pull_by_force(f64::NAN, 1.0).unwrap_err()), "force");
    assert_eq!(name(m.pull_by_force(fl, -1.0).unwrap_err()), "duration");
}

// ---------------------------------------------------------- bristles

/// 12 bristles of stiffness 1e5 /m per unit normal force and break
/// deflections 1 µm × (1 + 0.37 i) (incommensurate: they snap at different
/// places).
fn brush() -> Bristles {
    let k = vec![1e5; 12];
    let d: Vec<f64> = (0..12).map(|i| 1e-6 * (1.0 + 0.37 * i as f64)).collect();
    Bristles::new(&k, &d, 0.0).unwrap()
}

/// One bristle (5-8) along a track from rest: a sawtooth F = N k (x mod δ),
/// ½ N k δ² dissipated per snap; one long increment counts its snaps
/// exactly (the same state and dissipation as many short ones).
#[test]
fn a_bristle_snaps_at_its_break_deflection_and_bonds_again() {
    let (k, delta, n) = (2e5, 1e-6, 3.0);
    let b = Bristles::new(&[k], &[delta], 0.0).unwrap();
    let mut s = vec![0.0; b.state_len()];
    // Steps of 0.0613 δ: no step ends on a multiple of δ.
    let h = 0.0613 * delta;
    let mut snaps = 0;
    for i in 1..=100 {
        let r = b
            .step_in_place(&mut s, &inc(n, [h, 0.0], 1e-3), &mut b.work())
            .unwrap();
        let x = i as f64 * h;
        let d = x % delta;
        assert!(
            (-r.force[0] - n * k * d).abs() <= 1e-9 * n * k * delta,
            "step {i}: {r:?}"
        );
        if r.dissipated > 0.0 {
            snaps += 1;
            assert!((r.dissipated - 0.5 * n * k * delta * delta).abs() <= 1e-12 * r.dissipated);
            assert_eq!(r.regime, 2);
        }
    }
    assert_eq!(snaps, 6); // at 1, 2, …, 6 δ on the way to 6.13 δ
                          // One increment of 6.13 δ from rest: the same deflection and energy.
    let mut one = vec![0.0; b.state_len()];
    let r = b
        .step_in_place(&mut one, &inc(n, [100.0 * h, 0.0], 1e-3), &mut b.work())
        .unwrap();
    assert!((one[STATE_MODEL] - s[STATE_MODEL]).abs() <= 1e-12 * delta);
    assert!((r.dissipated - s[STATE_DISSIPATION]).abs() <= 1e-12 * s[STATE_DISSIPATION]);
    // Reversal: the bristle unloads elastically, then snaps the other way.
    let r = b
        .step_in_place(&mut one, &inc(n, [-0.13 * delta, 0.0], 1e-3), &mut b.work())
        .unwrap();
    assert_eq!(r.dissipated, 0.0);
    assert!(one[STATE_MODEL].abs() <= 1e-12 * delta);
    let r = b
        .step_in_place(&mut one, &inc(n, [-1.5 * delta, 0.0], 1e-3), &mut b.work())
        .unwrap();
    assert!((r.dissipated - 0.5 * n * k * delta * delta).abs() <= 1e-12 * r.dissipated);
    assert!((one[STATE_MODEL] + 0.5 * delta).abs() <= 1e-12 * delta);
}

/// Many incommensurate bristles in steady sliding average their sawtooths:
/// μ → Σkᵢδᵢ/2, never above the static coefficient Σkᵢδᵢ; along a random
/// path the work of the force equals the stored energy's change plus the
/// dissipation.
#[test]
fn bristles_slide_at_half_their_static_coefficient_and_balance_energy() {
    let b = brush();
    let n = 2.0;
    let mut s = vec![0.0; b.state_len()];
    let mut mean = 0.0;
    let steps = 20_000;
    for i in 0..steps {
        let r = b
            .step_in_place(&mut s, &inc(n, [3e-8, 0.0], 1e-4), &mut b.work())
            .unwrap();
        assert!(r.cof <= b.static_coefficient() * (1.0 + 1e-12));
        if i >= steps / 2 {
            mean += r.cof / (steps / 2) as f64;
        }
    }
    let want = 0.5 * b.static_coefficient();
    assert!((mean / want - 1.0).abs() < 0.02, "mean μ {mean} vs {want}");
    // Energy along a random path: the work of the force, integrated on a
    // fine sub-division of every increment, against Δstored + dissipation.
    let mut seed = 7u64;
    let mut s = vec![0.0; b.state_len()];
    let (mut work, mut stored0) = (0.0, 0.0);
    for _ in 0..400 {
        let ds = 4e-6 * (rng(&mut seed) - 0.45);
        let pieces = 4000;
        let h = ds / pieces as f64;
        let mut probe = s.clone();
        for _ in 0..pieces {
            let before = b
                .step_in_place(&mut probe.clone(), &inc(n, [0.0, 0.0], 1e-4), &mut b.work())
                .unwrap();
            let after = b
                .step_in_place(&mut probe, &inc(n, [h, 0.0], 1e-4), &mut b.work())
                .unwrap();
            // The resisting force's work: the trapezoid rule, exact
            // between snaps; across a snap the force before it (the snap
            // falls within 1/1000 of the smallest break deflection).
            work -= if after.dissipated == 0.0 {
                0.5 * (before.force[0] + after.force[0]) * h
            } else {
                before.force[0] * h
            };
        }
        let r = b
            .step_in_place(&mut s, &inc(n, [ds, 0.0], 1e-4), &mut b.work())
            .unwrap();
        stored0 = r.stored_energy;
    }
    let balance = stored0 + s[STATE_DISSIPATION];
    assert!(
        (work - balance).abs() <= 2e-3 * balance,
        "work {work} vs {balance}"
    );
}

#[test]
fn bristles_bad_input_names_the_argument() {
    let e = |r: asperity::Result<Bristles>| name(r.unwrap_err());
    assert_eq!(e(Bristles::new(&[], &[], 0.0)), "break_deflection.len()");
    assert_eq!(
        e(Bristles::new(&[1.0], &[1.0, 2.0], 0.0)),
        "break_deflection.len()"
    );
    assert_eq!(e(Bristles::new(&[0.0], &[1.0], 0.0)), "stiffness");
    assert_eq!(e(Bristles::new(&[1.0], &[-1.0], 0.0)), "break_deflection");
    assert_eq!(e(Bristles::new(&[1.0], &[1.0], f64::NAN)), "sigma2");
    let b = brush();
    let mut s = vec![0.0; b.state_len()];
    assert_eq!(
        name(
            b.step_in_place(&mut s, &inc(1.0, [1e-7, 1e-9], 1e-3), &mut b.work())
                .unwrap_err()
        ),
        "slip"
    );
    assert!(s.iter().all(|&v| v == 0.0));
}

/// N = 0 is no contact for the LuGre and bristle models as for
/// Maxwell-slip: regime 3 whether the point moves or not (the viscous σ₂
/// term, which does not scale with N, may still act).
#[test]
fn zero_load_is_no_contact_for_lugre_and_bristles() {
    let laws: [(&str, Box<dyn FrictionLaw>); 2] = [
        ("lugre", Box::new(lugre())),
        ("bristles", Box::new(brush())),
    ];
    for (label, law) in laws {
        let mut s = vec![0.0; law.state_len()];
        for (k, ds) in [[0.0, 0.0], [2e-7, 0.0], [-1e-7, 0.0]]
            .into_iter()
            .enumerate()
        {
            let r = law
                .step_in_place(&mut s, &inc(0.0, ds, 1e-3), &mut law.work())
                .unwrap();
            assert_eq!(r.regime, 3, "{label}, increment {k}");
            assert!(r.force.iter().all(|f| f.is_finite()), "{label}");
        }
        // Loaded again, the regime is a contact one.
        let r = law
            .step_in_place(&mut s, &inc(1.0, [1e-7, 0.0], 1e-3), &mut law.work())
            .unwrap();
        assert_ne!(r.regime, 3, "{label}");
    }
}
