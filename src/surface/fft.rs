//! FFT plumbing on top of `rustfft`: fast transform lengths, a real-input
//! forward transform (half-length complex FFT with the usual split), and 2-D
//! complex transforms. Private to `surface`.
//!
//! Plans: planning a 5·10⁵-point transform costs about as much as running it,
//! so the plans of the last [`PLAN_CACHE`] lengths are kept per thread
//! (bounded memory: a plan holds its twiddle table, 16 bytes per point).
//!
//! # Formulas
//!
//! The real-input forward transform computes, for $n$ even,
//!
//! $$X_k = \sum_{j=0}^{n-1} x_j e^{-2\pi ijk/n}$$
//!
//! from one complex FFT of length $n/2$ of $y_j = x_{2j} + i\\,x_{2j+1}$, with
//! $X_k = \tfrac12\bigl(Y_k + \overline{Y_{n/2-k}}\bigr) - \tfrac{i}{2}e^{-2\pi ik/n}\bigl(Y_k - \overline{Y_{n/2-k}}\bigr)$.
//!
//! # References
//!
//! * The `rustfft` crate (mixed-radix and Bluestein algorithms).
//! * W. H. Press, S. A. Teukolsky, W. T. Vetterling, B. P. Flannery (2007),
//!   *Numerical Recipes*, 3rd ed., Cambridge University Press, §12.3 (FFT of
//!   real data by a half-length complex transform).

use rustfft::num_complex::Complex64;
use rustfft::{Fft, FftPlanner};
use std::cell::RefCell;
use std::sync::Arc;

/// Number of (length, direction) plans cached per thread.
const PLAN_CACHE: usize = 4;

type PlanEntry = (usize, bool, Arc<dyn Fft<f64>>);

thread_local! {
    static PLANS: RefCell<Vec<PlanEntry>> = const { RefCell::new(Vec::new()) };
}

/// A forward or inverse plan of `len`, from the per-thread cache.
pub(crate) fn plan(len: usize, inverse: bool) -> Arc<dyn Fft<f64>> {
    PLANS.with(|cache| {
        let mut cache = cache.borrow_mut();
        if let Some(pos) = cache.iter().position(|e| e.0 == len && e.1 == inverse) {
            let e = cache.remove(pos);
            let f = e.2.clone();
            cache.push(e);
            return f;
        }
        let mut planner = FftPlanner::new();
        let f = if inverse {
            planner.plan_fft_inverse(len)
        } else {
            planner.plan_fft_forward(len)
        };
        if cache.len() == PLAN_CACHE {
            cache.remove(0);
        }
        cache.push((len, inverse, f.clone()));
        f
    })
}

/// e^{−2πik/n} for any k, as the product of two short exact tables
/// (coarse steps of 1024 and fine steps of 1): about 2 ulp, and building
/// it costs √n-ish sine evaluations instead of n.
pub(crate) struct Twiddles {
    coarse: Vec<Complex64>,
    fine: Vec<Complex64>,
}

impl Twiddles {
    const BITS: usize = 10;

    pub(crate) fn new(n: usize) -> Self {
        let e = |k: usize| {
            let a = -2.0 * core::f64::consts::PI * (k as f64 / n as f64);
            let (s, c) = a.sin_cos();
            Complex64::new(c, s)
        };
        let fine_len = 1usize << Self::BITS;
        Self {
            coarse: (0..=(n >> Self::BITS) + 1)
                .map(|c| e(c << Self::BITS))
                .collect(),
            fine: (0..fine_len).map(e).collect(),
        }
    }

    /// e^{−2πik/n}, k ≤ n + 1023.
    #[inline]
    pub(crate) fn get(&self, k: usize) -> Complex64 {
        self.coarse[k >> Self::BITS] * self.fine[k & ((1 << Self::BITS) - 1)]
    }
}

/// The smallest `2^a 3^b 5^c` that is `>= min` (and `>= 1`).
pub(crate) fn fast_len(min: usize) -> usize {
    let min = min.max(1);
    let mut best = usize::MAX;
    let mut p2 = 1usize;
    loop {
        let mut p3 = p2;
        loop {
            let mut p5 = p3;
            while p5 < min {
                p5 *= 5;
            }
            best = best.min(p5);
            if p3 >= min {
                break;
            }
            p3 *= 3;
        }
        if p2 >= min {
            break;
        }
        p2 *= 2;
    }
    best
}

