//! Fuzz harness `c_abi`: the `extern "C"` entry points themselves
//! (`asperity::ffi::*`, the functions `libasperity` exports), called in an
//! arbitrary sequence with arbitrary doubles (NaN, ±inf, ±0, subnormals,
//! ±MAX, log-uniform magnitudes, raw bit patterns), integers (selectors out
//! of range, sizes 0 and huge where no caller buffer depends on them) and
//! NULL pointers, on handles the sequence created (laws, tables, homogenised
//! friction, slider geometries, empirical GW surfaces, sliders from scene
//! JSON and from structs, the friction handles of sliders and the dynamic
//! friction models and their work buffers), freed at the end.
//!
//! Findings: any panic. The C guard catches a library panic and returns
//! `ASPERITY_ERR_INTERNAL`; the harness treats that status as a finding
//! (it panics with the message), as it does an error status without a
//! message, an unknown status code, and a constructor that fails without
//! writing NULL to its out-handle. For `asperity_friction_step` and
//! `asperity_friction_step_in_place` of the dynamic models also: a failure
//! that wrote the new state or `*out` (documented untouched), and
//! `ASPERITY_OK` with a negative `dissipated`.
//!
//! What the harness does not feed (caller undefined behaviour, outside the
//! contract): a pointer with a length longer than its buffer (every
//! pointer+length pair is a real buffer of that length, or NULL; a state
//! array is the model's or slider's state size), a freed or foreign handle,
//! a partially overlapping in/out pair where the library cannot detect it.
//! Inconsistent *counts* that the library can check (a PSD length other
//! than n/2+1, a rod-heights buffer shorter than the level, a work buffer of
//! another law, a new state partially overlapping the old one) are fed.
//!
//! Cost bounds (so an input runs in milliseconds): the Lennard-Jones entry
//! points get grids of at most 64 cells, or invalid ones (0 = the converged
//! default of up to 1024 cells, and the library's upper bound of 16384, are
//! not fed: see RELIABILITY.md), and Lennard-Jones tables valid tolerances
//! of at least 1e-5 only (1e-10 samples 10^5 solver points: seconds);
//! `asperity_fidelity_advise` is fed only
//! argument sets that its validation rejects (a valid set runs the
//! Lennard-Jones reference for seconds to minutes); scenes generate at most
//! 160-point profiles; `asperity_slider_new` gets geometries of at most 256
//! rods; sliders with more than 2^22 nano-asperities in all are built but not
//! stepped; a Prandtl–Tomlinson increment expected to take more than 2·10⁴
//! integration sub-steps (the library stops at 10⁶) runs once per input,
//! like the other expensive calls; `asperity_afm_analyze` gets at most 48
//! points (it fits up to four laws by Levenberg–Marquardt);
//! `asperity_borodich_kryukova_run` at most 255 steps on at most 2047
//! cells; `asperity_schmittbuhl_run` the fuzzed fields only where its
//! validation rejects them (a valid field takes the default: the chain runs
//! cost with the stiffness and mass ratios), at most N = 4 and G = 2, once
//! per input.
//!
//! Shared by `fuzz/fuzz_targets/c_abi.rs` (libFuzzer) and
//! `tests/fuzz_corpus.rs` (corpus replay on stable).
//!
//! Layout: this file holds the operation enum [`Op`] (its variant order and
//! payloads are the input encoding: the committed corpus in
//! `fuzz/corpus/c_abi/` and `fuzz/regressions/c_abi/` keeps its meaning only
//! while they stay as they are), the per-input handles ([`Ctx`]), the
//! dispatch and [`run`]. Each operation runs in the module of its
//! `src/ffi/` domain, `c_abi/<domain>.rs`, with the inputs and helpers only
//! that domain uses; `c_abi/common.rs` holds the shared values and checks.
//! The modules are included by `#[path]` relative to this file, so both
//! includers (`fuzz/fuzz_targets/c_abi.rs`, `tests/fuzz_corpus.rs`) see
//! the same tree.

#![allow(clippy::too_many_arguments)]

