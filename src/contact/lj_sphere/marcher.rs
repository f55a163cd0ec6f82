//! Natural-parameter continuation in the central gap h̄₀ or the approach ᾱ
//! (the [`Marcher`]): [`LjSolver::sweep`], the solve at a prescribed
//! approach reached from far away, and [`LjSolver::max_turning_slope`].

use super::newton::{Mode, Work};
use super::observe::unresolved;
use super::{LjPoint, LjSolution, LjSolver};
use crate::error::{check, Error, Result};

impl LjSolver {
    /// The state reached on approach from far away at approach `al`: the
    /// first upward crossing of ᾱ = `al` along decreasing h̄₀ (outer branch
    /// before the jump-in, contact branch after it), bracketed by the
    /// continuation and finished by Newton at prescribed approach.
    pub(super) fn approach_by_continuation(&self, al: f64) -> Result<LjSolution> {
        let start = self.opts.start_gap.max(1.5 - al);
        let mut m = Marcher::start(self, start)?;
        let mut prev = m.point()?;
        if prev.approach >= al {
            return Err(Error::OutOfDomain {
                name: "approach",
                value: al,
                reason: "farther than the start of the continuation (raise start_gap)",
            });
        }
        let mut step = (-0.02 * start, 0.0f64);
        let mut guard = 0;
        loop {
            guard += 1;
            if guard > 100_000 || prev.central_gap + step.0 < 0.05 {
                return Err(Error::NotConverged {
                    what: "LJ sphere continuation towards a prescribed approach",
                    iterations: m.w.iterations.min(u32::MAX as u64) as u32,
                    residual: m.w.max_residual,
                });
            }
            let y_old = m.y.clone();
            m.advance(step)?;
            let p = m.point()?;
            if p.approach >= al && p.approach > prev.approach {
                // Bracketed: interpolate the log-gaps, finish at prescribed ᾱ.
                let t = (al - prev.approach) / (p.approach - prev.approach);
                let mut y: Vec<f64> = y_old
                    .iter()
                    .zip(&m.y)
                    .map(|(a, b)| a + t * (b - a))
                    .collect();
                let mut w = Work::new(self.n());
                if let Ok((it, res)) = self.newton(Mode::Approach(al), &mut y, &mut w, true) {
                    return self.solution(Mode::Approach(al), &w, it, res);
                }
                // Too coarse a bracket: go back and take smaller steps.
                m.set(&prev, &y_old);
                step = (0.25 * step.0, 0.25 * step.1);
                if step.0.abs().max(step.1.abs()) < 1e-9 {
                    return Err(Error::NotConverged {
                        what: "LJ sphere Newton solve at prescribed approach",
                        iterations: m.w.iterations.min(u32::MAX as u64) as u32,
                        residual: m.w.max_residual,
                    });
                }
                continue;
            }
            let ds = (p.approach - prev.approach)
                .abs()
                .max(p.central_gap - prev.central_gap);
            let ds = ds.abs();
            // Aim at steps of ~0.05 z₀ in the larger of ᾱ and h̄₀.
            let f = if ds > 0.0 { 0.05 / ds } else { 2.0 };
            let f = f.clamp(0.5, 2.0);
            step = (
                f * (p.central_gap - prev.central_gap),
                f * (p.approach - prev.approach),
            );
            prev = p;
        }
    }

    /// Equilibria at the central gaps `h0s` (strictly decreasing, the first
    /// ≥ 1.5), by continuation from the rigid profile at the first one (with
    /// internal sub-steps where needed). Returns points without stiffness.
    pub fn sweep(&self, h0s: &[f64]) -> Result<Vec<LjPoint>> {
        if h0s.is_empty() {
            return Ok(Vec::new());
        }
        for (i, &h) in h0s.iter().enumerate() {
            check::positive("central_gap", h)?;
            if i > 0 && h >= h0s[i - 1] {
                return Err(Error::InvalidArgument {
                    name: "central_gap",
                    value: h,
                    bound: "strictly decreasing",
                });
            }
        }
        if h0s[0] < 1.5 {
            return Err(Error::InvalidArgument {
                name: "central_gap",
                value: h0s[0],
                bound: "first value >= 1.5 (start away from contact)",
            });
        }
        let mut m = Marcher::start(self, h0s[0])?;
        let mut out = vec![m.point()?];
        for &h in &h0s[1..] {
            m.step_to(h)?;
            out.push(m.point()?);
        }
        Ok(out)
    }

    /// Largest `dᾱ/dh̄₀` over the curve (by the continuation's samples and a
    /// local refinement): negative when ᾱ decreases monotonically with h̄₀
    /// (no S-shape), positive when the curve is S-shaped (unstable branch
    /// under displacement control). Its zero in μ is the S-curve onset.
    pub fn max_turning_slope(&self) -> Result<f64> {
        let mut o = self.opts;
        o.max_force = o.max_force.min(2.0);
        let mut m = Marcher::start(self, o.start_gap)?;
        let mut prev = m.point()?;
        let mut best = f64::NEG_INFINITY;
        let mut best_h = prev.central_gap;
        let mut h = prev.central_gap;
        let dh0 = 0.02;
        while prev.force < o.max_force && h > 0.3 {
            h -= if h > 3.0 { 0.1 } else { dh0 };
            m.step_to(h)?;
            let p = m.point()?;
            let slope = (p.approach - prev.approach) / (p.central_gap - prev.central_gap);
            if slope > best {
                best = slope;
                best_h = 0.5 * (p.central_gap + prev.central_gap);
            }
            prev = p;
        }
        // Refine on a fine local sweep around the best sample.
        let mut m = Marcher::start(self, o.start_gap)?;
        let hi = best_h + 2.0 * dh0;
        let n0 = 60;
        for i in 1..=n0 {
            m.step_to(o.start_gap + (hi - o.start_gap) * i as f64 / n0 as f64)?;
        }
        let mut prev = m.point()?;
        let fine = dh0 / 50.0;
        let mut hh = hi;
        for _ in 0..200 {
            hh -= fine;
            m.step_to(hh)?;
            let p = m.point()?;
            let slope = (p.approach - prev.approach) / (p.central_gap - prev.central_gap);
            best = best.max(slope);
            prev = p;
        }
        Ok(best)
    }
}

