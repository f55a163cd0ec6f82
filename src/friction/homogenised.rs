//! The homogenised friction law of an FE integration point: the slider
//! model's results over a range of nominal
//! pressures — coefficient of friction μ(p), adhesive holding pressure,
//! true contact fraction and the split of the dissipation between the
//! mechanisms — tabulated once, then evaluated per point and per time
//! increment as a regularised Coulomb (Derjaguin) law with a return mapping.
//!
//! # The table
//!
//! [`HomogenisedFriction::from_samples`] takes [`HomogenisedSample`]s at
//! strictly increasing nominal pressures p_k (Pa) — usually from slider runs
//! ([`HomogenisedFriction::from_fn`] samples any function of p). Between the
//! samples, μ, the adhesion pressure and the contact fraction are
//! interpolated by the monotone piecewise cubic Hermite interpolant of
//! Fritsch & Carlson (SIAM J. Numer. Anal. 17 (1980) 238–246), with the
//! slopes of Fritsch & Butland (SIAM J. Sci. Stat. Comput. 5 (1984)
//! 300–304) as in MATLAB's `pchip`: at an interior knot the weighted
//! harmonic mean m_k of the neighbouring secants δ (*Formulas*), and 0 where
//! the secants change sign (a local extremum); the one-sided three-point
//! slope at the ends, limited to keep the shape. The interpolant is C¹,
//! passes through every sample exactly, and is monotone wherever the samples
//! are (so it stays within the samples' range: μ ≥ 0, fractions in [0, 1]).
//! The dissipation shares are interpolated linearly, so they stay ≥ 0 and sum
//! to 1. Below the first and above the last pressure every quantity is held
//! constant at the end sample (constant extrapolation, derivative 0): a
//! pressure outside the sampled range is not an error, and a table whose
//! first sample is above 0 gives the first sample's values at zero load.
//!
//! # The step
//!
//! The step ([`FrictionLaw`]) is the return mapping of regularised
//! Coulomb friction (Wriggers, *Computational Contact Mechanics*, 2nd ed.,
//! 2006, §5.2 and §6.2; Simo & Hughes, *Computational Inelasticity*, 1998,
//! §1.2) with the slip limit of the Derjaguin law (thesis (4-3)), each step
//! under *Formulas*:
//!
//! * nominal pressure p and adhesive force A;
//! * slip limit F_lim (or `μN`, `A + μN` for the Amontons and Coulomb forms
//!   (1-1), (1-2) of [`CofForm`]);
//! * trial force F_tr (k the stick stiffness);
//! * `|F_tr| ≤ F_lim`: stick;
//! * otherwise slip, with the plastic slip Δs_p and the dissipation
//!   `ΔD = −F·Δs_p`, split between the mechanisms by the interpolated
//!   shares.
//!
//! With `k = 0` (rigid–plastic) any non-zero slip increment slides:
//! `F = −F_lim Δs/|Δs|`, `Δs_p = Δs`, `ΔD = F_lim|Δs|`.
//!
//! ## Sign convention
//!
//! The slip increment Δs is the displacement increment of the point (the
//! slave node, in FE terms) relative to the counter-surface, as two
//! components in a tangent basis the caller chooses; the tangential force F
//! is the force the counter-surface applies to that point, in the same basis.
//! It opposes slip: `F·Δs_p ≤ 0`, and in pure sliding `F = −F_lim Δs/|Δs|`.
//! This is the convention of Abaqus/Explicit's VFRIC, whose local 1-direction
//! is `t₁ = Δs/|Δs|` (the incremental slip) and whose `fTangential(1)` must
//! lie between zero and minus the stick force (Abaqus User Subroutines
//! Reference, VFRIC: "Local coordinate system", "Frictional forces"): our
//! `F·t₁` is that `fTangential(1)`, negative while sliding. A VFRIC wrapper
//! passes `dSlipFric` as Δs and stores F in its state (VFRIC's `fTangPrev`
//! plays the role of the state's stick force, [`HomogenisedFriction::STATE_FORCE`]).
//!
//! The step is rate independent: the time increment is validated and
//! otherwise unused, so rate-dependent laws can share the signature.
//!
//! # Formulas
//!
//! Interpolation (Fritsch–Butland slopes at interior knots, $h_k = p_{k+1} - p_k$,
//! secants $\delta_k$):
//!
//! $$m_k = \frac{w_1 + w_2}{w_1/\delta_{k-1} + w_2/\delta_k}, \qquad w_1 = 2h_k + h_{k-1}, \qquad w_2 = h_k + 2h_{k-1} .$$
//!
//! Return mapping of one step, $p = N/A_n$:
//!
//! $$F_\mathrm{lim} = \mu(p)\\,(N + A), \quad A = p_\mathrm{adh}(p)\\,A_n, \qquad F_\mathrm{tr} = F_\mathrm{old} - k\\,\Delta s,$$
//!
//! $$F = F_\mathrm{tr} \ \ \text{if}\ \lvert F_\mathrm{tr}\rvert \le F_\mathrm{lim}, \quad \text{else} \quad F = F_\mathrm{lim}\frac{F_\mathrm{tr}}{\lvert F_\mathrm{tr}\rvert}, \quad \Delta\lambda = \frac{\lvert F_\mathrm{tr}\rvert - F_\mathrm{lim}}{k}, \quad \Delta s_p = -\Delta\lambda\frac{F_\mathrm{tr}}{\lvert F_\mathrm{tr}\rvert}, \quad \Delta D = F_\mathrm{lim}\\,\Delta\lambda \ge 0 .$$
//!
//! # References
//!
//! * Thesis (1-1), (1-2), (4-3).
//! * F. N. Fritsch, R. E. Carlson (1980), "Monotone piecewise cubic
//!   interpolation", SIAM J. Numer. Anal. 17, 238–246,
//!   [doi:10.1137/0717021](https://doi.org/10.1137/0717021).
//! * F. N. Fritsch, J. Butland (1984), "A method for constructing local monotone
//!   piecewise cubic interpolants", SIAM J. Sci. Stat. Comput. 5, 300–304,
//!   [doi:10.1137/0905021](https://doi.org/10.1137/0905021).
//! * P. Wriggers (2006), *Computational Contact Mechanics*, 2nd ed., Springer,
//!   §5.2, §6.2.
//! * J. C. Simo, T. J. R. Hughes (1998), *Computational Inelasticity*,
//!   Springer, §1.2.
//! * Abaqus User Subroutines Reference Guide, VFRIC (sign convention).

