//! The dynamic friction models of thesis chapter 5, through the
//! friction step's conventions: a pure function of the model's parameters,
//! a caller-owned old state and one increment, giving the new state and the
//! response. Nothing is allocated, old and new states are separate (a host
//! can re-evaluate or cut back an increment), and an all-zero state is a
//! fresh one.
//!
//! * [`Bristles`]: the bristle model of Haessig and Friedland (thesis
//!   5.3.6, (5-8)): elastic bristles that snap at their break deflection
//!   and bond again undeflected, the snaps counted exactly per increment.
//! * [`LuGre`]: its standard continuous form, LuGre (Canudas de Wit et al.
//!   1995), with Stribeck velocity weakening, integrated exactly over each
//!   increment.
//! * [`PrandtlTomlinson::pull_by_force`]: the tip pulled by a constant
//!   force (thesis (5-5)), whose static friction is the lattice force.
//! * [`DynamicModel`]: any of them, chosen by configuration; every model
//!   implements [`FrictionLaw`] (step, in place, VFRIC-shaped block).
//! * [`PrandtlTomlinson`]: a tip in a periodic lattice potential pulled
//!   through a spring (thesis 5.3.1, (5-5), (5-6)), or through the tip and
//!   cantilever springs in series ([`PrandtlTomlinson::two_spring`]),
//!   integrated with error control; stick-slip when 4π²U₀/(k_eff a²) > 1.
//! * [`MaxwellSlip`]: N Maxwell-slip elements in parallel (Al-Bender,
//!   Lampaert and Swevers 2004; thesis 5.3.8, (5-9)..(5-12) reduced to the
//!   tangential direction): pre-sliding hysteresis with non-local memory.
//! * [`GeneralizedMaxwellSlip`]: the generalised Maxwell-slip model
//!   (Al-Bender, Lampaert and Swevers 2005; thesis 5.3.8): the elements'
//!   slip attracted to a Stribeck curve, integrated exactly per increment.
//! * [`BurridgeKnopoff`]: a chain of blocks coupled by springs and pulled
//!   from a driver plate over velocity-weakening friction (Burridge and
//!   Knopoff 1967, Carlson and Langer 1989; thesis (5-14)), with the stick
//!   and slip of every block located as events.
//! * [`stick_slip()`]: stick-slip events and the static and kinetic friction
//!   of a force history.
//!
//! The integrated models (Prandtl–Tomlinson, Burridge–Knopoff) share one
//! Dormand–Prince 5(4) integrator with error control and dense output.
//!
//! # Conventions
//!
//! LuGre and Maxwell-slip are **Amontons-scaled**: every force is
//! proportional to the normal force N of the increment (bristle and element
//! stiffnesses and break-away forces are given per unit normal force), so
//! μ = |F|/N does not depend on N and a change of N between increments
//! rescales the stored forces without slip. A viscous term σ₂·v (N·s/m) is
//! added on top. The Burridge–Knopoff blocks carry N/M each with friction
//! coefficients (their springs are absolute); the Prandtl–Tomlinson model
//! does not depend on N.
//!
//! The slip increment Δs is the motion of the point relative to the
//! counter-surface (two components in the caller's tangent basis; a track
//! uses `slip[1] = 0`); the force is the force on the point from the
//! counter-surface, opposing slip, as in [`super::HomogenisedFriction`].
//! Each increment is taken at constant velocity v = Δs/Δt and constant N.
//!
//! **Energy.** The response gives the energy dissipated in the increment
//! (≥ 0, the integral of the dissipation rate along the increment) and the
//! elastic energy stored at its end. At constant N the work of the friction
//! force along the increment equals the dissipation plus the change of the
//! stored energy. The work of the *end-of-increment* force, −F·Δs, differs
//! from it by a term of second order in the increment.
//!
//! # State layout
//!
//! `state_len()` doubles: `[dissipation, slip path, model state…]` with the
//! accumulated dissipation (J) and slip path Σ|Δs| (m) first
//! ([`STATE_DISSIPATION`], [`STATE_SLIP_PATH`]), then the model's own
//! variables (see each model).

pub mod bristles;
pub mod burridge_knopoff;
mod dormand_prince;
pub mod generalized_maxwell_slip;
pub mod lugre;
pub mod maxwell_slip;
pub mod prandtl_tomlinson;
pub mod stick_slip;

pub use bristles::Bristles;
pub use burridge_knopoff::BurridgeKnopoff;
pub use generalized_maxwell_slip::GeneralizedMaxwellSlip;
pub use lugre::LuGre;
pub use maxwell_slip::MaxwellSlip;
pub use prandtl_tomlinson::{ForcePull, PrandtlTomlinson};
pub use stick_slip::{stick_slip, SlipEvent, StickSlip};

pub(crate) use super::law::{book_path, read};
pub use super::law::{
    FrictionIncrement, FrictionLaw, FrictionRegime, FrictionResponse, FrictionWork,
    STATE_DISSIPATION, STATE_MODEL, STATE_SLIP_PATH, TANGENT_NORMAL, TANGENT_SLIP,
};
use crate::error::{check, Error, Result};

