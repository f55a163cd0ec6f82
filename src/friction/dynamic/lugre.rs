//! The LuGre friction model (Canudas de Wit, Olsson, Åström and Lischinsky
//! 1995), the continuous form of the bristle model of Haessig and Friedland
//! (1991; thesis 5.3.6, (5-8)), with Stribeck velocity weakening, scaled by
//! the normal force.
//!
//! # Formulas
//!
//! The mean bristle deflection z (m, a 2-vector) obeys, at slip velocity v,
//!
//! $$\dot z = v - \frac{\sigma_0 |v|}{\mu(|v|)}\, z,\qquad
//! \mu(v) = \mu_c + (\mu_s - \mu_c)\, e^{-(v/v_s)^{\delta}},$$
//!
//! and the friction force (along the motion, resisting it) is
//!
//! $$F = N\left(\sigma_0 z + \sigma_1(|v|)\,\dot z\right) + \sigma_2 v,\qquad
//! \sigma_1(v) = \sigma_1 e^{-(v/v_d)^2},$$
//!
//! with N the normal force: the bristle stiffness N σ₀ and damping N σ₁ are
//! proportional to N (Amontons scaling), σ₀ in 1/m and σ₁ in s/m. At steady
//! sliding z = μ(v)/σ₀ · v/|v| and F = N μ(v) + σ₂ v: the Stribeck curve.
//! The velocity-dependent damping σ₁(v) is Canudas de Wit et al.'s (1995)
//! remedy for the loss of passivity of constant damping.
//!
//! # Integration
//!
//! Over an increment at constant v = Δs/Δt the equation is linear with the
//! constant rate a = σ₀|v|/μ(|v|), so it is integrated exactly:
//! z(t) = z_ss + (z₀ − z_ss) e^{−a t}, z_ss = μ(|v|)/σ₀ · v/|v|. No step-size
//! limit, no sub-stepping; an increment of any length is exact.
//!
//! # Energy
//!
//! The stored energy is E = ½ N σ₀ |z|². The dissipation rate, the power of
//! F less dE/dt, is
//!
//! $$\dot D = N\sigma_0 a\,\bigl|z - c\bigr|^2 + |v|^2\Bigl(N\sigma_1(1 - \tfrac{\sigma_1 a}{4\sigma_0}) + \sigma_2\Bigr), \qquad c = \frac{\sigma_1 v}{2\sigma_0},$$
//!
//! which is ≥ 0 for every z when σ₁(|v|)|v| ≤ 4 μ(|v|) (exactly when, if
//! σ₂ = 0). [`LuGre::new`] checks the sufficient condition
//! σ₁ v_d /√(2e) ≤ 4 min(μ_c, μ_s) (the maximum of v e^{−(v/v_d)²} is
//! v_d/√(2e)), so every increment dissipates ≥ 0. The increment's
//! dissipation is the exact integral of Ḋ along z(t).
//!
//! # State
//!
//! `[dissipation, slip path, z_x, z_y]` (J, m, m, m); all-zero = undeflected
//! bristles.
//!
//! # References
//!
//! * C. Canudas de Wit, H. Olsson, K. J. Åström, P. Lischinsky, "A new
//!   model for control of systems with friction", IEEE Trans. Automatic
//!   Control 40 (1995) 419–425.
//! * D. A. Haessig, B. Friedland, "On the modeling and simulation of
//!   friction", J. Dyn. Sys., Meas., Control 113 (1991) 354–362.
//! * N. Barabanov, R. Ortega, "Necessary and sufficient conditions for
//!   passivity of the LuGre friction model", IEEE Trans. Automatic Control
//!   45 (2000) 830–832.

use super::{
    book_path, norm, read, respond, FrictionIncrement, FrictionLaw, FrictionRegime,
    FrictionResponse, FrictionWork, STATE_MODEL, TANGENT_NORMAL, TANGENT_SLIP,
};
use crate::error::{check, Error, Result};

