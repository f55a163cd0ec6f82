//! Maxwell-slip elements in parallel (Al-Bender, Lampaert and Swevers 2004;
//! Lampaert, Al-Bender and Swevers 2003; thesis 5.3.8, (5-9)..(5-12) reduced
//! to the tangential direction), scaled by the normal force: pre-sliding
//! hysteresis with non-local memory.
//!
//! # Formulas
//!
//! Element i is a spring of stiffness N kᵢ (kᵢ in 1/m, per unit normal
//! force) in series with a Coulomb slip block of break-away force N μᵢ; its
//! spring deflection δᵢ (m, a 2-vector) obeys |δᵢ| ≤ rᵢ = μᵢ/kᵢ. Over an
//! increment Δs the trial deflection is tᵢ = δᵢ + Δs; if |tᵢ| ≤ rᵢ the
//! element sticks (δᵢ = tᵢ), otherwise it slips by |tᵢ| − rᵢ and
//! δᵢ = rᵢ tᵢ/|tᵢ| (the radial return; exact in one dimension). The friction
//! force along the motion is
//!
//! $$F = N \sum_i k_i \delta_i + \sigma_2 v,\qquad v = \Delta s/\Delta t.$$
//!
//! The virgin curve of a one-dimensional loading from rest is
//! F_v(x) = N Σ min(kᵢ x, μᵢ); the elements give the Masing rules exactly:
//! after a reversal at x_r the force is F(x_r) − 2 F_v((x_r − x)/2), and a
//! closed inner loop is forgotten (non-local memory).
//!
//! # Energy
//!
//! Stored energy E = ½ N Σ kᵢ|δᵢ|²; the increment dissipates
//! N Σ μᵢ (|tᵢ| − rᵢ)⁺ in the slip blocks and σ₂|Δs|²/Δt in the viscous term
//! (0 when Δt = 0: then σ₂ is not used), each ≥ 0.
//!
//! # State
//!
//! `[dissipation, slip path, δ₁x, δ₁y, δ₂x, δ₂y, …]` (J, m, m…); all-zero =
//! every spring relaxed.
//!
//! # References
//!
//! * F. Al-Bender, V. Lampaert, J. Swevers, "Modeling of dry sliding
//!   friction dynamics: from heuristic models to physically motivated
//!   models and back", Chaos 14 (2004) 446–460.
//! * V. Lampaert, F. Al-Bender, J. Swevers, "A generalized Maxwell-slip
//!   friction model appropriate for control purposes", Proc. IEEE PhysCon
//!   (2003) 1170–1177.
//! * G. Masing, "Eigenspannungen und Verfestigung beim Messing", Proc. 2nd
//!   Int. Congress of Applied Mechanics (1926) 332–335.

use super::{
    book, check_elements, norm, respond, FrictionIncrement, FrictionLaw, FrictionResponse,
    FrictionWork, STATE_MODEL, TANGENT_NORMAL, TANGENT_SLIP,
};
use crate::error::{check, Result};
use crate::friction::law::FrictionRegime;

/// The parameters of N Maxwell-slip elements (immutable; share between
/// threads).
#[derive(Debug, Clone, PartialEq)]
pub struct MaxwellSlip {
    /// Element stiffness kᵢ per unit normal force (1/m).
    stiffness: Vec<f64>,
    /// Element break-away coefficient μᵢ (break-away force N μᵢ).
    capacity: Vec<f64>,
    /// Element slip deflection rᵢ = μᵢ/kᵢ (m).
    reach: Vec<f64>,
    sigma2: f64,
    /// Elements with μᵢ > 0.
    active: usize,
}

