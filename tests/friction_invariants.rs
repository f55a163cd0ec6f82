//! Friction invariants (issue 8 §5, issue 30 §1) over long random
//! host-code increment sequences — random loads, slip increments with
//! reversals and zeros, random cut-backs (re-evaluating from an older
//! state) — for the homogenised law and the slider patch through
//! `FrictionLaw`, in Rust and through the C handle `AsperityFriction`; and
//! the contract every friction law keeps, checked for each (the homogenised
//! law, the slider, the five dynamic models of chapter 5):
//!
//! * dissipation ≥ 0 on every increment (in total and by mechanism);
//! * the work of the friction force equals the dissipation, to rounding.
//!   What "work" means follows each law's documentation:
//!   - homogenised law: `ΔD = −F·Δs_p` (the force at the end of the
//!     increment over the plastic slip, of length the growth of the
//!     state's plastic slip path, along −F) — by construction, to a few
//!     ulps of |F||Δs_p|; the plastic slip is also what the elastic slip
//!     −F/k leaves of the slip, Δs_p = Δs + ΔF/k. Over the **total** slip
//!     the backward-Euler return mapping gives, exactly in real arithmetic,
//!     `−F·Δs = ΔD + ΔE + |ΔF|²/(2k)` with `E = |F|²/(2k)` the stick
//!     energy: the work over the total slip is the dissipation plus the
//!     stored energy change plus `|ΔF|²/(2k)`: not a loss but the extra
//!     work of the end-of-increment force over a force varying linearly
//!     along the increment; not booked in `ΔD`, second order in the
//!     increment. Checked to 1e-12 of Σ|F||Δs|. With k = 0,
//!     `−F·Δs = ΔD`. In the no-contact regime (N + A = 0) the stored
//!     elastic force is dropped to 0 and its energy `|F_old|²/(2k)` is
//!     released without being booked (documented: "no friction, the force
//!     and the stored elastic force are 0"); the balance accounts for it
//!     separately.
//!   - slider: `F_t = ΔU/|Δs|` (thesis (4-1)), so `−F·Δs = F_t|Δs| = ΔU`
//!     to a few ulps.
//!     The accumulators of the state grow by exactly the increment's
//!     dissipation (to rounding of one addition), and their sum over the
//!     slide is the sum of the increments' dissipation (to n·ε).
//! * re-evaluating an increment from the same old state is bit-identical
//!   (what FE hosts rely on for cut-backs);
//! * an all-zero state is always accepted;
//! * every law (`every_law_*`): `step` with old and new separate,
//!   `step_in_place` and `step_block` (old and new separate, and in place)
//!   give bit-identical forces, dissipations and states; state[0] grows by
//!   exactly ΔD and state[1] by exactly |Δs| each increment (so they are the
//!   running sums of the responses, bit for bit); a refused increment or
//!   state leaves the new state (the state stepped in place, the block's
//!   points from the failing one on) untouched; the block with `responses`
//!   gives each point's full response, tangents included, bit for bit as
//!   `step`, and refuses unknown tangent bits or a short `responses` slice
//!   before writing anything.

mod common;
#[path = "common/laws.rs"]
mod laws;

use asperity::ffi::friction_law::*;
use asperity::ffi::homogenised::*;
use asperity::ffi::slider::*;
use asperity::ffi::*;
use asperity::friction::CofForm;
use asperity::friction::{
    FrictionIncrement, FrictionLaw, FrictionRegime, FrictionResponse, HomogenisedFriction, Slider,
    SliderWork,
};
use laws::{bits, same, Rng};
use std::ptr::{null, null_mut};

const EPS: f64 = f64::EPSILON;

fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

fn norm(a: [f64; 2]) -> f64 {
    dot(a, a).sqrt()
}

fn response_bits(r: &FrictionResponse) -> String {
    format!("{r:?}")
}

