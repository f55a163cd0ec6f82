//! The homogenised friction step through `src/ffi/homogenised.rs`
//! (`homogenised_*`): ΔD ≥ 0, |F| ≤ μ(N + A), failing calls leave outputs
//! untouched.

use super::*;
use asperity::ffi::homogenised::*;
use asperity::friction::{FrictionIncrement, FrictionPointState, FrictionResponse};

const NORMAL_FORCE: Arg = arg(&["normal_force"], Dom::NonNeg, 1e-3, 1e3);
const AREA: Arg = arg(&["area"], Dom::Pos, 1e-8, 1e-4);
const SLIP: Arg = arg(&["slip"], Dom::Finite, 1e-10, 1e-4);
const DT: Arg = arg(&["dt"], Dom::NonNeg, 1e-6, 1.0);
const STICK: Arg = arg(&["stick_stiffness"], Dom::NonNeg, 1e5, 1e12);

/// The bytes of a plain `repr(C)` value without padding (the friction state
/// and response), for bit-for-bit comparison.
fn raw<T: Copy>(x: &T) -> &[u8] {
    unsafe { std::slice::from_raw_parts((x as *const T).cast::<u8>(), size_of::<T>()) }
}

fn friction_response_finite(r: &FrictionResponse) -> bool {
    let d = &r.dissipation;
    [
        r.force[0],
        r.force[1],
        r.force_magnitude,
        r.normal_force,
        r.cof,
        r.slip_limit,
        r.adhesion,
        r.true_contact_area,
        r.plastic_slip[0],
        r.plastic_slip[1],
        r.dissipated,
        d.chemical,
        d.van_der_waals,
        d.elastic,
        d.plastic,
        r.dforce_dnormal[0],
        r.dforce_dnormal[1],
        r.dforce_dslip[0][0],
        r.dforce_dslip[0][1],
        r.dforce_dslip[1][0],
        r.dforce_dslip[1][1],
    ]
    .iter()
    .all(|x| x.is_finite())
}

fn state_finite(s: &FrictionPointState) -> bool {
    let d = &s.dissipation;
    [
        s.force[0],
        s.force[1],
        s.slip_path,
        d.chemical,
        d.van_der_waals,
        d.elastic,
        d.plastic,
    ]
    .iter()
    .all(|x| x.is_finite())
}

/// A state and response full of sentinels, to see what a failing call wrote.
fn friction_sentinels() -> (FrictionPointState, FrictionResponse) {
    let s = FrictionPointState {
        force: [-3.5, -3.5],
        slip_path: -3.5,
        steps: 77,
        ..FrictionPointState::default()
    };
    let r = FrictionResponse {
        force: [-3.5, -3.5],
        cof: -3.5,
        dissipated: -3.5,
        regime: 9,
        ..FrictionResponse::default()
    };
    (s, r)
}

