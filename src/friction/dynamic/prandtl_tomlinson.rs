//! The Prandtl–Tomlinson model (Prandtl 1928; thesis 5.3.1, (5-5), (5-6)):
//! a point mass in a periodic potential pulled through a spring, the
//! standard model of an AFM tip sliding on a crystal lattice; and its
//! two-spring tip–cantilever version (thesis figure 5-5).
//!
//! # Formulas
//!
//! **One spring** ([`PrandtlTomlinson::new`]). The tip (mass m, position
//! x) sits in the potential U(x) = −U₀ cos(2πx/a) and is pulled by a spring
//! of stiffness k whose far end (the support, the cantilever) is at x_s:
//!
//! $$m\ddot x = k(x_s - x) - \gamma\dot x - \frac{2\pi U_0}{a}\sin\frac{2\pi x}{a}.$$
//!
//! The lateral force on the support is F = k(x − x_s) (opposing its motion
//! when the tip lags). The total potential ½k(x − x_s)² + U(x) has one
//! minimum for every x_s exactly when η = 4π²U₀/(k a²) ≤ 1 (smooth sliding,
//! no hysteresis in the quasi-static limit); for η > 1 the tip sticks and
//! slips (Prandtl 1928; Socoliuc et al. 2004).
//!
//! **Two springs** ([`PrandtlTomlinson::two_spring`]). The tip (mass m_t,
//! position x_t, in the lattice potential) is joined by the tip (contact)
//! spring k_t to the cantilever body (mass m_c, position x_c), which is
//! joined by the cantilever's lateral spring k_c to the support x_s, with
//! damping γ_t, γ_c on each (Johnson and Woodhouse 1998; Maier et al. 2005):
//!
//! $$m_t\ddot x_t = k_t(x_c - x_t) - \gamma_t\dot x_t - U'(x_t),\qquad
//! m_c\ddot x_c = k_c(x_s - x_c) - k_t(x_c - x_t) - \gamma_c\dot x_c.$$
//!
//! The force on the support is F = k_c(x_c − x_s). In the quasi-static
//! limit the cantilever body carries no net force, the two springs act in
//! series with 1/k_eff = 1/k_t + 1/k_c, and the model reduces to the one-
//! spring model with k = k_eff (Lu et al. 2011, as the thesis notes): stick-
//! slip when η = 4π²U₀/(k_eff a²) > 1 ([`PrandtlTomlinson::eta`]). With
//! k_t → ∞ and m_c → 0 it is the one-spring model with k = k_c, m = m_t.
//!
//! # Integration
//!
//! Over an increment the support moves at constant velocity V = Δs/Δt and
//! the equations of motion are integrated by the embedded Runge–Kutta pair
//! of Dormand and Prince (1980, order 5(4)) with error control (relative
//! and absolute tolerances, step-size control with a safety factor; see
//! `dormand_prince`), carrying the dissipated energy ∫γẋ² dt (both masses)
//! as a component, so the work of the support equals the change of
//! kinetic, spring and lattice energy plus the dissipation to the
//! tolerance.
//!
//! # State
//!
//! One spring: `[dissipation, slip path, x − x_s, ẋ, x_s]` (J, m, m, m/s,
//! m): the tip relative to the support, its velocity and the support
//! position. Two springs: the same five, then `x_c − x_s, ẋ_c` (m, m/s)
//! ([`STATE_CANTILEVER`], [`STATE_CANTILEVER_VELOCITY`]). All-zero = at rest
//! at a potential minimum with the springs relaxed. One-dimensional:
//! `slip[1]` must be 0. The normal force is reported (μ = |F|/N) but does
//! not enter the model.
//!
//! # References
//!
//! * L. Prandtl, "Ein Gedankenmodell zur kinetischen Theorie der festen
//!   Körper", ZAMM 8 (1928) 85–106.
//! * A. Socoliuc, R. Bennewitz, E. Gnecco, E. Meyer, "Transition from
//!   stick-slip to continuous sliding in atomic friction", Phys. Rev. Lett.
//!   92 (2004) 134301.
//! * K. L. Johnson, J. Woodhouse, "Stick-slip motion in the atomic force
//!   microscope", Tribology Letters 5 (1998) 155–160.
//! * S. Maier, Y. Sang, T. Filleter, M. Heyde, R. Bennewitz, E. Gnecco,
//!   E. Meyer, "Fluctuations and jump dynamics in atomic friction
//!   experiments", Phys. Rev. B 72 (2005) 245418.
//! * J. R. Dormand, P. J. Prince, "A family of embedded Runge–Kutta
//!   formulae", J. Comput. Appl. Math. 6 (1980) 19–26.

