//! The dense kernels on the continuation's critical path: the influence
//! product `out = α A q` (column-major `A`, in f64 for residuals and exact
//! tangents, in f32 for the loose GMRES products) and the panel update of
//! the blocked triangular solves in [`super::lu32`].
//!
//! # Why hand-written
//!
//! Every GMRES iteration applies one f32 influence product and one pair of
//! triangular solves of order N + 1, and every Newton residual one f64
//! product; at N = 256 these are all single vectors against a matrix that
//! sits in L2, so the cost is the traffic per matrix element. Here eight
//! columns are combined per pass over the output (`panel`): one load and
//! one store of `out` per eight columns, the eight column streams summed in
//! two accumulators with fused multiply–adds. A column-at-a-time update
//! loads and stores `out` once per column. For these single vectors the
//! panels are faster than faer's `matmul`, in f32 and in f64 (BENCHMARKS.md
//! §3). Machines without AVX2 and FMA, and other architectures, take the
//! plain loops (same results to rounding).

/// Columns combined per pass over the output.
const PANEL: usize = 8;

/// An element type with its AVX2 vector (f32: 8 lanes, f64: 4).
pub(super) trait Elem:
    Copy + Default + core::ops::Mul<Output = Self> + core::ops::SubAssign
{
    /// `y[..m] -= Σ_k x[k] · a[k·lda ..][..m]` over [`PANEL`] columns.
    fn panel(a: &[Self], lda: usize, x: &[Self; PANEL], y: &mut [Self]);
}

/// `y[..m] -= Σ_k x[k] · a[k·lda ..][..m]`, plain loops.
#[inline(always)]
fn panel_plain<T: Elem>(a: &[T], lda: usize, x: &[T; PANEL], y: &mut [T]) {
    for (k, &xk) in x.iter().enumerate() {
        let col = &a[k * lda..k * lda + y.len()];
        for (o, &c) in y.iter_mut().zip(col) {
            *o -= c * xk;
        }
    }
}

macro_rules! avx2_panel {
    ($t:ty, $name:ident, $lanes:expr, $vec:ty, $set1:ident, $load:ident, $store:ident,
     $mul:ident, $fmadd:ident, $add:ident, $sub:ident) => {
        /// The AVX2/FMA panel: two accumulators over the eight columns,
        /// one load and store of `y` per vector.
        ///
        /// # Safety
        /// AVX2 and FMA must be available; `a` must hold
        /// `7·lda + y.len()` elements (checked).
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx2,fma")]
        unsafe fn $name(a: &[$t], lda: usize, x: &[$t; PANEL], y: &mut [$t]) {
            use core::arch::x86_64::*;
            let m = y.len();
            assert!(m == 0 || a.len() >= (PANEL - 1) * lda + m);
            let b: [$vec; PANEL] = core::array::from_fn(|k| $set1(x[k]));
            let p = a.as_ptr();
            let yp = y.as_mut_ptr();
            let mut i = 0;
            while i + $lanes <= m {
                // SAFETY: i + lanes ≤ m, and column k spans
                // a[k·lda .. k·lda + m] (asserted above).
                unsafe {
                    let mut s0 = $mul($load(p.add(i)), b[0]);
                    let mut s1 = $mul($load(p.add(lda + i)), b[1]);
                    s0 = $fmadd($load(p.add(2 * lda + i)), b[2], s0);
                    s1 = $fmadd($load(p.add(3 * lda + i)), b[3], s1);
                    s0 = $fmadd($load(p.add(4 * lda + i)), b[4], s0);
                    s1 = $fmadd($load(p.add(5 * lda + i)), b[5], s1);
                    s0 = $fmadd($load(p.add(6 * lda + i)), b[6], s0);
                    s1 = $fmadd($load(p.add(7 * lda + i)), b[7], s1);
                    $store(yp.add(i), $sub($load(yp.add(i)), $add(s0, s1)));
                }
                i += $lanes;
            }
            for r in i..m {
                let mut s: $t = 0.0;
                for k in 0..PANEL {
                    s += a[k * lda + r] * x[k];
                }
                y[r] -= s;
            }
        }

        impl Elem for $t {
            #[inline(always)]
            fn panel(a: &[$t], lda: usize, x: &[$t; PANEL], y: &mut [$t]) {
                crate::simd::dispatch!(
                    // SAFETY: AVX2 and FMA are present (checked by the
                    // dispatch).
                    avx2_fma => unsafe { $name(a, lda, x, y) },
                    portable => panel_plain(a, lda, x, y),
                )
            }
        }
    };
}

avx2_panel!(
    f32,
    panel_f32_avx2,
    8,
    __m256,
    _mm256_set1_ps,
    _mm256_loadu_ps,
    _mm256_storeu_ps,
    _mm256_mul_ps,
    _mm256_fmadd_ps,
    _mm256_add_ps,
    _mm256_sub_ps
);
avx2_panel!(
    f64,
    panel_f64_avx2,
    4,
    __m256d,
    _mm256_set1_pd,
    _mm256_loadu_pd,
    _mm256_storeu_pd,
    _mm256_mul_pd,
    _mm256_fmadd_pd,
    _mm256_add_pd,
    _mm256_sub_pd
);

