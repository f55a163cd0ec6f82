//! Equilibrium curves of adhesive spheres: a source-agnostic, serialisable
//! description of the equilibrium path from which [`super::tabulated`] builds
//! its tables.
//!
//! # What a curve is
//!
//! An adhesive elastic sphere pressed against a flat has one continuous
//! equilibrium path, from far apart (zero or long-range force) to deep
//! contact (Hertz). Along it the approach Δ may turn back (the S-shaped curve
//! of Maugis–Dugdale for λ > 0.938 or of the Lennard-Jones sphere for
//! μ ≳ 0.7): the pieces where Δ increases along the path are stable under
//! displacement control, the others are not, and the turning points between
//! them are where the contact jumps in and out.
//!
//! An [`EquilibriumCurve`] holds
//!
//! * ordered [`PathPoint`]s from far to deep, each with the reduced approach
//!   Δ, the reduced force F (repulsive positive) and the reduced contact
//!   radius, and their derivatives along a path parameter t (any parameter,
//!   which may change from point to point: only the ratios of *Formulas*
//!   are used, and the sign of `dΔ/dt`);
//! * the SI scales that make them dimensional (*Formulas*):
//!   `approach_origin` and `approach_scale` (m), `force_scale` (N),
//!   `radius_scale` (m);
//! * the far-field tail before the first point ([`FarTail`]) and the deep tail
//!   after the last one ([`DeepTail`]);
//! * exact source points beyond both ends (`tail_checks`), used only to
//!   measure the error of the tails;
//! * a `source` description.
//!
//! # Rules a curve keeps (checked by [`EquilibriumCurve::validate`])
//!
//! * Every number is finite; the scales are positive.
//! * **Turning points are explicit**: a point with `d_delta == 0` exactly,
//!   with the second derivative `d2_delta` (≠ 0) along the same parameter.
//!   Between two consecutive points `dΔ/dt` keeps its sign and Δ moves in that
//!   direction (monotone pieces).
//! * **Extrema of the force on stable pieces are explicit**: a point with
//!   `d_force == 0` exactly (the load-controlled pull-off is one).
//! * **Corners** (a derivative discontinuity, such as the point where a
//!   Maugis–Dugdale contact radius leaves zero) are two consecutive points with
//!   equal values and different derivatives. A point with `d_delta == 0` where
//!   Δ does not turn back (after a corner, as at the Maugis–Dugdale contact
//!   onset; *Formulas*) is allowed and also needs `d2_delta`.
//! * **Zero crossings of the force** on stable pieces should be points with
//!   `force == 0` exactly: the error measure is relative down to a floor, and
//!   a knot there keeps the error small.
//! * The last piece is stable (Δ increases to the deep tail).
//!
//! A solver that feeds curves (Maugis–Dugdale here, the numerical
//! Lennard-Jones sphere later) samples its path densely enough that cubic
//! Hermite interpolation between neighbours is accurate well below the
//! tolerance asked of the table: the table builder picks its knots among the
//! points and measures its error on the points it leaves out.
//!
//! # Formulas
//!
//! A curve stores reduced values and the scales that make them dimensional:
//!
//! $$\delta = \delta_\mathrm{origin} + \Delta\\,\delta_\mathrm{scale}, \qquad P = F\\,P_\mathrm{scale}, \qquad a = \bar a\\, a_\mathrm{scale},$$
//!
//! ($\delta_\mathrm{origin}$ = `approach_origin`, $\delta_\mathrm{scale}$ =
//! `approach_scale`, $P_\mathrm{scale}$ = `force_scale`, $a_\mathrm{scale}$ =
//! `radius_scale`), and only the ratios $dF/d\Delta = (dF/dt)/(d\Delta/dt)$,
//! $d\bar a/d\Delta$ of its path derivatives enter the tables. At a corner
//! after which $\Delta - \Delta_c \propto t^2$ the radius grows like
//! $\sqrt{\Delta - \Delta_c}$.
//!
//! # References
//!
//! * The sources of the curves: D. Maugis (1992), J. Colloid Interface Sci. 150,
//!   243–269 ([`super::maugis_dugdale`]); J. A. Greenwood (1997), Proc. R. Soc.
//!   Lond. A 453, 1277–1297,
//!   [doi:10.1098/rspa.1997.0070](https://doi.org/10.1098/rspa.1997.0070)
//!   ([`super::lj_sphere`]).
//! * The interpolation they feed: F. N. Fritsch, R. E. Carlson (1980), SIAM J.
//!   Numer. Anal. 17, 238–246,
//!   [doi:10.1137/0717021](https://doi.org/10.1137/0717021) ([`super::tabulated`]).

