//! Tabulated contact laws: the exact equilibrium path of an adhesive sphere
//! (Maugis–Dugdale now, the numerical Lennard-Jones sphere later) at the cost
//! of a closed-form law.
//!
//! # Construction
//!
//! [`TabulatedLaw::from_curve`] takes an [`EquilibriumCurve`] (the path in
//! reduced units, with turning points, force extrema and corners explicit)
//! and a relative tolerance. It
//!
//! 1. splits the path at its turning points into monotone pieces in Δ and
//!    keeps the **stable** ones (Δ increasing along the path); the jump
//!    points are the turning points themselves, so jumps happen at exactly the
//!    source's Δ;
//! 2. on each stable piece interpolates `F` and the contact radius with
//!    **cubic Hermite** polynomials in a regularising variable
//!    `u = √(Δ − Δ_turn)` (or `√(Δ_turn − Δ)` towards a turning point at the
//!    piece's end, or `u = Δ − Δ_start` on a piece without turning points):
//!    at a turning point F(Δ) has a square-root singularity (infinite
//!    stiffness) but is analytic in u, and the Hertz regime `F ∝ Δ^{3/2}` is
//!    a cubic in u. Slopes are the source's exact derivatives;
//! 3. picks the knots among the curve's points, greedily, each interval as
//!    long as the interpolant reproduces every curve point it skips to half
//!    the tolerance, with the Fritsch–Carlson condition `α² + β² ≤ 9` so that
//!    the interpolant is **monotone** between knots (force extrema such as the
//!    load-controlled pull-off, and corners such as the contact onset, are
//!    always knots);
//! 4. measures the error of the final table on every curve point it skipped
//!    and on the curve's tail checks, stores it ([`TabulatedLaw::measured_error`])
//!    and fails if it exceeds the tolerance ([`TabulatedLaw::tolerance`], the
//!    stated bound).
//!
//! Beyond the last point the force follows the Hertz asymptote with a
//! correction fitted to the last point's value and slope (see
//! [`DeepTail::Hertz`]); before the first, the curve's [`FarTail`].
//!
//! # Error measure
//!
//! For the force, `|F_table − F_exact| / max(|F_exact|, F_floor)` with
//! `F_floor = 10⁻³ |P_c|` (P_c the load-controlled pull-off force), so that
//! the error is relative except near a zero crossing of the force, where it
//! is relative to a thousandth of the pull-off; for the contact radius the
//! same with `a_floor = 10⁻³ max(a_c, 10⁻³·radius unit)` (a_c the contact
//! radius at the load-controlled pull-off). [`TabulatedLaw::relative_error`]
//! computes it. The default tolerance is [`DEFAULT_TOLERANCE`] = 10⁻⁴.
//!
//! # Lookup
//!
//! O(1) per call: a bucket index computed from the bit pattern of
//! `max(d − d₀, 0) + bias`, where `d = ±(Δ − Δ_ref)` is the variable under
//! the square root (a piecewise-linear logarithm, so buckets are fine where
//! the knots are dense near a turning point and coarse in the deep Hertz
//! regime), at most a couple of comparisons, and two cubic polynomials in
//! `u = √d`. The lookup works on `d` so that it runs while the square root is
//! computed. The stiffness `dP/dδ` is the derivative of the interpolant.
//!
//! No division precedes the lookup: branches and segments are chosen by
//! comparing the overlap δ itself with thresholds computed once per table,
//! each the last (or first) double for which the reduced approach
//! `(δ − origin)/unit` lies within the bound, so the choice is exactly the
//! one the reduced comparison would make; `d` is then `(δ − δ_ref)·(±1/unit)`.
//! A call that stays on its branch and lands on the branch's widest segment
//! (in overlap) takes a single range test for both choices.
//!
//! # Hysteresis
//!
//! Exactly as [`super::MaugisDugdale`]'s: `ContactState::branch` is the
//! index of the stable branch the contact is on — 0 for the far branch (the
//! far tail, plus the first stable piece of the path when the path starts
//! stable, as the Lennard-Jones sphere does), then 1, 2, … in path order. An
//! all-zero state is fresh: approaching from far. A contact stays on its
//! branch while Δ lies in the branch's range (`lo ≤ Δ ≤ hi`, the turning
//! points); beyond `hi` it jumps forward to the next branch that contains Δ
//! (jump-in), below `lo` back to the previous one (jump-out). For
//! Maugis–Dugdale this gives branch 0 = separated for `δ ≤ −h₀` and branch 1
//! = the stable piece down to its turning point, as `MaugisDugdale::eval`.
//! `ContactState::in_contact` is 1 on branches ≥ 1 or when the radius is
//! positive; `cohesive_radius` is 0 (a table does not carry it).
//!
//! # Sharing and storage
//!
//! A table is immutable after construction, `Send + Sync`, and serialises
//! with serde ([`TabulatedLaw::to_json`], [`TabulatedLaw::from_json`]):
//! numbers are written as exact decimal strings, so a loaded table evaluates
//! bit-identically. Loading validates everything (finite numbers, lengths,
//! strictly increasing knots, monotone knot data, branch ranges) and rebuilds
//! the lookup index; a corrupted table is an error, never a panic.
//!
//! # Formulas
//!
//! On a stable piece, with $u = \sqrt{\Delta - \Delta_\mathrm{turn}}$, each interval
//! $[u_k, u_{k+1}]$ of length $h$ carries the cubic Hermite interpolant
//! ($t = (u - u_k)/h$)
//!
//! $$F(u) = (2t^3 - 3t^2 + 1)F_k + (t^3 - 2t^2 + t)\\,h m_k + (-2t^3 + 3t^2)F_{k+1} + (t^3 - t^2)\\,h m_{k+1},$$
//!
//! with $m_k = dF/du$ at $u_k$ (the source's exact slope), monotone when
//! $\alpha^2 + \beta^2 \le 9$ with $\alpha = m_k/\Delta_k$,
//! $\beta = m_{k+1}/\Delta_k$, $\Delta_k = (F_{k+1} - F_k)/h$.
//! The error measure is
//!
//! $$e_F = \frac{\lvert F_\mathrm{table} - F_\mathrm{exact}\rvert}{\max(\lvert F_\mathrm{exact}\rvert,\ 10^{-3}\lvert P_c\rvert)} .$$
//!
//! # References
//!
//! * F. N. Fritsch, R. E. Carlson (1980), "Monotone piecewise cubic
//!   interpolation", SIAM J. Numer. Anal. 17, 238–246,
//!   [doi:10.1137/0717021](https://doi.org/10.1137/0717021).
//! * The tabulated sources: D. Maugis (1992), J. Colloid Interface Sci. 150,
//!   243–269 ([`super::maugis_dugdale`]); J. A. Greenwood (1997), Proc. R. Soc.
//!   Lond. A 453, 1277–1297,
//!   [doi:10.1098/rspa.1997.0070](https://doi.org/10.1098/rspa.1997.0070)
//!   ([`super::lj_sphere`]).

// NaN-aware comparisons (`!(x <= hi)`) are intended.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::type_complexity)]

use super::curve::{exact_f64, exact_vec, DeepTail, EquilibriumCurve, FarTail, PathPoint};
use super::{
    below_pull_off, check_delta, check_force, finite_response, overflow, BatchError, ContactState,
    Control, LjSphere, MaugisDugdale, NormalContact, NormalResponse, RawBatch,
};
use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};

/// Default relative tolerance of a table (see the module's error measure).
pub const DEFAULT_TOLERANCE: f64 = 1e-4;

