//! C ABI for `crate::friction::slider`: the full hierarchical slider as the
//! friction step per time increment of a surface patch.
//!
//! * `AsperitySlider` (opaque, a boxed [`Slider`]) is built from a scene's
//!   JSON text ([`Scene::from_json`], [`Scene::build`]) or from structs
//!   (`asperity_slider_new`: a geometry handle, `AsperityFrictionMaterial`,
//!   a counter-surface array, `AsperitySliderOptions`); immutable, one
//!   handle may be used by any number of threads at once.
//! * `AsperitySliderWork` (opaque, a boxed [`SliderWork`]) holds the
//!   scratch buffers of a step: one per thread, built once.
//! * Per-patch states are caller-owned arrays of
//!   `asperity_slider_state_size` doubles (all-zero = fresh; layout:
//!   the `ASPERITY_SLIDER_STATE_*` indices, [`Slider::state_len`]).
//! * `asperity_slider_step` steps one patch with every output and optional
//!   tangents; `asperity_slider_step_block` steps n patches in the shape of
//!   Abaqus/Explicit VFRIC (as `asperity_homogenised_friction_step_block`).
//!
//! Sign convention (as VFRIC and the homogenised law): the slip increment
//! is the motion of the patch relative to the counter-surface, the
//! tangential force is the force on the patch and opposes slip.

use super::friction::AsperitySliderGeometry;
use super::{guard, input, output, partial_overlap, read_text, set_last_error, Failure};
use crate::error::{Error, Result};
use crate::friction::{
    CofForm, FrictionMaterial, Loading, Mechanisms, PlasticUpdate, RodOptions, RodSolver, Slider,
    SliderIncrement, SliderOptions, SliderResponse, SliderStates, SliderTangents, SliderWork,
    TrackEnd,
};
use crate::scene::{Scene, SceneError};
use std::ffi::{c_char, CStr};

/// `AsperitySliderIncrement.control`: the slider's own loading (the
/// scene's); `normal_force` and `gap` are ignored.
pub const ASPERITY_SLIDER_CONTROL_SCENE: i32 = 0;
/// `AsperitySliderIncrement.control`: fixed load `normal_force` (N).
pub const ASPERITY_SLIDER_CONTROL_LOAD: i32 = 1;
/// `AsperitySliderIncrement.control`: fixed gap, the slider's mean line at
/// `gap` (m) above the counter-surface's mean line.
pub const ASPERITY_SLIDER_CONTROL_GAP: i32 = 2;

/// `AsperitySliderIncrement.tangents` bit: compute dF/dN.
pub const ASPERITY_SLIDER_TANGENT_NORMAL: i32 = 1;
/// `AsperitySliderIncrement.tangents` bit: compute dF/d(slip).
pub const ASPERITY_SLIDER_TANGENT_SLIP: i32 = 2;

/// `AsperitySliderOptions.mechanisms` bit: breaking of chemical bonds (4.1).
pub const ASPERITY_MECHANISM_CHEMICAL: i32 = 1;
/// `AsperitySliderOptions.mechanisms` bit: breaking of van der Waals bonds
/// (4.2).
pub const ASPERITY_MECHANISM_VAN_DER_WAALS: i32 = 2;
/// `AsperitySliderOptions.mechanisms` bit: elastic strain energy released by
/// unloading rods (4-15).
pub const ASPERITY_MECHANISM_ELASTIC: i32 = 4;
/// `AsperitySliderOptions.mechanisms` bit: plastic work of yielding rods
/// (4-16).
pub const ASPERITY_MECHANISM_PLASTIC: i32 = 8;
/// `AsperitySliderOptions.mechanisms`: every mechanism (the default).
pub const ASPERITY_MECHANISM_ALL: i32 = 15;

/// `AsperitySliderOptions.cof_form`: Derjaguin, mu = F/(N + A) (4-3), the
/// default.
pub const ASPERITY_COF_DERJAGUIN: i32 = 0;
/// `AsperitySliderOptions.cof_form`: Amontons, mu = F/N (1-1).
pub const ASPERITY_COF_AMONTONS: i32 = 1;
/// `AsperitySliderOptions.cof_form`: Coulomb, mu = (F - A)/N (1-2).
pub const ASPERITY_COF_COULOMB: i32 = 2;

