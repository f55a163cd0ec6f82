//! The dynamic friction models a scene chooses, and the run of
//! a dynamic model along the energy-dissipation slider's track.
//!
//! # In a scene
//!
//! The optional `friction_models` list names models of
//! [`crate::friction::dynamic`], each with its parameters (the Rust
//! constructor's argument names), and `sliding.velocity` (m/s, required with
//! models) gives them the time increment of a slide step:
//!
//! ```json
//! "sliding": { "distance": 1.5e-4, "step": 1.5e-6, "velocity": 1e-3 },
//! "friction_models": [
//!   { "name": "LuGre", "lugre": { "mu_coulomb": 0.9, "mu_static": 1.2,
//!       "stribeck_velocity": 1e-3, "sigma0": 3e5, "sigma1": 100, "damping_velocity": 1e-2 } },
//!   { "name": "Maxwell-slip 4", "maxwell_slip": { "stiffness": [4e5, 2e5, 1e5, 5e4],
//!       "capacity": [0.3, 0.3, 0.25, 0.2] } },
//!   { "name": "Prandtl-Tomlinson", "prandtl_tomlinson": { "amplitude": 1.8e-6,
//!       "period": 3e-5, "stiffness": 2.5e4, "mass": 1e-3, "damping": 5 } }
//! ]
//! ```
//!
//! Each entry has a `name` (non-empty, no control characters, unique in the
//! list: it labels the model's CSV column, plot line and summary) and exactly
//! one model key:
//!
//! | key | model | parameters (defaults) |
//! |---|---|---|
//! | `lugre` | [`LuGre::new`] | `mu_coulomb`, `mu_static`, `stribeck_velocity` (m/s), `stribeck_exponent` (2), `sigma0` (1/m), `sigma1` (s/m; 0), `damping_velocity` (m/s; absent = +∞, only with `sigma1` = 0), `sigma2` (N·s/m; 0) |
//! | `maxwell_slip` | [`MaxwellSlip::new`] | `stiffness` (1/m, a list), `capacity` (a list of the same length), `sigma2` (N·s/m; 0) |
//! | `generalized_maxwell_slip` | [`GeneralizedMaxwellSlip::new`] | `stiffness` (1/m, a list), `weight` (a list of the same length), `mu_coulomb`, `mu_static`, `stribeck_velocity` (m/s), `stribeck_exponent` (2), `attraction` (1/s; absent = +∞), `sigma2` (N·s/m; 0) |
//! | `prandtl_tomlinson` | [`PrandtlTomlinson::new`] | `amplitude` (J), `period` (m), `stiffness` (N/m), `mass` (kg), `damping` (kg/s; 0), `tolerance` (1e-8) |
//! | `prandtl_tomlinson_two_spring` | [`PrandtlTomlinson::two_spring`] | `amplitude` (J), `period` (m), `tip_stiffness` (N/m), `tip_mass` (kg), `tip_damping` (kg/s; 0), `cantilever_stiffness` (N/m), `cantilever_mass` (kg), `cantilever_damping` (kg/s; 0), `tolerance` (1e-8) |
//! | `bristles` | [`Bristles::new`] | `stiffness` (1/m, a list), `break_deflection` (m, a list of the same length), `sigma2` (N·s/m; 0) |
//! | `burridge_knopoff` | [`BurridgeKnopoff::new`] | `blocks` (1–256), `mass` (kg), `coupling_stiffness` (N/m), `pulling_stiffness` (N/m), `mu_static`, `mu_kinetic`, `weakening_velocity` (m/s; absent = +∞, Coulomb), `damping` (kg/s; 0), `tolerance` (1e-8) |
//!
//! A parameter the constructor rejects is reported with its path:
//! [`SceneError::Invalid`](super::SceneError::Invalid) with `field`
//! `friction_models[i].<key>` and the constructor's error naming the
//! argument: ``invalid scene field `friction_models[1].lugre`: … `sigma1` …``.
//!
//! Adding a model: one line in the `model_specs!` list below and one spec
//! struct with a `build` method.
//!
//! # Along the track
//!
//! [`run_along`] steps a model once per increment k of an
//! energy-dissipation run ([`SlideRun::steps`]) with that increment's normal
//! load N_k (a tensile load as 0), the slip Δs = d/n along x (d the run's
//! distance, n its increments: the slide step as [`Slider::slide`] used
//! it) and Δt = Δs/v at the scene's sliding velocity v, from a fresh state,
//! in place ([`FrictionLaw::step_in_place`]; one state and one record
//! vector are allocated per run, nothing per step).
//!
//! [`Slider::slide`]: crate::friction::Slider::slide