/// Bound on the reduced stiffness (infinite at a turning point).
const STIFFNESS_BAR_MAX: f64 = 1e100;
/// Identifies the serialised format.
const FORMAT: &str = "asperity-tabulated-law-1";
/// Largest lookup index per segment (entries).
const MAX_INDEX: usize = 1 << 16;

// ------------------------------------------------------------------ data

/// How a segment maps Δ to its interpolation variable u ≥ 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
enum Transform {
    /// `u = √(sign·(Δ − reference))`.
    Sqrt,
    /// `u = sign·(Δ − reference)`.
    Linear,
}

/// Serialised segment: knots in ascending u.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct SegmentData {
    transform: Transform,
    /// +1 or −1.
    #[serde(with = "exact_f64")]
    sign: f64,
    #[serde(with = "exact_f64")]
    reference: f64,
    /// Δ range covered.
    #[serde(with = "exact_f64")]
    lo: f64,
    #[serde(with = "exact_f64")]
    hi: f64,
    #[serde(with = "exact_vec")]
    u: Vec<f64>,
    #[serde(with = "exact_vec")]
    force: Vec<f64>,
    /// dF/du.
    #[serde(with = "exact_vec")]
    d_force: Vec<f64>,
    #[serde(with = "exact_vec")]
    radius: Vec<f64>,
    /// d(radius)/du.
    #[serde(with = "exact_vec")]
    d_radius: Vec<f64>,
}

/// Serialised branch: a stable piece. `None` bounds are unbounded.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct BranchData {
    #[serde(with = "crate::serde_exact::opt")]
    lo: Option<f64>,
    #[serde(with = "crate::serde_exact::opt")]
    hi: Option<f64>,
    segments: Vec<SegmentData>,
}

/// Serialised far tail.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
enum FarData {
    Zero,
    RigidLennardJones {
        #[serde(with = "exact_f64")]
        k: f64,
    },
}

/// Serialised deep tail: `F = h x^{3/2} + bf x^{qf}`, `a = g x^{1/2} + ba x^{qa}`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
struct DeepData {
    #[serde(with = "exact_f64")]
    delta_zero: f64,
    #[serde(with = "exact_f64")]
    h: f64,
    #[serde(with = "exact_f64")]
    bf: f64,
    #[serde(with = "exact_f64")]
    qf: f64,
    #[serde(with = "exact_f64")]
    g: f64,
    #[serde(with = "exact_f64")]
    ba: f64,
    #[serde(with = "exact_f64")]
    qa: f64,
}

/// The serialised table.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
struct TableData {
    format: String,
    source: String,
    #[serde(with = "exact_f64")]
    tolerance: f64,
    #[serde(with = "exact_f64")]
    measured_error: f64,
    #[serde(with = "exact_f64")]
    force_floor: f64,
    #[serde(with = "exact_f64")]
    radius_floor: f64,
    #[serde(with = "exact_f64")]
    approach_origin: f64,
    #[serde(with = "exact_f64")]
    approach_scale: f64,
    #[serde(with = "exact_f64")]
    force_scale: f64,
    #[serde(with = "exact_f64")]
    radius_scale: f64,
    branches: Vec<BranchData>,
    far: FarData,
    deep: DeepData,
    /// Reduced load-controlled pull-off force and the u of its knot (in the
    /// last branch's single segment).
    #[serde(with = "exact_f64")]
    load_pull_off: f64,
    #[serde(with = "exact_f64")]
    load_pull_off_u: f64,
    /// Reduced displacement-controlled pull-off force.
    #[serde(with = "exact_f64")]
    displacement_pull_off: f64,
}

// --------------------------------------------------------------- runtime

/// One Hermite interval as a cubic in `s = u − lo ∈ [0, hi − lo]`:
/// `y(s) = c0 + s(c1 + s(c2 + s c3))` for the force and the radius side by
/// side (`c[j] = [F_j, a_j]`), and the stiffness `dF/dΔ = F'(s)·du/dΔ` as
/// `(e0 + s(e1 + s e2))/u` on a square-root segment (`du/dΔ = ±1/(2u)`) or
/// without the division on a linear one (`du/dΔ = ±1`), the factor ±½ or ±1
/// folded into `e`.
#[derive(Debug, Clone, Copy)]
struct Interval {
    lo: f64,
    hi: f64,
    c: [[f64; 2]; 4],
    e: [f64; 3],
}

impl Interval {
    /// From the Hermite coefficients in `t = s/(hi − lo)` and the factor of
    /// du/dΔ (±½ times 1/u, or ±1).
    fn new(lo: f64, hi: f64, du_dx_factor: f64, ct: [[f64; 2]; 4]) -> Interval {
        let inv_h = 1.0 / (hi - lo);
        let mut c = ct;
        let mut scale = 1.0;
        for cj in c.iter_mut() {
            *cj = [cj[0] * scale, cj[1] * scale];
            scale *= inv_h;
        }
        let e = [
            du_dx_factor * c[1][0],
            du_dx_factor * 2.0 * c[2][0],
            du_dx_factor * 3.0 * c[3][0],
        ];
        Interval { lo, hi, c, e }
    }

    /// The force's coefficients (in `s`).
    fn f(&self) -> [f64; 4] {
        self.c.map(|p| p[0])
    }

    /// The force at `t = s/(hi − lo) ∈ [0, 1]`, and its derivative in t.
    fn force_at(&self, t: f64) -> (f64, f64) {
        let h = self.hi - self.lo;
        let f = self.f();
        (horner(&f, t * h), horner_d(&f, t * h) * h)
    }
}

#[derive(Debug, Clone)]
struct Segment {
    sqrt: bool,
    sign: f64,
    /// Overlap (m) threshold equivalent to `Δ ≤ hi` (see
    /// [`overlap_threshold`]).
    hi_delta: f64,
    /// Where the segment's range begins in the branch's scan: the threshold
    /// equivalent to `Δ ≥ lo` for the first segment, otherwise the overlap
    /// just above the previous segment's `hi_delta` (a δ on both is on the
    /// earlier one).
    start_delta: f64,
    /// The reference as an overlap (m), and `sign/approach_scale`: the
    /// pre-root variable is `d = (δ − reference_delta)·d_per_delta`.
    reference_delta: f64,
    d_per_delta: f64,
    reference: f64,
    /// The first knot in `d`.
    d0: f64,
    bias: f64,
    bias_bits: u64,
    shift: u32,
    intervals: Vec<Interval>,
    /// The end of each interval in `d` (`hi²` or `hi`), the last one +∞:
    /// the walk from an index entry stops at the interval holding `d`.
    ends: Vec<f64>,
    index: Vec<u32>,
}

#[derive(Debug, Clone)]
struct Branch {
    lo: f64,
    hi: f64,
    /// Overlap (m) thresholds equivalent to `Δ ≥ lo` and `Δ ≤ hi`.
    lo_delta: f64,
    hi_delta: f64,
    /// The overlaps (m) where a contact on this branch stays on it and is
    /// on its widest segment (in overlap), `[max(lo_delta, start),
    /// min(hi_delta, end)]` of that segment; empty (+∞, −∞) without
    /// segments. Most calls land here and take one range test.
    stay_lo: f64,
    stay_hi: f64,
    /// The widest segment.
    stay: usize,
    segments: Vec<Segment>,
}

/// A tabulated adhesive-sphere law; see the module documentation. Build it
/// with [`TabulatedLaw::from_curve`] or [`TabulatedLaw::from_maugis_dugdale`],
/// load it with [`TabulatedLaw::from_json`].
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(into = "TableData", try_from = "TableData")]
pub struct TabulatedLaw {
    data: TableData,
    branches: Vec<Branch>,
    stiffness_scale: f64,
    /// The load-controlled pull-off's interval in the last segment.
    load_interval: usize,
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<TabulatedLaw>();
};

