//! JKR sphere and JKR power-law punches: reference values (REFERENCE.md §1, §7,
//! §8), pull-offs, hysteresis, closed-form accuracy, limits and extremes.

use asperity::contact::jkr_power_punch::{k_star, k_star_with_error};
use asperity::contact::{Dmt, Hertz, Jkr, JkrPowerPunch, PowerPunch};
use asperity::material::{no_slip_epsilon, no_slip_factor};
use asperity::{ContactState, Control, Error, NormalContact, NormalLaw};
use core::f64::consts::PI;
use proptest::prelude::*;

const R: f64 = 1e-6;
const W: f64 = 0.05;
const E: f64 = 1e9;

/// `x` equals the printed value to its last printed digit (half a unit).
fn printed(x: f64, text: &str) {
    let v: f64 = text.parse().unwrap();
    let (mant, exp) = text.split_once('e').unwrap_or((text, "0"));
    let decimals = mant.split_once('.').map_or(0, |(_, f)| f.len()) as i32;
    let exp: i32 = exp.parse().unwrap();
    let half_unit = 0.5 * 10f64.powi(exp - decimals);
    assert!(
        (x - v).abs() <= half_unit * (1.0 + 1e-9),
        "{x:e} does not print as {text}"
    );
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs().max(f64::MIN_POSITIVE)
}

fn fresh() -> ContactState {
    ContactState::default()
}

fn touching() -> ContactState {
    ContactState {
        in_contact: 1,
        branch: 1,
        ..Default::default()
    }
}

fn logspace(lo: f64, hi: f64, n: usize) -> impl Iterator<Item = f64> {
    let (l, h) = (lo.ln(), hi.ln());
    (0..n).map(move |i| (l + (h - l) * i as f64 / (n - 1) as f64).exp())
}

fn example() -> Jkr {
    Jkr::new(R, E, W).unwrap()
}

#[test]
fn worked_example_section_8() {
    let j = example();
    printed(-j.pull_off_force(Control::Load).unwrap(), "2.35619e-7");
    printed(j.eval_at_load(0.0).unwrap().contact_radius, "8.90794e-8");
    printed(j.eval_at_load(1e-6).unwrap().contact_radius, "1.24133e-7");
    let pc = j.pull_off_force(Control::Load).unwrap();
    printed(j.eval_at_load(pc).unwrap().contact_radius, "5.61165e-8");
    let dmt = Dmt::new(R, E, W).unwrap();
    printed(-dmt.pull_off_force(Control::Load).unwrap(), "3.14159e-7");
    // Closed forms of those radii.
    assert!(
        rel(
            j.eval_at_load(0.0).unwrap().contact_radius,
            (9.0 * PI * W * R * R / (2.0 * E)).cbrt()
        ) < 1e-14
    );
    assert!(
        rel(
            j.eval_at_load(pc).unwrap().contact_radius,
            (9.0 * PI * W * R * R / (8.0 * E)).cbrt()
        ) < 1e-14
    );
}

#[test]
fn pull_offs_and_critical_points() {
    for (r, w, e) in [(R, W, E), (2e-3, 1e-3, 1e6), (0.1, 10.0, 1e11)] {
        let j = Jkr::new(r, e, w).unwrap();
        assert!(rel(j.pull_off_force(Control::Load).unwrap(), -1.5 * PI * w * r) < 1e-15);
        assert!(
            rel(
                j.pull_off_force(Control::Displacement).unwrap(),
                -5.0 / 6.0 * PI * w * r
            ) < 1e-15
        );
        let dc = -0.75 * (PI * PI * w * w * r / (e * e)).cbrt();
        assert!(rel(j.critical_delta(), dc) < 1e-14);
        let dc = j.critical_delta();
        assert!(rel(j.length_scale(), -dc) < 1e-14);
        // At δ_c, still in contact: a = (πwR²/(8E*))^{1/3}, P = −(5/6)πwR.
        let (resp, st) = j.eval(dc, &touching()).unwrap();
        assert_eq!(st.in_contact, 1);
        let ac = (PI * w * r * r / (8.0 * e)).cbrt();
        assert!(
            rel(resp.contact_radius, ac) < 1e-7,
            "{} {}",
            resp.contact_radius,
            ac
        );
        assert!(rel(resp.force, -5.0 / 6.0 * PI * w * r) < 1e-12);
        assert!(resp.stiffness.is_finite() && resp.stiffness < 0.0);
        // Just below: out.
        let (resp, st) = j.eval(dc * (1.0 + 1e-12), &touching()).unwrap();
        assert_eq!((resp.force, resp.in_contact, st.in_contact), (0.0, 0, 0));
        // Jump-in radius at δ = 0 from a fresh state.
        let (resp, st) = j.eval(0.0, &fresh()).unwrap();
        assert_eq!(st.in_contact, 1);
        assert!(rel(resp.contact_radius, (2.0 * PI * w * r * r / e).cbrt()) < 1e-14);
        assert!(rel(resp.force, -4.0 / 3.0 * PI * w * r) < 1e-14);
        // The law's own (a → P, δ) agree with the response.
        assert!(rel(j.force_at_radius(resp.contact_radius), resp.force) < 1e-13);
        // Below the load pull-off there is no equilibrium.
        let below = j.eval_at_load(-1.5 * PI * w * r * (1.0 + 1e-9));
        assert!(matches!(
            below,
            Err(Error::OutOfDomain { name: "force", .. })
        ));
    }
}

