//! Tabulated laws (`src/ffi/tabulated.rs`): Maugis–Dugdale and
//! Lennard-Jones tables, their evaluation, JSON round trips, freeing.

use super::common::*;
use super::contact::{eval_one, normal_batch};
use super::{pick, take, Ctx, Op};
use asperity::contact::NormalResponse;
use asperity::ffi::tabulated::*;
use std::ffi::c_char;
use std::ptr::{null, null_mut};

/// Runs one operation of this domain; `super::call` routes each variant
/// to the module of its `src/ffi/` file.
pub(super) unsafe fn call(ctx: &mut Ctx, op: &Op) {
    match op {
        Op::TableMd { a, null } => {
            let [r, e, w, s0, tol] = fs(*a);
            // A tolerance below 1e-6 builds large tables: one per input.
            if tol.abs() < 1e-6 && tol != 0.0 {
                if ctx.expensive > 0 {
                    return;
                }
                ctx.expensive += 1;
            }
            let mut t = null_mut();
            let s = asperity_table_new_maugis_dugdale(r, e, w, s0, tol, mp(&mut t, *null));
            if let Some(t) = made(s, t, !*null, "table_new_maugis_dugdale") {
                ctx.tables.push(t);
            }
        }
        Op::TableLj {
            a,
            grid,
            tolerance,
            null,
        } => {
            // A valid tolerance below 1e-5 samples 10^4–10^5 solver points
            // (2–8 s in a release build, ten times that instrumented).
            if (1e-10..1e-5).contains(&tolerance.0) {
                return;
            }
            if ctx.expensive > 0 {
                return;
            }
            ctx.expensive += 1;
            let [r, e, w, z0] = fs(*a);
            let mut t = null_mut();
            let s = asperity_table_new_lj(r, e, w, z0, grid.0, tolerance.0, mp(&mut t, *null));
            if let Some(t) = made(s, t, !*null, "table_new_lj") {
                ctx.tables.push(t);
            }
        }
        Op::TableEval {
            table,
            delta,
            old,
            nulls,
        } => {
            let t = pick(&ctx.tables, *table);
            eval_one(ctx, *old, *nulls, nulls.at(3), "table_eval", |o, n, r| {
                asperity_table_eval(t, delta.0, o, n, r)
            });
        }
        Op::TableEvalBatch {
            table,
            delta,
            old,
            nulls,
            alias,
        } => {
            let t = pick(&ctx.tables, *table);
            normal_batch(
                ctx,
                delta,
                *old,
                *nulls,
                *alias,
                "table_eval_batch",
                |n, d, o, w, f, r, k| asperity_table_eval_batch(t, n, d, o, w, f, r, k),
            );
        }
        Op::TableEvalAtLoad { table, force, null } => {
            let t = pick(&ctx.tables, *table);
            let mut out: NormalResponse = zeroed();
            ok(
                asperity_table_eval_at_load(t, force.0, mp(&mut out, *null)),
                "table_eval_at_load",
            );
        }
        Op::TablePullOff {
            table,
            control,
            null,
        } => {
            let t = pick(&ctx.tables, *table);
            let mut f = 0.0;
            ok(
                asperity_table_pull_off_force(t, control.0, mp(&mut f, *null)),
                "table_pull_off",
            );
        }
        Op::TableMaxError { table, nulls } => {
            let t = pick(&ctx.tables, *table);
            let (mut a, mut b) = (0.0, 0.0);
            ok(
                asperity_table_max_error(t, mp(&mut a, nulls.at(0)), mp(&mut b, nulls.at(1))),
                "table_max_error",
            );
        }
        Op::TableToJson { table, len, nulls } => {
            let t = pick(&ctx.tables, *table);
            let mut buf = vec![1 as c_char; len.0];
            let mut needed = 0;
            let p = if nulls.at(0) {
                null_mut()
            } else {
                buf.as_mut_ptr()
            };
            let s = asperity_table_to_json(t, p, len.0, mp(&mut needed, nulls.at(1)));
            if ok(s, "table_to_json") && !nulls.at(0) && len.0 > 0 {
                assert_eq!(buf[needed.min(len.0 - 1)], 0);
            }
        }
        Op::TableFromJson {
            table,
            mutation,
            raw,
            nulls,
        } => {
            let t = pick(&ctx.tables, *table);
            let mut text = match raw {
                Some(r) => r.clone(),
                None if t.is_null() => return,
                None => match json_of(|b, l, n| asperity_table_to_json(t, b, l, n)) {
                    Some(j) => j,
                    None => return,
                },
            };
            mutation.apply(&mut text);
            let mut out = null_mut();
            let jp = if nulls.at(0) {
                null()
            } else {
                text.as_ptr() as *const c_char
            };
            let s = asperity_table_from_json(jp, text.len(), mp(&mut out, nulls.at(1)));
            if let Some(t) = made(s, out, !nulls.at(1), "table_from_json") {
                ctx.tables.push(t);
            }
        }
        Op::TableFree { table } => {
            if let Some(t) = take(&mut ctx.tables, *table) {
                asperity_table_free(t);
            } else {
                asperity_table_free(null_mut());
            }
        }
        Op::TableReach {
            table,
            control,
            rel_force,
            null,
        } => {
            let t = pick(&ctx.tables, *table);
            let mut d = 0.0;
            ok(
                asperity_table_reach(t, control.0, rel_force.0, mp(&mut d, *null)),
                "table_reach",
            );
        }
        _ => unreachable!("not a tabulated operation: {op:?}"),
    }
}
