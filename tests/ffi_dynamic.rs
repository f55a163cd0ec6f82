//! The C ABI of the dynamic friction models (constructors of the one
//! friction handle `AsperityFriction`), called from Rust: equality with the
//! Rust API bit for bit (scalar, in place, block, old == new, NULL work),
//! the handle's contract for each model (overlapping and overflowing
//! blocks), errors naming the argument with outputs untouched, NULL
//! pointers.

mod common;
#[path = "common/laws.rs"]
mod laws;
use common::c_errors::{expect_error, last_message};

use asperity::ffi::dynamic::*;
use asperity::ffi::friction_law::*;
use asperity::ffi::*;
use asperity::friction::dynamic::{
    FrictionIncrement, FrictionLaw, FrictionResponse, LuGre, MaxwellSlip,
};
use asperity::friction::{BlockStates, FrictionBlock};
use std::ptr::{null, null_mut};

const K: [f64; 3] = [2e5, 5e4, 1e4];
const MU: [f64; 3] = [0.2, 0.2, 0.1];

/// The two models through C, and the same through Rust.
fn models() -> Vec<(*mut AsperityFriction, Box<dyn FrictionLaw>)> {
    let p = laws::lugre_params();
    let mut a = null_mut();
    assert_eq!(
        unsafe { asperity_friction_lugre_new(&p, &mut a) },
        ASPERITY_OK
    );
    let mut b = null_mut();
    assert_eq!(
        unsafe { asperity_friction_maxwell_slip_new(K.as_ptr(), MU.as_ptr(), 3, 0.1, &mut b) },
        ASPERITY_OK
    );
    vec![
        (
            a,
            Box::new(LuGre::new(0.3, 0.5, 1e-3, 2.0, 1e5, 1000.0, 1e-3, 0.4).unwrap()),
        ),
        (b, Box::new(MaxwellSlip::new(&K, &MU, 0.1).unwrap())),
    ]
}

fn increment(k: usize) -> FrictionIncrement {
    let th = 0.7 * k as f64;
    FrictionIncrement {
        normal_force: 2.0 + (0.3 * k as f64).sin(),
        slip: [2e-6 * th.cos(), 1e-6 * th.sin()],
        dt: 1e-3,
        tangents: (k % 4) as i32,
        ..Default::default()
    }
}

#[test]
fn steps_equal_the_rust_api_bit_for_bit() {
    for (h, rust) in models() {
        let mut n = 0usize;
        assert_eq!(
            unsafe { asperity_friction_state_size(h, &mut n) },
            ASPERITY_OK
        );
        assert_eq!(n, rust.state_len());
        let mut work = null_mut();
        assert_eq!(
            unsafe { asperity_friction_work_new(h, &mut work) },
            ASPERITY_OK
        );
        let (mut c, mut c_new, mut r) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        for k in 0..30 {
            let inc = increment(k);
            let mut out = FrictionResponse::default();
            let st = unsafe {
                asperity_friction_step(h, &inc, c.as_ptr(), c_new.as_mut_ptr(), work, &mut out)
            };
            assert_eq!(st, ASPERITY_OK, "{}", last_message());
            let want = rust.step_in_place(&mut r, &inc, &mut rust.work()).unwrap();
            assert_eq!(format!("{out:?}"), format!("{want:?}"));
            assert_eq!(c_new, r);
            // In place gives the same.
            let mut out2 = FrictionResponse::default();
            let st = unsafe {
                asperity_friction_step(h, &inc, c.as_ptr(), c.as_mut_ptr(), null_mut(), &mut out2)
            };
            assert_eq!(st, ASPERITY_OK, "{}", last_message());
            assert_eq!(out, out2);
            assert_eq!(c, c_new);
        }
        // The block: 4 points, against the Rust block.
        let pts = 4;
        let normal: Vec<f64> = (0..pts).map(|i| 1.0 + i as f64).collect();
        let slip: Vec<f64> = (0..2 * pts).map(|i| 1e-6 * (i as f64 - 3.5)).collect();
        let (mut cs, mut rs) = (vec![0.0; pts * n], vec![0.0; pts * n]);
        let (mut cf, mut rf) = (vec![0.0; 2 * pts], vec![0.0; 2 * pts]);
        let (mut cd, mut rd) = (vec![0.0; pts], vec![0.0; pts]);
        for _ in 0..3 {
            let st = unsafe {
                asperity_friction_step_block_in_place(
                    h,
                    pts,
                    normal.as_ptr(),
                    null(),
                    slip.as_ptr(),
                    1e-3,
                    cs.as_mut_ptr(),
                    cf.as_mut_ptr(),
                    cd.as_mut_ptr(),
                    work,
                )
            };
            assert_eq!(st, ASPERITY_OK, "{}", last_message());
            let block = FrictionBlock {
                normal_force: &normal,
                area: None,
                slip: &slip,
                dt: 1e-3,
                tangents: 0,
                states: BlockStates::InPlace(&mut rs),
                tangential_force: Some(&mut rf),
                dissipation: Some(&mut rd),
                responses: None,
            };
            rust.step_block(block, &mut rust.work()).unwrap();
            assert_eq!((&cs, &cf, &cd), (&rs, &rf, &rd));
        }
        unsafe {
            asperity_friction_work_free(work);
            asperity_friction_free(h);
        }
    }
}

