//! Single-asperity normal contact laws.
//!
//! One file per law; every law implements [`NormalContact`]. Conventions, the
//! same everywhere in the library:
//!
//! * `delta` δ (m) is the **overlap**: δ > 0 is penetration, δ < 0 separation.
//!   For a rigid sphere under a surface-force law ([`derjaguin`]) δ = z₀ − D
//!   for Lennard-Jones (0 at the gap z₀) and δ = −D (0 at touching) for the
//!   Dugdale and exponential laws, D the gap.
//! * `force` P (N) is **positive when repulsive** (compressive).
//! * `work_of_adhesion` w (J/m²) is Dupré's, `w = 2γ` for identical surfaces.
//! * `e_star` E* (Pa) is the contact modulus of
//!   [`crate::material::effective_modulus`].
//!
//! Hysteretic laws (JKR, Maugis–Dugdale with jump-in/jump-out, Kendall) read
//! their history from a caller-owned [`ContactState`] and return the new one
//! separately, so a host code can re-evaluate an increment or cut it back. An
//! all-zero state means "never touched" (the surfaces approach from afar).
//!
//! Evaluations never allocate.
//!
//! # Formulas
//!
//! The laws, each detailed (with its sources) in its module:
//!
//! | law | force at overlap δ | pull-off |
//! |---|---|---|
//! | [`hertz`] | $P = \tfrac43 E^\ast R^{1/2}\delta^{3/2}$ | 0 |
//! | [`power_punch`] | $P = C(d)BE^\ast a^{d+1}$, $\delta = D(d)Ba^d$ | 0 |
//! | [`flat_punch`] | $P = 2E^\ast a\delta$ | 0 |
//! | [`dmt`] | $P = \tfrac43 E^\ast R^{1/2}\delta^{3/2} - 2\pi wR$ | $-2\pi wR$ |
//! | [`jkr`] | $P = \frac{4E^\ast a^3}{3R} - \sqrt{8\pi wE^\ast a^3}$, $\delta = \frac{a^2}{R} - \sqrt{\frac{2\pi wa}{E^\ast}}$ | $-\tfrac32\pi wR$ |
//! | [`jkr_power_punch`] | $P = C(d)BE^\ast a^{d+1} - \sqrt{8\pi wE^\ast a^3}$ | see module |
//! | [`kendall`] | $P = 2E^\ast C_\mathrm{NS} a\delta$ | $-\sqrt{8\pi wE^\ast C_\mathrm{NS}a^3}$ |
//! | [`maugis_dugdale`] | Maugis (1992), parameter $\lambda$ | $-2\pi wR \ldots -\tfrac32\pi wR$ |
//! | [`derjaguin`] | $P = -2\pi R\int_D^\infty p(z)\\,dz$ | $-2\pi wR$ |
//! | [`lj_sphere`] | Lennard-Jones 3-9 law, elastic sphere | $-2\pi wR \ldots -\tfrac32\pi wR$ |
//!
//! The contact modulus is $1/E^\ast = (1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2$.
//!
//! # References
//!
//! * Thesis chapter 1 (1-15)–(1-44) and §4.4; REFERENCE.md §1, §6, §7.
//! * K. L. Johnson (1985), *Contact Mechanics*, Cambridge University Press,
//!   [doi:10.1017/CBO9781139171731](https://doi.org/10.1017/CBO9781139171731).
//! * The original papers are cited in each law's module.

use crate::error::{check, Error, Result};

/// The inputs of a law. `$params` is the plain `repr(C)` struct of what a
/// caller gives (SI units; in the C header `Asperity<Law>Params`), and the
/// `repr(C)` law `$law` starts with the same fields in the same order,
/// followed by the values it derives from them (private, so caching can
/// change without touching the API or the C ABI). Generates `$law::params`
/// and checks at compile time that the fields sit at the same offsets, which
/// lets the C ABI hand out a law's storage whose leading bytes read as its
/// inputs.
macro_rules! law_inputs {
    ($law:ident, $params:ident { $($field:ident),+ $(,)? }) => {
        impl $law {
            /// The inputs the law was built from, as given (see
            #[doc = concat!("[`", stringify!($params), "`]).")]
            #[inline]
            pub fn params(&self) -> $params {
                $params { $($field: self.$field),+ }
            }
        }
        const _: () = {
            $(assert!(
                core::mem::offset_of!($law, $field) == core::mem::offset_of!($params, $field)
            );)+
        };
    };
}

