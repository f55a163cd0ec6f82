//! Tanh–sinh (double-exponential) quadrature on a finite interval, for the
//! integrals of the statistics module that have no closed form or fast path
//! (Gaussian height moments of arbitrary order, see
//! [`super::gaussian::tail_moment_quadrature`]).
//!
//! Takahasi & Mori (1974): under the substitution of *Formulas* the
//! integrand decays double-exponentially in `t`, so the trapezoidal rule in `t` converges
//! exponentially even for algebraic endpoint singularities (`t^q` at 0). Each
//! level halves the step and reuses the previous nodes; the difference between
//! two successive levels is the error estimate (a pessimistic one: the error
//! roughly squares from one level to the next).
//!
//! # Formulas
//!
//! $$x = c + w\tanh\Bigl(\frac{\pi}{2}\sinh t\Bigr), \qquad \int_{c-w}^{c+w} f(x)\\,dx \approx h\sum_{k} f(x_k)\\,\frac{w\\,\frac{\pi}{2}\cosh t_k}{\cosh^2\bigl(\frac{\pi}{2}\sinh t_k\bigr)}, \qquad t_k = kh .$$
//!
//! # References
//!
//! * H. Takahasi, M. Mori (1974), "Double exponential formulas for numerical
//!   integration", Publ. RIMS Kyoto Univ. 9, 721–741,
//!   [doi:10.2977/prims/1195192451](https://doi.org/10.2977/prims/1195192451).

use crate::error::{Error, Result};

/// The outcome of an adaptive quadrature, with the accuracy it reached.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Quadrature {
    /// The value of the integral (in the integrand's units times the
    /// variable's).
    pub value: f64,
    /// Estimated absolute error: the change from the previous level.
    pub error_estimate: f64,
    /// Number of integrand evaluations.
    pub evaluations: u32,
    /// Number of step halvings performed (level 0 has step 1 in `t`).
    pub levels: u32,
}

/// Largest `t`: beyond it the node sits within `(b − a)·1e-17` of an endpoint
/// and its weight is below 1e-20.
const T_MAX: f64 = 3.2;
/// Deepest level (step `2^-MAX_LEVEL` in `t`, about 6600 evaluations).
const MAX_LEVEL: u32 = 11;
const FRAC_PI_2: f64 = core::f64::consts::FRAC_PI_2;

/// Sum of the weighted integrand over the nodes `t = k·step` for the `k` of
/// the level (all `k` at level 0, odd `k` afterwards), without the factor
/// `half_width·step`.
fn level_sum(
    f: &impl Fn(f64) -> f64,
    a: f64,
    b: f64,
    half_width: f64,
    step: f64,
    odd_only: bool,
    evaluations: &mut u32,
) -> f64 {
    let mut sum = 0.0;
    let (first, stride) = if odd_only { (1u32, 2u32) } else { (1, 1) };
    let mut k = first;
    loop {
        let t = k as f64 * step;
        if t > T_MAX {
            break;
        }
        let u = FRAC_PI_2 * t.sinh();
        let cosh_u = u.cosh();
        let weight = FRAC_PI_2 * t.cosh() / (cosh_u * cosh_u);
        // Distance of the node from the nearer endpoint, without cancellation:
        // w(1 − tanh u) = 2w/(1 + e^{2u}).
        let delta = 2.0 * half_width / (1.0 + (2.0 * u).exp());
        sum += weight * (f(a + delta) + f(b - delta));
        *evaluations += 2;
        k += stride;
    }
    sum
}

/// ∫_a^b f(x) dx by tanh–sinh quadrature, refined until two successive levels
/// agree within `max(rel_tol·|I|, abs_tol)`. `a < b` finite; `f` finite on
/// the open interval. [`Error::NotConverged`] after [`MAX_LEVEL`] levels.
pub(crate) fn tanh_sinh(
    f: impl Fn(f64) -> f64,
    a: f64,
    b: f64,
    rel_tol: f64,
    abs_tol: f64,
) -> Result<Quadrature> {
    let half_width = 0.5 * (b - a);
    if half_width <= 0.0 {
        return Ok(Quadrature {
            value: 0.0,
            error_estimate: 0.0,
            evaluations: 0,
            levels: 0,
        });
    }
    let centre = 0.5 * (a + b);
    let mut evaluations = 1u32;
    let mut step = 1.0;
    let mut sum =
        FRAC_PI_2 * f(centre) + level_sum(&f, a, b, half_width, step, false, &mut evaluations);
    let mut value = half_width * step * sum;
    let mut error = f64::INFINITY;
    for level in 1..=MAX_LEVEL {
        step *= 0.5;
        sum += level_sum(&f, a, b, half_width, step, true, &mut evaluations);
        let next = half_width * step * sum;
        error = (next - value).abs();
        value = next;
        if !value.is_finite() {
            break;
        }
        if level >= 3 && error <= (rel_tol * value.abs()).max(abs_tol) {
            return Ok(Quadrature {
                value,
                error_estimate: error,
                evaluations,
                levels: level,
            });
        }
    }
    Err(Error::NotConverged {
        what: "tanh-sinh quadrature",
        iterations: MAX_LEVEL,
        residual: if value != 0.0 {
            error / value.abs()
        } else {
            error
        },
    })
}

