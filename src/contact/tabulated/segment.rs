//! The runtime structures of a table: cubic intervals, segments (the
//! intervals of one interpolation variable, with their lookup index) and
//! branches, and the evaluation of a segment at an overlap.

use super::bad;
use super::data::{SegmentData, Transform};
use super::hermite::{coefficients, horner, horner_d, pair};
use crate::error::Result;

/// Bound on the reduced stiffness (infinite at a turning point).
pub(super) const STIFFNESS_BAR_MAX: f64 = 1e100;

/// One Hermite interval as a cubic in `s = u − lo ∈ [0, hi − lo]`:
/// `y(s) = c0 + s(c1 + s(c2 + s c3))` for the force and the radius side by
/// side (`c[j] = [F_j, a_j]`), and the stiffness `dF/dΔ = F'(s)·du/dΔ` as
/// `(e0 + s(e1 + s e2))/u` on a square-root segment (`du/dΔ = ±1/(2u)`) or
/// without the division on a linear one (`du/dΔ = ±1`), the factor ±½ or ±1
/// folded into `e`.
#[derive(Debug, Clone, Copy)]
pub(super) struct Interval {
    pub(super) lo: f64,
    pub(super) hi: f64,
    pub(super) c: [[f64; 2]; 4],
    pub(super) e: [f64; 3],
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
    pub(super) fn force_at(&self, t: f64) -> (f64, f64) {
        let h = self.hi - self.lo;
        let f = self.f();
        (horner(&f, t * h), horner_d(&f, t * h) * h)
    }
}

#[derive(Debug, Clone)]
pub(super) struct Segment {
    pub(super) sqrt: bool,
    pub(super) sign: f64,
    /// Overlap (m) threshold equivalent to `Δ ≤ hi` (see
    /// [`overlap_threshold`](super::threshold::overlap_threshold)).
    pub(super) hi_delta: f64,
    /// Where the segment's range begins in the branch's scan: the threshold
    /// equivalent to `Δ ≥ lo` for the first segment, otherwise the overlap
    /// just above the previous segment's `hi_delta` (a δ on both is on the
    /// earlier one).
    pub(super) start_delta: f64,
    /// The reference as an overlap (m), and `sign/approach_scale`: the
    /// pre-root variable is `d = (δ − reference_delta)·d_per_delta`.
    pub(super) reference_delta: f64,
    pub(super) d_per_delta: f64,
    pub(super) reference: f64,
    /// The first knot in `d`.
    pub(super) d0: f64,
    pub(super) bias: f64,
    pub(super) bias_bits: u64,
    pub(super) shift: u32,
    pub(super) intervals: Vec<Interval>,
    /// The end of each interval in `d` (`hi²` or `hi`), the last one +∞:
    /// the walk from an index entry stops at the interval holding `d`.
    pub(super) ends: Vec<f64>,
    pub(super) index: Vec<u32>,
}

#[derive(Debug, Clone)]
pub(super) struct Branch {
    pub(super) lo: f64,
    pub(super) hi: f64,
    /// Overlap (m) thresholds equivalent to `Δ ≥ lo` and `Δ ≤ hi`.
    pub(super) lo_delta: f64,
    pub(super) hi_delta: f64,
    /// The overlaps (m) where a contact on this branch stays on it and is
    /// on its widest segment (in overlap), `[max(lo_delta, start),
    /// min(hi_delta, end)]` of that segment; empty (+∞, −∞) without
    /// segments. Most calls land here and take one range test.
    pub(super) stay_lo: f64,
    pub(super) stay_hi: f64,
    /// The widest segment.
    pub(super) stay: usize,
    pub(super) segments: Vec<Segment>,
}

/// A segment's pre-root variable `d` at its interpolation variable `u`:
/// `u²` for a square-root segment, `u` for a linear one.
#[inline]
pub(super) fn d_of_u(sqrt: bool, u: f64) -> f64 {
    if sqrt {
        u * u
    } else {
        u
    }
}

impl Branch {
    /// Whether overlap δ (m) is in the stay range.
    #[inline(always)]
    pub(super) fn stays(&self, delta: f64) -> bool {
        delta >= self.stay_lo && delta <= self.stay_hi
    }

    /// The widest segment, on a branch whose stay range is not empty.
    #[inline(always)]
    pub(super) fn stay_segment(&self) -> &Segment {
        debug_assert!(self.stay_lo <= self.stay_hi);
        // SAFETY: a non-empty stay range means segments, `stay` one of them
        // (`from_data`).
        unsafe { self.segments.get_unchecked(self.stay) }
    }
}

impl Segment {
    #[inline]
    pub(super) fn x_of(&self, u: f64) -> f64 {
        if self.sqrt {
            self.reference + self.sign * u * u
        } else {
            self.reference + self.sign * u
        }
    }

    /// Reduced (F, radius, dF/dΔ) at overlap δ (m).
    #[inline(always)]
    pub(super) fn eval(&self, delta: f64) -> (f64, f64, f64) {
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

    pub(super) fn build(d: &SegmentData) -> Result<Segment> {
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
        seg.build_index(&ends);
        if let Some(last) = ends.last_mut() {
            *last = f64::INFINITY;
        }
        seg.ends = ends;
        Ok(seg)
    }
}