use super::law::{
    book_path, read, FrictionIncrement, FrictionLaw, FrictionRegime, FrictionResponse,
    FrictionWork, STATE_MODEL, TANGENT_NORMAL, TANGENT_SLIP,
};
use super::ledger::{CofForm, Dissipation};
use crate::error::{check, Error, Result};
use serde::{Deserialize, Serialize};

/// Identifies the serialised format.
const FORMAT: &str = "asperity-homogenised-friction-1";
/// Tolerance on the sum of a sample's dissipation shares.
const SHARE_SUM_TOLERANCE: f64 = 1e-9;

// ------------------------------------------------------------- samples

/// The slider model's response at one nominal pressure: one row of the
/// homogenised table. A plain `repr(C)` value (the C ABI's
/// `AsperityHomogenisedSample`); serde reads plain JSON numbers as well as
/// the exact strings it writes.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HomogenisedSample {
    /// Nominal contact pressure p = N/A_n (Pa), finite and ≥ 0.
    #[serde(with = "crate::serde_exact::lenient")]
    pub pressure: f64,
    /// Coefficient of friction μ at this pressure, finite and ≥ 0, in the
    /// table's [`CofForm`] (Derjaguin μ = F/(N + A), thesis (4-3), by
    /// default).
    #[serde(with = "crate::serde_exact::lenient")]
    pub cof: f64,
    /// Adhesive holding force per nominal area (Pa), finite and ≥ 0: the
    /// adhesive force A of the thesis (4.2, 4.4) divided by A_n.
    #[serde(with = "crate::serde_exact::lenient")]
    pub adhesion_pressure: f64,
    /// True contact area over nominal area (dimensionless), in [0, 1].
    #[serde(with = "crate::serde_exact::lenient")]
    pub contact_fraction: f64,
    /// Fractions of the dissipation due to each mechanism (dimensionless,
    /// each in [0, 1], summing to 1 within 1e-9), held in a [`Dissipation`]
    /// value: a step's dissipation ΔD is split as ΔD·shares.
    pub shares: Dissipation,
}

impl HomogenisedSample {
    /// Checks every field (errors name it: `pressure`, `cof`,
    /// `adhesion_pressure`, `contact_fraction`, `shares` with the sum as
    /// value, or the offending share).
    pub fn validate(&self) -> Result<()> {
        check::non_negative("pressure", self.pressure)?;
        check::non_negative("cof", self.cof)?;
        check::non_negative("adhesion_pressure", self.adhesion_pressure)?;
        check::in_range(
            "contact_fraction",
            self.contact_fraction,
            0.0,
            1.0,
            "in [0, 1]",
        )?;
        let s = &self.shares;
        for (name, v) in [
            ("shares.chemical", s.chemical),
            ("shares.van_der_waals", s.van_der_waals),
            ("shares.elastic", s.elastic),
            ("shares.plastic", s.plastic),
        ] {
            check::in_range(name, v, 0.0, 1.0, "in [0, 1]")?;
        }
        let sum = s.total();
        if (sum - 1.0).abs() > SHARE_SUM_TOLERANCE {
            return Err(Error::InvalidArgument {
                name: "shares",
                value: sum,
                bound: "fractions summing to 1 (within 1e-9)",
            });
        }
        Ok(())
    }
}

