//! Dense sampling of the Lennard-Jones equilibrium path for tabulated laws
//! ([`LjSolver::path_samples`]): the coarse pseudo-arclength continuation of
//! [`LjSolver::curve`], its special points refined exactly, and every
//! interval between neighbours bisected until cubic Hermite interpolation
//! along the path parameter reproduces the exact midpoint to `tolerance/8`.

// NaN-aware comparisons (`!(x > 0.0)`) are intended.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::needless_range_loop)]

use super::edge::EdgeState;
use super::observe::unresolved;
use super::path::{BWork, State};
use super::LjSolver;
use crate::contact::curve::PathPoint;
use crate::error::{check, Error, Result};

/// The sampled path of [`LjSolver::path_samples`], in the reduced units of
/// the sphere: `delta` = ᾱ (approach in units of z₀, 0 where the undeformed
/// apex sits at z₀), `force` = `P/(πRΔγ)` (repulsive positive), `radius` =
/// `a/√(Rz₀)`; derivatives along the path parameter of
/// [`crate::contact::curve`] (see [`LjSolver::path_samples`]).
#[derive(Debug, Clone, PartialEq)]
pub struct LjPathSamples {
    /// Points from far (the continuation start) to deep contact, with the
    /// special points explicit (rules of [`crate::contact::curve`]).
    pub points: Vec<PathPoint>,
    /// Exact points before the first one (central gaps 1.25 to 10 times the
    /// start gap): the far tail's checks.
    pub tail_checks: Vec<PathPoint>,
    /// Exact points beyond the last one (the continuation up to three times
    /// [`LjOptions::max_force`](super::LjOptions::max_force)), outside the range the mesh is designed for:
    /// there the discrete solution carries node-crossing ripples of ~1e-4
    /// (force) to ~1e-3 (radius) relative at N = 128 that no smooth tail
    /// follows; for reporting the deep tail's deviation, not for bounds.
    pub deep_checks: Vec<PathPoint>,
    /// Index in `points` of the jump-in turning point (S-shaped curves).
    pub jump_in: Option<usize>,
    /// Index in `points` of the jump-out turning point (S-shaped curves).
    pub jump_out: Option<usize>,
    /// Index in `points` of the load-controlled pull-off (`d_force == 0`).
    pub pull_off_load: usize,
    /// Index in `points` of the first point of the contact-onset corner
    /// (central gap `h̄₀ = 1`, where the contact radius leaves zero).
    pub contact_onset: Option<usize>,
    /// Newton iterations over all solves.
    pub iterations: u64,
    /// LU factorisations over all solves.
    pub factorizations: u64,
}

/// What a node of the sampled path is.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Kind {
    Regular,
    /// Turning point of ᾱ, with d²ᾱ/ds².
    Turn(f64),
    /// Minimum of the force on the last stable piece.
    Min,
    /// Zero of the force on the last stable piece.
    Zero,
    /// Contact onset (h̄₀ = 1): a corner; d(radius)/dτ at τ = 0⁺ with
    /// τ = √σ, σ the distance along the tangent.
    Corner(f64),
}

#[derive(Debug, Clone)]
struct Node {
    st: State,
    kind: Kind,
    /// (dᾱ/ds, dP̄/ds, da/ds).
    d: [f64; 3],
}

/// A node of the edge phase (μ > 1, [`super::edge`]): the state on the mesh
/// banded at its marker radius `m`, with (dᾱ/dm, dP̄/dm, da/dm).
#[derive(Debug, Clone)]
struct ENode {
    e: EdgeState,
    kind: Kind,
    d: [f64; 3],
}

/// Indices of the special points among the emitted path points.
#[derive(Debug, Default)]
struct Marks {
    jump_in: Option<usize>,
    jump_out: Option<usize>,
    pull: Option<usize>,
    onset: Option<usize>,
}

impl Marks {
    /// Emit the point `p` of a node of kind `kind` (`d_delta`: dᾱ/dt there),
    /// with the exact zeros the curve rules ask for.
    fn push(&mut self, out: &mut Vec<PathPoint>, mut p: PathPoint, kind: Kind, d_delta: f64) {
        match kind {
            Kind::Regular => out.push(p),
            Kind::Turn(d2) => {
                p.d_delta = 0.0;
                p.d2_delta = d2;
                if d2 < 0.0 {
                    self.jump_in = Some(out.len());
                } else {
                    self.jump_out = Some(out.len());
                }
                out.push(p);
            }
            Kind::Min => {
                p.d_force = 0.0;
                self.pull = Some(out.len());
                out.push(p);
            }
            Kind::Zero => {
                p.force = 0.0;
                out.push(p);
            }
            Kind::Corner(g) => {
                self.onset = Some(out.len());
                p.radius = 0.0;
                p.d_radius = 0.0;
                out.push(p);
                out.push(PathPoint {
                    d_delta: 0.0,
                    d_force: 0.0,
                    d_radius: g,
                    d2_delta: 2.0 * d_delta,
                    ..p
                });
            }
        }
    }
}

/// Refinement criterion: Hermite midpoints within `tol` of the exact ones,
/// relative to `max(|value|, floor)` (ᾱ: absolute `tol·d_abs`).
struct Crit {
    tol: f64,
    d_abs: f64,
    f_floor: f64,
    a_floor: f64,
}

