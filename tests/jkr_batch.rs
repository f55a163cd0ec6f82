//! Batch evaluation of the JKR sphere (the vectorised kernel of
//! `src/contact/jkr_simd.rs` where the CPU has AVX2) against the scalar
//! `Jkr::eval` and a reference element loop over `NormalLaw::eval`: every
//! output bit for bit, over overlaps from 1e-12 to 1e6 length scales of both
//! signs, across δ_c and 0, beyond the Hertz switch, with random histories,
//! for w = 0, tiny and ordinary w; tail lengths, aliasing, NULL arrays, errors
//! at every position and determinism.

mod common;
use common::c_errors::last_message;

use asperity::contact::{eval_batch, BatchError, ContactState, Jkr, NormalLaw};
use asperity::ffi::contact::*;
use asperity::ffi::*;
use asperity::NormalContact;
use std::ptr::null_mut;

/// xorshift64*: deterministic pseudo-random numbers.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn below(&mut self, n: usize) -> usize {
        (self.next() % n as u64) as usize
    }
}

/// The laws: ordinary, Hertz (w = 0), a w whose scales underflow (Hertz too),
/// a tiny but representable w (δ_c ≈ 1e-206 m, so most overlaps are beyond
/// the Hertz switch), and a stiff, strongly adhesive one.
fn laws() -> Vec<Jkr> {
    vec![
        Jkr::new(1e-5, 1e9, 0.05).unwrap(),
        Jkr::new(1e-5, 1e9, 0.0).unwrap(),
        Jkr::new(1e-5, 1e9, 1e-320).unwrap(),
        Jkr::new(1e-5, 1e9, 1e-300).unwrap(),
        Jkr::new(2e-3, 1e6, 10.0).unwrap(),
    ]
}

/// Overlaps for `law`: ±(1e-12 … 1e6)·scale log-uniform, the neighbourhoods
/// of δ_c and 0 (exact values, ±1 ulp, relative offsets), ±0, beyond the
/// Hertz switch, and random ones.
fn overlaps(law: &Jkr, rng: &mut Rng) -> Vec<f64> {
    let scale = law.length_scale();
    let mut d = Vec::new();
    for i in 0..=180 {
        let x = scale * 10f64.powf(-12.0 + 18.0 * i as f64 / 180.0);
        d.push(x);
        d.push(-x);
    }
    let dc = law.critical_delta();
    for c in [dc, 0.0, -scale] {
        d.push(c);
        d.push(f64::from_bits(c.to_bits() + 1));
        if c != 0.0 {
            d.push(f64::from_bits(c.to_bits() - 1));
        }
        for r in [1e-12, 1e-8, 1e-6, 1e-4, 1e-3, 1e-2, 0.1, 0.5] {
            d.push(c + r * scale);
            d.push(c - r * scale);
        }
    }
    d.push(-0.0);
    d.push(f64::MIN_POSITIVE);
    d.push(-f64::MIN_POSITIVE);
    if law.delta_scale() > 0.0 {
        // Reduced overlap Δ around and beyond HERTZ_SWITCH = 1e60.
        for big in [1e59, 9.99e59, 1e60, 1.0001e60, 1e61, 1e80] {
            d.push(big * law.delta_scale());
        }
    }
    for _ in 0..300 {
        let x = scale * 10f64.powf(-12.0 + 18.0 * rng.unit());
        d.push(if rng.unit() < 0.5 { x } else { -x });
        d.push(dc * (0.5 + rng.unit()));
    }
    d.retain(|x| x.is_finite());
    // Shuffle, so every kind of value lands at every lane position.
    for i in (1..d.len()).rev() {
        let j = rng.below(i + 1);
        d.swap(i, j);
    }
    d
}

fn random_states(n: usize, rng: &mut Rng) -> Vec<ContactState> {
    (0..n)
        .map(|_| {
            let c = rng.below(3);
            ContactState {
                contact_radius: rng.unit(),
                cohesive_radius: 0.0,
                // Any non-zero value means "in contact".
                in_contact: [0, 1, 7][c],
                branch: (c != 0) as i32,
            }
        })
        .collect()
}