impl From<TabulatedLaw> for TableData {
    fn from(t: TabulatedLaw) -> Self {
        t.data
    }
}

impl TryFrom<TableData> for TabulatedLaw {
    type Error = Error;
    fn try_from(d: TableData) -> Result<Self> {
        TabulatedLaw::from_data(d)
    }
}

fn bad(name: &'static str, value: f64, bound: &'static str) -> Error {
    Error::InvalidArgument { name, value, bound }
}

#[inline]
fn horner(c: &[f64; 4], t: f64) -> f64 {
    c[0] + t * (c[1] + t * (c[2] + t * c[3]))
}

#[inline]
fn horner_d(c: &[f64; 4], t: f64) -> f64 {
    c[1] + t * (2.0 * c[2] + t * (3.0 * c[3]))
}

/// A segment's pre-root variable `d` at its interpolation variable `u`:
/// `u²` for a square-root segment, `u` for a linear one.
#[inline]
fn d_of_u(sqrt: bool, u: f64) -> f64 {
    if sqrt {
        u * u
    } else {
        u
    }
}

/// Force and radius coefficients side by side.
fn pair(f: [f64; 4], a: [f64; 4]) -> [[f64; 2]; 4] {
    [[f[0], a[0]], [f[1], a[1]], [f[2], a[2]], [f[3], a[3]]]
}

fn coefficients(y0: f64, m0: f64, y1: f64, m1: f64, h: f64) -> [f64; 4] {
    let d = y1 - y0;
    let (p0, p1) = (h * m0, h * m1);
    [y0, p0, 3.0 * d - 2.0 * p0 - p1, p0 + p1 - 2.0 * d]
}

/// Fritsch–Carlson: whether the Hermite cubic through (y0, m0), (y1, m1)
/// over length h is monotone.
fn monotone(y0: f64, m0: f64, y1: f64, m1: f64, h: f64) -> bool {
    let s = (y1 - y0) / h;
    if s == 0.0 {
        return m0 == 0.0 && m1 == 0.0;
    }
    let (al, be) = (m0 / s, m1 / s);
    al >= 0.0 && be >= 0.0 && al * al + be * be <= 9.0 * (1.0 + 1e-12)
}

/// Make the slopes of one interval monotone (Fritsch–Carlson limiter).
fn limit(y0: f64, m0: &mut f64, y1: f64, m1: &mut f64, h: f64) {
    let s = (y1 - y0) / h;
    if s == 0.0 {
        *m0 = 0.0;
        *m1 = 0.0;
        return;
    }
    if *m0 / s < 0.0 {
        *m0 = 0.0;
    }
    if *m1 / s < 0.0 {
        *m1 = 0.0;
    }
    let (al, be) = (*m0 / s, *m1 / s);
    let r = al * al + be * be;
    if r > 9.0 {
        let tau = 3.0 / r.sqrt();
        *m0 = tau * al * s;
        *m1 = tau * be * s;
    }
}

impl Branch {
    /// Whether overlap δ (m) is in the stay range.
    #[inline(always)]
    fn stays(&self, delta: f64) -> bool {
        delta >= self.stay_lo && delta <= self.stay_hi
    }

    /// The widest segment, on a branch whose stay range is not empty.
    #[inline(always)]
    fn stay_segment(&self) -> &Segment {
        debug_assert!(self.stay_lo <= self.stay_hi);
        // SAFETY: a non-empty stay range means segments, `stay` one of them
        // (`from_data`).
        unsafe { self.segments.get_unchecked(self.stay) }
    }
}

impl Segment {
    /// Index key of `d` (see [`Segment::interval`]): never negative, as
    /// `max(d − d0, 0) + bias ≥ bias`.
    #[inline]
    fn key(&self, d: f64) -> u64 {
        ((d - self.d0).max(0.0) + self.bias).to_bits() - self.bias_bits
    }

    #[inline]
    fn x_of(&self, u: f64) -> f64 {
        if self.sqrt {
            self.reference + self.sign * u * u
        } else {
            self.reference + self.sign * u
        }
    }

    /// Reduced (F, radius, dF/dΔ) at overlap δ (m).
    #[inline(always)]
    fn eval(&self, delta: f64) -> (f64, f64, f64) {
        // d = sign·(Δ − Δ_ref) from δ by one product: no division by the
        // approach unit on the way to the lookup.
        let d = (delta - self.reference_delta) * self.d_per_delta;
        // The interval is looked up on d, so that the lookup does not wait
        // for the square root.
        let iv = self.interval(d);
        // u, and 1/u (sqrt; the ±½ of du/dΔ = ±1/(2u) is in the stiffness
        // coefficients) or 1 (linear), the quotient taken here so that it
        // runs while the interval is looked up.
        let root = d.max(0.0).sqrt();
        let (u, den) = if self.sqrt { (root, root) } else { (d, 1.0) };
        let inv_den = 1.0 / den;
        let s = u - iv.lo;
        let c = &iv.c;
        let mut y = c[3];
        for cj in [c[2], c[1], c[0]] {
            y = [cj[0] + s * y[0], cj[1] + s * y[1]];
        }
        let e = &iv.e;
        let k = (e[0] + s * (e[1] + s * e[2])) * inv_den;
        let k = if k.abs() < STIFFNESS_BAR_MAX {
            k
        } else {
            self.stiffness_limit(iv, u, k)
        };
        (y[0], y[1].max(0.0), k)
    }

    /// The stiffness at a turning point (u = 0, where du/dΔ is infinite)
    /// or beyond ±[`STIFFNESS_BAR_MAX`]. Inlined behind its (predicted)
    /// test: as a call it would clobber every vector register and make the
    /// caller spill the interpolant's coefficients on the common path.
    #[inline(always)]
    fn stiffness_limit(&self, iv: &Interval, u: f64, k: f64) -> f64 {
        if self.sqrt && u == 0.0 && iv.e[0] == 0.0 {
            // F − F₀ ∝ u²: the finite limit, ±F''(0)/2.
            iv.e[1]
        } else if k.is_nan() {
            STIFFNESS_BAR_MAX
        } else {
            k.clamp(-STIFFNESS_BAR_MAX, STIFFNESS_BAR_MAX)
        }
    }

    #[inline(always)]
    fn interval(&self, d: f64) -> &Interval {
        let b = ((self.key(d) >> self.shift) as usize).min(self.index.len() - 1);
        // SAFETY (the invariants of `build`, and a segment is never changed
        // after it): the index is not empty, so `b` is in range; its entries
        // are below `intervals.len() == ends.len()`; the last end is +∞ and
        // the walk compares a finite value (NaN becomes f64::MAX), so it
        // stops in range.
        unsafe {
            let mut i = *self.index.get_unchecked(b) as usize;
            let dw = d.min(f64::MAX);
            while dw >= *self.ends.get_unchecked(i) {
                i += 1;
            }
            self.intervals.get_unchecked(i)
        }
    }

