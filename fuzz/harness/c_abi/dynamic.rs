//! Dynamic friction (`src/ffi/dynamic.rs`, stepped through the one friction
//! handle of `src/ffi/friction_law.rs`): LuGre, Maxwell-slip, bristles,
//! Prandtl–Tomlinson (one and two springs), Burridge–Knopoff; state sizes,
//! steps (separate, old == new, in place, with and without a work; with the
//! untouched-on-failure checks), blocks (separate and in place), freeing;
//! and the cost bound on Prandtl–Tomlinson integrations.

use super::common::*;
use super::{Ctx, Op};
use arbitrary::Arbitrary;
use asperity::ffi::dynamic::*;
use asperity::ffi::friction_law::*;
use asperity::ffi::ASPERITY_OK;
use asperity::friction::{FrictionIncrement, FrictionResponse};
use std::ptr::{null, null_mut};

/// Runs one operation of this domain; `super::call` routes each variant
/// to the module of its `src/ffi/` file.
pub(super) unsafe fn call(ctx: &mut Ctx, op: &Op) {
    match op {
        Op::LugreNew { params, nulls } => {
            let p = params.get();
            let mut out = null_mut();
            let s = asperity_friction_lugre_new(cp(&p, nulls.at(0)), mp(&mut out, nulls.at(1)));
            if let Some(d) = made(s, out, !nulls.at(1), "friction_lugre_new") {
                ctx.dynamics.push(Dynamic {
                    model: d,
                    pt: None,
                    heavy: false,
                });
            }
        }
        Op::GmsNew {
            elements,
            params,
            nulls,
        } => {
            let (k, a) = elements.make();
            let [mc, ms, vs, de, c, s2] = fs(*params);
            let p = AsperityGeneralizedMaxwellSlipParams {
                mu_coulomb: mc,
                mu_static: ms,
                stribeck_velocity: vs,
                stribeck_exponent: de,
                attraction: c,
                sigma2: s2,
            };
            let mut out = null_mut();
            let s = asperity_friction_generalized_maxwell_slip_new(
                bufp(&k, nulls.at(0)),
                bufp(&a, nulls.at(1)),
                k.len(),
                cp(&p, nulls.at(2)),
                mp(&mut out, nulls.at(3)),
            );
            if let Some(d) = made(
                s,
                out,
                !nulls.at(3),
                "friction_generalized_maxwell_slip_new",
            ) {
                ctx.dynamics.push(Dynamic {
                    model: d,
                    pt: None,
                    heavy: false,
                });
            }
        }
        Op::MaxwellNew {
            elements,
            sigma2,
            nulls,
            bristles,
        } => {
            let (k, m) = elements.make();
            let mut out = null_mut();
            let (k, m, n) = (bufp(&k, nulls.at(0)), bufp(&m, nulls.at(1)), k.len());
            let s = if *bristles {
                asperity_friction_bristles_new(k, m, n, sigma2.0, mp(&mut out, nulls.at(2)))
            } else {
                asperity_friction_maxwell_slip_new(k, m, n, sigma2.0, mp(&mut out, nulls.at(2)))
            };
            let what = if *bristles {
                "friction_bristles_new"
            } else {
                "friction_maxwell_slip_new"
            };
            if let Some(d) = made(s, out, !nulls.at(2), what) {
                ctx.dynamics.push(Dynamic {
                    model: d,
                    pt: None,
                    heavy: false,
                });
            }
        }
        Op::PtNew {
            variant: Integrated::TwoSpring { params, null: np },
            null,
            ..
        } => {
            let v = params.get([2e-21, 3e-10, 2.0, 1e-12, 1e-6, 2.0, 1e-12, 1e-6, 1e-9]);
            let p = AsperityPrandtlTomlinsonTwoSpringParams {
                amplitude: v[0],
                period: v[1],
                tip_stiffness: v[2],
                tip_mass: v[3],
                tip_damping: v[4],
                cantilever_stiffness: v[5],
                cantilever_mass: v[6],
                cantilever_damping: v[7],
                tolerance: v[8],
            };
            let mut out = null_mut();
            let s = asperity_friction_prandtl_tomlinson_two_spring_new(
                cp(&p, *np),
                mp(&mut out, *null),
            );
            if let Some(d) = made(s, out, !*null, "friction_prandtl_tomlinson_two_spring_new") {
                ctx.dynamics.push(Dynamic {
                    model: d,
                    pt: None,
                    heavy: true,
                });
            }
        }
        Op::PtNew {
            variant: Integrated::Chain { params, null: np },
            null,
            ..
        } => {
            let v = params.get([4.0, 1e-5, 1e4, 1e3, 0.5, 0.3, 0.05, 0.01, 1e-9]);
            // A raw block count: the saturating cast keeps huge and
            // non-finite values huge or 0 (refused by the library).
            let p = AsperityBurridgeKnopoffParams {
                blocks: v[0] as usize,
                mass: v[1],
                coupling_stiffness: v[2],
                pulling_stiffness: v[3],
                mu_static: v[4],
                mu_kinetic: v[5],
                weakening_velocity: v[6],
                damping: v[7],
                tolerance: v[8],
            };
            let mut out = null_mut();
            let s = asperity_friction_burridge_knopoff_new(cp(&p, *np), mp(&mut out, *null));
            if let Some(d) = made(s, out, !*null, "friction_burridge_knopoff_new") {
                ctx.dynamics.push(Dynamic {
                    model: d,
                    pt: None,
                    heavy: true,
                });
            }
        }
        Op::PtNew { params, null, .. } => {
            let p = params.get();
            let mut out = null_mut();
            let s = asperity_friction_prandtl_tomlinson_new(
                p[0],
                p[1],
                p[2],
                p[3],
                p[4],
                p[5],
                mp(&mut out, *null),
            );
            if let Some(d) = made(s, out, !*null, "friction_prandtl_tomlinson_new") {
                ctx.dynamics.push(Dynamic {
                    model: d,
                    pt: Some(p),
                    heavy: false,
                });
            }
        }
        Op::DynStateSize { model, null } => {
            let (d, _, _) = pick_dynamic(ctx, *model);
            let mut n = 0usize;
            if ok(
                asperity_friction_state_size(d, mp(&mut n, *null)),
                "friction_state_size",
            ) && !*null
            {
                assert!(n >= 2, "dynamic_friction_state_size: {n} < 2");
            }
        }
        Op::DynStep {
            model,
            inc,
            tangents,
            reserved,
            state,
            placement,
            nulls,
        } => {
            let (d, pt, heavy) = pick_dynamic(ctx, *model);
            if heavy && !ctx.affordable(f64::INFINITY) {
                return;
            }
            let v = inc.get();
            let i = FrictionIncrement {
                normal_force: v[0],
                area: 0.0,
                slip: [v[1], v[2]],
                dt: v[3],
                tangents: tangents.0,
                reserved: reserved.0,
            };
            let m = dynamic_state_len(d);
            let old = make_state(&ctx.dynamic_state, state, m);
            if let Some(p) = pt {
                let integrations = if i.tangents & ASPERITY_FRICTION_TANGENT_SLIP != 0 {
                    3.0
                } else {
                    1.0
                };
                let cost = integrations * pt_substeps(&p, &old, i.dt, &[i.slip[0]]);
                if !ctx.affordable(cost) {
                    return;
                }
            }
            // One buffer: the old state at 0, the new one at `shift` (m:
            // apart, 0: in place, in between: partially overlapping).
            let shift = match placement {
                Placement::InPlace => 0,
                Placement::Overlap(k) if m > 1 => 1 + *k as usize % (m - 1),
                _ => m,
            };
            let mut buf = old.clone();
            buf.resize(shift + m, f64::from_bits(SENTINEL));
            let before = buf.clone();
            let mut out: FrictionResponse = zeroed();
            std::ptr::write_bytes(&mut out as *mut FrictionResponse as *mut u8, 0xa5, 1);
            let out_before = bytes_of(&out).to_vec();
            let base = buf.as_mut_ptr();
            // A work of the model's own (made and freed here) for odd
            // `reserved`, none (NULL) otherwise.
            let mut work = null_mut();
            if reserved.0 & 1 == 1 {
                assert!(ok(asperity_friction_work_new(d, &mut work), "work_new") || d.is_null());
            }
            // In place: old == new, or `asperity_friction_step_in_place`.
            let s = if shift == 0 && reserved.0 & 2 == 2 && !nulls.at(1) {
                asperity_friction_step_in_place(
                    d,
                    cp(&i, nulls.at(0)),
                    if nulls.at(2) { null_mut() } else { base },
                    work,
                    mp(&mut out, nulls.at(3)),
                )
            } else {
                asperity_friction_step(
                    d,
                    cp(&i, nulls.at(0)),
                    if nulls.at(1) { null() } else { base },
                    if nulls.at(2) {
                        null_mut()
                    } else {
                        base.add(shift)
                    },
                    work,
                    mp(&mut out, nulls.at(3)),
                )
            };
            asperity_friction_work_free(work);
            if ok(s, "friction_step (dynamic)") {
                ctx.dynamic_state = buf[shift..shift + m].to_vec();
                assert!(
                    out.dissipated.is_nan() || out.dissipated >= 0.0,
                    "friction_step: OK with dissipated = {} < 0",
                    out.dissipated
                );
            } else {
                // Documented: on failure the new state and `*out` are
                // untouched.
                assert!(
                    bits(&buf) == bits(&before),
                    "friction_step failed ({}) but wrote the state",
                    last_message()
                );
                assert!(
                    bytes_of(&out) == out_before.as_slice(),
                    "friction_step failed ({}) but wrote *out",
                    last_message()
                );
            }
        }
        Op::DynBlock {
            model,
            n,
            inc,
            dt,
            state,
            nulls,
        } => {
            let (d, pt, heavy) = pick_dynamic(ctx, *model);
            if heavy && !ctx.affordable(f64::INFINITY) {
                return;
            }
            let dt = dt.map_or(1e-3, |f| f.0);
            let separate = *n / 9 % 2 == 1;
            let n = *n as usize % 9;
            let m = dynamic_state_len(d);
            let val = |i: usize, d: f64| inc.get(i).map_or(d, |f| f.0);
            let normal: Vec<f64> = (0..n).map(|i| val(3 * i, 1.0)).collect();
            let slip: Vec<f64> = (0..2 * n)
                .map(|i| val(3 * (i / 2) + 1 + i % 2, 1e-6))
                .collect();
            let one = make_state(&ctx.dynamic_state, state, m);
            if let Some(p) = pt {
                let ds: Vec<f64> = slip.iter().step_by(2).copied().collect();
                if !ctx.affordable(pt_substeps(&p, &one, dt, &ds)) {
                    return;
                }
            }
            let mut states: Vec<f64> = (0..n).flat_map(|_| one.iter().copied()).collect();
            let mut new = vec![0.0; n * m];
            let mut force = vec![0.0; 2 * n];
            let mut diss = vec![0.0; n];
            let area = vec![0.0; n];
            let s = if separate {
                asperity_friction_step_block(
                    d,
                    n,
                    bufp(&normal, nulls.at(0)),
                    bufp(&area, nulls.at(5)),
                    bufp(&slip, nulls.at(1)),
                    dt,
                    bufp(&states, nulls.at(2)),
                    bufm(&mut new, nulls.at(6)),
                    bufm(&mut force, nulls.at(3)),
                    bufm(&mut diss, nulls.at(4)),
                    null_mut(),
                )
            } else {
                asperity_friction_step_block_in_place(
                    d,
                    n,
                    bufp(&normal, nulls.at(0)),
                    bufp(&area, nulls.at(5)),
                    bufp(&slip, nulls.at(1)),
                    dt,
                    bufm(&mut states, nulls.at(2)),
                    bufm(&mut force, nulls.at(3)),
                    bufm(&mut diss, nulls.at(4)),
                    null_mut(),
                )
            };
            if ok(s, "friction_step_block (dynamic)") && n > 0 {
                let last = if separate { &new } else { &states };
                ctx.dynamic_state = last[(n - 1) * m..].to_vec();
            }
        }
        Op::DynFree { model } => {
            if ctx.dynamics.is_empty() {
                asperity_friction_free(null_mut());
            } else {
                let i = *model as usize % ctx.dynamics.len();
                asperity_friction_free(ctx.dynamics.swap_remove(i).model);
            }
        }
        _ => unreachable!("not a dynamic operation: {op:?}"),
    }
}

