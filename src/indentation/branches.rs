//! The branches of a segmented curve, prepared for the fits: the anchor and
//! load window of the loading fit, and the start point of unloading for the
//! Oliver–Pharr evaluation.

use super::fit::{log_log_fit, Anchor, PowerLawFit};
use super::oliver_pharr::{oliver_pharr, OliverPharr, OliverPharrOptions};
use super::options::IndentationOptions;
use super::read::Curve;
use super::segment::{in_range, Segmentation};
use super::window::WindowSensitivity;
use crate::error::{Error, Result};

/// The log–log fit of the loading branch: anchored at the maximum point of
/// the branch or at a given point (or free), on the points whose load lies in
/// the loading window (fractions of the anchor load).
pub(super) fn fit_loading_branch(
    curve: &Curve,
    seg: &Segmentation,
    o: &IndentationOptions,
) -> Result<PowerLawFit> {
    let w = o.loading_window;
    let n = curve.len();
    let lr = in_range(seg.loading, n);
    if lr.len() < 3 {
        return Err(Error::OutOfDomain {
            name: "loading_points",
            value: lr.len() as f64,
            reason: "no loading branch (fewer than 3 loading points)",
        });
    }
    let (h, p) = (&curve.depth, &curve.load);
    // Anchor: the maximum point of the loading branch, or a given point.
    let ipk = lr
        .clone()
        .max_by(|&a, &b| p[a].total_cmp(&p[b]))
        .unwrap_or(lr.start);
    let anchor = match o.anchor {
        Anchor::MaxPoint => Some((h[ipk], p[ipk])),
        Anchor::Index { index } => {
            if index >= n {
                return Err(Error::InvalidArgument {
                    name: "anchor_index",
                    value: index as f64,
                    bound: "< number of points",
                });
            }
            Some((h[index], p[index]))
        }
        Anchor::Free => None,
    };
    if let Some((ah, ap)) = anchor {
        if !(ah > 0.0 && ap > 0.0) {
            return Err(Error::OutOfDomain {
                name: "anchor",
                value: ah,
                reason: "the anchor point needs positive depth and load",
            });
        }
    }
    let pref = anchor.map(|a| a.1).unwrap_or(p[ipk]);
    let (lh, lp): (Vec<f64>, Vec<f64>) = lr
        .clone()
        .filter(|&i| p[i] >= w[0] * pref && p[i] <= w[1] * pref * (1.0 + 1e-12))
        .map(|i| (h[i], p[i]))
        .unzip();
    log_log_fit(&lh, &lp, anchor)
}

/// What became of the unloading branch: its Oliver–Pharr evaluation, or why
/// there is none.
#[derive(Debug)]
pub(super) struct UnloadingBranch {
    /// The evaluation; `None` when the segment is too short or it failed.
    pub(super) evaluation: Option<OliverPharr>,
    /// Why the evaluation failed, when it was tried.
    pub(super) error: Option<Error>,
    /// Points in the unloading segment (before the load window of the fit).
    pub(super) segment_points: usize,
    /// The evaluation repeated over windows, when there is one.
    pub(super) sensitivity: Option<WindowSensitivity>,
}

/// Oliver–Pharr on the unloading segment when it has at least 5 points.
/// Unloading starts from the point before the segment (the end of the hold or
/// of loading) when its load is not lower, otherwise from the segment's first
/// point. A failed evaluation is kept as the error, not returned: d or κ may
/// be known without it.
pub(super) fn evaluate_unloading_branch(
    curve: &Curve,
    seg: &Segmentation,
    o: &IndentationOptions,
) -> UnloadingBranch {
    let n = curve.len();
    let (h, p) = (&curve.depth, &curve.load);
    let ur = in_range(seg.unloading, n);
    let area = o.area.clone().unwrap_or_else(|| o.indenter.ideal_area());
    let beta = o.beta.unwrap_or_else(|| o.indenter.beta());
    let mut unloading_error = None;
    let mut sensitivity = None;
    let unloading = if ur.len() >= 5 {
        // Unloading starts from the point before it (the end of the hold or
        // of loading), or its own first point.
        let start = if ur.start > 0 && p[ur.start - 1] >= p[ur.start] {
            ur.start - 1
        } else {
            ur.start
        };
        let opts = OliverPharrOptions {
            area: area.clone(),
            epsilon: o.epsilon,
            beta,
            window: o.unloading_window,
        };
        match oliver_pharr(&h[ur.clone()], &p[ur.clone()], h[start], p[start], &opts) {
            Ok(r) => {
                sensitivity = Some(WindowSensitivity::measure(
                    &h[ur.clone()],
                    &p[ur.clone()],
                    &r,
                    &opts,
                    o,
                ));
                Some(r)
            }
            Err(e) => {
                unloading_error = Some(e);
                None
            }
        }
    } else {
        None
    };
    UnloadingBranch {
        evaluation: unloading,
        error: unloading_error,
        segment_points: ur.len(),
        sensitivity,
    }
}
