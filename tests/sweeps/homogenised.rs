//! The homogenised friction law through the one C friction handle
//! (`src/ffi/friction_law.rs`, `asperity_friction_from_homogenised`;
//! `homogenised_*`): ΔD ≥ 0, |F| ≤ μ(N + A), failing calls leave outputs
//! untouched; the stick stiffness is swept through the law's constructor.

use super::*;
use asperity::ffi::friction_law::*;
use asperity::ffi::homogenised::*;
use asperity::friction::{FrictionIncrement, FrictionLaw, FrictionResponse, HomogenisedFriction};

const NORMAL_FORCE: Arg = arg(&["normal_force"], Dom::NonNeg, 1e-3, 1e3);
const AREA: Arg = arg(&["area"], Dom::Pos, 1e-8, 1e-4);
const SLIP: Arg = arg(&["slip"], Dom::Finite, 1e-10, 1e-4);
const DT: Arg = arg(&["dt"], Dom::NonNeg, 1e-6, 1.0);
const STICK: Arg = arg(&["stick_stiffness"], Dom::NonNeg, 1e5, 1e12);

const M: usize = HomogenisedFriction::STATE_LEN;
const FORCE: usize = HomogenisedFriction::STATE_FORCE;
const PLASTIC: usize = HomogenisedFriction::STATE_PLASTIC_SLIP_PATH;

/// The bytes of a plain `repr(C)` value without padding (the response),
/// for bit-for-bit comparison.
fn raw<T: Copy>(x: &T) -> &[u8] {
    unsafe { std::slice::from_raw_parts((x as *const T).cast::<u8>(), size_of::<T>()) }
}

fn bits(v: &[f64]) -> Vec<u64> {
    v.iter().map(|x| x.to_bits()).collect()
}