#[test]
fn hysteresis_loop_under_displacement_control() {
    let j = example();
    let dc = j.critical_delta();
    let n = 400;
    let mut state = fresh();
    let mut path = Vec::new();
    // Approach from −2|δ_c| to +3|δ_c|, then retract to −2|δ_c|.
    for i in 0..=n {
        path.push(2.0 * dc + (-5.0 * dc) * i as f64 / n as f64);
    }
    for i in 0..=n {
        path.push(-3.0 * dc + (5.0 * dc) * i as f64 / n as f64);
    }
    let mut jumped_in = None;
    let mut jumped_out = None;
    let mut prev_contact = 0;
    for (i, &delta) in path.iter().enumerate() {
        let old = state;
        let (r, s) = j.eval(delta, &old).unwrap();
        // Re-evaluating the same step from the same old state is identical.
        assert_eq!(j.eval(delta, &old).unwrap(), (r, s));
        assert!(r.force.is_finite() && r.stiffness.is_finite());
        assert_eq!(r.in_contact, s.in_contact);
        let approaching = i <= n;
        if approaching {
            assert_eq!(r.in_contact == 1, delta >= 0.0, "approach δ = {delta:e}");
        } else {
            assert_eq!(r.in_contact == 1, delta >= dc, "retraction δ = {delta:e}");
        }
        if r.in_contact == 0 {
            assert_eq!(r.force, 0.0);
            assert_eq!(r.contact_radius, 0.0);
        } else {
            assert!(
                rel(j.force_at_radius(r.contact_radius), r.force) < 1e-9 || r.force.abs() < 1e-20
            );
        }
        if prev_contact == 0 && r.in_contact == 1 {
            jumped_in = Some((delta, r));
        }
        if prev_contact == 1 && r.in_contact == 0 {
            jumped_out = Some((path[i - 1], delta));
        }
        prev_contact = r.in_contact;
        state = s;
    }
    let (din, rin) = jumped_in.unwrap();
    assert!(
        din >= 0.0 && din <= -5.0 * dc / n as f64 * (1.0 + 1e-9),
        "{din:e} {dc:e}"
    );
    // The force jumps from 0 to about −(4/3)πwR.
    assert!(rin.force < -1.2 * PI * W * R);
    let (last_in, first_out) = jumped_out.unwrap();
    assert!(last_in >= dc && first_out < dc);
    // Just before the jump the force is near −(5/6)πwR.
    let (r, _) = j.eval(last_in, &touching()).unwrap();
    assert!(
        r.force < -0.8 * PI * W * R && r.force > -0.9 * PI * W * R,
        "{}",
        r.force
    );
    // The loop encloses dissipated energy: on retraction between δ_c and 0 the
    // contact carries tension, on approach it carried nothing.
    let (r, _) = j.eval(0.5 * dc, &touching()).unwrap();
    assert!(r.force < 0.0);
    let (r, _) = j.eval(0.5 * dc, &fresh()).unwrap();
    assert_eq!(r.force, 0.0);
}

