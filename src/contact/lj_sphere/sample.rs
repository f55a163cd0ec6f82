//! Dense sampling of the Lennard-Jones equilibrium path for tabulated laws
//! ([`LjSolver::path_samples`]): the coarse pseudo-arclength continuation of
//! [`LjSolver::curve`], its special points refined exactly, and every
//! interval between neighbours bisected until cubic Hermite interpolation
//! along the path parameter reproduces the exact midpoint to `tolerance/8`.

// NaN-aware comparisons (`!(x > 0.0)`) are intended.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::needless_range_loop)]

use super::path::State;
use super::*;
use crate::contact::curve::PathPoint;

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
    /// [`LjOptions::max_force`]), outside the range the mesh is designed for:
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
    /// [`LjOptions::max_force`], such that cubic Hermite interpolation along
    /// the path parameter between neighbouring points reproduces the exact
    /// path to `tolerance/8` (force and radius relative to
    /// `max(|value|, 10⁻³·scale)`, approach absolute to `0.1·tolerance/8`);
    /// the midpoints of accepted intervals are kept as extra points.
    ///
    /// Derivatives are along the pseudo-arclength `s` of the continuation
    /// (unit tangent; see [`LjPoint::d_approach`]), except at the special
    /// points, which are exact roots along the path (Illinois method, exact
    /// tangents):
    ///
    /// * turning points of ᾱ (jump-in, jump-out): `d_delta = 0`,
    ///   `d2_delta = d²ᾱ/ds²` (central differences of the exact tangent);
    /// * the load-controlled pull-off (minimum of P̄ on the last stable
    ///   piece): `d_force = 0`;
    /// * the zero of P̄ on the last stable piece: `force = 0`;
    /// * the contact onset `h̄₀ = 1`, where the contact radius (first root of
    ///   `h̄ = 1`, see [`LjSolution::contact_radius`]) leaves zero like
    ///   `√(s − s₀)`: a corner, two points with radius 0, the second with
    ///   derivatives along `τ = √(s − s₀)` (`d_delta = d_force = 0`,
    ///   `d2_delta = 2 dᾱ/ds`, `d_radius = lim a/τ`); the interval after it is
    ///   sampled in τ.
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
        let n = self.n();
        // Coarse continuation beyond the end: the states past `f_end` are the
        // deep tail checks.
        let f_tail = 3.0 * f_end;
        let base_gap = 6.0 + 4.0 * self.mu.sqrt();
        let target = (self.opts.target_points as f64 * (self.opts.start_gap / base_gap).max(1.0))
            .ceil() as usize;
        let (states, mut bw) = self.path_march(f_tail, target, &|_| false)?;
        let i_end = states
            .iter()
            .position(|s| s.pt.force >= f_end)
            .unwrap_or(states.len() - 1);
        let mut nodes: Vec<Node> = Vec::with_capacity(i_end + 8);
        for st in &states[..=i_end] {
            let e = self.exactify(st, &mut bw)?;
            nodes.push(self.node(e, Kind::Regular)?);
        }
        let ta = |s: &State| s.t[n];
        // Turning points.
        let mut i = 0;
        while i + 1 < nodes.len() {
            let (a, b) = (ta(&nodes[i].st), ta(&nodes[i + 1].st));
            if a * b < 0.0 && nodes[i].kind == Kind::Regular && nodes[i + 1].kind == Kind::Regular {
                let st = self.path_root(&nodes[i].st, &nodes[i + 1].st, &mut bw, &ta)?;
                let d2 = self.second_derivative(&st, &mut bw)?;
                let nd = self.node(st, Kind::Turn(d2))?;
                nodes.insert(i + 1, nd);
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
                self.path_root(&nodes[i].st, &nodes[i + 1].st, &mut bw, &gap)?
            };
            let g = self.onset_slope(&st, &mut bw)?;
            let mut nd = self.node(st, Kind::Corner(g))?;
            nd.st.pt.contact_radius = 0.0;
            nd.d[2] = 0.0;
            if gap(&nodes[i + 1].st) == 0.0 {
                nodes[i + 1] = nd;
            } else {
                nodes.insert(i + 1, nd);
            }
        }
        // Force minimum and zero on the last stable piece.
        let last_turn = nodes
            .iter()
            .rposition(|nd| matches!(nd.kind, Kind::Turn(_)))
            .unwrap_or(0);
        let dfs = |s: &State| s.df;
        let imin = (last_turn..nodes.len() - 1)
            .find(|&i| nodes[i].d[1] < 0.0 && nodes[i + 1].d[1] >= 0.0)
            .ok_or(Error::NotConverged {
                what: "LJ sphere path samples: no force minimum on the last stable piece",
                iterations: 0,
                residual: f64::NAN,
            })?;
        let st = self.path_root(&nodes[imin].st, &nodes[imin + 1].st, &mut bw, &dfs)?;
        let nd = self.node(st, Kind::Min)?;
        nodes.insert(imin + 1, nd);
        let force = |s: &State| s.pt.force;
        if let Some(i) = (imin + 1..nodes.len() - 1)
            .find(|&i| force(&nodes[i].st) < 0.0 && force(&nodes[i + 1].st) >= 0.0)
        {
            let st = self.path_root(&nodes[i].st, &nodes[i + 1].st, &mut bw, &force)?;
            let nd = self.node(st, Kind::Zero)?;
            nodes.insert(i + 1, nd);
        }
        // Error scales.
        let f_min = nodes[imin + 1].st.pt.force;
        let a_min = nodes[imin + 1].st.pt.contact_radius;
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
        let (mut jump_in, mut jump_out, mut pull, mut onset) = (None, None, 0, None);
        for k in 0..nodes.len() {
            let nd = &nodes[k];
            let mut p = path_point(&nd.st, nd.d);
            match nd.kind {
                Kind::Regular => out.push(p),
                Kind::Turn(d2) => {
                    p.d_delta = 0.0;
                    p.d2_delta = d2;
                    if d2 < 0.0 {
                        jump_in = Some(out.len());
                    } else {
                        jump_out = Some(out.len());
                    }
                    out.push(p);
                }
                Kind::Min => {
                    p.d_force = 0.0;
                    pull = out.len();
                    out.push(p);
                }
                Kind::Zero => {
                    p.force = 0.0;
                    out.push(p);
                }
                Kind::Corner(g) => {
                    onset = Some(out.len());
                    p.radius = 0.0;
                    p.d_radius = 0.0;
                    out.push(p);
                    out.push(PathPoint {
                        d_delta: 0.0,
                        d_force: 0.0,
                        d_radius: g,
                        d2_delta: 2.0 * nd.d[0],
                        ..p
                    });
                }
            }
            if k + 1 < nodes.len() {
                self.sample_interval(nd, &nodes[k + 1], &crit, &mut bw, &mut out)?;
            }
        }
        // Tail checks: far (larger central gaps) and deep (beyond the end).
        let mut tail_checks = Vec::new();
        let g0 = self.opts.start_gap;
        for f in [1.25, 1.5, 2.0, 3.0, 5.0, 10.0] {
            let s = self.solve_at_central_gap(g0 * f, None)?;
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
        let mut deep_checks = Vec::new();
        for st in &states[i_end + 1..] {
            deep_checks.push(PathPoint {
                delta: st.al,
                force: st.pt.force,
                radius: st.pt.contact_radius,
                d_delta: 1.0,
                d_force: 0.0,
                d_radius: 0.0,
                d2_delta: 0.0,
            });
        }
        Ok(LjPathSamples {
            points: out,
            tail_checks,
            deep_checks,
            jump_in,
            jump_out,
            pull_off_load: pull,
            contact_onset: onset,
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
        let n = self.n();
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
        let h = r.0 - l.0;
        let floors = [f64::INFINITY, c.f_floor, c.a_floor];
        let ok = (0..3).all(|q| {
            let y = hermite_mid(l.2[q].0, l.2[q].1, r.2[q].0, r.2[q].1, h);
            let err = (y - vm[q].0).abs();
            if q == 0 {
                err <= c.tol * c.d_abs
            } else {
                err <= c.tol * vm[q].0.abs().max(floors[q])
            }
        });
        let _ = n;
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
