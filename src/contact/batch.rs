//! Batch evaluation: one law, many contacts, plain arrays.
//!
//! [`eval_batch`] is the entry point for Rust callers: slices, checked for
//! length, which cannot overlap. The C ABI's `asperity_normal_eval_batch` and
//! `asperity_table_eval_batch` (`src/ffi/`) pass the caller's arrays straight
//! through as raw pointers, so a host code's own arrays are used without
//! copying and input and output arrays may be the same memory. That raw form
//! (`RawBatch`) and the per-law kernel hook (`NormalContact::eval_batch_raw`,
//! hidden) are private to the crate: each element is read completely before
//! it is written, which is what makes the aliasing safe, and only the crate's
//! own kernels and the C boundary rely on it. Laws with a vectorised kernel
//! (JKR, and the pointwise laws Hertz, DMT and flat punch) override the hook;
//! every other law runs the element loop. Batch and scalar evaluation agree to
//! rounding, and a batch is deterministic: an element's result does not depend
//! on its position in the arrays or on the other elements.
//!
//! # Formulas
//!
//! None of its own: element $i$ of a batch is exactly the scalar evaluation
//! $(P_i, a_i, k_i, \tilde s_i) = \mathrm{eval}(\delta_i, s_i)$ of the law, whose
//! module gives the formula.
//!
//! # References
//!
//! * The laws' own modules (for example [`super::hertz`], [`super::jkr`]).
//! * The batched-kernel calling convention follows libxc, `f(p, n, x[])`:
//!   S. Lehtola, C. Steigemann, M. J. T. Oliveira, M. A. L. Marques (2018),
//!   "Recent developments in libxc — A comprehensive library of functionals
//!   for density functional theory", SoftwareX 7, 1–5.

use super::{is_finite, overflow, ContactState, NormalContact};
use crate::error::{Error, Result};

/// A failed batch: the error and the element it happened at. Elements before
/// `index` have been written; elements from `index` on are untouched.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BatchError {
    /// Index of the failing element.
    pub index: usize,
    /// What went wrong there.
    pub error: Error,
}

impl core::fmt::Display for BatchError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "element {}: {}", self.index, self.error)
    }
}

impl std::error::Error for BatchError {}

pub(crate) use raw::RawBatch;

/// The raw form lives in a private module: it is `pub` only so that the hidden
/// hook of the public trait [`NormalContact`] may name it, and nothing outside
/// the crate can name, build or receive one (so no caller outside the crate
/// can call or override the hook).
mod raw {
    use crate::contact::ContactState;

    /// The arrays of a batch, as raw pointers so that inputs and outputs may
    /// alias element by element (each element is read completely before it is
    /// written).
    ///
    /// `delta` and `force` must be valid for `n` elements; the others are
    /// either NULL (fresh states / output not wanted) or valid for `n`
    /// elements.
    #[derive(Debug, Clone, Copy)]
    pub struct RawBatch {
        /// Number of contacts.
        pub n: usize,
        /// Overlaps δ (m).
        pub delta: *const f64,
        /// Histories before the step, or NULL for fresh contacts.
        pub old_state: *const ContactState,
        /// Histories after the step, or NULL.
        pub new_state: *mut ContactState,
        /// Forces (N).
        pub force: *mut f64,
        /// Contact radii (m), or NULL.
        pub contact_radius: *mut f64,
        /// Tangent stiffnesses dP/dδ (N/m), or NULL.
        pub stiffness: *mut f64,
    }
}

/// The element loop every law can use: [`NormalContact::eval`] per element,
/// with the finiteness guarantee of [`super::NormalLaw`].
///
/// # Safety
/// The pointers of `b` must satisfy the contract of [`RawBatch`].
#[inline]
pub(crate) unsafe fn eval_elementwise<L: NormalContact + ?Sized>(
    law: &L,
    b: &RawBatch,
) -> core::result::Result<(), BatchError> {
    elementwise::<L, true>(law, b)
}

/// [`eval_elementwise`] for a law whose `eval` already returns an error
/// rather than a non-finite response: the same loop without the second
/// finiteness test.
///
/// # Safety
/// The pointers of `b` must satisfy the contract of [`RawBatch`].
#[inline]
pub(crate) unsafe fn eval_elementwise_finite<L: NormalContact + ?Sized>(
    law: &L,
    b: &RawBatch,
) -> core::result::Result<(), BatchError> {
    elementwise::<L, false>(law, b)
}

#[inline(always)]
unsafe fn elementwise<L: NormalContact + ?Sized, const CHECK: bool>(
    law: &L,
    b: &RawBatch,
) -> core::result::Result<(), BatchError> {
    for i in 0..b.n {
        let d = b.delta.add(i).read();
        let old = if b.old_state.is_null() {
            ContactState::default()
        } else {
            b.old_state.add(i).read()
        };
        let (r, s) = law
            .eval(d, &old)
            .map_err(|error| BatchError { index: i, error })?;
        if CHECK && !is_finite(&r) {
            return Err(BatchError {
                index: i,
                error: overflow(d),
            });
        }
        b.force.add(i).write(r.force);
        if !b.contact_radius.is_null() {
            b.contact_radius.add(i).write(r.contact_radius);
        }
        if !b.stiffness.is_null() {
            b.stiffness.add(i).write(r.stiffness);
        }
        if !b.new_state.is_null() {
            b.new_state.add(i).write(s);
        }
    }
    Ok(())
}

fn check_len(name: &'static str, len: usize, n: usize) -> Result<()> {
    if len == n {
        Ok(())
    } else {
        Err(Error::InvalidArgument {
            name,
            value: len as f64,
            bound: "of the same length as delta",
        })
    }
}

