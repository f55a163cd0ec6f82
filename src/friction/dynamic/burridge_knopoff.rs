//! The Burridge–Knopoff block chain (Burridge and Knopoff 1967; thesis
//! 5.4.3, (5-14), where it is the step of Schmittbuhl's hierarchical
//! model) with velocity-weakening friction (Carlson and Langer 1989): M
//! blocks on a substrate, coupled to their neighbours by springs
//! and pulled by leaf springs from a driver plate, the model of an
//! earthquake fault and of a slider's many micro-contacts.
//!
//! # Formulas
//!
//! Block i (mass m, position x_i, velocity v_i = ẋ_i) obeys (5-14)
//!
//! $$m\ddot x_i = k_c(x_{i+1} - 2x_i + x_{i-1}) - k_p(x_i - x_d) - \gamma\dot x_i - R_i,$$
//!
//! with k_c the coupling springs between neighbours, k_p the leaf (pulling)
//! springs from the driver plate at x_d, γ an optional viscous damping
//! against the substrate and R_i the friction of the substrate. The ends
//! are **free**: block 1 has no left neighbour and block M no right one
//! (their coupling term has one spring). Write f_i for the spring force on
//! block i (the first two terms).
//!
//! The friction is **Amontons-scaled**: the normal force N of the increment
//! is shared equally, each block carries N/M, and the friction is
//!
//! * **stuck** (v_i = 0): R_i = f_i, holding the block, as long as
//!   |f_i| ≤ F_s = μ_s N/M (static friction);
//! * **sliding**: R_i = sgn(v_i) F_k(|v_i|),
//!   F_k(v) = μ_k (N/M) / (1 + v/v_c): kinetic friction μ_k ≤ μ_s at the
//!   onset of slip (the drop from the static value) weakening with the
//!   velocity on the scale v_c, the velocity-weakening law of Carlson and
//!   Langer (1989) (v_c = ∞: constant Coulomb kinetic friction).
//!
//! The force on the driver, the response's force, is the pull of the leaf
//! springs, F = Σ k_p (x_i − x_d): it opposes the driver's motion when the
//! blocks lag behind. The elastic and kinetic energy is
//! E = Σ ½k_p(x_i − x_d)² + Σ ½k_c(x_{i+1} − x_i)² + Σ ½m v_i², and the
//! dissipation rate Σ (F_k(|v_i|)|v_i| + γ v_i²) ≥ 0: the driver's work
//! equals ΔE plus the dissipation.
//!
//! # Stick and slip
//!
//! The switching between sticking and sliding is handled by **event
//! location**, not by a regularisation: between events every block keeps
//! its mode (stuck, sliding forward, sliding backward) and the equations
//! are smooth; after each accepted step the event functions are checked —
//! F_s − |f_i| for a stuck block (break-away), s·v_i for a block sliding in
//! the direction s (stop). When one changed sign, the first crossing in the
//! step is located on the continuous extension of the step (Illinois
//! regula falsi), the step is taken again to that instant, and the blocks
//! whose event is due switch: a stopping block is set to rest (v_i = 0;
//! the kinetic energy left, of the order of the tolerance, is booked as
//! dissipation, so no energy is created) and sticks when |f_i| ≤ F_s, or
//! slides on in the direction of f_i; a breaking-away block slides in the
//! direction of f_i. Blocks with identical event values switch together,
//! so a uniform chain stays uniform. A block at rest in a state is stuck
//! when |f_i| ≤ F_s and slides in the direction of f_i otherwise, so an
//! increment from a state is reproducible (cut-backs give the same
//! result). Stops within one step that are undone in the same step (the
//! velocity dips through zero and back) are missed; the error control
//! keeps their size at the tolerance.
//!
//! # Integration
//!
//! Over an increment the driver moves at constant velocity V = Δs/Δt. The
//! equations, in the coordinates x_i − x_d and v_i, are integrated by the
//! Dormand–Prince 5(4) pair with error control (see `dormand_prince`),
//! carrying the dissipated energy as a component. The fixed-size arrays of
//! the integration live on the stack (no allocation), in size classes of
//! 1, 4, 16, 64 and 256 blocks: about 60 KB for chains of 65 to
//! [`MAX_BLOCKS`] blocks, about 16 KB up to 64. An increment may take at most
//! min([`super::prandtl_tomlinson::MAX_SUBSTEPS`], [`MAX_BLOCK_SUBSTEPS`]/M)
//! sub-steps (trial steps and event steps); more is an error naming `dt`
//! (split the increment).
//!
//! # State
//!
//! `[dissipation, slip path, x_1 − x_d, v_1, …, x_M − x_d, v_M, x_d]` (J,
//! m, then m and m/s per block, then m): [`state_block`] gives the index of
//! block i's x_i − x_d (its velocity follows),
//! [`BurridgeKnopoff::state_driver`] that of the driver position.
//! All-zero = every block at rest under the driver, springs relaxed
//! (stuck). One-dimensional: `slip[1]` must be 0.
//!
//! # References
//!
//! * R. Burridge, L. Knopoff, "Model and theoretical seismicity", Bull.
//!   Seismol. Soc. Am. 57 (1967) 341–371.
//! * J. M. Carlson, J. S. Langer, "Mechanical model of an earthquake
//!   fault", Phys. Rev. A 40 (1989) 6470–6484.
//! * J. R. Dormand, P. J. Prince, "A family of embedded Runge–Kutta
//!   formulae", J. Comput. Appl. Math. 6 (1980) 19–26.