use super::dormand_prince::{integrate, System};
use super::{
    book, read, respond, track_only, FrictionIncrement, FrictionLaw, FrictionResponse,
    FrictionWork, STATE_MODEL, TANGENT_SLIP,
};
use crate::error::{check, Error, Result};
use core::f64::consts::PI;

/// Index of x − x_s (m; the tip's) in a state.
pub const STATE_TIP: usize = STATE_MODEL;
/// Index of the tip velocity ẋ (m/s) in a state.
pub const STATE_VELOCITY: usize = STATE_MODEL + 1;
/// Index of the support position x_s (m) in a state.
pub const STATE_SUPPORT: usize = STATE_MODEL + 2;
/// Index of the cantilever body's x_c − x_s (m) in a two-spring state.
pub const STATE_CANTILEVER: usize = STATE_MODEL + 3;
/// Index of the cantilever body's velocity ẋ_c (m/s) in a two-spring state.
pub const STATE_CANTILEVER_VELOCITY: usize = STATE_MODEL + 4;

/// Sub-steps one increment may take before the integration gives up.
pub const MAX_SUBSTEPS: u32 = 1_000_000;

/// The cantilever body of the two-spring model.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Cantilever {
    stiffness: f64,
    mass: f64,
    damping: f64,
}

/// The Prandtl–Tomlinson model's parameters (immutable), with one spring
/// or two (tip and cantilever).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrandtlTomlinson {
    amplitude: f64,
    period: f64,
    /// k (one spring) or the tip spring k_t (two springs).
    stiffness: f64,
    mass: f64,
    damping: f64,
    tolerance: f64,
    cantilever: Option<Cantilever>,
}

fn check_tolerance(tolerance: f64) -> Result<()> {
    if (1e-13..=1e-2).contains(&tolerance) {
        Ok(())
    } else {
        Err(Error::InvalidArgument {
            name: "tolerance",
            value: tolerance,
            bound: "in [1e-13, 1e-2]",
        })
    }
}

impl PrandtlTomlinson {
    /// One spring: potential amplitude `amplitude` U₀ (J, finite, > 0),
    /// period `period` a (m, > 0), spring stiffness `stiffness` k
    /// (N/m, > 0), tip mass `mass` m (kg, > 0), damping `damping` γ
    /// (kg/s, ≥ 0), relative tolerance of the integration `tolerance` (in
    /// [1e-13, 1e-2]). Errors name the argument.
    pub fn new(
        amplitude: f64,
        period: f64,
        stiffness: f64,
        mass: f64,
        damping: f64,
        tolerance: f64,
    ) -> Result<Self> {
        check::positive("amplitude", amplitude)?;
        check::positive("period", period)?;
        check::positive("stiffness", stiffness)?;
        check::positive("mass", mass)?;
        check::non_negative("damping", damping)?;
        check_tolerance(tolerance)?;
        Ok(Self {
            amplitude,
            period,
            stiffness,
            mass,
            damping,
            tolerance,
            cantilever: None,
        })
    }

