//! Rigid flat-ended cylindrical punch on an elastic half-space (Boussinesq),
//! no adhesion, frictionless or bonded (no slip; thesis §4.4, Borodich et
//! al. 2014, with [`crate::material::no_slip_factor`]). The stiffness is
//! constant while in contact. The adhesive version is [`super::Kendall`].
//!
//! # Formulas
//!
//! Boussinesq; the no-slip factor from Borodich et al. 2014:
//!
//! $$P = 2 E^\ast a \delta \ \ \text{(frictionless)}, \qquad P = 2 E^\ast a \delta\\, C_\mathrm{NS} \ \ \text{(no slip)}, \qquad C_\mathrm{NS} = \frac{(1-\nu)\ln(3-4\nu)}{1-2\nu},$$
//!
//! and the stiffness $dP/d\delta = 2E^\ast a$ (times $C_\mathrm{NS}$) while
//! $\delta > 0$.
//!
//! # References
//!
//! * Thesis §4.4 (no-slip factor of a bonded punch).
//! * J. Boussinesq (1885), *Application des potentiels à l'étude de l'équilibre
//!   et du mouvement des solides élastiques*, Gauthier-Villars, Paris.
//! * K. L. Johnson (1985), *Contact Mechanics*, Cambridge University Press,
//!   §3.8, [doi:10.1017/CBO9781139171731](https://doi.org/10.1017/CBO9781139171731).
//! * F. M. Borodich, B. A. Galanov, M. M. Suarez-Alvarez (2014), "The JKR-type
//!   adhesive contact problems for power-law shaped axisymmetric punches",
//!   J. Mech. Phys. Solids 68, 14–32,
//!   [doi:10.1016/j.jmps.2014.03.003](https://doi.org/10.1016/j.jmps.2014.03.003)
//!   (the no-slip factor).

use super::batch::{eval_pointwise, Pointwise};
use super::{
    check_delta, check_force, stateless, BatchError, ContactState, Control, NormalContact,
    NormalResponse, RawBatch,
};
use crate::error::{check, Result};
use crate::material::no_slip_factor;

/// Inputs of a flat punch, as [`FlatPunch::from_params`] and C's
/// `asperity_law_from_params` take them.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct FlatPunchParams {
    /// Punch radius a (m, > 0).
    pub radius: f64,
    /// Contact modulus E* (Pa, > 0).
    pub e_star: f64,
    /// Poisson's ratio ν of the half-space (0 ≤ ν ≤ 0.5): gives the no-slip
    /// factor when `no_slip` = 1; range-checked only when 0.
    pub nu: f64,
    /// 1 for a punch bonded to the half-space (no slip), 0 frictionless.
    pub no_slip: i32,
    /// Reserved, 0.
    pub reserved: i32,
}

/// Flat punch. Its inputs are [`FlatPunchParams`]; it caches its stiffness.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlatPunch {
    /// a (m).
    pub(crate) radius: f64,
    /// E* (Pa).
    pub(crate) e_star: f64,
    /// ν.
    pub(crate) nu: f64,
    /// 1 bonded, 0 frictionless.
    pub(crate) no_slip: i32,
    /// 0.
    pub(crate) reserved: i32,
    /// Cached stiffness `2 E* a` times the no-slip factor (1 when
    /// frictionless) (N/m).
    stiffness: f64,
}

law_inputs!(
    FlatPunch,
    FlatPunchParams {
        radius,
        e_star,
        nu,
        no_slip,
        reserved
    }
);

impl FlatPunch {
    /// Frictionless punch of radius `radius` (m) and contact modulus `e_star` (Pa).
    pub fn new(radius: f64, e_star: f64) -> Result<Self> {
        let radius = check::positive("radius", radius)?;
        let e_star = check::positive("e_star", e_star)?;
        Ok(Self {
            radius,
            e_star,
            nu: 0.0,
            no_slip: 0,
            reserved: 0,
            stiffness: 2.0 * e_star * radius,
        })
    }

    /// Punch bonded to a half-space of Poisson's ratio `nu` (no slip):
    /// stiffness `2 E* a C_NS(ν)`.
    pub fn no_slip(radius: f64, e_star: f64, nu: f64) -> Result<Self> {
        let mut p = Self::new(radius, e_star)?;
        p.stiffness *= no_slip_factor(nu)?;
        p.nu = nu;
        p.no_slip = 1;
        Ok(p)
    }

    /// The punch of the inputs `p`: `no_slip` is checked first (0 or 1),
    /// then, when frictionless, `nu` (range only), then as by
    /// [`FlatPunch::new`] or [`FlatPunch::no_slip`].
    pub fn from_params(p: &FlatPunchParams) -> Result<Self> {
        if super::no_slip_flag(p.no_slip)? {
            Self::no_slip(p.radius, p.e_star, p.nu)
        } else {
            let nu = check::poisson("nu", p.nu)?;
            Ok(Self {
                nu,
                ..Self::new(p.radius, p.e_star)?
            })
        }
    }

    /// The contact stiffness `2E*a`, times `C_NS(ν)` when bonded (N/m).
    #[inline]
    pub fn stiffness(&self) -> f64 {
        self.stiffness
    }
}

impl Pointwise for FlatPunch {
    /// `(2E*aδ·C, a, 2E*a·C)` for δ ≥ 0, zero below (selected, not branched).
    #[inline]
    fn point(&self, delta: f64) -> (f64, f64, f64) {
        if delta >= 0.0 {
            (self.stiffness * delta, self.radius, self.stiffness)
        } else {
            (0.0, 0.0, 0.0)
        }
    }
}

impl NormalContact for FlatPunch {
    #[inline]
    fn eval(&self, delta: f64, _old: &ContactState) -> Result<(NormalResponse, ContactState)> {
        let delta = check_delta(delta)?;
        let (f, a, k) = self.point(delta);
        Ok(stateless(f, delta, a, k))
    }

    #[inline]
    unsafe fn eval_batch_raw(&self, b: &RawBatch) -> core::result::Result<(), BatchError> {
        eval_pointwise(self, b)
    }

    fn eval_at_load(&self, force: f64) -> Result<NormalResponse> {
        let force = check_force(force)?;
        if force < 0.0 {
            return Err(super::below_pull_off(force));
        }
        Ok(stateless(force, force / self.stiffness, self.radius, self.stiffness).0)
    }

    fn pull_off_force(&self, _control: Control) -> Result<f64> {
        Ok(0.0)
    }

    fn length_scale(&self) -> f64 {
        self.radius
    }

    /// 0: no adhesion (`rel_force` is checked, then ignored).
    fn reach(&self, _control: Control, rel_force: f64) -> Result<f64> {
        super::check_rel_force(rel_force)?;
        Ok(0.0)
    }

    /// `U = ½ k δ²` for δ ≥ 0 (k = 2E*a, times C_NS when bonded), 0 otherwise.
    fn energy(&self, delta: f64, _old: &ContactState) -> Result<f64> {
        let delta = check_delta(delta)?;
        Ok(if delta > 0.0 {
            0.5 * self.stiffness * delta * delta
        } else {
            0.0
        })
    }
}
