//! Edge continuation for μ > 1: the contact branch followed in the radius of
//! its edge zone, on a mesh that moves with the edge.
//!
//! # Why
//!
//! Above μ ≈ 1 the edge (cohesive) zone has width `~μ^{-3/2}` (units of
//! `√(Rz₀)`), while the contact radius travels from 0 (neck formation) to
//! `~3μ^{1/2}` (at `P̄ = 10`). On any mesh fixed in `r`, the log-gap of a
//! node changes by `O(1)` whenever the edge passes it, so a continuation in
//! the nodal unknowns advances the edge by a fraction of the zone width per
//! step: `O(μ²)` steps (≈ 10⁴ at μ = 10, 10⁶ at μ = 100).
//!
//! # How
//!
//! The curve is split at the moment the edge zone has formed:
//!
//! 1. **Neck phase**: pseudo-arclength continuation on one fixed mesh from
//!    far away through the jump-in until the edge marker `m` (first crossing
//!    of the peak-attraction gap `h̄ = 3^{1/6}` from the centre,
//!    [`LjSolver::edge_marker`]) reaches the switch marker
//!    `m_s = 0.75 w` (`w = clamp(N μ^{-3/2}/16, 0.01, 2)`), located exactly
//!    as a root along the path. The mesh ([`Mesh::marker`]) has a node at
//!    `m_s`, uniform cells of `4w/N` inside it (the neck's resolution), and
//!    cells falling geometrically towards that node from both sides. For
//!    curves and pull-offs, once the neck has spread over
//!    [`NECK_START`] cells the marker itself becomes the continuation
//!    parameter on this mesh, up to exactly `m_s`
//!    ([`LjSolver::neck_by_marker`]); the table sampler keeps the
//!    arclength march, whose closer states it bisects between.
//! 2. **Edge phase**: the marker itself is the continuation parameter, and
//!    the mesh at marker `m` is the neck mesh **scaled by `m/m_s`**, so the
//!    marker stays on its node. The displacement of a loaded disk is
//!    homogeneous of degree 1 (`D(λr, λc) = λD(r, c)`), so the scaled mesh's
//!    influence matrix is the neck mesh's times `m/m_s`: one matrix of
//!    elliptic integrals serves every marker ([`LjSolver::scaled`], `O(N)`
//!    per marker). The neck mesh's cells at `m_s` are finer than `4w/N` by
//!    the factor of the marker's travel up to `P̄ = max_force` (from the
//!    JKR radius), so that the largest marker still has cells of `4w/N` at
//!    its edge zone. The bordered system `[J 1; e_jᵀ 0]` (the log-gap at the
//!    marker's node `j` is `ln 3^{1/6}`) is solved by inexact Newton (GMRES
//!    on this marker's Jacobian, preconditioned by the last
//!    factorisation), from the secant extrapolation of the last two
//!    solutions node by node (a node keeps its place relative to the
//!    marker). The marker grows monotonically along the branch (neck →
//!    jump-out → pull-off → Hertz regime), as the contact radius of JKR and
//!    Maugis–Dugdale does.
//!
//! The discrete problem at marker `m` depends smoothly on `m` (the nodes,
//! the matrix and the parabola scale), so its solutions form a smooth
//! family: no node crosses the marker. A mesh of its own per marker, with a
//! band of fixed width centred on it, would let the nodes drift past the
//! marker, and the family would have a corner at each crossing and wiggles
//! between them: spurious folds of the contact branch (13 branches in the
//! μ = 10, N = 512 table, which then does not build; BENCHMARKS §3).
//!
//! The edge-phase path derivatives are taken along the family, by 3-point
//! differences in `m`: smooth, unlike the tangent of one fixed mesh, which
//! oscillates where the edge zone crosses its cells ("lattice trapping" of
//! the discrete problem). Turning points of ᾱ and the force minimum are
//! refined as extrema in `m` (Brent's method); the marker grows
//! monotonically along the branch, so an extremum in `m` is one along the
//! path.

use super::march::{StepMetric, KRYLOV_REFRESH};
use super::mesh::Mesh;
use super::numeric::{deriv3, stencil3};
use super::observe::is_unresolved;
use super::path::{self, BWork, Con, State};
use super::setup::jkr_radius_estimate;
use super::special::Special;
use super::{LjCurve, LjPullOff, LjSolver};
use crate::error::{Error, Result};

/// `ln 3^{1/6}`: the log-gap of the peak of the Lennard-Jones attraction.
pub(super) const MARK: f64 = 0.183_102_048_111_638_9;

/// The switch marker of the edge continuation, in band half-widths `w`.
///
/// In the arclength march the neck spreads over the fixed mesh of the neck
/// phase by steps of at most `DY_STEP` in a log-gap, so the neck phase's
/// cost grows with the switch marker (at μ = 10, N = 256 it takes 55 of the
/// curve's 220 states, the marker continuing it,
/// [`LjSolver::neck_by_marker`]). An earlier switch is cheaper but less
/// accurate, because the neck mesh then spreads its
/// geometric grading over a larger travel of the marker: pull-offs at
/// N = 256 of −1.509508, −1.509443, −1.509019, −1.508411 at μ = 10 and
/// −1.501963, −1.501438, −1.497187 at μ = 30 for 0.75 w, 0.5 w, 0.3 w and
/// 0.15 w (the last fails the resolution check at μ = 30), against
/// about −1.5093 and −1.5016 converged (BENCHMARKS §3).
const SWITCH: f64 = 0.75;

