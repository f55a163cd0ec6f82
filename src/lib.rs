//! # asperity
//!
//! The physics of dry contact between rough surfaces for simulation codes:
//! single-asperity normal contact laws (Hertz, Galin power-law punches, JKR,
//! DMT, Maugis–Dugdale, Kendall, Derjaguin with a surface-force law), with a
//! stable C ABI (`include/asperity.h`) for finite-element, DEM and
//! molecular-dynamics host codes.
//!
//! ## Units and conventions
//!
//! SI throughout, plain `f64`: m, N, Pa, J, J/m². No hidden scaling:
//! dimensionless groups (Tabor μ, Maugis λ) are computed by named functions in
//! [`material`]. Overlap δ > 0 is penetration; force P > 0 is repulsive. The
//! adhesion parameter is the work of adhesion `w` (Dupré; `w = 2γ` for
//! identical surfaces), named `work_of_adhesion` everywhere.
//!
//! ## Modules
//!
//! * [`material`]: contact modulus E*, rod modulus, no-slip factor, Tabor and
//!   Maugis parameters.
//! * [`contact`]: the laws, one file each, all implementing
//!   [`contact::NormalContact`].
//! * [`rescaling`] and [`indentation`]: Borodich rescaling, Galanov shapes, κ and d from measured curves, Oliver–Pharr, hardness numbers.
//! * [`afm`]: AFM force–distance curves: baseline, contact point, jump-in, pull-off, adhesion energy, contact-law fits and the model the data support.
//! * [`surface`]: profiles and maps, ISO 4287 parameters, ACF/PSD, generators.
//! * [`statistics`]: Zhuravlev, Greenwood–Williamson and Kragelsky models.
//! * [`hierarchical`]: hierarchical roughness (thesis 5.4): Archard's
//!   spheres on spheres, Cantor–Liu and Cantor–Borodich profile contact.
//! * [`friction`]: the slider geometry of the hierarchical friction model
//!   (micro-rods and nano-asperities from measured profiles, thesis 6.2.1).
//! * [`fidelity`]: the cheapest adhesive-sphere model within a force
//!   tolerance, measured against the converged Lennard-Jones sphere.
//! * [`error`]: the error type; every fallible call returns
//!   [`error::Result`].
//! * `ffi`: the C ABI (thin translation only; see `include/asperity.h`).
//!
//! ## Sources
//!
//! Equation numbers "(1-37)" refer to the PhD thesis on multi-scale dry
//! friction that seeds this project; `REFERENCE.md` in the project's shared
//! folder restores its formulas. Each law's documentation cites its equation
//! and the original paper, and ends with a *References* section.
//!
//! ## Reading the formulas
//!
//! The module docs write their formulas in LaTeX, rendered by KaTeX from
//! `docs/katex-header.html` (docs.rs passes it through
//! `[package.metadata.docs.rs]`). A local build needs the header on the
//! command line, for this crate only:
//!
//! ```text
//! RUSTDOCFLAGS="--html-in-header docs/katex-header.html" cargo doc --no-deps --open
//! ```
//!
//! (`scripts/check-docs.sh` does this and fails on any rustdoc warning.)
//! The header is not set in `.cargo/config.toml`: cargo would pass it to
//! every dependency documented by a plain `cargo doc`, where the relative
//! path does not resolve. Without the header the formulas show as their
//! LaTeX source, for example $P = \tfrac43 E^\ast R^{1/2}\delta^{3/2}$.

#![deny(missing_docs)]

pub mod afm;
pub mod contact;
pub mod error;
pub mod ffi;
pub mod fidelity;
pub mod friction;
pub mod hierarchical;
pub mod indentation;
pub mod material;
mod report;
pub mod rescaling;
pub mod scene;
mod serde_exact;
mod simd;
pub mod statistics;
pub mod surface;
mod thread_safety;

pub use contact::{ContactState, Control, NormalContact, NormalLaw, NormalResponse};
pub use error::{Error, Result};