/// A random slip increment: a direction that reverses or turns, a size
/// log-uniform over 4 decades, zero one time in eight.
fn random_slip(rng: &mut Rng, last: [f64; 2]) -> [f64; 2] {
    if rng.f() < 0.125 {
        return [0.0, 0.0];
    }
    let size = log_uniform(rng, 1e-9, 1e-5);
    let u = rng.f();
    let dir = if u < 0.3 && norm(last) > 0.0 {
        // Reversal.
        let n = norm(last);
        [-last[0] / n, -last[1] / n]
    } else if u < 0.6 {
        [1.0, 0.0]
    } else {
        let th = 2.0 * std::f64::consts::PI * rng.f();
        [th.cos(), th.sin()]
    };
    [size * dir[0], size * dir[1]]
}

fn log_uniform(rng: &mut Rng, lo: f64, hi: f64) -> f64 {
    (lo.ln() + (hi.ln() - lo.ln()) * rng.f()).exp()
}

// ------------------------------------------------- homogenised law

const FORCE: usize = HomogenisedFriction::STATE_FORCE;
const PLASTIC: usize = HomogenisedFriction::STATE_PLASTIC_SLIP_PATH;
const MECHANISMS: usize = HomogenisedFriction::STATE_MECHANISMS;

/// The stick force of a homogenised state (N).
fn force(s: &[f64]) -> [f64; 2] {
    [s[FORCE], s[FORCE + 1]]
}

/// The accumulated dissipation by mechanism of a homogenised state (J).
fn mechanisms(s: &[f64]) -> f64 {
    s[MECHANISMS..MECHANISMS + 4].iter().sum()
}

/// The slip limit (the cone's radius) of a response, in the law's COF
/// form: μ(N + A), μN or A + μN (module documentation).
fn slip_limit(form: CofForm, r: &FrictionResponse) -> f64 {
    match form {
        CofForm::Derjaguin => r.cof * (r.normal_force + r.adhesion),
        CofForm::DerjaguinDoubleAdhesion => r.cof * (r.normal_force + 2.0 * r.adhesion),
        CofForm::Amontons => r.cof * r.normal_force,
        CofForm::Coulomb => r.adhesion + r.cof * r.normal_force,
    }
}

