//! Shared by the domain modules: the values an input decodes to (doubles
//! biased towards the ones that break numerical code, sizes, selectors,
//! NULL choices, profiles), the status checks that turn a library failure
//! into a finding, pointer helpers, and the inputs several domains use
//! (stored-JSON mutations, state buffers).

use arbitrary::{Arbitrary, Result as AResult, Unstructured};
use asperity::ffi::{
    asperity_last_error_message, asperity_status_string, ASPERITY_ERR_INTERNAL, ASPERITY_OK,
};
use std::ffi::{c_char, CStr};
use std::ptr::{null, null_mut};

// ------------------------------------------------------------------ values

/// A double biased towards the values that break numerical code.
#[derive(Debug, Clone, Copy)]
pub struct F(pub f64);

impl<'a> Arbitrary<'a> for F {
    fn arbitrary(u: &mut Unstructured<'a>) -> AResult<Self> {
        let tag: u8 = u.arbitrary()?;
        let sign = if tag & 0x80 != 0 { -1.0 } else { 1.0 };
        let v = match tag & 0x1f {
            0 => 0.0,
            1 => f64::NAN,
            2 => f64::INFINITY,
            3 => f64::MIN_POSITIVE,
            4 => 5e-324,
            5 => f64::MAX,
            6 => 1.0,
            7 => 0.5,
            8 => f64::EPSILON,
            9..=11 => {
                // Small values: ratios, Poisson's ratios, angles, fractions.
                let m: u16 = u.arbitrary()?;
                m as f64 / 1000.0
            }
            12..=23 => {
                // Log-uniform magnitude 1e-30 .. 1e30 with a 2-digit mantissa.
                let e: u8 = u.arbitrary()?;
                let m: u8 = u.arbitrary()?;
                (1.0 + m as f64 / 64.0) * 10f64.powi(e as i32 % 61 - 30)
            }
            24..=27 => {
                // Physical magnitudes of this library: nm .. GPa.
                let k: u8 = u.arbitrary()?;
                const P: [f64; 16] = [
                    1e-9, 3e-10, 1e-6, 1.5e-6, 5e-7, 1e-4, 1e-3, 0.3, 2.0, 10.0, 1e3, 1e6, 1e8,
                    1.2e11, 7e10, 0.05,
                ];
                P[k as usize % 16]
            }
            _ => return Ok(F(f64::from_bits(u.arbitrary()?))),
        };
        Ok(F(sign * v))
    }
}

/// An integer size where no caller buffer depends on it: small, or huge.
#[derive(Debug, Clone, Copy)]
pub struct Big(pub usize);

impl<'a> Arbitrary<'a> for Big {
    fn arbitrary(u: &mut Unstructured<'a>) -> AResult<Self> {
        let tag: u8 = u.arbitrary()?;
        Ok(Big(match tag % 12 {
            0..=5 => tag as usize % 20,
            6 => usize::MAX,
            7 => usize::MAX / 8 + 1,
            8 => 1 << 32,
            9 => 1 << 40,
            10 => u32::MAX as usize,
            _ => u.arbitrary::<u64>()? as usize,
        }))
    }
}

/// The length of a caller buffer: 0 ..= 256, mostly short.
#[derive(Debug, Clone, Copy)]
pub struct Len(pub usize);

impl<'a> Arbitrary<'a> for Len {
    fn arbitrary(u: &mut Unstructured<'a>) -> AResult<Self> {
        let tag: u8 = u.arbitrary()?;
        Ok(Len(if tag < 200 {
            tag as usize % 17
        } else {
            u.arbitrary::<u16>()? as usize % 257
        }))
    }
}

/// A selector (`int32_t` enum-like argument): near the valid range, or any.
#[derive(Debug, Clone, Copy)]
pub struct Sel(pub i32);

