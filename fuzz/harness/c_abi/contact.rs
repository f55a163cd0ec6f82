//! Closed-form normal laws (`src/ffi/contact.rs`): constructors (from
//! scalars and from raw inputs), raw and tampered law structs, evaluation
//! (single, batch, at load), pull-off, length scale, reach, energy; and the
//! contact-state helpers the tables share.

use super::common::*;
use super::{Ctx, Op};
use arbitrary::Arbitrary;
use asperity::contact::{ContactState, NormalResponse};
use asperity::ffi::contact::*;
use std::ptr::{null, null_mut};

/// Runs one operation of this domain; `super::call` routes each variant
/// to the module of its `src/ffi/` file.
pub(super) unsafe fn call(ctx: &mut Ctx, op: &Op) {
    match op {
        Op::Law {
            which,
            a,
            sel,
            null,
        } => {
            let [a0, a1, a2, a3, a4] = fs(*a);
            let mut out: AsperityNormalLaw = zeroed();
            let o = mp(&mut out, *null);
            let s = match which % 14 {
                0 => asperity_law_hertz(a0, a1, o),
                1 => asperity_law_sphere_in_crater(a0, a1, a2, o),
                2 => asperity_law_power_punch(a0, a1, a2, o),
                3 => asperity_law_cone(a0, a1, o),
                4 => asperity_law_cone_in_imprint(a0, a1, a2, o),
                5 => asperity_law_flat_punch(a0, a1, o),
                6 => asperity_law_flat_punch_no_slip(a0, a1, a2, o),
                7 => asperity_law_dmt(a0, a1, a2, o),
                8 => asperity_law_jkr(a0, a1, a2, o),
                9 => asperity_law_jkr_power_punch(a0, a1, a2, a3, a4, sel.0, o),
                10 => asperity_law_kendall(a0, a1, a2, a3, sel.0, o),
                11 => asperity_law_maugis_dugdale(a0, a1, a2, a3, o),
                12 => asperity_law_derjaguin(a0, a1, sel.0, a2, o),
                _ => asperity_law_jkr_power_punch(a0, 1.0 + a1.abs() % 99.0, a2, a3, 0.3, 0, o),
            };
            if ok(s, "law constructor") && ctx.laws.len() < 16 {
                ctx.laws.push(out);
            }
        }
        Op::LawRaw { kind, raw } => {
            let mut l: AsperityNormalLaw = zeroed();
            l.kind = kind.0;
            l.params.raw = fs(*raw);
            if ctx.laws.len() < 16 {
                ctx.laws.push(l);
            }
        }
        Op::LawFromParams { kind, raw, nulls } => {
            let p = AsperityLawParams { raw: fs(*raw) };
            let mut out: AsperityNormalLaw = zeroed();
            let s =
                asperity_law_from_params(kind.0, cp(&p, nulls.at(0)), mp(&mut out, nulls.at(1)));
            if ok(s, "law_from_params") && ctx.laws.len() < 16 {
                ctx.laws.push(out);
            }
        }
        Op::LawTamper { law: i, at, value } => {
            let mut l = law(ctx, *i);
            l.params.raw[*at as usize % 16] = value.0;
            if ctx.laws.len() < 16 {
                ctx.laws.push(l);
            }
        }
        Op::Eval {
            law: i,
            delta,
            old,
            nulls,
            alias,
        } => {
            let l = law(ctx, *i);
            let lp = cp(&l, nulls.at(2));
            eval_one(ctx, *old, *nulls, *alias, "normal_eval", |o, n, r| {
                asperity_normal_eval(lp, delta.0, o, n, r)
            });
        }
        Op::EvalBatch {
            law: i,
            delta,
            old,
            nulls,
            alias,
        } => {
            let l = law(ctx, *i);
            let lp = cp(&l, nulls.at(6));
            normal_batch(
                ctx,
                delta,
                *old,
                *nulls,
                *alias,
                "normal_eval_batch",
                |n, d, o, w, f, r, k| asperity_normal_eval_batch(lp, n, d, o, w, f, r, k),
            );
        }
        Op::EvalAtLoad {
            law: i,
            force,
            null,
        } => {
            let l = law(ctx, *i);
            let mut out: NormalResponse = zeroed();
            ok(
                asperity_normal_eval_at_load(&l, force.0, mp(&mut out, *null)),
                "eval_at_load",
            );
        }
        Op::PullOff {
            law: i,
            control,
            null,
        } => {
            let l = law(ctx, *i);
            let mut f = 0.0;
            ok(
                asperity_pull_off_force(&l, control.0, mp(&mut f, *null)),
                "pull_off_force",
            );
        }
        Op::LengthScale { law: i, null } => {
            let l = law(ctx, *i);
            let mut f = 0.0;
            ok(
                asperity_law_length_scale(&l, mp(&mut f, *null)),
                "length_scale",
            );
        }
        Op::Reach {
            law: i,
            control,
            rel_force,
            null,
        } => {
            let l = law(ctx, *i);
            let mut d = 0.0;
            ok(
                asperity_normal_reach(&l, control.0, rel_force.0, mp(&mut d, *null)),
                "normal_reach",
            );
        }
        Op::Energy {
            law: i,
            delta,
            old,
            null: null_out,
        } => {
            let l = law(ctx, *i);
            let (s, old_null) = old_state(ctx, *old);
            let old_p: *const ContactState = if old_null { null() } else { &s };
            let mut u = 0.0;
            ok(
                asperity_normal_energy(&l, delta.0, old_p, mp(&mut u, *null_out)),
                "normal_energy",
            );
        }
        _ => unreachable!("not a contact operation: {op:?}"),
    }
}