    /// Two springs (module docs): potential amplitude `amplitude` U₀
    /// (J, > 0) and period `period` a (m, > 0); the tip: contact spring
    /// `tip_stiffness` k_t (N/m, > 0) to the cantilever body, mass
    /// `tip_mass` m_t (kg, > 0), damping `tip_damping` γ_t (kg/s, ≥ 0); the
    /// cantilever body: lateral spring `cantilever_stiffness` k_c
    /// (N/m, > 0) to the support, mass `cantilever_mass` m_c (kg, > 0),
    /// damping `cantilever_damping` γ_c (kg/s, ≥ 0); relative tolerance
    /// `tolerance` (in [1e-13, 1e-2]). The state has two more values than
    /// one spring's. Errors name the argument.
    #[allow(clippy::too_many_arguments)]
    pub fn two_spring(
        amplitude: f64,
        period: f64,
        tip_stiffness: f64,
        tip_mass: f64,
        tip_damping: f64,
        cantilever_stiffness: f64,
        cantilever_mass: f64,
        cantilever_damping: f64,
        tolerance: f64,
    ) -> Result<Self> {
        check::positive("amplitude", amplitude)?;
        check::positive("period", period)?;
        check::positive("tip_stiffness", tip_stiffness)?;
        check::positive("tip_mass", tip_mass)?;
        check::non_negative("tip_damping", tip_damping)?;
        check::positive("cantilever_stiffness", cantilever_stiffness)?;
        check::positive("cantilever_mass", cantilever_mass)?;
        check::non_negative("cantilever_damping", cantilever_damping)?;
        check_tolerance(tolerance)?;
        Ok(Self {
            amplitude,
            period,
            stiffness: tip_stiffness,
            mass: tip_mass,
            damping: tip_damping,
            tolerance,
            cantilever: Some(Cantilever {
                stiffness: cantilever_stiffness,
                mass: cantilever_mass,
                damping: cantilever_damping,
            }),
        })
    }

    /// Whether this is the two-spring (tip–cantilever) model.
    pub fn is_two_spring(&self) -> bool {
        self.cantilever.is_some()
    }

    /// The stiffness between the tip and the support (N/m): k, or the two
    /// springs in series k_t k_c/(k_t + k_c).
    pub fn effective_stiffness(&self) -> f64 {
        match self.cantilever {
            None => self.stiffness,
            Some(c) => {
                let (kt, kc) = (self.stiffness, c.stiffness);
                // kt·kc/(kt + kc) without overflow for huge stiffnesses.
                if kt >= kc {
                    kc / (1.0 + kc / kt)
                } else {
                    kt / (1.0 + kt / kc)
                }
            }
        }
    }

    /// The Tomlinson parameter η = 4π²U₀/(k_eff a²) with k_eff
    /// [`Self::effective_stiffness`]: stick-slip when η > 1 (quasi-static
    /// limit).
    pub fn eta(&self) -> f64 {
        4.0 * PI * PI * self.amplitude / (self.effective_stiffness() * self.period * self.period)
    }

    /// The largest lateral force the lattice can exert, max U'(x) = 2πU₀/a
    /// (N): the quasi-static friction force's peak for any η > 1 (the
    /// equilibrium at x = a/4, where U'' = 0, is stable); the tip then
    /// follows the falling branch and jumps where k_eff + U''(x) = 0, at
    /// the force F_L √(1 − 1/η²).
    pub fn lattice_force(&self) -> f64 {
        2.0 * PI * self.amplitude / self.period
    }

    /// Lattice energy U(x) = −U₀ cos(2πx/a) (J).
    fn lattice(&self, x: f64) -> f64 {
        -self.amplitude * (2.0 * PI * x / self.period).cos()
    }

    /// The lattice's force on the tip at x, −U'(x) (N).
    #[inline]
    fn lattice_pull(&self, x: f64) -> f64 {
        let w = 2.0 * PI / self.period;
        -self.amplitude * w * (w * x).sin()
    }

