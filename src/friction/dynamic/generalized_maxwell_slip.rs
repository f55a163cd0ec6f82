//! The generalised Maxwell-slip (GMS) model (Al-Bender, Lampaert and
//! Swevers 2005; thesis 5.3.8): N Maxwell-slip elements whose slip law is
//! rate dependent, attracted to a Stribeck curve, scaled by the normal
//! force. Pre-sliding hysteresis with non-local memory, the Stribeck
//! steady-state curve and frictional lag in one model.
//!
//! # Formulas
//!
//! Element i has the stiffness kᵢ per unit normal force (1/m) and the
//! weight αᵢ ≥ 0; fᵢ is its force per unit normal force (dimensionless).
//! The Stribeck curve is
//!
//! $$s(v) = \mu_c + (\mu_s - \mu_c)\, e^{-|v/v_s|^{\delta}} .$$
//!
//! An element **sticks** while its force is below its share of the Stribeck
//! curve, |fᵢ| < αᵢ s(v): dfᵢ/dt = kᵢ v. When |fᵢ| reaches αᵢ s(v) it
//! **slips**, and stays slipping until the velocity changes sign:
//!
//! $$\frac{df_i}{dt} = \operatorname{sgn}(v)\, C \Big(1 - \frac{f_i}{\alpha_i\, s(v)\operatorname{sgn}(v)}\Big),$$
//!
//! which attracts fᵢ to sgn(v) αᵢ s(v) with the time constant αᵢ s(v)/C
//! (C, 1/s, the attraction rate per unit normal force; Al-Bender et al.
//! 2005, eqs. (3)–(5)). The friction force along the motion is
//!
//! $$F = N \sum_i f_i + \sigma_2 v .$$
//!
//! In steady sliding every element sits on its share, so
//! F_ss(v) = N s(v) Σαᵢ + σ₂ v: the Stribeck curve. With a flat curve
//! (μ_c = μ_s) an element in slip already sits on αᵢ μ_s, and the model is
//! exactly [`super::MaxwellSlip`] with break-away coefficients αᵢ μ_s (for
//! every C); so is the limit C → ∞ of a curved one with μᵢ = αᵢ s(v).
//!
//! **Passivity.** As published, the slip law can raise fᵢ faster than its
//! spring loads (C(1 − |fᵢ|/(αᵢ s)) > kᵢ|v|, after a velocity increase on a
//! rising Stribeck branch or a decrease on a falling one): the element's
//! block would then slide backwards while its force pushes forwards,
//! creating energy. Here that rate is limited to the stick rate kᵢ|v| (the
//! element loads like a stuck spring until the attraction is the slower of
//! the two), which keeps every element passive; the limit is inactive in
//! steady sliding, in every decreasing relaxation and whenever
//! C ≤ kᵢ|v|·αᵢs/(αᵢs − |fᵢ|).
//!
//! **Integration.** Each increment is taken at constant v = Δs/Δt, so s(v)
//! is constant over it and each phase (stick, rate-limited loading,
//! exponential attraction) is integrated in closed form: the step is exact,
//! and two half increments at the same velocity give the whole one.
//!
//! # Energy
//!
//! Element i is a spring N kᵢ in series with a block carrying N fᵢ; the
//! stored energy is ½ N Σ fᵢ²/kᵢ and the block dissipates
//! N ∫ fᵢ (ds − dfᵢ/kᵢ) ≥ 0 (zero while it sticks or loads at the stick
//! rate); the viscous term dissipates σ₂|Δs|²/Δt.
//!
//! # State
//!
//! `[dissipation, slip path, f₁, m₁, f₂, m₂, …]` (J, m, then per element
//! the force per unit normal force and the mode: 0 sticking, ±1 slipping
//! in ±x); all-zero = every element relaxed and sticking. One-dimensional:
//! `slip[1]` must be 0 (the slip-to-stick switch is a velocity reversal).
//!
//! # References
//!
//! * F. Al-Bender, V. Lampaert, J. Swevers, "The generalized Maxwell-slip
//!   model: a novel model for friction simulation and compensation", IEEE
//!   Trans. Automatic Control 50 (2005) 1883–1887.
//! * V. Lampaert, F. Al-Bender, J. Swevers, "A generalized Maxwell-slip
//!   friction model appropriate for control purposes", Proc. IEEE PhysCon
//!   (2003) 1170–1177.
//! * F. Al-Bender, V. Lampaert, J. Swevers, "Modeling of dry sliding
//!   friction dynamics: from heuristic models to physically motivated
//!   models and back", Chaos 14 (2004) 446–460.