impl<'a> Arbitrary<'a> for Sel {
    fn arbitrary(u: &mut Unstructured<'a>) -> AResult<Self> {
        let tag: u8 = u.arbitrary()?;
        Ok(Sel(if tag < 224 {
            tag as i32 % 8 - 1
        } else {
            u.arbitrary()?
        }))
    }
}

/// Which pointer arguments are NULL: none most of the time, else by bit.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub struct Nulls(u8);

impl Nulls {
    pub(super) fn at(self, i: u32) -> bool {
        self.0 >= 0xe0 && (self.0 >> i) & 1 == 1
    }
}

/// A Lennard-Jones grid: small valid ones, and invalid ones.
#[derive(Debug, Clone, Copy)]
pub struct Grid(pub usize);

impl<'a> Arbitrary<'a> for Grid {
    fn arbitrary(u: &mut Unstructured<'a>) -> AResult<Self> {
        const G: [usize; 10] = [16, 24, 32, 48, 64, 1, 15, 16385, usize::MAX, 1 << 40];
        Ok(Grid(G[u.arbitrary::<u8>()? as usize % G.len()]))
    }
}

/// Heights of a profile: raw values, or a smooth wave with a little noise.
#[derive(Debug, Clone, Arbitrary)]
pub enum Heights {
    Raw(Vec<F>),
    Wave {
        n: Len,
        amplitude: F,
        k: u8,
        noise: u8,
    },
}

impl Heights {
    pub(super) fn make(&self) -> Vec<f64> {
        match self {
            Heights::Raw(v) => v.iter().map(|f| f.0).collect(),
            Heights::Wave {
                n,
                amplitude,
                k,
                noise,
            } => (0..n.0)
                .map(|j| {
                    let x = j as f64;
                    amplitude.0
                        * ((0.05 + *k as f64 / 40.0) * x).sin()
                        * (1.0 + *noise as f64 / 255.0 * (7.3 * x).cos())
                })
                .collect(),
        }
    }
}

pub(super) fn fs<const N: usize>(a: [F; N]) -> [f64; N] {
    a.map(|f| f.0)
}

// ------------------------------------------------------------------ checks

pub(super) fn last_message() -> String {
    let n = unsafe { asperity_last_error_message(null_mut(), 0) };
    let mut buf = vec![0 as c_char; n + 1];
    let m = unsafe { asperity_last_error_message(buf.as_mut_ptr(), buf.len()) };
    assert_eq!(m, n, "asperity_last_error_message: length changed");
    unsafe { CStr::from_ptr(buf.as_ptr()) }
        .to_string_lossy()
        .into_owned()
}

/// Triage: `ASPERITY_FUZZ_DEBUG=1` prints each call before it is made and
/// each error status with its message.
pub(super) fn debug() -> bool {
    static DEBUG: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *DEBUG.get_or_init(|| std::env::var_os("ASPERITY_FUZZ_DEBUG").is_some())
}

/// Check a status: a caught panic, an unknown code or an error without a
/// message is a finding. Returns true on `ASPERITY_OK`.
pub(super) fn ok(status: i32, what: &str) -> bool {
    if status == ASPERITY_OK {
        return true;
    }
    let msg = last_message();
    if debug() {
        eprintln!("  -> {what}: status {status}: {msg}");
    }
    if status == ASPERITY_ERR_INTERNAL {
        panic!("{what}: panic caught by the C guard: {msg}");
    }
    let s = unsafe { CStr::from_ptr(asperity_status_string(status)) };
    assert!(
        s.to_bytes() != b"unknown status",
        "{what}: unknown status {status}"
    );
    assert!(!msg.is_empty(), "{what}: status {status} without a message");
    false
}

/// A constructor writes NULL to its out-handle when it fails.
pub(super) fn made<T>(status: i32, p: *mut T, out_given: bool, what: &str) -> Option<*mut T> {
    if ok(status, what) {
        assert!(!p.is_null(), "{what}: OK with a NULL handle");
        Some(p)
    } else {
        if out_given {
            assert!(p.is_null(), "{what}: failed without writing NULL to *out");
        }
        None
    }
}