/// The LuGre model's parameters (immutable; share between threads).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LuGre {
    mu_coulomb: f64,
    mu_static: f64,
    stribeck_velocity: f64,
    stribeck_exponent: f64,
    sigma0: f64,
    sigma1: f64,
    damping_velocity: f64,
    sigma2: f64,
    /// 1/v_s (s/m).
    inv_stribeck_velocity: f64,
    /// 1/v_d (s/m; 0 when v_d = +∞).
    inv_damping_velocity: f64,
    /// 1/σ₀ (m).
    inv_sigma0: f64,
    /// Whether σ₁'s decay e^{−(v/v_d)²} is the Stribeck decay (δ = 2,
    /// v_d = v_s), so one exponential serves both.
    shared_decay: bool,
}

/// e^{−x} and 1 − e^{−x} for x ≥ 0 (or +∞), each to a few ulp: below 1/32,
/// where e^{−x} − 1 would lose the leading digits, 1 − e^{−x} by its Taylor
/// polynomial of degree 8 (truncation < x⁸/9! ≤ 3e-18 relative), evaluated
/// by Estrin's scheme; above, by `exp`. Cheaper than `exp_m1`.
#[inline]
fn exp_neg(x: f64) -> (f64, f64) {
    if x < 1.0 / 32.0 {
        // 1 − e^{−x} = x (c₀ + c₁x + … + c₇x⁷), c_k = (−1)^k/(k+1)!.
        const C: [f64; 8] = [
            1.0,
            -1.0 / 2.0,
            1.0 / 6.0,
            -1.0 / 24.0,
            1.0 / 120.0,
            -1.0 / 720.0,
            1.0 / 5040.0,
            -1.0 / 40320.0,
        ];
        let x2 = x * x;
        let lo = (C[0] + C[1] * x) + (C[2] + C[3] * x) * x2;
        let hi = (C[4] + C[5] * x) + (C[6] + C[7] * x) * x2;
        let om = x * (lo + hi * (x2 * x2));
        (1.0 - om, om)
    } else {
        let e = (-x).exp();
        (e, 1.0 - e)
    }
}

/// e^{−x^p} from x² ≥ 0, 0 for x² = +∞ (p = 2 without `powf`).
#[inline]
fn decay(x2: f64, p: f64) -> f64 {
    if p == 2.0 {
        (-x2).exp()
    } else {
        (-x2.powf(0.5 * p)).exp()
    }
}

/// Index of LuGre's bristle deflection z (2 values, m) in a state.
pub const STATE_Z: usize = STATE_MODEL;
/// Doubles of a LuGre state.
const STATE_LEN: usize = STATE_MODEL + 2;

