//! The C ABI of the slider as the friction law of a patch, called from
//! Rust: a slider built from scene JSON (with `base_dir` for the files a
//! scene names) or from structs, its friction handle
//! (`asperity_friction_from_slider`) and work, sizes, equality of the scalar
//! and block steps with the Rust API (bit for bit, in place and separate,
//! with and without a work), the handle's contract (overlapping and
//! overflowing blocks), NULL pointers, bad input (status and the message of
//! `asperity_last_error_message`), and outputs untouched on failure.

mod common;
#[path = "common/laws.rs"]
mod laws;
use common::c_errors::{expect_error, last_message};
use laws::{c_scene_slider, c_slider_law, scene_path, scene_slider};

use asperity::ffi::friction_law::*;
use asperity::ffi::slider::*;
use asperity::ffi::*;
use asperity::friction::{
    BlockStates, FrictionBlock, FrictionIncrement, FrictionLaw, FrictionResponse, Loading, Slider,
};
use asperity::scene::Scene;
use std::ffi::CString;
use std::path::Path;
use std::ptr::{null, null_mut};

fn scene_text() -> String {
    std::fs::read_to_string(scene_path()).unwrap()
}

fn from_json(text: &str, base: Option<&Path>) -> (i32, *mut AsperitySlider) {
    let base = base.map(|b| CString::new(b.to_str().unwrap()).unwrap());
    let mut h = null_mut();
    let st = unsafe {
        asperity_slider_from_scene_json(
            text.as_ptr().cast(),
            text.len(),
            base.as_ref().map_or(null(), |b| b.as_ptr()),
            &mut h,
        )
    };
    (st, h)
}