#[test]
fn errors_name_the_argument_and_leave_outputs_untouched() {
    let mut p = laws::lugre_params();
    p.sigma1 = 1e6;
    let mut h = 1usize as *mut AsperityFriction;
    expect_error(
        unsafe { asperity_friction_lugre_new(&p, &mut h) },
        ASPERITY_ERR_INVALID_ARGUMENT,
        "params.sigma1",
    );
    assert!(h.is_null());
    expect_error(
        unsafe { asperity_friction_lugre_new(null(), &mut h) },
        ASPERITY_ERR_NULL_POINTER,
        "params",
    );
    expect_error(
        unsafe { asperity_friction_maxwell_slip_new(K.as_ptr(), MU.as_ptr(), 0, 0.0, &mut h) },
        ASPERITY_ERR_INVALID_ARGUMENT,
        "capacity.len()",
    );
    expect_error(
        unsafe { asperity_friction_maxwell_slip_new(null(), MU.as_ptr(), 3, 0.0, &mut h) },
        ASPERITY_ERR_NULL_POINTER,
        "stiffness",
    );
    for (h, _) in models() {
        let mut n = 0usize;
        unsafe { asperity_friction_state_size(h, &mut n) };
        let old = vec![0.0; 2 * n];
        let mut new = vec![7.0; n];
        let mut out = FrictionResponse {
            cof: 9.0,
            ..Default::default()
        };
        let mut bad = increment(1);
        bad.dt = -1.0;
        expect_error(
            unsafe {
                asperity_friction_step(
                    h,
                    &bad,
                    old.as_ptr(),
                    new.as_mut_ptr(),
                    null_mut(),
                    &mut out,
                )
            },
            ASPERITY_ERR_INVALID_ARGUMENT,
            "dt",
        );
        assert!(new.iter().all(|&x| x == 7.0) && out.cof == 9.0);
        // Partially overlapping states.
        let mut both = vec![0.0; 2 * n];
        let p = both.as_mut_ptr();
        expect_error(
            unsafe { asperity_friction_step(h, &increment(1), p, p.add(1), null_mut(), &mut out) },
            ASPERITY_ERR_INVALID_ARGUMENT,
            "new_state",
        );
        expect_error(
            unsafe {
                asperity_friction_step(
                    h,
                    null(),
                    old.as_ptr(),
                    new.as_mut_ptr(),
                    null_mut(),
                    &mut out,
                )
            },
            ASPERITY_ERR_NULL_POINTER,
            "increment",
        );
        // A bad point in a block names its index.
        let normal = [1.0, 1.0, f64::NAN];
        let slip = [1e-6; 6];
        let mut states = vec![0.0; 3 * n];
        let mut forces = [0.0; 6];
        expect_error(
            unsafe {
                asperity_friction_step_block_in_place(
                    h,
                    3,
                    normal.as_ptr(),
                    null(),
                    slip.as_ptr(),
                    1e-3,
                    states.as_mut_ptr(),
                    forces.as_mut_ptr(),
                    null_mut(),
                    null_mut(),
                )
            },
            ASPERITY_ERR_INVALID_ARGUMENT,
            "element 2: ",
        );
        assert!(last_message().contains("normal_force"));
        assert!(forces[..4].iter().all(|&f| f != 0.0) && forces[4..] == [0.0, 0.0]);
        unsafe { asperity_friction_free(h) };
    }
}

