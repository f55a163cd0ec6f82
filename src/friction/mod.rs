//! Friction between rough surfaces by energy dissipation (thesis chapters 4–6).
//!
//! * [`geometry`]: the slider of the multi-scale, multi-level hierarchical
//!   model — micro-rods cut from a profilometer profile (6-1), nested in
//!   levels, carrying nano-asperities whose van der Waals and chemical
//!   domains come from an AFM profile (5-15..5-19, 6-2, 6-3). The result,
//!   [`SliderGeometry`], is built once, immutable, shareable between threads
//!   and serialisable; the friction model consumes it.
//! * [`mechanisms`]: the dissipation mechanisms of chapter 4 and their
//!   constants — [`FrictionMaterial`] (the thesis's copper built in),
//!   chemical and van der Waals bond counts and their dissipation per unit
//!   slip (4-6..4-9), the adhesive holding force of a nano-asperity
//!   (no-slip Kendall, 4.4), the Lennard-Jones nano-asperity and its
//!   bilinear elastic–rigid law (4-11..4-14), and the elastic (4-15) and
//!   plastic (4-16) energies of an elastic–perfectly plastic micro-rod.
//! * [`ledger`]: the energy ledger — [`Dissipation`] by mechanism,
//!   [`Mechanisms`] switches, the quasi-static step [`ledger_step`]
//!   (F = ΔU/Δx, 4-1), the coefficient of friction in the Amontons, Coulomb
//!   or Derjaguin form (1-1..1-3, 4-3), the hand calculation of 4.4
//!   ([`apparent_friction`], μ = 1.0156) and the single-rod model of 5.2
//!   ([`single_rod`]).
//! * [`rods`]: the mechanical equilibrium of the micro-rods (elastic–perfectly
//!   plastic, 4.3.1) against the rigid counter-surface at fixed gap
//!   (6-9..6-12) and fixed load (6-13..6-16) — exact breakpoint sweep, warm
//!   start, the thesis's dense formulation as reference, plastic shortening
//!   with volume-conserving pile-up (6.2.3), energies (4-15, 4-16), and rods
//!   coupled through an elastic substrate ([`CoupledRodBed`]).
//! * [`law`]: the friction step per time increment of a host code, one
//!   contract for every friction law ([`FrictionLaw`]: caller-owned flat
//!   states, old and new separate or in place, tangents for implicit codes,
//!   a VFRIC-shaped block).
//! * [`homogenised`]: the friction law of an FE integration point —
//!   [`HomogenisedFriction`], μ(p), adhesion, contact fraction and
//!   dissipation shares tabulated over the nominal pressure (monotone cubic
//!   interpolation), evaluated by a regularised Coulomb/Derjaguin return
//!   mapping.
//! * [`slider`]: the hierarchical slider that slides (6.3–6.5) — counter
//!   heights under the rods, the rod equilibrium, nano-asperities in contact
//!   (adhesive snap-in, yielded rods), the ledger of every increment, true
//!   contact area (6.5.3), runs and their summaries ([`Slider`]).
//! * [`dynamic`]: the dynamic friction models of chapter 5 (LuGre with
//!   Stribeck weakening, Maxwell-slip elements) in the same per-increment
//!   shape, as [`FrictionLaw`]s.

pub mod dynamic;
pub mod geometry;
pub mod homogenised;
pub mod law;
pub mod ledger;
pub mod mechanisms;
pub mod rods;
pub mod slider;

pub use geometry::{
    asperity_statistics, nano_analysis, nano_per_rod, rod_heights, rod_levels, AsperityStatistics,
    NanoAnalysis, NanoAsperities, RodLevel, SliderGeometry, MAX_NANO_PER_ROD, MAX_RODS,
};
pub use homogenised::{HomogenisedFriction, HomogenisedSample};
pub use law::{
    BlockStates, FrictionBlock, FrictionIncrement, FrictionLaw, FrictionRegime, FrictionResponse,
    FrictionWork, STATE_DISSIPATION, STATE_MODEL, STATE_SLIP_PATH, TANGENT_NORMAL, TANGENT_SLIP,
};
pub use ledger::{
    apparent_friction, coefficient_of_friction, ledger_step, ledger_step_for, single_rod,
    yielded_slider_friction, ApparentFriction, CofForm, Dissipation, LedgerStep, Mechanisms,
};
pub use mechanisms::{
    bond_dissipation_per_slip, bond_energy_from_molar, chemical_bond_count, elastic_strain_energy,
    nano_holding_force, plastic_work, released_elastic_energy, vdw_bond_count, ElasticPlasticRod,
    FrictionMaterial, LjNanoAsperity, NanoAsperityBonds, RodIncrement,
};
pub use rods::{
    square_influence, CoupledRodBed, Loading, PlasticUpdate, RodBed, RodOptions, RodReport,
    RodSolution, RodSolver, RodState,
};
pub use slider::{
    summarize, CounterHeight, SlideRun, SlideStep, SlideSummary, Slider, SliderOptions, SliderWork,
    TrackEnd,
};
