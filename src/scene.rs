//! Scenes: a serde JSON description of a sliding simulation —
//! material, surfaces (files or seeded generators), rods, mechanisms,
//! loading, sliding distance and step, outputs — validated on load and built
//! into a [`Slider`].
//!
//! ```json
//! {
//!   "material": { "preset": "copper" },
//!   "surfaces": {
//!     "slider":  { "self_affine": { "hurst": 0.8, "rq": 7e-7, "roll_off_wavelength": 3e-5,
//!                                   "points": 91, "dx": 1.5e-6, "seed": 1 } },
//!     "counter": { "file": { "path": "profile.csv", "form": "quadratic",
//!                            "start": 0.0, "length": 4e-4 } },
//!     "nano":    { "asperities": { "h_vdw": 6e-9, "w_vdw": 4.3e-7, "h_chem": 2.2e-9,
//!                                  "w_chem": 1.61e-7, "spacing": 1.35e-6 } }
//!   },
//!   "rods": { "widths": [1.5e-6], "depth": 1.35e-5 },
//!   "mechanisms": { "chemical": true, "van_der_waals": true, "elastic": true, "plastic": true },
//!   "loading": { "fixed_load_fraction": { "fraction": 0.35 } },
//!   "sliding": { "distance": 1.5e-4, "step": 1.5e-6, "velocity": 1e-3 },
//!   "outputs": { "csv": true, "svg": true },
//!   "load_sweep": { "fractions": [0.05, 0.11, 0.25, 0.45] },
//!   "friction_models": [
//!     { "name": "LuGre", "lugre": { "mu_coulomb": 0.9, "mu_static": 1.2,
//!                                   "stribeck_velocity": 1e-3, "sigma0": 3e5 } },
//!     { "name": "Maxwell-slip 2", "maxwell_slip": { "stiffness": [4e5, 1e5],
//!                                                   "capacity": [0.5, 0.5] } }
//!   ]
//! }
//! ```
//!
//! `friction_models` (optional) chooses dynamic friction models of
//! [`crate::friction::dynamic`] to run along the same track; with models,
//! `sliding.velocity` (m/s) is required. See [`models`] for the keys and
//! [`Scene::run_friction_models`] for the run.
//!
//! Every object rejects unknown fields. All numbers SI (m, N, Pa, J).
//! File paths are relative to the scene file's directory
//! ([`Scene::from_file`]) or to the `base` given to [`Scene::from_json`].
//! Errors are [`SceneError`]: the JSON message with line and column, or the
//! library's [`Error`] naming the offending field (e.g. `loading.load`,
//! `sliding.step`, `surfaces.counter.path`).

use crate::error::{check, Error};
use crate::friction::dynamic::DynamicModel;
use crate::friction::geometry::{nano_analysis, rod_levels, NanoAsperities, SliderGeometry};
use crate::friction::ledger::{CofForm, Mechanisms};
use crate::friction::mechanisms::FrictionMaterial;
use crate::friction::rods::{PlasticUpdate, RodOptions, RodSolver};
use crate::friction::slider::{CounterHeight, Loading, SlideRun, Slider, SliderOptions, TrackEnd};
use crate::surface::{read_profile, read_topography, Form, MapForm, Profile, SelfAffine, Spacing};
use serde::{Deserialize, Serialize};
use std::borrow::Cow;
use std::fmt;
use std::path::{Path, PathBuf};

pub mod models;

pub use models::{
    run_along, BristlesSpec, BurridgeKnopoffSpec, DynamicModelSpec, FrictionModelSpec,
    GeneralizedMaxwellSlipSpec, LuGreSpec, MaxwellSlipSpec, PrandtlTomlinsonSpec,
    PrandtlTomlinsonTwoSpringSpec, TrackRun, TrackStep, TrackSummary,
};

/// Most samples a scene's generated (`self_affine`) profile may ask for:
/// 2²⁴ (16 777 216; 128 MiB of heights and twice that for the FFT). A scene
/// is outside data (a file, or text passed through the C ABI); a larger count
/// is an error naming `points`, not an allocation that aborts the process.
pub const MAX_POINTS: usize = 1 << 24;

