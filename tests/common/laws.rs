//! One instance of every friction law of the one friction contract
//! ([`FrictionLaw`]: the homogenised law, the chapter-6 slider as a patch
//! law, the chapter-5 dynamic models), each with valid increments in its own
//! scales and increments it must refuse, and the checks every law passes
//! whatever it is (issue 30 §1):
//!
//! * [`check_forms`]: `step` (old and new separate), `step_in_place` and
//!   `step_block` (both [`BlockStates`] forms) give bit-identical forces,
//!   dissipations and states;
//! * [`check_accumulators`]: state[0] grows by exactly the increment's
//!   dissipation and state[1] by |Δs|;
//! * [`check_rejections`]: a refused increment or state leaves `new` (or
//!   the state stepped in place, or the block's points from the failing one
//!   on) untouched, the error naming the argument;
//! * [`check_block_responses`], [`check_block_rejections`]: the block with
//!   `responses` gives each point's response as `step` with the same
//!   tangent bits, and refuses bad tangent bits or a short `responses`
//!   slice before writing anything;
//! * [`c_contract`]: the same through the C handle `AsperityFriction`
//!   (old == new, NULL work, in place, the blocks, a partial overlap, a
//!   point count whose states overflow `size_t`), equal to the Rust law bit
//!   for bit; [`c_block_responses`]: `asperity_friction_step_block_responses`
//!   as `asperity_friction_step` point by point, its NULL and error cases.
//!
//! The laws are also made through C here ([`lugre_params`],
//! [`two_spring_params`], [`burridge_knopoff_params`], [`c_scene_slider`]),
//! with the same parameters as their Rust instances; [`slider_record`] is
//! the record `asperity_slider_record` should give for a slider's work.
//!
//! Included with `#[path = "common/laws.rs"] mod laws;` by the friction
//! tests that use it, so the other test binaries do not compile it.

#![allow(dead_code)]

use asperity::ffi::dynamic::{
    AsperityBurridgeKnopoffParams, AsperityGeneralizedMaxwellSlipParams, AsperityLugreParams,
    AsperityPrandtlTomlinsonTwoSpringParams,
};
use asperity::ffi::friction_law::*;
use asperity::ffi::slider::{
    asperity_slider_free, asperity_slider_from_scene_json, AsperitySlider, AsperitySliderRecord,
};
use asperity::ffi::{asperity_last_error_message, ASPERITY_OK};
use asperity::friction::dynamic::{
    Bristles, BurridgeKnopoff, GeneralizedMaxwellSlip, LuGre, MaxwellSlip, PrandtlTomlinson,
};
use asperity::friction::{
    BlockStates, CofForm, Dissipation, FrictionBlock, FrictionIncrement, FrictionLaw,
    FrictionResponse, FrictionWork, HomogenisedFriction, HomogenisedSample, Slider, SliderWork,
};
use asperity::scene::Scene;
use asperity::Error;
use std::path::{Path, PathBuf};
use std::ptr::{null, null_mut};

// ------------------------------------------------------------ helpers

/// The bits of every value (NaN payloads and −0.0 count).
pub fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

/// Two responses equal bit for bit (through the debug text of every
/// field, so −0.0 and NaN count).
pub fn same(a: &FrictionResponse, b: &FrictionResponse) -> bool {
    format!("{a:?}") == format!("{b:?}")
}

/// A NaN with a payload no computation produces: marks untouched doubles.
pub const SENTINEL: u64 = 0x7ff8_dead_beef_0001;

/// `n` sentinels.
pub fn sentinels(n: usize) -> Vec<f64> {
    vec![f64::from_bits(SENTINEL); n]
}

/// The argument an error names.
pub fn arg_name(e: &Error) -> &'static str {
    match *e {
        Error::InvalidArgument { name, .. }
        | Error::OutOfDomain { name, .. }
        | Error::UnknownSelector { name, .. }
        | Error::NullPointer { name } => name,
        Error::NotConverged { what, .. } => what,
        ref other => panic!("an error without an argument name: {other:?}"),
    }
}

/// splitmix64.
pub struct Rng(pub u64);