    fn build(d: &SegmentData) -> Result<Segment> {
        let n = d.u.len();
        let sqrt = d.transform == Transform::Sqrt;
        let mut intervals = Vec::with_capacity(n);
        let mut ends = Vec::with_capacity(n);
        for i in 0..n - 1 {
            let h = d.u[i + 1] - d.u[i];
            if h == 0.0 {
                continue;
            }
            ends.push(d_of_u(sqrt, d.u[i + 1]));
            intervals.push(Interval::new(
                d.u[i],
                d.u[i + 1],
                if sqrt { 0.5 * d.sign } else { d.sign },
                pair(
                    coefficients(
                        d.force[i],
                        d.d_force[i],
                        d.force[i + 1],
                        d.d_force[i + 1],
                        h,
                    ),
                    coefficients(
                        d.radius[i],
                        d.d_radius[i],
                        d.radius[i + 1],
                        d.d_radius[i + 1],
                        h,
                    ),
                ),
            ));
        }
        if intervals.is_empty() {
            return Err(bad("segment.u", n as f64, "spanning a non-empty range"));
        }
        let d0 = d_of_u(sqrt, intervals[0].lo);
        let span = ends[ends.len() - 1] - d0;
        let bias = (ends[0] - d0).max(span * 1e-12);
        let mut seg = Segment {
            sqrt,
            sign: d.sign,
            reference: d.reference,
            hi_delta: f64::NAN,
            start_delta: f64::NAN,
            reference_delta: f64::NAN,
            d_per_delta: f64::NAN,
            d0,
            bias,
            bias_bits: bias.to_bits(),
            shift: 52,
            intervals,
            ends: Vec::new(),
            index: Vec::new(),
        };
        // The coarsest index (largest shift) whose buckets hold at most two
        // interval starts, within MAX_INDEX entries.
        let keys: Vec<u64> = seg
            .intervals
            .iter()
            .map(|iv| seg.key(d_of_u(sqrt, iv.lo)))
            .collect();
        let kmax = seg.key(ends[ends.len() - 1]);
        let mut best = 62u32;
        for shift in (0..=62u32).rev() {
            let nb = (kmax >> shift) + 1;
            if nb as usize > MAX_INDEX {
                break;
            }
            best = shift;
            let mut worst = 0;
            let mut run = 0;
            let mut prev = None;
            for &k in &keys {
                let b = Some(k >> shift);
                run = if b == prev { run + 1 } else { 1 };
                prev = b;
                worst = worst.max(run);
            }
            if worst <= 2 {
                break;
            }
        }
        seg.shift = best;
        let nb = ((kmax >> best) + 1) as usize;
        let mut index = Vec::with_capacity(nb);
        let mut j = 0usize;
        for b in 0..nb as u64 {
            // Largest interval whose start key lies in an earlier bucket.
            while j + 1 < keys.len() && (keys[j + 1] >> best) < b {
                j += 1;
            }
            index.push(j as u32);
        }
        seg.index = index;
        if let Some(last) = ends.last_mut() {
            *last = f64::INFINITY;
        }
        seg.ends = ends;
        Ok(seg)
    }
}

// ------------------------------------------------------------- building

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