pub mod batch;
pub mod curve;
pub mod derjaguin;
pub mod dmt;
pub mod flat_punch;
pub mod hertz;
pub mod jkr;
pub mod jkr_power_punch;
mod jkr_simd;
pub mod kendall;
pub mod lj_sphere;
pub mod maugis_dugdale;
pub mod power_punch;
pub mod tabulated;

pub(crate) use batch::RawBatch;
pub use batch::{eval_batch, BatchError};
pub use derjaguin::{Derjaguin, DerjaguinParams, SurfaceLaw};
pub use dmt::{Dmt, DmtParams};
pub use flat_punch::{FlatPunch, FlatPunchParams};
pub use hertz::{Hertz, HertzParams};
pub use jkr::{Jkr, JkrParams};
pub use jkr_power_punch::{JkrPowerPunch, JkrPowerPunchParams};
pub use kendall::{Kendall, KendallParams};
pub use lj_sphere::{LjCurve, LjOptions, LjPoint, LjPullOff, LjSolution, LjSolver, LjSphere};
pub use maugis_dugdale::{MaugisDugdale, MaugisDugdaleParams};
pub use power_punch::{PowerPunch, PowerPunchParams};
pub use tabulated::TabulatedLaw;

/// How the contact is driven, which decides where an adhesive contact
/// separates.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Control {
    /// The force is prescribed ("load control", soft machine): the contact
    /// separates at the minimum of P on the equilibrium curve.
    Load,
    /// The approach δ is prescribed ("displacement control", rigid machine,
    /// fixed grips): the contact separates where dδ/da = 0 on retraction.
    Displacement,
}

/// Per-contact history, owned by the caller. All-zero means "never touched".
///
/// Laws without hysteresis ignore the old state and write the current one.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactState {
    /// Contact radius a at the end of the step (m).
    pub contact_radius: f64,
    /// Outer radius c of the cohesive (adhesive) zone at the end of the step (m);
    /// 0 when the law has none.
    pub cohesive_radius: f64,
    /// 1 when the surfaces are in contact (or, for laws with a cohesive zone,
    /// interacting) at the end of the step, 0 otherwise.
    pub in_contact: i32,
    /// Law-specific index of the equilibrium branch the contact is on; 0 for a
    /// fresh state.
    pub branch: i32,
}

/// Result of one evaluation.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct NormalResponse {
    /// Normal force P (N), positive when repulsive.
    pub force: f64,
    /// Overlap δ (m) of this equilibrium (the input under displacement control).
    pub delta: f64,
    /// Contact radius a (m); 0 out of contact.
    pub contact_radius: f64,
    /// Tangent stiffness dP/dδ (N/m) along the branch the contact is on.
    pub stiffness: f64,
    /// 1 in contact, 0 otherwise.
    pub in_contact: i32,
    /// Reserved, always 0.
    pub reserved: i32,
}

/// A single-asperity normal contact law.
pub trait NormalContact {
    /// Equilibrium at the prescribed overlap `delta` (m), starting from the
    /// history `old`. Returns the response and the new state; `old` is not
    /// modified, so the same step can be evaluated again.
    fn eval(&self, delta: f64, old: &ContactState) -> Result<(NormalResponse, ContactState)>;

    /// Equilibrium at the prescribed force `force` (N) on the stable branch
    /// (largest contact radius). Errors with [`Error::OutOfDomain`] below the
    /// load-controlled pull-off force.
    fn eval_at_load(&self, force: f64) -> Result<NormalResponse>;

    /// The force at which the contact separates (N, ≤ 0 for adhesive laws, 0
    /// without adhesion) under the given control.
    fn pull_off_force(&self, control: Control) -> Result<f64>;

