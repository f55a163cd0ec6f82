//! Summit-height distributions and their tail moments M_q(d) (m^q), the
//! height integrals of the Zhuravlev / Greenwood–Williamson / Kragelsky
//! models (thesis (1-29), (1-30), (5-7)).
//!
//! Heights z (m) are measured upwards; the separation d (m) is the height of
//! the counter-surface's reference plane in the same frame. The parametric
//! distributions have zero mean, so d is measured from the mean summit height
//! (GW 1966's convention); an empirical list is used in its own frame.
//!
//! # Formulas
//!
//! $$M_q(d) = \int_d^\infty (z-d)^q\\,\varphi(z)\\,dz \quad (\mathrm{m}^q),$$
//!
//! for Gaussian heights $M_q(d) = \sigma^q F_q(d/\sigma)$ ([`super::gaussian`]);
//! for the zero-mean exponential $\varphi(z) = e^{-(z+\sigma)/\sigma}/\sigma$
//! ($z \ge -\sigma$)
//!
//! $$M_q(d) = \sigma^q\\,\Gamma(q+1)\\,e^{-(d+\sigma)/\sigma} \quad (d \ge -\sigma), \qquad M_q(d) = \sigma^q e^{x}\\,\Gamma(q+1, x), \ \ x = -\frac{d+\sigma}{\sigma} \quad (d < -\sigma);$$
//!
//! for an empirical list of $M$ heights $M_q(d) = \frac{1}{M}\sum_{z_i > d}(z_i - d)^q$.
//!
//! # References
//!
//! * Thesis (1-29), (1-30), (5-7).
//! * J. A. Greenwood, J. B. P. Williamson (1966), Proc. R. Soc. Lond. A 295,
//!   300–319, [doi:10.1098/rspa.1966.0242](https://doi.org/10.1098/rspa.1966.0242).

use super::gaussian;
use crate::error::{check, Error, Result};

/// Largest accepted moment order q (as [`gaussian::MAX_ORDER`]).
pub const MAX_ORDER: f64 = gaussian::MAX_ORDER;

/// A measured (or generated) set of summits: heights (m), sorted on
/// construction, and optionally each summit's radius of curvature (m).
///
/// Its distribution is the empirical one: each of the M summits has
/// probability 1/M, so `M_q(d) = (1/M) Σ_{z_i > d} (z_i − d)^q`, a straight
/// sum over the sorted suffix above d (found by binary search): O(log M + k)
/// for k summits in contact.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct EmpiricalHeights {
    heights: Vec<f64>,
    radii: Option<Vec<f64>>,
    mean: f64,
    std_dev: f64,
}

impl EmpiricalHeights {
    /// Summit heights (m): at least one, all finite; any order (they are
    /// sorted here).
    pub fn new(mut heights: Vec<f64>) -> Result<Self> {
        check_heights(&heights)?;
        heights.sort_by(f64::total_cmp);
        Ok(Self::from_sorted(heights, None))
    }

    /// Summit heights (m) with each summit's radius of curvature (m, finite
    /// and > 0), the same number of each; the pairs are sorted by height.
    pub fn with_radii(heights: Vec<f64>, radii: Vec<f64>) -> Result<Self> {
        check_heights(&heights)?;
        if radii.len() != heights.len() {
            return Err(Error::InvalidArgument {
                name: "radii",
                value: radii.len() as f64,
                bound: "as many radii as heights",
            });
        }
        for &r in &radii {
            check::positive("radii", r)?;
        }
        let mut pairs: Vec<(f64, f64)> = heights.into_iter().zip(radii).collect();
        pairs.sort_by(|a, b| a.0.total_cmp(&b.0));
        let (h, r): (Vec<f64>, Vec<f64>) = pairs.into_iter().unzip();
        Ok(Self::from_sorted(h, Some(r)))
    }

    fn from_sorted(heights: Vec<f64>, radii: Option<Vec<f64>>) -> Self {
        let n = heights.len() as f64;
        let mean = heights.iter().sum::<f64>() / n;
        let var = heights.iter().map(|z| (z - mean).powi(2)).sum::<f64>() / n;
        Self {
            heights,
            radii,
            mean,
            std_dev: var.sqrt(),
        }
    }

    /// The heights (m), ascending.
    pub fn heights(&self) -> &[f64] {
        &self.heights
    }

    /// The radii (m), in the order of [`Self::heights`], when given.
    pub fn radii(&self) -> Option<&[f64]> {
        self.radii.as_deref()
    }

    /// Number of summits M (≥ 1).
    pub fn len(&self) -> usize {
        self.heights.len()
    }

    /// Always false: an empirical distribution has at least one summit.
    pub fn is_empty(&self) -> bool {
        self.heights.is_empty()
    }

    /// Mean height (m).
    pub fn mean(&self) -> f64 {
        self.mean
    }

    /// Population standard deviation of the heights (m), `√((1/M) Σ (z − z̄)²)`.
    pub fn std_dev(&self) -> f64 {
        self.std_dev
    }