/// Outputs of one batch evaluation, NaN-initialised.
#[derive(Debug, Clone, PartialEq)]
struct Outs {
    new: Vec<ContactState>,
    force: Vec<f64>,
    radius: Vec<f64>,
    stiffness: Vec<f64>,
}

const POISON: ContactState = ContactState {
    contact_radius: -7.0,
    cohesive_radius: -7.0,
    in_contact: -7,
    branch: -7,
};

impl Outs {
    fn new(n: usize) -> Self {
        Self {
            new: vec![POISON; n],
            force: vec![f64::NAN; n],
            radius: vec![f64::NAN; n],
            stiffness: vec![f64::NAN; n],
        }
    }
    /// Bit-level equality (NaN == NaN).
    fn assert_same(&self, other: &Self, what: &str) {
        let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&self.force), bits(&other.force), "{what}: force");
        assert_eq!(bits(&self.radius), bits(&other.radius), "{what}: radius");
        assert_eq!(
            bits(&self.stiffness),
            bits(&other.stiffness),
            "{what}: stiffness"
        );
        let sbits = |v: &[ContactState]| {
            v.iter()
                .map(|s| {
                    (
                        s.contact_radius.to_bits(),
                        s.cohesive_radius.to_bits(),
                        s.in_contact,
                        s.branch,
                    )
                })
                .collect::<Vec<_>>()
        };
        assert_eq!(sbits(&self.new), sbits(&other.new), "{what}: state");
    }
}

/// The library batch (safe wrapper).
fn batch(law: &Jkr, d: &[f64], old: Option<&[ContactState]>) -> (Outs, Result<(), BatchError>) {
    let mut o = Outs::new(d.len());
    let r = eval_batch(
        law,
        d,
        old,
        Some(&mut o.new),
        &mut o.force,
        Some(&mut o.radius),
        Some(&mut o.stiffness),
    );
    (o, r)
}

/// The reference element loop: `NormalLaw::eval` (which turns an
/// overflowed response into an error) per element, stopping at the first
/// error with the elements before it written.
fn reference(law: &Jkr, d: &[f64], old: Option<&[ContactState]>) -> (Outs, Result<(), BatchError>) {
    let mut o = Outs::new(d.len());
    let law = NormalLaw::Jkr(*law);
    for (i, &di) in d.iter().enumerate() {
        let old_i = old.map_or(ContactState::default(), |s| s[i]);
        match law.eval(di, &old_i) {
            Ok((r, s)) => {
                o.force[i] = r.force;
                o.radius[i] = r.contact_radius;
                o.stiffness[i] = r.stiffness;
                o.new[i] = s;
            }
            Err(error) => return (o, Err(BatchError { index: i, error })),
        }
    }
    (o, Ok(()))
}

fn c_law(l: &Jkr) -> AsperityNormalLaw {
    let mut out = std::mem::MaybeUninit::<AsperityNormalLaw>::zeroed();
    let s = unsafe {
        asperity_law_jkr(
            l.params().radius,
            l.params().e_star,
            l.params().work_of_adhesion,
            out.as_mut_ptr(),
        )
    };
    assert_eq!(s, ASPERITY_OK);
    unsafe { out.assume_init() }
}

#[test]
fn batch_equals_scalar_bit_for_bit() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for law in laws() {
        let d = overlaps(&law, &mut rng);
        let old = random_states(d.len(), &mut rng);
        let (o, r) = batch(&law, &d, Some(&old));
        assert_eq!(r, Ok(()), "{law:?}");
        for i in 0..d.len() {
            let (resp, st) = law.eval(d[i], &old[i]).unwrap();
            let ctx = format!("{law:?} δ = {:e} old {:?}", d[i], old[i].in_contact);
            assert_eq!(o.force[i].to_bits(), resp.force.to_bits(), "{ctx}");
            assert_eq!(
                o.radius[i].to_bits(),
                resp.contact_radius.to_bits(),
                "{ctx}"
            );
            assert_eq!(o.stiffness[i].to_bits(), resp.stiffness.to_bits(), "{ctx}");
            assert_eq!(o.new[i], st, "{ctx}");
            assert!(resp.force.is_finite() && resp.stiffness.is_finite());
        }
        let (want, rw) = reference(&law, &d, Some(&old));
        assert_eq!(rw, Ok(()));
        o.assert_same(&want, "whole batch");
        // Fresh states (NULL old_state) too.
        let (o, r) = batch(&law, &d, None);
        let (want, rw) = reference(&law, &d, None);
        assert_eq!(r, rw);
        o.assert_same(&want, "fresh states");
    }
}