    /// The crate's batch-kernel hook behind [`eval_batch`] and the C ABI's
    /// batch calls (see [`batch`]); not an API. Its argument type cannot be
    /// named outside the crate, so the hook can be neither called nor
    /// overridden there: a law of another crate gets the default, which runs
    /// [`NormalContact::eval`] element by element. Laws of the crate with a
    /// vectorised kernel override it; results agree with `eval` to rounding.
    ///
    /// # Safety
    /// The pointers of `b` must satisfy the contract of `RawBatch`: `delta`
    /// and `force` valid for `n` elements, the other arrays NULL or valid for
    /// `n` elements, aliasing allowed element by element.
    #[doc(hidden)]
    #[inline]
    unsafe fn eval_batch_raw(&self, b: &RawBatch) -> core::result::Result<(), BatchError> {
        batch::eval_elementwise(self, b)
    }

    /// A characteristic overlap of the law (m), used to non-dimensionalise
    /// (for example the JKR critical approach for adhesive spheres, the
    /// radius for Hertz).
    fn length_scale(&self) -> f64;

    /// The **reach** δ_r (m, ≤ 0 for every law of the library): the overlap
    /// below which the law's force is exactly zero from any history state,
    /// on approach or retraction, when the contact separates under
    /// `control`:
    ///
    /// * [`Control::Displacement`]: the law's own jump-out rule, i.e. what
    ///   [`NormalContact::eval`] does: for every δ < δ_r `eval(δ, old)`
    ///   returns force 0 whatever `old` is, and δ_r is the smallest such
    ///   bound (a contact that has not yet jumped out still has a force at
    ///   δ_r for the hysteretic laws);
    /// * [`Control::Load`]: the contact is taken to separate at the
    ///   load-controlled pull-off point (the minimum of the force), so δ_r is
    ///   the overlap there, or lower when a fresh contact already feels a
    ///   force further out on approach (the cohesive zone of Maugis–Dugdale).
    ///
    /// Laws whose force never becomes exactly zero (a Lennard-Jones tail, an
    /// exponential surface law) return the overlap below which
    /// `|P| < rel_force · |P_c|`, `P_c` the load-controlled pull-off force;
    /// each law documents the tail formula it inverts. `rel_force` must be
    /// finite and in (0, 1) (checked for every law, so a caller's bad value
    /// never passes silently), and is otherwise ignored by laws with a finite
    /// reach.
    ///
    /// A host code (an MD pair style) uses δ_r to size its neighbour cutoff
    /// (gap `−δ_r` beyond touching) and to release a contact where the law
    /// lets go.
    fn reach(&self, control: Control, rel_force: f64) -> Result<f64>;

    /// The energy U (J) of the equilibrium at overlap `delta` (m) reached
    /// from the history `old` (the same branch choice as
    /// [`NormalContact::eval`]): the elastic energy stored in the solids
    /// minus the surface energy of the contact area, such that
    /// `dU/dδ = P` along the branch the step ends on; 0 for a separated
    /// contact. Laws without a closed form return [`Error::OutOfDomain`]
    /// naming `law` (the default).
    fn energy(&self, delta: f64, old: &ContactState) -> Result<f64> {
        let _ = (delta, old);
        Err(no_energy())
    }
}

/// The error of [`NormalContact::energy`] for a law without a closed-form
/// energy.
#[cold]
pub(crate) fn no_energy() -> Error {
    Error::OutOfDomain {
        name: "law",
        value: f64::NAN,
        reason: "no closed-form energy for this law",
    }
}

/// Check the `rel_force` argument of [`NormalContact::reach`]: finite and in
/// (0, 1).
#[inline]
pub(crate) fn check_rel_force(rel_force: f64) -> Result<f64> {
    if rel_force.is_finite() && rel_force > 0.0 && rel_force < 1.0 {
        Ok(rel_force)
    } else {
        Err(Error::InvalidArgument {
            name: "rel_force",
            value: rel_force,
            bound: "finite and in (0, 1)",
        })
    }
}