    /// Highest summit (m).
    pub fn max(&self) -> f64 {
        self.heights[self.heights.len() - 1]
    }

    /// Index of the first summit strictly above `d`: the summits in contact
    /// are `first_above(d)..len()`.
    #[inline]
    pub(crate) fn first_above(&self, d: f64) -> usize {
        self.heights.partition_point(|&z| z <= d)
    }

    /// `(1/M) Σ_{z_i > d} w_i (z_i − d)^q` with `w_i = R_i^p` when radii are
    /// given (and `p ≠ 0`), 1 otherwise.
    pub(crate) fn weighted_moment(&self, q: f64, d: f64, radius_power: f64) -> f64 {
        let start = self.first_above(d);
        let z = &self.heights[start..];
        let sum: f64 = match (&self.radii, radius_power != 0.0) {
            (Some(r), true) => z
                .iter()
                .zip(&r[start..])
                .map(|(&z, &r)| r.powf(radius_power) * power(z - d, q))
                .sum(),
            _ => z.iter().map(|&z| power(z - d, q)).sum(),
        };
        sum / self.heights.len() as f64
    }
}

#[inline]
fn power(x: f64, q: f64) -> f64 {
    if q == 0.0 {
        1.0
    } else if q == 1.0 {
        x
    } else if q == 1.5 {
        x * x.sqrt()
    } else if q == 0.5 {
        x.sqrt()
    } else {
        x.powf(q)
    }
}

fn check_heights(heights: &[f64]) -> Result<()> {
    if heights.is_empty() {
        return Err(Error::InvalidArgument {
            name: "heights",
            value: 0.0,
            bound: "at least one summit height",
        });
    }
    for &z in heights {
        check::finite("heights", z)?;
    }
    Ok(())
}

/// The summit-height distribution φ of a statistical contact model.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub enum HeightDistribution {
    /// Normal heights of zero mean and standard deviation `sigma` (m, > 0):
    /// `φ(z) = e^{−z²/(2σ²)}/(σ√(2π))` (Kragelsky 1948; GW 1966). Tail moments
    /// `σ^q F_q(d/σ)` ([`gaussian`]).
    Gaussian {
        /// Standard deviation σ of the summit heights (m).
        sigma: f64,
    },
    /// The exponential tail GW 1966 used as the case of exact proportionality
    /// between area and load, shifted to zero mean: `φ(z) = e^{−(z+σ)/σ}/σ`
    /// for `z ≥ −σ` (mean 0, standard deviation σ). Tail moments
    /// `σ^q Γ(q+1) e^{−(d+σ)/σ}` for `d ≥ −σ` and `σ^q e^{x} Γ(q+1, x)`,
    /// `x = −(d+σ)/σ`, below (upper incomplete Γ).
    Exponential {
        /// Standard deviation σ (= the decay length) of the heights (m).
        sigma: f64,
    },
    /// A measured or generated list of summits.
    Empirical(EmpiricalHeights),
}

impl HeightDistribution {
    /// Gaussian heights, σ (m) finite and > 0.
    pub fn gaussian(sigma: f64) -> Result<Self> {
        Ok(Self::Gaussian {
            sigma: check::positive("sigma", sigma)?,
        })
    }

    /// Zero-mean exponential heights, σ (m) finite and > 0.
    pub fn exponential(sigma: f64) -> Result<Self> {
        Ok(Self::Exponential {
            sigma: check::positive("sigma", sigma)?,
        })
    }

    /// Empirical heights (m), see [`EmpiricalHeights::new`].
    pub fn empirical(heights: Vec<f64>) -> Result<Self> {
        Ok(Self::Empirical(EmpiricalHeights::new(heights)?))
    }

    /// Checks σ (the enum's fields are public, so a hand-built value may hold
    /// a bad one); empirical lists are valid by construction.
    pub fn validate(&self) -> Result<()> {
        match self {
            Self::Gaussian { sigma } | Self::Exponential { sigma } => {
                check::positive("sigma", *sigma).map(|_| ())
            }
            Self::Empirical(_) => Ok(()),
        }
    }

    /// Standard deviation of the summit heights (m): the σ of the plasticity
    /// index (1-31).
    pub fn std_dev(&self) -> f64 {
        match self {
            Self::Gaussian { sigma } | Self::Exponential { sigma } => *sigma,
            Self::Empirical(e) => e.std_dev(),
        }
    }

    /// A length scale for searches in d (m): σ, or for an empirical list its
    /// standard deviation (its largest |height|·1e-9 if all are equal, 1e-12
    /// m if all are zero).
    pub(crate) fn scale(&self) -> f64 {
        let s = self.std_dev();
        if s > 0.0 {
            return s;
        }
        match self {
            Self::Empirical(e) => (e.max().abs() * 1e-9).max(1e-12),
            _ => s,
        }
    }