use super::lj_sphere::{LjOptions, LjSolver, LjSphere};
use super::{MaugisDugdale, NormalContact};
use crate::error::{Error, Result};
use core::f64::consts::PI;
use serde::{Deserialize, Serialize};

pub(crate) use crate::serde_exact as exact_f64;
pub(crate) use crate::serde_exact::vec as exact_vec;

/// One point of an equilibrium path in reduced units, with derivatives along
/// a path parameter t.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct PathPoint {
    /// Reduced approach Δ (δ = origin + Δ·approach_scale).
    #[serde(with = "exact_f64")]
    pub delta: f64,
    /// Reduced force F (P = F·force_scale), repulsive positive.
    #[serde(with = "exact_f64")]
    pub force: f64,
    /// Reduced contact radius (a = radius·radius_scale), ≥ 0.
    #[serde(with = "exact_f64")]
    pub radius: f64,
    /// dΔ/dt; exactly 0 at a turning point.
    #[serde(with = "exact_f64")]
    pub d_delta: f64,
    /// dF/dt; exactly 0 at an extremum of F.
    #[serde(with = "exact_f64")]
    pub d_force: f64,
    /// d(radius)/dt.
    #[serde(with = "exact_f64")]
    pub d_radius: f64,
    /// d²Δ/dt²: required (≠ 0) at turning points, otherwise unused (0).
    #[serde(with = "exact_f64")]
    pub d2_delta: f64,
}

/// The force before the first point of the curve (far from contact).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum FarTail {
    /// Zero force and radius for every Δ below the first point, which must
    /// itself have zero force and radius (Maugis–Dugdale: no interaction for
    /// δ ≤ −h₀).
    Zero,
    /// The rigid Derjaguin form of the Lennard-Jones 3-9 law, asymptotically
    /// exact far from contact, in the reduced units of the Lennard-Jones
    /// sphere (force unit πRΔγ, approach unit z₀, origin where the undeformed
    /// apex sits at z₀): `F = −k(8/3)[h⁻² − h⁻⁸/4]`, `h = 1 − Δ`, zero radius,
    /// with k fitted so that the tail meets the first point (k → 1 as the
    /// first point moves away). The first point must lie on a stable piece
    /// with Δ < 1 and F < 0.
    RigidLennardJones,
}

/// The force beyond the last point of the curve (deep contact).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum DeepTail {
    /// Hertz asymptote with a fitted correction:
    /// `F = H x^{3/2} + B x^q`, `radius = G x^{1/2} + B_a x^{q_a}`,
    /// `x = Δ − delta_zero`, where H and G are exact (Hertz in reduced units)
    /// and `B, q`, `B_a, q_a` are fitted to the value and slope of the last
    /// point.
    Hertz {
        /// H, the Hertz force coefficient in reduced units.
        #[serde(with = "exact_f64")]
        force_coefficient: f64,
        /// G, the Hertz radius coefficient in reduced units.
        #[serde(with = "exact_f64")]
        radius_coefficient: f64,
        /// Δ of the Hertz origin (the reduced approach where the undeformed
        /// sphere touches).
        #[serde(with = "exact_f64")]
        delta_zero: f64,
    },
}

