//! `asperity_slider_record`, called from Rust: the full record of a slider
//! patch's last step (positions, counts of contacts, whether the step seated
//! a fresh state) equals the Rust API's `SliderWork::record()` after the
//! same steps of the chapter-6 scene, in place and old/new apart, with
//! tangents and in a block; all zero for a slider law's work that has not
//! stepped; errors naming `work` for a work of another law (a LuGre law's)
//! and for NULL; NULL `out`.

mod common;
#[path = "common/laws.rs"]
mod laws;
use common::c_errors::{expect_error, last_message};
use laws::{c_scene_slider, scene_slider, slider_record as expected};

use asperity::ffi::dynamic::*;
use asperity::ffi::friction_law::*;
use asperity::ffi::slider::*;
use asperity::ffi::*;
use asperity::friction::{FrictionIncrement, FrictionLaw, FrictionResponse, Slider};
use std::ptr::{null, null_mut};

/// The record of `work` through C.
fn c_record(work: *const AsperityFrictionWork) -> AsperitySliderRecord {
    // Poisoned, so a field left unwritten shows.
    let mut out = AsperitySliderRecord {
        position: f64::NAN,
        rod_position: f64::NAN,
        adhesion_area_share: f64::NAN,
        nano_contacts: u64::MAX,
        adhesive_contacts: u64::MAX,
        rods_in_contact: u64::MAX,
        yielded_rods: u64::MAX,
        seated: -1,
        reserved: -1,
    };
    let st = unsafe { asperity_slider_record(work, &mut out) };
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    out
}

/// Field by field, the doubles bit for bit.
#[track_caller]
fn assert_same(c: &AsperitySliderRecord, rust: &AsperitySliderRecord, what: &str) {
    let bits = |r: &AsperitySliderRecord| {
        [
            r.position.to_bits(),
            r.rod_position.to_bits(),
            r.adhesion_area_share.to_bits(),
        ]
    };
    assert_eq!(bits(c), bits(rust), "{what}: C {c:?}, Rust {rust:?}");
    assert_eq!(c, rust, "{what}");
}

/// The counts hang together and the slider is in contact.
#[track_caller]
fn assert_consistent(r: &AsperitySliderRecord, rods: u64, what: &str) {
    assert!(r.nano_contacts > 0, "{what}: no contact {r:?}");
    assert!(r.adhesive_contacts <= r.nano_contacts, "{what}: {r:?}");
    assert!(
        r.rods_in_contact > 0 && r.rods_in_contact <= rods,
        "{what}: {r:?}"
    );
    assert!(r.yielded_rods <= r.rods_in_contact, "{what}: {r:?}");
    assert!(
        (0.0..=1.0).contains(&r.adhesion_area_share),
        "{what}: {r:?}"
    );
    assert!(r.rod_position.is_finite(), "{what}: {r:?}");
    assert_eq!(r.reserved, 0, "{what}");
}