fn sweep_homogenised(n: usize, seed: u64) -> Tally {
    let law = common::native::fe_strip_law();
    let samples = law.samples().to_vec();
    let mut h = null_mut();
    assert_eq!(
        unsafe { asperity_homogenised_friction_new(samples.as_ptr(), samples.len(), &mut h) },
        ASPERITY_OK
    );
    let mut rng = Rng::new(seed);
    let mut t = Tally::default();
    let mut last = FrictionPointState::default();
    let mut last_typical = true;
    for _ in 0..n {
        t.points += 1;
        let slip_x = sample(&mut rng, &SLIP);
        let slip_y = if rng.f() < 0.5 {
            0.0
        } else {
            sample(&mut rng, &SLIP)
        };
        let inc = FrictionIncrement {
            normal_force: sample(&mut rng, &NORMAL_FORCE),
            area: sample(&mut rng, &AREA),
            slip: [slip_x, slip_y],
            dt: sample(&mut rng, &DT),
            stick_stiffness: if rng.f() < 0.2 {
                0.0
            } else {
                sample(&mut rng, &STICK)
            },
        };
        let u_old = rng.f();
        let old_typical = u_old < 0.4 || (u_old < 0.95 && last_typical);
        let old = match u_old {
            u if u < 0.4 => FrictionPointState::default(),
            u if u < 0.95 => last,
            _ => {
                let fx = sample(&mut rng, &arg(&["old.force"], Dom::Finite, 1e-6, 1e3));
                let path = sample(&mut rng, &arg(&["old.slip_path"], Dom::NonNeg, 1e-9, 1.0));
                FrictionPointState {
                    force: [fx, 0.0],
                    slip_path: path,
                    ..FrictionPointState::default()
                }
            }
        };
        let vals = [
            (NORMAL_FORCE, inc.normal_force),
            (AREA, inc.area),
            (SLIP, slip_x),
            (SLIP, slip_y),
            (DT, inc.dt),
            (STICK, inc.stick_stiffness),
        ];
        let bad: Vec<&Arg> = vals
            .iter()
            .filter(|(a, x)| !a.dom.contains(*x))
            .map(|(a, _)| a)
            .collect();
        let typical_inc = old_typical
            && vals
                .iter()
                .all(|(a, x)| typical(a, *x) || (*x == 0.0 && a.dom.contains(0.0)));
        let (mut s, mut r) = friction_sentinels();
        let st = unsafe { asperity_homogenised_friction_step(h, &inc, &old, &mut s, &mut r) };
        let rust = law.step_value(&old, &inc);
        if st == ASPERITY_OK {
            assert!(bad.is_empty(), "{inc:?}: accepted");
            t.ok += 1;
            let (rs, rr) = rust.unwrap();
            assert!(raw(&s) == raw(&rs) && raw(&r) == raw(&rr), "{s:?} {r:?}");
            assert!(
                friction_response_finite(&r) && state_finite(&s),
                "{inc:?} {old:?}: {r:?}"
            );
            assert!(r.dissipated >= 0.0, "{inc:?}: ΔD = {:e}", r.dissipated);
            let d = &r.dissipation;
            assert!(
                d.chemical >= 0.0 && d.van_der_waals >= 0.0 && d.elastic >= 0.0 && d.plastic >= 0.0
            );
            // |F| ≤ F_lim = μ(N + A) (Derjaguin form, thesis (4-3)).
            let fm = r.force[0].hypot(r.force[1]);
            // (+ a few units of the subnormal spacing: F_lim = 5e-318 N has
            // five significant digits.)
            assert!(
                fm <= r.slip_limit * (1.0 + 4.0 * f64::EPSILON) + 8.0 * 5e-324,
                "{inc:?}: |F| = {fm:e} > F_lim = {:e}",
                r.slip_limit
            );
            let want = r.cof * (r.normal_force + r.adhesion);
            assert!(
                (r.slip_limit - want).abs() <= 4.0 * f64::EPSILON * want + 8.0 * 5e-324,
                "{:e} vs μ(N + A) = {want:e}",
                r.slip_limit
            );
            last = s;
            last_typical = typical_inc;
        } else {
            let m = last_message();
            t.error(&m);
            assert_eq!(m, rust.unwrap_err().to_string());
            let (s0, r0) = friction_sentinels();
            assert!(
                raw(&s) == raw(&s0) && raw(&r) == raw(&r0),
                "written on failure"
            );
            if !bad.is_empty() {
                assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT, "{m}");
                assert!(names_one_of(&m, &bad), "{inc:?}: {m}");
            } else {
                assert!(
                    m.contains("`old.") || m.contains("`normal_force`") || m.contains("`slip`"),
                    "{inc:?} {old:?}: {m}"
                );
                assert!(
                    !typical_inc || m.contains("`old."),
                    "{inc:?} {old:?}: typical increment refused: {m}"
                );
            }
            last = FrictionPointState::default();
            last_typical = true;
        }

        // The block: one bad element j; elements before j written (equal to
        // single steps), from j on untouched, the message names j.
        if rng.f() < 0.01 {
            let nb = 8;
            let j = (rng.u64() % nb as u64) as usize;
            let k = rng.pick(&[0.0, 1e9]);
            let mut nf: Vec<f64> = (0..nb).map(|_| rng.log_uniform(1e-2, 1e2)).collect();
            let mut ar = vec![1e-6; nb];
            let sl: Vec<f64> = (0..2 * nb).map(|_| rng.uniform(-1e-6, 1e-6)).collect();
            if rng.f() < 0.5 {
                nf[j] = rng.pick(&[f64::NAN, -1.0, f64::INFINITY]);
            } else {
                ar[j] = rng.pick(&[0.0, -1e-6, f64::NAN]);
            }
            let (s0, _) = friction_sentinels();
            let mut ns = vec![s0; nb];
            let mut tf = vec![-3.5; 2 * nb];
            let mut dis = vec![-3.5; nb];
            let st = unsafe {
                asperity_homogenised_friction_step_block(
                    h,
                    nb,
                    nf.as_ptr(),
                    ar.as_ptr(),
                    sl.as_ptr(),
                    1e-3,
                    k,
                    core::ptr::null(),
                    ns.as_mut_ptr(),
                    tf.as_mut_ptr(),
                    dis.as_mut_ptr(),
                )
            };
            assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT);
            let m = last_message();
            assert!(m.starts_with(&format!("element {j}: ")), "{m}");
            for i in 0..nb {
                if i < j {
                    let inc = FrictionIncrement {
                        normal_force: nf[i],
                        area: ar[i],
                        slip: [sl[2 * i], sl[2 * i + 1]],
                        dt: 1e-3,
                        stick_stiffness: k,
                    };
                    let (ws, wr) = law
                        .step_value(&FrictionPointState::default(), &inc)
                        .unwrap();
                    assert_eq!(format!("{:?}", ns[i]), format!("{ws:?}"));
                    assert_eq!(
                        (tf[2 * i], tf[2 * i + 1], dis[i]),
                        (wr.force[0], wr.force[1], wr.dissipated)
                    );
                } else {
                    assert_eq!(
                        format!("{:?}", ns[i]),
                        format!("{s0:?}"),
                        "element {i} ≥ {j}"
                    );
                    assert_eq!((tf[2 * i], tf[2 * i + 1], dis[i]), (-3.5, -3.5, -3.5));
                }
            }
        }
    }
    unsafe { asperity_homogenised_friction_free(h) };
    t
}

#[test]
fn homogenised_quick() {
    sweep_homogenised(QUICK, 0x5EED_0005).print("homogenised friction step");
}

#[test]
#[ignore = "10⁶ increments: run in release (.ci/run)"]
fn homogenised_full() {
    sweep_homogenised(FULL, 0x5EED_0005).print("homogenised friction step");
}
