//! Borodich & Kryukova (1997), thesis §5.3.7: a rigid block of length 2a and
//! mass M, held by a horizontal spring k_x, on a belt moving at speed U; both
//! faces carry a rough layer of linear springs (stiffness ε per unit length)
//! whose profiles f_s (block) and f_b (belt) interpenetrate; the block moves
//! horizontally and vertically.
//!
//! # Formulas (thesis §5.3.7, symbols restored)
//!
//! With x the block's horizontal position (spring unstretched at x = 0), y
//! the distance between the mean lines of the two profiles, ξ ∈ [−a, a] the
//! block's local coordinate and ξ + x − Ut the belt's local coordinate under
//! it, the local elastic interaction and its resultant are
//!
//! $$\Phi(\xi) = \varepsilon\\,\Psi\bigl(f_s(\xi) + f_b(\xi + x - Ut) - y\bigr), \qquad \Psi(s) = \max(s, 0), \qquad F_{el,y} = \int_{-a}^{a}\Phi(\xi)\\,d\xi,$$
//!
//! (profiles measured towards the other body), and the motion is
//!
//! $$M\ddot x = F_{fr,x} - k_x x, \qquad M\ddot y = F_{el,y} - Mg, \qquad F_{fr,x} = \mu\\,F_{el,y}\\,\operatorname{sign}(U - \dot x).$$
//!
//! The thesis (after Borodich & Kryukova) uses sinusoidal profiles, here
//! `f(ξ) = A cos(2πξ/λ)` for each face. Two choices are ours and stated:
//! the sign function is smoothed to `clamp((U − ẋ)/v_s, −1, 1)` with a
//! user-given `v_s` (a discontinuous right-hand side has no classical
//! solution at sticking), and the integral over the block is the midpoint
//! rule on `nodes` equal cells. Time integration: classical Runge–Kutta
//! with a fixed step. As the thesis notes, nothing dissipates energy in the
//! vertical direction: the block bounces on the layer indefinitely.
//!
//! Closed forms (tests): on flat profiles the layer is a spring 2aε, so the
//! block rests at `y* = −Mg/(2aε)`, oscillates vertically at
//! `ω_y = √(2aε/M)`, and, sliding (ẋ < U), `x(t) = x*(1 − cos ω_x t)` with
//! `x* = μMg/k_x`, `ω_x = √(k_x/M)`.
//!
//! # References
//!
//! * Thesis §5.3.7 (Figure 5-9).
//! * F. M. Borodich, S. V. Kryukova (1997), as described in the thesis
//!   (§5.3.7; the paper's equations are the ones restored above, the
//!   bibliography entry is not in the seed text).

use crate::error::{check, Error, Result};

/// A sinusoidal roughness profile `A cos(2πξ/λ)`.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Sinusoid {
    /// Amplitude A (m, finite, ≥ 0).
    pub amplitude: f64,
    /// Wavelength λ (m, > 0).
    pub wavelength: f64,
}

impl Sinusoid {
    #[inline]
    fn at(&self, xi: f64) -> f64 {
        self.amplitude * (core::f64::consts::TAU * xi / self.wavelength).cos()
    }
}

/// Parameters of the Borodich–Kryukova slider.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct BorodichKryukova {
    /// Half-length a of the block (m, > 0).
    pub half_length: f64,
    /// Mass M (kg, > 0).
    pub mass: f64,
    /// Belt speed U (m/s, finite).
    pub belt_speed: f64,
    /// Horizontal spring stiffness k_x (N/m, > 0).
    pub spring_stiffness: f64,
    /// Layer stiffness ε (N/m per m of block length, i.e. N/m², > 0).
    pub layer_stiffness: f64,
    /// Friction coefficient μ (finite, ≥ 0).
    pub friction_coefficient: f64,
    /// Gravity g (m/s², finite, ≥ 0).
    pub gravity: f64,
    /// Smoothing speed v_s of the friction sign (m/s, > 0).
    pub sign_speed: f64,
    /// The block's profile f_s.
    pub slider: Sinusoid,
    /// The belt's profile f_b.
    pub belt: Sinusoid,
    /// Midpoint cells along the block (1..=100000).
    pub nodes: u32,
}

/// The block's state.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct SliderState {
    /// Time t (s).
    pub time: f64,
    /// Horizontal position x (m).
    pub x: f64,
    /// Horizontal velocity ẋ (m/s).
    pub vx: f64,
    /// Mean-line distance y (m).
    pub y: f64,
    /// Vertical velocity ẏ (m/s).
    pub vy: f64,
}

/// One recorded sample of a run.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SliderSample {
    /// The state.
    pub state: SliderState,
    /// Elastic normal force F_el,y (N).
    pub normal_force: f64,
    /// Friction force F_fr,x (N).
    pub friction_force: f64,
}

