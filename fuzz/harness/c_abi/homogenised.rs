//! Homogenised friction (`src/ffi/homogenised.rs`): construction from
//! samples and JSON, steps, blocks, freeing.

use super::common::*;
use super::{pick, take, Ctx, Op};
use arbitrary::Arbitrary;
use asperity::ffi::homogenised::*;
use asperity::friction::{
    Dissipation, FrictionIncrement, FrictionPointState, FrictionResponse, HomogenisedSample,
};
use std::ffi::c_char;
use std::ptr::{null, null_mut};

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
            let i = FrictionIncrement {
                normal_force: v[0],
                area: v[1],
                slip: [v[2], v[3]],
                dt: v[4],
                stick_stiffness: v[5],
            };
            let (mut s0, old_null) = old_point(ctx, *old);
            let mut new = FrictionPointState::default();
            let mut out: FrictionResponse = zeroed();
            let sp: *mut FrictionPointState = &mut s0;
            let new_p = if nulls.at(2) {
                null_mut()
            } else if *alias {
                sp
            } else {
                &mut new
            };
            let s = asperity_homogenised_friction_step(
                f,
                cp(&i, nulls.at(0)),
                if old_null { null() } else { sp },
                new_p,
                mp(&mut out, nulls.at(1)),
            );
            if ok(s, "homogenised_friction_step") && !nulls.at(2) {
                ctx.point = if *alias { s0 } else { new };
            }
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
            let n = *n as usize % 9;
            let val = |i: usize, d: f64| inc.get(i).map_or(d, |f| f.0);
            let normal: Vec<f64> = (0..n).map(|i| val(4 * i, 1.0)).collect();
            let area: Vec<f64> = (0..n).map(|i| val(4 * i + 1, 1e-4)).collect();
            let slip: Vec<f64> = (0..2 * n)
                .map(|i| val(4 * (i / 2) + 2 + i % 2, 1e-6))
                .collect();
            let (s0, old_null) = old_point(ctx, *old);
            let mut states = vec![s0; n];
            let mut new_states = vec![FrictionPointState::default(); n];
            let mut force = vec![0.0; 2 * n];
            let mut diss = vec![0.0; n];
            let sp = states.as_mut_ptr();
            let new_p = if nulls.at(4) {
                null_mut()
            } else if *alias {
                sp
            } else {
                new_states.as_mut_ptr()
            };
            let s = asperity_homogenised_friction_step_block(
                f,
                n,
                bufp(&normal, nulls.at(0)),
                bufp(&area, nulls.at(1)),
                bufp(&slip, nulls.at(2)),
                dt.0,
                k.0,
                if old_null { null() } else { sp },
                new_p,
                bufm(&mut force, nulls.at(3)),
                bufm(&mut diss, nulls.at(5)),
            );
            ok(s, "homogenised_friction_step_block");
        }
        Op::HomStateSize => {
            assert_eq!(
                asperity_homogenised_friction_state_size(),
                core::mem::size_of::<FrictionPointState>()
            );
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
    fn get(&self) -> FrictionPointState {
        let d = fs(self.dissipation);
        FrictionPointState {
            force: fs(self.force),
            slip_path: self.slip_path.0,
            dissipation: Dissipation {
                chemical: d[0],
                van_der_waals: d[1],
                elastic: d[2],
                plastic: d[3],
            },
            steps: self.steps,
        }
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

pub(super) fn old_point(ctx: &Ctx, old: OldPoint) -> (FrictionPointState, bool) {
    match old {
        OldPoint::Null => (FrictionPointState::default(), true),
        OldPoint::Fresh => (FrictionPointState::default(), false),
        OldPoint::Carried => (ctx.point, false),
        OldPoint::Given(s) => (s.get(), false),
    }
}