use super::dormand_prince::{factor, Stages, System};
use super::prandtl_tomlinson::MAX_SUBSTEPS;
use super::{
    book, read, respond, track_only, FrictionIncrement, FrictionLaw, FrictionResponse,
    FrictionWork, STATE_MODEL, TANGENT_NORMAL, TANGENT_SLIP,
};
use crate::error::{check, Error, Result};

/// The largest chain (blocks).
pub const MAX_BLOCKS: usize = 256;

/// Blocks times sub-steps one increment may take (the sub-step budget of a
/// chain of M blocks is this over M, at most
/// [`super::prandtl_tomlinson::MAX_SUBSTEPS`]).
pub const MAX_BLOCK_SUBSTEPS: u64 = 2_000_000;

/// Index in a state of block `i`'s x_i − x_d (m; i from 0); its velocity
/// v_i (m/s) is at the next index.
pub const fn state_block(i: usize) -> usize {
    STATE_MODEL + 2 * i
}

/// The Burridge–Knopoff chain's parameters (immutable; share between
/// threads).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BurridgeKnopoff {
    blocks: usize,
    mass: f64,
    coupling_stiffness: f64,
    pulling_stiffness: f64,
    mu_static: f64,
    mu_kinetic: f64,
    weakening_velocity: f64,
    damping: f64,
    tolerance: f64,
}

/// A block's mode between events.
const STUCK: i8 = 0;