/// Measure of the module documentation, in reduced units.
#[inline]
fn measure(ft: f64, fe: f64, at: f64, ae: f64, ff: f64, af: f64) -> f64 {
    ((ft - fe).abs() / fe.abs().max(ff)).max((at - ae).abs() / ae.max(af))
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
    /// [1e-10, 0.1]; [`DEFAULT_TOLERANCE`] is 1e-4), in the error measure of
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
    /// the contact branch where the grid leaves several).
    ///
    /// Build time (optimised, tolerance 1e-4): 0.1–0.5 s at N = 128 for
    /// μ ≤ 1, about 2 s at μ = 3 and 10 (N = 256) and 17 s at μ = 10 on the
    /// default grid (512; BENCHMARKS.md §3). Tolerances near 1e-10 take tens
    /// of seconds and fail at μ = 1 (`NotConverged`, residual 3e-8).
    pub fn from_lj_sphere(lj: &LjSphere, n_grid: usize, tolerance: f64) -> Result<Self> {
        let curve = EquilibriumCurve::from_lj_sphere(lj, n_grid, tolerance)?;
        Self::from_curve(&curve, tolerance)
    }

    /// Validate serialised data and build the runtime structures.
    fn from_data(d: TableData) -> Result<Self> {
        if d.format != FORMAT {
            return Err(bad("format", 0.0, "\"asperity-tabulated-law-1\""));
        }
        crate::error::check::in_range("tolerance", d.tolerance, 1e-10, 0.1, "in [1e-10, 0.1]")?;
        crate::error::check::in_range(
            "measured_error",
            d.measured_error,
            0.0,
            d.tolerance,
            "in [0, tolerance]",
        )?;
        for (n, v) in [
            ("force_floor", d.force_floor),
            ("radius_floor", d.radius_floor),
            ("approach_scale", d.approach_scale),
            ("force_scale", d.force_scale),
            ("radius_scale", d.radius_scale),
            ("deep.h", d.deep.h),
            ("deep.g", d.deep.g),
        ] {
            crate::error::check::positive(n, v)?;
        }
        let nbr = d.branches.len();
        if nbr < 2 && d.branches.first().map_or(true, |b| b.segments.is_empty()) {
            return Err(bad("branches", nbr as f64, "at least one stable branch"));
        }
        crate::error::check::finite("approach_origin", d.approach_origin)?;
        let (o, sc) = (d.approach_origin, d.approach_scale);
        let mut branches: Vec<Branch> = Vec::with_capacity(nbr);
        for (k, b) in d.branches.iter().enumerate() {
            let lo = match (k, b.lo) {
                (0, None) => f64::NEG_INFINITY,
                (k, Some(v)) if k > 0 => v,
                _ => {
                    return Err(bad(
                        "branches.lo",
                        k as f64,
                        "unbounded exactly for branch 0",
                    ))
                }
            };
            let hi = match (k + 1 == nbr, b.hi) {
                (true, None) => f64::INFINITY,
                (false, Some(v)) => v,
                _ => {
                    return Err(bad(
                        "branches.hi",
                        k as f64,
                        "unbounded exactly for the last branch",
                    ))
                }
            };
            if !(lo < hi) || (k > 0 && b.segments.is_empty()) {
                return Err(bad(
                    "branches",
                    k as f64,
                    "lo < hi and segments on branches ≥ 1",
                ));
            }
            let mut segments: Vec<Segment> = Vec::with_capacity(b.segments.len());
            let mut x_prev = f64::NEG_INFINITY;
            for s in &b.segments {
                let n = s.u.len();
                if n < 2
                    || s.force.len() != n
                    || s.d_force.len() != n
                    || s.radius.len() != n
                    || s.d_radius.len() != n
                {
                    return Err(bad(
                        "segment",
                        n as f64,
                        "at least 2 knots and equal lengths",
                    ));
                }
                if !(s.sign == 1.0 || s.sign == -1.0) || !(s.lo < s.hi) || s.lo < x_prev {
                    return Err(bad("segment", s.lo, "sign ±1 and ordered ranges lo < hi"));
                }
                x_prev = s.hi;
                if (k > 0 && s.lo < lo) || s.hi > hi {
                    return Err(bad("segment", s.lo, "inside its branch's range"));
                }
                for i in 0..n {
                    if s.u[i] < 0.0 || s.radius[i] < 0.0 {
                        return Err(bad("segment.u", s.u[i], "u ≥ 0 and radius ≥ 0"));
                    }
                }
                for i in 0..n - 1 {
                    let h = s.u[i + 1] - s.u[i];
                    let dup = h == 0.0 && (i + 2 >= n || s.u[i + 2] > s.u[i + 1]) && i > 0;
                    if !(h > 0.0 || dup) {
                        return Err(bad("segment.u", i as f64, "strictly increasing knots"));
                    }
                    if h > 0.0
                        && !(monotone(
                            s.force[i],
                            s.d_force[i],
                            s.force[i + 1],
                            s.d_force[i + 1],
                            h,
                        ) && monotone_or_flat(
                            s.radius[i],
                            s.d_radius[i],
                            s.radius[i + 1],
                            s.d_radius[i + 1],
                            h,
                        ))
                    {
                        return Err(bad("segment.force", i as f64, "monotone between knots"));
                    }
                }
                // The knot range reproduces the Δ range.
                let sq = s.transform == Transform::Sqrt;
                let xu = |u: f64| {
                    if sq {
                        s.reference + s.sign * u * u
                    } else {
                        s.reference + s.sign * u
                    }
                };
                let (x0, x1) = (xu(s.u[0]), xu(s.u[n - 1]));
                let (xa, xb) = if s.sign > 0.0 { (x0, x1) } else { (x1, x0) };
                let tolx = 1e-9 * (s.hi - s.lo).abs().max(s.hi.abs()).max(s.lo.abs());
                if (xa - s.lo).abs() > tolx || (xb - s.hi).abs() > tolx {
                    return Err(bad("segment.lo", s.lo, "equal to the Δ of its first knot"));
                }
                let mut seg = Segment::build(s)?;
                seg.hi_delta = overlap_threshold(o, sc, s.hi, false);
                seg.start_delta = match segments.last() {
                    None => overlap_threshold(o, sc, s.lo, true),
                    Some(p) => next_up(p.hi_delta),
                };
                seg.reference_delta = o + s.reference * sc;
                seg.d_per_delta = s.sign / sc;
                segments.push(seg);
            }
            let (lo_delta, hi_delta) = (
                overlap_threshold(o, sc, lo, true),
                overlap_threshold(o, sc, hi, false),
            );
            // The widest segment (the first of equals), by its overlap range
            // within the branch's.
            let range = |s: &Segment| (lo_delta.max(s.start_delta), hi_delta.min(s.hi_delta));
            let width = |s: &Segment| {
                let (a, b) = range(s);
                b - a
            };
            let stay = (0..segments.len()).fold(0, |w, j| {
                if width(&segments[j]) > width(&segments[w]) {
                    j
                } else {
                    w
                }
            });
            let (stay_lo, stay_hi) = segments
                .get(stay)
                .map_or((f64::INFINITY, f64::NEG_INFINITY), range);
            branches.push(Branch {
                lo,
                hi,
                lo_delta,
                hi_delta,
                stay_lo,
                stay_hi,
                stay,
                segments,
            });
        }
        let far_k = match d.far {
            FarData::Zero => 0.0,
            FarData::RigidLennardJones { k } => crate::error::check::positive("far.k", k)?,
        };
        if matches!(d.far, FarData::RigidLennardJones { .. }) && branches[0].segments.is_empty() {
            return Err(bad(
                "far",
                far_k,
                "a far branch with segments for a Lennard-Jones tail",
            ));
        }
        let ls = branches[nbr - 1].segments.last().ok_or(bad(
            "branches",
            nbr as f64,
            "segments on the last branch",
        ))?;
        let load_interval = ls
            .intervals
            .iter()
            .position(|iv| iv.lo == d.load_pull_off_u)
            .ok_or(bad(
                "load_pull_off_u",
                d.load_pull_off_u,
                "a knot of the last branch",
            ))?;
        if ls.intervals[load_interval].c[0][0] != d.load_pull_off
            || ls.intervals[load_interval..]
                .iter()
                .any(|iv| iv.force_at(1.0).0 < iv.c[0][0])
        {
            return Err(bad(
                "load_pull_off",
                d.load_pull_off,
                "the force at its knot, increasing beyond",
            ));
        }
        if !(d.load_pull_off < 0.0 && d.displacement_pull_off <= 0.0) {
            return Err(bad("load_pull_off", d.load_pull_off, "adhesive (< 0)"));
        }
        for v in [
            d.deep.delta_zero,
            d.deep.bf,
            d.deep.qf,
            d.deep.ba,
            d.deep.qa,
        ] {
            crate::error::check::finite("deep", v)?;
        }
        let stiffness_scale = d.force_scale / d.approach_scale;
        if !stiffness_scale.is_finite() {
            return Err(bad("force_scale", d.force_scale, "a finite stiffness unit"));
        }
        Ok(TabulatedLaw {
            stiffness_scale,
            branches,
            load_interval,
            data: d,
        })
    }

    // ------------------------------------------------------------ accessors

    /// The stated bound of the relative error (the tolerance the table was
    /// built for), in the measure of the module documentation.
    #[inline]
    pub fn tolerance(&self) -> f64 {
        self.data.tolerance
    }

    /// The largest error measured at construction, on every curve point the
    /// table skipped and on the curve's tail checks (≤ [`Self::tolerance`]).
    #[inline]
    pub fn measured_error(&self) -> f64 {
        self.data.measured_error
    }

    /// The error measure of the module documentation between an exact
    /// response and an approximate one (dimensionless).
    pub fn relative_error(&self, exact: &NormalResponse, approx: &NormalResponse) -> f64 {
        let d = &self.data;
        measure(
            approx.force / d.force_scale,
            exact.force / d.force_scale,
            approx.contact_radius / d.radius_scale,
            exact.contact_radius / d.radius_scale,
            d.force_floor,
            d.radius_floor,
        )
    }

    /// Where the table came from.
    pub fn source(&self) -> &str {
        &self.data.source
    }

    /// Number of branches (ContactState::branch runs over 0..branch_count()).
    pub fn branch_count(&self) -> usize {
        self.branches.len()
    }

    /// The overlap range (m) of branch `k`: a contact on it stays while
    /// `lo ≤ δ ≤ hi` (up to rounding: the comparison is made in reduced
    /// units); `lo` is the jump-out point, `hi` the jump-in point.
    pub fn branch_range(&self, k: usize) -> Option<(f64, f64)> {
        let b = self.branches.get(k)?;
        let d = &self.data;
        Some((
            d.approach_origin + b.lo * d.approach_scale,
            d.approach_origin + b.hi * d.approach_scale,
        ))
    }

    /// All segments, branch by branch.
    fn segments(&self) -> impl Iterator<Item = &Segment> {
        self.branches.iter().flat_map(|b| &b.segments)
    }

    /// Number of knots over all segments.
    pub fn knot_count(&self) -> usize {
        self.segments().map(|s| s.intervals.len() + 1).sum()
    }

    /// Number of lookup-index entries over all segments.
    pub fn index_len(&self) -> usize {
        self.segments().map(|s| s.index.len()).sum()
    }

    /// Memory of the evaluation structures (bytes).
    pub fn memory_bytes(&self) -> usize {
        self.segments()
            .map(|s| {
                s.intervals.len() * core::mem::size_of::<Interval>()
                    + s.ends.len() * 8
                    + s.index.len() * 4
                    + core::mem::size_of::<Segment>()
            })
            .sum::<usize>()
            + self.branches.len() * core::mem::size_of::<Branch>()
            + core::mem::size_of::<Self>()
    }

    /// JSON text of the table (numbers written exactly).
    pub fn to_json(&self) -> String {
        serde_json::to_string(&self.data).expect("a table always serialises")
    }

    /// A table from [`TabulatedLaw::to_json`] text, validated; evaluates
    /// bit-identically to the table written.
    pub fn from_json(json: &str) -> Result<Self> {
        let d: TableData = serde_json::from_str(json).map_err(|e| {
            bad(
                "json",
                e.line() as f64,
                "a serialised TabulatedLaw (syntax, field or value error at this line)",
            )
        })?;
        Self::from_data(d)
    }

    // ---------------------------------------------------------- evaluation

    /// Whether overlap δ (m) lies on branch j.
    #[inline]
    fn contains(&self, j: usize, delta: f64) -> bool {
        let b = &self.branches[j];
        delta >= b.lo_delta && delta <= b.hi_delta
    }

    /// The first branch after k that contains δ (m), else the last: the
    /// last needs no test, so a two-branch table jumps without one.
    #[inline]
    fn jump_forward(&self, k: usize, delta: f64) -> usize {
        let n = self.branches.len();
        (k + 1..n - 1)
            .find(|&j| self.contains(j, delta))
            .unwrap_or(n - 1)
    }

    /// The last branch before k that contains δ (m), else branch 0.
    #[inline]
    fn jump_back(&self, k: usize, delta: f64) -> usize {
        (1..k).rev().find(|&j| self.contains(j, delta)).unwrap_or(0)
    }

    /// Overlap δ (m) at reduced approach Δ.
    fn overlap(&self, x: f64) -> f64 {
        self.data.approach_origin + x * self.data.approach_scale
    }

    /// Reduced approach Δ at overlap δ (m).
    #[inline]
    fn reduced(&self, delta: f64) -> f64 {
        (delta - self.data.approach_origin) / self.data.approach_scale
    }

    /// Reduced (F, radius, dF/dΔ) on branch k at overlap δ (m).
    ///
    /// The segments are scanned from the last, where most of a branch's
    /// range lies: the first segment that starts at or below δ (the
    /// `start_delta` are increasing, so this is the first whose range ends
    /// at or above δ).
    #[inline(always)]
    fn on_branch(&self, k: usize, delta: f64) -> (f64, f64, f64) {
        let segs = &self.branches[k].segments;
        if let Some(last) = segs.last() {
            if delta > last.hi_delta {
                return self.beyond(k, delta);
            }
            for s in segs.iter().rev() {
                if delta >= s.start_delta {
                    return s.eval(delta);
                }
            }
        }
        self.far(self.reduced(delta))
    }

    #[cold]
    fn beyond(&self, k: usize, delta: f64) -> (f64, f64, f64) {
        match self.branches[k].segments.last() {
            Some(s) if k + 1 < self.branches.len() => s.eval(delta),
            _ => self.deep(self.reduced(delta)),
        }
    }

    fn far(&self, x: f64) -> (f64, f64, f64) {
        match self.data.far {
            FarData::Zero => (0.0, 0.0, 0.0),
            FarData::RigidLennardJones { k } => {
                let (g, dg) = rigid_lj(x);
                (k * g, 0.0, k * dg)
            }
        }
    }

    fn deep(&self, x: f64) -> (f64, f64, f64) {
        let d = &self.data.deep;
        let z = x - d.delta_zero;
        // One logarithm and two exponentials instead of three `powf`: the
        // tail is where deep-contact calls land, and `powf` cost 3× the
        // whole table lookup there.
        let (sz, lz) = (z.sqrt(), z.ln());
        let (zf1, za) = (((d.qf - 1.0) * lz).exp(), (d.qa * lz).exp());
        let f = d.h * z * sz + d.bf * z * zf1;
        let a = d.g * sz + d.ba * za;
        let k = 1.5 * d.h * sz + d.qf * d.bf * zf1;
        (f, a.max(0.0), k)
    }

    /// The last segment of the last branch (validated to exist).
    fn last_segment(&self) -> &Segment {
        let segs = &self.branches[self.branches.len() - 1].segments;
        &segs[segs.len() - 1]
    }

    /// Reduced approach on the load-controlled stable branch at reduced
    /// force `target` (≥ the load pull-off).
    fn x_at_load(&self, target: f64) -> f64 {
        let s = self.last_segment();
        let ivs = &s.intervals[self.load_interval..];
        let end = ivs[ivs.len() - 1].force_at(1.0).0;
        if target > end {
            // Deep tail: Newton on z, F increasing and convex.
            let d = &self.data.deep;
            let x_last = s.x_of(ivs[ivs.len() - 1].hi);
            let mut z = (x_last - d.delta_zero).max((target / d.h).powf(2.0 / 3.0));
            for _ in 0..100 {
                let f = d.h * z * z.sqrt() + d.bf * z.powf(d.qf) - target;
                let k = 1.5 * d.h * z.sqrt() + d.qf * d.bf * z.powf(d.qf - 1.0);
                let step = f / k;
                let zn = (z - step).max(0.5 * z);
                if !(zn.is_finite()) || (zn - z).abs() <= 1e-15 * z {
                    z = if zn.is_finite() { zn } else { z };
                    break;
                }
                z = zn;
            }
            return d.delta_zero + z;
        }
        // Interval whose force range contains the target.
        let i = ivs
            .partition_point(|iv| iv.force_at(1.0).0 < target)
            .min(ivs.len() - 1);
        let iv = &ivs[i];
        // Safeguarded Newton on t ∈ [0, 1] (monotone cubic).
        let (mut lo, mut hi) = (0.0f64, 1.0f64);
        let mut t = 0.5;
        for _ in 0..100 {
            let (f, df) = iv.force_at(t);
            let f = f - target;
            if f == 0.0 {
                break;
            }
            if f < 0.0 {
                lo = t;
            } else {
                hi = t;
            }
            let mut tn = t - f / df;
            if !(tn > lo && tn < hi) {
                tn = 0.5 * (lo + hi);
            }
            if (tn - t).abs() <= 1e-16 || hi - lo <= 1e-16 {
                t = tn;
                break;
            }
            t = tn;
        }
        s.x_of(iv.lo + t * (iv.hi - iv.lo))
    }
}

