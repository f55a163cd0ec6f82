//! Friction invariants (issue 8 §5) over long random host-code increment
//! sequences — random loads, slip increments with reversals and zeros,
//! random cut-backs (re-evaluating from an older state) — for the
//! homogenised law (`HomogenisedFriction::step`) and the slider patch
//! (`Slider::step_flat`), through Rust and the C ABI:
//!
//! * dissipation ≥ 0 on every increment (in total and by mechanism);
//! * the work of the friction force equals the dissipation, to rounding.
//!   What "work" means follows each step's documentation:
//!   - homogenised law: `ΔD = −F·Δs_p` (the force at the end of the
//!     increment over the plastic slip) — by construction, to a few ulps of
//!     |F||Δs_p|. Over the **total** slip the backward-Euler return mapping
//!     gives, exactly in real arithmetic,
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
//! * an all-zero state is always accepted.

mod common;

use asperity::ffi::homogenised::*;
use asperity::ffi::slider::*;
use asperity::ffi::*;
use asperity::friction::{
    FrictionIncrement, FrictionPointState, FrictionRegime, FrictionResponse, HomogenisedFriction,
    Loading, Slider, SliderIncrement, SliderResponse, SliderTangents,
};
use asperity::scene::Scene;
use std::path::Path;
use std::ptr::{null, null_mut};

/// splitmix64.
struct Rng(u64);

impl Rng {
    fn u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }
    fn f(&mut self) -> f64 {
        (self.u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
    fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        (lo.ln() + (hi.ln() - lo.ln()) * self.f()).exp()
    }
}

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
    let size = rng.log_uniform(1e-9, 1e-5);
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

// ------------------------------------------------- homogenised law

/// The per-increment invariants of one homogenised step; returns
/// (work over total slip, the end-force excess |ΔF|²/2k, released
/// stored energy, scale Σ|F||Δs| of this step).
fn homogenised_invariants(
    old: &FrictionPointState,
    inc: &FrictionIncrement,
    new: &FrictionPointState,
    r: &FrictionResponse,
) -> (f64, f64, f64, f64) {
    // Dissipation >= 0, in total and by mechanism.
    assert!(r.dissipated >= 0.0, "{r:?}");
    r.dissipation.validate().unwrap();
    // Work over the plastic slip = dissipation (by construction).
    let wp = -dot(r.force, r.plastic_slip);
    assert!(
        (wp - r.dissipated).abs() <= 8.0 * EPS * norm(r.force) * norm(r.plastic_slip),
        "−F·Δs_p = {wp:e} vs ΔD = {:e}",
        r.dissipated
    );
    // Mechanisms sum to the total; the accumulators grow by it.
    let parts = r.dissipation.total();
    assert!((parts - r.dissipated).abs() <= 4.0 * EPS * r.dissipated);
    let grown = new.dissipation.total() - old.dissipation.total();
    assert!(
        (grown - r.dissipated).abs() <= 8.0 * EPS * new.dissipation.total().max(r.dissipated),
        "accumulator grew {grown:e}, step dissipated {:e}",
        r.dissipated
    );
    let lam = norm(r.plastic_slip);
    assert!((new.slip_path - old.slip_path - lam).abs() <= 4.0 * EPS * new.slip_path);
    // Inside the cone.
    assert!(norm(r.force) <= r.slip_limit * (1.0 + 4.0 * EPS));
    let k = inc.stick_stiffness;
    let w = -dot(r.force, inc.slip);
    let scale = norm(r.force) * norm(inc.slip) + norm(old.force).powi(2) / k.max(1e-300);
    if r.regime() == FrictionRegime::NoContact {
        assert_eq!(r.force, [0.0, 0.0]);
        assert_eq!(r.dissipated, 0.0);
        let released = if k > 0.0 {
            dot(old.force, old.force) / (2.0 * k)
        } else {
            0.0
        };
        return (0.0, 0.0, released, scale);
    }
    let alg = if k > 0.0 {
        let df = [r.force[0] - old.force[0], r.force[1] - old.force[1]];
        dot(df, df) / (2.0 * k)
    } else {
        0.0
    };
    if k == 0.0 && r.regime() == FrictionRegime::Slip {
        assert!((w - r.dissipated).abs() <= 8.0 * EPS * norm(r.force) * norm(inc.slip));
    }
    (w, alg, 0.0, scale)
}

