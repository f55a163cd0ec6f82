//! Sweeps at the extremes (issue 8 §4): a deterministic random sweep of
//! parameter points per law, log-uniform over the documented domain of every
//! argument and a decade beyond it on each side, plus zero, negatives, NaN
//! and ±∞ at a small rate, and a few points out at the ends of `f64`
//! (1e±300). Through the C ABI (so the status and message path is swept),
//! compared with the Rust API on every point.
//!
//! Asserted on every point:
//! * status OK ⇒ every output finite (and the documented signs: contact
//!   radius ≥ 0, pull-off ≤ 0, …);
//! * an argument outside its documented domain ⇒ a non-zero status whose
//!   message names (one of) the offending argument(s), and the Rust API gives
//!   the same error text;
//! * inside the domain an error is allowed only where it is documented
//!   (overflow of f64, a load below pull-off, a combination bound such as
//!   Maugis–Dugdale's λ ∈ [1e-8, 1e8]) and must name an argument of the call;
//! * monotonicity where the theory promises it: the force grows with the
//!   approach on the contact branch, dP/dδ ≥ 0 there (> 0 for Hertz), the
//!   overlap and contact radius grow with the load on the load-controlled
//!   stable branch, pull-off is finite and negative for adhesive laws (and
//!   equals its closed form for JKR, DMT, Kendall; lies between them for
//!   Maugis–Dugdale);
//! * continuity across the internal switches (`continuity_across_switches`).
//!
//! Beyond the closed-form laws (`laws_*`), the same harness sweeps the
//! scalar C functions of `material` and `rescaling` (`scalars_*`),
//! Greenwood–Williamson surfaces (`statistics_*`: monotone in the
//! separation, the inverse reproduces the load), the homogenised friction
//! step (`homogenised_*`: ΔD ≥ 0, |F| ≤ μ(N + A)) and tabulated
//! Maugis–Dugdale tables (`tabulated_*`: within tolerance of the closed
//! form); failing calls must leave outputs untouched (sentinels), batch
//! calls write exactly the elements before the failing one.
//!
//! `cargo test --test sweeps` runs 10⁴ points per family; the 10⁶-point
//! sweeps are `#[ignore]`d and run in release by `.ci/run`:
//! `cargo test --release --test sweeps -- --ignored`.

use asperity::contact::{
    maugis_dugdale::SERIES_SWITCH, ContactState, Jkr, MaugisDugdale, NormalContact, NormalLaw,
    NormalResponse,
};
use asperity::ffi::contact::*;
use asperity::ffi::*;
use asperity::material::{no_slip_factor, NO_SLIP_SERIES_SWITCH};
use std::collections::BTreeMap;
use std::f64::consts::PI;
use std::ptr::null_mut;

const QUICK: usize = 10_000;
const FULL: usize = 1_000_000;

// ------------------------------------------------------------ sampling

/// splitmix64 (Steele, Lea & Flood 2014): small, seeded, platform
/// independent.
struct Rng(u64);

impl Rng {
    fn new(seed: u64) -> Self {
        Self(seed)
    }
    fn u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    fn f(&mut self) -> f64 {
        (self.u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.f()
    }
    fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (self.uniform(lo.ln(), hi.ln())).exp()
    }
    fn pick<T: Copy>(&mut self, v: &[T]) -> T {
        v[(self.u64() % v.len() as u64) as usize]
    }
}

/// The documented domain of an argument.
#[derive(Clone, Copy, Debug)]
enum Dom {
    /// Finite and > 0.
    Pos,
    /// Finite and ≥ 0.
    NonNeg,
    /// In the closed interval.
    Closed(f64, f64),
    /// In the open interval.
    Open(f64, f64),
    /// In `[lo, hi)`.
    HalfOpen(f64, f64),
    /// Finite and > the bound.
    Gt(f64),
    /// > 0, `+∞` allowed (a rigid body's modulus, a flat's radius).
    PosInf,
    /// Finite, any sign.
    Finite,
}

impl Dom {
    fn contains(self, v: f64) -> bool {
        match self {
            Dom::Pos => v.is_finite() && v > 0.0,
            Dom::NonNeg => v.is_finite() && v >= 0.0,
            Dom::Closed(a, b) => v >= a && v <= b,
            Dom::Open(a, b) => v > a && v < b,
            Dom::HalfOpen(a, b) => v >= a && v < b,
            Dom::Gt(a) => v.is_finite() && v > a,
            Dom::PosInf => v > 0.0,
            Dom::Finite => v.is_finite(),
        }
    }
}

/// An argument: its C name, the names a message may use for it, its domain
/// and the range of typical values (the sweep goes a decade beyond).
#[derive(Clone, Copy)]
struct Arg {
    names: &'static [&'static str],
    dom: Dom,
    lo: f64,
    hi: f64,
}

const fn arg(names: &'static [&'static str], dom: Dom, lo: f64, hi: f64) -> Arg {
    Arg { names, dom, lo, hi }
}

/// One value of `a`: mostly log-uniform over [lo/10, 10·hi] (uniform ±20 %
/// beyond for bounded domains), and at small rates 0, negatives, NaN, ±∞,
/// the domain's end points and values out at 1e±300.
fn sample(rng: &mut Rng, a: &Arg) -> f64 {
    let u = rng.f();
    match u {
        u if u < 0.004 => f64::NAN,
        u if u < 0.008 => f64::INFINITY,
        u if u < 0.012 => f64::NEG_INFINITY,
        u if u < 0.022 => 0.0,
        u if u < 0.035 => -rng.log_uniform(a.lo / 10.0, a.hi * 10.0),
        u if u < 0.05 => {
            let x = rng.log_uniform(1e-300, 1e300);
            if rng.f() < 0.1 {
                -x
            } else {
                x
            }
        }
        u if u < 0.06 => match a.dom {
            Dom::Closed(lo, hi) | Dom::Open(lo, hi) | Dom::HalfOpen(lo, hi) => rng.pick(&[
                lo,
                hi,
                next_up(lo),
                next_down(hi),
                next_down(lo),
                next_up(hi),
            ]),
            Dom::Gt(x) => rng.pick(&[x, next_up(x), next_down(x), f64::MAX]),
            Dom::PosInf => rng.pick(&[f64::MIN_POSITIVE, 5e-324, f64::MAX, f64::INFINITY]),
            Dom::Finite => rng.pick(&[f64::MAX, -f64::MAX, 5e-324, -5e-324]),
            _ => rng.pick(&[f64::MIN_POSITIVE, 5e-324, f64::MAX]),
        },
        _ => match a.dom {
            Dom::Closed(lo, hi) | Dom::Open(lo, hi) | Dom::HalfOpen(lo, hi) if lo <= 0.0 => {
                let w = hi - lo;
                rng.uniform(lo - 0.2 * w, hi + 0.2 * w)
            }
            Dom::Finite => {
                let x = rng.log_uniform(a.lo / 10.0, a.hi * 10.0);
                if rng.f() < 0.5 {
                    -x
                } else {
                    x
                }
            }
            Dom::PosInf if rng.f() < 0.05 => f64::INFINITY,
            _ => rng.log_uniform(a.lo / 10.0, a.hi * 10.0),
        },
    }
}

fn next_up(x: f64) -> f64 {
    if x == 0.0 {
        5e-324
    } else if x > 0.0 {
        f64::from_bits(x.to_bits() + 1)
    } else {
        f64::from_bits(x.to_bits() - 1)
    }
}

fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

/// Whether the value is "typical": inside [lo/10, 10·hi] (or the bounded
/// domain), where no overflow is possible and every call must succeed.
fn typical(a: &Arg, v: f64) -> bool {
    a.dom.contains(v)
        && match a.dom {
            Dom::Closed(..) | Dom::Open(..) => true,
            _ => v >= a.lo / 10.0 && v <= a.hi * 10.0,
        }
}

