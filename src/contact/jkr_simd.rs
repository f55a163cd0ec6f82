//! Vectorised batch kernel for the [`Jkr`] sphere under displacement control:
//! AVX2 vectors of four contacts, sixteen contacts per loop iteration, chosen
//! at run time (the element loop on CPUs without AVX2/FMA and on other
//! architectures).
//!
//! # What it computes
//!
//! Exactly what `Jkr::eval` computes, element by element, **bit for bit**:
//! every lane performs the same IEEE operations in the same order as the
//! scalar code of `jkr.rs` (`on_branch`, `reduced_root_and_slope`,
//! `cbrt_positive`): additions, multiplications, divisions and square roots
//! are correctly rounded in both, no operation is fused (the intrinsics are
//! separate `vmulpd`/`vaddpd`, and rustc does not contract the scalar code
//! into FMAs either), and `max` only sees finite, non-NaN operands, where
//! `vmaxpd` and `f64::max` agree. Branches become lane masks:
//!
//! * hysteresis: `stays = old.in_contact ≠ 0 ? δ ≥ δ_c : δ ≥ 0`; lanes that
//!   do not stay get force, radius and stiffness `+0.0` and the all-zero
//!   state, as `out_of_contact`;
//! * `Δ > HERTZ_SWITCH`: the seed `√√Δ` is blended in (computed only when a
//!   lane of the group needs it); such lanes, and lanes out of contact, run
//!   the closed form on the benign `Δ = 0` instead, so no lane overflows
//!   needlessly;
//! * the Newton polish, skipped where `g′(η₀) ≤ 1e-8`, is a blend;
//! * w = 0 (Hertz: `a = √(Rδ)`) is a separate body, behind a branch that
//!   goes the same way for the whole batch.
//!
//! The only non-trivial piece is the cube root of `cbrt_positive`, whose seed
//! `from_bits(bits(x)/3 + K)` divides a `u64` by 3. AVX2 has neither a 64-bit
//! division nor a 64-bit high multiply, so the quotient is formed exactly by
//! the multiplication of *Formulas* (the reciprocal the compiler itself uses
//! for the scalar u64 division by 3), with the 128-bit
//! product's high half assembled from four 32×32→64 multiplications
//! (`vpmuludq`) and their carries. The seed, and so the two Halley steps after
//! it, are those of the scalar code.
//!
//! Because the lanes are bit-identical to `Jkr::eval`, a batch is
//! deterministic (an element's result does not depend on its position or its
//! neighbours) and agrees exactly with scalar evaluation (`tests/jkr_batch.rs`
//! checks every bit).
//!
//! # Batch contract
//!
//! * A group reads all its inputs (δ, `old_state[i].in_contact`) into
//!   registers before it writes any output, so inputs and outputs may be the
//!   same memory element by element.
//! * The last, partial group is padded: its inputs are copied into local
//!   arrays of sixteen whose extra lanes hold δ = 0 with a fresh state, it is
//!   computed by the same vector code, and only the real elements are written.
//! * Before a group is written, its δ are checked to be finite and then its
//!   outputs. If either check fails, the group and everything after it are
//!   handed to [`eval_elementwise`], which reports the first bad element with
//!   the same error as the element loop (invalid δ, or the overflow error of
//!   the finiteness guarantee) and writes the good elements before it, so the
//!   error index and the partial writes are exactly those of the element
//!   loop.
//!
//! # Cost
//!
//! Per vector of four contacts: six divisions and three square roots (what
//! the scalar code does per contact) and about 115 other vector operations.
//! One vector's dependency chain (√disc → two Halley divisions → u → √ → 2/v →
//! √ → Newton division → stiffness division) is ≈ 250 cycles long, far more
//! than its share of divider time, so the main loop interleaves eight
//! independent vectors (32 contacts) statement by statement: the
//! out-of-order core then always finds independent divisions to issue. On AMD
//! Zen 4, relative to one vector per iteration, two vectors per iteration
//! gain about 1.1×, four about 1.5×, eight about 1.7× (with fewer, the
//! scheduler fills with operations waiting on a division). The divider alone would
//! allow ≈ 15 cycles per contact (`vdivpd` ymm ≈ 5.5, `vsqrtpd` ymm ≈ 9 cycles
//! reciprocal throughput).
//!
//! # Formulas
//!
//! Each lane solves the reduced JKR equilibrium of [`super::jkr`],
//!
//! $$\eta^4 - \eta - \Delta = 0, \qquad \delta = L\Delta, \quad L = \left(\frac{4\pi^2 w^2 R}{E^{\ast 2}}\right)^{1/3},$$
//!
//! and the exact quotient of the cube-root seed is
//! $\lfloor x/3 \rfloor = \lfloor x M / 2^{65} \rfloor$ with
//! $M = \mathrm{AAAAAAAAAAAAAAAB}_{16}$ for every 64-bit $x$.
//!
//! # References
//!
//! * K. L. Johnson, K. Kendall, A. D. Roberts (1971), Proc. R. Soc. Lond. A 324,
//!   301–313, [doi:10.1098/rspa.1971.0141](https://doi.org/10.1098/rspa.1971.0141)
//!   (the law; thesis (1-34)–(1-36)).
//! * T. Granlund, P. L. Montgomery (1994), "Division by invariant integers
//!   using multiplication", Proc. ACM SIGPLAN PLDI '94, 61–72 (the reciprocal
//!   multiplication for the division by 3).