/// Reference: bisection on the reduced quartic η⁴ − η − Δ = 0 over the stable
/// branch [4^{−1/3}, max(1, Δ^{1/4}) + 1], to adjacent floats.
fn reference_eta(big: f64) -> f64 {
    let mut lo = 0.25f64.cbrt();
    let mut hi = big.max(1.0).sqrt().sqrt() + 1.0;
    let g = |e: f64| e * e * e * e - e - big;
    for _ in 0..2000 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if g(mid) > 0.0 {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    // The float nearest to the root among lo, hi.
    if g(hi).abs() < g(lo).abs() {
        hi
    } else {
        lo
    }
}

#[test]
fn closed_form_matches_bracketed_reference() {
    let mut worst: f64 = 0.0;
    let mut count = 0;
    for w_rel in [1e-12, 1e-8, 1e-4, 1.0, 1e3, 1e6] {
        let w = W * w_rel;
        let j = Jkr::new(R, E, w).unwrap();
        let natural = (PI * PI * w * w * R / (E * E)).cbrt();
        let k = (2.0 * PI * w / E).sqrt();
        let ys = (k * R).cbrt();
        let l = ys.powi(4) / R;
        let mut deltas: Vec<f64> = logspace(1e-12, 1e6, 400).map(|x| x * natural).collect();
        deltas.extend(logspace(1e-12, 0.75 * (1.0 - 1e-3), 200).map(|x| -x * natural));
        deltas.push(0.0);
        for delta in deltas {
            let a = j.contact_radius_at_delta(delta).unwrap();
            let eta = reference_eta(delta / l);
            let a_ref = ys * ys * eta * eta;
            let e = rel(a, a_ref);
            worst = worst.max(e);
            count += 1;
            assert!(
                e < 1e-13,
                "w = {w:e}, δ = {delta:e}: a = {a:e}, ref {a_ref:e}, rel {e:e}"
            );
            // The response uses the same root.
            let old = if delta >= 0.0 { fresh() } else { touching() };
            let (r, _) = j.eval(delta, &old).unwrap();
            assert_eq!(r.contact_radius, a);
        }
        // Within 1e-3 of the fold the root is ill-conditioned (∂η/∂Δ → ∞); the
        // closed form still satisfies the equation to rounding.
        let dc = j.critical_delta();
        for x in logspace(1e-16, 1e-3, 50) {
            let delta = dc * (1.0 - x);
            let a = j.contact_radius_at_delta(delta).unwrap();
            let back = j.delta_at_radius(a);
            assert!(
                (back - delta).abs() <= 1e-14 * natural,
                "near fold: {back:e} vs {delta:e}"
            );
            let ac = (PI * w * R * R / (8.0 * E)).cbrt();
            assert!(a >= ac * (1.0 - 1e-7));
        }
        assert!(j.contact_radius_at_delta(dc * (1.0 + 1e-9)).is_none());
    }
    eprintln!("Ferrari vs bisection: worst relative error {worst:e} over {count} points");
}

#[test]
fn zero_adhesion_is_hertz_and_galin() {
    let j = Jkr::new(R, E, 0.0).unwrap();
    let h = Hertz::new(R, E).unwrap();
    for delta in [-1e-9, 0.0, 1e-12, 1e-9, 1e-7, 1e-3] {
        for old in [fresh(), touching()] {
            let (rj, _) = j.eval(delta, &old).unwrap();
            let (rh, _) = h.eval(delta, &old).unwrap();
            assert!(
                rel(rj.force, rh.force) < 1e-14 || rh.force == rj.force,
                "{delta}"
            );
            assert!(rel(rj.contact_radius, rh.contact_radius) < 1e-14 || rh.contact_radius == 0.0);
            assert!(rel(rj.stiffness, rh.stiffness) < 1e-14 || rh.stiffness == 0.0);
        }
    }
    for p in [0.0, 1e-9, 1e-3] {
        let rj = j.eval_at_load(p).unwrap();
        let rh = h.eval_at_load(p).unwrap();
        assert!(rel(rj.contact_radius, rh.contact_radius) < 1e-14 || p == 0.0);
        assert!(rel(rj.delta, rh.delta) < 1e-14 || p == 0.0);
    }
    assert_eq!(j.pull_off_force(Control::Load).unwrap(), 0.0);
    assert_eq!(j.pull_off_force(Control::Displacement).unwrap(), 0.0);
    assert_eq!(j.length_scale(), R);
    assert!(j.eval_at_load(-1e-12).is_err());

    for d in [1.0, 1.5, 2.0, 3.0, 7.5] {
        let b = 1e3;
        let jp = JkrPowerPunch::new(b, d, E, 0.0).unwrap();
        let g = PowerPunch::new(b, d, E).unwrap();
        for delta in [-1e-9, 0.0, 1e-12, 1e-9, 1e-6] {
            let (rj, _) = jp.eval(delta, &fresh()).unwrap();
            let (rg, _) = g.eval(delta, &fresh()).unwrap();
            assert!(
                rel(rj.force, rg.force) < 1e-13 || rg.force == 0.0,
                "d={d} δ={delta}"
            );
            assert!(rel(rj.contact_radius, rg.contact_radius) < 1e-13 || rg.contact_radius == 0.0);
            assert!(rel(rj.stiffness, rg.stiffness) < 1e-13 || rg.stiffness == 0.0);
        }
        for p in [1e-9, 1e-3] {
            let rj = jp.eval_at_load(p).unwrap();
            let rg = g.eval_at_load(p).unwrap();
            assert!(rel(rj.contact_radius, rg.contact_radius) < 1e-13);
            assert!(rel(rj.delta, rg.delta) < 1e-13);
        }
        assert_eq!(jp.pull_off_force(Control::Load).unwrap(), 0.0);
        assert!(rel(jp.length_scale(), g.length_scale()) < 1e-14);
    }
}

#[test]
fn power_punch_d2_is_the_jkr_sphere() {
    for (r, w, e) in [(R, W, E), (1e-2, 1e-4, 3e6), (5e-9, 2.0, 2e11)] {
        let s = Jkr::new(r, e, w).unwrap();
        let p = JkrPowerPunch::new(1.0 / (2.0 * r), 2.0, e, w).unwrap();
        let lc = s.length_scale();
        assert!(rel(p.length_scale(), lc) < 1e-13);
        for c in [Control::Load, Control::Displacement] {
            assert!(rel(p.pull_off_force(c).unwrap(), s.pull_off_force(c).unwrap()) < 1e-13);
        }
        let fscale = PI * w * r;
        let deltas = logspace(1e-9, 1e5, 120)
            .map(|x| x * lc)
            .chain(logspace(1e-9, 1.0 - 1e-9, 120).map(|x| -x * lc));
        for delta in deltas {
            for old in [fresh(), touching()] {
                let (a, sa) = s.eval(delta, &old).unwrap();
                let (b, sb) = p.eval(delta, &old).unwrap();
                assert_eq!(sa.in_contact, sb.in_contact);
                // Near the fold the root is ill-conditioned (∂a/∂δ → ∞).
                let tol = if delta < 0.999 * s.critical_delta() {
                    1e-7
                } else {
                    1e-12
                };
                assert!(
                    (a.force - b.force).abs() <= tol * (a.force.abs() + fscale),
                    "δ={delta:e}: {} {}",
                    a.force,
                    b.force
                );
                assert!(rel(b.contact_radius, a.contact_radius) < tol || a.contact_radius == 0.0);
                let ds = 2.0 * e * a.contact_radius;
                assert!(
                    (a.stiffness - b.stiffness).abs() <= 1e3 * tol * (a.stiffness.abs() + ds),
                    "δ={delta:e}: {} {}",
                    a.stiffness,
                    b.stiffness
                );
            }
        }
        for x in [-1.5, -1.0, -0.5, 0.0, 1.0, 1e3, 1e8] {
            let f = x * fscale;
            let a = s.eval_at_load(f).unwrap();
            let b = p.eval_at_load(f).unwrap();
            // At the load pull-off (x = −1.5) the radius is ill-conditioned: √ε.
            let tol = if x == -1.5 { 1e-7 } else { 1e-12 };
            assert!(rel(b.contact_radius, a.contact_radius) < tol);
            assert!((a.delta - b.delta).abs() <= tol * (a.delta.abs() + lc));
            assert!((a.stiffness - b.stiffness).abs() <= 1e3 * tol * (2.0 * e * a.contact_radius));
        }
    }
}

#[test]
fn k_star_table_and_closed_form() {
    let table = [
        (
            0.0,
            "1.0986123",
            ["0.951426151", "0.918498211", "0.893251438"],
        ),
        (
            0.355,
            "1.0173760",
            ["0.991334685", "0.985405871", "0.980826443"],
        ),
    ];
    for (nu, cns, ks) in table {
        printed(no_slip_factor(nu).unwrap(), cns);
        for (i, text) in ks.iter().enumerate() {
            let d = (i + 1) as f64;
            let (k, err) = k_star_with_error(d, nu).unwrap();
            printed(k, text);
            assert!(err < 1e-13, "error estimate {err:e}");
            let law = JkrPowerPunch::no_slip(1.0, d, E, W, nu).unwrap();
            assert_eq!(law.k_star(), k);
            printed(law.no_slip_factor(), cns);
        }
    }
    // k*(1) = πε/sinh(πε) over the whole range of ν.
    for i in 0..=50 {
        let nu = 0.5 * i as f64 / 50.0;
        let pe = PI * no_slip_epsilon(nu).unwrap();
        let closed = if pe == 0.0 { 1.0 } else { pe / pe.sinh() };
        let k = k_star(1.0, nu).unwrap();
        assert!((k - closed).abs() < 1e-14, "ν={nu}: {k} vs {closed}");
    }
    // Integer d against an independent Gauss–Legendre-free check: the
    // frictionless value is exactly 1, and k* decreases with d and increases
    // with ν.
    for d in [1.0, 1.7, 3.0, 10.0, 50.0, 100.0] {
        assert!((k_star(d, 0.5).unwrap() - 1.0).abs() < 1e-14);
        let mut prev = 0.0;
        for i in 0..=10 {
            let k = k_star(d, 0.05 * i as f64).unwrap();
            assert!(k > prev && k <= 1.0 + 1e-15);
            prev = k;
        }
    }
    assert!(k_star(1.0, 0.0).unwrap() > k_star(2.0, 0.0).unwrap());
    assert!(k_star(50.0, 0.0).unwrap() > 0.5);
}

/// The dimensional pull-off formula of REFERENCE.md §7 for
/// `P = A a^{d+1} − b a^{3/2}`.
fn pull_off_formula(a_coef: f64, b: f64, d: f64) -> (f64, f64) {
    let q = 3.0 * b / (2.0 * (d + 1.0) * a_coef);
    let ac = q.powf(1.0 / (d - 0.5));
    let pc = -b * (2.0 * d - 1.0) / (2.0 * (d + 1.0)) * q.powf(3.0 / (2.0 * d - 1.0));
    (ac, pc)
}

#[test]
fn load_pull_off_for_any_d() {
    // The cone d = 1, B = cot γ: −(54/π) w² tan³γ/E* = −17.18873 for w = E* = tan γ = 1.
    let cone = JkrPowerPunch::new(1.0, 1.0, 1.0, 1.0).unwrap();
    let pc = cone.pull_off_force(Control::Load).unwrap();
    printed(pc, "-17.18873");
    assert!(rel(pc, -54.0 / PI) < 1e-14);
    let tan_g: f64 = 0.3;
    let cone = JkrPowerPunch::new(1.0 / tan_g, 1.0, 2e9, 0.07).unwrap();
    let expect = -54.0 / PI * 0.07 * 0.07 * tan_g.powi(3) / 2e9;
    assert!(rel(cone.pull_off_force(Control::Load).unwrap(), expect) < 1e-13);

    for nu in [None, Some(0.0), Some(0.3), Some(0.5)] {
        for d in [1.0, 1.25, 1.5, 2.0, 3.0, 4.7, 10.0, 20.0] {
            let (b, e, w) = (2.5e2, 3e9, 0.04);
            let law = match nu {
                None => JkrPowerPunch::new(b, d, e, w).unwrap(),
                Some(nu) => JkrPowerPunch::no_slip(b, d, e, w, nu).unwrap(),
            };
            let c_ns = law.no_slip_factor();
            let alpha = c_ns * asperity::contact::power_punch::galin_c(d) * b * e / law.k_star();
            let beta = (8.0 * PI * w * e * c_ns).sqrt();
            let (ac, pc) = pull_off_formula(alpha, beta, d);
            let got = law.pull_off_force(Control::Load).unwrap();
            assert!(rel(got, pc) < 1e-12, "d={d} ν={nu:?}: {got:e} vs {pc:e}");
            let r = law.eval_at_load(got).unwrap();
            // a is ill-conditioned at the fold of P(a): √ε.
            assert!(rel(r.contact_radius, ac) < 1e-7);
            assert!(r.stiffness.abs() < 1e-7 * 2.0 * e * ac);
            assert!(rel(law.force_at_radius(ac), pc) < 1e-12);
            assert!(matches!(
                law.eval_at_load(got * (1.0 + 1e-9)),
                Err(Error::OutOfDomain { name: "force", .. })
            ));
            // Displacement pull-off: force at the minimum of δ(a), scanned.
            let pd = law.pull_off_force(Control::Displacement).unwrap();
            assert!(pd > got && pd < 0.0);
            let (_, st) = law.eval(law.critical_delta(), &touching()).unwrap();
            assert_eq!(st.in_contact, 1);
            let r = law.eval(law.critical_delta(), &touching()).unwrap().0;
            assert!(rel(r.force, pd) < 1e-7, "d={d}: {} vs {pd}", r.force);
            let amin = (0..=20000)
                .map(|i| st.contact_radius * (0.5 + i as f64 / 20000.0))
                .map(|a| law.delta_at_radius(a))
                .fold(f64::INFINITY, f64::min);
            assert!((amin - law.critical_delta()).abs() < 1e-7 * law.critical_delta().abs());
            assert_eq!(
                law.eval(law.critical_delta() * (1.0 + 1e-12), &touching())
                    .unwrap()
                    .1
                    .in_contact,
                0
            );
        }
    }
}

#[test]
fn no_slip_tends_to_frictionless_as_nu_to_half() {
    for d in [1.0, 1.5, 2.0, 3.0, 8.0] {
        let (b, e, w) = (1e3, 1e9, 0.05);
        let f = JkrPowerPunch::new(b, d, e, w).unwrap();
        let delta = 0.5 * f.length_scale();
        let (rf, _) = f.eval(delta, &touching()).unwrap();
        let pf = f.pull_off_force(Control::Load).unwrap();
        let mut prev = f64::INFINITY;
        for k in 1..=15 {
            let nu = 0.5 - 10f64.powi(-k);
            let n = JkrPowerPunch::no_slip(b, d, e, w, nu).unwrap();
            let (rn, _) = n.eval(delta, &touching()).unwrap();
            let diff = rel(rn.force, rf.force)
                + rel(n.pull_off_force(Control::Load).unwrap(), pf)
                + rel(rn.contact_radius, rf.contact_radius)
                + (n.k_star() - 1.0).abs()
                + (n.no_slip_factor() - 1.0).abs();
            assert!(
                diff <= prev * 1.0001 + 1e-14,
                "d={d} ν={nu}: {diff:e} after {prev:e}"
            );
            assert!(
                diff < 20.0 * 10f64.powi(-k) + 1e-13,
                "d={d} ν={nu}: {diff:e}"
            );
            prev = diff;
        }
        let n = JkrPowerPunch::no_slip(b, d, e, w, 0.5).unwrap();
        let (rn, _) = n.eval(delta, &touching()).unwrap();
        assert!(rel(rn.force, rf.force) < 1e-13);
        assert!(
            rel(
                n.pull_off_force(Control::Displacement).unwrap(),
                f.pull_off_force(Control::Displacement).unwrap()
            ) < 1e-13
        );
    }
}

/// Check a law along its stable branches: finite outputs, monotone a(δ) under
/// displacement control and a(P), δ(P) under load control, and stiffness
/// against a central finite difference.
fn check_branches(law: &dyn NormalContact, fd_tol: f64) {
    let lc = law.length_scale();
    let pl = law.pull_off_force(Control::Load).unwrap();
    let pd = law.pull_off_force(Control::Displacement).unwrap();
    assert!(pl <= pd && pd <= 0.0);
    // Displacement control, in contact, from just above the fold outwards.
    let mut deltas: Vec<f64> = logspace(1e-3, 1.0, 40).map(|x| -x.min(1.0) * lc).collect();
    deltas.reverse();
    deltas.push(0.0);
    deltas.extend(logspace(1e-6, 1e6, 80).map(|x| x * lc));
    let mut prev_a = 0.0;
    for &delta in &deltas {
        let (r, s) = law.eval(delta, &touching()).unwrap();
        assert_eq!(s.in_contact, 1);
        for v in [r.force, r.delta, r.contact_radius, r.stiffness] {
            assert!(v.is_finite(), "{r:?}");
        }
        assert!(
            r.contact_radius > prev_a,
            "a not increasing at δ = {delta:e}"
        );
        prev_a = r.contact_radius;
        let h = 1e-6 * (delta.abs() + lc);
        if delta - h >= -lc * (1.0 - 1e-6) {
            let fp = law.eval(delta + h, &touching()).unwrap().0.force;
            let fm = law.eval(delta - h, &touching()).unwrap().0.force;
            let fd = (fp - fm) / (2.0 * h);
            let scale = r
                .stiffness
                .abs()
                .max(law.eval(lc, &touching()).unwrap().0.stiffness * 1e-3);
            assert!(
                (fd - r.stiffness).abs() <= fd_tol * scale,
                "δ={delta:e}: fd {fd:e} vs {:e}",
                r.stiffness
            );
        }
    }
    // Load control, from the pull-off upwards.
    let fscale = -pl;
    let mut loads: Vec<f64> = logspace(1e-6, 1.0, 30).map(|x| pl * x).collect();
    loads.reverse();
    loads.push(0.0);
    loads.extend(logspace(1e-6, 1e8, 60).map(|x| x * fscale));
    let (mut prev_a, mut prev_d) = (0.0, f64::NEG_INFINITY);
    for &f in &loads {
        let r = law.eval_at_load(f).unwrap();
        for v in [r.force, r.delta, r.contact_radius, r.stiffness] {
            assert!(v.is_finite(), "{r:?}");
        }
        assert!(r.contact_radius > prev_a && r.delta > prev_d, "P = {f:e}");
        assert!(r.stiffness >= 0.0);
        prev_a = r.contact_radius;
        prev_d = r.delta;
        let h = 1e-6 * (f.abs() + fscale);
        if f - h >= pl {
            let dp = law.eval_at_load(f + h).unwrap().delta;
            let dm = law.eval_at_load(f - h).unwrap().delta;
            let compliance = (dp - dm) / (2.0 * h);
            assert!(
                (compliance * r.stiffness - 1.0).abs() <= fd_tol.max(1e-6) * 10.0,
                "P={f:e}: {} vs {}",
                1.0 / compliance,
                r.stiffness
            );
        }
    }
}

#[test]
fn branches_sphere() {
    for w_rel in [1e-10, 1e-3, 1.0, 1e4] {
        check_branches(&Jkr::new(R, E, W * w_rel).unwrap(), 1e-5);
    }
}

#[test]
fn branches_power_punch_extremes() {
    for d in [1.0, 1.3, 2.0, 3.0, 5.5, 10.0, 20.0] {
        for nu in [None, Some(0.0), Some(0.25), Some(0.49), Some(0.5)] {
            let law = match nu {
                None => JkrPowerPunch::new(1e2, d, E, W).unwrap(),
                Some(nu) => JkrPowerPunch::no_slip(1e2, d, E, W, nu).unwrap(),
            };
            check_branches(&law, 1e-5);
        }
    }
    // Many decades of w and B; d up to the limit.
    for d in [1.0, 2.0, 50.0, 100.0] {
        for w in [1e-9, 1e-3, 1.0, 1e3] {
            for b in [1e-3, 1.0, 1e6] {
                let law = JkrPowerPunch::no_slip(b, d, E, w, 0.3).unwrap();
                let lc = law.length_scale();
                assert!(lc.is_finite() && lc > 0.0, "d={d} w={w} b={b}");
                for x in [-1.0, -0.5, 0.0, 1.0, 1e3] {
                    let (r, _) = law.eval(x * lc, &touching()).unwrap();
                    assert!(
                        r.force.is_finite()
                            && r.contact_radius.is_finite()
                            && r.stiffness.is_finite()
                    );
                }
                let r = law
                    .eval_at_load(law.pull_off_force(Control::Load).unwrap())
                    .unwrap();
                assert!(r.delta.is_finite());
            }
        }
    }
}

#[test]
fn bad_input_names_the_argument() {
    let inv = |r: asperity::Result<f64>| match r {
        Err(Error::InvalidArgument { name, .. }) => name,
        other => panic!("{other:?}"),
    };
    assert_eq!(inv(Jkr::new(-1.0, E, W).map(|_| 0.0)), "radius");
    assert_eq!(inv(Jkr::new(R, f64::NAN, W).map(|_| 0.0)), "e_star");
    assert_eq!(inv(Jkr::new(R, E, -1e-3).map(|_| 0.0)), "work_of_adhesion");
    assert_eq!(
        inv(Jkr::new(R, E, f64::INFINITY).map(|_| 0.0)),
        "work_of_adhesion"
    );
    assert_eq!(inv(JkrPowerPunch::new(0.0, 2.0, E, W).map(|_| 0.0)), "b");
    assert_eq!(inv(JkrPowerPunch::new(1.0, 0.9, E, W).map(|_| 0.0)), "d");
    assert_eq!(inv(JkrPowerPunch::new(1.0, 101.0, E, W).map(|_| 0.0)), "d");
    assert_eq!(
        inv(JkrPowerPunch::new(1.0, 2.0, 0.0, W).map(|_| 0.0)),
        "e_star"
    );
    assert_eq!(
        inv(JkrPowerPunch::no_slip(1.0, 2.0, E, W, 0.51).map(|_| 0.0)),
        "nu"
    );
    assert_eq!(
        inv(JkrPowerPunch::no_slip(1.0, 2.0, E, W, -0.1).map(|_| 0.0)),
        "nu"
    );
    assert_eq!(inv(k_star(2.0, f64::NAN)), "nu");
    assert_eq!(inv(k_star(0.5, 0.3)), "d");
    let j = example();
    assert_eq!(inv(j.eval(f64::NAN, &fresh()).map(|r| r.0.force)), "delta");
    assert_eq!(inv(j.eval_at_load(f64::INFINITY).map(|r| r.force)), "force");
    let p = JkrPowerPunch::new(1.0, 3.0, E, W).unwrap();
    assert_eq!(
        inv(p.eval(f64::NEG_INFINITY, &fresh()).map(|r| r.0.force)),
        "delta"
    );
    assert!(matches!(
        p.eval_at_load(-1e6),
        Err(Error::OutOfDomain { name: "force", .. })
    ));
}

#[test]
fn through_normal_law_and_struct_size() {
    // The laws travel in the C union of 16 doubles.
    assert!(core::mem::size_of::<Jkr>() <= 16 * 8);
    assert!(core::mem::size_of::<JkrPowerPunch>() <= 16 * 8);
    let law = NormalLaw::Jkr(example());
    let (r, s) = law.eval(0.0, &fresh()).unwrap();
    assert_eq!(s.in_contact, 1);
    assert!(r.force < 0.0);
    let law = NormalLaw::JkrPowerPunch(JkrPowerPunch::no_slip(1e3, 1.5, E, W, 0.3).unwrap());
    assert!(law.eval_at_load(0.0).unwrap().contact_radius > 0.0);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn sphere_stiffness_matches_finite_difference(
        lr in -8.0f64..-1.0, lw in -4.0f64..1.0, le in 6.0f64..11.0, x in -0.999f64..50.0,
    ) {
        let j = Jkr::new(10f64.powf(lr), 10f64.powf(le), 10f64.powf(lw)).unwrap();
        let lc = j.length_scale();
        let delta = x * lc;
        let h = 1e-6 * lc;
        prop_assume!(delta - h > j.critical_delta() * (1.0 - 1e-4));
        let (r, _) = j.eval(delta, &touching()).unwrap();
        let fp = j.eval(delta + h, &touching()).unwrap().0.force;
        let fm = j.eval(delta - h, &touching()).unwrap().0.force;
        let fd = (fp - fm) / (2.0 * h);
        let tol = 1e-4 * r.stiffness.abs().max(2.0 * j.params().e_star * r.contact_radius);
        prop_assert!((fd - r.stiffness).abs() <= tol, "fd {} vs {}", fd, r.stiffness);
        // The response is on the equilibrium curve.
        prop_assert!((j.delta_at_radius(r.contact_radius) - delta).abs() <= 1e-12 * (delta.abs() + lc));
    }

    #[test]
    fn power_punch_on_equilibrium_curve(
        d in 1.0f64..20.0, nu in 0.0f64..0.5, lw in -4.0f64..1.0, x in -0.999f64..100.0,
    ) {
        let law = JkrPowerPunch::no_slip(1e2, d, 1e9, 10f64.powf(lw), nu).unwrap();
        let lc = law.length_scale();
        let delta = x * lc;
        prop_assume!(delta >= law.critical_delta());
        let (r, s) = law.eval(delta, &touching()).unwrap();
        prop_assert_eq!(s.in_contact, 1);
        prop_assert!((law.delta_at_radius(r.contact_radius) - delta).abs() <= 1e-11 * (delta.abs() + lc));
        prop_assert!((law.force_at_radius(r.contact_radius) - r.force).abs()
            <= 1e-11 * (r.force.abs() - law.pull_off_force(Control::Load).unwrap()));
    }
}

/// On-CPU time of this thread (ns) from /proc/thread-self/schedstat, so the
/// timings are not inflated by other processes on a shared machine; wall
/// clock where that file is missing.
struct Clock(Option<u64>, std::time::Instant);

impl Clock {
    fn cpu_ns() -> Option<u64> {
        let s = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
        s.split_whitespace().next()?.parse().ok()
    }
    fn now() -> Self {
        Clock(Self::cpu_ns(), std::time::Instant::now())
    }
    fn elapsed(&self) -> std::time::Duration {
        match (self.0, Self::cpu_ns()) {
            (Some(a), Some(b)) => std::time::Duration::from_nanos(b - a),
            _ => self.1.elapsed(),
        }
    }
}

/// `cargo test --release --test jkr -- --ignored --nocapture`
#[test]
#[ignore]
fn timing_release() {
    use std::hint::black_box;
    let j = example();
    let lc = j.length_scale();
    let n = 20_000_000usize;
    let st = touching();
    let deltas: Vec<f64> = (0..1024)
        .map(|i| (-0.9 + 5.0 * i as f64 / 1024.0) * lc)
        .collect();
    let t0 = Clock::now();
    let mut acc = 0.0;
    for i in 0..n {
        let (r, _) = j.eval(black_box(deltas[i & 1023]), black_box(&st)).unwrap();
        acc += r.force;
    }
    let dt = t0.elapsed().as_secs_f64() / n as f64;
    black_box(acc);
    eprintln!("Jkr::eval (displacement control): {:.1} ns/call", dt * 1e9);

    let t0 = Clock::now();
    for i in 0..n {
        acc += j
            .contact_radius_at_delta(black_box(deltas[i & 1023]))
            .unwrap_or(0.0);
    }
    let dt = t0.elapsed().as_secs_f64() / n as f64;
    black_box(acc);
    eprintln!("Jkr::contact_radius_at_delta: {:.1} ns/call", dt * 1e9);

    let h = Hertz::new(R, E).unwrap();
    let t0 = Clock::now();
    for i in 0..n {
        let (r, _) = h.eval(black_box(deltas[i & 1023]), black_box(&st)).unwrap();
        acc += r.force;
    }
    let dt = t0.elapsed().as_secs_f64() / n as f64;
    black_box(acc);
    eprintln!(
        "Hertz::eval (same loop, for comparison): {:.1} ns/call",
        dt * 1e9
    );

    let law = NormalLaw::Jkr(j);
    let t0 = Clock::now();
    for i in 0..n {
        let (r, _) = law
            .eval(black_box(deltas[i & 1023]), black_box(&st))
            .unwrap();
        acc += r.force;
    }
    let dt = t0.elapsed().as_secs_f64() / n as f64;
    black_box(acc);
    eprintln!("NormalLaw::Jkr eval: {:.1} ns/call", dt * 1e9);

    let t0 = Clock::now();
    for i in 0..n / 10 {
        let r = j
            .eval_at_load(black_box(1e-7 * (i & 1023) as f64 / 1024.0))
            .unwrap();
        acc += r.delta;
    }
    let dt = t0.elapsed().as_secs_f64() / (n / 10) as f64;
    black_box(acc);
    eprintln!("Jkr::eval_at_load: {:.1} ns/call", dt * 1e9);

    for (name, p) in [
        (
            "JkrPowerPunch d=1.5 frictionless",
            JkrPowerPunch::new(1e3, 1.5, E, W).unwrap(),
        ),
        (
            "JkrPowerPunch d=3 no-slip",
            JkrPowerPunch::no_slip(1e3, 3.0, E, W, 0.3).unwrap(),
        ),
    ] {
        let lc = p.length_scale();
        let deltas: Vec<f64> = (0..1024)
            .map(|i| (-0.9 + 5.0 * i as f64 / 1024.0) * lc)
            .collect();
        let m = n / 10;
        let t0 = Clock::now();
        for i in 0..m {
            let (r, _) = p.eval(black_box(deltas[i & 1023]), black_box(&st)).unwrap();
            acc += r.force;
        }
        let dt = t0.elapsed().as_secs_f64() / m as f64;
        black_box(acc);
        eprintln!("{name} eval: {:.1} ns/call", dt * 1e9);
    }
    let t0 = Clock::now();
    for _ in 0..1000 {
        acc += JkrPowerPunch::no_slip(1e3, black_box(2.5), E, W, 0.3)
            .unwrap()
            .k_star();
    }
    black_box(acc);
    eprintln!(
        "JkrPowerPunch::no_slip constructor (k* quadrature): {:.1} us",
        t0.elapsed().as_secs_f64() * 1e3
    );
}
