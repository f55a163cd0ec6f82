//! Kendall: rigid flat-ended cylindrical punch of radius a adhering to an
//! elastic half-space.
//!
//! In contact the punch is the Boussinesq flat punch, of constant stiffness
//! ($C_\mathrm{NS} = 1$ frictionless; for a bonded punch the no-slip factor
//! of [`crate::material::no_slip_factor`]). The contact, whose radius is
//! fixed, separates when the energy release rate of the edge crack reaches
//! w, at the same force under both controls: the radius cannot shrink, so
//! there is no stable partial detachment. Thesis §4.4 uses the no-slip form
//! for a nano-asperity.
//!
//! Hysteresis under displacement control: out of contact (including the
//! all-zero fresh state) the punch touches at δ ≥ 0; in contact it stays
//! down to δ_c inclusive, and below δ_c it jumps out (force 0,
//! `in_contact = 0`).
//!
//! # Formulas
//!
//! Kendall 1971; thesis §4.4; REFERENCE.md §1:
//!
//! $$P = 2E^\ast C_\mathrm{NS}\\, a\\, \delta, \qquad P_c = -\sqrt{8\pi w E^\ast C_\mathrm{NS} a^3}, \qquad \delta_c = \frac{P_c}{2E^\ast C_\mathrm{NS} a} = -\sqrt{\frac{2\pi w a}{E^\ast C_\mathrm{NS}}},$$
//!
//! with the constant stiffness $dP/d\delta = 2E^\ast C_\mathrm{NS} a$ in
//! contact and $C_\mathrm{NS} = 1$ for a frictionless punch.
//!
//! # References
//!
//! * Thesis §4.4 (the no-slip form for a nano-asperity).
//! * K. Kendall (1971), "The adhesion and surface energy of elastic solids",
//!   J. Phys. D: Appl. Phys. 4, 1186–1195,
//!   [doi:10.1088/0022-3727/4/8/320](https://doi.org/10.1088/0022-3727/4/8/320).
//! * F. M. Borodich, B. A. Galanov, M. M. Suarez-Alvarez (2014), J. Mech. Phys.
//!   Solids 68, 14–32,
//!   [doi:10.1016/j.jmps.2014.03.003](https://doi.org/10.1016/j.jmps.2014.03.003)
//!   (the no-slip factor $C_\mathrm{NS}$).

use super::jkr::contact_state;
use super::out_of_contact;
use super::{check_delta, check_force, ContactState, Control, NormalContact, NormalResponse};
use crate::error::{check, Result};
use core::f64::consts::PI;

/// Inputs of a Kendall punch, as [`Kendall::from_params`] and C's
/// `asperity_law_from_params` take them.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct KendallParams {
    /// Punch radius a (m, > 0).
    pub radius: f64,
    /// Contact modulus E* (Pa, > 0).
    pub e_star: f64,
    /// Work of adhesion w (J/m², ≥ 0).
    pub work_of_adhesion: f64,
    /// Poisson's ratio ν of the half-space (0 ≤ ν ≤ 0.5): gives the no-slip
    /// factor when `no_slip` = 1; range-checked only when 0.
    pub nu: f64,
    /// 1 for a punch bonded to the half-space (no slip), 0 frictionless.
    pub no_slip: i32,
    /// Reserved, 0.
    pub reserved: i32,
}

/// Kendall adhesive flat punch. Its inputs are [`KendallParams`]; it caches
/// C_NS, the stiffness, the pull-off force and the separation overlap.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kendall {
    /// a (m).
    pub(crate) radius: f64,
    /// E* (Pa).
    pub(crate) e_star: f64,
    /// w (J/m²).
    pub(crate) work_of_adhesion: f64,
    /// ν.
    pub(crate) nu: f64,
    /// 1 bonded, 0 frictionless.
    pub(crate) no_slip: i32,
    /// 0.
    pub(crate) reserved: i32,
    /// Cached no-slip factor C_NS (1 when frictionless).
    no_slip_factor: f64,
    /// Cached contact stiffness `2E* C_NS a` (N/m).
    stiffness: f64,
    /// Cached pull-off force `P_c = −√(8πwE* C_NS a³)` (N, ≤ 0).
    pub(crate) pull_off: f64,
    /// Cached separation overlap `δ_c = P_c/(2E* C_NS a)` (m, ≤ 0).
    critical_delta: f64,
}

law_inputs!(
    Kendall,
    KendallParams {
        radius,
        e_star,
        work_of_adhesion,
        nu,
        no_slip,
        reserved
    }
);

impl Kendall {
    /// Frictionless adhesive flat punch: radius (m, > 0), contact modulus
    /// (Pa, > 0), work of adhesion (J/m², ≥ 0).
    pub fn new(radius: f64, e_star: f64, work_of_adhesion: f64) -> Result<Self> {
        let radius = check::positive("radius", radius)?;
        let e_star = check::positive("e_star", e_star)?;
        let w = check::non_negative("work_of_adhesion", work_of_adhesion)?;
        Ok(Self::build(radius, e_star, w, (0.0, 0), 1.0))
    }

