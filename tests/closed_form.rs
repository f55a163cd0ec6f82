//! Reference values (REFERENCE.md §1, §5, §8) and limits of the closed-form
//! laws without hysteresis: materials, Hertz, Galin power punches and cones,
//! flat punch, DMT, Galanov effective shapes.

use approx::assert_relative_eq;
use asperity::contact::power_punch::{
    galin_c, galin_d, BERKOVICH_EQUIVALENT_HALF_ANGLE, CUBE_CORNER_EQUIVALENT_HALF_ANGLE,
    VICKERS_EQUIVALENT_HALF_ANGLE,
};
use asperity::contact::{Dmt, FlatPunch, Hertz, PowerPunch};
use asperity::material::*;
use asperity::{ContactState, Control, Error, NormalContact, NormalLaw};
use std::f64::consts::PI;

const FRESH: ContactState = ContactState {
    contact_radius: 0.0,
    cohesive_radius: 0.0,
    in_contact: 0,
    branch: 0,
};

fn force<L: NormalContact>(law: &L, delta: f64) -> f64 {
    law.eval(delta, &FRESH).unwrap().0.force
}

// ---------------------------------------------------------------- materials

#[test]
fn copper_contact_modulus_of_section_4_4() {
    // E = 120 GPa, ν = 0.355 on both sides: E* = E/(2(1−ν²)) = 68.65 GPa.
    let e = effective_modulus(120e9, 0.355, 120e9, 0.355).unwrap();
    assert_relative_eq!(e, 68.65e9, max_relative = 1e-4);
    assert_relative_eq!(
        e,
        120e9 / (2.0 * (1.0 - 0.355f64.powi(2))),
        max_relative = 1e-15
    );
}

#[test]
fn rigid_counterface_leaves_one_compliance() {
    let e = effective_modulus(200e9, 0.3, f64::INFINITY, 0.2).unwrap();
    assert_relative_eq!(e, 200e9 / (1.0 - 0.09), max_relative = 1e-15);
    assert!(matches!(
        effective_modulus(f64::INFINITY, 0.3, f64::INFINITY, 0.3),
        Err(Error::InvalidArgument { name: "e2", .. })
    ));
    // Rods in series (thesis (6-8)).
    assert_relative_eq!(rod_effective_modulus(1.0, 1.0).unwrap(), 0.5);
    assert_relative_eq!(rod_effective_modulus(3.0, f64::INFINITY).unwrap(), 3.0);
}

#[test]
fn modulus_ratio_sweep_is_finite_and_bounded() {
    // 1e-6 … 1e6 modulus ratios: E* lies between the softer body's plane
    // modulus and half of it (equal bodies), and is continuous in the ratio.
    let mut prev = None;
    for i in 0..=240 {
        let ratio = 10f64.powf(-6.0 + 12.0 * i as f64 / 240.0);
        let e = effective_modulus(1e9, 0.3, 1e9 * ratio, 0.3).unwrap();
        let soft = 1e9 * ratio.min(1.0) / (1.0 - 0.09);
        assert!(e.is_finite() && e <= soft * (1.0 + 1e-12) && e >= 0.5 * soft * (1.0 - 1e-12));
        if let Some(p) = prev {
            assert!(e > p, "E* must grow with the second modulus");
        }
        prev = Some(e);
    }
}

#[test]
fn no_slip_factor_reference_and_limit() {
    assert_relative_eq!(
        no_slip_factor(0.355).unwrap(),
        1.017376,
        max_relative = 1e-6
    );
    assert_relative_eq!(
        no_slip_factor(0.0).unwrap(),
        3f64.ln(),
        max_relative = 1e-15
    );
    assert_eq!(no_slip_factor(0.5).unwrap(), 1.0);
    // Continuity and monotone decrease over ν ∈ [0, 0.5], through the series
    // switch, on a fine grid near 1/2.
    let mut prev = f64::INFINITY;
    for i in 0..=2000 {
        // From 0 up to 0.5, dense near 0.5 (last steps ~1e-11).
        let nu = 0.5 * (1.0 - (1.0 - i as f64 / 2000.0).powi(3));
        let c = no_slip_factor(nu).unwrap();
        assert!(
            c.is_finite() && c >= 1.0 && c <= prev + 1e-15,
            "nu={nu} c={c}"
        );
        prev = c;
    }
    // Near 1/2: C_NS = 1 + (4/3)ε² − (16/3)ε³ + O(ε⁴) with ε = 1/2 − ν
    // (expand (1+2ε)·ln(1+4ε)/(4ε)).
    for eps in [1e-3, 1e-4, 1e-5, 1e-7] {
        let c = no_slip_factor(0.5 - eps).unwrap();
        assert!(
            (c - (1.0 + 4.0 / 3.0 * eps * eps)).abs() < 6.0 * eps.powi(3),
            "eps={eps}"
        );
    }
    assert!(matches!(
        no_slip_factor(0.5000001),
        Err(Error::InvalidArgument { name: "nu", .. })
    ));
    assert!(no_slip_factor(f64::NAN).is_err());
}