impl BurridgeKnopoff {
    /// A chain of `blocks` M blocks (1 ..= [`MAX_BLOCKS`]) of mass `mass` m
    /// (kg, > 0) each, coupled by `coupling_stiffness` k_c (N/m, finite,
    /// ≥ 0; 0: independent blocks), pulled by `pulling_stiffness` k_p
    /// (N/m, > 0) each, with static and kinetic coefficients `mu_static`
    /// μ_s (finite, ≥ 0) and `mu_kinetic` μ_k (in [0, μ_s]), weakening
    /// velocity `weakening_velocity` v_c (m/s, > 0, +∞ for constant kinetic
    /// friction), viscous damping `damping` γ (kg/s per block, finite,
    /// ≥ 0) and relative tolerance `tolerance` of the integration (in
    /// [1e-13, 1e-2]). Errors name the argument.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        blocks: usize,
        mass: f64,
        coupling_stiffness: f64,
        pulling_stiffness: f64,
        mu_static: f64,
        mu_kinetic: f64,
        weakening_velocity: f64,
        damping: f64,
        tolerance: f64,
    ) -> Result<Self> {
        if !(1..=MAX_BLOCKS).contains(&blocks) {
            return Err(Error::InvalidArgument {
                name: "blocks",
                value: blocks as f64,
                bound: "in [1, 256]",
            });
        }
        check::positive("mass", mass)?;
        check::non_negative("coupling_stiffness", coupling_stiffness)?;
        check::positive("pulling_stiffness", pulling_stiffness)?;
        check::non_negative("mu_static", mu_static)?;
        check::non_negative("mu_kinetic", mu_kinetic)?;
        if mu_kinetic > mu_static {
            return Err(Error::InvalidArgument {
                name: "mu_kinetic",
                value: mu_kinetic,
                bound: "<= mu_static",
            });
        }
        if weakening_velocity.is_nan() || weakening_velocity <= 0.0 {
            return Err(Error::InvalidArgument {
                name: "weakening_velocity",
                value: weakening_velocity,
                bound: "> 0 (+infinity: no weakening)",
            });
        }
        check::non_negative("damping", damping)?;
        if !(1e-13..=1e-2).contains(&tolerance) {
            return Err(Error::InvalidArgument {
                name: "tolerance",
                value: tolerance,
                bound: "in [1e-13, 1e-2]",
            });
        }
        Ok(Self {
            blocks,
            mass,
            coupling_stiffness,
            pulling_stiffness,
            mu_static,
            mu_kinetic,
            weakening_velocity,
            damping,
            tolerance,
        })
    }

    /// The number of blocks M.
    pub fn blocks(&self) -> usize {
        self.blocks
    }

    /// Index in a state of the driver position x_d (m).
    pub fn state_driver(&self) -> usize {
        state_block(self.blocks)
    }

    /// The kinetic friction of one block at slip speed `speed` (m/s ≥ 0)
    /// under the normal force `normal_force` (N, the chain's): μ_k (N/M) /
    /// (1 + v/v_c) (N).
    pub fn kinetic_force(&self, normal_force: f64, speed: f64) -> f64 {
        self.mu_kinetic * normal_force
            / self.blocks as f64
            / (1.0 + speed / self.weakening_velocity)
    }

    /// The static friction of one block under the chain's normal force
    /// `normal_force` (N): μ_s N/M (N).
    pub fn static_force(&self, normal_force: f64) -> f64 {
        self.mu_static * normal_force / self.blocks as f64
    }

    /// The period (s) of the stick-slip cycle of a uniform chain (every
    /// block alike, which moves as one block) with constant kinetic
    /// friction (v_c = ∞, γ = 0) driven at `velocity` V (m/s, > 0) under
    /// `normal_force` N: the stick time 2(F_s − F_k)/(k_p V) plus the slip
    /// time 2(π − atan2((F_s − F_k)ω, k_p V))/ω, ω = √(k_p/m), which tends
    /// to π/ω for small V. (During a slip the excess spring force
    /// u = k_p(x_d − x) − F_k obeys ü = −ω²u from u = F_s − F_k, u̇ = k_p V,
    /// and the block stops when u̇ = k_p V again, at u = −(F_s − F_k).)
    pub fn uniform_period(&self, normal_force: f64, velocity: f64) -> f64 {
        let n = normal_force / self.blocks as f64;
        let excess = (self.mu_static - self.mu_kinetic) * n;
        let k = self.pulling_stiffness;
        let w = (k / self.mass).sqrt();
        2.0 * excess / (k * velocity)
            + 2.0 * (core::f64::consts::PI - (excess * w).atan2(k * velocity)) / w
    }

    /// The elastic and kinetic energy of a state (J).
    fn stored(&self, y: &[f64]) -> f64 {
        let (kp, kc) = (self.pulling_stiffness, self.coupling_stiffness);
        let mut e = 0.0;
        for i in 0..self.blocks {
            let (rel, v) = (y[1 + 2 * i], y[2 + 2 * i]);
            e += 0.5 * kp * rel * rel + 0.5 * self.mass * v * v;
            if i + 1 < self.blocks {
                let d = y[3 + 2 * i] - rel;
                e += 0.5 * kc * d * d;
            }
        }
        e
    }

    /// Integrates one increment in the size class `B` blocks (`N` = 2B + 1
    /// components) from the blocks `y0` (components 1..2M+1) under the
    /// normal force `normal` with driver slip `ds` over `dt`: the end
    /// (dissipation in component 0) and the number of blocks that slid.
    fn integrate<const B: usize, const N: usize>(
        &self,
        y0: &[f64; N],
        normal: f64,
        ds: f64,
        dt: f64,
    ) -> Result<([f64; N], usize)> {
        let m = self.blocks;
        let n = 2 * m + 1;
        let velocity = if dt > 0.0 { ds / dt } else { 0.0 };
        let mut chain = Chain::<B> {
            model: self,
            modes: [STUCK; B],
            static_force: self.static_force(normal),
            kinetic: self.mu_kinetic * normal / m as f64,
            velocity,
        };
        let mut y = *y0;
        y[0] = 0.0;
        if dt == 0.0 {
            return Ok((y, 0));
        }
        for i in 0..m {
            chain.modes[i] = chain.mode_at_rest(&y, i);
        }
        let mut slid = [false; B];
        // Scales: a length (the static reach F_s/k_p, the slip, the largest
        // deflection and velocity over the fastest frequency), the velocity
        // of that length at that frequency, the chain's energy of it.
        let omega = ((self.pulling_stiffness + 4.0 * self.coupling_stiffness) / self.mass).sqrt();
        let mut deflection = 0.0f64;
        for i in 0..m {
            deflection = deflection.max(y[1 + 2 * i].abs() + y[2 + 2 * i].abs() / omega);
        }
        let length = chain.static_force / self.pulling_stiffness + ds.abs() + deflection;
        if length == 0.0 || !length.is_finite() {
            // Nothing deflected, nothing moves, no friction to load.
            return Ok((y, 0));
        }
        let speed = length * omega + velocity.abs();
        let mut scale = [0.0; N];
        scale[0] = m as f64 * self.pulling_stiffness * length * length;
        for i in 0..m {
            scale[1 + 2 * i] = length;
            scale[2 + 2 * i] = speed;
        }
        let budget = (MAX_BLOCK_SUBSTEPS / m as u64).min(MAX_SUBSTEPS as u64);

        let mut stages = Stages::<N>::new();
        let mut next = y;
        let (mut t, mut h) = (0.0, (0.05 / omega).min(dt));
        let mut steps = 0u64;
        chain.rate(0.0, &y, &mut stages.k[0]);
        for (i, s) in slid.iter_mut().enumerate().take(m) {
            *s = chain.modes[i] != STUCK;
        }
        while t < dt {
            if steps >= budget {
                return Err(Error::NotConverged {
                    what: "Burridge-Knopoff integration over dt (sub-step budget; split the increment)",
                    iterations: budget.min(u32::MAX as u64) as u32,
                    residual: f64::NAN,
                });
            }
            steps += 1;
            h = h.min(dt - t);
            let tol = self.tolerance;
            let err = stages.attempt(&chain, t, &y, h, n, tol, &scale, &mut next);
            if err.is_nan() || err > 1.0 {
                h *= if err.is_nan() { 0.2 } else { factor(err) };
                continue;
            }
            // The first event in the step, if any: (θ, block).
            let mut first: Option<(f64, usize)> = None;
            for i in 0..m {
                if chain.event(&next, i) < 0.0 {
                    let theta = chain.crossing(&stages, &y, &next, h, i);
                    match first {
                        Some((th, _)) if th <= theta => {}
                        _ => first = Some((theta, i)),
                    }
                }
            }
            let Some((theta, j)) = first else {
                t += h;
                y[..n].copy_from_slice(&next[..n]);
                let (first, last) = stages.k.split_at_mut(6);
                first[0][..n].copy_from_slice(&last[0][..n]);
                h *= factor(err);
                continue;
            };
            let hs = theta * h;
            if hs > 0.0 {
                steps += 1;
                let e = stages.attempt(&chain, t, &y, hs, n, tol, &scale, &mut next);
                if e.is_nan() || e > 1.0 {
                    h = hs * if e.is_nan() { 0.2 } else { factor(e) };
                    continue;
                }
                t += hs;
                y[..n].copy_from_slice(&next[..n]);
            }
            chain.switch(&mut y, j, &mut slid);
            chain.rate(t, &y, &mut stages.k[0]);
        }
        Ok((y, slid.iter().take(m).filter(|&&s| s).count()))
    }

    /// One increment in the size class `B` (module docs).
    fn advance_in<const B: usize, const N: usize>(
        &self,
        old: Option<&[f64]>,
        state: &mut [f64],
        inc: &FrictionIncrement,
    ) -> Result<FrictionResponse> {
        let m = self.blocks;
        let mut y0 = [0.0; N];
        for (c, v) in y0.iter_mut().enumerate().take(2 * m + 1).skip(1) {
            *v = read(old, state, STATE_MODEL + c - 1);
        }
        let driver = read(old, state, self.state_driver());
        let (normal, ds, dt) = (inc.normal_force, inc.slip[0], inc.dt);
        let (y, slid) = self.integrate::<B, N>(&y0, normal, ds, dt)?;
        let pull = |y: &[f64; N]| {
            let mut f = 0.0;
            for i in 0..m {
                f += y[1 + 2 * i];
            }
            self.pulling_stiffness * f
        };
        let force = pull(&y);
        // Tangents by differences of whole increments (not smooth across
        // stick-slip events); 0 when a perturbed increment fails.
        let mut reach = 0.0f64;
        for i in 0..m {
            reach = reach.max(y0[1 + 2 * i].abs());
        }
        reach += self.static_force(normal) / self.pulling_stiffness;
        let mut dslip = 0.0;
        if inc.tangents & TANGENT_SLIP != 0 && dt > 0.0 {
            let h = 1e-6 * (ds.abs() + reach);
            if h > 0.0 {
                if let (Ok((p, _)), Ok((q, _))) = (
                    self.integrate::<B, N>(&y0, normal, ds + h, dt),
                    self.integrate::<B, N>(&y0, normal, ds - h, dt),
                ) {
                    dslip = (pull(&p) - pull(&q)) / (2.0 * h);
                }
            }
        }
        let mut dnormal = 0.0;
        if inc.tangents & TANGENT_NORMAL != 0 {
            if normal > 0.0 {
                let h = 1e-6 * normal;
                if let (Ok((p, _)), Ok((q, _))) = (
                    self.integrate::<B, N>(&y0, normal + h, ds, dt),
                    self.integrate::<B, N>(&y0, normal - h, ds, dt),
                ) {
                    dnormal = (pull(&p) - pull(&q)) / (2.0 * h);
                }
            } else {
                // One-sided at N = 0, on the scale of the springs' force.
                let h = 1e-6 * self.pulling_stiffness * (ds.abs() + reach) * m as f64;
                if h > 0.0 {
                    if let Ok((p, _)) = self.integrate::<B, N>(&y0, h, ds, dt) {
                        dnormal = (pull(&p) - force) / h;
                    }
                }
            }
        }
        let dissipated = y[0].max(0.0);
        if let Some(o) = old {
            state.copy_from_slice(o);
        }
        state[STATE_MODEL..STATE_MODEL + 2 * m].copy_from_slice(&y[1..2 * m + 1]);
        let d = self.state_driver();
        state[d] = driver + ds;
        book(old, state, dissipated, inc.slip);
        // The force on the driver is the leaf springs' pull; along the
        // motion, resisting it, its negative.
        let mut r = respond([-force, 0.0], normal);
        r.dissipated = dissipated;
        r.stored_energy = self.stored(&y);
        r.regime = match slid {
            0 => 0,
            s if s == m => 2,
            _ => 1,
        };
        r.dforce_dnormal[0] = dnormal;
        r.dforce_dslip[0][0] = dslip;
        r.tangents = inc.tangents;
        Ok(r)
    }
}