impl LuGre {
    /// A LuGre model: Coulomb and static coefficients `mu_coulomb` μ_c and
    /// `mu_static` μ_s (finite, ≥ 0, at least one > 0), Stribeck velocity
    /// `stribeck_velocity` v_s (m/s, finite, > 0) and exponent
    /// `stribeck_exponent` δ (finite, > 0; 2 is Gaussian), bristle stiffness
    /// `sigma0` σ₀ (1/m, per unit normal force, finite, > 0), bristle damping
    /// `sigma1` σ₁ (s/m, per unit normal force, finite, ≥ 0) decaying with
    /// `damping_velocity` v_d (m/s, > 0, may be +∞ only when σ₁ = 0), and
    /// viscous coefficient `sigma2` σ₂ (N·s/m, finite, ≥ 0).
    ///
    /// Errors name the argument; σ₁ > 0 must satisfy the passivity bound
    /// σ₁ v_d/√(2e) ≤ 4 min(μ_c, μ_s) (module docs), named `sigma1`.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        mu_coulomb: f64,
        mu_static: f64,
        stribeck_velocity: f64,
        stribeck_exponent: f64,
        sigma0: f64,
        sigma1: f64,
        damping_velocity: f64,
        sigma2: f64,
    ) -> Result<Self> {
        check::non_negative("mu_coulomb", mu_coulomb)?;
        check::non_negative("mu_static", mu_static)?;
        if mu_coulomb == 0.0 && mu_static == 0.0 {
            return Err(Error::InvalidArgument {
                name: "mu_static",
                value: mu_static,
                bound: "> 0 or mu_coulomb > 0 (a frictionless LuGre model has no bristles)",
            });
        }
        check::positive("stribeck_velocity", stribeck_velocity)?;
        check::positive("stribeck_exponent", stribeck_exponent)?;
        check::positive("sigma0", sigma0)?;
        check::non_negative("sigma1", sigma1)?;
        if damping_velocity.is_nan() || damping_velocity <= 0.0 {
            return Err(Error::InvalidArgument {
                name: "damping_velocity",
                value: damping_velocity,
                bound: "> 0 (+inf allowed when sigma1 = 0)",
            });
        }
        check::non_negative("sigma2", sigma2)?;
        if sigma1 > 0.0 {
            let peak = damping_velocity / (2.0 * core::f64::consts::E).sqrt();
            if sigma1 * peak > 4.0 * mu_coulomb.min(mu_static) {
                return Err(Error::InvalidArgument {
                    name: "sigma1",
                    value: sigma1,
                    bound: "<= 4 min(mu_coulomb, mu_static) sqrt(2e)/damping_velocity (passivity: every increment dissipates >= 0)",
                });
            }
        }
        Ok(Self {
            mu_coulomb,
            mu_static,
            stribeck_velocity,
            stribeck_exponent,
            sigma0,
            sigma1,
            damping_velocity,
            sigma2,
            inv_stribeck_velocity: 1.0 / stribeck_velocity,
            inv_damping_velocity: 1.0 / damping_velocity,
            inv_sigma0: 1.0 / sigma0,
            shared_decay: stribeck_exponent == 2.0 && damping_velocity == stribeck_velocity,
        })
    }

    /// The Stribeck coefficient μ(v) = μ_c + (μ_s − μ_c) e^{−(v/v_s)^δ} at
    /// speed `v` ≥ 0 (m/s).
    #[inline]
    pub fn stribeck(&self, v: f64) -> f64 {
        self.coefficients(v * v).0
    }

    /// The steady sliding friction force N μ(v) + σ₂ v (N) at speed `v` ≥ 0
    /// (m/s) under normal force `normal_force` (N): the Stribeck curve.
    pub fn steady_force(&self, normal_force: f64, v: f64) -> f64 {
        normal_force * self.stribeck(v) + self.sigma2 * v
    }

    /// μ(v) and the damping σ₁(v) = σ₁ e^{−(v/v_d)²} (s/m) from the squared
    /// speed `v2` = v² ≥ 0 (m²/s²; no square root before the exponentials),
    /// one exponential serving both when the decays coincide.
    #[inline]
    fn coefficients(&self, v2: f64) -> (f64, f64) {
        let strib = decay(
            v2 * self.inv_stribeck_velocity * self.inv_stribeck_velocity,
            self.stribeck_exponent,
        );
        let mu = self.mu_coulomb + (self.mu_static - self.mu_coulomb) * strib;
        let s1 = if self.sigma1 == 0.0 {
            0.0
        } else if self.shared_decay {
            self.sigma1 * strib
        } else {
            self.sigma1 * (-(v2 * self.inv_damping_velocity * self.inv_damping_velocity)).exp()
        };
        (mu, s1)
    }

    /// z at the end of an increment, the bristle force per unit normal
    /// force σ₀z + σ₁ż (along the motion, resisting it), the viscous force
    /// σ₂v (N) and the dissipation (J); no checks. Three divisions and one
    /// or two exponentials; no infinite intermediate even where μ(v)
    /// underflows to 0 (μ_c = 0 far above v_s: the bristles relax at once).
    #[inline(always)]
    fn increment(&self, z0: [f64; 2], n: f64, ds: [f64; 2], dt: f64) -> Increment {
        let s0 = self.sigma0;
        let len = norm(ds[0], ds[1]);
        if len == 0.0 {
            // No motion: the bristles hold their deflection.
            return Increment {
                z: z0,
                bristle: [s0 * z0[0], s0 * z0[1]],
                viscous: [0.0; 2],
                dissipated: 0.0,
                path: 0.0,
            };
        }
        let inv_dt = 1.0 / dt;
        let inv_len = 1.0 / len;
        let v = [ds[0] * inv_dt, ds[1] * inv_dt];
        let speed = len * inv_dt;
        let (mu, s1) = self.coefficients(v[0] * v[0] + v[1] * v[1]);
        // The relaxation rate a = σ₀|v|/μ and x = a Δt = σ₀|Δs|/μ.
        let inv_mu = 1.0 / mu;
        let x = (s0 * len * inv_mu).min(f64::MAX);
        let (e, om) = exp_neg(x);
        // σ₁a, 0 when σ₁(v) = 0 (a may be +∞ then).
        let s1a = if s1 > 0.0 {
            s1 * speed * s0 * inv_mu
        } else {
            0.0
        };
        let zmag = mu * self.inv_sigma0;
        let zs = [zmag * ds[0] * inv_len, zmag * ds[1] * inv_len];
        let q = [z0[0] - zs[0], z0[1] - zs[1]];
        let z = [zs[0] + q[0] * e, zs[1] + q[1] * e];
        // σ₁ż = σ₁a(z_ss − z) = −σ₁a q e^{−x} (0 once relaxed).
        let relax = if e > 0.0 { s1a * e } else { 0.0 };
        let bristle = [s0 * z[0] - relax * q[0], s0 * z[1] - relax * q[1]];
        // a∫|z − c|² dt over the increment with z − c = p + q e^{−at},
        // c = σ₁v/(2σ₀): a·Δt = x, a∫e^{−at} = 1 − e^{−x},
        // a∫e^{−2at} = (1 − e^{−2x})/2.
        let half = 0.5 * s1 * self.inv_sigma0;
        let p = [zs[0] - half * v[0], zs[1] - half * v[1]];
        let pp = p[0] * p[0] + p[1] * p[1];
        let steady = if pp > 0.0 { pp * x } else { 0.0 };
        let square = steady
            + 2.0 * (p[0] * q[0] + p[1] * q[1]) * om
            + 0.5 * (q[0] * q[0] + q[1] * q[1]) * om * (1.0 + e);
        let rest = n * s1 * (1.0 - 0.25 * s1a * self.inv_sigma0) + self.sigma2;
        // Both terms are ≥ 0 in exact arithmetic; max(0) drops rounding.
        let dissipated = n * s0 * square.max(0.0) + (speed * len * rest).max(0.0);
        Increment {
            z,
            bristle,
            viscous: [self.sigma2 * v[0], self.sigma2 * v[1]],
            dissipated,
            path: len,
        }
    }

    /// [`Self::increment`] as a call (the tangents' four extra increments).
    #[inline(never)]
    fn increment_call(&self, z0: [f64; 2], n: f64, ds: [f64; 2], dt: f64) -> Increment {
        self.increment(z0, n, ds, dt)
    }
}

