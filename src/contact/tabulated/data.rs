//! The serialised form of a table (serde, numbers as exact decimal strings)
//! and its validation, which builds the runtime structures.

use super::hermite::{monotone, monotone_or_flat};
use super::segment::{Branch, Segment};
use super::threshold::{next_up, overlap_threshold};
use super::{bad, TabulatedLaw};
use crate::contact::curve::{exact_f64, exact_vec};
use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};

/// Identifies the serialised format.
pub(super) const FORMAT: &str = "asperity-tabulated-law-1";

/// How a segment maps Δ to its interpolation variable u ≥ 0.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub(super) enum Transform {
    /// `u = √(sign·(Δ − reference))`.
    Sqrt,
    /// `u = sign·(Δ − reference)`.
    Linear,
}

/// Serialised segment: knots in ascending u.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(super) struct SegmentData {
    pub(super) transform: Transform,
    /// +1 or −1.
    #[serde(with = "exact_f64")]
    pub(super) sign: f64,
    #[serde(with = "exact_f64")]
    pub(super) reference: f64,
    /// Δ range covered.
    #[serde(with = "exact_f64")]
    pub(super) lo: f64,
    #[serde(with = "exact_f64")]
    pub(super) hi: f64,
    #[serde(with = "exact_vec")]
    pub(super) u: Vec<f64>,
    #[serde(with = "exact_vec")]
    pub(super) force: Vec<f64>,
    /// dF/du.
    #[serde(with = "exact_vec")]
    pub(super) d_force: Vec<f64>,
    #[serde(with = "exact_vec")]
    pub(super) radius: Vec<f64>,
    /// d(radius)/du.
    #[serde(with = "exact_vec")]
    pub(super) d_radius: Vec<f64>,
}

/// Serialised branch: a stable piece. `None` bounds are unbounded.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(super) struct BranchData {
    #[serde(with = "crate::serde_exact::opt")]
    pub(super) lo: Option<f64>,
    #[serde(with = "crate::serde_exact::opt")]
    pub(super) hi: Option<f64>,
    pub(super) segments: Vec<SegmentData>,
}

/// Serialised far tail.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub(super) enum FarData {
    Zero,
    RigidLennardJones {
        #[serde(with = "exact_f64")]
        k: f64,
    },
}

/// Serialised deep tail: `F = h x^{3/2} + bf x^{qf}`, `a = g x^{1/2} + ba x^{qa}`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub(super) struct DeepData {
    #[serde(with = "exact_f64")]
    pub(super) delta_zero: f64,
    #[serde(with = "exact_f64")]
    pub(super) h: f64,
    #[serde(with = "exact_f64")]
    pub(super) bf: f64,
    #[serde(with = "exact_f64")]
    pub(super) qf: f64,
    #[serde(with = "exact_f64")]
    pub(super) g: f64,
    #[serde(with = "exact_f64")]
    pub(super) ba: f64,
    #[serde(with = "exact_f64")]
    pub(super) qa: f64,
}

/// The serialised table.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub(super) struct TableData {
    pub(super) format: String,
    pub(super) source: String,
    #[serde(with = "exact_f64")]
    pub(super) tolerance: f64,
    #[serde(with = "exact_f64")]
    pub(super) measured_error: f64,
    #[serde(with = "exact_f64")]
    pub(super) force_floor: f64,
    #[serde(with = "exact_f64")]
    pub(super) radius_floor: f64,
    #[serde(with = "exact_f64")]
    pub(super) approach_origin: f64,
    #[serde(with = "exact_f64")]
    pub(super) approach_scale: f64,
    #[serde(with = "exact_f64")]
    pub(super) force_scale: f64,
    #[serde(with = "exact_f64")]
    pub(super) radius_scale: f64,
    pub(super) branches: Vec<BranchData>,
    pub(super) far: FarData,
    pub(super) deep: DeepData,
    /// Reduced load-controlled pull-off force and the u of its knot (in the
    /// last branch's single segment).
    #[serde(with = "exact_f64")]
    pub(super) load_pull_off: f64,
    #[serde(with = "exact_f64")]
    pub(super) load_pull_off_u: f64,
    /// Reduced displacement-controlled pull-off force.
    #[serde(with = "exact_f64")]
    pub(super) displacement_pull_off: f64,
}

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

impl SegmentData {
    pub(super) fn u_of_delta(&self, x: f64) -> f64 {
        let d = self.sign * (x - self.reference);
        if self.transform == Transform::Sqrt {
            d.max(0.0).sqrt()
        } else {
            d
        }
    }
}

impl TabulatedLaw {
    /// Validate serialised data and build the runtime structures.
    pub(super) fn from_data(d: TableData) -> Result<Self> {
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
}
