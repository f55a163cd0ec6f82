//! Time per call of every single-asperity normal law, through the Rust API and
//! through the C ABI, scalar and batch, next to hand-written -O3 C kernels of
//! the same formulas (`benches/c/kernels.c`, compiled and linked by `build.rs`
//! into the bench targets only).
//!
//! Two modes:
//!
//! * criterion (default): `cargo bench --bench laws [-- FILTER]`; one group per
//!   law, each bench iteration evaluates the same 1024 pre-generated overlaps,
//!   so the reported throughput is per call / per contact.
//! * table: `ASPERITY_BENCH_TABLE=1 cargo bench --bench laws` prints a
//!   Markdown table (law, path, ns/call, ratio to the C kernel) from a simple
//!   calibrated timing loop (median over rounds; all paths of a law are
//!   interleaved round by round so machine noise hits them alike), followed by
//!   the pass/fail of the bars. Tunables: `ASPERITY_BENCH_ROUNDS`
//!   (default 11), `ASPERITY_BENCH_RUN_MS` (target length of one timed run,
//!   default 40).
//!
//! Laws that still return the "not implemented" stub error are reported as
//! pending and skipped (the C kernel rows still run); any other error during
//! the pre-flight check skips the law with the error printed.
//!
//! Inputs are deterministic: each law gets 1024 overlaps spanning its
//! in-contact branch (log-uniform for the non-adhesive laws, linear across
//! δ < 0 and δ > 0 for the adhesive ones). Hysteretic laws are evaluated from
//! a realistic in-contact history: the state the law itself returns after an
//! approach to the largest overlap of the array. Non-hysteretic laws are
//! called through the C ABI with NULL states (the host keeps no history for
//! them; the C kernels compute none either).

use asperity::contact::{
    Derjaguin, Dmt, FlatPunch, Hertz, Jkr, JkrPowerPunch, Kendall, MaugisDugdale, PowerPunch,
    SurfaceLaw,
};
use asperity::ffi::contact::{asperity_normal_eval, asperity_normal_eval_batch, AsperityNormalLaw};
use asperity::{ContactState, Error, NormalContact, NormalLaw, NormalResponse};
use criterion::{Criterion, Throughput};
use std::f64::consts::PI;
use std::hint::black_box;
use std::time::{Duration, Instant};

/// Contacts per batch call, and overlaps per bench iteration.
const N: usize = 1024;

// ---------------------------------------------------------------------------
// The C kernels (benches/c/kernels.h)
// ---------------------------------------------------------------------------

/// `ck_response`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
struct CkResponse {
    force: f64,
    contact_radius: f64,
    stiffness: f64,
}

/// `ck_state`.
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
struct CkState {
    contact_radius: f64,
    in_contact: i32,
    pad: i32,
}

#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
struct CkHertz {
    radius: f64,
    e_star: f64,
}

#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
struct CkPowerPunch {
    inv_depth_coefficient: f64,
    inv_d: f64,
    force_factor: f64,
    two_e_star: f64,
}

#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
struct CkFlatPunch {
    radius: f64,
    stiffness: f64,
}

#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
struct CkDmt {
    radius: f64,
    e_star: f64,
    adhesive_force: f64,
}

#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
struct CkJkr {
    radius: f64,
    e_star: f64,
    y0: f64,
    delta_scale: f64,
    a0: f64,
    delta_c: f64,
    force_scale: f64,
    stiff_scale: f64,
}

#[cfg(asperity_c_kernels)]
mod ck {
    use super::*;
    extern "C" {
        pub fn ck_hertz_init(law: *mut CkHertz, radius: f64, e_star: f64);
        pub fn ck_hertz_eval(law: *const CkHertz, delta: f64) -> CkResponse;
        pub fn ck_hertz_batch(
            law: *const CkHertz,
            n: usize,
            delta: *const f64,
            force: *mut f64,
            contact_radius: *mut f64,
            stiffness: *mut f64,
        );
        pub fn ck_power_punch_init(law: *mut CkPowerPunch, b: f64, d: f64, e_star: f64);
        pub fn ck_power_punch_eval(law: *const CkPowerPunch, delta: f64) -> CkResponse;
        pub fn ck_power_punch_batch(
            law: *const CkPowerPunch,
            n: usize,
            delta: *const f64,
            force: *mut f64,
            contact_radius: *mut f64,
            stiffness: *mut f64,
        );
        pub fn ck_flat_punch_init(law: *mut CkFlatPunch, radius: f64, e_star: f64, c_ns: f64);
        pub fn ck_flat_punch_eval(law: *const CkFlatPunch, delta: f64) -> CkResponse;
        pub fn ck_flat_punch_batch(
            law: *const CkFlatPunch,
            n: usize,
            delta: *const f64,
            force: *mut f64,
            contact_radius: *mut f64,
            stiffness: *mut f64,
        );
        pub fn ck_dmt_init(law: *mut CkDmt, radius: f64, e_star: f64, w: f64);
        pub fn ck_dmt_eval(law: *const CkDmt, delta: f64) -> CkResponse;
        pub fn ck_dmt_batch(
            law: *const CkDmt,
            n: usize,
            delta: *const f64,
            force: *mut f64,
            contact_radius: *mut f64,
            stiffness: *mut f64,
        );
        pub fn ck_jkr_init(law: *mut CkJkr, radius: f64, e_star: f64, w: f64);
        pub fn ck_jkr_eval(
            law: *const CkJkr,
            delta: f64,
            old_state: *const CkState,
            new_state: *mut CkState,
        ) -> CkResponse;
        pub fn ck_jkr_batch(
            law: *const CkJkr,
            n: usize,
            delta: *const f64,
            old_state: *const CkState,
            new_state: *mut CkState,
            force: *mut f64,
            contact_radius: *mut f64,
            stiffness: *mut f64,
        );
    }
}