/// An error reading or building a scene.
#[derive(Debug, Clone, PartialEq)]
pub enum SceneError {
    /// The text is not a valid scene (syntax, unknown or missing field,
    /// wrong type); `message` is serde's, naming the field.
    Json {
        /// What is wrong.
        message: String,
        /// 1-based line (0 if unknown).
        line: usize,
        /// 1-based column (0 if unknown).
        column: usize,
    },
    /// A value is outside its domain, or the model cannot be built; `field`
    /// is the scene field it came from.
    Invalid {
        /// Scene field path (e.g. `"loading"`, `"surfaces.counter"`,
        /// `"friction_models[1].lugre"`).
        field: Cow<'static, str>,
        /// The library's error (names the argument and bound).
        error: Error,
    },
    /// A file named by the scene cannot be read.
    File {
        /// The path as resolved.
        path: PathBuf,
        /// The read error.
        error: Error,
    },
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SceneError::Json {
                message,
                line,
                column,
            } => write!(
                f,
                "invalid scene at line {line}, column {column}: {message}"
            ),
            SceneError::Invalid { field, error } => {
                write!(f, "invalid scene field `{field}`: {error}")
            }
            SceneError::File { path, error } => write!(f, "scene file {}: {error}", path.display()),
        }
    }
}

impl std::error::Error for SceneError {}

fn at(field: &'static str) -> impl Fn(Error) -> SceneError {
    move |error| invalid(field, error)
}

/// The error `error` at scene field `field`.
fn invalid(field: impl Into<Cow<'static, str>>, error: Error) -> SceneError {
    SceneError::Invalid {
        field: field.into(),
        error,
    }
}

/// The material of both bodies.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "snake_case")]
pub enum MaterialSpec {
    /// A built-in material: `"copper"` ([`FrictionMaterial::copper`]).
    Preset(MaterialPreset),
    /// Every field of [`FrictionMaterial`].
    Custom(FrictionMaterial),
}

/// Built-in materials.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum MaterialPreset {
    /// The thesis's Cu–Cu (4.4).
    Copper,
}

/// Form removed from a measured profile before use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FormSpec {
    /// Mean only.
    Mean,
    /// Tilt (default).
    #[default]
    Linear,
    /// Tilt and curvature.
    Quadratic,
}

impl From<FormSpec> for Form {
    fn from(f: FormSpec) -> Self {
        match f {
            FormSpec::Mean => Form::Mean,
            FormSpec::Linear => Form::Linear,
            FormSpec::Quadratic => Form::Quadratic,
        }
    }
}

/// A micro profile (slider or counter-surface).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "snake_case")]
pub enum SurfaceSpec {
    /// A two-column CSV line scan (x, z in m), see [`read_profile`].
    File {
        /// Path, relative to the scene file.
        path: PathBuf,
        /// Form removed after cutting (default linear).
        #[serde(default)]
        form: FormSpec,
        /// Start of the part used (m from the first sample; default 0).
        #[serde(default)]
        start: f64,
        /// Length of the part used (m; default: to the end).
        #[serde(default)]
        length: Option<f64>,
    },
    /// A seeded self-affine profile ([`SelfAffine`]).
    SelfAffine {
        /// Hurst exponent in [0, 1].
        hurst: f64,
        /// Rq (m).
        rq: f64,
        /// Roll-off wavelength (m), optional.
        #[serde(default)]
        roll_off_wavelength: Option<f64>,
        /// Number of samples.
        points: usize,
        /// Sample spacing (m).
        dx: f64,
        /// Random seed.
        seed: u64,
    },
}

/// The nano-asperities.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "snake_case")]
pub enum NanoSpec {
    /// Explicit numbers ([`NanoAsperities`]).
    Asperities(NanoAsperities),
    /// One row of an AFM height map CSV (plane removed, then the row's
    /// tilt), analysed by [`nano_analysis`].
    AfmMap {
        /// Path, relative to the scene file.
        path: PathBuf,
        /// Row index (default 0).
        #[serde(default)]
        row: usize,
    },
}

