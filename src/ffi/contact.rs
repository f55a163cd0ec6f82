//! C ABI for `crate::contact`: the plain law value, its constructors, scalar
//! and batch evaluation, evaluation at a load, and pull-off.

use super::{guard, input, output, Failure};
use crate::contact::{
    normal_laws, ContactState, Control, Derjaguin, DerjaguinParams, Dmt, DmtParams, FlatPunch,
    FlatPunchParams, Hertz, HertzParams, Jkr, JkrParams, JkrPowerPunch, JkrPowerPunchParams,
    Kendall, KendallParams, MaugisDugdale, MaugisDugdaleParams, NormalContact, NormalLaw,
    NormalResponse, PowerPunch, PowerPunchParams, RawBatch,
};
use crate::error::{Error, Result};

/// Law kind: not a law (an all-zero `AsperityNormalLaw`).
pub const ASPERITY_LAW_NONE: i32 = 0;
/// Law kind: Hertz sphere.
pub const ASPERITY_LAW_HERTZ: i32 = 1;
/// Law kind: Galin power-law punch (cones included).
pub const ASPERITY_LAW_POWER_PUNCH: i32 = 2;
/// Law kind: flat punch (Boussinesq), frictionless or no-slip.
pub const ASPERITY_LAW_FLAT_PUNCH: i32 = 3;
/// Law kind: DMT sphere.
pub const ASPERITY_LAW_DMT: i32 = 4;
/// Law kind: JKR sphere.
pub const ASPERITY_LAW_JKR: i32 = 5;
/// Law kind: JKR power-law punch (Borodich 2014), frictionless or no-slip.
pub const ASPERITY_LAW_JKR_POWER_PUNCH: i32 = 6;
/// Law kind: Kendall adhesive flat punch.
pub const ASPERITY_LAW_KENDALL: i32 = 7;
/// Law kind: Maugis–Dugdale sphere.
pub const ASPERITY_LAW_MAUGIS_DUGDALE: i32 = 8;
/// Law kind: rigid sphere with a surface-force law (Derjaguin approximation).
pub const ASPERITY_LAW_DERJAGUIN: i32 = 9;

/// Control mode: prescribed force (soft machine).
pub const ASPERITY_CONTROL_LOAD: i32 = 0;
/// Control mode: prescribed approach (rigid machine, fixed grips).
pub const ASPERITY_CONTROL_DISPLACEMENT: i32 = 1;

/// Surface law of `asperity_law_derjaguin`: Lennard-Jones 3-9, `parameter` =
/// equilibrium separation z₀ (m).
pub const ASPERITY_SURFACE_LAW_LENNARD_JONES: i32 = 1;
/// Surface law: Dugdale step, `parameter` = σ₀ (Pa), the cohesive stress.
pub const ASPERITY_SURFACE_LAW_DUGDALE: i32 = 2;
/// Surface law: exponential, `parameter` = decay length ℓ (m).
pub const ASPERITY_SURFACE_LAW_EXPONENTIAL: i32 = 3;

const _: () = {
    use crate::contact::derjaguin::{DUGDALE, EXPONENTIAL, LENNARD_JONES};
    assert!(ASPERITY_SURFACE_LAW_LENNARD_JONES == LENNARD_JONES);
    assert!(ASPERITY_SURFACE_LAW_DUGDALE == DUGDALE);
    assert!(ASPERITY_SURFACE_LAW_EXPONENTIAL == EXPONENTIAL);
};

