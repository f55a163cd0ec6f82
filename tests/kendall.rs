//! Kendall adhesive flat punch: reference values (REFERENCE.md §5, §8),
//! hysteresis, limits, errors.

use asperity::contact::{FlatPunch, Kendall};
use asperity::material::{effective_modulus, no_slip_factor};
use asperity::{ContactState, Control, Error, NormalContact, NormalLaw};
use core::f64::consts::PI;

/// `x` equals the printed value to its last printed digit (half a unit).
fn printed(x: f64, text: &str) {
    let v: f64 = text.parse().unwrap();
    let (mant, exp) = text.split_once('e').unwrap_or((text, "0"));
    let decimals = mant.split_once('.').map_or(0, |(_, f)| f.len()) as i32;
    let exp: i32 = exp.parse().unwrap();
    let half_unit = 0.5 * 10f64.powi(exp - decimals);
    assert!(
        (x - v).abs() <= half_unit * (1.0 + 1e-9),
        "{x:e} does not print as {text}"
    );
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

fn touching() -> ContactState {
    ContactState {
        in_contact: 1,
        branch: 1,
        ..Default::default()
    }
}

#[test]
fn reference_values() {
    // §8: a = 1 µm, w = 0.05 J/m², E* = 1 GPa, frictionless.
    let k = Kendall::new(1e-6, 1e9, 0.05).unwrap();
    for c in [Control::Load, Control::Displacement] {
        printed(-k.pull_off_force(c).unwrap(), "3.54491e-5");
    }
    // §5: F_adh,1 = √(8πW₁₂E*C_NS a³) for Cu–Cu, W₁₂ = 0.10928, E = 120 GPa,
    // ν = 0.355 (E* = E/(2(1−ν²)) = 68.65 GPa), a = 215 nm.
    let e_star = effective_modulus(120e9, 0.355, 120e9, 0.355).unwrap();
    printed(e_star, "68.65e9");
    let k = Kendall::no_slip(215e-9, e_star, 0.10928, 0.355).unwrap();
    printed(k.no_slip_factor(), "1.017376");
    let f = -k.pull_off_force(Control::Load).unwrap();
    printed(f, "4.366e-5");
    printed(100.0 * f, "4.366e-3");
    assert!(
        rel(
            f,
            (8.0 * PI * 0.10928 * e_star * no_slip_factor(0.355).unwrap() * 215e-9f64.powi(3))
                .sqrt()
        ) < 1e-14
    );
}

#[test]
fn contact_law_and_critical_overlap() {
    let (a, e, w) = (2e-6, 5e9, 0.2);
    for nu in [None, Some(0.0), Some(0.3), Some(0.5)] {
        let k = match nu {
            None => Kendall::new(a, e, w).unwrap(),
            Some(nu) => Kendall::no_slip(a, e, w, nu).unwrap(),
        };
        let c = k.no_slip_factor();
        let stiff = 2.0 * e * c * a;
        assert!(rel(k.stiffness(), stiff) < 1e-15);
        let pc = -(8.0 * PI * w * e * c * a * a * a).sqrt();
        assert!(rel(k.pull_off_force(Control::Load).unwrap(), pc) < 1e-14);
        let dc = pc / stiff;
        assert!(rel(k.critical_delta(), dc) < 1e-14);
        assert!(rel(k.length_scale(), (2.0 * PI * w * a / (e * c)).sqrt()) < 1e-14);
        for delta in [dc, 0.5 * dc, 0.0, 1e-9, 1e-6] {
            let (r, s) = k.eval(delta, &touching()).unwrap();
            assert_eq!((r.in_contact, s.in_contact), (1, 1));
            assert!((r.force - stiff * delta).abs() <= 1e-15 * stiff * delta.abs());
            assert_eq!(r.stiffness, k.stiffness());
            assert_eq!(r.contact_radius, a);
            // Load control inverts it.
            let l = k.eval_at_load(r.force).unwrap();
            assert!((l.delta - delta).abs() <= 1e-15 * delta.abs().max(-dc));
        }
        assert!(matches!(
            k.eval_at_load(pc * (1.0 + 1e-12)),
            Err(Error::OutOfDomain { name: "force", .. })
        ));
        assert!(k
            .eval_at_load(k.pull_off_force(Control::Load).unwrap())
            .is_ok());
    }
}

#[test]
fn hysteresis_loop() {
    let k = Kendall::new(1e-6, 1e9, 0.05).unwrap();
    let dc = k.critical_delta();
    let n = 300;
    let approach = (0..=n).map(|i| 2.0 * dc - 5.0 * dc * i as f64 / n as f64);
    let retract = (0..=n).map(|i| -3.0 * dc + 5.0 * dc * i as f64 / n as f64);
    let mut state = ContactState::default();
    let mut forces = Vec::new();
    for (i, delta) in approach.chain(retract).enumerate() {
        let old = state;
        let (r, s) = k.eval(delta, &old).unwrap();
        assert_eq!(
            k.eval(delta, &old).unwrap(),
            (r, s),
            "re-evaluation differs"
        );
        let expect = if i <= n { delta >= 0.0 } else { delta >= dc };
        assert_eq!(r.in_contact == 1, expect, "step {i}, δ = {delta:e}");
        if r.in_contact == 0 {
            assert_eq!((r.force, r.stiffness, r.contact_radius), (0.0, 0.0, 0.0));
        }
        forces.push(r.force);
        state = s;
    }
    // On retraction the tension reaches close to P_c before the jump out.
    let pmin = forces.iter().cloned().fold(f64::INFINITY, f64::min);
    let pc = k.pull_off_force(Control::Displacement).unwrap();
    assert!(pmin >= pc && pmin < 0.98 * pc, "{pmin:e} vs {pc:e}");
    // Approach carries no tension.
    assert!(forces[..=n].iter().all(|&f| f >= 0.0));
}

#[test]
fn zero_adhesion_is_the_flat_punch() {
    for nu in [None, Some(0.2)] {
        let (k, f) = match nu {
            None => (
                Kendall::new(1e-3, 2e9, 0.0).unwrap(),
                FlatPunch::new(1e-3, 2e9).unwrap(),
            ),
            Some(nu) => (
                Kendall::no_slip(1e-3, 2e9, 0.0, nu).unwrap(),
                FlatPunch::no_slip(1e-3, 2e9, nu).unwrap(),
            ),
        };
        assert_eq!(k.pull_off_force(Control::Load).unwrap(), 0.0);
        assert_eq!(k.length_scale(), 1e-3);
        for delta in [-1e-9, 0.0, 1e-9, 1e-3] {
            let (rk, _) = k.eval(delta, &touching()).unwrap();
            let (rf, _) = f.eval(delta, &touching()).unwrap();
            assert_eq!(rk.force, rf.force);
            assert_eq!(rk.in_contact, rf.in_contact);
        }
    }
}

#[test]
fn no_slip_tends_to_frictionless() {
    let f = Kendall::new(1e-6, 1e9, 0.05).unwrap();
    let pf = f.pull_off_force(Control::Load).unwrap();
    let mut prev = f64::INFINITY;
    for k in 1..=15 {
        let n = Kendall::no_slip(1e-6, 1e9, 0.05, 0.5 - 10f64.powi(-k)).unwrap();
        let d =
            rel(n.pull_off_force(Control::Load).unwrap(), pf) + rel(n.stiffness(), f.stiffness());
        assert!(d <= prev && d < 10.0 * 10f64.powi(-k) + 1e-15, "{d:e}");
        prev = d;
    }
    // At ν = 0.5, C_NS = 1: the bonded punch is the frictionless one (the
    // inputs still say bonded, ν = 0.5).
    let n = Kendall::no_slip(1e-6, 1e9, 0.05, 0.5).unwrap();
    assert_eq!(n.no_slip_factor(), 1.0);
    assert_eq!(n.stiffness(), f.stiffness());
    assert_eq!(n.critical_delta(), f.critical_delta());
    assert_eq!(
        n.pull_off_force(Control::Load).unwrap(),
        f.pull_off_force(Control::Load).unwrap()
    );
    assert_eq!((n.params().nu, n.params().no_slip), (0.5, 1));
}

#[test]
fn bad_input_and_dispatch() {
    let name = |r: asperity::Result<Kendall>| match r {
        Err(Error::InvalidArgument { name, .. }) => name,
        other => panic!("{other:?}"),
    };
    assert_eq!(name(Kendall::new(0.0, 1e9, 0.05)), "radius");
    assert_eq!(name(Kendall::new(1e-6, -1.0, 0.05)), "e_star");
    assert_eq!(name(Kendall::new(1e-6, 1e9, f64::NAN)), "work_of_adhesion");
    assert_eq!(name(Kendall::no_slip(1e-6, 1e9, 0.05, 0.7)), "nu");
    let k = Kendall::new(1e-6, 1e9, 0.05).unwrap();
    assert!(matches!(
        k.eval(f64::NAN, &ContactState::default()),
        Err(Error::InvalidArgument { name: "delta", .. })
    ));
    assert!(matches!(
        k.eval_at_load(f64::NAN),
        Err(Error::InvalidArgument { name: "force", .. })
    ));
    assert!(core::mem::size_of::<Kendall>() <= 16 * 8);
    let law = NormalLaw::Kendall(k);
    let (r, _) = law.eval(-1e-12, &touching()).unwrap();
    assert_eq!(r.in_contact, 1);
    assert!(r.force < 0.0);
}