/// `AsperitySliderOptions.plastic`: the volume of a yielded rod goes in
/// halves to the nearest non-yielded rod on each side (thesis 6.2.3), the
/// default.
pub const ASPERITY_PLASTIC_NEAREST_NEIGHBOURS: i32 = 0;
/// `AsperitySliderOptions.plastic`: Gaussian weights of width
/// `plastic_width` over the non-yielded rods (the thesis's proposed
/// weighting function; the chapter-6 scenes use 20 um).
pub const ASPERITY_PLASTIC_GAUSSIAN: i32 = 1;
/// `AsperitySliderOptions.plastic`: yielded rods shorten, no pile-up
/// (volume not conserved).
pub const ASPERITY_PLASTIC_SHORTEN_ONLY: i32 = 2;

/// `AsperitySliderOptions.solver`: exact O(n log n) sweep of the rod
/// equilibrium, warm-started (the default).
pub const ASPERITY_ROD_SOLVER_SWEEP: i32 = 0;
/// `AsperitySliderOptions.solver`: the thesis's dense formulation
/// (6-12)/(6-16), iterated over active sets (reference; allocates).
pub const ASPERITY_ROD_SOLVER_DENSE: i32 = 1;

/// Index in a slider state of its flag: 0 fresh, 1 stepped.
pub const ASPERITY_SLIDER_STATE_FLAG: usize = 0;
/// Index in a slider state of the slider position X along its track (m).
/// A fresh state (flag 0) starts there: set it to place patches at
/// different points of the counter-surface.
pub const ASPERITY_SLIDER_STATE_POSITION: usize = 1;
/// Index in a slider state of the rod-bed position b of the last
/// equilibrium (m; NaN: none).
pub const ASPERITY_SLIDER_STATE_ROD_POSITION: usize = 2;
/// Index in a slider state of the accumulated slip path (m).
pub const ASPERITY_SLIDER_STATE_SLIP_PATH: usize = 3;
/// Index in a slider state of the accumulated dissipation (J), 4 values:
/// chemical, van der Waals, elastic, plastic.
pub const ASPERITY_SLIDER_STATE_DISSIPATION: usize = 4;
/// Index in a slider state of the rod heights (m, one per rod), followed by
/// the rods' stored elastic energies (J, one per rod).
pub const ASPERITY_SLIDER_STATE_HEIGHTS: usize = 8;

const _: () = {
    assert!(ASPERITY_SLIDER_TANGENT_NORMAL == SliderTangents::NORMAL);
    assert!(ASPERITY_SLIDER_TANGENT_SLIP == SliderTangents::SLIP);
    assert!(ASPERITY_SLIDER_STATE_FLAG == Slider::STATE_FLAG);
    assert!(ASPERITY_SLIDER_STATE_POSITION == Slider::STATE_POSITION);
    assert!(ASPERITY_SLIDER_STATE_ROD_POSITION == Slider::STATE_ROD_POSITION);
    assert!(ASPERITY_SLIDER_STATE_SLIP_PATH == Slider::STATE_SLIP_PATH);
    assert!(ASPERITY_SLIDER_STATE_DISSIPATION == Slider::STATE_DISSIPATION);
    assert!(ASPERITY_SLIDER_STATE_HEIGHTS == Slider::STATE_HEIGHTS);
};

/// The hierarchical slider against its counter-surface (opaque). Create it
/// with `asperity_slider_from_scene_json`, release it with
/// `asperity_slider_free`. Immutable; safe to share between threads.
pub struct AsperitySlider(Slider);

/// Scratch buffers of the slider step (opaque): one per thread. Create it
/// with `asperity_slider_work_new`, release it with
/// `asperity_slider_work_free`.
pub struct AsperitySliderWork(SliderWork);