/// One exact LuGre increment.
struct Increment {
    z: [f64; 2],
    bristle: [f64; 2],
    viscous: [f64; 2],
    dissipated: f64,
    /// |Δs| (m).
    path: f64,
}

impl Increment {
    /// The friction force along the motion (N) under normal force `n`.
    #[inline]
    fn force(&self, n: f64) -> [f64; 2] {
        [
            n * self.bristle[0] + self.viscous[0],
            n * self.bristle[1] + self.viscous[1],
        ]
    }
}

/// One increment (module docs). Regime: 0 when Δs = 0 (the bristles hold),
/// 2 otherwise. Tangents: dF/dN = −(σ₀z + σ₁ż) exactly (z does not depend
/// on N); dF/dΔs by central differences of the exact increment (4 more
/// evaluations; 0 when Δt = 0).
impl FrictionLaw for LuGre {
    fn state_len(&self) -> usize {
        STATE_LEN
    }

    fn rate_dependent(&self) -> bool {
        true
    }

    fn advance(
        &self,
        old: Option<&[f64]>,
        state: &mut [f64],
        inc: &FrictionIncrement,
        _work: &mut FrictionWork,
    ) -> Result<FrictionResponse> {
        let z0 = [read(old, state, STATE_Z), read(old, state, STATE_Z + 1)];
        let n = inc.normal_force;
        let step = self.increment(z0, n, inc.slip, inc.dt);
        if !step.dissipated.is_finite() {
            return Err(crate::error::Error::OutOfDomain {
                name: "slip",
                value: inc.slip[0].abs().max(inc.slip[1].abs()),
                reason: "the dissipated energy overflows f64",
            });
        }
        state[STATE_Z] = step.z[0];
        state[STATE_Z + 1] = step.z[1];
        book_path(old, state, step.dissipated, step.path);
        let mut r = respond(step.force(n), n);
        r.dissipated = step.dissipated;
        r.stored_energy = 0.5 * n * self.sigma0 * (step.z[0] * step.z[0] + step.z[1] * step.z[1]);
        r.regime = if n == 0.0 {
            FrictionRegime::NoContact as i32
        } else if inc.slip == [0.0, 0.0] {
            FrictionRegime::Stick as i32
        } else {
            FrictionRegime::Slip as i32
        };
        if inc.tangents & TANGENT_NORMAL != 0 {
            r.dforce_dnormal = [-step.bristle[0], -step.bristle[1]];
        }
        if inc.tangents & TANGENT_SLIP != 0 && inc.dt > 0.0 {
            let scale =
                norm(inc.slip[0], inc.slip[1]) + self.mu_static.max(self.mu_coulomb) / self.sigma0;
            let h = 1e-6 * scale;
            for j in 0..2 {
                let (mut plus, mut minus) = (inc.slip, inc.slip);
                plus[j] += h;
                minus[j] -= h;
                let fp = self.increment_call(z0, n, plus, inc.dt).force(n);
                let fm = self.increment_call(z0, n, minus, inc.dt).force(n);
                for i in 0..2 {
                    r.dforce_dslip[i][j] = -(fp[i] - fm[i]) / (2.0 * h);
                }
            }
        }
        r.tangents = inc.tangents;
        Ok(r)
    }
}

