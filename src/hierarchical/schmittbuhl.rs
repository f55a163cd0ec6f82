//! Schmittbuhl's hierarchical model (Schmittbuhl, Vilotte and Roux 1996;
//! thesis 5.4.3): the friction law of a slider renormalised generation by
//! generation, each step a Burridge–Knopoff chain (thesis (5-14),
//! [`crate::friction::dynamic::burridge_knopoff`]).
//!
//! # Hierarchy
//!
//! The slider is discretised in rigid blocks, finest at the interface and
//! coarser away from it: the element size grows in a geometric series,
//! L_g = Nᵍ L₀, each block of generation g resting on N blocks of
//! generation g − 1 (the thesis's sketch has N = 3 descendants, a
//! Cantor–Borodich profile of blocks and springs, Figure 5-19). Blocks of a
//! generation are coupled by horizontal springs k_c, each block to its
//! parent by a vertical spring k_p, and "all the physical parameters
//! describing the elastic interaction are rescaled accordingly" (thesis).
//! Here the rescaling is that of an elastic continuum of dimension d
//! (modulus E, density ρ, wave speed √(E/ρ) independent of the size): a
//! block of size L has stiffness ∝ E L^{d−2} and mass ∝ ρ L^d, so
//!
//! $$k_{c,g} = k_{c,0} N^{g(d-2)},\quad k_{p,g} = k_{p,0} N^{g(d-2)},\quad
//!   m_g = m_0 N^{g d},\quad n_g = n_0 N^{g},$$
//!
//! with d = 3 by default (springs ∝ size, the elastic cube of side L has
//! stiffness E L) or d = 2 (plane/antiplane strain per unit thickness:
//! springs independent of the size, the setting of Schmittbuhl et al.'s
//! scalar elastic medium). The normal force n_g of a block is the sum of
//! its N children's (the interface under a parent carries the parent's
//! load). The weakening velocity v_c of the law is kept from generation to
//! generation: velocities in an elastic medium do not scale with the size
//! (the wave speed is size-independent), and the thesis does not give the
//! functional form the paper fits to its renormalised law; the flow is in
//! the coefficients μ_s, μ_k.
//!
//! # Renormalisation
//!
//! Generation 0 carries the imposed law: static coefficient μ_s⁰, kinetic
//! coefficient μ_k⁰ ≤ μ_s⁰ at the onset of slip, weakening as
//! F_k(v) = μ_k n/(1 + v/v_c) (Carlson and Langer 1989, as the
//! Burridge–Knopoff module takes it). For g = 1, 2, …, G, the N blocks of
//! generation g − 1 under one block of generation g form a
//! Burridge–Knopoff chain (free ends, law of generation g − 1, normal force
//! N n_{g−1} = n_g shared equally) whose driver is the parent, moved at the
//! plate velocity V (the parent's own motion is not fed back: the
//! recursive reduction of each step to a Burridge–Knopoff problem, as the
//! thesis describes it). The chain starts at rest with a pre-stress
//! x_i − x_d = −δ r_i F_s/k_p (disorder δ ∈ [0, 1), r_i = frac(iφ) with
//! φ the golden ratio's fraction, a fixed low-discrepancy pattern; δ = 0:
//! identical blocks, which then move as one) and is pulled over
//! [`TRAVEL`] static reaches F_s/k_p in [`SAMPLES_PER_REACH`] increments
//! per reach. From the force history F_j on the driver (the force resisting
//! the motion) and the driver's slip increments the slip events are found by
//! [`stick_slip`](crate::friction::dynamic::stick_slip()) (drops of at
//! least [`MIN_DROP`] times the chain's static capacity N F_s):
//!
//! * the **static friction** of generation g is the mean peak force of the
//!   events, the force at which the chain breaks loose (the run's largest
//!   force when there is none: steady sliding), μ_s^g = F_s / n_g. (The
//!   peak before the first event alone is not used: with a pre-stress the
//!   first event is one block's, breaking loose under a partly loaded
//!   chain, and its peak can lie below the kinetic friction.)
//! * the **kinetic friction** is the friction work per unit slip of the
//!   blocks, F_k = D/s̄, with D the chain's dissipation (the friction work
//!   the Burridge–Knopoff response books) and s̄ the blocks' mean slip
//!   (the driver's plus the change of the mean lag Σ(x_i − x_d)/N) over a
//!   window from the first event's peak to the last one's (to the end of
//!   the run with one event, the second half of the run with none: steady
//!   sliding); μ_k^g = F_k / n_g, taken no larger than μ_s^g (they differ
//!   by the quasi-static error when the law is Coulomb's).
//!
//! The friction work per unit slip is the slip-weighted mean of the
//! blocks' friction:
//! with Coulomb friction μ_s = μ_k (v_c = ∞) the law is a fixed point
//! (every sliding block resists with μ_s n, the chain with μ_s N n), up to
//! the quasi-static error V√(k_p m)/F_s of the inertial overshoot; with
//! velocity weakening μ_k^g ≤ μ_k^{g−1} (F_k(v) ≤ μ_k n), and with
//! stuck blocks at most at their threshold the peak is at most N F_s, so
//! μ_s^g ≤ μ_s^{g−1} up to the same quasi-static error.
//!
//! # Flow of the law
//!
//! With the default blocks (N = 3, d = 3, μ_s⁰ = 0.5, μ_k⁰ = 0.3):
//! identical blocks (δ = 0) with Coulomb kinetic friction keep the law,
//! μ_s = 0.4999, 0.4990, 0.4986 and μ_k = 0.3000 at generations 1–3 (each
//! peak sampled up to F_s/400 low); with the pre-stress δ = 0.5 the static
//! friction falls to the kinetic one, μ_k/μ_s = 0.60, 0.85, 0.96, 0.997,
//! 0.9995 at generations 0–4: the static/kinetic distinction is lost as
//! the scale grows. With velocity weakening (v_c = 0.05 m/s against slip
//! velocities ≈ (F_s − F_k)/√(k_p m) ≈ 1 m/s) the kinetic coefficient
//! drops at the first generation (0.30 → 0.005 for identical blocks) and
//! both fall further with δ = 0.5. Because v_c is kept, each generation
//! weakens its already-averaged kinetic coefficient again: the flow of a
//! strongly weakening law goes to vanishing kinetic friction; a fit of
//! the renormalised law's velocity dependence (the paper's approach) is
//! not reproduced.
//!
//! # References
//!
//! * J. Schmittbuhl, J.-P. Vilotte, S. Roux, "Velocity weakening friction:
//!   a renormalization approach", J. Geophys. Res. 101(B12) (1996)
//!   27741–27764.
//! * R. Burridge, L. Knopoff, "Model and theoretical seismicity", Bull.
//!   Seismol. Soc. Am. 57 (1967) 341–371.
//! * J. M. Carlson, J. S. Langer, "Mechanical model of an earthquake
//!   fault", Phys. Rev. A 40 (1989) 6470–6484.

