//! Sliders (`src/ffi/slider.rs`): from scene JSON and from structs (with
//! geometries of `friction`), options and material presets; and the slider
//! as a patch friction law through the one friction handle
//! (`src/ffi/friction_law.rs`): its work buffers, steps (separate, old ==
//! new, in place), blocks.

use super::common::*;
use super::friction::geometry_rods;
use super::{pick, take, Ctx, Op};
use arbitrary::Arbitrary;
use asperity::ffi::friction::*;
use asperity::ffi::friction_law::*;
use asperity::ffi::slider::*;
use asperity::ffi::ASPERITY_OK;
use asperity::friction::{FrictionIncrement, FrictionMaterial, FrictionResponse};
use std::ffi::c_char;
use std::ptr::{null, null_mut};

/// Runs one operation of this domain; `super::call` routes each variant
/// to the module of its `src/ffi/` file.
pub(super) unsafe fn call(ctx: &mut Ctx, op: &Op) {
    match op {
        Op::SliderNew {
            scene,
            mutation,
            base,
            nulls,
        } => {
            let mut text = scene.json().into_bytes();
            mutation.apply(&mut text);
            let base_dir: &[u8] = match base % 4 {
                0 => b".\0",
                1 => b"/nonexistent-asperity-fuzz\0",
                2 => b"\xff\xfe\0",
                _ => b"\0",
            };
            let mut out = null_mut();
            let s = asperity_slider_from_scene_json(
                if nulls.at(0) {
                    null()
                } else {
                    text.as_ptr() as *const c_char
                },
                text.len(),
                if nulls.at(2) {
                    null()
                } else {
                    base_dir.as_ptr() as *const c_char
                },
                mp(&mut out, nulls.at(1)),
            );
            if let Some(sl) = made(s, out, !nulls.at(1), "slider_from_scene_json") {
                keep_slider(ctx, sl);
            }
        }
        Op::SliderQuery {
            slider,
            which,
            null,
        } => {
            let (sl, law) = pick_slider(ctx, *slider);
            let s = if which % 2 == 0 {
                let mut n = 0usize;
                asperity_friction_state_size(law, mp(&mut n, *null))
            } else {
                let mut info: AsperitySliderInfo = zeroed();
                asperity_slider_info(sl, mp(&mut info, *null))
            };
            ok(s, "slider query");
        }
        Op::WorkNew { slider, null } => {
            let (_, law) = pick_slider(ctx, *slider);
            let mut out = null_mut();
            let s = asperity_friction_work_new(law, mp(&mut out, *null));
            if let Some(w) = made(s, out, !*null, "friction_work_new") {
                ctx.works.push(w);
            }
        }
        Op::SliderStep {
            slider,
            work,
            inc,
            control,
            tangents,
            state,
            in_place,
            nulls,
        } => {
            let (_, law) = pick_slider(ctx, *slider);
            let w = pick(&ctx.works, *work);
            let v = fs(*inc);
            // (The former per-increment gap is the area now, the former
            // loading control the reserved field.)
            let i = FrictionIncrement {
                normal_force: v[0],
                area: v[1],
                slip: [v[2], v[3]],
                dt: v[4],
                tangents: tangents.0,
                reserved: control.0,
            };
            let m = slider_state_len(law);
            let mut old = make_slider_state(ctx, state, m);
            let mut new = vec![0.0; m];
            let mut out: FrictionResponse = zeroed();
            let op = bufm(&mut old, nulls.at(2));
            let s = if *in_place && nulls.at(4) {
                asperity_friction_step_in_place(
                    law,
                    cp(&i, nulls.at(0)),
                    op,
                    w,
                    mp(&mut out, nulls.at(1)),
                )
            } else {
                let np = if *in_place {
                    op
                } else {
                    bufm(&mut new, nulls.at(3))
                };
                asperity_friction_step(
                    law,
                    cp(&i, nulls.at(0)),
                    op,
                    np,
                    w,
                    mp(&mut out, nulls.at(1)),
                )
            };
            if ok(s, "friction_step (slider)") {
                ctx.slider_state = if *in_place { old } else { new };
            }
            // The record of the work's last step (a slider work, or NULL).
            let mut rec: AsperitySliderRecord = zeroed();
            if ok(
                asperity_slider_record(w, mp(&mut rec, nulls.at(5))),
                "slider_record",
            ) {
                assert!(rec.seated == 0 || rec.seated == 1, "{rec:?}");
                assert_eq!(rec.reserved, 0, "{rec:?}");
            }
        }
        Op::SliderBlock {
            slider,
            work,
            n,
            inc,
            dt,
            state,
            in_place,
            nulls,
        } => {
            let (_, law) = pick_slider(ctx, *slider);
            let w = pick(&ctx.works, *work);
            let form = *n / 5 % 2;
            let n = *n as usize % 5;
            let m = slider_state_len(law);
            let val = |i: usize, d: f64| inc.get(i).map_or(d, |f| f.0);
            let normal: Vec<f64> = (0..n).map(|i| val(3 * i, 0.05)).collect();
            let slip: Vec<f64> = (0..2 * n)
                .map(|i| val(3 * (i / 2) + 1 + i % 2, 1e-7))
                .collect();
            let area = vec![0.0; n];
            let one = make_slider_state(ctx, state, m);
            let mut old: Vec<f64> = (0..n).flat_map(|_| one.iter().copied()).collect();
            let mut new = vec![0.0; n * m];
            let mut force = vec![0.0; 2 * n];
            let mut diss = vec![0.0; n];
            let op = bufm(&mut old, nulls.at(2));
            let s = if *in_place && form == 1 {
                asperity_friction_step_block_in_place(
                    law,
                    n,
                    bufp(&normal, nulls.at(0)),
                    bufp(&area, nulls.at(6)),
                    bufp(&slip, nulls.at(1)),
                    dt.0,
                    op,
                    bufm(&mut force, nulls.at(4)),
                    bufm(&mut diss, nulls.at(5)),
                    w,
                )
            } else {
                let np = if *in_place {
                    op
                } else {
                    bufm(&mut new, nulls.at(3))
                };
                asperity_friction_step_block(
                    law,
                    n,
                    bufp(&normal, nulls.at(0)),
                    bufp(&area, nulls.at(6)),
                    bufp(&slip, nulls.at(1)),
                    dt.0,
                    op,
                    np,
                    bufm(&mut force, nulls.at(4)),
                    bufm(&mut diss, nulls.at(5)),
                    w,
                )
            };
            ok(s, "friction_step_block (slider)");
        }
        Op::SliderFree { slider } => {
            if ctx.sliders.is_empty() {
                asperity_slider_free(null_mut());
                asperity_friction_free(null_mut());
            } else {
                let i = *slider as usize % ctx.sliders.len();
                asperity_friction_free(ctx.slider_laws.swap_remove(i));
                asperity_slider_free(ctx.sliders.swap_remove(i));
            }
        }
        Op::WorkFree { work } => {
            if let Some(w) = take(&mut ctx.works, *work) {
                asperity_friction_work_free(w);
            } else {
                asperity_friction_work_free(null_mut());
            }
        }
        Op::SliderOptionsDefault { null } => {
            let mut o: AsperitySliderOptions = zeroed();
            ok(
                asperity_slider_options_default(mp(&mut o, *null)),
                "slider_options_default",
            );
        }
        Op::MaterialCopper { null } => {
            let mut m: FrictionMaterial = zeroed();
            ok(
                asperity_friction_material_copper(mp(&mut m, *null)),
                "friction_material_copper",
            );
        }
        Op::SliderFromStructs {
            geometry,
            material,
            counter,
            options,
            nulls,
        } => {
            let g = match *geometry {
                GeometrySource::Table(i) => pick(&ctx.geometries, i),
                GeometrySource::Uniform { rods, poke } => {
                    let mut v = [6e-9, 4.3e-7, 2.2e-9, 1.61e-7, 1.35e-6];
                    if let Some((at, value)) = poke {
                        v[at as usize % 5] = value.0;
                    }
                    let nano = AsperityNanoAsperities {
                        h_vdw: v[0],
                        w_vdw: v[1],
                        h_chem: v[2],
                        w_chem: v[3],
                        spacing: v[4],
                        per_rod: 1,
                    };
                    let mut g = null_mut();
                    let s = asperity_slider_geometry_new_uniform(
                        1.5e-6,
                        rods as usize % 16 + 1,
                        &nano,
                        &mut g,
                    );
                    if let Some(g) = made(s, g, true, "slider_geometry_new_uniform") {
                        ctx.geometries.push(g);
                    }
                    g
                }
            };
            if !g.is_null() && geometry_rods(g) > MAX_SLIDER_RODS {
                return;
            }
            let m = material.get();
            let o = options.as_ref().map_or_else(
                || {
                    let mut o: AsperitySliderOptions = zeroed();
                    assert!(ok(
                        asperity_slider_options_default(&mut o),
                        "slider_options_default"
                    ));
                    o
                },
                |o| o.get(),
            );
            // By default 256 samples at 0.1 µm: under up to 16 rods of 1.5 µm.
            let (c, dx) = match counter {
                Some((h, dx)) => (h.make(), dx.0),
                None => (
                    (0..256)
                        .map(|j| 5e-8 * (0.3 * j as f64).sin() * (0.07 * j as f64).cos())
                        .collect(),
                    1e-7,
                ),
            };
            let mut out = null_mut();
            let s = asperity_slider_new(
                g,
                cp(&m, nulls.at(0)),
                bufp(&c, nulls.at(1)),
                c.len(),
                dx,
                cp(&o, nulls.at(2)),
                mp(&mut out, nulls.at(3)),
            );
            if let Some(sl) = made(s, out, !nulls.at(3), "slider_new") {
                keep_slider(ctx, sl);
            }
        }
        _ => unreachable!("not a slider operation: {op:?}"),
    }
}