impl Rng {
    pub fn u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1).
    pub fn f(&mut self) -> f64 {
        (self.u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

// ------------------------------------------------------------- the laws

/// Copper-like homogenised table: μ from 1.10 at 10 MPa down to 0.90 at
/// 200 MPa, adhesion about 9 % of the load, chemical bonds dominant.
pub fn homogenised_samples() -> Vec<HomogenisedSample> {
    [
        (10.0, 1.10, 0.90, 0.010, 0.930, 0.067, 0.002),
        (50.0, 1.02, 4.50, 0.050, 0.925, 0.066, 0.006),
        (100.0, 0.97, 9.00, 0.100, 0.920, 0.064, 0.010),
        (150.0, 0.93, 13.5, 0.150, 0.910, 0.062, 0.018),
        (200.0, 0.90, 18.0, 0.200, 0.900, 0.060, 0.025),
    ]
    .iter()
    .map(|&(p, mu, pa, fr, c, v, e)| HomogenisedSample {
        pressure: p * 1e6,
        cof: mu,
        adhesion_pressure: pa * 1e6,
        contact_fraction: fr,
        shares: Dissipation {
            chemical: c,
            van_der_waals: v,
            elastic: e,
            plastic: 1.0 - c - v - e,
        },
    })
    .collect()
}

/// The homogenised law of [`homogenised_samples`] (Derjaguin form) with
/// the stick stiffness `k` (N/m).
pub fn homogenised(k: f64) -> HomogenisedFriction {
    HomogenisedFriction::from_samples(&homogenised_samples(), CofForm::Derjaguin)
        .unwrap()
        .with_stick_stiffness(k)
        .unwrap()
}

/// The chapter-6 copper scene (examples/scenes/chapter6_copper.json).
pub fn scene_path() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/chapter6_copper.json")
}

/// The chapter-6 copper scene's slider (90 rods of 1.5 µm, 10
/// nano-asperities per rod, fixed load 0.18 N).
pub fn scene_slider() -> Slider {
    Scene::from_file(scene_path()).unwrap().build().unwrap()
}

/// A slider made through C, its friction law and a work for the law,
/// freed on drop.
pub struct CSlider {
    pub slider: *mut AsperitySlider,
    pub law: *mut AsperityFriction,
    pub work: *mut AsperityFrictionWork,
}

impl Drop for CSlider {
    fn drop(&mut self) {
        // SAFETY: made by the constructors, freed once.
        unsafe {
            asperity_friction_work_free(self.work);
            asperity_friction_free(self.law);
            asperity_slider_free(self.slider);
        }
    }
}

/// The friction law of the C slider `slider`
/// (`asperity_friction_from_slider`) and a work for it.
pub fn c_slider_law(
    slider: *const AsperitySlider,
) -> (*mut AsperityFriction, *mut AsperityFrictionWork) {
    let mut law = null_mut();
    // SAFETY: `slider` is live; valid out-pointers.
    c_ok(
        unsafe { asperity_friction_from_slider(slider, &mut law) },
        "slider law",
    );
    assert!(!law.is_null());
    let mut work = null_mut();
    c_ok(
        unsafe { asperity_friction_work_new(law, &mut work) },
        "slider work",
    );
    (law, work)
}

/// [`scene_slider`] made through C (`asperity_slider_from_scene_json`, no
/// base directory), with its law and a work.
pub fn c_scene_slider() -> CSlider {
    let text = std::fs::read_to_string(scene_path()).unwrap();
    let mut slider = null_mut();
    // SAFETY: the text and its length; a valid out-pointer.
    let st = unsafe {
        asperity_slider_from_scene_json(text.as_ptr().cast(), text.len(), null(), &mut slider)
    };
    c_ok(st, "slider from the scene");
    assert!(!slider.is_null());
    let (law, work) = c_slider_law(slider);
    CSlider { slider, law, work }
}

/// The record of a slider's Rust work (`SliderWork::record()`, whether
/// the step seated a fresh state), as `asperity_slider_record` should give
/// it.
pub fn slider_record(work: &FrictionWork) -> AsperitySliderRecord {
    let w = work.get::<SliderWork>().expect("a slider's work");
    let r = w.record();
    AsperitySliderRecord {
        position: r.position,
        rod_position: r.rod_position,
        adhesion_area_share: r.adhesion_area_share,
        nano_contacts: r.nano_contacts as u64,
        adhesive_contacts: r.adhesive_contacts as u64,
        rods_in_contact: r.rods_in_contact as u64,
        yielded_rods: r.yielded_rods as u64,
        seated: w.seated() as i32,
        reserved: 0,
    }
}

/// LuGre: μ_c = 0.3, μ_s = 0.5, v_s = 1 mm/s, σ₀ = 1e5 /m, σ₁ = 1000 s/m,
/// v_d = 1 mm/s, σ₂ = 0.4 s/m.
pub fn lugre() -> LuGre {
    LuGre::new(0.3, 0.5, 1e-3, 2.0, 1e5, 1000.0, 1e-3, 0.4).unwrap()
}

/// [`lugre`] for `asperity_friction_lugre_new`.
pub fn lugre_params() -> AsperityLugreParams {
    AsperityLugreParams {
        mu_coulomb: 0.3,
        mu_static: 0.5,
        stribeck_velocity: 1e-3,
        stribeck_exponent: 2.0,
        sigma0: 1e5,
        sigma1: 1000.0,
        damping_velocity: 1e-3,
        sigma2: 0.4,
    }
}

/// Three Maxwell-slip elements.
pub const MAXWELL_K: [f64; 3] = [2e5, 5e4, 1e4];
/// Their break-away coefficients.
pub const MAXWELL_MU: [f64; 3] = [0.2, 0.2, 0.1];

pub fn maxwell_slip() -> MaxwellSlip {
    MaxwellSlip::new(&MAXWELL_K, &MAXWELL_MU, 0.1).unwrap()
}

/// The generalised Maxwell-slip model on the elements of [`maxwell_slip`]
/// (weights αᵢ = μᵢ/Σμ), μ_c = 0.3, μ_s = 0.5, v_s = 1 mm/s, C = 40/s,
/// σ₂ = 0.1 N·s/m.
pub const GMS_ALPHA: [f64; 3] = [0.4, 0.4, 0.2];

pub fn generalized_maxwell_slip() -> GeneralizedMaxwellSlip {
    let p = gms_params();
    GeneralizedMaxwellSlip::new(
        &MAXWELL_K,
        &GMS_ALPHA,
        p.mu_coulomb,
        p.mu_static,
        p.stribeck_velocity,
        p.stribeck_exponent,
        p.attraction,
        p.sigma2,
    )
    .unwrap()
}

/// [`generalized_maxwell_slip`] for
/// `asperity_friction_generalized_maxwell_slip_new`.
pub fn gms_params() -> AsperityGeneralizedMaxwellSlipParams {
    AsperityGeneralizedMaxwellSlipParams {
        mu_coulomb: 0.3,
        mu_static: 0.5,
        stribeck_velocity: 1e-3,
        stribeck_exponent: 2.0,
        attraction: 40.0,
        sigma2: 0.1,
    }
}

/// Three bristles.
pub const BRISTLE_K: [f64; 3] = [1e5, 2e5, 5e4];
/// Their break deflections (m).
pub const BRISTLE_BREAK: [f64; 3] = [1e-6, 2.5e-6, 4e-6];

pub fn bristles() -> Bristles {
    Bristles::new(&BRISTLE_K, &BRISTLE_BREAK, 0.1).unwrap()
}

/// An AFM tip: U₀ = 2e-21 J, a = 0.3 nm, k = 1 N/m, m = 1e-12 kg,
/// γ = 1e-6 kg/s.
pub fn prandtl_tomlinson() -> PrandtlTomlinson {
    PrandtlTomlinson::new(2e-21, 3e-10, 1.0, 1e-12, 1e-6, 1e-9).unwrap()
}

/// The tip of [`prandtl_tomlinson`] on a cantilever (two springs).
pub fn two_spring() -> PrandtlTomlinson {
    PrandtlTomlinson::two_spring(2e-21, 3e-10, 2.0, 1e-12, 1e-6, 3.0, 2e-12, 2e-6, 1e-9).unwrap()
}

/// [`two_spring`] for `asperity_friction_prandtl_tomlinson_two_spring_new`.
pub fn two_spring_params() -> AsperityPrandtlTomlinsonTwoSpringParams {
    AsperityPrandtlTomlinsonTwoSpringParams {
        amplitude: 2e-21,
        period: 3e-10,
        tip_stiffness: 2.0,
        tip_mass: 1e-12,
        tip_damping: 1e-6,
        cantilever_stiffness: 3.0,
        cantilever_mass: 2e-12,
        cantilever_damping: 2e-6,
        tolerance: 1e-9,
    }
}

/// Six blocks.
pub fn burridge_knopoff() -> BurridgeKnopoff {
    BurridgeKnopoff::new(6, 1e-5, 1e4, 1e3, 0.5, 0.3, 0.05, 0.01, 1e-9).unwrap()
}

/// The chain of [`burridge_knopoff`] with `blocks` blocks, for
/// `asperity_friction_burridge_knopoff_new`.
pub fn burridge_knopoff_params(blocks: usize) -> AsperityBurridgeKnopoffParams {
    AsperityBurridgeKnopoffParams {
        blocks,
        mass: 1e-5,
        coupling_stiffness: 1e4,
        pulling_stiffness: 1e3,
        mu_static: 0.5,
        mu_kinetic: 0.3,
        weakening_velocity: 0.05,
        damping: 0.01,
        tolerance: 1e-9,
    }
}

/// A law with the increments it is stepped along (one Δt for all, so a
/// block can take them) and those it must refuse, with the argument the
/// error names.
pub struct Case {
    pub name: &'static str,
    pub law: Box<dyn FrictionLaw>,
    pub incs: Vec<FrictionIncrement>,
    pub bad: Vec<(FrictionIncrement, &'static str)>,
}

/// `n` increments of `make(k, rng)` (tangents asked as k % 4).
fn along(
    n: usize,
    seed: u64,
    mut make: impl FnMut(usize, &mut Rng) -> FrictionIncrement,
) -> Vec<FrictionIncrement> {
    let mut rng = Rng(seed);
    (0..n)
        .map(|k| FrictionIncrement {
            tangents: (k % 4) as i32,
            ..make(k, &mut rng)
        })
        .collect()
}

/// A slip of size `size` in a direction that turns, reverses and is zero
/// one time in eight.
fn slip2(k: usize, rng: &mut Rng, size: f64) -> [f64; 2] {
    if k % 8 == 7 {
        return [0.0, 0.0];
    }
    let th = if k % 5 == 3 {
        std::f64::consts::PI
    } else {
        6.0 * rng.f()
    };
    let s = size * (0.2 + rng.f());
    [s * th.cos(), s * th.sin()]
}

/// A slip along the track (one-dimensional models): forward mostly,
/// backwards and zero now and then.
fn slip1(k: usize, rng: &mut Rng, size: f64) -> [f64; 2] {
    let s = size * (0.2 + rng.f());
    match k % 7 {
        3 => [-s, 0.0],
        6 => [0.0, 0.0],
        _ => [s, 0.0],
    }
}

/// The increment `inc` with one field spoiled.
fn spoil(inc: FrictionIncrement, f: impl FnOnce(&mut FrictionIncrement)) -> FrictionIncrement {
    let mut i = inc;
    f(&mut i);
    i
}

/// The increments every law refuses: N not finite or negative, Δs not
/// finite, Δt negative or NaN, unknown tangent bits.
fn common_bad(valid: FrictionIncrement) -> Vec<(FrictionIncrement, &'static str)> {
    vec![
        (spoil(valid, |i| i.normal_force = f64::NAN), "normal_force"),
        (spoil(valid, |i| i.normal_force = -1.0), "normal_force"),
        (spoil(valid, |i| i.area = -1.0), "area"),
        (spoil(valid, |i| i.slip[1] = f64::INFINITY), "slip"),
        (spoil(valid, |i| i.dt = -1.0), "dt"),
        (spoil(valid, |i| i.dt = f64::NAN), "dt"),
        (spoil(valid, |i| i.tangents = 4), "tangents"),
    ]
}

/// The homogenised law (k = 1e8 N/m) at 5–250 N on 1 mm², 2-D slips of
/// about 0.5 µm (stick, slip, reversals), one point in ten unloaded.
pub fn homogenised_case() -> Case {
    let incs = along(24, 0x40, |k, rng| FrictionIncrement {
        normal_force: if k % 10 == 9 {
            0.0
        } else {
            5.0 + 245.0 * rng.f()
        },
        area: 1e-6,
        slip: slip2(k, rng, 5e-7),
        dt: 1e-6,
        ..Default::default()
    });
    let v = incs[0];
    let mut bad = common_bad(v);
    bad.push((spoil(v, |i| i.area = 0.0), "area"));
    bad.push((spoil(v, |i| i.slip = [1e300, 1e300]), "slip"));
    Case {
        name: "homogenised",
        law: Box::new(homogenised(1e8)),
        incs,
        bad,
    }
}

/// The chapter-6 slider as a patch law at 1–30 % of its capacity, 2-D
/// slips of about 1 µm (zero one time in eight).
pub fn slider_case() -> Case {
    let slider = scene_slider();
    let cap = slider.capacity();
    let incs = along(16, 0x51, |k, rng| FrictionIncrement {
        normal_force: cap * (0.01 + 0.29 * rng.f()),
        area: 0.0,
        slip: slip2(k, rng, 1e-6),
        dt: 1e-3,
        ..Default::default()
    });
    let v = incs[0];
    let mut bad = common_bad(v);
    bad.push((spoil(v, |i| i.normal_force = 1.01 * cap), "normal_force"));
    // Past the end of the counter-surface profile.
    bad.push((spoil(v, |i| i.slip = [1e-3, 0.0]), "position"));
    Case {
        name: "slider",
        law: Box::new(slider),
        incs,
        bad,
    }
}

/// The chapter-5 models: LuGre and Maxwell-slip with 2-D slips of a few
/// µm, bristles on a track, Prandtl–Tomlinson (one and two springs) in
/// lattice-scale increments, a Burridge–Knopoff chain of six blocks.
pub fn dynamic_cases() -> Vec<Case> {
    let lugre_incs = along(24, 0x11, |k, rng| FrictionIncrement {
        normal_force: 1.0 + 2.0 * rng.f(),
        slip: slip2(k, rng, 2e-6),
        dt: 1e-3,
        ..Default::default()
    });
    let maxwell_incs = along(24, 0x12, |k, rng| FrictionIncrement {
        normal_force: 1.0 + 2.0 * rng.f(),
        slip: slip2(k, rng, 4e-6),
        dt: 1e-3,
        ..Default::default()
    });
    let bristle_incs = along(24, 0x13, |k, rng| FrictionIncrement {
        normal_force: 1.0 + rng.f(),
        slip: slip1(k, rng, 1.5e-6),
        dt: 1e-3,
        ..Default::default()
    });
    let gms_incs = along(24, 0x17, |k, rng| FrictionIncrement {
        normal_force: 1.0 + 2.0 * rng.f(),
        slip: slip1(k, rng, 4e-6),
        dt: 1e-3,
        ..Default::default()
    });
    let pt_incs = |seed| {
        along(16, seed, |k, rng| FrictionIncrement {
            normal_force: 1.0,
            slip: slip1(k, rng, 1e-11),
            dt: 1e-6,
            ..Default::default()
        })
    };
    let bk_incs = along(16, 0x16, |k, rng| FrictionIncrement {
        normal_force: 6.0,
        slip: slip1(k, rng, 2e-5),
        dt: 1e-6,
        ..Default::default()
    });
    // Rate-dependent laws refuse a slip without time; one-dimensional ones
    // a slip across the track.
    let rate = |v: FrictionIncrement| (spoil(v, |i| i.dt = 0.0), "dt");
    let track = |v: FrictionIncrement| (spoil(v, |i| i.slip[1] = 1e-9), "slip");
    let with = |mut bad: Vec<_>, extra: Vec<(FrictionIncrement, &'static str)>| {
        bad.extend(extra);
        bad
    };
    let pt = pt_incs(0x14);
    let pt2 = pt_incs(0x15);
    vec![
        Case {
            name: "lugre",
            law: Box::new(lugre()),
            bad: with(common_bad(lugre_incs[0]), vec![rate(lugre_incs[0])]),
            incs: lugre_incs,
        },
        Case {
            name: "maxwell_slip",
            law: Box::new(maxwell_slip()),
            bad: common_bad(maxwell_incs[0]),
            incs: maxwell_incs,
        },
        Case {
            name: "generalized_maxwell_slip",
            law: Box::new(generalized_maxwell_slip()),
            bad: with(
                common_bad(gms_incs[0]),
                vec![rate(gms_incs[0]), track(gms_incs[0])],
            ),
            incs: gms_incs,
        },
        Case {
            name: "bristles",
            law: Box::new(bristles()),
            bad: with(common_bad(bristle_incs[0]), vec![track(bristle_incs[0])]),
            incs: bristle_incs,
        },
        Case {
            name: "prandtl_tomlinson",
            law: Box::new(prandtl_tomlinson()),
            bad: with(common_bad(pt[0]), vec![rate(pt[0]), track(pt[0])]),
            incs: pt,
        },
        Case {
            name: "prandtl_tomlinson_two_spring",
            law: Box::new(two_spring()),
            bad: with(common_bad(pt2[0]), vec![rate(pt2[0]), track(pt2[0])]),
            incs: pt2,
        },
        Case {
            name: "burridge_knopoff",
            law: Box::new(burridge_knopoff()),
            bad: with(
                common_bad(bk_incs[0]),
                vec![rate(bk_incs[0]), track(bk_incs[0])],
            ),
            incs: bk_incs,
        },
    ]
}

/// Every law: the homogenised law, the slider, the dynamic models.
pub fn all_cases() -> Vec<Case> {
    let mut v = vec![homogenised_case(), slider_case()];
    v.extend(dynamic_cases());
    v
}

// ------------------------------------------------------------ checks

/// Points of the blocks of the checks.
pub const POINTS: usize = 3;

/// The increment of point `i` in round `k` (tangents as given, or none for
/// the block comparisons).
pub fn point_inc(case: &Case, k: usize, i: usize) -> FrictionIncrement {
    case.incs[(k + 5 * i) % case.incs.len()]
}

/// The arrays of a block and its one Δt.
pub struct BlockInputs {
    /// Normal forces, one a point.
    pub nf: Vec<f64>,
    /// Areas, one a point.
    pub area: Vec<f64>,
    /// Slips, x and y a point.
    pub slip: Vec<f64>,
    pub dt: f64,
}

impl BlockInputs {
    /// The arrays of `incs` (one a point) at `dt`.
    pub fn of(incs: &[FrictionIncrement], dt: f64) -> Self {
        Self {
            nf: incs.iter().map(|i| i.normal_force).collect(),
            area: incs.iter().map(|i| i.area).collect(),
            slip: incs.iter().flat_map(|i| i.slip).collect(),
            dt,
        }
    }

    /// The Rust block of these arrays (every area given) over `states`,
    /// the forces into `f` and the dissipations into `d` when given.
    pub fn block<'a>(
        &'a self,
        states: BlockStates<'a>,
        f: Option<&'a mut [f64]>,
        d: Option<&'a mut [f64]>,
    ) -> FrictionBlock<'a> {
        FrictionBlock {
            normal_force: &self.nf,
            area: Some(&self.area),
            slip: &self.slip,
            dt: self.dt,
            tangents: 0,
            states,
            tangential_force: f,
            dissipation: d,
            responses: None,
        }
    }
}

