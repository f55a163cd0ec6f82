//! Per-call evaluations allocate nothing: every closed-form law through the
//! C ABI (scalar, batch, load-controlled, pull-off) and tabulated-law lookups
//! (scalar and batch), counted by a global allocator that tallies the
//! current thread's allocations. Building a law or a table may allocate;
//! evaluating one may not (host codes call these millions of times per
//! increment, often from many threads). The friction steps through the one
//! C handle (`AsperityFriction`: the dynamic models, the homogenised law,
//! the slider) are counted here too, once their work exists; the Rust
//! homogenised and slider steps have their own counting tests
//! (tests/friction_homogenised.rs, tests/slider_alloc.rs).

use asperity::contact::ContactState;
use asperity::ffi::contact::*;
use asperity::ffi::tabulated::*;
use asperity::ffi::ASPERITY_OK;

mod common;
#[path = "common/laws.rs"]
mod laws;

use common::counting::allocations as count;

#[global_allocator]
static GLOBAL: common::counting::Counting = common::counting::Counting;

type Law = AsperityNormalLaw;

fn laws() -> Vec<(&'static str, Law)> {
    let mut v = Vec::new();
    let mut law = core::mem::MaybeUninit::<Law>::zeroed();
    let (r, e, w) = (1e-6, 1e9, 0.05);
    macro_rules! add {
        ($name:literal, $call:expr) => {
            // SAFETY: `law` is a valid out-pointer.
            let s = unsafe { $call(law.as_mut_ptr()) };
            assert_eq!(s, ASPERITY_OK, "{}", $name);
            // SAFETY: written by the successful call.
            v.push(($name, unsafe { law.assume_init() }));
        };
    }
    add!("hertz", |o| asperity_law_hertz(r, e, o));
    add!("power_punch", |o| asperity_law_power_punch(2e5, 2.5, e, o));
    add!("cone", |o| asperity_law_cone(1.2, e, o));
    add!("flat_punch", |o| asperity_law_flat_punch(r, e, o));
    add!("flat_punch_no_slip", |o| asperity_law_flat_punch_no_slip(
        r, e, 0.3, o
    ));
    add!("dmt", |o| asperity_law_dmt(r, e, w, o));
    add!("jkr", |o| asperity_law_jkr(r, e, w, o));
    add!("jkr_power_punch", |o| asperity_law_jkr_power_punch(
        2e5, 2.5, e, w, 0.3, 0, o
    ));
    add!("kendall", |o| asperity_law_kendall(r, e, w, 0.3, 1, o));
    add!("maugis_dugdale", |o| asperity_law_maugis_dugdale(
        r, e, w, 3.27e7, o
    ));
    add!("derjaguin", |o| asperity_law_derjaguin(r, w, 1, 3e-10, o));
    v
}

#[test]
fn every_kind_of_law_is_counted() {
    let names: Vec<&str> = laws().iter().map(|(n, _)| *n).collect();
    for kind in asperity::NormalLaw::NAMES {
        assert!(
            names.contains(kind),
            "tests/no_alloc.rs: laws() has no `{kind}` (add its asperity_law_{kind})"
        );
    }
}