/// A C kernel with its precomputed parameters.
#[derive(Debug, Clone, Copy)]
enum CKernel {
    Hertz(CkHertz),
    PowerPunch(CkPowerPunch),
    FlatPunch(CkFlatPunch),
    Dmt(CkDmt),
    Jkr(CkJkr),
}

/// Output arrays of one batch call.
struct Buffers {
    force: Vec<f64>,
    contact_radius: Vec<f64>,
    stiffness: Vec<f64>,
    states: Vec<ContactState>,
    ck_states: Vec<CkState>,
}

impl Buffers {
    fn new() -> Self {
        Self {
            force: vec![0.0; N],
            contact_radius: vec![0.0; N],
            stiffness: vec![0.0; N],
            states: vec![ContactState::default(); N],
            ck_states: vec![CkState::default(); N],
        }
    }
    fn sink(&self) {
        black_box(self.force.as_ptr());
        black_box(self.contact_radius.as_ptr());
        black_box(self.stiffness.as_ptr());
        black_box(self.states.as_ptr());
        black_box(self.ck_states.as_ptr());
    }
}

impl CKernel {
    /// Build the kernel for `spec`, or None when the law has none or the C
    /// kernels were not compiled.
    #[allow(unused_variables, unused_mut)]
    fn for_spec(spec: &Spec) -> Option<Self> {
        #[cfg(asperity_c_kernels)]
        unsafe {
            return match *spec {
                Spec::Hertz { radius, e_star } => {
                    let mut p = CkHertz::default();
                    ck::ck_hertz_init(&mut p, radius, e_star);
                    Some(CKernel::Hertz(p))
                }
                Spec::PowerPunch { b, d, e_star } => {
                    let mut p = CkPowerPunch::default();
                    ck::ck_power_punch_init(&mut p, b, d, e_star);
                    Some(CKernel::PowerPunch(p))
                }
                Spec::Cone { half_angle, e_star } => {
                    let mut p = CkPowerPunch::default();
                    ck::ck_power_punch_init(&mut p, 1.0 / half_angle.tan(), 1.0, e_star);
                    Some(CKernel::PowerPunch(p))
                }
                Spec::FlatPunch { radius, e_star } => {
                    let mut p = CkFlatPunch::default();
                    ck::ck_flat_punch_init(&mut p, radius, e_star, 1.0);
                    Some(CKernel::FlatPunch(p))
                }
                Spec::Dmt { radius, e_star, w } => {
                    let mut p = CkDmt::default();
                    ck::ck_dmt_init(&mut p, radius, e_star, w);
                    Some(CKernel::Dmt(p))
                }
                Spec::Jkr { radius, e_star, w } => {
                    let mut p = CkJkr::default();
                    ck::ck_jkr_init(&mut p, radius, e_star, w);
                    Some(CKernel::Jkr(p))
                }
                _ => None,
            };
        }
        #[allow(unreachable_code)]
        None
    }

    /// One scalar call per overlap.
    #[inline(never)]
    #[allow(unused_variables)]
    fn scalar_pass(&self, deltas: &[f64], old: &CkState) {
        #[cfg(asperity_c_kernels)]
        unsafe {
            match self {
                CKernel::Hertz(p) => {
                    for &d in deltas {
                        black_box(ck::ck_hertz_eval(black_box(p), black_box(d)));
                    }
                }
                CKernel::PowerPunch(p) => {
                    for &d in deltas {
                        black_box(ck::ck_power_punch_eval(black_box(p), black_box(d)));
                    }
                }
                CKernel::FlatPunch(p) => {
                    for &d in deltas {
                        black_box(ck::ck_flat_punch_eval(black_box(p), black_box(d)));
                    }
                }
                CKernel::Dmt(p) => {
                    for &d in deltas {
                        black_box(ck::ck_dmt_eval(black_box(p), black_box(d)));
                    }
                }
                CKernel::Jkr(p) => {
                    let mut new = CkState::default();
                    for &d in deltas {
                        black_box(ck::ck_jkr_eval(black_box(p), black_box(d), old, &mut new));
                        black_box(&mut new);
                    }
                }
            }
            return;
        }
        #[allow(unreachable_code)]
        {
            unreachable!("C kernels not compiled")
        }
    }