/// [`tanh_sinh`] for `N` integrands sharing the nodes (one call of `f` per
/// node returns all `N` values), refined until every component has converged
/// within `max(rel_tol·|I_j|, abs_tol)`. Used where several moments of one
/// expensive integrand are wanted together (the Bush–Gibson–Thomas load, area,
/// contact count and stiffness).
pub(crate) fn tanh_sinh_n<const N: usize>(
    f: impl Fn(f64) -> [f64; N],
    a: f64,
    b: f64,
    rel_tol: f64,
    abs_tol: f64,
) -> Result<[f64; N]> {
    let half_width = 0.5 * (b - a);
    if half_width <= 0.0 {
        return Ok([0.0; N]);
    }
    let centre = 0.5 * (a + b);
    let add = |sum: &mut [f64; N], w: f64, v: [f64; N]| {
        for (s, x) in sum.iter_mut().zip(v) {
            *s += w * x;
        }
    };
    // Weighted sum over the nodes k·step of one level (odd k after level 0).
    let level = |sum: &mut [f64; N], step: f64, odd_only: bool| {
        let stride = if odd_only { 2u32 } else { 1 };
        let mut k = 1u32;
        loop {
            let t = k as f64 * step;
            if t > T_MAX {
                break;
            }
            let u = FRAC_PI_2 * t.sinh();
            let cosh_u = u.cosh();
            let weight = FRAC_PI_2 * t.cosh() / (cosh_u * cosh_u);
            let delta = 2.0 * half_width / (1.0 + (2.0 * u).exp());
            add(sum, weight, f(a + delta));
            add(sum, weight, f(b - delta));
            k += stride;
        }
    };
    let mut step = 1.0;
    let mut sum = [0.0; N];
    add(&mut sum, FRAC_PI_2, f(centre));
    level(&mut sum, step, false);
    let mut value = sum.map(|s| half_width * step * s);
    let mut worst = f64::INFINITY;
    for lev in 1..=MAX_LEVEL {
        step *= 0.5;
        level(&mut sum, step, true);
        let next = sum.map(|s| half_width * step * s);
        let mut converged = true;
        worst = 0.0;
        for j in 0..N {
            let error = (next[j] - value[j]).abs();
            let scale = next[j].abs();
            if error > (rel_tol * scale).max(abs_tol) {
                converged = false;
            }
            if scale > 0.0 {
                worst = worst.max(error / scale);
            }
        }
        value = next;
        if value.iter().any(|v| !v.is_finite()) {
            break;
        }
        if lev >= 3 && converged {
            return Ok(value);
        }
    }
    Err(Error::NotConverged {
        what: "tanh-sinh quadrature",
        iterations: MAX_LEVEL,
        residual: worst,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn endpoint_singularity_and_smooth_integrands() {
        // ∫₀¹ x^{1/2} dx = 2/3, ∫₀¹ ln x dx = −1, ∫₀^π sin = 2.
        let q = tanh_sinh(|x: f64| x.sqrt(), 0.0, 1.0, 1e-14, 0.0).unwrap();
        assert!((q.value - 2.0 / 3.0).abs() < 1e-14, "{q:?}");
        let q = tanh_sinh(|x: f64| x.ln(), 0.0, 1.0, 1e-13, 0.0).unwrap();
        assert!((q.value + 1.0).abs() < 1e-13, "{q:?}");
        let q = tanh_sinh(f64::sin, 0.0, core::f64::consts::PI, 1e-14, 0.0).unwrap();
        assert!((q.value - 2.0).abs() < 1e-14, "{q:?}");
    }
}