#[test]
fn tabor_and_maugis_parameters_of_the_worked_example() {
    // REFERENCE §8: R = 1 µm, w = 0.05 J/m², E* = 1 GPa, z0 = 0.3 nm.
    let (r, w, e, z0) = (1e-6, 0.05, 1e9, 0.3e-9);
    assert_relative_eq!(
        tabor_parameter(r, w, e, z0).unwrap(),
        4.52403,
        max_relative = 1e-5
    );
    let s = lennard_jones_theoretical_stress(w, z0).unwrap();
    assert_relative_eq!(s, 1.710667e8, max_relative = 1e-6);
    assert_relative_eq!(
        maugis_parameter(r, w, e, s).unwrap(),
        5.23435,
        max_relative = 1e-5
    );
    assert_relative_eq!(maugis_over_tabor(), 1.157012, max_relative = 1e-6);
    assert_relative_eq!(
        maugis_parameter(r, w, e, s).unwrap() / tabor_parameter(r, w, e, z0).unwrap(),
        maugis_over_tabor(),
        max_relative = 1e-13
    );
}

// ---------------------------------------------------------------- Hertz

#[test]
fn hertz_closed_forms() {
    let h = Hertz::new(1e-3, 1e9).unwrap();
    let delta = 1e-6;
    let (r, s) = h.eval(delta, &FRESH).unwrap();
    let a = (1e-3f64 * 1e-6).sqrt();
    assert_relative_eq!(r.contact_radius, a, max_relative = 1e-15);
    assert_relative_eq!(
        r.force,
        4.0 / 3.0 * 1e9 * (1e-3f64).sqrt() * delta.powf(1.5),
        max_relative = 1e-14
    );
    assert_relative_eq!(r.stiffness, 2.0 * 1e9 * a, max_relative = 1e-15);
    assert_eq!((r.in_contact, s.in_contact), (1, 1));
    // Load control inverts displacement control; p0 = 3P/(2πa²).
    let l = h.eval_at_load(r.force).unwrap();
    assert_relative_eq!(l.delta, delta, max_relative = 1e-13);
    assert_relative_eq!(
        h.peak_pressure(r.force).unwrap(),
        3.0 * r.force / (2.0 * PI * a * a),
        max_relative = 1e-13
    );
    // Out of contact: nothing.
    let (r, _) = h.eval(-1e-9, &FRESH).unwrap();
    assert_eq!(
        (r.force, r.contact_radius, r.stiffness, r.in_contact),
        (0.0, 0.0, 0.0, 0)
    );
    assert_eq!(h.pull_off_force(Control::Load).unwrap(), 0.0);
    assert!(matches!(
        h.eval_at_load(-1.0),
        Err(Error::OutOfDomain { name: "force", .. })
    ));
}

#[test]
fn galanov_effective_radius_of_the_taljat_crater() {
    // REFERENCE §2: R = 0.788 mm in a medium of radius 0.798 mm ⇒ R₂ = 62.882 mm.
    let h = Hertz::sphere_in_crater(0.788e-3, 0.798e-3, 1e9).unwrap();
    assert_relative_eq!(h.params().radius, 62.882e-3, max_relative = 1e-4);
    let flat = Hertz::sphere_in_crater(0.788e-3, f64::INFINITY, 1e9).unwrap();
    assert_eq!(flat.params().radius, 0.788e-3);
    assert!(Hertz::sphere_in_crater(1e-3, 1e-3, 1e9).is_err());
}

// ---------------------------------------------------------------- Galin

#[test]
// The table's printed digits, not π/2: the point is to match the reference.
#[allow(clippy::approx_constant)]
fn galin_constants_table() {
    for (d, c, dd) in [
        (1.0, 1.570796327, 1.570796327),
        (1.5, 2.156652423, 1.797210352),
        (2.0, 2.666666667, 2.0),
        (3.0, 3.534291735, 2.356194490),
    ] {
        assert_relative_eq!(galin_c(d), c, max_relative = 1e-9);
        assert_relative_eq!(galin_d(d), dd, max_relative = 1e-9);
        // The closed form d²2^{d−1}Γ(d/2)²/((d+1)Γ(d)) of REFERENCE §1, at
        // integer d where Γ is known exactly.
        if d.fract() == 0.0 {
            let alt = d * d * 2f64.powf(d - 1.0) * gamma_half_integer(d / 2.0).powi(2)
                / ((d + 1.0) * gamma_half_integer(d));
            assert_relative_eq!(galin_c(d), alt, max_relative = 1e-12);
        }
    }
}