/// The block arrays of round `k` (at the Δt of the case's increments).
pub fn block_inputs(case: &Case, k: usize, points: usize) -> BlockInputs {
    let incs: Vec<_> = (0..points).map(|i| point_inc(case, k, i)).collect();
    BlockInputs::of(&incs, case.incs[0].dt)
}

/// The path a law books for the slip `s`: |Δs| rounded once, as
/// √(x² + y²) or as `hypot` (the laws use either; on a track both are
/// |x| exactly).
fn paths(s: [f64; 2]) -> [f64; 2] {
    [(s[0] * s[0] + s[1] * s[1]).sqrt(), s[0].hypot(s[1])]
}

/// state[0] grew by exactly ΔD and state[1] by exactly |Δs| (one addition
/// each) from `old` to `new`.
#[track_caller]
pub fn check_accumulators(
    what: &str,
    old: &[f64],
    new: &[f64],
    inc: &FrictionIncrement,
    r: &FrictionResponse,
) {
    assert!(r.dissipated >= 0.0, "{what}: ΔD = {} < 0", r.dissipated);
    assert_eq!(
        new[0].to_bits(),
        (old[0] + r.dissipated).to_bits(),
        "{what}: the dissipation accumulator grew by {:e}, the step dissipated {:e}",
        new[0] - old[0],
        r.dissipated
    );
    assert!(
        paths(inc.slip)
            .iter()
            .any(|p| new[1].to_bits() == (old[1] + p).to_bits()),
        "{what}: the slip path grew by {:e}, |Δs| = {:e}",
        new[1] - old[1],
        paths(inc.slip)[0]
    );
}