// ------------------------------------------------------------- the law

/// One interval of the interpolant between two samples: Hermite cubics
/// `y = c₀ + t(c₁ + t(c₂ + t c₃))`, `t = (p − p₀)/h`, and linear shares.
#[derive(Debug, Clone, Copy)]
struct Interval {
    p0: f64,
    inv_h: f64,
    cof: [f64; 4],
    adhesion: [f64; 4],
    fraction: [f64; 4],
    share0: [f64; 4],
    dshare: [f64; 4],
}

/// The table's values and their pressure derivatives at one pressure.
#[derive(Debug, Clone, Copy)]
struct Point {
    cof: f64,
    dcof: f64,
    adhesion: f64,
    dadhesion: f64,
    fraction: f64,
    shares: [f64; 4],
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
struct HomogenisedData {
    format: String,
    form: CofForm,
    samples: Vec<HomogenisedSample>,
}

/// The homogenised friction law; see the module documentation. Built once by
/// [`Self::from_samples`], [`Self::from_fn`] or [`Self::from_json`],
/// immutable, `Send + Sync`; a step touches only the caller's memory.
/// Serialises as its samples and form, and evaluates bit-identically after a
/// JSON round trip.
#[derive(Debug, Clone, Serialize, Deserialize)]
#[serde(into = "HomogenisedData", try_from = "HomogenisedData")]
pub struct HomogenisedFriction {
    data: HomogenisedData,
    pressures: Vec<f64>,
    intervals: Vec<Interval>,
    first: Point,
    last: Point,
    stick_stiffness: f64,
}

const _: () = {
    const fn shareable<T: Send + Sync>() {}
    shareable::<HomogenisedFriction>();
};

impl From<HomogenisedFriction> for HomogenisedData {
    fn from(h: HomogenisedFriction) -> Self {
        h.data
    }
}

impl TryFrom<HomogenisedData> for HomogenisedFriction {
    type Error = Error;
    fn try_from(d: HomogenisedData) -> Result<Self> {
        if d.format != FORMAT {
            return Err(Error::InvalidArgument {
                name: "format",
                value: 0.0,
                bound: "\"asperity-homogenised-friction-1\"",
            });
        }
        Self::from_samples(&d.samples, d.form)
    }
}

#[inline]
fn shares_of(d: &Dissipation) -> [f64; 4] {
    [d.chemical, d.van_der_waals, d.elastic, d.plastic]
}

/// The Fritsch–Butland / `pchip` slopes of the data (x, y), n ≥ 2.
fn pchip_slopes(x: &[f64], y: &[f64]) -> Vec<f64> {
    let n = x.len();
    let h: Vec<f64> = x.windows(2).map(|w| w[1] - w[0]).collect();
    let del: Vec<f64> = (0..n - 1).map(|k| (y[k + 1] - y[k]) / h[k]).collect();
    let mut m = vec![0.0; n];
    if n == 2 {
        m[0] = del[0];
        m[1] = del[0];
        return m;
    }
    for k in 1..n - 1 {
        let (d0, d1) = (del[k - 1], del[k]);
        if d0 * d1 > 0.0 {
            let w1 = 2.0 * h[k] + h[k - 1];
            let w2 = h[k] + 2.0 * h[k - 1];
            m[k] = (w1 + w2) / (w1 / d0 + w2 / d1);
        }
    }
    // One-sided three-point end slopes, shape-preserving (Moler, Numerical
    // Computing with MATLAB, 2004, §3.4).
    let end = |h0: f64, h1: f64, d0: f64, d1: f64| -> f64 {
        let s = ((2.0 * h0 + h1) * d0 - h0 * d1) / (h0 + h1);
        if s.signum() != d0.signum() || d0 == 0.0 {
            0.0
        } else if d0.signum() != d1.signum() && s.abs() > 3.0 * d0.abs() {
            3.0 * d0
        } else {
            s
        }
    };
    m[0] = end(h[0], h[1], del[0], del[1]);
    m[n - 1] = end(h[n - 2], h[n - 3], del[n - 2], del[n - 3]);
    m
}

/// Hermite coefficients in t ∈ [0, 1] of the cubic through (0, y0), (1, y1)
/// with slopes m0, m1 (per unit p) over an interval of length h.
fn hermite(y0: f64, m0: f64, y1: f64, m1: f64, h: f64) -> [f64; 4] {
    let d = y1 - y0;
    let (p0, p1) = (h * m0, h * m1);
    [y0, p0, 3.0 * d - 2.0 * p0 - p1, p0 + p1 - 2.0 * d]
}

#[inline(always)]
fn horner(c: &[f64; 4], t: f64) -> f64 {
    c[0] + t * (c[1] + t * (c[2] + t * c[3]))
}

#[inline(always)]
fn horner_d(c: &[f64; 4], t: f64) -> f64 {
    c[1] + t * (2.0 * c[2] + t * (3.0 * c[3]))
}

fn constant_point(s: &HomogenisedSample) -> Point {
    Point {
        cof: s.cof,
        dcof: 0.0,
        adhesion: s.adhesion_pressure,
        dadhesion: 0.0,
        fraction: s.contact_fraction,
        shares: shares_of(&s.shares),
    }
}

#[cold]
/// `√(x² + y²)`, by `hypot` when the squares are subnormal (|(x, y)| below
/// 1e-150): there the plain sum loses bits and a unit direction x/|(x, y)|
/// comes out above 1 (|F| > F_lim by 1e-10 at a slip of 8e-158 m). Above,
/// the plain form (and its overflow to ∞, which the
/// step reports) is kept.
#[inline(always)]
fn norm2(x: f64, y: f64) -> f64 {
    let n = (x * x + y * y).sqrt();
    if n < 1e-150 {
        x.hypot(y)
    } else {
        n
    }
}

fn overflow(name: &'static str, value: f64) -> Error {
    Error::OutOfDomain {
        name,
        value,
        reason: "the friction force overflows f64",
    }
}

impl HomogenisedFriction {
    /// The law from samples at strictly increasing nominal pressures (at
    /// least one; one sample gives a pressure-independent law), with the
    /// samples' `cof` read in the form `form` ([`CofForm::Derjaguin`], the
    /// thesis's choice, is the default). Errors: no samples (`samples`), a
    /// sample failing [`HomogenisedSample::validate`], pressures not
    /// strictly increasing (`pressure`, the offending value).
    pub fn from_samples(samples: &[HomogenisedSample], form: CofForm) -> Result<Self> {
        let Some((first, rest)) = samples.split_first() else {
            return Err(Error::InvalidArgument {
                name: "samples",
                value: 0.0,
                bound: "at least one sample",
            });
        };
        first.validate()?;
        let mut prev = first.pressure;
        for s in rest {
            s.validate()?;
            if s.pressure <= prev {
                return Err(Error::InvalidArgument {
                    name: "pressure",
                    value: s.pressure,
                    bound: "strictly increasing from sample to sample",
                });
            }
            prev = s.pressure;
        }
        let pressures: Vec<f64> = samples.iter().map(|s| s.pressure).collect();
        let n = samples.len();
        let mut intervals = Vec::with_capacity(n.saturating_sub(1));
        if n >= 2 {
            let col = |f: fn(&HomogenisedSample) -> f64| -> (Vec<f64>, Vec<f64>) {
                let y: Vec<f64> = samples.iter().map(f).collect();
                let m = pchip_slopes(&pressures, &y);
                (y, m)
            };
            let (mu, mu_m) = col(|s| s.cof);
            let (ad, ad_m) = col(|s| s.adhesion_pressure);
            let (fr, fr_m) = col(|s| s.contact_fraction);
            for k in 0..n - 1 {
                let h = pressures[k + 1] - pressures[k];
                let s0 = shares_of(&samples[k].shares);
                let s1 = shares_of(&samples[k + 1].shares);
                intervals.push(Interval {
                    p0: pressures[k],
                    inv_h: 1.0 / h,
                    cof: hermite(mu[k], mu_m[k], mu[k + 1], mu_m[k + 1], h),
                    adhesion: hermite(ad[k], ad_m[k], ad[k + 1], ad_m[k + 1], h),
                    fraction: hermite(fr[k], fr_m[k], fr[k + 1], fr_m[k + 1], h),
                    share0: s0,
                    dshare: [s1[0] - s0[0], s1[1] - s0[1], s1[2] - s0[2], s1[3] - s0[3]],
                });
            }
        }
        Ok(Self {
            data: HomogenisedData {
                format: FORMAT.to_string(),
                form,
                samples: samples.to_vec(),
            },
            pressures,
            intervals,
            first: constant_point(first),
            last: constant_point(&samples[n - 1]),
            stick_stiffness: 0.0,
        })
    }