/// The three profiles of a scene.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Surfaces {
    /// The slider's micro profile (rod heights, 6-1).
    pub slider: SurfaceSpec,
    /// The rigid counter-surface.
    pub counter: SurfaceSpec,
    /// The nano-asperities on the rod tips.
    pub nano: NanoSpec,
}

/// The rods.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RodsSpec {
    /// Rod widths of the levels (m), coarsest first; the last is the tips.
    pub widths: Vec<f64>,
    /// Rod depth across the track (m); default: square rods.
    #[serde(default)]
    pub depth: Option<f64>,
    /// Root margin below the deepest rod (m); default: the tip width.
    #[serde(default)]
    pub root_margin: Option<f64>,
    /// Plastic update (default nearest neighbours, the thesis's rule; the
    /// chapter-6 scenes use Gaussian weights, see
    /// [`PlasticUpdate`]).
    #[serde(default)]
    pub plastic: PlasticSpec,
    /// Solver (default sweep).
    #[serde(default)]
    pub solver: SolverSpec,
    /// The counter height a rod sees: `"rod_centre"` (default, the thesis's
    /// reading) or `"highest_point"` (not stated by the thesis; see
    /// [`CounterHeight`]).
    #[serde(default)]
    pub counter_height: CounterHeight,
}

/// Plastic update rule (thesis 6.2.3).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "snake_case")]
pub enum PlasticSpec {
    /// No pile-up.
    ShortenOnly,
    /// The thesis's rule (default).
    #[default]
    NearestNeighbours,
    /// Gaussian weights of width `width` (m): the project's extension,
    /// not the thesis's rule ([`PlasticUpdate::Gaussian`]).
    Gaussian {
        /// Width (m).
        width: f64,
    },
}

/// Rod solver.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum SolverSpec {
    /// Exact sweep (default).
    #[default]
    Sweep,
    /// The thesis's dense formulation.
    Dense,
}

/// Loading.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "snake_case")]
pub enum LoadingSpec {
    /// Fixed gap: slider mean line at `position` (m) above the counter's.
    FixedGap {
        /// b₀ (m).
        position: f64,
    },
    /// Fixed load `load` (N).
    FixedLoad {
        /// P (N).
        load: f64,
    },
    /// Fixed load P = fraction·σ_y·A_n (the thesis's Tables 6-1..6-3).
    FixedLoadFraction {
        /// P/(σ_y A_n), in [0, 1].
        fraction: f64,
    },
}

/// Sliding distance and increment.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SlidingSpec {
    /// Distance (m).
    pub distance: f64,
    /// Increment (m).
    pub step: f64,
    /// Counter-surface past its end (default error).
    #[serde(default)]
    pub track_end: TrackEnd,
    /// Sliding velocity (m/s): the time increment step/velocity of the
    /// scene's dynamic friction models (the energy-dissipation model is
    /// quasi-static and does not use it). Required when the scene has
    /// `friction_models`; finite and > 0 when given.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub velocity: Option<f64>,
}

/// Loads of a load sweep (`asperity slide` plots the mean true contact area
/// against them, thesis 6.5.3, Figure 6-60).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, rename_all = "snake_case")]
pub enum LoadSweep {
    /// Normal loads P (N), each finite, ≥ 0 and within the rods' capacity.
    Loads(Vec<f64>),
    /// Loads as fractions P/(σ_y A_n) of the capacity, each in [0, 1].
    Fractions(Vec<f64>),
}

/// What the command line writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Outputs {
    /// Per-step CSV (default true).
    pub csv: bool,
    /// SVG plots (default true).
    pub svg: bool,
}

impl Default for Outputs {
    fn default() -> Self {
        Self {
            csv: true,
            svg: true,
        }
    }
}

