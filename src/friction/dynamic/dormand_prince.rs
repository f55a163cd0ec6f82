//! The embedded Runge–Kutta pair of Dormand and Prince (1980), order 5(4),
//! shared by the integrated dynamic models ([`super::PrandtlTomlinson`],
//! one and two springs, and [`super::BurridgeKnopoff`]): one trial step with
//! its error estimate, the step-size rule, the continuous extension (dense
//! output) for locating events inside a step, and a plain error-controlled
//! integration over an increment.
//!
//! Generic over the state dimension `N` (a fixed-size array: nothing is
//! allocated); a system may use only its first `n ≤ N` components (the
//! Burridge–Knopoff chain runs in the next larger size class).
//!
//! # Formulas
//!
//! With stages k_s = f(t + c_s h, y + h Σ_j a_sj k_j), s = 1..7, the
//! fifth-order solution is y₁ = y + h Σ b_s k_s (b = the last row of a, so
//! k₇ = f(t + h, y₁) is the first stage of the next step, "first same as
//! last"), the error estimate is h Σ e_s k_s (the difference from the
//! embedded fourth-order solution), and a step is accepted when
//! max_c |err_c| / (tol · (scale_c + max(|y_c|, |y₁_c|))) ≤ 1; the next
//! step is h · clamp(0.9 err^{−1/5}, 0.2, 5).
//!
//! The continuous extension of order 4 (Shampine 1986, in the form of
//! Hairer, Nørsett and Wanner's DOPRI5) is, for θ ∈ [0, 1],
//!
//! y(t + θh) = y + θ(r₂ + (1 − θ)(r₃ + θ(r₄ + (1 − θ) r₅))),
//! r₂ = y₁ − y, r₃ = h k₁ − r₂, r₄ = r₂ − h k₇ − r₃, r₅ = h Σ d_s k_s;
//!
//! it equals y at θ = 0 and y₁ at θ = 1.
//!
//! # References
//!
//! * J. R. Dormand, P. J. Prince, "A family of embedded Runge–Kutta
//!   formulae", J. Comput. Appl. Math. 6 (1980) 19–26.
//! * L. F. Shampine, "Some practical Runge–Kutta formulas", Math. Comp. 46
//!   (1986) 135–150.
//! * E. Hairer, S. P. Nørsett, G. Wanner, *Solving Ordinary Differential
//!   Equations I*, 2nd ed., Springer (1993), II.5 and II.6.

/// Nodes c_s.
const C: [f64; 7] = [0.0, 0.2, 0.3, 0.8, 8.0 / 9.0, 1.0, 1.0];
/// Coefficients a_sj (row 6 is b, the fifth-order weights).
const A: [[f64; 6]; 7] = [
    [0.0; 6],
    [0.2, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
        0.0,
        0.0,
    ],
    [
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
        0.0,
    ],
    [
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];
/// Error weights e_s (fifth less fourth order).
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];
/// Dense-output weights d_s.
const D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

/// A system y' = f(t, y) of (at most) `N` components.
pub(crate) trait System<const N: usize> {
    /// Writes f(t, y) into `dy` (its first `n` components, the rest 0).
    fn rate(&self, t: f64, y: &[f64; N], dy: &mut [f64; N]);
}

/// The stages of the last trial step (for the next step and the dense
/// output).
pub(crate) struct Stages<const N: usize> {
    /// k₁..k₇; k₁ = f(t, y) must be set before [`Stages::attempt`].
    pub k: [[f64; N]; 7],
}

impl<const N: usize> Stages<N> {
    /// Zero stages.
    #[inline]
    pub fn new() -> Self {
        Self { k: [[0.0; N]; 7] }
    }

    /// A trial step of length `h` from `(t, y)` over the first `n`
    /// components, with `k[0] = f(t, y)` already in place: the fifth-order
    /// solution into `out` (its other components left as they are), the
    /// stages (`k[6]` = f(t + h, out)), and the scaled error norm (≤ 1:
    /// accept) with the absolute scales `scale` and relative tolerance
    /// `tol`.
    #[allow(clippy::too_many_arguments)]
    #[inline]
    pub fn attempt<S: System<N>>(
        &mut self,
        system: &S,
        t: f64,
        y: &[f64; N],
        h: f64,
        n: usize,
        tol: f64,
        scale: &[f64; N],
        out: &mut [f64; N],
    ) -> f64 {
        for s in 1..7 {
            out[..n].copy_from_slice(&y[..n]);
            for (a, kj) in A[s].iter().zip(&self.k).take(s) {
                let w = h * a;
                if w != 0.0 {
                    for (o, k) in out.iter_mut().zip(kj).take(n) {
                        *o += w * k;
                    }
                }
            }
            system.rate(t + C[s] * h, out, &mut self.k[s]);
        }
        // `out` holds the stage-7 argument: y + h Σ b_j k_j, the solution.
        let mut err = 0.0f64;
        for c in 0..n {
            let mut e = 0.0;
            for (w, k) in E.iter().zip(&self.k) {
                e += w * k[c];
            }
            let sc = tol * (scale[c] + y[c].abs().max(out[c].abs()));
            err = err.max((h * e / sc).abs());
        }
        err
    }

