//! Overlap thresholds: the overlap (m) where the reduced approach crosses a
//! bound, found by bisection over the ordered bit patterns of the doubles,
//! so that branches and segments are chosen on δ without a division.

/// The overlap threshold (m) equivalent to a reduced-approach bound `x`:
/// with the reduced approach `Δ(δ) = (δ − origin)/scale` rounded as f64
/// arithmetic rounds it, the smallest δ with `Δ(δ) ≥ x` (`at_least`) or the
/// largest δ with `Δ(δ) ≤ x`. Rounding keeps `Δ(δ)` monotone in δ, so `δ ≥ threshold` is
/// exactly `Δ(δ) ≥ x` (and `δ ≤ threshold` exactly `Δ(δ) ≤ x`) for every
/// finite δ: bisection over the ordered bit patterns of the finite doubles.
pub(super) fn overlap_threshold(origin: f64, scale: f64, x: f64, at_least: bool) -> f64 {
    if x.is_infinite() {
        return x;
    }
    // Order-preserving map of the doubles onto the integers and back.
    let key = |v: f64| {
        let b = v.to_bits() as i64;
        if b < 0 {
            i64::MIN - b
        } else {
            b
        }
    };
    let value = |k: i64| f64::from_bits(if k < 0 { i64::MIN - k } else { k } as u64);
    // Inside the bound is false then true along δ (at_least) or true then
    // false; `past(k)` is false then true along the keys either way.
    let past = |k: i64| {
        let r = (value(k) - origin) / scale;
        if at_least {
            r >= x
        } else {
            r > x
        }
    };
    // The keys span more than i64: sums and differences in i128.
    let (mut lo, mut hi) = (key(-f64::MAX), key(f64::MAX));
    if past(lo) {
        return f64::NEG_INFINITY;
    }
    if !past(hi) {
        return f64::INFINITY;
    }
    while (hi as i128) - (lo as i128) > 1 {
        let mid = ((lo as i128 + hi as i128) >> 1) as i64;
        if past(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    // The first δ inside (at_least), or the last one inside.
    value(if at_least { hi } else { lo })
}

/// The next double above a finite `v` (`f64::next_up`, stable only since
/// Rust 1.86).
pub(super) fn next_up(v: f64) -> f64 {
    if v.is_nan() || v == f64::INFINITY {
        return v;
    }
    if v == 0.0 {
        return f64::from_bits(1);
    }
    let b = v.to_bits();
    f64::from_bits(if v > 0.0 { b + 1 } else { b - 1 })
}