fn names_one_of(msg: &str, args: &[&Arg]) -> bool {
    args.iter()
        .flat_map(|a| a.names.iter())
        .any(|n| msg.contains(&format!("`{n}`")))
}

/// What a sweep saw, for the printed summary: counts of outcomes and of
/// each distinct message shape (numbers stripped).
#[derive(Default)]
struct Tally {
    points: usize,
    ok: usize,
    errors: BTreeMap<String, usize>,
}

impl Tally {
    fn error(&mut self, msg: &str) {
        let shape: String = msg
            .split_whitespace()
            .map(|w| {
                if w.chars()
                    .next()
                    .is_some_and(|c| c.is_ascii_digit() || c == '-')
                    || w.starts_with("NaN")
                    || w.starts_with("inf")
                {
                    "#"
                } else {
                    w
                }
            })
            .collect::<Vec<_>>()
            .join(" ");
        *self.errors.entry(shape).or_default() += 1;
    }
    fn print(&self, what: &str) {
        println!("{what}: {} points, {} ok", self.points, self.ok);
        for (m, n) in &self.errors {
            println!("  {n:>8} × {m}");
        }
    }
}

// ---------------------------------------------------------------- laws

const RADIUS: Arg = arg(&["radius"], Dom::Pos, 1e-9, 1e-1);
const E_STAR: Arg = arg(&["e_star"], Dom::Pos, 1e6, 1e12);
const W0: Arg = arg(&["work_of_adhesion"], Dom::NonNeg, 1e-3, 10.0);
const W: Arg = arg(&["work_of_adhesion"], Dom::Pos, 1e-3, 10.0);
const NU: Arg = arg(&["nu"], Dom::Closed(0.0, 0.5), 0.0, 0.5);
const B: Arg = arg(&["b"], Dom::Pos, 1e-3, 1e9);
const D: Arg = arg(&["d"], Dom::Closed(1.0, 100.0), 1.0, 100.0);
const HALF_ANGLE: Arg = arg(&["half_angle"], Dom::Open(0.0, PI / 2.0), 0.0, PI / 2.0);
// The C names: errors of `asperity_law_maugis_dugdale` name `sigma0`, those
// of `asperity_law_derjaguin` `parameter` (not the Rust API's
// `cohesive_stress`, `equilibrium_separation`, `decay_length`).
const SIGMA0: Arg = arg(&["sigma0"], Dom::Pos, 1e6, 1e11);
const Z0: Arg = arg(&["parameter"], Dom::Pos, 1e-11, 1e-8);

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

fn finite_response(r: &NormalResponse) -> bool {
    r.force.is_finite()
        && r.delta.is_finite()
        && r.contact_radius.is_finite()
        && r.stiffness.is_finite()
        && r.contact_radius >= 0.0
        && (r.in_contact == 0 || r.in_contact == 1)
}

fn finite_state(s: &ContactState) -> bool {
    s.contact_radius.is_finite()
        && s.cohesive_radius.is_finite()
        && s.contact_radius >= 0.0
        && s.cohesive_radius >= 0.0
}

fn bits(r: &NormalResponse) -> [u64; 5] {
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
fn sample_delta(rng: &mut Rng, l: f64) -> f64 {
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
    let d0 = 1e60 * jkr.delta_scale;
    let e = 1e-9;
    let f = |d: f64| jkr.eval(d, &ContactState::default()).unwrap().0.force;
    let ratio = f(d0 * (1.0 + e)) / f(d0 * (1.0 - e));
    let want = ((1.0 + e) / (1.0 - e)).powf(1.5);
    assert!((ratio - want).abs() <= 1e-12, "{ratio} vs {want}");
}

// ------------------------------------------------- scalar functions

/// Whether `v` is a typical value of `a` for the scalar sweeps: inside its
/// domain and within [lo, hi] for bounded domains, [lo/10, 10·hi] (in
/// magnitude) otherwise.
fn typical_in(a: &Arg, v: f64) -> bool {
    a.dom.contains(v)
        && match a.dom {
            Dom::Closed(..) | Dom::Open(..) | Dom::HalfOpen(..) => v >= a.lo && v <= a.hi,
            Dom::Finite => v.abs() >= a.lo / 10.0 && v.abs() <= a.hi * 10.0,
            Dom::PosInf if v == f64::INFINITY => true,
            _ => v >= a.lo / 10.0 && v <= a.hi * 10.0,
        }
}

/// A C function of scalar arguments with one `double` output, and the
/// Rust function it translates.
struct Scalar {
    name: &'static str,
    args: Vec<Arg>,
    /// Integer selector (its name and valid values), if any.
    sel: Option<(&'static str, &'static [i32])>,
    c: unsafe fn(&[f64], i32, *mut f64) -> i32,
    rust: fn(&[f64], i32) -> asperity::Result<f64>,
    /// The names an error must use when in-domain arguments violate a
    /// documented combination bound (None: no bound violated).
    combination: fn(&[f64]) -> Option<&'static [&'static str]>,
    /// In-domain errors allowed for typical values (the result can leave
    /// f64 there: the rescaling powers).
    overflow_ok: bool,
    /// The result is documented ≥ 0.
    nonneg: bool,
    /// `(i, +1/−1)`: the result is non-decreasing / non-increasing in
    /// argument i (others fixed).
    mono: Option<(usize, f64)>,
}

fn no_combination(_: &[f64]) -> Option<&'static [&'static str]> {
    None
}

fn sweep_scalar(f: &Scalar, n: usize, seed: u64) -> Tally {
    let mut rng = Rng::new(seed ^ f.name.len() as u64 ^ (f.name.as_bytes()[16] as u64) << 32);
    let mut t = Tally::default();
    for _ in 0..n {
        t.points += 1;
        let sel = match f.sel {
            Some((_, ok)) if rng.f() < 0.01 => rng.pick(&[-1, ok.len() as i32 + 1, i32::MIN]),
            Some((_, ok)) => rng.pick(ok),
            None => 0,
        };
        let sel_ok = f.sel.map_or(true, |(_, ok)| ok.contains(&sel));
        let v: Vec<f64> = f.args.iter().map(|a| sample(&mut rng, a)).collect();
        let bad: Vec<&Arg> = f
            .args
            .iter()
            .zip(&v)
            .filter(|(a, x)| !a.dom.contains(**x))
            .map(|(a, _)| a)
            .collect();
        let combo = if bad.is_empty() {
            (f.combination)(&v)
        } else {
            None
        };
        let all_typical = f.args.iter().zip(&v).all(|(a, x)| typical_in(a, *x));
        let sentinel = -12345.678;
        let mut out = sentinel;
        let st = unsafe { (f.c)(&v, sel, &mut out) };
        let rust = (f.rust)(&v, sel);
        let ctx = || format!("{} {v:?} sel {sel}", f.name);
        if st == ASPERITY_OK {
            assert!(
                bad.is_empty() && sel_ok && combo.is_none(),
                "{}: accepted out-of-domain arguments",
                ctx()
            );
            assert!(out.is_finite(), "{}: status OK, result {out:e}", ctx());
            assert!(!f.nonneg || out >= 0.0, "{}: result {out:e} < 0", ctx());
            let r = rust.unwrap_or_else(|e| panic!("{}: C OK, Rust {e}", ctx()));
            assert_eq!(out.to_bits(), r.to_bits(), "{}", ctx());
            t.ok += 1;
            if let (Some((i, dir)), true) = (f.mono, all_typical) {
                let mut w = v.clone();
                w[i] *= 1.0 + rng.log_uniform(1e-9, 1.0);
                if typical_in(&f.args[i], w[i]) {
                    let mut o2 = 0.0;
                    if unsafe { (f.c)(&w, sel, &mut o2) } == ASPERITY_OK {
                        assert!(
                            (o2 - out) * dir >= -1e-12 * out.abs().max(o2.abs()),
                            "{}: not monotone in `{}`: {out:e} then {o2:e} at {:e}",
                            ctx(),
                            f.args[i].names[0],
                            w[i]
                        );
                    }
                }
            }
            continue;
        }
        let m = last_message();
        t.error(&m);
        assert_eq!(
            out.to_bits(),
            sentinel.to_bits(),
            "{}: output written on failure",
            ctx()
        );
        let e = rust.expect_err("C error, Rust OK");
        // Same error text, except where the C function renames: the
        // rescaling calls name the known solution `known_load`,
        // `known_depth`, `known_radius` (Rust: `KnownSolution::new`'s `load`,
        // `depth`, `radius`; `Rescaling::*`'s `known.load`, …).
        let known = ["_depth", "_radius", "_load"]
            .iter()
            .any(|s| f.name.starts_with("asperity_rescaling") && f.name.ends_with(s));
        if !known {
            assert_eq!(m, e.to_string(), "{}", ctx());
        }
        if !sel_ok {
            if bad.is_empty() {
                assert!(m.contains(f.sel.unwrap().0), "{}: {m}", ctx());
            }
            continue;
        }
        if !bad.is_empty() {
            assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT, "{}: {m}", ctx());
            assert!(
                names_one_of(&m, &bad),
                "{}: `{m}` names no bad argument",
                ctx()
            );
        } else if let Some(names) = combo {
            assert!(
                names.iter().any(|n| m.contains(&format!("`{n}`"))),
                "{}: combination bound, message `{m}`",
                ctx()
            );
        } else {
            // In the domain: only an overflow of f64, naming an argument.
            assert_eq!(st, ASPERITY_ERR_OUT_OF_DOMAIN, "{}: {m}", ctx());
            assert!(
                names_one_of(&m, &f.args.iter().collect::<Vec<_>>()),
                "{}: `{m}` names no argument",
                ctx()
            );
            assert!(
                !all_typical || f.overflow_ok,
                "{}: typical arguments refused: {m}",
                ctx()
            );
        }
    }
    t
}

