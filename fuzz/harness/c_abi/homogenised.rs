//! Homogenised friction (`src/ffi/homogenised.rs`, and its law through the
//! one friction handle of `src/ffi/friction_law.rs`): construction from
//! samples and JSON, the law of a table at a stick stiffness, steps,
//! blocks (separate, old == new, in place, with responses), state sizes,
//! freeing.

use super::common::*;
use super::{pick, take, Ctx, Op};
use arbitrary::Arbitrary;
use asperity::ffi::friction_law::*;
use asperity::ffi::homogenised::*;
use asperity::friction::{Dissipation, FrictionIncrement, FrictionResponse, HomogenisedSample};
use std::ffi::c_char;
use std::ptr::{null, null_mut};

/// Doubles of a homogenised law's state.
const M: usize = 9;

/// The law of the table `table` at the stick stiffness `k` (through
/// `asperity_friction_from_homogenised`), or NULL when refused.
unsafe fn law_of(table: *const AsperityHomogenisedFriction, k: f64) -> *mut AsperityFriction {
    let mut law = null_mut();
    let s = asperity_friction_from_homogenised(table, k, &mut law);
    made(s, law, true, "friction_from_homogenised").unwrap_or(null_mut())
}

/// Runs one operation of this domain; `super::call` routes each variant
/// to the module of its `src/ffi/` file.
pub(super) unsafe fn call(ctx: &mut Ctx, op: &Op) {
    match op {
        Op::HomNew { samples, nulls } => {
            let v = samples.make();
            let mut out = null_mut();
            let s = asperity_homogenised_friction_new(
                if nulls.at(0) { null() } else { v.as_ptr() },
                v.len(),
                mp(&mut out, nulls.at(1)),
            );
            if let Some(f) = made(s, out, !nulls.at(1), "homogenised_friction_new") {
                ctx.frictions.push(f);
            }
        }
        Op::HomNewRaw { samples, nulls } => {
            let v: Vec<HomogenisedSample> = samples
                .iter()
                .take(16)
                .map(|a| {
                    let a = fs(*a);
                    HomogenisedSample {
                        pressure: a[0],
                        cof: a[1],
                        adhesion_pressure: a[2],
                        contact_fraction: a[3],
                        shares: Dissipation {
                            chemical: a[4],
                            van_der_waals: a[5],
                            elastic: a[6],
                            plastic: a[7],
                        },
                    }
                })
                .collect();
            let mut out = null_mut();
            let s = asperity_homogenised_friction_new(
                if nulls.at(0) { null() } else { v.as_ptr() },
                v.len(),
                mp(&mut out, nulls.at(1)),
            );
            if let Some(f) = made(s, out, !nulls.at(1), "homogenised_friction_new") {
                ctx.frictions.push(f);
            }
        }
        Op::HomFromJson {
            friction,
            mutation,
            raw,
            nulls,
        } => {
            let f = pick(&ctx.frictions, *friction);
            let mut text = match raw {
                Some(r) => r.clone(),
                None if f.is_null() => return,
                None => {
                    match json_of(|b, l, n| asperity_homogenised_friction_to_json(f, b, l, n)) {
                        Some(j) => j,
                        None => return,
                    }
                }
            };
            mutation.apply(&mut text);
            let mut out = null_mut();
            let jp = if nulls.at(0) {
                null()
            } else {
                text.as_ptr() as *const c_char
            };
            let s =
                asperity_homogenised_friction_from_json(jp, text.len(), mp(&mut out, nulls.at(1)));
            if let Some(f) = made(s, out, !nulls.at(1), "homogenised_friction_from_json") {
                ctx.frictions.push(f);
            }
        }
        Op::HomToJson {
            friction,
            len,
            nulls,
        } => {
            let f = pick(&ctx.frictions, *friction);
            let mut buf = vec![1 as c_char; len.0];
            let mut needed = 0;
            let p = if nulls.at(0) {
                null_mut()
            } else {
                buf.as_mut_ptr()
            };
            let s =
                asperity_homogenised_friction_to_json(f, p, len.0, mp(&mut needed, nulls.at(1)));
            if ok(s, "homogenised_friction_to_json") && !nulls.at(0) && len.0 > 0 {
                assert_eq!(buf[needed.min(len.0 - 1)], 0);
            }
        }
        Op::HomStep {
            friction,
            inc,
            old,
            nulls,
            alias,
        } => {
            let f = pick(&ctx.frictions, *friction);
            let v = fs(*inc);
            // The stick stiffness is the law's (v[5]).
            let law = law_of(f, v[5]);
            let i = FrictionIncrement {
                normal_force: v[0],
                area: v[1],
                slip: [v[2], v[3]],
                dt: v[4],
                ..Default::default()
            };
            let (mut s0, old_null) = old_point(ctx, *old);
            let mut new = vec![0.0; M];
            let mut out: FrictionResponse = zeroed();
            let sp = s0.as_mut_ptr();
            let new_p = if nulls.at(2) {
                null_mut()
            } else if *alias {
                sp
            } else {
                new.as_mut_ptr()
            };
            let s = asperity_friction_step(
                law,
                cp(&i, nulls.at(0)),
                if old_null { null() } else { sp },
                new_p,
                null_mut(),
                mp(&mut out, nulls.at(1)),
            );
            if ok(s, "friction_step (homogenised)") && !nulls.at(2) {
                ctx.point = if *alias { s0 } else { new };
            }
            asperity_friction_free(law);
        }
        Op::HomBlock {
            friction,
            n,
            inc,
            dt,
            k,
            old,
            nulls,
            alias,
        } => {
            let f = pick(&ctx.frictions, *friction);
            let law = law_of(f, k.0);
            let form = *n / 9 % 2;
            let with_responses = *n / 18 % 2 == 1;
            let tangents = (*n / 36 % 5) as i32;
            let n = *n as usize % 9;
            let val = |i: usize, d: f64| inc.get(i).map_or(d, |f| f.0);
            let normal: Vec<f64> = (0..n).map(|i| val(4 * i, 1.0)).collect();
            let area: Vec<f64> = (0..n).map(|i| val(4 * i + 1, 1e-4)).collect();
            let slip: Vec<f64> = (0..2 * n)
                .map(|i| val(4 * (i / 2) + 2 + i % 2, 1e-6))
                .collect();
            let (s0, old_null) = old_point(ctx, *old);
            let mut states: Vec<f64> = (0..n).flat_map(|_| s0.iter().copied()).collect();
            let mut new_states = vec![0.0; n * M];
            let mut force = vec![0.0; 2 * n];
            let mut diss = vec![0.0; n];
            let sp = states.as_mut_ptr();
            let s = if *alias && form == 1 {
                asperity_friction_step_block_in_place(
                    law,
                    n,
                    bufp(&normal, nulls.at(0)),
                    bufp(&area, nulls.at(1)),
                    bufp(&slip, nulls.at(2)),
                    dt.0,
                    if old_null { null_mut() } else { sp },
                    bufm(&mut force, nulls.at(3)),
                    bufm(&mut diss, nulls.at(5)),
                    null_mut(),
                )
            } else {
                let new_p = if nulls.at(4) {
                    null_mut()
                } else if *alias {
                    sp
                } else {
                    new_states.as_mut_ptr()
                };
                asperity_friction_step_block(
                    law,
                    n,
                    bufp(&normal, nulls.at(0)),
                    bufp(&area, nulls.at(1)),
                    bufp(&slip, nulls.at(2)),
                    dt.0,
                    if old_null { null() } else { sp },
                    new_p,
                    bufm(&mut force, nulls.at(3)),
                    bufm(&mut diss, nulls.at(5)),
                    null_mut(),
                )
            };
            ok(s, "friction_step_block (homogenised)");
            // Every other input also steps the block with full responses,
            // tangent bits 0..=4 (4 unknown), old == new when aliased.
            if with_responses {
                let mut responses: Vec<FrictionResponse> = (0..n).map(|_| zeroed()).collect();
                let mut next = vec![0.0; n * M];
                let sp = states.as_mut_ptr();
                let new_p = if nulls.at(4) {
                    null_mut()
                } else if *alias {
                    sp
                } else {
                    next.as_mut_ptr()
                };
                let s = asperity_friction_step_block_responses(
                    law,
                    n,
                    bufp(&normal, nulls.at(0)),
                    bufp(&area, nulls.at(1)),
                    bufp(&slip, nulls.at(2)),
                    dt.0,
                    tangents,
                    if old_null { null() } else { sp },
                    new_p,
                    if nulls.at(3) {
                        null_mut()
                    } else {
                        responses.as_mut_ptr()
                    },
                    null_mut(),
                );
                ok(s, "friction_step_block_responses (homogenised)");
            }
            asperity_friction_free(law);
        }
        Op::HomStateSize => {
            let law = law_of(pick(&ctx.frictions, 0), 0.0);
            let mut n = 0usize;
            if ok(
                asperity_friction_state_size(law, &mut n),
                "friction_state_size (homogenised)",
            ) {
                assert_eq!(n, M);
            }
            asperity_friction_free(law);
        }
        Op::HomFree { friction } => {
            if let Some(f) = take(&mut ctx.frictions, *friction) {
                asperity_homogenised_friction_free(f);
            } else {
                asperity_homogenised_friction_free(null_mut());
            }
        }
        _ => unreachable!("not a homogenised operation: {op:?}"),
    }
}