/// One time increment of a slider patch. SI units. An all-zero increment
/// seats a fresh patch under the scene's loading without sliding.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperitySliderIncrement {
    /// Normal force on the patch (N), finite, >= 0 and <= the capacity
    /// (`AsperitySliderInfo.capacity`); read when `control` is
    /// `ASPERITY_SLIDER_CONTROL_LOAD`.
    pub normal_force: f64,
    /// Position of the slider's mean line above the counter-surface's mean
    /// line (m), finite; read when `control` is `ASPERITY_SLIDER_CONTROL_GAP`.
    pub gap: f64,
    /// Slip increment of the patch relative to the counter-surface (m), two
    /// finite components in the caller's tangent basis; a track uses
    /// `slip[1] = 0`. The slider advances along its track by |slip|.
    pub slip: [f64; 2],
    /// Time increment (s), finite and >= 0 (unused: rate independent).
    pub dt: f64,
    /// `ASPERITY_SLIDER_CONTROL_SCENE` (0), `_LOAD` (1) or `_GAP` (2).
    pub control: i32,
    /// Tangents wanted: 0, or `ASPERITY_SLIDER_TANGENT_NORMAL` |
    /// `ASPERITY_SLIDER_TANGENT_SLIP` (each costs two more evaluations).
    pub tangents: i32,
}

impl AsperitySliderIncrement {
    fn increment(&self) -> Result<SliderIncrement> {
        let loading = match self.control {
            ASPERITY_SLIDER_CONTROL_SCENE => None,
            ASPERITY_SLIDER_CONTROL_LOAD => Some(Loading::FixedLoad {
                load: self.normal_force,
            }),
            ASPERITY_SLIDER_CONTROL_GAP => Some(Loading::FixedGap { position: self.gap }),
            other => {
                return Err(Error::UnknownSelector {
                    name: "control",
                    value: other as i64,
                })
            }
        };
        Ok(SliderIncrement {
            loading,
            slip: self.slip,
            dt: self.dt,
            tangents: SliderTangents::from_bits(self.tangents)?,
        })
    }
}

/// What a slider is: sizes and capacities (SI).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperitySliderInfo {
    /// Doubles per patch state (8 + 2 x rods).
    pub state_size: usize,
    /// Number of rods (micro-asperities of the finest level).
    pub rods: usize,
    /// Nano-asperities per rod.
    pub nano_per_rod: usize,
    /// Samples of the counter-surface profile.
    pub counter_samples: usize,
    /// Rod width along the track (m).
    pub rod_width: f64,
    /// Rod depth across the track (m).
    pub depth: f64,
    /// Nominal area of the patch, rods x width x depth (m^2).
    pub nominal_area: f64,
    /// Load capacity of the rods, n sigma_y A (N): the largest normal force.
    pub capacity: f64,
    /// Counter-surface sample spacing (m).
    pub counter_dx: f64,
    /// The scene's loading value: its load (N) or gap (m), per
    /// `scene_control`.
    pub scene_loading: f64,
    /// The scene's loading: `ASPERITY_SLIDER_CONTROL_LOAD` or `_GAP`.
    pub scene_control: i32,
    /// 1 when the counter-surface repeats past its end, 0 when running
    /// past it is an error.
    pub periodic: i32,
}

/// How `asperity_slider_new` builds a slider (SI units). Start from
/// `asperity_slider_options_default`, then set the loading.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AsperitySliderOptions {
    /// Fixed load (N), finite, >= 0 and <= the capacity n sigma_y A; read
    /// when `control` is `ASPERITY_SLIDER_CONTROL_LOAD`.
    pub normal_force: f64,
    /// Fixed gap: the slider's mean line this far above the
    /// counter-surface's mean line (m), finite; read when `control` is
    /// `ASPERITY_SLIDER_CONTROL_GAP`.
    pub gap: f64,
    /// Width of the Gaussian pile-up weights (m), finite and > 0; read when
    /// `plastic` is `ASPERITY_PLASTIC_GAUSSIAN`.
    pub plastic_width: f64,
    /// Rod depth across the track (m), finite and > 0, at least the
    /// nano-asperity spacing; 0 = square rods (the rod width).
    pub depth: f64,
    /// Margin of the rod roots below the deepest rod (m), finite and >= 0;
    /// negative = the rod width.
    pub root_margin: f64,
    /// `ASPERITY_SLIDER_CONTROL_LOAD` (1) or `ASPERITY_SLIDER_CONTROL_GAP`
    /// (2).
    pub control: i32,
    /// `ASPERITY_MECHANISM_*` bits: the mechanisms computed (0 = none; the
    /// default `ASPERITY_MECHANISM_ALL`).
    pub mechanisms: i32,
    /// `ASPERITY_COF_DERJAGUIN` (default), `_AMONTONS` or `_COULOMB`.
    pub cof_form: i32,
    /// `ASPERITY_PLASTIC_NEAREST_NEIGHBOURS` (default), `_GAUSSIAN` or
    /// `_SHORTEN_ONLY`.
    pub plastic: i32,
    /// `ASPERITY_ROD_SOLVER_SWEEP` (default) or `_DENSE`.
    pub solver: i32,
    /// 1: the counter-surface repeats with period n x counter_dx; 0 (default):
    /// running past its end is an error.
    pub periodic: i32,
}

