//! The Prandtl–Tomlinson model (Prandtl 1928; thesis 5.3.1, (5-5), (5-6)):
//! a point mass in a periodic potential pulled through a spring, the
//! standard model of an AFM tip sliding on a crystal lattice.
//!
//! # Formulas
//!
//! The tip (mass m, position x) sits in the potential
//! U(x) = −U₀ cos(2πx/a) and is pulled by a spring of stiffness k whose far
//! end (the support, the cantilever) is at x_s:
//!
//! $$m\ddot x = k(x_s - x) - \gamma\dot x - \frac{2\pi U_0}{a}\sin\frac{2\pi x}{a}.$$
//!
//! The lateral force on the support is F = k(x − x_s) (opposing its motion
//! when the tip lags). The total potential ½k(x − x_s)² + U(x) has one
//! minimum for every x_s exactly when η = 4π²U₀/(k a²) ≤ 1 (smooth sliding,
//! no hysteresis in the quasi-static limit); for η > 1 the tip sticks and
//! slips (Prandtl 1928; Socoliuc et al. 2004).
//!
//! # Integration
//!
//! Over an increment the support moves at constant velocity V = Δs/Δt and
//! the equation of motion is integrated by the embedded Runge–Kutta pair of
//! Dormand and Prince (1980, order 5(4)) with error control (relative and
//! absolute tolerances, step-size control with a safety factor), carrying
//! the dissipated energy ∫γẋ² dt as a third component, so the work of the
//! support equals the change of kinetic, spring and lattice energy plus the
//! dissipation to the tolerance.
//!
//! # State
//!
//! `[dissipation, slip path, x − x_s, ẋ, x_s]` (J, m, m, m/s, m): the tip
//! relative to the support, its velocity and the support position;
//! all-zero = tip at rest under the support at a potential minimum.
//! One-dimensional: `slip[1]` must be 0. The normal force is reported (μ =
//! |F|/N) but does not enter the model.
//!
//! # References
//!
//! * L. Prandtl, "Ein Gedankenmodell zur kinetischen Theorie der festen
//!   Körper", ZAMM 8 (1928) 85–106.
//! * A. Socoliuc, R. Bennewitz, E. Gnecco, E. Meyer, "Transition from
//!   stick-slip to continuous sliding in atomic friction", Phys. Rev. Lett.
//!   92 (2004) 134301.
//! * J. R. Dormand, P. J. Prince, "A family of embedded Runge–Kutta
//!   formulae", J. Comput. Appl. Math. 6 (1980) 19–26.

use super::{
    book, read, respond, sealed::Advance, DynamicFriction, DynamicIncrement, DynamicResponse,
    STATE_MODEL, TANGENT_SLIP,
};
use crate::error::{check, Error, Result};
use core::f64::consts::PI;

/// Index of x − x_s (m) in a state.
pub const STATE_TIP: usize = STATE_MODEL;
/// Index of the tip velocity ẋ (m/s) in a state.
pub const STATE_VELOCITY: usize = STATE_MODEL + 1;
/// Index of the support position x_s (m) in a state.
pub const STATE_SUPPORT: usize = STATE_MODEL + 2;

/// Sub-steps one increment may take before the integration gives up.
pub const MAX_SUBSTEPS: u32 = 1_000_000;

/// The Prandtl–Tomlinson model's parameters (immutable).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrandtlTomlinson {
    amplitude: f64,
    period: f64,
    stiffness: f64,
    mass: f64,
    damping: f64,
    tolerance: f64,
}

/// The integrated variables: x − x_s, ẋ and the dissipated energy D.
type Y = [f64; 3];