    /// One batch call over all overlaps.
    #[inline(never)]
    #[allow(unused_variables)]
    fn batch_pass(&self, deltas: &[f64], old: &[CkState], out: &mut Buffers) {
        #[cfg(asperity_c_kernels)]
        unsafe {
            let n = deltas.len();
            let (f, a, k) = (
                out.force.as_mut_ptr(),
                out.contact_radius.as_mut_ptr(),
                out.stiffness.as_mut_ptr(),
            );
            match self {
                CKernel::Hertz(p) => ck::ck_hertz_batch(black_box(p), n, deltas.as_ptr(), f, a, k),
                CKernel::PowerPunch(p) => {
                    ck::ck_power_punch_batch(black_box(p), n, deltas.as_ptr(), f, a, k)
                }
                CKernel::FlatPunch(p) => {
                    ck::ck_flat_punch_batch(black_box(p), n, deltas.as_ptr(), f, a, k)
                }
                CKernel::Dmt(p) => ck::ck_dmt_batch(black_box(p), n, deltas.as_ptr(), f, a, k),
                CKernel::Jkr(p) => ck::ck_jkr_batch(
                    black_box(p),
                    n,
                    deltas.as_ptr(),
                    old.as_ptr(),
                    out.ck_states.as_mut_ptr(),
                    f,
                    a,
                    k,
                ),
            }
            out.sink();
            return;
        }
        #[allow(unreachable_code)]
        {
            unreachable!("C kernels not compiled")
        }
    }

    /// (force, contact radius, stiffness, in_contact) of one scalar call.
    #[allow(unused_variables)]
    fn eval_one(&self, delta: f64, old: &CkState) -> (CkResponse, i32) {
        #[cfg(asperity_c_kernels)]
        unsafe {
            return match self {
                CKernel::Hertz(p) => (ck::ck_hertz_eval(p, delta), -1),
                CKernel::PowerPunch(p) => (ck::ck_power_punch_eval(p, delta), -1),
                CKernel::FlatPunch(p) => (ck::ck_flat_punch_eval(p, delta), -1),
                CKernel::Dmt(p) => (ck::ck_dmt_eval(p, delta), -1),
                CKernel::Jkr(p) => {
                    let mut new = CkState::default();
                    let r = ck::ck_jkr_eval(p, delta, old, &mut new);
                    (r, new.in_contact)
                }
            };
        }
        #[allow(unreachable_code)]
        {
            unreachable!("C kernels not compiled")
        }
    }
}

// ---------------------------------------------------------------------------
// The laws and their inputs
// ---------------------------------------------------------------------------

/// Parameters of one benchmarked law (SI).
#[derive(Debug, Clone, Copy)]
enum Spec {
    Hertz {
        radius: f64,
        e_star: f64,
    },
    PowerPunch {
        b: f64,
        d: f64,
        e_star: f64,
    },
    Cone {
        half_angle: f64,
        e_star: f64,
    },
    FlatPunch {
        radius: f64,
        e_star: f64,
    },
    Dmt {
        radius: f64,
        e_star: f64,
        w: f64,
    },
    Jkr {
        radius: f64,
        e_star: f64,
        w: f64,
    },
    JkrPowerPunch {
        b: f64,
        d: f64,
        e_star: f64,
        w: f64,
    },
    Kendall {
        radius: f64,
        e_star: f64,
        w: f64,
    },
    MaugisDugdale {
        radius: f64,
        e_star: f64,
        w: f64,
        sigma0: f64,
    },
    DerjaguinLj {
        radius: f64,
        w: f64,
        z0: f64,
    },
}

impl Spec {
    fn law(&self) -> asperity::Result<NormalLaw> {
        Ok(match *self {
            Spec::Hertz { radius, e_star } => NormalLaw::Hertz(Hertz::new(radius, e_star)?),
            Spec::PowerPunch { b, d, e_star } => {
                NormalLaw::PowerPunch(PowerPunch::new(b, d, e_star)?)
            }
            Spec::Cone { half_angle, e_star } => {
                NormalLaw::PowerPunch(PowerPunch::cone(half_angle, e_star)?)
            }
            Spec::FlatPunch { radius, e_star } => {
                NormalLaw::FlatPunch(FlatPunch::new(radius, e_star)?)
            }
            Spec::Dmt { radius, e_star, w } => NormalLaw::Dmt(Dmt::new(radius, e_star, w)?),
            Spec::Jkr { radius, e_star, w } => NormalLaw::Jkr(Jkr::new(radius, e_star, w)?),
            Spec::JkrPowerPunch { b, d, e_star, w } => {
                NormalLaw::JkrPowerPunch(JkrPowerPunch::new(b, d, e_star, w)?)
            }
            Spec::Kendall { radius, e_star, w } => {
                NormalLaw::Kendall(Kendall::new(radius, e_star, w)?)
            }
            Spec::MaugisDugdale {
                radius,
                e_star,
                w,
                sigma0,
            } => NormalLaw::MaugisDugdale(MaugisDugdale::new(radius, e_star, w, sigma0)?),
            Spec::DerjaguinLj { radius, w, z0 } => NormalLaw::Derjaguin(Derjaguin::new(
                radius,
                SurfaceLaw::LennardJones {
                    work_of_adhesion: w,
                    equilibrium_separation: z0,
                },
            )?),
        })
    }

    /// Whether the law keeps history (hysteresis), so the state is passed.
    fn hysteretic(&self) -> bool {
        matches!(
            self,
            Spec::Jkr { .. }
                | Spec::JkrPowerPunch { .. }
                | Spec::Kendall { .. }
                | Spec::MaugisDugdale { .. }
        )
    }

    /// Closed-form laws: the 1.5× bar against the C kernel applies.
    fn closed_form(&self) -> bool {
        matches!(
            self,
            Spec::Hertz { .. }
                | Spec::PowerPunch { .. }
                | Spec::Cone { .. }
                | Spec::FlatPunch { .. }
                | Spec::Dmt { .. }
                | Spec::Jkr { .. }
        )
    }