    /// Integrates over `dt` with the support starting at `xs0` moving at
    /// `v_s`; returns the state or None when the sub-step budget runs out.
    fn solve<const N: usize>(&self, y0: [f64; N], xs0: f64, v_s: f64, dt: f64) -> Option<[f64; N]>
    where
        for<'a> Drive<'a>: System<N>,
    {
        // Scales: the lattice period for positions, the lattice's natural
        // velocity for velocities, U₀ for energy; the first step from the
        // fastest natural frequency.
        let (slow, fast) = match self.cantilever {
            None => {
                let w = (self.stiffness / self.mass).sqrt();
                (w, w)
            }
            Some(c) => (
                (self.effective_stiffness() / (self.mass + c.mass)).sqrt(),
                (self.stiffness / self.mass + (self.stiffness + c.stiffness) / c.mass).sqrt(),
            ),
        };
        let velocity = self.period * slow + v_s.abs();
        let scale: [f64; N] = core::array::from_fn(|c| match c {
            0 | 3 => self.period,
            2 => self.amplitude,
            _ => velocity,
        });
        let mut y = y0;
        let drive = Drive {
            model: self,
            cantilever: self.cantilever.unwrap_or(Cantilever {
                stiffness: 0.0,
                mass: 1.0,
                damping: 0.0,
            }),
            xs0,
            v_s,
        };
        integrate(
            &drive,
            &mut y,
            N,
            dt,
            0.05 / fast,
            self.tolerance,
            &scale,
            MAX_SUBSTEPS,
        )
        .map(|()| y)
    }
}

/// The tip pulled by a constant force ([`PrandtlTomlinson::pull_by_force`]).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ForcePull {
    /// Displacement of the tip from its start at a potential minimum (m).
    pub displacement: f64,
    /// Mean velocity, displacement over duration (m/s).
    pub mean_velocity: f64,
    /// Velocity at the end (m/s).
    pub velocity: f64,
    /// Energy dissipated by the damping, ∫γẋ² dt (J).
    pub dissipated: f64,
}

impl PrandtlTomlinson {
    /// The tip pulled by the constant force `force` F (N, finite) instead of
    /// a spring (thesis (5-5); Prandtl 1928): m ẍ = F − γ ẋ − U'(x), from
    /// rest at the potential minimum x = 0, over `duration` (s, finite,
    /// ≥ 0), integrated with the model's error control. The springs (and a
    /// cantilever) play no part: the tip's mass and damping do.
    ///
    /// The static friction of this form is the lattice force
    /// F_L = 2πU₀/a ([`Self::lattice_force`]): below it the tip settles at
    /// x* = (a/2π) asin(F/F_L) and stays; above it the tip slides, in the
    /// overdamped limit (m → 0) at the mean velocity √(F² − F_L²)/γ (the
    /// time to cross one period is ∫dx/(F − F_L sin(2πx/a)) · γ).
    ///
    /// Errors: `force`, `duration` (named); [`Error::NotConverged`] naming
    /// `duration` when [`MAX_SUBSTEPS`] steps do not reach its end.
    pub fn pull_by_force(&self, force: f64, duration: f64) -> Result<ForcePull> {
        check::finite("force", force)?;
        check::non_negative("duration", duration)?;
        let w = (self.lattice_force() * 2.0 * PI / (self.period * self.mass)).sqrt();
        let velocity = self.period * w + (force / self.damping.max(self.mass * w)).abs();
        let scale = [self.period, velocity, self.amplitude];
        let mut y = [0.0; 3];
        integrate(
            &Pulled { model: self, force },
            &mut y,
            3,
            duration,
            0.05 / w,
            self.tolerance,
            &scale,
            MAX_SUBSTEPS,
        )
        .ok_or(Error::NotConverged {
            what: "Prandtl-Tomlinson pull by a constant force over duration (sub-step budget)",
            iterations: MAX_SUBSTEPS,
            residual: f64::NAN,
        })?;
        Ok(ForcePull {
            displacement: y[0],
            mean_velocity: if duration > 0.0 { y[0] / duration } else { 0.0 },
            velocity: y[1],
            dissipated: y[2],
        })
    }
}