/// Whether the Hermite cubic is monotone, or the data are flat/decreasing
/// radii where no monotonicity is promised (then always true).
fn monotone_or_flat(y0: f64, m0: f64, y1: f64, m1: f64, h: f64) -> bool {
    if y1 < y0 || (y1 == y0 && m0 == 0.0 && m1 == 0.0) {
        true
    } else {
        monotone(y0, m0, y1, m1, h)
    }
}

/// Rigid Lennard-Jones sphere (Derjaguin), reduced: `g = −(8/3)[h⁻² − h⁻⁸/4]`,
/// `h = 1 − x`, and dg/dx.
fn rigid_lj(x: f64) -> (f64, f64) {
    let ih = 1.0 / (1.0 - x);
    let h2 = ih * ih;
    let h8 = h2 * h2 * h2 * h2;
    let g = -(8.0 / 3.0) * (h2 - 0.25 * h8);
    let dg = -(16.0 / 3.0) * (h2 - h8) * ih;
    (g, dg)
}

impl SegmentData {
    fn u_of_delta(&self, x: f64) -> f64 {
        let d = self.sign * (x - self.reference);
        if self.transform == Transform::Sqrt {
            d.max(0.0).sqrt()
        } else {
            d
        }
    }
}

impl NormalContact for TabulatedLaw {
    /// Equilibrium at overlap δ (m) under displacement control, following the
    /// history in `old` (see the module documentation).
    ///
    /// Errors: [`Error::InvalidArgument`] for a non-finite δ or a branch
    /// outside `0..branch_count()`; [`Error::OutOfDomain`] when the response
    /// overflows.
    #[inline(always)]
    fn eval(&self, delta: f64, old: &ContactState) -> Result<(NormalResponse, ContactState)> {
        let br = old.branch;
        let mut k = br as u32 as usize;
        if !(delta.is_finite() && k < self.branches.len()) {
            return Err(bad_input(delta, br));
        }
        let d = &self.data;
        // Branches and segments are chosen on δ against thresholds
        // equivalent to the reduced ones, so that no division precedes the
        // choice. Most calls stay on their branch and land on its widest
        // segment: one range test; otherwise the jumps and the full choice.
        let b = &self.branches[k];
        let (f, a, kbar) = if b.stays(delta) {
            b.stay_segment().eval(delta)
        } else {
            if !(delta <= b.hi_delta) {
                k = self.jump_forward(k, delta);
            } else if delta < b.lo_delta {
                k = self.jump_back(k, delta);
            }
            self.on_branch(k, delta)
        };
        let radius = a * d.radius_scale;
        let r = NormalResponse {
            force: f * d.force_scale,
            delta,
            contact_radius: radius,
            stiffness: kbar * self.stiffness_scale,
            in_contact: (a > 0.0) as i32,
            reserved: 0,
        };
        let s = ContactState {
            contact_radius: radius,
            cohesive_radius: 0.0,
            in_contact: (k > 0 || a > 0.0) as i32,
            branch: k as i32,
        };
        // One test for the three computed values (δ is finite): x·0 is 0
        // exactly when x is finite, NaN otherwise.
        if r.force * 0.0 + radius * 0.0 + r.stiffness * 0.0 == 0.0 {
            Ok((r, s))
        } else {
            Err(overflow(delta))
        }
    }