#[path = "c_abi/abi.rs"]
mod abi;
#[path = "c_abi/afm.rs"]
mod afm;
#[path = "c_abi/common.rs"]
mod common;
#[path = "c_abi/contact.rs"]
mod contact;
#[path = "c_abi/dynamic.rs"]
mod dynamic;
#[path = "c_abi/fidelity.rs"]
mod fidelity;
#[path = "c_abi/friction.rs"]
mod friction;
#[path = "c_abi/hierarchical.rs"]
mod hierarchical;
#[path = "c_abi/homogenised.rs"]
mod homogenised;
#[path = "c_abi/indentation.rs"]
mod indentation;
#[path = "c_abi/lj_sphere.rs"]
mod lj_sphere;
#[path = "c_abi/material.rs"]
mod material;
#[path = "c_abi/slider.rs"]
mod slider;
#[path = "c_abi/statistics.rs"]
mod statistics;
#[path = "c_abi/status.rs"]
mod status;
#[path = "c_abi/surface.rs"]
mod surface;
#[path = "c_abi/tabulated.rs"]
mod tabulated;

use arbitrary::{Arbitrary, Unstructured};
use asperity::contact::ContactState;
use asperity::ffi::contact::AsperityNormalLaw;
use asperity::ffi::friction::{asperity_slider_geometry_free, AsperitySliderGeometry};
use asperity::ffi::friction_law::{
    asperity_friction_free, asperity_friction_work_free, AsperityFriction, AsperityFrictionWork,
};
use asperity::ffi::homogenised::{asperity_homogenised_friction_free, AsperityHomogenisedFriction};
use asperity::ffi::slider::{asperity_slider_free, AsperitySlider};
use asperity::ffi::statistics::{asperity_gw_empirical_free, AsperityGwEmpirical};
use asperity::ffi::tabulated::{asperity_table_free, AsperityTable};
use common::*;
use contact::OldState;
use dynamic::{DynIncSpec, Dynamic, Integrated, LugreSpec, MaxwellSpec, Placement, PtSpec};
use homogenised::{OldPoint, SampleSpec};
use indentation::{CurveSpec, OptionsSpec};
use slider::{GeometrySource, MaterialSpec, SceneSpec, SliderOptionsSpec};
use statistics::GwSpec;
use std::ptr::null_mut;

// ------------------------------------------------------------------ calls

