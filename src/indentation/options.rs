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
    /// Indenter Young's modulus (Pa), default diamond 1141 GPa.
    pub e_indenter: f64,
    /// Indenter Poisson's ratio, default diamond 0.07.
    pub nu_indenter: f64,
    /// Sample Poisson's ratio (default 0.3).
    pub nu_sample: f64,
    /// β; `None` uses the indenter's (1.05 pyramids, 1 axisymmetric).
    pub beta: Option<f64>,
    /// ε of the contact depth (0.75).
    pub epsilon: f64,
    /// Load window of the loading fit, fractions of the anchor load
    /// (default 0.1–1: the first 10 % of the load, where surface detection and
    /// noise dominate the logarithm, is left out).
    pub loading_window: [f64; 2],
    /// Load window of the unloading fit, fractions of P_max (default 0.25–0.95).
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
            unloading_window: [0.25, 0.95],
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
        check::positive("epsilon", o.epsilon)?;
        if let Some(b) = o.beta {
            check::positive("beta", b)?;
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