use crate::contact::BatchError;
use crate::error::{check, Error, Result};
use crate::friction::dynamic::{
    Bristles, BurridgeKnopoff, DynamicModel, FrictionIncrement, FrictionLaw,
    GeneralizedMaxwellSlip, LuGre, MaxwellSlip, PrandtlTomlinson, STATE_DISSIPATION,
};
use crate::friction::slider::SlideRun;
use serde::de::{self, DeserializeSeed, Deserializer, EnumAccess, MapAccess, VariantAccess};
use serde::{Deserialize, Serialize};
use std::fmt;

// ------------------------------------------------------------ the specs

/// Parameters of [`LuGre::new`], under the same names.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LuGreSpec {
    /// Coulomb coefficient μ_c.
    pub mu_coulomb: f64,
    /// Static coefficient μ_s.
    pub mu_static: f64,
    /// Stribeck velocity v_s (m/s).
    pub stribeck_velocity: f64,
    /// Stribeck exponent δ (default 2, Gaussian).
    #[serde(default = "two")]
    pub stribeck_exponent: f64,
    /// Bristle stiffness σ₀ per unit normal force (1/m).
    pub sigma0: f64,
    /// Bristle damping σ₁ per unit normal force (s/m; default 0).
    #[serde(default)]
    pub sigma1: f64,
    /// Velocity v_d of the damping's decay (m/s); `None` (absent) is +∞,
    /// allowed only with σ₁ = 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub damping_velocity: Option<f64>,
    /// Viscous coefficient σ₂ (N·s/m; default 0).
    #[serde(default)]
    pub sigma2: f64,
}

fn two() -> f64 {
    2.0
}

impl LuGreSpec {
    /// The model ([`LuGre::new`]; its errors name the argument).
    pub fn build(&self) -> Result<LuGre> {
        LuGre::new(
            self.mu_coulomb,
            self.mu_static,
            self.stribeck_velocity,
            self.stribeck_exponent,
            self.sigma0,
            self.sigma1,
            self.damping_velocity.unwrap_or(f64::INFINITY),
            self.sigma2,
        )
    }
}

/// Parameters of [`MaxwellSlip::new`], under the same names.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaxwellSlipSpec {
    /// Element stiffnesses kᵢ per unit normal force (1/m).
    pub stiffness: Vec<f64>,
    /// Element break-away coefficients μᵢ, as many as `stiffness`.
    pub capacity: Vec<f64>,
    /// Viscous coefficient σ₂ (N·s/m; default 0).
    #[serde(default)]
    pub sigma2: f64,
}

impl MaxwellSlipSpec {
    /// The model ([`MaxwellSlip::new`]; its errors name the argument).
    pub fn build(&self) -> Result<MaxwellSlip> {
        MaxwellSlip::new(&self.stiffness, &self.capacity, self.sigma2)
    }
}