/// One call (or a few related calls) of the C ABI.
#[derive(Debug, Clone, Arbitrary)]
pub enum Op {
    // Library, status and layout queries.
    Version,
    LastError {
        len: Len,
        null: bool,
    },
    StatusString(i32),
    TypeLayout {
        index: Big,
        name: Option<Vec<u8>>,
        nulls: Nulls,
    },
    TypeName {
        index: Big,
        len: Len,
        nulls: Nulls,
    },
    FlagName(u32),
    // Laws.
    Law {
        which: u8,
        a: [F; 5],
        sel: Sel,
        null: bool,
    },
    LawRaw {
        kind: Sel,
        raw: [F; 16],
    },
    LawTamper {
        law: u8,
        at: u8,
        value: F,
    },
    Eval {
        law: u8,
        delta: F,
        old: OldState,
        nulls: Nulls,
        alias: bool,
    },
    EvalBatch {
        law: u8,
        delta: Vec<F>,
        old: OldState,
        nulls: Nulls,
        alias: bool,
    },
    EvalAtLoad {
        law: u8,
        force: F,
        null: bool,
    },
    PullOff {
        law: u8,
        control: Sel,
        null: bool,
    },
    LengthScale {
        law: u8,
        null: bool,
    },
    // Tables.
    TableMd {
        a: [F; 5],
        null: bool,
    },
    TableLj {
        a: [F; 4],
        grid: Grid,
        tolerance: F,
        null: bool,
    },
    TableEval {
        table: u8,
        delta: F,
        old: OldState,
        nulls: Nulls,
    },
    TableEvalBatch {
        table: u8,
        delta: Vec<F>,
        old: OldState,
        nulls: Nulls,
        alias: bool,
    },
    TableEvalAtLoad {
        table: u8,
        force: F,
        null: bool,
    },
    TablePullOff {
        table: u8,
        control: Sel,
        null: bool,
    },
    TableMaxError {
        table: u8,
        nulls: Nulls,
    },
    TableToJson {
        table: u8,
        len: Len,
        nulls: Nulls,
    },
    TableFromJson {
        table: u8,
        mutation: Mutation,
        raw: Option<Vec<u8>>,
        nulls: Nulls,
    },
    TableFree {
        table: u8,
    },
    // Models, materials, Lennard-Jones.
    Fidelity {
        a: [F; 5],
        null: bool,
    },
    LjPullOff {
        a: [F; 4],
        grid: Grid,
        null: bool,
    },
    Material {
        which: u8,
        a: [F; 6],
        sel: Sel,
        null: bool,
    },
    // Indentation and rescaling.
    DefaultOptions {
        null: bool,
    },
    IndentFit {
        curve: CurveSpec,
        segments: Option<Vec<Sel>>,
        options: Option<OptionsSpec>,
        nulls: Nulls,
    },
    IndentFitRaw {
        depth: Vec<F>,
        load: Vec<F>,
        nulls: Nulls,
    },
    Rescaling {
        which: u8,
        a: [F; 6],
        null: bool,
    },
    // Statistics.
    Gw {
        gw: GwSpec,
        x: F,
        nulls: Nulls,
    },
    GwBatch {
        gw: GwSpec,
        x: Vec<F>,
        nulls: Nulls,
        alias: bool,
    },
    GwAtLoad {
        gw: GwSpec,
        load: F,
        nulls: Nulls,
    },
    GwPlasticity {
        gw: GwSpec,
        hardness: F,
        nulls: Nulls,
    },
    Plasticity {
        a: [F; 4],
        null: bool,
    },
    Regime {
        psi: F,
        null: bool,
    },
    GwEmpiricalNew {
        a: [F; 3],
        heights: Heights,
        radii: Option<Vec<F>>,
        nulls: Nulls,
    },
    GwEmpirical {
        gw: u8,
        which: u8,
        x: F,
        n: Vec<F>,
        nulls: Nulls,
    },
    GwEmpiricalFree {
        gw: u8,
    },
    Zhuravlev {
        model: [F; 4],
        which: u8,
        a: [F; 4],
        nulls: Nulls,
    },
    ZhuravlevEval {
        model: [F; 4],
        approach: F,
        n1: (u8, F),
        n2: (u8, F),
        order: Big,
        nulls: Nulls,
    },
    Bgt {
        p: [F; 5],
        which: u8,
        x: Vec<F>,
        nulls: Nulls,
    },
    Bora {
        a: [F; 4],
        nx: u8,
        heights: Heights,
        nulls: Nulls,
    },
    SergienkoBukharov {
        a: [F; 14],
        distribution: Sel,
        periods: [u8; 3],
        heights: Heights,
        nulls: Nulls,
    },
    // Surfaces.
    Roughness {
        h: Heights,
        dx: F,
        form: Sel,
        cutoff: F,
        sampling: F,
        nulls: Nulls,
    },
    RemoveForm {
        h: Heights,
        form: Sel,
        nulls: Nulls,
        alias: bool,
    },
    Filter {
        h: Heights,
        dx: F,
        cutoff: F,
        ends: Sel,
        nulls: Nulls,
        alias: bool,
    },
    MaterialRatio {
        h: Heights,
        points: Len,
        nulls: Nulls,
    },
    Psd {
        h: Heights,
        dx: F,
        window: Sel,
        n_q: Option<Len>,
        nulls: Nulls,
    },
    HurstFit {
        h: Heights,
        dx: F,
        q: [F; 2],
        nulls: Nulls,
    },
    Peaks {
        h: Heights,
        dx: F,
        nulls: Nulls,
    },
    SelfAffine {
        a: [F; 5],
        seed: u64,
        n: Len,
        null: bool,
    },
    Weierstrass {
        a: [F; 4],
        seed: u64,
        n: Len,
        null: bool,
    },
    Cantor {
        descendants: u32,
        a: [F; 4],
        levels: u32,
        n: Len,
        null: bool,
    },
    // Slider geometry.
    GeometryNew {
        micro: Heights,
        micro_dx: F,
        nano: Heights,
        nano_dx: F,
        widths: Vec<F>,
        nulls: Nulls,
    },
    GeometryUniform {
        width: F,
        rods: Big,
        nano: [F; 5],
        per_rod: Big,
        nulls: Nulls,
    },
    GeometryQuery {
        geometry: u8,
        which: u8,
        level: Big,
        len: Len,
        nulls: Nulls,
    },
    GeometryFree {
        geometry: u8,
    },
    // Homogenised friction.
    HomNew {
        samples: SampleSpec,
        nulls: Nulls,
    },
    HomNewRaw {
        samples: Vec<[F; 8]>,
        nulls: Nulls,
    },
    HomFromJson {
        friction: u8,
        mutation: Mutation,
        raw: Option<Vec<u8>>,
        nulls: Nulls,
    },
    HomToJson {
        friction: u8,
        len: Len,
        nulls: Nulls,
    },
    HomStep {
        friction: u8,
        inc: [F; 6],
        old: OldPoint,
        nulls: Nulls,
        alias: bool,
    },
    HomBlock {
        friction: u8,
        n: u8,
        inc: Vec<F>,
        dt: F,
        k: F,
        old: OldPoint,
        nulls: Nulls,
        alias: bool,
    },
    HomStateSize,
    HomFree {
        friction: u8,
    },
    // Slider.
    SliderNew {
        scene: SceneSpec,
        mutation: Mutation,
        base: u8,
        nulls: Nulls,
    },
    SliderQuery {
        slider: u8,
        which: u8,
        null: bool,
    },
    WorkNew {
        slider: u8,
        null: bool,
    },
    SliderStep {
        slider: u8,
        work: u8,
        inc: [F; 5],
        control: Sel,
        tangents: Sel,
        state: SliderState,
        in_place: bool,
        nulls: Nulls,
    },
    SliderBlock {
        slider: u8,
        work: u8,
        n: u8,
        inc: Vec<F>,
        dt: F,
        state: SliderState,
        in_place: bool,
        nulls: Nulls,
    },
    SliderFree {
        slider: u8,
    },
    WorkFree {
        work: u8,
    },
    // Slider from structs.
    SliderOptionsDefault {
        null: bool,
    },
    MaterialCopper {
        null: bool,
    },
    SliderFromStructs {
        geometry: GeometrySource,
        material: MaterialSpec,
        counter: Option<(Heights, F)>,
        options: Option<SliderOptionsSpec>,
        nulls: Nulls,
    },
    // Dynamic friction.
    LugreNew {
        params: LugreSpec,
        nulls: Nulls,
    },
    /// Maxwell-slip elements, or bristles (the second array as break
    /// deflections, m) when `bristles`.
    MaxwellNew {
        elements: MaxwellSpec,
        sigma2: F,
        nulls: Nulls,
        bristles: bool,
    },
    /// An integrated model: one-spring Prandtl–Tomlinson (`params`), or
    /// the struct-built two-spring model or Burridge–Knopoff chain. (New
    /// models extend these payloads rather than `Op`: a new variant would
    /// change how every committed input decodes.)
    PtNew {
        params: PtSpec,
        null: bool,
        variant: Integrated,
    },
    DynStateSize {
        model: u8,
        null: bool,
    },
    DynStep {
        model: u8,
        inc: DynIncSpec,
        tangents: Sel,
        reserved: Sel,
        state: SliderState,
        placement: Placement,
        nulls: Nulls,
    },
    DynBlock {
        model: u8,
        n: u8,
        inc: Vec<F>,
        dt: Option<F>,
        state: SliderState,
        nulls: Nulls,
    },
    DynFree {
        model: u8,
    },
    // Reach and energy (added last: the existing corpus keeps its meaning).
    Reach {
        law: u8,
        control: Sel,
        rel_force: F,
        null: bool,
    },
    Energy {
        law: u8,
        delta: F,
        old: OldState,
        null: bool,
    },
    TableReach {
        table: u8,
        control: Sel,
        rel_force: F,
        null: bool,
    },
    // A law from its inputs (added last: the existing corpus keeps its
    // meaning).
    LawFromParams {
        kind: Sel,
        raw: [F; 16],
        nulls: Nulls,
    },
    // AFM force curves (added last: the existing corpus keeps its meaning).
    AfmFlagName(u32),
    AfmAnalyze {
        curve: afm::AfmSpec,
        input_kind: Sel,
        retract_start: u8,
        spring_constant: F,
        tip_radius: F,
        model: Sel,
        nulls: Nulls,
    },
    // The generalised Maxwell-slip model and the hierarchical roughness
    // functions (added last: the existing corpus keeps its meaning).
    GmsNew {
        elements: MaxwellSpec,
        params: [F; 6],
        nulls: Nulls,
    },
    Archard {
        model: Sel,
        radii: Vec<F>,
        densities: Vec<F>,
        modulus: F,
        loads: Vec<F>,
        generations: u8,
        nulls: Nulls,
    },
    CantorContact {
        descendants: u32,
        generations: u32,
        a: [F; 6],
        depths: Vec<F>,
        nulls: Nulls,
    },
    // Borodich–Kryukova and Schmittbuhl (added last: the existing corpus
    // keeps its meaning).
    BorodichKryukova {
        a: [F; 12],
        nodes: u16,
        start: [F; 5],
        dt: F,
        steps: u8,
        every: u8,
        room: u8,
        nulls: Nulls,
    },
    Schmittbuhl {
        a: [F; 9],
        ratio: u8,
        generations: u8,
        dimension: u8,
        room: u8,
        nulls: Nulls,
    },
    // Maps: the areal Gaussian filter and the radial 2-D PSD (added last:
    // the existing corpus keeps its meaning).
    MapFilter {
        h: Heights,
        nx: u8,
        d: [F; 3],
        ends: Sel,
        nulls: Nulls,
    },
    MapPsdRadial {
        h: Heights,
        nx: u8,
        d: [F; 2],
        window: Sel,
        room: u8,
        nulls: Nulls,
    },
}