#[test]
fn hysteresis_and_branch_fields() {
    let law = Jkr::new(1e-5, 1e9, 0.05).unwrap();
    let dc = law.critical_delta();
    // (δ, old in contact) → in contact after the step?
    let cases = [
        (0.5 * dc, 1, true),
        (0.5 * dc, 0, false),
        (dc, 1, true),
        (1.0001 * dc, 1, false),
        (0.0, 0, true),
        (-0.0, 0, true),
        (-1e-30, 0, false),
        (1e-9, 0, true),
    ];
    let d: Vec<f64> = cases.iter().map(|c| c.0).collect();
    let old: Vec<ContactState> = cases
        .iter()
        .map(|c| ContactState {
            in_contact: c.1,
            ..Default::default()
        })
        .collect();
    let (o, r) = batch(&law, &d, Some(&old));
    assert_eq!(r, Ok(()));
    for (i, c) in cases.iter().enumerate() {
        let s = o.new[i];
        assert_eq!(s.in_contact, c.2 as i32, "case {i}");
        assert_eq!(s.branch, c.2 as i32, "case {i}");
        assert_eq!(s.cohesive_radius.to_bits(), 0f64.to_bits());
        if c.2 {
            assert!(o.radius[i] > 0.0 && s.contact_radius == o.radius[i]);
            assert!(o.force[i] < 0.0, "adhesive near δ = 0");
        } else {
            for x in [o.force[i], o.radius[i], o.stiffness[i], s.contact_radius] {
                assert_eq!(x.to_bits(), 0f64.to_bits(), "out of contact: +0");
            }
        }
    }
}

#[test]
fn every_length_and_every_optional_array() {
    let mut rng = Rng(42);
    for law in laws() {
        let pool = overlaps(&law, &mut rng);
        for n in [
            0usize, 1, 2, 3, 4, 5, 6, 7, 8, 9, 15, 16, 17, 31, 32, 33, 35, 63, 64, 65, 1023,
        ] {
            let d: Vec<f64> = (0..n).map(|_| pool[rng.below(pool.len())]).collect();
            let old = random_states(n, &mut rng);
            let (want, rw) = reference(&law, &d, Some(&old));
            assert_eq!(rw, Ok(()));
            let (o, r) = batch(&law, &d, Some(&old));
            assert_eq!(r, Ok(()));
            o.assert_same(&want, &format!("n = {n}"));
            // NULL optional arrays, through the safe wrapper and the C ABI.
            for mask in 0..8 {
                let mut got = Outs::new(n);
                let r = eval_batch(
                    &law,
                    &d,
                    Some(&old),
                    (mask & 1 != 0).then_some(&mut got.new[..]),
                    &mut got.force,
                    (mask & 2 != 0).then_some(&mut got.radius[..]),
                    (mask & 4 != 0).then_some(&mut got.stiffness[..]),
                );
                assert_eq!(r, Ok(()));
                let mut via_c = Outs::new(n);
                let cl = c_law(&law);
                let s = unsafe {
                    asperity_normal_eval_batch(
                        &cl,
                        n,
                        d.as_ptr(),
                        old.as_ptr(),
                        if mask & 1 != 0 {
                            via_c.new.as_mut_ptr()
                        } else {
                            null_mut()
                        },
                        via_c.force.as_mut_ptr(),
                        if mask & 2 != 0 {
                            via_c.radius.as_mut_ptr()
                        } else {
                            null_mut()
                        },
                        if mask & 4 != 0 {
                            via_c.stiffness.as_mut_ptr()
                        } else {
                            null_mut()
                        },
                    )
                };
                assert_eq!(s, ASPERITY_OK, "{}", last_message());
                got.assert_same(&via_c, "safe wrapper vs C ABI");
                let mut exp = want.clone();
                if mask & 1 == 0 {
                    exp.new = vec![POISON; n];
                }
                if mask & 2 == 0 {
                    exp.radius = vec![f64::NAN; n];
                }
                if mask & 4 == 0 {
                    exp.stiffness = vec![f64::NAN; n];
                }
                got.assert_same(&exp, &format!("n = {n}, mask {mask}"));
            }
        }
    }
}