fn hermite_mid(y0: f64, m0: f64, y1: f64, m1: f64, h: f64) -> f64 {
    0.5 * (y0 + y1) + 0.125 * h * (m0 - m1)
}

impl LjSolver {
    /// `⟨T_a, X_b − X_a⟩` in the continuation metric.
    fn chart_proj(&self, a: &State, b: &State) -> f64 {
        let n = self.n();
        let my = self.metric_y();
        let mut s = 0.0;
        for i in 0..n {
            s += a.t[i] * (b.y[i] - a.y[i]);
        }
        my * s + a.t[n] * (b.al - a.al)
    }

    /// `⟨T_a, T_b⟩` in the continuation metric.
    fn chart_cos(&self, a: &State, b: &State) -> f64 {
        let n = self.n();
        my_dot(self.metric_y(), &a.t[..n], &b.t[..n]) + a.t[n] * b.t[n]
    }

    /// (dᾱ/ds, dP̄/ds, da/ds) at `st` by central differences of step `e`
    /// along its (exact) tangent.
    fn path_derivs(&self, st: &State, e: f64) -> Result<[f64; 3]> {
        let n = self.n();
        let mut yp = vec![0.0; n];
        let mut vals = [(0.0, 0.0); 2];
        for (q, sg) in [1.0, -1.0].into_iter().enumerate() {
            for i in 0..n {
                yp[i] = st.y[i] + sg * e * st.t[i];
            }
            let (_, f, a) = self.observe_y(&yp, st.al + sg * e * st.t[n]);
            vals[q] = (f, a);
        }
        let df = (vals[0].0 - vals[1].0) / (2.0 * e);
        let mut da = (vals[0].1 - vals[1].1) / (2.0 * e);
        if st.pt.contact_radius == 0.0 {
            da = 0.0;
        }
        if !(df.is_finite() && da.is_finite()) {
            return Err(unresolved(0, f64::NAN));
        }
        Ok([st.t[n], df, da])
    }

    fn node(&self, st: State, kind: Kind) -> Result<Node> {
        let d = self.path_derivs(&st, 1e-6)?;
        Ok(Node { st, kind, d })
    }

