//! Fuzz harness `c_abi`: the `extern "C"` entry points themselves
//! (`asperity::ffi::*`, the functions `libasperity` exports), called in an
//! arbitrary sequence with arbitrary doubles (NaN, ±inf, ±0, subnormals,
//! ±MAX, log-uniform magnitudes, raw bit patterns), integers (selectors out
//! of range, sizes 0 and huge where no caller buffer depends on them) and
//! NULL pointers, on handles the sequence created (laws, tables, homogenised
//! friction, slider geometries, empirical GW surfaces, sliders from scene
//! JSON and from structs and their work buffers, dynamic friction models),
//! freed at the end.
//!
//! Findings: any panic. The C guard catches a library panic and returns
//! `ASPERITY_ERR_INTERNAL`; the harness treats that status as a finding
//! (it panics with the message), as it does an error status without a
//! message, an unknown status code, and a constructor that fails without
//! writing NULL to its out-handle. For `asperity_dynamic_friction_step`
//! also: a failure that wrote `new_state` or `*out` (documented untouched),
//! and `ASPERITY_OK` with a negative `dissipated`.
//!
//! What the harness does not feed (caller undefined behaviour, outside the
//! contract): a pointer with a length longer than its buffer (every
//! pointer+length pair is a real buffer of that length, or NULL; a state
//! array is the model's or slider's state size), a freed or foreign handle,
//! a partially overlapping in/out pair where the library cannot detect it.
//! Inconsistent *counts* that the library can check (a PSD length other
//! than n/2+1, a rod-heights buffer shorter than the level, a work buffer of
//! another slider, a dynamic new state partially overlapping the old one)
//! are fed.
//!
//! Cost bounds (so an input runs in milliseconds): the Lennard-Jones entry
//! points get grids of at most 64 cells, or invalid ones (0 = the converged
//! default of up to 1024 cells, and the library's upper bound of 16384, are
//! not fed: see RELIABILITY.md), and Lennard-Jones tables valid tolerances
//! of at least 1e-5 only (1e-10 samples 10^5 solver points: seconds);
//! `asperity_fidelity_advise` is fed only
//! argument sets that its validation rejects (a valid set runs the
//! Lennard-Jones reference for seconds to minutes); scenes generate at most
//! 160-point profiles; `asperity_slider_new` gets geometries of at most 256
//! rods; sliders with more than 2^22 nano-asperities in all are built but not
//! stepped; a Prandtl–Tomlinson increment expected to take more than 2·10⁴
//! integration sub-steps (the library stops at 10⁶) runs once per input,
//! like the other expensive calls.
//!
//! Shared by `fuzz/fuzz_targets/c_abi.rs` (libFuzzer) and
//! `tests/fuzz_corpus.rs` (corpus replay on stable).

#![allow(clippy::too_many_arguments)]