/// A sliding scene (see the module docs).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scene {
    /// Material.
    pub material: MaterialSpec,
    /// Profiles.
    pub surfaces: Surfaces,
    /// Rods.
    pub rods: RodsSpec,
    /// Mechanisms switched on (default all).
    #[serde(default)]
    pub mechanisms: Mechanisms,
    /// COF form (default Derjaguin).
    #[serde(default)]
    pub cof_form: CofForm,
    /// Loading.
    pub loading: LoadingSpec,
    /// Sliding.
    pub sliding: SlidingSpec,
    /// Outputs.
    #[serde(default)]
    pub outputs: Outputs,
    /// Optional load sweep: one slide per load, the same slider otherwise
    /// (see [`Scene::sweep_loads`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub load_sweep: Option<LoadSweep>,
    /// Dynamic friction models run along the same track (optional; see
    /// [`models`] and [`Scene::run_friction_models`]).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub friction_models: Vec<FrictionModelSpec>,
    /// Directory that relative paths are resolved against (not serialised).
    #[serde(skip)]
    pub base: PathBuf,
}

impl Scene {
    /// Parses and validates a scene; relative paths resolve against `base`.
    pub fn from_json(text: &str, base: impl AsRef<Path>) -> Result<Self, SceneError> {
        let mut scene: Scene = serde_json::from_str(text).map_err(|e| SceneError::Json {
            message: e.to_string(),
            line: e.line(),
            column: e.column(),
        })?;
        scene.base = base.as_ref().to_path_buf();
        scene.validate()?;
        Ok(scene)
    }

    /// Reads a scene file (paths relative to its directory).
    pub fn from_file(path: impl AsRef<Path>) -> Result<Self, SceneError> {
        let path = path.as_ref();
        let text = std::fs::read_to_string(path).map_err(|e| SceneError::File {
            path: path.to_path_buf(),
            error: Error::Io {
                what: "scene file",
                kind: e.kind(),
            },
        })?;
        let base = path.parent().unwrap_or(Path::new(".")).to_path_buf();
        Self::from_json(&text, base)
    }

    /// Checks the numbers that do not need the files (the rest is checked by
    /// [`Self::build`]).
    pub fn validate(&self) -> Result<(), SceneError> {
        if let MaterialSpec::Custom(m) = &self.material {
            m.validate().map_err(at("material"))?;
        }
        check::positive("distance", self.sliding.distance).map_err(at("sliding"))?;
        check::positive("step", self.sliding.step).map_err(at("sliding"))?;
        if let Some(v) = self.sliding.velocity {
            check::positive("velocity", v).map_err(at("sliding"))?;
        }
        if self.rods.widths.is_empty() {
            return Err(invalid(
                "rods",
                Error::InvalidArgument {
                    name: "widths.len()",
                    value: 0.0,
                    bound: ">= 1 width",
                },
            ));
        }
        match self.loading {
            LoadingSpec::FixedGap { position } => {
                check::finite("position", position).map_err(at("loading"))?;
            }
            LoadingSpec::FixedLoad { load } => {
                check::non_negative("load", load).map_err(at("loading"))?;
            }
            LoadingSpec::FixedLoadFraction { fraction } => {
                check::in_range("fraction", fraction, 0.0, 1.0, "in [0, 1]")
                    .map_err(at("loading"))?;
            }
        }
        for (field, s) in [
            ("surfaces.slider", &self.surfaces.slider),
            ("surfaces.counter", &self.surfaces.counter),
        ] {
            if let SurfaceSpec::SelfAffine {
                hurst,
                rq,
                roll_off_wavelength,
                points,
                dx,
                ..
            } = s
            {
                let mut g = SelfAffine::new(*hurst, *rq).map_err(at(field))?;
                if let Some(r) = roll_off_wavelength {
                    g = g.with_roll_off(*r).map_err(at(field))?;
                }
                let _ = g;
                check::positive("dx", *dx).map_err(at(field))?;
                if *points > MAX_POINTS {
                    return Err(invalid(
                        field,
                        Error::InvalidArgument {
                            name: "points",
                            value: *points as f64,
                            bound: "<= 2^24 (scene::MAX_POINTS)",
                        },
                    ));
                }
            }
        }
        if let NanoSpec::Asperities(n) = &self.surfaces.nano {
            n.validate().map_err(at("surfaces.nano"))?;
        }
        if let Some(sweep) = &self.load_sweep {
            let (name, values, fraction) = match sweep {
                LoadSweep::Loads(v) => ("loads", v, false),
                LoadSweep::Fractions(v) => ("fractions", v, true),
            };
            if values.is_empty() {
                return Err(invalid(
                    "load_sweep",
                    Error::InvalidArgument {
                        name,
                        value: 0.0,
                        bound: "at least one load",
                    },
                ));
            }
            for &v in values {
                if fraction {
                    check::in_range(name, v, 0.0, 1.0, "in [0, 1]")
                } else {
                    check::non_negative(name, v)
                }
                .map_err(at("load_sweep"))?;
            }
        }
        self.friction_models()?;
        Ok(())
    }

