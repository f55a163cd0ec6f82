//! Friction between rough surfaces by energy dissipation (thesis chapters 4–6).
//!
//! * [`geometry`]: the slider of the multi-scale, multi-level hierarchical
//!   model — micro-rods cut from a profilometer profile (6-1), nested in
//!   levels, carrying nano-asperities whose van der Waals and chemical
//!   domains come from an AFM profile (5-15..5-19, 6-2, 6-3). The result,
//!   [`SliderGeometry`], is built once, immutable, shareable between threads
//!   and serialisable; the friction model consumes it.

pub mod geometry;

pub use geometry::{
    asperity_statistics, nano_analysis, nano_per_rod, rod_heights, rod_levels, AsperityStatistics,
    NanoAnalysis, NanoAsperities, RodLevel, SliderGeometry,
};