    /// The law sampled from `f` at the nominal pressures `pressures` (Pa,
    /// strictly increasing, finite, ≥ 0), e.g. a slider model run at each
    /// pressure. The `pressure` field of each returned sample is set to the
    /// pressure asked for. Errors: the first error of `f`, and those of
    /// [`Self::from_samples`].
    pub fn from_fn(
        pressures: &[f64],
        form: CofForm,
        mut f: impl FnMut(f64) -> Result<HomogenisedSample>,
    ) -> Result<Self> {
        let mut samples = Vec::with_capacity(pressures.len());
        for &p in pressures {
            check::non_negative("pressure", p)?;
            let mut s = f(p)?;
            s.pressure = p;
            samples.push(s);
        }
        Self::from_samples(&samples, form)
    }

    /// The samples the law was built from.
    pub fn samples(&self) -> &[HomogenisedSample] {
        &self.data.samples
    }

    /// The form in which the samples' `cof` is read.
    pub fn form(&self) -> CofForm {
        self.data.form
    }

    /// JSON text of the law (numbers written exactly).
    pub fn to_json(&self) -> String {
        serde_json::to_string(&self.data).expect("a homogenised law always serialises")
    }

    /// A law from [`Self::to_json`] text (or hand-written JSON with plain
    /// numbers), validated as [`Self::from_samples`]; evaluates
    /// bit-identically to the law written. A syntax or field error names
    /// `json` with the line as value.
    pub fn from_json(json: &str) -> Result<Self> {
        let d: HomogenisedData =
            serde_json::from_str(json).map_err(|e| Error::InvalidArgument {
                name: "json",
                value: e.line() as f64,
                bound:
                    "a serialised HomogenisedFriction (syntax, field or value error at this line)",
            })?;
        Self::try_from(d)
    }