#[test]
fn laws_and_table_lookups_allocate_nothing() {
    let laws = laws();
    let deltas: Vec<f64> = (0..64).map(|i| -4e-9 + 0.25e-9 * i as f64).collect();
    let n = deltas.len();
    let old = vec![ContactState::default(); n];
    let mut new = vec![ContactState::default(); n];
    let (mut f, mut a, mut k) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    let mut table: *mut AsperityTable = core::ptr::null_mut();
    // SAFETY: valid out-pointer.
    let s = unsafe { asperity_table_new_maugis_dugdale(1e-6, 1e9, 0.05, 3.27e7, 1e-4, &mut table) };
    assert_eq!(s, ASPERITY_OK);
    // Warm up the thread-local error buffer and any lazy statics.
    let mut resp = core::mem::MaybeUninit::zeroed();
    for (_, law) in &laws {
        // SAFETY: valid pointers.
        unsafe { asperity_normal_eval(law, 1e-9, &old[0], &mut new[0], resp.as_mut_ptr()) };
    }
    for (name, law) in &laws {
        // The rigid Derjaguin sphere is defined out of contact only.
        let shift = if *name == "derjaguin" { -20e-9 } else { 0.0 };
        let shifted: Vec<f64> = deltas.iter().map(|d| d + shift).collect();
        let before = count();
        let mut ok = 0;
        for (i, &d) in shifted.iter().enumerate() {
            // SAFETY: valid pointers for one element.
            let s =
                unsafe { asperity_normal_eval(law, d, &old[i], &mut new[i], resp.as_mut_ptr()) };
            ok += (s == ASPERITY_OK) as usize;
        }
        // SAFETY: arrays of n elements.
        let s = unsafe {
            asperity_normal_eval_batch(
                law,
                n,
                shifted.as_ptr(),
                old.as_ptr(),
                new.as_mut_ptr(),
                f.as_mut_ptr(),
                a.as_mut_ptr(),
                k.as_mut_ptr(),
            )
        };
        let mut p = 0.0;
        // SAFETY: valid out-pointer.
        let s2 = unsafe { asperity_pull_off_force(law, ASPERITY_CONTROL_LOAD, &mut p) };
        let used = count() - before;
        assert_eq!(ok, n, "{name}: not every scalar call succeeded");
        assert_eq!(
            (s, s2),
            (ASPERITY_OK, ASPERITY_OK),
            "{name}: batch or pull-off failed"
        );
        assert_eq!(
            used, 0,
            "{name}: {used} allocations in {n} scalar calls, a batch of {n} and a pull-off"
        );
    }
    let before = count();
    for (i, &d) in deltas.iter().enumerate() {
        // SAFETY: valid pointers.
        let s = unsafe { asperity_table_eval(table, d, &old[i], &mut new[i], resp.as_mut_ptr()) };
        assert_eq!(s, ASPERITY_OK);
    }
    // SAFETY: arrays of n elements.
    let s = unsafe {
        asperity_table_eval_batch(
            table,
            n,
            deltas.as_ptr(),
            old.as_ptr(),
            new.as_mut_ptr(),
            f.as_mut_ptr(),
            a.as_mut_ptr(),
            k.as_mut_ptr(),
        )
    };
    assert_eq!(s, ASPERITY_OK);
    let used = count() - before;
    assert_eq!(
        used, 0,
        "tabulated law: {used} allocations in {n} lookups and a batch"
    );
    // The counter works: a Vec allocates.
    let before = count();
    let v: Vec<u8> = Vec::with_capacity(16);
    assert!(count() > before && v.capacity() >= 16);
    // SAFETY: from asperity_table_new_maugis_dugdale.
    unsafe { asperity_table_free(table) };
}