/// `step` (separate), `step_in_place` and `step_block` (separate and in
/// place) along `rounds` rounds of [`POINTS`] points: bit-identical
/// responses (scalar forms, with the tangents asked), forces, dissipations
/// and states (all four), and the accumulators of every scalar step.
pub fn check_forms(case: &Case, rounds: usize) {
    let law = &*case.law;
    let m = law.state_len();
    let p = POINTS;
    let mut w = law.work();
    let mut sep = vec![0.0; p * m];
    let mut inp = vec![0.0; p * m];
    let mut bsep = vec![0.0; p * m];
    let mut bnext = sentinels(p * m);
    let mut binp = vec![0.0; p * m];
    let name = case.name;
    for k in 0..rounds {
        // Scalar, with the tangents the increment asks: separate and in
        // place agree, response and state.
        let mut f = vec![0.0; 2 * p];
        let mut d = vec![0.0; p];
        for i in 0..p {
            let asked = point_inc(case, k, i);
            let r = i * m..(i + 1) * m;
            let mut na = sentinels(m);
            let ra = law.step(&sep[r.clone()], &mut na, &asked, &mut w).unwrap();
            let mut again = inp[r.clone()].to_vec();
            let rb = law.step_in_place(&mut again, &asked, &mut w).unwrap();
            assert!(
                same(&ra, &rb),
                "{name} round {k} point {i}:\n{ra:?}\n{rb:?}"
            );
            assert_eq!(bits(&na), bits(&again), "{name} round {k} point {i}");
            check_accumulators(name, &sep[r.clone()], &na, &asked, &ra);
            // The block asks for no tangents: step as it does. Asking for
            // tangents does not change the step itself.
            let plain = FrictionIncrement {
                tangents: 0,
                ..asked
            };
            let mut new = sentinels(m);
            let a = law.step(&sep[r.clone()], &mut new, &plain, &mut w).unwrap();
            let b = law
                .step_in_place(&mut inp[r.clone()], &plain, &mut w)
                .unwrap();
            assert!(same(&a, &b), "{name} round {k} point {i}:\n{a:?}\n{b:?}");
            assert_eq!(
                bits(&new),
                bits(&inp[r.clone()]),
                "{name} round {k} point {i}"
            );
            assert_eq!(
                (bits(&ra.force), ra.dissipated.to_bits(), bits(&na)),
                (bits(&a.force), a.dissipated.to_bits(), bits(&new)),
                "{name} round {k} point {i}: the tangents asked changed the step"
            );
            check_accumulators(name, &sep[r.clone()], &new, &plain, &a);
            sep[r].copy_from_slice(&new);
            f[2 * i..2 * i + 2].copy_from_slice(&a.force);
            d[i] = a.dissipated;
        }
        assert_eq!(bits(&sep), bits(&inp), "{name} round {k}");
        // The block, both forms.
        let b = block_inputs(case, k, p);
        let (mut f1, mut d1) = (sentinels(2 * p), sentinels(p));
        let separate = BlockStates::Separate {
            old: &bsep,
            new: &mut bnext,
        };
        law.step_block(b.block(separate, Some(&mut f1), Some(&mut d1)), &mut w)
            .unwrap();
        std::mem::swap(&mut bsep, &mut bnext);
        let (mut f2, mut d2) = (sentinels(2 * p), sentinels(p));
        let in_place = BlockStates::InPlace(&mut binp);
        law.step_block(b.block(in_place, Some(&mut f2), Some(&mut d2)), &mut w)
            .unwrap();
        for (what, ff, dd, ss) in [
            ("separate block", &f1, &d1, &bsep),
            ("in-place block", &f2, &d2, &binp),
        ] {
            assert_eq!(bits(ff), bits(&f), "{name} {what} forces, round {k}");
            assert_eq!(bits(dd), bits(&d), "{name} {what} dissipation, round {k}");
            assert_eq!(bits(ss), bits(&sep), "{name} {what} states, round {k}");
        }
    }
    // The states were stepped: something was dissipated and slid.
    assert!(sep.chunks(m).all(|s| s[1] > 0.0), "{name}: no slip booked");
}

