//! The hardening index κ and the bluntness index d from the slopes of the
//! fits (thesis (3-21), (3-26)), with first-order standard errors.

use super::branches::UnloadingBranch;
use super::fit::PowerLawFit;
use crate::error::{Error, Result};
use crate::rescaling;
use serde::Serialize;

/// Where a parameter came from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Source {
    /// Given by the caller.
    Given,
    /// Fixed by the indenter geometry (a sphere's d = 2).
    Indenter,
    /// From the unloading exponent (κ = 1).
    Unloading,
    /// From the loading slope.
    Loading,
}

/// κ and d known before any fit, checked by `IndentationOptions::validate`.
#[derive(Debug, Clone, Copy)]
pub(super) struct KnownIndices {
    /// Hardening index κ when given (dimensionless).
    pub(super) kappa: Option<f64>,
    /// Bluntness index d when given or fixed by the indenter (dimensionless).
    pub(super) d: Option<f64>,
    /// Where a known d comes from: [`Source::Given`] or [`Source::Indenter`].
    pub(super) d_source: Source,
}

/// κ and d of an analysis, with their standard errors and sources.
#[derive(Debug, Clone, Copy)]
pub(super) struct Indices {
    /// Hardening index κ (dimensionless).
    pub(super) kappa: f64,
    /// Standard error of κ (0 when given).
    pub(super) kappa_stderr: f64,
    /// Where κ came from.
    pub(super) kappa_source: Source,
    /// Bluntness index d (dimensionless).
    pub(super) d: f64,
    /// Standard error of d (0 when given or fixed by the indenter).
    pub(super) d_stderr: f64,
    /// Where d came from.
    pub(super) d_source: Source,
}

/// κ and d from what is known and the slopes: both given; κ from the loading
/// slope m_l with d known, `κ = (d m_l − 2)/(d − 1)`; d from m_l with κ known,
/// `d = (2 − κ)/(m_l − κ)`; or d from the unloading exponent, `d = 1/(m − 1)`,
/// and κ from m_l with it. Fails when neither is known and the unloading
/// branch gave no evaluation, or when a value is not finite.
pub(super) fn kappa_and_d(
    known: KnownIndices,
    loading: &PowerLawFit,
    unloading: &UnloadingBranch,
) -> Result<Indices> {
    let ml = loading.slope;
    let sl = loading.slope_stderr;
    let indices = match (known.kappa, known.d) {
        (Some(k), Some(d)) => Indices {
            kappa: k,
            kappa_stderr: 0.0,
            kappa_source: Source::Given,
            d,
            d_stderr: 0.0,
            d_source: Source::Given,
        },
        (None, Some(d)) => {
            let k = rescaling::kappa_from_loading_slope(ml, d)?;
            Indices {
                kappa: k,
                kappa_stderr: sl * d / (d - 1.0).abs(),
                kappa_source: Source::Loading,
                d,
                d_stderr: 0.0,
                d_source: known.d_source,
            }
        }
        (Some(k), None) => {
            let d = rescaling::d_from_loading_slope(ml, k)?;
            // d = (2 − κ)/(m − κ): |∂d/∂m| = |2 − κ|/(m − κ)².
            let se = sl * (2.0 - k).abs() / (ml - k).powi(2);
            Indices {
                kappa: k,
                kappa_stderr: 0.0,
                kappa_source: Source::Given,
                d,
                d_stderr: se,
                d_source: Source::Loading,
            }
        }
        (None, None) => {
            let Some(op) = unloading.evaluation.as_ref() else {
                return Err(unloading.error.unwrap_or(Error::OutOfDomain {
                    name: "unloading_points",
                    value: unloading.segment_points as f64,
                    reason: "no usable unloading branch: d cannot be found; give known_d or known_kappa",
                }));
            };
            let m = op.fit.exponent;
            let d = rescaling::d_from_unloading_slope(m)?;
            let d_se = op.fit.exponent_stderr / (m - 1.0).powi(2);
            let k = rescaling::kappa_from_loading_slope(ml, d)?;
            let dk_dm = d / (d - 1.0);
            let dk_dd = (2.0 - ml) / (d - 1.0).powi(2);
            let k_se = ((dk_dm * sl).powi(2) + (dk_dd * d_se).powi(2)).sqrt();
            Indices {
                kappa: k,
                kappa_stderr: k_se,
                kappa_source: Source::Loading,
                d,
                d_stderr: d_se,
                d_source: Source::Unloading,
            }
        }
    };
    Ok(Indices {
        kappa: finite("kappa", indices.kappa)?,
        kappa_stderr: finite("kappa_stderr", indices.kappa_stderr)?,
        d: finite("d", indices.d)?,
        d_stderr: finite("d_stderr", indices.d_stderr)?,
        ..indices
    })
}

fn finite(name: &'static str, v: f64) -> Result<f64> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(Error::OutOfDomain {
            name,
            value: v,
            reason: "not finite: the slopes do not determine it",
        })
    }
}
