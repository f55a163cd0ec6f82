//! The closed-form laws through `src/ffi/contact.rs` (`laws_*`: every
//! point checked against the Rust API, monotonicity, pull-off), and the
//! continuity across the laws' internal series/limit switches.

use super::*;
use asperity::contact::{
    maugis_dugdale::SERIES_SWITCH, ContactState, Jkr, MaugisDugdale, NormalContact, NormalLaw,
    NormalResponse,
};
use asperity::ffi::contact::*;
use asperity::material::{no_slip_factor, NO_SLIP_SERIES_SWITCH};

#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    Hertz,
    PowerPunch,
    Cone,
    FlatPunch,
    Dmt,
    Jkr,
    JkrPowerPunch,
    Kendall,
    MaugisDugdale,
    Derjaguin,
}

const KINDS: [Kind; 10] = [
    Kind::Hertz,
    Kind::PowerPunch,
    Kind::Cone,
    Kind::FlatPunch,
    Kind::Dmt,
    Kind::Jkr,
    Kind::JkrPowerPunch,
    Kind::Kendall,
    Kind::MaugisDugdale,
    Kind::Derjaguin,
];

impl Kind {
    fn args(self) -> Vec<Arg> {
        match self {
            Kind::Hertz => vec![RADIUS, E_STAR],
            Kind::PowerPunch => vec![B, D, E_STAR],
            Kind::Cone => vec![HALF_ANGLE, E_STAR],
            Kind::FlatPunch => vec![RADIUS, E_STAR, NU],
            Kind::Dmt | Kind::Jkr => vec![RADIUS, E_STAR, W0],
            Kind::JkrPowerPunch => vec![B, D, E_STAR, W0, NU],
            Kind::Kendall => vec![RADIUS, E_STAR, W0, NU],
            Kind::MaugisDugdale => vec![RADIUS, E_STAR, W, SIGMA0],
            Kind::Derjaguin => vec![RADIUS, W, Z0],
        }
    }

    /// Builds through the C ABI; `sel` is the integer selector (no_slip,
    /// surface law) when the law has one.
    fn build(self, v: &[f64], sel: i32, out: &mut AsperityNormalLaw) -> i32 {
        unsafe {
            match self {
                Kind::Hertz => asperity_law_hertz(v[0], v[1], out),
                Kind::PowerPunch => asperity_law_power_punch(v[0], v[1], v[2], out),
                Kind::Cone => asperity_law_cone(v[0], v[1], out),
                Kind::FlatPunch if sel == 0 => asperity_law_flat_punch(v[0], v[1], out),
                Kind::FlatPunch => asperity_law_flat_punch_no_slip(v[0], v[1], v[2], out),
                Kind::Dmt => asperity_law_dmt(v[0], v[1], v[2], out),
                Kind::Jkr => asperity_law_jkr(v[0], v[1], v[2], out),
                Kind::JkrPowerPunch => {
                    asperity_law_jkr_power_punch(v[0], v[1], v[2], v[3], v[4], sel, out)
                }
                Kind::Kendall => asperity_law_kendall(v[0], v[1], v[2], v[3], sel, out),
                Kind::MaugisDugdale => asperity_law_maugis_dugdale(v[0], v[1], v[2], v[3], out),
                Kind::Derjaguin => asperity_law_derjaguin(v[0], v[1], sel, v[2], out),
            }
        }
    }

    /// Which arguments a call reads (the frictionless flat punch ignores ν).
    fn used(self, sel: i32) -> Vec<bool> {
        let n = self.args().len();
        match self {
            Kind::FlatPunch if sel == 0 => vec![true, true, false],
            _ => vec![true; n],
        }
    }