impl MaxwellSlip {
    /// Elements with stiffnesses `stiffness` kᵢ (1/m per unit normal force,
    /// finite, > 0) and break-away coefficients `capacity` μᵢ (finite, ≥ 0;
    /// the model's static coefficient is Σμᵢ), of equal length ≥ 1, and the
    /// viscous coefficient `sigma2` σ₂ (N·s/m, finite, ≥ 0). Errors name the
    /// argument.
    pub fn new(stiffness: &[f64], capacity: &[f64], sigma2: f64) -> Result<Self> {
        check_elements(stiffness, capacity, "capacity.len()")?;
        for &m in capacity {
            check::non_negative("capacity", m)?;
        }
        check::non_negative("sigma2", sigma2)?;
        Ok(Self {
            stiffness: stiffness.to_vec(),
            capacity: capacity.to_vec(),
            reach: stiffness.iter().zip(capacity).map(|(k, m)| m / k).collect(),
            sigma2,
            active: capacity.iter().filter(|&&m| m > 0.0).count(),
        })
    }

    /// Number of elements.
    pub fn elements(&self) -> usize {
        self.stiffness.len()
    }

    /// The static coefficient Σμᵢ: |F| ≤ N Σμᵢ + σ₂|v|.
    pub fn static_coefficient(&self) -> f64 {
        self.capacity.iter().sum()
    }

    /// The virgin curve F_v(x) = N Σ min(kᵢ x, μᵢ) (N) of a one-dimensional
    /// loading from rest to slip `x` ≥ 0 (m) under normal force
    /// `normal_force` (N), without the viscous term.
    pub fn virgin_force(&self, normal_force: f64, x: f64) -> f64 {
        normal_force
            * self
                .stiffness
                .iter()
                .zip(&self.capacity)
                .map(|(k, m)| (k * x).min(*m))
                .sum::<f64>()
    }
}

/// The sums over the elements of one increment.
#[derive(Default)]
struct Sums {
    /// Σ kᵢδᵢ (1/m · m).
    spring: [f64; 2],
    /// Σ kᵢ|δᵢ|².
    energy: f64,
    /// Σ μᵢ × slip of element i (m).
    slipped: f64,
    /// Elements that slipped.
    slipping: usize,
    /// Σ kᵢ ∂δᵢ/∂Δs (when asked for).
    tangent: [[f64; 2]; 2],
}

/// Element (kᵢ = `k`, μᵢ = `m`, rᵢ = `r`) with old deflection `d` after the
/// slip `ds`: the radial return of the trial deflection t = d + Δs onto
/// |δ| ≤ rᵢ. Adds to `sums`; returns the new deflection.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn element(
    d: [f64; 2],
    ds: [f64; 2],
    k: f64,
    m: f64,
    r: f64,
    want_slip: bool,
    sums: &mut Sums,
) -> [f64; 2] {
    let t = [d[0] + ds[0], d[1] + ds[1]];
    if m == 0.0 {
        // No break-away force (r = 0): the spring never deflects, carries
        // no force and has no stiffness; it neither sticks nor slips.
        return [0.0, 0.0];
    }
    // Stick when |t| ≤ r, decided on the squares (no square root for a
    // sticking element); a slipping element takes |t| exactly.
    let len2 = t[0] * t[0] + t[1] * t[1];
    let e = if len2 > r * r || (len2.is_infinite() && norm(t[0], t[1]) > r) {
        let len = norm(t[0], t[1]);
        sums.slipping += 1;
        sums.slipped += m * (len - r);
        let s = r / len;
        if want_slip {
            let u = [t[0] / len, t[1] / len];
            for a in 0..2 {
                for b in 0..2 {
                    let id = if a == b { 1.0 } else { 0.0 };
                    sums.tangent[a][b] += k * s * (id - u[a] * u[b]);
                }
            }
        }
        [t[0] * s, t[1] * s]
    } else {
        if want_slip {
            sums.tangent[0][0] += k;
            sums.tangent[1][1] += k;
        }
        t
    };
    sums.spring[0] += k * e[0];
    sums.spring[1] += k * e[1];
    sums.energy += k * (e[0] * e[0] + e[1] * e[1]);
    e
}