/// The tip under a constant force: d/dt of (x, ẋ, D).
struct Pulled<'a> {
    model: &'a PrandtlTomlinson,
    force: f64,
}

impl System<3> for Pulled<'_> {
    #[inline]
    fn rate(&self, _t: f64, y: &[f64; 3], dy: &mut [f64; 3]) {
        let m = self.model;
        let f = self.force - m.damping * y[1] + m.lattice_pull(y[0]);
        *dy = [y[1], f / m.mass, m.damping * y[1] * y[1]];
    }
}

/// The model with its support starting at `xs0`, moving at `v_s` (and
/// its cantilever body, unused with one spring).
struct Drive<'a> {
    model: &'a PrandtlTomlinson,
    cantilever: Cantilever,
    xs0: f64,
    v_s: f64,
}

/// One spring: d/dt of (x − x_s, ẋ, D).
impl System<3> for Drive<'_> {
    #[inline]
    fn rate(&self, t: f64, y: &[f64; 3], dy: &mut [f64; 3]) {
        let m = self.model;
        let (rel, v) = (y[0], y[1]);
        let x = self.xs0 + self.v_s * t + rel;
        let f = -m.stiffness * rel - m.damping * v + m.lattice_pull(x);
        *dy = [v - self.v_s, f / m.mass, m.damping * v * v];
    }
}

/// Two springs: d/dt of (x_t − x_s, ẋ_t, D, x_c − x_s, ẋ_c).
impl System<5> for Drive<'_> {
    #[inline]
    fn rate(&self, t: f64, y: &[f64; 5], dy: &mut [f64; 5]) {
        let m = self.model;
        let c = &self.cantilever;
        let (rel, v, rel_c, v_c) = (y[0], y[1], y[3], y[4]);
        let x = self.xs0 + self.v_s * t + rel;
        let tip_spring = m.stiffness * (rel_c - rel);
        let f = tip_spring - m.damping * v + m.lattice_pull(x);
        let f_c = -c.stiffness * rel_c - tip_spring - c.damping * v_c;
        *dy = [
            v - self.v_s,
            f / m.mass,
            m.damping * v * v + c.damping * v_c * v_c,
            v_c - self.v_s,
            f_c / c.mass,
        ];
    }
}

/// The sub-step budget error.
fn budget_error() -> Error {
    Error::NotConverged {
        what: "Prandtl-Tomlinson integration over dt (sub-step budget; split the increment)",
        iterations: MAX_SUBSTEPS,
        residual: f64::NAN,
    }
}

/// One increment (module docs). Regime: 0 when the support does not move,
/// 2 otherwise. The stored energy is the kinetic, spring and lattice energy
/// (one spring: ½k(x − x_s)² + ½mẋ² + U(x) + U₀; two springs:
/// ½k_t(x_t − x_c)² + ½k_c(x_c − x_s)² + ½m_tẋ_t² + ½m_cẋ_c² + U(x_t) + U₀;
/// ≥ 0). dF/dN = 0 (N does not enter the model); dF/dΔs by central
/// differences of the integrated increment (two more integrations; 0 when
/// Δt = 0). Errors: `slip` with a non-zero second component; the sub-step
/// budget [`MAX_SUBSTEPS`] exhausted ([`Error::NotConverged`] naming `dt`,
/// the state untouched).
impl FrictionLaw for PrandtlTomlinson {
    fn state_len(&self) -> usize {
        if self.cantilever.is_some() {
            STATE_MODEL + 5
        } else {
            STATE_MODEL + 3
        }
    }

    fn rate_dependent(&self) -> bool {
        true
    }

    fn check(&self, increment: &FrictionIncrement) -> Result<()> {
        track_only(increment)
    }

