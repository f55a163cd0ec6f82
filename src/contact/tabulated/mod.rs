//! Tabulated contact laws: the exact equilibrium path of an adhesive sphere
//! (Maugis–Dugdale, or the numerical Lennard-Jones sphere) at the cost
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
//! The tolerance is against the curve the table was built from: the closed
//! form for Maugis–Dugdale, the Lennard-Jones solver on the table's own grid
//! for [`TabulatedLaw::from_lj_sphere`]. That grid's own error is not in it:
//! at μ = 1 an N = 128 table is within 10⁻⁴ of its solver but pulls off
//! 4·10⁻⁴ πRw from the converged pull-off (BENCHMARKS.md §4).
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
//!
//! [`EquilibriumCurve`]: super::curve::EquilibriumCurve
//! [`DeepTail::Hertz`]: super::curve::DeepTail::Hertz
//! [`FarTail`]: super::curve::FarTail

// NaN-aware comparisons (`!(x <= hi)`) are intended.
#![allow(clippy::neg_cmp_op_on_partial_ord, clippy::type_complexity)]

mod build;
mod data;
mod eval;
mod hermite;
mod index;
mod segment;
#[cfg(test)]
mod tests;
mod threshold;

use self::data::TableData;
use self::segment::{Branch, Interval, Segment};
use super::NormalResponse;
use crate::error::{Error, Result};
use serde::{Deserialize, Serialize};

/// Default relative tolerance of a table (see the module's error measure).
pub const DEFAULT_TOLERANCE: f64 = 1e-4;

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

fn bad(name: &'static str, value: f64, bound: &'static str) -> Error {
    Error::InvalidArgument { name, value, bound }
}

/// Measure of the module documentation, in reduced units.
#[inline]
fn measure(ft: f64, fe: f64, at: f64, ae: f64, ff: f64, af: f64) -> f64 {
    ((ft - fe).abs() / fe.abs().max(ff)).max((at - ae).abs() / ae.max(af))
}

impl TabulatedLaw {
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
}
