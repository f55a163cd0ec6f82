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
//!   implements [`DynamicFriction`] (step, in place, VFRIC-shaped block).
//! * [`PrandtlTomlinson`]: a tip in a periodic lattice potential pulled
//!   through a spring (thesis 5.3.1, (5-5), (5-6)), or through the tip and
//!   cantilever springs in series ([`PrandtlTomlinson::two_spring`]),
//!   integrated with error control; stick-slip when 4π²U₀/(k_eff a²) > 1.
//! * [`MaxwellSlip`]: N Maxwell-slip elements in parallel (Al-Bender,
//!   Lampaert and Swevers 2004; thesis 5.3.7, (5-9)..(5-12) reduced to the
//!   tangential direction): pre-sliding hysteresis with non-local memory.
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
pub mod lugre;
pub mod maxwell_slip;
pub mod prandtl_tomlinson;
pub mod stick_slip;

pub use bristles::Bristles;
pub use burridge_knopoff::BurridgeKnopoff;
pub use lugre::LuGre;
pub use maxwell_slip::MaxwellSlip;
pub use prandtl_tomlinson::{ForcePull, PrandtlTomlinson};
pub use stick_slip::{stick_slip, SlipEvent, StickSlip};

use crate::contact::BatchError;
use crate::error::{check, Error, Result};

/// Index of the accumulated dissipation (J) in a state.
pub const STATE_DISSIPATION: usize = 0;
/// Index of the accumulated slip path Σ|Δs| (m) in a state.
pub const STATE_SLIP_PATH: usize = 1;
/// Index of the first model variable in a state.
pub const STATE_MODEL: usize = 2;

/// [`DynamicIncrement::tangents`] bit: compute dF/dN.
pub const TANGENT_NORMAL: i32 = 1;
/// [`DynamicIncrement::tangents`] bit: compute dF/dΔs.
pub const TANGENT_SLIP: i32 = 2;

/// One increment of a contact point (SI units).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct DynamicIncrement {
    /// Normal force N (N), finite and ≥ 0 (compressive), constant over the
    /// increment.
    pub normal_force: f64,
    /// Slip increment Δs of the point relative to the counter-surface (m),
    /// two finite components.
    pub slip: [f64; 2],
    /// Time increment Δt (s), finite and ≥ 0; > 0 when the slip is not zero
    /// and the model is rate dependent.
    pub dt: f64,
    /// Tangents wanted: 0, or [`TANGENT_NORMAL`] | [`TANGENT_SLIP`].
    pub tangents: i32,
    /// Reserved, 0.
    pub reserved: i32,
}

/// The response of one increment (SI units).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct DynamicResponse {
    /// Tangential force on the point from the counter-surface at the end of
    /// the increment (N), in the basis of the slip.
    pub force: [f64; 2],
    /// |F| (N).
    pub force_magnitude: f64,
    /// Normal force N (N), as given.
    pub normal_force: f64,
    /// |F|/N; 0 when N = 0.
    pub cof: f64,
    /// Energy dissipated in the increment (J), ≥ 0.
    pub dissipated: f64,
    /// Elastic energy stored in the model at the end of the increment (J).
    pub stored_energy: f64,
    /// dF/dN at fixed slip increment and old state (dimensionless), when
    /// asked for.
    pub dforce_dnormal: [f64; 2],
    /// dF_i/dΔs_j (N/m), `dforce_dslip[i][j]`, at fixed N, Δt and old state,
    /// when asked for.
    pub dforce_dslip: [[f64; 2]; 2],
    /// What the increment did (each model documents its values): 0 stick,
    /// 1 partial slip (pre-sliding), 2 gross sliding.
    pub regime: i32,
    /// The tangents computed, as [`TANGENT_NORMAL`] | [`TANGENT_SLIP`] bits.
    pub tangents: i32,
}

/// A friction model stepped once per increment. Implemented by [`LuGre`],
/// [`MaxwellSlip`], [`PrandtlTomlinson`], [`BurridgeKnopoff`], [`Bristles`] and
/// [`DynamicModel`] (the choice by configuration).
pub trait DynamicFriction: sealed::Advance {
    /// Doubles of one point's state.
    fn state_len(&self) -> usize;