#[test]
fn aliasing_inputs_and_outputs() {
    let mut rng = Rng(7);
    for law in laws() {
        let pool = overlaps(&law, &mut rng);
        for n in [1usize, 3, 4, 5, 8, 13, 16, 17, 32, 37, 1023] {
            let d: Vec<f64> = (0..n).map(|_| pool[rng.below(pool.len())]).collect();
            let old = random_states(n, &mut rng);
            let (want, _) = reference(&law, &d, Some(&old));
            let cl = c_law(&law);
            // force == delta, new_state == old_state, radius and stiffness
            // separate.
            let mut buf = d.clone();
            let mut states = old.clone();
            let mut radius = vec![f64::NAN; n];
            let mut stiffness = vec![f64::NAN; n];
            let s = unsafe {
                asperity_normal_eval_batch(
                    &cl,
                    n,
                    buf.as_ptr(),
                    states.as_ptr(),
                    states.as_mut_ptr(),
                    buf.as_mut_ptr(),
                    radius.as_mut_ptr(),
                    stiffness.as_mut_ptr(),
                )
            };
            assert_eq!(s, ASPERITY_OK, "{}", last_message());
            let got = Outs {
                new: states,
                force: buf,
                radius,
                stiffness,
            };
            got.assert_same(&want, &format!("aliased, n = {n}"));
            // contact_radius == delta, stiffness not wanted: the radius
            // overwrites δ.
            let mut buf = d.clone();
            let mut force = vec![f64::NAN; n];
            let mut new = vec![POISON; n];
            let s = unsafe {
                asperity_normal_eval_batch(
                    &cl,
                    n,
                    buf.as_ptr(),
                    old.as_ptr(),
                    new.as_mut_ptr(),
                    force.as_mut_ptr(),
                    buf.as_mut_ptr(),
                    null_mut(),
                )
            };
            assert_eq!(s, ASPERITY_OK, "{}", last_message());
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(&buf), bits(&want.radius));
            assert_eq!(bits(&force), bits(&want.force));
            assert_eq!(new, want.new);
        }
    }
}

#[test]
fn non_finite_delta_at_every_position() {
    let mut rng = Rng(99);
    let law = Jkr::new(1e-5, 1e9, 0.05).unwrap();
    let hertz = Jkr::new(1e-5, 1e9, 0.0).unwrap();
    for law in [law, hertz] {
        let pool = overlaps(&law, &mut rng);
        for n in [1usize, 2, 3, 4, 5, 7, 8, 9, 16, 17, 32, 33, 40, 1023] {
            let mut ks: Vec<usize> = (0..n.min(36)).collect();
            ks.extend([n / 2, n - 1]);
            for k in ks {
                for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                    let mut d: Vec<f64> = (0..n).map(|_| pool[rng.below(pool.len())]).collect();
                    d[k] = bad;
                    // A second bad element later must not matter.
                    if k + 2 < n {
                        d[k + 2] = f64::NAN;
                    }
                    let old = random_states(n, &mut rng);
                    let (want, rw) = reference(&law, &d, Some(&old));
                    let err = law.eval(bad, &old[k]).unwrap_err();
                    // Debug strings: the error carries the NaN itself.
                    let dbg = |r: &Result<(), BatchError>| format!("{r:?}");
                    let expected = Err(BatchError {
                        index: k,
                        error: err,
                    });
                    assert_eq!(dbg(&rw), dbg(&expected));
                    let (got, r) = batch(&law, &d, Some(&old));
                    assert_eq!(dbg(&r), dbg(&rw), "n = {n}, k = {k}");
                    got.assert_same(&want, &format!("n = {n}, k = {k}"));
                    // Before k written, from k on untouched.
                    assert!(got.force[..k].iter().all(|x| x.is_finite()));
                    assert!(got.force[k..].iter().all(|x| x.is_nan()));
                    assert!(got.new[k..].iter().all(|s| *s == POISON));
                    // The C ABI: status and the index in the message.
                    let cl = c_law(&law);
                    let mut via_c = Outs::new(n);
                    let s = unsafe {
                        asperity_normal_eval_batch(
                            &cl,
                            n,
                            d.as_ptr(),
                            old.as_ptr(),
                            via_c.new.as_mut_ptr(),
                            via_c.force.as_mut_ptr(),
                            via_c.radius.as_mut_ptr(),
                            via_c.stiffness.as_mut_ptr(),
                        )
                    };
                    assert_eq!(s, ASPERITY_ERR_INVALID_ARGUMENT, "{}", last_message());
                    let msg = last_message();
                    assert!(msg.contains(&format!("{k}")), "message `{msg}` names {k}");
                    via_c.assert_same(&want, "C ABI error");
                }
            }
        }
    }
}

