//! The dynamic friction models of thesis chapter 5 (issue 9): LuGre against
//! its Stribeck curve and a fine Runge–Kutta integration, Maxwell-slip
//! against the Masing rules and non-local memory, dissipation ≥ 0, tangents
//! against finite differences, cut-backs, bad input.

use asperity::friction::dynamic::{
    DynamicFriction, DynamicIncrement, LuGre, MaxwellSlip, STATE_DISSIPATION, STATE_SLIP_PATH,
    TANGENT_NORMAL, TANGENT_SLIP,
};
use asperity::Error;

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

fn inc(n: f64, slip: [f64; 2], dt: f64) -> DynamicIncrement {
    DynamicIncrement {
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
            let r = m.step(&s, &mut t, &inc(n, [v * dt, 0.0], dt)).unwrap();
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
                let r = m.step(&s, &mut t, &inc(n, [0.0, -v * h], h)).unwrap();
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
            let r = m.step(&old, &mut new, &inc(n, [ds, 0.0], dt)).unwrap();
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
        let r = m.step(&old, &mut new, &inc(n, slip, dt)).unwrap();
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
fn random_increments(m: &dyn DynamicFriction, seed: u64, rate_dependent: bool) {
    random_path(m, seed, rate_dependent, false)
}

/// [`random_increments`], along x only when `track`.
fn random_path(m: &dyn DynamicFriction, seed: u64, rate_dependent: bool, track: bool) {
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
        let i = DynamicIncrement {
            normal_force: n,
            slip: if track {
                [len * ang.cos(), 0.0]
            } else {
                [len * ang.cos(), len * ang.sin()]
            },
            dt,
            tangents: k % 4,
            reserved: 0,
        };
        let r = m.step(&old, &mut new, &i).unwrap();
        assert!(r.dissipated >= 0.0, "{k}: {r:?}");
        assert!(r.force.iter().all(|f| f.is_finite()) && r.stored_energy >= 0.0);
        assert_eq!(
            new[STATE_DISSIPATION],
            old[STATE_DISSIPATION] + r.dissipated
        );
        let r2 = m.step(&old, &mut again, &i).unwrap();
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
    let r = m.step(&s, &mut t, &inc(3.0, [0.0, 0.0], 0.0)).unwrap();
    assert_eq!(t, s);
    assert_eq!(r.dissipated, 0.0);
    assert_eq!(r.regime, 0);
    assert_eq!(r.force, [-3.0 * 1e5 * 2e-6, -0.0]);
    // A tiny slow displacement from rest: the bristles act as a spring of
    // stiffness N σ₀ (pre-sliding), force ≈ N σ₀ x.
    let s = vec![0.0; m.state_len()];
    let x = 1e-9;
    let r = m.step(&s, &mut t, &inc(2.0, [x, 0.0], 100.0)).unwrap();
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
    let i = DynamicIncrement {
        normal_force: 5.0,
        slip: [3e-7, 1e-7],
        dt: 2e-4,
        tangents: TANGENT_NORMAL | TANGENT_SLIP,
        reserved: 0,
    };
    let r = m.step(&s, &mut t, &i).unwrap();
    assert_eq!(r.tangents, TANGENT_NORMAL | TANGENT_SLIP);
    let f = |n: f64, ds: [f64; 2]| {
        let mut t = s.clone();
        m.step(&s, &mut t, &inc(n, ds, 2e-4)).unwrap().force
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
            DynamicIncrement {
                tangents: 4,
                ..inc(1.0, [0.0; 2], 1.0)
            },
            "tangents",
        ),
    ] {
        assert_eq!(name(m.step(&s, &mut t, &i).unwrap_err()), want);
        assert!(t.iter().all(|&x| x == 7.0), "new untouched on failure");
    }
    let mut bad = s.clone();
    bad[STATE_DISSIPATION] = -1.0;
    assert_eq!(
        name(m.step(&bad, &mut t, &inc(1.0, [0.0; 2], 1.0)).unwrap_err()),
        "old.dissipation"
    );
    bad[STATE_DISSIPATION] = 0.0;
    bad[asperity::friction::dynamic::lugre::STATE_Z] = f64::NAN;
    assert_eq!(
        name(m.step(&bad, &mut t, &inc(1.0, [0.0; 2], 1.0)).unwrap_err()),
        "old"
    );
    let mut short = vec![0.0; 3];
    assert_eq!(
        name(
            m.step(&s, &mut short, &inc(1.0, [0.0; 2], 1.0))
                .unwrap_err()
        ),
        "new.len()"
    );
}

// -------------------------------------------------------- Maxwell-slip

fn maxwell() -> MaxwellSlip {
    // Five elements, reaches 1, 2, 4, 8, 16 µm.
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
            let r = m.step(&s, &mut t, &inc(n, [d, 0.0], 1.0)).unwrap();
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
            let r = m.step(&s, &mut t, &inc(n, [d, 0.0], 1.0)).unwrap();
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
fn maxwell_slip_random_increments_and_tangents() {
    random_increments(&maxwell(), 4, false);
    let viscous = MaxwellSlip::new(&[1e5, 3e4], &[0.25, 0.35], 0.8).unwrap();
    random_increments(&viscous, 5, false);
    // Consistent tangents against finite differences, in 2-D, with some
    // elements slipping and some sticking.
    let m = maxwell();
    let mut s = vec![0.0; m.state_len()];
    let mut t = s.clone();
    m.step(&s, &mut t, &inc(1.0, [5e-6, 1e-6], 1.0)).unwrap();
    s.copy_from_slice(&t);
    let i = DynamicIncrement {
        normal_force: 4.0,
        slip: [1.5e-6, -2e-6],
        dt: 0.5,
        tangents: TANGENT_NORMAL | TANGENT_SLIP,
        reserved: 0,
    };
    let r = m.step(&s, &mut t, &i).unwrap();
    assert_eq!(r.regime, 1, "partial slip");
    let f = |n: f64, ds: [f64; 2]| {
        let mut t = s.clone();
        m.step(&s, &mut t, &inc(n, ds, 0.5)).unwrap().force
    };
    let (fp, fm) = (f(4.001, i.slip), f(3.999, i.slip));
    for c in 0..2 {
        assert!((r.dforce_dnormal[c] - (fp[c] - fm[c]) / 0.002).abs() <= 1e-9);
    }
    for j in 0..2 {
        let h = 1e-12;
        let (mut p, mut q) = (i.slip, i.slip);
        p[j] += h;
        q[j] -= h;
        let (fp, fq) = (f(4.0, p), f(4.0, q));
        for c in 0..2 {
            let d = (fp[c] - fq[c]) / (2.0 * h);
            assert!(
                (r.dforce_dslip[c][j] - d).abs() <= 1e-5 * d.abs().max(1e3),
                "[{c}][{j}]: {} vs {d}",
                r.dforce_dslip[c][j]
            );
        }
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
        name(m.step(&s, &mut t, &inc(-1.0, [0.0; 2], 1.0)).unwrap_err()),
        "normal_force"
    );
    assert!(t.iter().all(|&x| x == 7.0), "new untouched on failure");
    // A rate-independent model accepts dt = 0 with a slip.
    m.step(&s, &mut t, &inc(1.0, [1e-6, 0.0], 0.0)).unwrap();
}

// ------------------------------------------- one interface, block calls

use asperity::friction::dynamic::DynamicModel;

#[test]
fn model_choice_in_place_and_block_equal_the_single_steps() {
    for model in [
        DynamicModel::LuGre(lugre()),
        DynamicModel::MaxwellSlip(maxwell()),
        DynamicModel::PrandtlTomlinson(tomlinson(3.0, 1e-3)),
    ] {
        let direct: &dyn DynamicFriction = match &model {
            DynamicModel::LuGre(m) => m,
            DynamicModel::MaxwellSlip(m) => m,
            DynamicModel::PrandtlTomlinson(m) => m,
        };
        let m = model.state_len();
        assert_eq!(m, direct.state_len());
        let points = 5;
        let normal: Vec<f64> = (0..points).map(|i| 1.0 + i as f64).collect();
        let track = matches!(model, DynamicModel::PrandtlTomlinson(_));
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
                    &normal,
                    &slip,
                    dt,
                    &mut states,
                    &mut forces,
                    Some(&mut diss),
                )
                .unwrap();
            for i in 0..points {
                let inc = inc(normal[i], [slip[2 * i], slip[2 * i + 1]], dt);
                let mut next = vec![0.0; m];
                let r = direct.step(&single[i], &mut next, &inc).unwrap();
                let mut in_place = single[i].clone();
                let q = model.step_in_place(&mut in_place, &inc).unwrap();
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
            .step_block(&bad, &slip, dt, &mut states, &mut forces, None)
            .unwrap_err();
        assert_eq!((e.index, name(e.error)), (3, "normal_force"));
        assert_ne!(&states[..3 * m], &before[..3 * m]);
        assert_eq!(&states[3 * m..], &before[3 * m..]);
        let e = model
            .step_block(&normal, &slip[1..], dt, &mut states, &mut forces, None)
            .unwrap_err();
        assert_eq!((e.index, name(e.error)), (0, "slip.len()"));
        // In place: a bad state is refused and left untouched.
        let mut s = vec![0.0; m];
        s[STATE_SLIP_PATH] = -1.0;
        let e = model
            .step_in_place(&mut s, &inc(1.0, [0.0; 2], 1.0))
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
            .step_in_place(&mut s, &inc(1.0, [v * dt, 0.0], dt))
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
            m.step(&s, &mut t, &inc(1.0, [1e-9, 1e-9], 1e-3))
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