/// `y[..m] -= Σ_{k<cols} x[k] · a[k·lda ..][..m]` for any number of
/// columns: whole panels, then the remaining columns one by one.
#[inline(always)]
pub(super) fn update<T: Elem>(a: &[T], lda: usize, x: &[T], y: &mut [T]) {
    let m = y.len();
    let mut k = 0;
    while k + PANEL <= x.len() {
        let xs: [T; PANEL] = core::array::from_fn(|l| x[k + l]);
        T::panel(&a[k * lda..], lda, &xs, y);
        k += PANEL;
    }
    for (l, &xk) in x.iter().enumerate().skip(k) {
        for (o, &c) in y.iter_mut().zip(&a[l * lda..l * lda + m]) {
            *o -= c * xk;
        }
    }
}

/// `out = α A q` with `A` column-major `n × n` (`n = q.len() = out.len()`).
pub(super) fn matvec<T: Elem + core::ops::Neg<Output = T>>(
    a: &[T],
    q: &[T],
    alpha: T,
    out: &mut [T],
) {
    let n = q.len();
    debug_assert!(a.len() == n * n && out.len() == n);
    out.iter_mut().for_each(|v| *v = T::default());
    // out −= Σ_j (−α q_j) A_{:,j}; the scaling is applied to the n entries
    // of q, not to the n² of A.
    let mut k = 0;
    let mut xs = [T::default(); PANEL];
    while k < n {
        let len = PANEL.min(n - k);
        for l in 0..len {
            xs[l] = -(alpha * q[k + l]);
        }
        update(&a[k * n..], n, &xs[..len], out);
        k += len;
    }
}

#[cfg(test)]
mod tests {
    use super::{matvec, panel_plain, Elem, PANEL};

    /// The dispatched panel (AVX2/FMA where available) equals the plain
    /// loops that machines without them run, for every remainder of the
    /// vector width.
    #[test]
    fn panel_matches_the_plain_loops() {
        /// The dispatched and the plain panel from `y0`, equal within
        /// `tol` relative.
        fn agree<T: Elem + Into<f64>>(a: &[T], lda: usize, x: &[T; PANEL], y0: &[T], tol: f64) {
            let (mut fast, mut plain) = (y0.to_vec(), y0.to_vec());
            T::panel(a, lda, x, &mut fast);
            panel_plain(a, lda, x, &mut plain);
            for (&f, &p) in fast.iter().zip(&plain) {
                let (f, p): (f64, f64) = (f.into(), p.into());
                assert!(
                    (f - p).abs() <= tol * (1.0 + p.abs()),
                    "m = {}: {f} vs {p}",
                    y0.len()
                );
            }
        }
        let lda = 41;
        let a: Vec<f64> = (0..PANEL * lda)
            .map(|i| ((i * 29 % 83) as f64 - 41.0) / 13.0)
            .collect();
        let x: [f64; PANEL] = core::array::from_fn(|k| (k as f64 - 3.5) / 3.0);
        let a32: Vec<f32> = a.iter().map(|&v| v as f32).collect();
        let x32: [f32; PANEL] = core::array::from_fn(|k| x[k] as f32);
        for m in 0..=lda {
            let y0: Vec<f64> = (0..m).map(|i| (i as f64 * 0.3).sin()).collect();
            agree(&a, lda, &x, &y0, 1e-14);
            let y32: Vec<f32> = y0.iter().map(|&v| v as f32).collect();
            agree(&a32, lda, &x32, &y32, 1e-5);
        }
    }

    /// The products equal a plain column loop to rounding, at orders
    /// around the vector widths and the continuation's.
    #[test]
    fn matvec_matches_the_plain_loop() {
        for n in [1usize, 3, 4, 7, 8, 9, 15, 16, 17, 33, 256, 257] {
            let a: Vec<f64> = (0..n * n)
                .map(|i| ((i * 37 % 101) as f64 - 50.0) / 17.0)
                .collect();
            let q: Vec<f64> = (0..n)
                .map(|i| ((i * 13 % 29) as f64 - 14.0) / 7.0)
                .collect();
            let mut want = vec![0.0f64; n];
            for j in 0..n {
                for i in 0..n {
                    want[i] += 1.5 * a[j * n + i] * q[j];
                }
            }
            let scale = want.iter().fold(1.0f64, |m, v| m.max(v.abs()));
            let mut got = vec![f64::NAN; n];
            matvec(&a, &q, 1.5, &mut got);
            for (g, w) in got.iter().zip(&want) {
                assert!(
                    (g - w).abs() <= 1e-14 * scale * n as f64,
                    "n = {n}: {g} vs {w}"
                );
            }
            let a32: Vec<f32> = a.iter().map(|&v| v as f32).collect();
            let q32: Vec<f32> = q.iter().map(|&v| v as f32).collect();
            let mut got32 = vec![f32::NAN; n];
            matvec(&a32, &q32, 1.5, &mut got32);
            for (g, w) in got32.iter().zip(&want) {
                assert!(
                    (f64::from(*g) - w).abs() <= 1e-6 * scale * n as f64,
                    "n = {n}: {g} vs {w}"
                );
            }
        }
    }
}