/// Steps `h` through C, in place, and `rust` along `incs` from fresh
/// states: every response and state equal bit for bit (compared through
/// `Debug`, so -0.0 and NaN count). Returns the state size.
fn in_place_equals_rust(
    h: *mut AsperityFriction,
    rust: &dyn FrictionLaw,
    incs: impl Iterator<Item = FrictionIncrement>,
) -> usize {
    let mut n = 0usize;
    assert_eq!(
        unsafe { asperity_friction_state_size(h, &mut n) },
        ASPERITY_OK
    );
    assert_eq!(n, rust.state_len());
    let (mut c, mut r) = (vec![0.0; n], vec![0.0; n]);
    for (k, inc) in incs.enumerate() {
        let mut out = FrictionResponse::default();
        let st = unsafe {
            asperity_friction_step(h, &inc, c.as_ptr(), c.as_mut_ptr(), null_mut(), &mut out)
        };
        assert_eq!(st, ASPERITY_OK, "increment {k}: {}", last_message());
        let want = rust.step_in_place(&mut r, &inc, &mut rust.work()).unwrap();
        assert_eq!(format!("{out:?}"), format!("{want:?}"), "increment {k}");
        assert_eq!(c, r, "increment {k}");
    }
    n
}

#[test]
fn prandtl_tomlinson_through_c_equals_rust() {
    use asperity::friction::dynamic::PrandtlTomlinson;
    let (u0, a, k, m, g) = (2e-21, 3e-10, 1.0, 1e-12, 1e-6);
    let mut h = null_mut();
    assert_eq!(
        unsafe { asperity_friction_prandtl_tomlinson_new(u0, a, k, m, g, 1e-9, &mut h) },
        ASPERITY_OK
    );
    let rust = PrandtlTomlinson::new(u0, a, k, m, g, 1e-9).unwrap();
    let incs = (0..50).map(|k| FrictionIncrement {
        normal_force: 1.0,
        slip: [1e-11 * (1.0 + (0.3 * k as f64).sin()), 0.0],
        dt: 1e-6,
        tangents: k % 4,
        ..Default::default()
    });
    assert_eq!(in_place_equals_rust(h, &rust, incs), 5);
    let mut c = vec![0.0; 5];
    let mut out = FrictionResponse::default();
    let bad = FrictionIncrement {
        normal_force: 1.0,
        slip: [1e-11, 1e-11],
        dt: 1e-6,
        ..Default::default()
    };
    expect_error(
        unsafe {
            asperity_friction_step(h, &bad, c.as_ptr(), c.as_mut_ptr(), null_mut(), &mut out)
        },
        ASPERITY_ERR_INVALID_ARGUMENT,
        "slip",
    );
    let mut bad_h = 1usize as *mut AsperityFriction;
    expect_error(
        unsafe { asperity_friction_prandtl_tomlinson_new(u0, a, k, 0.0, g, 1e-9, &mut bad_h) },
        ASPERITY_ERR_INVALID_ARGUMENT,
        "mass",
    );
    assert!(bad_h.is_null());
    unsafe { asperity_friction_free(h) };
}

