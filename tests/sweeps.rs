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
//!
//! Layout, mirroring `src/ffi/`: this file holds the shared sweep harness
//! (seeded sampling, argument domains, the tally) and the arguments several
//! families use; each family is a module in `tests/sweeps/` (included by
//! `#[path]`, so the test binary stays `sweeps`): `contact` (the laws and
//! the continuity across internal switches), `scalars` (the scalar-function
//! harness and its tests, over the lists of `material` and `indentation`),
//! `statistics`, `homogenised`, `tabulated`. Test names carry the module:
//! `contact::laws_quick`, `scalars::scalars_full`, ….

#[allow(dead_code)]
mod common;

#[path = "sweeps/contact.rs"]
mod contact;
#[path = "sweeps/homogenised.rs"]
mod homogenised;
#[path = "sweeps/indentation.rs"]
mod indentation;
#[path = "sweeps/material.rs"]
mod material;
#[path = "sweeps/scalars.rs"]
mod scalars;
#[path = "sweeps/statistics.rs"]
mod statistics;
#[path = "sweeps/tabulated.rs"]
mod tabulated;

use asperity::ffi::*;
use common::c_errors::last_message;
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
// ---------------------------------------------------- shared arguments

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