    /// 1024 deterministic overlaps spanning the in-contact branch.
    fn deltas(&self) -> Vec<f64> {
        match *self {
            Spec::Hertz { .. }
            | Spec::PowerPunch { .. }
            | Spec::FlatPunch { .. }
            | Spec::Dmt { .. } => log_uniform(1e-10, 1e-8, 1),
            Spec::Cone { .. } => log_uniform(1e-9, 1e-7, 2),
            Spec::Jkr { radius, e_star, w } => {
                let dc = jkr_delta_c(radius, e_star, w);
                uniform(0.95 * dc, -4.0 * dc, 3)
            }
            Spec::JkrPowerPunch { b, d, e_star, w } => {
                // δ(a) = D B a^d − √(2πwa/E*); its minimum is the displacement-
                // controlled separation.
                let dd = asperity::contact::power_punch::galin_d(d);
                let dmin = (0..4000)
                    .map(|i| 1e-10 * 10f64.powf(i as f64 * 6.0 / 4000.0))
                    .map(|a| dd * b * a.powf(d) - (2.0 * PI * w * a / e_star).sqrt())
                    .fold(0.0, f64::min);
                uniform(0.95 * dmin, -4.0 * dmin, 4)
            }
            Spec::Kendall { radius, e_star, w } => {
                let dc = -(2.0 * PI * w * radius / e_star).sqrt();
                uniform(0.95 * dc, -4.0 * dc, 5)
            }
            Spec::MaugisDugdale {
                radius, e_star, w, ..
            } => {
                let dc = jkr_delta_c(radius, e_star, w);
                uniform(0.3 * dc, -4.0 * dc, 6)
            }
            Spec::DerjaguinLj { z0, .. } => uniform(-4.0 * z0, 0.3 * z0, 7),
        }
    }
}

/// JKR displacement-controlled separation `−(3/4)(π²w²R/E*²)^{1/3}` (m).
fn jkr_delta_c(radius: f64, e_star: f64, w: f64) -> f64 {
    -0.75 * (PI * PI * w * w * radius / (e_star * e_star)).cbrt()
}

/// Deterministic uniform numbers in [0, 1) (64-bit LCG, top 53 bits).
fn lcg(seed: u64) -> impl Iterator<Item = f64> {
    let mut s = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) ^ 0x2545_F491_4F6C_DD1D;
    std::iter::repeat_with(move || {
        s = s
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (s >> 11) as f64 / (1u64 << 53) as f64
    })
}

fn uniform(lo: f64, hi: f64, seed: u64) -> Vec<f64> {
    lcg(seed).take(N).map(|u| lo + (hi - lo) * u).collect()
}

fn log_uniform(lo: f64, hi: f64, seed: u64) -> Vec<f64> {
    let (l, h) = (lo.ln(), hi.ln());
    lcg(seed).take(N).map(|u| (l + (h - l) * u).exp()).collect()
}

/// The benchmarked laws. Soft adhesive contacts (E* = 1 GPa, w = 0.05 J/m²,
/// R = 10 µm) for the adhesive laws, stiff ones (E* = 100 GPa) otherwise.
fn specs() -> Vec<(&'static str, &'static str, Spec)> {
    let (e_soft, w, r) = (1e9, 0.05, 10e-6);
    // Maugis λ = 2σ₀ (R/(πwK²))^{1/3} = 1 with K = 4E*/3.
    let k = 4.0 * e_soft / 3.0;
    let sigma0 = 0.5 * (PI * w * k * k / r).cbrt();
    vec![
        (
            "hertz",
            "Hertz",
            Spec::Hertz {
                radius: r,
                e_star: 100e9,
            },
        ),
        (
            "power_punch_d1.5",
            "power punch d=1.5",
            Spec::PowerPunch {
                b: 50.0,
                d: 1.5,
                e_star: 100e9,
            },
        ),
        (
            "cone_70.3deg",
            "cone 70.3°",
            Spec::Cone {
                half_angle: asperity::contact::power_punch::BERKOVICH_EQUIVALENT_HALF_ANGLE,
                e_star: 100e9,
            },
        ),
        (
            "flat_punch",
            "flat punch",
            Spec::FlatPunch {
                radius: 1e-6,
                e_star: 100e9,
            },
        ),
        (
            "dmt",
            "DMT",
            Spec::Dmt {
                radius: r,
                e_star: 100e9,
                w: 0.1,
            },
        ),
        (
            "jkr",
            "JKR sphere (displacement control)",
            Spec::Jkr {
                radius: r,
                e_star: e_soft,
                w,
            },
        ),
        (
            "jkr_power_punch_d1.5",
            "JKR power punch d=1.5",
            Spec::JkrPowerPunch {
                b: 50.0,
                d: 1.5,
                e_star: e_soft,
                w,
            },
        ),
        (
            "kendall",
            "Kendall",
            Spec::Kendall {
                radius: 1e-6,
                e_star: e_soft,
                w,
            },
        ),
        (
            "maugis_dugdale_lambda1",
            "Maugis–Dugdale λ=1",
            Spec::MaugisDugdale {
                radius: r,
                e_star: e_soft,
                w,
                sigma0,
            },
        ),
        (
            "derjaguin_lj",
            "Derjaguin LJ 3-9",
            Spec::DerjaguinLj {
                radius: r,
                w,
                z0: 0.3e-9,
            },
        ),
    ]
}