/// The chain over one increment: the model, the blocks' modes (0 stuck,
/// ±1 sliding forward or backward) and the loads.
struct Chain<'a, const B: usize> {
    model: &'a BurridgeKnopoff,
    modes: [i8; B],
    /// F_s = μ_s N/M (N).
    static_force: f64,
    /// μ_k N/M (N).
    kinetic: f64,
    /// The driver's velocity V (m/s).
    velocity: f64,
}

impl<const B: usize> Chain<'_, B> {
    /// The spring force f_i on block `i` of the positions `y`.
    #[inline]
    fn spring(&self, y: &[f64], i: usize) -> f64 {
        let m = self.model;
        let rel = y[1 + 2 * i];
        let mut coupling = 0.0;
        if i > 0 {
            coupling += y[2 * i - 1] - rel;
        }
        if i + 1 < m.blocks {
            coupling += y[3 + 2 * i] - rel;
        }
        m.coupling_stiffness * coupling - m.pulling_stiffness * rel
    }

    /// The mode of block `i` at rest in `y` (or moving: the sign of v).
    fn mode_at_rest(&self, y: &[f64], i: usize) -> i8 {
        let v = y[2 + 2 * i];
        if v != 0.0 {
            return if v > 0.0 { 1 } else { -1 };
        }
        let f = self.spring(y, i);
        if f.abs() <= self.static_force {
            STUCK
        } else if f > 0.0 {
            1
        } else {
            -1
        }
    }

    /// The event function of block `i` in its mode at `y` (< 0: due).
    #[inline]
    fn event(&self, y: &[f64], i: usize) -> f64 {
        match self.modes[i] {
            STUCK => self.static_force - self.spring(y, i).abs(),
            s => f64::from(s) * y[2 + 2 * i],
        }
    }

    /// The first θ ∈ (0, 1] at which block `i`'s event function, ≥ 0 at
    /// `y` and < 0 at `next`, crosses zero on the step's continuous
    /// extension (Illinois regula falsi).
    fn crossing<const N: usize>(
        &self,
        stages: &Stages<N>,
        y: &[f64; N],
        next: &[f64; N],
        h: f64,
        i: usize,
    ) -> f64 {
        let m = self.model.blocks;
        let sign = self.spring(next, i).signum();
        let g = |theta: f64| -> f64 {
            let at = |c: usize| stages.dense(y, next, h, theta, c);
            match self.modes[i] {
                STUCK => {
                    let mp = self.model;
                    let rel = at(1 + 2 * i);
                    let mut coupling = 0.0;
                    if i > 0 {
                        coupling += at(2 * i - 1) - rel;
                    }
                    if i + 1 < m {
                        coupling += at(3 + 2 * i) - rel;
                    }
                    let f = mp.coupling_stiffness * coupling - mp.pulling_stiffness * rel;
                    self.static_force - sign * f
                }
                s => f64::from(s) * at(2 + 2 * i),
            }
        };
        let (mut a, mut b) = (0.0f64, 1.0f64);
        let (mut ga, mut gb) = (g(0.0).max(0.0), self.event(next, i));
        let mut side = 0i8;
        for _ in 0..60 {
            if b - a <= 1e-13 {
                break;
            }
            let mut th = (a * gb - b * ga) / (gb - ga);
            if !(th > a && th < b) {
                th = 0.5 * (a + b);
            }
            let gt = g(th);
            if gt >= 0.0 {
                a = th;
                ga = gt;
                if side == 1 {
                    gb *= 0.5;
                }
                side = 1;
            } else {
                b = th;
                gb = gt;
                if side == -1 {
                    ga *= 0.5;
                }
                side = -1;
            }
            if ga == 0.0 {
                return a;
            }
        }
        b
    }

    /// Switches the modes at an event of block `j` (module docs): block `j`,
    /// every block whose event is past, and every block of the same kind
    /// (stuck, sliding) whose event value is no larger than `j`'s.
    fn switch(&mut self, y: &mut [f64], j: usize, slid: &mut [bool; B]) {
        let m = self.model.blocks;
        let gj = self.event(y, j);
        let stuck_j = self.modes[j] == STUCK;
        let mut due = [false; B];
        for (i, d) in due.iter_mut().enumerate().take(m) {
            let g = self.event(y, i);
            *d = i == j || g < 0.0 || ((self.modes[i] == STUCK) == stuck_j && g <= gj);
        }
        for i in 0..m {
            if !due[i] {
                continue;
            }
            if self.modes[i] == STUCK {
                // Break-away: slide along the spring force.
                self.modes[i] = if self.spring(y, i) >= 0.0 { 1 } else { -1 };
                slid[i] = true;
            } else {
                // Stop: the kinetic energy left is dissipated.
                let v = y[2 + 2 * i];
                y[0] += 0.5 * self.model.mass * v * v;
                y[2 + 2 * i] = 0.0;
                self.modes[i] = self.mode_at_rest(y, i);
            }
        }
    }
}