use super::batch::{eval_elementwise, BatchError, RawBatch};
use super::jkr::Jkr;

/// Evaluate the batch `b` of `law`: the AVX2 kernel when the CPU has AVX2 and
/// FMA (detected once per process), the element loop otherwise.
///
/// # Safety
/// The pointers of `b` must satisfy the contract of [`RawBatch`].
#[inline]
pub(crate) unsafe fn eval_batch(law: &Jkr, b: &RawBatch) -> Result<(), BatchError> {
    crate::simd::dispatch!(
        // SAFETY: AVX2 and FMA are present (checked by the dispatch); the
        // pointer contract is the caller's.
        avx2_fma => unsafe { x86::eval_batch_avx2(law, b) },
        // SAFETY: the pointer contract is the caller's.
        portable => unsafe { eval_elementwise(law, b) },
    )
}

#[cfg(target_arch = "x86_64")]
mod x86 {
    use super::super::batch::{eval_elementwise, BatchError, RawBatch};
    use super::super::jkr::{Jkr, HERTZ_SWITCH};
    use super::super::ContactState;
    use core::arch::x86_64::*;

    /// The law's constants, broadcast to four lanes.
    #[derive(Clone, Copy)]
    struct Consts {
        /// `true` for w > 0 (closed form), `false` for Hertz.
        adhesive: bool,
        critical_delta: __m256d,
        inv_delta_scale: __m256d,
        radius_scale: __m256d,
        force_scale: __m256d,
        /// `E*·2` (as the scalar code forms it).
        e_star_2: __m256d,
        /// Hertz: R.
        radius: __m256d,
        /// Hertz: `(4/3)·E*`.
        e_star_4_3: __m256d,
        /// Hertz: `2·E*`.
        two_e_star: __m256d,
    }

    impl Consts {
        #[inline]
        #[target_feature(enable = "avx2,fma")]
        unsafe fn new(law: &Jkr) -> Self {
            Self {
                adhesive: law.delta_scale > 0.0,
                critical_delta: _mm256_set1_pd(law.critical_delta),
                inv_delta_scale: _mm256_set1_pd(law.inv_delta_scale),
                radius_scale: _mm256_set1_pd(law.radius_scale),
                force_scale: _mm256_set1_pd(law.force_scale),
                e_star_2: _mm256_set1_pd(law.e_star * 2.0),
                radius: _mm256_set1_pd(law.radius),
                e_star_4_3: _mm256_set1_pd(4.0 / 3.0 * law.e_star),
                two_e_star: _mm256_set1_pd(2.0 * law.e_star),
            }
        }
    }