/// A sampled equilibrium path; see the module documentation.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EquilibriumCurve {
    /// Where the curve came from (law, parameters, sampling tolerance).
    pub source: String,
    /// δ (m) at Δ = 0.
    #[serde(with = "exact_f64")]
    pub approach_origin: f64,
    /// Approach unit (m): δ = origin + Δ·approach_scale.
    #[serde(with = "exact_f64")]
    pub approach_scale: f64,
    /// Force unit (N).
    #[serde(with = "exact_f64")]
    pub force_scale: f64,
    /// Radius unit (m).
    #[serde(with = "exact_f64")]
    pub radius_scale: f64,
    /// Points from far to deep.
    pub points: Vec<PathPoint>,
    /// Before the first point.
    pub far_tail: FarTail,
    /// After the last point.
    pub deep_tail: DeepTail,
    /// Exact points beyond the ends (Δ below the first or above the last
    /// point, on the stable pieces reached there), used only to measure the
    /// error of the tails. May be empty.
    pub tail_checks: Vec<PathPoint>,
}

fn bad(name: &'static str, value: f64, bound: &'static str) -> Error {
    Error::InvalidArgument { name, value, bound }
}

impl EquilibriumCurve {
    /// Check the rules of the module documentation.
    pub fn validate(&self) -> Result<()> {
        for (n, v) in [
            ("approach_scale", self.approach_scale),
            ("force_scale", self.force_scale),
            ("radius_scale", self.radius_scale),
        ] {
            crate::error::check::positive(n, v)?;
        }
        crate::error::check::finite("approach_origin", self.approach_origin)?;
        let p = &self.points;
        if p.len() < 2 {
            return Err(bad("points", p.len() as f64, "at least 2 points"));
        }
        for (i, q) in p.iter().chain(self.tail_checks.iter()).enumerate() {
            let all = [
                q.delta, q.force, q.radius, q.d_delta, q.d_force, q.d_radius, q.d2_delta,
            ];
            if !all.iter().all(|v| v.is_finite()) || q.radius < 0.0 {
                return Err(bad(
                    "points",
                    i as f64,
                    "finite numbers and a non-negative radius at every point",
                ));
            }
        }
        for (i, q) in p.iter().enumerate() {
            if q.d_delta == 0.0 && q.d2_delta == 0.0 && !(i + 1 == p.len() || i == 0) {
                return Err(bad(
                    "points.d2_delta",
                    i as f64,
                    "non-zero at a turning point (d_delta == 0)",
                ));
            }
        }
        for i in 0..p.len() - 1 {
            let (a, b) = (&p[i], &p[i + 1]);
            if a.delta == b.delta && a.force == b.force && a.radius == b.radius {
                continue; // corner
            }
            if a.d_delta * b.d_delta < 0.0 {
                return Err(bad(
                    "points",
                    i as f64,
                    "turning points given explicitly (d_delta changes sign between points)",
                ));
            }
            let dir = if a.d_delta != 0.0 {
                a.d_delta
            } else {
                b.d_delta
            };
            if dir == 0.0 || (b.delta - a.delta) * dir <= 0.0 {
                return Err(bad(
                    "points.delta",
                    i as f64,
                    "moving in the direction of d_delta between consecutive points",
                ));
            }
        }
        let last = p[p.len() - 1];
        let prev = p[p.len() - 2];
        if !(last.delta > prev.delta && last.d_delta > 0.0) {
            return Err(bad(
                "points",
                (p.len() - 1) as f64,
                "ending on a stable piece (Δ increasing towards the deep tail)",
            ));
        }
        match self.far_tail {
            FarTail::Zero => {
                if p[0].force != 0.0 || p[0].radius != 0.0 {
                    return Err(bad(
                        "far_tail",
                        p[0].force,
                        "Zero only when the first point has zero force and radius",
                    ));
                }
            }
            FarTail::RigidLennardJones => {
                if !(p[0].delta < 1.0 && p[0].force < 0.0 && p[0].d_delta > 0.0) {
                    return Err(bad(
                        "far_tail",
                        p[0].delta,
                        "RigidLennardJones only when the first point is stable, with Δ < 1 and F < 0",
                    ));
                }
            }
        }
        let DeepTail::Hertz {
            force_coefficient,
            radius_coefficient,
            delta_zero,
        } = self.deep_tail;
        crate::error::check::positive("deep_tail.force_coefficient", force_coefficient)?;
        crate::error::check::positive("deep_tail.radius_coefficient", radius_coefficient)?;
        crate::error::check::finite("deep_tail.delta_zero", delta_zero)?;
        if !(last.delta > delta_zero && last.force > 0.0 && last.radius > 0.0) {
            return Err(bad(
                "points",
                last.delta,
                "a last point in compressive contact (F > 0, radius > 0, Δ > delta_zero)",
            ));
        }
        Ok(())
    }