fn homogenised_sequence(law: &HomogenisedFriction, seed: u64, k: f64, n: usize) {
    let mut rng = Rng(seed);
    let area = 1e-6;
    let mut history: Vec<FrictionPointState> = vec![FrictionPointState::default()];
    let mut last = [1.0, 0.0];
    let mut accepted = 0;
    while accepted < n {
        let old = *history.last().unwrap();
        let inc = FrictionIncrement {
            normal_force: if rng.f() < 0.05 {
                0.0
            } else {
                rng.log_uniform(1e-3, 300.0)
            },
            area,
            slip: random_slip(&mut rng, last),
            dt: 1e-3,
            stick_stiffness: k,
        };
        let (s1, r1) = law.step_value(&old, &inc).unwrap();
        // Re-evaluation from the same old state: bit-identical.
        let (s2, r2) = law.step_value(&old, &inc).unwrap();
        assert_eq!(response_bits(&r1), response_bits(&r2));
        assert_eq!(format!("{s1:?}"), format!("{s2:?}"));
        // An all-zero state is always accepted.
        law.step_value(&FrictionPointState::default(), &inc)
            .unwrap();
        // A cut-back: one time in five the host rejects the increment and
        // goes back up to 3 accepted increments (re-evaluating from an old
        // state must reproduce what it gave then).
        if rng.f() < 0.2 && history.len() > 3 {
            let back = 1 + (rng.u64() % 3) as usize;
            history.truncate(history.len() - back);
            continue;
        }
        homogenised_invariants(&old, &inc, &s1, &r1);
        if norm(inc.slip) > 0.0 {
            last = inc.slip;
        }
        history.push(s1);
        accepted += 1;
    }
}