    fn selector(self, rng: &mut Rng) -> i32 {
        match self {
            Kind::FlatPunch => (rng.f() < 0.5) as i32,
            Kind::JkrPowerPunch | Kind::Kendall => {
                if rng.f() < 0.01 {
                    rng.pick(&[-1, 2, i32::MAX])
                } else {
                    (rng.f() < 0.5) as i32
                }
            }
            Kind::Derjaguin => {
                if rng.f() < 0.01 {
                    rng.pick(&[0, 4, -7])
                } else {
                    rng.pick(&[1, 2, 3])
                }
            }
            _ => 0,
        }
    }

    /// Whether a selector value is valid.
    fn selector_ok(self, sel: i32) -> bool {
        match self {
            Kind::JkrPowerPunch | Kind::Kendall => sel == 0 || sel == 1,
            Kind::Derjaguin => (1..=3).contains(&sel),
            _ => true,
        }
    }

    fn selector_name(self) -> &'static str {
        match self {
            Kind::Derjaguin => "surface_law",
            _ => "no_slip",
        }
    }

    /// Laws whose parameters must also satisfy a documented combination
    /// bound (an error naming one of them inside the per-argument domains).
    fn has_combination_bound(self) -> bool {
        matches!(self, Kind::MaugisDugdale | Kind::Derjaguin | Kind::Cone)
    }

    fn adhesive(self) -> bool {
        matches!(
            self,
            Kind::Dmt
                | Kind::Jkr
                | Kind::JkrPowerPunch
                | Kind::Kendall
                | Kind::MaugisDugdale
                | Kind::Derjaguin
        )
    }
}

pub(crate) fn finite_response(r: &NormalResponse) -> bool {
    r.force.is_finite()
        && r.delta.is_finite()
        && r.contact_radius.is_finite()
        && r.stiffness.is_finite()
        && r.contact_radius >= 0.0
        && (r.in_contact == 0 || r.in_contact == 1)
}

pub(crate) fn finite_state(s: &ContactState) -> bool {
    s.contact_radius.is_finite()
        && s.cohesive_radius.is_finite()
        && s.contact_radius >= 0.0
        && s.cohesive_radius >= 0.0
}

pub(crate) fn bits(r: &NormalResponse) -> [u64; 5] {
    [
        r.force.to_bits(),
        r.delta.to_bits(),
        r.contact_radius.to_bits(),
        r.stiffness.to_bits(),
        r.in_contact as u64,
    ]
}

/// C evaluation, checked against the Rust API (same bits or same error).
fn c_eval(
    c: &AsperityNormalLaw,
    law: &NormalLaw,
    delta: f64,
    old: &ContactState,
) -> Result<(NormalResponse, ContactState), String> {
    let mut r = NormalResponse::default();
    let mut s = ContactState::default();
    let st = unsafe { asperity_normal_eval(c, delta, old, &mut s, &mut r) };
    let rust = law.eval(delta, old);
    if st == ASPERITY_OK {
        let (rr, rs) = rust.unwrap_or_else(|e| panic!("C ok, Rust {e} at {law:?} δ={delta:e}"));
        assert_eq!(bits(&r), bits(&rr), "{law:?} δ={delta:e}");
        assert_eq!(s, rs);
        Ok((r, s))
    } else {
        let m = last_message();
        let e = rust.expect_err("C error, Rust ok");
        assert_eq!(m, e.to_string());
        Err(m)
    }
}

/// Delta values around the law's length scale L: ±L·10^U(−6, 6) mostly;
/// near ±L (the critical overlaps), 0, tiny and huge, NaN and ±∞.
pub(crate) fn sample_delta(rng: &mut Rng, l: f64) -> f64 {
    let u = rng.f();
    match u {
        u if u < 0.004 => f64::NAN,
        u if u < 0.008 => f64::INFINITY,
        u if u < 0.012 => f64::NEG_INFINITY,
        u if u < 0.02 => 0.0,
        u if u < 0.04 => {
            let x = rng.log_uniform(1e-300, 1e300);
            if rng.f() < 0.5 {
                -x
            } else {
                x
            }
        }
        u if u < 0.10 => {
            let s = if rng.f() < 0.5 { -1.0 } else { 1.0 };
            s * l * (1.0 + rng.uniform(-1e-6, 1e-6))
        }
        _ => {
            let s = if rng.f() < 0.5 { -1.0 } else { 1.0 };
            s * l * rng.log_uniform(1e-6, 1e6)
        }
    }
}