fn friction_response_finite(r: &FrictionResponse) -> bool {
    let d = &r.dissipation;
    [
        r.force[0],
        r.force[1],
        r.force_magnitude,
        r.normal_force,
        r.cof,
        r.adhesion,
        r.true_contact_area,
        r.dissipated,
        d.chemical,
        d.van_der_waals,
        d.elastic,
        d.plastic,
        r.stored_energy,
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

/// A state and response full of sentinels, to see what a failing call wrote.
fn friction_sentinels() -> (Vec<f64>, FrictionResponse) {
    let s = vec![-3.5; M];
    let r = FrictionResponse {
        force: [-3.5, -3.5],
        cof: -3.5,
        dissipated: -3.5,
        regime: 9,
        ..FrictionResponse::default()
    };
    (s, r)
}

/// The law of `table` with the stick stiffness `k`, through C.
fn c_law(table: *const AsperityHomogenisedFriction, k: f64) -> (i32, *mut AsperityFriction) {
    let mut law = 1usize as *mut AsperityFriction;
    let st = unsafe { asperity_friction_from_homogenised(table, k, &mut law) };
    (st, law)
}

fn sweep_homogenised(n: usize, seed: u64) -> Tally {
    let table = common::native::fe_strip_law();
    let samples = table.samples().to_vec();
    let mut h = null_mut();
    assert_eq!(
        unsafe { asperity_homogenised_friction_new(samples.as_ptr(), samples.len(), &mut h) },
        ASPERITY_OK
    );
    let mut rng = Rng::new(seed);
    let mut t = Tally::default();
    let mut last = vec![0.0; M];
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
            ..Default::default()
        };
        let k = if rng.f() < 0.2 {
            0.0
        } else {
            sample(&mut rng, &STICK)
        };
        let u_old = rng.f();
        let old_typical = u_old < 0.4 || (u_old < 0.95 && last_typical);
        let old = match u_old {
            u if u < 0.4 => vec![0.0; M],
            u if u < 0.95 => last.clone(),
            _ => {
                let fx = sample(&mut rng, &arg(&["old.force"], Dom::Finite, 1e-6, 1e3));
                let path = sample(
                    &mut rng,
                    &arg(
                        &["old.slip_path", "old.plastic_slip_path"],
                        Dom::NonNeg,
                        1e-9,
                        1.0,
                    ),
                );
                let mut s = vec![0.0; M];
                s[FORCE] = fx;
                s[1] = path;
                s[PLASTIC] = path;
                s
            }
        };
        // The stick stiffness is the law's: a bad one is refused by the
        // constructor, naming it, with the Rust error's text and a NULL
        // handle.
        let rust_law = table.clone().with_stick_stiffness(k);
        let (st, law) = c_law(h, k);
        if st != ASPERITY_OK {
            let m = last_message();
            t.error(&m);
            assert!(law.is_null(), "*out is NULL on failure");
            assert!(!STICK.dom.contains(k), "k = {k:e}: refused: {m}");
            assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT, "{m}");
            assert!(names_one_of(&m, &[&STICK]), "{m}");
            assert_eq!(m, rust_law.unwrap_err().to_string());
            continue;
        }
        assert!(STICK.dom.contains(k), "k = {k:e}: accepted");
        let rust_law = rust_law.unwrap();
        let vals = [
            (NORMAL_FORCE, inc.normal_force),
            (AREA, inc.area),
            (SLIP, slip_x),
            (SLIP, slip_y),
            (DT, inc.dt),
            (STICK, k),
        ];
        // A_n = 0 is valid with N = 0: an open gap (no contact).
        let open_gap = inc.area == 0.0 && inc.normal_force == 0.0;
        let bad: Vec<&Arg> = vals
            .iter()
            .filter(|(a, x)| {
                let valid = a.dom.contains(*x) || (open_gap && a.names == AREA.names);
                !valid
            })
            .map(|(a, _)| a)
            .collect();
        let typical_inc = old_typical
            && vals
                .iter()
                .all(|(a, x)| typical(a, *x) || (*x == 0.0 && a.dom.contains(0.0)));
        let (mut s, mut r) = friction_sentinels();
        let st = unsafe {
            asperity_friction_step(law, &inc, old.as_ptr(), s.as_mut_ptr(), null_mut(), &mut r)
        };
        unsafe { asperity_friction_free(law) };
        let mut rs = vec![0.0; M];
        let rust = rust_law.step(&old, &mut rs, &inc, &mut rust_law.work());
        if st == ASPERITY_OK {
            assert!(bad.is_empty(), "{inc:?}: accepted");
            t.ok += 1;
            let rr = rust.unwrap();
            assert!(bits(&s) == bits(&rs) && raw(&r) == raw(&rr), "{s:?} {r:?}");
            assert!(
                friction_response_finite(&r) && s.iter().all(|x| x.is_finite()),
                "{inc:?} {old:?}: {r:?}"
            );
            assert!(r.dissipated >= 0.0, "{inc:?}: ΔD = {:e}", r.dissipated);
            let d = &r.dissipation;
            assert!(
                d.chemical >= 0.0 && d.van_der_waals >= 0.0 && d.elastic >= 0.0 && d.plastic >= 0.0
            );
            // |F| ≤ F_lim = μ(N + A) (Derjaguin form, thesis (4-3)).
            let fm = r.force[0].hypot(r.force[1]);
            let limit = r.cof * (r.normal_force + r.adhesion);
            // (+ a few units of the subnormal spacing: F_lim = 5e-318 N has
            // five significant digits.)
            assert!(
                fm <= limit * (1.0 + 4.0 * f64::EPSILON) + 8.0 * 5e-324,
                "{inc:?}: |F| = {fm:e} > F_lim = {limit:e}"
            );
            last = s;
            last_typical = typical_inc;
        } else {
            let m = last_message();
            t.error(&m);
            assert_eq!(m, rust.unwrap_err().to_string());
            let (s0, r0) = friction_sentinels();
            assert!(
                bits(&s) == bits(&s0) && raw(&r) == raw(&r0),
                "written on failure"
            );
            if !bad.is_empty() {
                assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT, "{m}");
                assert!(names_one_of(&m, &bad), "{inc:?}: {m}");
            } else {
                assert!(
                    m.contains("`old.")
                        || m.contains("`normal_force`")
                        || m.contains("`slip`")
                        || m.contains("`stick_stiffness`"),
                    "{inc:?} {old:?}: {m}"
                );
                assert!(
                    !typical_inc || m.contains("`old."),
                    "{inc:?} {old:?}: typical increment refused: {m}"
                );
            }
            last = vec![0.0; M];
            last_typical = true;
        }

        // The block: one bad element j; elements before j written (equal to
        // single steps), from j on untouched, the message names j.
        if rng.f() < 0.01 {
            let nb = 8;
            let j = (rng.u64() % nb as u64) as usize;
            let k = rng.pick(&[0.0, 1e9]);
            let (st, law) = c_law(h, k);
            assert_eq!(st, ASPERITY_OK, "{}", last_message());
            let rust_law = table.clone().with_stick_stiffness(k).unwrap();
            let mut nf: Vec<f64> = (0..nb).map(|_| rng.log_uniform(1e-2, 1e2)).collect();
            let mut ar = vec![1e-6; nb];
            let sl: Vec<f64> = (0..2 * nb).map(|_| rng.uniform(-1e-6, 1e-6)).collect();
            if rng.f() < 0.5 {
                nf[j] = rng.pick(&[f64::NAN, -1.0, f64::INFINITY]);
            } else {
                ar[j] = rng.pick(&[0.0, -1e-6, f64::NAN]);
            }
            let (s0, _) = friction_sentinels();
            let fresh = vec![0.0; nb * M];
            let mut ns: Vec<f64> = (0..nb).flat_map(|_| s0.iter().copied()).collect();
            let mut tf = vec![-3.5; 2 * nb];
            let mut dis = vec![-3.5; nb];
            let st = unsafe {
                asperity_friction_step_block(
                    law,
                    nb,
                    nf.as_ptr(),
                    ar.as_ptr(),
                    sl.as_ptr(),
                    1e-3,
                    fresh.as_ptr(),
                    ns.as_mut_ptr(),
                    tf.as_mut_ptr(),
                    dis.as_mut_ptr(),
                    null_mut(),
                )
            };
            unsafe { asperity_friction_free(law) };
            assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT);
            let m = last_message();
            assert!(m.starts_with(&format!("element {j}: ")), "{m}");
            for i in 0..nb {
                let got = &ns[i * M..(i + 1) * M];
                if i < j {
                    let inc = FrictionIncrement {
                        normal_force: nf[i],
                        area: ar[i],
                        slip: [sl[2 * i], sl[2 * i + 1]],
                        dt: 1e-3,
                        ..Default::default()
                    };
                    let mut ws = vec![0.0; M];
                    let wr = rust_law
                        .step(&[0.0; M], &mut ws, &inc, &mut rust_law.work())
                        .unwrap();
                    assert_eq!(bits(got), bits(&ws));
                    assert_eq!(
                        (tf[2 * i], tf[2 * i + 1], dis[i]),
                        (wr.force[0], wr.force[1], wr.dissipated)
                    );
                } else {
                    assert_eq!(bits(got), bits(&s0), "element {i} ≥ {j}");
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