/// One increment (module docs). Regime (counting the elements with μᵢ > 0;
/// those with μᵢ = 0 never deflect): 0 every element sticks, 1 some slip
/// (pre-sliding), 2 every element slips (gross sliding; without such
/// elements, any non-zero slip), 3 no contact when N = 0 (the springs and
/// blocks carry no force; the viscous term σ₂v remains, and the elements
/// are released to rest: no junction survives a separation). Tangents are
/// the consistent tangents of the radial return: dF/dN = −Σ kᵢδᵢ (at N = 0
/// the derivative from above, with the deflections the slip would give),
/// dF/dΔs = −N Σ kᵢ ∂δᵢ/∂Δs (kᵢ I sticking, kᵢ rᵢ/|tᵢ| (I − nᵢnᵢᵀ)
/// slipping, 0 for μᵢ = 0) − σ₂/Δt I.
impl FrictionLaw for MaxwellSlip {
    fn state_len(&self) -> usize {
        STATE_MODEL + 2 * self.elements()
    }

    fn rate_dependent(&self) -> bool {
        false
    }

    fn advance(
        &self,
        old: Option<&[f64]>,
        new: &mut [f64],
        inc: &FrictionIncrement,
        _work: &mut FrictionWork,
    ) -> Result<FrictionResponse> {
        let n = inc.normal_force;
        let ds = inc.slip;
        let want_slip = inc.tangents & TANGENT_SLIP != 0;
        let mut sums = Sums::default();
        let params = self.stiffness.iter().zip(&self.capacity).zip(&self.reach);
        // Two loops rather than a branch per element: from a separate old
        // state, or in place.
        let elements = new[STATE_MODEL..].chunks_exact_mut(2);
        match old {
            Some(old) => {
                for ((d, o), ((&k, &m), &r)) in
                    elements.zip(old[STATE_MODEL..].chunks_exact(2)).zip(params)
                {
                    let e = element([o[0], o[1]], ds, k, m, r, want_slip, &mut sums);
                    d.copy_from_slice(&e);
                }
            }
            None => {
                for (d, ((&k, &m), &r)) in elements.zip(params) {
                    let e = element([d[0], d[1]], ds, k, m, r, want_slip, &mut sums);
                    d.copy_from_slice(&e);
                }
            }
        }
        let Sums {
            spring,
            energy,
            slipped,
            slipping,
            tangent,
        } = sums;
        let active = self.active;
        let viscous = if inc.dt > 0.0 {
            let c = self.sigma2 / inc.dt;
            [c * ds[0], c * ds[1]]
        } else {
            [0.0; 2]
        };
        let dissipated = n * slipped + (viscous[0] * ds[0] + viscous[1] * ds[1]);
        book(old, new, dissipated, ds);
        if n == 0.0 {
            // No contact: no junctions, so nothing stays deflected (and
            // nothing was stored: the springs are N kᵢ). A point that closes
            // again starts from rest, not from where its motion while open
            // dragged the elements. The tangents below are those from above
            // (N → 0⁺), from the deflections before this release.
            new[STATE_MODEL..].fill(0.0);
        }
        let mut resp = respond([n * spring[0] + viscous[0], n * spring[1] + viscous[1]], n);
        resp.dissipated = dissipated;
        resp.stored_energy = 0.5 * n * energy;
        let moving = ds[0] != 0.0 || ds[1] != 0.0;
        resp.regime = if n == 0.0 {
            FrictionRegime::NoContact
        } else if slipping == active && (active > 0 || moving) {
            FrictionRegime::Slip
        } else if slipping == 0 {
            FrictionRegime::Stick
        } else {
            FrictionRegime::PartialSlip
        } as i32;
        if inc.tangents & TANGENT_NORMAL != 0 {
            resp.dforce_dnormal = [-spring[0], -spring[1]];
        }
        if want_slip {
            let c = if inc.dt > 0.0 {
                self.sigma2 / inc.dt
            } else {
                0.0
            };
            for (a, (row, t)) in resp.dforce_dslip.iter_mut().zip(&tangent).enumerate() {
                for (b, (out, t)) in row.iter_mut().zip(t).enumerate() {
                    let id = if a == b { c } else { 0.0 };
                    *out = -(n * t + id);
                }
            }
        }
        resp.tangents = inc.tangents;
        Ok(resp)
    }
}