/// The sweep of one law kind over `n` points.
fn sweep_law(kind: Kind, n: usize, seed: u64) -> Tally {
    let mut rng = Rng::new(seed ^ (kind as u64).wrapping_mul(0x9E37_79B9));
    let args = kind.args();
    let mut t = Tally::default();
    for _ in 0..n {
        t.points += 1;
        let sel = kind.selector(&mut rng);
        let v: Vec<f64> = args.iter().map(|a| sample(&mut rng, a)).collect();
        let used = kind.used(sel);
        let bad: Vec<&Arg> = args
            .iter()
            .zip(&v)
            .zip(&used)
            .filter(|((a, x), u)| **u && !a.dom.contains(**x))
            .map(|((a, _), _)| a)
            .collect();
        let all_typical = args
            .iter()
            .zip(&v)
            .zip(&used)
            .all(|((a, x), u)| !*u || typical(a, *x));
        let mut c = unsafe { core::mem::zeroed::<AsperityNormalLaw>() };
        let st = kind.build(&v, sel, &mut c);
        if st != ASPERITY_OK {
            let m = last_message();
            t.error(&m);
            assert!(
                st == ASPERITY_ERR_INVALID_ARGUMENT || st == ASPERITY_ERR_OUT_OF_DOMAIN,
                "{kind:?} {v:?}: status {st}: {m}"
            );
            if !kind.selector_ok(sel) {
                if bad.is_empty() {
                    assert!(m.contains(kind.selector_name()), "{kind:?}: {m}");
                }
                continue;
            }
            if bad.is_empty() {
                assert!(
                    kind.has_combination_bound()
                        && names_one_of(&m, &args.iter().collect::<Vec<_>>()),
                    "{kind:?} {v:?} sel {sel}: in-domain arguments refused: {m}"
                );
                assert!(!all_typical || kind.has_combination_bound());
            } else {
                assert!(
                    names_one_of(&m, &bad)
                        || (kind.has_combination_bound()
                            && names_one_of(&m, &args.iter().collect::<Vec<_>>())),
                    "{kind:?} {v:?}: message `{m}` names none of the bad arguments"
                );
            }
            continue;
        }
        assert!(
            bad.is_empty() && kind.selector_ok(sel),
            "{kind:?} {v:?} sel {sel}: accepted out-of-domain arguments"
        );
        t.ok += 1;
        let law = c.to_law().unwrap();
        check_law(kind, &c, &law, &v, sel, all_typical, &mut rng, &mut t);
    }
    t
}