/// The neck phase continues in its marker once the marker has passed this
/// many cells of the neck mesh's core ([`LjSolver::neck_by_marker`]). The
/// μ = 3 and 10 curves at N = 256 took the same number of states (±4) for
/// 1, 2, 3 and 6.
const NECK_START: f64 = 3.0;

/// Target of the predictor's largest log-gap error per marker step of the
/// neck phase (0.05–0.2 gave the same states ±3 at μ = 3 and 10: the
/// step metric limits the steps).
const NECK_PREDICTOR: f64 = 0.05;

/// Number of edge-phase states through which the guess of the next one is
/// extrapolated in the marker. Newton iterations of the μ = 10, N = 256
/// curve (both phases) for 2 (the secant), 3, 4, 5 and 6 points: 771, 655,
/// 618, 560, 516. Four keeps the extrapolation of a smooth family well
/// inside the range where its polynomial is reliable with the step
/// changes of the march (at most 2× from one step to the next).
const EXTRAPOLATION_POINTS: usize = 4;

/// Relative tolerance on the marker radius of an extremum located by
/// [`LjSolver::edge_extremum`]. A tighter one spends solves on noise: the
/// force of states converged to a gap residual of `1e-10` scatters by about
/// `1e-8` from marker to marker (near the μ = 3, N = 256 pull-off, 1.4e-8
/// between markers 2.6e-7 apart, where `P̄'' ≈ 11`), so the location of a
/// minimum is not determined below about `√(1e-8/11) ≈ 3e-5`, while at
/// `δ = 1e-6·m` the extremised value is off by `½P̄''δ² ≈ 3e-11`. At 1e-9
/// Brent's method took 15–27 solves per extremum at μ = 3 and 10,
/// N = 256, at 1e-6 8–16, and the pull-off, jump points and hysteresis
/// agree to the six printed digits (the approach at the pull-off moves by
/// 3e-6; the grid's own error there is 5e-4).
const BRENT_RTOL: f64 = 1e-6;

/// One state of the edge phase: marker radius and the state on the family's
/// mesh scaled to it.
#[derive(Debug, Clone)]
pub(super) struct EdgeState {
    pub(super) m: f64,
    pub(super) st: State,
}

/// The guess `Σ w_k y_k` node by node: the edge family's meshes are one
/// mesh scaled by the marker, so a node keeps its place relative to the
/// marker.
fn scaled_guess(from: &[(&EdgeState, f64)]) -> (Vec<f64>, f64) {
    let n = from[0].0.st.y.len();
    let y = (0..n)
        .map(|i| from.iter().map(|(e, w)| w * e.st.y[i]).sum())
        .collect();
    let al = from.iter().map(|(e, w)| w * e.st.al).sum();
    (y, al)
}

/// The two phases of a large-μ continuation.
pub(super) struct EdgePath {
    /// Solver of the neck phase (band at the switch marker [`SWITCH`]` w`: the
    /// first edge-phase mesh).
    pub(super) neck_solver: LjSolver,
    /// Neck-phase states (on `neck_solver`'s mesh).
    pub(super) neck: Vec<State>,
    /// Edge-phase states, by increasing marker.
    pub(super) edge: Vec<EdgeState>,
    pub(super) bw: BWork,
    /// Band plan `(w, fraction)`.
    pub(super) plan: (f64, f64),
}

impl LjSolver {
    /// The band plan `(w, fraction)` of the edge continuation: `None` for
    /// μ ≤ 1 (the fixed mesh resolves the edge zone at N ≥ 64) or when the
    /// options fix a band.
    pub(super) fn band_plan(&self) -> Option<(f64, f64)> {
        if self.mu <= 1.0 || self.opts.edge_fraction > 0.0 {
            return None;
        }
        let e = self.mu.powf(-1.5);
        let w = (self.n() as f64 * e / 16.0).clamp(0.01, 2.0);
        Some((w, 0.5))
    }

    /// The edge marker: the first crossing of `h̄ = 3^{1/6}` (the peak of the
    /// attraction, inside the edge zone) from the centre, by linear
    /// interpolation of the log-gap between nodes; 0 when `h̄₀` is above it.
    /// It also follows the edge of the flat neck that forms at `h̄ ≈ 1.01`
    /// before contact at large μ, where the contact radius is still 0.
    pub(super) fn edge_marker(&self, y: &[f64]) -> f64 {
        let x = &self.mesh.x;
        if y[0] >= MARK {
            return 0.0;
        }
        for i in 1..y.len() {
            if y[i] >= MARK {
                let t = (MARK - y[i - 1]) / (y[i] - y[i - 1]);
                return x[i - 1] + t * (x[i] - x[i - 1]);
            }
        }
        x[x.len() - 1]
    }

    /// The solver of the edge family at the marker `a_e > 0`: the family's
    /// solver at the switch marker scaled by `a_e/m_s` (no new elliptic
    /// integrals; `edge` module docs).
    pub(super) fn at_marker(&self, a_e: f64, plan: (f64, f64)) -> Result<LjSolver> {
        if !(a_e > 0.0 && a_e.is_finite()) {
            return Err(Error::InvalidArgument {
                name: "edge marker",
                value: a_e,
                bound: "> 0",
            });
        }
        let base = self.family(plan)?;
        Ok(base.scaled(a_e / base.opts.edge_radius))
    }