/// Γ at the half-integers and integers the table needs, exactly.
fn gamma_half_integer(x: f64) -> f64 {
    match (2.0 * x) as i64 {
        1 => PI.sqrt(),
        2 | 4 => 1.0,
        3 => PI.sqrt() / 2.0,
        6 => 2.0,
        _ => panic!("gamma({x}) not tabulated"),
    }
}

#[test]
fn galin_worked_example() {
    // REFERENCE §8: d = 1.5, B = 1e3 m^-1/2, E* = 1 GPa, a = 1 µm.
    let p = PowerPunch::new(1e3, 1.5, 1e9).unwrap();
    assert_relative_eq!(p.force_at_radius(1e-6), 2.1566524e-3, max_relative = 1e-7);
    assert_relative_eq!(p.delta_at_radius(1e-6), 1.7972104e-6, max_relative = 1e-7);
    let (r, _) = p.eval(1.7972104e-6, &FRESH).unwrap();
    assert_relative_eq!(r.contact_radius, 1e-6, max_relative = 1e-7);
    assert_relative_eq!(r.force, 2.1566524e-3, max_relative = 1e-7);
    assert_relative_eq!(
        r.stiffness,
        2.0 * 1e9 * r.contact_radius,
        max_relative = 1e-15
    );
}

#[test]
fn galin_d2_is_hertz_and_d1_is_the_cone() {
    let rad = 2e-3;
    let galin = PowerPunch::new(1.0 / (2.0 * rad), 2.0, 70e9).unwrap();
    let hertz = Hertz::new(rad, 70e9).unwrap();
    for k in -12..=3 {
        let delta = rad * 10f64.powi(k);
        let (g, _) = galin.eval(delta, &FRESH).unwrap();
        let (h, _) = hertz.eval(delta, &FRESH).unwrap();
        assert_relative_eq!(g.force, h.force, max_relative = 1e-13);
        assert_relative_eq!(g.contact_radius, h.contact_radius, max_relative = 1e-13);
        assert_relative_eq!(g.stiffness, h.stiffness, max_relative = 1e-13);
    }
    // Cone: P = (π/2) E* a² cot γ, δ = (π/2) a cot γ.
    let gamma = 60f64.to_radians();
    let cone = PowerPunch::cone(gamma, 70e9).unwrap();
    let a = 3e-6;
    let delta = PI / 2.0 * a / gamma.tan();
    let (r, _) = cone.eval(delta, &FRESH).unwrap();
    assert_relative_eq!(r.contact_radius, a, max_relative = 1e-14);
    assert_relative_eq!(
        r.force,
        PI / 2.0 * 70e9 * a * a / gamma.tan(),
        max_relative = 1e-14
    );
}

#[test]
fn equivalent_cones_and_galanov_cone() {
    assert_relative_eq!(
        BERKOVICH_EQUIVALENT_HALF_ANGLE.to_degrees(),
        70.3,
        max_relative = 1e-12
    );
    assert_relative_eq!(
        VICKERS_EQUIVALENT_HALF_ANGLE.to_degrees(),
        70.3,
        max_relative = 1e-12
    );
    assert_relative_eq!(
        CUBE_CORNER_EQUIVALENT_HALF_ANGLE.to_degrees(),
        42.3,
        max_relative = 1e-12
    );
    // B₁ = cot γ_i − cot γ_f (thesis (2-18)).
    let (gi, gf) = (70.3f64.to_radians(), 75f64.to_radians());
    let c = PowerPunch::cone_in_imprint(gi, gf, 1e9).unwrap();
    assert_relative_eq!(
        c.params().b,
        1.0 / gi.tan() - 1.0 / gf.tan(),
        max_relative = 1e-14
    );
    assert!(PowerPunch::cone_in_imprint(gi, gi, 1e9).is_err());
    assert!(PowerPunch::cone(PI / 2.0, 1e9).is_err());
}

// ---------------------------------------------------------------- flat punch, DMT