    /// JSON text of the curve (numbers written exactly).
    pub fn to_json(&self) -> String {
        serde_json::to_string(self).expect("a curve always serialises")
    }

    /// A curve from [`EquilibriumCurve::to_json`] text, validated.
    pub fn from_json(json: &str) -> Result<Self> {
        let c: Self = serde_json::from_str(json).map_err(|e| {
            bad(
                "json",
                e.line() as f64,
                "a serialised EquilibriumCurve (syntax or field error at this line)",
            )
        })?;
        c.validate()?;
        Ok(c)
    }

    /// Sample the equilibrium path of a Maugis–Dugdale sphere, adaptively,
    /// with its turning point (jump-out), load-controlled pull-off and
    /// contact-onset corner exactly.
    ///
    /// Reduced units are Maugis's: force `P̄ = P/(πwR)`, radius
    /// `Ā = a (K/(πwR²))^{1/3}`, and the approach measured from `δ = −h₀`:
    /// `Δ = Δ̄ + 2/(πλ) = (δ + h₀)/(π²w²R/K²)^{1/3}` (so that the jump-in at
    /// `δ = −h₀` is Δ = 0 without cancellation). The path: non-contact branch
    /// `C̄ ∈ [0, C̄₀]` (parameter C̄), then the contact branch with parameter
    /// `t = 1/s`, `s = √(m²−1)` (t = 0 is the junction, a corner where the
    /// contact radius leaves zero), down to `Δ̄ ≥ 10⁶` (Ā ≈ 10³); beyond it
    /// the Hertz tail `P̄ = Δ̄^{3/2}`, `Ā = Δ̄^{1/2}` with a fitted correction,
    /// checked on exact points up to `Δ̄ ≈ 10¹⁵`.
    ///
    /// `tolerance` (relative, in [1e-10, 0.1], as for the tables) steers the
    /// density: neighbouring points interpolate each other to `tolerance/8`.
    /// Errors: `tolerance` out of range, or not reached within
    /// [`MAX_CURVE_POINTS`] points (naming `tolerance`).
    pub fn from_maugis_dugdale(md: &MaugisDugdale, tolerance: f64) -> Result<Self> {
        // Below 1e-10 the interpolation test meets f64 rounding: the
        // bisection then refines towards its depth limit (10^7 points in a
        // second at 3e-12, no end at 1e-12) or yields a non-monotone curve.
        let tol =
            crate::error::check::in_range("tolerance", tolerance, 1e-10, 0.1, "in [1e-10, 0.1]")?;
        let lam = md.lambda();
        let off = 2.0 / (PI * lam);
        let b = 8.0 * lam / (3.0 * PI);
        let c0 = md.closure_c_bar();
        let nc = |c: f64| PathPoint {
            delta: c * (0.5 * c - b),
            force: -0.5 * lam * PI * c * c,
            radius: 0.0,
            d_delta: c - b,
            d_force: -lam * PI * c,
            d_radius: 0.0,
            d2_delta: 1.0,
        };
        // Contact branch at t = 1/s, derivatives along t (d/dt = −s² d/ds).
        let ct = |t: f64| -> Result<PathPoint> {
            let s = 1.0 / t;
            let q = md.contact_point(s)?;
            Ok(contact_path_point(lam, s, &q, off))
        };
        let jo = md.jump_out_point();
        let po = md.load_pull_off_point();
        let s_of = |q: &super::maugis_dugdale::CurvePoint| {
            let m = q.c_bar / q.a_bar;
            ((m - 1.0) * (m + 1.0)).sqrt()
        };
        // Scales of the error measure (reduced units).
        let f_floor = 1e-3 * po.p_bar.abs();
        let a_floor = 1e-3 * po.a_bar.max(1e-3);
        let d_span = (po.delta_bar - jo.delta_bar).abs().max(1e-300);
        let d_floor = 1e-3 * d_span;
        let crit = Crit {
            tol: tol / 8.0,
            floors: [d_floor, f_floor, a_floor],
        };

        let mut pts: Vec<PathPoint> = vec![nc(0.0)];
        // Non-contact branch.
        let junction_left = nc(c0);
        if md.has_contact_jump() {
            sample(&mut pts, 0.0, c0, &|c| Ok(nc(c)), &crit, 8)?;
        } else {
            sample(&mut pts, 0.0, b, &|c| Ok(nc(c)), &crit, 8)?;
            pts.pop();
            let mut t = nc(b);
            t.d_delta = 0.0;
            pts.push(t);
            sample(&mut pts, b, c0, &|c| Ok(nc(c)), &crit, 8)?;
        }
        pts.pop();
        pts.push(junction_left);
        // (junction_right is pushed below, once it is known.)
        // Corner: the contact branch leaves the junction (t = 1/s = 0) with
        // Δ − Δ_j ∝ t², F − F_j ∝ t² and Ā ∝ t, so dΔ/dt = dF/dt = 0 there
        // (F is smooth in Δ, the radius grows like √(Δ − Δ_j)); Ā' and Δ''
        // by Richardson extrapolation from t = h, 2h.
        let hj = 1e-4;
        let (p1, p2) = (ct(hj)?, ct(2.0 * hj)?);
        let junction_right = PathPoint {
            d_delta: 0.0,
            d_force: 0.0,
            d_radius: 2.0 * p1.d_radius - p2.d_radius,
            d2_delta: 2.0 * p1.d_delta / hj - p2.d_delta / (2.0 * hj),
            ..junction_left
        };
        let contact = |t: f64| {
            if t == 0.0 {
                Ok(junction_right)
            } else {
                ct(t)
            }
        };
        let t_pull = 1.0 / s_of(&po);
        let mut pull = contact_path_point(lam, 1.0 / t_pull, &po, off);
        pull.d_force = 0.0;
        // Deep end: Δ̄ ≥ 1e6.
        let mut t_end = 2.0 * t_pull;
        while ct(t_end)?.delta - off < 1e6 {
            t_end *= 2.0;
        }
        pts.push(junction_right);
        let mut t0 = 0.0;
        if md.has_contact_jump() {
            let t_turn = 1.0 / s_of(&jo);
            let mut turn = contact_path_point(lam, 1.0 / t_turn, &jo, off);
            turn.d_delta = 0.0;
            let h = 1e-5 * t_turn;
            turn.d2_delta = (ct(t_turn + h)?.d_delta - ct(t_turn - h)?.d_delta) / (2.0 * h);
            sample_geometric(&mut pts, t0, t_turn, &contact, &crit)?;
            pts.pop();
            pts.push(turn);
            t0 = t_turn;
        }
        sample_geometric(&mut pts, t0, t_pull, &contact, &crit)?;
        pts.pop();
        pts.push(pull);
        // The zero crossing of the force, exactly (the error measure is
        // relative to a floor there, and a knot keeps it small).
        let (mut lo, mut hi) = (t_pull, t_end);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if ct(mid)?.force < 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let t_zero = hi;
        let mut zero = ct(t_zero)?;
        zero.force = 0.0;
        sample_geometric(&mut pts, t_pull, t_zero, &contact, &crit)?;
        pts.pop();
        pts.push(zero);
        sample_geometric(&mut pts, t_zero, t_end, &contact, &crit)?;
        // Exact points deeper than the last one, for the tail error.
        let mut tail_checks = Vec::new();
        let mut t = t_end;
        for _ in 0..24 {
            t *= 1.5;
            tail_checks.push(ct(t)?);
        }
        let curve = EquilibriumCurve {
            source: format!(
                "Maugis-Dugdale sphere: R = {:e} m, E* = {:e} Pa, w = {:e} J/m^2, sigma0 = {:e} Pa \
                 (lambda = {lam:e}); sampled to {tol:e}",
                md.radius, md.e_star, md.work_of_adhesion, md.cohesive_stress
            ),
            approach_origin: -md.range(),
            approach_scale: md.length_scale(),
            force_scale: md.force_scale(),
            radius_scale: md.radius_scale(),
            points: pts,
            far_tail: FarTail::Zero,
            deep_tail: DeepTail::Hertz {
                force_coefficient: 1.0,
                radius_coefficient: 1.0,
                delta_zero: off,
            },
            tail_checks,
        };
        curve.validate()?;
        Ok(curve)
    }
}

