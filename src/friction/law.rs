//! The friction step: one contract for every friction law stepped once per
//! time increment of a host code (an FE integration point or contact node,
//! a DEM or MD contact).
//!
//! A law is a pure function of its parameters, a caller-owned **old state**
//! and one **increment**, giving the **new state** and the **response**.
//! Nothing is allocated once a [`FrictionWork`] exists, old and new states
//! are separate (a host can re-evaluate or cut back an increment: the same
//! old state and increment give bit-identical results), and an all-zero
//! state is a fresh one. [`FrictionLaw`] is implemented by the homogenised
//! law ([`super::HomogenisedFriction`]), the hierarchical slider as a patch
//! law ([`super::Slider`]) and the chapter-5 dynamic models
//! ([`super::dynamic`]); the C ABI's `AsperityFriction` handle is one
//! `Box<dyn FrictionLaw>`, so adding a law means implementing this trait.
//!
//! # Formulas
//!
//! Per increment at constant normal force N and velocity v = Δs/Δt:
//!
//! $$
//! (\mathbf F,\ \Delta D,\ \sigma_{\mathrm{new}}) = \mathrm{law}(\sigma_{\mathrm{old}};\ N, A_n, \Delta\mathbf s, \Delta t),
//! \qquad \Delta D \ge 0,
//! \qquad W_F = \Delta D + \Delta E_{\mathrm{stored}},
//! $$
//!
//! with **F** the tangential force on the point from the counter-surface,
//! opposing slip (the convention of Abaqus VFRIC), ΔD the energy dissipated
//! in the increment, E_stored the elastic energy the law stores and W_F the
//! work of the friction force along the increment. Tangents, when asked for:
//! ∂**F**/∂N and ∂F_i/∂Δs_j at fixed old state — the consistent
//! linearisation an implicit host needs.
//!
//! # State layout
//!
//! `state_len()` doubles: `[D, S, law…]`, the accumulated dissipation
//! D = ΣΔD (J, [`STATE_DISSIPATION`]) and slip path S = Σ|Δs| (m,
//! [`STATE_SLIP_PATH`]) first for every law, then the law's own variables
//! from [`STATE_MODEL`] (each law documents them). The accumulators saturate
//! at `f64::MAX` rather than overflow.
//!
//! # References
//!
//! * Abaqus/Explicit user subroutine VFRIC: the block shape (n points, one
//!   Δt, slips and forces interleaved, states stepped).
//! * J. C. Simo, T. J. R. Hughes (1998), *Computational Inelasticity*,
//!   Springer, ch. 1–3: return mapping and consistent tangents.

use core::any::Any;

use super::ledger::Dissipation;
use crate::contact::BatchError;
use crate::error::{check, Error, Result};

/// Index of the accumulated dissipation ΣΔD (J) in a state.
pub const STATE_DISSIPATION: usize = 0;
/// Index of the accumulated slip path Σ|Δs| (m) in a state.
pub const STATE_SLIP_PATH: usize = 1;
/// Index of the law's first own variable in a state.
pub const STATE_MODEL: usize = 2;

/// [`FrictionIncrement::tangents`] bit: compute ∂F/∂N.
pub const TANGENT_NORMAL: i32 = 1;
/// [`FrictionIncrement::tangents`] bit: compute ∂F/∂Δs.
pub const TANGENT_SLIP: i32 = 2;