use crate::error::{check, Error, Result};
use crate::friction::dynamic::burridge_knopoff::{state_block, BurridgeKnopoff};
use crate::friction::dynamic::stick_slip;
use crate::friction::law::{FrictionIncrement, FrictionLaw};

/// The driver's travel of a chain run, in static reaches F_s/k_p.
pub const TRAVEL: f64 = 8.0;

/// Increments of a chain run per static reach.
pub const SAMPLES_PER_REACH: f64 = 400.0;

/// A slip event drops at least this fraction of the chain's static
/// capacity N F_s.
pub const MIN_DROP: f64 = 1e-3;

/// The most generations.
pub const MAX_GENERATIONS: usize = 12;

/// The largest ratio N (blocks per chain).
pub const MAX_RATIO: usize = 64;

/// Relative tolerance of the chain integrations.
const TOLERANCE: f64 = 1e-9;

/// Schmittbuhl's hierarchical model (module docs). SI units; the fields
/// are checked by [`Schmittbuhl::run`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Schmittbuhl {
    /// Static coefficient μ_s⁰ of a generation-0 block, finite, ≥ 0.
    pub mu_static: f64,
    /// Kinetic coefficient μ_k⁰ at the onset of slip, in [0, μ_s⁰].
    pub mu_kinetic: f64,
    /// Weakening velocity v_c (m/s), > 0; +∞: constant kinetic friction.
    pub weakening_velocity: f64,
    /// Ratio N of sizes between generations (blocks per chain), in
    /// [2, [`MAX_RATIO`]]; the thesis's 3.
    pub ratio: usize,
    /// Generations G renormalised above generation 0, in
    /// [1, [`MAX_GENERATIONS`]].
    pub generations: usize,
    /// Dimension d of the elastic continuum, 2 or 3 (module docs).
    pub dimension: u32,
    /// Mass m₀ of a generation-0 block (kg), > 0.
    pub mass: f64,
    /// Horizontal (coupling) spring k_c,0 between generation-0 blocks
    /// (N/m), finite, ≥ 0.
    pub coupling_stiffness: f64,
    /// Vertical spring k_p,0 from a generation-0 block to its parent (N/m),
    /// > 0.
    pub pulling_stiffness: f64,
    /// Normal force n₀ on a generation-0 block (N), > 0.
    pub normal_force: f64,
    /// Plate velocity V (m/s), > 0.
    pub velocity: f64,
    /// Pre-stress disorder δ of a chain, in [0, 1) (module docs).
    pub disorder: f64,
}