use super::{
    book, check_elements, respond, track_only, FrictionIncrement, FrictionLaw, FrictionRegime,
    FrictionResponse, FrictionWork, STATE_MODEL, TANGENT_NORMAL, TANGENT_SLIP,
};
use crate::error::{check, Error, Result};

/// The parameters of the generalised Maxwell-slip model (immutable; share
/// between threads).
#[derive(Debug, Clone, PartialEq)]
pub struct GeneralizedMaxwellSlip {
    stiffness: Vec<f64>,
    weight: Vec<f64>,
    mu_coulomb: f64,
    mu_static: f64,
    stribeck_velocity: f64,
    stribeck_exponent: f64,
    attraction: f64,
    sigma2: f64,
    /// Σαᵢ.
    weight_sum: f64,
    /// Elements with αᵢ > 0.
    active: usize,
}

/// What one element did in an increment.
#[derive(Default, Clone, Copy)]
struct Element {
    /// New force per unit normal force.
    f: f64,
    /// New mode (0, ±1).
    mode: f64,
    /// ∂f/∂Δs at fixed old state and Δt.
    df: f64,
    /// Block dissipation per unit normal force (m).
    dissipated: f64,
    /// Whether the element slipped (its block moved) in the increment.
    slipped: bool,
}

impl GeneralizedMaxwellSlip {
    /// Elements with stiffnesses `stiffness` kᵢ (1/m per unit normal force,
    /// finite, > 0) and weights `weight` αᵢ (finite, ≥ 0) of equal length
    /// ≥ 1; the Stribeck curve's Coulomb and static coefficients
    /// `mu_coulomb` μ_c and `mu_static` μ_s (finite, > 0), velocity
    /// `stribeck_velocity` v_s (m/s, finite, > 0) and exponent
    /// `stribeck_exponent` δ (finite, > 0); the attraction rate `attraction`
    /// C (1/s, > 0; +∞ for the instantaneous limit) and the viscous
    /// coefficient `sigma2` σ₂ (N·s/m, finite, ≥ 0). The static coefficient
    /// is μ_s Σαᵢ (Σαᵢ = 1 makes s(v) the friction coefficient). Errors name
    /// the argument.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        stiffness: &[f64],
        weight: &[f64],
        mu_coulomb: f64,
        mu_static: f64,
        stribeck_velocity: f64,
        stribeck_exponent: f64,
        attraction: f64,
        sigma2: f64,
    ) -> Result<Self> {
        check_elements(stiffness, weight, "weight.len()")?;
        for &a in weight {
            check::non_negative("weight", a)?;
        }
        check::positive("mu_coulomb", mu_coulomb)?;
        check::positive("mu_static", mu_static)?;
        check::positive("stribeck_velocity", stribeck_velocity)?;
        check::positive("stribeck_exponent", stribeck_exponent)?;
        if attraction.is_nan() || attraction <= 0.0 {
            return Err(Error::InvalidArgument {
                name: "attraction",
                value: attraction,
                bound: "> 0 (+infinity: instantaneous)",
            });
        }
        check::non_negative("sigma2", sigma2)?;
        Ok(Self {
            stiffness: stiffness.to_vec(),
            weight: weight.to_vec(),
            mu_coulomb,
            mu_static,
            stribeck_velocity,
            stribeck_exponent,
            attraction,
            sigma2,
            weight_sum: weight.iter().sum(),
            active: weight.iter().filter(|&&a| a > 0.0).count(),
        })
    }

    /// Number of elements.
    pub fn elements(&self) -> usize {
        self.stiffness.len()
    }

    /// The static coefficient μ_s Σαᵢ: |F| ≤ N μ_s Σαᵢ + σ₂|v| once the
    /// elements started from rest.
    pub fn static_coefficient(&self) -> f64 {
        self.mu_static * self.weight_sum
    }

    /// The Stribeck curve s(v) = μ_c + (μ_s − μ_c) e^{−|v/v_s|^δ} at
    /// velocity `v` (m/s).
    pub fn stribeck(&self, v: f64) -> f64 {
        self.stribeck_and_slope(v.abs()).0
    }

    /// The steady-state friction force F_ss(v) = N s(v) Σαᵢ + σ₂ v (N) at
    /// speed `v` ≥ 0 (m/s) under normal force `normal_force` (N).
    pub fn steady_force(&self, normal_force: f64, v: f64) -> f64 {
        normal_force * self.stribeck(v) * self.weight_sum + self.sigma2 * v
    }

    /// The virgin curve N Σ min(kᵢ x, αᵢ s(v)) (N) of a loading from rest
    /// by `x` ≥ 0 (m) at speed `v` ≥ 0 (m/s), without the viscous term.
    pub fn virgin_force(&self, normal_force: f64, x: f64, v: f64) -> f64 {
        let s = self.stribeck(v);
        normal_force
            * self
                .stiffness
                .iter()
                .zip(&self.weight)
                .map(|(k, a)| (k * x).min(a * s))
                .sum::<f64>()
    }

    /// s(u) and ds/du at speed u ≥ 0.
    #[inline]
    fn stribeck_and_slope(&self, u: f64) -> (f64, f64) {
        let r = u / self.stribeck_velocity;
        let p = self.stribeck_exponent;
        let rp = if p == 2.0 { r * r } else { r.powf(p) };
        let e = (-rp).exp();
        let drop = self.mu_static - self.mu_coulomb;
        let s = self.mu_coulomb + drop * e;
        // d/du e^{−r^p} = −p r^{p−1}/v_s e^{−r^p}; 0 at u = 0 for p > 1.
        let slope = if e == 0.0 || drop == 0.0 || u == 0.0 {
            0.0
        } else {
            -drop * e * p * rp / u
        };
        (s, slope)
    }

    /// Element (stiffness `k`, old force `f0`, old mode `m0`) moved by
    /// `x` = |Δs| > 0 in the direction `d` = ±1 at speed `u` = x/Δt, its
    /// target αs = `a` with ∂a/∂x = `da` (module docs; all in the
    /// projection g = d·f on the direction of motion).
    #[inline]
    #[allow(clippy::too_many_arguments)]
    fn element(
        &self,
        k: f64,
        f0: f64,
        m0: f64,
        d: f64,
        x: f64,
        u: f64,
        a: f64,
        da: f64,
    ) -> Element {
        let g0 = d * f0;
        // (g, ∂g/∂x, block dissipation, slipped, mode).
        let (g, dg, diss, slipped, slipping) = if m0 != d {
            // Sticking (or a reversal: stick). Load at the stick rate.
            if g0 < a && g0 + k * x <= a {
                (g0 + k * x, k, 0.0, false, false)
            } else if g0 < a {
                // Reaches the target within the step and stays on it: the
                // target is constant at constant velocity.
                let x1 = (a - g0) / k;
                (a, da, a * (x - x1), true, true)
            } else {
                // Already at or above the target: slip at once.
                let (g, dg, diss) = self.relax(k, g0, x, u, a, da);
                (g, dg, diss, true, true)
            }
        } else {
            let (g, dg, diss) = self.relax(k, g0, x, u, a, da);
            (g, dg, diss, true, true)
        };
        Element {
            f: d * g,
            mode: if slipping { d } else { 0.0 },
            df: dg,
            dissipated: diss.max(0.0),
            slipped,
        }
    }

    /// A slipping element's projected force from `g0` over the displacement
    /// `x` at speed `u`, towards the target `a` (∂a/∂x = `da`): the
    /// attraction dg/dx = λ(a − g), λ = C/(u a), limited to the stick rate
    /// k. Returns (g, ∂g/∂x, block dissipation).
    #[inline]
    fn relax(&self, k: f64, g0: f64, x: f64, u: f64, a: f64, da: f64) -> (f64, f64, f64) {
        let c = self.attraction;
        if c == f64::INFINITY {
            // Instantaneous: down to the target at once, up at the stick
            // rate (the limit of the rate-limited law).
            if g0 < a {
                if g0 + k * x <= a {
                    return (g0 + k * x, k, 0.0);
                }
                let x1 = (a - g0) / k;
                return (a, da, a * (x - x1));
            }
            // The block slides back by (g0 − a)/k at the force falling
            // from g0 to a: ∫ g dw = x a + (g0² − a²)/(2k) − … exactly
            // a x + (g0 − a)²/(2k) + a (g0 − a)/k − (g0² − a²)/(2k)·0.
            return (a, da, a * x + 0.5 * (g0 - a) * (g0 + a) / k);
        }
        let lambda = c / (u * a);
        // ∂λ/∂x with u = x/Δt: λ' = −λ (1/x + a'/a).
        let dlambda = -lambda * (1.0 / x + da / a);
        let gc = a - k / lambda;
        if g0 < gc {
            // Rate-limited loading up to g_c, then the attraction.
            let xc = (gc - g0) / k;
            if x <= xc {
                return (g0 + k * x, k, 0.0);
            }
            // g = a − (k/λ) e^{−q}, q = λ(x − (a − g0)/k) + 1.
            let b = x - (a - g0) / k;
            let q = lambda * b + 1.0;
            let e = (-q).exp();
            let g = a - k / lambda * e;
            let dq = dlambda * b + lambda * (1.0 - da / k);
            let dg = if e == 0.0 {
                da
            } else {
                da + k * dlambda / (lambda * lambda) * e + k / lambda * e * dq
            };
            // Dissipation of the exponential part from g_c over x − x_c.
            let diss = attraction_dissipation(k, gc, g, a, lambda, x - xc);
            return (g, dg, diss);
        }
        // g = a + (g0 − a) e^{−λx}.
        let lx = lambda * x;
        let e = (-lx).exp();
        let g = a + (g0 - a) * e;
        let dg = if e == 0.0 {
            da
        } else {
            da * (1.0 - e) - (g0 - a) * e * (lambda + x * dlambda)
        };
        (g, dg, attraction_dissipation(k, g0, g, a, lambda, x))
    }
}