fn same(a: &FrictionResponse, b: &FrictionResponse) -> bool {
    format!("{a:?}") == format!("{b:?}")
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

#[test]
fn sizes_and_info_match_the_rust_slider() {
    let h = c_scene_slider();
    let rs = scene_slider();
    let mut n = 0usize;
    assert_eq!(
        unsafe { asperity_friction_state_size(h.law, &mut n) },
        ASPERITY_OK
    );
    assert_eq!(n, 9 + 2 * 90);
    assert_eq!(n, rs.state_len());
    let mut info = AsperitySliderInfo::default();
    assert_eq!(
        unsafe { asperity_slider_info(h.slider, &mut info) },
        ASPERITY_OK
    );
    assert_eq!(info.state_size, n);
    assert_eq!(info.rods, 90);
    assert_eq!(info.nano_per_rod, 10);
    assert_eq!(info.counter_samples, 241);
    assert_eq!(info.capacity, rs.capacity());
    assert_eq!(info.nominal_area, 90.0 * 1.5e-6 * 13.5e-6);
    assert!((info.nominal_area - rs.nominal_area()).abs() <= 1e-12 * info.nominal_area);
    assert_eq!((info.rod_width, info.depth), (1.5e-6, 1.35e-5));
    assert_eq!(info.scene_control, ASPERITY_SLIDER_CONTROL_LOAD);
    assert_eq!(info.scene_loading, 0.18);
    assert_eq!(info.periodic, 0);
    assert_eq!(info.counter_dx, 1.5e-6);
    // The layout of the state.
    assert_eq!(
        (
            ASPERITY_SLIDER_STATE_FLAG,
            ASPERITY_SLIDER_STATE_POSITION,
            ASPERITY_SLIDER_STATE_ROD_POSITION,
            ASPERITY_SLIDER_STATE_MECHANISMS,
            ASPERITY_SLIDER_STATE_HEIGHTS
        ),
        (
            Slider::STATE_FLAG,
            Slider::STATE_POSITION,
            Slider::STATE_ROD_POSITION,
            Slider::STATE_MECHANISMS,
            Slider::STATE_HEIGHTS
        )
    );
}

#[test]
fn scalar_step_equals_the_rust_api_bit_for_bit() {
    let h = c_scene_slider();
    let rs = scene_slider();
    let m = rs.state_len();
    let mut w = rs.work();
    let mut c_state = vec![0.0; m];
    let mut c_new = vec![0.0; m];
    let mut r_state = vec![0.0; m];
    for k in 0..12 {
        let th = 0.4 * k as f64;
        let inc = FrictionIncrement {
            normal_force: 0.05 + 0.01 * k as f64,
            slip: [1.5e-6 * th.cos(), 1.5e-6 * th.sin()],
            dt: 1e-4,
            tangents: k % 4,
            ..Default::default()
        };
        let mut out = FrictionResponse::default();
        let st = unsafe {
            asperity_friction_step(
                h.law,
                &inc,
                c_state.as_ptr(),
                c_new.as_mut_ptr(),
                h.work,
                &mut out,
            )
        };
        assert_eq!(st, ASPERITY_OK, "{}", last_message());
        let want = rs.step_in_place(&mut r_state, &inc, &mut w).unwrap();
        assert!(same(&out, &want), "{k}: {out:?}\n{want:?}");
        assert_eq!(bits(&c_new), bits(&r_state), "{k}");
        assert_eq!(out.tangents, inc.tangents);
        assert!(out.dissipated >= 0.0);
        // NULL work: a fresh one inside the call, the same result.
        let mut out3 = FrictionResponse::default();
        let mut c_new3 = vec![0.0; m];
        let st = unsafe {
            asperity_friction_step(
                h.law,
                &inc,
                c_state.as_ptr(),
                c_new3.as_mut_ptr(),
                null_mut(),
                &mut out3,
            )
        };
        assert_eq!(st, ASPERITY_OK, "{}", last_message());
        assert!(same(&out, &out3));
        assert_eq!(bits(&c_new3), bits(&c_new));
        // In place gives the same.
        let mut out2 = FrictionResponse::default();
        let st = unsafe {
            asperity_friction_step(
                h.law,
                &inc,
                c_state.as_ptr(),
                c_state.as_mut_ptr(),
                h.work,
                &mut out2,
            )
        };
        assert_eq!(st, ASPERITY_OK, "{}", last_message());
        assert!(same(&out, &out2));
        assert_eq!(bits(&c_state), bits(&c_new));
    }
}

/// The contract of the one friction handle (issue 30 §1) for the slider:
/// old == new, NULL work, `asperity_friction_step_in_place`, the blocks
/// separate, old == new and in place, a partially overlapping block
/// (`new_states`) and a point count whose states overflow `size_t` (`n`),
/// bit for bit against the Rust slider.
#[test]
fn the_friction_handle_keeps_the_contract() {
    let h = c_scene_slider();
    let case = laws::slider_case();
    unsafe { laws::c_contract(h.law, &case, 10) };
}

/// `asperity_slider_record` gives the record of the work's last step, as
/// the Rust `SliderWork::record` does, whatever the form of the step.
#[test]
fn record_of_the_last_step_equals_the_rust_record() {
    let h = c_scene_slider();
    let rs = scene_slider();
    let m = rs.state_len();
    let mut w = rs.work();
    let (mut c_state, mut r_state) = (vec![0.0; m], vec![0.0; m]);
    c_state[ASPERITY_SLIDER_STATE_POSITION] = 6e-6;
    r_state[Slider::STATE_POSITION] = 6e-6;
    for k in 0..6 {
        let inc = FrictionIncrement {
            normal_force: 0.04 + 0.02 * k as f64,
            slip: if k == 3 { [0.0; 2] } else { [1.2e-6, 0.4e-6] },
            dt: 1e-4,
            tangents: k % 4,
            ..Default::default()
        };
        let mut out = FrictionResponse::default();
        let st = unsafe {
            asperity_friction_step_in_place(h.law, &inc, c_state.as_mut_ptr(), h.work, &mut out)
        };
        assert_eq!(st, ASPERITY_OK, "{}", last_message());
        rs.step_in_place(&mut r_state, &inc, &mut w).unwrap();
        let mut rec = AsperitySliderRecord {
            reserved: 7,
            ..Default::default()
        };
        let st = unsafe { asperity_slider_record(h.work, &mut rec) };
        assert_eq!(st, ASPERITY_OK, "{}", last_message());
        assert_eq!(rec, laws::slider_record(&w), "{k}");
        assert_eq!(rec.seated, (k == 0) as i32, "{k}");
        assert_eq!(rec.position, c_state[ASPERITY_SLIDER_STATE_POSITION]);
        assert_eq!(
            rec.rod_position,
            c_state[ASPERITY_SLIDER_STATE_ROD_POSITION]
        );
    }
    // A work that belongs to no slider, NULL pointers: named.
    let mut lugre = null_mut();
    let p = laws::lugre_params();
    assert_eq!(
        unsafe { asperity::ffi::dynamic::asperity_friction_lugre_new(&p, &mut lugre) },
        ASPERITY_OK
    );
    let mut other = null_mut();
    assert_eq!(
        unsafe { asperity_friction_work_new(lugre, &mut other) },
        ASPERITY_OK
    );
    let mut rec = AsperitySliderRecord::default();
    expect_error(
        unsafe { asperity_slider_record(other, &mut rec) },
        ASPERITY_ERR_INVALID_ARGUMENT,
        "`work`",
    );
    expect_error(
        unsafe { asperity_slider_record(null(), &mut rec) },
        ASPERITY_ERR_NULL_POINTER,
        "`work`",
    );
    expect_error(
        unsafe { asperity_slider_record(h.work, null_mut()) },
        ASPERITY_ERR_NULL_POINTER,
        "`out`",
    );
    unsafe {
        asperity_friction_work_free(other);
        asperity_friction_free(lugre);
    }
}

#[test]
fn block_step_equals_the_rust_block_and_steps_in_place() {
    let h = c_scene_slider();
    let rs = scene_slider();
    let m = rs.state_len();
    let n = 3;
    let normal = [0.03, 0.12, 0.25];
    let mut w = rs.work();
    let mut c_states = vec![0.0; n * m];
    let mut r_states = vec![0.0; n * m];
    c_states[2 * m + ASPERITY_SLIDER_STATE_POSITION] = 30e-6;
    r_states[2 * m + Slider::STATE_POSITION] = 30e-6;
    let mut c_sep = vec![0.0; n * m];
    for k in 0..5 {
        let slip: Vec<f64> = (0..2 * n).map(|j| 1e-6 * ((j + k) as f64).sin()).collect();
        let (mut cf, mut cd, mut rf, mut rd) = ([0.0; 6], [0.0; 3], [0.0; 6], [0.0; 3]);
        let mut cf2 = [0.0; 6];
        let st = unsafe {
            asperity_friction_step_block(
                h.law,
                n,
                normal.as_ptr(),
                null(),
                slip.as_ptr(),
                1e-4,
                c_states.as_ptr(),
                c_sep.as_mut_ptr(),
                cf2.as_mut_ptr(),
                null_mut(),
                h.work,
            )
        };
        assert_eq!(st, ASPERITY_OK, "{}", last_message());
        let st = unsafe {
            asperity_friction_step_block(
                h.law,
                n,
                normal.as_ptr(),
                null(),
                slip.as_ptr(),
                1e-4,
                c_states.as_ptr(),
                c_states.as_mut_ptr(),
                cf.as_mut_ptr(),
                cd.as_mut_ptr(),
                h.work,
            )
        };
        assert_eq!(st, ASPERITY_OK, "{}", last_message());
        let block = FrictionBlock {
            normal_force: &normal,
            area: None,
            slip: &slip,
            dt: 1e-4,
            tangents: 0,
            states: BlockStates::InPlace(&mut r_states),
            tangential_force: Some(&mut rf),
            dissipation: Some(&mut rd),
            responses: None,
        };
        rs.step_block(block, &mut w).unwrap();
        assert_eq!(bits(&cf), bits(&rf));
        assert_eq!(bits(&cf2), bits(&rf));
        assert_eq!(bits(&cd), bits(&rd));
        assert_eq!(bits(&c_states), bits(&r_states));
        assert_eq!(bits(&c_sep), bits(&r_states));
    }
    // n = 0 does nothing, even with NULL arrays.
    let st = unsafe {
        asperity_friction_step_block(
            h.law,
            0,
            null(),
            null(),
            null(),
            0.0,
            null(),
            null_mut(),
            null_mut(),
            null_mut(),
            h.work,
        )
    };
    assert_eq!(st, ASPERITY_OK);
}

#[test]
fn errors_name_the_argument_and_leave_outputs_untouched() {
    let h = c_scene_slider();
    let m = scene_slider().state_len();
    let old = vec![0.0; m];
    let mut new = vec![-3.0; m];
    let mut out = FrictionResponse {
        cof: -5.0,
        ..FrictionResponse::default()
    };
    let inc = FrictionIncrement {
        slip: [1e-6, 0.0],
        ..FrictionIncrement::default()
    };
    let step = |inc: &FrictionIncrement,
                old: *const f64,
                new: *mut f64,
                out: *mut FrictionResponse| unsafe {
        asperity_friction_step(h.law, inc, old, new, h.work, out)
    };
    // NULL pointers.
    let p_new = new.as_mut_ptr();
    expect_error(
        unsafe { asperity_friction_step(null(), &inc, old.as_ptr(), p_new, h.work, &mut out) },
        ASPERITY_ERR_NULL_POINTER,
        "`law`",
    );
    expect_error(
        step(&inc, null(), p_new, &mut out),
        ASPERITY_ERR_NULL_POINTER,
        "`old_state`",
    );
    expect_error(
        step(&inc, old.as_ptr(), null_mut(), &mut out),
        ASPERITY_ERR_NULL_POINTER,
        "`new_state`",
    );
    expect_error(
        step(&inc, old.as_ptr(), p_new, null_mut()),
        ASPERITY_ERR_NULL_POINTER,
        "`out`",
    );
    expect_error(
        unsafe { asperity_friction_step(h.law, null(), old.as_ptr(), p_new, h.work, &mut out) },
        ASPERITY_ERR_NULL_POINTER,
        "`increment`",
    );
    expect_error(
        unsafe { asperity_friction_step_in_place(h.law, &inc, null_mut(), h.work, &mut out) },
        ASPERITY_ERR_NULL_POINTER,
        "`state`",
    );
    // Selectors and values.
    let bad = |f: &dyn Fn(&mut FrictionIncrement)| {
        let mut i = inc;
        f(&mut i);
        i
    };
    let p_new = new.as_mut_ptr();
    expect_error(
        step(&bad(&|i| i.tangents = 4), old.as_ptr(), p_new, &mut out),
        ASPERITY_ERR_INVALID_ARGUMENT,
        "`tangents`",
    );
    expect_error(
        step(
            &bad(&|i| i.slip[1] = f64::NAN),
            old.as_ptr(),
            p_new,
            &mut out,
        ),
        ASPERITY_ERR_INVALID_ARGUMENT,
        "`slip`",
    );
    expect_error(
        step(&bad(&|i| i.dt = -1.0), old.as_ptr(), p_new, &mut out),
        ASPERITY_ERR_INVALID_ARGUMENT,
        "`dt`",
    );
    expect_error(
        step(&bad(&|i| i.area = f64::NAN), old.as_ptr(), p_new, &mut out),
        ASPERITY_ERR_INVALID_ARGUMENT,
        "`area`",
    );
    expect_error(
        step(
            &bad(&|i| i.normal_force = 1e3),
            old.as_ptr(),
            p_new,
            &mut out,
        ),
        ASPERITY_ERR_OUT_OF_DOMAIN,
        "`normal_force`",
    );
    let mut flagged = old.clone();
    flagged[ASPERITY_SLIDER_STATE_FLAG] = 3.0;
    expect_error(
        step(&inc, flagged.as_ptr(), p_new, &mut out),
        ASPERITY_ERR_INVALID_ARGUMENT,
        "`old.flag`",
    );
    expect_error(
        unsafe {
            asperity_friction_step_in_place(h.law, &inc, flagged.as_mut_ptr(), h.work, &mut out)
        },
        ASPERITY_ERR_INVALID_ARGUMENT,
        "`state.flag`",
    );
    // Past the end of the counter-surface.
    expect_error(
        step(
            &bad(&|i| i.slip = [1e-3, 0.0]),
            old.as_ptr(),
            p_new,
            &mut out,
        ),
        ASPERITY_ERR_OUT_OF_DOMAIN,
        "`position`",
    );
    // States that partially overlap.
    let mut both = vec![0.0; 2 * m];
    let p = both.as_mut_ptr();
    expect_error(
        step(&inc, p, unsafe { p.add(3) }, &mut out),
        ASPERITY_ERR_INVALID_ARGUMENT,
        "`new_state`",
    );
    assert!(new.iter().all(|&x| x == -3.0), "new_state untouched");
    assert_eq!(out.cof, -5.0, "out untouched");
    assert_eq!(both, vec![0.0; 2 * m]);

    // Block: an error at element 1 names it; element 0 written, 1.. not.
    let normal = [0.1, 1e3, 0.1];
    let slip = [1e-6; 6];
    let mut states = vec![0.0; 3 * m];
    let mut f = [7.0; 6];
    let st = unsafe {
        asperity_friction_step_block(
            h.law,
            3,
            normal.as_ptr(),
            null(),
            slip.as_ptr(),
            0.0,
            states.as_ptr(),
            states.as_mut_ptr(),
            f.as_mut_ptr(),
            null_mut(),
            h.work,
        )
    };
    expect_error(st, ASPERITY_ERR_OUT_OF_DOMAIN, "element 1");
    assert!(last_message().contains("`normal_force`"));
    assert_eq!(states[ASPERITY_SLIDER_STATE_FLAG], 1.0);
    assert!(states[m..].iter().all(|&x| x == 0.0));
    assert_ne!(f[0], 7.0);
    assert_eq!(f[2..], [7.0; 4]);
    let p = states.as_mut_ptr();
    let st = unsafe {
        asperity_friction_step_block(
            h.law,
            2,
            normal.as_ptr(),
            null(),
            slip.as_ptr(),
            0.0,
            p,
            p.add(m),
            f.as_mut_ptr(),
            null_mut(),
            h.work,
        )
    };
    expect_error(st, ASPERITY_ERR_INVALID_ARGUMENT, "`new_states`");
    let st = unsafe {
        asperity_friction_step_block(
            h.law,
            1,
            null(),
            null(),
            slip.as_ptr(),
            0.0,
            p,
            p,
            f.as_mut_ptr(),
            null_mut(),
            h.work,
        )
    };
    expect_error(st, ASPERITY_ERR_NULL_POINTER, "`normal_forces`");
    let st = unsafe {
        asperity_friction_step_block_in_place(
            h.law,
            1,
            normal.as_ptr(),
            null(),
            slip.as_ptr(),
            0.0,
            null_mut(),
            f.as_mut_ptr(),
            null_mut(),
            h.work,
        )
    };
    expect_error(st, ASPERITY_ERR_NULL_POINTER, "`states`");
    // Sizes and handles.
    let mut n = 0usize;
    expect_error(
        unsafe { asperity_friction_state_size(null(), &mut n) },
        ASPERITY_ERR_NULL_POINTER,
        "`law`",
    );
    expect_error(
        unsafe { asperity_friction_state_size(h.law, null_mut()) },
        ASPERITY_ERR_NULL_POINTER,
        "`n`",
    );
    let mut w = 1usize as *mut AsperityFrictionWork;
    expect_error(
        unsafe { asperity_friction_work_new(null(), &mut w) },
        ASPERITY_ERR_NULL_POINTER,
        "`law`",
    );
    assert!(w.is_null());
    let mut l = 1usize as *mut AsperityFriction;
    expect_error(
        unsafe { asperity_friction_from_slider(null(), &mut l) },
        ASPERITY_ERR_NULL_POINTER,
        "`slider`",
    );
    assert!(l.is_null());
    expect_error(
        unsafe { asperity_friction_from_slider(h.slider, null_mut()) },
        ASPERITY_ERR_NULL_POINTER,
        "`out`",
    );
    unsafe {
        asperity_slider_free(null_mut());
        asperity_friction_free(null_mut());
        asperity_friction_work_free(null_mut());
    }
}

#[test]
fn scene_json_errors_and_base_dir() {
    let good = scene_text();
    // Syntax: a parse error with the line.
    let (st, h) = from_json("{\n  \"material\": ", None);
    expect_error(st, ASPERITY_ERR_PARSE, "`json`");
    assert!(h.is_null());
    assert!(last_message().contains("line 2"), "{}", last_message());
    // Unknown field: named.
    let (st, _) = from_json(&good.replacen("\"outputs\"", "\"output\"", 1), None);
    expect_error(st, ASPERITY_ERR_PARSE, "unknown field `output`");
    // A value outside its domain: the field and the bound.
    let (st, _) = from_json(&good.replace("\"load\": 0.18", "\"load\": 99"), None);
    expect_error(st, ASPERITY_ERR_OUT_OF_DOMAIN, "`load`");
    // A scene choosing dynamic friction models builds the same slider; a
    // bad model parameter is named by its field path.
    let models = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/dynamic_models.json"),
    )
    .unwrap();
    let (st, h) = from_json(&models, None);
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    unsafe { asperity_slider_free(h) };
    let (st, h) = from_json(&models.replace("\"sigma1\": 100", "\"sigma1\": 1e6"), None);
    expect_error(
        st,
        ASPERITY_ERR_INVALID_ARGUMENT,
        "`friction_models[0].lugre`",
    );
    assert!(
        h.is_null() && last_message().contains("sigma1"),
        "{}",
        last_message()
    );
    // Not UTF-8.
    let bytes = b"{\xff}";
    let mut h = null_mut();
    let st = unsafe { asperity_slider_from_scene_json(bytes.as_ptr().cast(), 3, null(), &mut h) };
    expect_error(st, ASPERITY_ERR_INVALID_ARGUMENT, "`json`");
    let st = unsafe { asperity_slider_from_scene_json(null(), 0, null(), &mut h) };
    expect_error(st, ASPERITY_ERR_NULL_POINTER, "`json`");
    let st = unsafe {
        asperity_slider_from_scene_json(good.as_ptr().cast(), good.len(), null(), null_mut())
    };
    expect_error(st, ASPERITY_ERR_NULL_POINTER, "`out`");

    // A scene naming a profile file: relative to base_dir, or to the
    // current directory without it.
    let dir = std::env::temp_dir().join(format!("asperity-ffi-slider-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let csv: String = (0..300)
        .map(|j| {
            let x = j as f64 * 1.5e-6;
            format!(
                "{x:e},{:e}\n",
                4e-7 * (x * 2.0e5).sin() + 2e-7 * (x * 7.1e5).cos()
            )
        })
        .collect();
    let name = "ffi_slider_counter_profile.csv";
    std::fs::write(dir.join(name), csv).unwrap();
    let counter = "{ \"hurst\": 0.8, \"rq\": 5e-7, \"roll_off_wavelength\": 1e-4, \"points\": 241, \"dx\": 1.5e-6, \"seed\": 7 }";
    assert!(good.contains(counter));
    let with_file = good
        .replace(counter, &format!("{{ \"path\": \"{name}\" }}"))
        .replacen("\"self_affine\": { \"path", "\"file\": { \"path", 1);
    assert!(with_file.contains("\"file\""), "{with_file}");
    let (st, h) = from_json(&with_file, Some(&dir));
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    let mut info = AsperitySliderInfo::default();
    assert_eq!(unsafe { asperity_slider_info(h, &mut info) }, ASPERITY_OK);
    assert_eq!(info.counter_samples, 300);
    // The same through the Rust scene API.
    let rs = Scene::from_json(&with_file, &dir).unwrap().build().unwrap();
    assert_eq!(info.capacity, rs.capacity());
    let rs_counter = rs.counter().to_vec();
    unsafe { asperity_slider_free(h) };
    assert_eq!(rs_counter.len(), 300);
    let (st, h) = from_json(&with_file, None);
    expect_error(st, ASPERITY_ERR_IO, name);
    assert!(h.is_null());
    let _ = std::fs::remove_dir_all(&dir);
}

// ------------------------------------------------ built from structs

use asperity::ffi::friction::{
    asperity_slider_geometry_free, asperity_slider_geometry_new_uniform, AsperityNanoAsperities,
    AsperitySliderGeometry,
};
use asperity::friction::{
    CofForm, FrictionMaterial, Mechanisms, NanoAsperities, PlasticUpdate, RodOptions,
    SliderGeometry, SliderOptions, TrackEnd,
};

fn c_copper() -> FrictionMaterial {
    let mut m = FrictionMaterial::copper();
    m.yield_stress = 0.0;
    assert_eq!(
        unsafe { asperity_friction_material_copper(&mut m) },
        ASPERITY_OK
    );
    assert_eq!(m, FrictionMaterial::copper());
    m
}

fn c_defaults() -> AsperitySliderOptions {
    let mut o = std::mem::MaybeUninit::<AsperitySliderOptions>::zeroed();
    assert_eq!(
        unsafe { asperity_slider_options_default(o.as_mut_ptr()) },
        ASPERITY_OK
    );
    unsafe { o.assume_init() }
}

/// 90 flat rods of 1.5 µm with the chapter-6 nano-asperities (one across
/// a tip), through C and through Rust.
fn uniform_geometry() -> (*mut AsperitySliderGeometry, SliderGeometry) {
    let rs = scene_slider();
    let n = rs.geometry().nano();
    let nano = AsperityNanoAsperities {
        h_vdw: n.h_vdw,
        w_vdw: n.w_vdw,
        h_chem: n.h_chem,
        w_chem: n.w_chem,
        spacing: n.spacing,
        per_rod: 1,
    };
    let mut g = null_mut();
    let st = unsafe { asperity_slider_geometry_new_uniform(1.5e-6, 90, &nano, &mut g) };
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    let parameters = NanoAsperities {
        h_vdw: n.h_vdw,
        w_vdw: n.w_vdw,
        h_chem: n.h_chem,
        w_chem: n.w_chem,
        spacing: n.spacing,
    };
    (
        g,
        SliderGeometry::uniform(1.5e-6, 90, parameters, 1).unwrap(),
    )
}

#[test]
fn slider_from_structs_equals_the_rust_slider() {
    let (g, geometry) = uniform_geometry();
    let rs = scene_slider();
    let counter = rs.counter().to_vec();
    let dx = rs.counter_dx();
    let mut material = c_copper();
    material.adhesive_layer = 8e-9;
    // Two option sets: the scene's kind (Gaussian pile-up, deep rods, fixed
    // load, some mechanisms off) and the defaults at a fixed gap.
    let mut a = c_defaults();
    a.control = ASPERITY_SLIDER_CONTROL_LOAD;
    a.normal_force = 0.04;
    a.plastic = ASPERITY_PLASTIC_GAUSSIAN;
    a.plastic_width = 2e-5;
    a.depth = 1.35e-5;
    a.mechanisms = ASPERITY_MECHANISM_CHEMICAL | ASPERITY_MECHANISM_PLASTIC;
    a.cof_form = ASPERITY_COF_AMONTONS;
    let ra = SliderOptions {
        loading: Loading::FixedLoad { load: 0.04 },
        rod: RodOptions {
            plastic: PlasticUpdate::Gaussian { width: 2e-5 },
            ..RodOptions::default()
        },
        mechanisms: Mechanisms {
            chemical: true,
            van_der_waals: false,
            elastic: false,
            plastic: true,
        },
        cof_form: CofForm::Amontons,
        depth: Some(1.35e-5),
        root_margin: None,
        track_end: TrackEnd::Error,
        counter_height: asperity::friction::CounterHeight::RodCentre,
    };
    let mut b = c_defaults();
    b.control = ASPERITY_SLIDER_CONTROL_GAP;
    b.gap = -3e-7;
    b.periodic = 1;
    b.solver = ASPERITY_ROD_SOLVER_DENSE;
    b.root_margin = 2e-6;
    let rb = SliderOptions {
        loading: Loading::FixedGap { position: -3e-7 },
        rod: RodOptions {
            solver: asperity::friction::RodSolver::Dense,
            ..RodOptions::default()
        },
        root_margin: Some(2e-6),
        track_end: TrackEnd::Periodic,
        ..SliderOptions::new(Loading::FixedLoad { load: 0.0 })
    };
    let mut want_material = FrictionMaterial::copper();
    want_material.adhesive_layer = 8e-9;
    for (c_opts, r_opts) in [(a, ra), (b, rb)] {
        let mut h = null_mut();
        let st = unsafe {
            asperity_slider_new(
                g,
                &material,
                counter.as_ptr(),
                counter.len(),
                dx,
                &c_opts,
                &mut h,
            )
        };
        assert_eq!(st, ASPERITY_OK, "{}", last_message());
        let want =
            Slider::new(geometry.clone(), want_material, counter.clone(), dx, r_opts).unwrap();
        // The loading is the scene's (Slider::slide); the friction law
        // steps at the load of each increment.
        let mut info = AsperitySliderInfo::default();
        assert_eq!(unsafe { asperity_slider_info(h, &mut info) }, ASPERITY_OK);
        match r_opts.loading {
            Loading::FixedLoad { load } => {
                assert_eq!(info.scene_control, ASPERITY_SLIDER_CONTROL_LOAD);
                assert_eq!(info.scene_loading, load);
            }
            Loading::FixedGap { position } => {
                assert_eq!(info.scene_control, ASPERITY_SLIDER_CONTROL_GAP);
                assert_eq!(info.scene_loading, position);
            }
        }
        assert_eq!(
            info.periodic,
            (r_opts.track_end == TrackEnd::Periodic) as i32
        );
        let (law, work) = c_slider_law(h);
        let m = want.state_len();
        let (mut c_state, mut r_state) = (vec![0.0; m], vec![0.0; m]);
        let mut w = want.work();
        let mut dissipated = 0.0;
        for k in 0..40 {
            let inc = FrictionIncrement {
                normal_force: 0.04,
                slip: [1.5e-6, 0.0],
                ..Default::default()
            };
            let mut out = FrictionResponse::default();
            let st = unsafe {
                asperity_friction_step(
                    law,
                    &inc,
                    c_state.as_ptr(),
                    c_state.as_mut_ptr(),
                    work,
                    &mut out,
                )
            };
            assert_eq!(st, ASPERITY_OK, "{k}: {}", last_message());
            let r = want.step_in_place(&mut r_state, &inc, &mut w).unwrap();
            assert!(same(&out, &r), "{k}: {out:?}\n{r:?}");
            assert_eq!(bits(&c_state), bits(&r_state), "{k}");
            dissipated += out.dissipated;
        }
        // The options took effect: the run dissipates, and with only the
        // chemical and plastic mechanisms nothing else is booked.
        assert!(dissipated > 0.0);
        let d = &r_state[Slider::STATE_MECHANISMS..Slider::STATE_MECHANISMS + 4];
        if c_opts.mechanisms != ASPERITY_MECHANISM_ALL {
            assert_eq!((d[1], d[2]), (0.0, 0.0));
            assert!(d[0] > 0.0);
        }
        unsafe {
            asperity_friction_work_free(work);
            asperity_friction_free(law);
            asperity_slider_free(h);
        }
    }
    unsafe { asperity_slider_geometry_free(g) };
}

#[test]
fn slider_from_structs_errors_name_the_argument() {
    let (g, _) = uniform_geometry();
    let rs = scene_slider();
    let counter = rs.counter().to_vec();
    let dx = rs.counter_dx();
    let material = c_copper();
    let ok = c_defaults();
    let new = |g: *const AsperitySliderGeometry,
               m: *const FrictionMaterial,
               c: &[f64],
               dx: f64,
               o: *const AsperitySliderOptions| {
        let mut h = 1usize as *mut AsperitySlider;
        let st = unsafe { asperity_slider_new(g, m, c.as_ptr(), c.len(), dx, o, &mut h) };
        assert!(h.is_null(), "*out is NULL on failure");
        st
    };
    expect_error(
        new(null(), &material, &counter, dx, &ok),
        ASPERITY_ERR_NULL_POINTER,
        "geometry",
    );
    expect_error(
        new(g, null(), &counter, dx, &ok),
        ASPERITY_ERR_NULL_POINTER,
        "material",
    );
    let mut bad = material;
    bad.yield_stress = -1.0;
    expect_error(
        new(g, &bad, &counter, dx, &ok),
        ASPERITY_ERR_INVALID_ARGUMENT,
        "yield_stress",
    );
    expect_error(
        new(g, &material, &counter, 0.0, &ok),
        ASPERITY_ERR_INVALID_ARGUMENT,
        "counter_dx",
    );
    expect_error(
        new(g, &material, &counter[..20], dx, &ok),
        ASPERITY_ERR_INVALID_ARGUMENT,
        "n_counter",
    );
    let mut nan = counter.clone();
    nan[7] = f64::NAN;
    expect_error(
        new(g, &material, &nan, dx, &ok),
        ASPERITY_ERR_INVALID_ARGUMENT,
        "counter",
    );
    let with = |f: &dyn Fn(&mut AsperitySliderOptions)| {
        let mut o = ok;
        f(&mut o);
        o
    };
    for (o, code, name) in [
        (
            with(&|o| o.control = 0),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "options.control",
        ),
        (
            with(&|o| o.mechanisms = 16),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "options.mechanisms",
        ),
        (
            with(&|o| o.cof_form = 4),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "options.cof_form",
        ),
        (
            with(&|o| o.plastic = -1),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "options.plastic",
        ),
        (
            with(&|o| o.solver = 2),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "options.solver",
        ),
        (
            with(&|o| o.periodic = 2),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "options.periodic",
        ),
        (
            with(&|o| o.normal_force = -1.0),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "options.normal_force",
        ),
        (
            with(&|o| o.normal_force = 1e3),
            ASPERITY_ERR_OUT_OF_DOMAIN,
            "options.normal_force",
        ),
        (
            with(&|o| {
                o.control = ASPERITY_SLIDER_CONTROL_GAP;
                o.gap = f64::INFINITY
            }),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "options.gap",
        ),
        (
            with(&|o| {
                o.plastic = ASPERITY_PLASTIC_GAUSSIAN;
                o.plastic_width = 0.0
            }),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "options.plastic_width",
        ),
        (
            with(&|o| o.depth = -1e-6),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "options.depth",
        ),
        (
            with(&|o| o.depth = 1e-7),
            ASPERITY_ERR_INVALID_ARGUMENT,
            "options.depth",
        ),
    ] {
        expect_error(new(g, &material, &counter, dx, &o), code, name);
    }
    expect_error(
        new(g, &material, &counter, dx, null()),
        ASPERITY_ERR_NULL_POINTER,
        "options",
    );
    unsafe { asperity_slider_geometry_free(g) };
}

/// A scene is outside data: a generated profile of more than
/// `scene::MAX_POINTS` samples is an error naming `points` (before, 10^12
/// points reached an allocation that aborts the host process). The bound
/// itself passes validation.
#[test]
fn scene_points_beyond_the_bound_are_errors() {
    let text = scene_text();
    assert!(
        text.contains("\"points\": 241"),
        "the scene changed: update this test"
    );
    for points in [asperity::scene::MAX_POINTS + 1, 1_000_000_000_000] {
        let big = text.replace("\"points\": 241", &format!("\"points\": {points}"));
        let (st, h) = from_json(&big, Some(scene_path().parent().unwrap()));
        assert!(h.is_null());
        expect_error(st, ASPERITY_ERR_INVALID_ARGUMENT, "`points`");
        let e = Scene::from_json(&big, ".").unwrap_err().to_string();
        assert!(
            e.contains("points") && e.contains("surfaces.counter"),
            "{e}"
        );
    }
    let at_bound = text.replace(
        "\"points\": 241",
        &format!("\"points\": {}", asperity::scene::MAX_POINTS),
    );
    assert!(Scene::from_json(&at_bound, ".").is_ok());
}

/// A file surface's `start` or `length` far past the profile is an error
/// naming `length`, not an index overflow (found reviewing the scene parser
/// for fuzzing; fuzz/regressions/scene_json/file_*_overflow.json).
#[test]
fn scene_file_ranges_beyond_the_profile_are_errors() {
    let dir = std::env::temp_dir().join(format!("asperity-scene-range-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let profile: String = (0..64)
        .map(|j| {
            format!(
                "{:e},{:e}\n",
                j as f64 * 1e-6,
                1e-7 * (0.3 * j as f64).sin()
            )
        })
        .collect();
    std::fs::write(dir.join("p.csv"), profile).unwrap();
    let text = scene_text();
    let counter = "\"counter\": {\n      \"self_affine\": { \"hurst\": 0.8, \"rq\": 5e-7, \"roll_off_wavelength\": 1e-4, \"points\": 241, \"dx\": 1.5e-6, \"seed\": 7 }\n    }";
    assert!(
        text.contains(counter),
        "the scene changed: update this test"
    );
    for range in [
        "\"start\": 0, \"length\": 1e300",
        "\"start\": 1e300",
        "\"start\": 1e300, \"length\": 1e300",
    ] {
        let t = text.replace(
            counter,
            &format!("\"counter\": {{ \"file\": {{ \"path\": \"p.csv\", {range} }} }}"),
        );
        let e = Scene::from_json(&t, &dir)
            .unwrap()
            .build()
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("`length`") && e.contains("surfaces.counter"),
            "{range}: {e}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A nano-asperity spacing far below the rod width or depth gave the
/// slider ⌊w/λ⌋ nano-asperity columns saturated to `usize::MAX`:
/// `asperity_slider_info` overflowed m_x·m_y (the C guard's
/// `ASPERITY_ERR_INTERNAL`) and a step looped over ~10¹⁹ columns per rod (a
/// hang). Found reviewing `asperity_slider_new` for the fuzz harness. Now at
/// most `MAX_NANO_PER_ROD` = 2²⁴ nano-asperities per rod, an error naming
/// `spacing` (or `options.depth` when the depth makes the excess), the
/// handle NULL.
#[test]
fn slider_nano_counts_beyond_the_bound_are_errors() {
    let w = 1.5e-6;
    let geometry = |spacing: f64| {
        let nano = AsperityNanoAsperities {
            h_vdw: 6e-9,
            w_vdw: spacing,
            h_chem: 0.0,
            w_chem: 0.0,
            spacing,
            per_rod: 1,
        };
        let mut g = null_mut();
        let st = unsafe { asperity_slider_geometry_new_uniform(w, 2, &nano, &mut g) };
        assert_eq!(st, ASPERITY_OK, "{}", last_message());
        g
    };
    // 64 samples at 0.1 µm lie under the two 1.5 µm rods.
    let counter: Vec<f64> = (0..64).map(|j| 1e-8 * (0.4 * j as f64).sin()).collect();
    let material = c_copper();
    let build = |g: *const AsperitySliderGeometry, o: &AsperitySliderOptions| {
        let mut h = 1usize as *mut AsperitySlider;
        let st = unsafe {
            asperity_slider_new(
                g,
                &material,
                counter.as_ptr(),
                counter.len(),
                1e-7,
                o,
                &mut h,
            )
        };
        (st, h)
    };
    let square = c_defaults();
    for spacing in [1e-30, 1e-300, w / 4097.0] {
        let g = geometry(spacing);
        let (st, h) = build(g, &square);
        assert!(h.is_null(), "spacing {spacing:e}");
        expect_error(st, ASPERITY_ERR_INVALID_ARGUMENT, "`spacing`");
        assert!(last_message().contains("2^24"), "{}", last_message());
        unsafe { asperity_slider_geometry_free(g) };
    }
    // The bound itself: 4096 × 4096 on a square tip.
    let g = geometry(w / 4096.0);
    let (st, h) = build(g, &square);
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    let mut info = AsperitySliderInfo::default();
    assert_eq!(unsafe { asperity_slider_info(h, &mut info) }, ASPERITY_OK);
    assert_eq!((info.rods, info.nano_per_rod), (2, 16_777_216));
    unsafe { asperity_slider_free(h) };
    unsafe { asperity_slider_geometry_free(g) };
    // 64 columns, and a depth of 2^19 spacings: 2^25 per rod.
    let g = geometry(w / 64.0);
    let mut deep = c_defaults();
    deep.depth = (1u64 << 19) as f64 * w / 64.0;
    let (st, h) = build(g, &deep);
    assert!(h.is_null());
    expect_error(st, ASPERITY_ERR_INVALID_ARGUMENT, "`options.depth`");
    deep.depth = (1u64 << 18) as f64 * w / 64.0;
    let (st, h) = build(g, &deep);
    assert_eq!(st, ASPERITY_OK, "{}", last_message());
    assert_eq!(unsafe { asperity_slider_info(h, &mut info) }, ASPERITY_OK);
    assert_eq!(info.nano_per_rod, 64 << 18);
    unsafe { asperity_slider_free(h) };
    unsafe { asperity_slider_geometry_free(g) };
}