impl AsperitySliderOptions {
    /// The library's defaults ([`SliderOptions::new`]) with a zero fixed
    /// load.
    fn defaults() -> Self {
        Self {
            normal_force: 0.0,
            gap: 0.0,
            plastic_width: 0.0,
            depth: 0.0,
            root_margin: -1.0,
            control: ASPERITY_SLIDER_CONTROL_LOAD,
            mechanisms: ASPERITY_MECHANISM_ALL,
            cof_form: ASPERITY_COF_DERJAGUIN,
            plastic: ASPERITY_PLASTIC_NEAREST_NEIGHBOURS,
            solver: ASPERITY_ROD_SOLVER_SWEEP,
            periodic: 0,
        }
    }

    fn options(&self) -> Result<SliderOptions> {
        let selector = |name: &'static str, value: i32| Error::UnknownSelector {
            name,
            value: value as i64,
        };
        let loading = match self.control {
            ASPERITY_SLIDER_CONTROL_LOAD => Loading::FixedLoad {
                load: self.normal_force,
            },
            ASPERITY_SLIDER_CONTROL_GAP => Loading::FixedGap { position: self.gap },
            other => return Err(selector("options.control", other)),
        };
        if self.mechanisms & !ASPERITY_MECHANISM_ALL != 0 {
            return Err(selector("options.mechanisms", self.mechanisms));
        }
        let bit = |b: i32| self.mechanisms & b != 0;
        let mechanisms = Mechanisms {
            chemical: bit(ASPERITY_MECHANISM_CHEMICAL),
            van_der_waals: bit(ASPERITY_MECHANISM_VAN_DER_WAALS),
            elastic: bit(ASPERITY_MECHANISM_ELASTIC),
            plastic: bit(ASPERITY_MECHANISM_PLASTIC),
        };
        let cof_form = match self.cof_form {
            ASPERITY_COF_DERJAGUIN => CofForm::Derjaguin,
            ASPERITY_COF_AMONTONS => CofForm::Amontons,
            ASPERITY_COF_COULOMB => CofForm::Coulomb,
            other => return Err(selector("options.cof_form", other)),
        };
        let plastic = match self.plastic {
            ASPERITY_PLASTIC_NEAREST_NEIGHBOURS => PlasticUpdate::NearestNeighbours,
            ASPERITY_PLASTIC_GAUSSIAN => PlasticUpdate::Gaussian {
                width: self.plastic_width,
            },
            ASPERITY_PLASTIC_SHORTEN_ONLY => PlasticUpdate::ShortenOnly,
            other => return Err(selector("options.plastic", other)),
        };
        let solver = match self.solver {
            ASPERITY_ROD_SOLVER_SWEEP => RodSolver::Sweep,
            ASPERITY_ROD_SOLVER_DENSE => RodSolver::Dense,
            other => return Err(selector("options.solver", other)),
        };
        let track_end = match self.periodic {
            0 => TrackEnd::Error,
            1 => TrackEnd::Periodic,
            other => return Err(selector("options.periodic", other)),
        };
        let depth = if self.depth == 0.0 {
            None
        } else {
            Some(self.depth)
        };
        let root_margin = if self.root_margin < 0.0 {
            None
        } else {
            Some(self.root_margin)
        };
        Ok(SliderOptions {
            loading,
            rod: RodOptions {
                solver,
                plastic,
                ..RodOptions::default()
            },
            mechanisms,
            cof_form,
            depth,
            root_margin,
            track_end,
        })
    }
}

/// Write the library's default slider options to `*out`: fixed load 0 N
/// (set `normal_force`), every mechanism, the Derjaguin COF, the thesis's
/// nearest-neighbour pile-up, the exact sweep, square rods, root margin =
/// the rod width, a non-periodic counter-surface.
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_options_default(out: *mut AsperitySliderOptions) -> i32 {
    guard(|| {
        *output(out, "out")? = AsperitySliderOptions::defaults();
        Ok(())
    })
}