/// LuGre parameters: the valid set of `tests/ffi_dynamic.rs`, that set with
/// one field replaced, or raw values.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum LugreSpec {
    Valid,
    Poked { at: u8, value: F },
    Raw([F; 8]),
}

impl LugreSpec {
    fn get(&self) -> AsperityLugreParams {
        let mut v = [0.3, 0.5, 1e-3, 2.0, 1e5, 1000.0, 1e-3, 0.4];
        match self {
            LugreSpec::Valid => {}
            LugreSpec::Poked { at, value } => v[*at as usize % 8] = value.0,
            LugreSpec::Raw(r) => v = fs(*r),
        }
        AsperityLugreParams {
            mu_coulomb: v[0],
            mu_static: v[1],
            stribeck_velocity: v[2],
            stribeck_exponent: v[3],
            sigma0: v[4],
            sigma1: v[5],
            damping_velocity: v[6],
            sigma2: v[7],
        }
    }
}

/// Maxwell-slip elements: `n` valid ones (stiffnesses 2e5/2^i, break-away
/// coefficients 0.2/(i+1)), those with one value replaced, or raw pairs.
/// The arrays are real buffers of `n` values (at most 256).
#[derive(Debug, Clone, Arbitrary)]
pub enum MaxwellSpec {
    Valid {
        n: u8,
    },
    Poked {
        n: u8,
        at: u8,
        value: F,
        capacity: bool,
    },
    Raw(Vec<(F, F)>),
}

