//! The scalar C functions (one `double` out) of `src/ffi/material.rs` and
//! `src/ffi/indentation.rs` (rescaling, hardness): the harness and the
//! `scalars_*` tests over the lists in `material` and `indentation`.

use super::*;

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
pub(crate) struct Scalar {
    pub(crate) name: &'static str,
    pub(crate) args: Vec<Arg>,
    /// Integer selector (its name and valid values), if any.
    pub(crate) sel: Option<(&'static str, &'static [i32])>,
    pub(crate) c: unsafe fn(&[f64], i32, *mut f64) -> i32,
    pub(crate) rust: fn(&[f64], i32) -> asperity::Result<f64>,
    /// The names an error must use when in-domain arguments violate a
    /// documented combination bound (None: no bound violated).
    pub(crate) combination: fn(&[f64]) -> Option<&'static [&'static str]>,
    /// In-domain errors allowed for typical values (the result can leave
    /// f64 there: the rescaling powers).
    pub(crate) overflow_ok: bool,
    /// The result is documented ≥ 0.
    pub(crate) nonneg: bool,
    /// `(i, +1/−1)`: the result is non-decreasing / non-increasing in
    /// argument i (others fixed).
    pub(crate) mono: Option<(usize, f64)>,
}

pub(crate) fn no_combination(_: &[f64]) -> Option<&'static [&'static str]> {
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

pub(crate) const MOD_E: Arg = arg(&["e1", "e2"], Dom::PosInf, 1e6, 1e12);
pub(crate) const POISSON1: Arg = arg(&["nu1"], Dom::Closed(0.0, 0.5), 0.0, 0.5);
pub(crate) const POISSON2: Arg = arg(&["nu2"], Dom::Closed(0.0, 0.5), 0.0, 0.5);
pub(crate) const Z0_EQ: Arg = arg(&["equilibrium_separation"], Dom::Pos, 1e-11, 1e-8);
pub(crate) const COHESIVE: Arg = arg(&["cohesive_stress"], Dom::Pos, 1e6, 1e11);
pub(crate) const GAMMA: Arg = arg(&["gamma1", "gamma2"], Dom::NonNeg, 1e-2, 10.0);
pub(crate) const HAMAKER: Arg = arg(&["hamaker"], Dom::Pos, 1e-21, 1e-18);
pub(crate) const SEPARATION: Arg = arg(&["separation"], Dom::Pos, 1e-10, 1e-8);
pub(crate) const KAPPA: Arg = arg(&["kappa"], Dom::Closed(0.0, 10.0), 0.0, 10.0);
pub(crate) const LAMBDA: Arg = arg(&["lambda"], Dom::Pos, 1e-3, 1e3);
pub(crate) const LOAD: Arg = arg(&["load"], Dom::NonNeg, 1e-6, 1e2);
pub(crate) const DEPTH: Arg = arg(&["depth"], Dom::NonNeg, 1e-9, 1e-3);
pub(crate) const KNOWN_LOAD: Arg = arg(&["known_load"], Dom::Pos, 1e-6, 1e2);
pub(crate) const KNOWN_DEPTH: Arg = arg(&["known_depth"], Dom::Pos, 1e-9, 1e-3);
pub(crate) const KNOWN_RADIUS: Arg = arg(&["known_radius"], Dom::Pos, 1e-9, 1e-3);
pub(crate) const ANGLE: Arg = arg(
    &["half_angle", "known_half_angle"],
    Dom::Open(0.0, PI / 2.0),
    1e-3,
    1.57,
);
pub(crate) const SLOPE: Arg = arg(
    &["loading_slope", "unloading_slope"],
    Dom::Finite,
    0.1,
    10.0,
);

fn sweep_scalars(n: usize) {
    // The material functions, then the rescaling and hardness ones (each
    // function's points are seeded by its name, not by its place).
    let fs: Vec<Scalar> = super::material::scalars()
        .into_iter()
        .chain(super::indentation::scalars())
        .collect();
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
