//! Threads (issue 8 §3): every evaluation family called concurrently from 8
//! threads on one shared handle, each thread doing a distinct deterministic
//! slice of the inputs, compared bit for bit (`to_bits`) with the
//! single-threaded results. The same through the C ABI (the `extern "C"`
//! functions called from Rust threads on one shared handle), and the
//! thread-locality of `asperity_last_error_message`.
//!
//! The `Send + Sync` contract itself is asserted at compile time in the
//! library (`src/thread_safety.rs`); these tests check that sharing gives the
//! same numbers.

mod common;
use common::c_errors::last_message;

use asperity::contact::{
    eval_batch, ContactState, Control, Derjaguin, Dmt, FlatPunch, Hertz, Jkr, JkrPowerPunch,
    Kendall, LjSphere, MaugisDugdale, NormalContact, NormalLaw, NormalResponse, PowerPunch,
    SurfaceLaw, TabulatedLaw,
};
use asperity::ffi::contact::*;
use asperity::ffi::friction_law::*;
use asperity::ffi::homogenised::*;
use asperity::ffi::lj_sphere::asperity_lj_sphere_pull_off;
use asperity::ffi::slider::*;
use asperity::ffi::statistics::*;
use asperity::ffi::tabulated::*;
use asperity::ffi::*;
use asperity::friction::{
    BlockStates, FrictionBlock, FrictionIncrement, FrictionLaw, FrictionResponse,
    HomogenisedFriction, Slider,
};
use asperity::rescaling::{KnownSolution, Rescaling};
use asperity::scene::Scene;
use asperity::statistics::{GreenwoodWilliamson, HeightDistribution, KragelskyRods};
use std::path::Path;
use std::ptr::{null, null_mut};
use std::sync::Barrier;

const THREADS: usize = 8;