/// The per-increment invariants of one homogenised step; returns
/// (work over total slip, the end-force excess |ΔF|²/2k, released
/// stored energy, scale Σ|F||Δs| of this step).
fn homogenised_invariants(
    law: &HomogenisedFriction,
    old: &[f64],
    inc: &FrictionIncrement,
    new: &[f64],
    r: &FrictionResponse,
) -> (f64, f64, f64, f64) {
    let k = law.stick_stiffness();
    // Dissipation >= 0, in total and by mechanism.
    assert!(r.dissipated >= 0.0, "{r:?}");
    r.dissipation.validate().unwrap();
    // The plastic slip: of the length Δλ the state's plastic slip path
    // grows by, against the force while sliding; 0 in stick. Δλ is read
    // exactly from the same step from a plastic path of 0 (which changes
    // nothing else: the path is only booked), and the path of `new` is
    // the old one plus Δλ, exactly.
    let mut probe = old.to_vec();
    probe[PLASTIC] = 0.0;
    let (probed, rp) = hstep(law, &probe, inc);
    assert!(same(&rp, r), "the plastic path changed the step");
    let lam = probed[PLASTIC];
    assert_eq!(new[PLASTIC].to_bits(), (old[PLASTIC] + lam).to_bits());
    let fm = norm(r.force);
    let plastic_slip = if r.regime() == FrictionRegime::Slip && fm > 0.0 {
        [-lam * r.force[0] / fm, -lam * r.force[1] / fm]
    } else {
        assert_eq!(lam, 0.0, "plastic slip outside the slip regime: {r:?}");
        [0.0, 0.0]
    };
    // Work over the plastic slip = dissipation (by construction).
    let wp = -dot(r.force, plastic_slip);
    assert!(
        (wp - r.dissipated).abs() <= 8.0 * EPS * norm(r.force) * norm(plastic_slip),
        "−F·Δs_p = {wp:e} vs ΔD = {:e}",
        r.dissipated
    );
    // The plastic slip is what the elastic slip −F/k leaves of the slip
    // (k > 0), the slip itself when rigid–plastic.
    if r.regime() != FrictionRegime::NoContact {
        let (want, scale) = if k > 0.0 {
            let (f0, f1) = (force(old), r.force);
            (
                [
                    inc.slip[0] + (f1[0] - f0[0]) / k,
                    inc.slip[1] + (f1[1] - f0[1]) / k,
                ],
                (norm(f0) + norm(f1)) / k + norm(inc.slip),
            )
        } else if r.regime() == FrictionRegime::Slip {
            (inc.slip, norm(inc.slip))
        } else {
            ([0.0, 0.0], 0.0)
        };
        let miss = norm([plastic_slip[0] - want[0], plastic_slip[1] - want[1]]);
        assert!(
            miss <= 16.0 * EPS * scale + 1e-300,
            "Δs_p = {plastic_slip:?}, Δs + ΔF/k = {want:?}"
        );
    }
    // Mechanisms sum to the total; the accumulators grow by it.
    let parts = r.dissipation.total();
    assert!((parts - r.dissipated).abs() <= 4.0 * EPS * r.dissipated);
    let grown = mechanisms(new) - mechanisms(old);
    assert!(
        (grown - r.dissipated).abs() <= 8.0 * EPS * mechanisms(new).max(r.dissipated),
        "accumulator grew {grown:e}, step dissipated {:e}",
        r.dissipated
    );
    laws::check_accumulators("homogenised", old, new, inc, r);
    // Inside the cone.
    let limit = slip_limit(law.form(), r);
    assert!(norm(r.force) <= limit * (1.0 + 4.0 * EPS));
    let w = -dot(r.force, inc.slip);
    let scale = norm(r.force) * norm(inc.slip) + norm(force(old)).powi(2) / k.max(1e-300);
    if r.regime() == FrictionRegime::NoContact {
        assert_eq!(r.force, [0.0, 0.0]);
        assert_eq!(r.dissipated, 0.0);
        let released = if k > 0.0 {
            dot(force(old), force(old)) / (2.0 * k)
        } else {
            0.0
        };
        return (0.0, 0.0, released, scale);
    }
    let alg = if k > 0.0 {
        let f0 = force(old);
        let df = [r.force[0] - f0[0], r.force[1] - f0[1]];
        dot(df, df) / (2.0 * k)
    } else {
        0.0
    };
    if k == 0.0 && r.regime() == FrictionRegime::Slip {
        assert!((w - r.dissipated).abs() <= 8.0 * EPS * norm(r.force) * norm(inc.slip));
    }
    (w, alg, 0.0, scale)
}

/// One homogenised step from `old` into a new state.
fn hstep(
    law: &HomogenisedFriction,
    old: &[f64],
    inc: &FrictionIncrement,
) -> (Vec<f64>, FrictionResponse) {
    let mut new = vec![0.0; HomogenisedFriction::STATE_LEN];
    let r = law.step(old, &mut new, inc, &mut law.work()).unwrap();
    (new, r)
}

fn homogenised_sequence(law: &HomogenisedFriction, seed: u64, n: usize) {
    let mut rng = Rng(seed);
    let area = 1e-6;
    let zero = vec![0.0; HomogenisedFriction::STATE_LEN];
    let mut history: Vec<Vec<f64>> = vec![zero.clone()];
    let mut last = [1.0, 0.0];
    let mut accepted = 0;
    while accepted < n {
        let old = history.last().unwrap().clone();
        let inc = FrictionIncrement {
            normal_force: if rng.f() < 0.05 {
                0.0
            } else {
                log_uniform(&mut rng, 1e-3, 300.0)
            },
            area,
            slip: random_slip(&mut rng, last),
            dt: 1e-3,
            ..Default::default()
        };
        let (s1, r1) = hstep(law, &old, &inc);
        // Re-evaluation from the same old state: bit-identical.
        let (s2, r2) = hstep(law, &old, &inc);
        assert_eq!(response_bits(&r1), response_bits(&r2));
        assert_eq!(bits(&s1), bits(&s2));
        // An all-zero state is always accepted.
        hstep(law, &zero, &inc);
        // A cut-back: one time in five the host rejects the increment and
        // goes back up to 3 accepted increments (re-evaluating from an old
        // state must reproduce what it gave then).
        if rng.f() < 0.2 && history.len() > 3 {
            let back = 1 + (rng.u64() % 3) as usize;
            history.truncate(history.len() - back);
            continue;
        }
        homogenised_invariants(law, &old, &inc, &s1, &r1);
        if norm(inc.slip) > 0.0 {
            last = inc.slip;
        }
        history.push(s1);
        accepted += 1;
    }
}