impl Default for Schmittbuhl {
    /// μ_s = 0.5, μ_k = 0.3, v_c = 0.05 m/s, N = 3, G = 3, d = 3, blocks of
    /// 10 mg on 1000 N/m springs (coupling and pulling), n₀ = 1 N,
    /// V = 1e-4 m/s (quasi-static: V√(k_p m)/F_s = 2e-5), δ = 0.5.
    fn default() -> Self {
        Self {
            mu_static: 0.5,
            mu_kinetic: 0.3,
            weakening_velocity: 0.05,
            ratio: 3,
            generations: 3,
            dimension: 3,
            mass: 1e-5,
            coupling_stiffness: 1e3,
            pulling_stiffness: 1e3,
            normal_force: 1.0,
            velocity: 1e-4,
            disorder: 0.5,
        }
    }
}

/// The friction law of one generation and its blocks.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Generation {
    /// The generation g (0: the imposed law).
    pub index: usize,
    /// Block size relative to generation 0, Nᵍ.
    pub size: f64,
    /// Block mass m_g (kg).
    pub mass: f64,
    /// Horizontal spring k_c,g (N/m).
    pub coupling_stiffness: f64,
    /// Vertical spring k_p,g (N/m).
    pub pulling_stiffness: f64,
    /// Normal force n_g on a block (N).
    pub normal_force: f64,
    /// Static coefficient μ_s^g.
    pub mu_static: f64,
    /// Kinetic coefficient μ_k^g (at the onset of slip).
    pub mu_kinetic: f64,
    /// Weakening velocity v_c (m/s), the same at every generation.
    pub weakening_velocity: f64,
    /// μ_k^g / μ_s^g (1 when μ_s^g = 0).
    pub ratio: f64,
    /// Slip events of the chain run that gave this law (0 at g = 0).
    pub events: usize,
}

impl Schmittbuhl {
    /// Checks the fields; errors name the field and its bound.
    pub fn validate(&self) -> Result<()> {
        check::non_negative("mu_static", self.mu_static)?;
        check::non_negative("mu_kinetic", self.mu_kinetic)?;
        if self.mu_kinetic > self.mu_static {
            return Err(Error::InvalidArgument {
                name: "mu_kinetic",
                value: self.mu_kinetic,
                bound: "<= mu_static",
            });
        }
        if self.weakening_velocity.is_nan() || self.weakening_velocity <= 0.0 {
            return Err(Error::InvalidArgument {
                name: "weakening_velocity",
                value: self.weakening_velocity,
                bound: "> 0 (+infinity: no weakening)",
            });
        }
        if !(2..=MAX_RATIO).contains(&self.ratio) {
            return Err(Error::InvalidArgument {
                name: "ratio",
                value: self.ratio as f64,
                bound: "in [2, 64]",
            });
        }
        if !(1..=MAX_GENERATIONS).contains(&self.generations) {
            return Err(Error::InvalidArgument {
                name: "generations",
                value: self.generations as f64,
                bound: "in [1, 12]",
            });
        }
        if !(2..=3).contains(&self.dimension) {
            return Err(Error::InvalidArgument {
                name: "dimension",
                value: f64::from(self.dimension),
                bound: "2 or 3",
            });
        }
        check::positive("mass", self.mass)?;
        check::non_negative("coupling_stiffness", self.coupling_stiffness)?;
        check::positive("pulling_stiffness", self.pulling_stiffness)?;
        check::positive("normal_force", self.normal_force)?;
        check::positive("velocity", self.velocity)?;
        if !(0.0..1.0).contains(&self.disorder) {
            return Err(Error::InvalidArgument {
                name: "disorder",
                value: self.disorder,
                bound: "in [0, 1)",
            });
        }
        Ok(())
    }