/// Run `item(i)` for `i in 0..n` on one thread, then on 8 threads at once
/// (thread t takes i ≡ t mod 8, all released together by a barrier), and
/// compare the bit patterns item by item.
fn same_on_threads<F>(what: &str, n: usize, item: F)
where
    F: Fn(usize) -> Vec<u64> + Sync,
{
    let serial: Vec<Vec<u64>> = (0..n).map(&item).collect();
    let barrier = Barrier::new(THREADS);
    let mut parallel: Vec<Option<Vec<u64>>> = vec![None; n];
    let slices: Vec<Vec<(usize, Vec<u64>)>> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..THREADS)
            .map(|t| {
                let (item, barrier) = (&item, &barrier);
                s.spawn(move || {
                    barrier.wait();
                    (t..n)
                        .step_by(THREADS)
                        .map(|i| (i, item(i)))
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        handles.into_iter().map(|h| h.join().unwrap()).collect()
    });
    for (i, v) in slices.into_iter().flatten() {
        assert!(parallel[i].is_none());
        parallel[i] = Some(v);
    }
    for (i, (a, b)) in serial.iter().zip(&parallel).enumerate() {
        let b = b
            .as_ref()
            .unwrap_or_else(|| panic!("{what}: item {i} not run"));
        assert_eq!(a, b, "{what}: item {i} differs between 1 and 8 threads");
        assert!(!a.is_empty(), "{what}: item {i} produced nothing");
    }
}

fn response_bits(r: &NormalResponse) -> [u64; 5] {
    [
        r.force.to_bits(),
        r.delta.to_bits(),
        r.contact_radius.to_bits(),
        r.stiffness.to_bits(),
        r.in_contact as u64,
    ]
}

fn state_bits(s: &ContactState) -> [u64; 4] {
    [
        s.contact_radius.to_bits(),
        s.cohesive_radius.to_bits(),
        s.in_contact as u64,
        s.branch as u64,
    ]
}

/// One law of each kind, with adhesion where the law has it.
fn laws() -> Vec<NormalLaw> {
    let (r, e, w) = (1e-6, 1e11, 0.5);
    vec![
        Hertz::new(r, e).unwrap().into(),
        PowerPunch::new(2e3, 1.5, e).unwrap().into(),
        FlatPunch::no_slip(r, e, 0.3).unwrap().into(),
        Dmt::new(r, e, w).unwrap().into(),
        Jkr::new(r, e, w).unwrap().into(),
        JkrPowerPunch::no_slip(2e3, 1.5, e, w, 0.3).unwrap().into(),
        Kendall::new(r, e, w).unwrap().into(),
        MaugisDugdale::new(r, e, w, 3e9).unwrap().into(),
        Derjaguin::new(
            r,
            SurfaceLaw::LennardJones {
                work_of_adhesion: w,
                equilibrium_separation: 3e-10,
            },
        )
        .unwrap()
        .into(),
    ]
}

#[test]
fn laws_cover_every_kind() {
    let names: Vec<&str> = laws().iter().map(NormalLaw::name).collect();
    for kind in NormalLaw::NAMES {
        assert!(
            names.contains(kind),
            "tests/threads.rs: laws() has no `{kind}` law"
        );
    }
}

/// The i-th overlap of a deterministic approach–retraction path over ±4
/// length scales (a cycle of 64 points), with a few repeats.
fn delta_at(law: &impl NormalContact, i: usize) -> f64 {
    let l = law.length_scale();
    let k = (i % 64) as f64;
    let x = if k < 32.0 {
        -4.0 + k / 4.0
    } else {
        4.0 - (k - 32.0) / 4.0
    };
    l * x * (1.0 + 1e-3 * (i / 64) as f64)
}

/// A path of `m` steps starting at item i: the overlaps, their responses
/// and states, the history carried from step to step.
fn law_path(law: &impl NormalContact, i: usize, m: usize) -> Vec<u64> {
    let mut out = vec![];
    let mut st = ContactState::default();
    for k in 0..m {
        let d = delta_at(law, i * 7 + k);
        match law.eval(d, &st) {
            Ok((r, s)) => {
                out.extend(response_bits(&r));
                out.extend(state_bits(&s));
                st = s;
            }
            Err(e) => out.push(format!("{e}").len() as u64),
        }
    }
    out
}

fn scene_slider() -> Slider {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/chapter6_copper.json");
    Scene::from_file(p).unwrap().build().unwrap()
}

// ---------------------------------------------------------------- Rust

#[test]
fn closed_form_laws_scalar_and_batch() {
    let laws = laws();
    for law in &laws {
        let what = format!("{law:?}");
        same_on_threads(&what, 64, |i| law_path(law, i, 24));
        // Batch: 40 contacts per item, each from the state of a first batch.
        same_on_threads(&what, 32, |i| {
            let n = 40;
            let d: Vec<f64> = (0..n).map(|k| delta_at(law, i * n + k)).collect();
            let mut s1 = vec![ContactState::default(); n];
            let mut f = vec![0.0; n];
            let (mut a, mut k) = (vec![0.0; n], vec![0.0; n]);
            // (The Derjaguin Lennard-Jones law refuses δ ≥ z₀: the error
            // index is part of the compared output.)
            let e1 = eval_batch(law, &d, None, Some(&mut s1), &mut f, None, None);
            let d2: Vec<f64> = d.iter().map(|x| -0.5 * x).collect();
            let mut s2 = vec![ContactState::default(); n];
            let e2 = eval_batch(
                law,
                &d2,
                Some(&s1),
                Some(&mut s2),
                &mut f,
                Some(&mut a),
                Some(&mut k),
            );
            let mut out: Vec<u64> = [f, a, k].concat().iter().map(|x| x.to_bits()).collect();
            out.extend([e1, e2].map(|e| e.map_or_else(|e| e.index as u64, |_| u64::MAX)));
            out.extend(s2.iter().flat_map(state_bits));
            out
        });
        // Load control and pull-off.
        same_on_threads(&what, 16, |i| {
            let p0 = law.pull_off_force(Control::Load).unwrap_or(0.0).min(-1e-12);
            let mut out = vec![];
            for k in 0..8 {
                let p = p0 * (1.0 - 0.3 * (i * 8 + k) as f64);
                match law.eval_at_load(p) {
                    Ok(r) => out.extend(response_bits(&r)),
                    Err(e) => out.push(format!("{e}").len() as u64),
                }
            }
            for c in [Control::Load, Control::Displacement] {
                out.push(law.pull_off_force(c).map_or(1, f64::to_bits));
            }
            out
        });
    }
}

#[test]
fn tabulated_lookups() {
    let md = MaugisDugdale::new(1e-6, 1e11, 0.5, 3e9).unwrap();
    let table = TabulatedLaw::from_maugis_dugdale(&md, 1e-4).unwrap();
    same_on_threads("table eval", 64, |i| law_path(&table, i, 32));
    same_on_threads("table batch + load", 32, |i| {
        let n = 50;
        let d: Vec<f64> = (0..n).map(|k| delta_at(&table, i * n + k)).collect();
        let mut f = vec![0.0; n];
        let mut s = vec![ContactState::default(); n];
        eval_batch(&table, &d, None, Some(&mut s), &mut f, None, None).unwrap();
        let mut out: Vec<u64> = f.iter().map(|x| x.to_bits()).collect();
        out.extend(s.iter().flat_map(state_bits));
        let p0 = table.pull_off_force(Control::Load).unwrap();
        for k in 0..4 {
            let r = table.eval_at_load(p0 * (0.9 - (i + k) as f64)).unwrap();
            out.extend(response_bits(&r));
        }
        out
    });
}

fn increment(i: usize, k: usize) -> FrictionIncrement {
    let t = (i * 31 + k) as f64;
    FrictionIncrement {
        normal_force: 20.0 + 15.0 * (0.7 * t).sin(),
        area: 1e-6,
        slip: [2e-7 * (0.3 * t).cos(), 1e-7 * (0.11 * t).sin()],
        dt: 1e-3,
        ..Default::default()
    }
}

/// The stick stiffness (N/m) of point `i`'s law: rigid–plastic for one
/// point in three.
fn stick_stiffness(i: usize) -> f64 {
    if i % 3 == 0 {
        0.0
    } else {
        1e8
    }
}

fn friction_bits(r: &FrictionResponse, s: &[f64]) -> Vec<u64> {
    let mut v: Vec<u64> = [
        r.force[0],
        r.force[1],
        r.force_magnitude,
        r.dissipated,
        r.stored_energy,
        r.dforce_dnormal[0],
        r.dforce_dslip[0][1],
    ]
    .iter()
    .chain(s)
    .map(|x| x.to_bits())
    .collect();
    v.push(r.regime as u64);
    v
}

#[test]
fn homogenised_friction_step_and_block() {
    let table: HomogenisedFriction = common::native::fe_strip_law();
    let laws = [0.0, 1e8].map(|k| table.clone().with_stick_stiffness(k).unwrap());
    let law = |i: usize| &laws[(stick_stiffness(i) > 0.0) as usize];
    let m = HomogenisedFriction::STATE_LEN;
    same_on_threads("homogenised step", 64, |i| {
        let law = law(i);
        let mut work = law.work();
        let mut st = vec![0.0; m];
        let mut s = vec![0.0; m];
        let mut out = vec![];
        for k in 0..50 {
            let r = law.step(&st, &mut s, &increment(i, k), &mut work).unwrap();
            out.extend(friction_bits(&r, &s));
            std::mem::swap(&mut st, &mut s);
        }
        out
    });
    let law = &laws[1];
    same_on_threads("homogenised block", 32, |i| {
        let n = 16;
        let mut work = law.work();
        let mut old = vec![0.0; n * m];
        let mut new = old.clone();
        let (mut f, mut d) = (vec![0.0; 2 * n], vec![0.0; n]);
        let mut out = vec![];
        for k in 0..10 {
            let incs: Vec<FrictionIncrement> = (0..n).map(|j| increment(i * n + j, k)).collect();
            let nf: Vec<f64> = incs.iter().map(|c| c.normal_force).collect();
            let ar: Vec<f64> = incs.iter().map(|c| c.area).collect();
            let sl: Vec<f64> = incs.iter().flat_map(|c| c.slip).collect();
            let block = FrictionBlock {
                normal_force: &nf,
                area: Some(&ar),
                slip: &sl,
                dt: 1e-3,
                tangents: 0,
                states: BlockStates::Separate {
                    old: &old,
                    new: &mut new,
                },
                tangential_force: Some(&mut f),
                dissipation: Some(&mut d),
                responses: None,
            };
            law.step_block(block, &mut work).unwrap();
            out.extend(f.iter().chain(&d).map(|x| x.to_bits()));
            std::mem::swap(&mut old, &mut new);
        }
        out
    });
}

fn slider_increment(i: usize, k: usize) -> FrictionIncrement {
    let th = 0.4 * (i + k) as f64;
    let slip = if k % 5 == 4 {
        [0.0, 0.0]
    } else {
        [1.2e-6 * th.cos(), 1.2e-6 * th.sin()]
    };
    FrictionIncrement {
        normal_force: 0.02 + 0.01 * ((i + 3 * k) % 7) as f64,
        slip,
        dt: 1e-3,
        ..Default::default()
    }
}

#[test]
fn slider_step_and_block() {
    let slider = scene_slider();
    let m = slider.state_len();
    same_on_threads("slider step", 16, |i| {
        let mut work = slider.work();
        let mut st = vec![0.0; m];
        st[Slider::STATE_POSITION] = 4e-6 * i as f64;
        let mut out = vec![];
        for k in 0..6 {
            let r = slider
                .step_in_place(&mut st, &slider_increment(i, k), &mut work)
                .unwrap();
            out.extend([r.force[0], r.force[1], r.dissipated, r.normal_force].map(f64::to_bits));
        }
        out.extend(st.iter().map(|x| x.to_bits()));
        out
    });
    same_on_threads("slider block", 8, |i| {
        let n = 3;
        let mut work = slider.work();
        let mut states = vec![0.0; n * m];
        for j in 0..n {
            states[j * m + Slider::STATE_POSITION] = 6e-6 * (i * n + j) as f64;
        }
        let (mut f, mut d) = (vec![0.0; 2 * n], vec![0.0; n]);
        let mut out = vec![];
        for k in 0..3 {
            let loads: Vec<f64> = (0..n)
                .map(|j| 0.02 + 0.01 * ((i + j + k) % 5) as f64)
                .collect();
            let slips: Vec<f64> = (0..n)
                .flat_map(|j| {
                    let th = 0.5 * (i * n + j + k) as f64;
                    [1.5e-6 * th.cos(), 1.5e-6 * th.sin()]
                })
                .collect();
            let block = FrictionBlock {
                normal_force: &loads,
                area: None,
                slip: &slips,
                dt: 1e-3,
                tangents: 0,
                states: BlockStates::InPlace(&mut states),
                tangential_force: Some(&mut f),
                dissipation: Some(&mut d),
                responses: None,
            };
            slider.step_block(block, &mut work).unwrap();
            out.extend(f.iter().chain(&d).map(|x| x.to_bits()));
        }
        out.extend(states.iter().map(|x| x.to_bits()));
        out
    });
}

#[test]
fn statistical_models_and_rescaling() {
    let gw = GreenwoodWilliamson::new(1e4, 1e-5, 1e11, HeightDistribution::gaussian(1e-6).unwrap())
        .unwrap();
    let gw_exp = GreenwoodWilliamson::new(
        1e4,
        1e-5,
        1e11,
        HeightDistribution::exponential(1e-6).unwrap(),
    )
    .unwrap();
    let heights: Vec<f64> = (0..200)
        .map(|k| 1e-6 * ((k as f64 * 0.37).sin() + 0.3 * (k as f64 * 1.7).cos()))
        .collect();
    let gw_emp = GreenwoodWilliamson::new(
        1e4,
        1e-5,
        1e11,
        HeightDistribution::empirical(heights).unwrap(),
    )
    .unwrap();
    let kr = KragelskyRods::new(1e4, 1e-10, 1e3, HeightDistribution::gaussian(1e-6).unwrap());
    for (name, m) in [
        ("GW gaussian", &gw),
        ("GW exponential", &gw_exp),
        ("GW empirical", &gw_emp),
    ] {
        same_on_threads(name, 64, |i| {
            let mut out = vec![];
            for k in 0..8 {
                let d = 1e-6 * (-1.0 + 0.03 * (i * 8 + k) as f64);
                let r = m.response(d).unwrap();
                out.extend([r.load, r.area, r.contacts, m.stiffness(d).unwrap()].map(f64::to_bits));
            }
            let load = 1e-3 * (1 + i) as f64;
            let s = m.separation_at_load(load).unwrap();
            out.push(s.separation.to_bits());
            out
        });
    }
    {
        let kr = kr.unwrap();
        same_on_threads("Kragelsky rods", 64, |i| {
            let d = 1e-6 * (-1.0 + 0.05 * i as f64);
            let r = kr.response(d).unwrap();
            vec![r.load.to_bits(), r.area.to_bits(), r.contacts.to_bits()]
        });
    }
    let resc = Rescaling::new(0.4, 1.7).unwrap();
    let known = KnownSolution::new(1e-3, 1e-7, 1e-5).unwrap();
    same_on_threads("rescaling", 64, |i| {
        let lam = 0.5 + 0.1 * i as f64;
        let p = 1e-3 * (1.0 + 0.2 * i as f64);
        [
            resc.depth(lam, p, &known).unwrap(),
            resc.radius(lam, p, &known).unwrap(),
            resc.load(lam, 1e-7 * lam, &known).unwrap(),
        ]
        .map(f64::to_bits)
        .to_vec()
    });
}

#[test]
fn lennard_jones_pull_off_at_small_n() {
    let spheres: Vec<LjSphere> = [0.5, 0.8, 1.0, 1.2]
        .iter()
        .map(|&mu| LjSphere::from_tabor(mu).unwrap())
        .collect();
    same_on_threads("LJ pull-off", 8, |i| {
        let sp = &spheres[i % spheres.len()];
        let n = 96 + 32 * (i / spheres.len());
        vec![sp.pull_off_force(n).unwrap().to_bits()]
    });
    // And a table built from it, shared.
    let table = TabulatedLaw::from_lj_sphere(&spheres[1], 96, 1e-3).unwrap();
    same_on_threads("LJ table", 32, |i| law_path(&table, i, 16));
}

// ---------------------------------------------------------------- C ABI

/// A C handle shared by reference between threads (the pointee is
/// `Sync`: asserted in the library).
struct Shared<T>(*const T);
unsafe impl<T: Sync> Sync for Shared<T> {}
unsafe impl<T: Sync> Send for Shared<T> {}
impl<T> Shared<T> {
    fn get(&self) -> *const T {
        self.0
    }
}

fn c_law(law: &NormalLaw) -> AsperityNormalLaw {
    AsperityNormalLaw::from(*law)
}

#[test]
fn c_abi_laws_tables_friction_on_shared_handles() {
    for law in laws() {
        let c = c_law(&law);
        let what = format!("C {law:?}");
        same_on_threads(&what, 64, |i| {
            let mut st = ContactState::default();
            let mut out = vec![];
            for k in 0..16 {
                let d = delta_at(&law, i * 7 + k);
                let mut r = NormalResponse::default();
                let mut s = ContactState::default();
                let status = unsafe { asperity_normal_eval(&c, d, &st, &mut s, &mut r) };
                out.push(status as u64);
                out.extend(response_bits(&r));
                // Same bits as the Rust API on this thread.
                if status == ASPERITY_OK {
                    let (rr, _) = law.eval(d, &st).unwrap();
                    assert_eq!(response_bits(&rr), response_bits(&r));
                }
                st = s;
            }
            let n = 24;
            let d: Vec<f64> = (0..n).map(|k| delta_at(&law, i * n + k)).collect();
            let (mut f, mut a, mut k) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
            let mut s = vec![ContactState::default(); n];
            let status = unsafe {
                asperity_normal_eval_batch(
                    &c,
                    n,
                    d.as_ptr(),
                    null(),
                    s.as_mut_ptr(),
                    f.as_mut_ptr(),
                    a.as_mut_ptr(),
                    k.as_mut_ptr(),
                )
            };
            out.push(status as u64);
            out.extend(f.iter().chain(&a).chain(&k).map(|x| x.to_bits()));
            let mut p = 0.0;
            let status = unsafe { asperity_pull_off_force(&c, ASPERITY_CONTROL_LOAD, &mut p) };
            out.extend([status as u64, p.to_bits()]);
            out
        });
    }

    // Tabulated Maugis–Dugdale table.
    let mut t = null_mut();
    assert_eq!(
        unsafe { asperity_table_new_maugis_dugdale(1e-6, 1e11, 0.5, 3e9, 1e-4, &mut t) },
        ASPERITY_OK
    );
    let table = Shared(t as *const AsperityTable);
    same_on_threads("C table", 64, |i| {
        let t = table.get();
        let mut st = ContactState::default();
        let mut out = vec![];
        for k in 0..16 {
            let d = 1e-9 * (-3.0 + 0.37 * ((i * 16 + k) % 29) as f64);
            let mut r = NormalResponse::default();
            let mut s = ContactState::default();
            let status = unsafe { asperity_table_eval(t, d, &st, &mut s, &mut r) };
            out.push(status as u64);
            out.extend(response_bits(&r));
            st = s;
        }
        let mut r = NormalResponse::default();
        let status = unsafe { asperity_table_eval_at_load(t, 1e-7 * i as f64, &mut r) };
        out.push(status as u64);
        out.extend(response_bits(&r));
        out
    });
    unsafe { asperity_table_free(t) };

    // Homogenised friction: two laws of one table (rigid–plastic and
    // k = 1e8 N/m), shared, stepped without a work.
    let samples = common::native::fe_strip_law().samples().to_vec();
    let mut h = null_mut();
    assert_eq!(
        unsafe { asperity_homogenised_friction_new(samples.as_ptr(), samples.len(), &mut h) },
        ASPERITY_OK
    );
    let laws = [0.0, 1e8].map(|k| {
        let mut law = null_mut();
        assert_eq!(
            unsafe { asperity_friction_from_homogenised(h, k, &mut law) },
            ASPERITY_OK
        );
        Shared(law as *const AsperityFriction)
    });
    unsafe { asperity_homogenised_friction_free(h) };
    let m = HomogenisedFriction::STATE_LEN;
    same_on_threads("C homogenised", 64, |i| {
        let law = &laws[(stick_stiffness(i) > 0.0) as usize];
        let mut st = vec![0.0; m];
        let mut out = vec![];
        for k in 0..30 {
            let mut s = vec![0.0; m];
            let mut r = FrictionResponse::default();
            let inc = increment(i, k);
            let status = unsafe {
                asperity_friction_step(
                    law.get(),
                    &inc,
                    st.as_ptr(),
                    s.as_mut_ptr(),
                    null_mut(),
                    &mut r,
                )
            };
            assert_eq!(status, ASPERITY_OK);
            out.extend(friction_bits(&r, &s));
            st = s;
        }
        out
    });
    for law in laws {
        unsafe { asperity_friction_free(law.get() as *mut AsperityFriction) };
    }

    // Statistics: an empirical GW handle.
    let heights: Vec<f64> = (0..100).map(|k| 1e-6 * (k as f64 * 0.61).sin()).collect();
    let mut g = null_mut();
    assert_eq!(
        unsafe {
            asperity_gw_empirical_new(
                1e4,
                1e-5,
                1e11,
                heights.len(),
                heights.as_ptr(),
                null(),
                &mut g,
            )
        },
        ASPERITY_OK
    );
    let gw = Shared(g as *const AsperityGwEmpirical);
    same_on_threads("C GW empirical", 64, |i| {
        let mut r = AsperityGwResponse::default();
        let status =
            unsafe { asperity_gw_empirical_eval(gw.get(), 1e-6 * (0.02 * i as f64 - 0.5), &mut r) };
        vec![
            status as u64,
            r.load.to_bits(),
            r.area.to_bits(),
            r.contacts.to_bits(),
            r.stiffness.to_bits(),
        ]
    });
    unsafe { asperity_gw_empirical_free(g) };

    // LJ pull-off, a stateless call.
    same_on_threads("C LJ pull-off", 8, |i| {
        let mut f = 0.0;
        let status = unsafe {
            asperity_lj_sphere_pull_off(1e-8, 1e10 * (1 + i % 4) as f64, 0.1, 3e-10, 96, &mut f)
        };
        assert_eq!(status, ASPERITY_OK, "{}", last_message());
        vec![status as u64, f.to_bits()]
    });
}

#[test]
fn c_abi_slider_shared_with_one_work_per_thread() {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/chapter6_copper.json"),
    )
    .unwrap();
    let mut s = null_mut();
    assert_eq!(
        unsafe {
            asperity_slider_from_scene_json(text.as_ptr().cast(), text.len(), null(), &mut s)
        },
        ASPERITY_OK
    );
    let mut law = null_mut();
    assert_eq!(
        unsafe { asperity_friction_from_slider(s, &mut law) },
        ASPERITY_OK
    );
    unsafe { asperity_slider_free(s) };
    let mut m = 0usize;
    assert_eq!(
        unsafe { asperity_friction_state_size(law, &mut m) },
        ASPERITY_OK
    );
    let slider = Shared(law as *const AsperityFriction);
    same_on_threads("C slider", 16, |i| {
        let mut work = null_mut();
        assert_eq!(
            unsafe { asperity_friction_work_new(slider.get(), &mut work) },
            ASPERITY_OK
        );
        let mut st = vec![0.0; m];
        st[Slider::STATE_POSITION] = 4e-6 * i as f64;
        let mut out = vec![];
        for k in 0..5 {
            let inc = slider_increment(i, k);
            let mut resp = FrictionResponse::default();
            let p = st.as_mut_ptr();
            let status =
                unsafe { asperity_friction_step(slider.get(), &inc, p, p, work, &mut resp) };
            assert_eq!(status, ASPERITY_OK);
            out.extend([resp.force[0], resp.force[1], resp.dissipated].map(f64::to_bits));
        }
        unsafe { asperity_friction_work_free(work) };
        out.extend(st.iter().map(|x| x.to_bits()));
        out
    });
    unsafe { asperity_friction_free(law) };
}