    #[inline(always)]
    fn point(&self, p: f64) -> Point {
        let x = &self.pressures;
        if p < x[0] {
            return self.first;
        }
        if p >= x[x.len() - 1] {
            return self.last;
        }
        // x[0] ≤ p < x[n−1], n ≥ 2: the interval k with x[k] ≤ p < x[k+1].
        let k = x.partition_point(|&xi| xi <= p) - 1;
        let iv = &self.intervals[k];
        let t = (p - iv.p0) * iv.inv_h;
        Point {
            cof: horner(&iv.cof, t),
            dcof: horner_d(&iv.cof, t) * iv.inv_h,
            adhesion: horner(&iv.adhesion, t),
            dadhesion: horner_d(&iv.adhesion, t) * iv.inv_h,
            fraction: horner(&iv.fraction, t),
            shares: [
                iv.share0[0] + t * iv.dshare[0],
                iv.share0[1] + t * iv.dshare[1],
                iv.share0[2] + t * iv.dshare[2],
                iv.share0[3] + t * iv.dshare[3],
            ],
        }
    }

    /// The interpolated sample at the nominal pressure `pressure` (Pa,
    /// finite and ≥ 0); constant beyond the sampled range.
    pub fn sample_at(&self, pressure: f64) -> Result<HomogenisedSample> {
        let p = check::non_negative("pressure", pressure)?;
        let q = self.point(p);
        Ok(HomogenisedSample {
            pressure: p,
            cof: q.cof,
            adhesion_pressure: q.adhesion,
            contact_fraction: q.fraction,
            shares: Dissipation {
                chemical: q.shares[0],
                van_der_waals: q.shares[1],
                elastic: q.shares[2],
                plastic: q.shares[3],
            },
        })
    }

    /// dμ/dp (1/Pa) at `pressure` (Pa, finite and ≥ 0): the derivative of
    /// the interpolant (0 beyond the sampled range; at a knot, the
    /// derivative of the interval to its right, which is continuous).
    pub fn cof_slope(&self, pressure: f64) -> Result<f64> {
        let p = check::non_negative("pressure", pressure)?;
        Ok(self.point(p).dcof)
    }

    /// The same law with the stick stiffness k (N/m, finite and ≥ 0) of
    /// the regularised stick (*Formulas*): the elastic slip before sliding
    /// is |F|/k; 0 (the default) is rigid–plastic. A penalty of the host's
    /// discretisation, not a property of the table: it is not serialised.
    pub fn with_stick_stiffness(mut self, stick_stiffness: f64) -> Result<Self> {
        self.stick_stiffness = check::non_negative("stick_stiffness", stick_stiffness)?;
        Ok(self)
    }

    /// The stick stiffness k (N/m).
    pub fn stick_stiffness(&self) -> f64 {
        self.stick_stiffness
    }

    /// Books into `r` the release of the stick force `old_force` when the
    /// point loses contact (F → 0 at once): its stored energy |F|²/2k is
    /// lost, so it is dissipated (split by `shares`); 0 when k = 0.
    fn release(
        &self,
        old_force: [f64; 2],
        shares: &[f64; 4],
        r: &mut FrictionResponse,
    ) -> Result<()> {
        let k = self.stick_stiffness;
        if k > 0.0 {
            let f = norm2(old_force[0], old_force[1]);
            let e = (0.5 * f / k) * f;
            if !e.is_finite() {
                return Err(Error::OutOfDomain {
                    name: "stick_stiffness",
                    value: k,
                    reason: "the released stored energy |F|^2/(2k) overflows f64 (stick stiffness too small for the old force)",
                });
            }
            r.dissipated = e;
            r.dissipation = Dissipation {
                chemical: e * shares[0],
                van_der_waals: e * shares[1],
                elastic: e * shares[2],
                plastic: e * shares[3],
            };
        }
        Ok(())
    }

