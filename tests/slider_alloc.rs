//! The slider's friction step allocates nothing once its work exists
//! (ARCHITECTURE.md: the hot path does not allocate): a counting global
//! allocator, in its own test binary, around `FrictionLaw::step`,
//! `step_in_place` (with tangents, zero slip, a fresh state seated inside
//! the call, an error) and `step_block` (both state forms), for the slider
//! as the friction law of a patch.

use asperity::friction::{BlockStates, FrictionBlock, FrictionIncrement, FrictionLaw};
use asperity::scene::Scene;
use std::path::Path;

mod common;

use common::counting::allocations;

#[global_allocator]
static GLOBAL: common::counting::Counting = common::counting::Counting;

#[test]
fn flat_step_does_not_allocate() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/chapter6_copper.json");
    let slider = Scene::from_file(path).unwrap().build().unwrap();
    let m = slider.state_len();
    let mut work = slider.work();
    let mut a = vec![0.0; m];
    let mut b = vec![0.0; m];
    let along = FrictionIncrement {
        normal_force: 0.18,
        slip: [1.5e-6, 0.0],
        dt: 1e-3,
        ..Default::default()
    };
    let oblique = FrictionIncrement {
        normal_force: 0.1,
        slip: [0.8e-6, -1.1e-6],
        dt: 1e-3,
        tangents: 3,
        ..Default::default()
    };
    let heavy = FrictionIncrement {
        normal_force: 0.3,
        tangents: 3,
        ..along
    };
    let still = FrictionIncrement {
        normal_force: 0.18,
        tangents: 3,
        ..Default::default()
    };
    // The first call with this work (a fresh state: seated inside).
    slider.step(&a, &mut b, &along, &mut work).unwrap();
    core::mem::swap(&mut a, &mut b);

    let before = allocations();
    for k in 0..40 {
        let inc = match k % 4 {
            0 => along,
            1 => oblique,
            2 => heavy,
            _ => still, // zero slip
        };
        let r = slider.step(&a, &mut b, &inc, &mut work).unwrap();
        assert!(r.dissipated >= 0.0);
        core::mem::swap(&mut a, &mut b);
        slider.step_in_place(&mut a, &along, &mut work).unwrap();
    }
    // A fresh state seated inside the call, and an error path.
    b.iter_mut().for_each(|x| *x = 0.0);
    slider.step_in_place(&mut b, &oblique, &mut work).unwrap();
    let bad = FrictionIncrement {
        slip: [f64::NAN, 0.0],
        ..along
    };
    assert!(slider.step(&a, &mut b, &bad, &mut work).is_err());
    let past_the_end = FrictionIncrement {
        slip: [1e-3, 0.0],
        ..along
    };
    assert!(slider.step(&a, &mut b, &past_the_end, &mut work).is_err());
    assert_eq!(allocations() - before, 0, "the slider's step allocated");

    // The block step.
    let n = 4;
    let normal = [0.02, 0.05, 0.1, 0.2];
    let slip = [1e-6, 0.0, 0.0, 1e-6, -1e-6, 0.5e-6, 0.7e-6, -0.7e-6];
    let mut states = vec![0.0; n * m];
    let mut new = vec![0.0; n * m];
    let mut force = [0.0; 8];
    let mut diss = [0.0; 4];
    let before = allocations();
    for _ in 0..10 {
        slider
            .step_block(
                FrictionBlock {
                    normal_force: &normal,
                    area: None,
                    slip: &slip,
                    dt: 1e-3,
                    tangents: 0,
                    states: BlockStates::InPlace(&mut states),
                    tangential_force: Some(&mut force),
                    dissipation: Some(&mut diss),
                    responses: None,
                },
                &mut work,
            )
            .unwrap();
        slider
            .step_block(
                FrictionBlock {
                    normal_force: &normal,
                    area: None,
                    slip: &slip,
                    dt: 1e-3,
                    tangents: 0,
                    states: BlockStates::Separate {
                        old: &states,
                        new: &mut new,
                    },
                    tangential_force: Some(&mut force),
                    dissipation: None,
                    responses: None,
                },
                &mut work,
            )
            .unwrap();
    }
    assert_eq!(
        allocations() - before,
        0,
        "the slider's step_block allocated"
    );
    assert!(force.iter().all(|f| f.is_finite()));
}
