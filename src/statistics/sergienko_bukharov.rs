//! The Sergienko–Bukharov model (Sergienko & Bukharov 2015, after Kudinov
//! 1980; thesis §5.3.5, Figure 5-7): a rigid body resting on an assembly of
//! independent springs (the asperities); normal oscillations of the body
//! change the number of springs it touches, so they change the friction
//! force ("dynamic lift", Tolstoi 1967).
//!
//! **Formulated from the thesis's description; the book's own equations were
//! not available.** The thesis gives the idea only (a rigid body on springs,
//! normal oscillations that accompany any tangential impulse, more springs
//! touched as the body descends, less friction for larger oscillations
//! because of the higher mean level and fewer contacting springs, springs
//! that deform independently, a multi-level model like Kragelsky's). The
//! equations below are this library's formulation of that description on
//! top of Kragelsky's rods ([`KragelskyRods`], thesis §5.3.4), and they are
//! named as such: they are not the book's.
//!
//! # Formulation
//!
//! **Springs.** N rods of axial stiffness k and section A_rod with tops at
//! heights z distributed as φ ([`HeightDistribution`]: Gaussian, exponential
//! or a list, e.g. a measured profile's summits). A body whose flat lower
//! face is at the separation d (m, upwards, in the heights' frame) compresses
//! every rod with z > d, so the springs carry (thesis (5-7), Kragelsky)
//!
//! $$P(d) = Nk\int_d^\infty (z-d)\\,\varphi(z)\\,dz, \qquad n(d) = N\int_d^\infty\varphi(z)\\,dz, \qquad -\frac{dP}{dd} = k\\,n(d).$$
//!
//! **Normal motion.** The body (mass m) carries the normal load N_0 plus a
//! driven normal force F_n(t) = F_0 sin ωt (both pressing it down), and a
//! viscous damper c acts on its vertical velocity:
//!
//! $$m\ddot d = P(d) - N_0 - F_0\sin\omega t - c\\,\dot d, \qquad c = 2\zeta\sqrt{m K_0}, \quad K_0 = k\\,n(d_s),$$
//!
//! with ζ the damping ratio of the motion linearised about the static
//! equilibrium P(d_s) = N_0 (natural frequency ω_0 = √(K_0/m)).
//!
//! **Tangential impulse.** A horizontal impulse J makes the body ride up the
//! inclined flanks of the asperities; with contact flanks of slope tan θ the
//! horizontal velocity J/m becomes an upward velocity
//! `ḋ(0) = tanθ · J/m` (the geometric form of the thesis's "any horizontal
//! impulse given to the rigid body will be accompanied by oscillations in
//! the normal direction"). The run starts at `d(0) = d_s + offset`.
//!
//! **Friction.** Derjaguin's two-term law (thesis (1-3)) on the instantaneous
//! contact, `F_f(t) = μ (P(t) + p_0 S(t))`, with the true area
//! `S = n A_rod` and the specific attractive force p_0: a mechanical term
//! proportional to the load the springs carry and a molecular term
//! proportional to the number of contacting springs. The static value is
//! `F_s = μ (N_0 + p_0 A_rod n(d_s))`.
//!
//! # Why the friction drops (the closed form behind the thesis's statement)
//!
//! Over whole periods of a periodic steady state the mean of m d̈ and of c ḋ
//! vanish, so `⟨P⟩ = N_0`: the mechanical term of the friction does not
//! change on average. The molecular term follows ⟨n⟩. Along the load curve,
//! `dn/dP = φ(d)/(k ∫_d^∞ φ)`, the hazard rate of the heights over k: when
//! it grows with d (log-concave tails: Gaussian, uniform), n is a concave
//! function of P and Jensen's inequality gives `⟨n⟩ ≤ n(d_s)` (with P = 0,
//! n = 0 off contact as well): the body's mean level rises (`⟨d⟩ > d_s`, the
//! dynamic lift), fewer springs touch, the friction falls, and more so for
//! larger oscillations. For springs spread uniformly in height (ρ per metre,
//! penetration y = z_top − d): `P = kρy²/2`, `n = ρy`, so in the quasi-static
//! limit (ω ≪ ω_0)
//!
//! $$\langle y\rangle = \frac{1}{2\pi}\int_0^{2\pi}\sqrt{\frac{2(N_0 + F_0\sin\varphi)}{k\rho}}\\,d\varphi < y_s = \sqrt{\frac{2N_0}{k\rho}} \quad (F_0 \le N_0).$$
//!
//! Exponential heights are the borderline: n = P/(kσ) exactly, so ⟨n⟩ and
//! the friction keep their static values at any amplitude while the body
//! still lifts (d is a convex function of P). These three statements are
//! the tests of `tests/statistics_sergienko_bukharov.rs`.
//!
//! # Numerics
//!
//! Classical Runge–Kutta with a fixed step: a whole number of steps per
//! period T (the excitation period 2π/ω, or the natural period 2π/ω_0 when
//! F_0 = 0), at least 32, and at least `steps_per_natural_period` steps per
//! period of the stiffest state reached, √(k n_max/m). The stiffness is
//! estimated at the load 2(N_0 + F_0) and the run is repeated with a smaller
//! step when the body reaches a stiffer state than estimated; the report
//! gives the resolution achieved. Averages are taken at the step ends over
//! `average_periods` whole periods after `transient_periods` (the
//! rectangle rule over whole periods, exact for the periodic steady state's
//! trigonometric content). For a list of heights the load is a prefix sum
//! over the sorted tops (O(log M) per evaluation).
//!
//! Like Kragelsky's (1948), the model is multi-level but neither
//! multi-scale nor hierarchical, and its asperities are uncoupled.
//!
//! # References
//!
//! * Thesis §5.3.5 (Figure 5-7), §5.3.4 ((5-7), Kragelsky's rods), (1-3)
//!   (Derjaguin's friction law).
//! * V. P. Sergienko, S. N. Bukharov (2015), *Noise and Vibration in Friction
//!   Systems*, Springer Series in Materials Science 212,
//!   [doi:10.1007/978-3-319-11334-0](https://doi.org/10.1007/978-3-319-11334-0)
//!   (not consulted: see above).
//! * V. A. Kudinov (1980); D. M. Tolstoi (1967), as cited by the thesis.