/// The handles and carried states of one input; all freed on drop.
#[derive(Default)]
struct Ctx {
    laws: Vec<AsperityNormalLaw>,
    state: ContactState,
    tables: Vec<*mut AsperityTable>,
    gws: Vec<*mut AsperityGwEmpirical>,
    geometries: Vec<*mut AsperitySliderGeometry>,
    frictions: Vec<*mut AsperityHomogenisedFriction>,
    /// The carried state of a homogenised law (9 doubles, or empty).
    point: Vec<f64>,
    sliders: Vec<*mut AsperitySlider>,
    /// The friction law of each slider (`slider_laws[i]` of `sliders[i]`).
    slider_laws: Vec<*mut AsperityFriction>,
    works: Vec<*mut AsperityFrictionWork>,
    slider_state: Vec<f64>,
    dynamics: Vec<Dynamic>,
    dynamic_state: Vec<f64>,
    expensive: u32,
}

impl Drop for Ctx {
    fn drop(&mut self) {
        unsafe {
            self.tables.drain(..).for_each(|p| asperity_table_free(p));
            self.gws
                .drain(..)
                .for_each(|p| asperity_gw_empirical_free(p));
            self.geometries
                .drain(..)
                .for_each(|p| asperity_slider_geometry_free(p));
            self.frictions
                .drain(..)
                .for_each(|p| asperity_homogenised_friction_free(p));
            self.works
                .drain(..)
                .for_each(|p| asperity_friction_work_free(p));
            self.slider_laws
                .drain(..)
                .for_each(|p| asperity_friction_free(p));
            self.sliders.drain(..).for_each(|p| asperity_slider_free(p));
            self.dynamics
                .drain(..)
                .for_each(|d| asperity_friction_free(d.model));
        }
    }
}

