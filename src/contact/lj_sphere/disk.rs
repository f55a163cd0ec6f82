//! The uniformly loaded disk: displacement `D(r, c)` and the influence
//! matrix of piecewise-constant pressure on annular cells, through the
//! arithmetic–geometric mean.
//!
//! # Formulas
//!
//! A uniform unit pressure on the disk of radius `c` displaces the surface
//! at radius `r` by (Johnson 1985, §3.4; REFERENCE §6; `k` the modulus,
//! `m = k²`)
//!
//! ```text
//! D(r, c) = c E(k),                   k = r/c ≤ 1,
//! D(r, c) = r [E(k) − (1 − k²) K(k)], k = c/r ≤ 1.
//! ```
//!
//! With the AGM sequences `a₀ = 1`, `b₀ = k' = √((1 − k)(1 + k))`, `c₀ = k`,
//! `a_{n+1} = (a_n + b_n)/2`, `b_{n+1} = √(a_n b_n)`,
//! `c_{n+1} = (a_n − b_n)/2` and `S = Σ_{n≥1} 2^{n−1} c_n²` (DLMF §19.8(i);
//! Abramowitz & Stegun 17.6):
//!
//! ```text
//! K = π/(2 a_∞),   E = K (1 − k²/2 − S),   E − (1 − k²) K = K (k²/2 − S).
//! ```
//!
//! The last form is why the library evaluates `D` itself rather than
//! through separate `K` and `E`: outside the disk `E − (1 − k²)K ≈ πk²/4`
//! is a difference of two numbers of order 1, which loses `ε/k²` relative
//! (3e-8 at `r = 8900 c`, measured against 40-digit values), while `k²/2 − S`
//! subtracts terms of order `k²` and `k⁴` (`c₁ = (1 − k')/2` carries an
//! absolute error `ε`, which is `ε k²/8` in `c₁²`). Near the rim `k'` is formed from
//! `(1 − k)(1 + k)`, so its absolute error stays at `ε` (the displacement
//! depends on `k'²` with a weight `ln(1/k')`). The iteration stops when
//! `c_n ≤ 10⁻⁹ a_n`: the next term would be below `10⁻¹⁸`; any double
//! `k < 1` (so `k' ≥ 1.5·10⁻⁸`) needs at most 9 iterations.
//!
//! The matrix evaluates each column (one cell edge `c`) over all nodes in
//! blocks of [`LANES`] nodes, the same number of AGM iterations per block,
//! so that the compiler vectorises the block (AVX2 with FMA when the CPU
//! has them, detected at run time). The iteration takes `c_{n+1}` as the
//! difference `(a_n − b_n)/2`, with no division: `c_n²/(4a_{n+1})` is no
//! more accurate and adds a division per step. This is faster than the
//! `ellip` crate's scalar `K` and `E` (BENCHMARKS.md §3), and the largest
//! relative error of `D` over `r/c ∈ [10⁻⁴, 10⁴]` and within `10⁻¹²` of the
//! rim is 2.4e-15 against their 3.3e-8 (`tests::matches_forty_digit_values`
//! pins values).
//!
//! # References
//!
//! * NIST DLMF §19.8(i), "Arithmetic–geometric mean",
//!   <https://dlmf.nist.gov/19.8>.
//! * M. Abramowitz, I. A. Stegun (1964), *Handbook of Mathematical
//!   Functions*, §17.6 (the AGM scale).
//! * K. L. Johnson (1985), *Contact Mechanics*, §3.4 (the loaded disk).

use core::f64::consts::PI;

/// Nodes per vectorised block of a matrix column.
const LANES: usize = 16;

/// AGM iterations at most (9 suffice for any double modulus below 1).
const AGM_MAX: usize = 16;