/// Along an accepted path (no cut-backs), the summed balances.
fn homogenised_balance(law: &HomogenisedFriction, seed: u64, k: f64, n: usize) {
    let mut rng = Rng(seed);
    let mut st = FrictionPointState::default();
    let (mut work, mut alg, mut released, mut scale, mut booked) = (0.0, 0.0, 0.0, 0.0, 0.0);
    let mut last = [1.0, 0.0];
    for _ in 0..n {
        let inc = FrictionIncrement {
            normal_force: if rng.f() < 0.02 {
                0.0
            } else {
                rng.log_uniform(1.0, 300.0)
            },
            area: 1e-6,
            slip: random_slip(&mut rng, last),
            dt: 1e-3,
            stick_stiffness: k,
        };
        let (s, r) = law.step_value(&st, &inc).unwrap();
        let (w, a, rel, sc) = homogenised_invariants(&st, &inc, &s, &r);
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
    // Σ ΔD = the state's accumulator (n additions: n·ε).
    let acc = st.dissipation.total();
    assert!(
        (acc - booked).abs() <= n as f64 * 4.0 * EPS * acc,
        "accumulated {acc:e} vs Σ ΔD {booked:e}"
    );
    // Σ −F·Δs = Σ ΔD + E_final − E_0 + Σ|ΔF|²/2k − released (E_0 = 0).
    let e_final = if k > 0.0 {
        dot(st.force, st.force) / (2.0 * k)
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
    let law = common::native::fe_strip_law();
    for (i, k) in [0.0, 1e7, 1e9, 1e11].into_iter().enumerate() {
        homogenised_sequence(&law, 0xF00 + i as u64, k, 3000);
        homogenised_balance(&law, 0xBA1 + i as u64, k, 5000);
    }
}

#[test]
fn homogenised_law_invariants_through_c() {
    let law = common::native::fe_strip_law();
    let samples = law.samples().to_vec();
    let mut h = null_mut();
    assert_eq!(
        unsafe { asperity_homogenised_friction_new(samples.as_ptr(), samples.len(), &mut h) },
        ASPERITY_OK
    );
    let mut rng = Rng(0xC1);
    let mut history = vec![FrictionPointState::default()];
    let mut last = [1.0, 0.0];
    for step in 0..3000 {
        let old = *history.last().unwrap();
        let inc = FrictionIncrement {
            normal_force: rng.log_uniform(1e-3, 300.0),
            area: 1e-6,
            slip: random_slip(&mut rng, last),
            dt: 1e-3,
            stick_stiffness: if step % 2 == 0 { 1e9 } else { 0.0 },
        };
        let mut runs = vec![];
        for _ in 0..2 {
            let mut s = FrictionPointState::default();
            let mut r = FrictionResponse::default();
            let st = unsafe { asperity_homogenised_friction_step(h, &inc, &old, &mut s, &mut r) };
            assert_eq!(st, ASPERITY_OK);
            runs.push((s, r));
        }
        // Bit-identical re-evaluation and equal to the Rust step.
        assert_eq!(format!("{:?}", runs[0]), format!("{:?}", runs[1]));
        let (rs, rr) = law.step_value(&old, &inc).unwrap();
        assert_eq!(format!("{:?}", runs[0]), format!("{:?}", (rs, rr)));
        // All-zero (and NULL) old state accepted.
        let mut s = FrictionPointState::default();
        let mut r = FrictionResponse::default();
        let zero = FrictionPointState::default();
        assert_eq!(
            unsafe { asperity_homogenised_friction_step(h, &inc, &zero, &mut s, &mut r) },
            ASPERITY_OK
        );
        assert_eq!(
            unsafe { asperity_homogenised_friction_step(h, &inc, null(), &mut s, &mut r) },
            ASPERITY_OK
        );
        let (s1, r1) = runs[0];
        homogenised_invariants(&old, &inc, &s1, &r1);
        if rng.f() < 0.2 && history.len() > 3 {
            history.truncate(history.len() - 1 - (rng.u64() % 3) as usize);
            continue;
        }
        if norm(inc.slip) > 0.0 {
            last = inc.slip;
        }
        history.push(s1);
    }
    unsafe { asperity_homogenised_friction_free(h) };
}

// ---------------------------------------------------------- slider

fn slider() -> Slider {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/chapter6_copper.json");
    Scene::from_file(p).unwrap().build().unwrap()
}

fn acc(flat: &[f64]) -> f64 {
    flat[Slider::STATE_DISSIPATION..Slider::STATE_HEIGHTS]
        .iter()
        .sum()
}

fn slider_invariants(old: &[f64], new: &[f64], inc: &SliderIncrement, r: &SliderResponse) {
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
        assert!(
            (r.friction_force * r.slip_length - r.dissipated).abs() <= 4.0 * EPS * r.dissipated
        );
        let w = -dot(r.force, inc.slip);
        assert!(
            (w - r.dissipated).abs() <= 8.0 * EPS * r.dissipated.max(r.friction_force * s),
            "−F·Δs = {w:e} vs ΔU = {:e}",
            r.dissipated
        );
    }
    // The state's accumulators grow by ΔU (old accumulators are 0 when
    // the old state was fresh).
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
}

fn slider_increment(rng: &mut Rng, cap: f64, last: [f64; 2]) -> SliderIncrement {
    let slip = random_slip(rng, last);
    // Slider steps are longer: scale the slip to 0.1–3 µm.
    let s = norm(slip);
    let slip = if s > 0.0 {
        let t = rng.log_uniform(1e-7, 3e-6) / s;
        [slip[0] * t, slip[1] * t]
    } else {
        slip
    };
    SliderIncrement {
        loading: Some(Loading::FixedLoad {
            load: if rng.f() < 0.05 {
                0.0
            } else {
                cap * rng.log_uniform(1e-4, 0.2)
            },
        }),
        slip,
        dt: 1e-3,
        tangents: SliderTangents::default(),
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
        let r1 = slider.step_flat(&old, &mut n1, &inc, &mut work).unwrap();
        let r2 = slider.step_flat(&old, &mut n2, &inc, &mut work).unwrap();
        assert_eq!(
            format!("{r1:?}"),
            format!("{r2:?}"),
            "re-evaluation differs"
        );
        assert_eq!(
            n1.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
            n2.iter().map(|x| x.to_bits()).collect::<Vec<_>>()
        );
        slider_invariants(&old, &n1, &inc, &r1);
        // An all-zero state is always accepted.
        let zero = vec![0.0; m];
        let rz = slider.step_flat(&zero, &mut n2, &inc, &mut work).unwrap();
        assert_eq!(rz.seated, 1);
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
        Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/scenes/chapter6_copper.json"),
    )
    .unwrap();
    let mut s = null_mut();
    assert_eq!(
        unsafe {
            asperity_slider_from_scene_json(text.as_ptr().cast(), text.len(), null(), &mut s)
        },
        ASPERITY_OK
    );
    let mut w = null_mut();
    assert_eq!(unsafe { asperity_slider_work_new(s, &mut w) }, ASPERITY_OK);
    let rust = slider();
    let mut rw = rust.work();
    let m = rust.state_len();
    let cap = rust.capacity();
    let mut rng = Rng(0x52);
    let mut old = vec![0.0; m];
    let mut last = [1.0, 0.0];
    for _ in 0..25 {
        let inc = slider_increment(&mut rng, cap, last);
        let Some(Loading::FixedLoad { load }) = inc.loading else {
            unreachable!()
        };
        let c_inc = AsperitySliderIncrement {
            normal_force: load,
            gap: 0.0,
            slip: inc.slip,
            dt: inc.dt,
            control: ASPERITY_SLIDER_CONTROL_LOAD,
            tangents: 0,
        };
        let mut outs = vec![];
        for _ in 0..2 {
            let mut new = vec![0.0; m];
            let mut r = SliderResponse::default();
            let st = unsafe {
                asperity_slider_step(s, w, &c_inc, old.as_ptr(), new.as_mut_ptr(), &mut r)
            };
            assert_eq!(st, ASPERITY_OK);
            outs.push((new, r));
        }
        assert_eq!(format!("{:?}", outs[0]), format!("{:?}", outs[1]));
        let mut rn = vec![0.0; m];
        let rr = rust.step_flat(&old, &mut rn, &inc, &mut rw).unwrap();
        assert_eq!(format!("{:?}", outs[0]), format!("{:?}", (rn, rr)));
        slider_invariants(&old, &outs[0].0, &inc, &outs[0].1);
        // All-zero state accepted through C.
        let zero = vec![0.0; m];
        let mut n = vec![0.0; m];
        let mut r = SliderResponse::default();
        assert_eq!(
            unsafe { asperity_slider_step(s, w, &c_inc, zero.as_ptr(), n.as_mut_ptr(), &mut r) },
            ASPERITY_OK
        );
        if norm(inc.slip) > 0.0 {
            last = inc.slip;
        }
        old = outs.swap_remove(0).0;
    }
    unsafe {
        asperity_slider_work_free(w);
        asperity_slider_free(s);
    }
}