use super::heights::HeightDistribution;
use super::kragelsky::KragelskyRods;
use crate::error::{check, Error, Result};
use core::f64::consts::TAU;

/// Largest number of time steps of one run.
pub const MAX_STEPS: u64 = 50_000_000;

/// Spring load, relative to N_0, at or below which the body counts as
/// lifted off (exactly zero for a list of heights above its highest top; a
/// parametric distribution's load only underflows, many σ up).
pub const LIFT_OFF: f64 = 1e-9;

/// Fewest steps per averaging period.
const MIN_STEPS_PER_PERIOD: u64 = 32;

/// The body on its springs, with the friction law's constants.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct SergienkoBukharov {
    rods: KragelskyRods,
    rod_area: f64,
    mass: f64,
    load: f64,
    damping_ratio: f64,
    friction_coefficient: f64,
    attractive_pressure: f64,
    static_separation: f64,
    static_contacts: f64,
    damping: f64,
    #[serde(skip)]
    table: Option<SpringTable>,
}

/// A list of spring tops as depths below the highest one, for O(log M)
/// load evaluations.
#[derive(Debug, Clone, PartialEq)]
struct SpringTable {
    /// Highest top z_max (m).
    top: f64,
    /// Depths z_max − z_i (m), ascending.
    depth: Vec<f64>,
    /// `prefix[c] = Σ_{i<c} depth[i]` (m).
    prefix: Vec<f64>,
    /// Rods per listed top, N/M.
    weight: f64,
}

impl SpringTable {
    fn new(heights: &[f64], rod_count: f64) -> Self {
        let top = heights[heights.len() - 1];
        let depth: Vec<f64> = heights.iter().rev().map(|&z| top - z).collect();
        let mut prefix = Vec::with_capacity(depth.len() + 1);
        let mut s = 0.0;
        prefix.push(0.0);
        for &e in &depth {
            s += e;
            prefix.push(s);
        }
        Self {
            top,
            weight: rod_count / depth.len() as f64,
            depth,
            prefix,
        }
    }