/// The smallest double δ near `guess` at which `stays(δ)` holds, for a
/// predicate that is false below some point and true above it (a jump-out
/// rule evaluated in rounded arithmetic): `guess` corrected by at most 64
/// ulps each way, so that every δ below the result fails `stays` and the
/// result itself passes.
pub(crate) fn first_staying(guess: f64, stays: impl Fn(f64) -> bool) -> f64 {
    let down = |v: f64| {
        if v == 0.0 {
            -f64::from_bits(1)
        } else if v > 0.0 {
            f64::from_bits(v.to_bits() - 1)
        } else {
            f64::from_bits(v.to_bits() + 1)
        }
    };
    let up = |v: f64| {
        if v == 0.0 {
            f64::from_bits(1)
        } else if v > 0.0 {
            f64::from_bits(v.to_bits() + 1)
        } else {
            f64::from_bits(v.to_bits() - 1)
        }
    };
    let mut d = guess;
    if !d.is_finite() {
        return d;
    }
    for _ in 0..64 {
        let lower = down(d);
        if stays(lower) {
            d = lower;
        } else {
            break;
        }
    }
    for _ in 0..64 {
        if stays(d) {
            break;
        }
        d = up(d);
    }
    d
}

/// Hertz's elastic energy `U = (8/15) E* √R δ^{5/2}` (J) at overlap δ ≥ 0
/// (∫P dδ of `P = (4/3)E*√R δ^{3/2}`), written `(2/5)Pδ` with `a = √(Rδ)`.
#[inline]
pub(crate) fn hertz_energy(radius: f64, e_star: f64, delta: f64) -> f64 {
    if delta > 0.0 {
        let a = (radius * delta).sqrt();
        8.0 / 15.0 * e_star * a * delta * delta
    } else {
        0.0
    }
}

/// The library's normal laws, one entry each, in the order of their C kind
/// values: the one list that [`NormalLaw`] (variants, `From`, names,
/// dispatch), the C ABI's kind mapping, storage and construction from inputs
/// (`src/ffi/contact.rs`) and the ABI's list of types (`src/ffi/abi.rs`) are
/// generated from. `normal_laws!(callback!(args))` expands to
/// `callback! { (args) entries }`, each entry being
///
/// ```text
/// /// the doc line of the `NormalLaw` variant
/// Law(LawParams) name = ASPERITY_LAW_NAME,
/// ```
///
/// with `Law` the law type, `LawParams` its input struct, `name` its name
/// (the member of the C union `AsperityLawParams`, the suffix of the C
/// constructor `asperity_law_<name>`, [`NormalLaw::name`]) and
/// `ASPERITY_LAW_NAME` its C kind constant, a bare name resolved where a
/// callback in `src/ffi/` expands (the contact laws themselves know nothing
/// of the C ABI).
macro_rules! normal_laws {
    ($callback:ident!($($args:tt)*)) => {
        $callback! {
            ($($args)*)
            /// [`Hertz`] sphere.
            Hertz(HertzParams) hertz = ASPERITY_LAW_HERTZ,
            /// [`PowerPunch`] (Galin), including cones.
            PowerPunch(PowerPunchParams) power_punch = ASPERITY_LAW_POWER_PUNCH,
            /// [`FlatPunch`] (Boussinesq).
            FlatPunch(FlatPunchParams) flat_punch = ASPERITY_LAW_FLAT_PUNCH,
            /// [`Dmt`] sphere.
            Dmt(DmtParams) dmt = ASPERITY_LAW_DMT,
            /// [`Jkr`] sphere.
            Jkr(JkrParams) jkr = ASPERITY_LAW_JKR,
            /// [`JkrPowerPunch`], frictionless or no-slip.
            JkrPowerPunch(JkrPowerPunchParams) jkr_power_punch = ASPERITY_LAW_JKR_POWER_PUNCH,
            /// [`Kendall`] adhesive flat punch.
            Kendall(KendallParams) kendall = ASPERITY_LAW_KENDALL,
            /// [`MaugisDugdale`] sphere.
            MaugisDugdale(MaugisDugdaleParams) maugis_dugdale = ASPERITY_LAW_MAUGIS_DUGDALE,
            /// [`Derjaguin`] rigid sphere with a surface-force law.
            Derjaguin(DerjaguinParams) derjaguin = ASPERITY_LAW_DERJAGUIN,
        }
    };
}
pub(crate) use normal_laws;