#[test]
fn overflowing_response_is_the_element_loop_error() {
    let mut rng = Rng(5);
    for law in laws() {
        // Overlaps whose force (η⁶ or δ^{3/2}) overflows f64, and some whose
        // reduced overlap is infinite.
        let huge = [1e200, 1e250, 1e300, f64::MAX];
        let pool = overlaps(&law, &mut rng);
        for n in [1usize, 4, 6, 16, 21, 32, 45, 1023] {
            for k in [0, n / 3, n - 1] {
                let mut d: Vec<f64> = (0..n).map(|_| pool[rng.below(pool.len())]).collect();
                d[k] = huge[rng.below(huge.len())];
                let old = random_states(n, &mut rng);
                let (want, rw) = reference(&law, &d, Some(&old));
                let (got, r) = batch(&law, &d, Some(&old));
                assert_eq!(r, rw, "{law:?} n = {n}, k = {k}, δ = {:e}", d[k]);
                got.assert_same(&want, "overflow");
                if let Err(e) = r {
                    assert_eq!(e.index, k);
                }
            }
        }
    }
}

#[test]
fn deterministic_whatever_the_position() {
    let mut rng = Rng(2024);
    for law in laws() {
        let pool = overlaps(&law, &mut rng);
        for probe in pool.iter().step_by(7).take(120) {
            let old_one = random_states(1, &mut rng)[0];
            let (alone, r) = batch(&law, &[*probe], Some(&[old_one]));
            assert_eq!(r, Ok(()));
            for pos in 0..40 {
                for extra in [0usize, 1, 3, 4, 10, 16, 32] {
                    let n = pos + 1 + extra;
                    let mut d: Vec<f64> = (0..n).map(|_| pool[rng.below(pool.len())]).collect();
                    let mut old = random_states(n, &mut rng);
                    d[pos] = *probe;
                    old[pos] = old_one;
                    let (o, r) = batch(&law, &d, Some(&old));
                    assert_eq!(r, Ok(()));
                    assert_eq!(o.force[pos].to_bits(), alone.force[0].to_bits());
                    assert_eq!(o.radius[pos].to_bits(), alone.radius[0].to_bits());
                    assert_eq!(o.stiffness[pos].to_bits(), alone.stiffness[0].to_bits());
                    assert_eq!(o.new[pos], alone.new[0]);
                }
            }
        }
    }
}

#[test]
fn agrees_with_the_enum_and_repeats() {
    // Through NormalLaw (the C ABI's dispatch) and twice in a row.
    let mut rng = Rng(11);
    let law = Jkr::new(1e-5, 1e9, 0.05).unwrap();
    let d = overlaps(&law, &mut rng);
    let old = random_states(d.len(), &mut rng);
    let (a, _) = batch(&law, &d, Some(&old));
    let (b, _) = batch(&law, &d, Some(&old));
    a.assert_same(&b, "repeat");
    let e = asperity::NormalLaw::Jkr(law);
    let mut c = Outs::new(d.len());
    eval_batch(
        &e,
        &d,
        Some(&old),
        Some(&mut c.new),
        &mut c.force,
        Some(&mut c.radius),
        Some(&mut c.stiffness),
    )
    .unwrap();
    a.assert_same(&c, "NormalLaw");
}