impl MaxwellSpec {
    fn make(&self) -> (Vec<f64>, Vec<f64>) {
        let valid = |n: u8| -> (Vec<f64>, Vec<f64>) {
            let n = n as usize % 12;
            (
                (0..n).map(|i| 2e5 / (1u64 << i) as f64).collect(),
                (0..n).map(|i| 0.2 / (i + 1) as f64).collect(),
            )
        };
        match self {
            MaxwellSpec::Valid { n } => valid(*n),
            MaxwellSpec::Poked {
                n,
                at,
                value,
                capacity,
            } => {
                let (mut k, mut m) = valid(*n);
                if !k.is_empty() {
                    let i = *at as usize % k.len();
                    if *capacity {
                        m[i] = value.0;
                    } else {
                        k[i] = value.0;
                    }
                }
                (k, m)
            }
            MaxwellSpec::Raw(v) => v.iter().take(256).map(|(a, b)| (a.0, b.0)).unzip(),
        }
    }
}

/// Prandtl–Tomlinson parameters (U0, a, k, m, gamma, tolerance): the valid
/// AFM-tip set of `tests/ffi_dynamic.rs`, that set with one value replaced,
/// or raw values.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum PtSpec {
    Valid,
    Poked { at: u8, value: F },
    Raw([F; 6]),
}