/// A scene for `asperity_slider_from_scene_json`: each number is the value
/// of `examples/scenes/chapter6_copper.json` (smaller surfaces) unless given.
#[derive(Debug, Clone, Arbitrary)]
pub struct SceneSpec {
    hurst: Option<F>,
    rq: Option<F>,
    roll_off: Option<F>,
    slider_points: u8,
    counter_points: u8,
    dx: Option<F>,
    seeds: (u8, u8),
    nano: [Option<F>; 5],
    widths: Option<Vec<F>>,
    depth: Option<F>,
    load: Option<F>,
    loading: u8,
    mechanisms: u8,
    cof_form: u8,
    periodic: bool,
    plastic: u8,
    dense: bool,
}

impl SceneSpec {
    fn json(&self) -> String {
        let g = |o: &Option<F>, d: f64| num(o.map_or(d, |f| f.0));
        let nano_d = [6e-9, 4.3e-7, 2.2e-9, 1.61e-7, 1.35e-6];
        let nano: Vec<String> = ["h_vdw", "w_vdw", "h_chem", "w_chem", "spacing"]
            .iter()
            .zip(self.nano.iter().zip(nano_d))
            .map(|(k, (o, d))| format!("\"{k}\": {}", g(o, d)))
            .collect();
        let widths = match &self.widths {
            None => "[1.5e-6]".to_string(),
            Some(w) => format!(
                "[{}]",
                w.iter()
                    .take(4)
                    .map(|f| num(f.0))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        };
        let loading = match self.loading % 3 {
            0 => format!(
                "{{ \"fixed_load\": {{ \"load\": {} }} }}",
                g(&self.load, 0.18)
            ),
            1 => format!(
                "{{ \"fixed_load_fraction\": {{ \"fraction\": {} }} }}",
                g(&self.load, 0.35)
            ),
            _ => format!(
                "{{ \"fixed_gap\": {{ \"position\": {} }} }}",
                g(&self.load, 0.0)
            ),
        };
        let m = self.mechanisms;
        let plastic = match self.plastic % 3 {
            0 => "\"shorten_only\"".to_string(),
            1 => "\"nearest_neighbours\"".to_string(),
            _ => format!(
                "{{ \"gaussian\": {{ \"width\": {} }} }}",
                g(&self.depth, 2.0)
            ),
        };
        let surface = |points: u8, seed: u8| {
            format!(
                "{{ \"self_affine\": {{ \"hurst\": {}, \"rq\": {}, \"roll_off_wavelength\": {}, \"points\": {}, \"dx\": {}, \"seed\": {} }} }}",
                g(&self.hurst, 0.8),
                g(&self.rq, 5e-7),
                g(&self.roll_off, 1e-4),
                points as usize % 160,
                g(&self.dx, 1.5e-6),
                seed
            )
        };
        format!(
            "{{ \"material\": {{ \"preset\": \"copper\" }}, \"surfaces\": {{ \"slider\": {}, \"counter\": {}, \"nano\": {{ \"asperities\": {{ {} }} }} }}, \"rods\": {{ \"widths\": {}, \"depth\": {}, \"plastic\": {}, \"solver\": \"{}\" }}, \"mechanisms\": {{ \"chemical\": {}, \"van_der_waals\": {}, \"elastic\": {}, \"plastic\": {} }}, \"cof_form\": \"{}\", \"loading\": {}, \"sliding\": {{ \"distance\": 1.5e-4, \"step\": 1.5e-6, \"track_end\": \"{}\" }}, \"outputs\": {{ \"csv\": false, \"svg\": false }} }}",
            surface(self.slider_points, self.seeds.0),
            surface(self.counter_points, self.seeds.1),
            nano.join(", "),
            widths,
            g(&self.depth, 1.35e-5),
            plastic,
            if self.dense { "dense" } else { "sweep" },
            m & 1 != 0,
            m & 2 != 0,
            m & 4 != 0,
            m & 8 != 0,
            ["Derjaguin", "Amontons", "Bowden"][self.cof_form as usize % 3],
            loading,
            if self.periodic { "periodic" } else { "error" },
        )
    }
}

/// The friction material of `asperity_slider_new`: the C copper preset,
/// the preset with fields replaced, or raw values.
#[derive(Debug, Clone, Arbitrary)]
pub enum MaterialSpec {
    Copper,
    Poked(Vec<(u8, F)>),
    Raw([F; 12]),
}

impl MaterialSpec {
    /// The material (through `asperity_friction_material_copper`).
    unsafe fn get(&self) -> FrictionMaterial {
        let mut m: FrictionMaterial = zeroed();
        assert!(ok(
            asperity_friction_material_copper(&mut m),
            "friction_material_copper"
        ));
        let field = |m: &mut FrictionMaterial, k: u8| -> *mut f64 {
            match k % 12 {
                0 => &mut m.yield_stress,
                1 => &mut m.youngs_modulus,
                2 => &mut m.poisson_ratio,
                3 => &mut m.counter_youngs_modulus,
                4 => &mut m.counter_poisson_ratio,
                5 => &mut m.bond_diameter,
                6 => &mut m.chemical_bond_energy,
                7 => &mut m.vdw_bond_energy,
                8 => &mut m.work_of_adhesion,
                9 => &mut m.adhesive_layer,
                10 => &mut m.threshold_strain,
                _ => &mut m.areal_density,
            }
        };
        match self {
            MaterialSpec::Copper => {}
            MaterialSpec::Poked(v) => {
                for &(k, f) in v.iter().take(3) {
                    *field(&mut m, k) = f.0;
                }
            }
            MaterialSpec::Raw(v) => {
                for (k, f) in v.iter().enumerate() {
                    *field(&mut m, k as u8) = f.0;
                }
            }
        }
        m
    }
}

/// `AsperitySliderOptions`: the C defaults with the fields selected by
/// `which` replaced.
#[derive(Debug, Clone, Arbitrary)]
pub struct SliderOptionsSpec {
    which: u16,
    normal_force: F,
    gap: F,
    plastic_width: F,
    depth: F,
    root_margin: F,
    control: Sel,
    mechanisms: u8,
    cof_form: Sel,
    plastic: Sel,
    solver: Sel,
    periodic: Sel,
}

impl SliderOptionsSpec {
    /// The options (through `asperity_slider_options_default`).
    unsafe fn get(&self) -> AsperitySliderOptions {
        let mut o: AsperitySliderOptions = zeroed();
        assert!(ok(
            asperity_slider_options_default(&mut o),
            "slider_options_default"
        ));
        let w = |i: u32| self.which >> i & 1 == 1;
        if w(0) {
            o.normal_force = self.normal_force.0;
        }
        if w(1) {
            o.gap = self.gap.0;
        }
        if w(2) {
            o.plastic_width = self.plastic_width.0;
        }
        if w(3) {
            o.depth = self.depth.0;
        }
        if w(4) {
            o.root_margin = self.root_margin.0;
        }
        if w(5) {
            o.control = self.control.0;
        }
        if w(6) {
            // -1 ..= 16: every valid bit set, and two invalid ones.
            o.mechanisms = self.mechanisms as i32 % 18 - 1;
        }
        if w(7) {
            o.cof_form = self.cof_form.0;
        }
        if w(8) {
            o.plastic = self.plastic.0;
        }
        if w(9) {
            o.solver = self.solver.0;
        }
        if w(10) {
            o.periodic = self.periodic.0;
        }
        o
    }
}

/// The geometry of `asperity_slider_new`: one the input made, or a uniform
/// one made here (`rods` % 16 + 1 rods of 1.5 µm with the chapter-6
/// nano-asperities, one value replaced when `poke` is given).
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum GeometrySource {
    Table(u8),
    Uniform { rods: u8, poke: Option<(u8, F)> },
}

/// Most rods (over all levels) of a geometry that `asperity_slider_new` is
/// given: the dense rod solver is cubic in the rod count.
pub(super) const MAX_SLIDER_RODS: usize = 256;

/// Most rods × nano-asperities per rod of a slider the harness steps: a step
/// visits every nano-asperity column of every rod (the library allows 2^24
/// per rod, `MAX_NANO_PER_ROD`).
pub(super) const MAX_SLIDER_NANO: usize = 1 << 22;

/// Keep `slider` and its friction law for the steps, or free it at once
/// when its steps would cost more than [`MAX_SLIDER_NANO`] (a harness cost
/// bound).
pub(super) unsafe fn keep_slider(ctx: &mut Ctx, slider: *mut AsperitySlider) {
    let mut info: AsperitySliderInfo = zeroed();
    assert!(ok(asperity_slider_info(slider, &mut info), "slider_info"));
    if info.rods.saturating_mul(info.nano_per_rod) > MAX_SLIDER_NANO {
        asperity_slider_free(slider);
    } else {
        let mut law = null_mut();
        let s = asperity_friction_from_slider(slider, &mut law);
        let law = made(s, law, true, "friction_from_slider").expect("the law of a slider");
        let mut m = 0usize;
        assert!(ok(asperity_friction_state_size(law, &mut m), "state size"));
        assert_eq!(m, info.state_size, "friction_state_size vs slider_info");
        ctx.sliders.push(slider);
        ctx.slider_laws.push(law);
    }
}

/// The slider `sel` and its friction law (both NULL for 255 or none).
pub(super) fn pick_slider(ctx: &Ctx, sel: u8) -> (*mut AsperitySlider, *mut AsperityFriction) {
    if sel == 255 || ctx.sliders.is_empty() {
        (null_mut(), null_mut())
    } else {
        let i = sel as usize % ctx.sliders.len();
        (ctx.sliders[i], ctx.slider_laws[i])
    }
}

/// The state size of the law `law`, or 8 for NULL (the call then fails).
pub(super) unsafe fn slider_state_len(law: *const AsperityFriction) -> usize {
    let mut m = 0usize;
    if law.is_null() || asperity_friction_state_size(law, &mut m) != ASPERITY_OK {
        8
    } else {
        m
    }
}

pub(super) fn make_slider_state(ctx: &Ctx, state: &SliderState, m: usize) -> Vec<f64> {
    make_state(&ctx.slider_state, state, m)
}