/// The parameters of a law: the inputs of `AsperityNormalLaw::kind`, as
/// given, in the member of that kind. In an `AsperityNormalLaw` built by a
/// constructor, `raw` holds the library's own form of the law: those inputs
/// first, then values it derives from them, whose layout is private and may
/// change between releases. As input of `asperity_law_from_params` only the
/// member of `kind` is read.
#[repr(C)]
#[derive(Clone, Copy)]
pub union AsperityLawParams {
    /// `ASPERITY_LAW_HERTZ`.
    pub hertz: HertzParams,
    /// `ASPERITY_LAW_POWER_PUNCH`.
    pub power_punch: PowerPunchParams,
    /// `ASPERITY_LAW_FLAT_PUNCH`.
    pub flat_punch: FlatPunchParams,
    /// `ASPERITY_LAW_DMT`.
    pub dmt: DmtParams,
    /// `ASPERITY_LAW_JKR`.
    pub jkr: JkrParams,
    /// `ASPERITY_LAW_JKR_POWER_PUNCH`.
    pub jkr_power_punch: JkrPowerPunchParams,
    /// `ASPERITY_LAW_KENDALL`.
    pub kendall: KendallParams,
    /// `ASPERITY_LAW_MAUGIS_DUGDALE`.
    pub maugis_dugdale: MaugisDugdaleParams,
    /// `ASPERITY_LAW_DERJAGUIN`.
    pub derjaguin: DerjaguinParams,
    /// Storage: the inputs, then the library's private derived values.
    pub raw: [f64; 16],
}

/// A single-asperity normal law, by value: copy it freely, share it between
/// threads, keep it in your own arrays. Build it with an `asperity_law_*`
/// constructor (or `asperity_law_from_params`), which validates the inputs
/// and stores derived values after them; read the inputs from the member of
/// `params` that `kind` names, and build a new law to change them (a write
/// to a member leaves the derived values stale).
#[repr(C)]
#[derive(Clone, Copy)]
pub struct AsperityNormalLaw {
    /// One of `ASPERITY_LAW_*`.
    pub kind: i32,
    /// Reserved, 0.
    pub reserved: i32,
    /// The inputs of `kind` (and the library's derived values).
    pub params: AsperityLawParams,
}

const _: () = assert!(core::mem::size_of::<AsperityLawParams>() == 16 * 8);

/// A Rust law that lives in the storage of [`AsperityLawParams`].
///
/// # Safety
/// The type is `repr(C)`, made of `f64` and `i32` fields only and without
/// padding (so every bit pattern is a valid value and every stored byte is
/// initialised), at most 16 doubles in size and aligned to at most 8, and its
/// leading fields are its inputs, laid out as the union member of its kind
/// (which `law_inputs!` checks).
unsafe trait Stored: Copy {}