    /// Dense samples of the equilibrium path for a tabulated law, from the
    /// continuation start (far, stable, attractive) to `P̄ ≥`
    /// [`LjOptions::max_force`](super::LjOptions::max_force), such that cubic Hermite interpolation along
    /// the path parameter between neighbouring points reproduces the exact
    /// path to `tolerance/8` (force and radius relative to
    /// `max(|value|, 10⁻³·scale)`, approach absolute to `0.1·tolerance/8`);
    /// the midpoints of accepted intervals are kept as extra points.
    ///
    /// Derivatives are along the pseudo-arclength `s` of the continuation
    /// (unit tangent; see [`LjPoint::d_approach`](super::LjPoint::d_approach)), except at the special
    /// points, which are exact roots along the path (Illinois method, exact
    /// tangents):
    ///
    /// * turning points of ᾱ (jump-in, jump-out): `d_delta = 0`,
    ///   `d2_delta = d²ᾱ/ds²` (central differences of the exact tangent);
    /// * the load-controlled pull-off (minimum of P̄ on the last stable
    ///   piece): `d_force = 0`;
    /// * the zero of P̄ on the last stable piece: `force = 0`;
    /// * the contact onset `h̄₀ = 1`, where the contact radius (first root of
    ///   `h̄ = 1`, see [`LjSolution::contact_radius`](super::LjSolution::contact_radius)) leaves zero like
    ///   `√(s − s₀)`: a corner, two points with radius 0, the second with
    ///   derivatives along `τ = √(s − s₀)` (`d_delta = d_force = 0`,
    ///   `d2_delta = 2 dᾱ/ds`, `d_radius = lim a/τ`); the interval after it is
    ///   sampled in τ.
    ///
    /// Above μ = 1 the path comes from the edge continuation
    /// (module `edge`): its neck phase (one fixed mesh) is sampled as
    /// above; its edge phase is a family of meshes scaled with the marker
    /// radius `m`, so there the parameter is `m`: derivatives by
    /// central differences in `m` (step 1e-4·w, each a solve on the mesh
    /// scaled to its marker), special points as roots
    /// in `m`, bisection in `m` (in
    /// `τ = √(m − m_c)` after an onset there), and turning points sought
    /// again between the dense samples (small folds of the discrete model
    /// near the jump-out on coarse grids are kept as extra branches, not
    /// smoothed). The two phases share their junction state, so the path is
    /// continuous. Each edge-phase point costs three solves (five where the
    /// contact radius jumps): a table at N = 256 takes about 2 s at μ = 3
    /// and at μ = 10 (release).
    ///
    /// Errors: [`Error::InvalidArgument`] for a tolerance outside
    /// [1e-10, 0.1] or `max_force ≤ 0`; the continuation's errors.
    pub fn path_samples(&self, tolerance: f64) -> Result<LjPathSamples> {
        let tol = check::in_range("tolerance", tolerance, 1e-10, 0.1, "in [1e-10, 0.1]")?;
        let f_end = check::positive("max_force", self.opts.max_force)?;
        if self.mu == 0.0 {
            return Err(Error::InvalidArgument {
                name: "tabor_parameter",
                value: 0.0,
                bound: "> 0 (a rigid sphere never comes into contact)",
            });
        }
        // Coarse continuation beyond the end: the states past `f_end` are the
        // deep tail checks.
        let f_tail = 3.0 * f_end;
        let base_gap = 6.0 + 4.0 * self.mu.sqrt();
        let target = (self.opts.target_points as f64 * (self.opts.start_gap / base_gap).max(1.0))
            .ceil() as usize;
        // The fixed-mesh states (the neck phase above μ = 1) and the
        // edge-phase states, whose first one is the last fixed-mesh state.
        let (neck_solver, states, edge_states, plan, mut bw) = match self.band_plan() {
            None => {
                let (states, bw) = self.path_march(f_tail, target, &|_| false)?;
                (None, states, Vec::new(), (0.0, 0.0), bw)
            }
            Some(plan) => {
                let p = self.edge_march(plan, f_tail, target, true, &|_| false)?;
                (Some(p.neck_solver), p.neck, p.edge, plan, p.bw)
            }
        };
        let ns = neck_solver.as_ref().unwrap_or(self);
        let nn = ns.n();
        let end_at = |f: f64| f >= f_end;
        // Fixed-mesh nodes up to the end.
        let i_end = states
            .iter()
            .position(|s| end_at(s.pt.force))
            .unwrap_or(states.len() - 1);
        let mut nodes: Vec<Node> = Vec::with_capacity(i_end + 8);
        for st in &states[..=i_end] {
            let e = ns.exactify(st, &mut bw)?;
            nodes.push(ns.node(e, Kind::Regular)?);
        }
        // Edge-phase nodes up to the end (none when the fixed mesh ended).
        let mut enodes: Vec<ENode> = Vec::new();
        if i_end + 1 == states.len() && !edge_states.is_empty() {
            let j_end = edge_states
                .iter()
                .position(|e| end_at(e.st.pt.force))
                .unwrap_or(edge_states.len() - 1);
            for e in &edge_states[..=j_end] {
                enodes.push(self.enode(e.clone(), Kind::Regular, plan, &mut bw)?);
            }
        }
        let deep: Vec<(f64, f64, f64)> = if enodes.is_empty() {
            states[i_end + 1..]
                .iter()
                .map(|s| (s.al, s.pt.force, s.pt.contact_radius))
                .collect()
        } else {
            edge_states[enodes.len()..]
                .iter()
                .map(|e| (e.st.al, e.st.pt.force, e.st.pt.contact_radius))
                .collect()
        };
        let ta = |s: &State| s.t[nn];
        // Turning points.
        let mut i = 0;
        while i + 1 < nodes.len() {
            let (a, b) = (ta(&nodes[i].st), ta(&nodes[i + 1].st));
            if a * b < 0.0 && nodes[i].kind == Kind::Regular && nodes[i + 1].kind == Kind::Regular {
                let st = ns.path_root(&nodes[i].st, &nodes[i + 1].st, &mut bw, &ta, 0.0)?;
                let d2 = ns.second_derivative(&st, &mut bw)?;
                let nd = ns.node(st, Kind::Turn(d2))?;
                nodes.insert(i + 1, nd);
                i += 2;
            } else {
                i += 1;
            }
        }
        let mut i = 0;
        while i + 1 < enodes.len() {
            if enodes[i].d[0] * enodes[i + 1].d[0] < 0.0 {
                let e = self.eroot(&enodes[i], &enodes[i + 1], plan, &mut bw, &|e| e.d[0])?;
                let d2 = self.esecond(&e, plan, &mut bw)?;
                let mut e = e;
                e.kind = Kind::Turn(d2);
                enodes.insert(i + 1, e);
                i += 2;
            } else {
                i += 1;
            }
        }
        // Contact onset.
        let gap = |s: &State| s.h0 - 1.0;
        if let Some(i) =
            (0..nodes.len() - 1).find(|&i| gap(&nodes[i].st) > 0.0 && gap(&nodes[i + 1].st) <= 0.0)
        {
            let st = if gap(&nodes[i + 1].st) == 0.0 {
                nodes[i + 1].st.clone()
            } else {
                ns.path_root(&nodes[i].st, &nodes[i + 1].st, &mut bw, &gap, 0.0)?
            };
            let g = ns.onset_slope(&st, &mut bw)?;
            let mut nd = ns.node(st, Kind::Corner(g))?;
            nd.st.pt.contact_radius = 0.0;
            nd.d[2] = 0.0;
            if gap(&nodes[i + 1].st) == 0.0 {
                nodes[i + 1] = nd;
            } else {
                nodes.insert(i + 1, nd);
            }
        } else if let Some(i) = (0..enodes.len().saturating_sub(1))
            .find(|&i| gap(&enodes[i].e.st) > 0.0 && gap(&enodes[i + 1].e.st) <= 0.0)
        {
            let mut e = self.eroot(&enodes[i], &enodes[i + 1], plan, &mut bw, &|e| gap(&e.e.st))?;
            let g = self.eonset_slope(&e, plan, &mut bw)?;
            e.kind = Kind::Corner(g);
            e.e.st.pt.contact_radius = 0.0;
            e.d[2] = 0.0;
            enodes.insert(i + 1, e);
        }
        // Force minimum and zero on the last stable piece (fixed-mesh
        // nodes, then edge-phase nodes).
        let not_found = Error::NotConverged {
            what: "LJ sphere path samples: no force minimum on the last stable piece",
            iterations: 0,
            residual: f64::NAN,
        };
        let last_turn_e = enodes
            .iter()
            .rposition(|nd| matches!(nd.kind, Kind::Turn(_)));
        let last_turn = nodes
            .iter()
            .rposition(|nd| matches!(nd.kind, Kind::Turn(_)))
            .unwrap_or(0);
        // The load-controlled pull-off is the last minimum (the one a
        // retraction from deep contact under load control reaches first).
        let emin = (last_turn_e.unwrap_or(0)..enodes.len().saturating_sub(1))
            .rev()
            .find(|&i| enodes[i].d[1] < 0.0 && enodes[i + 1].d[1] >= 0.0);
        let neck_min = if emin.is_some() || last_turn_e.is_some() {
            None
        } else {
            (last_turn..nodes.len() - 1)
                .rev()
                .find(|&i| nodes[i].d[1] < 0.0 && nodes[i + 1].d[1] >= 0.0)
        };
        let force = |s: &State| s.pt.force;
        let (f_min, a_min);
        if let Some(imin) = neck_min {
            let dfs = |s: &State| s.df;
            let st = ns.path_root(&nodes[imin].st, &nodes[imin + 1].st, &mut bw, &dfs, 0.0)?;
            let nd = ns.node(st, Kind::Min)?;
            (f_min, a_min) = (nd.st.pt.force, nd.st.pt.contact_radius);
            nodes.insert(imin + 1, nd);
        } else {
            let imin = emin.ok_or(not_found)?;
            let mut e = self.eroot(&enodes[imin], &enodes[imin + 1], plan, &mut bw, &|e| e.d[1])?;
            e.kind = Kind::Min;
            (f_min, a_min) = (e.e.st.pt.force, e.e.st.pt.contact_radius);
            enodes.insert(imin + 1, e);
        }
        let imin_n = nodes.iter().position(|nd| nd.kind == Kind::Min);
        let zero_n = imin_n.and_then(|imin| {
            (imin + 1..nodes.len() - 1)
                .find(|&i| force(&nodes[i].st) < 0.0 && force(&nodes[i + 1].st) >= 0.0)
        });
        if let Some(i) = zero_n {
            let st = ns.path_root(&nodes[i].st, &nodes[i + 1].st, &mut bw, &force, 0.0)?;
            let nd = ns.node(st, Kind::Zero)?;
            nodes.insert(i + 1, nd);
        } else {
            // After the minimum: all the edge phase when the minimum is on
            // the fixed mesh.
            let from = enodes
                .iter()
                .position(|nd| nd.kind == Kind::Min)
                .unwrap_or(0);
            if let Some(i) = (from..enodes.len().saturating_sub(1))
                .find(|&i| force(&enodes[i].e.st) < 0.0 && force(&enodes[i + 1].e.st) >= 0.0)
            {
                let mut e = self.eroot(&enodes[i], &enodes[i + 1], plan, &mut bw, &|e| {
                    force(&e.e.st)
                })?;
                e.kind = Kind::Zero;
                enodes.insert(i + 1, e);
            }
        }
        // Error scales.
        // tol/8 as specified, halved again after the contact onset, where
        // the table interpolates in √(Δ − Δ_onset) rather than along τ.
        let crit = Crit {
            tol: tol / 16.0,
            d_abs: 0.1,
            f_floor: 1e-3 * f_min.abs(),
            a_floor: 1e-3 * a_min.max(1e-3),
        };
        // Dense sampling.
        let mut out: Vec<PathPoint> = Vec::new();
        let mut marks = Marks::default();
        for k in 0..nodes.len() {
            let nd = &nodes[k];
            marks.push(&mut out, path_point(&nd.st, nd.d), nd.kind, nd.d[0]);
            if k + 1 < nodes.len() {
                ns.sample_interval(nd, &nodes[k + 1], &crit, &mut bw, &mut out)?;
            }
        }
        // Edge phase: densified first, then turning points between dense
        // neighbours (the discrete model's small folds, which the coarse
        // nodes can step over) refined, then emitted.
        let mut dense: Vec<ENode> = Vec::with_capacity(4 * enodes.len());
        for k in 0..enodes.len() {
            dense.push(enodes[k].clone());
            if k + 1 < enodes.len() {
                self.esample_interval(
                    &enodes[k],
                    &enodes[k + 1],
                    plan,
                    &crit,
                    &mut bw,
                    &mut dense,
                )?;
            }
        }
        let mut i = 0;
        while i + 1 < dense.len() {
            let (a, b) = (&dense[i], &dense[i + 1]);
            let plain = |k: Kind| matches!(k, Kind::Regular | Kind::Min | Kind::Zero);
            // ᾱ moving against dᾱ/dm at both ends: a pair of turning points
            // inside; split until the signs show them.
            let hidden = a.d[0] * b.d[0] > 0.0
                && (b.e.st.al - a.e.st.al) * a.d[0] < 0.0
                && b.e.m - a.e.m > MIN_SAMPLE_STEP * plan.0;
            if hidden && plain(a.kind) && plain(b.kind) {
                let mid = self.esolve(0.5 * (a.e.m + b.e.m), &a.e, &b.e, plan, &mut bw)?;
                let nd = self.enode(mid, Kind::Regular, plan, &mut bw)?;
                dense.insert(i + 1, nd);
                continue;
            }
            if a.d[0] * b.d[0] < 0.0 && plain(a.kind) && plain(b.kind) {
                let mut e = self.eroot(a, b, plan, &mut bw, &|e| e.d[0])?;
                e.kind = Kind::Turn(self.esecond(&e, plan, &mut bw)?);
                dense.insert(i + 1, e);
                i += 2;
            } else {
                i += 1;
            }
        }
        for (k, nd) in dense.iter().enumerate() {
            // The first edge node is the last fixed-mesh node.
            if k > 0 || nodes.is_empty() {
                marks.push(&mut out, path_point(&nd.e.st, nd.d), nd.kind, nd.d[0]);
            }
        }
        // Tail checks: far (larger central gaps) and deep (beyond the end).
        let mut tail_checks = Vec::new();
        let g0 = self.opts.start_gap;
        for f in [1.25, 1.5, 2.0, 3.0, 5.0, 10.0] {
            let s = ns.solve_at_central_gap(g0 * f, None)?;
            tail_checks.push(PathPoint {
                delta: s.approach,
                force: s.force,
                radius: s.contact_radius,
                d_delta: 1.0,
                d_force: 0.0,
                d_radius: 0.0,
                d2_delta: 0.0,
            });
        }
        let deep_checks = deep
            .into_iter()
            .map(|(delta, force, radius)| PathPoint {
                delta,
                force,
                radius,
                d_delta: 1.0,
                d_force: 0.0,
                d_radius: 0.0,
                d2_delta: 0.0,
            })
            .collect();
        let Some(pull) = marks.pull else {
            return Err(not_found);
        };
        Ok(LjPathSamples {
            points: out,
            tail_checks,
            deep_checks,
            jump_in: marks.jump_in,
            jump_out: marks.jump_out,
            pull_off_load: pull,
            contact_onset: marks.onset,
            iterations: bw.w.iterations,
            factorizations: bw.w.factorizations,
        })
    }