pub(super) fn cp<T>(x: &T, is_null: bool) -> *const T {
    if is_null {
        null()
    } else {
        x
    }
}

pub(super) fn mp<T>(x: &mut T, null: bool) -> *mut T {
    if null {
        null_mut()
    } else {
        x
    }
}

pub(super) fn bufp(v: &[f64], is_null: bool) -> *const f64 {
    if is_null {
        null()
    } else {
        v.as_ptr()
    }
}

pub(super) fn bufm(v: &mut [f64], null: bool) -> *mut f64 {
    if null {
        null_mut()
    } else {
        v.as_mut_ptr()
    }
}

pub(super) fn zeroed<T>() -> T {
    // SAFETY: used only for the library's repr(C) plain-old-data structs
    // (f64, integer and array fields), valid for the all-zero pattern.
    unsafe { core::mem::zeroed() }
}

pub(super) fn num(v: f64) -> String {
    // JSON has no NaN or infinity: write them as the tokens a careless
    // host would (a parse error), which is worth feeding too.
    if v.is_finite() {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

/// A change to a stored JSON text before it is loaded again.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Mutation {
    None,
    Byte { at: u16, value: u8 },
    Truncate { at: u16 },
    Number { at: u16, value: F },
}

impl Mutation {
    pub(super) fn apply(self, text: &mut Vec<u8>) {
        if text.is_empty() {
            return;
        }
        let n = text.len();
        match self {
            Mutation::None => {}
            Mutation::Byte { at, value } => text[at as usize % n] = value,
            Mutation::Truncate { at } => text.truncate(at as usize % n),
            Mutation::Number { at, value } => {
                // Replace the number that starts at or after `at`.
                let start =
                    (at as usize % n..n).find(|&i| text[i].is_ascii_digit() || text[i] == b'-');
                if let Some(s) = start {
                    let e = (s + 1..n)
                        .find(|&i| {
                            !matches!(text[i], b'0'..=b'9' | b'.' | b'e' | b'E' | b'-' | b'+')
                        })
                        .unwrap_or(n);
                    let v = num(value.0);
                    text.splice(s..e, v.bytes());
                }
            }
        }
    }
}

pub(super) fn json_of(
    len_needed: impl Fn(*mut c_char, usize, *mut usize) -> i32,
) -> Option<Vec<u8>> {
    let mut needed = 0usize;
    if !ok(len_needed(null_mut(), 0, &mut needed), "to_json size") {
        return None;
    }
    let mut buf = vec![0 as c_char; needed + 1];
    let mut again = 0usize;
    assert!(ok(
        len_needed(buf.as_mut_ptr(), buf.len(), &mut again),
        "to_json"
    ));
    assert_eq!(again, needed, "to_json: length changed");
    assert_eq!(buf[needed], 0, "to_json: no NUL");
    Some(buf[..needed].iter().map(|&c| c as u8).collect())
}

/// Slider state buffer contents.
#[derive(Debug, Clone, Arbitrary)]
pub enum SliderState {
    Zero,
    Carried,
    Raw(Vec<F>),
    Poked { at: u8, value: F },
}

/// A state of `m` doubles: zero, the carried one `carried` (when of that
/// length), raw values, or the carried one with one value replaced.
pub(super) fn make_state(carried: &[f64], state: &SliderState, m: usize) -> Vec<f64> {
    match state {
        SliderState::Zero => vec![0.0; m],
        SliderState::Carried if carried.len() == m => carried.to_vec(),
        SliderState::Carried => vec![0.0; m],
        SliderState::Raw(v) => (0..m).map(|i| v.get(i).map_or(0.0, |f| f.0)).collect(),
        SliderState::Poked { at, value } => {
            let mut s = if carried.len() == m {
                carried.to_vec()
            } else {
                vec![0.0; m]
            };
            if m > 0 {
                s[*at as usize % m] = value.0;
            }
            s
        }
    }
}