impl PrandtlTomlinson {
    /// Potential amplitude `amplitude` U₀ (J, finite, > 0), period `period`
    /// a (m, > 0), spring stiffness `stiffness` k (N/m, > 0), tip mass
    /// `mass` m (kg, > 0), damping `damping` γ (kg/s, ≥ 0), relative
    /// tolerance of the integration `tolerance` (in [1e-13, 1e-2]). Errors
    /// name the argument.
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
        if !(1e-13..=1e-2).contains(&tolerance) {
            return Err(Error::InvalidArgument {
                name: "tolerance",
                value: tolerance,
                bound: "in [1e-13, 1e-2]",
            });
        }
        Ok(Self {
            amplitude,
            period,
            stiffness,
            mass,
            damping,
            tolerance,
        })
    }

    /// The Tomlinson parameter η = 4π²U₀/(k a²): stick-slip when η > 1.
    pub fn eta(&self) -> f64 {
        4.0 * PI * PI * self.amplitude / (self.stiffness * self.period * self.period)
    }

    /// The largest lateral force the lattice can exert, max U'(x) = 2πU₀/a
    /// (N): the static friction force of the limit η → ∞; for a finite
    /// η > 1 the tip slips before the spring force reaches it.
    pub fn lattice_force(&self) -> f64 {
        2.0 * PI * self.amplitude / self.period
    }

    /// Lattice energy U(x) = −U₀ cos(2πx/a) (J).
    fn lattice(&self, x: f64) -> f64 {
        -self.amplitude * (2.0 * PI * x / self.period).cos()
    }

    /// d/dt of (x − x_s, ẋ, D) with the support at `xs` moving at `v_s`.
    #[inline]
    fn rate(&self, y: &Y, xs: f64, v_s: f64) -> Y {
        let (rel, v) = (y[0], y[1]);
        let x = xs + rel;
        let w = 2.0 * PI / self.period;
        let f = -self.stiffness * rel - self.damping * v - self.amplitude * w * (w * x).sin();
        [v - v_s, f / self.mass, self.damping * v * v]
    }

    /// Integrates over `dt` with the support starting at `xs0` moving at
    /// `v_s`; returns the state or None when the sub-step budget runs out.
    fn integrate(&self, y0: Y, xs0: f64, v_s: f64, dt: f64) -> Option<Y> {
        // Dormand–Prince 5(4) coefficients.
        const C: [f64; 7] = [0.0, 0.2, 0.3, 0.8, 8.0 / 9.0, 1.0, 1.0];
        const A: [[f64; 6]; 7] = [
            [0.0; 6],
            [0.2, 0.0, 0.0, 0.0, 0.0, 0.0],
            [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
            [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
            [
                19372.0 / 6561.0,
                -25360.0 / 2187.0,
                64448.0 / 6561.0,
                -212.0 / 729.0,
                0.0,
                0.0,
            ],
            [
                9017.0 / 3168.0,
                -355.0 / 33.0,
                46732.0 / 5247.0,
                49.0 / 176.0,
                -5103.0 / 18656.0,
                0.0,
            ],
            [
                35.0 / 384.0,
                0.0,
                500.0 / 1113.0,
                125.0 / 192.0,
                -2187.0 / 6784.0,
                11.0 / 84.0,
            ],
        ];
        const E: [f64; 7] = [
            71.0 / 57600.0,
            0.0,
            -71.0 / 16695.0,
            71.0 / 1920.0,
            -17253.0 / 339200.0,
            22.0 / 525.0,
            -1.0 / 40.0,
        ];
        if dt == 0.0 {
            return Some(y0);
        }
        // Scales: the lattice period for positions, the lattice's natural
        // velocity for velocities, U₀ for energy.
        let omega = (self.stiffness / self.mass).sqrt();
        let scale = [self.period, self.period * omega + v_s.abs(), self.amplitude];
        let tol = self.tolerance;
        let (mut t, mut y) = (0.0, y0);
        let mut h = (0.05 / omega).min(dt);
        for _ in 0..MAX_SUBSTEPS {
            if t >= dt {
                return Some(y);
            }
            h = h.min(dt - t);
            let mut k = [[0.0; 3]; 7];
            for s in 0..7 {
                let mut ys = y;
                for (j, kj) in k.iter().enumerate().take(s) {
                    for c in 0..3 {
                        ys[c] += h * A[s][j] * kj[c];
                    }
                }
                k[s] = self.rate(&ys, xs0 + v_s * (t + C[s] * h), v_s);
            }
            let mut y5 = y;
            let mut err = 0.0f64;
            for c in 0..3 {
                let mut e = 0.0;
                for s in 0..7 {
                    if s < 6 {
                        y5[c] += h * A[6][s] * k[s][c];
                    }
                    e += h * E[s] * k[s][c];
                }
                let sc = tol * (scale[c] + y[c].abs().max(y5[c].abs()));
                err = err.max((e / sc).abs());
            }
            if err <= 1.0 {
                t += h;
                y = y5;
            }
            let factor = if err == 0.0 {
                5.0
            } else {
                (0.9 * err.powf(-0.2)).clamp(0.2, 5.0)
            };
            h *= factor;
        }
        None
    }
}

impl DynamicFriction for PrandtlTomlinson {
    fn state_len(&self) -> usize {
        STATE_MODEL + 3
    }
}

/// One increment (module docs). Regime: 0 when the support does not move,
/// 2 otherwise. The stored energy is the kinetic, spring and lattice energy
/// ½k(x − x_s)² + ½mẋ² + U(x) + U₀ (≥ 0). dF/dN = 0 (N does not enter
/// the model); dF/dΔs by central differences of the integrated increment
/// (two more integrations; 0 when Δt = 0). Errors: `slip` with a non-zero
/// second component; the sub-step budget [`MAX_SUBSTEPS`] exhausted
/// ([`Error::NotConverged`], the state untouched).
impl Advance for PrandtlTomlinson {
    fn rate_dependent(&self) -> bool {
        true
    }

    fn check(&self, increment: &DynamicIncrement) -> Result<()> {
        if increment.slip[1] != 0.0 {
            return Err(Error::InvalidArgument {
                name: "slip",
                value: increment.slip[1],
                bound: "slip[1] = 0 (the Prandtl-Tomlinson model is one-dimensional)",
            });
        }
        Ok(())
    }

    fn advance(
        &self,
        old: Option<&[f64]>,
        state: &mut [f64],
        inc: &DynamicIncrement,
    ) -> Result<DynamicResponse> {
        let y0 = [
            read(old, state, STATE_TIP),
            read(old, state, STATE_VELOCITY),
            0.0,
        ];
        let xs0 = read(old, state, STATE_SUPPORT);
        let ds = inc.slip[0];
        let v_s = if inc.dt > 0.0 { ds / inc.dt } else { 0.0 };
        let y = self
            .integrate(y0, xs0, v_s, inc.dt)
            .ok_or(Error::NotConverged {
                what: "Prandtl-Tomlinson integration (sub-step budget)",
                iterations: MAX_SUBSTEPS,
                residual: f64::NAN,
            })?;
        let mut derivative = 0.0;
        if inc.tangents & TANGENT_SLIP != 0 && inc.dt > 0.0 {
            let h = 1e-6 * (ds.abs() + self.period);
            let f = |d: f64| {
                self.integrate(y0, xs0, d / inc.dt, inc.dt)
                    .map(|y| self.stiffness * y[0])
            };
            if let (Some(p), Some(m)) = (f(ds + h), f(ds - h)) {
                derivative = (p - m) / (2.0 * h);
            }
        }
        let dissipated = y[2].max(0.0);
        if let Some(o) = old {
            state.copy_from_slice(o);
        }
        state[STATE_TIP] = y[0];
        state[STATE_VELOCITY] = y[1];
        state[STATE_SUPPORT] = xs0 + ds;
        book(old, state, dissipated, inc.slip);
        // The force on the support is k(x − x_s); along the motion,
        // resisting it, −k(x − x_s).
        let spring = self.stiffness * y[0];
        let mut r = respond([-spring, 0.0], inc.normal_force);
        r.dissipated = dissipated;
        let x = state[STATE_SUPPORT] + y[0];
        r.stored_energy = 0.5 * self.stiffness * y[0] * y[0]
            + 0.5 * self.mass * y[1] * y[1]
            + self.lattice(x)
            + self.amplitude;
        r.regime = if ds == 0.0 { 0 } else { 2 };
        r.dforce_dslip[0][0] = derivative;
        r.tangents = inc.tangents;
        Ok(r)
    }
}