/// The last-error message is per thread: a failure on one thread does not
/// change another thread's message, and a thread that never failed reads an
/// empty message.
#[test]
fn last_error_message_is_thread_local() {
    let barrier = Barrier::new(THREADS);
    std::thread::scope(|s| {
        for t in 0..THREADS {
            let barrier = &barrier;
            s.spawn(move || {
                // Round 1: even threads fail on `radius`, odd ones stay clean.
                let mut law = c_law(&Hertz::new(1.0, 1.0).unwrap().into());
                if t % 2 == 0 {
                    let st = unsafe { asperity_law_hertz(-(t as f64) - 1.0, 1e9, &mut law) };
                    assert_ne!(st, ASPERITY_OK);
                }
                barrier.wait();
                let m = last_message();
                if t % 2 == 0 {
                    assert!(m.contains("`radius`"), "thread {t}: {m}");
                    assert!(
                        m.contains(&format!("{:e}", -(t as f64) - 1.0)),
                        "thread {t}: {m}"
                    );
                } else {
                    assert_eq!(m, "", "thread {t} never failed");
                }
                barrier.wait();
                // Round 2: odd threads fail on `e_star`; even ones succeed (a
                // success leaves the message unchanged).
                if t % 2 == 1 {
                    let st = unsafe { asperity_law_hertz(1.0, f64::NAN, &mut law) };
                    assert_ne!(st, ASPERITY_OK);
                } else {
                    let st = unsafe { asperity_law_hertz(1.0, 1e9, &mut law) };
                    assert_eq!(st, ASPERITY_OK);
                }
                barrier.wait();
                let m = last_message();
                if t % 2 == 1 {
                    assert!(m.contains("`e_star`"), "thread {t}: {m}");
                } else {
                    assert!(m.contains("`radius`"), "thread {t}: {m}");
                    assert!(!m.contains("e_star"), "thread {t}: {m}");
                }
                // Many failures interleaved with the other threads' ones.
                for k in 0..200 {
                    let bad = -((t * 1000 + k) as f64) - 1.0;
                    unsafe { asperity_law_jkr(1e-6, 1e9, bad, &mut law) };
                    let m = last_message();
                    assert!(
                        m.contains("`work_of_adhesion`") && m.contains(&format!("{bad:e}")),
                        "thread {t}: {m}"
                    );
                }
            });
        }
    });
}

