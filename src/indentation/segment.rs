//! Segments of a curve: the labels of the data format, or detection of
//! loading, the hold at peak and unloading from the load signal.

use super::read::Curve;
use crate::error::{Error, Result};
use serde::Serialize;

/// Segment of an indentation curve.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Segment {
    /// Not assigned.
    Unknown,
    /// Before surface contact.
    Approach,
    /// Loading.
    Loading,
    /// Hold at peak load.
    Hold,
    /// Unloading from the peak.
    Unloading,
    /// Thermal-drift hold (usually at ~10 % of the peak, after unloading).
    DriftHold,
    /// Final withdrawal after the drift hold.
    FinalUnloading,
}

impl Segment {
    /// From the data format's label (`approach`, `loading`, `hold_at_peak`,
    /// `unloading`, `thermal_drift_hold`, `final_unloading`; `hold` and
    /// `unknown` are accepted too).
    pub fn from_label(s: &str) -> Option<Segment> {
        Some(match s.trim() {
            "approach" => Segment::Approach,
            "loading" => Segment::Loading,
            "hold_at_peak" | "hold" => Segment::Hold,
            "unloading" => Segment::Unloading,
            "thermal_drift_hold" => Segment::DriftHold,
            "final_unloading" => Segment::FinalUnloading,
            "unknown" | "" => Segment::Unknown,
            _ => return None,
        })
    }

    /// The integer code of the C ABI (0 unknown, 1 approach, 2 loading, 3 hold,
    /// 4 unloading, 5 drift hold, 6 final unloading).
    pub fn code(self) -> i32 {
        match self {
            Segment::Unknown => 0,
            Segment::Approach => 1,
            Segment::Loading => 2,
            Segment::Hold => 3,
            Segment::Unloading => 4,
            Segment::DriftHold => 5,
            Segment::FinalUnloading => 6,
        }
    }

    /// The inverse of [`Segment::code`].
    pub fn from_code(code: i32) -> Option<Segment> {
        Some(match code {
            0 => Segment::Unknown,
            1 => Segment::Approach,
            2 => Segment::Loading,
            3 => Segment::Hold,
            4 => Segment::Unloading,
            5 => Segment::DriftHold,
            6 => Segment::FinalUnloading,
            _ => return None,
        })
    }
}

/// Where the segments are, as half-open index ranges into the curve.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Segmentation {
    /// True when the file's labels were used, false when detected.
    pub from_labels: bool,
    /// Loading `[start, end)`.
    pub loading: [usize; 2],
    /// Hold at peak `[start, end)` (may be empty).
    pub hold: [usize; 2],
    /// Unloading from the peak `[start, end)` (may be empty).
    pub unloading: [usize; 2],
}

/// Fraction of the peak load above which detected points belong to the hold.
const HOLD_FRACTION: f64 = 0.998;

fn label_range(labels: &[Segment], s: Segment) -> [usize; 2] {
    let first = labels.iter().position(|&x| x == s);
    let last = labels.iter().rposition(|&x| x == s);
    match (first, last) {
        (Some(a), Some(b)) => [a, b + 1],
        _ => [0, 0],
    }
}

/// Find the segments: from the labels when the curve has them and
/// `use_labels` is set, otherwise by detection:
///
/// * the peak is the first maximum of the load; the **hold** is the contiguous
///   run around it with load ≥ 99.8 % of the peak;
/// * **loading** is everything before the hold;
/// * **unloading** runs from the end of the hold while the load keeps falling:
///   it ends where the drop over the last 5 points is below 20 % of the mean
///   drop per 5 points so far (a drift hold or the end of the test), or where
///   the load rises again by more than 5 % of the peak (a reload).
pub fn segment(curve: &Curve, use_labels: bool) -> Result<Segmentation> {
    if curve.is_empty() {
        return Err(Error::InvalidArgument {
            name: "curve",
            value: 0.0,
            bound: "at least one point",
        });
    }
    if let (true, Some(labels)) = (use_labels, curve.segments.as_ref()) {
        return Ok(Segmentation {
            from_labels: true,
            loading: label_range(labels, Segment::Loading),
            hold: label_range(labels, Segment::Hold),
            unloading: label_range(labels, Segment::Unloading),
        });
    }
    let p = &curve.load;
    let n = p.len();
    let (ipk, pmax) =
        p.iter().enumerate().fold(
            (0, f64::NEG_INFINITY),
            |(i0, m), (i, &v)| {
                if v > m {
                    (i, v)
                } else {
                    (i0, m)
                }
            },
        );
    let thr = if pmax > 0.0 {
        HOLD_FRACTION * pmax
    } else {
        pmax
    };
    let mut h0 = ipk;
    while h0 > 0 && p[h0 - 1] >= thr {
        h0 -= 1;
    }
    let mut h1 = ipk + 1;
    while h1 < n && p[h1] >= thr {
        h1 += 1;
    }
    // Unloading from the last hold point (the peak of unloading).
    let u0 = h1 - 1;
    const W: usize = 5;
    let mut runmin = vec![p[u0]; n - u0];
    for k in 1..n - u0 {
        runmin[k] = runmin[k - 1].min(p[u0 + k]);
    }
    let mut end = n;
    for k in 1..n - u0 {
        if p[u0 + k] > runmin[k] + 0.05 * pmax.abs() {
            end = u0 + k;
            break;
        }
        if k >= 2 * W {
            let drop_w = runmin[k - W] - runmin[k];
            let mean_w = (runmin[0] - runmin[k - W]) / (k - W) as f64 * W as f64;
            if drop_w < 0.2 * mean_w {
                end = u0 + k - W + 1;
                break;
            }
        }
    }
    Ok(Segmentation {
        from_labels: false,
        loading: [0, h0],
        hold: [h0, h1],
        unloading: [h1.min(end), end.max(h1)],
    })
}

/// The indices of `seg`, clipped to a curve of `n` points.
pub(super) fn in_range(seg: [usize; 2], n: usize) -> std::ops::Range<usize> {
    seg[0].min(n)..seg[1].min(n)
}