impl EquilibriumCurve {
    /// Sample the equilibrium path of a Lennard-Jones sphere (the numerical
    /// solver of [`super::lj_sphere`] with `n_grid` cells, 0 = the converged
    /// default grid, and otherwise default options: the same discrete model
    /// as `lj.solver(n_grid)`), via
    /// [`LjSolver::path_samples`]: neighbouring
    /// points interpolate each other to `tolerance/8` (cubic Hermite along
    /// the continuation's path parameter), with the jump-in and jump-out
    /// turning points, the load-controlled pull-off, the zero of the force
    /// and the contact-onset corner exact.
    ///
    /// Reduced units are the sphere's: Δ = ᾱ = α/z₀ (origin 0, where the
    /// undeformed apex sits at z₀; scale z₀), `F = P/(πRΔγ)`, radius
    /// `a/√(Rz₀)`. The far tail is [`FarTail::RigidLennardJones`] (the path
    /// starts at the central gap `6 + 4√μ`, where the rigid law is exact to
    /// O(μ^{3/2} h̄₀⁻⁴)), checked on exact points out to ten times that gap;
    /// the deep tail is Hertz, `F = 4/(3π μ^{3/2}) x^{3/2}`, `radius = x^{1/2}`
    /// with `x = Δ − delta_zero` and a fitted correction, checked on the
    /// continuation up to three times the last point's force
    /// ([`LjOptions::max_force`]).
    ///
    /// Errors: [`Error::InvalidArgument`] for a tolerance outside
    /// [1e-10, 0.1], a grid in `1..16` or a rigid sphere (μ = 0); the
    /// solver's errors.
    pub fn from_lj_sphere(lj: &LjSphere, n_grid: usize, tolerance: f64) -> Result<Self> {
        let tol =
            crate::error::check::in_range("tolerance", tolerance, 1e-10, 0.1, "in [1e-10, 0.1]")?;
        let mu = lj.tabor();
        if mu.is_nan() || mu <= 0.0 {
            return Err(bad(
                "tabor_parameter",
                mu,
                "> 0 (a rigid sphere never comes into contact)",
            ));
        }
        // The default model of `lj.solver(n_grid)` (the start gap changes
        // only where the continuation begins): far enough that the rigid
        // law, fitted to the first point, is exact to a quarter of the
        // tolerance beyond it (the elastic correction of the attraction is
        // ≈ 20 μ^{3/2} h̄₀⁻⁴ relative, measured at μ = 1).
        let o = LjOptions {
            n_grid,
            start_gap: (6.0 + 4.0 * mu.sqrt()).max((80.0 * mu.powf(1.5) / tol).powf(0.25)),
            ..LjOptions::default()
        };
        let solver = LjSolver::new(lj, o)?;
        let s = solver.path_samples(tol)?;
        let curve = EquilibriumCurve {
            source: format!(
                "Lennard-Jones sphere: R = {:e} m, E* = {:e} Pa, w = {:e} J/m^2, z0 = {:e} m \
                 (mu = {mu:e}), N = {}; sampled to {tol:e}",
                lj.radius,
                lj.e_star,
                lj.work_of_adhesion,
                lj.z0,
                solver.nodes().len()
            ),
            approach_origin: 0.0,
            approach_scale: lj.z0,
            force_scale: lj.force_scale(),
            radius_scale: lj.radius_scale(),
            points: s.points,
            far_tail: FarTail::RigidLennardJones,
            deep_tail: DeepTail::Hertz {
                force_coefficient: 4.0 / (3.0 * PI * mu.powf(1.5)),
                radius_coefficient: 1.0,
                delta_zero: LJ_DELTA_ZERO,
            },
            tail_checks: s.tail_checks,
        };
        curve.validate()?;
        Ok(curve)
    }
}

