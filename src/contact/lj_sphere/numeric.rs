//! Small numerical helpers of the solver: dot product, Euclidean norm,
//! 3-point stencil, cubic Hermite and 3-point parabola derivative.

pub(super) fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

pub(super) fn norm2(a: &[f64]) -> f64 {
    a.iter().map(|x| x * x).sum::<f64>().sqrt()
}

/// The 3-point stencil around sample `i` of `n ≥ 3` (one-sided at the ends).
pub(super) fn stencil3(i: usize, n: usize) -> (usize, usize, usize) {
    if i == 0 {
        (0, 1, 2)
    } else if i + 1 == n {
        (n - 3, n - 2, n - 1)
    } else {
        (i - 1, i, i + 1)
    }
}

/// Cubic Hermite on [0, 1] with end values `y0`, `y1` and end slopes (per
/// unit t) `m0`, `m1`.
pub(super) fn hermite01(y0: f64, m0: f64, y1: f64, m1: f64, t: f64) -> f64 {
    let t2 = t * t;
    let t3 = t2 * t;
    (2.0 * t3 - 3.0 * t2 + 1.0) * y0
        + (t3 - 2.0 * t2 + t) * m0
        + (-2.0 * t3 + 3.0 * t2) * y1
        + (t3 - t2) * m1
}

/// Derivative at `x` of the parabola through three points.
pub(super) fn deriv3(xs: [f64; 3], ys: [f64; 3], x: f64) -> f64 {
    let [x0, x1, x2] = xs;
    let [y0, y1, y2] = ys;
    y0 * ((x - x1) + (x - x2)) / ((x0 - x1) * (x0 - x2))
        + y1 * ((x - x0) + (x - x2)) / ((x1 - x0) * (x1 - x2))
        + y2 * ((x - x0) + (x - x1)) / ((x2 - x0) * (x2 - x1))
}