/// Block dissipation (per unit normal force) of the attraction
/// g = a + (gs − a) e^{−λy} over y: ∫ g dy − (ge² − gs²)/(2k), with
/// ∫ g dy = a y + (gs − a)(1 − e^{−λy})/λ.
#[inline]
fn attraction_dissipation(k: f64, gs: f64, ge: f64, a: f64, lambda: f64, y: f64) -> f64 {
    // (1 − e^{−λy})/λ → y as λ → 0 (an infinite speed: no attraction).
    let reach = if lambda == 0.0 {
        y
    } else {
        -(-lambda * y).exp_m1() / lambda
    };
    a * y + (gs - a) * reach - 0.5 * (ge - gs) * (ge + gs) / k
}

/// One increment (module docs). Regime (counting the elements with αᵢ > 0):
/// 0 every element sticks, 1 some slip, 2 every element slips, 3 no contact
/// when N = 0 (the elements are released to rest; the viscous term
/// remains). Tangents at fixed old state and Δt: dF/dN = −Σfᵢ;
/// dF/dΔs = −N Σ ∂fᵢ/∂Δs − σ₂/Δt, with ∂fᵢ/∂Δs through the phase
/// boundaries and through s(v), v = Δs/Δt.
impl FrictionLaw for GeneralizedMaxwellSlip {
    fn state_len(&self) -> usize {
        STATE_MODEL + 2 * self.elements()
    }