/// One increment of a contact point (the C ABI's
/// `AsperityFrictionIncrement`). SI units.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct FrictionIncrement {
    /// Normal force N on the point (N), finite and ≥ 0 (compressive),
    /// constant over the increment.
    pub normal_force: f64,
    /// Nominal area A_n the point represents (m²), finite and ≥ 0; > 0 for
    /// laws that depend on the nominal pressure N/A_n (the homogenised law)
    /// unless N = 0 too: A_n = 0 with N = 0 is an open gap, no contact
    /// (the homogenised law then releases its stick force). Unused by the
    /// other laws, for which N = 0 is no contact.
    pub area: f64,
    /// Slip increment Δs of the point relative to the counter-surface (m),
    /// two finite components in the caller's tangent basis; a track uses
    /// `slip[1] = 0`.
    pub slip: [f64; 2],
    /// Time increment Δt (s), finite and ≥ 0; > 0 when the slip is not zero
    /// and the law is rate dependent.
    pub dt: f64,
    /// Tangents wanted: 0, or [`TANGENT_NORMAL`] | [`TANGENT_SLIP`].
    pub tangents: i32,
    /// Reserved, 0.
    pub reserved: i32,
}

/// What an increment did at a point (the `regime` field of
/// [`FrictionResponse`]).
#[repr(i32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FrictionRegime {
    /// No slip of the law's slip variable (inside the slip cone, a zero
    /// slip increment, or every element stuck).
    Stick = 0,
    /// Partial slip: pre-sliding, some elements or bristles slipping.
    PartialSlip = 1,
    /// Gross sliding: the force is on the slip limit.
    Slip = 2,
    /// No normal force and no adhesion: no friction.
    NoContact = 3,
}

/// The response of one increment (the C ABI's `AsperityFrictionResponse`).
/// SI units.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct FrictionResponse {
    /// Tangential force F on the point from the counter-surface at the end
    /// of the increment (N), in the basis of the slip; opposes slip.
    pub force: [f64; 2],
    /// |F| (N).
    pub force_magnitude: f64,
    /// Normal force N (N): as given, or what the law carries.
    pub normal_force: f64,
    /// Coefficient of friction of the increment in the law's form; 0 when
    /// undefined (no contact).
    pub cof: f64,
    /// Adhesive holding force A (N) of laws that model adhesion, else 0.
    pub adhesion: f64,
    /// True contact area (m²) of laws that model it, else 0.
    pub true_contact_area: f64,
    /// Energy dissipated in the increment ΔD (J), ≥ 0.
    pub dissipated: f64,
    /// ΔD by mechanism (J) for laws built on the mechanisms of thesis
    /// chapter 4 (homogenised, slider); all 0 for the others.
    pub dissipation: Dissipation,
    /// Elastic energy stored in the law at the end of the increment (J).
    pub stored_energy: f64,
    /// ∂F/∂N (dimensionless) at fixed slip increment and old state, when
    /// asked for.
    pub dforce_dnormal: [f64; 2],
    /// ∂F_i/∂Δs_j (N/m), `dforce_dslip[i][j]`, at fixed N, Δt and old
    /// state, when asked for.
    pub dforce_dslip: [[f64; 2]; 2],
    /// [`FrictionRegime`] as an integer.
    pub regime: i32,
    /// The tangents computed, as [`TANGENT_NORMAL`] | [`TANGENT_SLIP`] bits
    /// (a law may compute more than was asked for).
    pub tangents: i32,
}

impl FrictionResponse {
    /// The regime of the increment.
    pub fn regime(&self) -> FrictionRegime {
        match self.regime {
            0 => FrictionRegime::Stick,
            1 => FrictionRegime::PartialSlip,
            2 => FrictionRegime::Slip,
            _ => FrictionRegime::NoContact,
        }
    }
}

/// Scratch memory of a law's step, built by [`FrictionLaw::work`] and
/// reused from increment to increment (one per thread). Laws without
/// scratch use an empty one, which costs nothing; a work made for another
/// law (or none) is rebuilt on first use, so a step never fails for it.
#[derive(Default)]
pub struct FrictionWork(Option<Box<dyn Any + Send>>);

impl core::fmt::Debug for FrictionWork {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(if self.0.is_some() {
            "FrictionWork(..)"
        } else {
            "FrictionWork(empty)"
        })
    }
}