#[derive(Debug, Clone, Copy, Arbitrary)]
pub struct State {
    contact_radius: F,
    cohesive_radius: F,
    in_contact: Sel,
    branch: Sel,
}

impl State {
    fn get(&self) -> ContactState {
        ContactState {
            contact_radius: self.contact_radius.0,
            cohesive_radius: self.cohesive_radius.0,
            in_contact: self.in_contact.0,
            branch: self.branch.0,
        }
    }
}

/// Where the old contact state comes from.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum OldState {
    Null,
    Fresh,
    Carried,
    Given(State),
}

pub(super) fn law(ctx: &Ctx, sel: u8) -> AsperityNormalLaw {
    if sel == 255 || ctx.laws.is_empty() {
        // An all-zero law: kind ASPERITY_LAW_NONE.
        zeroed()
    } else {
        ctx.laws[sel as usize % ctx.laws.len()]
    }
}

pub(super) fn old_state(ctx: &Ctx, old: OldState) -> (ContactState, bool) {
    match old {
        OldState::Null => (ContactState::default(), true),
        OldState::Fresh => (ContactState::default(), false),
        OldState::Carried => (ctx.state, false),
        OldState::Given(s) => (s.get(), false),
    }
}

/// A batch of normal evaluations through `call(n, delta, old, new, force,
/// radius, stiffness)`, with NULL or aliased arrays as chosen.
pub(super) fn normal_batch(
    ctx: &mut Ctx,
    delta: &[F],
    old: OldState,
    nulls: Nulls,
    alias: bool,
    what: &str,
    call: impl FnOnce(
        usize,
        *const f64,
        *const ContactState,
        *mut ContactState,
        *mut f64,
        *mut f64,
        *mut f64,
    ) -> i32,
) {
    let n = delta.len().min(256);
    let mut d: Vec<f64> = delta[..n].iter().map(|f| f.0).collect();
    let (s0, old_null) = old_state(ctx, old);
    let mut states = vec![s0; n];
    let mut force = vec![0.0; n];
    let mut radius = vec![0.0; n];
    let mut stiff = vec![0.0; n];
    let sp = states.as_mut_ptr();
    let old_p = if old_null || nulls.at(1) {
        null()
    } else {
        sp as *const ContactState
    };
    let new_p = if nulls.at(2) { null_mut() } else { sp };
    let status = if alias {
        // Outputs written over the input array.
        let dp = bufm(&mut d, nulls.at(0));
        call(
            n,
            dp,
            old_p,
            new_p,
            dp,
            bufm(&mut radius, nulls.at(3)),
            bufm(&mut stiff, nulls.at(4)),
        )
    } else {
        call(
            n,
            bufp(&d, nulls.at(0)),
            old_p,
            new_p,
            bufm(&mut force, nulls.at(5)),
            bufm(&mut radius, nulls.at(3)),
            bufm(&mut stiff, nulls.at(4)),
        )
    };
    if ok(status, what) {
        if let Some(s) = states.last() {
            ctx.state = *s;
        }
    }
}

pub(super) fn eval_one(
    ctx: &mut Ctx,
    old: OldState,
    nulls: Nulls,
    alias: bool,
    what: &str,
    call: impl FnOnce(*const ContactState, *mut ContactState, *mut NormalResponse) -> i32,
) {
    let (mut s, old_null) = old_state(ctx, old);
    let mut new = ContactState::default();
    let mut out: NormalResponse = zeroed();
    let sp: *mut ContactState = &mut s;
    let old_p = if old_null { null() } else { sp as *const _ };
    let new_p = if nulls.at(1) {
        null_mut()
    } else if alias {
        sp
    } else {
        &mut new
    };
    let status = call(old_p, new_p, mp(&mut out, nulls.at(0)));
    if ok(status, what) && !nulls.at(1) {
        ctx.state = if alias { s } else { new };
    }
}