#[test]
fn two_spring_and_burridge_knopoff_through_c_equal_rust() {
    let t = laws::two_spring_params();
    let b = laws::burridge_knopoff_params(6);
    let (mut ht, mut hb) = (null_mut(), null_mut());
    assert_eq!(
        unsafe { asperity_friction_prandtl_tomlinson_two_spring_new(&t, &mut ht) },
        ASPERITY_OK
    );
    assert_eq!(
        unsafe { asperity_friction_burridge_knopoff_new(&b, &mut hb) },
        ASPERITY_OK
    );
    let (rust_t, rust_b) = (laws::two_spring(), laws::burridge_knopoff());
    let cases: [(_, &dyn FrictionLaw, usize, f64); 2] =
        [(ht, &rust_t, 7, 1e-11), (hb, &rust_b, 15, 2e-5)];
    for (h, rust, len, scale) in cases {
        let incs = (0..40).map(|k| FrictionIncrement {
            normal_force: 6.0,
            slip: [scale * (1.0 + (0.3 * k as f64).sin()), 0.0],
            dt: 1e-6,
            tangents: k % 4,
            ..Default::default()
        });
        assert_eq!(in_place_equals_rust(h, rust, incs), len);
        unsafe { asperity_friction_free(h) };
    }
    // Errors name the field of the parameters, the handle is NULL.
    let mut bad_h = 1usize as *mut AsperityFriction;
    let mut bad = t;
    bad.cantilever_mass = -1.0;
    expect_error(
        unsafe { asperity_friction_prandtl_tomlinson_two_spring_new(&bad, &mut bad_h) },
        ASPERITY_ERR_INVALID_ARGUMENT,
        "`params.cantilever_mass`",
    );
    assert!(bad_h.is_null());
    for (edit, field) in [
        (
            (|p: &mut AsperityBurridgeKnopoffParams| p.blocks = 257) as fn(&mut _),
            "`params.blocks`",
        ),
        (|p| p.mu_kinetic = 0.6, "`params.mu_kinetic`"),
        (
            |p| p.weakening_velocity = f64::NAN,
            "`params.weakening_velocity`",
        ),
        (|p| p.tolerance = 0.0, "`params.tolerance`"),
    ] {
        let mut bad = b;
        edit(&mut bad);
        bad_h = 1usize as *mut AsperityFriction;
        expect_error(
            unsafe { asperity_friction_burridge_knopoff_new(&bad, &mut bad_h) },
            ASPERITY_ERR_INVALID_ARGUMENT,
            field,
        );
        assert!(bad_h.is_null());
    }
    expect_error(
        unsafe { asperity_friction_burridge_knopoff_new(null(), &mut bad_h) },
        ASPERITY_ERR_NULL_POINTER,
        "params",
    );
    expect_error(
        unsafe { asperity_friction_prandtl_tomlinson_two_spring_new(&t, null_mut()) },
        ASPERITY_ERR_NULL_POINTER,
        "out",
    );
    // A stiff chain over a long increment: the sub-step budget, naming dt,
    // the state untouched.
    let mut stiff = b;
    stiff.blocks = 256;
    stiff.coupling_stiffness = 1e9;
    let mut h = null_mut();
    assert_eq!(
        unsafe { asperity_friction_burridge_knopoff_new(&stiff, &mut h) },
        ASPERITY_OK
    );
    let mut s = vec![0.0; 2 + 2 * 256 + 1];
    s[2 + 2 * 100] = -1e-6;
    let before = s.clone();
    let inc = FrictionIncrement {
        normal_force: 256.0,
        slip: [0.1, 0.0],
        dt: 10.0,
        ..Default::default()
    };
    let mut out = FrictionResponse::default();
    expect_error(
        unsafe {
            asperity_friction_step(h, &inc, s.as_ptr(), s.as_mut_ptr(), null_mut(), &mut out)
        },
        ASPERITY_ERR_NOT_CONVERGED,
        "dt",
    );
    assert_eq!(s, before);
    unsafe { asperity_friction_free(h) };
}