    /// The edge family's solver at the switch marker `m_s = SWITCH·w`, built
    /// once per solver ([`Mesh::marker`]).
    fn family(&self, plan: (f64, f64)) -> Result<&LjSolver> {
        if let Some(f) = self.family.get() {
            return Ok(f);
        }
        let (w, frac) = plan;
        let n = self.n();
        let m_s = SWITCH * w;
        let h_in = 4.0 * w / n as f64;
        let m_end =
            (1.2 * jkr_radius_estimate(self.mu, self.opts.max_force.max(0.0))).max(2.0 * m_s);
        let h_a = h_in * m_s / m_end;
        let (mesh, _) = Mesh::marker(n, m_s, h_in, h_a, self.opts.outer_radius);
        let mut o = self.opts;
        o.edge_radius = m_s;
        o.edge_width = w;
        o.edge_fraction = frac;
        let built = LjSolver::with_mesh(self.mu, o, mesh)?;
        Ok(self.family.get_or_init(|| Box::new(built)))
    }

    /// Border row `c(m)` of the marker equation on this mesh: linear
    /// interpolation weights of the log-gap at `m` (`N+1`, 0 on ᾱ); on the
    /// edge family's meshes `m` is a node, and the row is `e_j` up to
    /// rounding.
    fn marker_row(&self, m: f64) -> Vec<f64> {
        let x = &self.mesh.x;
        let n = x.len();
        let mut row = vec![0.0; n + 1];
        let i = x.partition_point(|&v| v <= m).clamp(1, n - 1) - 1;
        let t = (m - x[i]) / (x[i + 1] - x[i]);
        row[i] = 1.0 - t;
        row[i + 1] = t;
        row
    }

    /// The equilibrium with the marker at `m`, on the family's mesh scaled to
    /// `m`, from the guess [`scaled_guess`] of the weighted states `from`.
    /// Its tangent and path derivatives are left for [`derivs_in_m`].
    pub(super) fn edge_solve(
        &self,
        m: f64,
        plan: (f64, f64),
        from: &[(&EdgeState, f64)],
        s: f64,
        bw: &mut BWork,
    ) -> Result<EdgeState> {
        let sv = self.at_marker(m, plan)?;
        let (mut y, mut al) = scaled_guess(from);
        let row = sv.marker_row(m);
        // Inexact Newton preconditioned by the last factorisation, although
        // it belongs to the previous marker: the meshes are one mesh scaled,
        // so node by node the Jacobians are close. GMRES acts on this
        // marker's true Jacobian and the factorisation is refreshed when it
        // needs more than a few iterations, as on a fixed mesh.
        sv.bnewton(&Con::Plane { row, c: MARK }, &mut y, &mut al, bw, false)?;
        let n = sv.n();
        let st = sv.make_state(&y, al, vec![0.0; n + 1], s, bw, false)?;
        Ok(EdgeState { m, st })
    }