    /// One increment from `old` into `new` (each [`Self::state_len`]
    /// doubles; all-zero `old` = fresh). Errors name the argument: the
    /// increment's `normal_force`, `slip`, `dt`, `tangents`; `old.len()`,
    /// `new.len()`; `old.dissipation`, `old.slip_path` (finite, ≥ 0), `old`
    /// (finite). On error `new` is untouched.
    fn step(
        &self,
        old: &[f64],
        new: &mut [f64],
        increment: &DynamicIncrement,
    ) -> Result<DynamicResponse> {
        check_increment(increment, self.rate_dependent())?;
        self.check(increment)?;
        check_len("new.len()", new.len(), self.state_len())?;
        check_state(old, "old", self.state_len())?;
        self.advance(Some(old), new, increment)
    }

    /// [`Self::step`] with the state updated in place (errors name
    /// `state…`); on error `state` is untouched.
    fn step_in_place(
        &self,
        state: &mut [f64],
        increment: &DynamicIncrement,
    ) -> Result<DynamicResponse> {
        check_increment(increment, self.rate_dependent())?;
        self.check(increment)?;
        check_state(state, "state", self.state_len())?;
        self.advance(None, state, increment)
    }

    /// n points at once, in the shape of Abaqus/Explicit VFRIC: normal
    /// forces `normal_force[i]` (N), slip increments `slip[2i]`, `[2i+1]`
    /// (m), one `dt` (s), states `states[i·m..(i+1)·m]` (m =
    /// [`Self::state_len`]) stepped in place, forces on the points into
    /// `tangential_force[2i]`, `[2i+1]` (N) and the increments' dissipation
    /// into `dissipation[i]` (J) when given. No tangents. On an error at
    /// point i, the points before i are written and the error names i.
    fn step_block(
        &self,
        normal_force: &[f64],
        slip: &[f64],
        dt: f64,
        states: &mut [f64],
        tangential_force: &mut [f64],
        mut dissipation: Option<&mut [f64]>,
    ) -> core::result::Result<(), BatchError> {
        let n = normal_force.len();
        let m = self.state_len();
        let size = |name: &'static str, got: usize, want: usize| {
            check_len(name, got, want).map_err(|error| BatchError { index: 0, error })
        };
        size("slip.len()", slip.len(), 2 * n)?;
        size("tangential_force.len()", tangential_force.len(), 2 * n)?;
        size("states.len()", states.len(), n * m)?;
        if let Some(d) = dissipation.as_deref() {
            size("dissipation.len()", d.len(), n)?;
        }
        for i in 0..n {
            let inc = DynamicIncrement {
                normal_force: normal_force[i],
                slip: [slip[2 * i], slip[2 * i + 1]],
                dt,
                ..DynamicIncrement::default()
            };
            let r = self
                .step_in_place(&mut states[i * m..(i + 1) * m], &inc)
                .map_err(|error| BatchError { index: i, error })?;
            tangential_force[2 * i] = r.force[0];
            tangential_force[2 * i + 1] = r.force[1];
            if let Some(d) = dissipation.as_deref_mut() {
                d[i] = r.dissipated;
            }
        }
        Ok(())
    }
}

pub(crate) mod sealed {
    use super::{DynamicIncrement, DynamicResponse};
    use crate::error::Result;

    /// The body of a step, after every check (not callable from outside the
    /// crate: an unchecked state would give unchecked results).
    pub trait Advance {
        /// Whether a non-zero slip needs Δt > 0.
        fn rate_dependent(&self) -> bool;
        /// The model's own checks of an increment (before anything is
        /// written).
        fn check(&self, _increment: &DynamicIncrement) -> Result<()> {
            Ok(())
        }
        /// Steps the checked state `old` (`None`: `new` itself, in place)
        /// into `new`. On `Err`, `new` is untouched.
        fn advance(
            &self,
            old: Option<&[f64]>,
            new: &mut [f64],
            increment: &DynamicIncrement,
        ) -> Result<DynamicResponse>;
    }
}

