//! The bristle model of Haessig and Friedland (1991; thesis 5.3.6, (5-8)):
//! the bonds between the surfaces as N elastic bristles that snap when
//! deflected too far and bond again undeflected, scaled by the normal force.
//! Its standard continuous form is [`super::LuGre`].
//!
//! # Formulas
//!
//! Bristle i has the stiffness kᵢ per unit normal force (1/m) and the break
//! deflection δᵢ (m). The friction force is (5-8)
//!
//! $$F = N \sum_i k_i d_i + \sigma_2 v,$$
//!
//! with dᵢ the bristle's deflection (its attachment point relative to its
//! root, |dᵢ| ≤ δᵢ). A slip Δs deflects every bristle by Δs. A bristle
//! that reaches δᵢ snaps: its elastic energy ½ N kᵢ δᵢ² is dissipated and
//! it bonds again undeflected, from where the rest of the slip deflects it
//! again. Over a slip of any length the snaps are counted exactly: with
//! r = |dᵢ + Δs| − δᵢ > 0 past the first snap, the bristle snaps ⌈r/δᵢ⌉
//! times and ends at r − (⌈r/δᵢ⌉ − 1) δᵢ in the direction of the slip.
//!
//! Bristles that all bond at once snap at once (a sawtooth between 0 and
//! N Σkᵢδᵢ). Haessig and Friedland bond them again at random places; here
//! the bristles differ in their break deflections (and may start deflected),
//! so they snap at different places and steady sliding averages the
//! sawtooths: μ → Σkᵢδᵢ/2 when the δᵢ are incommensurate.
//!
//! # Energy
//!
//! The work of the friction force along an increment equals the change of
//! the stored energy ½ N Σkᵢdᵢ² plus the dissipation (the snaps' energy
//! and σ₂v·Δs), exactly.
//!
//! # State
//!
//! `[dissipation, slip path, d₁, …, d_N]` (J, m, m…); all-zero =
//! undeflected bristles. One-dimensional: `slip[1]` must be 0.
//!
//! # References
//!
//! * D. A. Haessig, B. Friedland, "On the modeling and simulation of
//!   friction", J. Dyn. Sys., Meas., Control 113 (1991) 354–362.

use super::{
    book, check_elements, respond, track_only, FrictionIncrement, FrictionLaw, FrictionRegime,
    FrictionResponse, FrictionWork, STATE_MODEL, TANGENT_NORMAL, TANGENT_SLIP,
};
use crate::error::{check, Result};

/// The parameters of N bristles (immutable; share between threads).
#[derive(Debug, Clone, PartialEq)]
pub struct Bristles {
    /// Stiffness kᵢ per unit normal force (1/m).
    stiffness: Vec<f64>,
    /// Break deflection δᵢ (m).
    break_deflection: Vec<f64>,
    sigma2: f64,
}

impl Bristles {
    /// Bristles with stiffnesses `stiffness` kᵢ (1/m per unit normal force,
    /// finite, > 0) and break deflections `break_deflection` δᵢ (m, finite
    /// and > 0), of equal length ≥ 1, and the viscous coefficient `sigma2`
    /// σ₂ (N·s/m, finite, ≥ 0). Errors name the argument.
    pub fn new(stiffness: &[f64], break_deflection: &[f64], sigma2: f64) -> Result<Self> {
        check_elements(stiffness, break_deflection, "break_deflection.len()")?;
        for &d in break_deflection {
            check::positive("break_deflection", d)?;
        }
        check::non_negative("sigma2", sigma2)?;
        Ok(Self {
            stiffness: stiffness.to_vec(),
            break_deflection: break_deflection.to_vec(),
            sigma2,
        })
    }

    /// Number of bristles.
    pub fn bristles(&self) -> usize {
        self.stiffness.len()
    }

    /// The static coefficient Σkᵢδᵢ: the largest μ, with every bristle at
    /// its break deflection.
    pub fn static_coefficient(&self) -> f64 {
        self.stiffness
            .iter()
            .zip(&self.break_deflection)
            .map(|(k, d)| k * d)
            .sum()
    }
}

/// One bristle of break deflection `delta` deflected from `d` by the slip
/// `ds`: its new deflection and its number of snaps.
#[inline]
fn bristle(d: f64, ds: f64, delta: f64) -> (f64, f64) {
    let t = d + ds;
    let r = t.abs() - delta;
    if r <= 0.0 {
        return (t, 0.0);
    }
    let snaps = (r / delta).ceil();
    ((r - (snaps - 1.0) * delta).copysign(t), snaps)
}

/// One increment (module docs). Regime: 0 no bristle snapped, 1 some, 2
/// every bristle snapped. Tangents: dF/dN = −Σkᵢdᵢ; dF/dΔs = −N Σkᵢ −
/// σ₂/Δt (exact between snaps: a bristle's deflection follows the slip;
/// the force jumps where one snaps).
impl FrictionLaw for Bristles {
    fn state_len(&self) -> usize {
        STATE_MODEL + self.bristles()
    }

    fn rate_dependent(&self) -> bool {
        false
    }

    fn check(&self, increment: &FrictionIncrement) -> Result<()> {
        track_only(increment)
    }

    fn advance(
        &self,
        old: Option<&[f64]>,
        new: &mut [f64],
        inc: &FrictionIncrement,
        _work: &mut FrictionWork,
    ) -> Result<FrictionResponse> {
        let (n, ds) = (inc.normal_force, inc.slip[0]);
        let (mut spring, mut energy, mut released) = (0.0, 0.0, 0.0);
        let mut snapped = 0usize;
        let params = self.stiffness.iter().zip(&self.break_deflection);
        let mut one = |d: f64, k: f64, delta: f64| {
            let (e, snaps) = bristle(d, ds, delta);
            if snaps > 0.0 {
                snapped += 1;
                released += snaps * k * delta * delta;
            }
            spring += k * e;
            energy += k * e * e;
            e
        };
        let bristles = new[STATE_MODEL..].iter_mut();
        match old {
            Some(old) => {
                for ((d, &o), (&k, &delta)) in bristles.zip(&old[STATE_MODEL..]).zip(params) {
                    *d = one(o, k, delta);
                }
            }
            None => {
                for (d, (&k, &delta)) in bristles.zip(params) {
                    *d = one(*d, k, delta);
                }
            }
        }
        let viscous = if inc.dt > 0.0 {
            self.sigma2 / inc.dt * ds
        } else {
            0.0
        };
        let dissipated = 0.5 * n * released + viscous * ds;
        book(old, new, dissipated, inc.slip);
        let mut resp = respond([n * spring + viscous, 0.0], n);
        resp.dissipated = dissipated;
        resp.stored_energy = 0.5 * n * energy;
        resp.regime = if n == 0.0 {
            FrictionRegime::NoContact as i32
        } else if snapped == 0 {
            FrictionRegime::Stick as i32
        } else if snapped == self.bristles() {
            FrictionRegime::Slip as i32
        } else {
            FrictionRegime::PartialSlip as i32
        };
        if inc.tangents & TANGENT_NORMAL != 0 {
            resp.dforce_dnormal = [-spring, 0.0];
        }
        if inc.tangents & TANGENT_SLIP != 0 {
            let c = if inc.dt > 0.0 {
                self.sigma2 / inc.dt
            } else {
                0.0
            };
            resp.dforce_dslip[0][0] = -(n * self.stiffness.iter().sum::<f64>() + c);
        }
        resp.tangents = inc.tangents;
        Ok(resp)
    }
}