/// `(K(k), S)` for `L` moduli `k ∈ [0, 1)` at once (module docs).
#[inline(always)]
fn agm<const L: usize>(k: &[f64; L]) -> ([f64; L], [f64; L]) {
    let mut a = [1.0f64; L];
    let mut b = [0.0f64; L];
    let mut s = [0.0f64; L];
    for l in 0..L {
        b[l] = ((1.0 - k[l]) * (1.0 + k[l])).sqrt();
    }
    let mut w = 1.0f64;
    for _ in 0..AGM_MAX {
        let mut done = true;
        for l in 0..L {
            let an = 0.5 * (a[l] + b[l]);
            let cn = 0.5 * (a[l] - b[l]);
            b[l] = (a[l] * b[l]).sqrt();
            a[l] = an;
            s[l] += w * cn * cn;
            done &= cn <= 1e-9 * an;
        }
        w *= 2.0;
        if done {
            break;
        }
    }
    let mut kk = [0.0f64; L];
    for l in 0..L {
        kk[l] = 0.5 * PI / a[l];
    }
    (kk, s)
}

/// `D` inside the disk from the modulus `k = r/c < 1` and its `(K, S)`.
#[inline(always)]
fn inside(c: f64, k: f64, kk: f64, s: f64) -> f64 {
    c * kk * (1.0 - 0.5 * k * k - s)
}

/// `D` outside the disk from the modulus `k = c/r < 1` and its `(K, S)`.
#[inline(always)]
fn outside(r: f64, k: f64, kk: f64, s: f64) -> f64 {
    r * kk * (0.5 * k * k - s)
}

/// `D(r, c) = ∫₀^c s/(r+s) K(2√(rs)/(r+s)) ds`: the (scaled) surface
/// displacement at radius `r` of a uniform unit pressure on the disk of
/// radius `c`, `c E(r/c)` inside, `r[E(c/r) − (1 − c²/r²)K(c/r)]` outside,
/// `c` on the rim (module docs; REFERENCE §6). `r, c ≥ 0`.
pub fn disk_displacement(r: f64, c: f64) -> f64 {
    if c <= 0.0 {
        return 0.0;
    }
    if r == c {
        return c;
    }
    if r < c {
        let k = r / c;
        let (kk, s) = agm(&[k]);
        inside(c, k, kk[0], s[0])
    } else {
        let k = c / r;
        let (kk, s) = agm(&[k]);
        outside(r, k, kk[0], s[0])
    }
}

/// `D(x_i, c)` for all nodes `x` (increasing, positive) into `out`.
#[inline(always)]
fn disk_column(x: &[f64], c: f64, out: &mut [f64]) {
    let split = x.partition_point(|&v| v < c);
    let ic = 1.0 / c;
    // Inside the disk: k = x/c, D = c K (1 − k²/2 − S) (c itself should
    // x·(1/c) round up to 1 for a node within an ulp of the edge).
    for (xs, os) in x[..split].chunks(LANES).zip(out[..split].chunks_mut(LANES)) {
        let mut k = [0.0f64; LANES];
        for (kl, &xl) in k.iter_mut().zip(xs) {
            *kl = xl * ic;
        }
        let (kk, s) = agm(&k);
        for l in 0..os.len() {
            os[l] = if k[l] < 1.0 {
                inside(c, k[l], kk[l], s[l])
            } else {
                c
            };
        }
    }
    // Outside (and on the rim, k = 1 exactly: D = c): k = c/x,
    // D = x K (k²/2 − S).
    for (xs, os) in x[split..].chunks(LANES).zip(out[split..].chunks_mut(LANES)) {
        let mut k = [0.0f64; LANES];
        for (kl, &xl) in k.iter_mut().zip(xs) {
            *kl = c / xl;
        }
        let (kk, s) = agm(&k);
        for l in 0..os.len() {
            os[l] = if k[l] < 1.0 {
                outside(xs[l], k[l], kk[l], s[l])
            } else {
                c
            };
        }
    }
}