impl BorodichKryukova {
    /// Validate the parameters (each named in the error).
    pub fn validate(&self) -> Result<()> {
        check::positive("half_length", self.half_length)?;
        check::positive("mass", self.mass)?;
        check::finite("belt_speed", self.belt_speed)?;
        check::positive("spring_stiffness", self.spring_stiffness)?;
        check::positive("layer_stiffness", self.layer_stiffness)?;
        check::non_negative("friction_coefficient", self.friction_coefficient)?;
        check::non_negative("gravity", self.gravity)?;
        check::positive("sign_speed", self.sign_speed)?;
        check::non_negative("slider.amplitude", self.slider.amplitude)?;
        check::positive("slider.wavelength", self.slider.wavelength)?;
        check::non_negative("belt.amplitude", self.belt.amplitude)?;
        check::positive("belt.wavelength", self.belt.wavelength)?;
        if self.nodes == 0 || self.nodes > 100_000 {
            return Err(Error::InvalidArgument {
                name: "nodes",
                value: self.nodes as f64,
                bound: "in 1..=100000",
            });
        }
        Ok(())
    }

    /// The elastic normal force F_el,y (N) at position x, distance y and
    /// time t (midpoint rule over the block).
    pub fn normal_force(&self, x: f64, y: f64, t: f64) -> f64 {
        let n = self.nodes as usize;
        let h = 2.0 * self.half_length / n as f64;
        let shift = x - self.belt_speed * t;
        let mut sum = 0.0;
        for i in 0..n {
            let xi = -self.half_length + (i as f64 + 0.5) * h;
            let s = self.slider.at(xi) + self.belt.at(xi + shift) - y;
            if s > 0.0 {
                sum += s;
            }
        }
        self.layer_stiffness * h * sum
    }

    fn friction(&self, normal: f64, vx: f64) -> f64 {
        let r = ((self.belt_speed - vx) / self.sign_speed).clamp(-1.0, 1.0);
        self.friction_coefficient * normal * r
    }

    /// Time derivative of (x, ẋ, y, ẏ) at time t.
    fn rate(&self, t: f64, s: [f64; 4]) -> [f64; 4] {
        let n = self.normal_force(s[0], s[2], t);
        let fr = self.friction(n, s[1]);
        [
            s[1],
            (fr - self.spring_stiffness * s[0]) / self.mass,
            s[3],
            n / self.mass - self.gravity,
        ]
    }

    /// Integrate from `start` for `steps` steps of `dt` (s, > 0) by
    /// Runge–Kutta 4, recording every `every`-th step (≥ 1) and the start.
    /// Errors: invalid parameters or arguments (named), a non-finite state.
    pub fn run(
        &self,
        start: SliderState,
        dt: f64,
        steps: u32,
        every: u32,
    ) -> Result<Vec<SliderSample>> {
        self.validate()?;
        let dt = check::positive("dt", dt)?;
        for (name, v) in [
            ("start.time", start.time),
            ("start.x", start.x),
            ("start.vx", start.vx),
            ("start.y", start.y),
            ("start.vy", start.vy),
        ] {
            check::finite(name, v)?;
        }
        if every == 0 {
            return Err(Error::InvalidArgument {
                name: "every",
                value: 0.0,
                bound: ">= 1",
            });
        }
        let sample = |t: f64, s: [f64; 4]| {
            let n = self.normal_force(s[0], s[2], t);
            SliderSample {
                state: SliderState {
                    time: t,
                    x: s[0],
                    vx: s[1],
                    y: s[2],
                    vy: s[3],
                },
                normal_force: n,
                friction_force: self.friction(n, s[1]),
            }
        };
        let mut s = [start.x, start.vx, start.y, start.vy];
        let mut t = start.time;
        let mut out = Vec::with_capacity((steps / every) as usize + 1);
        out.push(sample(t, s));
        let add = |a: [f64; 4], k: [f64; 4], h: f64| {
            [
                a[0] + h * k[0],
                a[1] + h * k[1],
                a[2] + h * k[2],
                a[3] + h * k[3],
            ]
        };
        for step in 1..=steps {
            let k1 = self.rate(t, s);
            let k2 = self.rate(t + 0.5 * dt, add(s, k1, 0.5 * dt));
            let k3 = self.rate(t + 0.5 * dt, add(s, k2, 0.5 * dt));
            let k4 = self.rate(t + dt, add(s, k3, dt));
            for i in 0..4 {
                s[i] += dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
            }
            t = start.time + step as f64 * dt;
            if s.iter().any(|v| !v.is_finite()) {
                return Err(Error::NotConverged {
                    what: "Borodich-Kryukova integration (state not finite)",
                    iterations: step,
                    residual: f64::INFINITY,
                });
            }
            if step % every == 0 {
                out.push(sample(t, s));
            }
        }
        Ok(out)
    }
}