    /// Spring load per unit k and the contact count at separation d.
    #[inline]
    fn eval(&self, d: f64) -> (f64, f64) {
        let y = self.top - d;
        if y <= 0.0 {
            return (0.0, 0.0);
        }
        let c = self.depth.partition_point(|&e| e < y);
        (
            self.weight * (c as f64 * y - self.prefix[c]),
            self.weight * c as f64,
        )
    }
}

/// The driving of one run.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Excitation {
    /// Amplitude F_0 of the normal force `F_0 sin ωt` (N, finite, ≥ 0; it
    /// may exceed the load: the body then leaves the springs part of the time).
    pub force_amplitude: f64,
    /// Angular frequency ω (rad/s, finite, > 0 when `force_amplitude` > 0;
    /// ignored otherwise).
    pub frequency: f64,
    /// Tangential impulse J given to the body at t = 0 (N·s, finite, ≥ 0).
    pub tangential_impulse: f64,
    /// Slope tan θ of the asperity flanks that turns the horizontal velocity
    /// J/m into the upward velocity tan θ·J/m (finite, ≥ 0).
    pub slope: f64,
    /// Start position relative to the static equilibrium, d(0) − d_s (m,
    /// finite; > 0 above it).
    pub initial_offset: f64,
}

/// Time stepping and averaging of one run.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Integration {
    /// Periods T skipped before averaging (the transient).
    pub transient_periods: u32,
    /// Periods T averaged over (≥ 1).
    pub average_periods: u32,
    /// Least number of steps per natural period of the stiffest state
    /// reached (16..=100000).
    pub steps_per_natural_period: u32,
    /// Record every this many steps into [`SergienkoBukharovRun::samples`]
    /// (0: record nothing).
    pub record_every: u32,
    /// Most time steps a run may take (0: [`MAX_STEPS`]); a run that needs
    /// more is refused before it starts.
    pub max_steps: u64,
}

impl Default for Integration {
    /// 20 transient periods, 10 averaged, 64 steps per natural period, no
    /// record.
    fn default() -> Self {
        Self {
            transient_periods: 20,
            average_periods: 10,
            steps_per_natural_period: 64,
            record_every: 0,
            max_steps: 0,
        }
    }
}

/// One recorded instant of a run.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct SergienkoBukharovSample {
    /// Time t (s).
    pub time: f64,
    /// Separation d (m).
    pub separation: f64,
    /// Vertical velocity ḋ (m/s, > 0 upwards).
    pub velocity: f64,
    /// Load carried by the springs P (N).
    pub load: f64,
    /// Springs in contact n.
    pub contacts: f64,
    /// Friction force F_f (N).
    pub friction: f64,
}

/// The result of one run: static reference, time averages over the
/// averaging window, and the integration report.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct SergienkoBukharovRun {
    /// Static separation d_s (m): P(d_s) = N_0.
    pub static_separation: f64,
    /// Springs in contact at rest n(d_s).
    pub static_contacts: f64,
    /// Static friction F_s = μ(N_0 + p_0 A_rod n(d_s)) (N).
    pub static_friction: f64,
    /// Mean separation ⟨d⟩ (m).
    pub mean_separation: f64,
    /// Dynamic lift ⟨d⟩ − d_s (m).
    pub lift: f64,
    /// Half the peak-to-peak range of d over the window (m).
    pub separation_amplitude: f64,
    /// Mean number of contacting springs ⟨n⟩.
    pub mean_contacts: f64,
    /// ⟨n⟩/n(d_s).
    pub contact_ratio: f64,
    /// Mean spring load ⟨P⟩ (N); N_0 in a periodic steady state.
    pub mean_load: f64,
    /// Mean friction force ⟨F_f⟩ (N).
    pub mean_friction: f64,
    /// ⟨F_f⟩/F_s.
    pub friction_ratio: f64,
    /// Fraction of the window in which the body is off the springs,
    /// P ≤ [`LIFT_OFF`]·N_0 (for a list of heights: no spring touches).
    pub lift_off_fraction: f64,
    /// Damping coefficient c (N·s/m).
    pub damping: f64,
    /// Averaging period T (s).
    pub period: f64,
    /// Time step (s).
    pub time_step: f64,
    /// Steps taken in the accepted run.
    pub steps: u64,
    /// Steps per natural period of the stiffest state reached,
    /// 2π/(dt √(k n_max/m)).
    pub resolution: f64,
    /// Recorded samples (empty unless `record_every` > 0).
    pub samples: Vec<SergienkoBukharovSample>,
}

