//! Special points of the path — the turning points of ᾱ (jump-in,
//! jump-out) and the force minimum (load-controlled pull-off): located
//! between the samples of a march and refined as roots along the path.

use super::numeric::dot;
use super::path::{self, BWork, State};
use super::LjSolver;
use crate::error::{Error, Result};

/// A special point of the path.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Special {
    /// Local maximum of the approach (jump-in).
    ApproachMax,
    /// Local minimum of the approach (jump-out).
    ApproachMin,
    /// Minimum of the force (load-controlled pull-off).
    ForceMin,
}

impl Special {
    /// The path derivative whose zero is the point: `dᾱ/ds` or `dP̄/ds`.
    pub(super) fn phi(self, st: &path::State) -> f64 {
        match self {
            Special::ApproachMax | Special::ApproachMin => st.t[st.t.len() - 1],
            Special::ForceMin => st.df,
        }
    }

    /// The `rtol` of [`LjSolver::path_root`] for the point: the force is an
    /// extremum at the pull-off (a location error costs its square, and
    /// `dP̄/ds` by central differences is noisy), [`path::ROOT_RTOL`]; the
    /// force at a turning point of ᾱ moves with the location at first
    /// order, 1e-10 (`dᾱ/ds` converges to 1e-16 there).
    fn root_rtol(self) -> f64 {
        match self {
            Special::ApproachMax | Special::ApproachMin => 1e-10,
            Special::ForceMin => path::ROOT_RTOL,
        }
    }
}

impl LjSolver {
    /// The state `st` again, with its tangent and derivatives exact.
    pub(super) fn exactify(&self, st: &State, bw: &mut BWork) -> Result<State> {
        let mut y = st.y.clone();
        let mut al = st.al;
        if self
            .bnewton(&path::Con::Approach(st.al), &mut y, &mut al, bw, false)
            .is_err()
        {
            bw.invalidate();
            y.copy_from_slice(&st.y);
            al = st.al;
            self.bnewton(&path::Con::Approach(st.al), &mut y, &mut al, bw, true)?;
        }
        // Tangent refined against the true Jacobian (`LjSolver::tangent`).
        let t = self.tangent(bw, &st.t, false, path::EXACT_RTOL, None)?;
        self.make_state(&y, al, t, st.s, bw, true)
    }

    /// Refine the special point `sp` (the root of [`Special::phi`]) in the
    /// sample interval `[i, i + 1]` of the fixed-mesh `states` (or a
    /// neighbouring interval when the exact signs say so).
    pub(super) fn refine_between(
        &self,
        states: &[State],
        i: usize,
        bw: &mut BWork,
        sp: Special,
    ) -> Result<State> {
        let phi = |st: &State| sp.phi(st);
        let n = states.len();
        let mut cands = vec![i];
        if i > 0 {
            cands.push(i - 1);
        }
        if i + 2 < n {
            cands.push(i + 1);
        }
        for a in cands {
            let l = self.exactify(&states[a], bw)?;
            let r = self.exactify(&states[a + 1], bw)?;
            if phi(&l) * phi(&r) <= 0.0 {
                return self.path_root(&l, &r, bw, &phi, sp.root_rtol());
            }
        }
        self.exactify(&states[i], bw)
    }

    /// [`LjSolver::refine_between`] on a dense arclength march from
    /// `states[i − 1]` past `states[i + 2]`: the neck phase continued in its
    /// marker (`edge` module) can leave states too far apart for the
    /// guesses of [`LjSolver::path_root`] (interpolation between the
    /// states: at μ = 3 with 100 target points, the jump-out). The point's
    /// arclength is placed among those of `states` by its projections on
    /// their tangents, so that it sorts among them.
    pub(super) fn refine_densely(
        &self,
        states: &[State],
        i: usize,
        bw: &mut BWork,
        sp: Special,
    ) -> Result<State> {
        let n = self.n();
        let my = self.metric_y();
        let (a, b) = (i.saturating_sub(1), (i + 2).min(states.len() - 1));
        bw.invalidate();
        let end = &states[b];
        let ahead = |x: &State| {
            my * dot(&end.t[..n], &x.y) + end.t[n] * x.al
                - my * dot(&end.t[..n], &end.y)
                - end.t[n] * end.al
        };
        let mut dense = vec![self.exactify(&states[a], bw)?];
        let sigma = (end.s - states[a].s) / 16.0;
        let o = self.opts;
        self.march_on(&mut dense, bw, o.max_force, o.target_points, sigma, &|st| {
            ahead(&st[st.len() - 1]) > 0.0
        })?;
        let j = (0..dense.len() - 1)
            .find(|&j| sp.phi(&dense[j]) * sp.phi(&dense[j + 1]) <= 0.0)
            .ok_or(Error::NotConverged {
                what: "LJ sphere special point (dense march)",
                iterations: 0,
                residual: f64::NAN,
            })?;
        let mut st = self.refine_between(&dense, j, bw, sp)?;
        // Its place among `states`: after the last state it lies ahead of
        // (along that state's tangent), at the fraction of the way to the
        // next one that the projections give.
        let proj = |k: usize, x: &State| {
            let e = &states[k];
            my * (dot(&e.t[..n], &x.y) - dot(&e.t[..n], &e.y)) + e.t[n] * (x.al - e.al)
        };
        let k = (a..b).rev().find(|&k| proj(k, &st) >= 0.0).unwrap_or(a);
        let (p0, p1) = (proj(k, &st), proj(k, &states[k + 1]));
        let th = if p1 > 0.0 {
            (p0 / p1).clamp(0.0, 1.0)
        } else {
            0.5
        };
        st.s = states[k].s + th * (states[k + 1].s - states[k].s);
        Ok(st)
    }

    /// The sample interval holding the force minimum: `[i−1, i]` or `[i, i+1]`
    /// around the smallest sample `i` (by the parabola through the three).
    pub(super) fn min_interval(states: &[State]) -> Option<usize> {
        let n = states.len();
        let i = (0..n).min_by(|&a, &b| states[a].pt.force.total_cmp(&states[b].pt.force))?;
        if i == 0 || i + 1 >= n {
            return None;
        }
        Some(if states[i - 1].pt.force < states[i + 1].pt.force {
            i - 1
        } else {
            i
        })
    }
}