/// The bristle model from C equals the Rust model bit for bit; a length
/// mismatch is impossible through C (one `n`), a bad value is named.
#[test]
fn bristles_from_c_equal_rust() {
    use asperity::friction::dynamic::Bristles;
    let (k, d) = ([1e5, 2e5, 5e4], [1e-6, 2.5e-6, 4e-6]);
    let mut h = null_mut();
    assert_eq!(
        unsafe { asperity_friction_bristles_new(k.as_ptr(), d.as_ptr(), 3, 0.1, &mut h) },
        ASPERITY_OK
    );
    let rust = Bristles::new(&k, &d, 0.1).unwrap();
    let incs = (0..200).map(|i| FrictionIncrement {
        normal_force: 1.0 + 0.01 * i as f64,
        slip: [1e-7 * ((i as f64) * 0.3).sin(), 0.0],
        dt: 1e-3,
        tangents: 3,
        ..Default::default()
    });
    assert_eq!(in_place_equals_rust(h, &rust, incs), 5);
    unsafe { asperity_friction_free(h) };
    let bad = [1e-6, -1.0, 4e-6];
    expect_error(
        unsafe { asperity_friction_bristles_new(k.as_ptr(), bad.as_ptr(), 3, 0.0, &mut h) },
        ASPERITY_ERR_INVALID_ARGUMENT,
        "break_deflection",
    );
    assert!(h.is_null());
    expect_error(
        unsafe { asperity_friction_bristles_new(k.as_ptr(), d.as_ptr(), 0, 0.0, &mut h) },
        ASPERITY_ERR_INVALID_ARGUMENT,
        "n",
    );
}

/// The C handle of the dynamic model of `case` (the fixtures of
/// `tests/common/laws.rs`, built through C).
fn c_model(case: &laws::Case) -> *mut AsperityFriction {
    let mut h = null_mut();
    let st = unsafe {
        match case.name {
            "lugre" => asperity_friction_lugre_new(&laws::lugre_params(), &mut h),
            "maxwell_slip" => asperity_friction_maxwell_slip_new(
                laws::MAXWELL_K.as_ptr(),
                laws::MAXWELL_MU.as_ptr(),
                3,
                0.1,
                &mut h,
            ),
            "generalized_maxwell_slip" => asperity_friction_generalized_maxwell_slip_new(
                laws::MAXWELL_K.as_ptr(),
                laws::GMS_ALPHA.as_ptr(),
                3,
                &laws::gms_params(),
                &mut h,
            ),
            "bristles" => asperity_friction_bristles_new(
                laws::BRISTLE_K.as_ptr(),
                laws::BRISTLE_BREAK.as_ptr(),
                3,
                0.1,
                &mut h,
            ),
            "prandtl_tomlinson" => asperity_friction_prandtl_tomlinson_new(
                2e-21, 3e-10, 1.0, 1e-12, 1e-6, 1e-9, &mut h,
            ),
            "prandtl_tomlinson_two_spring" => asperity_friction_prandtl_tomlinson_two_spring_new(
                &laws::two_spring_params(),
                &mut h,
            ),
            "burridge_knopoff" => {
                asperity_friction_burridge_knopoff_new(&laws::burridge_knopoff_params(6), &mut h)
            }
            other => panic!("no C constructor for {other}"),
        }
    };
    assert_eq!(st, ASPERITY_OK, "{}: {}", case.name, last_message());
    h
}

/// The contract of the one friction handle (issue 30 §1) for each of the
/// five models (Prandtl–Tomlinson with one and two springs): old == new,
/// NULL work, `asperity_friction_step_in_place`, the blocks separate, old
/// == new and in place, a partially overlapping block (`new_states`) and a
/// point count whose states overflow `size_t` (`n`), bit for bit against
/// the Rust model.
#[test]
fn the_friction_handle_keeps_the_contract_for_every_model() {
    let cases = laws::dynamic_cases();
    assert_eq!(cases.len(), 7);
    for case in &cases {
        let h = c_model(case);
        unsafe {
            laws::c_contract(h, case, 16);
            asperity_friction_free(h);
        }
    }
}