#[test]
fn the_record_equals_the_rust_record_step_by_step() {
    let h = c_scene_slider();
    let rs = scene_slider();
    let mut rw = rs.work();
    let m = rs.state_len();
    let rods = rs.rods() as u64;
    let load = 0.10 * rs.capacity();
    let step = 1.5e-6;
    let start = 45e-6;
    let mut c_state = vec![0.0; m];
    c_state[Slider::STATE_POSITION] = start;
    let mut r_state = c_state.clone();
    let inc = FrictionIncrement {
        normal_force: load,
        // 30 degrees: the track advances by |slip|.
        slip: [3f64.sqrt() / 2.0 * step, 0.5 * step],
        dt: 1e-5,
        ..FrictionIncrement::default()
    };
    let s = inc.slip[0].hypot(inc.slip[1]);
    let mut resp = FrictionResponse::default();
    for n in 0..8 {
        let before = c_state[Slider::STATE_POSITION];
        let st = unsafe {
            asperity_friction_step_in_place(h.law, &inc, c_state.as_mut_ptr(), h.work, &mut resp)
        };
        assert_eq!(st, ASPERITY_OK, "{}", last_message());
        rs.step_in_place(&mut r_state, &inc, &mut rw).unwrap();
        let c = c_record(h.work);
        let what = format!("step {n}");
        assert_same(&c, &expected(&rw), &what);
        assert_consistent(&c, rods, &what);
        // Seated on the first step of the fresh state only; the position
        // advances by |slip| along the track, as the state says.
        assert_eq!(c.seated, (n == 0) as i32, "{what}");
        assert_eq!(c.position, before + s, "{what}");
        assert_eq!(c.position, c_state[Slider::STATE_POSITION], "{what}");
        assert_eq!(
            c.rod_position.to_bits(),
            c_state[Slider::STATE_ROD_POSITION].to_bits(),
            "{what}"
        );
        // The response's true contact area is N_c w_vdW^2.
        let w = rs.geometry().nano().w_vdw;
        let area = c.nano_contacts as f64 * w * w;
        assert!(
            (resp.true_contact_area - area).abs() <= 1e-12 * area,
            "{what}: true contact area {} for {} contacts",
            resp.true_contact_area,
            c.nano_contacts
        );
    }

    // Old and new states apart, with both tangents: the record is the
    // step's own, not a tangent evaluation's, and the same as in Rust.
    let mut t = inc;
    t.tangents = TANGENT_BOTH;
    let mut c_new = vec![0.0; m];
    let st = unsafe {
        asperity_friction_step(
            h.law,
            &t,
            c_state.as_ptr(),
            c_new.as_mut_ptr(),
            h.work,
            &mut resp,
        )
    };
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    let mut r_new = vec![0.0; m];
    rs.step(&r_state, &mut r_new, &t, &mut rw).unwrap();
    let c = c_record(h.work);
    assert_same(&c, &expected(&rw), "tangent step");
    assert_eq!(c.seated, 0);
    assert_eq!(c.position, c_state[Slider::STATE_POSITION] + s);
    assert_eq!(c.position, c_new[Slider::STATE_POSITION]);

    // A zero slip increment: the rods re-seated where they are, no advance.
    let z = FrictionIncrement {
        slip: [0.0, 0.0],
        ..inc
    };
    let st = unsafe {
        asperity_friction_step(
            h.law,
            &z,
            c_state.as_ptr(),
            c_new.as_mut_ptr(),
            h.work,
            &mut resp,
        )
    };
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    rs.step(&r_state, &mut r_new, &z, &mut rw).unwrap();
    let c = c_record(h.work);
    assert_same(&c, &expected(&rw), "zero slip");
    assert_eq!(c.position, c_state[Slider::STATE_POSITION]);
    assert_eq!(c.seated, 0);
}

const TANGENT_BOTH: i32 = ASPERITY_FRICTION_TANGENT_NORMAL | ASPERITY_FRICTION_TANGENT_SLIP;

#[test]
fn a_slider_work_that_has_not_stepped_gives_zeros() {
    let h = c_scene_slider();
    let c = c_record(h.work);
    assert_eq!(c, AsperitySliderRecord::default());
    assert_eq!(c.position.to_bits(), 0, "+0, not -0");
    // As the Rust work of the same law says.
    assert_same(&c, &expected(&scene_slider().work()), "fresh work");
}

