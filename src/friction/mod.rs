//! Friction between rough surfaces by energy dissipation (thesis chapters 4–6).
//!
//! * [`geometry`]: the slider of the multi-scale, multi-level hierarchical
//!   model — micro-rods cut from a profilometer profile (6-1), nested in
//!   levels, carrying nano-asperities whose van der Waals and chemical
//!   domains come from an AFM profile (5-15..5-19, 6-2, 6-3). The result,
//!   [`SliderGeometry`], is built once, immutable, shareable between threads
//!   and serialisable; the friction model consumes it.
//! * [`rods`]: the mechanical equilibrium of the micro-rods (elastic–perfectly
//!   plastic, 4.3.1) against the rigid counter-surface at fixed gap
//!   (6-9..6-12) and fixed load (6-13..6-16) — exact breakpoint sweep, warm
//!   start, the thesis's dense formulation as reference, plastic shortening
//!   with volume-conserving pile-up (6.2.3), energies (4-15, 4-16), and rods
//!   coupled through an elastic substrate ([`CoupledRodBed`]).

pub mod geometry;
pub mod rods;

pub use geometry::{
    asperity_statistics, nano_analysis, nano_per_rod, rod_heights, rod_levels, AsperityStatistics,
    NanoAnalysis, NanoAsperities, RodLevel, SliderGeometry,
};
pub use rods::{
    square_influence, CoupledRodBed, PlasticUpdate, RodBed, RodOptions, RodReport, RodSolution,
    RodSolver, RodState,
};