/// A response whose every field is a sentinel: shows what a call wrote.
pub fn sentinel_response() -> FrictionResponse {
    let x = f64::from_bits(SENTINEL);
    FrictionResponse {
        force: [x; 2],
        force_magnitude: x,
        normal_force: x,
        cof: x,
        adhesion: x,
        true_contact_area: x,
        dissipated: x,
        dissipation: Dissipation {
            chemical: x,
            van_der_waals: x,
            elastic: x,
            plastic: x,
        },
        stored_energy: x,
        dforce_dnormal: [x; 2],
        dforce_dslip: [[x; 2]; 2],
        regime: -7,
        tangents: -7,
    }
}

/// Responses equal bit for bit, slice by slice.
#[track_caller]
pub fn same_all(a: &[FrictionResponse], b: &[FrictionResponse], what: &str) {
    assert_eq!(a.len(), b.len(), "{what}");
    for (i, (x, y)) in a.iter().zip(b).enumerate() {
        assert!(same(x, y), "{what}, point {i}:\n{x:?}\n{y:?}");
    }
}

/// `step_block` with `responses` (issue 32) along `rounds` rounds of
/// [`POINTS`] points, the tangents asked cycling through 0, ∂F/∂N, ∂F/∂Δs
/// and both: every point's response is bit for bit the one `step` gives
/// with the same tangent bits, and the forces, dissipations and states are
/// those of the scalar steps, with old and new states separate (forces and
/// dissipations asked too) and in place (responses only, no force slice).
pub fn check_block_responses(case: &Case, rounds: usize) {
    let law = &*case.law;
    let m = law.state_len();
    let p = POINTS;
    let name = case.name;
    let mut w = law.work();
    let (mut scalar, mut sep, mut inp) = (vec![0.0; p * m], vec![0.0; p * m], vec![0.0; p * m]);
    for k in 0..rounds {
        let tangents = (k % 4) as i32;
        let mut next = sentinels(p * m);
        let want: Vec<FrictionResponse> = (0..p)
            .map(|i| {
                let inc = FrictionIncrement {
                    tangents,
                    ..point_inc(case, k, i)
                };
                let r = i * m..(i + 1) * m;
                law.step(&scalar[r.clone()], &mut next[r], &inc, &mut w)
                    .unwrap()
            })
            .collect();
        let b = block_inputs(case, k, p);
        // Separate, with the forces and dissipations.
        let (mut f, mut d) = (sentinels(2 * p), sentinels(p));
        let mut out = vec![sentinel_response(); p];
        let mut new = sentinels(p * m);
        let separate = BlockStates::Separate {
            old: &sep,
            new: &mut new,
        };
        law.step_block(
            FrictionBlock {
                tangents,
                responses: Some(&mut out),
                ..b.block(separate, Some(&mut f), Some(&mut d))
            },
            &mut w,
        )
        .unwrap();
        let what = format!("{name} round {k}, tangents {tangents}");
        same_all(&out, &want, &format!("{what}, separate"));
        let forces: Vec<f64> = want.iter().flat_map(|r| r.force).collect();
        let dissipated: Vec<f64> = want.iter().map(|r| r.dissipated).collect();
        assert_eq!(bits(&f), bits(&forces), "{what}");
        assert_eq!(bits(&d), bits(&dissipated), "{what}");
        assert_eq!(bits(&new), bits(&next), "{what}");
        // In place, the responses only.
        let mut out = vec![sentinel_response(); p];
        law.step_block(
            FrictionBlock {
                tangents,
                responses: Some(&mut out),
                ..b.block(BlockStates::InPlace(&mut inp), None, None)
            },
            &mut w,
        )
        .unwrap();
        same_all(&out, &want, &format!("{what}, in place"));
        assert_eq!(bits(&inp), bits(&next), "{what}, in place");
        scalar = next;
        sep = new;
    }
}

/// A block whose arguments are wrong as a whole — unknown tangent bits, a
/// `responses` slice of another length, forces of another length — is
/// refused at index 0, naming the argument, before anything is written
/// (states separate and in place).
pub fn check_block_rejections(case: &Case) {
    let law = &*case.law;
    let m = law.state_len();
    let p = POINTS;
    let name = case.name;
    let mut w = law.work();
    let b = block_inputs(case, 0, p);
    let old = vec![0.0; p * m];
    // (tangents, responses and forces (None: not asked), the name).
    let faults: [(i32, Option<usize>, Option<usize>, &str); 7] = [
        (4, Some(p), Some(2 * p), "tangents"),
        (-1, Some(p), None, "tangents"),
        (8, None, Some(2 * p), "tangents"),
        (3, Some(p - 1), Some(2 * p), "responses.len()"),
        (0, Some(p + 1), None, "responses.len()"),
        (0, Some(0), None, "responses.len()"),
        (1, None, Some(p), "tangential_force.len()"),
    ];
    for (tangents, responses, forces, want) in faults {
        for in_place in [false, true] {
            let what = format!("{name}: tangents {tangents}, {responses:?} responses, {forces:?} forces, in place {in_place}");
            let mut out = vec![sentinel_response(); responses.unwrap_or(0)];
            let (mut f, mut d) = (sentinels(forces.unwrap_or(0)), sentinels(p));
            let mut news = sentinels(p * m);
            let mut states = old.clone();
            let st = if in_place {
                BlockStates::InPlace(&mut states)
            } else {
                BlockStates::Separate {
                    old: &old,
                    new: &mut news,
                }
            };
            let e = law
                .step_block(
                    FrictionBlock {
                        tangents,
                        responses: responses.map(|_| &mut out[..]),
                        ..b.block(st, forces.map(|_| &mut f[..]), Some(&mut d))
                    },
                    &mut w,
                )
                .unwrap_err();
            assert_eq!(
                (e.index, arg_name(&e.error)),
                (0, want),
                "{what}: {}",
                e.error
            );
            assert_eq!(bits(&news), bits(&sentinels(p * m)), "{what}");
            assert_eq!(bits(&states), bits(&old), "{what}");
            assert_eq!(bits(&f), bits(&sentinels(forces.unwrap_or(0))), "{what}");
            assert_eq!(bits(&d), bits(&sentinels(p)), "{what}");
            let blank = vec![sentinel_response(); out.len()];
            same_all(&out, &blank, &what);
        }
    }
    // An empty block: nothing to step, but unknown tangent bits are still
    // refused.
    let e = law
        .step_block(
            FrictionBlock {
                normal_force: &[],
                area: None,
                slip: &[],
                dt: 0.0,
                tangents: 5,
                states: BlockStates::InPlace(&mut []),
                tangential_force: None,
                dissipation: None,
                responses: Some(&mut []),
            },
            &mut w,
        )
        .unwrap_err();
    assert_eq!((e.index, arg_name(&e.error)), (0, "tangents"), "{name}");
    law.step_block(
        FrictionBlock {
            normal_force: &[],
            area: None,
            slip: &[],
            dt: 0.0,
            tangents: 3,
            states: BlockStates::InPlace(&mut []),
            tangential_force: None,
            dissipation: None,
            responses: Some(&mut []),
        },
        &mut w,
    )
    .unwrap();
}