    /// d²ᾱ/ds² at a turning point, by central differences of the exact
    /// tangent at `±h` along it.
    fn second_derivative(&self, st: &State, bw: &mut BWork) -> Result<f64> {
        let n = self.n();
        let h = 1e-4;
        let mut g = [0.0; 2];
        for (q, sg) in [1.0, -1.0].into_iter().enumerate() {
            let guess = (
                st.y.iter()
                    .zip(&st.t)
                    .map(|(y, t)| y + sg * h * t)
                    .collect(),
                st.al + sg * h * st.t[n],
            );
            let s = self.path_step(st, sg * h, Some(guess), bw, true)?;
            g[q] = s.t[n] / self.chart_cos(st, &s);
        }
        Ok((g[0] - g[1]) / (2.0 * h))
    }

    /// `lim a/τ` at the contact onset `st` (τ = √σ, σ along the tangent), by
    /// Richardson extrapolation from τ = h, 2h.
    fn onset_slope(&self, st: &State, bw: &mut BWork) -> Result<f64> {
        let n = self.n();
        let h = 1e-3;
        let mut a = [0.0; 2];
        for (q, tau) in [h, 2.0 * h].into_iter().enumerate() {
            let sig = tau * tau;
            let guess = (
                st.y.iter().zip(&st.t).map(|(y, t)| y + sig * t).collect(),
                st.al + sig * st.t[n],
            );
            a[q] = self
                .path_step(st, sig, Some(guess), bw, true)?
                .pt
                .contact_radius;
        }
        Ok(2.0 * a[0] / h - a[1] / (2.0 * h))
    }