    /// The return mapping of one step (module documentation) from the old
    /// stick force `old_force` (N), on a checked increment with A_n > 0.
    /// Returns the response and the plastic slip length Δλ (m). Errors:
    /// OutOfDomain (`normal_force` or `slip`) when the force, the
    /// dissipation or the consistent tangent (`F_lim/|Δs|` for k = 0, e.g.
    /// N = 1.8e308 N with Δs = 4e-9 m) overflows f64.
    #[inline(always)]
    fn return_map(
        &self,
        old_force: [f64; 2],
        inc: &FrictionIncrement,
    ) -> Result<(FrictionResponse, f64)> {
        let (n, a_n) = (inc.normal_force, inc.area);
        let [dsx, dsy] = inc.slip;
        let k = self.stick_stiffness;
        if a_n == 0.0 {
            // An open gap (N = 0, checked): no contact, no adhesion, no
            // tangents; the stick force is released and its stored energy
            // lost (booked as dissipated, split as at zero pressure).
            let mut r = FrictionResponse {
                regime: FrictionRegime::NoContact as i32,
                tangents: TANGENT_NORMAL | TANGENT_SLIP,
                ..FrictionResponse::default()
            };
            self.release(old_force, &self.first.shares, &mut r)?;
            return Ok((r, 0.0));
        }

        let p = n / a_n;
        let q = self.point(p);
        let adhesion = q.adhesion * a_n;
        // Slip limit and dF_lim/dN; dp/dN = 1/A_n, dA/dN = p_adh'(p).
        let (limit, dlimit) = match self.data.form {
            CofForm::Derjaguin => (
                q.cof * (n + adhesion),
                q.dcof / a_n * (n + adhesion) + q.cof * (1.0 + q.dadhesion),
            ),
            CofForm::DerjaguinDoubleAdhesion => (
                q.cof * (n + 2.0 * adhesion),
                q.dcof / a_n * (n + 2.0 * adhesion) + q.cof * (1.0 + 2.0 * q.dadhesion),
            ),
            CofForm::Amontons => (q.cof * n, q.dcof / a_n * n + q.cof),
            CofForm::Coulomb => (adhesion + q.cof * n, q.dadhesion + q.dcof / a_n * n + q.cof),
        };
        if !(limit.is_finite() && dlimit.is_finite() && adhesion.is_finite()) {
            return Err(overflow("normal_force", n));
        }

        let mut r = FrictionResponse {
            normal_force: n,
            cof: q.cof,
            adhesion,
            true_contact_area: q.fraction * a_n,
            tangents: TANGENT_NORMAL | TANGENT_SLIP,
            ..FrictionResponse::default()
        };
        if n + adhesion == 0.0 {
            r.regime = FrictionRegime::NoContact as i32;
            // F = 0 here; under a load N → 0⁺ the point slides on a cone of
            // radius F_lim(N) → 0 (or is held at its rim) along the unit
            // direction of the trial force (k > 0), of −Δs (k = 0), or of
            // the old force (k = 0, no slip): ∂F/∂N is that direction times
            // dF_lim/dN, the derivative from above (N ≥ 0); ∂F/∂Δs → 0.
            let (dx, dy) = if k > 0.0 {
                (old_force[0] - k * dsx, old_force[1] - k * dsy)
            } else if dsx != 0.0 || dsy != 0.0 {
                (-dsx, -dsy)
            } else {
                (old_force[0], old_force[1])
            };
            let len = norm2(dx, dy);
            if len > 0.0 && len.is_finite() {
                r.dforce_dnormal = [dx / len * dlimit, dy / len * dlimit];
            }
            self.release(old_force, &q.shares, &mut r)?;
            return Ok((r, 0.0));
        }

        // Return mapping. `dir` is the unit direction of the force on the
        // cone when sliding, `mag` the magnitude of the quantity it was
        // taken from (trial force, or |Δs| when rigid–plastic).
        let (fx, fy, lambda);
        if k > 0.0 {
            let tx = old_force[0] - k * dsx;
            let ty = old_force[1] - k * dsy;
            let tn = norm2(tx, ty);
            if !tn.is_finite() {
                return Err(overflow("slip", dsx.abs().max(dsy.abs())));
            }
            if tn <= limit {
                (fx, fy, lambda) = (tx, ty, 0.0);
                r.regime = FrictionRegime::Stick as i32;
                r.dforce_dslip = [[-k, 0.0], [0.0, -k]];
            } else {
                let (nx, ny) = (tx / tn, ty / tn);
                (fx, fy) = (limit * nx, limit * ny);
                lambda = (tn - limit) / k;
                r.regime = FrictionRegime::Slip as i32;
                let c = -k * limit / tn;
                r.dforce_dslip = [
                    [c * (1.0 - nx * nx), -c * nx * ny],
                    [-c * nx * ny, c * (1.0 - ny * ny)],
                ];
                r.dforce_dnormal = [nx * dlimit, ny * dlimit];
            }
        } else {
            let sn = norm2(dsx, dsy);
            if !sn.is_finite() {
                return Err(overflow("slip", dsx.abs().max(dsy.abs())));
            }
            if sn > 0.0 {
                let (ux, uy) = (dsx / sn, dsy / sn);
                (fx, fy) = (-limit * ux, -limit * uy);
                lambda = sn;
                r.regime = FrictionRegime::Slip as i32;
                let c = -limit / sn;
                r.dforce_dslip = [
                    [c * (1.0 - ux * ux), -c * ux * uy],
                    [-c * ux * uy, c * (1.0 - uy * uy)],
                ];
                r.dforce_dnormal = [-ux * dlimit, -uy * dlimit];
            } else {
                // Rigid stick: the old force, capped by the cone (without
                // slip, so without dissipation).
                let (tx, ty) = (old_force[0], old_force[1]);
                let tn = norm2(tx, ty);
                r.regime = FrictionRegime::Stick as i32;
                lambda = 0.0;
                if tn <= limit {
                    (fx, fy) = (tx, ty);
                } else {
                    let (nx, ny) = (tx / tn, ty / tn);
                    (fx, fy) = (limit * nx, limit * ny);
                    r.dforce_dnormal = [nx * dlimit, ny * dlimit];
                }
            }
        }

        let dissipated = limit * lambda;
        if !dissipated.is_finite() {
            return Err(overflow("slip", dsx.abs().max(dsy.abs())));
        }
        let t = &r.dforce_dslip;
        if !(t[0][0].is_finite()
            && t[0][1].is_finite()
            && t[1][0].is_finite()
            && t[1][1].is_finite()
            && r.dforce_dnormal[0].is_finite()
            && r.dforce_dnormal[1].is_finite())
        {
            // F_lim/|Δs| (or k F_lim/|F_tr|) beyond f64: a huge load with a
            // tiny slip.
            return Err(Error::OutOfDomain {
                name: "slip",
                value: dsx.abs().max(dsy.abs()),
                reason:
                    "the consistent tangent dF/dslip overflows f64 (slip too small for this load)",
            });
        }
        r.force = [fx, fy];
        r.force_magnitude = if r.regime == FrictionRegime::Slip as i32 {
            limit
        } else {
            (fx * fx + fy * fy).sqrt()
        };
        r.stored_energy = if k > 0.0 {
            0.5 * r.force_magnitude * r.force_magnitude / k
        } else {
            0.0
        };
        if !r.stored_energy.is_finite() {
            return Err(Error::OutOfDomain {
                name: "stick_stiffness",
                value: k,
                reason: "the stored elastic energy |F|^2/(2k) overflows f64 (stick stiffness too small for this force)",
            });
        }
        r.dissipated = dissipated;
        r.dissipation = Dissipation {
            chemical: dissipated * q.shares[0],
            van_der_waals: dissipated * q.shares[1],
            elastic: dissipated * q.shares[2],
            plastic: dissipated * q.shares[3],
        };
        Ok((r, lambda))
    }
}

/// cbindgen:ignore
///
/// The layout of a state ([`FrictionLaw::state_len`] = [`Self::STATE_LEN`]).
impl HomogenisedFriction {
    /// Index of the stick force F (N, x and y) carried into the next
    /// increment; the elastic slip is −F/k.
    pub const STATE_FORCE: usize = STATE_MODEL;
    /// Index of the accumulated plastic slip path Σ|Δs_p| (m), the slip
    /// that dissipates (the common slip path Σ|Δs| also counts elastic
    /// slip).
    pub const STATE_PLASTIC_SLIP_PATH: usize = STATE_MODEL + 2;
    /// Index of the accumulated dissipation by mechanism (J): chemical, van
    /// der Waals, elastic, plastic.
    pub const STATE_MECHANISMS: usize = STATE_MODEL + 3;
    /// Doubles of a state.
    pub const STATE_LEN: usize = STATE_MODEL + 7;
}

/// The regularised Coulomb (Derjaguin) return mapping per increment
/// (module documentation). State: the common accumulators, then
/// [`HomogenisedFriction::STATE_FORCE`], `STATE_PLASTIC_SLIP_PATH`,
/// `STATE_MECHANISMS`. Errors beyond the common ones: `area` not > 0;
/// `old.force`, `old.plastic_slip_path`, `old.mechanisms` (finite, the
/// accumulators ≥ 0); OutOfDomain when the force, the dissipation or a
/// tangent overflows f64. Tangents are always computed (they cost nothing);
/// with no contact, ∂F/∂N is the derivative from above (N → 0⁺).
/// Regimes: stick, slip, no contact (N + A = 0, or an open gap: A_n = 0
/// with N = 0; an FE host passes it for a node whose gap is open, since
/// with A_n > 0 the table's adhesive pressure holds a point under zero
/// load). No contact releases the stick force; its stored energy |F|²/2k
/// is booked as dissipated, so the energy balance closes.
impl FrictionLaw for HomogenisedFriction {
    fn state_len(&self) -> usize {
        Self::STATE_LEN
    }