/// Parameters of [`GeneralizedMaxwellSlip::new`], under the same names.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GeneralizedMaxwellSlipSpec {
    /// Element stiffnesses kᵢ per unit normal force (1/m).
    pub stiffness: Vec<f64>,
    /// Element weights αᵢ, as many as `stiffness`.
    pub weight: Vec<f64>,
    /// Coulomb coefficient μ_c of the Stribeck curve.
    pub mu_coulomb: f64,
    /// Static coefficient μ_s of the Stribeck curve.
    pub mu_static: f64,
    /// Stribeck velocity v_s (m/s).
    pub stribeck_velocity: f64,
    /// Stribeck exponent δ (default 2).
    #[serde(default = "two")]
    pub stribeck_exponent: f64,
    /// Attraction rate C (1/s; absent = +∞, instantaneous).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub attraction: Option<f64>,
    /// Viscous coefficient σ₂ (N·s/m; default 0).
    #[serde(default)]
    pub sigma2: f64,
}

impl GeneralizedMaxwellSlipSpec {
    /// The model ([`GeneralizedMaxwellSlip::new`]; its errors name the
    /// argument).
    pub fn build(&self) -> Result<GeneralizedMaxwellSlip> {
        GeneralizedMaxwellSlip::new(
            &self.stiffness,
            &self.weight,
            self.mu_coulomb,
            self.mu_static,
            self.stribeck_velocity,
            self.stribeck_exponent,
            self.attraction.unwrap_or(f64::INFINITY),
            self.sigma2,
        )
    }
}

/// Parameters of [`PrandtlTomlinson::new`], under the same names.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PrandtlTomlinsonSpec {
    /// Potential amplitude U₀ (J).
    pub amplitude: f64,
    /// Potential period a (m).
    pub period: f64,
    /// Spring stiffness k (N/m).
    pub stiffness: f64,
    /// Tip mass m (kg).
    pub mass: f64,
    /// Damping γ (kg/s; default 0).
    #[serde(default)]
    pub damping: f64,
    /// Relative tolerance of the integration (default 1e-8).
    #[serde(default = "pt_tolerance")]
    pub tolerance: f64,
}

/// The Prandtl–Tomlinson integration tolerance when a scene gives none.
fn pt_tolerance() -> f64 {
    1e-8
}

impl PrandtlTomlinsonSpec {
    /// The model ([`PrandtlTomlinson::new`]; its errors name the argument).
    pub fn build(&self) -> Result<PrandtlTomlinson> {
        PrandtlTomlinson::new(
            self.amplitude,
            self.period,
            self.stiffness,
            self.mass,
            self.damping,
            self.tolerance,
        )
    }
}

/// Parameters of [`PrandtlTomlinson::two_spring`] (tip–cantilever), under
/// the same names.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PrandtlTomlinsonTwoSpringSpec {
    /// Potential amplitude U₀ (J).
    pub amplitude: f64,
    /// Potential period a (m).
    pub period: f64,
    /// Tip (contact) spring stiffness k_t (N/m).
    pub tip_stiffness: f64,
    /// Tip mass (kg).
    pub tip_mass: f64,
    /// Tip damping (kg/s; default 0).
    #[serde(default)]
    pub tip_damping: f64,
    /// Cantilever lateral stiffness k_c (N/m).
    pub cantilever_stiffness: f64,
    /// Cantilever mass (kg).
    pub cantilever_mass: f64,
    /// Cantilever damping (kg/s; default 0).
    #[serde(default)]
    pub cantilever_damping: f64,
    /// Relative tolerance of the integration (default 1e-8).
    #[serde(default = "pt_tolerance")]
    pub tolerance: f64,
}

impl PrandtlTomlinsonTwoSpringSpec {
    /// The model ([`PrandtlTomlinson::two_spring`]; its errors name the
    /// argument).
    pub fn build(&self) -> Result<PrandtlTomlinson> {
        PrandtlTomlinson::two_spring(
            self.amplitude,
            self.period,
            self.tip_stiffness,
            self.tip_mass,
            self.tip_damping,
            self.cantilever_stiffness,
            self.cantilever_mass,
            self.cantilever_damping,
            self.tolerance,
        )
    }
}