    fn advance(
        &self,
        old: Option<&[f64]>,
        state: &mut [f64],
        inc: &FrictionIncrement,
        _work: &mut FrictionWork,
    ) -> Result<FrictionResponse> {
        let ds = inc.slip[0];
        let v_s = if inc.dt > 0.0 { ds / inc.dt } else { 0.0 };
        let xs0 = read(old, state, STATE_SUPPORT);
        let (rel, v) = (
            read(old, state, STATE_TIP),
            read(old, state, STATE_VELOCITY),
        );
        // The end state (x_t − x_s, ẋ_t, D, x_c − x_s, ẋ_c; the last two 0
        // with one spring), the force on the support k(x − x_s) or
        // k_c(x_c − x_s), and dF/dΔs.
        let (y, spring, derivative) = match self.cantilever {
            None => {
                let y0 = [rel, v, 0.0];
                let y = self.solve(y0, xs0, v_s, inc.dt).ok_or_else(budget_error)?;
                let force = |y: [f64; 3]| self.stiffness * y[0];
                let d = self.tangent(inc, |d| self.solve(y0, xs0, d, inc.dt).map(force));
                ([y[0], y[1], y[2], 0.0, 0.0], force(y), d)
            }
            Some(c) => {
                let y0 = [
                    rel,
                    v,
                    0.0,
                    read(old, state, STATE_CANTILEVER),
                    read(old, state, STATE_CANTILEVER_VELOCITY),
                ];
                let y = self.solve(y0, xs0, v_s, inc.dt).ok_or_else(budget_error)?;
                let force = |y: [f64; 5]| c.stiffness * y[3];
                let d = self.tangent(inc, |d| self.solve(y0, xs0, d, inc.dt).map(force));
                (y, force(y), d)
            }
        };
        let dissipated = y[2].max(0.0);
        if let Some(o) = old {
            state.copy_from_slice(o);
        }
        state[STATE_TIP] = y[0];
        state[STATE_VELOCITY] = y[1];
        state[STATE_SUPPORT] = xs0 + ds;
        let x = state[STATE_SUPPORT] + y[0];
        let mut stored = 0.5 * self.mass * y[1] * y[1] + self.lattice(x) + self.amplitude;
        match self.cantilever {
            None => stored += 0.5 * self.stiffness * y[0] * y[0],
            Some(c) => {
                state[STATE_CANTILEVER] = y[3];
                state[STATE_CANTILEVER_VELOCITY] = y[4];
                let tip = y[0] - y[3];
                stored += 0.5 * self.stiffness * tip * tip
                    + 0.5 * c.stiffness * y[3] * y[3]
                    + 0.5 * c.mass * y[4] * y[4];
            }
        }
        book(old, state, dissipated, inc.slip);
        // The force on the support is the spring's pull k(x − x_s); along
        // the motion, resisting it, its negative.
        let mut r = respond([-spring, 0.0], inc.normal_force);
        r.dissipated = dissipated;
        r.stored_energy = stored;
        r.regime = if ds == 0.0 { 0 } else { 2 };
        r.dforce_dslip[0][0] = derivative;
        r.tangents = inc.tangents;
        Ok(r)
    }
}

impl PrandtlTomlinson {
    /// dF/dΔs by central differences of `force_at(support velocity)` when
    /// asked for and Δt > 0; 0 otherwise (or when a perturbed integration
    /// runs out of sub-steps).
    fn tangent(&self, inc: &FrictionIncrement, force_at: impl Fn(f64) -> Option<f64>) -> f64 {
        if inc.tangents & TANGENT_SLIP == 0 || inc.dt <= 0.0 {
            return 0.0;
        }
        let ds = inc.slip[0];
        let h = 1e-6 * (ds.abs() + self.period);
        match (force_at((ds + h) / inc.dt), force_at((ds - h) / inc.dt)) {
            (Some(p), Some(m)) => (p - m) / (2.0 * h),
            _ => 0.0,
        }
    }
}