#[cfg(test)]
mod tests {
    use super::exp_neg;

    /// e^{−x} and 1 − e^{−x} against `exp` and `exp_m1` over 15 decades of
    /// x, densely across the switch at 1/32: within 4e-15 relative (the
    /// `exp` branch loses log₂(1/x) ≤ 5 bits of 1 − e^{−x} at the switch),
    /// and continuous there.
    #[test]
    fn exp_neg_matches_exp_m1() {
        let grid = (0..=1500)
            .map(|i| 10f64.powf(-12.0 + i as f64 / 100.0))
            .chain((0..=2000).map(|i| (1.0 / 32.0) * (0.999 + 0.002 * i as f64 / 2000.0)));
        for x in grid {
            let (e, om) = exp_neg(x);
            let want = -(-x).exp_m1();
            assert!((om - want).abs() <= 4e-15 * want, "x = {x}: {om} vs {want}");
            let want = (-x).exp();
            assert!(
                (e - want).abs() <= 4e-16 * want.max(1e-300),
                "x = {x}: {e} vs {want}"
            );
        }
        assert_eq!(exp_neg(0.0), (1.0, 0.0));
        assert_eq!(exp_neg(f64::INFINITY), (0.0, 1.0));
        assert_eq!(exp_neg(f64::MAX), (0.0, 1.0));
    }
}