const MOD_E: Arg = arg(&["e1", "e2"], Dom::PosInf, 1e6, 1e12);
const POISSON1: Arg = arg(&["nu1"], Dom::Closed(0.0, 0.5), 0.0, 0.5);
const POISSON2: Arg = arg(&["nu2"], Dom::Closed(0.0, 0.5), 0.0, 0.5);
const Z0_EQ: Arg = arg(&["equilibrium_separation"], Dom::Pos, 1e-11, 1e-8);
const COHESIVE: Arg = arg(&["cohesive_stress"], Dom::Pos, 1e6, 1e11);
const GAMMA: Arg = arg(&["gamma1", "gamma2"], Dom::NonNeg, 1e-2, 10.0);
const HAMAKER: Arg = arg(&["hamaker"], Dom::Pos, 1e-21, 1e-18);
const SEPARATION: Arg = arg(&["separation"], Dom::Pos, 1e-10, 1e-8);
const KAPPA: Arg = arg(&["kappa"], Dom::Closed(0.0, 10.0), 0.0, 10.0);
const LAMBDA: Arg = arg(&["lambda"], Dom::Pos, 1e-3, 1e3);
const LOAD: Arg = arg(&["load"], Dom::NonNeg, 1e-6, 1e2);
const DEPTH: Arg = arg(&["depth"], Dom::NonNeg, 1e-9, 1e-3);
const KNOWN_LOAD: Arg = arg(&["known_load"], Dom::Pos, 1e-6, 1e2);
const KNOWN_DEPTH: Arg = arg(&["known_depth"], Dom::Pos, 1e-9, 1e-3);
const KNOWN_RADIUS: Arg = arg(&["known_radius"], Dom::Pos, 1e-9, 1e-3);
const ANGLE: Arg = arg(
    &["half_angle", "known_half_angle"],
    Dom::Open(0.0, PI / 2.0),
    1e-3,
    1.57,
);
const SLOPE: Arg = arg(
    &["loading_slope", "unloading_slope"],
    Dom::Finite,
    0.1,
    10.0,
);