/// Every increment of `case.bad` and two bad old states are refused,
/// naming the argument, with `new` (the state stepped in place; the block's
/// points from the failing one on) untouched; wrong state lengths too.
pub fn check_rejections(case: &Case) {
    let law = &*case.law;
    let m = law.state_len();
    let mut w = law.work();
    let name = case.name;
    // A stepped state, not a fresh one.
    let mut old = vec![0.0; m];
    for inc in case.incs.iter().take(5) {
        law.step_in_place(&mut old, inc, &mut w).unwrap();
    }
    let good = case.incs[0];
    assert_eq!(good.tangents, 0);
    // (increment, old state, name refusing it separate / in place, whether
    // a block can carry the fault at one point: one Δt, no tangents).
    let mut faults: Vec<(FrictionIncrement, Vec<f64>, &str, &str, bool)> = case
        .bad
        .iter()
        .map(|&(i, n)| {
            let blockable = i.dt.to_bits() == good.dt.to_bits() && i.tangents == 0;
            (i, old.clone(), n, n, blockable)
        })
        .collect();
    let mut negative = old.clone();
    negative[0] = -1.0;
    let mut nan_path = old.clone();
    nan_path[1] = f64::NAN;
    faults.push((good, negative, "old.dissipation", "state.dissipation", true));
    faults.push((good, nan_path, "old.slip_path", "state.slip_path", true));
    for (inc, from, want, want_in_place, blockable) in faults {
        let mut new = sentinels(m);
        let e = law.step(&from, &mut new, &inc, &mut w).unwrap_err();
        assert_eq!(arg_name(&e), want, "{name}: {e}");
        assert!(e.to_string().contains(want), "{name}: {e}");
        assert_eq!(
            bits(&new),
            bits(&sentinels(m)),
            "{name}: `new` written ({want})"
        );
        let mut st = from.clone();
        let e = law.step_in_place(&mut st, &inc, &mut w).unwrap_err();
        assert_eq!(arg_name(&e), want_in_place, "{name}: {e}");
        assert_eq!(bits(&st), bits(&from), "{name}: state written ({want})");
        if !blockable {
            continue;
        }
        // A block whose point 1 fails: point 0 written, 1 and 2 untouched.
        let b = BlockInputs::of(&[good, inc, good], good.dt);
        let olds: Vec<f64> = [&old, &from, &old].into_iter().flatten().copied().collect();
        let mut news = sentinels(3 * m);
        let mut f = sentinels(6);
        let mut d = sentinels(3);
        let mut resp = vec![sentinel_response(); 3];
        let separate = BlockStates::Separate {
            old: &olds,
            new: &mut news,
        };
        let e = law
            .step_block(
                FrictionBlock {
                    responses: Some(&mut resp),
                    ..b.block(separate, Some(&mut f), Some(&mut d))
                },
                &mut w,
            )
            .unwrap_err();
        assert_eq!(
            (e.index, arg_name(&e.error)),
            (1, want),
            "{name}: {}",
            e.error
        );
        let mut first = sentinels(m);
        let r0 = law.step(&old, &mut first, &good, &mut w).unwrap();
        assert_eq!(bits(&news[..m]), bits(&first), "{name}: point 0 ({want})");
        assert_eq!(bits(&f[..2]), bits(&r0.force), "{name}: point 0 ({want})");
        assert_eq!(d[0].to_bits(), r0.dissipated.to_bits());
        assert!(same(&resp[0], &r0), "{name}: point 0 ({want})");
        assert_eq!(bits(&news[m..]), bits(&sentinels(2 * m)), "{name} ({want})");
        assert_eq!(bits(&f[2..]), bits(&sentinels(4)), "{name} ({want})");
        assert_eq!(bits(&d[1..]), bits(&sentinels(2)), "{name} ({want})");
        same_all(
            &resp[1..],
            &[sentinel_response(); 2],
            &format!("{name} ({want})"),
        );
        let mut states = olds.clone();
        let mut f = sentinels(6);
        let e = law
            .step_block(
                b.block(BlockStates::InPlace(&mut states), Some(&mut f), None),
                &mut w,
            )
            .unwrap_err();
        assert_eq!(
            (e.index, arg_name(&e.error)),
            (1, want_in_place),
            "{name}: {}",
            e.error
        );
        assert_eq!(bits(&states[..m]), bits(&first), "{name}: point 0 ({want})");
        assert_eq!(bits(&states[m..]), bits(&olds[m..]), "{name} ({want})");
        assert_eq!(bits(&f[2..]), bits(&sentinels(4)), "{name} ({want})");
    }
    // Lengths.
    let mut new = sentinels(m + 1);
    let e = law.step(&old, &mut new, &good, &mut w).unwrap_err();
    assert_eq!(arg_name(&e), "new.len()", "{name}");
    assert_eq!(bits(&new), bits(&sentinels(m + 1)));
    let mut new = sentinels(m);
    let e = law.step(&old[1..], &mut new, &good, &mut w).unwrap_err();
    assert_eq!(arg_name(&e), "old.len()", "{name}");
    assert_eq!(bits(&new), bits(&sentinels(m)));
    let mut short = old[1..].to_vec();
    let e = law.step_in_place(&mut short, &good, &mut w).unwrap_err();
    assert_eq!(arg_name(&e), "state.len()", "{name}");
}

// ------------------------------------------------------------ the C ABI

/// The calling thread's last C error message.
pub fn c_message() -> String {
    // SAFETY: a NULL buffer sizes the message, then a buffer of that size.
    unsafe {
        let n = asperity_last_error_message(null_mut(), 0);
        let mut buf = vec![0u8; n + 1];
        asperity_last_error_message(buf.as_mut_ptr().cast(), buf.len());
        String::from_utf8_lossy(&buf[..n]).into_owned()
    }
}

/// A C status is OK, else the message.
#[track_caller]
fn c_ok(status: i32, what: &str) {
    assert_eq!(status, ASPERITY_OK, "{what}: {}", c_message());
}

/// A C status is an error whose message names `what`.
#[track_caller]
fn c_err(status: i32, what: &str) {
    let msg = c_message();
    assert_ne!(status, ASPERITY_OK, "expected an error naming {what}");
    assert!(msg.contains(what), "message `{msg}` should name {what}");
}

