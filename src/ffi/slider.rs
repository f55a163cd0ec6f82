//! C ABI for `crate::friction::slider`: the full hierarchical slider as the
//! friction law of a surface patch.
//!
//! * `AsperitySlider` (opaque, a boxed [`Slider`]) is built from a scene's
//!   JSON text ([`Scene::from_json`], [`Scene::build`]) or from structs
//!   (`asperity_slider_new`: a geometry handle, `AsperityFrictionMaterial`,
//!   a counter-surface array, `AsperitySliderOptions`); immutable, one
//!   handle may be used by any number of threads at once.
//! * `asperity_friction_from_slider` makes it the friction law of a surface
//!   patch, stepped per increment through the one friction handle
//!   (`ffi::friction_law`).

use super::friction::AsperitySliderGeometry;
use super::friction_law::AsperityFrictionWork;
use super::{guard, input, output, read_text, set_last_error, Failure};
use crate::error::{Error, Result};
use crate::friction::{
    CofForm, CounterHeight, FrictionLaw, FrictionMaterial, Loading, Mechanisms, PlasticUpdate,
    RodOptions, RodSolver, Slider, SliderOptions, SliderWork, TrackEnd,
};
use crate::scene::{Scene, SceneError};
use std::ffi::{c_char, CStr};

/// `AsperitySliderInfo.scene_control`: the scene's loading is a fixed load
/// (N).
pub const ASPERITY_SLIDER_CONTROL_LOAD: i32 = 1;
/// `AsperitySliderInfo.scene_control`: the scene's loading is a fixed gap,
/// the slider's mean line at `scene_loading` (m) above the counter-surface's
/// mean line.
pub const ASPERITY_SLIDER_CONTROL_GAP: i32 = 2;

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
/// `AsperitySliderOptions.cof_form`: mu = F/(N + 2A), not the thesis's
/// stated form but the arithmetic of its Tables 6-1 and 6-2 (THESIS.md).
pub const ASPERITY_COF_DERJAGUIN_DOUBLE_ADHESION: i32 = 3;

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

/// Index in a slider's friction state of its flag: 0 fresh, 1 stepped.
pub const ASPERITY_SLIDER_STATE_FLAG: usize = 2;
/// Index in a slider's friction state of the slider position X along its
/// track (m). A fresh state (flag 0) starts there: set it to place patches
/// at different points of the counter-surface.
pub const ASPERITY_SLIDER_STATE_POSITION: usize = 3;
/// Index in a slider's friction state of the rod-bed position b of the
/// last equilibrium (m; NaN: none).
pub const ASPERITY_SLIDER_STATE_ROD_POSITION: usize = 4;
/// Index in a slider's friction state of the accumulated dissipation by
/// mechanism (J), 4 values: chemical, van der Waals, elastic, plastic.
pub const ASPERITY_SLIDER_STATE_MECHANISMS: usize = 5;
/// Index in a slider's friction state of the rod heights (m, one per rod),
/// followed by the rods' stored elastic energies (J, one per rod).
pub const ASPERITY_SLIDER_STATE_HEIGHTS: usize = 9;
/// Index in a homogenised friction state of the stick force (N, x and y).
pub const ASPERITY_HOMOGENISED_STATE_FORCE: usize = 2;
/// Index in a homogenised friction state of the accumulated plastic slip
/// path (m).
pub const ASPERITY_HOMOGENISED_STATE_PLASTIC_SLIP_PATH: usize = 4;
/// Index in a homogenised friction state of the accumulated dissipation by
/// mechanism (J), 4 values: chemical, van der Waals, elastic, plastic.
pub const ASPERITY_HOMOGENISED_STATE_MECHANISMS: usize = 5;