// ---------------------------------------------------------------------------
// Cases: a law, its inputs, its state, and whether it runs yet
// ---------------------------------------------------------------------------

enum Status {
    Ready,
    /// The law still returns the stub error.
    Pending,
    /// Pre-flight failed with another error.
    Failed(String),
}

struct Case {
    /// Criterion group id.
    id: &'static str,
    name: &'static str,
    spec: Spec,
    law: Option<NormalLaw>,
    c_law: Option<AsperityNormalLaw>,
    deltas: Vec<f64>,
    /// In-contact history for hysteretic laws (the state after approaching to
    /// the largest overlap); default otherwise.
    state: ContactState,
    states: Vec<ContactState>,
    ck: Option<CKernel>,
    ck_state: CkState,
    ck_states: Vec<CkState>,
    status: Status,
}

fn is_stub(e: &Error) -> bool {
    matches!(e, Error::OutOfDomain { reason, .. } if reason.contains("not implemented"))
}

impl Case {
    fn new(id: &'static str, name: &'static str, spec: Spec) -> Self {
        let deltas = spec.deltas();
        let ck = CKernel::for_spec(&spec);
        let ck_state = CkState {
            contact_radius: 0.0,
            in_contact: 1,
            pad: 0,
        };
        let mut case = Case {
            id,
            name,
            spec,
            law: None,
            c_law: None,
            deltas,
            state: ContactState::default(),
            states: vec![ContactState::default(); N],
            ck,
            ck_state,
            ck_states: vec![ck_state; N],
            status: Status::Ready,
        };
        case.status = case.preflight();
        case
    }

    fn preflight(&mut self) -> Status {
        let law = match self.spec.law() {
            Ok(l) => l,
            Err(e) => return Status::Failed(format!("constructor: {e}")),
        };
        self.law = Some(law);
        self.c_law = Some(law.into());
        let approach = self.deltas.iter().cloned().fold(f64::MIN, f64::max);
        let state = match law.eval(approach, &ContactState::default()) {
            Ok((_, s)) => s,
            Err(e) if is_stub(&e) => return Status::Pending,
            Err(e) => return Status::Failed(format!("approach to δ = {approach:e}: {e}")),
        };
        if self.spec.hysteretic() {
            if state.in_contact != 1 {
                return Status::Failed(format!(
                    "approach to δ = {approach:e} did not make contact: {state:?}"
                ));
            }
            self.state = state;
            self.states = vec![state; N];
        }
        for &d in &self.deltas {
            if let Err(e) = law.eval(d, &self.state) {
                if is_stub(&e) {
                    return Status::Pending;
                }
                return Status::Failed(format!("δ = {d:e}: {e}"));
            }
        }
        let mut b = Buffers::new();
        if let Err(msg) = self.c_abi_batch_pass(&mut b) {
            return Status::Failed(format!("C ABI batch: {msg}"));
        }
        Status::Ready
    }

    fn ready(&self) -> bool {
        matches!(self.status, Status::Ready)
    }

    fn status_note(&self) -> String {
        match &self.status {
            Status::Ready => String::new(),
            Status::Pending => "pending: law not yet implemented".into(),
            Status::Failed(m) => format!("error: {m}"),
        }
    }

    /// Rust API, concrete law type.
    fn rust_pass(&self) {
        let keep = self.spec.hysteretic();
        match self.law.as_ref().expect("law") {
            NormalLaw::Hertz(l) => rust_pass(l, &self.deltas, &self.state, keep),
            NormalLaw::PowerPunch(l) => rust_pass(l, &self.deltas, &self.state, keep),
            NormalLaw::FlatPunch(l) => rust_pass(l, &self.deltas, &self.state, keep),
            NormalLaw::Dmt(l) => rust_pass(l, &self.deltas, &self.state, keep),
            NormalLaw::Jkr(l) => rust_pass(l, &self.deltas, &self.state, keep),
            NormalLaw::JkrPowerPunch(l) => rust_pass(l, &self.deltas, &self.state, keep),
            NormalLaw::Kendall(l) => rust_pass(l, &self.deltas, &self.state, keep),
            NormalLaw::MaugisDugdale(l) => rust_pass(l, &self.deltas, &self.state, keep),
            NormalLaw::Derjaguin(l) => rust_pass(l, &self.deltas, &self.state, keep),
        }
    }

    /// Rust API through the `NormalLaw` enum (dispatch on every call).
    fn rust_enum_pass(&self) {
        rust_pass(
            self.law.as_ref().expect("law"),
            &self.deltas,
            &self.state,
            self.spec.hysteretic(),
        )
    }

    fn c_abi_scalar_pass(&self) {
        let law = self.c_law.as_ref().expect("law");
        if self.spec.hysteretic() {
            c_abi_scalar_pass(law, &self.deltas, &self.state, true)
        } else {
            c_abi_scalar_pass(law, &self.deltas, &self.state, false)
        }
    }