    /// Points strictly between the nodes `a` and `b` (bisection in the chart
    /// of `a`: σ along its tangent, or τ = √σ after a corner).
    fn sample_interval(
        &self,
        a: &Node,
        b: &Node,
        c: &Crit,
        bw: &mut BWork,
        out: &mut Vec<PathPoint>,
    ) -> Result<()> {
        let corner = matches!(a.kind, Kind::Corner(_));
        let sb = self.chart_proj(&a.st, &b.st);
        if !(sb > 0.0) {
            return Err(Error::NotConverged {
                what: "LJ sphere path samples: neighbouring points out of order",
                iterations: 0,
                residual: sb,
            });
        }
        let pb = if corner { sb.sqrt() } else { sb };
        // Values and derivatives with respect to the chart parameter.
        let chart = |nd: &Node, p: f64| -> [(f64, f64); 3] {
            let v = [nd.st.al, nd.st.pt.force, nd.st.pt.contact_radius];
            if corner && p == 0.0 {
                let Kind::Corner(g) = a.kind else {
                    unreachable!()
                };
                return [(v[0], 0.0), (v[1], 0.0), (0.0, g)];
            }
            let cs = self.chart_cos(&a.st, &nd.st);
            let k = if corner { 2.0 * p / cs } else { 1.0 / cs };
            [
                (v[0], nd.d[0] * k),
                (v[1], nd.d[1] * k),
                (v[2], nd.d[2] * k),
            ]
        };
        let la = chart(a, 0.0);
        let lb = chart(b, pb);
        self.bisect_chart(a, corner, (0.0, &a.st, la), (pb, &b.st, lb), c, bw, out, 0)
    }