/// Hertz origin of the Lennard-Jones deep tail (reduced approach).
const LJ_DELTA_ZERO: f64 = 0.0;

/// A contact-branch point of Maugis–Dugdale as a path point along t = 1/s.
fn contact_path_point(
    lam: f64,
    s: f64,
    q: &super::maugis_dugdale::CurvePoint,
    off: f64,
) -> PathPoint {
    let a = q.a_bar;
    // dĀ/ds from Δ̄ = Ā² − (4/3)λĀs or from P̄ = Ā³ − λĀ²g(s), whichever is
    // better conditioned.
    let den_d = 2.0 * a - 4.0 / 3.0 * lam * s;
    let scale_d = 2.0 * a + 4.0 / 3.0 * lam * s;
    let at = s.atan();
    let g = s + (1.0 + s * s) * at;
    let gp = 2.0 + 2.0 * s * at;
    let den_p = 3.0 * a * a - 2.0 * lam * a * g;
    let scale_p = 3.0 * a * a + 2.0 * lam * a * g;
    let da = if (den_d / scale_d).abs() >= 0.2 || (den_d / scale_d).abs() >= (den_p / scale_p).abs()
    {
        (q.ddelta_bar + 4.0 / 3.0 * lam * a) / den_d
    } else {
        (q.dp_bar + lam * a * a * gp) / den_p
    };
    let k = -s * s;
    PathPoint {
        delta: q.delta_bar + off,
        force: q.p_bar,
        radius: a,
        d_delta: k * q.ddelta_bar,
        d_force: k * q.dp_bar,
        d_radius: k * da,
        d2_delta: 0.0,
    }
}