#[derive(Debug, Clone, Copy, Arbitrary)]
pub struct PointState {
    force: [F; 2],
    slip_path: F,
    dissipation: [F; 4],
    steps: u64,
}

impl PointState {
    /// The state `[D, S, F_x, F_y, plastic slip path, dissipation by
    /// mechanism]`: D the sum of the mechanisms, S and the plastic path the
    /// given slip path, F the force. (`steps`, a field of the former state
    /// struct, keeps the input encoding: with an odd count the total
    /// dissipation is set to the path instead, an inconsistent state.)
    fn get(&self) -> Vec<f64> {
        let d = fs(self.dissipation);
        let f = fs(self.force);
        let path = self.slip_path.0;
        let total = if self.steps % 2 == 1 {
            path
        } else {
            d.iter().sum()
        };
        vec![total, path, f[0], f[1], path, d[0], d[1], d[2], d[3]]
    }
}

#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum OldPoint {
    Null,
    Fresh,
    Carried,
    Given(PointState),
}

/// Hand-written homogenised samples that pass validation unless a value is
/// replaced.
#[derive(Debug, Clone, Arbitrary)]
pub struct SampleSpec {
    n: u8,
    first_pressure: F,
    cof: F,
    adhesion: F,
    fraction: F,
    replace: Option<(u8, F)>,
}