/// A dynamic friction model chosen by configuration.
#[derive(Debug, Clone, PartialEq)]
pub enum DynamicModel {
    /// [`LuGre`].
    LuGre(LuGre),
    /// [`MaxwellSlip`].
    MaxwellSlip(MaxwellSlip),
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
            DynamicModel::PrandtlTomlinson($m) => $e,
            DynamicModel::BurridgeKnopoff($m) => $e,
            DynamicModel::Bristles($m) => $e,
        }
    };
}

impl sealed::Advance for DynamicModel {
    fn rate_dependent(&self) -> bool {
        each_model!(self, m => m.rate_dependent())
    }
    fn check(&self, increment: &DynamicIncrement) -> Result<()> {
        each_model!(self, m => m.check(increment))
    }
    fn advance(
        &self,
        old: Option<&[f64]>,
        new: &mut [f64],
        increment: &DynamicIncrement,
    ) -> Result<DynamicResponse> {
        each_model!(self, m => m.advance(old, new, increment))
    }
}

impl DynamicFriction for DynamicModel {
    fn state_len(&self) -> usize {
        each_model!(self, m => m.state_len())
    }
}

/// Checks an increment: N finite and ≥ 0, Δs finite, Δt finite and ≥ 0
/// (and > 0 with a non-zero slip when `rate_dependent`), tangent bits known.
/// One branch on the valid path; the error path names the argument.
#[inline]
fn check_increment(inc: &DynamicIncrement, rate_dependent: bool) -> Result<()> {
    let moving = inc.slip[0] != 0.0 || inc.slip[1] != 0.0;
    let valid = (0.0..=f64::MAX).contains(&inc.normal_force)
        && (0.0..=f64::MAX).contains(&inc.dt)
        && inc.slip[0].is_finite()
        && inc.slip[1].is_finite()
        && inc.tangents & !(TANGENT_NORMAL | TANGENT_SLIP) == 0
        && !(rate_dependent && inc.dt == 0.0 && moving);
    if valid {
        Ok(())
    } else {
        increment_error(inc, rate_dependent)
    }
}

/// The error of an increment [`check_increment`] refused.
#[cold]
#[inline(never)]
fn increment_error(inc: &DynamicIncrement, rate_dependent: bool) -> Result<()> {
    check::non_negative("normal_force", inc.normal_force)?;
    check::finite("slip", inc.slip[0])?;
    check::finite("slip", inc.slip[1])?;
    check::non_negative("dt", inc.dt)?;
    if rate_dependent && inc.dt == 0.0 && (inc.slip[0] != 0.0 || inc.slip[1] != 0.0) {
        return Err(Error::InvalidArgument {
            name: "dt",
            value: inc.dt,
            bound: "> 0 when the slip increment is not zero (the model is rate dependent)",
        });
    }
    Err(Error::UnknownSelector {
        name: "tangents",
        value: inc.tangents as i64,
    })
}

/// A length that must equal `want`.
#[inline]
fn check_len(name: &'static str, got: usize, want: usize) -> Result<()> {
    if got == want {
        Ok(())
    } else {
        Err(length_error(name, got))
    }
}

/// The error of a length [`check_len`] refused.
#[cold]
#[inline(never)]
fn length_error(name: &'static str, got: usize) -> Error {
    Error::InvalidArgument {
        name,
        value: got as f64,
        bound: "equal to the model's state_len() (points times it for a block; slips and forces twice the points)",
    }
}

/// Whether every value is finite, in one branch-free pass the compiler
/// vectorises: adding 2⁵² to the exponent bits carries into the sign bit
/// exactly when they are all ones (±∞, NaN).
#[inline]
fn all_finite(values: &[f64]) -> bool {
    const EXPONENT: u64 = 0x7ff0_0000_0000_0000;
    const ONE: u64 = 0x0010_0000_0000_0000;
    values
        .iter()
        .fold(0u64, |acc, v| acc | ((v.to_bits() & EXPONENT) + ONE))
        >> 63
        == 0
}