/// The generalised Maxwell-slip model from C: its errors name the array,
/// `n` or the parameter field, and leave the handle NULL; a flat Stribeck
/// curve steps like the Maxwell-slip handle with capacities αᵢ μ_s.
#[test]
fn generalized_maxwell_slip_from_c_names_its_errors() {
    let k = laws::MAXWELL_K;
    let a = laws::GMS_ALPHA;
    let p = laws::gms_params();
    let mut h = null_mut();
    expect_error(
        unsafe {
            asperity_friction_generalized_maxwell_slip_new(
                k.as_ptr(),
                a.as_ptr(),
                3,
                null(),
                &mut h,
            )
        },
        ASPERITY_ERR_NULL_POINTER,
        "params",
    );
    assert!(h.is_null());
    expect_error(
        unsafe {
            asperity_friction_generalized_maxwell_slip_new(k.as_ptr(), null(), 3, &p, &mut h)
        },
        ASPERITY_ERR_NULL_POINTER,
        "weight",
    );
    expect_error(
        unsafe {
            asperity_friction_generalized_maxwell_slip_new(k.as_ptr(), a.as_ptr(), 0, &p, &mut h)
        },
        ASPERITY_ERR_INVALID_ARGUMENT,
        "`n`",
    );
    for (field, spoil) in [
        (
            "params.attraction",
            AsperityGeneralizedMaxwellSlipParams {
                attraction: 0.0,
                ..p
            },
        ),
        (
            "params.mu_coulomb",
            AsperityGeneralizedMaxwellSlipParams {
                mu_coulomb: -1.0,
                ..p
            },
        ),
        (
            "params.stribeck_velocity",
            AsperityGeneralizedMaxwellSlipParams {
                stribeck_velocity: f64::NAN,
                ..p
            },
        ),
        (
            "params.sigma2",
            AsperityGeneralizedMaxwellSlipParams { sigma2: -1.0, ..p },
        ),
    ] {
        expect_error(
            unsafe {
                asperity_friction_generalized_maxwell_slip_new(
                    k.as_ptr(),
                    a.as_ptr(),
                    3,
                    &spoil,
                    &mut h,
                )
            },
            ASPERITY_ERR_INVALID_ARGUMENT,
            field,
        );
        assert!(h.is_null());
    }
    // Flat curve: the Maxwell-slip handle with μᵢ = αᵢ μ_s, step for step.
    let flat = AsperityGeneralizedMaxwellSlipParams {
        mu_coulomb: 0.5,
        mu_static: 0.5,
        ..p
    };
    let mu: Vec<f64> = a.iter().map(|x| x * 0.5).collect();
    let (mut g, mut m) = (null_mut(), null_mut());
    unsafe {
        assert_eq!(
            asperity_friction_generalized_maxwell_slip_new(
                k.as_ptr(),
                a.as_ptr(),
                3,
                &flat,
                &mut g
            ),
            ASPERITY_OK
        );
        assert_eq!(
            asperity_friction_maxwell_slip_new(k.as_ptr(), mu.as_ptr(), 3, p.sigma2, &mut m),
            ASPERITY_OK
        );
        let (mut n_g, mut n_m) = (0usize, 0usize);
        asperity_friction_state_size(g, &mut n_g);
        asperity_friction_state_size(m, &mut n_m);
        let (mut sg, mut sm) = (vec![0.0; n_g], vec![0.0; n_m]);
        for i in 0..300 {
            let inc = FrictionIncrement {
                normal_force: 2.0,
                slip: [3e-6 * ((i as f64) * 0.37).sin(), 0.0],
                dt: 1e-3,
                ..Default::default()
            };
            let (mut rg, mut rm) = (FrictionResponse::default(), FrictionResponse::default());
            assert_eq!(
                asperity_friction_step_in_place(g, &inc, sg.as_mut_ptr(), null_mut(), &mut rg),
                ASPERITY_OK
            );
            assert_eq!(
                asperity_friction_step_in_place(m, &inc, sm.as_mut_ptr(), null_mut(), &mut rm),
                ASPERITY_OK
            );
            assert!(
                (rg.force[0] - rm.force[0]).abs() <= 1e-12,
                "{i}: {} vs {}",
                rg.force[0],
                rm.force[0]
            );
        }
        asperity_friction_free(g);
        asperity_friction_free(m);
    }
}