    fn rate_dependent(&self) -> bool {
        true
    }

    fn check(&self, increment: &FrictionIncrement) -> Result<()> {
        track_only(increment)
    }

    fn check_state(&self, state: &[f64], what: &'static str) -> Result<()> {
        for e in state[STATE_MODEL..].chunks_exact(2) {
            check::finite(what, e[0])?;
            if !(e[1] == 0.0 || e[1] == 1.0 || e[1] == -1.0) {
                return Err(Error::InvalidArgument {
                    name: what,
                    value: e[1],
                    bound: "element mode 0 or +-1",
                });
            }
        }
        Ok(())
    }

    fn advance(
        &self,
        old: Option<&[f64]>,
        new: &mut [f64],
        inc: &FrictionIncrement,
        _work: &mut FrictionWork,
    ) -> Result<FrictionResponse> {
        let n = inc.normal_force;
        let ds = inc.slip[0];
        let moving = ds != 0.0;
        let (d, x) = (ds.signum(), ds.abs());
        let u = if moving { x / inc.dt } else { 0.0 };
        let (s, slope) = self.stribeck_and_slope(u);
        let (mut sum_f, mut sum_df, mut energy, mut diss) = (0.0, 0.0, 0.0, 0.0);
        let mut slipping = 0usize;
        for i in 0..self.elements() {
            let j = STATE_MODEL + 2 * i;
            let (f0, m0) = match old {
                Some(o) => (o[j], o[j + 1]),
                None => (new[j], new[j + 1]),
            };
            let (k, alpha) = (self.stiffness[i], self.weight[i]);
            let e = if alpha == 0.0 {
                Element::default()
            } else if !moving {
                // No motion: nothing changes (a pause keeps the mode).
                Element {
                    f: f0,
                    mode: m0,
                    df: if m0 == 0.0 { k } else { 0.0 },
                    ..Element::default()
                }
            } else {
                let a = alpha * s;
                let da = alpha * slope / inc.dt;
                self.element(k, f0, m0, d, x, u, a, da)
            };
            new[j] = e.f;
            new[j + 1] = e.mode;
            sum_f += e.f;
            sum_df += e.df;
            energy += e.f * e.f / k;
            diss += e.dissipated;
            slipping += e.slipped as usize;
        }
        let c = if inc.dt > 0.0 {
            self.sigma2 / inc.dt
        } else {
            0.0
        };
        let viscous = c * ds;
        let dissipated = n * diss + viscous * ds;
        book(old, new, dissipated, inc.slip);
        if n == 0.0 {
            for e in new[STATE_MODEL..].iter_mut() {
                *e = 0.0;
            }
        }
        let mut resp = respond([n * sum_f + viscous, 0.0], n);
        resp.dissipated = dissipated;
        resp.stored_energy = if n == 0.0 { 0.0 } else { 0.5 * n * energy };
        resp.regime = if n == 0.0 {
            FrictionRegime::NoContact
        } else if slipping == self.active && (self.active > 0 || moving) {
            FrictionRegime::Slip
        } else if slipping == 0 {
            FrictionRegime::Stick
        } else {
            FrictionRegime::PartialSlip
        } as i32;
        if inc.tangents & TANGENT_NORMAL != 0 {
            resp.dforce_dnormal = [-sum_f, 0.0];
        }
        if inc.tangents & TANGENT_SLIP != 0 {
            resp.dforce_dslip[0][0] = -(n * sum_df + c);
        }
        resp.tangents = inc.tangents;
        Ok(resp)
    }
}