impl PtSpec {
    fn get(&self) -> [f64; 6] {
        let mut v = [2e-21, 3e-10, 1.0, 1e-12, 1e-6, 1e-9];
        match self {
            PtSpec::Valid => {}
            PtSpec::Poked { at, value } => v[*at as usize % 6] = value.0,
            PtSpec::Raw(r) => v = fs(*r),
        }
        v
    }
}

/// Nine parameters of a struct-built model (two-spring Prandtl–Tomlinson,
/// Burridge–Knopoff): the valid set given, that set with one value
/// replaced, or raw values.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum NineSpec {
    Valid,
    Poked { at: u8, value: F },
    Raw([F; 9]),
}

impl NineSpec {
    fn get(&self, valid: [f64; 9]) -> [f64; 9] {
        match self {
            NineSpec::Valid => valid,
            NineSpec::Poked { at, value } => {
                let mut v = valid;
                v[*at as usize % 9] = value.0;
                v
            }
            NineSpec::Raw(r) => fs(*r),
        }
    }
}

/// Which integrated model [`Op::PtNew`] builds.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Integrated {
    OneSpring,
    TwoSpring { params: NineSpec, null: bool },
    Chain { params: NineSpec, null: bool },
}

/// A dynamic-friction increment: valid (N = 1 N, a slip of a few µm in a
/// direction set by `k`, Δt = 1 ms), that with one value replaced, or raw
/// values (N, slip x, slip y, Δt).
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum DynIncSpec {
    Valid { k: u8 },
    Poked { k: u8, at: u8, value: F },
    Raw([F; 4]),
}