/// Element `sel` of `v`, or NULL for 255 or an empty `v`.
fn pick<T>(v: &[*mut T], sel: u8) -> *mut T {
    if sel == 255 || v.is_empty() {
        null_mut()
    } else {
        v[sel as usize % v.len()]
    }
}

fn take<T>(v: &mut Vec<*mut T>, sel: u8) -> Option<*mut T> {
    if v.is_empty() {
        None
    } else {
        let i = sel as usize % v.len();
        Some(v.swap_remove(i))
    }
}

impl Ctx {
    /// Whether a call of about `substeps` integration sub-steps may run: a
    /// cheap one always, an expensive one once per input (the library's own
    /// bound, `MAX_SUBSTEPS` = 10^6 per integration, makes each call take up
    /// to a second).
    fn affordable(&mut self, substeps: f64) -> bool {
        if substeps <= 2e4 {
            return true;
        }
        if self.expensive > 0 {
            return false;
        }
        self.expensive += 1;
        true
    }
}

/// One operation, run by the module of its `src/ffi/` domain.
unsafe fn call(ctx: &mut Ctx, op: &Op) {
    match op {
        Op::Version | Op::LastError { .. } | Op::StatusString(_) => status::call(op),
        Op::TypeLayout { .. } | Op::TypeName { .. } => abi::call(op),
        Op::Law { .. }
        | Op::LawRaw { .. }
        | Op::LawTamper { .. }
        | Op::Eval { .. }
        | Op::EvalBatch { .. }
        | Op::EvalAtLoad { .. }
        | Op::PullOff { .. }
        | Op::LengthScale { .. }
        | Op::Reach { .. }
        | Op::Energy { .. }
        | Op::LawFromParams { .. } => contact::call(ctx, op),
        Op::TableMd { .. }
        | Op::TableLj { .. }
        | Op::TableEval { .. }
        | Op::TableEvalBatch { .. }
        | Op::TableEvalAtLoad { .. }
        | Op::TablePullOff { .. }
        | Op::TableMaxError { .. }
        | Op::TableToJson { .. }
        | Op::TableFromJson { .. }
        | Op::TableFree { .. }
        | Op::TableReach { .. } => tabulated::call(ctx, op),
        Op::Fidelity { .. } => fidelity::call(op),
        Op::AfmFlagName(_) | Op::AfmAnalyze { .. } => afm::call(op),
        Op::LjPullOff { .. } => lj_sphere::call(ctx, op),
        Op::Material { .. } => material::call(op),
        Op::FlagName(_)
        | Op::DefaultOptions { .. }
        | Op::IndentFit { .. }
        | Op::IndentFitRaw { .. }
        | Op::Rescaling { .. } => indentation::call(op),
        Op::Gw { .. }
        | Op::GwBatch { .. }
        | Op::GwAtLoad { .. }
        | Op::GwPlasticity { .. }
        | Op::Plasticity { .. }
        | Op::Regime { .. }
        | Op::GwEmpiricalNew { .. }
        | Op::GwEmpirical { .. }
        | Op::GwEmpiricalFree { .. }
        | Op::Zhuravlev { .. }
        | Op::ZhuravlevEval { .. }
        | Op::Bgt { .. }
        | Op::Bora { .. }
        | Op::SergienkoBukharov { .. } => statistics::call(ctx, op),
        Op::Roughness { .. }
        | Op::RemoveForm { .. }
        | Op::Filter { .. }
        | Op::MaterialRatio { .. }
        | Op::Psd { .. }
        | Op::HurstFit { .. }
        | Op::Peaks { .. }
        | Op::SelfAffine { .. }
        | Op::Weierstrass { .. }
        | Op::Cantor { .. } => surface::call(op),
        Op::GeometryNew { .. }
        | Op::GeometryUniform { .. }
        | Op::GeometryQuery { .. }
        | Op::GeometryFree { .. } => friction::call(ctx, op),
        Op::HomNew { .. }
        | Op::HomNewRaw { .. }
        | Op::HomFromJson { .. }
        | Op::HomToJson { .. }
        | Op::HomStep { .. }
        | Op::HomBlock { .. }
        | Op::HomStateSize
        | Op::HomFree { .. } => homogenised::call(ctx, op),
        Op::SliderNew { .. }
        | Op::SliderQuery { .. }
        | Op::WorkNew { .. }
        | Op::SliderStep { .. }
        | Op::SliderBlock { .. }
        | Op::SliderFree { .. }
        | Op::WorkFree { .. }
        | Op::SliderOptionsDefault { .. }
        | Op::MaterialCopper { .. }
        | Op::SliderFromStructs { .. } => slider::call(ctx, op),
        Op::LugreNew { .. }
        | Op::MaxwellNew { .. }
        | Op::PtNew { .. }
        | Op::DynStateSize { .. }
        | Op::DynStep { .. }
        | Op::DynBlock { .. }
        | Op::DynFree { .. }
        | Op::GmsNew { .. } => dynamic::call(ctx, op),
        Op::Archard { .. } | Op::CantorContact { .. } => hierarchical::call(op),
        Op::BorodichKryukova { .. } => statistics::call(ctx, op),
        Op::Schmittbuhl { .. } => hierarchical::call_schmittbuhl(ctx, op),
        Op::MapFilter { .. } | Op::MapPsdRadial { .. } => surface::call(op),
    }
}

/// Most calls per input.
const MAX_OPS: usize = 48;

pub fn run(data: &[u8]) {
    let mut u = Unstructured::new(data);
    let mut ctx = Ctx::default();
    let debug = debug();
    for _ in 0..MAX_OPS {
        if u.is_empty() {
            break;
        }
        let Ok(op) = Op::arbitrary(&mut u) else {
            break;
        };
        if debug {
            eprintln!("{op:?}");
        }
        // SAFETY: every pointer the harness passes is NULL or a live buffer
        // of the stated length; handles are live until freed once.
        unsafe { call(&mut ctx, &op) };
    }
}
