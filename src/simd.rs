//! Run-time choice between the AVX2+FMA kernels and the portable code.
//!
//! # The rule
//!
//! There is one vector tier: x86-64 with **AVX2 and FMA**. AVX2 gives the
//! 256-bit float and integer operations the kernels are written in (the JKR
//! cube-root seed needs 64-bit integer lanes), FMA the fused multiply–adds
//! of the dense panels; Intel since Haswell (2013) and AMD since Excavator
//! (2015) have both, so one binary built for baseline x86-64 runs the
//! 256-bit kernels on most machines, and a single tier keeps one fast path
//! per kernel to test. [`avx2_fma`] asks the CPU once per process and
//! caches the answer (one relaxed atomic load afterwards; no detection at
//! all when the build already targets both features). [`dispatch!`] takes
//! the AVX2+FMA path when the answer is yes and the portable path
//! otherwise; on other architectures only the portable path is compiled.
//!
//! A kernel behind [`dispatch!`] is an `unsafe fn` compiled with
//! `#[target_feature(enable = "avx2,fma")]`, exactly the features checked
//! here, and gated by `#[cfg(target_arch = "x86_64")]`: either hand-written
//! intrinsics, or the portable code itself (an `#[inline(always)]` body)
//! recompiled so that the compiler may vectorise it with 256-bit registers.
//!
//! # What agrees with what
//!
//! The choice changes how fast, not what is computed. How closely the two
//! paths agree is stated by each caller and checked by its tests:
//!
//! * the JKR batch kernel (`contact::jkr_simd`) is **bit-identical** to the
//!   element loop: no operation is fused and each lane repeats the scalar
//!   operations in order (`tests/jkr_batch.rs` compares every bit);
//! * recompiling portable code (`lj_sphere::disk`'s influence matrix,
//!   `lj_sphere::lu32`'s substitution) changes no result by itself: Rust
//!   never contracts `a·b + c` into a fused multiply–add, and vectorised
//!   loops keep the order of each element's operations;
//! * the dense panels (`lj_sphere::kernels`, also called by the
//!   substitution) use fused multiply–adds and two partial sums, so they
//!   agree with the plain loops to rounding (relative 1e-14 in f64, 1e-5 in
//!   f32 in their unit tests).

/// Whether the AVX2+FMA kernels may run on this CPU: detected on the first
/// call (`std::is_x86_feature_detected!`), then one relaxed atomic load.
/// `true` without detection when the build already enables both features.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(crate) fn avx2_fma() -> bool {
    use core::sync::atomic::{AtomicU8, Ordering};

    /// 0: not yet detected; 1: AVX2 + FMA absent; 2: present.
    static AVX2_FMA: AtomicU8 = AtomicU8::new(0);

    #[cold]
    #[inline(never)]
    fn detect() -> bool {
        let yes = std::is_x86_feature_detected!("avx2") && std::is_x86_feature_detected!("fma");
        AVX2_FMA.store(if yes { 2 } else { 1 }, Ordering::Relaxed);
        yes
    }

    if cfg!(all(target_feature = "avx2", target_feature = "fma")) {
        return true;
    }
    match AVX2_FMA.load(Ordering::Relaxed) {
        2 => true,
        1 => false,
        _ => detect(),
    }
}

/// `dispatch!(avx2_fma => FAST, portable => PORTABLE)`: the value of `FAST`
/// when [`avx2_fma`] says the CPU has AVX2 and FMA, of `PORTABLE`
/// otherwise. `FAST` is compiled on x86-64 only, so it may name
/// `#[cfg(target_arch = "x86_64")]` items; it calls an `unsafe`
/// `#[target_feature(enable = "avx2,fma")]` kernel in an `unsafe` block whose
/// `SAFETY` comment cites this check (and any contract of the caller's).
macro_rules! dispatch {
    (avx2_fma => $fast:expr, portable => $portable:expr $(,)?) => {{
        #[cfg(target_arch = "x86_64")]
        let chosen = if $crate::simd::avx2_fma() {
            $fast
        } else {
            $portable
        };
        #[cfg(not(target_arch = "x86_64"))]
        let chosen = $portable;
        chosen
    }};
}
pub(crate) use dispatch;