impl FrictionWork {
    /// Work holding `value`.
    pub fn new<T: Any + Send>(value: T) -> Self {
        Self(Some(Box::new(value)))
    }

    /// The work's content as `T`, if it is one.
    pub fn get<T: Any + Send>(&self) -> Option<&T> {
        self.0.as_ref()?.downcast_ref()
    }

    /// The work's content as `T`, replaced by `make()` when it is not a `T`
    /// or `fits` refuses it (built for a law of another size).
    pub fn get_or_make<T: Any + Send>(
        &mut self,
        fits: impl FnOnce(&T) -> bool,
        make: impl FnOnce() -> T,
    ) -> &mut T {
        let keep = matches!(self.get::<T>(), Some(t) if fits(t));
        if !keep {
            self.0 = Some(Box::new(make()));
        }
        self.0
            .as_mut()
            .and_then(|b| b.downcast_mut())
            .expect("the work was just made as a T")
    }
}

/// The states of a block: n states of [`FrictionLaw::state_len`] doubles
/// each, back to back.
#[derive(Debug)]
pub enum BlockStates<'a> {
    /// Old states read, new states written.
    Separate {
        /// States before the increment.
        old: &'a [f64],
        /// States after the increment.
        new: &'a mut [f64],
    },
    /// States stepped in place.
    InPlace(&'a mut [f64]),
}

/// n points stepped at once, in the shape of Abaqus/Explicit VFRIC (SI).
/// Point i is stepped as [`FrictionLaw::step`] would step the increment
/// `normal_force[i]`, `area[i]`, `slip[2i..2i+2]`, `dt`, `tangents`.
#[derive(Debug)]
pub struct FrictionBlock<'a> {
    /// Normal forces N_i (N); n is its length.
    pub normal_force: &'a [f64],
    /// Nominal areas A_n,i (m², n values), or `None`: 0 for every point.
    pub area: Option<&'a [f64]>,
    /// Slip increments, `slip[2i]`, `slip[2i+1]` (m, 2n values).
    pub slip: &'a [f64],
    /// One time increment Δt (s) for all points.
    pub dt: f64,
    /// Tangents wanted at every point, as [`FrictionIncrement::tangents`]:
    /// 0, or [`TANGENT_NORMAL`] | [`TANGENT_SLIP`]; they arrive in
    /// `responses`.
    pub tangents: i32,
    /// The states.
    pub states: BlockStates<'a>,
    /// Tangential forces out, `tangential_force[2i]`, `[2i+1]` (N, 2n),
    /// when wanted (`responses` carry them too).
    pub tangential_force: Option<&'a mut [f64]>,
    /// Energy dissipated in the increment per point (J, n values), when
    /// wanted.
    pub dissipation: Option<&'a mut [f64]>,
    /// Each point's full response (n values: force, energies, regime,
    /// the tangents asked), when wanted.
    pub responses: Option<&'a mut [FrictionResponse]>,
}

/// A friction law stepped once per increment; see the module
/// documentation. An implementation gives [`Self::state_len`] and
/// [`Self::advance`] (and the optional hooks); the checks, the in-place
/// form and the block come with the trait.
pub trait FrictionLaw: Send + Sync {
    /// Doubles of one point's state (≥ 2: the dissipation and slip path).
    fn state_len(&self) -> usize;

    /// Whether a non-zero slip needs Δt > 0.
    fn rate_dependent(&self) -> bool {
        false
    }

    /// Scratch for [`Self::step`] (empty unless the law needs some; one per
    /// thread).
    fn work(&self) -> FrictionWork {
        FrictionWork::default()
    }

    /// The law's own checks of an increment, after the common ones (N, Δs,
    /// Δt, area finite and in range, known tangent bits) and before
    /// anything is written.
    fn check(&self, _increment: &FrictionIncrement) -> Result<()> {
        Ok(())
    }