/// Parameters of [`BurridgeKnopoff::new`], under the same names. The chain
/// starts uniform (a fresh state), so it slides as one block: periodic
/// stick-slip.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BurridgeKnopoffSpec {
    /// Number of blocks M (1 to 256).
    pub blocks: usize,
    /// Mass of a block (kg).
    pub mass: f64,
    /// Stiffness of the springs between neighbours (N/m).
    pub coupling_stiffness: f64,
    /// Stiffness of each block's leaf spring to the driver (N/m).
    pub pulling_stiffness: f64,
    /// Static coefficient (per unit normal force; each block carries N/M).
    pub mu_static: f64,
    /// Kinetic coefficient at zero speed.
    pub mu_kinetic: f64,
    /// Carlson–Langer weakening velocity v_c (m/s); absent = +∞ (Coulomb).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub weakening_velocity: Option<f64>,
    /// Damping of each block (kg/s; default 0).
    #[serde(default)]
    pub damping: f64,
    /// Relative tolerance of the integration (default 1e-8).
    #[serde(default = "pt_tolerance")]
    pub tolerance: f64,
}

impl BurridgeKnopoffSpec {
    /// The model ([`BurridgeKnopoff::new`]; its errors name the argument).
    pub fn build(&self) -> Result<BurridgeKnopoff> {
        BurridgeKnopoff::new(
            self.blocks,
            self.mass,
            self.coupling_stiffness,
            self.pulling_stiffness,
            self.mu_static,
            self.mu_kinetic,
            self.weakening_velocity.unwrap_or(f64::INFINITY),
            self.damping,
            self.tolerance,
        )
    }
}

/// Parameters of [`Bristles::new`], under the same names.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BristlesSpec {
    /// Bristle stiffnesses kᵢ per unit normal force (1/m).
    pub stiffness: Vec<f64>,
    /// Break deflections δᵢ (m), as many as `stiffness`.
    pub break_deflection: Vec<f64>,
    /// Viscous coefficient σ₂ (N·s/m; default 0).
    #[serde(default)]
    pub sigma2: f64,
}

impl BristlesSpec {
    /// The model ([`Bristles::new`]; its errors name the argument).
    pub fn build(&self) -> Result<Bristles> {
        Bristles::new(&self.stiffness, &self.break_deflection, self.sigma2)
    }
}

/// Declares [`DynamicModelSpec`]: one variant per model with the
/// [`DynamicModel`] variant it builds and its scene key; each spec type has
/// `build(&self) -> Result<Model>`.
macro_rules! model_specs {
    ($($(#[$doc:meta])* $variant:ident($spec:ty) => $model:ident = $key:literal,)*) => {
        /// A model's parameters, by its scene key (see the module docs).
        #[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
        pub enum DynamicModelSpec {
            $($(#[$doc])* #[serde(rename = $key)] $variant($spec),)*
        }

        impl DynamicModelSpec {
            /// The scene keys of the models.
            pub const KEYS: &'static [&'static str] = &[$($key),*];

            /// The scene key of this model (`"lugre"`, …).
            pub fn key(&self) -> &'static str {
                match self {
                    $(DynamicModelSpec::$variant(_) => $key,)*
                }
            }

            /// The model; the constructor's errors name the argument.
            pub fn build(&self) -> Result<DynamicModel> {
                match self {
                    $(DynamicModelSpec::$variant(s) => s.build().map(DynamicModel::$model),)*
                }
            }
        }
    };
}

model_specs! {
    /// [`LuGre`].
    LuGre(LuGreSpec) => LuGre = "lugre",
    /// [`MaxwellSlip`].
    MaxwellSlip(MaxwellSlipSpec) => MaxwellSlip = "maxwell_slip",
    /// [`GeneralizedMaxwellSlip`].
    GeneralizedMaxwellSlip(GeneralizedMaxwellSlipSpec) => GeneralizedMaxwellSlip = "generalized_maxwell_slip",
    /// [`PrandtlTomlinson`] (one spring).
    PrandtlTomlinson(PrandtlTomlinsonSpec) => PrandtlTomlinson = "prandtl_tomlinson",
    /// [`PrandtlTomlinson::two_spring`] (tip and cantilever).
    PrandtlTomlinsonTwoSpring(PrandtlTomlinsonTwoSpringSpec) => PrandtlTomlinson = "prandtl_tomlinson_two_spring",
    /// [`BurridgeKnopoff`].
    BurridgeKnopoff(BurridgeKnopoffSpec) => BurridgeKnopoff = "burridge_knopoff",
    /// [`Bristles`].
    Bristles(BristlesSpec) => Bristles = "bristles",
}

/// One entry of a scene's `friction_models`: a name and one model,
/// `{"name": "LuGre", "lugre": {…}}`. Unknown keys are rejected (as an
/// unknown model), and so are a missing name or model and two models in one
/// entry.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct FrictionModelSpec {
    /// The label of the model's CSV column, plot line and summary.
    pub name: String,
    /// The model and its parameters.
    #[serde(flatten)]
    pub model: DynamicModelSpec,
}

impl<'de> Deserialize<'de> for FrictionModelSpec {
    fn deserialize<D: Deserializer<'de>>(d: D) -> core::result::Result<Self, D::Error> {
        d.deserialize_map(EntryVisitor)
    }
}