/// The handle `h` (made through C for `case.law`) steps as the Rust law,
/// bit for bit, through every C form: `asperity_friction_step` with old
/// and new separate, old == new (in place), NULL work;
/// `asperity_friction_step_in_place`; `asperity_friction_step_block` with
/// states separate and old == new, `_block_in_place`; and refuses a block
/// whose new states partially overlap the old ones (naming `new_states`)
/// and a point count n whose n × state size overflows `size_t` (naming
/// `n`), writing nothing.
///
/// # Safety
/// `h` is a live handle.
pub unsafe fn c_contract(h: *const AsperityFriction, case: &Case, rounds: usize) {
    let law = &*case.law;
    let name = case.name;
    let mut m = 0usize;
    c_ok(asperity_friction_state_size(h, &mut m), name);
    assert_eq!(m, law.state_len(), "{name}: state size");
    let mut work = null_mut();
    c_ok(asperity_friction_work_new(h, &mut work), name);
    let mut rw = law.work();
    // Scalar forms.
    let mut rust = vec![0.0; m];
    let mut c = vec![0.0; m];
    for k in 0..rounds {
        let inc = case.incs[k % case.incs.len()];
        let old = rust.clone();
        let want = law.step_in_place(&mut rust, &inc, &mut rw).unwrap();
        // Separate, with a work.
        let mut new = sentinels(m);
        let mut out = FrictionResponse::default();
        c_ok(
            asperity_friction_step(h, &inc, c.as_ptr(), new.as_mut_ptr(), work, &mut out),
            name,
        );
        assert!(same(&out, &want), "{name} {k}:\n{out:?}\n{want:?}");
        assert_eq!(bits(&new), bits(&rust), "{name} {k}");
        // Separate, NULL work.
        let mut new2 = sentinels(m);
        let mut out2 = FrictionResponse::default();
        c_ok(
            asperity_friction_step(
                h,
                &inc,
                c.as_ptr(),
                new2.as_mut_ptr(),
                null_mut(),
                &mut out2,
            ),
            name,
        );
        assert!(same(&out2, &want), "{name} {k} (NULL work)");
        assert_eq!(bits(&new2), bits(&rust), "{name} {k} (NULL work)");
        // In place: old == new, and asperity_friction_step_in_place.
        let mut same_ptr = c.clone();
        let p = same_ptr.as_mut_ptr();
        let mut out3 = FrictionResponse::default();
        c_ok(asperity_friction_step(h, &inc, p, p, work, &mut out3), name);
        assert!(same(&out3, &want), "{name} {k} (old == new)");
        assert_eq!(bits(&same_ptr), bits(&rust), "{name} {k} (old == new)");
        let mut in_place = c.clone();
        let mut out4 = FrictionResponse::default();
        let w = if k % 2 == 0 { work } else { null_mut() };
        c_ok(
            asperity_friction_step_in_place(h, &inc, in_place.as_mut_ptr(), w, &mut out4),
            name,
        );
        assert!(same(&out4, &want), "{name} {k} (in place)");
        assert_eq!(bits(&in_place), bits(&rust), "{name} {k} (in place)");
        assert_eq!(bits(&old), bits(&c), "{name} {k}: the C state drifted");
        c = new;
    }
    // Blocks.
    let p = POINTS;
    let dt = case.incs[0].dt;
    let mut rust = vec![0.0; p * m];
    let mut sep = vec![0.0; p * m];
    let mut same_ptr = vec![0.0; p * m];
    let mut in_place = vec![0.0; p * m];
    for k in 0..rounds {
        let b = block_inputs(case, k, p);
        let BlockInputs { nf, area, slip, .. } = &b;
        // NULL areas (0 for every point) every other round, when 0 is
        // what the points have.
        let ap = if k % 2 == 1 && area.iter().all(|&a| a == 0.0) {
            null()
        } else {
            area.as_ptr()
        };
        let (mut rf, mut rd) = (vec![0.0; 2 * p], vec![0.0; p]);
        let states = BlockStates::InPlace(&mut rust);
        law.step_block(b.block(states, Some(&mut rf), Some(&mut rd)), &mut rw)
            .unwrap();
        // Separate (NULL work every other round).
        let mut next = sentinels(p * m);
        let (mut f, mut d) = (sentinels(2 * p), sentinels(p));
        let w = if k % 2 == 0 { work } else { null_mut() };
        c_ok(
            asperity_friction_step_block(
                h,
                p,
                nf.as_ptr(),
                ap,
                slip.as_ptr(),
                dt,
                sep.as_ptr(),
                next.as_mut_ptr(),
                f.as_mut_ptr(),
                d.as_mut_ptr(),
                w,
            ),
            name,
        );
        assert_eq!(
            (bits(&f), bits(&d)),
            (bits(&rf), bits(&rd)),
            "{name} block {k}"
        );
        assert_eq!(bits(&next), bits(&rust), "{name} block {k}");
        sep = next;
        // old == new.
        let q = same_ptr.as_mut_ptr();
        let mut f = sentinels(2 * p);
        c_ok(
            asperity_friction_step_block(
                h,
                p,
                nf.as_ptr(),
                ap,
                slip.as_ptr(),
                dt,
                q,
                q,
                f.as_mut_ptr(),
                null_mut(),
                work,
            ),
            name,
        );
        assert_eq!(bits(&f), bits(&rf), "{name} block {k} (old == new)");
        assert_eq!(
            bits(&same_ptr),
            bits(&rust),
            "{name} block {k} (old == new)"
        );
        // In place.
        let mut f = sentinels(2 * p);
        let mut d = sentinels(p);
        c_ok(
            asperity_friction_step_block_in_place(
                h,
                p,
                nf.as_ptr(),
                ap,
                slip.as_ptr(),
                dt,
                in_place.as_mut_ptr(),
                f.as_mut_ptr(),
                d.as_mut_ptr(),
                w,
            ),
            name,
        );
        assert_eq!(
            (bits(&f), bits(&d)),
            (bits(&rf), bits(&rd)),
            "{name} block {k}"
        );
        assert_eq!(bits(&in_place), bits(&rust), "{name} block {k} (in place)");
    }
    // A partial overlap of old and new: refused, naming `new_states`,
    // nothing written.
    let BlockInputs { nf, area, slip, .. } = block_inputs(case, 0, p);
    let mut both = vec![0.0; 2 * p * m];
    let before = bits(&both);
    let q = both.as_mut_ptr();
    let mut f = sentinels(2 * p);
    let mut d = sentinels(p);
    c_err(
        asperity_friction_step_block(
            h,
            p,
            nf.as_ptr(),
            area.as_ptr(),
            slip.as_ptr(),
            dt,
            q,
            q.add(1),
            f.as_mut_ptr(),
            d.as_mut_ptr(),
            work,
        ),
        "`new_states`",
    );
    assert_eq!(
        bits(&both),
        before,
        "{name}: overlapping block wrote states"
    );
    assert_eq!(bits(&f), bits(&sentinels(2 * p)), "{name}: forces written");
    assert_eq!(bits(&d), bits(&sentinels(p)), "{name}: dissipation written");
    // The scalar step likewise names `new_state`.
    let mut out = FrictionResponse {
        cof: -9.0,
        ..Default::default()
    };
    c_err(
        asperity_friction_step(h, &case.incs[0], q, q.add(1), work, &mut out),
        "`new_state`",
    );
    assert_eq!(bits(&both), before);
    assert_eq!(out.cof, -9.0, "{name}: *out written");
    // n × state size overflows size_t: refused before any array is read,
    // naming `n`, nothing written.
    let huge = usize::MAX / m + 1;
    let mut f = sentinels(2 * p);
    let mut states = vec![0.0; p * m];
    c_err(
        asperity_friction_step_block(
            h,
            huge,
            nf.as_ptr(),
            area.as_ptr(),
            slip.as_ptr(),
            dt,
            states.as_ptr(),
            states.as_mut_ptr(),
            f.as_mut_ptr(),
            null_mut(),
            work,
        ),
        "`n`",
    );
    c_err(
        asperity_friction_step_block_in_place(
            h,
            huge,
            nf.as_ptr(),
            area.as_ptr(),
            slip.as_ptr(),
            dt,
            states.as_mut_ptr(),
            f.as_mut_ptr(),
            null_mut(),
            null_mut(),
        ),
        "`n`",
    );
    let mut next = sentinels(p * m);
    c_err(
        asperity_friction_step_block(
            h,
            huge,
            nf.as_ptr(),
            area.as_ptr(),
            slip.as_ptr(),
            dt,
            states.as_ptr(),
            next.as_mut_ptr(),
            f.as_mut_ptr(),
            null_mut(),
            work,
        ),
        "`n`",
    );
    assert_eq!(
        bits(&states),
        bits(&vec![0.0; p * m]),
        "{name}: states written"
    );
    assert_eq!(
        bits(&next),
        bits(&sentinels(p * m)),
        "{name}: states written"
    );
    assert_eq!(bits(&f), bits(&sentinels(2 * p)), "{name}: forces written");
    asperity_friction_work_free(work);
    c_block_responses(h, case, rounds);
}