impl SergienkoBukharov {
    /// The body of `mass` m (kg, > 0) under `load` N_0 (N, > 0) on `rods`,
    /// with `damping_ratio` ζ (finite, ≥ 0), `friction_coefficient` μ (> 0)
    /// and `attractive_pressure` p_0 (Pa, finite, ≥ 0) of Derjaguin's law.
    /// Solves the static equilibrium (Kragelsky's separation at the load).
    pub fn new(
        rods: KragelskyRods,
        mass: f64,
        load: f64,
        damping_ratio: f64,
        friction_coefficient: f64,
        attractive_pressure: f64,
    ) -> Result<Self> {
        let mass = check::positive("mass", mass)?;
        let load = check::positive("load", load)?;
        let damping_ratio = check::non_negative("damping_ratio", damping_ratio)?;
        let friction_coefficient = check::positive("friction_coefficient", friction_coefficient)?;
        let attractive_pressure = check::non_negative("attractive_pressure", attractive_pressure)?;
        let rod_count = rods.rod_count();
        let rod_area = rods.rod_area();
        let table = match rods.heights() {
            HeightDistribution::Empirical(e) => Some(SpringTable::new(e.heights(), rod_count)),
            _ => None,
        };
        let d_s = rods.separation_at_load(load)?.separation;
        let mut model = Self {
            rods,
            rod_area,
            mass,
            load,
            damping_ratio,
            friction_coefficient,
            attractive_pressure,
            static_separation: d_s,
            static_contacts: 0.0,
            damping: 0.0,
            table,
        };
        let n_s = model.eval(d_s)?.1;
        model.static_contacts = n_s;
        let k0 = model.rods.rod_stiffness() * n_s;
        model.damping = check::finite_of(
            2.0 * damping_ratio * (mass * k0).sqrt(),
            &[("mass", mass), ("damping_ratio", damping_ratio)],
            "the damping coefficient overflows",
        )?;
        Ok(model)
    }

    /// The springs.
    pub fn rods(&self) -> &KragelskyRods {
        &self.rods
    }

    /// Static separation d_s (m).
    pub fn static_separation(&self) -> f64 {
        self.static_separation
    }

    /// Springs in contact at rest.
    pub fn static_contacts(&self) -> f64 {
        self.static_contacts
    }

    /// Natural angular frequency ω_0 = √(k n(d_s)/m) (rad/s) of the motion
    /// linearised about the static equilibrium.
    pub fn natural_frequency(&self) -> f64 {
        (self.rods.rod_stiffness() * self.static_contacts / self.mass).sqrt()
    }

    /// Damping coefficient c = 2ζ√(m K_0) (N·s/m).
    pub fn damping(&self) -> f64 {
        self.damping
    }

    /// Static friction F_s = μ(N_0 + p_0 A_rod n(d_s)) (N).
    pub fn static_friction(&self) -> f64 {
        self.friction(self.load, self.static_contacts)
    }

    #[inline]
    fn friction(&self, load: f64, contacts: f64) -> f64 {
        self.friction_coefficient * (load + self.attractive_pressure * self.rod_area * contacts)
    }

    /// Spring load P (N) and contacts n at separation d (m).
    #[inline]
    fn eval(&self, d: f64) -> Result<(f64, f64)> {
        match &self.table {
            Some(t) => {
                let (p, n) = t.eval(d);
                Ok((self.rods.rod_stiffness() * p, n))
            }
            None => {
                let r = self.rods.response(d)?;
                Ok((r.load, r.contacts))
            }
        }
    }