/// Reads `name` and one model key of an entry (serde cannot flatten an
/// enum into a struct that denies unknown fields).
struct EntryVisitor;

impl<'de> de::Visitor<'de> for EntryVisitor {
    type Value = FrictionModelSpec;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "a friction model: `name` and one of {}",
            DynamicModelSpec::KEYS.join(", ")
        )
    }

    fn visit_map<A: MapAccess<'de>>(
        self,
        mut map: A,
    ) -> core::result::Result<Self::Value, A::Error> {
        let mut name = None;
        let mut model: Option<DynamicModelSpec> = None;
        while let Some(key) = map.next_key::<String>()? {
            if key == "name" {
                if name.is_some() {
                    return Err(de::Error::duplicate_field("name"));
                }
                name = Some(map.next_value::<String>()?);
            } else if let Some(first) = &model {
                return Err(de::Error::custom(format_args!(
                    "one model per entry: `{key}` after `{}`",
                    first.key()
                )));
            } else {
                model = Some(DynamicModelSpec::deserialize(ModelEntry {
                    key,
                    map: &mut map,
                })?);
            }
        }
        let name = name.ok_or_else(|| de::Error::missing_field("name"))?;
        let model = model.ok_or_else(|| {
            de::Error::custom(format_args!(
                "missing the model: one of {}",
                DynamicModelSpec::KEYS.join(", ")
            ))
        })?;
        Ok(FrictionModelSpec { name, model })
    }
}

/// A model key already read from an entry, and the entry with its value
/// next: deserialises as the externally tagged `{key: value}`.
struct ModelEntry<'a, A> {
    key: String,
    map: &'a mut A,
}

impl<'de, A: MapAccess<'de>> Deserializer<'de> for ModelEntry<'_, A> {
    type Error = A::Error;

    fn deserialize_any<V: de::Visitor<'de>>(
        self,
        visitor: V,
    ) -> core::result::Result<V::Value, A::Error> {
        visitor.visit_enum(self)
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string
        bytes byte_buf option unit unit_struct newtype_struct seq tuple
        tuple_struct map struct enum identifier ignored_any
    }
}

impl<'de, A: MapAccess<'de>> EnumAccess<'de> for ModelEntry<'_, A> {
    type Error = A::Error;
    type Variant = Self;