    /// The scene's dynamic friction models, in order, built and checked:
    /// names (not empty, no control characters, unique; errors at
    /// `friction_models[i].name`), parameters (the constructor's error at
    /// `friction_models[i].<key>`), and `sliding.velocity` given when there
    /// are models (error at `sliding`, naming `velocity`). Empty without
    /// models.
    pub fn friction_models(&self) -> Result<Vec<DynamicModel>, SceneError> {
        let specs = &self.friction_models;
        if !specs.is_empty() && self.sliding.velocity.is_none() {
            return Err(invalid(
                "sliding",
                Error::InvalidArgument {
                    name: "velocity",
                    value: f64::NAN,
                    bound: "given (m/s, finite, > 0) when the scene has friction_models",
                },
            ));
        }
        let mut out = Vec::with_capacity(specs.len());
        let mut seen = std::collections::HashMap::with_capacity(specs.len());
        for (i, spec) in specs.iter().enumerate() {
            let name_at = || format!("friction_models[{i}].name");
            models::check_name(&spec.name).map_err(|e| invalid(name_at(), e))?;
            if let Some(&j) = seen.get(spec.name.as_str()) {
                return Err(invalid(
                    name_at(),
                    Error::InvalidArgument {
                        name: "name",
                        value: j as f64,
                        bound: "unique among friction_models (the entry at this index has it)",
                    },
                ));
            }
            seen.insert(spec.name.as_str(), i);
            let model = spec
                .model
                .build()
                .map_err(|e| invalid(format!("friction_models[{i}].{}", spec.model.key()), e))?;
            out.push(model);
        }
        Ok(out)
    }

    /// Runs the scene's dynamic friction models along the track of `run`
    /// (the energy-dissipation run of this scene's slider) at
    /// `sliding.velocity`, one [`TrackRun`] per model in scene order
    /// ([`run_along`]); empty without models. Errors: those of
    /// [`Self::friction_models`], `sliding.velocity` not finite and > 0, and
    /// a failed step at `friction_models[i].<key>`, its increment given in
    /// the field (`… at increment k`).
    pub fn run_friction_models(&self, run: &SlideRun) -> Result<Vec<TrackRun>, SceneError> {
        let built = self.friction_models()?;
        if built.is_empty() {
            return Ok(Vec::new());
        }
        let velocity = self.sliding.velocity.unwrap_or(f64::NAN);
        check::positive("velocity", velocity).map_err(at("sliding"))?;
        built
            .iter()
            .zip(&self.friction_models)
            .enumerate()
            .map(|(i, (model, spec))| {
                run_along(model, run, velocity).map_err(|e| {
                    invalid(
                        format!(
                            "friction_models[{i}].{} at increment {}",
                            spec.model.key(),
                            e.index
                        ),
                        e.error,
                    )
                })
            })
            .collect()
    }