/// Evaluate `law` for every overlap of `delta` (m), from the histories `old`
/// (or fresh ones) into `new` (if given), writing forces (N) and, if given,
/// contact radii (m) and stiffnesses (N/m). Every slice given must have the
/// length of `delta` (else [`Error::InvalidArgument`] naming the slice, at
/// index 0, nothing written). Runs the law's own batch kernel where it has
/// one (the same code as the C ABI's batch call), element `i` equal to
/// `law.eval(delta[i], old[i])` to rounding; on an error at element `i` the
/// elements before `i` are written and the rest untouched.
pub fn eval_batch<L: NormalContact + ?Sized>(
    law: &L,
    delta: &[f64],
    old: Option<&[ContactState]>,
    new: Option<&mut [ContactState]>,
    force: &mut [f64],
    contact_radius: Option<&mut [f64]>,
    stiffness: Option<&mut [f64]>,
) -> core::result::Result<(), BatchError> {
    let n = delta.len();
    let lens = [
        ("old", old.as_ref().map(|s| s.len())),
        ("new", new.as_ref().map(|s| s.len())),
        ("force", Some(force.len())),
        ("contact_radius", contact_radius.as_ref().map(|s| s.len())),
        ("stiffness", stiffness.as_ref().map(|s| s.len())),
    ];
    for (name, len) in lens {
        if let Some(len) = len {
            check_len(name, len, n).map_err(|error| BatchError { index: 0, error })?;
        }
    }
    let b = RawBatch {
        n,
        delta: delta.as_ptr(),
        old_state: old.map_or(core::ptr::null(), |s| s.as_ptr()),
        new_state: new.map_or(core::ptr::null_mut(), |s| s.as_mut_ptr()),
        force: force.as_mut_ptr(),
        contact_radius: contact_radius.map_or(core::ptr::null_mut(), |s| s.as_mut_ptr()),
        stiffness: stiffness.map_or(core::ptr::null_mut(), |s| s.as_mut_ptr()),
    };
    // SAFETY: every pointer comes from a slice of length n (or is NULL), and
    // distinct slices do not overlap.
    unsafe { law.eval_batch_raw(&b) }
}

/// A law whose response is a pure function of the overlap (no hysteresis).
/// Its batch runs in chunks the compiler can vectorise: the chunk's responses
/// are computed branch-free into local arrays, checked, then copied out.
pub(crate) trait Pointwise: NormalContact {
    /// Force (N), contact radius (m) and stiffness (N/m) at overlap `delta`
    /// (m). Must be branch-free in spirit (selects, not early returns) and is
    /// the single source of the law's scalar `eval` too, so batch and scalar
    /// results agree bit for bit. Non-finite `delta` may give anything but a
    /// panic.
    fn point(&self, delta: f64) -> (f64, f64, f64);
}

/// Batch kernel of a [`Pointwise`] law. Same contract and results as
/// [`eval_elementwise`]; on a non-finite input or output in a chunk, the
/// element loop takes over from the chunk's start so the error index and the
/// partial writes are exactly the element loop's.
///
/// # Safety
/// The pointers of `b` must satisfy the contract of [`RawBatch`].
#[inline]
#[allow(clippy::needless_range_loop)] // index loops over parallel arrays vectorise
pub(crate) unsafe fn eval_pointwise<L: Pointwise>(
    law: &L,
    b: &RawBatch,
) -> core::result::Result<(), BatchError> {
    const CHUNK: usize = 64;
    let mut d = [0.0f64; CHUNK];
    let mut f = [0.0f64; CHUNK];
    let mut a = [0.0f64; CHUNK];
    let mut k = [0.0f64; CHUNK];
    let mut start = 0;
    while start < b.n {
        let m = (b.n - start).min(CHUNK);
        for (j, dj) in d.iter_mut().enumerate().take(m) {
            *dj = b.delta.add(start + j).read();
        }
        let mut finite = true;
        for j in 0..m {
            let (fj, aj, kj) = law.point(d[j]);
            f[j] = fj;
            a[j] = aj;
            k[j] = kj;
            finite &= d[j].is_finite() & fj.is_finite() & aj.is_finite() & kj.is_finite();
        }
        if !finite {
            let rest = RawBatch {
                n: b.n - start,
                delta: b.delta.add(start),
                old_state: if b.old_state.is_null() {
                    b.old_state
                } else {
                    b.old_state.add(start)
                },
                new_state: if b.new_state.is_null() {
                    b.new_state
                } else {
                    b.new_state.add(start)
                },
                force: b.force.add(start),
                contact_radius: if b.contact_radius.is_null() {
                    b.contact_radius
                } else {
                    b.contact_radius.add(start)
                },
                stiffness: if b.stiffness.is_null() {
                    b.stiffness
                } else {
                    b.stiffness.add(start)
                },
            };
            return eval_elementwise(law, &rest).map_err(|e| BatchError {
                index: e.index + start,
                error: e.error,
            });
        }
        for j in 0..m {
            b.force.add(start + j).write(f[j]);
        }
        if !b.contact_radius.is_null() {
            for j in 0..m {
                b.contact_radius.add(start + j).write(a[j]);
            }
        }
        if !b.stiffness.is_null() {
            for j in 0..m {
                b.stiffness.add(start + j).write(k[j]);
            }
        }
        if !b.new_state.is_null() {
            for j in 0..m {
                b.new_state
                    .add(start + j)
                    .write(super::stateless(f[j], d[j], a[j], k[j]).1);
            }
        }
        start += m;
    }
    Ok(())
}