impl DynIncSpec {
    fn get(&self) -> [f64; 4] {
        let valid = |k: u8| {
            let th = 0.7 * k as f64;
            [1.0, 2e-6 * th.cos(), 1e-6 * th.sin(), 1e-3]
        };
        match *self {
            DynIncSpec::Valid { k } => valid(k),
            DynIncSpec::Poked { k, at, value } => {
                let mut v = valid(k);
                v[at as usize % 4] = value.0;
                v
            }
            DynIncSpec::Raw(r) => fs(r),
        }
    }
}

/// How the new state of a dynamic step is placed against the old one.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Placement {
    Apart,
    InPlace,
    /// `new_state` = `old_state` + 1 + k % (m − 1) doubles: a partial
    /// overlap, which the library detects (an error naming `new_state`).
    Overlap(u8),
}

/// A dynamic friction model the input made, and for a Prandtl–Tomlinson tip
/// what bounds the cost of its steps.
pub(super) struct Dynamic {
    pub(super) model: *mut AsperityFriction,
    /// Prandtl–Tomlinson: its parameters (U0, a, k, m, gamma, tolerance),
    /// for [`pt_substeps`]; `None` for the other models (cheap steps).
    pub(super) pt: Option<[f64; 6]>,
    /// The two-spring Prandtl–Tomlinson model and the Burridge–Knopoff
    /// chain: integrated, without a cost estimate here, so stepped once
    /// per input (the library bounds each integration).
    pub(super) heavy: bool,
}

/// A NaN with a payload no computation produces: marks untouched doubles.
pub(super) const SENTINEL: u64 = 0x7ff8_dead_beef_0001;

pub(super) fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

pub(super) fn bytes_of<T>(x: &T) -> &[u8] {
    // SAFETY: the library's repr(C) response structs, all f64/i32 fields
    // without padding, fully initialised.
    unsafe { std::slice::from_raw_parts(x as *const T as *const u8, core::mem::size_of::<T>()) }
}

/// The dynamic model `sel` (NULL for 255 or none) and its
/// Prandtl–Tomlinson parameters.
pub(super) fn pick_dynamic(ctx: &Ctx, sel: u8) -> (*mut AsperityFriction, Option<[f64; 6]>, bool) {
    if sel == 255 || ctx.dynamics.is_empty() {
        (null_mut(), None, false)
    } else {
        let d = &ctx.dynamics[sel as usize % ctx.dynamics.len()];
        (d.model, d.pt, d.heavy)
    }
}

/// The state size of `model`, or 4 for NULL (the call then fails).
pub(super) unsafe fn dynamic_state_len(model: *const AsperityFriction) -> usize {
    let mut m = 0usize;
    if model.is_null() || asperity_friction_state_size(model, &mut m) != ASPERITY_OK {
        4
    } else {
        m
    }
}

/// Sub-steps the Prandtl–Tomlinson integrations of the increments `dt`,
/// `ds[i]` from `state` are expected to take: about 20 per time scale of
/// the tip (its spring, lattice and damping rates, and the time to cross a
/// lattice period at the speeds the state, the lattice and the support
/// give it), more for tight tolerances. 0 when the library rejects the
/// arguments before integrating; +inf when they overflow.
pub(super) fn pt_substeps(p: &[f64; 6], state: &[f64], dt: f64, ds: &[f64]) -> f64 {
    let [u0, a, k, m, g, tol] = *p;
    let finite = dt.is_finite()
        && dt >= 0.0
        && ds.iter().all(|x| x.is_finite())
        && state.iter().all(|x| x.is_finite());
    if !finite || dt == 0.0 {
        return 0.0;
    }
    let tau = std::f64::consts::TAU;
    let w = (k / m).sqrt();
    let wl = tau * (u0 / m).sqrt() / a;
    let (rel, v) = (
        state
            .get(ASPERITY_FRICTION_STATE_MODEL)
            .map_or(0.0, |x| x.abs()),
        state
            .get(ASPERITY_FRICTION_STATE_MODEL + 1)
            .map_or(0.0, |x| x.abs()),
    );
    let tol_factor = (1e-9 / tol).powf(0.2).max(1.0);
    ds.iter()
        .map(|s| {
            let speed = v + w * rel + 2.0 * (u0 / m).sqrt() + s.abs() / dt;
            let rate = w.max(wl).max(g / m) + tau * speed / a;
            let n = 20.0 * dt * rate * tol_factor;
            if n.is_nan() {
                f64::INFINITY
            } else {
                n
            }
        })
        .sum()
}