/// Along an accepted path (no cut-backs), the summed balances.
fn homogenised_balance(law: &HomogenisedFriction, seed: u64, n: usize) {
    let k = law.stick_stiffness();
    let mut rng = Rng(seed);
    let mut st = vec![0.0; HomogenisedFriction::STATE_LEN];
    let (mut work, mut alg, mut released, mut scale, mut booked) = (0.0, 0.0, 0.0, 0.0, 0.0);
    let mut last = [1.0, 0.0];
    for _ in 0..n {
        let inc = FrictionIncrement {
            normal_force: if rng.f() < 0.02 {
                0.0
            } else {
                log_uniform(&mut rng, 1.0, 300.0)
            },
            area: 1e-6,
            slip: random_slip(&mut rng, last),
            dt: 1e-3,
            ..Default::default()
        };
        let (s, r) = hstep(law, &st, &inc);
        let (w, a, rel, sc) = homogenised_invariants(law, &st, &inc, &s, &r);
        work += w;
        alg += a;
        released += rel;
        scale += sc;
        booked += r.dissipated;
        if norm(inc.slip) > 0.0 {
            last = inc.slip;
        }
        st = s;
    }
    // Σ ΔD = the state's accumulator, bit for bit (the same additions in
    // the same order), and the sum over the mechanisms (n·ε).
    assert_eq!(st[0].to_bits(), booked.to_bits());
    let acc = mechanisms(&st);
    assert!(
        (acc - booked).abs() <= n as f64 * 4.0 * EPS * acc,
        "accumulated {acc:e} vs Σ ΔD {booked:e}"
    );
    // Σ −F·Δs = Σ ΔD + E_final − E_0 + Σ|ΔF|²/2k − released (E_0 = 0).
    let e_final = if k > 0.0 {
        dot(force(&st), force(&st)) / (2.0 * k)
    } else {
        0.0
    };
    let rhs = booked + e_final + alg - released;
    println!(
        "k = {k:e}: Σ−F·Δs = {work:e}, ΣΔD = {booked:e}, E_end = {e_final:e}, Σ|ΔF|²/2k = {alg:e}, released = {released:e}"
    );
    assert!(
        (work - rhs).abs() <= 1e-12 * scale,
        "work {work:e} vs dissipation + stored + end-force excess {rhs:e} (scale {scale:e})"
    );
    if k == 0.0 {
        assert!((work - booked).abs() <= 1e-12 * scale);
    }
}

#[test]
fn homogenised_law_invariants() {
    for (i, k) in [0.0, 1e7, 1e9, 1e11].into_iter().enumerate() {
        let law = common::native::fe_strip_law()
            .with_stick_stiffness(k)
            .unwrap();
        homogenised_sequence(&law, 0xF00 + i as u64, 3000);
        homogenised_balance(&law, 0xBA1 + i as u64, 5000);
    }
}