#[test]
fn flat_punch_boussinesq_and_no_slip() {
    let f = FlatPunch::new(1e-6, 68.65e9).unwrap();
    let (r, _) = f.eval(1e-9, &FRESH).unwrap();
    assert_relative_eq!(r.force, 2.0 * 68.65e9 * 1e-6 * 1e-9, max_relative = 1e-15);
    let ns = FlatPunch::no_slip(1e-6, 68.65e9, 0.355).unwrap();
    assert_relative_eq!(force(&ns, 1e-9) / r.force, 1.017376, max_relative = 1e-6);
    assert_eq!(
        force(&FlatPunch::no_slip(1e-6, 1e9, 0.5).unwrap(), 1e-9),
        force(&FlatPunch::new(1e-6, 1e9).unwrap(), 1e-9)
    );
}

#[test]
fn dmt_pull_off_and_law() {
    // REFERENCE §8: DMT P_c = 2πwR = 3.14159e-7 N for R = 1 µm, w = 0.05 J/m².
    let d = Dmt::new(1e-6, 1e9, 0.05).unwrap();
    for c in [Control::Load, Control::Displacement] {
        assert_relative_eq!(
            d.pull_off_force(c).unwrap(),
            -3.14159e-7,
            max_relative = 1e-5
        );
    }
    let h = Hertz::new(1e-6, 1e9).unwrap();
    for delta in [0.0, 1e-10, 1e-9, 1e-8] {
        assert_relative_eq!(
            force(&d, delta),
            force(&h, delta) - 2.0 * PI * 0.05 * 1e-6,
            max_relative = 1e-14,
            epsilon = 1e-22
        );
    }
    assert_eq!(force(&d, -1e-12), 0.0);
    // Load control: at the pull-off load the contact radius vanishes.
    let r = d.eval_at_load(-2.0 * PI * 0.05 * 1e-6).unwrap();
    assert!(r.contact_radius.abs() < 1e-12);
    assert!(d.eval_at_load(-3.2e-7).is_err());
}

// ---------------------------------------------------------------- extremes

/// Every non-hysteretic closed-form law: δ over 1e-12 … 1e6 natural lengths,
/// finite, continuous and monotone (force and contact radius non-decreasing).
#[test]
fn extreme_overlaps_are_finite_and_monotone() {
    let mut laws: Vec<NormalLaw> = vec![
        NormalLaw::Hertz(Hertz::new(1e-6, 1e9).unwrap()),
        NormalLaw::Hertz(Hertz::new(1.0, 1e12).unwrap()),
        NormalLaw::FlatPunch(FlatPunch::new(1e-6, 1e9).unwrap()),
        NormalLaw::Dmt(Dmt::new(1e-6, 1e9, 0.05).unwrap()),
        NormalLaw::Dmt(Dmt::new(1e-9, 1e12, 1.0).unwrap()),
    ];
    for i in 0..=19 {
        let d = 1.0 + i as f64;
        laws.push(NormalLaw::PowerPunch(PowerPunch::new(1e3, d, 1e9).unwrap()));
    }
    for law in &laws {
        let scale = law.length_scale();
        let mut prev: Option<(f64, f64)> = None;
        for k in 0..=360 {
            let delta = scale * 10f64.powf(-12.0 + 18.0 * k as f64 / 360.0);
            match law.eval(delta, &FRESH) {
                Ok((r, _)) => {
                    assert!(
                        r.force.is_finite()
                            && r.contact_radius.is_finite()
                            && r.stiffness.is_finite()
                    );
                    assert!(r.stiffness >= 0.0);
                    if let Some((f, a)) = prev {
                        assert!(
                            r.force >= f && r.contact_radius >= a,
                            "{law:?} at δ={delta}"
                        );
                    }
                    prev = Some((r.force, r.contact_radius));
                }
                // A huge-d punch may overflow at an extreme overlap: that is a
                // clean error naming delta, never a NaN.
                Err(Error::OutOfDomain { name: "delta", .. }) => {}
                Err(e) => panic!("{law:?} at δ={delta}: {e}"),
            }
        }
    }
}

#[test]
fn nan_and_infinite_overlaps_are_rejected() {
    let law = NormalLaw::Hertz(Hertz::new(1e-6, 1e9).unwrap());
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        assert!(matches!(
            law.eval(bad, &FRESH),
            Err(Error::InvalidArgument { name: "delta", .. })
        ));
        assert!(matches!(
            law.eval_at_load(bad),
            Err(Error::InvalidArgument { name: "force", .. })
        ));
    }
    for (name, r) in [
        ("radius", Hertz::new(-1.0, 1e9).err()),
        ("e_star", Hertz::new(1.0, 0.0).err()),
        ("e_star", Hertz::new(1.0, f64::INFINITY).err()),
        ("d", PowerPunch::new(1.0, 0.5, 1e9).err()),
        ("b", PowerPunch::new(-1.0, 2.0, 1e9).err()),
        ("work_of_adhesion", Dmt::new(1.0, 1.0, -0.1).err()),
        ("nu", FlatPunch::no_slip(1.0, 1.0, 0.6).err()),
    ] {
        match r {
            Some(Error::InvalidArgument { name: n, .. }) => assert_eq!(n, name),
            other => panic!("expected InvalidArgument for {name}, got {other:?}"),
        }
    }
}