/// Checks a state's length and content: accumulators finite and ≥ 0,
/// every value finite. Errors name `{what}.len()`, `{what}.dissipation`,
/// `{what}.slip_path` or `{what}` (`what` is `old` or `state`).
#[inline]
fn check_state(state: &[f64], what: &'static str, len: usize) -> Result<()> {
    if state.len() == len
        && state[STATE_DISSIPATION] >= 0.0
        && state[STATE_SLIP_PATH] >= 0.0
        && all_finite(state)
    {
        Ok(())
    } else {
        state_error(state, what, len)
    }
}

/// The error of a state [`check_state`] refused.
#[cold]
#[inline(never)]
fn state_error(state: &[f64], what: &'static str, len: usize) -> Result<()> {
    let (n_len, n_d, n_p) = if what == "old" {
        ("old.len()", "old.dissipation", "old.slip_path")
    } else {
        ("state.len()", "state.dissipation", "state.slip_path")
    };
    check_len(n_len, state.len(), len)?;
    check::non_negative(n_d, state[STATE_DISSIPATION])?;
    check::non_negative(n_p, state[STATE_SLIP_PATH])?;
    for &v in &state[STATE_MODEL..] {
        check::finite(what, v)?;
    }
    Ok(())
}

/// The check of a one-dimensional model (Prandtl–Tomlinson,
/// Burridge–Knopoff, bristles): the increment's `slip[1]` must be 0.
pub(crate) fn track_only(increment: &DynamicIncrement) -> Result<()> {
    if increment.slip[1] != 0.0 {
        return Err(Error::InvalidArgument {
            name: "slip",
            value: increment.slip[1],
            bound: "slip[1] = 0 (the model is one-dimensional)",
        });
    }
    Ok(())
}

/// The shared checks of parallel elements (Maxwell-slip, bristles):
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

/// Value `i` of the old state: of `old`, or of `new` when stepping in place.
#[inline]
pub(crate) fn read(old: Option<&[f64]>, new: &[f64], i: usize) -> f64 {
    match old {
        Some(o) => o[i],
        None => new[i],
    }
}

/// Books an increment's dissipation and slip into the common part of `new`,
/// from the old state's accumulators.
#[inline]
pub(crate) fn book(old: Option<&[f64]>, new: &mut [f64], dissipated: f64, slip: [f64; 2]) {
    book_path(old, new, dissipated, norm(slip[0], slip[1]));
}

/// [`book`] with the slip's length `path` = |Δs| (m) already known.
#[inline(always)]
pub(crate) fn book_path(old: Option<&[f64]>, new: &mut [f64], dissipated: f64, path: f64) {
    new[STATE_DISSIPATION] = read(old, new, STATE_DISSIPATION) + dissipated;
    new[STATE_SLIP_PATH] = read(old, new, STATE_SLIP_PATH) + path;
}

/// Fills the force, its magnitude, N and μ of a response from the friction
/// force `f` (N, along the motion, resisting it).
pub(crate) fn respond(f: [f64; 2], normal_force: f64) -> DynamicResponse {
    let force = [-f[0], -f[1]];
    let magnitude = norm(force[0], force[1]);
    DynamicResponse {
        force,
        force_magnitude: magnitude,
        normal_force,
        cof: if normal_force > 0.0 {
            magnitude / normal_force
        } else {
            0.0
        },
        ..DynamicResponse::default()
    }
}

#[cfg(test)]
mod tests {
    use super::{all_finite, norm};

    /// The branch-free finiteness test agrees with `is_finite` for every
    /// special value at every position, and `norm` with `hypot` (exactly
    /// on a track, y = 0).
    #[test]
    fn all_finite_and_norm_agree_with_std() {
        let specials = [
            0.0,
            -0.0,
            f64::MIN_POSITIVE,
            5e-324,
            -5e-324,
            1.0,
            -1.0,
            f64::MAX,
            f64::MIN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            -f64::NAN,
        ];
        for len in 0..6 {
            for pos in 0..len {
                for &v in &specials {
                    let mut xs = vec![1.5; len];
                    xs[pos] = v;
                    assert_eq!(all_finite(&xs), v.is_finite(), "{v} at {pos} of {len}");
                }
            }
        }
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