    /// Spring load P (N), contacts n and friction F_f (N) at `separation`
    /// d (m, finite).
    pub fn state_at(&self, separation: f64) -> Result<(f64, f64, f64)> {
        let d = check::finite("separation", separation)?;
        let (p, n) = self.eval(d)?;
        Ok((p, n, self.friction(p, n)))
    }

    /// Integrate the body's normal motion under `excitation` and average
    /// over whole periods as `integration` says. Errors name the offending
    /// argument; a run needing more than `max_steps` (default [`MAX_STEPS`])
    /// steps is refused (naming `frequency`, or `average_periods` when
    /// F_0 = 0).
    pub fn run(
        &self,
        excitation: &Excitation,
        integration: &Integration,
    ) -> Result<SergienkoBukharovRun> {
        let f0 = check::non_negative("force_amplitude", excitation.force_amplitude)?;
        let omega = check::non_negative("frequency", excitation.frequency)?;
        if f0 > 0.0 && omega == 0.0 {
            return Err(Error::InvalidArgument {
                name: "frequency",
                value: omega,
                bound: "> 0 when force_amplitude > 0",
            });
        }
        let j = check::non_negative("tangential_impulse", excitation.tangential_impulse)?;
        let slope = check::non_negative("slope", excitation.slope)?;
        let offset = check::finite("initial_offset", excitation.initial_offset)?;
        if integration.average_periods == 0 {
            return Err(Error::InvalidArgument {
                name: "average_periods",
                value: 0.0,
                bound: ">= 1",
            });
        }
        let spp = integration.steps_per_natural_period;
        if !(16..=100_000).contains(&spp) {
            return Err(Error::InvalidArgument {
                name: "steps_per_natural_period",
                value: spp as f64,
                bound: "in 16..=100000",
            });
        }
        let v0 = check::finite_of(
            slope * j / self.mass,
            &[
                ("tangential_impulse", j),
                ("slope", slope),
                ("mass", self.mass),
            ],
            "the initial velocity overflows",
        )?;
        let d0 = check::finite_result(
            self.static_separation + offset,
            "initial_offset",
            offset,
            "the start position overflows",
        )?;
        let (omega, f0) = if f0 > 0.0 { (omega, f0) } else { (0.0, 0.0) };
        let period = if f0 > 0.0 {
            TAU / omega
        } else {
            TAU / self.natural_frequency()
        };
        let k = self.rods.rod_stiffness();
        // Stiffness estimate: at twice the largest load of the excitation.
        let mut stiff = match self.rods.separation_at_load(2.0 * (self.load + f0)) {
            Ok(s) => k * self.eval(s.separation)?.1,
            Err(_) => k * self.static_contacts,
        }
        .max(k * self.static_contacts);
        let periods = integration.transient_periods as u64 + integration.average_periods as u64;
        let budget = if integration.max_steps == 0 {
            MAX_STEPS
        } else {
            integration.max_steps
        };
        for _attempt in 0..8 {
            let dt_max = TAU / ((stiff / self.mass).sqrt() * spp as f64);
            let per = (period / dt_max).ceil();
            let too_many = |per: f64| {
                let name = if f0 > 0.0 {
                    "frequency"
                } else {
                    "average_periods"
                };
                let value = if f0 > 0.0 {
                    omega
                } else {
                    integration.average_periods as f64
                };
                Error::OutOfDomain {
                    name,
                    value,
                    reason: if per.is_finite() {
                        "the run needs more time steps than max_steps (default 5e7)"
                    } else {
                        "the time step is not finite"
                    },
                }
            };
            if !(per.is_finite() && per * periods as f64 <= budget as f64) {
                return Err(too_many(per));
            }
            let per = (per as u64).max(MIN_STEPS_PER_PERIOD);
            if per.saturating_mul(periods) > budget {
                return Err(too_many(per as f64));
            }
            let dt = period / per as f64;
            let run = self.integrate((d0, v0), (f0, omega), dt, per, integration, period)?;
            let n_max = run.1;
            let mut out = run.0;
            let reached = k * n_max;
            out.resolution = if reached > 0.0 {
                TAU / (dt * (reached / self.mass).sqrt())
            } else {
                f64::INFINITY
            };
            if out.resolution >= 0.8 * spp as f64 {
                return Ok(out);
            }
            stiff = 1.25 * reached;
        }
        Err(Error::NotConverged {
            what: "Sergienko-Bukharov time step (stiffness keeps growing)",
            iterations: 8,
            residual: f64::INFINITY,
        })
    }