fn scalars() -> Vec<Scalar> {
    use asperity::ffi::indentation::*;
    use asperity::ffi::material::*;
    use asperity::material as m;
    use asperity::rescaling as rs;
    vec![
        Scalar {
            name: "asperity_effective_modulus",
            args: vec![MOD_E, POISSON1, MOD_E, POISSON2],
            sel: None,
            c: |v, _, o| unsafe { asperity_effective_modulus(v[0], v[1], v[2], v[3], o) },
            rust: |v, _| m::effective_modulus(v[0], v[1], v[2], v[3]),
            combination: |v| (v[0].is_infinite() && v[2].is_infinite()).then_some(&["e2"][..]),
            overflow_ok: false,
            nonneg: true,
            mono: Some((0, 1.0)),
        },
        Scalar {
            name: "asperity_rod_effective_modulus",
            args: vec![MOD_E, MOD_E],
            sel: None,
            c: |v, _, o| unsafe { asperity_rod_effective_modulus(v[0], v[1], o) },
            rust: |v, _| m::rod_effective_modulus(v[0], v[1]),
            combination: |v| (v[0].is_infinite() && v[1].is_infinite()).then_some(&["e2"][..]),
            overflow_ok: false,
            nonneg: true,
            mono: Some((1, 1.0)),
        },
        Scalar {
            name: "asperity_no_slip_factor",
            args: vec![NU],
            sel: None,
            c: |v, _, o| unsafe { asperity_no_slip_factor(v[0], o) },
            rust: |v, _| m::no_slip_factor(v[0]),
            combination: no_combination,
            overflow_ok: false,
            nonneg: true,
            mono: None, // ν scaled multiplicatively would leave [0, 0.5]; see switches test
        },
        Scalar {
            name: "asperity_tabor_parameter",
            args: vec![RADIUS, W0, E_STAR, Z0_EQ],
            sel: None,
            c: |v, _, o| unsafe { asperity_tabor_parameter(v[0], v[1], v[2], v[3], o) },
            rust: |v, _| m::tabor_parameter(v[0], v[1], v[2], v[3]),
            combination: no_combination,
            overflow_ok: false,
            nonneg: true,
            mono: Some((0, 1.0)),
        },
        Scalar {
            name: "asperity_maugis_parameter",
            args: vec![RADIUS, W, E_STAR, COHESIVE],
            sel: None,
            c: |v, _, o| unsafe { asperity_maugis_parameter(v[0], v[1], v[2], v[3], o) },
            rust: |v, _| m::maugis_parameter(v[0], v[1], v[2], v[3]),
            combination: no_combination,
            overflow_ok: false,
            nonneg: true,
            mono: Some((3, 1.0)),
        },
        Scalar {
            name: "asperity_weir_surface_energy_with",
            args: vec![
                arg(&["atomic_mass"], Dom::Pos, 1e-27, 1e-24),
                arg(&["density"], Dom::Pos, 1e2, 3e4),
                arg(&["youngs_modulus"], Dom::Pos, 1e9, 1.2e12),
                arg(&["poisson_ratio"], Dom::HalfOpen(0.0, 0.5), 0.0, 0.499),
                arg(&["m"], Dom::Gt(2.0), 2.5, 12.0),
                arg(&["n"], Dom::Gt(2.0), 6.0, 24.0),
            ],
            sel: Some((
                "prefactor",
                &[ASPERITY_WEIR_PLANE_SUM, ASPERITY_WEIR_THREE_OVER_MN],
            )),
            c: |v, s, o| unsafe {
                asperity_weir_surface_energy_with(v[0], v[1], v[2], v[3], v[4], v[5], s, o)
            },
            rust: |v, s| {
                let k = if s == ASPERITY_WEIR_PLANE_SUM {
                    m::WeirPrefactor::PlaneSum
                } else {
                    m::WeirPrefactor::ThreeOverMn
                };
                if s != ASPERITY_WEIR_PLANE_SUM && s != ASPERITY_WEIR_THREE_OVER_MN {
                    return Err(asperity::Error::UnknownSelector {
                        name: "prefactor",
                        value: s as i64,
                    });
                }
                m::weir_surface_energy(v[0], v[1], v[2], v[3], v[4], v[5], k)
            },
            combination: |v| (v[5] <= v[4]).then_some(&["n"][..]),
            overflow_ok: false,
            nonneg: true,
            mono: Some((2, 1.0)),
        },
        Scalar {
            name: "asperity_pair_work_of_adhesion",
            args: vec![GAMMA, GAMMA],
            sel: Some((
                "rule",
                &[
                    ASPERITY_PAIR_GEOMETRIC_MEAN,
                    ASPERITY_PAIR_SEED001_DIFFERENCE,
                ],
            )),
            c: |v, s, o| unsafe { asperity_pair_work_of_adhesion(v[0], v[1], s, o) },
            rust: |v, s| {
                let rule = match s {
                    ASPERITY_PAIR_GEOMETRIC_MEAN => m::PairRule::GeometricMean,
                    ASPERITY_PAIR_SEED001_DIFFERENCE => m::PairRule::Seed001Difference,
                    v => {
                        return Err(asperity::Error::UnknownSelector {
                            name: "rule",
                            value: v as i64,
                        })
                    }
                };
                m::pair_work_of_adhesion(v[0], v[1], rule)
            },
            combination: no_combination,
            overflow_ok: false,
            nonneg: true,
            mono: None,
        },
        Scalar {
            name: "asperity_hamaker_work_of_adhesion",
            args: vec![HAMAKER, SEPARATION],
            sel: None,
            c: |v, _, o| unsafe { asperity_hamaker_work_of_adhesion(v[0], v[1], o) },
            rust: |v, _| m::hamaker_work_of_adhesion(v[0], v[1]),
            combination: no_combination,
            overflow_ok: false,
            nonneg: true,
            mono: Some((1, -1.0)),
        },
        Scalar {
            name: "asperity_rescaling_depth",
            args: vec![KAPPA, D, LAMBDA, LOAD, KNOWN_LOAD, KNOWN_DEPTH],
            sel: None,
            c: |v, _, o| unsafe { asperity_rescaling_depth(v[0], v[1], v[2], v[3], v[4], v[5], o) },
            rust: |v, _| {
                let k = rs::KnownSolution::new(v[4], v[5], 1.0)?;
                rs::Rescaling::new(v[0], v[1])?.depth(v[2], v[3], &k)
            },
            combination: no_combination,
            overflow_ok: true,
            nonneg: true,
            mono: Some((3, 1.0)),
        },
        Scalar {
            name: "asperity_rescaling_radius",
            args: vec![KAPPA, D, LAMBDA, LOAD, KNOWN_LOAD, KNOWN_RADIUS],
            sel: None,
            c: |v, _, o| unsafe {
                asperity_rescaling_radius(v[0], v[1], v[2], v[3], v[4], v[5], o)
            },
            rust: |v, _| {
                let k = rs::KnownSolution::new(v[4], 1.0, v[5])?;
                rs::Rescaling::new(v[0], v[1])?.radius(v[2], v[3], &k)
            },
            combination: no_combination,
            overflow_ok: true,
            nonneg: true,
            mono: Some((3, 1.0)),
        },
        Scalar {
            name: "asperity_rescaling_load",
            args: vec![KAPPA, D, LAMBDA, DEPTH, KNOWN_LOAD, KNOWN_DEPTH],
            sel: None,
            c: |v, _, o| unsafe { asperity_rescaling_load(v[0], v[1], v[2], v[3], v[4], v[5], o) },
            rust: |v, _| {
                let k = rs::KnownSolution::new(v[4], v[5], 1.0)?;
                rs::Rescaling::new(v[0], v[1])?.load(v[2], v[3], &k)
            },
            combination: no_combination,
            overflow_ok: true,
            nonneg: true,
            mono: Some((3, 1.0)),
        },
        Scalar {
            name: "asperity_rescaling_lambda_spheres",
            args: vec![KNOWN_RADIUS, arg(&["radius"], Dom::Pos, 1e-9, 1e-3)],
            sel: None,
            c: |v, _, o| unsafe { asperity_rescaling_lambda_spheres(v[0], v[1], o) },
            rust: |v, _| rs::lambda_spheres(v[0], v[1]),
            combination: no_combination,
            overflow_ok: false,
            nonneg: true,
            mono: Some((1, -1.0)),
        },
        Scalar {
            name: "asperity_rescaling_lambda_cones",
            args: vec![ANGLE, ANGLE],
            sel: None,
            c: |v, _, o| unsafe { asperity_rescaling_lambda_cones(v[0], v[1], o) },
            rust: |v, _| rs::lambda_cones(v[0], v[1]),
            combination: no_combination,
            overflow_ok: false,
            nonneg: true,
            mono: Some((0, 1.0)),
        },
        Scalar {
            name: "asperity_rescaling_kappa_from_slope",
            args: vec![SLOPE, arg(&["d"], Dom::Pos, 1.0, 100.0)],
            sel: None,
            c: |v, _, o| unsafe { asperity_rescaling_kappa_from_slope(v[0], v[1], o) },
            rust: |v, _| rs::kappa_from_loading_slope(v[0], v[1]),
            combination: |v| ((v[1] - 1.0).abs() < 1e-6).then_some(&["d"][..]),
            overflow_ok: false,
            nonneg: false,
            mono: None,
        },
        Scalar {
            name: "asperity_rescaling_d_from_unloading_slope",
            args: vec![SLOPE],
            sel: None,
            c: |v, _, o| unsafe { asperity_rescaling_d_from_unloading_slope(v[0], o) },
            rust: |v, _| rs::d_from_unloading_slope(v[0]),
            combination: |v| (v[0] <= 1.0).then_some(&["unloading_slope"][..]),
            overflow_ok: false,
            nonneg: true,
            mono: Some((0, -1.0)),
        },
        Scalar {
            name: "asperity_rescaling_d_from_loading_slope",
            args: vec![SLOPE, arg(&["kappa"], Dom::Finite, 0.1, 10.0)],
            sel: None,
            c: |v, _, o| unsafe { asperity_rescaling_d_from_loading_slope(v[0], v[1], o) },
            rust: |v, _| rs::d_from_loading_slope(v[0], v[1]),
            combination: |v| ((v[0] - v[1]).abs() < 1e-12).then_some(&["loading_slope"][..]),
            // (2 − κ)/(m − κ) with m − κ ≥ 1e-12 can exceed f64 for κ ~ 1e300.
            overflow_ok: false,
            nonneg: false,
            mono: None,
        },
        Scalar {
            name: "asperity_galanov_unloading_radius",
            args: vec![
                arg(&["r1"], Dom::Pos, 1e-9, 1e-3),
                arg(&["p1"], Dom::Pos, 1e-6, 1e2),
                arg(&["delta1"], Dom::Pos, 1e-9, 1e-3),
                arg(&["p2"], Dom::Pos, 1e-6, 1e2),
                arg(&["delta2"], Dom::Pos, 1e-9, 1e-3),
            ],
            sel: None,
            c: |v, _, o| unsafe {
                asperity_galanov_unloading_radius(v[0], v[1], v[2], v[3], v[4], o)
            },
            rust: |v, _| rs::galanov_unloading_radius(v[0], v[1], v[2], v[3], v[4]),
            combination: no_combination,
            // (P₂/P₁)²(δ₁/δ₂)³ spans 10^±(2·10 + 3·8) over the typical ranges.
            overflow_ok: false,
            nonneg: true,
            mono: Some((3, 1.0)),
        },
        Scalar {
            name: "asperity_galanov_medium_radius",
            args: vec![
                arg(&["radius"], Dom::Pos, 1e-9, 1e-3),
                arg(&["unloading_radius"], Dom::PosInf, 1e-9, 1e-3),
            ],
            sel: None,
            c: |v, _, o| unsafe { asperity_galanov_medium_radius(v[0], v[1], o) },
            rust: |v, _| rs::medium_radius(v[0], v[1]),
            combination: |v| (v[1] <= v[0]).then_some(&["unloading_radius"][..]),
            overflow_ok: false,
            nonneg: true,
            mono: Some((1, -1.0)),
        },
    ]
}