impl SampleSpec {
    fn make(&self) -> Vec<HomogenisedSample> {
        let n = self.n as usize % 8 + 1;
        let p0 = self.first_pressure.0.abs();
        let mut v: Vec<HomogenisedSample> = (0..n)
            .map(|i| HomogenisedSample {
                pressure: p0 * (1.0 + i as f64),
                cof: self.cof.0.abs().min(1e3),
                adhesion_pressure: self.adhesion.0.abs(),
                contact_fraction: self.fraction.0.abs().min(1.0),
                shares: Dissipation {
                    chemical: 0.25,
                    van_der_waals: 0.25,
                    elastic: 0.25,
                    plastic: 0.25,
                },
            })
            .collect();
        if let Some((k, f)) = self.replace {
            let s = &mut v[k as usize % n];
            match k / 16 % 6 {
                0 => s.pressure = f.0,
                1 => s.cof = f.0,
                2 => s.adhesion_pressure = f.0,
                3 => s.contact_fraction = f.0,
                4 => s.shares.elastic = f.0,
                _ => s.shares.chemical = f.0,
            }
        }
        v
    }
}

/// An old state of a homogenised law (NULL when the flag is set).
pub(super) fn old_point(ctx: &Ctx, old: OldPoint) -> (Vec<f64>, bool) {
    match old {
        OldPoint::Null => (vec![0.0; M], true),
        OldPoint::Fresh => (vec![0.0; M], false),
        OldPoint::Carried if ctx.point.len() == M => (ctx.point.clone(), false),
        OldPoint::Carried => (vec![0.0; M], false),
        OldPoint::Given(s) => (s.get(), false),
    }
}