    /// Component `c` of the continuous extension of the last accepted trial
    /// step (from `y` to `out` over `h`) at θ ∈ [0, 1].
    #[inline]
    pub fn dense(&self, y: &[f64; N], out: &[f64; N], h: f64, theta: f64, c: usize) -> f64 {
        let r2 = out[c] - y[c];
        let r3 = h * self.k[0][c] - r2;
        let r4 = r2 - h * self.k[6][c] - r3;
        let mut r5 = 0.0;
        for (w, k) in D.iter().zip(&self.k) {
            r5 += w * k[c];
        }
        let r5 = h * r5;
        let u = 1.0 - theta;
        y[c] + theta * (r2 + u * (r3 + theta * (r4 + u * r5)))
    }
}

/// The step-size factor after a trial step of error norm `err`.
#[inline]
pub(crate) fn factor(err: f64) -> f64 {
    if err == 0.0 {
        5.0
    } else {
        (0.9 * err.powf(-0.2)).clamp(0.2, 5.0)
    }
}

/// Integrates `y` over `[0, dt]` (the first `n` components) from the first
/// step `h0`, with relative tolerance `tol` and absolute scales `scale`,
/// in at most `budget` trial steps; `None` when the budget runs out (`y`
/// is then partly advanced).
#[allow(clippy::too_many_arguments)]
pub(crate) fn integrate<const N: usize, S: System<N>>(
    system: &S,
    y: &mut [f64; N],
    n: usize,
    dt: f64,
    h0: f64,
    tol: f64,
    scale: &[f64; N],
    budget: u32,
) -> Option<()> {
    if dt == 0.0 {
        return Some(());
    }
    let mut stages = Stages::<N>::new();
    let mut next = *y;
    let mut t = 0.0;
    let mut h = h0.min(dt);
    system.rate(t, y, &mut stages.k[0]);
    for _ in 0..budget {
        if t >= dt {
            return Some(());
        }
        h = h.min(dt - t);
        let err = stages.attempt(system, t, y, h, n, tol, scale, &mut next);
        if err <= 1.0 {
            t += h;
            *y = next;
            stages.k[0] = stages.k[6];
        }
        h *= factor(err);
    }
    (t >= dt).then_some(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// y'' = −y as (y, y'), from (0, 1): sin and cos.
    struct Oscillator;
    impl System<2> for Oscillator {
        fn rate(&self, _t: f64, y: &[f64; 2], dy: &mut [f64; 2]) {
            *dy = [y[1], -y[0]];
        }
    }

    #[test]
    fn integrates_to_the_tolerance() {
        for tol in [1e-6, 1e-9, 1e-12] {
            let mut y = [0.0, 1.0];
            integrate(&Oscillator, &mut y, 2, 10.0, 0.1, tol, &[1.0; 2], 100_000).unwrap();
            let e = (y[0] - 10f64.sin()).abs().max((y[1] - 10f64.cos()).abs());
            assert!(e < 100.0 * tol, "tol {tol}: error {e}");
        }
        // The budget is honoured.
        let mut y = [0.0, 1.0];
        assert!(integrate(&Oscillator, &mut y, 2, 1e3, 0.1, 1e-12, &[1.0; 2], 10).is_none());
    }

    #[test]
    fn dense_output_is_fourth_order_and_hits_the_ends() {
        // The interpolation error inside one step falls as h^5.
        let mut errors = vec![];
        for h in [0.4, 0.2, 0.1] {
            let y = [0.0, 1.0];
            let mut st = Stages::<2>::new();
            Oscillator.rate(0.0, &y, &mut st.k[0]);
            let mut out = [0.0; 2];
            st.attempt(&Oscillator, 0.0, &y, h, 2, 1e-9, &[1.0; 2], &mut out);
            assert_eq!(st.dense(&y, &out, h, 0.0, 0), y[0]);
            assert!((st.dense(&y, &out, h, 1.0, 1) - out[1]).abs() < 1e-15);
            let e = (0..=10)
                .map(|i| {
                    let th = i as f64 / 10.0;
                    (st.dense(&y, &out, h, th, 0) - (th * h).sin()).abs()
                })
                .fold(0.0, f64::max);
            errors.push(e);
        }
        for w in errors.windows(2) {
            let order = (w[0] / w[1]).log2();
            assert!(order > 4.5, "{errors:?}");
        }
    }
}