fn sweep_scalars(n: usize) {
    let fs = scalars();
    let tallies: Vec<(&str, Tally)> = std::thread::scope(|s| {
        let hs: Vec<_> = fs
            .chunks(fs.len().div_ceil(2))
            .map(|chunk| {
                s.spawn(move || {
                    chunk
                        .iter()
                        .map(|f| (f.name, sweep_scalar(f, n, 0x5EED_0002)))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        hs.into_iter().flat_map(|h| h.join().unwrap()).collect()
    });
    for (k, t) in &tallies {
        t.print(k);
    }
}

#[test]
fn scalars_quick() {
    sweep_scalars(QUICK);
}

#[test]
#[ignore = "10⁶ points per function: run in release (.ci/run)"]
fn scalars_full() {
    sweep_scalars(FULL);
}

// ------------------------------------------- Greenwood–Williamson

use asperity::ffi::statistics::*;

const SUMMITS: Arg = arg(&["summit_count"], Dom::Pos, 1.0, 1e9);
const SUMMIT_RADIUS: Arg = arg(&["radius"], Dom::Pos, 1e-7, 1e-3);
const SIGMA: Arg = arg(&["sigma"], Dom::Pos, 1e-9, 1e-5);

/// A separation around the height scale `s`: ±s·U(0, 8) mostly, 0, huge,
/// tiny, NaN and ±∞ at small rates.
fn sample_separation(rng: &mut Rng, s: f64) -> f64 {
    match rng.f() {
        u if u < 0.004 => f64::NAN,
        u if u < 0.008 => f64::INFINITY,
        u if u < 0.012 => f64::NEG_INFINITY,
        u if u < 0.02 => 0.0,
        u if u < 0.05 => rng.log_uniform(1e-300, 1e300) * rng.pick(&[-1.0, 1.0]),
        u if u < 0.1 => s * rng.log_uniform(1e-6, 1e6) * rng.pick(&[-1.0, 1.0]),
        _ => s * rng.uniform(-8.0, 8.0),
    }
}

fn gw_bits(r: &AsperityGwResponse) -> [u64; 4] {
    [
        r.load.to_bits(),
        r.area.to_bits(),
        r.contacts.to_bits(),
        r.stiffness.to_bits(),
    ]
}

fn gw_finite(r: &AsperityGwResponse) -> bool {
    [r.load, r.area, r.contacts, r.stiffness]
        .iter()
        .all(|x| x.is_finite() && *x >= 0.0)
}

/// One Greenwood–Williamson surface (C evaluation closure, Rust model,
/// whether its parameters are typical) swept over separations: OK ⇒ every
/// output finite and ≥ 0, equal to the Rust API's; load, area, contacts and
/// stiffness non-increasing in the separation; the separation at a load
/// reproduces the load; a batch with a bad element at j writes the elements
/// before j, leaves those from j on untouched and names j.
/// A batch call: separations in, loads and areas out, the status.
type GwBatch<'a> = dyn Fn(&[f64], &mut [f64], &mut [f64]) -> i32 + 'a;

#[allow(clippy::too_many_arguments)]
fn gw_check(
    eval: &dyn Fn(f64, &mut AsperityGwResponse) -> i32,
    at_load: &dyn Fn(f64, &mut AsperitySeparation) -> i32,
    batch: &GwBatch<'_>,
    model: &asperity::statistics::GreenwoodWilliamson,
    scale: f64,
    typical: bool,
    rng: &mut Rng,
    t: &mut Tally,
) {
    let d1 = sample_separation(rng, scale);
    let d2 = d1 + scale * rng.log_uniform(1e-6, 1.0);
    let mut r = [AsperityGwResponse::default(); 2];
    let mut ok = [false; 2];
    for (k, d) in [d1, d2].into_iter().enumerate() {
        let st = eval(d, &mut r[k]);
        let rust = model.response(d).and_then(|x| Ok((x, model.stiffness(d)?)));
        if st == ASPERITY_OK {
            assert!(gw_finite(&r[k]), "{model:?} d={d:e}: {:?}", r[k]);
            let (x, s) = rust.unwrap();
            assert_eq!(
                gw_bits(&r[k]),
                gw_bits(&AsperityGwResponse {
                    load: x.load,
                    area: x.area,
                    contacts: x.contacts,
                    stiffness: s
                })
            );
            ok[k] = true;
        } else {
            let m = last_message();
            t.error(&m);
            assert_eq!(m, rust.unwrap_err().to_string());
            assert!(m.contains("`separation`"), "{model:?} d={d:e}: {m}");
            assert!(
                !d.is_finite() || !typical || d.abs() > 1e6 * scale,
                "{model:?}: typical separation {d:e} refused: {m}"
            );
        }
    }
    if ok[0] && ok[1] && d2 > d1 {
        let (a, b) = (&r[0], &r[1]);
        for (x, y, what) in [
            (a.load, b.load, "load"),
            (a.area, b.area, "area"),
            (a.contacts, b.contacts, "contacts"),
            (a.stiffness, b.stiffness, "stiffness"),
        ] {
            assert!(
                y <= x * (1.0 + 1e-12),
                "{model:?}: {what} grows with the separation: {x:e} at {d1:e}, {y:e} at {d2:e}"
            );
        }
    }
    // Inverse: the separation that carries the load at d1.
    if ok[0] && typical && r[0].load > 1e-300 * scale {
        let mut s = AsperitySeparation::default();
        let st = at_load(r[0].load, &mut s);
        if st == ASPERITY_OK {
            assert!(
                s.separation.is_finite() && s.relative_residual <= 1e-9,
                "{s:?}"
            );
            let p = model.load(s.separation).unwrap();
            assert!(
                (p / r[0].load - 1.0).abs() <= 1e-9,
                "{model:?}: P({:e}) = {p:e}, wanted {:e}",
                s.separation,
                r[0].load
            );
        } else {
            let m = last_message();
            t.error(&m);
            assert!(m.contains("`load`"), "{m}");
            assert!(
                d1.abs() > 100.0 * scale,
                "separation at load {:e} (d = {d1:e}) refused: {m}",
                r[0].load
            );
        }
    }
    // Batch with one bad element.
    if typical && rng.f() < 0.02 {
        let n = 8;
        let j = (rng.u64() % n as u64) as usize;
        let mut sep: Vec<f64> = (0..n).map(|_| scale * rng.uniform(-4.0, 4.0)).collect();
        sep[j] = rng.pick(&[f64::NAN, f64::INFINITY, f64::NEG_INFINITY]);
        let sentinel = -7.25;
        let mut load = vec![sentinel; n];
        let mut area = vec![sentinel; n];
        let st = batch(&sep, &mut load, &mut area);
        assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT);
        let m = last_message();
        assert!(
            m.starts_with(&format!("element {j}: ")) && m.contains("`separation`"),
            "{m}"
        );
        for i in 0..n {
            if i < j {
                let x = model.response(sep[i]).unwrap();
                assert_eq!((load[i], area[i]), (x.load, x.area), "element {i} < {j}");
            } else {
                assert_eq!(
                    (load[i], area[i]),
                    (sentinel, sentinel),
                    "element {i} ≥ {j}"
                );
            }
        }
    }
}

fn sweep_gw(n: usize, seed: u64) -> Tally {
    let mut rng = Rng::new(seed);
    let mut t = Tally::default();
    let args = [SUMMITS, SUMMIT_RADIUS, SIGMA, E_STAR];
    for _ in 0..n {
        t.points += 1;
        let dist = if rng.f() < 0.01 {
            rng.pick(&[0, 3, -1])
        } else {
            rng.pick(&[ASPERITY_HEIGHTS_GAUSSIAN, ASPERITY_HEIGHTS_EXPONENTIAL])
        };
        let v: Vec<f64> = args.iter().map(|a| sample(&mut rng, a)).collect();
        let gw = AsperityGwParams {
            distribution: dist,
            reserved: 0,
            summit_count: v[0],
            radius: v[1],
            sigma: v[2],
            e_star: v[3],
        };
        let bad: Vec<&Arg> = args
            .iter()
            .zip(&v)
            .filter(|(a, x)| !a.dom.contains(**x))
            .map(|(a, _)| a)
            .collect();
        let typical = args.iter().zip(&v).all(|(a, x)| typical(a, *x));
        let model = match gw.to_model() {
            Ok(m) => m,
            Err(e) => {
                // Every C call refuses the parameters with the same message.
                let mut r = AsperityGwResponse::default();
                let st = unsafe { asperity_gw_eval(&gw, 0.0, &mut r) };
                assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT);
                let m = last_message();
                assert_eq!(m, e.to_string());
                t.error(&m);
                assert!(
                    names_one_of(&m, &bad) || m.contains("`gw.distribution`"),
                    "{gw:?}: {m}"
                );
                continue;
            }
        };
        assert!(bad.is_empty(), "{gw:?} accepted");
        t.ok += 1;
        gw_check(
            &|d, r| unsafe { asperity_gw_eval(&gw, d, r) },
            &|p, s| unsafe { asperity_gw_separation_at_load(&gw, p, s) },
            &|s, l, a| unsafe {
                asperity_gw_eval_batch(
                    &gw,
                    s.len(),
                    s.as_ptr(),
                    l.as_mut_ptr(),
                    a.as_mut_ptr(),
                    null_mut(),
                    null_mut(),
                )
            },
            &model,
            v[2],
            typical,
            &mut rng,
            &mut t,
        );
    }
    t
}

/// An empirical surface (300 summits, heights Gaussian-ish, radii
/// log-uniform) built once, swept over separations.
fn sweep_gw_empirical(n: usize, seed: u64) -> Tally {
    let mut rng = Rng::new(seed);
    let mut t = Tally::default();
    let heights: Vec<f64> = (0..300)
        .map(|_| 1e-7 * (rng.f() + rng.f() + rng.f() - 1.5))
        .collect();
    let radii: Vec<f64> = (0..300).map(|_| rng.log_uniform(1e-6, 1e-4)).collect();
    let mut h = null_mut();
    assert_eq!(
        unsafe {
            asperity_gw_empirical_new(
                1e6,
                1e-5,
                1e11,
                300,
                heights.as_ptr(),
                radii.as_ptr(),
                &mut h,
            )
        },
        ASPERITY_OK
    );
    let model = asperity::statistics::GreenwoodWilliamson::new(
        1e6,
        1e-5,
        1e11,
        asperity::statistics::HeightDistribution::Empirical(
            asperity::statistics::EmpiricalHeights::with_radii(heights, radii).unwrap(),
        ),
    )
    .unwrap();
    let hc = h as usize;
    for _ in 0..n {
        t.points += 1;
        t.ok += 1;
        let h = hc as *const AsperityGwEmpirical;
        gw_check(
            &|d, r| unsafe { asperity_gw_empirical_eval(h, d, r) },
            &|p, s| unsafe { asperity_gw_empirical_separation_at_load(h, p, s) },
            &|s, l, a| unsafe {
                asperity_gw_empirical_eval_batch(
                    h,
                    s.len(),
                    s.as_ptr(),
                    l.as_mut_ptr(),
                    a.as_mut_ptr(),
                    null_mut(),
                    null_mut(),
                )
            },
            &model,
            5e-8,
            true,
            &mut rng,
            &mut t,
        );
    }
    unsafe { asperity_gw_empirical_free(h) };
    t
}

fn sweep_statistics(n: usize) {
    let (a, b) = std::thread::scope(|s| {
        let a = s.spawn(|| sweep_gw(n, 0x5EED_0003));
        let b = s.spawn(|| sweep_gw_empirical(n / 10, 0x5EED_0004));
        (a.join().unwrap(), b.join().unwrap())
    });
    a.print("Greenwood–Williamson (Gaussian, exponential)");
    b.print("Greenwood–Williamson (300 listed summits)");
}

#[test]
fn statistics_quick() {
    sweep_statistics(QUICK);
}

#[test]
#[ignore = "10⁶ points: run in release (.ci/run)"]
fn statistics_full() {
    sweep_statistics(FULL);
}

// ------------------------------------------- homogenised friction

#[allow(dead_code)]
mod common;
use common::c_errors::last_message;

use asperity::ffi::homogenised::*;
use asperity::friction::{FrictionIncrement, FrictionPointState, FrictionResponse};

const NORMAL_FORCE: Arg = arg(&["normal_force"], Dom::NonNeg, 1e-3, 1e3);
const AREA: Arg = arg(&["area"], Dom::Pos, 1e-8, 1e-4);
const SLIP: Arg = arg(&["slip"], Dom::Finite, 1e-10, 1e-4);
const DT: Arg = arg(&["dt"], Dom::NonNeg, 1e-6, 1.0);
const STICK: Arg = arg(&["stick_stiffness"], Dom::NonNeg, 1e5, 1e12);

/// The bytes of a plain `repr(C)` value without padding (the friction state
/// and response), for bit-for-bit comparison.
fn raw<T: Copy>(x: &T) -> &[u8] {
    unsafe { std::slice::from_raw_parts((x as *const T).cast::<u8>(), size_of::<T>()) }
}

fn friction_response_finite(r: &FrictionResponse) -> bool {
    let d = &r.dissipation;
    [
        r.force[0],
        r.force[1],
        r.force_magnitude,
        r.normal_force,
        r.cof,
        r.slip_limit,
        r.adhesion,
        r.true_contact_area,
        r.plastic_slip[0],
        r.plastic_slip[1],
        r.dissipated,
        d.chemical,
        d.van_der_waals,
        d.elastic,
        d.plastic,
        r.dforce_dnormal[0],
        r.dforce_dnormal[1],
        r.dforce_dslip[0][0],
        r.dforce_dslip[0][1],
        r.dforce_dslip[1][0],
        r.dforce_dslip[1][1],
    ]
    .iter()
    .all(|x| x.is_finite())
}

fn state_finite(s: &FrictionPointState) -> bool {
    let d = &s.dissipation;
    [
        s.force[0],
        s.force[1],
        s.slip_path,
        d.chemical,
        d.van_der_waals,
        d.elastic,
        d.plastic,
    ]
    .iter()
    .all(|x| x.is_finite())
}

/// A state and response full of sentinels, to see what a failing call wrote.
fn friction_sentinels() -> (FrictionPointState, FrictionResponse) {
    let s = FrictionPointState {
        force: [-3.5, -3.5],
        slip_path: -3.5,
        steps: 77,
        ..FrictionPointState::default()
    };
    let r = FrictionResponse {
        force: [-3.5, -3.5],
        cof: -3.5,
        dissipated: -3.5,
        regime: 9,
        ..FrictionResponse::default()
    };
    (s, r)
}

fn sweep_homogenised(n: usize, seed: u64) -> Tally {
    let law = common::native::fe_strip_law();
    let samples = law.samples().to_vec();
    let mut h = null_mut();
    assert_eq!(
        unsafe { asperity_homogenised_friction_new(samples.as_ptr(), samples.len(), &mut h) },
        ASPERITY_OK
    );
    let mut rng = Rng::new(seed);
    let mut t = Tally::default();
    let mut last = FrictionPointState::default();
    let mut last_typical = true;
    for _ in 0..n {
        t.points += 1;
        let slip_x = sample(&mut rng, &SLIP);
        let slip_y = if rng.f() < 0.5 {
            0.0
        } else {
            sample(&mut rng, &SLIP)
        };
        let inc = FrictionIncrement {
            normal_force: sample(&mut rng, &NORMAL_FORCE),
            area: sample(&mut rng, &AREA),
            slip: [slip_x, slip_y],
            dt: sample(&mut rng, &DT),
            stick_stiffness: if rng.f() < 0.2 {
                0.0
            } else {
                sample(&mut rng, &STICK)
            },
        };
        let u_old = rng.f();
        let old_typical = u_old < 0.4 || (u_old < 0.95 && last_typical);
        let old = match u_old {
            u if u < 0.4 => FrictionPointState::default(),
            u if u < 0.95 => last,
            _ => {
                let fx = sample(&mut rng, &arg(&["old.force"], Dom::Finite, 1e-6, 1e3));
                let path = sample(&mut rng, &arg(&["old.slip_path"], Dom::NonNeg, 1e-9, 1.0));
                FrictionPointState {
                    force: [fx, 0.0],
                    slip_path: path,
                    ..FrictionPointState::default()
                }
            }
        };
        let vals = [
            (NORMAL_FORCE, inc.normal_force),
            (AREA, inc.area),
            (SLIP, slip_x),
            (SLIP, slip_y),
            (DT, inc.dt),
            (STICK, inc.stick_stiffness),
        ];
        let bad: Vec<&Arg> = vals
            .iter()
            .filter(|(a, x)| !a.dom.contains(*x))
            .map(|(a, _)| a)
            .collect();
        let typical_inc = old_typical
            && vals
                .iter()
                .all(|(a, x)| typical(a, *x) || (*x == 0.0 && a.dom.contains(0.0)));
        let (mut s, mut r) = friction_sentinels();
        let st = unsafe { asperity_homogenised_friction_step(h, &inc, &old, &mut s, &mut r) };
        let rust = law.step_value(&old, &inc);
        if st == ASPERITY_OK {
            assert!(bad.is_empty(), "{inc:?}: accepted");
            t.ok += 1;
            let (rs, rr) = rust.unwrap();
            assert!(raw(&s) == raw(&rs) && raw(&r) == raw(&rr), "{s:?} {r:?}");
            assert!(
                friction_response_finite(&r) && state_finite(&s),
                "{inc:?} {old:?}: {r:?}"
            );
            assert!(r.dissipated >= 0.0, "{inc:?}: ΔD = {:e}", r.dissipated);
            let d = &r.dissipation;
            assert!(
                d.chemical >= 0.0 && d.van_der_waals >= 0.0 && d.elastic >= 0.0 && d.plastic >= 0.0
            );
            // |F| ≤ F_lim = μ(N + A) (Derjaguin form, thesis (4-3)).
            let fm = r.force[0].hypot(r.force[1]);
            // (+ a few units of the subnormal spacing: F_lim = 5e-318 N has
            // five significant digits.)
            assert!(
                fm <= r.slip_limit * (1.0 + 4.0 * f64::EPSILON) + 8.0 * 5e-324,
                "{inc:?}: |F| = {fm:e} > F_lim = {:e}",
                r.slip_limit
            );
            let want = r.cof * (r.normal_force + r.adhesion);
            assert!(
                (r.slip_limit - want).abs() <= 4.0 * f64::EPSILON * want + 8.0 * 5e-324,
                "{:e} vs μ(N + A) = {want:e}",
                r.slip_limit
            );
            last = s;
            last_typical = typical_inc;
        } else {
            let m = last_message();
            t.error(&m);
            assert_eq!(m, rust.unwrap_err().to_string());
            let (s0, r0) = friction_sentinels();
            assert!(
                raw(&s) == raw(&s0) && raw(&r) == raw(&r0),
                "written on failure"
            );
            if !bad.is_empty() {
                assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT, "{m}");
                assert!(names_one_of(&m, &bad), "{inc:?}: {m}");
            } else {
                assert!(
                    m.contains("`old.") || m.contains("`normal_force`") || m.contains("`slip`"),
                    "{inc:?} {old:?}: {m}"
                );
                assert!(
                    !typical_inc || m.contains("`old."),
                    "{inc:?} {old:?}: typical increment refused: {m}"
                );
            }
            last = FrictionPointState::default();
            last_typical = true;
        }

        // The block: one bad element j; elements before j written (equal to
        // single steps), from j on untouched, the message names j.
        if rng.f() < 0.01 {
            let nb = 8;
            let j = (rng.u64() % nb as u64) as usize;
            let k = rng.pick(&[0.0, 1e9]);
            let mut nf: Vec<f64> = (0..nb).map(|_| rng.log_uniform(1e-2, 1e2)).collect();
            let mut ar = vec![1e-6; nb];
            let sl: Vec<f64> = (0..2 * nb).map(|_| rng.uniform(-1e-6, 1e-6)).collect();
            if rng.f() < 0.5 {
                nf[j] = rng.pick(&[f64::NAN, -1.0, f64::INFINITY]);
            } else {
                ar[j] = rng.pick(&[0.0, -1e-6, f64::NAN]);
            }
            let (s0, _) = friction_sentinels();
            let mut ns = vec![s0; nb];
            let mut tf = vec![-3.5; 2 * nb];
            let mut dis = vec![-3.5; nb];
            let st = unsafe {
                asperity_homogenised_friction_step_block(
                    h,
                    nb,
                    nf.as_ptr(),
                    ar.as_ptr(),
                    sl.as_ptr(),
                    1e-3,
                    k,
                    core::ptr::null(),
                    ns.as_mut_ptr(),
                    tf.as_mut_ptr(),
                    dis.as_mut_ptr(),
                )
            };
            assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT);
            let m = last_message();
            assert!(m.starts_with(&format!("element {j}: ")), "{m}");
            for i in 0..nb {
                if i < j {
                    let inc = FrictionIncrement {
                        normal_force: nf[i],
                        area: ar[i],
                        slip: [sl[2 * i], sl[2 * i + 1]],
                        dt: 1e-3,
                        stick_stiffness: k,
                    };
                    let (ws, wr) = law
                        .step_value(&FrictionPointState::default(), &inc)
                        .unwrap();
                    assert_eq!(format!("{:?}", ns[i]), format!("{ws:?}"));
                    assert_eq!(
                        (tf[2 * i], tf[2 * i + 1], dis[i]),
                        (wr.force[0], wr.force[1], wr.dissipated)
                    );
                } else {
                    assert_eq!(
                        format!("{:?}", ns[i]),
                        format!("{s0:?}"),
                        "element {i} ≥ {j}"
                    );
                    assert_eq!((tf[2 * i], tf[2 * i + 1], dis[i]), (-3.5, -3.5, -3.5));
                }
            }
        }
    }
    unsafe { asperity_homogenised_friction_free(h) };
    t
}