    /// The neck and edge phases from far away until `P̄ ≥ max_force` or
    /// `stop(edge-phase states)` (see the module documentation).
    /// `dense_neck` keeps the neck phase in arclength up to the switch: the
    /// table sampler bisects between neck states along their tangents,
    /// which on the fixed mesh needs them as close as the arclength march
    /// puts them. Otherwise the neck phase continues in its marker once the
    /// neck has formed ([`LjSolver::neck_by_marker`]).
    pub(super) fn edge_march(
        &self,
        plan: (f64, f64),
        max_force: f64,
        target: usize,
        dense_neck: bool,
        stop: &dyn Fn(&[EdgeState]) -> bool,
    ) -> Result<EdgePath> {
        let (w, _) = plan;
        let m_switch = SWITCH * w;
        // The neck phase runs on the mesh banded at the switch marker, the
        // first edge mesh: the phases meet at one equilibrium of one
        // discrete problem, so the path is continuous across the switch.
        let neck_solver = self.at_marker(m_switch, plan)?;
        let ns = &neck_solver;
        // The march in arclength until the neck has spread over a few cells,
        // then in the marker up to the switch (`LjSolver::neck_by_marker`).
        let m_start = if dense_neck {
            m_switch
        } else {
            (NECK_START * 4.0 * w / self.n() as f64).min(m_switch)
        };
        let marker_at = |st: &[State], m: f64| ns.edge_marker(&st[st.len() - 1].y) >= m;
        let (mut neck, mut bw) =
            ns.path_march(max_force, target, &|st: &[State]| marker_at(st, m_start))?;
        let mut edge: Vec<EdgeState> = Vec::new();
        let done = |neck: &[State]| neck[neck.len() - 1].pt.force >= max_force || neck.len() < 2;
        // Whether the last neck state is exactly at the switch marker.
        let mut at_switch = false;
        if !done(&neck) && !marker_at(&neck, m_switch) {
            let metric = ns.step_metric(max_force, target);
            at_switch = ns
                .neck_by_marker(&mut neck, m_switch, max_force, &metric, &mut bw)
                .is_ok();
            if !at_switch {
                // Back to the arclength march from the last state reached,
                // with the last step's length.
                bw.invalidate();
                let k = neck.len();
                let sigma = neck[k - 1].s - neck[k - 2].s;
                ns.march_on(
                    &mut neck,
                    &mut bw,
                    max_force,
                    target,
                    sigma,
                    &|st: &[State]| marker_at(st, m_switch),
                )?;
            }
        }
        if done(&neck) {
            return Ok(EdgePath {
                neck_solver,
                neck,
                edge,
                bw,
                plan,
            });
        }
        let k = neck.len();
        // The junction: the neck state whose marker is exactly the switch
        // marker (the last one of the marker continuation, or a root along
        // the path), then the same equilibrium under the marker equation.
        let junction = if at_switch {
            neck[k - 1].clone()
        } else {
            let phi = |st: &State| ns.edge_marker(&st.y) - m_switch;
            ns.path_root(&neck[k - 2], &neck[k - 1], &mut bw, &phi, 0.0)?
        };
        let junction_state = EdgeState {
            m: m_switch,
            st: junction.clone(),
        };
        let e0 = self.edge_solve(
            m_switch,
            plan,
            &[(&junction_state, 1.0)],
            junction.s,
            &mut bw,
        )?;
        neck[k - 1] = junction;
        edge.push(e0);
        let metric = self.step_metric(max_force, target);
        let mut dm = 0.5 * w;
        let mut fails = 0u32;
        let mut guard = 0usize;
        loop {
            let k = edge.len();
            let cur = &edge[k - 1];
            if cur.st.pt.force >= max_force || stop(&edge) {
                break;
            }
            guard += 1;
            if guard > 20 * target.max(10) {
                return Err(Error::NotConverged {
                    what: "LJ sphere edge continuation (too many steps)",
                    iterations: bw.w.iterations.min(u32::MAX as u64) as u32,
                    residual: bw.w.max_residual,
                });
            }
            let m = cur.m + dm;
            // Lagrange extrapolation in the marker through the last
            // EXTRAPOLATION_POINTS states, node by node (the family is
            // smooth in m); the last state alone after a failure.
            let from: Vec<(&EdgeState, f64)> = if fails == 0 && k >= 2 {
                let pts: Vec<&EdgeState> = edge[k.saturating_sub(EXTRAPOLATION_POINTS)..]
                    .iter()
                    .collect();
                pts.iter()
                    .enumerate()
                    .map(|(i, e)| {
                        let l = pts
                            .iter()
                            .enumerate()
                            .filter(|&(j, _)| j != i)
                            .map(|(_, o)| (m - o.m) / (e.m - o.m))
                            .product::<f64>();
                        (*e, l)
                    })
                    .collect()
            } else {
                vec![(cur, 1.0)]
            };
            // Refresh the factorisation once it needed more than a few GMRES
            // iterations, as the fixed-mesh march does: an LU costs about a
            // dozen iterations, while a stale one lets the edge phase spend
            // some 30 iterations per marker at μ = 10.
            if bw.krylov > KRYLOV_REFRESH {
                bw.invalidate();
            }
            match self.edge_solve(m, plan, &from, 0.0, &mut bw) {
                Err(e) => {
                    dm *= 0.5;
                    fails += 1;
                    if fails > 30 || dm < 1e-9 * (1.0 + cur.m) {
                        return Err(e);
                    }
                }
                Ok(mut es) => {
                    let ds = metric.dist(&cur.st.pt, &es.st.pt);
                    let ratio = ds / metric.target;
                    if ratio > 3.0 {
                        dm *= (0.8 / ratio).max(0.05);
                        continue;
                    }
                    fails = 0;
                    es.st.s = cur.st.s + ds;
                    let f = if ratio > 0.0 { 1.0 / ratio } else { 2.0 };
                    dm *= f.clamp(0.5, 2.0);
                    // The band must not jump past the zone it resolves.
                    dm = dm.min(4.0 * w + 0.5 * m);
                    edge.push(es);
                }
            }
        }
        derivs_in_m(&mut edge, self.metric_y());
        Ok(EdgePath {
            neck_solver,
            neck,
            edge,
            bw,
            plan,
        })
    }