/// Continuation state. The curve is followed in whichever of the central
/// gap h̄₀ and the approach ᾱ changed more over the last step (local
/// parametrisation): h̄₀ through the folds of ᾱ (jump-in, jump-out), ᾱ
/// where h̄₀ folds (large μ, near contact formation) and in the Hertz regime.
struct Marcher<'a> {
    s: &'a LjSolver,
    w: Work,
    y: Vec<f64>,
    /// Previous state: log-gaps, h̄₀, ᾱ.
    y_prev: Option<(Vec<f64>, f64, f64)>,
    h0: f64,
    al: f64,
    mode: Mode,
}

impl<'a> Marcher<'a> {
    fn start(s: &'a LjSolver, h0: f64) -> Result<Self> {
        let mut w = Work::new(s.n());
        let mut y = s.rigid_guess(h0);
        s.newton(Mode::Gap(h0), &mut y, &mut w, false)?;
        let (_, al, _, _) = s.observe(Mode::Gap(h0), &w);
        Ok(Self {
            s,
            w,
            y,
            y_prev: None,
            h0,
            al,
            mode: Mode::Gap(h0),
        })
    }

    /// Solve at central gap `target` (see [`Marcher::step`]).
    fn step_to(&mut self, target: f64) -> Result<()> {
        self.step(true, target)
    }

    /// Solve at `target` of h̄₀ (`gap`) or ᾱ, from the current state with the
    /// secant predictor; halves the step on failure.
    fn step(&mut self, gap: bool, target: f64) -> Result<()> {
        self.step_limited(gap, target, 40)
    }

    /// Advance by `step = (Δh̄₀, Δᾱ)` in the parameter with the larger
    /// component, switching to the other one if that fails.
    fn advance(&mut self, step: (f64, f64)) -> Result<()> {
        let gap = step.0.abs() >= step.1.abs();
        let mut err = None;
        for g in [gap, !gap] {
            let d = if g { step.0 } else { step.1 };
            if d == 0.0 {
                continue;
            }
            let target = if g { self.h0 + d } else { self.al + d };
            match self.step_limited(g, target, if g == gap { 8 } else { 40 }) {
                Ok(()) => return Ok(()),
                Err(e) => err = Some(e),
            }
        }
        Err(err.unwrap_or(Error::NotConverged {
            what: "LJ sphere continuation step",
            iterations: 0,
            residual: f64::NAN,
        }))
    }

    fn step_limited(&mut self, gap: bool, target: f64, max_fails: u32) -> Result<()> {
        let mut goal = target;
        let mut fails = 0;
        loop {
            let cur = if gap { self.h0 } else { self.al };
            let dh = goal - cur;
            let mut y = self.y.clone();
            if let Some((yp, hp, ap)) = &self.y_prev {
                let prev = if gap { *hp } else { *ap };
                let r = dh / (cur - prev);
                if r.is_finite() && r.abs() <= 4.0 {
                    for i in 0..y.len() {
                        y[i] += r * (self.y[i] - yp[i]);
                    }
                }
            }
            let mode = if gap {
                Mode::Gap(goal)
            } else {
                Mode::Approach(goal)
            };
            match self.s.newton(mode, &mut y, &mut self.w, false) {
                Ok(_) => {
                    let old = core::mem::replace(&mut self.y, y);
                    self.y_prev = Some((old, self.h0, self.al));
                    self.mode = mode;
                    let (h0, al, _, _) = self.s.observe(mode, &self.w);
                    self.h0 = h0;
                    self.al = al;
                    if goal == target {
                        return Ok(());
                    }
                    goal = target;
                    fails = 0;
                }
                Err(e) => {
                    fails += 1;
                    self.w.lu = None;
                    if fails > max_fails || dh.abs() < 1e-10 {
                        return Err(e);
                    }
                    self.s.residual(self.mode, &self.y, &mut self.w);
                    goal = cur + 0.5 * dh;
                }
            }
        }
    }

    fn point(&self) -> Result<LjPoint> {
        let (h0, al, f, a) = self.s.observe(self.mode, &self.w);
        if !f.is_finite() {
            return Err(unresolved(
                self.w.iterations.min(u32::MAX as u64) as u32,
                self.w.max_residual,
            ));
        }
        Ok(LjPoint {
            central_gap: h0,
            approach: al,
            force: f,
            contact_radius: a,
            stiffness: f64::NAN,
            d_approach: f64::NAN,
            d_force: f64::NAN,
            d_radius: f64::NAN,
        })
    }

    /// Jump to a stored curve state.
    fn set(&mut self, p: &LjPoint, y: &[f64]) {
        self.y.copy_from_slice(y);
        self.y_prev = None;
        self.h0 = p.central_gap;
        self.al = p.approach;
        self.mode = Mode::Gap(p.central_gap);
        self.s.residual(self.mode, &self.y, &mut self.w);
    }
}