/// Per law of [`normal_laws!`]: it lives in the storage (size and alignment
/// checked here), and the kind constants count 1, 2, … in the list's order,
/// so `ASPERITY_LAW_NONE` (0) stays "not a law" and a new law takes the next
/// value.
macro_rules! c_laws {
    (() $($(#[$doc:meta])* $law:ident($params:ident) $name:ident = $kind:ident,)*) => {
        $(
            // SAFETY: see the law's definition; size and alignment checked here.
            unsafe impl Stored for $law {}
            const _: () = assert!(
                core::mem::size_of::<$law>() <= core::mem::size_of::<AsperityLawParams>()
                    && core::mem::align_of::<$law>() <= 8
            );
        )*
        const _: () = {
            let mut next = ASPERITY_LAW_NONE;
            $(
                next += 1;
                assert!($kind == next, "kinds count 1, 2, ... in the order of normal_laws!");
            )*
        };
    };
}
normal_laws!(c_laws!());

/// The storage of `law`: zeros, then the law (inputs first).
#[inline]
fn store<L: Stored>(law: L) -> AsperityLawParams {
    let mut p = AsperityLawParams { raw: [0.0; 16] };
    // SAFETY: `Stored` guarantees the size and alignment fit the storage.
    unsafe { p.raw.as_mut_ptr().cast::<L>().write(law) };
    p
}

/// The law of type `L` in the storage `p`.
///
/// # Safety
/// None beyond the choice of `L` by the caller: every bit pattern is a valid
/// `L` (see [`Stored`]); a wrong `L` gives a wrong law, never undefined
/// behaviour.
#[inline(always)]
unsafe fn stored<L: Stored>(p: &AsperityLawParams) -> &L {
    // SAFETY: `Stored` guarantees size, alignment and validity.
    unsafe { &*p.raw.as_ptr().cast::<L>() }
}

/// The C value of a [`NormalLaw`], and a law from its inputs: one arm per
/// law of [`normal_laws!`].
macro_rules! c_law_conversions {
    (() $($(#[$doc:meta])* $law:ident($params:ident) $name:ident = $kind:ident,)*) => {
        impl From<NormalLaw> for AsperityNormalLaw {
            fn from(law: NormalLaw) -> Self {
                let (kind, params) = match law {
                    $(NormalLaw::$law(l) => ($kind, store(l)),)*
                };
                AsperityNormalLaw {
                    kind,
                    reserved: 0,
                    params,
                }
            }
        }

        /// The law of kind `kind` from the inputs `params`, validated by the
        /// law's `from_params`.
        fn law_from_params(kind: i32, params: &AsperityLawParams) -> Result<NormalLaw> {
            // SAFETY: every member is plain old data (f64/i32 fields), valid
            // for any bit pattern; `kind` selects the member the caller filled.
            unsafe {
                match kind {
                    $($kind => $law::from_params(&params.$name).map(NormalLaw::$law),)*
                    k => Err(Error::UnknownSelector {
                        name: "kind",
                        value: k as i64,
                    }),
                }
            }
        }
    };
}
normal_laws!(c_law_conversions!());

/// Run `$e` with `$l` bound to a reference to the concrete law stored in the
/// C value `$c`, after validating the kind (never transmuted). `$e` must
/// evaluate to `Result<_, E>` with `E: From<Error>`.
macro_rules! with_law {
    ($c:expr, $l:ident => $e:expr) => {{
        let c: &AsperityNormalLaw = $c;
        normal_laws!(with_law_arms!(c, $l, $e))
    }};
}

/// The `match` of [`with_law!`]: one arm per law of [`normal_laws!`].
macro_rules! with_law_arms {
    (($c:ident, $l:ident, $e:expr) $($(#[$doc:meta])* $law:ident($params:ident) $name:ident = $kind:ident,)*) => {
        // SAFETY: `stored` is sound for any bits; `kind` selects the type the
        // constructor stored.
        unsafe {
            match $c.kind {
                $($kind => {
                    let $l = stored::<$law>(&$c.params);
                    $e
                })*
                k => Err(Error::UnknownSelector {
                    name: "law.kind",
                    value: k as i64,
                }
                .into()),
            }
        }
    };
}

impl AsperityNormalLaw {
    /// The Rust law of this value; the kind is validated, never transmuted.
    #[inline]
    pub fn to_law(&self) -> Result<NormalLaw> {
        with_law!(self, l => Ok(NormalLaw::from(*l)))
    }
}

pub(crate) fn control_of(control: i32) -> Result<Control> {
    match control {
        ASPERITY_CONTROL_LOAD => Ok(Control::Load),
        ASPERITY_CONTROL_DISPLACEMENT => Ok(Control::Displacement),
        v => Err(Error::UnknownSelector {
            name: "control",
            value: v as i64,
        }),
    }
}

unsafe fn build(out: *mut AsperityNormalLaw, make: impl FnOnce() -> Result<NormalLaw>) -> i32 {
    guard(|| {
        let out = output(out, "out")?;
        *out = make()?.into();
        Ok(())
    })
}

/// The law of kind `kind` (`ASPERITY_LAW_*`) from its inputs: the member of
/// `params` that `kind` names (`params->jkr` for `ASPERITY_LAW_JKR`, ...;
/// `params` must point to a whole `AsperityLawParams`), validated as by the
/// kind's `asperity_law_*` constructor; errors name the member's field
/// (`radius`, `no_slip`, `parameter`, ...), or `kind` for an unknown kind.
#[no_mangle]
pub unsafe extern "C" fn asperity_law_from_params(
    kind: i32,
    params: *const AsperityLawParams,
    out: *mut AsperityNormalLaw,
) -> i32 {
    build(out, || law_from_params(kind, input(params, "params")?))
}

/// Hertz sphere: radius R (m), contact modulus E* (Pa).
#[no_mangle]
pub unsafe extern "C" fn asperity_law_hertz(
    radius: f64,
    e_star: f64,
    out: *mut AsperityNormalLaw,
) -> i32 {
    build(out, || Ok(NormalLaw::Hertz(Hertz::new(radius, e_star)?)))
}

/// Galanov effective sphere: a sphere of radius `radius` (m) in a spherical
/// crater (the deformed medium) of radius `medium_radius` (m, INFINITY for a
/// flat), `1/R = 1/R_s − 1/R_medium` (thesis (2-19), (3-23)).
#[no_mangle]
pub unsafe extern "C" fn asperity_law_sphere_in_crater(
    radius: f64,
    medium_radius: f64,
    e_star: f64,
    out: *mut AsperityNormalLaw,
) -> i32 {
    build(out, || {
        Ok(NormalLaw::Hertz(Hertz::sphere_in_crater(
            radius,
            medium_radius,
            e_star,
        )?))
    })
}

/// Galin power-law punch `f(r) = b r^d`: b (m^(1−d)), 1 ≤ d ≤ 100, E* (Pa).
#[no_mangle]
pub unsafe extern "C" fn asperity_law_power_punch(
    b: f64,
    d: f64,
    e_star: f64,
    out: *mut AsperityNormalLaw,
) -> i32 {
    build(out, || {
        Ok(NormalLaw::PowerPunch(PowerPunch::new(b, d, e_star)?))
    })
}

/// Cone of half-angle `half_angle` (rad, in (0, π/2)); a power punch with
/// d = 1, b = cot(half_angle).
#[no_mangle]
pub unsafe extern "C" fn asperity_law_cone(
    half_angle: f64,
    e_star: f64,
    out: *mut AsperityNormalLaw,
) -> i32 {
    build(out, || {
        Ok(NormalLaw::PowerPunch(PowerPunch::cone(half_angle, e_star)?))
    })
}

/// Galanov effective cone: indenter half-angle γ_i in an imprint of half-angle
/// γ_f > γ_i (rad), `b = cot γ_i − cot γ_f` (thesis (2-18)).
#[no_mangle]
pub unsafe extern "C" fn asperity_law_cone_in_imprint(
    indenter_half_angle: f64,
    imprint_half_angle: f64,
    e_star: f64,
    out: *mut AsperityNormalLaw,
) -> i32 {
    build(out, || {
        Ok(NormalLaw::PowerPunch(PowerPunch::cone_in_imprint(
            indenter_half_angle,
            imprint_half_angle,
            e_star,
        )?))
    })
}

/// Frictionless flat punch of radius a (m): `P = 2E*aδ`.
#[no_mangle]
pub unsafe extern "C" fn asperity_law_flat_punch(
    radius: f64,
    e_star: f64,
    out: *mut AsperityNormalLaw,
) -> i32 {
    build(out, || {
        Ok(NormalLaw::FlatPunch(FlatPunch::new(radius, e_star)?))
    })
}

/// Bonded (no-slip) flat punch: `P = 2E*aδ·C_NS(ν)`.
#[no_mangle]
pub unsafe extern "C" fn asperity_law_flat_punch_no_slip(
    radius: f64,
    e_star: f64,
    nu: f64,
    out: *mut AsperityNormalLaw,
) -> i32 {
    build(out, || {
        Ok(NormalLaw::FlatPunch(FlatPunch::no_slip(
            radius, e_star, nu,
        )?))
    })
}

/// DMT sphere: radius (m), E* (Pa), work of adhesion (J/m²).
#[no_mangle]
pub unsafe extern "C" fn asperity_law_dmt(
    radius: f64,
    e_star: f64,
    work_of_adhesion: f64,
    out: *mut AsperityNormalLaw,
) -> i32 {
    build(out, || {
        Ok(NormalLaw::Dmt(Dmt::new(radius, e_star, work_of_adhesion)?))
    })
}

/// JKR sphere: radius (m), E* (Pa), work of adhesion (J/m²).
#[no_mangle]
pub unsafe extern "C" fn asperity_law_jkr(
    radius: f64,
    e_star: f64,
    work_of_adhesion: f64,
    out: *mut AsperityNormalLaw,
) -> i32 {
    build(out, || {
        Ok(NormalLaw::Jkr(Jkr::new(radius, e_star, work_of_adhesion)?))
    })
}

/// JKR power-law punch (Borodich 2014): `f(r) = b r^d`, E* (Pa), work of
/// adhesion (J/m²); `no_slip` = 1 for a punch bonded to a half-space of
/// Poisson's ratio `nu` (thesis (1-39), (1-40)), 0 for frictionless (then `nu`
/// is only range-checked).
#[no_mangle]
pub unsafe extern "C" fn asperity_law_jkr_power_punch(
    b: f64,
    d: f64,
    e_star: f64,
    work_of_adhesion: f64,
    nu: f64,
    no_slip: i32,
    out: *mut AsperityNormalLaw,
) -> i32 {
    build(out, || {
        JkrPowerPunch::from_params(&JkrPowerPunchParams {
            b,
            d,
            e_star,
            work_of_adhesion,
            nu,
            no_slip,
            reserved: 0,
        })
        .map(NormalLaw::JkrPowerPunch)
    })
}

/// Kendall adhesive flat punch of radius a (m); `no_slip` = 1 for a bonded
/// punch on a half-space of Poisson's ratio `nu`.
#[no_mangle]
pub unsafe extern "C" fn asperity_law_kendall(
    radius: f64,
    e_star: f64,
    work_of_adhesion: f64,
    nu: f64,
    no_slip: i32,
    out: *mut AsperityNormalLaw,
) -> i32 {
    build(out, || {
        Kendall::from_params(&KendallParams {
            radius,
            e_star,
            work_of_adhesion,
            nu,
            no_slip,
            reserved: 0,
        })
        .map(NormalLaw::Kendall)
    })
}

/// Maugis–Dugdale sphere: radius (m), E* (Pa), work of adhesion (J/m²),
/// Dugdale cohesive stress σ₀ (Pa).
#[no_mangle]
pub unsafe extern "C" fn asperity_law_maugis_dugdale(
    radius: f64,
    e_star: f64,
    work_of_adhesion: f64,
    sigma0: f64,
    out: *mut AsperityNormalLaw,
) -> i32 {
    build(out, || {
        // The Rust API calls σ₀ `cohesive_stress`; the C argument is `sigma0`.
        MaugisDugdale::new(radius, e_star, work_of_adhesion, sigma0)
            .map(NormalLaw::MaugisDugdale)
            .map_err(|e| e.renamed("cohesive_stress", "sigma0"))
    })
}

/// Rigid sphere of radius (m) with a surface-force law between flats
/// (Derjaguin approximation). `surface_law` is one of `ASPERITY_SURFACE_LAW_*`
/// and `parameter` its second parameter: z₀ (m) for Lennard-Jones, σ₀ (Pa) for
/// Dugdale, ℓ (m) for exponential.
#[no_mangle]
pub unsafe extern "C" fn asperity_law_derjaguin(
    radius: f64,
    work_of_adhesion: f64,
    surface_law: i32,
    parameter: f64,
    out: *mut AsperityNormalLaw,
) -> i32 {
    build(out, || {
        Derjaguin::from_params(&DerjaguinParams {
            radius,
            work_of_adhesion,
            parameter,
            surface_law,
            reserved: 0,
        })
        .map(NormalLaw::Derjaguin)
    })
}

/// Evaluate `law` at the overlap `delta` (m; > 0 penetration) from the history
/// `old_state`, writing the history after the step to `new_state` and the
/// response to `out`. `old_state` may be NULL (a fresh contact) and
/// `new_state` NULL (history discarded); they may point to the same struct.
/// `law` and `out` are required.
#[no_mangle]
pub unsafe extern "C" fn asperity_normal_eval(
    law: *const AsperityNormalLaw,
    delta: f64,
    old_state: *const ContactState,
    new_state: *mut ContactState,
    out: *mut NormalResponse,
) -> i32 {
    guard(|| {
        let law = input(law, "law")?;
        let out = output(out, "out")?;
        let old = read_state(old_state);
        with_law!(law, l => eval_one(l, delta, &old, new_state, out))
    })
}

/// The arrays of a C batch call, with the required ones checked for NULL.
#[inline]
pub(crate) unsafe fn raw_batch(
    n: usize,
    delta: *const f64,
    old_state: *const ContactState,
    new_state: *mut ContactState,
    force: *mut f64,
    contact_radius: *mut f64,
    stiffness: *mut f64,
) -> Result<RawBatch> {
    input(delta, "delta")?;
    output(force, "force")?;
    Ok(RawBatch {
        n,
        delta,
        old_state,
        new_state,
        force,
        contact_radius,
        stiffness,
    })
}

/// The caller's old state, or a fresh one for NULL.
#[inline(always)]
pub(crate) unsafe fn read_state(old_state: *const ContactState) -> ContactState {
    if old_state.is_null() {
        ContactState::default()
    } else {
        old_state.read()
    }
}

/// One evaluation written through the C ABI's out-pointers, with the
/// finiteness guarantee; shared by every scalar `*_eval` export.
#[inline(always)]
pub(crate) unsafe fn eval_one<L: NormalContact>(
    law: &L,
    delta: f64,
    old: &ContactState,
    new_state: *mut ContactState,
    out: &mut NormalResponse,
) -> core::result::Result<(), Failure> {
    let (r, s) = law.eval(delta, old)?;
    if !crate::contact::is_finite(&r) {
        return Err(crate::contact::overflow(delta).into());
    }
    // Field by field: a whole-struct copy of the just-returned tuple is done
    // with 16-byte loads over 8-byte stores, which defeats store forwarding
    // and slows every call.
    out.force = r.force;
    out.delta = r.delta;
    out.contact_radius = r.contact_radius;
    out.stiffness = r.stiffness;
    out.in_contact = r.in_contact;
    out.reserved = 0;
    if !new_state.is_null() {
        let n = &mut *new_state;
        n.contact_radius = s.contact_radius;
        n.cohesive_radius = s.cohesive_radius;
        n.in_contact = s.in_contact;
        n.branch = s.branch;
    }
    Ok(())
}

/// Evaluate `law` for `n` contacts: `delta[i]` (m), `old_state[i]` →
/// `new_state[i]`, writing `force[i]` (N), `contact_radius[i]` (m) and
/// `stiffness[i]` (N/m). `delta` and `force` are required; the other arrays may
/// be NULL (fresh states / not wanted). Input and output arrays may be the same
/// memory. On an error at element i, elements before i are written, those from
/// i on are untouched, the status is returned and the message names i.
#[no_mangle]
pub unsafe extern "C" fn asperity_normal_eval_batch(
    law: *const AsperityNormalLaw,
    n: usize,
    delta: *const f64,
    old_state: *const ContactState,
    new_state: *mut ContactState,
    force: *mut f64,
    contact_radius: *mut f64,
    stiffness: *mut f64,
) -> i32 {
    guard(|| {
        let law = input(law, "law")?;
        if n == 0 {
            // Still reject an invalid kind.
            return law.to_law().map(|_| ()).map_err(Into::into);
        }
        let b = raw_batch(
            n,
            delta,
            old_state,
            new_state,
            force,
            contact_radius,
            stiffness,
        )?;
        with_law!(law, l => l.eval_batch_raw(&b).map_err(|e| Failure::at(e.index, e.error)))
    })
}

/// Equilibrium of `law` at the prescribed force `force` (N) on the stable
/// branch (largest contact radius); `out->delta` is the overlap.
/// `ASPERITY_ERR_OUT_OF_DOMAIN` below the load-controlled pull-off force.
#[no_mangle]
pub unsafe extern "C" fn asperity_normal_eval_at_load(
    law: *const AsperityNormalLaw,
    force: f64,
    out: *mut NormalResponse,
) -> i32 {
    guard(|| {
        let law = input(law, "law")?.to_law()?;
        let out = output(out, "out")?;
        *out = law.eval_at_load(force)?;
        Ok(())
    })
}

/// The force (N, ≤ 0 for adhesive laws) at which the contact separates under
/// `control` (`ASPERITY_CONTROL_LOAD` or `ASPERITY_CONTROL_DISPLACEMENT`).
#[no_mangle]
pub unsafe extern "C" fn asperity_pull_off_force(
    law: *const AsperityNormalLaw,
    control: i32,
    force: *mut f64,
) -> i32 {
    guard(|| {
        let law = input(law, "law")?.to_law()?;
        let control = control_of(control)?;
        let out = output(force, "force")?;
        *out = law.pull_off_force(control)?;
        Ok(())
    })
}

/// The reach of `law` under `control` (`ASPERITY_CONTROL_LOAD` or
/// `ASPERITY_CONTROL_DISPLACEMENT`): the overlap δ_r (m, ≤ 0) below which
/// the force is exactly zero from any history state, on approach and
/// retraction, when the contact separates under `control` (displacement:
/// the law's own jump-out rule, as `asperity_normal_eval`; load: at the
/// load-controlled pull-off, the force minimum). For laws whose force never
/// vanishes (Lennard-Jones or exponential surface laws) the overlap below
/// which |force| < `rel_force` × |load-controlled pull-off force|.
/// `rel_force` must be finite and in (0, 1) (`ASPERITY_ERR_INVALID_ARGUMENT`
/// naming `rel_force` otherwise); laws with a finite reach ignore its value.
/// Non-adhesive laws and DMT give 0; JKR gives δ_c = −(3/4)(π²w²R/E*²)^{1/3}
/// (displacement) and a²/R − √(2πwa/E*) at a = (9πwR²/(8E*))^{1/3} (load).
/// A host code sizes its neighbour cutoff and releases contacts with it.
#[no_mangle]
pub unsafe extern "C" fn asperity_normal_reach(
    law: *const AsperityNormalLaw,
    control: i32,
    rel_force: f64,
    delta: *mut f64,
) -> i32 {
    guard(|| {
        let law = input(law, "law")?.to_law()?;
        let control = control_of(control)?;
        let out = output(delta, "delta")?;
        *out = law.reach(control, rel_force)?;
        Ok(())
    })
}

/// The energy (J) of the equilibrium of `law` at the overlap `delta` (m)
/// reached from the history `old_state` (NULL: a fresh contact), with the
/// branch choice of `asperity_normal_eval`: elastic energy minus the surface
/// energy of the contact area, with dU/dδ = P along the branch, 0 for a
/// separated contact. Hertz (8/15)E*√R δ^{5/2}, DMT (Hertz − 2πwRδ), JKR
/// (elastic energy − πa²w), flat and power-law punches, Kendall and the
/// Derjaguin rigid sphere (interaction energy, 0 at infinite separation);
/// other laws give `ASPERITY_ERR_OUT_OF_DOMAIN` naming `law`.
#[no_mangle]
pub unsafe extern "C" fn asperity_normal_energy(
    law: *const AsperityNormalLaw,
    delta: f64,
    old_state: *const ContactState,
    energy: *mut f64,
) -> i32 {
    guard(|| {
        let law = input(law, "law")?.to_law()?;
        let out = output(energy, "energy")?;
        let old = read_state(old_state);
        *out = law.energy(delta, &old)?;
        Ok(())
    })
}

/// A characteristic overlap of `law` (m, finite and > 0), for
/// non-dimensionalising host-code tolerances. `ASPERITY_ERR_OUT_OF_DOMAIN`
/// (naming `law`, `length` untouched) when the parameters are so extreme
/// (e.g. a subnormal E*) that the scale underflows to 0 or overflows f64.
#[no_mangle]
pub unsafe extern "C" fn asperity_law_length_scale(
    law: *const AsperityNormalLaw,
    length: *mut f64,
) -> i32 {
    guard(|| {
        let law = input(law, "law")?.to_law()?;
        let out = output(length, "length")?;
        let l = law.length_scale();
        // A backstop: at the ends of f64 (a Kendall punch with E* = 5e-324,
        // a power punch with B = 3e165, d = 1.0017) the natural scale over-
        // or underflows; the laws fall back to another length, and nothing
        // but a finite, positive length leaves with status OK.
        if !(l.is_finite() && l > 0.0) {
            return Err(Error::OutOfDomain {
                name: "law",
                value: l,
                reason: "its length scale is not finite and > 0 (parameters at the ends of f64)",
            }
            .into());
        }
        *out = l;
        Ok(())
    })
}