    fn c_abi_batch_pass(&self, out: &mut Buffers) -> Result<(), String> {
        let law = self.c_law.as_ref().expect("law");
        let (old, new): (*const ContactState, *mut ContactState) = if self.spec.hysteretic() {
            (self.states.as_ptr(), out.states.as_mut_ptr())
        } else {
            (std::ptr::null(), std::ptr::null_mut())
        };
        let s = unsafe {
            asperity_normal_eval_batch(
                black_box(law),
                self.deltas.len(),
                self.deltas.as_ptr(),
                old,
                new,
                out.force.as_mut_ptr(),
                out.contact_radius.as_mut_ptr(),
                out.stiffness.as_mut_ptr(),
            )
        };
        out.sink();
        if s != 0 {
            return Err(format!("status {s}: {}", last_error()));
        }
        Ok(())
    }

    fn c_kernel_scalar_pass(&self) {
        self.ck
            .as_ref()
            .expect("C kernel")
            .scalar_pass(&self.deltas, &self.ck_state)
    }

    fn c_kernel_batch_pass(&self, out: &mut Buffers) {
        self.ck
            .as_ref()
            .expect("C kernel")
            .batch_pass(&self.deltas, &self.ck_states, out)
    }

    /// Compare the C kernel with the library (or, while the law is pending,
    /// check it against the law's forward formula), and print the worst
    /// relative differences.
    fn cross_check(&self) {
        let Some(ck) = self.ck.as_ref() else { return };
        let (mut df, mut da, mut dk) = (0f64, 0f64, 0f64);
        let rel = |x: f64, y: f64, scale: f64| (x - y).abs() / scale.max(1e-300);
        if self.ready() {
            let law = self.law.as_ref().unwrap();
            let fscale = self
                .deltas
                .iter()
                .map(|&d| law.eval(d, &self.state).unwrap().0.force.abs())
                .fold(0.0, f64::max);
            for &d in &self.deltas {
                let (r, _) = law.eval(d, &self.state).unwrap();
                let (c, _) = ck.eval_one(d, &self.ck_state);
                df = df.max(rel(r.force, c.force, fscale));
                da = da.max(rel(
                    r.contact_radius,
                    c.contact_radius,
                    r.contact_radius.abs(),
                ));
                dk = dk.max(rel(r.stiffness, c.stiffness, r.stiffness.abs()));
            }
            eprintln!(
                "check {:<28} C kernel vs library: max rel. diff force {df:.1e} (of max |P|), radius {da:.1e}, stiffness {dk:.1e}",
                self.name
            );
        } else if let Spec::Jkr { radius, e_star, w } = self.spec {
            // Independent check of the C JKR kernel: the returned a must give
            // back δ = a²/R − √(2πwa/E*) and P = 4E*a³/(3R) − √(8πwE*a³).
            let dc = jkr_delta_c(radius, e_star, w).abs();
            let mut fscale = 0f64;
            let mut out_of_contact = 0;
            for &d in &self.deltas {
                let (c, inc) = ck.eval_one(d, &self.ck_state);
                if inc != 1 {
                    out_of_contact += 1;
                    continue;
                }
                let a = c.contact_radius;
                let delta = a * a / radius - (2.0 * PI * w * a / e_star).sqrt();
                let p = 4.0 * e_star * a.powi(3) / (3.0 * radius)
                    - (8.0 * PI * w * e_star * a.powi(3)).sqrt();
                // dP/dδ = (dP/da)/(dδ/da)
                let dp = 4.0 * e_star * a * a / radius - 1.5 * (8.0 * PI * w * e_star * a).sqrt();
                let dd = 2.0 * a / radius - 0.5 * (2.0 * PI * w / (e_star * a)).sqrt();
                fscale = fscale.max(p.abs());
                da = da.max((delta - d).abs() / dc);
                df = df.max((p - c.force).abs());
                dk = dk.max(rel(dp / dd, c.stiffness, c.stiffness.abs()));
            }
            eprintln!(
                "check {:<28} C kernel self-check (law pending): max |δ(a) − δ|/|δ_c| {da:.1e}, force {:.1e} (of max |P|), stiffness {dk:.1e}, {out_of_contact} out of contact",
                self.name,
                df / fscale
            );
        }
    }
}

fn last_error() -> String {
    let mut buf = vec![0u8; 512];
    let n =
        unsafe { asperity::ffi::asperity_last_error_message(buf.as_mut_ptr().cast(), buf.len()) };
    buf.truncate(n.min(511));
    String::from_utf8_lossy(&buf).into_owned()
}

#[cold]
#[inline(never)]
fn failed(what: &str, d: f64, msg: String) -> ! {
    panic!("{what} failed at δ = {d:e}: {msg}")
}

/// One scalar Rust-API call per overlap; `law` is re-read through a
/// `black_box`ed reference on every call, like a host that keeps its laws in
/// memory.
#[inline(never)]
fn rust_pass<L: NormalContact>(law: &L, deltas: &[f64], old: &ContactState, keep_state: bool) {
    for &d in deltas {
        match black_box(law).eval(black_box(d), old) {
            Ok((r, s)) => {
                black_box::<NormalResponse>(r);
                if keep_state {
                    black_box(s);
                }
            }
            Err(e) => failed("Rust eval", d, e.to_string()),
        }
    }
}

/// One `asperity_normal_eval` per overlap.
#[inline(never)]
fn c_abi_scalar_pass(
    law: &AsperityNormalLaw,
    deltas: &[f64],
    old: &ContactState,
    with_state: bool,
) {
    let mut out = NormalResponse::default();
    let mut new = ContactState::default();
    let (old_p, new_p): (*const ContactState, *mut ContactState) = if with_state {
        (old, &mut new)
    } else {
        (std::ptr::null(), std::ptr::null_mut())
    };
    for &d in deltas {
        let s =
            unsafe { asperity_normal_eval(black_box(law), black_box(d), old_p, new_p, &mut out) };
        if s != 0 {
            failed("asperity_normal_eval", d, last_error());
        }
        black_box(&mut out);
        if with_state {
            black_box(new_p);
        }
    }
}