const _: () = {
    use crate::friction::HomogenisedFriction as H;
    assert!(ASPERITY_SLIDER_STATE_FLAG == Slider::STATE_FLAG);
    assert!(ASPERITY_SLIDER_STATE_POSITION == Slider::STATE_POSITION);
    assert!(ASPERITY_SLIDER_STATE_ROD_POSITION == Slider::STATE_ROD_POSITION);
    assert!(ASPERITY_SLIDER_STATE_MECHANISMS == Slider::STATE_MECHANISMS);
    assert!(ASPERITY_SLIDER_STATE_HEIGHTS == Slider::STATE_HEIGHTS);
    assert!(ASPERITY_HOMOGENISED_STATE_FORCE == H::STATE_FORCE);
    assert!(ASPERITY_HOMOGENISED_STATE_PLASTIC_SLIP_PATH == H::STATE_PLASTIC_SLIP_PATH);
    assert!(ASPERITY_HOMOGENISED_STATE_MECHANISMS == H::STATE_MECHANISMS);
};

/// The hierarchical slider against its counter-surface (opaque). Create it
/// with `asperity_slider_from_scene_json`, release it with
/// `asperity_slider_free`. Immutable; safe to share between threads.
pub struct AsperitySlider(pub(crate) Slider);

/// What a slider is: sizes and capacities (SI).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperitySliderInfo {
    /// Doubles per patch state of its friction law (9 + 2 x rods).
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
    /// `ASPERITY_COF_DERJAGUIN` (default), `_AMONTONS`, `_COULOMB` or
    /// `_DERJAGUIN_DOUBLE_ADHESION`.
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
            ASPERITY_COF_DERJAGUIN_DOUBLE_ADHESION => CofForm::DerjaguinDoubleAdhesion,
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
            // Not in the C options (its layout is part of ABI 0.2): the
            // counter height at the rod centre, the thesis's reading.
            counter_height: CounterHeight::RodCentre,
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

/// The full record of a slider patch's last step (SI), beyond the friction
/// response: positions and the counts of contacts.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct AsperitySliderRecord {
    /// Slider position X along the track after the increment (m).
    pub position: f64,
    /// Rod-bed position b: height of the slider's mean line above the
    /// counter-surface's mean line (m).
    pub rod_position: f64,
    /// Fraction of the nano-asperities in contact touching only thanks to
    /// adhesion, in [0, 1].
    pub adhesion_area_share: f64,
    /// Nano-asperities in contact N_c.
    pub nano_contacts: u64,
    /// Of those, in contact only thanks to adhesion.
    pub adhesive_contacts: u64,
    /// Rods carrying force.
    pub rods_in_contact: u64,
    /// Rods at the yield force.
    pub yielded_rods: u64,
    /// 1 when the step seated a fresh state first, else 0.
    pub seated: i32,
    /// Reserved, 0.
    pub reserved: i32,
}

/// Write the record of the last step taken with `work` by a slider law
/// (`asperity_friction_from_slider`) to `*out`; all zero for a work made
/// for a slider law that has not stepped yet. Errors: NULL, or a work of
/// another law (`work`).
#[no_mangle]
pub unsafe extern "C" fn asperity_slider_record(
    work: *const AsperityFrictionWork,
    out: *mut AsperitySliderRecord,
) -> i32 {
    guard(|| {
        let w = &input(work, "work")?.0;
        let out = output(out, "out")?;
        let w = w.get::<SliderWork>().ok_or(Error::InvalidArgument {
            name: "work",
            value: 0.0,
            bound: "a work of a slider law",
        })?;
        let r = w.record();
        *out = AsperitySliderRecord {
            position: r.position,
            rod_position: r.rod_position,
            adhesion_area_share: r.adhesion_area_share,
            nano_contacts: r.nano_contacts as u64,
            adhesive_contacts: r.adhesive_contacts as u64,
            rods_in_contact: r.rods_in_contact as u64,
            yielded_rods: r.yielded_rods as u64,
            seated: w.seated() as i32,
            reserved: 0,
        };
        Ok(())
    })
}