/// Write the thesis's Cu–Cu friction material (REFERENCE.md §5:
/// sigma_y = 276 MPa, E = 120 GPa, nu = 0.355 for both bodies, D_chem =
/// 2.56 A, U_chem = 3.35429e-19 J, U_vdW = U_chem/100, W12 = 0.10928 J/m^2,
/// adhesive layer 5 nm, threshold strain 0.10, N_A = 1.53e19 m^-2) to
/// `*out`.
#[no_mangle]
pub unsafe extern "C" fn asperity_friction_material_copper(out: *mut FrictionMaterial) -> i32 {
    guard(|| {
        *output(out, "out")? = FrictionMaterial::copper();
        Ok(())
    })
}

/// Build a slider from structs: the rods and nano-asperities of `geometry`
/// (copied; the handle stays the caller's), the friction `material`, the
/// rigid counter-surface `counter` (`n_counter` >= 2 heights from its mean
/// line, m) sampled at `counter_dx` (m), and `options`. Writes a new handle
/// to `*out` (NULL on failure). Equivalent to a scene with the same
/// profiles and settings. Errors: NULL pointers; the material's bounds
/// (each field named); `counter_dx` not finite and > 0; a non-finite
/// counter height; a counter-surface too short to lie under the slider
/// (unless periodic); unknown selectors (`control`, `mechanisms`,
/// `cof_form`, `plastic`, `solver`, `periodic`); the loading, `depth`,
/// `root_margin` and `plastic_width` bounds of `AsperitySliderOptions`;
/// more than 2^24 nano-asperities per rod, floor(width/spacing) *
/// floor(depth/spacing) (`spacing`, or `options.depth`).
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_new(
    geometry: *const AsperitySliderGeometry,
    material: *const FrictionMaterial,
    counter: *const f64,
    n_counter: usize,
    counter_dx: f64,
    options: *const AsperitySliderOptions,
    out: *mut *mut AsperitySlider,
) -> i32 {
    guard(|| {
        let out = output(out, "out")?;
        *out = core::ptr::null_mut();
        let geometry = input(geometry, "geometry")?.0.clone();
        let material = *input(material, "material")?;
        let counter = input(counter, "counter")?;
        // SAFETY: the caller provides `n_counter` readable values at `counter`.
        let counter = core::slice::from_raw_parts(counter, n_counter).to_vec();
        let options = input(options, "options")?.options()?;
        let slider =
            Slider::new(geometry, material, counter, counter_dx, options).map_err(c_names)?;
        *out = Box::into_raw(Box::new(AsperitySlider(slider)));
        Ok(())
    })
}

/// A `Slider::new` error with the argument named as `asperity_slider_new`
/// names it.
fn c_names(e: Error) -> Error {
    [
        ("load", "options.normal_force"),
        ("position", "options.gap"),
        ("width", "options.plastic_width"),
        ("depth", "options.depth"),
        ("root_margin", "options.root_margin"),
        ("counter.len()", "n_counter"),
    ]
    .into_iter()
    .fold(e, |e, (from, to)| e.renamed(from, to))
}

/// The library error a scene error maps to, and its full message.
fn scene_failure(e: &SceneError) -> Error {
    match e {
        SceneError::Json { line, .. } => Error::Parse {
            what: "a scene (JSON syntax, unknown or missing field, or wrong type)",
            line: *line as u64,
        },
        SceneError::Invalid { error, .. } | SceneError::File { error, .. } => *error,
    }
}