    fn variant_seed<S: DeserializeSeed<'de>>(
        self,
        seed: S,
    ) -> core::result::Result<(S::Value, Self), A::Error> {
        use de::IntoDeserializer;
        let key: de::value::StrDeserializer<'_, A::Error> = self.key.as_str().into_deserializer();
        let v = seed.deserialize(key)?;
        Ok((v, self))
    }
}

impl<'de, A: MapAccess<'de>> VariantAccess<'de> for ModelEntry<'_, A> {
    type Error = A::Error;

    fn unit_variant(self) -> core::result::Result<(), A::Error> {
        Err(de::Error::custom("a model needs its parameters"))
    }

    fn newtype_variant_seed<S: DeserializeSeed<'de>>(
        self,
        seed: S,
    ) -> core::result::Result<S::Value, A::Error> {
        self.map.next_value_seed(seed)
    }

    fn tuple_variant<V: de::Visitor<'de>>(
        self,
        _len: usize,
        _visitor: V,
    ) -> core::result::Result<V::Value, A::Error> {
        Err(de::Error::custom("a model's parameters are an object"))
    }

    fn struct_variant<V: de::Visitor<'de>>(
        self,
        _fields: &'static [&'static str],
        _visitor: V,
    ) -> core::result::Result<V::Value, A::Error> {
        Err(de::Error::custom("a model's parameters are an object"))
    }
}

/// Checks an entry's name: not empty, no control characters (errors name
/// `name`; the value is its length in characters).
pub(super) fn check_name(name: &str) -> Result<()> {
    let len = name.chars().count() as f64;
    if name.trim().is_empty() {
        return Err(Error::InvalidArgument {
            name: "name",
            value: len,
            bound: "not empty",
        });
    }
    if name.chars().any(char::is_control) {
        return Err(Error::InvalidArgument {
            name: "name",
            value: len,
            bound: "without control characters",
        });
    }
    Ok(())
}

// ------------------------------------------------------------ the run

/// An increment dissipating more than this many times the run's median
/// increment dissipation belongs to a slip
/// ([`TrackSummary::stick_slip_events`]). Not `pub`: cbindgen would put a
/// public constant in the C header.
const STICK_SLIP_BURST: f64 = 10.0;

/// One increment of a dynamic model along the track (SI).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct TrackStep {
    /// Friction force along the motion, resisting it, at the end of the
    /// increment (N): −F_x of [`FrictionResponse::force`].
    ///
    /// [`FrictionResponse::force`]: crate::friction::FrictionResponse::force
    pub friction_force: f64,
    /// μ = F/N with F = `friction_force` (0 when N = 0): signed, negative
    /// while the force drives the point forward (a Prandtl–Tomlinson tip
    /// overshooting after a slip); |μ| is the step's
    /// [`FrictionResponse::cof`].
    ///
    /// [`FrictionResponse::cof`]: crate::friction::FrictionResponse::cof
    pub cof: f64,
    /// Energy dissipated in the increment (J), ≥ 0.
    pub dissipated: f64,
    /// Energy dissipated from the start of the run to the end of the
    /// increment (J): the state's accumulator.
    pub dissipation: f64,
}

/// Averages and totals of a model's run along the track (SI).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
pub struct TrackSummary {
    /// Number of increments.
    pub steps: usize,
    /// Mean μ over the increments (of the signed μ of [`TrackStep::cof`]).
    pub mean_cof: f64,
    /// The static coefficient: the largest μ of the run.
    pub static_cof: f64,
    /// Mean friction force over the increments (N).
    pub mean_friction_force: f64,
    /// Total dissipation (J).
    pub dissipation: f64,
    /// Stick-slip events: bursts of dissipation. Stick-slip stores energy
    /// slowly while sticking and dissipates it suddenly in the slip, so a
    /// slip is a run of consecutive increments each dissipating more than
    /// ten times the median increment dissipation of the
    /// run (any dissipation when the median is 0). Steady sliding (LuGre,
    /// Maxwell-slip in gross sliding, Prandtl–Tomlinson well below its
    /// stick-slip threshold) dissipates evenly and has none. The
    /// dissipation of an increment is integrated over it, so a slip shorter
    /// than an increment still counts (once, even when it crosses several
    /// lattice periods); smooth sliding close to the threshold, where the
    /// tip already darts through the steep parts of the potential
    /// (Prandtl–Tomlinson with η ≳ 0.8), counts as well. Meaningful at a
    /// steady normal load (the dissipation of Amontons-scaled models
    /// follows the load).
    pub stick_slip_events: usize,
}