    /// `∫_d^∞ φ(z) dz`: the fraction of summits above the separation `d` (m,
    /// finite); times N it is the number of contacts of (1-29).
    pub fn exceedance(&self, d: f64) -> Result<f64> {
        self.tail_moment(0.0, d)
    }

    /// `M_q(d) = ∫_d^∞ (z − d)^q φ(z) dz` (m^q) for `0 ≤ q ≤ 16` and finite
    /// separation `d` (m): the height integrals of (1-29) (q = 3/2), (1-30)
    /// (q = 1) and of the power-law extension (3-28) (q = (2 + κ(d−1))/d).
    pub fn tail_moment(&self, q: f64, d: f64) -> Result<f64> {
        let q = check::in_range("q", q, 0.0, MAX_ORDER, "in [0, 16]")?;
        let d = check::finite("separation", d)?;
        self.validate()?;
        self.tail_moment_unchecked(q, d)
    }

    /// [`Self::tail_moment`] for arguments already checked.
    pub(crate) fn tail_moment_unchecked(&self, q: f64, d: f64) -> Result<f64> {
        match self {
            Self::Gaussian { sigma } => {
                let h = d / sigma;
                let f = gaussian::tail_moment_unchecked(q, h)?;
                Ok(if q == 0.0 { f } else { sigma.powf(q) * f })
            }
            Self::Exponential { sigma } => {
                let x = -(d + sigma) / sigma;
                let f = exponential_moment(q, x);
                Ok(if q == 0.0 { f } else { sigma.powf(q) * f })
            }
            Self::Empirical(e) => Ok(e.weighted_moment(q, d, 0.0)),
        }
    }
}

/// Standardised moment of the exponential distribution,
/// `∫_{x}^∞ (v)^q e^{−(v − x)} dv` with `x = −(h + 1)`:
/// `Γ(q+1) e^{x}` for `x ≤ 0`, `e^{x} Γ(q+1, x)` for `x > 0`.
fn exponential_moment(q: f64, x: f64) -> f64 {
    if x <= 0.0 {
        libm::tgamma(q + 1.0) * x.exp()
    } else {
        upper_gamma_scaled(q + 1.0, x)
    }
}

/// `e^{x} Γ(a, x)` for `a > 0`, `x > 0`: the power series of the lower
/// function for `x < a + 1`, Lentz's continued fraction otherwise (Numerical
/// Recipes §6.2; relative accuracy about 1e-15). Never overflows for the
/// `x ≤ 1e300` and `a ≤ 17` used here (it grows like `x^{a−1}`).
pub(crate) fn upper_gamma_scaled(a: f64, x: f64) -> f64 {
    if x < a + 1.0 {
        // γ(a, x) = x^a e^{−x} Σ x^n / (a (a+1) … (a+n)).
        let mut term = 1.0 / a;
        let mut sum = term;
        let mut ap = a;
        for _ in 0..500 {
            ap += 1.0;
            term *= x / ap;
            sum += term;
            if term < sum * 1e-17 {
                break;
            }
        }
        libm::tgamma(a) * x.exp() - x.powf(a) * sum
    } else {
        // Γ(a, x) = e^{−x} x^a / (x + 1 − a − 1(1 − a)/(x + 3 − a − …)).
        let tiny = 1e-300;
        let mut b = x + 1.0 - a;
        let mut c = 1.0 / tiny;
        let mut d = 1.0 / b;
        let mut h = d;
        for i in 1..500 {
            let an = -(i as f64) * (i as f64 - a);
            b += 2.0;
            d = an * d + b;
            if d.abs() < tiny {
                d = tiny;
            }
            c = b + an / c;
            if c.abs() < tiny {
                c = tiny;
            }
            d = 1.0 / d;
            let del = d * c;
            h *= del;
            if (del - 1.0).abs() < 1e-16 {
                break;
            }
        }
        x.powf(a) * h
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scaled_upper_gamma_closed_forms() {
        // e^x Γ(1, x) = 1, e^x Γ(2, x) = 1 + x, e^x Γ(3, x) = x² + 2x + 2,
        // e^x Γ(1/2, x) = √π e^x erfc(√x).
        for &x in &[1e-3, 0.3, 1.0, 2.5, 4.0, 10.0, 60.0, 1e4] {
            let rel = |a: f64, b: f64| (a / b - 1.0).abs();
            assert!(rel(upper_gamma_scaled(1.0, x), 1.0) < 1e-14, "x = {x}");
            assert!(rel(upper_gamma_scaled(2.0, x), 1.0 + x) < 1e-14, "x = {x}");
            assert!(
                rel(upper_gamma_scaled(3.0, x), x * x + 2.0 * x + 2.0) < 1e-14,
                "x = {x}"
            );
            if x < 30.0 {
                let exact = core::f64::consts::PI.sqrt() * x.exp() * libm::erfc(x.sqrt());
                assert!(rel(upper_gamma_scaled(0.5, x), exact) < 1e-13, "x = {x}");
            }
        }
    }
}