/// The smallest even fast length `>= min`.
pub(crate) fn fast_even_len(min: usize) -> usize {
    2 * fast_len(min.div_ceil(2))
}

/// Forward DFT of a real sequence of length `n`: `X_k = Σ_j f_j e^{-2πijk/n}`
/// for `k = 0..=n/2`. For even `n` it runs one complex FFT of length `n/2` on
/// the even/odd-packed input and splits the result; for odd `n` one complex FFT
/// of length `n`. Plans and buffers are made once.
pub(crate) struct RealFft {
    n: usize,
    packed: bool,
    fft: Arc<dyn Fft<f64>>,
    twiddles: Twiddles,
    buf: Vec<Complex64>,
    scratch: Vec<Complex64>,
}

impl RealFft {
    pub(crate) fn new(n: usize) -> Self {
        let packed = n % 2 == 0 && n >= 2;
        let m = if packed { n / 2 } else { n.max(1) };
        let fft = plan(m, false);
        let scratch = vec![Complex64::default(); fft.get_inplace_scratch_len()];
        Self {
            n,
            packed,
            fft,
            twiddles: Twiddles::new(n.max(1)),
            buf: vec![Complex64::default(); m],
            scratch,
        }
    }

    pub(crate) fn len(&self) -> usize {
        self.n
    }

    /// `out[k] = X_k`, `k = 0..=n/2`, of `f_j = (x_j - shift) w_j`, with the
    /// periodic Hann window w_j = sin²(πj/n) = (1 − cos(2πj/n))/2 if `hann`,
    /// else w_j = 1. `x.len()` must be ≤ `n` (entries `x.len()..n` are taken
    /// as zero: zero padding), `out.len()` `n/2 + 1`.
    #[cfg(test)]
    pub(crate) fn forward(&mut self, x: &[f64], shift: f64, hann: bool, out: &mut [Complex64]) {
        debug_assert_eq!(out.len(), self.n / 2 + 1);
        self.forward_with(x, shift, hann, |k, v| out[k] = v);
    }

    /// As [`Self::forward`], handing each `X_k` to `sink(k, X_k)` in order
    /// `k = 0..=n/2` instead of storing the spectrum.
    pub(crate) fn forward_with(
        &mut self,
        x: &[f64],
        shift: f64,
        hann: bool,
        mut sink: impl FnMut(usize, Complex64),
    ) {
        let n = self.n;
        debug_assert!(x.len() <= n);
        let tw = &self.twiddles;
        let f = |j: usize| -> f64 {
            if j < x.len() {
                if hann {
                    (x[j] - shift) * 0.5 * (1.0 - tw.get(j.min(n - j)).re)
                } else {
                    x[j] - shift
                }
            } else {
                0.0
            }
        };
        if self.packed {
            let m = n / 2;
            if !hann && x.len() == n {
                for (j, b) in self.buf.iter_mut().enumerate() {
                    *b = Complex64::new(x[2 * j] - shift, x[2 * j + 1] - shift);
                }
            } else {
                for (j, b) in self.buf.iter_mut().enumerate() {
                    *b = Complex64::new(f(2 * j), f(2 * j + 1));
                }
            }
            self.fft
                .process_with_scratch(&mut self.buf, &mut self.scratch);
            let buf = &self.buf;
            for k in 0..=m {
                let yk = buf[k % m];
                let ymk = buf[(m - k % m) % m].conj();
                let e = (yk + ymk) * 0.5;
                let d = yk - ymk;
                // (yk - ymk) / (2i) = -i d / 2
                let od = Complex64::new(d.im * 0.5, -d.re * 0.5);
                sink(k, e + tw.get(k) * od);
            }
        } else {
            for (j, b) in self.buf.iter_mut().enumerate() {
                *b = Complex64::new(f(j), 0.0);
            }
            self.fft
                .process_with_scratch(&mut self.buf, &mut self.scratch);
            for (k, &v) in self.buf[..n / 2 + 1].iter().enumerate() {
                sink(k, v);
            }
        }
    }
}