    /// The `asperity slide SCENE --json` summary of `run` (this scene's
    /// slider run) and `tracks` (its [`Self::run_friction_models`]): the
    /// run's [`SlideSummary`](crate::friction::slider::SlideSummary) in the
    /// CLI's keys (`mean_cof`, `dissipation`, …, `steps`), `files` an empty
    /// list, and `friction_models` (name, model key and track summary per
    /// model) when `tracks` is not empty. The CLI fills in `files` and adds
    /// the plots' `area_load`; the Python package's `run_scene` returns it
    /// as is.
    pub fn summary_json(&self, run: &SlideRun, tracks: &[TrackRun]) -> serde_json::Value {
        let s = &run.summary;
        let d = s.dissipation;
        let mut v = serde_json::json!({
            "mean_cof": s.mean_cof,
            "mean_friction_force": s.mean_friction_force,
            "normal_load": s.normal_load,
            "dissipation": {
                "chemical": d.chemical,
                "van_der_waals": d.van_der_waals,
                "elastic": d.elastic,
                "plastic": d.plastic,
            },
            "mean_true_contact_area": s.mean_true_contact_area,
            "mean_adhesion_area_share": s.mean_adhesion_area_share,
            "mean_nano_contacts": s.mean_nano_contacts,
            "max_yielded_rods": s.max_yielded_rods,
            "no_contact_steps": s.no_contact_steps,
            "distance": s.distance,
            "steps": s.steps,
            "files": Vec::<String>::new(),
        });
        if !tracks.is_empty() {
            v["friction_models"] = self
                .friction_models
                .iter()
                .zip(tracks)
                .map(|(spec, t)| {
                    let m = &t.summary;
                    serde_json::json!({
                        "name": spec.name,
                        "model": spec.model.key(),
                        "mean_cof": m.mean_cof,
                        "static_cof": m.static_cof,
                        "mean_friction_force": m.mean_friction_force,
                        "dissipation": m.dissipation,
                        "stick_slip_events": m.stick_slip_events,
                    })
                })
                .collect();
        }
        v
    }

    /// The loads (N) of the scene's load sweep for `slider` (fractions are
    /// of its capacity σ_y A_n, [`Slider::capacity`]); `None` without a
    /// sweep. The loads are validated against the capacity by
    /// [`Slider::with_loading`] when used.
    pub fn sweep_loads(&self, slider: &Slider) -> Option<Vec<f64>> {
        self.load_sweep.as_ref().map(|sweep| match sweep {
            LoadSweep::Loads(v) => v.clone(),
            LoadSweep::Fractions(v) => v.iter().map(|f| f * slider.capacity()).collect(),
        })
    }

    /// The material.
    pub fn material(&self) -> FrictionMaterial {
        match self.material {
            MaterialSpec::Preset(MaterialPreset::Copper) => FrictionMaterial::copper(),
            MaterialSpec::Custom(m) => m,
        }
    }

    fn profile(&self, field: &'static str, spec: &SurfaceSpec) -> Result<Profile, SceneError> {
        match spec {
            SurfaceSpec::File {
                path,
                form,
                start,
                length,
            } => {
                let full = self.base.join(path);
                let p =
                    read_profile(&full, Spacing::default()).map_err(|error| SceneError::File {
                        path: full.clone(),
                        error,
                    })?;
                let start = check::non_negative("start", *start).map_err(at(field))?;
                let i0 = (start / p.dx()).round() as usize;
                let i1 = match length {
                    None => p.len(),
                    Some(l) => {
                        let l = check::positive("length", *l).map_err(at(field))?;
                        // Saturating: a start or length far past the
                        // profile is the error below, not an overflow.
                        i0.saturating_add((l / p.dx()).round() as usize)
                            .saturating_add(1)
                    }
                };
                if i1 > p.len() || i0.saturating_add(8) > i1 {
                    return Err(invalid(
                        field,
                        Error::InvalidArgument {
                            name: "length",
                            value: length.unwrap_or(f64::NAN),
                            bound: "start + length within the profile (at least 8 samples)",
                        },
                    ));
                }
                let cut = p.slice(i0, i1).map_err(at(field))?;
                let cut = Profile::new(cut.dx(), cut.heights().to_vec()).map_err(at(field))?;
                cut.remove_form((*form).into()).map_err(at(field))
            }
            SurfaceSpec::SelfAffine {
                hurst,
                rq,
                roll_off_wavelength,
                points,
                dx,
                seed,
            } => {
                let mut g = SelfAffine::new(*hurst, *rq).map_err(at(field))?;
                if let Some(r) = roll_off_wavelength {
                    g = g.with_roll_off(*r).map_err(at(field))?;
                }
                g.profile(*points, *dx, *seed).map_err(at(field))
            }
        }
    }