    fn check(&self, increment: &FrictionIncrement) -> Result<()> {
        // A_n = 0 with N = 0 is an open gap (no contact); otherwise the
        // nominal pressure N/A_n needs A_n > 0.
        let a = increment.area;
        if a > 0.0 || (a == 0.0 && increment.normal_force == 0.0) {
            return Ok(());
        }
        Err(Error::InvalidArgument {
            name: "area",
            value: a,
            bound: "finite and > 0 (0 only with normal_force = 0: an open gap)",
        })
    }

    #[inline]
    fn check_state(&self, state: &[f64], what: &'static str) -> Result<()> {
        let f = Self::STATE_FORCE;
        let valid = state[f].is_finite()
            && state[f + 1].is_finite()
            && state[Self::STATE_PLASTIC_SLIP_PATH..Self::STATE_LEN]
                .iter()
                .all(|v| (0.0..=f64::MAX).contains(v));
        if valid {
            Ok(())
        } else {
            state_error(state, what)
        }
    }

    #[inline]
    fn advance(
        &self,
        old: Option<&[f64]>,
        new: &mut [f64],
        inc: &FrictionIncrement,
        _work: &mut FrictionWork,
    ) -> Result<FrictionResponse> {
        let f = Self::STATE_FORCE;
        let old_force = [read(old, new, f), read(old, new, f + 1)];
        let (r, lambda) = self.return_map(old_force, inc)?;
        let path = crate::friction::dynamic::norm(inc.slip[0], inc.slip[1]);
        book_path(old, new, r.dissipated, path);
        new[f] = r.force[0];
        new[f + 1] = r.force[1];
        let p = Self::STATE_PLASTIC_SLIP_PATH;
        new[p] = read(old, new, p) + lambda;
        let d = &r.dissipation;
        for (j, dj) in [d.chemical, d.van_der_waals, d.elastic, d.plastic]
            .into_iter()
            .enumerate()
        {
            let i = Self::STATE_MECHANISMS + j;
            new[i] = read(old, new, i) + dj;
        }
        Ok(r)
    }
}

/// The error of a homogenised state that [`FrictionLaw::check_state`]
/// refused, naming the field (`old.…` or `state.…`).
#[cold]
#[inline(never)]
fn state_error(state: &[f64], what: &'static str) -> Result<()> {
    let old = what == "old";
    let f = HomogenisedFriction::STATE_FORCE;
    let name = |o: &'static str, s: &'static str| if old { o } else { s };
    check::finite(name("old.force", "state.force"), state[f])?;
    check::finite(name("old.force", "state.force"), state[f + 1])?;
    check::non_negative(
        name("old.plastic_slip_path", "state.plastic_slip_path"),
        state[HomogenisedFriction::STATE_PLASTIC_SLIP_PATH],
    )?;
    for &v in &state[HomogenisedFriction::STATE_MECHANISMS..HomogenisedFriction::STATE_LEN] {
        check::non_negative(name("old.mechanisms", "state.mechanisms"), v)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(p: f64, mu: f64) -> HomogenisedSample {
        HomogenisedSample {
            pressure: p,
            cof: mu,
            adhesion_pressure: 0.0,
            contact_fraction: 0.0,
            shares: Dissipation {
                chemical: 1.0,
                ..Dissipation::default()
            },
        }
    }

    #[test]
    fn pchip_linear_data_is_linear() {
        let s: Vec<_> = (0..5)
            .map(|i| sample(i as f64, 1.0 + 0.5 * i as f64))
            .collect();
        let h = HomogenisedFriction::from_samples(&s, CofForm::Derjaguin).unwrap();
        for j in 0..=40 {
            let p = j as f64 * 0.1;
            let v = h.sample_at(p).unwrap().cof;
            assert!((v - (1.0 + 0.5 * p)).abs() < 1e-14, "{p} {v}");
        }
    }

    #[test]
    fn single_sample_is_constant() {
        let h = HomogenisedFriction::from_samples(&[sample(1e6, 0.7)], CofForm::Derjaguin).unwrap();
        assert_eq!(h.sample_at(0.0).unwrap().cof, 0.7);
        assert_eq!(h.sample_at(1e9).unwrap().cof, 0.7);
    }
}