/// The friction steps through the C handle (LuGre, Maxwell-slip,
/// Prandtl–Tomlinson with one and two springs, Burridge–Knopoff from 1 to
/// 256 blocks, bristles, the homogenised law, the slider): scalar with
/// tangents, old and new separate and the same (in place), in place, and
/// the blocks (with the responses and tangents too), with the law's work.
#[test]
fn friction_steps_allocate_nothing() {
    use asperity::ffi::dynamic::*;
    use asperity::ffi::friction_law::*;
    use asperity::friction::{FrictionIncrement, FrictionResponse};
    // (handle, slip scale m, area m², normal force scale N)
    let mut models = vec![];
    let p = laws::lugre_params();
    let mut h = core::ptr::null_mut();
    assert_eq!(
        unsafe { asperity_friction_lugre_new(&p, &mut h) },
        ASPERITY_OK
    );
    models.push((h, 1e-6, 0.0, 1.0));
    let (k, mu) = ([2e5, 5e4, 1e4], [0.2, 0.2, 0.1]);
    let mut h = core::ptr::null_mut();
    assert_eq!(
        unsafe { asperity_friction_maxwell_slip_new(k.as_ptr(), mu.as_ptr(), 3, 0.1, &mut h) },
        ASPERITY_OK
    );
    models.push((h, 1e-6, 0.0, 1.0));
    let mut h = core::ptr::null_mut();
    assert_eq!(
        unsafe {
            asperity_friction_prandtl_tomlinson_new(2e-21, 3e-10, 1.0, 1e-12, 1e-6, 1e-9, &mut h)
        },
        ASPERITY_OK
    );
    models.push((h, 1e-11, 0.0, 1.0));
    let t = AsperityPrandtlTomlinsonTwoSpringParams {
        amplitude: 2e-21,
        period: 3e-10,
        tip_stiffness: 2.0,
        tip_mass: 1e-12,
        tip_damping: 1e-6,
        cantilever_stiffness: 2.0,
        cantilever_mass: 1e-12,
        cantilever_damping: 1e-6,
        tolerance: 1e-9,
    };
    let mut h = core::ptr::null_mut();
    assert_eq!(
        unsafe { asperity_friction_prandtl_tomlinson_two_spring_new(&t, &mut h) },
        ASPERITY_OK
    );
    models.push((h, 1e-11, 0.0, 1.0));
    // Every size class of the chain's integration arrays.
    for blocks in [1, 3, 16, 64, 256] {
        let b = laws::burridge_knopoff_params(blocks);
        let mut h = core::ptr::null_mut();
        assert_eq!(
            unsafe { asperity_friction_burridge_knopoff_new(&b, &mut h) },
            ASPERITY_OK
        );
        models.push((h, 1e-5, 0.0, 1.0));
    }
    let (kb, db) = ([1e5, 2e5, 5e4], [1e-6, 2.5e-6, 4e-6]);
    let mut h = core::ptr::null_mut();
    assert_eq!(
        unsafe { asperity_friction_bristles_new(kb.as_ptr(), db.as_ptr(), 3, 0.1, &mut h) },
        ASPERITY_OK
    );
    models.push((h, 2e-6, 0.0, 1.0));
    // The homogenised law (k = 1e8 N/m) on 1 mm² points at 10–60 MPa.
    {
        use asperity::ffi::homogenised::*;
        use asperity::friction::{Dissipation, HomogenisedSample};
        let samples: Vec<HomogenisedSample> = [(10e6, 1.1), (100e6, 0.97)]
            .iter()
            .map(|&(p, cof)| HomogenisedSample {
                pressure: p,
                cof,
                adhesion_pressure: 0.09 * p,
                contact_fraction: p / 1e9,
                shares: Dissipation {
                    chemical: 0.9,
                    van_der_waals: 0.06,
                    elastic: 0.03,
                    plastic: 0.01,
                },
            })
            .collect();
        let mut table = core::ptr::null_mut();
        assert_eq!(
            unsafe {
                asperity_homogenised_friction_new(samples.as_ptr(), samples.len(), &mut table)
            },
            ASPERITY_OK
        );
        let mut h = core::ptr::null_mut();
        assert_eq!(
            unsafe { asperity_friction_from_homogenised(table, 1e8, &mut h) },
            ASPERITY_OK
        );
        unsafe { asperity_homogenised_friction_free(table) };
        models.push((h, 1e-6, 1e-6, 15.0));
    }
    // The chapter-6 slider as a patch law at 0.02–0.1 N.
    {
        use asperity::ffi::slider::*;
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("examples/scenes/chapter6_copper.json");
        let text = std::fs::read_to_string(path).unwrap();
        let mut slider = core::ptr::null_mut();
        assert_eq!(
            unsafe {
                asperity_slider_from_scene_json(
                    text.as_ptr().cast(),
                    text.len(),
                    core::ptr::null(),
                    &mut slider,
                )
            },
            ASPERITY_OK
        );
        let mut h = core::ptr::null_mut();
        assert_eq!(
            unsafe { asperity_friction_from_slider(slider, &mut h) },
            ASPERITY_OK
        );
        unsafe { asperity_slider_free(slider) };
        models.push((h, 2e-7, 0.0, 0.02));
    }
    for (h, scale, area, load) in models {
        let mut n = 0usize;
        unsafe { asperity_friction_state_size(h, &mut n) };
        let mut work = core::ptr::null_mut();
        assert_eq!(
            unsafe { asperity_friction_work_new(h, &mut work) },
            ASPERITY_OK
        );
        let mut a = vec![0.0; n];
        let mut b = vec![0.0; n];
        let mut blocks = vec![0.0; 4 * n];
        let mut next = vec![0.0; 4 * n];
        let normal = [load, 2.0 * load, 3.0 * load, 4.0 * load];
        let areas = [area; 4];
        let slip = [scale, 0.0, -scale, 0.0, 2.0 * scale, 0.0, 0.5 * scale, 0.0];
        let (mut f, mut d) = ([0.0; 8], [0.0; 4]);
        let mut out = FrictionResponse::default();
        let mut responses = [FrictionResponse::default(); 4];
        // Once, so that the work is at capacity.
        let first = FrictionIncrement {
            normal_force: 1.5 * load,
            area,
            slip: [scale, 0.0],
            dt: 1e-6,
            ..Default::default()
        };
        assert_eq!(
            unsafe { asperity_friction_step_in_place(h, &first, a.as_mut_ptr(), work, &mut out) },
            ASPERITY_OK
        );
        let before = count();
        for k in 0..50 {
            let inc = FrictionIncrement {
                normal_force: 1.5 * load,
                area,
                slip: [scale * (0.3 * k as f64).cos(), 0.0],
                dt: 1e-6,
                tangents: k % 4,
                ..Default::default()
            };
            unsafe {
                assert_eq!(
                    asperity_friction_step(h, &inc, a.as_ptr(), b.as_mut_ptr(), work, &mut out),
                    ASPERITY_OK
                );
                assert_eq!(
                    asperity_friction_step(h, &inc, b.as_ptr(), b.as_mut_ptr(), work, &mut out),
                    ASPERITY_OK
                );
                assert_eq!(
                    asperity_friction_step_in_place(h, &inc, b.as_mut_ptr(), work, &mut out),
                    ASPERITY_OK
                );
                assert_eq!(
                    asperity_friction_step_block_in_place(
                        h,
                        4,
                        normal.as_ptr(),
                        areas.as_ptr(),
                        slip.as_ptr(),
                        1e-6,
                        blocks.as_mut_ptr(),
                        f.as_mut_ptr(),
                        d.as_mut_ptr(),
                        work,
                    ),
                    ASPERITY_OK
                );
                assert_eq!(
                    asperity_friction_step_block(
                        h,
                        4,
                        normal.as_ptr(),
                        areas.as_ptr(),
                        slip.as_ptr(),
                        1e-6,
                        blocks.as_ptr(),
                        next.as_mut_ptr(),
                        f.as_mut_ptr(),
                        core::ptr::null_mut(),
                        work,
                    ),
                    ASPERITY_OK
                );
                assert_eq!(
                    asperity_friction_step_block_responses(
                        h,
                        4,
                        normal.as_ptr(),
                        areas.as_ptr(),
                        slip.as_ptr(),
                        1e-6,
                        k % 4,
                        next.as_ptr(),
                        blocks.as_mut_ptr(),
                        responses.as_mut_ptr(),
                        work,
                    ),
                    ASPERITY_OK
                );
            }
            core::mem::swap(&mut a, &mut b);
        }
        assert_eq!(count() - before, 0, "a friction step allocated");
        unsafe {
            asperity_friction_work_free(work);
            asperity_friction_free(h);
        }
    }
}
