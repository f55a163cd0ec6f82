//! How much the Oliver–Pharr numbers depend on the load window of the
//! unloading fit: the evaluation repeated with the window's lower bound moved
//! from 0.2 to 0.8 of P_max (upper bound kept).
//!
//! The unloading power law `P = α(h − h_f)^m` is an approximation: on a real
//! curve its exponent drifts along the branch, so the stiffness at h_max
//! depends on which part is fitted (Oliver & Pharr 2004, J. Mater. Res. 19:3,
//! §II.C: the fit is made to the upper part of the curve and the result
//! should be checked for its sensitivity to the range). The statistical
//! standard error of S says nothing about this; the spread over windows
//! does.

use super::hardness::sample_modulus;
use super::oliver_pharr::{oliver_pharr, OliverPharr, OliverPharrOptions};
use super::options::IndentationOptions;
use serde::Serialize;

/// Lower bounds (fractions of P_max) the window is moved through.
pub(super) const WINDOW_LOWER_BOUNDS: [f64; 7] = [0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8];

/// The smallest relative change of S that counts: on a noise-free curve
/// the standard error of S is the rounding of the file's digits (1e-7 of S
/// for the shipped synthetic curve) and the fit's convergence moves S by
/// about 1e-6 between windows, which is no dependence on the window.
pub(super) const STIFFNESS_RESOLUTION: f64 = 1e-4;

/// The evaluation with one window.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WindowPoint {
    /// Load window of the fit, fractions of P_max.
    pub window: [f64; 2],
    /// Points fitted.
    pub n_points: usize,
    /// Unloading stiffness S (N/m).
    pub stiffness: f64,
    /// Reduced modulus E_r (Pa).
    pub reduced_modulus: f64,
    /// Sample modulus E (Pa); `None` when E_r is not below the indenter's
    /// plane-strain modulus.
    pub sample_modulus: Option<f64>,
}

/// The sensitivity of S and E to the window of the unloading fit.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct WindowSensitivity {
    /// One evaluation per lower bound 0.2, 0.3, …, 0.8 below the
    /// upper bound that gave a fit (fewer than 5 points or a failed fit leave
    /// it out).
    pub points: Vec<WindowPoint>,
    /// (max − min)/value of the chosen window, of S over the points and the
    /// chosen window.
    pub stiffness_relative_spread: f64,
    /// The same for the sample modulus (for E_r when there is no sample
    /// modulus).
    pub modulus_relative_spread: f64,
    /// (max − min) of S over the windows in units of the stated error of S:
    /// its standard error for the chosen window, at least
    /// 1e-4·S (the resolution of the fit). Above 1 raises the flag
    /// `window_dependent_stiffness`.
    pub stiffness_spread_in_stderr: f64,
}

impl WindowSensitivity {
    /// Repeat the evaluation `base` (made with `opts`) on the unloading
    /// branch `(depth, load)` for each lower bound below the upper bound.
    pub(super) fn measure(
        depth: &[f64],
        load: &[f64],
        base: &OliverPharr,
        opts: &OliverPharrOptions,
        o: &IndentationOptions,
    ) -> Self {
        let hi = opts.window[1];
        let es = |er: f64| sample_modulus(er, o.nu_sample, o.e_indenter, o.nu_indenter).ok();
        let points: Vec<WindowPoint> = WINDOW_LOWER_BOUNDS
            .iter()
            .filter(|&&lo| lo < hi)
            .filter_map(|&lo| {
                let w = OliverPharrOptions {
                    window: [lo, hi],
                    ..opts.clone()
                };
                let r = oliver_pharr(depth, load, base.peak_depth, base.peak_load, &w).ok()?;
                Some(WindowPoint {
                    window: [lo, hi],
                    n_points: r.fit.n_points,
                    stiffness: r.stiffness,
                    reduced_modulus: r.reduced_modulus,
                    sample_modulus: es(r.reduced_modulus),
                })
            })
            .collect();
        let spread = |vals: &mut dyn Iterator<Item = f64>| {
            vals.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
                (a.min(v), b.max(v))
            })
        };
        let (s_lo, s_hi) = spread(&mut points.iter().map(|p| p.stiffness).chain([base.stiffness]));
        let base_e = es(base.reduced_modulus);
        let (e_lo, e_hi, e0) = match base_e {
            Some(e0) if points.iter().all(|p| p.sample_modulus.is_some()) => {
                let (a, b) =
                    spread(&mut points.iter().filter_map(|p| p.sample_modulus).chain([e0]));
                (a, b, e0)
            }
            _ => {
                let (a, b) = spread(
                    &mut points
                        .iter()
                        .map(|p| p.reduced_modulus)
                        .chain([base.reduced_modulus]),
                );
                (a, b, base.reduced_modulus)
            }
        };
        let ds = s_hi - s_lo;
        Self {
            points,
            stiffness_relative_spread: ds / base.stiffness,
            modulus_relative_spread: (e_hi - e_lo) / e0,
            stiffness_spread_in_stderr: ds
                / base
                    .stiffness_stderr
                    .max(STIFFNESS_RESOLUTION * base.stiffness),
        }
    }
}