    /// The neck phase continued in its marker from the last of `neck` up
    /// to exactly `m_end` (or until `P̄ ≥ max_force`), on this fixed mesh:
    /// each state solves the gap equations with the marker equation
    /// `y(m) = ln 3^{1/6}` as its border (linear interpolation between
    /// nodes), from the secant extrapolation of the last two states in the
    /// frame moving with the marker (the neck spreads as a front: the
    /// profile near it translates). Steps start at one core cell and
    /// follow the curve's step metric and the predictor's error
    /// ([`NECK_PREDICTOR`]). The arclength march advances the front by
    /// about 0.4 cell per step, its log-gap steps being limited by
    /// `DY_STEP` while the path itself hardly moves (3 % of its target
    /// step): 115 of the 159 neck states at μ = 10, N = 256, against 11
    /// here. The states are those of the same discrete problem, with the
    /// fixed-mesh tangents and path derivatives of
    /// [`LjSolver::path_step`].
    ///
    /// Errors: a solve that fails at 1/256 of the step, or a solution whose
    /// marker is not `m` (an earlier crossing: not the continued path); the
    /// caller then marches on in arclength from the last state of `neck`.
    fn neck_by_marker(
        &self,
        neck: &mut Vec<State>,
        m_end: f64,
        max_force: f64,
        metric: &StepMetric,
        bw: &mut BWork,
    ) -> Result<()> {
        let n = self.n();
        let cell = 4.0 * self.opts.edge_width / self.n() as f64;
        let mut dm = cell;
        let mut fails = 0u32;
        // Marker of the state before the last, once the last is a marker
        // state (the secant's second point).
        let mut prev_m: Option<f64> = None;
        let bad = |m: f64| Error::NotConverged {
            what: "LJ sphere neck continuation in the marker",
            iterations: 0,
            residual: m,
        };
        loop {
            let k = neck.len();
            let cur = &neck[k - 1];
            let mc = self.edge_marker(&cur.y);
            if mc >= m_end || cur.pt.force >= max_force {
                return Ok(());
            }
            let mut m = (mc + dm).min(m_end);
            if m_end - m < 0.25 * dm {
                m = m_end;
            }
            let d = m - mc;
            let x = &self.mesh.x;
            let (mut y, mut al): (Vec<f64>, f64) = match prev_m {
                Some(pm) if fails == 0 => {
                    let prev = &neck[k - 2];
                    let th = d / (mc - pm);
                    let y = (0..n)
                        .map(|i| {
                            (1.0 + th) * self.y_at(&cur.y, x[i] - d)
                                - th * self.y_at(&prev.y, x[i] - d - (mc - pm))
                        })
                        .collect();
                    (y, (1.0 + th) * cur.al - th * prev.al)
                }
                _ => (
                    (0..n).map(|i| self.y_at(&cur.y, x[i] - d)).collect(),
                    cur.al,
                ),
            };
            let guess = y.clone();
            if bw.krylov > KRYLOV_REFRESH {
                bw.invalidate();
            }
            let con = Con::Plane {
                row: self.marker_row(m),
                c: MARK,
            };
            let solved = self.bnewton(&con, &mut y, &mut al, bw, false);
            let ok = match solved {
                Err(e) if is_unresolved(&e) => return Err(e),
                Err(_) => false,
                Ok(_) => (self.edge_marker(&y) - m).abs() <= 1e-9 * (1.0 + m),
            };
            if !ok {
                bw.invalidate();
                dm *= 0.5;
                fails += 1;
                if fails > 8 {
                    return Err(bad(m));
                }
                continue;
            }
            let t = self.tangent(bw, &cur.t, false, path::PREDICTOR_RTOL, None)?;
            let dist = self.chord(&y, al, &cur.y, cur.al);
            let st = self.make_state(&y, al, t, cur.s + dist, bw, true)?;
            let ratio = metric.dist(&cur.pt, &st.pt) / metric.target;
            if ratio > 3.0 {
                dm *= (0.8 / ratio).max(0.05);
                continue;
            }
            let e_pred = y
                .iter()
                .zip(&guess)
                .fold(0.0f64, |a, (p, q)| a.max((p - q).abs()));
            let f = (1.0 / ratio.max(1e-12)).min(NECK_PREDICTOR / e_pred.max(1e-12));
            dm = d * f.clamp(0.5, 2.0);
            fails = 0;
            prev_m = Some(mc);
            neck.push(st);
        }
    }

    /// The log-gap at radius `r` (linear interpolation between the nodes,
    /// even in `r`).
    fn y_at(&self, y: &[f64], r: f64) -> f64 {
        let x = &self.mesh.x;
        let r = r.abs();
        let i = x.partition_point(|&v| v <= r).clamp(1, x.len() - 1) - 1;
        let t = (r - x[i]) / (x[i + 1] - x[i]);
        y[i] + t * (y[i + 1] - y[i])
    }

    /// The extremum of `sign·value(state)` over the marker radius in
    /// `[lo.m, hi.m]`, bracketed by the interior sample `mid` (Brent's
    /// minimisation: parabolic steps with golden-section safeguards).
    fn edge_extremum(
        &self,
        lo: &EdgeState,
        mid: &EdgeState,
        hi: &EdgeState,
        plan: (f64, f64),
        bw: &mut BWork,
        value: &dyn Fn(&State) -> f64,
    ) -> Result<Vec<EdgeState>> {
        const CGOLD: f64 = 0.381_966_011_250_105_1;
        let samples = [lo.clone(), mid.clone(), hi.clone()];
        let guess = |m: f64| {
            // Interpolation between the bracketing samples.
            let k = if m <= samples[1].m { 0 } else { 1 };
            let (l, r) = (&samples[k], &samples[k + 1]);
            let th = (m - l.m) / (r.m - l.m);
            ([(l, 1.0 - th), (r, th)], l.st.s + th * (r.st.s - l.st.s))
        };
        let (mut a, mut b) = (lo.m, hi.m);
        let (mut x, mut w, mut v) = (mid.m, mid.m, mid.m);
        let fx0 = value(&mid.st);
        let (mut fx, mut fw, mut fv) = (fx0, fx0, fx0);
        let (mut d, mut e) = (0.0f64, 0.0f64);
        let mut evals: Vec<EdgeState> = Vec::new();
        for _ in 0..60 {
            let xm = 0.5 * (a + b);
            let tol1 = BRENT_RTOL * x.abs() + 1e-12;
            let tol2 = 2.0 * tol1;
            if (x - xm).abs() <= tol2 - 0.5 * (b - a) {
                break;
            }
            let mut golden = true;
            if e.abs() > tol1 {
                let r = (x - w) * (fx - fv);
                let mut q = (x - v) * (fx - fw);
                let mut p = (x - v) * q - (x - w) * r;
                q = 2.0 * (q - r);
                if q > 0.0 {
                    p = -p;
                }
                q = q.abs();
                let etemp = e;
                e = d;
                if p.abs() < (0.5 * q * etemp).abs() && p > q * (a - x) && p < q * (b - x) {
                    d = p / q;
                    let u = x + d;
                    if u - a < tol2 || b - u < tol2 {
                        d = tol1.copysign(xm - x);
                    }
                    golden = false;
                }
            }
            if golden {
                e = if x >= xm { a - x } else { b - x };
                d = CGOLD * e;
            }
            let u = if d.abs() >= tol1 {
                x + d
            } else {
                x + tol1.copysign(d)
            };
            let (from, s) = guess(u);
            let es = match self.edge_solve(u, plan, &from, s, bw) {
                Ok(es) => es,
                Err(_) => {
                    // From the nearest sample instead of the interpolation.
                    let near = samples
                        .iter()
                        .chain(evals.iter())
                        .min_by(|p, q| (p.m - u).abs().total_cmp(&(q.m - u).abs()))
                        .unwrap();
                    self.edge_solve(u, plan, &[(near, 1.0)], s, bw)?
                }
            };
            let fu = value(&es.st);
            evals.push(es);
            if fu <= fx {
                if u >= x {
                    a = x;
                } else {
                    b = x;
                }
                (v, fv, w, fw, x, fx) = (w, fw, x, fx, u, fu);
            } else {
                if u < x {
                    a = u;
                } else {
                    b = u;
                }
                if fu <= fw || w == x {
                    (v, fv, w, fw) = (w, fw, u, fu);
                } else if fu <= fv || v == x || v == w {
                    (v, fv) = (u, fu);
                }
            }
        }
        let _ = (v, fv);
        evals.push(mid.clone());
        evals.sort_by(|p, q| p.m.total_cmp(&q.m));
        Ok(evals)
    }
}

