//! The single-precision preconditioner of the continuation: an LU
//! factorisation with partial pivoting computed in place in a reused buffer,
//! and its forward and back substitution for one right-hand side.
//!
//! # Why not `PartialPivLu`
//!
//! faer's `PartialPivLu::new` allocates and copies the matrix on every
//! factorisation; at order 257 (N = 256 plus the border) that is a 264 KB
//! block, which the allocator maps and the kernel zero-fills anew each time
//! (a visible share of a μ = 1 curve, all in page faults). Here the
//! bordered Jacobian is assembled straight into the buffer that
//! [`faer::linalg::lu::partial_pivoting::factor::lu_in_place`] factors, so a
//! factorisation allocates nothing after the first.
//!
//! For the solves, faer's triangular kernels are built for many right-hand
//! sides and recurse into blocks; for a single vector of order 257 a plain
//! column-oriented substitution compiled for AVX2/FMA is about twice as
//! fast, with results equal to single-precision rounding. Every GMRES
//! iteration of the
//! continuation applies the preconditioner once, so this is on the critical
//! path of every curve. The substitution below works in blocks of eight
//! columns: the inverses of the diagonal blocks are formed once per
//! factorisation, so a block's unknowns are one small dense product instead
//! of a chain of dependent scalar updates, and the rest of the vector is
//! updated by eight columns per pass ([`kernels::update`]), which is faster
//! again than column by column (BENCHMARKS.md §3).

use super::kernels;
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::lu::partial_pivoting::factor::{lu_in_place, lu_in_place_scratch};
use faer::{MatMut, Par};

/// An LU factorisation `P A = L U` of a square single-precision matrix, in
/// place: `L` (unit lower) and `U` share the column-major buffer.
#[derive(Default)]
pub(super) struct Lu32 {
    /// Column-major `n × n`: the matrix before [`Lu32::factor`], its factors
    /// after.
    a: Vec<f32>,
    n: usize,
    /// Row permutation: row `i` of `P A` is row `perm[i]` of `A`.
    perm: Vec<usize>,
    perm_inv: Vec<usize>,
    /// faer's scratch (the transpositions).
    mem: Option<MemBuffer>,
    /// Whether `a` holds the factors of the last [`Lu32::factor`].
    valid: bool,
    /// Scratch of the permuted right-hand side.
    tmp: Vec<f32>,
    /// The negated inverses of the diagonal blocks of `L` and of `U`
    /// ([`BLOCK`]² column-major each, zero-padded in a last partial
    /// block): the substitution applies them as small dense products
    /// instead of solving each block's triangle element by element.
    linv: Vec<f32>,
    uinv: Vec<f32>,
}

impl Lu32 {
    /// The matrix to be filled (column-major, `n × n`), resized and marked
    /// unfactored.
    pub(super) fn matrix_mut(&mut self, n: usize) -> &mut [f32] {
        if self.n != n || self.a.len() != n * n {
            self.a = vec![0.0; n * n];
            self.perm = vec![0; n];
            self.perm_inv = vec![0; n];
            self.tmp = vec![0.0; n];
            self.linv = vec![0.0; n.div_ceil(BLOCK) * BLOCK * BLOCK];
            self.uinv = vec![0.0; n.div_ceil(BLOCK) * BLOCK * BLOCK];
            self.mem = Some(MemBuffer::new(lu_in_place_scratch::<usize, f32>(
                n,
                n,
                Par::Seq,
                Default::default(),
            )));
            self.n = n;
        }
        self.valid = false;
        &mut self.a
    }

    /// Factor the matrix filled through [`Lu32::matrix_mut`] (before any,
    /// nothing is factored and [`Lu32::is_valid`] stays false). A singular
    /// matrix is factored too (faer does not stop); its solves are not
    /// finite, which the callers check.
    pub(super) fn factor(&mut self) {
        let n = self.n;
        // Set with the buffer by `matrix_mut`: without it nothing was filled.
        let Some(mem) = self.mem.as_mut() else {
            return;
        };
        lu_in_place(
            MatMut::from_column_major_slice_mut(&mut self.a, n, n),
            &mut self.perm,
            &mut self.perm_inv,
            Par::Seq,
            MemStack::new(mem),
            Default::default(),
        );
        self.invert_diagonal_blocks();
        self.valid = true;
    }