/// A dynamic friction model chosen by configuration.
#[derive(Debug, Clone, PartialEq)]
pub enum DynamicModel {
    /// [`LuGre`].
    LuGre(LuGre),
    /// [`MaxwellSlip`].
    MaxwellSlip(MaxwellSlip),
    /// [`GeneralizedMaxwellSlip`].
    GeneralizedMaxwellSlip(GeneralizedMaxwellSlip),
    /// [`PrandtlTomlinson`] (one or two springs).
    PrandtlTomlinson(PrandtlTomlinson),
    /// [`BurridgeKnopoff`].
    BurridgeKnopoff(BurridgeKnopoff),
    /// [`Bristles`].
    Bristles(Bristles),
}

macro_rules! each_model {
    ($self:expr, $m:ident => $e:expr) => {
        match $self {
            DynamicModel::LuGre($m) => $e,
            DynamicModel::MaxwellSlip($m) => $e,
            DynamicModel::GeneralizedMaxwellSlip($m) => $e,
            DynamicModel::PrandtlTomlinson($m) => $e,
            DynamicModel::BurridgeKnopoff($m) => $e,
            DynamicModel::Bristles($m) => $e,
        }
    };
}

impl FrictionLaw for DynamicModel {
    fn state_len(&self) -> usize {
        each_model!(self, m => m.state_len())
    }
    fn rate_dependent(&self) -> bool {
        each_model!(self, m => m.rate_dependent())
    }
    fn check(&self, increment: &FrictionIncrement) -> Result<()> {
        each_model!(self, m => m.check(increment))
    }
    fn check_state(&self, state: &[f64], what: &'static str) -> Result<()> {
        each_model!(self, m => m.check_state(state, what))
    }
    fn advance(
        &self,
        old: Option<&[f64]>,
        new: &mut [f64],
        increment: &FrictionIncrement,
        work: &mut FrictionWork,
    ) -> Result<FrictionResponse> {
        each_model!(self, m => m.advance(old, new, increment, work))
    }
}

/// The check of a one-dimensional model (Prandtl–Tomlinson,
/// Burridge–Knopoff, bristles): the increment's `slip[1]` must be 0.
pub(crate) fn track_only(increment: &FrictionIncrement) -> Result<()> {
    if increment.slip[1] != 0.0 {
        return Err(Error::InvalidArgument {
            name: "slip",
            value: increment.slip[1],
            bound: "slip[1] = 0 (the model is one-dimensional)",
        });
    }
    Ok(())
}

/// The shared checks of parallel elements (Maxwell-slip, generalised
/// Maxwell-slip, bristles):
/// `stiffness` not empty, every value finite and > 0, and `other` as long
/// (its length error names `other_len`, e.g. `capacity.len()`). The caller
/// checks `other`'s values.
pub(crate) fn check_elements(
    stiffness: &[f64],
    other: &[f64],
    other_len: &'static str,
) -> Result<()> {
    if stiffness.is_empty() || other.len() != stiffness.len() {
        return Err(Error::InvalidArgument {
            name: other_len,
            value: other.len() as f64,
            bound: "equal to stiffness.len() >= 1",
        });
    }
    for &k in stiffness {
        check::positive("stiffness", k)?;
    }
    Ok(())
}

/// |(x, y)|: √(x² + y²), exactly |x| on a track (y = 0) without the
/// square root, with `hypot`'s care only where the squares overflow or
/// underflow (`hypot` costs several times more per call).
#[inline]
pub(crate) fn norm(x: f64, y: f64) -> f64 {
    if y == 0.0 {
        return x.abs();
    }
    let s = x * x + y * y;
    if s.is_finite() && s >= f64::MIN_POSITIVE {
        s.sqrt()
    } else {
        x.hypot(y)
    }
}

/// Books an increment's dissipation and slip into the common part of `new`,
/// from the old state's accumulators.
#[inline]
pub(crate) fn book(old: Option<&[f64]>, new: &mut [f64], dissipated: f64, slip: [f64; 2]) {
    book_path(old, new, dissipated, norm(slip[0], slip[1]));
}

/// Fills the force, its magnitude, N and μ of a response from the friction
/// force `f` (N, along the motion, resisting it).
pub(crate) fn respond(f: [f64; 2], normal_force: f64) -> FrictionResponse {
    let force = [-f[0], -f[1]];
    let magnitude = norm(force[0], force[1]);
    FrictionResponse {
        force,
        force_magnitude: magnitude,
        normal_force,
        cof: if normal_force > 0.0 {
            magnitude / normal_force
        } else {
            0.0
        },
        ..FrictionResponse::default()
    }
}

#[cfg(test)]
mod tests {
    use super::norm;

    /// `norm` agrees with `hypot` (exactly on a track, y = 0) for every
    /// pair of special values.
    #[test]
    fn norm_agrees_with_hypot() {
        let specials = crate::friction::law::tests::SPECIALS;
        for &x in &specials {
            for &y in &specials {
                let (got, want) = (norm(x, y), x.hypot(y));
                assert!(
                    got == want || (got.is_nan() && want.is_nan()),
                    "norm({x}, {y}) = {got}, hypot {want}"
                );
            }
        }
    }
}