/// A dynamic model's run along the track: every increment and the summary.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrackRun {
    /// Records of the increments, in the order of the slide's.
    pub steps: Vec<TrackStep>,
    /// Averages and totals.
    pub summary: TrackSummary,
}

/// Runs `model` along the track of the energy-dissipation run `run` at the
/// sliding velocity `velocity` (m/s, finite, > 0): see the module docs.
/// Errors: `velocity` (index 0, nothing stepped), or the step's error at
/// increment `index` (a Prandtl–Tomlinson integration out of sub-steps, a
/// non-finite slip).
pub fn run_along<M: FrictionLaw + ?Sized>(
    model: &M,
    run: &SlideRun,
    velocity: f64,
) -> core::result::Result<TrackRun, BatchError> {
    check::positive("velocity", velocity).map_err(|error| BatchError { index: 0, error })?;
    let n = run.steps.len();
    let mut steps = Vec::with_capacity(n);
    let mut state = vec![0.0; model.state_len()];
    let mut work = model.work();
    if n > 0 {
        let dx = run.summary.distance / n as f64;
        let dt = dx / velocity;
        for (index, s) in run.steps.iter().enumerate() {
            let increment = FrictionIncrement {
                normal_force: s.normal_load.max(0.0),
                slip: [dx, 0.0],
                dt,
                ..FrictionIncrement::default()
            };
            let r = model
                .step_in_place(&mut state, &increment, &mut work)
                .map_err(|error| BatchError { index, error })?;
            let friction_force = -r.force[0];
            let normal = increment.normal_force;
            steps.push(TrackStep {
                friction_force,
                cof: if normal > 0.0 {
                    friction_force / normal
                } else {
                    0.0
                },
                dissipated: r.dissipated,
                dissipation: state[STATE_DISSIPATION],
            });
        }
    }
    let summary = TrackSummary::of(&steps);
    Ok(TrackRun { steps, summary })
}

impl TrackSummary {
    /// The summary of a model's increments.
    pub fn of(steps: &[TrackStep]) -> Self {
        let n = steps.len();
        let mut s = Self {
            steps: n,
            ..Self::default()
        };
        if n == 0 {
            return s;
        }
        s.static_cof = f64::NEG_INFINITY;
        for r in steps {
            s.mean_cof += r.cof;
            s.mean_friction_force += r.friction_force;
            s.static_cof = s.static_cof.max(r.cof);
        }
        s.mean_cof /= n as f64;
        s.mean_friction_force /= n as f64;
        s.dissipation = steps[n - 1].dissipation;
        s.stick_slip_events = stick_slip_events(steps);
        s
    }
}

/// The stick-slip events of a run (see
/// [`TrackSummary::stick_slip_events`]).
fn stick_slip_events(steps: &[TrackStep]) -> usize {
    let mut d: Vec<f64> = steps.iter().map(|r| r.dissipated).collect();
    if d.is_empty() {
        return 0;
    }
    let mid = d.len() / 2;
    let median = *d.select_nth_unstable_by(mid, f64::total_cmp).1;
    let threshold = STICK_SLIP_BURST * median;
    let mut events = 0;
    let mut in_slip = false;
    for r in steps {
        let slip = r.dissipated > threshold;
        if slip && !in_slip {
            events += 1;
        }
        in_slip = slip;
    }
    events
}