#[test]
fn homogenised_quick() {
    sweep_homogenised(QUICK, 0x5EED_0005).print("homogenised friction step");
}

#[test]
#[ignore = "10⁶ increments: run in release (.ci/run)"]
fn homogenised_full() {
    sweep_homogenised(FULL, 0x5EED_0005).print("homogenised friction step");
}

// ------------------------------------------- tabulated Maugis–Dugdale

use asperity::contact::{Control, TabulatedLaw};
use asperity::ffi::tabulated::*;

/// Tables of Maugis–Dugdale spheres (R = 1 µm, E* = 100 GPa, w = 0.5 J/m²)
/// at Maugis parameters 0.05 (DMT-like) … 10 (JKR-like), built once through
/// the C ABI and once through Rust, swept over overlaps (with the history
/// carried from point to point, and fresh), loads and batches.
fn sweep_tabulated(n: usize, seed: u64) -> Tally {
    let mut rng = Rng::new(seed);
    let mut t = Tally::default();
    let tol = 1e-4;
    let tables: Vec<(MaugisDugdale, TabulatedLaw, usize)> = [0.05, 0.5, 2.0, 10.0]
        .iter()
        .map(|&lam| {
            let md = MaugisDugdale::from_maugis_parameter(1e-6, 1e11, 0.5, lam).unwrap();
            let mut h = null_mut();
            let st = unsafe {
                asperity_table_new_maugis_dugdale(
                    md.radius,
                    md.e_star,
                    md.work_of_adhesion,
                    md.cohesive_stress,
                    tol,
                    &mut h,
                )
            };
            assert_eq!(st, ASPERITY_OK, "{}", last_message());
            let rust = TabulatedLaw::from_maugis_dugdale(&md, tol).unwrap();
            (md, rust, h as usize)
        })
        .collect();
    let mut states = vec![ContactState::default(); tables.len()];
    for _ in 0..n {
        t.points += 1;
        let k = (rng.u64() % tables.len() as u64) as usize;
        let (md, law, hc) = &tables[k];
        let h = *hc as *const AsperityTable;
        let l = law.length_scale();
        let fresh = rng.f() < 0.3;
        let old = if fresh {
            ContactState::default()
        } else {
            states[k]
        };
        // Mostly within a few length scales (crossing the jumps with the
        // history carried over); sometimes anywhere.
        let delta = if !fresh && rng.f() < 0.7 {
            l * rng.uniform(-3.0, 5.0)
        } else {
            sample_delta(&mut rng, l)
        };
        let mut r = NormalResponse::default();
        let mut s = ContactState::default();
        let st = unsafe { asperity_table_eval(h, delta, &old, &mut s, &mut r) };
        let rust = law.eval(delta, &old);
        if st == ASPERITY_OK {
            t.ok += 1;
            let (rr, rs) = rust.unwrap();
            assert_eq!(bits(&r), bits(&rr));
            assert_eq!(s, rs);
            assert!(
                finite_response(&r) && finite_state(&s),
                "λ#{k} δ={delta:e}: {r:?}"
            );
            // Against the closed-form law from the same history: the
            // documented error measure, within the tolerance (×2 for the
            // rounding of the measure itself), where both are on the same
            // branch and inside 10³ length scales.
            if let Ok((ex, _)) = md.eval(delta, &old) {
                if ex.in_contact == r.in_contact && delta.abs() <= 1e3 * l {
                    let e = law.relative_error(&ex, &r);
                    assert!(
                        e <= 2.0 * tol,
                        "λ#{k} δ={delta:e} (L = {l:e}) {old:?}: table error {e:e}: {r:?} vs {ex:?}"
                    );
                }
            }
            // Monotone on the branch: a larger overlap from the new state,
            // same branch, compressive ⇒ larger force.
            let d2 = delta + l * rng.log_uniform(1e-6, 1.0);
            if let Ok((r2, s2)) = law.eval(d2, &s) {
                if s2.branch == s.branch && r.force >= 0.0 && delta.abs() <= 1e3 * l {
                    assert!(
                        r2.force >= r.force * (1.0 - 1e-12),
                        "λ#{k}: F({d2:e}) = {:e} < F({delta:e}) = {:e}",
                        r2.force,
                        r.force
                    );
                }
            }
            states[k] = s;
        } else {
            let m = last_message();
            t.error(&m);
            assert_eq!(m, rust.unwrap_err().to_string());
            assert!(m.contains("`delta`"), "{m}");
            assert!(
                !delta.is_finite() || delta.abs() > 1e6 * l,
                "λ#{k} δ={delta:e} (L = {l:e}) refused: {m}"
            );
            states[k] = ContactState::default();
        }

        // Load control.
        let po = law.pull_off_force(Control::Load).unwrap();
        let p = match rng.f() {
            u if u < 0.01 => f64::NAN,
            u if u < 0.03 => po * (1.0 + rng.uniform(-1e-6, 1e-6)),
            u if u < 0.05 => rng.log_uniform(1e-300, 1e300) * rng.pick(&[-1.0, 1.0]),
            _ => -po * rng.log_uniform(1e-6, 1e6) * rng.pick(&[-1.0, 1.0, 1.0]),
        };
        let mut ra = NormalResponse::default();
        let st = unsafe { asperity_table_eval_at_load(h, p, &mut ra) };
        if st == ASPERITY_OK {
            assert!(
                finite_response(&ra) && p >= po * (1.0 + 1e-9),
                "P={p:e}: {ra:?}"
            );
            assert_eq!(bits(&ra), bits(&law.eval_at_load(p).unwrap()));
        } else {
            let m = last_message();
            t.error(&m);
            assert!(m.contains("`force`"), "P={p:e}: {m}");
            assert!(
                !p.is_finite() || p < po * (1.0 - 1e-7) || p.abs() > -po * 1e6,
                "P={p:e} (pull-off {po:e}) refused: {m}"
            );
        }

        // Batch with a bad element j.
        if rng.f() < 0.01 {
            let nb = 8;
            let j = (rng.u64() % nb as u64) as usize;
            let mut d: Vec<f64> = (0..nb).map(|_| l * rng.uniform(-3.0, 5.0)).collect();
            d[j] = rng.pick(&[f64::NAN, f64::INFINITY, f64::NEG_INFINITY]);
            let sentinel = -9.75;
            let mut f = vec![sentinel; nb];
            let mut a = vec![sentinel; nb];
            let mut ns = vec![
                ContactState {
                    contact_radius: sentinel,
                    ..ContactState::default()
                };
                nb
            ];
            let st = unsafe {
                asperity_table_eval_batch(
                    h,
                    nb,
                    d.as_ptr(),
                    core::ptr::null(),
                    ns.as_mut_ptr(),
                    f.as_mut_ptr(),
                    a.as_mut_ptr(),
                    null_mut(),
                )
            };
            assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT);
            let m = last_message();
            assert!(
                m.starts_with(&format!("element {j}: ")) && m.contains("`delta`"),
                "{m}"
            );
            for i in 0..nb {
                if i < j {
                    let (w, ws) = law.eval(d[i], &ContactState::default()).unwrap();
                    assert_eq!((f[i], a[i], ns[i]), (w.force, w.contact_radius, ws));
                } else {
                    assert_eq!(
                        (f[i], a[i], ns[i].contact_radius),
                        (sentinel, sentinel, sentinel)
                    );
                }
            }
        }
    }
    for (_, _, h) in tables {
        unsafe { asperity_table_free(h as *mut AsperityTable) };
    }
    t
}

#[test]
fn tabulated_quick() {
    sweep_tabulated(QUICK, 0x5EED_0006).print("tabulated Maugis–Dugdale");
}

#[test]
#[ignore = "10⁶ points: run in release (.ci/run)"]
fn tabulated_full() {
    sweep_tabulated(FULL, 0x5EED_0006).print("tabulated Maugis–Dugdale");
}