/// Build a slider from the scene JSON text of `len` bytes at `json` (UTF-8,
/// no NUL needed; the format of `examples/scenes/*.json`). Relative file
/// paths in the scene are resolved against `base_dir` (a NUL-terminated
/// UTF-8 directory path), or against the current directory when `base_dir`
/// is NULL. The scene's `sliding`, `outputs`, `load_sweep` and
/// `friction_models` are validated but unused by the step. Writes a new
/// handle to `*out` (NULL on failure). Errors: NULL `json` or `out`;
/// invalid UTF-8 (`json`, `base_dir`);
/// `ASPERITY_ERR_PARSE` for a JSON or field error (the message gives line,
/// column and the field); the scene's value errors naming the field; a
/// file the scene names that cannot be read (`ASPERITY_ERR_IO`).
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_from_scene_json(
    json: *const c_char,
    len: usize,
    base_dir: *const c_char,
    out: *mut *mut AsperitySlider,
) -> i32 {
    let mut detail = None;
    let status = guard(|| {
        let out = output(out, "out")?;
        *out = core::ptr::null_mut();
        let text = read_text(json, len, "json")?;
        let base = if base_dir.is_null() {
            "."
        } else {
            CStr::from_ptr(base_dir)
                .to_str()
                .map_err(|e| Error::InvalidArgument {
                    name: "base_dir",
                    value: e.valid_up_to() as f64,
                    bound: "UTF-8 text (invalid byte at this offset)",
                })?
        };
        let built = Scene::from_json(text, base).and_then(|s| s.build());
        match built {
            Ok(slider) => {
                *out = Box::into_raw(Box::new(AsperitySlider(slider)));
                Ok(())
            }
            Err(e) => {
                let error = scene_failure(&e);
                detail = Some(e.to_string());
                Err(Failure::from(error))
            }
        }
    });
    if let Some(d) = detail {
        if status != super::ASPERITY_OK && status != super::ASPERITY_ERR_INTERNAL {
            set_last_error(format!("`json`: {d}"));
        }
    }
    status
}

/// Release a slider; NULL is accepted and ignored.
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_free(slider: *mut AsperitySlider) {
    if !slider.is_null() {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            drop(Box::from_raw(slider));
        }));
    }
}

/// Write the number of doubles of one patch state (8 + 2 x rods) to `*n`.
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_state_size(
    slider: *const AsperitySlider,
    n: *mut usize,
) -> i32 {
    guard(|| {
        let s = &input(slider, "slider")?.0;
        *output(n, "n")? = s.state_len();
        Ok(())
    })
}

/// Write the sizes and capacities of `slider` to `*info`.
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_info(
    slider: *const AsperitySlider,
    info: *mut AsperitySliderInfo,
) -> i32 {
    guard(|| {
        let s = &input(slider, "slider")?.0;
        let info = output(info, "info")?;
        let (scene_control, scene_loading) = match s.options().loading {
            Loading::FixedLoad { load } => (ASPERITY_SLIDER_CONTROL_LOAD, load),
            Loading::FixedGap { position } => (ASPERITY_SLIDER_CONTROL_GAP, position),
        };
        *info = AsperitySliderInfo {
            state_size: s.state_len(),
            rods: s.rods(),
            nano_per_rod: s.nano_per_rod(),
            counter_samples: s.counter().len(),
            rod_width: s.rod_width(),
            depth: s.depth(),
            nominal_area: s.nominal_area(),
            capacity: s.capacity(),
            counter_dx: s.counter_dx(),
            scene_loading,
            scene_control,
            periodic: (s.options().track_end == TrackEnd::Periodic) as i32,
        };
        Ok(())
    })
}

/// Build the scratch buffers of a step with `slider` and write the handle to
/// `*out` (NULL on failure). Use one per thread; it may serve any slider
/// with the same number of rods.
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_work_new(
    slider: *const AsperitySlider,
    out: *mut *mut AsperitySliderWork,
) -> i32 {
    guard(|| {
        let out = output(out, "out")?;
        *out = core::ptr::null_mut();
        let s = &input(slider, "slider")?.0;
        *out = Box::into_raw(Box::new(AsperitySliderWork(s.work())));
        Ok(())
    })
}

/// Release work buffers; NULL is accepted and ignored.
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_work_free(work: *mut AsperitySliderWork) {
    if !work.is_null() {
        let _ = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            drop(Box::from_raw(work));
        }));
    }
}