#[allow(clippy::too_many_arguments)]
fn check_law(
    kind: Kind,
    c: &AsperityNormalLaw,
    law: &NormalLaw,
    v: &[f64],
    sel: i32,
    all_typical: bool,
    rng: &mut Rng,
    t: &mut Tally,
) {
    // Length scale: finite and > 0.
    let mut l = f64::NAN;
    if unsafe { asperity_law_length_scale(c, &mut l) } != ASPERITY_OK {
        let m = last_message();
        t.error(&m);
        assert!(m.contains("`law`") && l.is_nan(), "{law:?}: {m}");
        assert!(
            !all_typical,
            "{law:?}: typical law without a length scale: {m}"
        );
        return;
    }
    assert!(l.is_finite() && l > 0.0, "{law:?}: length scale {l:e}");

    // Pull-off: OK ⇒ finite and ≤ 0; closed forms where there are.
    let mut po = [0.0; 2];
    for (k, control) in [ASPERITY_CONTROL_LOAD, ASPERITY_CONTROL_DISPLACEMENT]
        .into_iter()
        .enumerate()
    {
        let st = unsafe { asperity_pull_off_force(c, control, &mut po[k]) };
        if st != ASPERITY_OK {
            let m = last_message();
            t.error(&m);
            assert!(
                m.contains("`law`") && m.contains("overflows"),
                "{law:?}: {m}"
            );
            assert!(!all_typical, "{law:?}: typical law without a pull-off: {m}");
            return;
        }
        assert!(
            po[k].is_finite() && po[k] <= 0.0,
            "{law:?}: pull-off {:e}",
            po[k]
        );
    }
    if kind.adhesive() && all_typical {
        let r = v[0];
        let w = match kind {
            Kind::Derjaguin => v[1],
            Kind::JkrPowerPunch => v[3],
            _ => v[2],
        };
        let fs = PI * w * r; // πwR
        match kind {
            Kind::Jkr if w > 0.0 => close(po[0], -1.5 * fs, 1e-12, law),
            Kind::Dmt => close(po[0], -2.0 * fs, 1e-12, law),
            Kind::Derjaguin => close(po[0], -2.0 * fs, 1e-9, law),
            Kind::MaugisDugdale => assert!(
                po[0] <= -1.5 * fs * (1.0 - 1e-9) && po[0] >= -2.0 * fs * (1.0 + 1e-9),
                "{law:?}: MD pull-off {:e} outside [−2πwR, −1.5πwR]",
                po[0]
            ),
            Kind::Kendall if w > 0.0 => {
                let cns = if sel == 1 {
                    no_slip_factor(v[3]).unwrap()
                } else {
                    1.0
                };
                let want = -(8.0 * PI * w * v[1] * cns * r.powi(3)).sqrt();
                close(po[0], want, 1e-12, law);
            }
            _ => {}
        }
        if w > 0.0 && kind != Kind::JkrPowerPunch {
            assert!(po[0] < 0.0, "{law:?}: adhesive law without pull-off");
        }
    }

    // Two evaluations: from a fresh state, then from its state.
    let d1 = sample_delta(rng, l);
    let r1 = c_eval(c, law, d1, &ContactState::default());
    let s1 = match &r1 {
        Ok((r, s)) => {
            assert!(
                finite_response(r) && finite_state(s),
                "{law:?} δ={d1:e}: {r:?}"
            );
            *s
        }
        Err(m) => {
            t.error(m);
            assert!(m.contains("`delta`"), "{law:?} δ={d1:e}: {m}");
            if d1.is_finite() && all_typical && (d1 / l).abs() <= 1e6 && d1.abs() <= 1.0 {
                assert!(
                    kind == Kind::Derjaguin,
                    "{law:?} δ={d1:e}: typical point refused: {m}"
                );
            }
            ContactState::default()
        }
    };
    let d2 = if rng.f() < 0.5 {
        d1 * rng.uniform(-1.5, 1.5)
    } else {
        sample_delta(rng, l)
    };
    match c_eval(c, law, d2, &s1) {
        Ok((r, s)) => assert!(finite_response(&r) && finite_state(&s), "{law:?}: {r:?}"),
        Err(m) => {
            t.error(&m);
            assert!(m.contains("`delta`"), "{law:?} δ={d2:e}: {m}");
        }
    }

    // Monotone in approach on the contact branch: δa < δb, both in
    // contact, F(δb) ≥ F(δa), stiffness ≥ 0 (Hertz: > 0).
    if all_typical {
        let da = l * rng.log_uniform(1e-3, 1e3);
        let db = da * rng.uniform(1.0 + 1e-9, 2.0);
        if let Ok((ra, sa)) = c_eval(c, law, da, &ContactState::default()) {
            if let Ok((rb, _)) = c_eval(c, law, db, &sa) {
                // Compressive: beyond the load-controlled pull-off, on the
                // branch where P grows with δ (between the displacement- and
                // load-controlled pull-offs of JKR-type laws dP/dδ < 0).
                if ra.in_contact == 1 && rb.in_contact == 1 && ra.force >= 0.0 {
                    assert!(
                        rb.force >= ra.force * (1.0 - 1e-12) - 1e-12 * ra.force.abs(),
                        "{law:?}: F({db:e}) = {:e} < F({da:e}) = {:e}",
                        rb.force,
                        ra.force
                    );
                    assert!(
                        ra.stiffness >= 0.0 && rb.stiffness >= 0.0,
                        "{law:?}: {ra:?}"
                    );
                    if kind == Kind::Hertz {
                        assert!(ra.stiffness > 0.0 && rb.force > ra.force, "{law:?}");
                    }
                }
            }
        }
    }

    // Load control: OK ⇒ finite; below pull-off ⇒ error naming `force`;
    // δ and a grow with P on the stable branch.
    let f0 = if po[0] < 0.0 {
        -po[0]
    } else {
        law.eval(l, &ContactState::default())
            .map(|(r, _)| r.force.abs())
            .ok()
            .filter(|f| f.is_finite() && *f > 0.0)
            .unwrap_or(1.0)
    };
    let p1 = match rng.f() {
        u if u < 0.01 => f64::NAN,
        u if u < 0.02 => rng.pick(&[f64::INFINITY, f64::NEG_INFINITY]),
        u if u < 0.05 => po[0] * (1.0 + rng.uniform(-1e-6, 1e-6)),
        u if u < 0.08 => rng.log_uniform(1e-300, 1e300) * rng.pick(&[-1.0, 1.0]),
        _ => f0 * rng.log_uniform(1e-6, 1e6) * if rng.f() < 0.3 { -1.0 } else { 1.0 },
    };
    let mut ra = NormalResponse::default();
    let st = unsafe { asperity_normal_eval_at_load(c, p1, &mut ra) };
    if st == ASPERITY_OK {
        assert!(finite_response(&ra), "{law:?} P={p1:e}: {ra:?}");
        assert!(
            p1 >= po[0] * (1.0 + 1e-9),
            "{law:?}: P={p1:e} below pull-off {:e} accepted",
            po[0]
        );
        // A larger load: more overlap, larger contact.
        let p2 = p1 + p1.abs().max(f0) * rng.log_uniform(1e-6, 10.0);
        let mut rb = NormalResponse::default();
        // A rigid sphere (Derjaguin) has no stable tensile equilibrium: its
        // attractive branch has dP/dδ < 0 (checked only for P ≥ 0).
        // Only for typical parameters: at the ends of f64 (R = 8e-234 m) the
        // scales are near the subnormal range and δ(P) jitters by ~1e-6.
        let check = all_typical && (kind != Kind::Derjaguin || p1 >= 0.0);
        if check && unsafe { asperity_normal_eval_at_load(c, p2, &mut rb) } == ASPERITY_OK {
            let tol = 1e-9;
            assert!(
                rb.delta >= ra.delta - tol * ra.delta.abs().max(rb.delta.abs()),
                "{law:?}: δ(P={p2:e}) = {:e} < δ(P={p1:e}) = {:e}",
                rb.delta,
                ra.delta
            );
            assert!(
                rb.contact_radius >= ra.contact_radius * (1.0 - tol),
                "{law:?}: a decreases with the load"
            );
        }
    } else {
        let m = last_message();
        t.error(&m);
        assert!(m.contains("`force`"), "{law:?} P={p1:e}: {m}");
        if p1.is_finite()
            && p1 > po[0] * (1.0 - 1e-6) + 1e-300
            && all_typical
            && p1.abs() <= f0 * 1e6
        {
            assert!(
                kind == Kind::Derjaguin || p1 < po[0] * (1.0 - 1e-7),
                "{law:?}: P={p1:e} (pull-off {:e}) refused: {m}",
                po[0]
            );
        }
    }
}