    #[allow(clippy::too_many_arguments, clippy::type_complexity)]
    fn bisect_chart(
        &self,
        anchor: &Node,
        corner: bool,
        l: (f64, &State, [(f64, f64); 3]),
        r: (f64, &State, [(f64, f64); 3]),
        c: &Crit,
        bw: &mut BWork,
        out: &mut Vec<PathPoint>,
        depth: u32,
    ) -> Result<()> {
        let pm = 0.5 * (l.0 + r.0);
        let sig = |p: f64| if corner { p * p } else { p };
        let (sl, sr, sm) = (sig(l.0), sig(r.0), sig(pm));
        if sr - sl < MIN_SAMPLE_STEP {
            // Below the resolution of the converged states (Newton residual
            // 1e-10): a midpoint would carry rounding noise, not the path
            // (its approach may even step backwards). The interval is
            // accepted as it is.
            return Ok(());
        }
        let th = (sm - sl) / (sr - sl);
        let guess = (
            l.1.y
                .iter()
                .zip(&r.1.y)
                .map(|(p, q)| p + th * (q - p))
                .collect(),
            l.1.al + th * (r.1.al - l.1.al),
        );
        let st = self.path_step(&anchor.st, sm, Some(guess), bw, true)?;
        let e = if corner { (1e-3 * sm).min(1e-6) } else { 1e-6 };
        let d = self.path_derivs(&st, e)?;
        let mnode = Node {
            st,
            kind: Kind::Regular,
            d,
        };
        let cs = self.chart_cos(&anchor.st, &mnode.st);
        let k = if corner { 2.0 * pm / cs } else { 1.0 / cs };
        let vm = [
            (mnode.st.al, d[0] * k),
            (mnode.st.pt.force, d[1] * k),
            (mnode.st.pt.contact_radius, d[2] * k),
        ];
        let ok = hermite_ok(&l.2, &r.2, &vm, r.0 - l.0, c);
        if ok || depth >= 30 {
            out.push(path_point(&mnode.st, d));
            return Ok(());
        }
        let m = (pm, &mnode.st, vm);
        self.bisect_chart(anchor, corner, l, (m.0, m.1, m.2), c, bw, out, depth + 1)?;
        out.push(path_point(&mnode.st, d));
        self.bisect_chart(anchor, corner, m, r, c, bw, out, depth + 1)
    }
}

/// Marker step of the differences in the edge phase, relative to
/// the band half-width `w` (states are converged to ~1e-12: derivatives to
/// ~1e-8, truncation ~1e-8 w²·(third derivative)).
const EDGE_DIFF: f64 = 1e-4;

impl LjSolver {
    /// The edge-phase equilibrium at the marker `m` between the nodes `l`
    /// and `r` (guess interpolated between them in the frame of the
    /// marker; the nearer node's state if that fails).
    fn esolve(
        &self,
        m: f64,
        l: &EdgeState,
        r: &EdgeState,
        plan: (f64, f64),
        bw: &mut BWork,
    ) -> Result<EdgeState> {
        let th = (m - l.m) / (r.m - l.m);
        let s = l.st.s + th * (r.st.s - l.st.s);
        match self.edge_solve(m, plan, &[(l, 1.0 - th), (r, th)], s, bw) {
            Ok(e) => Ok(e),
            Err(_) => {
                let near = if th < 0.5 { l } else { r };
                self.edge_solve(m, plan, &[(near, 1.0)], s, bw)
            }
        }
    }

    /// (ᾱ, P̄, a) of the edge-phase equilibrium at `m`, from the guess `e`.
    fn evals(&self, e: &EdgeState, m: f64, plan: (f64, f64), bw: &mut BWork) -> Result<[f64; 3]> {
        let x = self.edge_solve(m, plan, &[(e, 1.0)], e.st.s, bw)?;
        Ok([x.st.al, x.st.pt.force, x.st.pt.contact_radius])
    }

    /// An edge-phase node: `e` with its derivatives in the marker radius by
    /// central differences of step [`EDGE_DIFF`]·w (the edge family is
    /// smooth in `m`, `edge` module docs).
    fn enode(&self, e: EdgeState, kind: Kind, plan: (f64, f64), bw: &mut BWork) -> Result<ENode> {
        let h = EDGE_DIFF * plan.0;
        let v0 = [e.st.al, e.st.pt.force, e.st.pt.contact_radius];
        let mut d = [0.0; 3];
        let vp = self.evals(&e, e.m + h, plan, bw)?;
        let vm = self.evals(&e, e.m - h, plan, bw)?;
        for k in 0..3 {
            d[k] = (vp[k] - vm[k]) / (2.0 * h);
        }
        // The contact radius (first root of h̄ = 1) jumps where a dip of
        // the gap beyond it reaches h̄ = 1 (at μ = 10 from 0.12 to 0.25
        // in the neck). Its one-sided differences then disagree far
        // beyond the curvature term: take the side whose three points
        // agree.
        let (dl, dr) = (v0[2] - vm[2], vp[2] - v0[2]);
        if (dr - dl).abs() > 0.5 * dl.abs().max(dr.abs()) + 1e-9 * h {
            let vm2 = self.evals(&e, e.m - 2.0 * h, plan, bw)?;
            let vp2 = self.evals(&e, e.m + 2.0 * h, plan, bw)?;
            let cl = (v0[2] - 2.0 * vm[2] + vm2[2]).abs();
            let cr = (v0[2] - 2.0 * vp[2] + vp2[2]).abs();
            d[2] = if cr <= cl {
                (-3.0 * v0[2] + 4.0 * vp[2] - vp2[2]) / (2.0 * h)
            } else {
                (3.0 * v0[2] - 4.0 * vm[2] + vm2[2]) / (2.0 * h)
            };
        }
        if e.st.pt.contact_radius == 0.0 {
            d[2] = 0.0;
        }
        if !d.iter().all(|x| x.is_finite()) {
            return Err(unresolved(0, f64::NAN));
        }
        Ok(ENode { e, kind, d })
    }