/// Refinement criterion of the sampler.
struct Crit {
    tol: f64,
    floors: [f64; 3],
}

/// Most points an adaptively sampled Maugis–Dugdale curve may have: 2²⁰
/// (56 MiB). A tolerance the interpolation test cannot meet in f64 for
/// extreme parameters (λ ~ 10³ at 1e-10 needs ~10⁴ points) is an error
/// naming `tolerance` instead of a bisection to 2⁴⁰ points per interval.
pub const MAX_CURVE_POINTS: usize = 1 << 20;

fn hermite(y0: f64, m0: f64, y1: f64, m1: f64, h: f64, t: f64) -> f64 {
    let t2 = t * t;
    let t3 = t2 * t;
    (2.0 * t3 - 3.0 * t2 + 1.0) * y0
        + (t3 - 2.0 * t2 + t) * h * m0
        + (-2.0 * t3 + 3.0 * t2) * y1
        + (t3 - t2) * h * m1
}

/// Whether the Hermite interpolants along t between `a` and `b` reproduce
/// the exact midpoint `m`.
fn interpolates(a: &PathPoint, b: &PathPoint, m: &PathPoint, h: f64, c: &Crit) -> bool {
    let pairs = [
        (a.delta, a.d_delta, b.delta, b.d_delta, m.delta),
        (a.force, a.d_force, b.force, b.d_force, m.force),
        (a.radius, a.d_radius, b.radius, b.d_radius, m.radius),
    ];
    pairs
        .iter()
        .zip(c.floors)
        .all(|(&(y0, m0, y1, m1, ym), fl)| {
            (hermite(y0, m0, y1, m1, h, 0.5) - ym).abs() <= c.tol * ym.abs().max(fl)
        })
}