/// Path derivatives of the edge-phase states by 3-point differences in the
/// marker radius `m` (the family of solutions on meshes moving with the
/// edge, smooth in `m`; the tangent of a single fixed mesh is not, where the
/// edge crosses its cells). The unit tangent uses the node-by-node log-gap
/// differences with the continuation's metric.
fn derivs_in_m(edge: &mut [EdgeState], my: f64) {
    let n = edge.len();
    if n < 3 {
        return;
    }
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let (a, b, c) = stencil3(i, n);
        let xs = [edge[a].m, edge[b].m, edge[c].m];
        let x = edge[i].m;
        let d =
            |f: &dyn Fn(&EdgeState) -> f64| deriv3(xs, [f(&edge[a]), f(&edge[b]), f(&edge[c])], x);
        let dal = d(&|e| e.st.al);
        let df = d(&|e| e.st.pt.force);
        let da = d(&|e| e.st.pt.contact_radius);
        let ny = edge[i].st.y.len();
        let dy: Vec<f64> = (0..ny).map(|k| d(&|e| e.st.y[k])).collect();
        out.push((dal, df, da, dy));
    }
    for (e, (dal, df, da, dy)) in edge.iter_mut().zip(out) {
        let nrm = (my * dy.iter().map(|v| v * v).sum::<f64>() + dal * dal).sqrt();
        let ny = dy.len();
        let mut t: Vec<f64> = dy.into_iter().map(|v| v / nrm).collect();
        t.push(dal / nrm);
        e.st.t = t;
        e.st.df = df / nrm;
        e.st.pt.d_approach = e.st.t[ny];
        e.st.pt.d_force = e.st.df;
        e.st.pt.d_radius = da / nrm;
    }
}

impl EdgePath {
    /// Number of neck states kept in the combined path (the last one is
    /// dropped when the edge phase starts: the first edge state is the same
    /// equilibrium on the banded mesh).
    fn kept(&self) -> usize {
        self.neck.len() - usize::from(!self.edge.is_empty())
    }

    /// The combined path: kept neck states, then the edge states.
    fn states(&self) -> Vec<State> {
        let mut v: Vec<State> = self.neck[..self.kept()].to_vec();
        v.extend(self.edge.iter().map(|e| e.st.clone()));
        v
    }

    /// The special point around the interval `[i, i + 1]` of the combined
    /// path: a root of its path derivative in the neck phase, an extremum in
    /// the marker radius in the edge phase (with its derivatives from the
    /// evaluations around it; the extremised one is 0).
    fn refine(&mut self, base: &LjSolver, i: usize, sp: Special) -> Result<State> {
        let kept = self.kept();
        if i < kept {
            // Within the neck phase (the dropped last neck state closes the
            // interval that ends on the first edge state).
            let ns = &self.neck_solver;
            return match ns.refine_between(&self.neck, i, &mut self.bw, sp) {
                Err(e) if !is_unresolved(&e) => ns.refine_densely(&self.neck, i, &mut self.bw, sp),
                r => r,
            };
        }
        let j = i - kept;
        let n = self.edge.len();
        let sign = if sp == Special::ApproachMax {
            -1.0
        } else {
            1.0
        };
        let value = |st: &State| match sp {
            Special::ForceMin => st.pt.force,
            _ => sign * st.al,
        };
        // The extreme sample among j-1..=j+2, bracketed by its neighbours.
        let lo = j.saturating_sub(1);
        let hi = (j + 2).min(n - 1);
        let k = (lo..=hi)
            .min_by(|&p, &q| value(&self.edge[p].st).total_cmp(&value(&self.edge[q].st)))
            .unwrap_or(j);
        if k == 0 || k + 1 >= n {
            return Ok(self.edge[k].st.clone());
        }
        let (l, mid, r) = (
            self.edge[k - 1].clone(),
            self.edge[k].clone(),
            self.edge[k + 1].clone(),
        );
        let mut evals = base.edge_extremum(&l, &mid, &r, self.plan, &mut self.bw, &value)?;
        let best = (0..evals.len())
            .min_by(|&p, &q| value(&evals[p].st).total_cmp(&value(&evals[q].st)))
            .unwrap();
        let mut around = vec![l];
        around.append(&mut evals);
        around.push(r);
        derivs_in_m(&mut around, base.metric_y());
        let mut st = around[best + 1].st.clone();
        let n_al = st.t.len() - 1;
        match sp {
            Special::ForceMin => {
                st.df = 0.0;
                st.pt.d_force = 0.0;
            }
            _ => {
                st.t[n_al] = 0.0;
                st.pt.d_approach = 0.0;
            }
        }
        Ok(st)
    }
}