/// One friction step of one patch: the increment `*increment` from the
/// state `old_state` (`asperity_slider_state_size` doubles; all-zero =
/// fresh: seated first under the increment's loading) into `new_state`
/// (same size; may equal `old_state` to step in place, must not partially
/// overlap it) and the response into `*out`. The same old state and
/// increment give bit-identical results, so a host can re-evaluate or cut
/// back an increment. See `Slider::step_flat` for the zero-slip rule (stick:
/// force 0, nothing dissipated) and the finite-difference tangents. No
/// allocation. On failure `new_state` and `*out` are untouched; the message
/// names the argument and its bound.
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_step(
    slider: *const AsperitySlider,
    work: *mut AsperitySliderWork,
    increment: *const AsperitySliderIncrement,
    old_state: *const f64,
    new_state: *mut f64,
    out: *mut SliderResponse,
) -> i32 {
    guard(|| {
        let s = &input(slider, "slider")?.0;
        let w = &mut output(work, "work")?.0;
        let inc = input(increment, "increment")?.increment()?;
        input(old_state, "old_state")?;
        output(new_state, "new_state")?;
        let out = output(out, "out")?;
        let n = s.state_len();
        if partial_overlap(old_state, new_state, n) {
            return Err(Error::InvalidArgument {
                name: "new_state",
                value: 0.0,
                bound: "equal to old_state (in place) or not overlapping it",
            }
            .into());
        }
        // SAFETY: the caller provides `n` doubles at each pointer; equal
        // pointers are one mutable slice, otherwise they do not overlap.
        let r = if core::ptr::eq(old_state, new_state) {
            let state = core::slice::from_raw_parts_mut(new_state, n);
            s.step_flat_in_place(state, &inc, w)?
        } else {
            let old = core::slice::from_raw_parts(old_state, n);
            let new = core::slice::from_raw_parts_mut(new_state, n);
            s.step_flat(old, new, &inc, w)?
        };
        *out = r;
        Ok(())
    })
}

/// Step `n` patches at once, in the shape of Abaqus/Explicit VFRIC (as
/// `asperity_homogenised_friction_step_block`): the normal force on patch i
/// `normal_force[i]` (N, a fixed load, <= the capacity), its slip increment
/// `slip[2i]`, `[2i+1]` (m, x and y interleaved), one `dt` (s) for all,
/// states `old_states[i*m .. (i+1)*m]` -> `new_states[...]` with m =
/// `asperity_slider_state_size`, tangential forces out in
/// `tangential_force[2i]`, `[2i+1]` (N, interleaved, opposing slip) and the
/// dissipated energy of the increment in `dissipation[i]` (J). `dissipation`
/// may be NULL (not wanted); `new_states` may equal `old_states` (in place)
/// but must not partially overlap it. No tangents (use
/// `asperity_slider_step`). On an error at element i, elements before i are
/// written, those from i on are untouched, and the message names i.
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_step_block(
    slider: *const AsperitySlider,
    work: *mut AsperitySliderWork,
    n: usize,
    normal_force: *const f64,
    slip: *const f64,
    dt: f64,
    old_states: *const f64,
    new_states: *mut f64,
    tangential_force: *mut f64,
    dissipation: *mut f64,
) -> i32 {
    guard(|| {
        let s = &input(slider, "slider")?.0;
        let w = &mut output(work, "work")?.0;
        if n == 0 {
            return Ok(());
        }
        input(normal_force, "normal_force")?;
        input(slip, "slip")?;
        input(old_states, "old_states")?;
        output(new_states, "new_states")?;
        output(tangential_force, "tangential_force")?;
        let m = s.state_len();
        let total = n.checked_mul(m).ok_or(Error::InvalidArgument {
            name: "n",
            value: n as f64,
            bound: "such that n * state size fits in size_t",
        })?;
        if partial_overlap(old_states, new_states, total) {
            return Err(Error::InvalidArgument {
                name: "new_states",
                value: 0.0,
                bound: "equal to old_states (in place) or not overlapping it",
            }
            .into());
        }
        // SAFETY: the caller provides n normal forces, 2n slips, 2n
        // tangential forces, n dissipations (or NULL) and n*m doubles of
        // states; equal state pointers are one mutable slice.
        let normal = core::slice::from_raw_parts(normal_force, n);
        let slip = core::slice::from_raw_parts(slip, 2 * n);
        let force = core::slice::from_raw_parts_mut(tangential_force, 2 * n);
        let diss = if dissipation.is_null() {
            None
        } else {
            Some(core::slice::from_raw_parts_mut(dissipation, n))
        };
        let states = if core::ptr::eq(old_states, new_states) {
            SliderStates::InPlace(core::slice::from_raw_parts_mut(new_states, total))
        } else {
            SliderStates::Separate {
                old: core::slice::from_raw_parts(old_states, total),
                new: core::slice::from_raw_parts_mut(new_states, total),
            }
        };
        s.step_flat_block(normal, slip, dt, states, force, diss, w)
            .map_err(|e| Failure::at(e.index, e.error))
    })
}
