//! Building a table from an equilibrium curve: the monotone pieces and
//! branches, the greedy choice of knots, the tails, and the error measured
//! on every point the table skips.

use super::data::{BranchData, DeepData, FarData, SegmentData, TableData, Transform, FORMAT};
use super::eval::rigid_lj;
use super::hermite::{coefficients, horner, limit, monotone, monotone_or_flat};
use super::{bad, measure, TabulatedLaw};
use crate::contact::curve::{DeepTail, EquilibriumCurve, FarTail, PathPoint};
use crate::contact::{LjSphere, MaugisDugdale};
use crate::error::{Error, Result};

/// A candidate knot of a segment.
#[derive(Debug, Clone, Copy)]
struct Cand {
    u: f64,
    f: f64,
    df: f64,
    a: f64,
    da: f64,
    must: bool,
}

fn hermite_at(c0: &Cand, c1: &Cand, u: f64) -> (f64, f64) {
    let h = c1.u - c0.u;
    let t = (u - c0.u) / h;
    (
        horner(&coefficients(c0.f, c0.df, c1.f, c1.df, h), t),
        horner(&coefficients(c0.a, c0.da, c1.a, c1.da, h), t),
    )
}

impl TabulatedLaw {
    /// Build a table from `curve` with relative tolerance `tolerance` (in
    /// [1e-10, 0.1]; [`DEFAULT_TOLERANCE`](super::DEFAULT_TOLERANCE) is 1e-4), in the error measure of
    /// the module documentation.
    ///
    /// Errors: [`Error::InvalidArgument`] for an invalid curve or tolerance;
    /// [`Error::NotConverged`] when the curve is too coarse for the tolerance
    /// (its points interpolate each other, or the tails meet the tail checks,
    /// less accurately than asked), or too coarse for a table at all: its
    /// force dips again beyond the load-controlled pull-off (the residual is
    /// the largest dip relative to the pull-off force).
    pub fn from_curve(curve: &EquilibriumCurve, tolerance: f64) -> Result<Self> {
        let tol =
            crate::error::check::in_range("tolerance", tolerance, 1e-10, 0.1, "in [1e-10, 0.1]")?;
        curve.validate()?;
        let p = &curve.points;
        let n = p.len();
        // Monotone pieces of the path: (first, last, stable).
        let mut pieces: Vec<(usize, usize, bool)> = Vec::new();
        let mut start = 0;
        let reverses = |i: usize| {
            // Δ turns back at point i (corners skipped).
            let before = (1..=i)
                .rev()
                .map(|j| p[j].delta - p[j - 1].delta)
                .find(|d| *d != 0.0);
            let after = (i..n - 1)
                .map(|j| p[j + 1].delta - p[j].delta)
                .find(|d| *d != 0.0);
            matches!((before, after), (Some(b), Some(a)) if a * b < 0.0)
        };
        for i in 1..n {
            if p[i].d_delta == 0.0 && i + 1 < n && reverses(i) || i == n - 1 {
                let stable = p[start..=i].windows(2).any(|w| w[1].delta > w[0].delta);
                pieces.push((start, i, stable));
                start = i;
            }
        }
        let last_piece = *pieces.last().unwrap();
        // The load-controlled pull-off: the smallest force at a force
        // extremum (or the start) of the last piece.
        let (lp0, lp1, _) = last_piece;
        let mut load_idx = lp0;
        for i in lp0..=lp1 {
            if (p[i].d_force == 0.0 || i == lp0) && p[i].force < p[load_idx].force {
                load_idx = i;
            }
        }
        // Displacement-controlled pull-off: where contact is lost going back
        // along the last piece (radius reaching 0), or its start.
        // With a Lennard-Jones far tail the force stays continuous where the
        // radius reaches 0, and the contact is lost at the jump-out turning
        // point when there is one (the start of the last piece).
        let mut disp_idx = lp0;
        if !(matches!(curve.far_tail, FarTail::RigidLennardJones) && lp0 > 0) {
            for i in (lp0..=lp1).rev() {
                if p[i].radius == 0.0 {
                    disp_idx = i;
                    break;
                }
            }
        }
        let force_floor = 1e-3 * p[load_idx].force.abs().max(f64::MIN_POSITIVE);
        let radius_floor = 1e-3 * p[load_idx].radius.max(1e-3);

        // Branches: far (tail, plus the first piece when stable), then the
        // other stable pieces.
        let mut branch_pieces: Vec<Option<(usize, usize)>> = Vec::new();
        let first_stable = pieces[0].2;
        branch_pieces.push(if first_stable {
            Some((pieces[0].0, pieces[0].1))
        } else {
            None
        });
        for (k, &(a, b, s)) in pieces.iter().enumerate() {
            if s && !(k == 0 && first_stable) {
                branch_pieces.push(Some((a, b)));
            }
        }
        let nbr = branch_pieces.len();
        if nbr < 2 && !first_stable {
            return Err(bad("curve", 0.0, "a curve with a stable piece"));
        }
        let mut branches = Vec::new();
        // Skipped points with the branch of their segment (stable branches may
        // overlap in Δ: the far branch and the contact branch of an S-curve).
        let mut seg_data: Vec<(usize, Vec<(f64, f64, f64)>)> = Vec::new();
        for (k, bp) in branch_pieces.iter().enumerate() {
            let lo = if k == 0 {
                None
            } else {
                Some(p[bp.unwrap().0].delta)
            };
            let hi = if k + 1 == nbr {
                None
            } else {
                match bp {
                    Some((_, b)) => Some(p[*b].delta),
                    None => Some(p[0].delta),
                }
            };
            let mut segments = Vec::new();
            if let Some((a0, b0)) = *bp {
                // Split at corners (the second point of a pair starts a part).
                let mut cuts = vec![a0];
                for i in a0 + 1..b0 {
                    if p[i].delta == p[i - 1].delta
                        && p[i].force == p[i - 1].force
                        && p[i].radius == p[i - 1].radius
                    {
                        cuts.push(i);
                    }
                }
                let mut spans: Vec<(usize, usize)> = Vec::new();
                for (w, &c) in cuts.iter().enumerate() {
                    let end = cuts.get(w + 1).map_or(b0, |&nx| nx - 1);
                    spans.push((c, end));
                }
                let mut parts: Vec<(usize, usize, Transform, f64, f64)> = Vec::new();
                for (a, b) in spans {
                    let turn_lo = p[a].d_delta == 0.0;
                    let turn_hi = p[b].d_delta == 0.0 && b + 1 < n;
                    if turn_lo && turn_hi {
                        let mid_d = 0.5 * (p[a].delta + p[b].delta);
                        let m = (a + 1..b)
                            .min_by(|&i, &j| {
                                (p[i].delta - mid_d)
                                    .abs()
                                    .total_cmp(&(p[j].delta - mid_d).abs())
                            })
                            .ok_or(bad("curve", a as f64, "two points between turning points"))?;
                        parts.push((a, m, Transform::Sqrt, 1.0, p[a].delta));
                        parts.push((m, b, Transform::Sqrt, -1.0, p[b].delta));
                    } else if turn_lo {
                        parts.push((a, b, Transform::Sqrt, 1.0, p[a].delta));
                    } else if turn_hi {
                        parts.push((a, b, Transform::Sqrt, -1.0, p[b].delta));
                    } else {
                        parts.push((a, b, Transform::Linear, 1.0, p[a].delta));
                    }
                }
                for (i0, i1, tr, sign, reference) in parts {
                    let (sd, skipped) = Self::build_segment(
                        p,
                        i0,
                        i1,
                        tr,
                        sign,
                        reference,
                        tol,
                        force_floor,
                        radius_floor,
                    )?;
                    segments.push(sd);
                    seg_data.push((k, skipped));
                }
            }
            branches.push(BranchData { lo, hi, segments });
        }
        // Tails.
        let far = match curve.far_tail {
            FarTail::Zero => FarData::Zero,
            FarTail::RigidLennardJones => FarData::RigidLennardJones {
                k: p[0].force / rigid_lj(p[0].delta).0,
            },
        };
        let DeepTail::Hertz {
            force_coefficient: h,
            radius_coefficient: g,
            delta_zero,
        } = curve.deep_tail;
        let l = p[n - 1];
        let x = l.delta - delta_zero;
        let fit = |y: f64, slope: f64, c: f64, e: f64| -> (f64, f64) {
            let r = y - c * x.powf(e);
            let rp = slope - e * c * x.powf(e - 1.0);
            if r == 0.0 || r.abs() < 1e-14 * y.abs() {
                (0.0, 0.0)
            } else {
                let q = (x * rp / r).clamp(-4.0, e);
                (r / x.powf(q), q)
            }
        };
        let (bf, qf) = fit(l.force, l.d_force / l.d_delta, h, 1.5);
        let (ba, qa) = fit(l.radius, l.d_radius / l.d_delta, g, 0.5);
        let deep = DeepData {
            delta_zero,
            h,
            bf,
            qf,
            g,
            ba,
            qa,
        };
        // The load pull-off knot lies in the last segment of the last branch.
        let last_seg = branches[nbr - 1].segments.last().unwrap();
        if p[load_idx].delta < last_seg.lo {
            return Err(bad(
                "curve",
                p[load_idx].delta,
                "the load-controlled pull-off on the last part of the last stable piece",
            ));
        }
        let load_u = last_seg.u_of_delta(p[load_idx].delta);
        let data = TableData {
            format: FORMAT.to_string(),
            source: curve.source.clone(),
            tolerance: tol,
            measured_error: 0.0,
            force_floor,
            radius_floor,
            approach_origin: curve.approach_origin,
            approach_scale: curve.approach_scale,
            force_scale: curve.force_scale,
            radius_scale: curve.radius_scale,
            branches,
            far,
            deep,
            load_pull_off: p[load_idx].force,
            load_pull_off_u: load_u,
            displacement_pull_off: p[disp_idx].force,
        };
        // A table requires the force to increase beyond the load-controlled
        // pull-off. A curve whose contact branch dips again beyond it (a
        // solver grid that does not resolve the edge zone leaves wiggles of
        // ~1e-4 there: μ = 1 at N = 64) is too coarse, not an invalid
        // argument of the caller's.
        let mut table = Self::from_data(data).map_err(|e| match e {
            Error::InvalidArgument {
                name: "load_pull_off",
                ..
            } => {
                // The largest fall of the force below its running maximum
                // beyond the pull-off, relative to the pull-off force.
                let mut top = p[load_idx].force;
                let mut dip = 0.0f64;
                for q in &p[load_idx..=lp1] {
                    top = top.max(q.force);
                    dip = dip.max(top - q.force);
                }
                Error::NotConverged {
                    what: "tabulated law: the curve's force decreases again beyond its \
                           load-controlled pull-off (a grid too coarse for the edge zone: \
                           raise n_grid)",
                    iterations: 0,
                    residual: dip / p[load_idx].force.abs(),
                }
            }
            e => e,
        })?;
        // Measure the final table on every skipped point and tail check.
        let mut worst = 0.0f64;
        for (k, skipped) in &seg_data {
            for &(x, fe, ae) in skipped {
                let (ft, at, _) = table.on_branch(*k, table.overlap(x));
                worst = worst.max(measure(ft, fe, at, ae, force_floor, radius_floor));
            }
        }
        for c in &curve.tail_checks {
            let k = if c.delta > l.delta {
                nbr - 1
            } else if c.delta < p[0].delta {
                0
            } else {
                continue;
            };
            let (ft, at, _) = table.on_branch(k, table.overlap(c.delta));
            worst = worst.max(measure(
                ft,
                c.force,
                at,
                c.radius,
                force_floor,
                radius_floor,
            ));
        }
        if !(worst <= tol) {
            return Err(Error::NotConverged {
                what: "tabulated law: the curve is too coarse for the tolerance",
                iterations: 0,
                residual: worst,
            });
        }
        table.data.measured_error = worst;
        Ok(table)
    }