    /// d²ᾱ/dm² at an edge-phase turning point: the central second
    /// difference of step 10·[`EDGE_DIFF`]·w.
    fn esecond(&self, nd: &ENode, plan: (f64, f64), bw: &mut BWork) -> Result<f64> {
        let e = &nd.e;
        let step = 10.0 * EDGE_DIFF * plan.0;
        let ap = self.evals(e, e.m + step, plan, bw)?[0];
        let am = self.evals(e, e.m - step, plan, bw)?[0];
        Ok((ap - 2.0 * e.st.al + am) / (step * step))
    }

    /// `lim a/τ` at an edge-phase contact onset (τ = √(m − m_c)), by
    /// Richardson extrapolation from τ = h, 2h.
    fn eonset_slope(&self, nd: &ENode, plan: (f64, f64), bw: &mut BWork) -> Result<f64> {
        let h = 1e-3 * plan.0.sqrt();
        let e = &nd.e;
        let mut a = [0.0; 2];
        for (q, tau) in [h, 2.0 * h].into_iter().enumerate() {
            a[q] = self
                .edge_solve(e.m + tau * tau, plan, &[(e, 1.0)], e.st.s, bw)?
                .st
                .pt
                .contact_radius;
        }
        Ok(2.0 * a[0] / h - a[1] / (2.0 * h))
    }

    /// The edge-phase node between `l` and `r` where `phi` changes sign
    /// (Illinois method on the marker radius).
    fn eroot(
        &self,
        l: &ENode,
        r: &ENode,
        plan: (f64, f64),
        bw: &mut BWork,
        phi: &dyn Fn(&ENode) -> f64,
    ) -> Result<ENode> {
        let (mut a, mut fa) = (l.e.m, phi(l));
        let (mut b, mut fb) = (r.e.m, phi(r));
        if fa == 0.0 {
            return Ok(l.clone());
        }
        if fb == 0.0 {
            return Ok(r.clone());
        }
        let tol = 1e-10 * (r.e.m.abs() + plan.0);
        let mut best: Option<ENode> = None;
        for _ in 0..60 {
            let m = (a * fb - b * fa) / (fb - fa);
            let m = if m.is_finite() && (m - a) * (m - b) < 0.0 {
                m
            } else {
                0.5 * (a + b)
            };
            let e = self.esolve(m, &l.e, &r.e, plan, bw)?;
            let nd = self.enode(e, Kind::Regular, plan, bw)?;
            let f = phi(&nd);
            if f * fb < 0.0 {
                a = b;
                fa = fb;
            } else {
                fa *= 0.5;
            }
            b = m;
            fb = f;
            best = Some(nd);
            if f == 0.0 || (a - b).abs() < tol {
                break;
            }
        }
        best.ok_or(Error::NotConverged {
            what: "LJ sphere special point (edge phase)",
            iterations: 0,
            residual: f64::NAN,
        })
    }

    /// Nodes strictly between the edge-phase nodes `a` and `b` (bisection
    /// in the marker radius, or in τ = √(m − m_a) after a corner).
    fn esample_interval(
        &self,
        a: &ENode,
        b: &ENode,
        plan: (f64, f64),
        c: &Crit,
        bw: &mut BWork,
        out: &mut Vec<ENode>,
    ) -> Result<()> {
        let corner = matches!(a.kind, Kind::Corner(_));
        let dm = b.e.m - a.e.m;
        if !(dm > 0.0) {
            return Err(Error::NotConverged {
                what: "LJ sphere path samples: edge-phase points out of order",
                iterations: 0,
                residual: dm,
            });
        }
        let pb = if corner { dm.sqrt() } else { dm };
        let la = echart(a, a, corner, 0.0);
        let lb = echart(a, b, corner, pb);
        self.ebisect(a, corner, (0.0, a, la), (pb, b, lb), plan, c, bw, out, 0)
    }

    #[allow(clippy::too_many_arguments, clippy::type_complexity)]
    fn ebisect(
        &self,
        anchor: &ENode,
        corner: bool,
        l: (f64, &ENode, [(f64, f64); 3]),
        r: (f64, &ENode, [(f64, f64); 3]),
        plan: (f64, f64),
        c: &Crit,
        bw: &mut BWork,
        out: &mut Vec<ENode>,
        depth: u32,
    ) -> Result<()> {
        let pm = 0.5 * (l.0 + r.0);
        let mm = anchor.e.m + if corner { pm * pm } else { pm };
        if r.1.e.m - l.1.e.m < MIN_SAMPLE_STEP * plan.0 {
            return Ok(());
        }
        let e = self.esolve(mm, &l.1.e, &r.1.e, plan, bw)?;
        let mnode = self.enode(e, Kind::Regular, plan, bw)?;
        let vm = echart(anchor, &mnode, corner, pm);
        if hermite_ok(&l.2, &r.2, &vm, r.0 - l.0, c) || depth >= 30 {
            out.push(mnode);
            return Ok(());
        }
        let m = (pm, &mnode, vm);
        self.ebisect(
            anchor,
            corner,
            l,
            (m.0, m.1, m.2),
            plan,
            c,
            bw,
            out,
            depth + 1,
        )?;
        out.push(mnode.clone());
        self.ebisect(anchor, corner, m, r, plan, c, bw, out, depth + 1)
    }
}