/// The influence matrix of piecewise-constant pressure on the cells
/// `[c_j, c_{j+1}]` at the nodes `x_i`, column-major `n×n` (`n = x.len()`,
/// `c.len() = n + 1`, `c_0 = 0`): `A_ij = D(x_i, c_{j+1}) − D(x_i, c_j)`.
pub(super) fn influence_matrix(x: &[f64], c: &[f64]) -> Vec<f64> {
    crate::simd::dispatch!(
        // SAFETY: AVX2 and FMA are present (checked by the dispatch).
        avx2_fma => unsafe { influence_matrix_avx2(x, c) },
        portable => influence_matrix_generic(x, c),
    )
}

/// [`influence_matrix_generic`] compiled for AVX2+FMA (see `crate::simd`).
///
/// # Safety
/// AVX2 and FMA must be available.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn influence_matrix_avx2(x: &[f64], c: &[f64]) -> Vec<f64> {
    influence_matrix_generic(x, c)
}

#[inline(always)]
fn influence_matrix_generic(x: &[f64], c: &[f64]) -> Vec<f64> {
    let n = x.len();
    debug_assert_eq!(c.len(), n + 1);
    let mut a = vec![0.0; n * n];
    let mut prev = vec![0.0; n];
    let mut d = vec![0.0; n];
    for j in 0..n {
        disk_column(x, c[j + 1], &mut d);
        let col = &mut a[j * n..(j + 1) * n];
        for i in 0..n {
            col[i] = d[i] - prev[i];
        }
        core::mem::swap(&mut prev, &mut d);
    }
    a
}

#[cfg(test)]
mod tests {
    use super::{disk_column, disk_displacement, influence_matrix};

    /// `D(r, 1)` against values computed with mpmath at 40 digits for the
    /// double nearest each `r` (`r E(1/r²) − r(1 − 1/r²)K(1/r²)` outside,
    /// `E(r²)` inside, in mpmath's parameter convention).
    #[test]
    // The digits beyond a double are kept as computed.
    #[allow(clippy::excessive_precision)]
    fn matches_forty_digit_values() {
        let cases = [
            (0.5, 1.467_462_209_339_427_155),
            (0.999_999, 1.000_007_447_477_724_392),
            (1.1, 0.833_044_733_630_375_659_3),
            (2.0, 0.406_298_886_459_960_246_6),
            (10.0, 0.078_638_361_194_858_980_78),
            (1000.0, 0.000_785_398_261_572_255_549_9),
        ];
        for (r, v) in cases {
            let d = disk_displacement(r, 1.0);
            assert!(
                ((d - v) / v).abs() < 5e-15,
                "D({r}, 1) = {d:e}, 40 digits give {v:e}"
            );
        }
    }

    /// The vectorised columns agree with the scalar function to rounding
    /// (they multiply by `1/c` and iterate per block), including the rim
    /// and block tails.
    #[test]
    fn matrix_columns_equal_the_scalar_displacement() {
        let n = 37;
        let c: Vec<f64> = (0..=n)
            .map(|j| (j as f64 / n as f64).powf(1.3) * 3.0)
            .collect();
        let x: Vec<f64> = (0..n).map(|j| 0.5 * (c[j] + c[j + 1])).collect();
        let a = influence_matrix(&x, &c);
        for j in 0..n {
            for i in 0..n {
                let d1 = disk_displacement(x[i], c[j + 1]);
                let want = d1 - disk_displacement(x[i], c[j]);
                assert!(
                    (a[j * n + i] - want).abs() <= 1e-14 * d1,
                    "entry ({i}, {j}): {} against {want}",
                    a[j * n + i]
                );
            }
        }
        // On the rim and within an ulp of it on either side: D = c. For
        // this c, the node an ulp below has x·(1/c) = 1 exactly.
        let c = 29.049_183_297_589_51f64;
        let below = f64::from_bits(c.to_bits() - 1);
        assert_eq!(below * (1.0 / c), 1.0);
        let above = f64::from_bits(c.to_bits() + 1);
        let mut out = [0.0; 5];
        disk_column(&[0.5, below, c, above, 2.0 * c], c, &mut out);
        for (i, &v) in out[1..4].iter().enumerate() {
            assert!((v / c - 1.0).abs() < 1e-14, "node {}: D = {v}", i + 1);
        }
    }
}