#[test]
fn homogenised_law_invariants_through_c() {
    let table = common::native::fe_strip_law();
    let samples = table.samples().to_vec();
    let mut h = null_mut();
    assert_eq!(
        unsafe { asperity_homogenised_friction_new(samples.as_ptr(), samples.len(), &mut h) },
        ASPERITY_OK
    );
    // The stick stiffness is the law's: one law with k = 1e9 N/m, one
    // rigid–plastic, stepped alternately on the same states.
    let ks = [1e9, 0.0];
    let rust: Vec<HomogenisedFriction> = ks
        .iter()
        .map(|&k| table.clone().with_stick_stiffness(k).unwrap())
        .collect();
    let c: Vec<*mut AsperityFriction> = ks
        .iter()
        .map(|&k| {
            let mut law = null_mut();
            assert_eq!(
                unsafe { asperity_friction_from_homogenised(h, k, &mut law) },
                ASPERITY_OK
            );
            law
        })
        .collect();
    let m = HomogenisedFriction::STATE_LEN;
    let mut work = null_mut();
    assert_eq!(
        unsafe { asperity_friction_work_new(c[0], &mut work) },
        ASPERITY_OK
    );
    let mut rng = Rng(0xC1);
    let mut history = vec![vec![0.0; m]];
    let mut last = [1.0, 0.0];
    for step in 0..3000 {
        let (law, handle) = (&rust[step % 2], c[step % 2]);
        let old = history.last().unwrap().clone();
        let inc = FrictionIncrement {
            normal_force: log_uniform(&mut rng, 1e-3, 300.0),
            area: 1e-6,
            slip: random_slip(&mut rng, last),
            dt: 1e-3,
            ..Default::default()
        };
        let mut runs = vec![];
        for _ in 0..2 {
            let mut s = vec![0.0; m];
            let mut r = FrictionResponse::default();
            let st = unsafe {
                asperity_friction_step(handle, &inc, old.as_ptr(), s.as_mut_ptr(), work, &mut r)
            };
            assert_eq!(st, ASPERITY_OK);
            runs.push((s, r));
        }
        // Bit-identical re-evaluation and equal to the Rust step.
        assert_eq!(format!("{:?}", runs[0]), format!("{:?}", runs[1]));
        let (rs, rr) = hstep(law, &old, &inc);
        assert_eq!(format!("{:?}", runs[0]), format!("{:?}", (rs, rr)));
        // An all-zero old state is accepted (a NULL work too); a NULL one
        // is refused, naming it.
        let mut s = vec![0.0; m];
        let mut r = FrictionResponse::default();
        let zero = vec![0.0; m];
        assert_eq!(
            unsafe {
                asperity_friction_step(
                    handle,
                    &inc,
                    zero.as_ptr(),
                    s.as_mut_ptr(),
                    null_mut(),
                    &mut r,
                )
            },
            ASPERITY_OK
        );
        assert_eq!(
            unsafe { asperity_friction_step(handle, &inc, null(), s.as_mut_ptr(), work, &mut r) },
            ASPERITY_ERR_NULL_POINTER
        );
        assert!(laws::c_message().contains("`old_state`"));
        let (s1, r1) = runs.swap_remove(0);
        homogenised_invariants(law, &old, &inc, &s1, &r1);
        if rng.f() < 0.2 && history.len() > 3 {
            history.truncate(history.len() - 1 - (rng.u64() % 3) as usize);
            continue;
        }
        if norm(inc.slip) > 0.0 {
            last = inc.slip;
        }
        history.push(s1);
    }
    unsafe {
        asperity_friction_work_free(work);
        c.into_iter().for_each(|l| asperity_friction_free(l));
        asperity_homogenised_friction_free(h);
    }
}

// ---------------------------------------------------------- slider

fn slider() -> Slider {
    laws::scene_slider()
}

/// The accumulated dissipation by mechanism of a slider state (J).
fn acc(flat: &[f64]) -> f64 {
    flat[Slider::STATE_MECHANISMS..Slider::STATE_HEIGHTS]
        .iter()
        .sum()
}