    /// The blocks of generation `g` with the law `mu` (μ_s, μ_k).
    fn generation(&self, g: usize, mu: (f64, f64), events: usize) -> Generation {
        let n = self.ratio as f64;
        let size = n.powi(g as i32);
        let spring = size.powi(self.dimension as i32 - 2);
        Generation {
            index: g,
            size,
            mass: self.mass * size.powi(self.dimension as i32),
            coupling_stiffness: self.coupling_stiffness * spring,
            pulling_stiffness: self.pulling_stiffness * spring,
            normal_force: self.normal_force * size,
            mu_static: mu.0,
            mu_kinetic: mu.1,
            weakening_velocity: self.weakening_velocity,
            ratio: if mu.0 > 0.0 { mu.1 / mu.0 } else { 1.0 },
            events,
        }
    }

    /// The renormalisation (module docs): the law of generations 0 (the
    /// imposed one) to G. Errors: a field out of range (named); a chain
    /// integration that fails ([`Error::NotConverged`]).
    pub fn run(&self) -> Result<Vec<Generation>> {
        self.validate()?;
        let mut out = Vec::with_capacity(self.generations + 1);
        out.push(self.generation(0, (self.mu_static, self.mu_kinetic), 0));
        for g in 1..=self.generations {
            let child = out[g - 1];
            let (mu, events) = self.renormalise(&child)?;
            out.push(self.generation(g, mu, events));
        }
        Ok(out)
    }

    /// One step: the chain of N blocks of `child`'s generation and the
    /// law (μ_s, μ_k) of their parent, with the chain's slip events.
    fn renormalise(&self, child: &Generation) -> Result<((f64, f64), usize)> {
        let m = self.ratio;
        let normal = child.normal_force * m as f64;
        let chain = BurridgeKnopoff::new(
            m,
            child.mass,
            child.coupling_stiffness,
            child.pulling_stiffness,
            child.mu_static,
            child.mu_kinetic,
            self.weakening_velocity,
            0.0,
            TOLERANCE,
        )?;
        let block_static = child.mu_static * child.normal_force;
        if block_static == 0.0 {
            // No friction: nothing to hold, the law stays frictionless.
            return Ok(((0.0, 0.0), 0));
        }
        let reach = block_static / child.pulling_stiffness;
        let mut state = vec![0.0; chain.state_len()];
        let phi = 0.5 * (5f64.sqrt() - 1.0);
        for i in 0..m {
            let r = ((i + 1) as f64 * phi).fract();
            state[state_block(i)] = -self.disorder * r * reach;
        }
        let samples = (TRAVEL * SAMPLES_PER_REACH) as usize;
        let ds = reach / SAMPLES_PER_REACH;
        let inc = FrictionIncrement {
            normal_force: normal,
            slip: [ds, 0.0],
            dt: ds / self.velocity,
            ..Default::default()
        };
        let mut work = chain.work();
        // Per sample: the force on the driver, the dissipation of the
        // increment, Σ_i (x_i − x_d) at its end.
        let mut forces = Vec::with_capacity(samples);
        let mut dissipated = Vec::with_capacity(samples);
        let lag = |state: &[f64]| (0..m).map(|i| state[state_block(i)]).sum::<f64>();
        let mut lags = Vec::with_capacity(samples);
        for _ in 0..samples {
            let r = chain.step_in_place(&mut state, &inc, &mut work)?;
            forces.push(-r.force[0]);
            dissipated.push(r.dissipated);
            lags.push(lag(&state));
        }
        let slips = vec![ds; samples];
        let min_drop = MIN_DROP * m as f64 * block_static;
        let whole = stick_slip(&forces, &slips, min_drop)?;
        let events = &whole.events;
        let (a, b) = match (events.first(), events.last()) {
            (Some(first), Some(last)) if events.len() >= 2 => (first.peak_index, last.peak_index),
            (Some(first), _) => (first.peak_index, samples - 1),
            _ => (samples / 2, samples - 1),
        };
        // The blocks' mean slip over the window (samples a+1 ..= b): the
        // driver's plus the change of the mean lag.
        let slip = (b - a) as f64 * ds + (lags[b] - lags[a]) / m as f64;
        let work_done: f64 = dissipated[a + 1..=b].iter().sum();
        let kinetic = if slip > 0.0 { work_done / slip } else { 0.0 };
        let mu_s = (whole.static_force / normal).max(0.0);
        let mu_k = (kinetic / normal).clamp(0.0, mu_s);
        Ok(((mu_s, mu_k), events.len()))
    }
}