    /// [`Lu32::linv`] and [`Lu32::uinv`] of the factors in `a` (in f64, by
    /// substitution of the unit vectors). The entries of `L` are at most 1
    /// in magnitude (partial pivoting), and the factorisation is a
    /// preconditioner: the inverted blocks need no more accuracy than the
    /// f32 factors themselves.
    fn invert_diagonal_blocks(&mut self) {
        let n = self.n;
        let a = &self.a;
        for (b, j0) in (0..n).step_by(BLOCK).enumerate() {
            let s = BLOCK.min(n - j0);
            let at = |i: usize, j: usize| f64::from(a[(j0 + j) * n + j0 + i]);
            let li = &mut self.linv[b * BLOCK * BLOCK..(b + 1) * BLOCK * BLOCK];
            let ui = &mut self.uinv[b * BLOCK * BLOCK..(b + 1) * BLOCK * BLOCK];
            li.iter_mut().for_each(|v| *v = 0.0);
            ui.iter_mut().for_each(|v| *v = 0.0);
            for c in 0..s {
                let mut v = [0.0f64; BLOCK];
                v[c] = 1.0;
                for j in c..s {
                    for i in j + 1..s {
                        v[i] -= at(i, j) * v[j];
                    }
                }
                for i in 0..s {
                    li[c * BLOCK + i] = -v[i] as f32;
                }
                let mut v = [0.0f64; BLOCK];
                v[c] = 1.0;
                for j in (0..=c).rev() {
                    v[j] /= at(j, j);
                    for i in 0..j {
                        v[i] -= at(i, j) * v[j];
                    }
                }
                for i in 0..s {
                    ui[c * BLOCK + i] = -v[i] as f32;
                }
            }
        }
    }

    /// Whether a factorisation is held.
    pub(super) fn is_valid(&self) -> bool {
        self.valid
    }

    /// Forget the factorisation.
    pub(super) fn invalidate(&mut self) {
        self.valid = false;
    }

    /// `x ← A⁻¹ x` with the held factors (`x.len()` = n).
    pub(super) fn solve_in_place(&mut self, x: &mut [f32]) {
        debug_assert!(self.valid && x.len() == self.n);
        for (t, &p) in self.tmp.iter_mut().zip(&self.perm) {
            *t = x[p];
        }
        x.copy_from_slice(&self.tmp);
        substitute(&self.a, &self.linv, &self.uinv, self.n, x);
    }
}

/// Forward substitution with the unit lower factor, then back substitution
/// with the upper one, in blocks of [`BLOCK`] columns: each block's
/// unknowns from the inverse of its diagonal block (`linv`, `uinv`: a
/// small dense product, no chain of dependent scalar updates), then the
/// rest of the vector updated by the block's columns at once
/// ([`kernels::update`]: one pass over the vector per block instead of one
/// per column).
fn substitute(lu: &[f32], linv: &[f32], uinv: &[f32], n: usize, x: &mut [f32]) {
    crate::simd::dispatch!(
        // SAFETY: AVX2 and FMA are present (checked by the dispatch).
        avx2_fma => unsafe { substitute_avx2(lu, linv, uinv, n, x) },
        portable => substitute_generic(lu, linv, uinv, n, x),
    )
}

/// [`substitute_generic`] compiled for AVX2+FMA (see `crate::simd`).
///
/// # Safety
/// AVX2 and FMA must be available.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
unsafe fn substitute_avx2(lu: &[f32], linv: &[f32], uinv: &[f32], n: usize, x: &mut [f32]) {
    substitute_generic(lu, linv, uinv, n, x);
}