fn slider_invariants(old: &[f64], new: &[f64], inc: &FrictionIncrement, r: &FrictionResponse) {
    assert!(r.dissipated >= 0.0, "{r:?}");
    r.dissipation.validate().unwrap();
    let parts = r.dissipation.total();
    assert!((parts - r.dissipated).abs() <= 4.0 * EPS * r.dissipated);
    let s = norm(inc.slip);
    if s == 0.0 {
        // Zero slip is stick: nothing dissipated, no force.
        assert_eq!(r.dissipated, 0.0);
        assert_eq!(r.force, [0.0, 0.0]);
    } else {
        // F_t = ΔU/|Δs| (4-1): −F·Δs = F_t|Δs| = ΔU to a few ulps.
        let path = inc.slip[0].hypot(inc.slip[1]);
        assert!((r.force_magnitude * path - r.dissipated).abs() <= 4.0 * EPS * r.dissipated);
        let w = -dot(r.force, inc.slip);
        assert!(
            (w - r.dissipated).abs() <= 8.0 * EPS * r.dissipated.max(r.force_magnitude * s),
            "−F·Δs = {w:e} vs ΔU = {:e}",
            r.dissipated
        );
    }
    // The state's accumulators by mechanism grow by ΔU (old ones are 0
    // when the old state was fresh); the total by exactly ΔU.
    let grown = acc(new)
        - if old[Slider::STATE_FLAG] == 1.0 {
            acc(old)
        } else {
            0.0
        };
    assert!(
        (grown - r.dissipated).abs() <= 16.0 * EPS * acc(new).max(r.dissipated),
        "accumulator grew {grown:e}, step dissipated {:e}",
        r.dissipated
    );
    laws::check_accumulators("slider", old, new, inc, r);
}

fn slider_increment(rng: &mut Rng, cap: f64, last: [f64; 2]) -> FrictionIncrement {
    let slip = random_slip(rng, last);
    // Slider steps are longer: scale the slip to 0.1–3 µm.
    let s = norm(slip);
    let slip = if s > 0.0 {
        let t = log_uniform(rng, 1e-7, 3e-6) / s;
        [slip[0] * t, slip[1] * t]
    } else {
        slip
    };
    FrictionIncrement {
        normal_force: if rng.f() < 0.05 {
            0.0
        } else {
            cap * log_uniform(rng, 1e-4, 0.2)
        },
        slip,
        dt: 1e-3,
        ..Default::default()
    }
}

#[test]
fn slider_step_invariants() {
    let slider = slider();
    let m = slider.state_len();
    let cap = slider.capacity();
    let mut work = slider.work();
    let mut rng = Rng(0x51);
    let mut history = vec![vec![0.0; m]];
    let mut last = [1.0, 0.0];
    let (mut booked, mut accepted) = (0.0, 0);
    while accepted < 60 {
        let old = history.last().unwrap().clone();
        let inc = slider_increment(&mut rng, cap, last);
        let mut n1 = vec![0.0; m];
        let mut n2 = vec![7.0; m];
        let r1 = slider.step(&old, &mut n1, &inc, &mut work).unwrap();
        let r2 = slider.step(&old, &mut n2, &inc, &mut work).unwrap();
        assert_eq!(
            format!("{r1:?}"),
            format!("{r2:?}"),
            "re-evaluation differs"
        );
        assert_eq!(bits(&n1), bits(&n2));
        slider_invariants(&old, &n1, &inc, &r1);
        // An all-zero state is always accepted.
        let zero = vec![0.0; m];
        let rz = slider.step(&zero, &mut n2, &inc, &mut work).unwrap();
        assert!(work.get::<SliderWork>().unwrap().seated());
        slider_invariants(&zero, &n2, &inc, &rz);
        if rng.f() < 0.2 && history.len() > 3 {
            // Cut back: drop up to 3 accepted increments (and their booked
            // dissipation).
            let back = 1 + (rng.u64() % 3) as usize;
            history.truncate(history.len() - back);
            booked = acc(history.last().unwrap());
            continue;
        }
        booked += r1.dissipated;
        if norm(inc.slip) > 0.0 {
            last = inc.slip;
        }
        history.push(n1);
        accepted += 1;
    }
    let a = acc(history.last().unwrap());
    assert!((a - booked).abs() <= 1e-12 * a, "{a:e} vs {booked:e}");
}

