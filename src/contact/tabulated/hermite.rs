//! Cubic Hermite arithmetic: Horner evaluation, the coefficients of an
//! interval, and the Fritsch–Carlson monotonicity test and limiter (see the
//! module documentation's formulas).

#[inline]
pub(super) fn horner(c: &[f64; 4], t: f64) -> f64 {
    c[0] + t * (c[1] + t * (c[2] + t * c[3]))
}

#[inline]
pub(super) fn horner_d(c: &[f64; 4], t: f64) -> f64 {
    c[1] + t * (2.0 * c[2] + t * (3.0 * c[3]))
}

/// Force and radius coefficients side by side.
pub(super) fn pair(f: [f64; 4], a: [f64; 4]) -> [[f64; 2]; 4] {
    [[f[0], a[0]], [f[1], a[1]], [f[2], a[2]], [f[3], a[3]]]
}

pub(super) fn coefficients(y0: f64, m0: f64, y1: f64, m1: f64, h: f64) -> [f64; 4] {
    let d = y1 - y0;
    let (p0, p1) = (h * m0, h * m1);
    [y0, p0, 3.0 * d - 2.0 * p0 - p1, p0 + p1 - 2.0 * d]
}

/// Fritsch–Carlson: whether the Hermite cubic through (y0, m0), (y1, m1)
/// over length h is monotone.
pub(super) fn monotone(y0: f64, m0: f64, y1: f64, m1: f64, h: f64) -> bool {
    let s = (y1 - y0) / h;
    if s == 0.0 {
        return m0 == 0.0 && m1 == 0.0;
    }
    let (al, be) = (m0 / s, m1 / s);
    al >= 0.0 && be >= 0.0 && al * al + be * be <= 9.0 * (1.0 + 1e-12)
}

/// Make the slopes of one interval monotone (Fritsch–Carlson limiter).
pub(super) fn limit(y0: f64, m0: &mut f64, y1: f64, m1: &mut f64, h: f64) {
    let s = (y1 - y0) / h;
    if s == 0.0 {
        *m0 = 0.0;
        *m1 = 0.0;
        return;
    }
    if *m0 / s < 0.0 {
        *m0 = 0.0;
    }
    if *m1 / s < 0.0 {
        *m1 = 0.0;
    }
    let (al, be) = (*m0 / s, *m1 / s);
    let r = al * al + be * be;
    if r > 9.0 {
        let tau = 3.0 / r.sqrt();
        *m0 = tau * al * s;
        *m1 = tau * be * s;
    }
}

/// Whether the Hermite cubic is monotone, or the data are flat/decreasing
/// radii where no monotonicity is promised (then always true).
pub(super) fn monotone_or_flat(y0: f64, m0: f64, y1: f64, m1: f64, h: f64) -> bool {
    if y1 < y0 || (y1 == y0 && m0 == 0.0 && m1 == 0.0) {
        true
    } else {
        monotone(y0, m0, y1, m1, h)
    }
}