// ---------------------------------------------------------------------------
// Paths
// ---------------------------------------------------------------------------

#[derive(Debug, Clone, Copy, PartialEq)]
enum Path {
    RustConcrete,
    RustEnum,
    CAbiScalar,
    CAbiBatch,
    CKernelScalar,
    CKernelBatch,
}

impl Path {
    const ALL: [Path; 6] = [
        Path::RustConcrete,
        Path::RustEnum,
        Path::CAbiScalar,
        Path::CAbiBatch,
        Path::CKernelScalar,
        Path::CKernelBatch,
    ];

    fn id(self) -> &'static str {
        match self {
            Path::RustConcrete => "rust_scalar",
            Path::RustEnum => "rust_enum_scalar",
            Path::CAbiScalar => "c_abi_scalar",
            Path::CAbiBatch => "c_abi_batch",
            Path::CKernelScalar => "c_kernel_scalar",
            Path::CKernelBatch => "c_kernel_batch",
        }
    }

    fn label(self) -> &'static str {
        match self {
            Path::RustConcrete => "Rust `<Law>::eval` (scalar)",
            Path::RustEnum => "Rust `NormalLaw::eval` (scalar)",
            Path::CAbiScalar => "C ABI `asperity_normal_eval` (scalar)",
            Path::CAbiBatch => "C ABI `asperity_normal_eval_batch` (per contact, n = 1024)",
            Path::CKernelScalar => "C kernel -O3 (scalar)",
            Path::CKernelBatch => "C kernel -O3 (batch, per contact)",
        }
    }

    fn is_batch(self) -> bool {
        matches!(self, Path::CAbiBatch | Path::CKernelBatch)
    }

    fn is_kernel(self) -> bool {
        matches!(self, Path::CKernelScalar | Path::CKernelBatch)
    }

    /// The C-kernel path this one is compared with.
    fn reference(self) -> Path {
        if self.is_batch() {
            Path::CKernelBatch
        } else {
            Path::CKernelScalar
        }
    }

    fn available(self, case: &Case) -> bool {
        if self.is_kernel() {
            case.ck.is_some()
        } else {
            case.ready()
        }
    }

    /// One pass over the case's overlaps (N calls, or one batch of N).
    #[inline]
    fn run(self, case: &Case, buffers: &mut Buffers) {
        match self {
            Path::RustConcrete => case.rust_pass(),
            Path::RustEnum => case.rust_enum_pass(),
            Path::CAbiScalar => case.c_abi_scalar_pass(),
            Path::CAbiBatch => {
                if let Err(m) = case.c_abi_batch_pass(buffers) {
                    panic!("{}: asperity_normal_eval_batch failed: {m}", case.name)
                }
            }
            Path::CKernelScalar => case.c_kernel_scalar_pass(),
            Path::CKernelBatch => case.c_kernel_batch_pass(buffers),
        }
    }
}

// ---------------------------------------------------------------------------
// Criterion mode
// ---------------------------------------------------------------------------

fn bench_laws(c: &mut Criterion, cases: &[Case]) {
    for case in cases {
        if !case.ready() {
            eprintln!(
                "note: {}: {} (skipping its library paths)",
                case.name,
                case.status_note()
            );
        }
        let paths: Vec<Path> = Path::ALL
            .iter()
            .copied()
            .filter(|p| p.available(case))
            .collect();
        if paths.is_empty() {
            continue;
        }
        let mut group = c.benchmark_group(case.id);
        group.throughput(Throughput::Elements(case.deltas.len() as u64));
        let mut buffers = Buffers::new();
        for p in paths {
            group.bench_function(p.id(), |b| b.iter(|| p.run(case, &mut buffers)));
        }
        group.finish();
    }
}

// ---------------------------------------------------------------------------
// Table mode
// ---------------------------------------------------------------------------

fn env_num(name: &str, default: f64) -> f64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

/// Median ns per call of every available path of `case`, interleaved by round.
fn time_case(case: &Case, rounds: usize, run_time: Duration) -> Vec<(Path, f64)> {
    let mut buffers = Buffers::new();
    let paths: Vec<Path> = Path::ALL
        .iter()
        .copied()
        .filter(|p| p.available(case))
        .collect();
    // Calibrate: passes per timed run so that one run lasts about `run_time`.
    let reps: Vec<u64> = paths
        .iter()
        .map(|&p| {
            for _ in 0..3 {
                p.run(case, &mut buffers); // warm up
            }
            let t = Instant::now();
            let mut k = 0u64;
            while t.elapsed() < run_time / 10 {
                p.run(case, &mut buffers);
                k += 1;
            }
            (k * 10).max(1)
        })
        .collect();
    let mut samples: Vec<Vec<f64>> = vec![Vec::with_capacity(rounds); paths.len()];
    for _ in 0..rounds {
        for (i, &p) in paths.iter().enumerate() {
            let t = Instant::now();
            for _ in 0..reps[i] {
                p.run(case, &mut buffers);
            }
            let ns = t.elapsed().as_nanos() as f64 / (reps[i] as f64 * case.deltas.len() as f64);
            samples[i].push(ns);
        }
    }
    paths
        .into_iter()
        .zip(samples)
        .map(|(p, mut s)| {
            s.sort_by(|a, b| a.partial_cmp(b).unwrap());
            (p, s[s.len() / 2])
        })
        .collect()
}