impl LjSolver {
    /// [`LjSolver::curve`] by the edge continuation (μ > 1).
    pub(super) fn edge_curve(&self, plan: (f64, f64)) -> Result<LjCurve> {
        let o = self.opts;
        let mut path = self.edge_march(plan, o.max_force, o.target_points, false, &|_| false)?;
        let states = path.states();
        let mut c = self.finish_curve(states, &mut |i, sp| path.refine(self, i, sp))?;
        c.iterations = path.bw.w.iterations;
        c.factorizations = path.bw.w.factorizations;
        c.max_residual = path.bw.w.max_residual;
        Ok(c)
    }

    /// Load-controlled pull-off by the edge continuation (μ > 1): the march
    /// stops once the force has risen past its minimum, which is then
    /// refined as the zero of dP̄/ds.
    pub(super) fn edge_pull_off(&self, plan: (f64, f64)) -> Result<LjPullOff> {
        // Past the minimum on the contact branch: the force has risen after
        // its edge-phase minimum and the approach grows (stable branch).
        let stop = |e: &[EdgeState]| {
            let n = e.len();
            let f = |i: usize| e[i].st.pt.force;
            let imin = (0..n).min_by(|&a, &b| f(a).total_cmp(&f(b))).unwrap_or(0);
            n >= 3 && imin + 2 < n && f(n - 1) > f(imin) + 0.02 && e[n - 1].st.al > e[n - 2].st.al
        };
        let mut path = self.edge_march(plan, 1.0, 80, false, &stop)?;
        let states = path.states();
        let Some(i) = Self::min_interval(&states) else {
            return Err(Error::NotConverged {
                what: "LJ sphere pull-off: no force minimum along the continuation",
                iterations: path.bw.w.iterations.min(u32::MAX as u64) as u32,
                residual: path.bw.w.max_residual,
            });
        };
        let best = path.refine(self, i, Special::ForceMin)?;
        let p = best.pt;
        Ok(LjPullOff {
            force: p.force,
            approach: p.approach,
            central_gap: p.central_gap,
            contact_radius: p.contact_radius,
            iterations: path.bw.w.iterations,
            max_residual: path.bw.w.max_residual,
            n_grid: self.n(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::{jkr_radius_estimate, LjSolver, Mesh, SWITCH};
    use crate::contact::lj_sphere::LjSphere;

    /// The curve with the neck phase continued in its marker, against the
    /// same discrete problem followed in arclength through the whole neck
    /// (`dense_neck`, as the table sampler does): far fewer neck states,
    /// ordered along the path, ending exactly on the switch marker, and the
    /// same jump-in, jump-out and pull-off (measured: 60 against 104 neck
    /// states at μ = 3, 53 against 96 at μ = 10; pull-offs equal to 3e-12,
    /// hysteresis to 4e-7). The jump-out lies in the neck phase at μ = 3
    /// and in the edge phase at μ = 10.
    #[test]
    fn neck_in_the_marker_follows_the_arclength_path() {
        for mu in [3.0f64, 10.0] {
            let sv = LjSphere::from_tabor(mu).unwrap().solver(128).unwrap();
            let plan = sv.band_plan().unwrap();
            let o = sv.opts;
            let run = |dense: bool| {
                let mut p = sv
                    .edge_march(plan, o.max_force, o.target_points, dense, &|_| false)
                    .unwrap();
                let states = p.states();
                let c = sv
                    .finish_curve(states, &mut |i, sp| p.refine(&sv, i, sp))
                    .unwrap();
                (p, c)
            };
            let (fast, cf) = run(false);
            let (dense, cd) = run(true);
            let (nf, nd) = (fast.neck.len(), dense.neck.len());
            assert!(3 * nf < 2 * nd, "μ = {mu}: {nf} neck states against {nd}");
            assert!(fast.neck.windows(2).all(|w| w[1].s > w[0].s));
            let m_s = SWITCH * plan.0;
            let last = &fast.neck[nf - 1];
            let m_last = fast.neck_solver.edge_marker(&last.y);
            assert!(
                (m_last - m_s).abs() <= 1e-9 * m_s,
                "μ = {mu}: marker {m_last} against {m_s}"
            );
            let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
            let (ji, jd) = (cf.jump_in.unwrap(), cd.jump_in.unwrap());
            let (oi, od) = (cf.jump_out.unwrap(), cd.jump_out.unwrap());
            for (what, a, b) in [
                ("jump-in approach", ji.approach, jd.approach),
                ("jump-in force", ji.force, jd.force),
                ("jump-out approach", oi.approach, od.approach),
                ("jump-out force", oi.force, od.force),
                ("pull-off", cf.pull_off_load.force, cd.pull_off_load.force),
            ] {
                assert!(rel(a, b) < 1e-7, "μ = {mu}: {what} {a} against {b}");
            }
            // The hysteresis integrates the sampled branches by trapezoids:
            // fewer neck states move it by their quadrature error only.
            let (hf, hd) = (cf.hysteresis_energy, cd.hysteresis_energy);
            assert!(rel(hf, hd) < 1e-3, "μ = {mu}: hysteresis {hf} against {hd}");
        }
    }

    /// The edge family's mesh: `N` ordered cells on `[0, L]`, a node exactly
    /// at the switch marker, uniform cells of `4w/N` near the centre (the
    /// neck's resolution) and cells at the marker as fine as the travel of
    /// the marker requires (`4w/N` at the largest marker).
    #[test]
    fn family_mesh_has_its_node_on_the_marker() {
        for mu in [1.5f64, 3.0, 10.0, 30.0, 100.0] {
            for n in [64usize, 256, 1024] {
                let sv = LjSphere::from_tabor(mu).unwrap().solver(n).unwrap();
                let plan = sv.band_plan().unwrap();
                let f = sv.family(plan).unwrap();
                let (x, c) = (&f.mesh.x, &f.mesh.c);
                assert_eq!(x.len(), n);
                assert_eq!(c[n], sv.opts.outer_radius);
                for j in 0..n {
                    assert!(c[j] < x[j] && x[j] < c[j + 1], "mu {mu} n {n}: node {j}");
                }
                let m_s = SWITCH * plan.0;
                let j = x
                    .iter()
                    .position(|&v| v == m_s)
                    .expect("a node on the marker");
                let h_in = 4.0 * plan.0 / n as f64;
                let m_end = (1.2 * jkr_radius_estimate(mu, 10.0)).max(2.0 * m_s);
                let h_a = h_in * m_s / m_end;
                let hj = c[j + 1] - c[j];
                assert!(
                    hj > 0.5 * h_a && hj < 2.0 * h_a,
                    "mu {mu} n {n}: {hj} vs {h_a}"
                );
                // The grading reaches the uniform core only when the marker
                // is many core cells from the centre.
                if j > 40 {
                    let h0 = c[1] - c[0];
                    assert!(
                        (h0 / h_in - 1.0).abs() < 0.1,
                        "mu {mu} n {n}: {h0} vs {h_in}"
                    );
                }
            }
        }
    }

    /// A solver scaled by `s` is the solver of the scaled mesh: the
    /// influence product, the centre row and the tail agree with those
    /// built from elliptic integrals on the scaled mesh.
    #[test]
    fn scaled_solver_matches_the_directly_built_one() {
        let sv = LjSphere::from_tabor(10.0).unwrap().solver(128).unwrap();
        let f = sv.family(sv.band_plan().unwrap()).unwrap();
        for s in [0.5, 3.7, 41.0] {
            let sc = f.scaled(s);
            let mesh = Mesh {
                x: f.mesh.x.iter().map(|v| v * s).collect(),
                c: f.mesh.c.iter().map(|v| v * s).collect(),
            };
            let mut o = f.opts;
            o.outer_radius *= s;
            let direct = LjSolver::with_mesh(f.mu, o, mesh).unwrap();
            let q: Vec<f64> = (0..128)
                .map(|i| ((i * 37 % 11) as f64 - 5.0) * 0.1)
                .collect();
            let (u, v) = (sc.apply_influence(&q), direct.apply_influence(&q));
            let big = v.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            for i in 0..128 {
                assert!((u[i] - v[i]).abs() <= 1e-13 * big, "s {s}, node {i}");
                assert!((sc.tail[i] - direct.tail[i]).abs() <= 1e-15 * direct.tail[i].abs());
                assert!((sc.a0[i] - direct.a0[i]).abs() <= 1e-14 * direct.a0[i].abs());
            }
        }
    }

    /// The mesh map is inverted exactly for any band position: nodes
    /// strictly inside their cells, cells increasing. (Newton alone cycled
    /// around the inflections of a narrow band and returned a node outside
    /// its cell for some band centres.)
    #[test]
    fn banded_meshes_are_ordered_for_every_band_centre() {
        for mu in [1.5f64, 3.0, 30.0, 100.0] {
            for n in [64usize, 256] {
                let rf = 1.0 + 1.2 * jkr_radius_estimate(mu, 10.0);
                let l = (3.0 * rf).max(20.0);
                let w = (n as f64 * mu.powf(-1.5) / 16.0).clamp(0.01, 2.0);
                for k in 0..300 {
                    let a_e = 0.0731 * k as f64;
                    let m = Mesh::new(n, rf, l, a_e, w, 0.5);
                    for j in 0..n {
                        assert!(
                            m.c[j] < m.x[j] && m.x[j] < m.c[j + 1],
                            "mu {mu} n {n} a_e {a_e}: node {j} = {} outside [{}, {}]",
                            m.x[j],
                            m.c[j],
                            m.c[j + 1]
                        );
                    }
                }
            }
        }
    }
}