    /// Vectors of four per group of the main loop: the body handles
    /// `G_MAIN` independent vectors (32 contacts) statement by statement, so
    /// the out-of-order core sees that many independent dependency chains side
    /// by side (module docs, Cost). The rest (< 32 contacts) goes by single
    /// vectors of four (`G = 1`), the last one padded. Every lane runs the
    /// same operations whatever `G`, so results do not depend on it.
    const G_MAIN: usize = 8;

    /// `[expr; G]` with `$j` the vector index, evaluated for every vector of
    /// the group in turn (no closure, so the target features apply). `G` is
    /// the const generic parameter of the function it is used in.
    macro_rules! each {
        ($j:ident => $e:expr) => {{
            let mut out = [_mm256_setzero_pd(); G];
            for $j in 0..G {
                out[$j] = $e;
            }
            out
        }};
    }

    /// Outputs of one group of `G` vectors.
    #[derive(Clone, Copy)]
    struct Out<const G: usize> {
        force: [__m256d; G],
        radius: [__m256d; G],
        stiffness: [__m256d; G],
        /// Bit l set when contact l of the group ends in contact.
        stays: u32,
    }

    /// The batch loop (module docs).
    ///
    /// # Safety
    /// AVX2 and FMA must be available; the pointers of `b` must satisfy the
    /// contract of [`RawBatch`].
    #[target_feature(enable = "avx2,fma")]
    pub(super) unsafe fn eval_batch_avx2(law: &Jkr, b: &RawBatch) -> Result<(), BatchError> {
        let k = Consts::new(law);
        let n = b.n;
        let mut i = 0;
        while i + 4 * G_MAIN <= n {
            // SAFETY: elements i..i+32 are in bounds.
            if let Err(e) = unsafe { step::<G_MAIN>(law, &k, b, i, 4 * G_MAIN) } {
                return e;
            }
            i += 4 * G_MAIN;
        }
        while i < n {
            let m = (n - i).min(4);
            // SAFETY: elements i..i+m are in bounds.
            if let Err(e) = unsafe { step::<1>(law, &k, b, i, m) } {
                return e;
            }
            i += m;
        }
        Ok(())
    }