#[test]
fn a_block_leaves_the_last_points_record() {
    let h = c_scene_slider();
    let rs = scene_slider();
    let m = rs.state_len();
    let loads = [0.05 * rs.capacity(), 0.35 * rs.capacity()];
    let step = 1.5e-6;
    let mut states = vec![0.0; 2 * m];
    let slips = [step, 0.0, -step, 0.0];
    let mut forces = [0.0; 4];
    let mut rw = rs.work();
    let mut last = vec![0.0; m];
    for n in 0..3 {
        let st = unsafe {
            asperity_friction_step_block_in_place(
                h.law,
                2,
                loads.as_ptr(),
                null(),
                slips.as_ptr(),
                1e-5,
                states.as_mut_ptr(),
                forces.as_mut_ptr(),
                null_mut(),
                h.work,
            )
        };
        assert_eq!(st, ASPERITY_OK, "{}", last_message());
        // Point 1 alone through Rust: its record is the block's last.
        let inc = FrictionIncrement {
            normal_force: loads[1],
            slip: [-step, 0.0],
            dt: 1e-5,
            ..FrictionIncrement::default()
        };
        rs.step_in_place(&mut last, &inc, &mut rw).unwrap();
        let c = c_record(h.work);
        assert_same(&c, &expected(&rw), &format!("block {n}"));
        assert_consistent(&c, rs.rods() as u64, &format!("block {n}"));
        assert_eq!(c.seated, (n == 0) as i32);
        assert_eq!(c.position, states[m + Slider::STATE_POSITION]);
        assert_eq!(c.position, (n + 1) as f64 * step);
    }
}

#[test]
fn errors_name_work() {
    // A fresh work of a non-slider law (LuGre): no slider record.
    let p = laws::lugre_params();
    let mut lugre = null_mut();
    assert_eq!(
        unsafe { asperity_friction_lugre_new(&p, &mut lugre) },
        ASPERITY_OK
    );
    let mut work = null_mut();
    assert_eq!(
        unsafe { asperity_friction_work_new(lugre, &mut work) },
        ASPERITY_OK
    );
    let mut out = AsperitySliderRecord {
        position: 7.0,
        nano_contacts: 7,
        seated: 7,
        ..AsperitySliderRecord::default()
    };
    let before = out;
    let st = unsafe { asperity_slider_record(work, &mut out) };
    expect_error(st, ASPERITY_ERR_INVALID_ARGUMENT, "`work`");
    assert_eq!(out, before, "out untouched on failure");

    // Stepped by the LuGre law: still no slider record.
    let inc = FrictionIncrement {
        normal_force: 3.0,
        slip: [1e-6, 0.0],
        dt: 1e-3,
        ..FrictionIncrement::default()
    };
    let mut state = [0.0; 4];
    let mut resp = FrictionResponse::default();
    let st = unsafe {
        asperity_friction_step_in_place(lugre, &inc, state.as_mut_ptr(), work, &mut resp)
    };
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    let st = unsafe { asperity_slider_record(work, &mut out) };
    expect_error(st, ASPERITY_ERR_INVALID_ARGUMENT, "`work`");
    assert_eq!(out, before, "out untouched on failure");

    // A NULL work.
    let st = unsafe { asperity_slider_record(null(), &mut out) };
    expect_error(st, ASPERITY_ERR_NULL_POINTER, "`work`");
    assert_eq!(out, before, "out untouched on failure");

    // A NULL out, with a work that has a record.
    let h = c_scene_slider();
    let rs = scene_slider();
    let mut s = vec![0.0; rs.state_len()];
    let inc = FrictionIncrement {
        normal_force: 0.1 * rs.capacity(),
        slip: [1.5e-6, 0.0],
        dt: 1e-5,
        ..FrictionIncrement::default()
    };
    let st =
        unsafe { asperity_friction_step_in_place(h.law, &inc, s.as_mut_ptr(), h.work, &mut resp) };
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    let st = unsafe { asperity_slider_record(h.work, null_mut()) };
    expect_error(st, ASPERITY_ERR_NULL_POINTER, "`out`");

    // The LuGre work, once used by the slider law, holds its record.
    let st =
        unsafe { asperity_friction_step_in_place(h.law, &inc, s.as_mut_ptr(), work, &mut resp) };
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    let r = c_record(work);
    assert_eq!(r.position, 2.0 * 1.5e-6);
    assert_eq!(r.seated, 0);

    unsafe {
        asperity_friction_work_free(work);
        asperity_friction_free(lugre);
    }
}