#[test]
fn slider_step_invariants_through_c() {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("examples/scenes/chapter6_copper.json"),
    )
    .unwrap();
    let mut s = null_mut();
    assert_eq!(
        unsafe {
            asperity_slider_from_scene_json(text.as_ptr().cast(), text.len(), null(), &mut s)
        },
        ASPERITY_OK
    );
    let mut law = null_mut();
    assert_eq!(
        unsafe { asperity_friction_from_slider(s, &mut law) },
        ASPERITY_OK
    );
    let mut w = null_mut();
    assert_eq!(
        unsafe { asperity_friction_work_new(law, &mut w) },
        ASPERITY_OK
    );
    let rust = slider();
    let mut rw = rust.work();
    let m = rust.state_len();
    let cap = rust.capacity();
    let mut rng = Rng(0x52);
    let mut old = vec![0.0; m];
    let mut last = [1.0, 0.0];
    for _ in 0..25 {
        let inc = slider_increment(&mut rng, cap, last);
        let mut outs = vec![];
        for _ in 0..2 {
            let mut new = vec![0.0; m];
            let mut r = FrictionResponse::default();
            let st = unsafe {
                asperity_friction_step(law, &inc, old.as_ptr(), new.as_mut_ptr(), w, &mut r)
            };
            assert_eq!(st, ASPERITY_OK);
            outs.push((new, r));
        }
        assert_eq!(format!("{:?}", outs[0]), format!("{:?}", outs[1]));
        let mut rn = vec![0.0; m];
        let rr = rust.step(&old, &mut rn, &inc, &mut rw).unwrap();
        assert_eq!(format!("{:?}", outs[0]), format!("{:?}", (rn, rr)));
        slider_invariants(&old, &outs[0].0, &inc, &outs[0].1);
        // All-zero state accepted through C.
        let zero = vec![0.0; m];
        let mut n = vec![0.0; m];
        let mut r = FrictionResponse::default();
        assert_eq!(
            unsafe { asperity_friction_step(law, &inc, zero.as_ptr(), n.as_mut_ptr(), w, &mut r) },
            ASPERITY_OK
        );
        if norm(inc.slip) > 0.0 {
            last = inc.slip;
        }
        old = outs.swap_remove(0).0;
    }
    unsafe {
        asperity_friction_work_free(w);
        asperity_friction_free(law);
        asperity_slider_free(s);
    }
}

// ------------------------------------------------------ every law

/// `step`, `step_in_place`, `step_block` (separate and in place) agree
/// bit for bit, and the accumulators grow by exactly ΔD and |Δs|.
#[test]
fn every_law_steps_alike_in_every_form() {
    for case in laws::all_cases() {
        laws::check_forms(&case, 12);
    }
}

/// Over a long sequence stepped in place, state[0] and state[1] are the
/// running sums of the responses' ΔD and of |Δs| (the same additions in the
/// same order: bit for bit).
#[test]
fn every_law_accumulates_dissipation_and_slip_path() {
    for case in laws::all_cases() {
        let law = &*case.law;
        let mut w = law.work();
        let mut st = vec![0.0; law.state_len()];
        let (mut d, mut n) = (0.0, 0);
        for k in 0..5 * case.incs.len() {
            let inc = case.incs[k % case.incs.len()];
            let old = st.clone();
            let r = law.step_in_place(&mut st, &inc, &mut w).unwrap();
            laws::check_accumulators(case.name, &old, &st, &inc, &r);
            d += r.dissipated;
            n += (r.dissipated > 0.0) as usize;
        }
        assert_eq!(st[0].to_bits(), d.to_bits(), "{}", case.name);
        assert!(n > 0, "{}: nothing dissipated", case.name);
    }
}

/// A refused increment or state names the argument and leaves the new
/// state, the state stepped in place and the block's later points
/// untouched.
#[test]
fn every_law_refuses_without_writing() {
    for case in laws::all_cases() {
        laws::check_rejections(&case);
    }
}

/// The block with `responses` gives each point's full response (forces,
/// energies, regime, the tangents asked) bit for bit as `step` with the
/// same tangent bits, states separate and in place (issue 32).
#[test]
fn every_law_block_responses_equal_the_scalar_steps() {
    for case in laws::all_cases() {
        laws::check_block_responses(&case, 12);
    }
}

/// Unknown tangent bits, a `responses` slice of the wrong length, or no
/// forces and no responses: the block is refused at index 0 before
/// anything is written.
#[test]
fn every_law_block_refuses_bad_tangents_and_responses() {
    for case in laws::all_cases() {
        laws::check_block_rejections(&case);
    }
}