    /// Elements `i..i + m` (m ≤ 4·G; padded to 4·G lanes when fewer): read,
    /// compute, write. `Err(result of the batch)` when the group needs the
    /// element loop (non-finite δ or response), which then finishes the batch.
    ///
    /// # Safety
    /// Elements `i..i + m` are in bounds; the contract of [`RawBatch`].
    #[inline]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn step<const G: usize>(
        law: &Jkr,
        k: &Consts,
        b: &RawBatch,
        i: usize,
        m: usize,
    ) -> Result<(), Result<(), BatchError>> {
        // SAFETY: elements i..i+m are in bounds (caller).
        let (d, inc) = unsafe { load::<G>(b, i, m) };
        match group::<G>(k, &d, &inc) {
            Some(out) => {
                // SAFETY: as above; all inputs of the group were read before.
                unsafe { store::<G>(b, i, m, &out) };
                Ok(())
            }
            // SAFETY: i < n, so the rest is a valid sub-batch.
            None => Err(unsafe { rest_elementwise(law, b, i) }),
        }
    }

    /// The δ and the old-contact masks of elements `i..i + m` (m ≤ 4·G),
    /// padded up to 4·G lanes with δ = 0 and fresh states.
    ///
    /// # Safety
    /// `delta` is valid for elements `i..i + m`, `old_state` too or NULL.
    #[inline]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn load<const G: usize>(
        b: &RawBatch,
        i: usize,
        m: usize,
    ) -> ([__m256d; G], [__m256d; G]) {
        let d = if m == 4 * G {
            // SAFETY: elements i..i+4G are valid (caller).
            each!(j => unsafe { _mm256_loadu_pd(b.delta.add(i + 4 * j)) })
        } else {
            let mut buf = [[0.0f64; 4]; G];
            for l in 0..m {
                // SAFETY: i + l < i + m is valid (caller).
                buf[l / 4][l % 4] = unsafe { b.delta.add(i + l).read() };
            }
            each!(j => unsafe { _mm256_loadu_pd(buf[j].as_ptr()) })
        };
        let mut mask = [[0i64; 4]; G];
        if !b.old_state.is_null() {
            for l in 0..m {
                // SAFETY: element i + l < i + m is valid (caller).
                let old = unsafe { &*b.old_state.add(i + l) };
                mask[l / 4][l % 4] = -((old.in_contact != 0) as i64);
            }
        }
        // SAFETY: each `mask[j]` holds four i64.
        let inc = each!(j => _mm256_castsi256_pd(unsafe {
            _mm256_loadu_si256(mask[j].as_ptr().cast())
        }));
        (d, inc)
    }

    /// Elements `start..n` by the element loop, with the error index shifted
    /// back to the whole batch.
    ///
    /// # Safety
    /// `start ≤ b.n`; the pointer contract of [`RawBatch`].
    #[cold]
    #[inline(never)]
    unsafe fn rest_elementwise(law: &Jkr, b: &RawBatch, start: usize) -> Result<(), BatchError> {
        // Offsets a pointer that may be NULL (NULL stays NULL).
        fn off<T>(p: *const T, k: usize) -> *const T {
            if p.is_null() {
                p
            } else {
                p.wrapping_add(k)
            }
        }
        let rest = RawBatch {
            n: b.n - start,
            delta: b.delta.wrapping_add(start),
            old_state: off(b.old_state, start),
            new_state: off(b.new_state, start).cast_mut(),
            force: b.force.wrapping_add(start),
            contact_radius: off(b.contact_radius, start).cast_mut(),
            stiffness: off(b.stiffness, start).cast_mut(),
        };
        // SAFETY: every non-NULL pointer of `rest` points at element `start`
        // of an array valid for `b.n` elements, so it is valid for
        // `b.n − start`.
        unsafe { eval_elementwise(law, &rest) }.map_err(|e| BatchError {
            index: e.index + start,
            error: e.error,
        })
    }

    /// Write elements `i..i + m` (m ≤ 4·G) of the group's outputs, in the
    /// element loop's order per array: force, radius, stiffness, state.
    ///
    /// # Safety
    /// The output pointers are valid for elements `i..i + m` (or NULL where
    /// optional).
    #[inline]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn store<const G: usize>(b: &RawBatch, i: usize, m: usize, o: &Out<G>) {
        let mut force = [[0.0f64; 4]; G];
        let mut radius = [[0.0f64; 4]; G];
        let mut stiffness = [[0.0f64; 4]; G];
        for j in 0..G {
            // SAFETY: each local `[f64; 4]` holds one vector.
            unsafe {
                _mm256_storeu_pd(force[j].as_mut_ptr(), o.force[j]);
                _mm256_storeu_pd(radius[j].as_mut_ptr(), o.radius[j]);
                _mm256_storeu_pd(stiffness[j].as_mut_ptr(), o.stiffness[j]);
            }
        }
        // `[[f64; 4]; G]` is 4·G contiguous f64.
        let (force, radius, stiffness) = (
            force.as_ptr().cast::<f64>(),
            radius.as_ptr().cast::<f64>(),
            stiffness.as_ptr().cast::<f64>(),
        );
        // SAFETY: elements i..i+m of the outputs are valid (caller); the
        // local arrays hold 4·G ≥ m values.
        unsafe {
            core::ptr::copy_nonoverlapping(force, b.force.add(i), m);
            if !b.contact_radius.is_null() {
                core::ptr::copy_nonoverlapping(radius, b.contact_radius.add(i), m);
            }
            if !b.stiffness.is_null() {
                core::ptr::copy_nonoverlapping(stiffness, b.stiffness.add(i), m);
            }
            if !b.new_state.is_null() {
                for l in 0..m {
                    let c = ((o.stays >> l) & 1) as i32;
                    b.new_state.add(i + l).write(ContactState {
                        contact_radius: radius.add(l).read(),
                        cohesive_radius: 0.0,
                        in_contact: c,
                        branch: c,
                    });
                }
            }
        }
    }

    /// `|x| < ∞` per lane, as a 4-bit mask.
    #[inline]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn finite_bits(x: __m256d) -> i32 {
        let abs = _mm256_andnot_pd(_mm256_set1_pd(-0.0), x);
        _mm256_movemask_pd(_mm256_cmp_pd::<_CMP_LT_OQ>(
            abs,
            _mm256_set1_pd(f64::INFINITY),
        ))
    }

    /// Whether every lane of every vector of `x` is finite.
    #[inline]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn all_finite<const G: usize>(x: &[__m256d; G]) -> bool {
        let mut bits = 0xF;
        for v in x {
            bits &= finite_bits(*v);
        }
        bits == 0xF
    }

    /// One group: `None` when a δ or an output is not finite (the caller then
    /// hands over to the element loop).
    #[inline]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn group<const G: usize>(
        k: &Consts,
        d: &[__m256d; G],
        inc: &[__m256d; G],
    ) -> Option<Out<G>> {
        if !all_finite(d) {
            return None;
        }
        // Hysteresis: in contact before → stays while δ ≥ δ_c; out → δ ≥ 0.
        let stays = each!(j => _mm256_blendv_pd(
            _mm256_cmp_pd::<_CMP_GE_OQ>(d[j], _mm256_setzero_pd()),
            _mm256_cmp_pd::<_CMP_GE_OQ>(d[j], k.critical_delta),
            inc[j]
        ));
        let (force, radius, stiffness) = if k.adhesive {
            adhesive(k, d, &stays)
        } else {
            hertz(k, d, &stays)
        };
        // Out of contact: +0.0 everywhere.
        let force = each!(j => _mm256_and_pd(force[j], stays[j]));
        let radius = each!(j => _mm256_and_pd(radius[j], stays[j]));
        let stiffness = each!(j => _mm256_and_pd(stiffness[j], stays[j]));
        if !(all_finite(&force) && all_finite(&radius) && all_finite(&stiffness)) {
            return None;
        }
        let mut bits = 0u32;
        for (j, s) in stays.iter().enumerate() {
            bits |= (_mm256_movemask_pd(*s) as u32) << (4 * j);
        }
        Some(Out {
            force,
            radius,
            stiffness,
            stays: bits,
        })
    }

    /// Result vectors: force, contact radius, stiffness.
    type Triple<const G: usize> = ([__m256d; G], [__m256d; G], [__m256d; G]);

    /// w = 0: `a = √(Rδ)`, `P = (4/3)E*aδ`, `dP/dδ = 2E*a` (lanes that stay
    /// have δ ≥ 0; the others compute on δ = 0).
    #[inline]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn hertz<const G: usize>(
        k: &Consts,
        d: &[__m256d; G],
        stays: &[__m256d; G],
    ) -> Triple<G> {
        let d = each!(j => _mm256_and_pd(d[j], stays[j]));
        let a = each!(j => _mm256_sqrt_pd(_mm256_mul_pd(k.radius, d[j])));
        let force = each!(j => _mm256_mul_pd(_mm256_mul_pd(k.e_star_4_3, a[j]), d[j]));
        let stiffness = each!(j => _mm256_mul_pd(k.two_e_star, a[j]));
        (force, a, stiffness)
    }

    /// `x` in every lane.
    #[inline]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn set(x: f64) -> __m256d {
        _mm256_set1_pd(x)
    }

    /// w > 0: `Jkr::on_branch` on every lane (module docs of `jkr.rs`), the
    /// same operations in the same order.
    #[inline]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn adhesive<const G: usize>(
        k: &Consts,
        d: &[__m256d; G],
        stays: &[__m256d; G],
    ) -> Triple<G> {
        let zero = _mm256_setzero_pd();
        // Reduced overlap Δ = δ/L.
        let big_delta = each!(j => _mm256_mul_pd(d[j], k.inv_delta_scale));
        let big = each!(j => _mm256_cmp_pd::<_CMP_GT_OQ>(big_delta[j], set(HERTZ_SWITCH)));
        // Closed form on the lanes that stay and are not beyond the switch;
        // Δ = 0 elsewhere (benign: η = 1).
        let x = each!(j => _mm256_and_pd(big_delta[j], _mm256_andnot_pd(big[j], stays[j])));
        // Resolvent u³ + 3su − 2r = 0, r = 1/16:
        // disc = max(r² + s³, 0), C = ∛(r + √disc).
        const R: f64 = 1.0 / 16.0;
        let s = each!(j => _mm256_mul_pd(x[j], set(1.0 / 3.0)));
        let s2 = each!(j => _mm256_mul_pd(s[j], s[j]));
        let disc = each!(j => _mm256_max_pd(
            _mm256_add_pd(set(R * R), _mm256_mul_pd(s2[j], s[j])),
            zero
        ));
        let cx = each!(j => _mm256_add_pd(set(R), _mm256_sqrt_pd(disc[j])));
        let c = cbrt_positive(&cx);
        // u = 2rC²/(C⁴ + sC² + s²), v = √(2u), η₀ = (v + √max(2/v − v², 0))/2.
        let c2 = each!(j => _mm256_mul_pd(c[j], c[j]));
        let den = each!(j => _mm256_add_pd(
            _mm256_add_pd(_mm256_mul_pd(c2[j], c2[j]), _mm256_mul_pd(s[j], c2[j])),
            s2[j]
        ));
        let u = each!(j => _mm256_div_pd(_mm256_mul_pd(set(2.0 * R), c2[j]), den[j]));
        let v = each!(j => _mm256_sqrt_pd(_mm256_mul_pd(set(2.0), u[j])));
        let w = each!(j => _mm256_max_pd(
            _mm256_sub_pd(_mm256_div_pd(set(2.0), v[j]), _mm256_mul_pd(v[j], v[j])),
            zero
        ));
        let mut eta =
            each!(j => _mm256_mul_pd(set(0.5), _mm256_add_pd(v[j], _mm256_sqrt_pd(w[j]))));
        let mut any_big = 0;
        for m in &big {
            any_big |= _mm256_movemask_pd(*m);
        }
        if any_big != 0 {
            // Beyond the switch the Hertz value √√Δ seeds the Newton step.
            for j in 0..G {
                let hertz = _mm256_sqrt_pd(_mm256_sqrt_pd(big_delta[j]));
                eta[j] = _mm256_blendv_pd(eta[j], hertz, big[j]);
            }
        }
        // One Newton step on g(η) = η⁴ − η − Δ, skipped where g′ ≤ 1e-8.
        let e2 = each!(j => _mm256_mul_pd(eta[j], eta[j]));
        let gp = each!(j => _mm256_sub_pd(
            _mm256_mul_pd(_mm256_mul_pd(set(4.0), e2[j]), eta[j]),
            set(1.0)
        ));
        let g = each!(j => _mm256_sub_pd(
            _mm256_sub_pd(_mm256_mul_pd(e2[j], e2[j]), eta[j]),
            big_delta[j]
        ));
        let polished = each!(j => _mm256_sub_pd(eta[j], _mm256_div_pd(g[j], gp[j])));
        let eta = each!(j => _mm256_blendv_pd(
            eta[j],
            polished[j],
            _mm256_cmp_pd::<_CMP_GT_OQ>(gp[j], set(1e-8))
        ));
        // Response on the stable branch: a = scale·η², P = scale·η³((4/3)η³ − 2),
        // dP/dδ = 2E*a·(4η³ − 3)/max(g′(η₀), 4εη³).
        let e3 = each!(j => _mm256_mul_pd(_mm256_mul_pd(eta[j], eta[j]), eta[j]));
        let a = each!(j => _mm256_mul_pd(_mm256_mul_pd(k.radius_scale, eta[j]), eta[j]));
        let force = each!(j => _mm256_mul_pd(
            _mm256_mul_pd(k.force_scale, e3[j]),
            _mm256_sub_pd(_mm256_mul_pd(set(4.0 / 3.0), e3[j]), set(2.0))
        ));
        let den = each!(j => _mm256_max_pd(gp[j], _mm256_mul_pd(set(f64::EPSILON * 4.0), e3[j])));
        let ratio = each!(j => _mm256_div_pd(
            _mm256_sub_pd(_mm256_mul_pd(set(4.0), e3[j]), set(3.0)),
            den[j]
        ));
        let stiffness = each!(j => _mm256_mul_pd(_mm256_mul_pd(k.e_star_2, a[j]), ratio[j]));
        (force, a, stiffness)
    }

    /// `jkr::cbrt_positive` on every lane (x ≥ 1/16, finite): the same seed
    /// `from_bits(bits(x)/3 + 0x2A9F_7893_782D_A1CE)` (exact u64 quotient by
    /// 3, see the module docs) and the same two Halley steps
    /// `c ← c·((c³ + 2x)/(2c³ + x))`.
    #[inline]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn cbrt_positive<const G: usize>(x: &[__m256d; G]) -> [__m256d; G] {
        let mut c = each!(j => _mm256_castsi256_pd(_mm256_add_epi64(
            div3_u64(_mm256_castpd_si256(x[j])),
            _mm256_set1_epi64x(0x2A9F_7893_782D_A1CE)
        )));
        let two_x = each!(j => _mm256_mul_pd(set(2.0), x[j]));
        for _ in 0..2 {
            let c3 = each!(j => _mm256_mul_pd(_mm256_mul_pd(c[j], c[j]), c[j]));
            let num = each!(j => _mm256_add_pd(c3[j], two_x[j]));
            let den = each!(j => _mm256_add_pd(_mm256_mul_pd(set(2.0), c3[j]), x[j]));
            c = each!(j => _mm256_mul_pd(c[j], _mm256_div_pd(num[j], den[j])));
        }
        c
    }

    /// `⌊n/3⌋` for each unsigned 64-bit lane: the high half of the 128-bit
    /// product `n·M`, `M = 0xAAAA_AAAA_AAAA_AAAB = ⌈2^65/3⌉`, shifted right by
    /// one (exact for every u64). The high half is assembled from the four
    /// 32×32→64 partial products with their carries.
    #[inline]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn div3_u64(n: __m256i) -> __m256i {
        let m_lo = _mm256_set1_epi64x(0xAAAA_AAAB);
        let m_hi = _mm256_set1_epi64x(0xAAAA_AAAA);
        let low32 = _mm256_set1_epi64x(0xFFFF_FFFF);
        let n_hi = _mm256_srli_epi64::<32>(n);
        // _mm256_mul_epu32 multiplies the low 32 bits of each 64-bit lane.
        let p0 = _mm256_mul_epu32(n, m_lo);
        let p1 = _mm256_mul_epu32(n, m_hi);
        let p2 = _mm256_mul_epu32(n_hi, m_lo);
        let p3 = _mm256_mul_epu32(n_hi, m_hi);
        let mid = _mm256_add_epi64(
            _mm256_add_epi64(_mm256_srli_epi64::<32>(p0), _mm256_and_si256(p1, low32)),
            _mm256_and_si256(p2, low32),
        );
        let hi = _mm256_add_epi64(
            _mm256_add_epi64(p3, _mm256_srli_epi64::<32>(p1)),
            _mm256_add_epi64(_mm256_srli_epi64::<32>(p2), _mm256_srli_epi64::<32>(mid)),
        );
        _mm256_srli_epi64::<1>(hi)
    }
}
