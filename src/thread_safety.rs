//! Compile-time proof of the library's thread-safety contract.
//!
//! Host codes evaluate one law, one table, one friction law or one slider from
//! many threads at once. Every handle a user shares is immutable after
//! construction and must be `Send + Sync`; the per-caller scratch (a slider's
//! [`SliderWork`], states, solutions) must be `Send` so each thread can own
//! one. The assertions below are in the library, not a test: a field that
//! adds interior mutability or a raw pointer to one of these types breaks the
//! build of the crate itself.
//!
//! The C handles are covered too (`AsperityTable`, `AsperitySlider`, …): the
//! header's "Thread safety" paragraph (cbindgen.toml) promises what is
//! asserted here.

use crate::contact::{
    ContactState, LjSolver, LjSphere, NormalLaw, NormalResponse, SurfaceLaw, TabulatedLaw,
};
use crate::ffi::contact::AsperityNormalLaw;
use crate::ffi::friction::AsperitySliderGeometry;
use crate::ffi::friction_law::{AsperityFriction, AsperityFrictionWork};
use crate::ffi::homogenised::AsperityHomogenisedFriction;
use crate::ffi::slider::AsperitySlider;
use crate::ffi::statistics::{AsperityBora, AsperityGwEmpirical};
use crate::ffi::tabulated::AsperityTable;
use crate::friction::{
    CoupledRodBed, FrictionMaterial, HomogenisedFriction, RodBed, RodSolution, RodState, Slider,
    SliderGeometry, SliderWork,
};
use crate::material::Material;
use crate::rescaling::{KnownSolution, Rescaling};
use crate::statistics::{
    BearingCurveRods, GreenwoodWilliamson, HeightDistribution, KragelskyRods, PowerLawAsperities,
    Zhuravlev,
};

/// Shared, immutable handles: `Send + Sync`.
const _: () = {
    const fn shared<T: Send + Sync>() {}
    // Closed-form laws: the enum is Send + Sync only if every law it
    // carries is, so this one line covers each of them; and the C value.
    shared::<NormalLaw>();
    shared::<SurfaceLaw>();
    shared::<AsperityNormalLaw>();
    // Tabulated laws and the Lennard-Jones sphere.
    shared::<TabulatedLaw>();
    shared::<AsperityTable>();
    shared::<LjSphere>();
    shared::<LjSolver>();
    // Statistical models.
    shared::<GreenwoodWilliamson>();
    shared::<HeightDistribution>();
    shared::<KragelskyRods>();
    shared::<BearingCurveRods>();
    shared::<PowerLawAsperities>();
    shared::<Zhuravlev>();
    shared::<AsperityGwEmpirical>();
    shared::<AsperityBora>();
    // Rescaling and materials.
    shared::<Rescaling>();
    shared::<KnownSolution>();
    shared::<Material>();
    shared::<FrictionMaterial>();
    // Friction.
    shared::<HomogenisedFriction>();
    shared::<crate::friction::dynamic::LuGre>();
    shared::<crate::friction::dynamic::MaxwellSlip>();
    shared::<crate::friction::dynamic::GeneralizedMaxwellSlip>();
    shared::<crate::hierarchical::Archard>();
    shared::<crate::hierarchical::CantorProfile>();
    shared::<crate::friction::dynamic::PrandtlTomlinson>();
    shared::<crate::friction::dynamic::BurridgeKnopoff>();
    shared::<crate::friction::dynamic::Bristles>();
    shared::<crate::friction::dynamic::DynamicModel>();
    shared::<AsperityFriction>();
    shared::<AsperityHomogenisedFriction>();
    shared::<SliderGeometry>();
    shared::<AsperitySliderGeometry>();
    shared::<Slider>();
    shared::<AsperitySlider>();
    shared::<RodBed>();
    shared::<CoupledRodBed>();
};

/// Per-thread (per-caller) scratch and history: `Send`, so each thread can
/// own its own; never shared while mutated.
const _: () = {
    const fn per_thread<T: Send>() {}
    per_thread::<SliderWork>();
    per_thread::<AsperityFrictionWork>();
    per_thread::<crate::friction::FrictionWork>();
    per_thread::<RodState>();
    per_thread::<RodSolution>();
    per_thread::<ContactState>();
    per_thread::<NormalResponse>();
};