use arbitrary::{Arbitrary, Result as AResult, Unstructured};
use asperity::contact::{ContactState, NormalResponse};
use asperity::ffi::abi::*;
use asperity::ffi::contact::*;
use asperity::ffi::dynamic::*;
use asperity::ffi::fidelity::*;
use asperity::ffi::friction::*;
use asperity::ffi::homogenised::*;
use asperity::ffi::indentation::*;
use asperity::ffi::lj_sphere::*;
use asperity::ffi::material::*;
use asperity::ffi::slider::*;
use asperity::ffi::statistics::*;
use asperity::ffi::surface::*;
use asperity::ffi::tabulated::*;
use asperity::ffi::{
    asperity_last_error_message, asperity_status_string, asperity_version, ASPERITY_ERR_INTERNAL,
    ASPERITY_OK,
};
use asperity::friction::dynamic::{DynamicIncrement, DynamicResponse};
use asperity::friction::{
    Dissipation, FrictionIncrement, FrictionMaterial, FrictionPointState, FrictionResponse,
    HomogenisedSample, SliderResponse,
};
use std::ffi::{c_char, c_void, CStr};
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
    fn at(self, i: u32) -> bool {
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
    fn make(&self) -> Vec<f64> {
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

fn fs<const N: usize>(a: [F; N]) -> [f64; N] {
    a.map(|f| f.0)
}

// ------------------------------------------------------------------ checks

fn last_message() -> String {
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
fn debug() -> bool {
    static DEBUG: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    *DEBUG.get_or_init(|| std::env::var_os("ASPERITY_FUZZ_DEBUG").is_some())
}

/// Check a status: a caught panic, an unknown code or an error without a
/// message is a finding. Returns true on `ASPERITY_OK`.
fn ok(status: i32, what: &str) -> bool {
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
fn made<T>(status: i32, p: *mut T, out_given: bool, what: &str) -> Option<*mut T> {
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

fn cp<T>(x: &T, is_null: bool) -> *const T {
    if is_null {
        null()
    } else {
        x
    }
}

fn mp<T>(x: &mut T, null: bool) -> *mut T {
    if null {
        null_mut()
    } else {
        x
    }
}

fn bufp(v: &[f64], is_null: bool) -> *const f64 {
    if is_null {
        null()
    } else {
        v.as_ptr()
    }
}

fn bufm(v: &mut [f64], null: bool) -> *mut f64 {
    if null {
        null_mut()
    } else {
        v.as_mut_ptr()
    }
}

fn zeroed<T>() -> T {
    // SAFETY: used only for the library's repr(C) plain-old-data structs
    // (f64, integer and array fields), valid for the all-zero pattern.
    unsafe { core::mem::zeroed() }
}

// ------------------------------------------------------------------ inputs

#[derive(Debug, Clone, Copy, Arbitrary)]
pub struct State {
    contact_radius: F,
    cohesive_radius: F,
    in_contact: Sel,
    branch: Sel,
}

impl State {
    fn get(&self) -> ContactState {
        ContactState {
            contact_radius: self.contact_radius.0,
            cohesive_radius: self.cohesive_radius.0,
            in_contact: self.in_contact.0,
            branch: self.branch.0,
        }
    }
}

/// Where the old contact state comes from.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum OldState {
    Null,
    Fresh,
    Carried,
    Given(State),
}

#[derive(Debug, Clone, Copy, Arbitrary)]
pub struct PointState {
    force: [F; 2],
    slip_path: F,
    dissipation: [F; 4],
    steps: u64,
}

impl PointState {
    fn get(&self) -> FrictionPointState {
        let d = fs(self.dissipation);
        FrictionPointState {
            force: fs(self.force),
            slip_path: self.slip_path.0,
            dissipation: Dissipation {
                chemical: d[0],
                van_der_waals: d[1],
                elastic: d[2],
                plastic: d[3],
            },
            steps: self.steps,
        }
    }
}

#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum OldPoint {
    Null,
    Fresh,
    Carried,
    Given(PointState),
}

/// A scene for `asperity_slider_from_scene_json`: each number is the value
/// of `examples/scenes/chapter6_copper.json` (smaller surfaces) unless given.
#[derive(Debug, Clone, Arbitrary)]
pub struct SceneSpec {
    hurst: Option<F>,
    rq: Option<F>,
    roll_off: Option<F>,
    slider_points: u8,
    counter_points: u8,
    dx: Option<F>,
    seeds: (u8, u8),
    nano: [Option<F>; 5],
    widths: Option<Vec<F>>,
    depth: Option<F>,
    load: Option<F>,
    loading: u8,
    mechanisms: u8,
    cof_form: u8,
    periodic: bool,
    plastic: u8,
    dense: bool,
}

fn num(v: f64) -> String {
    // JSON has no NaN or infinity: write them as the tokens a careless
    // host would (a parse error), which is worth feeding too.
    if v.is_finite() {
        format!("{v:e}")
    } else {
        format!("{v}")
    }
}

impl SceneSpec {
    fn json(&self) -> String {
        let g = |o: &Option<F>, d: f64| num(o.map_or(d, |f| f.0));
        let nano_d = [6e-9, 4.3e-7, 2.2e-9, 1.61e-7, 1.35e-6];
        let nano: Vec<String> = ["h_vdw", "w_vdw", "h_chem", "w_chem", "spacing"]
            .iter()
            .zip(self.nano.iter().zip(nano_d))
            .map(|(k, (o, d))| format!("\"{k}\": {}", g(o, d)))
            .collect();
        let widths = match &self.widths {
            None => "[1.5e-6]".to_string(),
            Some(w) => format!(
                "[{}]",
                w.iter()
                    .take(4)
                    .map(|f| num(f.0))
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
        };
        let loading = match self.loading % 3 {
            0 => format!(
                "{{ \"fixed_load\": {{ \"load\": {} }} }}",
                g(&self.load, 0.18)
            ),
            1 => format!(
                "{{ \"fixed_load_fraction\": {{ \"fraction\": {} }} }}",
                g(&self.load, 0.35)
            ),
            _ => format!(
                "{{ \"fixed_gap\": {{ \"position\": {} }} }}",
                g(&self.load, 0.0)
            ),
        };
        let m = self.mechanisms;
        let plastic = match self.plastic % 3 {
            0 => "\"shorten_only\"".to_string(),
            1 => "\"nearest_neighbours\"".to_string(),
            _ => format!(
                "{{ \"gaussian\": {{ \"width\": {} }} }}",
                g(&self.depth, 2.0)
            ),
        };
        let surface = |points: u8, seed: u8| {
            format!(
                "{{ \"self_affine\": {{ \"hurst\": {}, \"rq\": {}, \"roll_off_wavelength\": {}, \"points\": {}, \"dx\": {}, \"seed\": {} }} }}",
                g(&self.hurst, 0.8),
                g(&self.rq, 5e-7),
                g(&self.roll_off, 1e-4),
                points as usize % 160,
                g(&self.dx, 1.5e-6),
                seed
            )
        };
        format!(
            "{{ \"material\": {{ \"preset\": \"copper\" }}, \"surfaces\": {{ \"slider\": {}, \"counter\": {}, \"nano\": {{ \"asperities\": {{ {} }} }} }}, \"rods\": {{ \"widths\": {}, \"depth\": {}, \"plastic\": {}, \"solver\": \"{}\" }}, \"mechanisms\": {{ \"chemical\": {}, \"van_der_waals\": {}, \"elastic\": {}, \"plastic\": {} }}, \"cof_form\": \"{}\", \"loading\": {}, \"sliding\": {{ \"distance\": 1.5e-4, \"step\": 1.5e-6, \"track_end\": \"{}\" }}, \"outputs\": {{ \"csv\": false, \"svg\": false }} }}",
            surface(self.slider_points, self.seeds.0),
            surface(self.counter_points, self.seeds.1),
            nano.join(", "),
            widths,
            g(&self.depth, 1.35e-5),
            plastic,
            if self.dense { "dense" } else { "sweep" },
            m & 1 != 0,
            m & 2 != 0,
            m & 4 != 0,
            m & 8 != 0,
            ["Derjaguin", "Amontons", "Bowden"][self.cof_form as usize % 3],
            loading,
            if self.periodic { "periodic" } else { "error" },
        )
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
    fn apply(self, text: &mut Vec<u8>) {
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

/// Hand-written homogenised samples that pass validation unless a value is
/// replaced.
#[derive(Debug, Clone, Arbitrary)]
pub struct SampleSpec {
    n: u8,
    first_pressure: F,
    cof: F,
    adhesion: F,
    fraction: F,
    replace: Option<(u8, F)>,
}

impl SampleSpec {
    fn make(&self) -> Vec<HomogenisedSample> {
        let n = self.n as usize % 8 + 1;
        let p0 = self.first_pressure.0.abs();
        let mut v: Vec<HomogenisedSample> = (0..n)
            .map(|i| HomogenisedSample {
                pressure: p0 * (1.0 + i as f64),
                cof: self.cof.0.abs().min(1e3),
                adhesion_pressure: self.adhesion.0.abs(),
                contact_fraction: self.fraction.0.abs().min(1.0),
                shares: Dissipation {
                    chemical: 0.25,
                    van_der_waals: 0.25,
                    elastic: 0.25,
                    plastic: 0.25,
                },
            })
            .collect();
        if let Some((k, f)) = self.replace {
            let s = &mut v[k as usize % n];
            match k / 16 % 6 {
                0 => s.pressure = f.0,
                1 => s.cof = f.0,
                2 => s.adhesion_pressure = f.0,
                3 => s.contact_fraction = f.0,
                4 => s.shares.elastic = f.0,
                _ => s.shares.chemical = f.0,
            }
        }
        v
    }
}

/// A loading–unloading curve P = c δ^m, then a power-law unloading, with
/// optional raw replacements.
#[derive(Debug, Clone, Arbitrary)]
pub struct CurveSpec {
    loading: u8,
    unloading: u8,
    depth: F,
    c: F,
    m: u8,
    recovery: u8,
    replace: Option<(u8, F, bool)>,
}

impl CurveSpec {
    fn make(&self) -> (Vec<f64>, Vec<f64>) {
        let nl = self.loading as usize % 60 + 1;
        let nu = self.unloading as usize % 60;
        let hmax = self.depth.0.abs();
        let m = 1.0 + self.m as f64 / 128.0;
        let c = self.c.0.abs();
        let hf = hmax * self.recovery as f64 / 300.0;
        let mut d = Vec::new();
        let mut p = Vec::new();
        for i in 1..=nl {
            let h = hmax * i as f64 / nl as f64;
            d.push(h);
            p.push(c * h.powf(m));
        }
        let pmax = c * hmax.powf(m);
        for i in 1..=nu {
            let h = hmax - (hmax - hf) * i as f64 / nu as f64;
            d.push(h);
            p.push(pmax * ((h - hf) / (hmax - hf)).max(0.0).powf(1.5));
        }
        if let Some((k, f, depth)) = self.replace {
            let i = k as usize % d.len();
            if depth {
                d[i] = f.0;
            } else {
                p[i] = f.0;
            }
        }
        (d, p)
    }
}

#[derive(Debug, Clone, Arbitrary)]
pub struct OptionsSpec {
    indenter: Sel,
    anchor: Sel,
    use_labels: Sel,
    n_area: Sel,
    area: [F; 8],
    radius: F,
    angle: F,
    known: (Sel, Sel, F, F),
    anchor_index: Big,
    moduli: [F; 3],
    beta: F,
    epsilon: F,
    windows: [F; 4],
    which: u16,
}

impl OptionsSpec {
    /// The defaults with the fields selected by `which` replaced.
    fn apply(&self, o: &mut AsperityIndentationOptions) {
        let w = |i: u32| self.which >> i & 1 == 1;
        if w(0) {
            o.indenter = self.indenter.0;
        }
        if w(1) {
            o.anchor = self.anchor.0;
        }
        if w(2) {
            o.use_labels = self.use_labels.0;
        }
        if w(3) {
            o.n_area_coefficients = self.n_area.0;
            o.area_coefficients = fs(self.area);
        }
        if w(4) {
            o.sphere_radius = self.radius.0;
            o.cone_half_angle = self.angle.0;
        }
        if w(5) {
            o.has_known_d = self.known.0 .0;
            o.has_known_kappa = self.known.1 .0;
            o.known_d = self.known.2 .0;
            o.known_kappa = self.known.3 .0;
        }
        if w(6) {
            o.anchor_index = self.anchor_index.0;
        }
        if w(7) {
            o.e_indenter = self.moduli[0].0;
            o.nu_indenter = self.moduli[1].0;
            o.nu_sample = self.moduli[2].0;
        }
        if w(8) {
            o.beta = self.beta.0;
            o.epsilon = self.epsilon.0;
        }
        if w(9) {
            let v = fs(self.windows);
            o.loading_window = [v[0], v[1]];
            o.unloading_window = [v[2], v[3]];
        }
    }
}

/// Slider state buffer contents.
#[derive(Debug, Clone, Arbitrary)]
pub enum SliderState {
    Zero,
    Carried,
    Raw(Vec<F>),
    Poked { at: u8, value: F },
}

#[derive(Debug, Clone, Arbitrary)]
pub struct GwSpec {
    distribution: Sel,
    v: [F; 4],
}

impl GwSpec {
    fn get(&self) -> AsperityGwParams {
        AsperityGwParams {
            distribution: self.distribution.0,
            reserved: 0,
            summit_count: self.v[0].0,
            radius: self.v[1].0,
            sigma: self.v[2].0,
            e_star: self.v[3].0,
        }
    }
}

unsafe extern "C" fn density_const(_xi: f64, data: *mut c_void) -> f64 {
    *(data as *const f64)
}

unsafe extern "C" fn density_linear(xi: f64, data: *mut c_void) -> f64 {
    *(data as *const f64) * xi
}

unsafe extern "C" fn density_step(xi: f64, data: *mut c_void) -> f64 {
    if xi < *(data as *const f64) {
        0.0
    } else {
        1e12
    }
}

fn density(sel: u8) -> AsperitySummitDensity {
    match sel % 4 {
        0 => None,
        1 => Some(density_const),
        2 => Some(density_linear),
        _ => Some(density_step),
    }
}

/// The friction material of `asperity_slider_new`: the C copper preset,
/// the preset with fields replaced, or raw values.
#[derive(Debug, Clone, Arbitrary)]
pub enum MaterialSpec {
    Copper,
    Poked(Vec<(u8, F)>),
    Raw([F; 12]),
}

impl MaterialSpec {
    /// The material (through `asperity_friction_material_copper`).
    unsafe fn get(&self) -> FrictionMaterial {
        let mut m: FrictionMaterial = zeroed();
        assert!(ok(
            asperity_friction_material_copper(&mut m),
            "friction_material_copper"
        ));
        let field = |m: &mut FrictionMaterial, k: u8| -> *mut f64 {
            match k % 12 {
                0 => &mut m.yield_stress,
                1 => &mut m.youngs_modulus,
                2 => &mut m.poisson_ratio,
                3 => &mut m.counter_youngs_modulus,
                4 => &mut m.counter_poisson_ratio,
                5 => &mut m.bond_diameter,
                6 => &mut m.chemical_bond_energy,
                7 => &mut m.vdw_bond_energy,
                8 => &mut m.work_of_adhesion,
                9 => &mut m.adhesive_layer,
                10 => &mut m.threshold_strain,
                _ => &mut m.areal_density,
            }
        };
        match self {
            MaterialSpec::Copper => {}
            MaterialSpec::Poked(v) => {
                for &(k, f) in v.iter().take(3) {
                    *field(&mut m, k) = f.0;
                }
            }
            MaterialSpec::Raw(v) => {
                for (k, f) in v.iter().enumerate() {
                    *field(&mut m, k as u8) = f.0;
                }
            }
        }
        m
    }
}

/// `AsperitySliderOptions`: the C defaults with the fields selected by
/// `which` replaced.
#[derive(Debug, Clone, Arbitrary)]
pub struct SliderOptionsSpec {
    which: u16,
    normal_force: F,
    gap: F,
    plastic_width: F,
    depth: F,
    root_margin: F,
    control: Sel,
    mechanisms: u8,
    cof_form: Sel,
    plastic: Sel,
    solver: Sel,
    periodic: Sel,
}

impl SliderOptionsSpec {
    /// The options (through `asperity_slider_options_default`).
    unsafe fn get(&self) -> AsperitySliderOptions {
        let mut o: AsperitySliderOptions = zeroed();
        assert!(ok(
            asperity_slider_options_default(&mut o),
            "slider_options_default"
        ));
        let w = |i: u32| self.which >> i & 1 == 1;
        if w(0) {
            o.normal_force = self.normal_force.0;
        }
        if w(1) {
            o.gap = self.gap.0;
        }
        if w(2) {
            o.plastic_width = self.plastic_width.0;
        }
        if w(3) {
            o.depth = self.depth.0;
        }
        if w(4) {
            o.root_margin = self.root_margin.0;
        }
        if w(5) {
            o.control = self.control.0;
        }
        if w(6) {
            // -1 ..= 16: every valid bit set, and two invalid ones.
            o.mechanisms = self.mechanisms as i32 % 18 - 1;
        }
        if w(7) {
            o.cof_form = self.cof_form.0;
        }
        if w(8) {
            o.plastic = self.plastic.0;
        }
        if w(9) {
            o.solver = self.solver.0;
        }
        if w(10) {
            o.periodic = self.periodic.0;
        }
        o
    }
}

/// LuGre parameters: the valid set of `tests/ffi_dynamic.rs`, that set with
/// one field replaced, or raw values.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum LugreSpec {
    Valid,
    Poked { at: u8, value: F },
    Raw([F; 8]),
}

impl LugreSpec {
    fn get(&self) -> AsperityLugreParams {
        let mut v = [0.3, 0.5, 1e-3, 2.0, 1e5, 1000.0, 1e-3, 0.4];
        match self {
            LugreSpec::Valid => {}
            LugreSpec::Poked { at, value } => v[*at as usize % 8] = value.0,
            LugreSpec::Raw(r) => v = fs(*r),
        }
        AsperityLugreParams {
            mu_coulomb: v[0],
            mu_static: v[1],
            stribeck_velocity: v[2],
            stribeck_exponent: v[3],
            sigma0: v[4],
            sigma1: v[5],
            damping_velocity: v[6],
            sigma2: v[7],
        }
    }
}

/// Maxwell-slip elements: `n` valid ones (stiffnesses 2e5/2^i, break-away
/// coefficients 0.2/(i+1)), those with one value replaced, or raw pairs.
/// The arrays are real buffers of `n` values (at most 256).
#[derive(Debug, Clone, Arbitrary)]
pub enum MaxwellSpec {
    Valid {
        n: u8,
    },
    Poked {
        n: u8,
        at: u8,
        value: F,
        capacity: bool,
    },
    Raw(Vec<(F, F)>),
}

impl MaxwellSpec {
    fn make(&self) -> (Vec<f64>, Vec<f64>) {
        let valid = |n: u8| -> (Vec<f64>, Vec<f64>) {
            let n = n as usize % 12;
            (
                (0..n).map(|i| 2e5 / (1u64 << i) as f64).collect(),
                (0..n).map(|i| 0.2 / (i + 1) as f64).collect(),
            )
        };
        match self {
            MaxwellSpec::Valid { n } => valid(*n),
            MaxwellSpec::Poked {
                n,
                at,
                value,
                capacity,
            } => {
                let (mut k, mut m) = valid(*n);
                if !k.is_empty() {
                    let i = *at as usize % k.len();
                    if *capacity {
                        m[i] = value.0;
                    } else {
                        k[i] = value.0;
                    }
                }
                (k, m)
            }
            MaxwellSpec::Raw(v) => v.iter().take(256).map(|(a, b)| (a.0, b.0)).unzip(),
        }
    }
}

/// Prandtl–Tomlinson parameters (U0, a, k, m, gamma, tolerance): the valid
/// AFM-tip set of `tests/ffi_dynamic.rs`, that set with one value replaced,
/// or raw values.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum PtSpec {
    Valid,
    Poked { at: u8, value: F },
    Raw([F; 6]),
}

impl PtSpec {
    fn get(&self) -> [f64; 6] {
        let mut v = [2e-21, 3e-10, 1.0, 1e-12, 1e-6, 1e-9];
        match self {
            PtSpec::Valid => {}
            PtSpec::Poked { at, value } => v[*at as usize % 6] = value.0,
            PtSpec::Raw(r) => v = fs(*r),
        }
        v
    }
}

/// Nine parameters of a struct-built model (two-spring Prandtl–Tomlinson,
/// Burridge–Knopoff): the valid set given, that set with one value
/// replaced, or raw values.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum NineSpec {
    Valid,
    Poked { at: u8, value: F },
    Raw([F; 9]),
}

impl NineSpec {
    fn get(&self, valid: [f64; 9]) -> [f64; 9] {
        match self {
            NineSpec::Valid => valid,
            NineSpec::Poked { at, value } => {
                let mut v = valid;
                v[*at as usize % 9] = value.0;
                v
            }
            NineSpec::Raw(r) => fs(*r),
        }
    }
}

/// Which integrated model [`Op::PtNew`] builds.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Integrated {
    OneSpring,
    TwoSpring { params: NineSpec, null: bool },
    Chain { params: NineSpec, null: bool },
}

/// The geometry of `asperity_slider_new`: one the input made, or a uniform
/// one made here (`rods` % 16 + 1 rods of 1.5 µm with the chapter-6
/// nano-asperities, one value replaced when `poke` is given).
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum GeometrySource {
    Table(u8),
    Uniform { rods: u8, poke: Option<(u8, F)> },
}

/// A dynamic-friction increment: valid (N = 1 N, a slip of a few µm in a
/// direction set by `k`, Δt = 1 ms), that with one value replaced, or raw
/// values (N, slip x, slip y, Δt).
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum DynIncSpec {
    Valid { k: u8 },
    Poked { k: u8, at: u8, value: F },
    Raw([F; 4]),
}

impl DynIncSpec {
    fn get(&self) -> [f64; 4] {
        let valid = |k: u8| {
            let th = 0.7 * k as f64;
            [1.0, 2e-6 * th.cos(), 1e-6 * th.sin(), 1e-3]
        };
        match *self {
            DynIncSpec::Valid { k } => valid(k),
            DynIncSpec::Poked { k, at, value } => {
                let mut v = valid(k);
                v[at as usize % 4] = value.0;
                v
            }
            DynIncSpec::Raw(r) => fs(r),
        }
    }
}

/// How the new state of a dynamic step is placed against the old one.
#[derive(Debug, Clone, Copy, Arbitrary)]
pub enum Placement {
    Apart,
    InPlace,
    /// `new_state` = `old_state` + 1 + k % (m − 1) doubles: a partial
    /// overlap, which the library detects (an error naming `new_state`).
    Overlap(u8),
}

// ------------------------------------------------------------------ calls

/// One call (or a few related calls) of the C ABI.
#[derive(Debug, Clone, Arbitrary)]
pub enum Op {
    // Library, status and layout queries.
    Version,
    LastError {
        len: Len,
        null: bool,
    },
    StatusString(i32),
    TypeLayout {
        index: Big,
        name: Option<Vec<u8>>,
        nulls: Nulls,
    },
    TypeName {
        index: Big,
        len: Len,
        nulls: Nulls,
    },
    FlagName(u32),
    // Laws.
    Law {
        which: u8,
        a: [F; 5],
        sel: Sel,
        null: bool,
    },
    LawRaw {
        kind: Sel,
        raw: [F; 16],
    },
    LawTamper {
        law: u8,
        at: u8,
        value: F,
    },
    Eval {
        law: u8,
        delta: F,
        old: OldState,
        nulls: Nulls,
        alias: bool,
    },
    EvalBatch {
        law: u8,
        delta: Vec<F>,
        old: OldState,
        nulls: Nulls,
        alias: bool,
    },
    EvalAtLoad {
        law: u8,
        force: F,
        null: bool,
    },
    PullOff {
        law: u8,
        control: Sel,
        null: bool,
    },
    LengthScale {
        law: u8,
        null: bool,
    },
    // Tables.
    TableMd {
        a: [F; 5],
        null: bool,
    },
    TableLj {
        a: [F; 4],
        grid: Grid,
        tolerance: F,
        null: bool,
    },
    TableEval {
        table: u8,
        delta: F,
        old: OldState,
        nulls: Nulls,
    },
    TableEvalBatch {
        table: u8,
        delta: Vec<F>,
        old: OldState,
        nulls: Nulls,
        alias: bool,
    },
    TableEvalAtLoad {
        table: u8,
        force: F,
        null: bool,
    },
    TablePullOff {
        table: u8,
        control: Sel,
        null: bool,
    },
    TableMaxError {
        table: u8,
        nulls: Nulls,
    },
    TableToJson {
        table: u8,
        len: Len,
        nulls: Nulls,
    },
    TableFromJson {
        table: u8,
        mutation: Mutation,
        raw: Option<Vec<u8>>,
        nulls: Nulls,
    },
    TableFree {
        table: u8,
    },
    // Models, materials, Lennard-Jones.
    Fidelity {
        a: [F; 5],
        null: bool,
    },
    LjPullOff {
        a: [F; 4],
        grid: Grid,
        null: bool,
    },
    Material {
        which: u8,
        a: [F; 6],
        sel: Sel,
        null: bool,
    },
    // Indentation and rescaling.
    DefaultOptions {
        null: bool,
    },
    IndentFit {
        curve: CurveSpec,
        segments: Option<Vec<Sel>>,
        options: Option<OptionsSpec>,
        nulls: Nulls,
    },
    IndentFitRaw {
        depth: Vec<F>,
        load: Vec<F>,
        nulls: Nulls,
    },
    Rescaling {
        which: u8,
        a: [F; 6],
        null: bool,
    },
    // Statistics.
    Gw {
        gw: GwSpec,
        x: F,
        nulls: Nulls,
    },
    GwBatch {
        gw: GwSpec,
        x: Vec<F>,
        nulls: Nulls,
        alias: bool,
    },
    GwAtLoad {
        gw: GwSpec,
        load: F,
        nulls: Nulls,
    },
    GwPlasticity {
        gw: GwSpec,
        hardness: F,
        nulls: Nulls,
    },
    Plasticity {
        a: [F; 4],
        null: bool,
    },
    Regime {
        psi: F,
        null: bool,
    },
    GwEmpiricalNew {
        a: [F; 3],
        heights: Heights,
        radii: Option<Vec<F>>,
        nulls: Nulls,
    },
    GwEmpirical {
        gw: u8,
        which: u8,
        x: F,
        n: Vec<F>,
        nulls: Nulls,
    },
    GwEmpiricalFree {
        gw: u8,
    },
    Zhuravlev {
        model: [F; 4],
        which: u8,
        a: [F; 4],
        nulls: Nulls,
    },
    ZhuravlevEval {
        model: [F; 4],
        approach: F,
        n1: (u8, F),
        n2: (u8, F),
        order: Big,
        nulls: Nulls,
    },
    // Surfaces.
    Roughness {
        h: Heights,
        dx: F,
        form: Sel,
        cutoff: F,
        sampling: F,
        nulls: Nulls,
    },
    RemoveForm {
        h: Heights,
        form: Sel,
        nulls: Nulls,
        alias: bool,
    },
    Filter {
        h: Heights,
        dx: F,
        cutoff: F,
        ends: Sel,
        nulls: Nulls,
        alias: bool,
    },
    MaterialRatio {
        h: Heights,
        points: Len,
        nulls: Nulls,
    },
    Psd {
        h: Heights,
        dx: F,
        window: Sel,
        n_q: Option<Len>,
        nulls: Nulls,
    },
    HurstFit {
        h: Heights,
        dx: F,
        q: [F; 2],
        nulls: Nulls,
    },
    Peaks {
        h: Heights,
        dx: F,
        nulls: Nulls,
    },
    SelfAffine {
        a: [F; 5],
        seed: u64,
        n: Len,
        null: bool,
    },
    Weierstrass {
        a: [F; 4],
        seed: u64,
        n: Len,
        null: bool,
    },
    Cantor {
        descendants: u32,
        a: [F; 4],
        levels: u32,
        n: Len,
        null: bool,
    },
    // Slider geometry.
    GeometryNew {
        micro: Heights,
        micro_dx: F,
        nano: Heights,
        nano_dx: F,
        widths: Vec<F>,
        nulls: Nulls,
    },
    GeometryUniform {
        width: F,
        rods: Big,
        nano: [F; 5],
        per_rod: Big,
        nulls: Nulls,
    },
    GeometryQuery {
        geometry: u8,
        which: u8,
        level: Big,
        len: Len,
        nulls: Nulls,
    },
    GeometryFree {
        geometry: u8,
    },
    // Homogenised friction.
    HomNew {
        samples: SampleSpec,
        nulls: Nulls,
    },
    HomNewRaw {
        samples: Vec<[F; 8]>,
        nulls: Nulls,
    },
    HomFromJson {
        friction: u8,
        mutation: Mutation,
        raw: Option<Vec<u8>>,
        nulls: Nulls,
    },
    HomToJson {
        friction: u8,
        len: Len,
        nulls: Nulls,
    },
    HomStep {
        friction: u8,
        inc: [F; 6],
        old: OldPoint,
        nulls: Nulls,
        alias: bool,
    },
    HomBlock {
        friction: u8,
        n: u8,
        inc: Vec<F>,
        dt: F,
        k: F,
        old: OldPoint,
        nulls: Nulls,
        alias: bool,
    },
    HomStateSize,
    HomFree {
        friction: u8,
    },
    // Slider.
    SliderNew {
        scene: SceneSpec,
        mutation: Mutation,
        base: u8,
        nulls: Nulls,
    },
    SliderQuery {
        slider: u8,
        which: u8,
        null: bool,
    },
    WorkNew {
        slider: u8,
        null: bool,
    },
    SliderStep {
        slider: u8,
        work: u8,
        inc: [F; 5],
        control: Sel,
        tangents: Sel,
        state: SliderState,
        in_place: bool,
        nulls: Nulls,
    },
    SliderBlock {
        slider: u8,
        work: u8,
        n: u8,
        inc: Vec<F>,
        dt: F,
        state: SliderState,
        in_place: bool,
        nulls: Nulls,
    },
    SliderFree {
        slider: u8,
    },
    WorkFree {
        work: u8,
    },
    // Slider from structs.
    SliderOptionsDefault {
        null: bool,
    },
    MaterialCopper {
        null: bool,
    },
    SliderFromStructs {
        geometry: GeometrySource,
        material: MaterialSpec,
        counter: Option<(Heights, F)>,
        options: Option<SliderOptionsSpec>,
        nulls: Nulls,
    },
    // Dynamic friction.
    LugreNew {
        params: LugreSpec,
        nulls: Nulls,
    },
    /// Maxwell-slip elements, or bristles (the second array as break
    /// deflections, m) when `bristles`.
    MaxwellNew {
        elements: MaxwellSpec,
        sigma2: F,
        nulls: Nulls,
        bristles: bool,
    },
    /// An integrated model: one-spring Prandtl–Tomlinson (`params`), or
    /// the struct-built two-spring model or Burridge–Knopoff chain. (New
    /// models extend these payloads rather than `Op`: a new variant would
    /// change how every committed input decodes.)
    PtNew {
        params: PtSpec,
        null: bool,
        variant: Integrated,
    },
    DynStateSize {
        model: u8,
        null: bool,
    },
    DynStep {
        model: u8,
        inc: DynIncSpec,
        tangents: Sel,
        reserved: Sel,
        state: SliderState,
        placement: Placement,
        nulls: Nulls,
    },
    DynBlock {
        model: u8,
        n: u8,
        inc: Vec<F>,
        dt: Option<F>,
        state: SliderState,
        nulls: Nulls,
    },
    DynFree {
        model: u8,
    },
    // Reach and energy (added last: the existing corpus keeps its meaning).
    Reach {
        law: u8,
        control: Sel,
        rel_force: F,
        null: bool,
    },
    Energy {
        law: u8,
        delta: F,
        old: OldState,
        null: bool,
    },
    TableReach {
        table: u8,
        control: Sel,
        rel_force: F,
        null: bool,
    },
}

/// A dynamic friction model the input made, and for a Prandtl–Tomlinson tip
/// what bounds the cost of its steps.
struct Dynamic {
    model: *mut AsperityDynamicFriction,
    /// Prandtl–Tomlinson: its parameters (U0, a, k, m, gamma, tolerance),
    /// for [`pt_substeps`]; `None` for the other models (cheap steps).
    pt: Option<[f64; 6]>,
    /// The two-spring Prandtl–Tomlinson model and the Burridge–Knopoff
    /// chain: integrated, without a cost estimate here, so stepped once
    /// per input (the library bounds each integration).
    heavy: bool,
}

/// The handles and carried states of one input; all freed on drop.
#[derive(Default)]
struct Ctx {
    laws: Vec<AsperityNormalLaw>,
    state: ContactState,
    tables: Vec<*mut AsperityTable>,
    gws: Vec<*mut AsperityGwEmpirical>,
    geometries: Vec<*mut AsperitySliderGeometry>,
    frictions: Vec<*mut AsperityHomogenisedFriction>,
    point: FrictionPointState,
    sliders: Vec<*mut AsperitySlider>,
    works: Vec<*mut AsperitySliderWork>,
    slider_state: Vec<f64>,
    dynamics: Vec<Dynamic>,
    dynamic_state: Vec<f64>,
    expensive: u32,
}

impl Drop for Ctx {
    fn drop(&mut self) {
        unsafe {
            self.tables.drain(..).for_each(|p| asperity_table_free(p));
            self.gws
                .drain(..)
                .for_each(|p| asperity_gw_empirical_free(p));
            self.geometries
                .drain(..)
                .for_each(|p| asperity_slider_geometry_free(p));
            self.frictions
                .drain(..)
                .for_each(|p| asperity_homogenised_friction_free(p));
            self.works
                .drain(..)
                .for_each(|p| asperity_slider_work_free(p));
            self.sliders.drain(..).for_each(|p| asperity_slider_free(p));
            self.dynamics
                .drain(..)
                .for_each(|d| asperity_dynamic_friction_free(d.model));
        }
    }
}

/// Element `sel` of `v`, or NULL for 255 or an empty `v`.
fn pick<T>(v: &[*mut T], sel: u8) -> *mut T {
    if sel == 255 || v.is_empty() {
        null_mut()
    } else {
        v[sel as usize % v.len()]
    }
}

fn take<T>(v: &mut Vec<*mut T>, sel: u8) -> Option<*mut T> {
    if v.is_empty() {
        None
    } else {
        let i = sel as usize % v.len();
        Some(v.swap_remove(i))
    }
}

impl Ctx {
    /// Whether a call of about `substeps` integration sub-steps may run: a
    /// cheap one always, an expensive one once per input (the library's own
    /// bound, `MAX_SUBSTEPS` = 10^6 per integration, makes each call take up
    /// to a second).
    fn affordable(&mut self, substeps: f64) -> bool {
        if substeps <= 2e4 {
            return true;
        }
        if self.expensive > 0 {
            return false;
        }
        self.expensive += 1;
        true
    }
}

fn law(ctx: &Ctx, sel: u8) -> AsperityNormalLaw {
    if sel == 255 || ctx.laws.is_empty() {
        // An all-zero law: kind ASPERITY_LAW_NONE.
        zeroed()
    } else {
        ctx.laws[sel as usize % ctx.laws.len()]
    }
}

fn old_state(ctx: &Ctx, old: OldState) -> (ContactState, bool) {
    match old {
        OldState::Null => (ContactState::default(), true),
        OldState::Fresh => (ContactState::default(), false),
        OldState::Carried => (ctx.state, false),
        OldState::Given(s) => (s.get(), false),
    }
}

fn old_point(ctx: &Ctx, old: OldPoint) -> (FrictionPointState, bool) {
    match old {
        OldPoint::Null => (FrictionPointState::default(), true),
        OldPoint::Fresh => (FrictionPointState::default(), false),
        OldPoint::Carried => (ctx.point, false),
        OldPoint::Given(s) => (s.get(), false),
    }
}

/// A batch of normal evaluations through `call(n, delta, old, new, force,
/// radius, stiffness)`, with NULL or aliased arrays as chosen.
fn normal_batch(
    ctx: &mut Ctx,
    delta: &[F],
    old: OldState,
    nulls: Nulls,
    alias: bool,
    what: &str,
    call: impl FnOnce(
        usize,
        *const f64,
        *const ContactState,
        *mut ContactState,
        *mut f64,
        *mut f64,
        *mut f64,
    ) -> i32,
) {
    let n = delta.len().min(256);
    let mut d: Vec<f64> = delta[..n].iter().map(|f| f.0).collect();
    let (s0, old_null) = old_state(ctx, old);
    let mut states = vec![s0; n];
    let mut force = vec![0.0; n];
    let mut radius = vec![0.0; n];
    let mut stiff = vec![0.0; n];
    let sp = states.as_mut_ptr();
    let old_p = if old_null || nulls.at(1) {
        null()
    } else {
        sp as *const ContactState
    };
    let new_p = if nulls.at(2) { null_mut() } else { sp };
    let status = if alias {
        // Outputs written over the input array.
        let dp = bufm(&mut d, nulls.at(0));
        call(
            n,
            dp,
            old_p,
            new_p,
            dp,
            bufm(&mut radius, nulls.at(3)),
            bufm(&mut stiff, nulls.at(4)),
        )
    } else {
        call(
            n,
            bufp(&d, nulls.at(0)),
            old_p,
            new_p,
            bufm(&mut force, nulls.at(5)),
            bufm(&mut radius, nulls.at(3)),
            bufm(&mut stiff, nulls.at(4)),
        )
    };
    if ok(status, what) {
        if let Some(s) = states.last() {
            ctx.state = *s;
        }
    }
}

fn eval_one(
    ctx: &mut Ctx,
    old: OldState,
    nulls: Nulls,
    alias: bool,
    what: &str,
    call: impl FnOnce(*const ContactState, *mut ContactState, *mut NormalResponse) -> i32,
) {
    let (mut s, old_null) = old_state(ctx, old);
    let mut new = ContactState::default();
    let mut out: NormalResponse = zeroed();
    let sp: *mut ContactState = &mut s;
    let old_p = if old_null { null() } else { sp as *const _ };
    let new_p = if nulls.at(1) {
        null_mut()
    } else if alias {
        sp
    } else {
        &mut new
    };
    let status = call(old_p, new_p, mp(&mut out, nulls.at(0)));
    if ok(status, what) && !nulls.at(1) {
        ctx.state = if alias { s } else { new };
    }
}

fn json_of(len_needed: impl Fn(*mut c_char, usize, *mut usize) -> i32) -> Option<Vec<u8>> {
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

unsafe fn call(ctx: &mut Ctx, op: &Op) {
    match op {
        Op::Version => {
            let v = CStr::from_ptr(asperity_version());
            assert!(!v.to_bytes().is_empty());
        }
        Op::LastError { len, null } => {
            let mut buf = vec![1 as c_char; len.0];
            let p = if *null { null_mut() } else { buf.as_mut_ptr() };
            let n = asperity_last_error_message(p, if *null { 0 } else { len.0 });
            if !*null && len.0 > 0 {
                let k = n.min(len.0 - 1);
                assert_eq!(buf[k], 0, "last_error_message: no NUL at {k}");
            }
        }
        Op::StatusString(s) => {
            let p = asperity_status_string(*s);
            assert!(!p.is_null());
            let _ = CStr::from_ptr(p);
        }
        Op::TypeLayout { index, name, nulls } => {
            let mut name_buf: Vec<u8> = match name {
                Some(b) => b.iter().copied().filter(|&c| c != 0).take(64).collect(),
                None => {
                    let count = asperity_type_count();
                    let mut needed = 0usize;
                    let i = if count == 0 { 0 } else { index.0 % count };
                    let mut b = vec![0 as c_char; 128];
                    let _ = asperity_type_name(i, b.as_mut_ptr(), b.len(), &mut needed);
                    CStr::from_ptr(b.as_ptr()).to_bytes().to_vec()
                }
            };
            name_buf.push(0);
            let (mut size, mut align) = (0usize, 0usize);
            let np = if nulls.at(0) {
                null()
            } else {
                name_buf.as_ptr() as *const c_char
            };
            let s =
                asperity_type_layout(np, mp(&mut size, nulls.at(1)), mp(&mut align, nulls.at(2)));
            if ok(s, "type_layout") {
                assert!(
                    align.is_power_of_two() && size % align == 0,
                    "layout {size}/{align}"
                );
            }
        }
        Op::TypeName { index, len, nulls } => {
            let mut buf = vec![1 as c_char; len.0];
            let mut needed = 0usize;
            let p = if nulls.at(0) {
                null_mut()
            } else {
                buf.as_mut_ptr()
            };
            let s = asperity_type_name(index.0, p, len.0, mp(&mut needed, nulls.at(1)));
            if ok(s, "type_name") && !nulls.at(0) && len.0 > 0 {
                assert_eq!(buf[needed.min(len.0 - 1)], 0);
            }
        }
        Op::FlagName(bit) => {
            let p = asperity_indentation_flag_name(*bit);
            if !p.is_null() {
                let _ = CStr::from_ptr(p);
            }
        }
        Op::Law {
            which,
            a,
            sel,
            null,
        } => {
            let [a0, a1, a2, a3, a4] = fs(*a);
            let mut out: AsperityNormalLaw = zeroed();
            let o = mp(&mut out, *null);
            let s = match which % 14 {
                0 => asperity_law_hertz(a0, a1, o),
                1 => asperity_law_sphere_in_crater(a0, a1, a2, o),
                2 => asperity_law_power_punch(a0, a1, a2, o),
                3 => asperity_law_cone(a0, a1, o),
                4 => asperity_law_cone_in_imprint(a0, a1, a2, o),
                5 => asperity_law_flat_punch(a0, a1, o),
                6 => asperity_law_flat_punch_no_slip(a0, a1, a2, o),
                7 => asperity_law_dmt(a0, a1, a2, o),
                8 => asperity_law_jkr(a0, a1, a2, o),
                9 => asperity_law_jkr_power_punch(a0, a1, a2, a3, a4, sel.0, o),
                10 => asperity_law_kendall(a0, a1, a2, a3, sel.0, o),
                11 => asperity_law_maugis_dugdale(a0, a1, a2, a3, o),
                12 => asperity_law_derjaguin(a0, a1, sel.0, a2, o),
                _ => asperity_law_jkr_power_punch(a0, 1.0 + a1.abs() % 99.0, a2, a3, 0.3, 0, o),
            };
            if ok(s, "law constructor") && ctx.laws.len() < 16 {
                ctx.laws.push(out);
            }
        }
        Op::LawRaw { kind, raw } => {
            let mut l: AsperityNormalLaw = zeroed();
            l.kind = kind.0;
            l.params.raw = fs(*raw);
            if ctx.laws.len() < 16 {
                ctx.laws.push(l);
            }
        }
        Op::LawTamper { law: i, at, value } => {
            let mut l = law(ctx, *i);
            l.params.raw[*at as usize % 16] = value.0;
            if ctx.laws.len() < 16 {
                ctx.laws.push(l);
            }
        }
        Op::Eval {
            law: i,
            delta,
            old,
            nulls,
            alias,
        } => {
            let l = law(ctx, *i);
            let lp = cp(&l, nulls.at(2));
            eval_one(ctx, *old, *nulls, *alias, "normal_eval", |o, n, r| {
                asperity_normal_eval(lp, delta.0, o, n, r)
            });
        }
        Op::EvalBatch {
            law: i,
            delta,
            old,
            nulls,
            alias,
        } => {
            let l = law(ctx, *i);
            let lp = cp(&l, nulls.at(6));
            normal_batch(
                ctx,
                delta,
                *old,
                *nulls,
                *alias,
                "normal_eval_batch",
                |n, d, o, w, f, r, k| asperity_normal_eval_batch(lp, n, d, o, w, f, r, k),
            );
        }
        Op::EvalAtLoad {
            law: i,
            force,
            null,
        } => {
            let l = law(ctx, *i);
            let mut out: NormalResponse = zeroed();
            ok(
                asperity_normal_eval_at_load(&l, force.0, mp(&mut out, *null)),
                "eval_at_load",
            );
        }
        Op::PullOff {
            law: i,
            control,
            null,
        } => {
            let l = law(ctx, *i);
            let mut f = 0.0;
            ok(
                asperity_pull_off_force(&l, control.0, mp(&mut f, *null)),
                "pull_off_force",
            );
        }
        Op::LengthScale { law: i, null } => {
            let l = law(ctx, *i);
            let mut f = 0.0;
            ok(
                asperity_law_length_scale(&l, mp(&mut f, *null)),
                "length_scale",
            );
        }
        Op::TableMd { a, null } => {
            let [r, e, w, s0, tol] = fs(*a);
            // A tolerance below 1e-6 builds large tables: one per input.
            if tol.abs() < 1e-6 && tol != 0.0 {
                if ctx.expensive > 0 {
                    return;
                }
                ctx.expensive += 1;
            }
            let mut t = null_mut();
            let s = asperity_table_new_maugis_dugdale(r, e, w, s0, tol, mp(&mut t, *null));
            if let Some(t) = made(s, t, !*null, "table_new_maugis_dugdale") {
                ctx.tables.push(t);
            }
        }
        Op::TableLj {
            a,
            grid,
            tolerance,
            null,
        } => {
            // A valid tolerance below 1e-5 samples 10^4–10^5 solver points
            // (2–8 s in a release build, ten times that instrumented).
            if (1e-10..1e-5).contains(&tolerance.0) {
                return;
            }
            if ctx.expensive > 0 {
                return;
            }
            ctx.expensive += 1;
            let [r, e, w, z0] = fs(*a);
            let mut t = null_mut();
            let s = asperity_table_new_lj(r, e, w, z0, grid.0, tolerance.0, mp(&mut t, *null));
            if let Some(t) = made(s, t, !*null, "table_new_lj") {
                ctx.tables.push(t);
            }
        }
        Op::TableEval {
            table,
            delta,
            old,
            nulls,
        } => {
            let t = pick(&ctx.tables, *table);
            eval_one(ctx, *old, *nulls, nulls.at(3), "table_eval", |o, n, r| {
                asperity_table_eval(t, delta.0, o, n, r)
            });
        }
        Op::TableEvalBatch {
            table,
            delta,
            old,
            nulls,
            alias,
        } => {
            let t = pick(&ctx.tables, *table);
            normal_batch(
                ctx,
                delta,
                *old,
                *nulls,
                *alias,
                "table_eval_batch",
                |n, d, o, w, f, r, k| asperity_table_eval_batch(t, n, d, o, w, f, r, k),
            );
        }
        Op::TableEvalAtLoad { table, force, null } => {
            let t = pick(&ctx.tables, *table);
            let mut out: NormalResponse = zeroed();
            ok(
                asperity_table_eval_at_load(t, force.0, mp(&mut out, *null)),
                "table_eval_at_load",
            );
        }
        Op::TablePullOff {
            table,
            control,
            null,
        } => {
            let t = pick(&ctx.tables, *table);
            let mut f = 0.0;
            ok(
                asperity_table_pull_off_force(t, control.0, mp(&mut f, *null)),
                "table_pull_off",
            );
        }
        Op::TableMaxError { table, nulls } => {
            let t = pick(&ctx.tables, *table);
            let (mut a, mut b) = (0.0, 0.0);
            ok(
                asperity_table_max_error(t, mp(&mut a, nulls.at(0)), mp(&mut b, nulls.at(1))),
                "table_max_error",
            );
        }
        Op::TableToJson { table, len, nulls } => {
            let t = pick(&ctx.tables, *table);
            let mut buf = vec![1 as c_char; len.0];
            let mut needed = 0;
            let p = if nulls.at(0) {
                null_mut()
            } else {
                buf.as_mut_ptr()
            };
            let s = asperity_table_to_json(t, p, len.0, mp(&mut needed, nulls.at(1)));
            if ok(s, "table_to_json") && !nulls.at(0) && len.0 > 0 {
                assert_eq!(buf[needed.min(len.0 - 1)], 0);
            }
        }
        Op::TableFromJson {
            table,
            mutation,
            raw,
            nulls,
        } => {
            let t = pick(&ctx.tables, *table);
            let mut text = match raw {
                Some(r) => r.clone(),
                None if t.is_null() => return,
                None => match json_of(|b, l, n| asperity_table_to_json(t, b, l, n)) {
                    Some(j) => j,
                    None => return,
                },
            };
            mutation.apply(&mut text);
            let mut out = null_mut();
            let jp = if nulls.at(0) {
                null()
            } else {
                text.as_ptr() as *const c_char
            };
            let s = asperity_table_from_json(jp, text.len(), mp(&mut out, nulls.at(1)));
            if let Some(t) = made(s, out, !nulls.at(1), "table_from_json") {
                ctx.tables.push(t);
            }
        }
        Op::TableFree { table } => {
            if let Some(t) = take(&mut ctx.tables, *table) {
                asperity_table_free(t);
            } else {
                asperity_table_free(null_mut());
            }
        }
        Op::Fidelity { a, null } => {
            let v = fs(*a);
            // A valid set runs the Lennard-Jones reference (seconds to
            // minutes): only sets that validation rejects are fed.
            if !*null && v.iter().all(|x| x.is_finite() && *x > 0.0) {
                return;
            }
            let mut out: AsperityFidelityAdvice = zeroed();
            ok(
                asperity_fidelity_advise(v[0], v[1], v[2], v[3], v[4], mp(&mut out, *null)),
                "fidelity_advise",
            );
        }
        Op::LjPullOff { a, grid, null } => {
            if ctx.expensive > 0 {
                return;
            }
            ctx.expensive += 1;
            let [r, e, w, z0] = fs(*a);
            let mut f = 0.0;
            ok(
                asperity_lj_sphere_pull_off(r, e, w, z0, grid.0, mp(&mut f, *null)),
                "lj_pull_off",
            );
        }
        Op::Material {
            which,
            a,
            sel,
            null,
        } => {
            let [a0, a1, a2, a3, a4, a5] = fs(*a);
            let mut out = 0.0;
            let o = mp(&mut out, *null);
            let s = match which % 9 {
                0 => asperity_effective_modulus(a0, a1, a2, a3, o),
                1 => asperity_rod_effective_modulus(a0, a1, o),
                2 => asperity_no_slip_factor(a0, o),
                3 => asperity_tabor_parameter(a0, a1, a2, a3, o),
                4 => asperity_maugis_parameter(a0, a1, a2, a3, o),
                5 => asperity_weir_surface_energy(a0, a1, a2, a3, a4, a5, o),
                6 => asperity_weir_surface_energy_with(a0, a1, a2, a3, a4, a5, sel.0, o),
                7 => asperity_pair_work_of_adhesion(a0, a1, sel.0, o),
                _ => asperity_hamaker_work_of_adhesion(a0, a1, o),
            };
            ok(s, "material");
        }
        Op::DefaultOptions { null } => {
            let mut o: AsperityIndentationOptions = zeroed();
            ok(
                asperity_indentation_default_options(mp(&mut o, *null)),
                "default_options",
            );
        }
        Op::IndentFit {
            curve,
            segments,
            options,
            nulls,
        } => {
            let (d, p) = curve.make();
            let n = d.len();
            let seg: Option<Vec<i32>> = segments
                .as_ref()
                .map(|s| (0..n).map(|i| s.get(i).map_or(2, |v| v.0)).collect());
            let mut o: AsperityIndentationOptions = zeroed();
            assert!(ok(
                asperity_indentation_default_options(&mut o),
                "default_options"
            ));
            if let Some(spec) = options {
                spec.apply(&mut o);
            }
            let mut r: AsperityIndentationResult = zeroed();
            let s = asperity_indentation_fit(
                n,
                bufp(&d, nulls.at(0)),
                bufp(&p, nulls.at(1)),
                seg.as_ref().map_or(null(), |s| s.as_ptr()),
                if options.is_none() { null() } else { &o },
                mp(&mut r, nulls.at(2)),
            );
            ok(s, "indentation_fit");
        }
        Op::IndentFitRaw { depth, load, nulls } => {
            let n = depth.len().min(load.len());
            let d: Vec<f64> = depth[..n].iter().map(|f| f.0).collect();
            let p: Vec<f64> = load[..n].iter().map(|f| f.0).collect();
            let mut r: AsperityIndentationResult = zeroed();
            let s = asperity_indentation_fit(
                n,
                bufp(&d, nulls.at(0)),
                bufp(&p, nulls.at(1)),
                null(),
                null(),
                mp(&mut r, nulls.at(2)),
            );
            ok(s, "indentation_fit");
        }
        Op::Rescaling { which, a, null } => {
            let [a0, a1, a2, a3, a4, a5] = fs(*a);
            let mut out = 0.0;
            let o = mp(&mut out, *null);
            let s = match which % 14 {
                0 => asperity_rescaling_depth(a0, a1, a2, a3, a4, a5, o),
                1 => asperity_rescaling_radius(a0, a1, a2, a3, a4, a5, o),
                2 => asperity_rescaling_load(a0, a1, a2, a3, a4, a5, o),
                3 => asperity_rescaling_lambda_spheres(a0, a1, o),
                4 => asperity_rescaling_lambda_cones(a0, a1, o),
                5 => asperity_rescaling_kappa_from_slope(a0, a1, o),
                6 => asperity_rescaling_d_from_unloading_slope(a0, o),
                7 => asperity_rescaling_d_from_loading_slope(a0, a1, o),
                8 => asperity_galanov_unloading_radius(a0, a1, a2, a3, a4, o),
                9 => asperity_galanov_medium_radius(a0, a1, o),
                10 => asperity_hardness_brinell(a0, a1, a2, o),
                11 => asperity_hardness_meyer(a0, a1, o),
                12 => asperity_hardness_ludwik(a0, a1, o),
                _ => asperity_hardness_vickers(a0, a1, o),
            };
            ok(s, "rescaling/hardness");
        }
        Op::Gw { gw, x, nulls } => {
            let g = gw.get();
            let mut out: AsperityGwResponse = zeroed();
            ok(
                asperity_gw_eval(cp(&g, nulls.at(0)), x.0, mp(&mut out, nulls.at(1))),
                "gw_eval",
            );
        }
        Op::GwBatch {
            gw,
            x,
            nulls,
            alias,
        } => {
            let g = gw.get();
            let mut xs: Vec<f64> = x.iter().take(256).map(|f| f.0).collect();
            let n = xs.len();
            let (mut l, mut a, mut c, mut k) =
                (vec![0.0; n], vec![0.0; n], vec![0.0; n], vec![0.0; n]);
            let xp = bufm(&mut xs, nulls.at(1));
            let lp = if *alias {
                xp
            } else {
                bufm(&mut l, nulls.at(2))
            };
            let s = asperity_gw_eval_batch(
                cp(&g, nulls.at(0)),
                n,
                xp,
                lp,
                bufm(&mut a, nulls.at(3)),
                bufm(&mut c, nulls.at(4)),
                bufm(&mut k, nulls.at(5)),
            );
            ok(s, "gw_eval_batch");
        }
        Op::GwAtLoad { gw, load, nulls } => {
            let g = gw.get();
            let mut out: AsperitySeparation = zeroed();
            ok(
                asperity_gw_separation_at_load(
                    cp(&g, nulls.at(0)),
                    load.0,
                    mp(&mut out, nulls.at(1)),
                ),
                "gw_separation_at_load",
            );
        }
        Op::GwPlasticity {
            gw,
            hardness,
            nulls,
        } => {
            let g = gw.get();
            let mut out = 0.0;
            ok(
                asperity_gw_plasticity_index(
                    cp(&g, nulls.at(0)),
                    hardness.0,
                    mp(&mut out, nulls.at(1)),
                ),
                "gw_plasticity_index",
            );
        }
        Op::Plasticity { a, null } => {
            let [a0, a1, a2, a3] = fs(*a);
            let mut out = 0.0;
            ok(
                asperity_plasticity_index(a0, a1, a2, a3, mp(&mut out, *null)),
                "plasticity_index",
            );
        }
        Op::Regime { psi, null } => {
            let mut out = 0i32;
            ok(
                asperity_deformation_regime(psi.0, mp(&mut out, *null)),
                "deformation_regime",
            );
        }
        Op::GwEmpiricalNew {
            a,
            heights,
            radii,
            nulls,
        } => {
            let h = heights.make();
            let n = h.len();
            let r: Option<Vec<f64>> = radii
                .as_ref()
                .map(|r| (0..n).map(|i| r.get(i).map_or(1e-6, |f| f.0)).collect());
            let mut out = null_mut();
            let s = asperity_gw_empirical_new(
                a[0].0,
                a[1].0,
                a[2].0,
                n,
                bufp(&h, nulls.at(0)),
                r.as_ref().map_or(null(), |r| r.as_ptr()),
                mp(&mut out, nulls.at(1)),
            );
            if let Some(g) = made(s, out, !nulls.at(1), "gw_empirical_new") {
                ctx.gws.push(g);
            }
        }
        Op::GwEmpirical {
            gw,
            which,
            x,
            n,
            nulls,
        } => {
            let g = pick(&ctx.gws, *gw);
            match which % 4 {
                0 => {
                    let mut out: AsperityGwResponse = zeroed();
                    ok(
                        asperity_gw_empirical_eval(g, x.0, mp(&mut out, nulls.at(0))),
                        "gw_emp_eval",
                    );
                }
                1 => {
                    let xs: Vec<f64> = n.iter().take(256).map(|f| f.0).collect();
                    let k = xs.len();
                    let (mut l, mut a, mut c, mut st) =
                        (vec![0.0; k], vec![0.0; k], vec![0.0; k], vec![0.0; k]);
                    let s = asperity_gw_empirical_eval_batch(
                        g,
                        k,
                        bufp(&xs, nulls.at(0)),
                        bufm(&mut l, nulls.at(1)),
                        bufm(&mut a, nulls.at(2)),
                        bufm(&mut c, nulls.at(3)),
                        bufm(&mut st, nulls.at(4)),
                    );
                    ok(s, "gw_emp_eval_batch");
                }
                2 => {
                    let mut out: AsperitySeparation = zeroed();
                    ok(
                        asperity_gw_empirical_separation_at_load(g, x.0, mp(&mut out, nulls.at(0))),
                        "gw_emp_separation_at_load",
                    );
                }
                _ => {
                    let mut out = 0.0;
                    ok(
                        asperity_gw_empirical_plasticity_index(g, x.0, mp(&mut out, nulls.at(0))),
                        "gw_emp_plasticity_index",
                    );
                }
            }
        }
        Op::GwEmpiricalFree { gw } => {
            if let Some(g) = take(&mut ctx.gws, *gw) {
                asperity_gw_empirical_free(g);
            } else {
                asperity_gw_empirical_free(null_mut());
            }
        }
        Op::Zhuravlev {
            model,
            which,
            a,
            nulls,
        } => {
            let m = fs(*model);
            let z = AsperityZhuravlev {
                cap_radius: m[0],
                effective_radius: m[1],
                e_star: m[2],
                summit_count: m[3],
            };
            let zp = cp(&z, nulls.at(0));
            let [a0, a1, a2, a3] = fs(*a);
            let s = match which % 3 {
                0 => {
                    let mut out: AsperityZhuravlevResponse = zeroed();
                    asperity_zhuravlev_linear(zp, a0, a1, a2, mp(&mut out, nulls.at(1)))
                }
                1 => {
                    let mut out = 0.0;
                    asperity_zhuravlev_approach_at_load_linear(
                        zp,
                        a0,
                        a1,
                        a2,
                        mp(&mut out, nulls.at(1)),
                    )
                }
                _ => {
                    let mut out: AsperityZhuravlevFriction = zeroed();
                    asperity_zhuravlev_friction_linear(
                        zp,
                        a0,
                        a1,
                        a2,
                        a3,
                        mp(&mut out, nulls.at(1)),
                    )
                }
            };
            ok(s, "zhuravlev");
        }
        Op::ZhuravlevEval {
            model,
            approach,
            n1,
            n2,
            order,
            nulls,
        } => {
            let m = fs(*model);
            let z = AsperityZhuravlev {
                cap_radius: m[0],
                effective_radius: m[1],
                e_star: m[2],
                summit_count: m[3],
            };
            let mut d1 = n1.1 .0;
            let mut d2 = n2.1 .0;
            let mut out: AsperityZhuravlevResponse = zeroed();
            let s = asperity_zhuravlev_eval(
                cp(&z, nulls.at(0)),
                approach.0,
                density(n1.0),
                &mut d1 as *mut f64 as *mut c_void,
                density(n2.0),
                &mut d2 as *mut f64 as *mut c_void,
                order.0,
                mp(&mut out, nulls.at(1)),
            );
            ok(s, "zhuravlev_eval");
        }
        Op::Roughness {
            h,
            dx,
            form,
            cutoff,
            sampling,
            nulls,
        } => {
            let z = h.make();
            let mut out: AsperityRoughness = zeroed();
            let s = asperity_roughness_parameters(
                z.len(),
                bufp(&z, nulls.at(0)),
                dx.0,
                form.0,
                cutoff.0,
                sampling.0,
                mp(&mut out, nulls.at(1)),
            );
            ok(s, "roughness_parameters");
        }
        Op::RemoveForm {
            h,
            form,
            nulls,
            alias,
        } => {
            let mut z = h.make();
            let mut out = vec![0.0; z.len()];
            let zp = bufm(&mut z, nulls.at(0));
            let op = if *alias {
                zp
            } else {
                bufm(&mut out, nulls.at(1))
            };
            ok(
                asperity_profile_remove_form(z.len(), zp, form.0, op),
                "remove_form",
            );
        }
        Op::Filter {
            h,
            dx,
            cutoff,
            ends,
            nulls,
            alias,
        } => {
            let mut z = h.make();
            let n = z.len();
            let (mut r, mut m) = (vec![0.0; n], vec![0.0; n]);
            let (mut n_out, mut first) = (0usize, 0usize);
            let zp = bufm(&mut z, nulls.at(0));
            let rp = if *alias {
                zp
            } else {
                bufm(&mut r, nulls.at(1))
            };
            let s = asperity_profile_gaussian_filter(
                n,
                zp,
                dx.0,
                cutoff.0,
                ends.0,
                rp,
                bufm(&mut m, nulls.at(2)),
                mp(&mut n_out, nulls.at(3)),
                mp(&mut first, nulls.at(4)),
            );
            if ok(s, "gaussian_filter") && !nulls.at(3) {
                assert!(n_out <= n, "gaussian_filter wrote {n_out} of {n}");
            }
        }
        Op::MaterialRatio { h, points, nulls } => {
            let z = h.make();
            let (mut r, mut l) = (vec![0.0; points.0], vec![0.0; points.0]);
            let s = asperity_material_ratio_curve(
                z.len(),
                bufp(&z, nulls.at(0)),
                points.0,
                bufm(&mut r, nulls.at(1)),
                bufm(&mut l, nulls.at(2)),
            );
            ok(s, "material_ratio_curve");
        }
        Op::Psd {
            h,
            dx,
            window,
            n_q,
            nulls,
        } => {
            let z = h.make();
            // The documented length n/2 + 1, or another (checked) length.
            let m = n_q.map_or(z.len() / 2 + 1, |l| l.0);
            let (mut q, mut g) = (vec![0.0; m], vec![0.0; m]);
            let s = asperity_profile_psd(
                z.len(),
                bufp(&z, nulls.at(0)),
                dx.0,
                window.0,
                m,
                bufm(&mut q, nulls.at(1)),
                bufm(&mut g, nulls.at(2)),
            );
            ok(s, "profile_psd");
        }
        Op::HurstFit { h, dx, q, nulls } => {
            let z = h.make();
            let mut out: AsperityHurstFit = zeroed();
            let s = asperity_profile_hurst_fit(
                z.len(),
                bufp(&z, nulls.at(0)),
                dx.0,
                q[0].0,
                q[1].0,
                mp(&mut out, nulls.at(1)),
            );
            ok(s, "hurst_fit");
        }
        Op::Peaks { h, dx, nulls } => {
            let z = h.make();
            let mut out: AsperityPeakStatistics = zeroed();
            let s = asperity_profile_peak_statistics(
                z.len(),
                bufp(&z, nulls.at(0)),
                dx.0,
                mp(&mut out, nulls.at(1)),
            );
            ok(s, "peak_statistics");
        }
        Op::SelfAffine { a, seed, n, null } => {
            let [a0, a1, a2, a3, a4] = fs(*a);
            let mut h = vec![0.0; n.0];
            let s =
                asperity_generate_self_affine(a0, a1, a2, a3, a4, *seed, n.0, bufm(&mut h, *null));
            ok(s, "generate_self_affine");
        }
        Op::Weierstrass { a, seed, n, null } => {
            let [a0, a1, a2, a3] = fs(*a);
            let mut h = vec![0.0; n.0];
            let s = asperity_generate_weierstrass_mandelbrot(
                a0,
                a1,
                a2,
                a3,
                *seed,
                n.0,
                bufm(&mut h, *null),
            );
            ok(s, "generate_weierstrass_mandelbrot");
        }
        Op::Cantor {
            descendants,
            a,
            levels,
            n,
            null,
        } => {
            let [a0, a1, a2, a3] = fs(*a);
            let mut h = vec![0.0; n.0];
            let s = asperity_generate_cantor_borodich(
                *descendants,
                a0,
                a1,
                a2,
                *levels,
                a3,
                n.0,
                bufm(&mut h, *null),
            );
            ok(s, "generate_cantor_borodich");
        }
        Op::GeometryNew {
            micro,
            micro_dx,
            nano,
            nano_dx,
            widths,
            nulls,
        } => {
            let m = micro.make();
            let n = nano.make();
            let w: Vec<f64> = widths.iter().take(6).map(|f| f.0).collect();
            let mut out = null_mut();
            let s = asperity_slider_geometry_new(
                bufp(&m, nulls.at(0)),
                m.len(),
                micro_dx.0,
                bufp(&n, nulls.at(1)),
                n.len(),
                nano_dx.0,
                bufp(&w, nulls.at(2)),
                w.len(),
                mp(&mut out, nulls.at(3)),
            );
            if let Some(g) = made(s, out, !nulls.at(3), "slider_geometry_new") {
                ctx.geometries.push(g);
            }
        }
        Op::GeometryUniform {
            width,
            rods,
            nano,
            per_rod,
            nulls,
        } => {
            let v = fs(*nano);
            let na = AsperityNanoAsperities {
                h_vdw: v[0],
                w_vdw: v[1],
                h_chem: v[2],
                w_chem: v[3],
                spacing: v[4],
                per_rod: per_rod.0,
            };
            let mut out = null_mut();
            let s = asperity_slider_geometry_new_uniform(
                width.0,
                rods.0,
                cp(&na, nulls.at(0)),
                mp(&mut out, nulls.at(1)),
            );
            if let Some(g) = made(s, out, !nulls.at(1), "slider_geometry_new_uniform") {
                ctx.geometries.push(g);
            }
        }
        Op::GeometryQuery {
            geometry,
            which,
            level,
            len,
            nulls,
        } => {
            let g = pick(&ctx.geometries, *geometry);
            let null = nulls.at(0);
            let s = match which % 5 {
                0 => {
                    let mut o: AsperityNanoAsperities = zeroed();
                    asperity_slider_geometry_nano(g, mp(&mut o, null))
                }
                1 => {
                    let mut c = 0usize;
                    asperity_slider_geometry_level_count(g, mp(&mut c, null))
                }
                2 => {
                    let mut c = 0usize;
                    asperity_slider_geometry_rod_count(g, level.0, mp(&mut c, null))
                }
                3 => {
                    let (mut w, mut o) = (0.0, 0.0);
                    asperity_slider_geometry_rod_width(
                        g,
                        level.0,
                        mp(&mut w, null),
                        mp(&mut o, nulls.at(1)),
                    )
                }
                _ => {
                    // A buffer of `len` values, or of the level's rod count.
                    let mut count = 0usize;
                    let l = if nulls.at(2)
                        && asperity_slider_geometry_rod_count(g, level.0, &mut count) == ASPERITY_OK
                    {
                        count.min(1 << 20)
                    } else {
                        len.0
                    };
                    let mut h = vec![0.0; l];
                    asperity_slider_geometry_rod_heights(g, level.0, bufm(&mut h, null), l)
                }
            };
            ok(s, "slider_geometry query");
        }
        Op::GeometryFree { geometry } => {
            if let Some(g) = take(&mut ctx.geometries, *geometry) {
                asperity_slider_geometry_free(g);
            } else {
                asperity_slider_geometry_free(null_mut());
            }
        }
        Op::HomNew { samples, nulls } => {
            let v = samples.make();
            let mut out = null_mut();
            let s = asperity_homogenised_friction_new(
                if nulls.at(0) { null() } else { v.as_ptr() },
                v.len(),
                mp(&mut out, nulls.at(1)),
            );
            if let Some(f) = made(s, out, !nulls.at(1), "homogenised_friction_new") {
                ctx.frictions.push(f);
            }
        }
        Op::HomNewRaw { samples, nulls } => {
            let v: Vec<HomogenisedSample> = samples
                .iter()
                .take(16)
                .map(|a| {
                    let a = fs(*a);
                    HomogenisedSample {
                        pressure: a[0],
                        cof: a[1],
                        adhesion_pressure: a[2],
                        contact_fraction: a[3],
                        shares: Dissipation {
                            chemical: a[4],
                            van_der_waals: a[5],
                            elastic: a[6],
                            plastic: a[7],
                        },
                    }
                })
                .collect();
            let mut out = null_mut();
            let s = asperity_homogenised_friction_new(
                if nulls.at(0) { null() } else { v.as_ptr() },
                v.len(),
                mp(&mut out, nulls.at(1)),
            );
            if let Some(f) = made(s, out, !nulls.at(1), "homogenised_friction_new") {
                ctx.frictions.push(f);
            }
        }
        Op::HomFromJson {
            friction,
            mutation,
            raw,
            nulls,
        } => {
            let f = pick(&ctx.frictions, *friction);
            let mut text = match raw {
                Some(r) => r.clone(),
                None if f.is_null() => return,
                None => {
                    match json_of(|b, l, n| asperity_homogenised_friction_to_json(f, b, l, n)) {
                        Some(j) => j,
                        None => return,
                    }
                }
            };
            mutation.apply(&mut text);
            let mut out = null_mut();
            let jp = if nulls.at(0) {
                null()
            } else {
                text.as_ptr() as *const c_char
            };
            let s =
                asperity_homogenised_friction_from_json(jp, text.len(), mp(&mut out, nulls.at(1)));
            if let Some(f) = made(s, out, !nulls.at(1), "homogenised_friction_from_json") {
                ctx.frictions.push(f);
            }
        }
        Op::HomToJson {
            friction,
            len,
            nulls,
        } => {
            let f = pick(&ctx.frictions, *friction);
            let mut buf = vec![1 as c_char; len.0];
            let mut needed = 0;
            let p = if nulls.at(0) {
                null_mut()
            } else {
                buf.as_mut_ptr()
            };
            let s =
                asperity_homogenised_friction_to_json(f, p, len.0, mp(&mut needed, nulls.at(1)));
            if ok(s, "homogenised_friction_to_json") && !nulls.at(0) && len.0 > 0 {
                assert_eq!(buf[needed.min(len.0 - 1)], 0);
            }
        }
        Op::HomStep {
            friction,
            inc,
            old,
            nulls,
            alias,
        } => {
            let f = pick(&ctx.frictions, *friction);
            let v = fs(*inc);
            let i = FrictionIncrement {
                normal_force: v[0],
                area: v[1],
                slip: [v[2], v[3]],
                dt: v[4],
                stick_stiffness: v[5],
            };
            let (mut s0, old_null) = old_point(ctx, *old);
            let mut new = FrictionPointState::default();
            let mut out: FrictionResponse = zeroed();
            let sp: *mut FrictionPointState = &mut s0;
            let new_p = if nulls.at(2) {
                null_mut()
            } else if *alias {
                sp
            } else {
                &mut new
            };
            let s = asperity_homogenised_friction_step(
                f,
                cp(&i, nulls.at(0)),
                if old_null { null() } else { sp },
                new_p,
                mp(&mut out, nulls.at(1)),
            );
            if ok(s, "homogenised_friction_step") && !nulls.at(2) {
                ctx.point = if *alias { s0 } else { new };
            }
        }
        Op::HomBlock {
            friction,
            n,
            inc,
            dt,
            k,
            old,
            nulls,
            alias,
        } => {
            let f = pick(&ctx.frictions, *friction);
            let n = *n as usize % 9;
            let val = |i: usize, d: f64| inc.get(i).map_or(d, |f| f.0);
            let normal: Vec<f64> = (0..n).map(|i| val(4 * i, 1.0)).collect();
            let area: Vec<f64> = (0..n).map(|i| val(4 * i + 1, 1e-4)).collect();
            let slip: Vec<f64> = (0..2 * n)
                .map(|i| val(4 * (i / 2) + 2 + i % 2, 1e-6))
                .collect();
            let (s0, old_null) = old_point(ctx, *old);
            let mut states = vec![s0; n];
            let mut new_states = vec![FrictionPointState::default(); n];
            let mut force = vec![0.0; 2 * n];
            let mut diss = vec![0.0; n];
            let sp = states.as_mut_ptr();
            let new_p = if nulls.at(4) {
                null_mut()
            } else if *alias {
                sp
            } else {
                new_states.as_mut_ptr()
            };
            let s = asperity_homogenised_friction_step_block(
                f,
                n,
                bufp(&normal, nulls.at(0)),
                bufp(&area, nulls.at(1)),
                bufp(&slip, nulls.at(2)),
                dt.0,
                k.0,
                if old_null { null() } else { sp },
                new_p,
                bufm(&mut force, nulls.at(3)),
                bufm(&mut diss, nulls.at(5)),
            );
            ok(s, "homogenised_friction_step_block");
        }
        Op::HomStateSize => {
            assert_eq!(
                asperity_homogenised_friction_state_size(),
                core::mem::size_of::<FrictionPointState>()
            );
        }
        Op::HomFree { friction } => {
            if let Some(f) = take(&mut ctx.frictions, *friction) {
                asperity_homogenised_friction_free(f);
            } else {
                asperity_homogenised_friction_free(null_mut());
            }
        }
        Op::SliderNew {
            scene,
            mutation,
            base,
            nulls,
        } => {
            let mut text = scene.json().into_bytes();
            mutation.apply(&mut text);
            let base_dir: &[u8] = match base % 4 {
                0 => b".\0",
                1 => b"/nonexistent-asperity-fuzz\0",
                2 => b"\xff\xfe\0",
                _ => b"\0",
            };
            let mut out = null_mut();
            let s = asperity_slider_from_scene_json(
                if nulls.at(0) {
                    null()
                } else {
                    text.as_ptr() as *const c_char
                },
                text.len(),
                if nulls.at(2) {
                    null()
                } else {
                    base_dir.as_ptr() as *const c_char
                },
                mp(&mut out, nulls.at(1)),
            );
            if let Some(sl) = made(s, out, !nulls.at(1), "slider_from_scene_json") {
                keep_slider(ctx, sl);
            }
        }
        Op::SliderQuery {
            slider,
            which,
            null,
        } => {
            let sl = pick(&ctx.sliders, *slider);
            let s = if which % 2 == 0 {
                let mut n = 0usize;
                asperity_slider_state_size(sl, mp(&mut n, *null))
            } else {
                let mut info: AsperitySliderInfo = zeroed();
                asperity_slider_info(sl, mp(&mut info, *null))
            };
            ok(s, "slider query");
        }
        Op::WorkNew { slider, null } => {
            let sl = pick(&ctx.sliders, *slider);
            let mut out = null_mut();
            let s = asperity_slider_work_new(sl, mp(&mut out, *null));
            if let Some(w) = made(s, out, !*null, "slider_work_new") {
                ctx.works.push(w);
            }
        }
        Op::SliderStep {
            slider,
            work,
            inc,
            control,
            tangents,
            state,
            in_place,
            nulls,
        } => {
            let sl = pick(&ctx.sliders, *slider);
            let w = pick(&ctx.works, *work);
            let v = fs(*inc);
            let i = AsperitySliderIncrement {
                normal_force: v[0],
                gap: v[1],
                slip: [v[2], v[3]],
                dt: v[4],
                control: control.0,
                tangents: tangents.0,
            };
            let m = slider_state_len(sl);
            let mut old = make_slider_state(ctx, state, m);
            let mut new = vec![0.0; m];
            let mut out: SliderResponse = zeroed();
            let op = bufm(&mut old, nulls.at(2));
            let np = if *in_place {
                op
            } else {
                bufm(&mut new, nulls.at(3))
            };
            let s = asperity_slider_step(
                sl,
                w,
                cp(&i, nulls.at(0)),
                op,
                np,
                mp(&mut out, nulls.at(1)),
            );
            if ok(s, "slider_step") {
                ctx.slider_state = if *in_place { old } else { new };
            }
        }
        Op::SliderBlock {
            slider,
            work,
            n,
            inc,
            dt,
            state,
            in_place,
            nulls,
        } => {
            let sl = pick(&ctx.sliders, *slider);
            let w = pick(&ctx.works, *work);
            let n = *n as usize % 5;
            let m = slider_state_len(sl);
            let val = |i: usize, d: f64| inc.get(i).map_or(d, |f| f.0);
            let normal: Vec<f64> = (0..n).map(|i| val(3 * i, 0.05)).collect();
            let slip: Vec<f64> = (0..2 * n)
                .map(|i| val(3 * (i / 2) + 1 + i % 2, 1e-7))
                .collect();
            let one = make_slider_state(ctx, state, m);
            let mut old: Vec<f64> = (0..n).flat_map(|_| one.iter().copied()).collect();
            let mut new = vec![0.0; n * m];
            let mut force = vec![0.0; 2 * n];
            let mut diss = vec![0.0; n];
            let op = bufm(&mut old, nulls.at(2));
            let np = if *in_place {
                op
            } else {
                bufm(&mut new, nulls.at(3))
            };
            let s = asperity_slider_step_block(
                sl,
                w,
                n,
                bufp(&normal, nulls.at(0)),
                bufp(&slip, nulls.at(1)),
                dt.0,
                op,
                np,
                bufm(&mut force, nulls.at(4)),
                bufm(&mut diss, nulls.at(5)),
            );
            ok(s, "slider_step_block");
        }
        Op::SliderFree { slider } => {
            if let Some(s) = take(&mut ctx.sliders, *slider) {
                asperity_slider_free(s);
            } else {
                asperity_slider_free(null_mut());
            }
        }
        Op::WorkFree { work } => {
            if let Some(w) = take(&mut ctx.works, *work) {
                asperity_slider_work_free(w);
            } else {
                asperity_slider_work_free(null_mut());
            }
        }
        Op::SliderOptionsDefault { null } => {
            let mut o: AsperitySliderOptions = zeroed();
            ok(
                asperity_slider_options_default(mp(&mut o, *null)),
                "slider_options_default",
            );
        }
        Op::MaterialCopper { null } => {
            let mut m: FrictionMaterial = zeroed();
            ok(
                asperity_friction_material_copper(mp(&mut m, *null)),
                "friction_material_copper",
            );
        }
        Op::SliderFromStructs {
            geometry,
            material,
            counter,
            options,
            nulls,
        } => {
            let g = match *geometry {
                GeometrySource::Table(i) => pick(&ctx.geometries, i),
                GeometrySource::Uniform { rods, poke } => {
                    let mut v = [6e-9, 4.3e-7, 2.2e-9, 1.61e-7, 1.35e-6];
                    if let Some((at, value)) = poke {
                        v[at as usize % 5] = value.0;
                    }
                    let nano = AsperityNanoAsperities {
                        h_vdw: v[0],
                        w_vdw: v[1],
                        h_chem: v[2],
                        w_chem: v[3],
                        spacing: v[4],
                        per_rod: 1,
                    };
                    let mut g = null_mut();
                    let s = asperity_slider_geometry_new_uniform(
                        1.5e-6,
                        rods as usize % 16 + 1,
                        &nano,
                        &mut g,
                    );
                    if let Some(g) = made(s, g, true, "slider_geometry_new_uniform") {
                        ctx.geometries.push(g);
                    }
                    g
                }
            };
            if !g.is_null() && geometry_rods(g) > MAX_SLIDER_RODS {
                return;
            }
            let m = material.get();
            let o = options.as_ref().map_or_else(
                || {
                    let mut o: AsperitySliderOptions = zeroed();
                    assert!(ok(
                        asperity_slider_options_default(&mut o),
                        "slider_options_default"
                    ));
                    o
                },
                |o| o.get(),
            );
            // By default 256 samples at 0.1 µm: under up to 16 rods of 1.5 µm.
            let (c, dx) = match counter {
                Some((h, dx)) => (h.make(), dx.0),
                None => (
                    (0..256)
                        .map(|j| 5e-8 * (0.3 * j as f64).sin() * (0.07 * j as f64).cos())
                        .collect(),
                    1e-7,
                ),
            };
            let mut out = null_mut();
            let s = asperity_slider_new(
                g,
                cp(&m, nulls.at(0)),
                bufp(&c, nulls.at(1)),
                c.len(),
                dx,
                cp(&o, nulls.at(2)),
                mp(&mut out, nulls.at(3)),
            );
            if let Some(sl) = made(s, out, !nulls.at(3), "slider_new") {
                keep_slider(ctx, sl);
            }
        }
        Op::LugreNew { params, nulls } => {
            let p = params.get();
            let mut out = null_mut();
            let s = asperity_dynamic_lugre_new(cp(&p, nulls.at(0)), mp(&mut out, nulls.at(1)));
            if let Some(d) = made(s, out, !nulls.at(1), "dynamic_lugre_new") {
                ctx.dynamics.push(Dynamic {
                    model: d,
                    pt: None,
                    heavy: false,
                });
            }
        }
        Op::MaxwellNew {
            elements,
            sigma2,
            nulls,
            bristles,
        } => {
            let (k, m) = elements.make();
            let mut out = null_mut();
            let (k, m, n) = (bufp(&k, nulls.at(0)), bufp(&m, nulls.at(1)), k.len());
            let s = if *bristles {
                asperity_dynamic_bristles_new(k, m, n, sigma2.0, mp(&mut out, nulls.at(2)))
            } else {
                asperity_dynamic_maxwell_slip_new(k, m, n, sigma2.0, mp(&mut out, nulls.at(2)))
            };
            let what = if *bristles {
                "dynamic_bristles_new"
            } else {
                "dynamic_maxwell_slip_new"
            };
            if let Some(d) = made(s, out, !nulls.at(2), what) {
                ctx.dynamics.push(Dynamic {
                    model: d,
                    pt: None,
                    heavy: false,
                });
            }
        }
        Op::PtNew {
            variant: Integrated::TwoSpring { params, null: np },
            null,
            ..
        } => {
            let v = params.get([2e-21, 3e-10, 2.0, 1e-12, 1e-6, 2.0, 1e-12, 1e-6, 1e-9]);
            let p = AsperityPrandtlTomlinsonTwoSpringParams {
                amplitude: v[0],
                period: v[1],
                tip_stiffness: v[2],
                tip_mass: v[3],
                tip_damping: v[4],
                cantilever_stiffness: v[5],
                cantilever_mass: v[6],
                cantilever_damping: v[7],
                tolerance: v[8],
            };
            let mut out = null_mut();
            let s =
                asperity_dynamic_prandtl_tomlinson_two_spring_new(cp(&p, *np), mp(&mut out, *null));
            if let Some(d) = made(s, out, !*null, "dynamic_prandtl_tomlinson_two_spring_new") {
                ctx.dynamics.push(Dynamic {
                    model: d,
                    pt: None,
                    heavy: true,
                });
            }
        }
        Op::PtNew {
            variant: Integrated::Chain { params, null: np },
            null,
            ..
        } => {
            let v = params.get([4.0, 1e-5, 1e4, 1e3, 0.5, 0.3, 0.05, 0.01, 1e-9]);
            // A raw block count: the saturating cast keeps huge and
            // non-finite values huge or 0 (refused by the library).
            let p = AsperityBurridgeKnopoffParams {
                blocks: v[0] as usize,
                mass: v[1],
                coupling_stiffness: v[2],
                pulling_stiffness: v[3],
                mu_static: v[4],
                mu_kinetic: v[5],
                weakening_velocity: v[6],
                damping: v[7],
                tolerance: v[8],
            };
            let mut out = null_mut();
            let s = asperity_dynamic_burridge_knopoff_new(cp(&p, *np), mp(&mut out, *null));
            if let Some(d) = made(s, out, !*null, "dynamic_burridge_knopoff_new") {
                ctx.dynamics.push(Dynamic {
                    model: d,
                    pt: None,
                    heavy: true,
                });
            }
        }
        Op::PtNew { params, null, .. } => {
            let p = params.get();
            let mut out = null_mut();
            let s = asperity_dynamic_prandtl_tomlinson_new(
                p[0],
                p[1],
                p[2],
                p[3],
                p[4],
                p[5],
                mp(&mut out, *null),
            );
            if let Some(d) = made(s, out, !*null, "dynamic_prandtl_tomlinson_new") {
                ctx.dynamics.push(Dynamic {
                    model: d,
                    pt: Some(p),
                    heavy: false,
                });
            }
        }
        Op::DynStateSize { model, null } => {
            let (d, _, _) = pick_dynamic(ctx, *model);
            let mut n = 0usize;
            if ok(
                asperity_dynamic_friction_state_size(d, mp(&mut n, *null)),
                "dynamic_friction_state_size",
            ) && !*null
            {
                assert!(n >= 2, "dynamic_friction_state_size: {n} < 2");
            }
        }
        Op::DynStep {
            model,
            inc,
            tangents,
            reserved,
            state,
            placement,
            nulls,
        } => {
            let (d, pt, heavy) = pick_dynamic(ctx, *model);
            if heavy && !ctx.affordable(f64::INFINITY) {
                return;
            }
            let v = inc.get();
            let i = DynamicIncrement {
                normal_force: v[0],
                slip: [v[1], v[2]],
                dt: v[3],
                tangents: tangents.0,
                reserved: reserved.0,
            };
            let m = dynamic_state_len(d);
            let old = make_state(&ctx.dynamic_state, state, m);
            if let Some(p) = pt {
                let integrations = if i.tangents & ASPERITY_DYNAMIC_TANGENT_SLIP != 0 {
                    3.0
                } else {
                    1.0
                };
                let cost = integrations * pt_substeps(&p, &old, i.dt, &[i.slip[0]]);
                if !ctx.affordable(cost) {
                    return;
                }
            }
            // One buffer: the old state at 0, the new one at `shift` (m:
            // apart, 0: in place, in between: partially overlapping).
            let shift = match placement {
                Placement::InPlace => 0,
                Placement::Overlap(k) if m > 1 => 1 + *k as usize % (m - 1),
                _ => m,
            };
            let mut buf = old.clone();
            buf.resize(shift + m, f64::from_bits(SENTINEL));
            let before = buf.clone();
            let mut out: DynamicResponse = zeroed();
            std::ptr::write_bytes(&mut out as *mut DynamicResponse as *mut u8, 0xa5, 1);
            let out_before = bytes_of(&out).to_vec();
            let base = buf.as_mut_ptr();
            let s = asperity_dynamic_friction_step(
                d,
                cp(&i, nulls.at(0)),
                if nulls.at(1) { null() } else { base },
                if nulls.at(2) {
                    null_mut()
                } else {
                    base.add(shift)
                },
                mp(&mut out, nulls.at(3)),
            );
            if ok(s, "dynamic_friction_step") {
                ctx.dynamic_state = buf[shift..shift + m].to_vec();
                assert!(
                    out.dissipated.is_nan() || out.dissipated >= 0.0,
                    "dynamic_friction_step: OK with dissipated = {} < 0",
                    out.dissipated
                );
            } else {
                // Documented: on failure `new_state` and `*out` are untouched.
                assert!(
                    bits(&buf) == bits(&before),
                    "dynamic_friction_step failed ({}) but wrote the state",
                    last_message()
                );
                assert!(
                    bytes_of(&out) == out_before.as_slice(),
                    "dynamic_friction_step failed ({}) but wrote *out",
                    last_message()
                );
            }
        }
        Op::DynBlock {
            model,
            n,
            inc,
            dt,
            state,
            nulls,
        } => {
            let (d, pt, heavy) = pick_dynamic(ctx, *model);
            if heavy && !ctx.affordable(f64::INFINITY) {
                return;
            }
            let dt = dt.map_or(1e-3, |f| f.0);
            let n = *n as usize % 9;
            let m = dynamic_state_len(d);
            let val = |i: usize, d: f64| inc.get(i).map_or(d, |f| f.0);
            let normal: Vec<f64> = (0..n).map(|i| val(3 * i, 1.0)).collect();
            let slip: Vec<f64> = (0..2 * n)
                .map(|i| val(3 * (i / 2) + 1 + i % 2, 1e-6))
                .collect();
            let one = make_state(&ctx.dynamic_state, state, m);
            if let Some(p) = pt {
                let ds: Vec<f64> = slip.iter().step_by(2).copied().collect();
                if !ctx.affordable(pt_substeps(&p, &one, dt, &ds)) {
                    return;
                }
            }
            let mut states: Vec<f64> = (0..n).flat_map(|_| one.iter().copied()).collect();
            let mut force = vec![0.0; 2 * n];
            let mut diss = vec![0.0; n];
            let s = asperity_dynamic_friction_step_block(
                d,
                n,
                bufp(&normal, nulls.at(0)),
                bufp(&slip, nulls.at(1)),
                dt,
                bufm(&mut states, nulls.at(2)),
                bufm(&mut force, nulls.at(3)),
                bufm(&mut diss, nulls.at(4)),
            );
            if ok(s, "dynamic_friction_step_block") && n > 0 {
                ctx.dynamic_state = states[(n - 1) * m..].to_vec();
            }
        }
        Op::DynFree { model } => {
            if ctx.dynamics.is_empty() {
                asperity_dynamic_friction_free(null_mut());
            } else {
                let i = *model as usize % ctx.dynamics.len();
                asperity_dynamic_friction_free(ctx.dynamics.swap_remove(i).model);
            }
        }
        Op::Reach {
            law: i,
            control,
            rel_force,
            null,
        } => {
            let l = law(ctx, *i);
            let mut d = 0.0;
            ok(
                asperity_normal_reach(&l, control.0, rel_force.0, mp(&mut d, *null)),
                "normal_reach",
            );
        }
        Op::Energy {
            law: i,
            delta,
            old,
            null: null_out,
        } => {
            let l = law(ctx, *i);
            let (s, old_null) = old_state(ctx, *old);
            let old_p: *const ContactState = if old_null { null() } else { &s };
            let mut u = 0.0;
            ok(
                asperity_normal_energy(&l, delta.0, old_p, mp(&mut u, *null_out)),
                "normal_energy",
            );
        }
        Op::TableReach {
            table,
            control,
            rel_force,
            null,
        } => {
            let t = pick(&ctx.tables, *table);
            let mut d = 0.0;
            ok(
                asperity_table_reach(t, control.0, rel_force.0, mp(&mut d, *null)),
                "table_reach",
            );
        }
    }
}

/// Most rods (over all levels) of a geometry that `asperity_slider_new` is
/// given: the dense rod solver is cubic in the rod count.
const MAX_SLIDER_RODS: usize = 256;

/// Most rods × nano-asperities per rod of a slider the harness steps: a step
/// visits every nano-asperity column of every rod (the library allows 2^24
/// per rod, `MAX_NANO_PER_ROD`).
const MAX_SLIDER_NANO: usize = 1 << 22;

/// Keep `slider` for the steps, or free it at once when its steps would
/// cost more than [`MAX_SLIDER_NANO`] (a harness cost bound).
unsafe fn keep_slider(ctx: &mut Ctx, slider: *mut AsperitySlider) {
    let mut info: AsperitySliderInfo = zeroed();
    assert!(ok(asperity_slider_info(slider, &mut info), "slider_info"));
    if info.rods.saturating_mul(info.nano_per_rod) > MAX_SLIDER_NANO {
        asperity_slider_free(slider);
    } else {
        ctx.sliders.push(slider);
    }
}

/// The rods of every level of `g`.
unsafe fn geometry_rods(g: *const AsperitySliderGeometry) -> usize {
    let mut levels = 0usize;
    if asperity_slider_geometry_level_count(g, &mut levels) != ASPERITY_OK {
        return usize::MAX;
    }
    (0..levels)
        .map(|l| {
            let mut c = 0usize;
            if asperity_slider_geometry_rod_count(g, l, &mut c) == ASPERITY_OK {
                c
            } else {
                usize::MAX
            }
        })
        .fold(0usize, usize::saturating_add)
}

/// A NaN with a payload no computation produces: marks untouched doubles.
const SENTINEL: u64 = 0x7ff8_dead_beef_0001;

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

fn bytes_of<T>(x: &T) -> &[u8] {
    // SAFETY: the library's repr(C) response structs, all f64/i32 fields
    // without padding, fully initialised.
    unsafe { std::slice::from_raw_parts(x as *const T as *const u8, core::mem::size_of::<T>()) }
}

/// The dynamic model `sel` (NULL for 255 or none) and its
/// Prandtl–Tomlinson parameters.
fn pick_dynamic(ctx: &Ctx, sel: u8) -> (*mut AsperityDynamicFriction, Option<[f64; 6]>, bool) {
    if sel == 255 || ctx.dynamics.is_empty() {
        (null_mut(), None, false)
    } else {
        let d = &ctx.dynamics[sel as usize % ctx.dynamics.len()];
        (d.model, d.pt, d.heavy)
    }
}

/// The state size of `model`, or 4 for NULL (the call then fails).
unsafe fn dynamic_state_len(model: *const AsperityDynamicFriction) -> usize {
    let mut m = 0usize;
    if model.is_null() || asperity_dynamic_friction_state_size(model, &mut m) != ASPERITY_OK {
        4
    } else {
        m
    }
}

/// Sub-steps the Prandtl–Tomlinson integrations of the increments `dt`,
/// `ds[i]` from `state` are expected to take: about 20 per time scale of
/// the tip (its spring, lattice and damping rates, and the time to cross a
/// lattice period at the speeds the state, the lattice and the support
/// give it), more for tight tolerances. 0 when the library rejects the
/// arguments before integrating; +inf when they overflow.
fn pt_substeps(p: &[f64; 6], state: &[f64], dt: f64, ds: &[f64]) -> f64 {
    let [u0, a, k, m, g, tol] = *p;
    let finite = dt.is_finite()
        && dt >= 0.0
        && ds.iter().all(|x| x.is_finite())
        && state.iter().all(|x| x.is_finite());
    if !finite || dt == 0.0 {
        return 0.0;
    }
    let tau = std::f64::consts::TAU;
    let w = (k / m).sqrt();
    let wl = tau * (u0 / m).sqrt() / a;
    let (rel, v) = (
        state
            .get(ASPERITY_DYNAMIC_STATE_MODEL)
            .map_or(0.0, |x| x.abs()),
        state
            .get(ASPERITY_DYNAMIC_STATE_MODEL + 1)
            .map_or(0.0, |x| x.abs()),
    );
    let tol_factor = (1e-9 / tol).powf(0.2).max(1.0);
    ds.iter()
        .map(|s| {
            let speed = v + w * rel + 2.0 * (u0 / m).sqrt() + s.abs() / dt;
            let rate = w.max(wl).max(g / m) + tau * speed / a;
            let n = 20.0 * dt * rate * tol_factor;
            if n.is_nan() {
                f64::INFINITY
            } else {
                n
            }
        })
        .sum()
}

/// The state size of `slider`, or 8 for NULL (the call then fails).
unsafe fn slider_state_len(slider: *const AsperitySlider) -> usize {
    let mut m = 0usize;
    if slider.is_null() || asperity_slider_state_size(slider, &mut m) != ASPERITY_OK {
        8
    } else {
        m
    }
}

fn make_slider_state(ctx: &Ctx, state: &SliderState, m: usize) -> Vec<f64> {
    make_state(&ctx.slider_state, state, m)
}

/// A state of `m` doubles: zero, the carried one `carried` (when of that
/// length), raw values, or the carried one with one value replaced.
fn make_state(carried: &[f64], state: &SliderState, m: usize) -> Vec<f64> {
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

/// Most calls per input.
const MAX_OPS: usize = 48;

pub fn run(data: &[u8]) {
    let mut u = Unstructured::new(data);
    let mut ctx = Ctx::default();
    let debug = debug();
    for _ in 0..MAX_OPS {
        if u.is_empty() {
            break;
        }
        let Ok(op) = Op::arbitrary(&mut u) else {
            break;
        };
        if debug {
            eprintln!("{op:?}");
        }
        // SAFETY: every pointer the harness passes is NULL or a live buffer
        // of the stated length; handles are live until freed once.
        unsafe { call(&mut ctx, &op) };
    }
}