/// In-place complex FFT of every row of a row-major `ny × nx` array, then of
/// every column. `inverse` selects the sign; no scaling is applied.
pub(crate) fn fft2(data: &mut [Complex64], nx: usize, ny: usize, inverse: bool) {
    let (fx, fy) = (plan(nx, inverse), plan(ny, inverse));
    let mut scratch = vec![
        Complex64::default();
        fx.get_inplace_scratch_len()
            .max(fy.get_inplace_scratch_len())
    ];
    // Rows: the whole buffer is a sequence of ny transforms of length nx.
    let sx = fx.get_inplace_scratch_len();
    fx.process_with_scratch(data, &mut scratch[..sx]);
    // Columns through a transposed copy.
    let mut t = vec![Complex64::default(); nx * ny];
    for j in 0..ny {
        for i in 0..nx {
            t[i * ny + j] = data[j * nx + i];
        }
    }
    let sy = fy.get_inplace_scratch_len();
    fy.process_with_scratch(&mut t, &mut scratch[..sy]);
    for j in 0..ny {
        for i in 0..nx {
            data[j * nx + i] = t[i * ny + j];
        }
    }
}

/// In-place complex FFT of one sequence.
pub(crate) fn fft1(data: &mut [Complex64], inverse: bool) {
    plan(data.len(), inverse).process(data);
}

#[cfg(test)]
mod tests {
    use super::*;

    fn naive(x: &[f64]) -> Vec<Complex64> {
        let n = x.len();
        (0..=n / 2)
            .map(|k| {
                x.iter()
                    .enumerate()
                    .fold(Complex64::default(), |acc, (j, &v)| {
                        let a = -2.0 * core::f64::consts::PI * (j * k) as f64 / n as f64;
                        acc + Complex64::new(a.cos(), a.sin()) * v
                    })
            })
            .collect()
    }

    #[test]
    fn twiddles_are_accurate() {
        for n in [1usize, 7, 1000, 1 << 20, 999_999] {
            let t = Twiddles::new(n);
            for k in [0usize, 1, n / 3, n / 2, n.saturating_sub(1), n] {
                let a = -2.0 * core::f64::consts::PI * k as f64 / n as f64;
                let d = t.get(k) - Complex64::new(a.cos(), a.sin());
                assert!(d.norm() < 1e-15, "n = {n}, k = {k}");
            }
        }
    }

    #[test]
    fn hann_window_is_applied() {
        let n = 16;
        let x: Vec<f64> = (0..n).map(|j| (j as f64 * 0.37).sin()).collect();
        let w: Vec<f64> = (0..n)
            .map(|j| {
                let s = (core::f64::consts::PI * j as f64 / n as f64).sin();
                x[j] * s * s
            })
            .collect();
        let mut f = RealFft::new(n);
        let mut a = vec![Complex64::default(); n / 2 + 1];
        f.forward(&x, 0.0, true, &mut a);
        for (p, q) in a.iter().zip(naive(&w)) {
            assert!((p - q).norm() < 1e-12);
        }
    }

    #[test]
    fn fast_lengths() {
        assert_eq!(fast_len(1), 1);
        assert_eq!(fast_len(7), 8);
        assert_eq!(fast_len(11), 12);
        assert_eq!(fast_len(1_000_000), 1_000_000);
        assert_eq!(fast_len(1_000_001), 1_012_500);
        assert_eq!(fast_even_len(7), 8);
        assert_eq!(fast_even_len(25), 30);
    }

    #[test]
    fn real_fft_matches_naive_dft() {
        for n in [2usize, 3, 8, 15, 30, 31] {
            let x: Vec<f64> = (0..n).map(|j| ((j * 7 + 3) % 11) as f64 - 4.5).collect();
            let mut f = RealFft::new(n);
            let mut out = vec![Complex64::default(); n / 2 + 1];
            f.forward(&x, 0.0, false, &mut out);
            for (a, b) in out.iter().zip(naive(&x)) {
                assert!((a - b).norm() < 1e-10, "n = {n}: {a} vs {b}");
            }
            // Zero padding: a shorter input.
            let mut f2 = RealFft::new(2 * n);
            let mut out2 = vec![Complex64::default(); n + 1];
            f2.forward(&x, 0.0, false, &mut out2);
            let mut xp = x.clone();
            xp.resize(2 * n, 0.0);
            for (a, b) in out2.iter().zip(naive(&xp)) {
                assert!((a - b).norm() < 1e-10);
            }
        }
    }
}