    /// Bonded (no-slip) adhesive flat punch on a half-space of Poisson's ratio
    /// `nu` (0 ≤ ν ≤ 0.5): stiffness and pull-off carry `C_NS(ν)`.
    pub fn no_slip(radius: f64, e_star: f64, work_of_adhesion: f64, nu: f64) -> Result<Self> {
        let radius = check::positive("radius", radius)?;
        let e_star = check::positive("e_star", e_star)?;
        let w = check::non_negative("work_of_adhesion", work_of_adhesion)?;
        let c_ns = crate::material::no_slip_factor(nu)?;
        Ok(Self::build(radius, e_star, w, (nu, 1), c_ns))
    }

    /// The punch of the inputs `p`: `no_slip` is checked first (0 or 1),
    /// then, when frictionless, `nu` (range only), then as by
    /// [`Kendall::new`] or [`Kendall::no_slip`].
    pub fn from_params(p: &KendallParams) -> Result<Self> {
        if super::no_slip_flag(p.no_slip)? {
            Self::no_slip(p.radius, p.e_star, p.work_of_adhesion, p.nu)
        } else {
            let nu = check::poisson("nu", p.nu)?;
            Ok(Self {
                nu,
                ..Self::new(p.radius, p.e_star, p.work_of_adhesion)?
            })
        }
    }

    /// The no-slip factor `C_NS(ν)` (1 when frictionless).
    #[inline]
    pub fn no_slip_factor(&self) -> f64 {
        self.no_slip_factor
    }

    /// The contact stiffness `2E* C_NS a` (N/m).
    #[inline]
    pub fn stiffness(&self) -> f64 {
        self.stiffness
    }

    /// The separation overlap `δ_c = P_c/(2E* C_NS a)` (m, ≤ 0).
    #[inline]
    pub fn critical_delta(&self) -> f64 {
        self.critical_delta
    }

    fn build(radius: f64, e_star: f64, w: f64, (nu, no_slip): (f64, i32), c_ns: f64) -> Self {
        let stiffness = 2.0 * e_star * c_ns * radius;
        let pull_off = if w > 0.0 {
            -(8.0 * PI * w * e_star * c_ns * radius).sqrt() * radius
        } else {
            0.0
        };
        Self {
            radius,
            e_star,
            work_of_adhesion: w,
            nu,
            no_slip,
            reserved: 0,
            no_slip_factor: c_ns,
            stiffness,
            pull_off,
            critical_delta: pull_off / stiffness,
        }
    }

    #[inline]
    fn respond(&self, force: f64, delta: f64) -> NormalResponse {
        NormalResponse {
            force,
            delta,
            contact_radius: self.radius,
            stiffness: self.stiffness,
            in_contact: 1,
            reserved: 0,
        }
    }
}

impl NormalContact for Kendall {
    /// Displacement-controlled step: touch at δ ≥ 0, separate below δ_c.
    #[inline]
    fn eval(&self, delta: f64, old: &ContactState) -> Result<(NormalResponse, ContactState)> {
        let delta = check_delta(delta)?;
        if !super::stays_in_contact(old, delta, self.critical_delta) {
            return Ok(out_of_contact(delta));
        }
        // δ ≥ δ_c implies P ≥ P_c; the clamp only removes rounding at δ_c, so
        // the force returned here is always accepted by `eval_at_load`.
        let r = self.respond((self.stiffness * delta).max(self.pull_off), delta);
        Ok((r, contact_state(&r)))
    }

    /// `δ = P/(2E* C_NS a)` for `P ≥ P_c`.
    fn eval_at_load(&self, force: f64) -> Result<NormalResponse> {
        let force = check_force(force)?;
        if force < self.pull_off {
            return Err(super::below_pull_off(force));
        }
        Ok(self.respond(force, force / self.stiffness))
    }

    /// `−√(8πwE* C_NS a³)` under both controls.
    fn pull_off_force(&self, _control: Control) -> Result<f64> {
        Ok(self.pull_off)
    }

    /// `|δ_c| = √(2πwa/(E* C_NS))`; the radius when w = 0, or when |δ_c|
    /// is not a normal number (a subnormal E* such as 5e-324 Pa makes it
    /// +∞).
    fn length_scale(&self) -> f64 {
        if self.critical_delta < 0.0 && (-self.critical_delta).is_normal() {
            -self.critical_delta
        } else {
            self.radius
        }
    }

    /// δ_c = `P_c/(2E* C_NS a)` under both controls (the punch separates at
    /// the same point under load and displacement control; out of contact it
    /// touches only at δ ≥ 0). 0 when w = 0. `rel_force` is checked, then
    /// ignored.
    fn reach(&self, _control: Control, rel_force: f64) -> Result<f64> {
        super::check_rel_force(rel_force)?;
        Ok(self.critical_delta)
    }

    /// In contact `U = ½ k δ² − πa²w` (elastic energy of the flat punch,
    /// k = 2E* C_NS a, minus the surface energy of the fixed contact area;
    /// Kendall 1971), `dU/dδ = kδ = P`; 0 out of contact (same branch
    /// choice as `eval`).
    fn energy(&self, delta: f64, old: &ContactState) -> Result<f64> {
        let (r, _) = self.eval(delta, old)?;
        if r.in_contact == 0 {
            return Ok(0.0);
        }
        Ok(0.5 * self.stiffness * delta * delta
            - PI * self.radius * self.radius * self.work_of_adhesion)
    }
}