mod stiffness_matches_finite_difference {
    use super::*;
    use proptest::prelude::*;

    fn check(law: &NormalLaw, delta: f64) {
        let h = 1e-6 * delta.abs();
        let (r, _) = law.eval(delta, &FRESH).unwrap();
        let fp = law.eval(delta + h, &FRESH).unwrap().0.force;
        let fm = law.eval(delta - h, &FRESH).unwrap().0.force;
        let fd = (fp - fm) / (2.0 * h);
        // Truncation O(h²) plus the rounding of the two forces divided by 2h.
        let rounding = 4.0 * f64::EPSILON * (fp.abs() + fm.abs()) / (2.0 * h);
        assert!(
            (r.stiffness - fd).abs() <= 1e-6 * r.stiffness.abs().max(fd.abs()) + rounding,
            "{law:?} δ={delta}: stiffness {} vs FD {fd}",
            r.stiffness
        );
    }

    proptest! {
        #[test]
        fn power_punch(d in 1.0f64..20.0, lb in -3.0f64..6.0, le in 6.0f64..12.0, ld in -14.0f64..-4.0) {
            let law = NormalLaw::PowerPunch(PowerPunch::new(10f64.powf(lb), d, 10f64.powf(le)).unwrap());
            check(&law, 10f64.powf(ld));
        }

        #[test]
        fn hertz_and_dmt(lr in -9.0f64..0.0, le in 6.0f64..12.0, lw in -3.0f64..0.0, ld in -14.0f64..-4.0) {
            check(&NormalLaw::Hertz(Hertz::new(10f64.powf(lr), 10f64.powf(le)).unwrap()), 10f64.powf(ld));
            check(&NormalLaw::Dmt(Dmt::new(10f64.powf(lr), 10f64.powf(le), 10f64.powf(lw)).unwrap()), 10f64.powf(ld));
        }
    }
}

/// The chunked (vectorisable) batch of the pointwise laws equals the scalar
/// law bit for bit, and a bad element in a later chunk is reported at its own
/// index with earlier outputs written and later ones untouched.
#[test]
fn pointwise_batches_match_scalar_and_stop_at_the_bad_element() {
    use asperity::contact::eval_batch;
    let laws = [
        NormalLaw::Hertz(Hertz::new(1e-6, 1e9).unwrap()),
        NormalLaw::Dmt(Dmt::new(1e-6, 1e9, 0.05).unwrap()),
        NormalLaw::FlatPunch(FlatPunch::no_slip(1e-6, 1e9, 0.3).unwrap()),
    ];
    for law in &laws {
        let n = 200;
        let mut delta: Vec<f64> = (0..n).map(|i| 1e-9 * (i as f64 - 60.5) / 7.0).collect();
        delta[3] = 0.0;
        delta[4] = -0.0;
        let mut force = vec![0.0; n];
        let mut radius = vec![0.0; n];
        let mut stiff = vec![0.0; n];
        let mut states = vec![ContactState::default(); n];
        eval_batch(
            law,
            &delta,
            None,
            Some(&mut states),
            &mut force,
            Some(&mut radius),
            Some(&mut stiff),
        )
        .unwrap();
        for i in 0..n {
            let (r, s) = law.eval(delta[i], &FRESH).unwrap();
            assert_eq!(
                (
                    r.force.to_bits(),
                    r.contact_radius.to_bits(),
                    r.stiffness.to_bits()
                ),
                (force[i].to_bits(), radius[i].to_bits(), stiff[i].to_bits()),
                "{law:?} element {i}"
            );
            assert_eq!(s, states[i]);
        }
        delta[70] = f64::NAN;
        delta[130] = f64::INFINITY;
        let mut force2 = vec![-7.0; n];
        let e = eval_batch(law, &delta, None, None, &mut force2, None, None).unwrap_err();
        assert_eq!(e.index, 70);
        assert!(matches!(
            e.error,
            Error::InvalidArgument { name: "delta", .. }
        ));
        assert!(force2[..70]
            .iter()
            .zip(&force)
            .all(|(a, b)| a.to_bits() == b.to_bits()));
        assert!(force2[70..].iter().all(|&x| x == -7.0));
    }
}