/// d/dt of (D, x_i − x_d, v_i …) in the current modes.
impl<const B: usize, const N: usize> System<N> for Chain<'_, B> {
    #[inline]
    fn rate(&self, _t: f64, y: &[f64; N], dy: &mut [f64; N]) {
        let model = self.model;
        let (mass, gamma, vc) = (model.mass, model.damping, model.weakening_velocity);
        let mut power = 0.0;
        for i in 0..model.blocks {
            let v = y[2 + 2 * i];
            dy[1 + 2 * i] = v - self.velocity;
            match self.modes[i] {
                STUCK => dy[2 + 2 * i] = 0.0,
                s => {
                    let friction = f64::from(s) * self.kinetic / (1.0 + v.abs() / vc);
                    dy[2 + 2 * i] = (self.spring(y, i) - friction - gamma * v) / mass;
                    power += friction * v + gamma * v * v;
                }
            }
        }
        dy[0] = power;
    }
}

/// One increment (module docs). Regime: 0 when no block slid during the
/// increment, 2 when every block did, 1 when some did. The stored energy is
/// the springs' and the blocks' kinetic energy. dF/dN and dF/dΔs by central
/// differences of the integrated increment (two more integrations each;
/// one-sided dF/dN at N = 0; not smooth across stick-slip events). Errors:
/// `slip` with a non-zero second component; the sub-step budget exhausted
/// ([`Error::NotConverged`] naming `dt`; the state untouched).
impl FrictionLaw for BurridgeKnopoff {
    fn state_len(&self) -> usize {
        STATE_MODEL + 2 * self.blocks + 1
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
        // Size classes of the fixed-size integration arrays.
        match self.blocks {
            1 => self.advance_in::<1, 3>(old, state, inc),
            2..=4 => self.advance_in::<4, 9>(old, state, inc),
            5..=16 => self.advance_in::<16, 33>(old, state, inc),
            17..=64 => self.advance_in::<64, 129>(old, state, inc),
            _ => self.advance_in::<MAX_BLOCKS, { 2 * MAX_BLOCKS + 1 }>(old, state, inc),
        }
    }
}