/// Append points of `f` on `(t0, t1]` (the caller has pushed t0), `n0` uniform
/// intervals refined by bisection; the midpoint of every accepted interval is
/// kept too, so that a table can check itself on it.
fn sample(
    out: &mut Vec<PathPoint>,
    t0: f64,
    t1: f64,
    f: &dyn Fn(f64) -> Result<PathPoint>,
    c: &Crit,
    n0: usize,
) -> Result<()> {
    let ts: Vec<f64> = (0..=n0)
        .map(|i| t0 + (t1 - t0) * i as f64 / n0 as f64)
        .collect();
    sample_at(out, &ts, f, c)
}

/// As [`sample`], with initial intervals geometric in t (the first one from
/// `t0` itself), for the contact branch whose scales grow like powers of t.
fn sample_geometric(
    out: &mut Vec<PathPoint>,
    t0: f64,
    t1: f64,
    f: &dyn Fn(f64) -> Result<PathPoint>,
    c: &Crit,
) -> Result<()> {
    let mut ts = vec![t0];
    let lo = if t0 > 0.0 { t0 } else { t1 * 1e-3 };
    let n = ((t1 / lo).log2().ceil() as usize * 2).clamp(4, 200);
    if t0 == 0.0 {
        ts.push(lo);
    }
    for i in 1..=n {
        ts.push(lo * (t1 / lo).powf(i as f64 / n as f64));
    }
    *ts.last_mut().unwrap() = t1;
    ts.dedup();
    sample_at(out, &ts, f, c)
}

fn sample_at(
    out: &mut Vec<PathPoint>,
    ts: &[f64],
    f: &dyn Fn(f64) -> Result<PathPoint>,
    c: &Crit,
) -> Result<()> {
    let mut pa = f(ts[0])?;
    for w in ts.windows(2) {
        let pb = f(w[1])?;
        bisect(out, w[0], &pa, w[1], &pb, f, c, 0)?;
        out.push(pb);
        pa = pb;
    }
    Ok(())
}

#[allow(clippy::too_many_arguments)]
fn bisect(
    out: &mut Vec<PathPoint>,
    ta: f64,
    pa: &PathPoint,
    tb: f64,
    pb: &PathPoint,
    f: &dyn Fn(f64) -> Result<PathPoint>,
    c: &Crit,
    depth: u32,
) -> Result<()> {
    if out.len() >= MAX_CURVE_POINTS {
        return Err(bad(
            "tolerance",
            8.0 * c.tol,
            "reachable within MAX_CURVE_POINTS = 2^20 curve points (f64 rounding limits the tolerance for these parameters; use a larger one)",
        ));
    }
    let tm = 0.5 * (ta + tb);
    let pm = f(tm)?;
    if depth >= 40 || interpolates(pa, pb, &pm, tb - ta, c) {
        out.push(pm);
        return Ok(());
    }
    bisect(out, ta, pa, tm, &pm, f, c, depth + 1)?;
    out.push(pm);
    bisect(out, tm, &pm, tb, pb, f, c, depth + 1)
}