/// `asperity_friction_step_block_responses` through the handle `h` (made
/// through C for `case.law`): every point's response and new state equal
/// `asperity_friction_step`'s with the same tangent bits (cycling through
/// 0..=3), old and new separate and equal, a work or NULL, NULL areas when
/// they are all 0; n = 0 does nothing; NULL `responses` and unknown tangent
/// bits are refused naming them, and a point count whose states overflow
/// `size_t` naming `n`, nothing written; an error at point 1 names element
/// 1, point 0 written, points 1 and 2 untouched.
///
/// # Safety
/// `h` is a live handle.
pub unsafe fn c_block_responses(h: *const AsperityFriction, case: &Case, rounds: usize) {
    let name = case.name;
    let m = case.law.state_len();
    let p = POINTS;
    let dt = case.incs[0].dt;
    let mut work = null_mut();
    c_ok(asperity_friction_work_new(h, &mut work), name);
    let mut sep = vec![0.0; p * m];
    let mut same_ptr = vec![0.0; p * m];
    for k in 0..rounds {
        let tangents = (k % 4) as i32;
        let BlockInputs { nf, area, slip, .. } = block_inputs(case, k, p);
        let ap = if k % 2 == 1 && area.iter().all(|&a| a == 0.0) {
            null()
        } else {
            area.as_ptr()
        };
        // Point by point through asperity_friction_step.
        let mut want = vec![FrictionResponse::default(); p];
        let mut next = sentinels(p * m);
        for i in 0..p {
            let inc = FrictionIncrement {
                tangents,
                ..point_inc(case, k, i)
            };
            c_ok(
                asperity_friction_step(
                    h,
                    &inc,
                    sep[i * m..].as_ptr(),
                    next[i * m..].as_mut_ptr(),
                    work,
                    &mut want[i],
                ),
                name,
            );
        }
        let what = format!("{name} block responses {k} (tangents {tangents})");
        // Separate, a work or NULL.
        let w = if k % 2 == 0 { work } else { null_mut() };
        let mut out = vec![sentinel_response(); p];
        let mut new = sentinels(p * m);
        c_ok(
            asperity_friction_step_block_responses(
                h,
                p,
                nf.as_ptr(),
                ap,
                slip.as_ptr(),
                dt,
                tangents,
                sep.as_ptr(),
                new.as_mut_ptr(),
                out.as_mut_ptr(),
                w,
            ),
            &what,
        );
        same_all(&out, &want, &what);
        assert_eq!(bits(&new), bits(&next), "{what}");
        // old == new.
        let q = same_ptr.as_mut_ptr();
        let mut out = vec![sentinel_response(); p];
        c_ok(
            asperity_friction_step_block_responses(
                h,
                p,
                nf.as_ptr(),
                ap,
                slip.as_ptr(),
                dt,
                tangents,
                q,
                q,
                out.as_mut_ptr(),
                work,
            ),
            &what,
        );
        same_all(&out, &want, &format!("{what} (old == new)"));
        assert_eq!(bits(&same_ptr), bits(&next), "{what} (old == new)");
        sep = next;
    }
    let BlockInputs { nf, area, slip, .. } = block_inputs(case, 0, p);
    // n = 0: nothing read, nothing written.
    c_ok(
        asperity_friction_step_block_responses(
            h,
            0,
            null(),
            null(),
            null(),
            dt,
            3,
            null(),
            null_mut(),
            null_mut(),
            null_mut(),
        ),
        name,
    );
    // NULL responses, unknown tangent bits, n too large: refused naming
    // them, nothing written.
    let old = vec![0.0; p * m];
    let mut news = sentinels(p * m);
    let mut out = vec![sentinel_response(); p];
    for (tangents, responses, n, want) in [
        (3, null_mut(), p, "`responses`"),
        (4, out.as_mut_ptr(), p, "`tangents`"),
        (-2, out.as_mut_ptr(), 0, "`tangents`"),
        (0, out.as_mut_ptr(), usize::MAX / m + 1, "`n`"),
    ] {
        c_err(
            asperity_friction_step_block_responses(
                h,
                n,
                nf.as_ptr(),
                area.as_ptr(),
                slip.as_ptr(),
                dt,
                tangents,
                old.as_ptr(),
                news.as_mut_ptr(),
                responses,
                work,
            ),
            want,
        );
        assert_eq!(bits(&news), bits(&sentinels(p * m)), "{name}: {want}");
        same_all(
            &out,
            &vec![sentinel_response(); p],
            &format!("{name}: {want}"),
        );
    }
    // NULL old or new states; a partial overlap.
    let mut both = vec![0.0; 2 * p * m];
    let q = both.as_mut_ptr();
    for (o, n, want) in [
        (null(), news.as_mut_ptr(), "`old_states`"),
        (old.as_ptr(), null_mut(), "`new_states`"),
        (q.cast_const(), q.add(1), "`new_states`"),
    ] {
        c_err(
            asperity_friction_step_block_responses(
                h,
                p,
                nf.as_ptr(),
                area.as_ptr(),
                slip.as_ptr(),
                dt,
                0,
                o,
                n,
                out.as_mut_ptr(),
                work,
            ),
            want,
        );
        same_all(
            &out,
            &vec![sentinel_response(); p],
            &format!("{name}: {want}"),
        );
    }
    assert_eq!(bits(&both), bits(&vec![0.0; 2 * p * m]), "{name}");
    // An error at point 1 (the first of the case's faults a block can
    // carry): element 1 named, point 0 written, points 1 and 2 untouched.
    let good = case.incs[0];
    if let Some(&(bad, arg)) = case
        .bad
        .iter()
        .find(|(i, _)| i.dt.to_bits() == good.dt.to_bits() && i.tangents == 0)
    {
        let b = BlockInputs::of(&[good, bad, good], good.dt);
        let olds = vec![0.0; p * m];
        let mut news = sentinels(p * m);
        let mut out = vec![sentinel_response(); p];
        c_err(
            asperity_friction_step_block_responses(
                h,
                p,
                b.nf.as_ptr(),
                b.area.as_ptr(),
                b.slip.as_ptr(),
                dt,
                3,
                olds.as_ptr(),
                news.as_mut_ptr(),
                out.as_mut_ptr(),
                work,
            ),
            &format!("`{arg}`"),
        );
        let msg = c_message();
        assert!(msg.starts_with("element 1:"), "{name}: {msg}");
        let mut first = sentinels(m);
        let mut r0 = FrictionResponse::default();
        let inc = FrictionIncrement {
            tangents: 3,
            ..good
        };
        c_ok(
            asperity_friction_step(h, &inc, olds.as_ptr(), first.as_mut_ptr(), work, &mut r0),
            name,
        );
        assert!(same(&out[0], &r0), "{name}: point 0 ({arg})");
        assert_eq!(bits(&news[..m]), bits(&first), "{name}: point 0 ({arg})");
        same_all(
            &out[1..],
            &[sentinel_response(); 2],
            &format!("{name} ({arg})"),
        );
        assert_eq!(bits(&news[m..]), bits(&sentinels(2 * m)), "{name} ({arg})");
    }
    asperity_friction_work_free(work);
}