    /// Knots of one segment chosen among the curve points `i0..=i1`; returns
    /// the segment and the skipped points (x, F, radius).
    #[allow(clippy::too_many_arguments)]
    fn build_segment(
        p: &[PathPoint],
        i0: usize,
        i1: usize,
        transform: Transform,
        sign: f64,
        reference: f64,
        tol: f64,
        ff: f64,
        af: f64,
    ) -> Result<(SegmentData, Vec<(f64, f64, f64)>)> {
        let sq = transform == Transform::Sqrt;
        let mut c: Vec<Cand> = Vec::with_capacity(i1 - i0 + 1);
        for i in i0..=i1 {
            let q = &p[i];
            let d = sign * (q.delta - reference);
            let u = if sq { d.max(0.0).sqrt() } else { d };
            let (df, da) = if q.d_delta == 0.0 {
                if !sq {
                    return Err(bad("curve", i as f64, "turning points only at piece ends"));
                }
                // u ≈ √(|Δ''|/2)|t − t_turn|; du/dt > 0 leaving a turning
                // point that starts the segment along the path.
                let dudt = (0.5 * q.d2_delta.abs()).sqrt() * if i == i0 { 1.0 } else { -1.0 };
                (q.d_force / dudt, q.d_radius / dudt)
            } else {
                let dxdu = if sq { 2.0 * sign * u } else { sign };
                (q.d_force / q.d_delta * dxdu, q.d_radius / q.d_delta * dxdu)
            };
            let corner = (i > i0
                && p[i - 1].delta == q.delta
                && p[i - 1].force == q.force
                && p[i - 1].radius == q.radius)
                || (i < i1
                    && p[i + 1].delta == q.delta
                    && p[i + 1].force == q.force
                    && p[i + 1].radius == q.radius);
            c.push(Cand {
                u,
                f: q.force,
                df,
                a: q.radius,
                da,
                must: i == i0 || i == i1 || corner || q.d_force == 0.0 || q.force == 0.0,
            });
        }
        if sign < 0.0 {
            c.reverse();
        }
        // u must not decrease (rounding near a turning point).
        for i in 1..c.len() {
            if c[i].u < c[i - 1].u {
                return Err(bad(
                    "curve.points",
                    (i0 + i) as f64,
                    "monotone in Δ on each piece",
                ));
            }
        }
        let accept = |i: usize, j: usize| -> bool {
            let (a, b) = (&c[i], &c[j]);
            let h = b.u - a.u;
            if h <= 0.0 {
                return j == i + 1;
            }
            if j > i + 1
                && !(monotone(a.f, a.df, b.f, b.df, h) && monotone_or_flat(a.a, a.da, b.a, b.da, h))
            {
                return false;
            }
            // At the skipped points (exact), and at quarter points of every
            // interval between neighbouring candidates, where the fine
            // interpolant through them stands in for the source.
            c[i + 1..j].iter().all(|m| {
                let (ft, at) = hermite_at(a, b, m.u);
                measure(ft, m.f, at, m.a, ff, af) <= 0.5 * tol
            }) && c[i..=j].windows(2).all(|w| {
                let h = w[1].u - w[0].u;
                h <= 0.0
                    || [0.25, 0.5, 0.75].iter().all(|&s| {
                        let u = w[0].u + s * h;
                        let (fe, ae) = hermite_at(&w[0], &w[1], u);
                        let (ft, at) = hermite_at(a, b, u);
                        measure(ft, fe, at, ae, ff, af) <= 0.5 * tol
                    })
            })
        };
        let mut keep = vec![0usize];
        let mut i = 0;
        let last = c.len() - 1;
        while i < last {
            // The next mandatory knot bounds the interval.
            let q = (i + 1..=last).find(|&j| c[j].must).unwrap_or(last);
            let mut best = i + 1;
            let mut step = 2;
            let mut fail = None;
            while best < q {
                let j = (i + step).min(q);
                if accept(i, j) {
                    best = j;
                    step *= 2;
                } else {
                    fail = Some(j);
                    break;
                }
            }
            if let Some(mut hi) = fail {
                let mut lo = best;
                while hi - lo > 1 {
                    let mid = (lo + hi) / 2;
                    if accept(i, mid) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                best = lo;
            }
            keep.push(best);
            i = best;
        }
        let mut k: Vec<Cand> = keep.iter().map(|&i| c[i]).collect();
        // Monotone slopes (Fritsch–Carlson limiter) where the data are.
        for w in 0..k.len() - 1 {
            let h = k[w + 1].u - k[w].u;
            if h <= 0.0 {
                continue;
            }
            let (y0, y1) = (k[w].f, k[w + 1].f);
            let (mut m0, mut m1) = (k[w].df, k[w + 1].df);
            limit(y0, &mut m0, y1, &mut m1, h);
            k[w].df = m0;
            k[w + 1].df = m1;
            let (y0, y1) = (k[w].a, k[w + 1].a);
            if y1 >= y0 {
                let (mut m0, mut m1) = (k[w].da, k[w + 1].da);
                limit(y0, &mut m0, y1, &mut m1, h);
                k[w].da = m0;
                k[w + 1].da = m1;
            }
        }
        let mut skipped = Vec::new();
        let kept: std::collections::HashSet<usize> = keep.iter().copied().collect();
        for (j, cj) in c.iter().enumerate() {
            if !kept.contains(&j) {
                // The curve's own Δ (exact), not a round trip through u.
                let idx = if sign < 0.0 { i1 - j } else { i0 + j };
                skipped.push((p[idx].delta, cj.f, cj.a));
            }
        }
        let (lo, hi) = (p[i0].delta, p[i1].delta);
        let sd = SegmentData {
            transform,
            sign,
            reference,
            lo,
            hi,
            u: k.iter().map(|q| q.u).collect(),
            force: k.iter().map(|q| q.f).collect(),
            d_force: k.iter().map(|q| q.df).collect(),
            radius: k.iter().map(|q| q.a).collect(),
            d_radius: k.iter().map(|q| q.da).collect(),
        };
        Ok((sd, skipped))
    }

    /// Build a table for a Maugis–Dugdale sphere: the curve of
    /// [`EquilibriumCurve::from_maugis_dugdale`] sampled for `tolerance`,
    /// then [`TabulatedLaw::from_curve`].
    pub fn from_maugis_dugdale(md: &MaugisDugdale, tolerance: f64) -> Result<Self> {
        let curve = EquilibriumCurve::from_maugis_dugdale(md, tolerance)?;
        Self::from_curve(&curve, tolerance)
    }

    /// Build a table for a Lennard-Jones sphere on `n_grid` cells (0 = the
    /// converged default grid, [`LjSphere::converged_default_grid`]): the
    /// curve of [`EquilibriumCurve::from_lj_sphere`] sampled for
    /// `tolerance`, then [`TabulatedLaw::from_curve`]. The table reproduces
    /// `lj.solver(n_grid)` (the same discrete model) within `tolerance` in
    /// the error measure of the module documentation, jumps at the solver's
    /// turning points and pulls off at its force minimum (the last one along
    /// the contact branch where the grid leaves several). The grid's own
    /// error comes on top: at μ = 1 an N = 128 table built for 1e-4 pulls off
    /// 4e-4 πRw from the converged pull-off (BENCHMARKS.md §4).
    ///
    /// Build time (optimised, tolerance 1e-4): 0.1–0.5 s at N = 128 for
    /// μ ≤ 1, about 2 s at μ = 3 and 10 (N = 256) and 17 s at μ = 10 on the
    /// default grid (512; BENCHMARKS.md §3). Tolerances near 1e-10 take tens
    /// of seconds and fail at μ = 1 (`NotConverged`, residual 3e-8).
    pub fn from_lj_sphere(lj: &LjSphere, n_grid: usize, tolerance: f64) -> Result<Self> {
        let curve = EquilibriumCurve::from_lj_sphere(lj, n_grid, tolerance)?;
        Self::from_curve(&curve, tolerance)
    }
}