    /// The law's own checks of a state, after its length and accumulators
    /// (finite, ≥ 0) were checked; `what` is `old` or `state`, for the
    /// error's name. The default: every value finite.
    fn check_state(&self, state: &[f64], what: &'static str) -> Result<()> {
        if all_finite(&state[STATE_MODEL..]) {
            Ok(())
        } else {
            for &v in &state[STATE_MODEL..] {
                check::finite(what, v)?;
            }
            Ok(())
        }
    }

    /// The body of a step, after every check: the checked state `old`
    /// (`None`: `new` itself, stepped in place) into `new`, booking the
    /// increment's dissipation and slip path into `new`'s accumulators. On
    /// `Err`, `new` is untouched.
    fn advance(
        &self,
        old: Option<&[f64]>,
        new: &mut [f64],
        increment: &FrictionIncrement,
        work: &mut FrictionWork,
    ) -> Result<FrictionResponse>;

    /// One increment from `old` into `new` (each [`Self::state_len`]
    /// doubles; all-zero `old` = fresh). Errors name the argument: the
    /// increment's `normal_force`, `area`, `slip`, `dt`, `tangents`;
    /// `old.len()`, `new.len()`; `old.dissipation`, `old.slip_path` (finite,
    /// ≥ 0); the law's own names. On error `new` is untouched.
    fn step(
        &self,
        old: &[f64],
        new: &mut [f64],
        increment: &FrictionIncrement,
        work: &mut FrictionWork,
    ) -> Result<FrictionResponse> {
        check_increment(increment, self.rate_dependent())?;
        self.check(increment)?;
        check_len("new.len()", new.len(), self.state_len())?;
        check_state(self, old, "old")?;
        self.advance(Some(old), new, increment, work)
    }

    /// [`Self::step`] with the state updated in place (errors name
    /// `state…`); on error `state` is untouched.
    fn step_in_place(
        &self,
        state: &mut [f64],
        increment: &FrictionIncrement,
        work: &mut FrictionWork,
    ) -> Result<FrictionResponse> {
        check_increment(increment, self.rate_dependent())?;
        self.check(increment)?;
        check_state(self, state, "state")?;
        self.advance(None, state, increment, work)
    }

    /// n points at once ([`FrictionBlock`], the shape of Abaqus/Explicit
    /// VFRIC): the tangential forces and dissipations, and when
    /// `responses` is given each point's full [`FrictionResponse`] (with
    /// the tangents `block.tangents` asks), bit-identical to n calls of
    /// [`Self::step`] (or [`Self::step_in_place`]). The tangent bits and
    /// the lengths are checked first (an error naming `tangents` or the
    /// slice, at index 0, nothing written); on an error at point i, the
    /// points before i are written and the error names i. No allocation
    /// once `work` exists.
    fn step_block(
        &self,
        block: FrictionBlock<'_>,
        work: &mut FrictionWork,
    ) -> core::result::Result<(), BatchError> {
        let FrictionBlock {
            normal_force,
            area,
            slip,
            dt,
            tangents,
            mut states,
            mut tangential_force,
            mut dissipation,
            mut responses,
        } = block;
        let n = normal_force.len();
        let m = self.state_len();
        let at0 = |error| BatchError { index: 0, error };
        check_tangents(tangents).map_err(at0)?;
        let twice = n.checked_mul(2);
        let all = n.checked_mul(m);
        block_len("slip.len()", slip.len(), twice).map_err(at0)?;
        if let Some(f) = tangential_force.as_deref() {
            block_len("tangential_force.len()", f.len(), twice).map_err(at0)?;
        }
        if let Some(a) = area {
            block_len("area.len()", a.len(), Some(n)).map_err(at0)?;
        }
        if let Some(d) = dissipation.as_deref() {
            block_len("dissipation.len()", d.len(), Some(n)).map_err(at0)?;
        }
        if let Some(r) = responses.as_deref() {
            block_len("responses.len()", r.len(), Some(n)).map_err(at0)?;
        }
        match &states {
            BlockStates::Separate { old, new } => {
                block_len("old.len()", old.len(), all).map_err(at0)?;
                block_len("new.len()", new.len(), all).map_err(at0)?;
            }
            BlockStates::InPlace(s) => block_len("states.len()", s.len(), all).map_err(at0)?,
        }
        for i in 0..n {
            let inc = FrictionIncrement {
                normal_force: normal_force[i],
                area: area.map_or(0.0, |a| a[i]),
                slip: [slip[2 * i], slip[2 * i + 1]],
                dt,
                tangents,
                reserved: 0,
            };
            let range = i * m..(i + 1) * m;
            let r = match &mut states {
                BlockStates::Separate { old, new } => {
                    self.step(&old[range.clone()], &mut new[range], &inc, work)
                }
                BlockStates::InPlace(s) => self.step_in_place(&mut s[range], &inc, work),
            }
            .map_err(|error| BatchError { index: i, error })?;
            if let Some(f) = tangential_force.as_deref_mut() {
                f[2 * i] = r.force[0];
                f[2 * i + 1] = r.force[1];
            }
            if let Some(d) = dissipation.as_deref_mut() {
                d[i] = r.dissipated;
            }
            if let Some(out) = responses.as_deref_mut() {
                out[i] = r;
            }
        }
        Ok(())
    }
}