#[track_caller]
fn close(got: f64, want: f64, rel: f64, law: &NormalLaw) {
    assert!(
        (got - want).abs() <= rel * want.abs(),
        "{law:?}: {got:e} vs closed form {want:e}"
    );
}

fn sweep_laws(n: usize) {
    // Two threads: the sweep is embarrassingly parallel and deterministic per
    // law (each law has its own seed).
    let tallies: Vec<(Kind, Tally)> = std::thread::scope(|s| {
        let hs: Vec<_> = KINDS
            .iter()
            .map(|&k| s.spawn(move || (k, sweep_law(k, n, 0x5EED_0001))))
            .collect();
        hs.into_iter().map(|h| h.join().unwrap()).collect()
    });
    for (k, t) in &tallies {
        t.print(&format!("{k:?}"));
    }
}

#[test]
fn laws_quick() {
    sweep_laws(QUICK);
}

#[test]
#[ignore = "10⁶ points per law: run in release (.ci/run)"]
fn laws_full() {
    sweep_laws(FULL);
}

// ------------------------------------------------------------ switches

/// Continuity across the internal series/limit switches, evaluated just
/// either side of each: Maugis–Dugdale's series for f₁ at s = 0.25 (random
/// λ), the no-slip factor's Taylor series at ν = 1/2 − 1e-4, JKR's Hertz
/// seed above Δ = 1e60.
#[test]
fn continuity_across_switches() {
    let mut rng = Rng::new(0xC0);
    // Maugis–Dugdale contact branch at s = SERIES_SWITCH (1 ± 1e-12).
    for _ in 0..2000 {
        let lam = rng.log_uniform(1e-6, 1e6);
        let md = MaugisDugdale::from_maugis_parameter(1e-6, 1e11, 0.5, lam).unwrap();
        let lo = md.contact_point(SERIES_SWITCH * (1.0 - 1e-12)).unwrap();
        let hi = md.contact_point(SERIES_SWITCH * (1.0 + 1e-12)).unwrap();
        for (a, b, what) in [
            (lo.a_bar, hi.a_bar, "A"),
            (lo.p_bar, hi.p_bar, "P"),
            (lo.delta_bar, hi.delta_bar, "Δ"),
        ] {
            let scale = a.abs().max(b.abs()).max(lo.a_bar.powi(3));
            assert!(
                (a - b).abs() <= 1e-9 * scale,
                "λ = {lam:e}: {what} jumps at the series switch: {a:e} vs {b:e}"
            );
        }
    }
    // No-slip factor: continuous and monotone (decreasing in ν) across
    // ν = 1/2 − 1e-4.
    let nu = 0.5 - NO_SLIP_SERIES_SWITCH;
    let below = no_slip_factor(nu - 1e-15).unwrap();
    let at = no_slip_factor(nu).unwrap();
    let above = no_slip_factor(nu + 1e-15).unwrap();
    assert!(below >= at && at >= above, "{below} {at} {above}");
    assert!((below - above).abs() <= 1e-14, "{below} {above}");
    // JKR at Δ = δ/δ_scale = 1e60 (1 ± 1e-9): the force ratio is Hertz's
    // (1 + ε)^{3/2}/(1 − ε)^{3/2}.
    let jkr = Jkr::new(1e-6, 1e11, 1e-20).unwrap();
    let d0 = 1e60 * jkr.delta_scale();
    let e = 1e-9;
    let f = |d: f64| jkr.eval(d, &ContactState::default()).unwrap().0.force;
    let ratio = f(d0 * (1.0 + e)) / f(d0 * (1.0 - e));
    let want = ((1.0 + e) / (1.0 - e)).powf(1.5);
    assert!((ratio - want).abs() <= 1e-12, "{ratio} vs {want}");
}
