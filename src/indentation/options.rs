//! The options of an analysis, their defaults and their checks.

use super::fit::Anchor;
use super::indenter::{AreaFunction, Indenter};
use super::indices::{KnownIndices, Source};
use crate::error::{check, Error, Result};
use serde::Serialize;

/// Options of [`analyze`](super::analyze).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct IndentationOptions {
    /// Indenter geometry (default Berkovich).
    pub indenter: Indenter,
    /// Area function; `None` uses the indenter's ideal one.
    pub area: Option<AreaFunction>,
    /// Bluntness index when known (a sphere's 2 is taken from the indenter).
    pub known_d: Option<f64>,
    /// Hardening index when known (then d comes from the loading slope).
    pub known_kappa: Option<f64>,
    /// Indenter (tip) Young's modulus E_i (Pa) in (2-15),
    /// `1/E_r = (1 − ν²)/E + (1 − ν_i²)/E_i`; default diamond 1141 GPa
    /// (Oliver & Pharr 1992, §II; ISO 14577-1:2015 Annex A). `+inf` is a rigid
    /// indenter.
    pub e_indenter: f64,
    /// Indenter Poisson's ratio ν_i, default diamond 0.07 (same sources).
    pub nu_indenter: f64,
    /// Sample Poisson's ratio (default 0.3).
    pub nu_sample: f64,
    /// β of `E_r = √π S/(2β√A)`; `None` uses the indenter's
    /// ([`Indenter::beta`]: 1.034 Berkovich and cube corner, 1.012 Vickers,
    /// King 1987 as recommended by Oliver & Pharr 2004 §III.A; 1 for
    /// axisymmetric indenters). Accepted range [0.5, 1.5].
    pub beta: Option<f64>,
    /// ε of the contact depth `h_c = h_max − ε P_max/S`: 0.75 for a
    /// paraboloid of revolution, the geometry Oliver & Pharr (1992, 2004)
    /// recommend for real Berkovich tips, and the value of ISO 14577-1:2015
    /// Annex A (0.72 is the cone's, 1 the flat punch's). Accepted range
    /// (0, 1].
    pub epsilon: f64,
    /// Load window of the loading fit, fractions of the anchor load
    /// (default 0.1–1: the first 10 % of the load, where surface detection and
    /// noise dominate the logarithm, is left out).
    pub loading_window: [f64; 2],
    /// Load window of the unloading fit, fractions of P_max (default
    /// 0.2–0.98, the range of ISO 14577-1:2015 Annex A as applied by the
    /// Czech Metrology Institute, OEFPIL `silica2098` data set: the top 2 %,
    /// where creep at the start of unloading bends the curve, and the bottom
    /// 20 %, which the power law does not describe near h_f, are left out).
    /// The result's `window_sensitivity` reports what other windows give.
    pub unloading_window: [f64; 2],
    /// Anchor of the loading fit (default the maximum point).
    pub anchor: Anchor,
    /// Use the file's segment labels when present (default true).
    pub use_labels: bool,
}

impl Default for IndentationOptions {
    fn default() -> Self {
        Self {
            indenter: Indenter::Berkovich,
            area: None,
            known_d: None,
            known_kappa: None,
            e_indenter: 1141e9,
            nu_indenter: 0.07,
            nu_sample: 0.3,
            beta: None,
            epsilon: 0.75,
            loading_window: [0.1, 1.0],
            unloading_window: [0.2, 0.98],
            anchor: Anchor::MaxPoint,
            use_labels: true,
        }
    }
}

impl IndentationOptions {
    /// Check every option (the first invalid one is the error) and return
    /// the indices known before any fit.
    pub(super) fn validate(&self) -> Result<KnownIndices> {
        let o = self;
        o.indenter.validate()?;
        if let Some(a) = &o.area {
            a.validate()?;
        }
        check::poisson("nu_sample", o.nu_sample)?;
        check::poisson("nu_indenter", o.nu_indenter)?;
        if !(o.e_indenter > 0.0) {
            return Err(Error::InvalidArgument {
                name: "e_indenter",
                value: o.e_indenter,
                bound: "> 0 (+inf for a rigid indenter)",
            });
        }
        if !(o.epsilon > 0.0 && o.epsilon <= 1.0) {
            return Err(Error::InvalidArgument {
                name: "epsilon",
                value: o.epsilon,
                bound: "in (0, 1] (0.72 cone, 0.75 paraboloid, 1 flat punch)",
            });
        }
        if let Some(b) = o.beta {
            check::in_range("beta", b, 0.5, 1.5, "in [0.5, 1.5] (1.034 Berkovich)")?;
        }
        let w = o.loading_window;
        if !(w[0] >= 0.0 && w[1] <= 1.0 && w[0] < w[1]) {
            return Err(Error::InvalidArgument {
                name: "loading_window",
                value: w[0],
                bound: "0 <= low < high <= 1",
            });
        }
        let uw = o.unloading_window;
        if !(uw[0] >= 0.0 && uw[1] <= 1.0 && uw[0] < uw[1]) {
            return Err(Error::InvalidArgument {
                name: "unloading_window",
                value: uw[0],
                bound: "0 <= low < high <= 1",
            });
        }
        let known_d = match o.known_d {
            Some(d) => Some(check::in_range("known_d", d, 1.0, 100.0, "in [1, 100]")?),
            None => o.indenter.known_d(),
        };
        let known_kappa = match o.known_kappa {
            Some(k) => Some(check::in_range("known_kappa", k, 0.0, 10.0, "in [0, 10]")?),
            None => None,
        };
        let d_source = if o.known_d.is_some() {
            Source::Given
        } else {
            Source::Indenter
        };
        Ok(KnownIndices {
            kappa: known_kappa,
            d: known_d,
            d_source,
        })
    }
}