impl<L: FrictionLaw + ?Sized> FrictionLaw for Box<L> {
    fn state_len(&self) -> usize {
        (**self).state_len()
    }
    fn rate_dependent(&self) -> bool {
        (**self).rate_dependent()
    }
    fn work(&self) -> FrictionWork {
        (**self).work()
    }
    fn check(&self, increment: &FrictionIncrement) -> Result<()> {
        (**self).check(increment)
    }
    fn check_state(&self, state: &[f64], what: &'static str) -> Result<()> {
        (**self).check_state(state, what)
    }
    fn advance(
        &self,
        old: Option<&[f64]>,
        new: &mut [f64],
        increment: &FrictionIncrement,
        work: &mut FrictionWork,
    ) -> Result<FrictionResponse> {
        (**self).advance(old, new, increment, work)
    }
    fn step_block(
        &self,
        block: FrictionBlock<'_>,
        work: &mut FrictionWork,
    ) -> core::result::Result<(), BatchError> {
        (**self).step_block(block, work)
    }
}

/// Checks an increment: N finite and ≥ 0, A_n finite and ≥ 0, Δs finite,
/// Δt finite and ≥ 0 (and > 0 with a non-zero slip when `rate_dependent`),
/// tangent bits known. One branch on the valid path; the error path names
/// the argument.
#[inline]
fn check_increment(inc: &FrictionIncrement, rate_dependent: bool) -> Result<()> {
    let moving = inc.slip[0] != 0.0 || inc.slip[1] != 0.0;
    let valid = (0.0..=f64::MAX).contains(&inc.normal_force)
        && (0.0..=f64::MAX).contains(&inc.area)
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

/// Checks tangent bits: 0, or [`TANGENT_NORMAL`] | [`TANGENT_SLIP`]; the
/// error names `tangents`.
#[inline]
pub(crate) fn check_tangents(tangents: i32) -> Result<()> {
    if tangents & !(TANGENT_NORMAL | TANGENT_SLIP) == 0 {
        Ok(())
    } else {
        Err(Error::UnknownSelector {
            name: "tangents",
            value: tangents as i64,
        })
    }
}

/// The error of an increment [`check_increment`] refused.
#[cold]
#[inline(never)]
fn increment_error(inc: &FrictionIncrement, rate_dependent: bool) -> Result<()> {
    check::non_negative("normal_force", inc.normal_force)?;
    check::non_negative("area", inc.area)?;
    check::finite("slip", inc.slip[0])?;
    check::finite("slip", inc.slip[1])?;
    check::non_negative("dt", inc.dt)?;
    if rate_dependent && inc.dt == 0.0 && (inc.slip[0] != 0.0 || inc.slip[1] != 0.0) {
        return Err(Error::InvalidArgument {
            name: "dt",
            value: inc.dt,
            bound: "> 0 when the slip increment is not zero (the law is rate dependent)",
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

/// A block slice's length that must equal `want` (`None`: the product
/// overflows `usize`, so no slice can have it).
fn block_len(name: &'static str, got: usize, want: Option<usize>) -> Result<()> {
    if want == Some(got) {
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
        bound: "equal to the law's state_len() (points times it for a block; areas, dissipations and responses the points, slips and forces twice the points)",
    }
}

/// Whether every value is finite, in one branch-free pass the compiler
/// vectorises: adding 2⁵² to the exponent bits carries into the sign bit
/// exactly when they are all ones (±∞, NaN).
#[inline]
pub(crate) fn all_finite(values: &[f64]) -> bool {
    const EXPONENT: u64 = 0x7ff0_0000_0000_0000;
    const ONE: u64 = 0x0010_0000_0000_0000;
    values
        .iter()
        .fold(0u64, |acc, v| acc | ((v.to_bits() & EXPONENT) + ONE))
        >> 63
        == 0
}

/// Checks a state's length and accumulators (finite, ≥ 0), then the law's
/// own part. Errors name `{what}.len()`, `{what}.dissipation`,
/// `{what}.slip_path` or the law's names.
#[inline]
fn check_state<L: FrictionLaw + ?Sized>(law: &L, state: &[f64], what: &'static str) -> Result<()> {
    let len = law.state_len();
    let valid = state.len() == len
        && (0.0..=f64::MAX).contains(&state[STATE_DISSIPATION])
        && (0.0..=f64::MAX).contains(&state[STATE_SLIP_PATH]);
    if !valid {
        let (n_len, n_d, n_p) = if what == "old" {
            ("old.len()", "old.dissipation", "old.slip_path")
        } else {
            ("state.len()", "state.dissipation", "state.slip_path")
        };
        check_len(n_len, state.len(), len)?;
        check::non_negative(n_d, state[STATE_DISSIPATION])?;
        check::non_negative(n_p, state[STATE_SLIP_PATH])?;
    }
    law.check_state(state, what)
}

/// Value `i` of the old state: of `old`, or of `new` when stepping in place.
#[inline]
pub(crate) fn read(old: Option<&[f64]>, new: &[f64], i: usize) -> f64 {
    match old {
        Some(o) => o[i],
        None => new[i],
    }
}

/// Books an increment's dissipation ΔD (J) and slip path |Δs| (m) into the
/// accumulators of `new`, from the old state's. The sums saturate at
/// `f64::MAX` (≈ 1.8e308 J or m) instead of overflowing to ∞, so a state
/// stays a valid old state for the next increment.
#[inline(always)]
pub(crate) fn book_path(old: Option<&[f64]>, new: &mut [f64], dissipated: f64, path: f64) {
    new[STATE_DISSIPATION] = (read(old, new, STATE_DISSIPATION) + dissipated).min(f64::MAX);
    new[STATE_SLIP_PATH] = (read(old, new, STATE_SLIP_PATH) + path).min(f64::MAX);
}

#[cfg(test)]
pub(crate) mod tests {
    use super::all_finite;

    /// Special values for the finiteness and norm tests.
    pub(crate) const SPECIALS: [f64; 13] = [
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

    /// The branch-free finiteness test agrees with `is_finite` for every
    /// special value at every position.
    #[test]
    fn all_finite_agrees_with_std() {
        for len in 0..6 {
            for pos in 0..len {
                for &v in &SPECIALS {
                    let mut xs = vec![1.5; len];
                    xs[pos] = v;
                    assert_eq!(all_finite(&xs), v.is_finite(), "{v} at {pos} of {len}");
                }
            }
        }
    }
}