    /// The element loop without a second finiteness test: `eval` already
    /// returns an error for a non-finite response.
    #[inline]
    unsafe fn eval_batch_raw(&self, b: &RawBatch) -> core::result::Result<(), BatchError> {
        super::batch::eval_elementwise_finite(self, b)
    }

    /// Equilibrium at force P (N) on the load-controlled stable branch (beyond
    /// the minimum of the force on the last branch), by inverting the
    /// interpolant.
    ///
    /// Errors: [`Error::OutOfDomain`] below the load-controlled pull-off.
    fn eval_at_load(&self, force: f64) -> Result<NormalResponse> {
        let force = check_force(force)?;
        let d = &self.data;
        let target = force / d.force_scale;
        if target < d.load_pull_off {
            return Err(below_pull_off(force));
        }
        let x = self.x_at_load(target);
        let k = self.branches.len() - 1;
        let delta = self.overlap(x);
        let (_, a, kbar) = self.on_branch(k, delta);
        let r = NormalResponse {
            force,
            delta,
            contact_radius: a * d.radius_scale,
            stiffness: kbar * self.stiffness_scale,
            in_contact: 1,
            reserved: 0,
        };
        finite_response((r, ContactState::default())).map(|rs| rs.0)
    }

    /// Load control: the minimum of the force on the last branch, the first
    /// met lowering the load from deep contact (the curve's point, unless
    /// the grid leaves the contact branch several minima: see
    /// [`crate::contact::lj_sphere::LjCurve::pull_off_load`]). Displacement
    /// control: the force where contact is lost
    /// on retraction, at the point where the radius reaches zero or at the
    /// jump-out turning point (exactly the curve's point).
    fn pull_off_force(&self, control: Control) -> Result<f64> {
        let bar = match control {
            Control::Load => self.data.load_pull_off,
            Control::Displacement => self.data.displacement_pull_off,
        };
        Ok(bar * self.data.force_scale)
    }

    /// The curve's approach unit (m).
    fn length_scale(&self) -> f64 {
        self.data.approach_scale
    }

    /// The reach from the table's branches and far tail (see
    /// [`NormalContact::reach`]); `rel_force` is checked always and used
    /// only with a Lennard-Jones far tail.
    ///
    /// * Approach: a fresh contact (branch 0) feels the far tail up to the
    ///   first knot of branch 0 (the first stable piece of a path that starts
    ///   stable, as the Lennard-Jones sphere's does) or, without one, up to
    ///   branch 0's upper end, where it jumps in. A Maugis–Dugdale table's
    ///   far tail is zero (up to `−h₀`). The Lennard-Jones sphere's far tail
    ///   is the rigid sphere's (Derjaguin; REFERENCE §6), in reduced units
    ///   `F = k·g(Δ)`, `g = −(8/3)[h⁻² − h⁻⁸/4]`, `h = 1 − Δ`; with
    ///   `y = h⁻² < 1`, `|F| = (8/3)|k|(y − y⁴/4)` increases with y, so
    ///   `|F| < rel_force·|P_c|` below the root of
    ///   `y − y⁴/4 = 3 rel_force |P_c|/(8|k|)` (Δ = 1 − 1/√y; the whole tail
    ///   Δ ≤ 0 when the right side is ≥ 3/4). The approach bound is the
    ///   lowest of these points: where the tail bound falls inside the
    ///   tabulated path, the path's first knot is taken instead
    ///   (conservative: the force there may already be below the bound).
    /// * Displacement control: also below the jump-out point (the lower end)
    ///   of every branch after the first, so that every history jumps back
    ///   to branch 0 below δ_r.
    /// * Load control: also below the overlap of the load-controlled
    ///   pull-off knot.
    fn reach(&self, control: Control, rel_force: f64) -> Result<f64> {
        let rel = super::check_rel_force(rel_force)?;
        let d = &self.data;
        let first = &self.branches[0];
        let mut onset = f64::INFINITY;
        if self.branches.len() > 1 {
            onset = onset.min(first.hi_delta);
        }
        if let Some(s) = first.segments.first() {
            onset = onset.min(s.start_delta);
        }
        if let FarData::RigidLennardJones { k } = d.far {
            if k != 0.0 {
                let c = 3.0 * rel * d.load_pull_off.abs() / (8.0 * k.abs());
                let x = if c < 0.75 {
                    let y = super::derjaguin::lj_tail_inverse(c);
                    1.0 - 1.0 / y.sqrt()
                } else {
                    0.0
                };
                onset = onset.min(self.overlap(x));
            }
        }
        let r = match control {
            Control::Displacement => self.branches[1..]
                .iter()
                .fold(onset, |m, b| m.min(b.lo_delta)),
            Control::Load => {
                let x = self.last_segment().x_of(d.load_pull_off_u);
                onset.min(self.overlap(x))
            }
        };
        crate::error::check::finite_result(r, "table", r, "its reach is not finite")
    }
}

