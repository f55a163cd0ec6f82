//! Hierarchical roughness (`src/ffi/hierarchical.rs`): Archard's exponent
//! and load–area batch, the Cantor profile's contact batch and exponents,
//! with NULL pointers and out-of-range values; every `Ok` output finite;
//! Schmittbuhl's renormalisation (default fields where a fuzzed one is
//! valid, a capacity short or long enough).

use super::common::*;
use super::{Ctx, Op};
use asperity::ffi::hierarchical::*;
use asperity::hierarchical::{CantorContact, CantorProfile};
use std::ptr::null_mut;

/// Runs one operation of this domain.
pub(super) unsafe fn call(op: &Op) {
    match op {
        Op::Archard {
            model,
            radii,
            densities,
            modulus,
            loads,
            generations,
            nulls,
        } => {
            let mut a = 0.0;
            let s =
                asperity_archard_exponent(model.0, *generations as usize, mp(&mut a, nulls.at(0)));
            if ok(s, "archard_exponent") {
                assert!(a.is_finite() && a > 0.0 && a <= 1.0, "exponent {a}");
            }
            let r: Vec<f64> = radii.iter().take(8).map(|f| f.0).collect();
            let d: Vec<f64> = densities.iter().take(8).map(|f| f.0).collect();
            let w: Vec<f64> = loads.iter().map(|f| f.0).collect();
            let mut out = vec![0.0; w.len()];
            // The densities need radii.len() - 1 readable values.
            let g = r.len().min(d.len() + 1);
            let s = asperity_archard_area_batch(
                model.0,
                bufp(&r, nulls.at(1)),
                bufp(&d, nulls.at(2)),
                g,
                modulus.0,
                w.len(),
                bufp(&w, nulls.at(3)),
                bufm(&mut out, nulls.at(4)),
            );
            if ok(s, "archard_area_batch") {
                assert!(out.iter().all(|x| x.is_finite() && *x >= 0.0), "{out:?}");
            }
        }
        Op::CantorContact {
            descendants,
            generations,
            a,
            depths,
            nulls,
        } => {
            let [r, q, w0, h0, k, h] = fs(*a);
            let p = CantorProfile {
                descendants: *descendants,
                generations: *generations,
                width_ratio: r,
                height_ratio: q,
                base_width: w0,
                base_height: h0,
            };
            let d: Vec<f64> = depths.iter().map(|f| f.0).collect();
            let mut out = vec![CantorContact::default(); d.len()];
            let o = if nulls.at(2) {
                null_mut()
            } else {
                out.as_mut_ptr()
            };
            let s = asperity_cantor_contact_batch(
                cp(&p, nulls.at(0)),
                k,
                h,
                d.len(),
                bufp(&d, nulls.at(1)),
                o,
            );
            if ok(s, "cantor_contact_batch") {
                for c in &out {
                    assert!(c.width.is_finite() && c.plastic_load.is_finite(), "{c:?}");
                }
            }
            let (mut x, mut y, mut z) = (0.0, 0.0, 0.0);
            let s = asperity_cantor_exponents(
                cp(&p, nulls.at(3)),
                mp(&mut x, nulls.at(4)),
                mp(&mut y, nulls.at(5)),
                mp(&mut z, nulls.at(6)),
            );
            if ok(s, "cantor_exponents") {
                assert!(x.is_finite() && z.is_finite(), "{x} {z}");
            }
        }
        _ => unreachable!("not a hierarchical operation"),
    }
}

/// Schmittbuhl's renormalisation: `asperity_schmittbuhl_default` and
/// `asperity_schmittbuhl_run`; a fuzzed field the validation accepts is
/// replaced by the default's (bounded cost), a rejected one is kept.
pub(super) unsafe fn call_schmittbuhl(ctx: &mut Ctx, op: &Op) {
    let Op::Schmittbuhl {
        a,
        ratio,
        generations,
        dimension,
        room,
        nulls,
    } = op
    else {
        unreachable!("not a Schmittbuhl operation")
    };
    let mut d: AsperitySchmittbuhl = zeroed();
    let s = asperity_schmittbuhl_default(mp(&mut d, nulls.at(0)));
    if !ok(s, "schmittbuhl_default") {
        d = AsperitySchmittbuhl {
            mu_static: 0.5,
            mu_kinetic: 0.3,
            weakening_velocity: 0.05,
            mass: 1e-5,
            coupling_stiffness: 1e3,
            pulling_stiffness: 1e3,
            normal_force: 1.0,
            velocity: 1e-4,
            disorder: 0.5,
            ratio: 3,
            generations: 3,
            dimension: 3,
            reserved: 0,
        };
    }
    let [mu_s, mu_k, vc, m, kc, kp, n, v, dis] = fs(*a);
    // Keep a value only where the validation rejects it.
    let bad = |x: f64, lo: f64, strict: bool| {
        x.is_nan() || x.is_infinite() || x < lo || (strict && x == lo)
    };
    let mut p = d;
    if bad(mu_s, 0.0, false) {
        p.mu_static = mu_s;
    }
    if bad(mu_k, 0.0, false) || mu_k > p.mu_static {
        p.mu_kinetic = mu_k;
    }
    if vc.is_nan() || vc <= 0.0 {
        p.weakening_velocity = vc;
    }
    if bad(m, 0.0, true) {
        p.mass = m;
    }
    if bad(kc, 0.0, false) {
        p.coupling_stiffness = kc;
    }
    if bad(kp, 0.0, true) {
        p.pulling_stiffness = kp;
    }
    if bad(n, 0.0, true) {
        p.normal_force = n;
    }
    if bad(v, 0.0, true) {
        p.velocity = v;
    }
    if !(0.0..1.0).contains(&dis) {
        p.disorder = dis;
    }
    p.ratio = match ratio % 8 {
        0..=5 => 1 + u32::from(ratio % 4), // 1 (invalid) ..= 4
        6 => 65,
        _ => u32::MAX,
    };
    p.generations = match generations % 8 {
        0..=5 => u32::from(generations % 3), // 0 (invalid) ..= 2
        6 => 13,
        _ => u32::MAX,
    };
    p.dimension = u32::from(*dimension % 5);
    // Room for G + 1, one fewer, or many.
    let want = (p.generations as usize).saturating_add(1).min(64);
    let cap = match room % 4 {
        0 => want.saturating_sub(1),
        1 => 64,
        _ => want,
    };
    let mut out = vec![AsperitySchmittbuhlGeneration::default(); cap];
    let mut written = usize::MAX;
    // A run that gets past the validation integrates chains: once per input.
    let valid = (2..=4).contains(&p.ratio)
        && (1..=2).contains(&p.generations)
        && (2..=3).contains(&p.dimension);
    if valid && !ctx.affordable(f64::INFINITY) {
        return;
    }
    let o = if nulls.at(2) {
        null_mut()
    } else {
        out.as_mut_ptr()
    };
    let s = asperity_schmittbuhl_run(cp(&p, nulls.at(1)), cap, o, mp(&mut written, nulls.at(3)));
    if ok(s, "schmittbuhl_run") {
        if !nulls.at(3) {
            assert_eq!(written, p.generations as usize + 1);
        }
        for g in &out[..p.generations as usize + 1] {
            assert!(
                g.mu_static.is_finite() && g.mu_kinetic >= 0.0 && g.mu_kinetic <= g.mu_static,
                "{g:?}"
            );
        }
    } else {
        assert_eq!(written, usize::MAX, "a failed run wrote `written`");
    }
}