fn machine() -> String {
    let cpu = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "unknown".into());
    let n = std::thread::available_parallelism()
        .map(|n| n.get())
        .unwrap_or(0);
    format!(
        "{cpu}, {n} logical CPUs available, load average {}",
        load_average()
    )
}

/// The 1-minute load average (other processes competing for the cores).
fn load_average() -> String {
    std::fs::read_to_string("/proc/loadavg")
        .ok()
        .and_then(|s| s.split_whitespace().next().map(str::to_string))
        .unwrap_or_else(|| "unknown".into())
}

fn table(cases: &[Case]) {
    let rounds = env_num("ASPERITY_BENCH_ROUNDS", 11.0).max(1.0) as usize;
    let run_time = Duration::from_secs_f64(env_num("ASPERITY_BENCH_RUN_MS", 40.0).max(1.0) / 1e3);
    println!("Machine: {}", machine());
    println!(
        "Timing: median of {rounds} rounds, each path ~{} ms per round ({N} overlaps per pass), paths interleaved.\n",
        run_time.as_millis()
    );
    println!("| law | path | ns/call | ratio to C kernel |");
    println!("|---|---|---:|---:|");
    let mut verdicts: Vec<String> = Vec::new();
    for case in cases {
        let times = time_case(case, rounds, run_time);
        let of = |p: Path| times.iter().find(|(q, _)| *q == p).map(|t| t.1);
        for p in Path::ALL {
            if p.is_kernel() && case.ck.is_none() {
                continue;
            }
            match of(p) {
                Some(ns) => {
                    let ratio = match of(p.reference()) {
                        Some(r) if !p.is_kernel() => format!("{:.2}", ns / r),
                        Some(_) => "1.00".into(),
                        None => "n/a (no C kernel)".into(),
                    };
                    println!("| {} | {} | {:.1} | {} |", case.name, p.label(), ns, ratio);
                }
                None => println!(
                    "| {} | {} | {} | |",
                    case.name,
                    p.label(),
                    case.status_note()
                ),
            }
        }
        // The bars of the issue.
        let lib_paths = [
            Path::RustConcrete,
            Path::RustEnum,
            Path::CAbiScalar,
            Path::CAbiBatch,
        ];
        if !case.ready() {
            verdicts.push(format!("- {}: {}", case.name, case.status_note()));
            continue;
        }
        if case.spec.closed_form() && case.ck.is_some() {
            let worst = lib_paths
                .iter()
                .filter_map(|&p| Some((p, of(p)? / of(p.reference())?)))
                .fold(
                    (Path::RustConcrete, 0.0),
                    |a, b| if b.1 > a.1 { b } else { a },
                );
            verdicts.push(format!(
                "- {}: closed form within 1.5× of the C kernel: {} (worst {:.2}× on {})",
                case.name,
                if worst.1 <= 1.5 { "PASS" } else { "FAIL" },
                worst.1,
                worst.0.id()
            ));
        }
        if let Spec::Jkr { .. } = case.spec {
            for p in [Path::RustConcrete, Path::RustEnum, Path::CAbiScalar] {
                let ns = of(p).unwrap();
                verdicts.push(format!(
                    "- {}: {} ≤ 40 ns scalar: {} ({ns:.1} ns)",
                    case.name,
                    p.id(),
                    if ns <= 40.0 { "PASS" } else { "FAIL" }
                ));
            }
            let ns = of(Path::CAbiBatch).unwrap();
            verdicts.push(format!(
                "- {}: c_abi_batch ≤ 10 ns per contact: {} ({ns:.1} ns)",
                case.name,
                if ns <= 10.0 { "PASS" } else { "FAIL" }
            ));
        }
        if let Spec::MaugisDugdale { .. } = case.spec {
            let worst = lib_paths.iter().filter_map(|&p| of(p)).fold(0.0, f64::max);
            verdicts.push(format!(
                "- {}: ≤ 1 µs per evaluation: {} (slowest path {worst:.1} ns)",
                case.name,
                if worst <= 1000.0 { "PASS" } else { "FAIL" }
            ));
        }
    }
    println!("\nBars:\n{}", verdicts.join("\n"));
    println!("\nLoad average at the end: {}", load_average());
}

// ---------------------------------------------------------------------------

fn main() {
    if cfg!(not(asperity_c_kernels)) {
        eprintln!("note: the C reference kernels were not compiled (no C compiler?); C-kernel rows are skipped");
    }
    let cases: Vec<Case> = specs()
        .into_iter()
        .map(|(i, n, s)| Case::new(i, n, s))
        .collect();
    for case in &cases {
        if !case.ready() {
            eprintln!("note: {}: {}", case.name, case.status_note());
        }
        case.cross_check();
    }
    if std::env::var("ASPERITY_BENCH_TABLE").is_ok_and(|v| v == "1") {
        table(&cases);
        return;
    }
    let mut c = Criterion::default().configure_from_args();
    bench_laws(&mut c, &cases);
    c.final_summary();
}