/// Values and derivatives of an edge-phase node with respect to the chart
/// parameter `p` of an interval anchored at `anchor` (`m − m_a = p`, or `p²`
/// after a corner).
fn echart(anchor: &ENode, nd: &ENode, corner: bool, p: f64) -> [(f64, f64); 3] {
    let v = [nd.e.st.al, nd.e.st.pt.force, nd.e.st.pt.contact_radius];
    if corner && p == 0.0 {
        let g = match anchor.kind {
            Kind::Corner(g) => g,
            _ => 0.0,
        };
        return [(v[0], 0.0), (v[1], 0.0), (0.0, g)];
    }
    let k = if corner { 2.0 * p } else { 1.0 };
    [
        (v[0], nd.d[0] * k),
        (v[1], nd.d[1] * k),
        (v[2], nd.d[2] * k),
    ]
}

/// Whether the cubic Hermite midpoints of `l`, `r` (interval length `h`)
/// reproduce the exact midpoint values `m` to the criterion `c`.
fn hermite_ok(
    l: &[(f64, f64); 3],
    r: &[(f64, f64); 3],
    m: &[(f64, f64); 3],
    h: f64,
    c: &Crit,
) -> bool {
    let floors = [f64::INFINITY, c.f_floor, c.a_floor];
    (0..3).all(|q| {
        let y = hermite_mid(l[q].0, l[q].1, r[q].0, r[q].1, h);
        let err = (y - m[q].0).abs();
        if q == 0 {
            err <= c.tol * c.d_abs
        } else {
            err <= c.tol * m[q].0.abs().max(floors[q])
        }
    })
}

/// Smallest path-parameter interval `bisect_chart` subdivides: the
/// converged states are accurate to ~1e-10, so the path is not resolved
/// below this.
const MIN_SAMPLE_STEP: f64 = 1e-8;

fn my_dot(w: f64, a: &[f64], b: &[f64]) -> f64 {
    w * a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>()
}

fn path_point(st: &State, d: [f64; 3]) -> PathPoint {
    PathPoint {
        delta: st.al,
        force: st.pt.force,
        radius: st.pt.contact_radius,
        d_delta: d[0],
        d_force: d[1],
        d_radius: d[2],
        d2_delta: 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::{EdgeState, Kind, EDGE_DIFF};
    use crate::contact::lj_sphere::LjSphere;

    /// At μ = 10, N = 256 the edge-phase family is smooth through the
    /// jump-out: ᾱ(m) on 13 equally spaced markers around its minimum has
    /// third differences far below its second differences, and the node's
    /// central-difference slope matches the secant of nearby values on both
    /// sides. (A mesh banded about each marker would have a corner there,
    /// where a node crosses the marker: dᾱ/dm jumps from −0.004 to +0.40, a
    /// third difference as large as the second.)
    #[test]
    fn edge_family_is_smooth_through_the_jump_out() {
        let sv = LjSphere::from_tabor(10.0).unwrap().solver(256).unwrap();
        let plan = sv.band_plan().unwrap();
        let path = sv
            .edge_march(plan, 1.0, 120, true, &|e: &[EdgeState]| {
                e[e.len() - 1].st.pt.force < -0.9
            })
            .unwrap();
        let mut bw = path.bw;
        let edge = &path.edge;
        // The coarse state of least approach: the jump-out is next to it.
        let k = (1..edge.len() - 1)
            .min_by(|&a, &b| edge[a].st.al.total_cmp(&edge[b].st.al))
            .unwrap();
        let (lo, hi) = (edge[k - 1].m, edge[k + 1].m);
        let g = &edge[k];
        let mut al = Vec::new();
        for q in 0..13 {
            let m = lo + (hi - lo) * q as f64 / 12.0;
            al.push(
                sv.edge_solve(m, plan, &[(g, 1.0)], 0.0, &mut bw)
                    .unwrap()
                    .st
                    .al,
            );
        }
        let d2: Vec<f64> = al.windows(3).map(|w| w[2] - 2.0 * w[1] + w[0]).collect();
        let d3 = d2
            .windows(2)
            .fold(0.0f64, |m, w| m.max((w[1] - w[0]).abs()));
        let d2min = d2.iter().fold(f64::INFINITY, |m, v| m.min(*v));
        assert!(d2min > 0.0, "ᾱ(m) not convex through the jump-out: {d2:?}");
        assert!(
            d3 < 0.1 * d2min,
            "third difference {d3} against second {d2min}"
        );
        let h = EDGE_DIFF * plan.0;
        let nd = sv.enode(g.clone(), Kind::Regular, plan, &mut bw).unwrap();
        for side in [-1.0f64, 1.0] {
            let near = sv
                .edge_solve(g.m + side * 0.5 * h, plan, &[(g, 1.0)], 0.0, &mut bw)
                .unwrap();
            let secant = (near.st.al - g.st.al) / (near.m - g.m);
            let tol = 1e-3 + 0.02 * secant.abs();
            assert!(
                (nd.d[0] - secant).abs() < tol,
                "side {side}: dᾱ/dm {} against secant {secant}",
                nd.d[0]
            );
        }
        assert!(sv.esecond(&nd, plan, &mut bw).unwrap() > 0.0);
    }
}