/// [`NormalLaw`] and what goes with it, from the list of [`normal_laws!`].
macro_rules! define_normal_law {
    (() $($(#[$doc:meta])* $law:ident($params:ident) $name:ident = $kind:ident,)*) => {
        /// Any of the library's normal laws, by value: what the C ABI's
        /// `AsperityNormalLaw` converts to. It dispatches to the law's own
        /// implementation.
        #[derive(Debug, Clone, Copy, PartialEq)]
        pub enum NormalLaw {
            $($(#[$doc])* $law($law),)*
        }

        $(impl From<$law> for NormalLaw {
            #[inline]
            fn from(l: $law) -> Self {
                NormalLaw::$law(l)
            }
        })*

        impl NormalLaw {
            /// The laws' names in the order of their C kinds
            /// (`ASPERITY_LAW_<NAME>` is the index plus one): the C
            /// constructor of a law is `asperity_law_<name>`.
            pub const NAMES: &'static [&'static str] = &[$(stringify!($name)),*];

            /// The name of this law (one of [`NormalLaw::NAMES`]).
            pub fn name(&self) -> &'static str {
                match self {
                    $(NormalLaw::$law(_) => stringify!($name),)*
                }
            }
        }
    };
}
normal_laws!(define_normal_law!());

/// `match` on a [`NormalLaw`] with one arm per law, each binding the law to
/// `$law` and evaluating `$e`.
macro_rules! dispatch {
    ($self:ident, $law:ident => $e:expr) => {
        normal_laws!(dispatch_arms!($self, $law, $e))
    };
}

/// The arms of [`dispatch!`], from the list of [`normal_laws!`].
macro_rules! dispatch_arms {
    (($self:ident, $l:ident, $e:expr) $($(#[$doc:meta])* $law:ident($params:ident) $name:ident = $kind:ident,)*) => {
        match $self {
            $(NormalLaw::$law($l) => $e,)*
        }
    };
}

/// `NormalLaw` adds one guarantee to the laws it dispatches to: an `Ok`
/// response or pull-off force is finite (an overflow at an extreme overlap,
/// load or parameter becomes [`Error::OutOfDomain`]).
impl NormalContact for NormalLaw {
    #[inline]
    fn eval(&self, delta: f64, old: &ContactState) -> Result<(NormalResponse, ContactState)> {
        // The check sits inside each arm so the response is checked in
        // registers and written once; a check after the merge would make
        // every call re-read the stored tuple with mismatched widths.
        dispatch!(self, l => l.eval(delta, old).and_then(finite_response))
    }
    #[inline]
    unsafe fn eval_batch_raw(&self, b: &RawBatch) -> core::result::Result<(), BatchError> {
        dispatch!(self, l => l.eval_batch_raw(b))
    }
    #[inline]
    fn eval_at_load(&self, force: f64) -> Result<NormalResponse> {
        let r = dispatch!(self, l => l.eval_at_load(force))?;
        if is_finite(&r) {
            Ok(r)
        } else {
            Err(Error::OutOfDomain {
                name: "force",
                value: force,
                reason: "the response overflows f64",
            })
        }
    }
    /// A pull-off force that overflows f64 (a DMT sphere of radius near
    /// f64::MAX, whose force is −∞) is [`Error::OutOfDomain`] naming `law`,
    /// not an `Ok` infinity.
    #[inline]
    fn pull_off_force(&self, control: Control) -> Result<f64> {
        let f = dispatch!(self, l => l.pull_off_force(control))?;
        if f.is_finite() {
            Ok(f)
        } else {
            Err(Error::OutOfDomain {
                name: "law",
                value: f,
                reason: "its pull-off force overflows f64",
            })
        }
    }
    #[inline]
    fn length_scale(&self) -> f64 {
        dispatch!(self, l => l.length_scale())
    }
    /// A reach that is not finite (parameters at the ends of f64) is
    /// [`Error::OutOfDomain`] naming `law`.
    fn reach(&self, control: Control, rel_force: f64) -> Result<f64> {
        let r = dispatch!(self, l => l.reach(control, rel_force))?;
        check::finite_result(r, "law", r, "its reach overflows f64")
    }
    /// An energy that overflows f64 is [`Error::OutOfDomain`] naming `delta`.
    fn energy(&self, delta: f64, old: &ContactState) -> Result<f64> {
        let u = dispatch!(self, l => l.energy(delta, old))?;
        check::finite_result(u, "delta", delta, "the energy overflows f64")
    }
}

/// The `no_slip` selector of the punch laws' inputs: 0 frictionless, 1
/// bonded; anything else is [`Error::UnknownSelector`] naming `no_slip`.
pub(crate) fn no_slip_flag(no_slip: i32) -> Result<bool> {
    match no_slip {
        0 => Ok(false),
        1 => Ok(true),
        v => Err(Error::UnknownSelector {
            name: "no_slip",
            value: v as i64,
        }),
    }
}

/// Check an overlap argument: any finite value.
#[inline]
pub(crate) fn check_delta(delta: f64) -> Result<f64> {
    crate::error::check::finite("delta", delta)
}

/// Check a force argument: any finite value.
#[inline]
pub(crate) fn check_force(force: f64) -> Result<f64> {
    crate::error::check::finite("force", force)
}

/// The response and state of a law without hysteresis.
#[inline]
pub(crate) fn stateless(
    force: f64,
    delta: f64,
    contact_radius: f64,
    stiffness: f64,
) -> (NormalResponse, ContactState) {
    let in_contact = (contact_radius > 0.0 || delta >= 0.0) as i32;
    (
        NormalResponse {
            force,
            delta,
            contact_radius,
            stiffness,
            in_contact,
            reserved: 0,
        },
        ContactState {
            contact_radius,
            cohesive_radius: 0.0,
            in_contact,
            branch: 0,
        },
    )
}

/// Response and state of a step that ends out of contact.
#[inline]
pub(crate) fn out_of_contact(delta: f64) -> (NormalResponse, ContactState) {
    (
        NormalResponse {
            force: 0.0,
            delta,
            contact_radius: 0.0,
            stiffness: 0.0,
            in_contact: 0,
            reserved: 0,
        },
        ContactState::default(),
    )
}

/// The hysteresis rule of the laws whose contact forms at δ = 0 and breaks
/// at a critical (negative) overlap: out of contact (or fresh) the surfaces
/// touch once δ ≥ 0; in contact they stay together down to `critical_delta`.
#[inline]
pub(crate) fn stays_in_contact(old: &ContactState, delta: f64, critical_delta: f64) -> bool {
    if old.in_contact != 0 {
        delta >= critical_delta
    } else {
        delta >= 0.0
    }
}

/// Error for a load below what a law can sustain.
#[inline]
pub(crate) fn below_pull_off(force: f64) -> Error {
    Error::OutOfDomain {
        name: "force",
        value: force,
        reason: "below the load-controlled pull-off force: no equilibrium",
    }
}

/// Whether every number of a response is finite.
#[inline]
pub(crate) fn is_finite(r: &NormalResponse) -> bool {
    r.force.is_finite()
        && r.delta.is_finite()
        && r.contact_radius.is_finite()
        && r.stiffness.is_finite()
}

/// The error of a response that overflowed at overlap `delta`.
#[cold]
pub(crate) fn overflow(delta: f64) -> Error {
    Error::OutOfDomain {
        name: "delta",
        value: delta,
        reason: "the response overflows f64",
    }
}

/// Pass a finite response through; an overflowed one becomes
/// [`Error::OutOfDomain`] on `delta`.
#[inline]
pub(crate) fn finite_response(
    rs: (NormalResponse, ContactState),
) -> Result<(NormalResponse, ContactState)> {
    if is_finite(&rs.0) {
        Ok(rs)
    } else {
        Err(overflow(rs.0.delta))
    }
}