/// The overlap threshold (m) equivalent to a reduced-approach bound `x`:
/// with the reduced approach `Δ(δ) = (δ − origin)/scale` rounded as f64
/// arithmetic rounds it, the smallest δ with `Δ(δ) ≥ x` (`at_least`) or the
/// largest δ with `Δ(δ) ≤ x`. Rounding keeps `Δ(δ)` monotone in δ, so `δ ≥ threshold` is
/// exactly `Δ(δ) ≥ x` (and `δ ≤ threshold` exactly `Δ(δ) ≤ x`) for every
/// finite δ: bisection over the ordered bit patterns of the finite doubles.
fn overlap_threshold(origin: f64, scale: f64, x: f64, at_least: bool) -> f64 {
    if x.is_infinite() {
        return x;
    }
    // Order-preserving map of the doubles onto the integers and back.
    let key = |v: f64| {
        let b = v.to_bits() as i64;
        if b < 0 {
            i64::MIN - b
        } else {
            b
        }
    };
    let value = |k: i64| f64::from_bits(if k < 0 { i64::MIN - k } else { k } as u64);
    // Inside the bound is false then true along δ (at_least) or true then
    // false; `past(k)` is false then true along the keys either way.
    let past = |k: i64| {
        let r = (value(k) - origin) / scale;
        if at_least {
            r >= x
        } else {
            r > x
        }
    };
    // The keys span more than i64: sums and differences in i128.
    let (mut lo, mut hi) = (key(-f64::MAX), key(f64::MAX));
    if past(lo) {
        return f64::NEG_INFINITY;
    }
    if !past(hi) {
        return f64::INFINITY;
    }
    while (hi as i128) - (lo as i128) > 1 {
        let mid = ((lo as i128 + hi as i128) >> 1) as i64;
        if past(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    // The first δ inside (at_least), or the last one inside.
    value(if at_least { hi } else { lo })
}

/// The next double above a finite `v` (`f64::next_up`, stable only since
/// Rust 1.86).
fn next_up(v: f64) -> f64 {
    if v.is_nan() || v == f64::INFINITY {
        return v;
    }
    if v == 0.0 {
        return f64::from_bits(1);
    }
    let b = v.to_bits();
    f64::from_bits(if v > 0.0 { b + 1 } else { b - 1 })
}

/// The error for a non-finite δ or a branch outside the table.
#[cold]
fn bad_input(delta: f64, b: i32) -> Error {
    match check_delta(delta) {
        Err(e) => e,
        Ok(_) => bad_branch(b),
    }
}

fn bad_branch(b: i32) -> Error {
    Error::InvalidArgument {
        name: "old.branch",
        value: b as f64,
        bound: "a branch of the table: 0 (far) to branch_count() - 1",
    }
}

#[cfg(test)]
mod tests {
    use super::{next_up, overlap_threshold, TabulatedLaw};
    use crate::contact::{ContactState, LjSphere, MaugisDugdale, NormalContact};

    fn next_down(v: f64) -> f64 {
        -next_up(-v)
    }

    #[test]
    fn next_up_steps_one_ulp() {
        assert_eq!(next_up(0.0), f64::from_bits(1));
        assert_eq!(next_up(-0.0), f64::from_bits(1));
        assert_eq!(next_up(1.0), 1.0 + f64::EPSILON);
        assert_eq!(next_up(-f64::from_bits(1)), -0.0);
        assert_eq!(next_up(f64::MAX), f64::INFINITY);
        assert_eq!(next_up(f64::NEG_INFINITY), -f64::MAX);
        assert_eq!(next_up(f64::INFINITY), f64::INFINITY);
        assert_eq!(next_down(1.0), 1.0 - f64::EPSILON / 2.0);
    }

    /// The overlap thresholds decide exactly as the reduced approach
    /// `(δ − origin)/scale` compared with the bound: true at the threshold,
    /// false one double beyond it.
    #[test]
    fn overlap_thresholds_reproduce_the_reduced_comparisons() {
        let reduced = |o: f64, s: f64, d: f64| (d - o) / s;
        let mut checked = 0;
        for o in [0.0, -3.7e-9, 1e-6, -2.5] {
            for s in [3e-10, 1.7320508075688772e-8, 1.0, 7.3, 1e10] {
                for x in [
                    -28.90788462585297,
                    -1.6294154310638171,
                    -1.7438050853496148,
                    0.0,
                    1e-300,
                    0.1 + 0.2,
                    8.902789206157527,
                    7.868170735204815e6,
                    1e300,
                ] {
                    let lo = overlap_threshold(o, s, x, true);
                    let hi = overlap_threshold(o, s, x, false);
                    if lo.is_finite() {
                        assert!(reduced(o, s, lo) >= x, "{o} {s} {x}");
                        assert!(reduced(o, s, next_down(lo)) < x, "{o} {s} {x}");
                        checked += 1;
                    } else {
                        // No finite δ reaches x (x beyond the range).
                        assert_eq!(lo, f64::INFINITY);
                        assert!(reduced(o, s, f64::MAX) < x, "{o} {s} {x}");
                    }
                    if hi.is_finite() {
                        assert!(reduced(o, s, hi) <= x, "{o} {s} {x}");
                        assert!(reduced(o, s, next_up(hi)) > x, "{o} {s} {x}");
                    } else {
                        assert_eq!(hi, f64::INFINITY);
                        assert!(reduced(o, s, f64::MAX) <= x, "{o} {s} {x}");
                    }
                }
            }
        }
        assert!(checked > 150);
        assert_eq!(
            overlap_threshold(0.0, 1.0, f64::INFINITY, false),
            f64::INFINITY
        );
        assert_eq!(
            overlap_threshold(0.0, 1.0, f64::NEG_INFINITY, true),
            f64::NEG_INFINITY
        );
    }

    /// The choice `eval` makes by the rules of the module documentation,
    /// without the stay range: the branch after the jumps, and the reduced
    /// response on it.
    fn full_choice(t: &TabulatedLaw, k: usize, delta: f64) -> (usize, (f64, f64, f64)) {
        let n = t.branches.len();
        let b = &t.branches[k];
        let k = if delta > b.hi_delta {
            (k + 1..n).find(|&j| t.contains(j, delta)).unwrap_or(n - 1)
        } else if delta < b.lo_delta {
            (0..k).rev().find(|&j| t.contains(j, delta)).unwrap_or(0)
        } else {
            k
        };
        (k, t.on_branch(k, delta))
    }

    /// The stay range is a shortcut only: from every branch, at every
    /// threshold of the table and the doubles beside it, and over a sweep,
    /// `eval` gives bit for bit the response and the branch of the full
    /// choice. The tables cover a widest segment that is not the last
    /// (μ = 0.1: linear, then square root), two segments on the contact
    /// branch (μ = 1) and a far branch without segments (Maugis–Dugdale).
    #[test]
    fn stay_range_is_the_full_choice() {
        let (r, w, z0) = (1e-6f64, 0.05f64, 0.3e-9f64);
        let lj = |mu: f64| {
            let e_star = (r * w * w / (mu * mu * mu * z0 * z0 * z0)).sqrt();
            let lj = LjSphere::new(r, e_star, w, z0).unwrap();
            TabulatedLaw::from_lj_sphere(&lj, 128, 1e-4).unwrap()
        };
        let md = MaugisDugdale::from_maugis_parameter(1e-6, 1e9, 0.05, 2.0).unwrap();
        let tables = [
            lj(0.1),
            lj(1.0),
            TabulatedLaw::from_maugis_dugdale(&md, 1e-4).unwrap(),
        ];
        assert_ne!(
            tables[0].branches[0].stay,
            tables[0].branches[0].segments.len() - 1
        );
        let mut checked = 0;
        for t in &tables {
            let mut points = Vec::new();
            for b in &t.branches {
                points.extend([b.lo_delta, b.hi_delta, b.stay_lo, b.stay_hi]);
                for s in &b.segments {
                    points.extend([s.start_delta, s.hi_delta]);
                }
            }
            let (lo, hi) = (t.overlap(-30.0), t.overlap(30.0));
            points.extend((0..=3000).map(|i| lo + (hi - lo) * i as f64 / 3000.0));
            let mut all = Vec::new();
            for p in points.into_iter().filter(|p| p.is_finite()) {
                all.extend([next_down(p), p, next_up(p)]);
            }
            for k in 0..t.branches.len() {
                let old = ContactState {
                    branch: k as i32,
                    ..Default::default()
                };
                for &delta in &all {
                    let (kk, (f, a, kbar)) = full_choice(t, k, delta);
                    let (resp, state) = t.eval(delta, &old).unwrap();
                    let d = &t.data;
                    assert_eq!(state.branch, kk as i32, "{} {k} {delta:e}", t.source());
                    assert_eq!(resp.force.to_bits(), (f * d.force_scale).to_bits());
                    assert_eq!(
                        resp.contact_radius.to_bits(),
                        (a * d.radius_scale).to_bits()
                    );
                    assert_eq!(
                        resp.stiffness.to_bits(),
                        (kbar * t.stiffness_scale).to_bits()
                    );
                    checked += 1;
                }
            }
        }
        assert!(checked > 30_000, "{checked}");
    }
}