    fn nano(&self) -> Result<NanoAsperities, SceneError> {
        match &self.surfaces.nano {
            NanoSpec::Asperities(n) => Ok(*n),
            NanoSpec::AfmMap { path, row } => {
                let full = self.base.join(path);
                let map = read_topography(&full, Spacing::default()).map_err(|error| {
                    SceneError::File {
                        path: full.clone(),
                        error,
                    }
                })?;
                let map = map
                    .remove_form(MapForm::Plane)
                    .map_err(at("surfaces.nano"))?;
                let r = map.row(*row).map_err(at("surfaces.nano"))?;
                let r = r.remove_form(Form::Linear).map_err(at("surfaces.nano"))?;
                Ok(nano_analysis(r.heights(), r.dx())
                    .map_err(at("surfaces.nano"))?
                    .asperities)
            }
        }
    }

    /// Builds the slider: reads or generates the profiles, cuts the rods
    /// (6-1), places the nano-asperities, resolves the load.
    pub fn build(&self) -> Result<Slider, SceneError> {
        self.validate()?;
        let material = self.material();
        let slider = self.profile("surfaces.slider", &self.surfaces.slider)?;
        let counter = self.profile("surfaces.counter", &self.surfaces.counter)?;
        let nano = self.nano()?;
        let levels =
            rod_levels(slider.heights(), slider.dx(), &self.rods.widths).map_err(at("rods"))?;
        let tip = *self.rods.widths.last().expect("validated");
        if nano.spacing > tip * (1.0 + 1e-9) {
            return Err(invalid(
                "rods",
                Error::OutOfDomain {
                    name: "widths",
                    value: tip,
                    reason: "the tip rods are narrower than the nano-asperity spacing: no nano-asperity fits",
                },
            ));
        }
        let per_side = (tip / nano.spacing * (1.0 + 1e-9)).floor().max(1.0) as usize;
        let geometry = SliderGeometry::new(levels, nano, per_side.saturating_mul(per_side))
            .map_err(at("rods"))?;
        let mut options = SliderOptions::new(Loading::FixedLoad { load: 0.0 });
        options.depth = self.rods.depth;
        options.root_margin = self.rods.root_margin;
        options.mechanisms = self.mechanisms;
        options.cof_form = self.cof_form;
        options.track_end = self.sliding.track_end;
        options.counter_height = self.rods.counter_height;
        options.rod = RodOptions {
            solver: match self.rods.solver {
                SolverSpec::Sweep => RodSolver::Sweep,
                SolverSpec::Dense => RodSolver::Dense,
            },
            warm_start: true,
            plastic: match self.rods.plastic {
                PlasticSpec::ShortenOnly => PlasticUpdate::ShortenOnly,
                PlasticSpec::NearestNeighbours => PlasticUpdate::NearestNeighbours,
                PlasticSpec::Gaussian { width } => PlasticUpdate::Gaussian { width },
            },
        };
        // Nominal area n·w·D for the load fraction.
        let rods = geometry.tips().len() as f64;
        let depth = self.rods.depth.unwrap_or(tip);
        options.loading = match self.loading {
            LoadingSpec::FixedGap { position } => Loading::FixedGap { position },
            LoadingSpec::FixedLoad { load } => Loading::FixedLoad { load },
            LoadingSpec::FixedLoadFraction { fraction } => Loading::FixedLoad {
                load: fraction * material.yield_stress * rods * tip * depth,
            },
        };
        Slider::new(
            geometry,
            material,
            counter.heights().to_vec(),
            counter.dx(),
            options,
        )
        .map_err(at("scene"))
    }
}