    /// One fixed-step run; returns the result and the most springs touched.
    fn integrate(
        &self,
        start: (f64, f64),
        forcing: (f64, f64),
        dt: f64,
        per: u64,
        integration: &Integration,
        period: f64,
    ) -> Result<(SergienkoBukharovRun, f64)> {
        let (f0, omega) = forcing;
        let m = self.mass;
        let c = self.damping;
        let n0 = self.load;
        let n_max = core::cell::Cell::new(0.0_f64);
        let accel = |t: f64, d: f64, v: f64| -> Result<f64> {
            let (p, n) = self.eval(d)?;
            n_max.set(n_max.get().max(n));
            Ok((p - n0 - f0 * (omega * t).sin() - c * v) / m)
        };
        let transient = integration.transient_periods as u64 * per;
        let total = transient + integration.average_periods as u64 * per;
        let every = integration.record_every as u64;
        let mut samples = Vec::new();
        let (mut d, mut v) = start;
        let sample = |t: f64, d: f64, v: f64| -> Result<SergienkoBukharovSample> {
            let (p, n) = self.eval(d)?;
            Ok(SergienkoBukharovSample {
                time: t,
                separation: d,
                velocity: v,
                load: p,
                contacts: n,
                friction: self.friction(p, n),
            })
        };
        if every > 0 {
            samples.push(sample(0.0, d, v)?);
        }
        let (mut sd, mut sn, mut sp, mut sf) = (0.0, 0.0, 0.0, 0.0);
        let (mut dmin, mut dmax) = (f64::INFINITY, f64::NEG_INFINITY);
        let mut off = 0u64;
        for step in 1..=total {
            let t = (step - 1) as f64 * dt;
            let h = 0.5 * dt;
            let a1 = accel(t, d, v)?;
            let (d2, v2) = (d + h * v, v + h * a1);
            let a2 = accel(t + h, d2, v2)?;
            let (d3, v3) = (d + h * v2, v + h * a2);
            let a3 = accel(t + h, d3, v3)?;
            let (d4, v4) = (d + dt * v3, v + dt * a3);
            let a4 = accel(t + dt, d4, v4)?;
            d += dt / 6.0 * (v + 2.0 * v2 + 2.0 * v3 + v4);
            v += dt / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4);
            if !(d.is_finite() && v.is_finite()) {
                return Err(Error::NotConverged {
                    what: "Sergienko-Bukharov integration (state not finite)",
                    iterations: step.min(u32::MAX as u64) as u32,
                    residual: f64::INFINITY,
                });
            }
            let t = step as f64 * dt;
            if every > 0 && step % every == 0 {
                samples.push(sample(t, d, v)?);
            }
            if step > transient {
                let (p, n) = self.eval(d)?;
                n_max.set(n_max.get().max(n));
                sd += d;
                sn += n;
                sp += p;
                sf += self.friction(p, n);
                dmin = dmin.min(d);
                dmax = dmax.max(d);
                if p <= LIFT_OFF * n0 {
                    off += 1;
                }
            }
        }
        let count = (total - transient) as f64;
        let mean_separation = sd / count;
        let mean_contacts = sn / count;
        let mean_friction = sf / count;
        let static_friction = self.static_friction();
        Ok((
            SergienkoBukharovRun {
                static_separation: self.static_separation,
                static_contacts: self.static_contacts,
                static_friction,
                mean_separation,
                lift: mean_separation - self.static_separation,
                separation_amplitude: 0.5 * (dmax - dmin),
                mean_contacts,
                contact_ratio: mean_contacts / self.static_contacts,
                mean_load: sp / count,
                mean_friction,
                friction_ratio: mean_friction / static_friction,
                lift_off_fraction: off as f64 / count,
                damping: c,
                period,
                time_step: dt,
                steps: total,
                resolution: 0.0,
                samples,
            },
            n_max.get(),
        ))
    }
}