#[test]
fn dynamic_friction_models_step_and_block() {
    use asperity::friction::dynamic::{
        Bristles, BurridgeKnopoff, DynamicModel, GeneralizedMaxwellSlip, LuGre, MaxwellSlip,
        PrandtlTomlinson,
    };
    let models = [
        DynamicModel::LuGre(LuGre::new(0.3, 0.5, 1e-3, 2.0, 1e5, 1000.0, 1e-3, 0.4).unwrap()),
        DynamicModel::MaxwellSlip(
            MaxwellSlip::new(&[2e5, 5e4, 1e4], &[0.2, 0.2, 0.1], 0.1).unwrap(),
        ),
        DynamicModel::PrandtlTomlinson(
            PrandtlTomlinson::new(2e-21, 3e-10, 1.0, 1e-12, 1e-6, 1e-9).unwrap(),
        ),
        DynamicModel::PrandtlTomlinson(
            PrandtlTomlinson::two_spring(2e-21, 3e-10, 2.0, 1e-12, 1e-6, 2.0, 1e-12, 1e-6, 1e-9)
                .unwrap(),
        ),
        DynamicModel::BurridgeKnopoff(
            BurridgeKnopoff::new(4, 1e-5, 1e4, 1e3, 0.5, 0.3, 0.05, 0.01, 1e-9).unwrap(),
        ),
        DynamicModel::Bristles(
            Bristles::new(&[1e5, 2e5, 5e4], &[1e-6, 2.5e-6, 4e-6], 0.1).unwrap(),
        ),
        DynamicModel::GeneralizedMaxwellSlip(
            GeneralizedMaxwellSlip::new(&[2e5, 5e4], &[0.5, 0.5], 0.3, 0.5, 1e-3, 2.0, 30.0, 0.1)
                .unwrap(),
        ),
    ];
    for model in &models {
        let track = matches!(
            model,
            DynamicModel::PrandtlTomlinson(_)
                | DynamicModel::BurridgeKnopoff(_)
                | DynamicModel::Bristles(_)
                | DynamicModel::GeneralizedMaxwellSlip(_)
        );
        let scale = match model {
            DynamicModel::PrandtlTomlinson(_) => 1e-11,
            DynamicModel::BurridgeKnopoff(_) => 1e-5,
            _ => 1e-6,
        };
        let inc = |i: usize, k: usize| {
            let t = (i * 31 + k) as f64;
            FrictionIncrement {
                normal_force: 1.0 + 0.5 * (0.3 * t).sin(),
                slip: [
                    scale * (0.7 * t).cos(),
                    if track { 0.0 } else { scale * (0.4 * t).sin() },
                ],
                dt: 1e-6,
                tangents: (k % 4) as i32,
                ..Default::default()
            }
        };
        same_on_threads("dynamic step", 32, |i| {
            let mut s = vec![0.0; model.state_len()];
            let mut work = model.work();
            let mut out = vec![];
            for k in 0..40 {
                let r = model.step_in_place(&mut s, &inc(i, k), &mut work).unwrap();
                out.extend(
                    [r.force[0], r.force[1], r.dissipated, r.dforce_dslip[0][0]]
                        .iter()
                        .chain(&s)
                        .map(|x| x.to_bits()),
                );
            }
            out
        });
        same_on_threads("dynamic block", 16, |i| {
            let n = 8;
            let m = model.state_len();
            let mut s = vec![0.0; n * m];
            let mut work = model.work();
            let (mut f, mut d) = (vec![0.0; 2 * n], vec![0.0; n]);
            let mut out = vec![];
            for k in 0..10 {
                let incs: Vec<FrictionIncrement> = (0..n).map(|j| inc(i * n + j, k)).collect();
                let nf: Vec<f64> = incs.iter().map(|c| c.normal_force).collect();
                let sl: Vec<f64> = incs.iter().flat_map(|c| c.slip).collect();
                let block = FrictionBlock {
                    normal_force: &nf,
                    area: None,
                    slip: &sl,
                    dt: 1e-6,
                    tangents: 0,
                    states: BlockStates::InPlace(&mut s),
                    tangential_force: Some(&mut f),
                    dissipation: Some(&mut d),
                    responses: None,
                };
                model.step_block(block, &mut work).unwrap();
                out.extend(f.iter().chain(&d).chain(&s).map(|x| x.to_bits()));
            }
            out
        });
    }
}