/// Columns per block of the substitution.
const BLOCK: usize = 8;

/// `x[j0..j1] ← −inv · x[j0..j1]` for the block starting at `j0` (`inv`
/// its negated inverse, [`BLOCK`]² column-major).
#[inline(always)]
fn apply_block(inv: &[f32], x: &mut [f32]) {
    let mut xb = [0.0f32; BLOCK];
    xb[..x.len()].copy_from_slice(x);
    x.iter_mut().for_each(|v| *v = 0.0);
    <f32 as kernels::Elem>::panel(inv, BLOCK, &xb, x);
}

#[inline(always)]
fn substitute_generic(lu: &[f32], linv: &[f32], uinv: &[f32], n: usize, x: &mut [f32]) {
    const B2: usize = BLOCK * BLOCK;
    for (b, j0) in (0..n).step_by(BLOCK).enumerate() {
        let j1 = (j0 + BLOCK).min(n);
        apply_block(&linv[b * B2..(b + 1) * B2], &mut x[j0..j1]);
        let (head, tail) = x.split_at_mut(j1);
        kernels::update(&lu[j0 * n + j1..], n, &head[j0..], tail);
    }
    for (b, j0) in (0..n).step_by(BLOCK).enumerate().rev() {
        let j1 = (j0 + BLOCK).min(n);
        apply_block(&uinv[b * B2..(b + 1) * B2], &mut x[j0..j1]);
        let (head, tail) = x.split_at_mut(j0);
        kernels::update(&lu[j0 * n..], n, &tail[..j1 - j0], head);
    }
}

#[cfg(test)]
mod tests {
    use super::{Lu32, MatMut};
    use faer::linalg::solvers::{PartialPivLu, Solve};
    use faer::MatRef;

    /// The in-place factors and the substitution solve as faer's
    /// `PartialPivLu` does, for a matrix that needs pivoting, at orders
    /// around the SIMD width and the continuation's.
    #[test]
    fn solves_like_faer_partial_piv_lu() {
        for n in [1usize, 2, 7, 8, 9, 33, 257] {
            let mut lu = Lu32::default();
            let m = lu.matrix_mut(n);
            for j in 0..n {
                for i in 0..n {
                    // A dominant cyclic shift (the pivot of column j is
                    // in row j + 1, so every column swaps rows) plus a
                    // smaller dense part: well conditioned at every order.
                    let shift = if i == (j + 1) % n { 4.0 } else { 0.0 };
                    let v = shift + 0.1 / (1.0 + (i as f32 - 0.7 * j as f32).abs());
                    m[j * n + i] = v;
                }
            }
            let a = m.to_vec();
            lu.factor();
            assert!(lu.is_valid());
            assert!(
                n == 1 || lu.perm.iter().enumerate().any(|(i, &p)| i != p),
                "n {n}: no row was swapped"
            );
            let b: Vec<f32> = (0..n).map(|i| (i as f32 * 0.37).sin() + 0.5).collect();
            let mut x = b.clone();
            lu.solve_in_place(&mut x);
            let reference = PartialPivLu::new(MatRef::from_column_major_slice(&a, n, n));
            let mut y = b.clone();
            reference.solve_in_place(MatMut::from_column_major_slice_mut(&mut y, n, 1));
            let scale = y.iter().fold(0.0f32, |s, v| s.max(v.abs()));
            for i in 0..n {
                assert!(
                    (x[i] - y[i]).abs() <= 1e-4 * scale,
                    "n {n}: x[{i}] = {} against faer {}",
                    x[i],
                    y[i]
                );
            }
            // And the residual of the original system is small.
            for i in 0..n {
                let r: f32 = (0..n).map(|j| a[j * n + i] * x[j]).sum::<f32>() - b[i];
                assert!(
                    r.abs() <= 1e-3 * (1.0 + scale),
                    "n {n}: residual {r} at row {i}"
                );
            }
            lu.invalidate();
            assert!(!lu.is_valid());
        }
    }
}
