//! `NormalContact::reach` and its C ABI (`asperity_normal_reach`,
//! `asperity_table_reach`): for every law, overlaps below the reach give
//! zero force (or below `rel_force`·|pull-off| for the infinite tails) from
//! several history states — fresh, on approach, at a deep overlap and step
//! by step on retraction — while a retracting contact still pulls exactly at
//! the displacement-control reach of the adhesive laws; the JKR closed
//! forms; sweeps over decades of the parameters.

mod common;
use common::c_errors::expect_error;

use asperity::contact::{
    ContactState, Control, Derjaguin, Dmt, FlatPunch, Hertz, Jkr, JkrPowerPunch, Kendall, LjSphere,
    MaugisDugdale, NormalContact, NormalLaw, PowerPunch, SurfaceLaw, TabulatedLaw,
};
use asperity::ffi::contact::*;
use asperity::ffi::tabulated::*;
use asperity::ffi::*;
use core::f64::consts::PI;
use std::ptr::{null, null_mut};

const R: f64 = 1e-5;
const E: f64 = 1e9;
const W: f64 = 0.05;
const REL: f64 = 1e-4;

fn next_down(v: f64) -> f64 {
    if v == 0.0 {
        -f64::from_bits(1)
    } else if v > 0.0 {
        f64::from_bits(v.to_bits() - 1)
    } else {
        f64::from_bits(v.to_bits() + 1)
    }
}

fn lin(a: f64, b: f64, n: usize) -> Vec<f64> {
    // The end points exactly.
    (0..=n)
        .map(|i| {
            if i == n {
                b
            } else {
                a + (b - a) * i as f64 / n as f64
            }
        })
        .collect()
}

/// One law under test: how deep to load it, and whether its force has an
/// infinite tail (then "zero" means below `REL`·|load pull-off|).
struct Case<'a> {
    name: String,
    law: &'a dyn NormalContact,
    delta_max: f64,
    tail: bool,
    adhesive: bool,
}

/// The histories of the brief: fresh, approach states, the deepest state and
/// every state of a step-by-step retraction down to exactly `reach`.
/// Returns them and the force at the last retraction step (δ = reach).
fn histories(c: &Case, reach: f64, scale: f64) -> (Vec<ContactState>, f64) {
    let law = c.law;
    let mut states = vec![ContactState::default()];
    let mut st = ContactState::default();
    for d in lin(reach - 3.0 * scale, c.delta_max, 300) {
        st = law.eval(d, &st).unwrap().1;
        states.push(st);
    }
    let mut last = 0.0;
    for d in lin(c.delta_max, reach, 400) {
        let (r, s) = law.eval(d, &st).unwrap();
        st = s;
        last = r.force;
        states.push(st);
    }
    (states, last)
}

fn below(reach: f64, scale: f64) -> Vec<f64> {
    let mut v = vec![next_down(reach)];
    for f in [
        1e-12, 1e-9, 1e-6, 1e-3, 0.01, 0.1, 0.5, 1.0, 3.0, 10.0, 100.0,
    ] {
        v.push(reach - f * scale);
    }
    v
}

fn check_case(c: &Case) {
    let law = c.law;
    let pc = law.pull_off_force(Control::Load).unwrap().abs();
    let bound = if c.tail { REL * pc } else { 0.0 };
    let scale = law.length_scale();
    for control in [Control::Displacement, Control::Load] {
        let reach = law.reach(control, REL).unwrap();
        assert!(
            reach.is_finite() && reach <= 0.0,
            "{}: reach {reach}",
            c.name
        );
        let (states, last) = histories(c, reach, scale);
        // Displacement control: every history. Load control: the histories
        // that never pulled past the load pull-off (fresh and approach
        // ones); a contact is released there by the host.
        let checked: Vec<ContactState> = match control {
            Control::Displacement => states,
            Control::Load => states[..302]
                .iter()
                .copied()
                .filter(|s| s.in_contact == 0)
                .collect(),
        };
        for st in &checked {
            for d in below(reach, scale) {
                let (r, _) = law.eval(d, st).unwrap();
                assert!(
                    r.force.abs() <= bound,
                    "{} {control:?}: force {} at δ = {d:e} < reach {reach:e} from {st:?}",
                    c.name,
                    r.force
                );
            }
        }
        if c.adhesive && control == Control::Displacement {
            assert!(
                last != 0.0,
                "{}: a retracting contact lets go before its reach {reach:e}",
                c.name
            );
        }
    }
}

#[test]
fn analytic_laws_have_no_force_below_their_reach() {
    let md = |lam: f64| MaugisDugdale::from_maugis_parameter(R, E, W, lam).unwrap();
    let laws: Vec<(String, NormalLaw, f64, bool, bool)> = vec![
        (
            "hertz".into(),
            Hertz::new(R, E).unwrap().into(),
            1e-7,
            false,
            false,
        ),
        (
            "cone".into(),
            PowerPunch::cone(1.2, E).unwrap().into(),
            1e-7,
            false,
            false,
        ),
        (
            "punch d=3".into(),
            PowerPunch::new(1e8, 3.0, E).unwrap().into(),
            1e-7,
            false,
            false,
        ),
        (
            "flat".into(),
            FlatPunch::new(R, E).unwrap().into(),
            1e-7,
            false,
            false,
        ),
        (
            "dmt".into(),
            Dmt::new(R, E, W).unwrap().into(),
            1e-7,
            false,
            false,
        ),
        (
            "jkr".into(),
            Jkr::new(R, E, W).unwrap().into(),
            1e-7,
            false,
            true,
        ),
        (
            "jkr w=0".into(),
            Jkr::new(R, E, 0.0).unwrap().into(),
            1e-7,
            false,
            false,
        ),
        (
            "jkr punch d=2".into(),
            JkrPowerPunch::new(0.5 / R, 2.0, E, W).unwrap().into(),
            1e-7,
            false,
            true,
        ),
        (
            "jkr punch d=1.2".into(),
            JkrPowerPunch::new(30.0, 1.2, E, W).unwrap().into(),
            1e-7,
            false,
            true,
        ),
        (
            "jkr punch d=4".into(),
            JkrPowerPunch::new(1e15, 4.0, E, W).unwrap().into(),
            1e-7,
            false,
            true,
        ),
        (
            "kendall".into(),
            Kendall::new(R, E, W).unwrap().into(),
            1e-7,
            false,
            true,
        ),
        ("md λ=0.1".into(), md(0.1).into(), 1e-7, false, true),
        ("md λ=0.5".into(), md(0.5).into(), 1e-7, false, true),
        ("md λ=1.5".into(), md(1.5).into(), 1e-7, false, true),
        ("md λ=10".into(), md(10.0).into(), 1e-7, false, true),
        (
            "derjaguin lj".into(),
            Derjaguin::new(
                R,
                SurfaceLaw::LennardJones {
                    work_of_adhesion: W,
                    equilibrium_separation: 3e-10,
                },
            )
            .unwrap()
            .into(),
            1e-10,
            true,
            false,
        ),
        (
            "derjaguin dugdale".into(),
            Derjaguin::new(
                R,
                SurfaceLaw::Dugdale {
                    work_of_adhesion: W,
                    cohesive_stress: 1e8,
                },
            )
            .unwrap()
            .into(),
            0.0,
            false,
            false,
        ),
        (
            "derjaguin exponential".into(),
            Derjaguin::new(
                R,
                SurfaceLaw::Exponential {
                    work_of_adhesion: W,
                    decay_length: 1e-9,
                },
            )
            .unwrap()
            .into(),
            0.0,
            true,
            false,
        ),
    ];
    for (name, law, delta_max, tail, adhesive) in &laws {
        check_case(&Case {
            name: name.clone(),
            law,
            delta_max: *delta_max,
            tail: *tail,
            adhesive: *adhesive,
        });
    }
}

#[test]
fn non_adhesive_laws_and_dmt_reach_zero() {
    let laws: [NormalLaw; 5] = [
        Hertz::new(R, E).unwrap().into(),
        PowerPunch::cone(1.2, E).unwrap().into(),
        FlatPunch::new(R, E).unwrap().into(),
        Dmt::new(R, E, W).unwrap().into(),
        Jkr::new(R, E, 0.0).unwrap().into(),
    ];
    for l in laws {
        for c in [Control::Load, Control::Displacement] {
            assert_eq!(l.reach(c, REL).unwrap(), 0.0, "{l:?}");
        }
    }
}

/// JKR: displacement reach δ_c; load reach `a²/R − √(2πwa/E*)` at
/// `a = (9πwR²/(8E*))^{1/3}` (LAMMPS's release point) to 1e-12, where the
/// force of a retracting contact is −(3/2)πwR to 1e-10; over decades.
#[test]
fn jkr_reach_closed_forms_over_decades() {
    for w in [1e-4, 1e-2, 0.05, 1.0, 1e2] {
        for r in [1e-9, 1e-7, 1e-5, 1e-3, 1.0] {
            for e in [1e6, 1e9, 1e12] {
                let j = Jkr::new(r, e, w).unwrap();
                let d = j.reach(Control::Displacement, REL).unwrap();
                assert_eq!(d, j.critical_delta());
                let dc = -0.75 * (PI * PI * w * w * r / (e * e)).cbrt();
                assert!(((d - dc) / dc).abs() < 1e-13, "δ_c {d} vs {dc}");
                let l = j.reach(Control::Load, REL).unwrap();
                let a = (9.0 * PI * w * r * r / (8.0 * e)).cbrt();
                let closed = a * a / r - (2.0 * PI * w * a / e).sqrt();
                assert!(
                    ((l - closed) / closed).abs() < 1e-12,
                    "w {w} R {r} E {e}: load reach {l:e} vs {closed:e}"
                );
                assert!(l.is_finite() && l < 0.0 && d < l);
                let inside = ContactState {
                    in_contact: 1,
                    branch: 1,
                    ..Default::default()
                };
                let f = j.eval(l, &inside).unwrap().0.force;
                let pc = -1.5 * PI * w * r;
                assert!(((f - pc) / pc).abs() < 1e-10, "force {f:e} vs {pc:e}");
                // Through the dispatching type as well.
                let n: NormalLaw = j.into();
                assert_eq!(n.reach(Control::Load, REL).unwrap(), l);
            }
        }
    }
}

/// The JKR power punch with d = 2 is the JKR sphere (B = 1/(2R)).
#[test]
fn jkr_power_punch_d2_matches_jkr() {
    let j = Jkr::new(R, E, W).unwrap();
    let p = JkrPowerPunch::new(0.5 / R, 2.0, E, W).unwrap();
    for c in [Control::Load, Control::Displacement] {
        let (a, b) = (j.reach(c, REL).unwrap(), p.reach(c, REL).unwrap());
        assert!(((a - b) / a).abs() < 1e-10, "{c:?}: {a:e} vs {b:e}");
    }
}

/// Maugis–Dugdale: the load reach is where a retracting contact pulls with
/// the load pull-off force (when that lies inside −h₀), and every reach is
/// at or below −h₀, where a fresh contact starts to feel the cohesive zone.
#[test]
fn maugis_dugdale_reach_covers_the_cohesive_zone() {
    for lam in [0.01, 0.1, 0.5, 0.938, 1.0, 3.0, 30.0, 1e3] {
        let m = MaugisDugdale::from_maugis_parameter(R, E, W, lam).unwrap();
        let h0 = m.range();
        let dr = m.reach(Control::Displacement, REL).unwrap();
        let lr = m.reach(Control::Load, REL).unwrap();
        assert!(dr <= -h0 && lr <= -h0 && dr.is_finite() && lr.is_finite());
        // A fresh contact feels the cohesive zone just inside −h₀.
        let f = m
            .eval(-h0 * (1.0 - 1e-6), &ContactState::default())
            .unwrap()
            .0
            .force;
        assert!(f < 0.0, "λ = {lam}: no force inside the cohesive range");
        if lr > -h0 * (1.0 + 1e-12) {
            continue;
        }
        let lp = m.load_pull_off_point();
        if lp.delta_bar * m.length_scale() < -h0 {
            let pc = m.pull_off_force(Control::Load).unwrap();
            let st = ContactState {
                in_contact: 1,
                branch: 1,
                ..Default::default()
            };
            let f = m.eval(lr, &st).unwrap().0.force;
            assert!(((f - pc) / pc).abs() < 1e-6, "λ = {lam}: {f:e} vs {pc:e}");
        }
    }
}

#[test]
fn derjaguin_tails_meet_the_bound() {
    let z = 3e-10;
    for rel in [1e-8, 1e-4, 0.1, 0.5, 0.99] {
        for (law, name) in [
            (
                SurfaceLaw::LennardJones {
                    work_of_adhesion: W,
                    equilibrium_separation: z,
                },
                "lj",
            ),
            (
                SurfaceLaw::Exponential {
                    work_of_adhesion: W,
                    decay_length: z,
                },
                "exp",
            ),
        ] {
            let d = Derjaguin::new(R, law).unwrap();
            let pc = d.pull_off_force(Control::Load).unwrap().abs();
            let r = d.reach(Control::Displacement, rel).unwrap();
            assert_eq!(r, d.reach(Control::Load, rel).unwrap());
            let f = |x: f64| d.eval(x, &ContactState::default()).unwrap().0.force.abs();
            // Below: under the bound; a little above: over it (the bound is
            // tight, not merely safe).
            assert!(f(next_down(r)) < rel * pc, "{name} rel {rel}");
            assert!(
                f(r + 1e-6 * z) > rel * pc * (1.0 - 1e-9),
                "{name} rel {rel}: not tight"
            );
        }
    }
}

/// Tables of Maugis–Dugdale (finite reach) and of the Lennard-Jones sphere
/// (far tail), with one and with two branches.
#[test]
fn tables_have_no_force_below_their_reach() {
    for lam in [0.3, 2.0] {
        let m = MaugisDugdale::from_maugis_parameter(R, E, W, lam).unwrap();
        let t = TabulatedLaw::from_maugis_dugdale(&m, 1e-4).unwrap();
        check_case(&Case {
            name: format!("md table λ = {lam}"),
            law: &t,
            delta_max: 1e-7,
            tail: false,
            adhesive: true,
        });
        // The table's reach is the law's to its tolerance.
        for c in [Control::Load, Control::Displacement] {
            let (a, b) = (t.reach(c, REL).unwrap(), m.reach(c, REL).unwrap());
            assert!(
                ((a - b) / m.length_scale()).abs() < 1e-3,
                "λ = {lam} {c:?}: table {a:e}, law {b:e}"
            );
        }
    }
    for (mu, n) in [(0.5, 48), (3.0, 64)] {
        let lj = LjSphere::from_tabor(mu).unwrap();
        let t = TabulatedLaw::from_lj_sphere(&lj, n, 1e-3).unwrap();
        check_case(&Case {
            name: format!("lj table μ = {mu}"),
            law: &t,
            delta_max: 5.0 * t.length_scale(),
            tail: true,
            adhesive: true,
        });
        // A looser bound reaches less far.
        let far = t.reach(Control::Displacement, 1e-6).unwrap();
        let near = t.reach(Control::Displacement, 1e-2).unwrap();
        eprintln!(
            "LJ table μ = {mu}: {} branches, reach (rel 1e-6) {far:.4}, (rel 1e-2) {near:.4}, \
             load {:.4} (approach unit {:.4})",
            t.branch_count(),
            t.reach(Control::Load, 1e-6).unwrap(),
            t.length_scale()
        );
        assert!(far < near, "μ = {mu}: {far} !< {near}");
    }
}

#[test]
fn reach_sweeps_stay_finite() {
    for w in [1e-3, 1e-1, 10.0] {
        for r in [1e-8, 1e-5, 1e-2] {
            for e in [1e7, 1e10, 1e12] {
                let laws: Vec<NormalLaw> = vec![
                    Jkr::new(r, e, w).unwrap().into(),
                    Kendall::new(r, e, w).unwrap().into(),
                    JkrPowerPunch::new(0.5 / r, 2.0, e, w).unwrap().into(),
                    Dmt::new(r, e, w).unwrap().into(),
                ];
                let mut laws = laws;
                for lam in [0.05, 1.0, 20.0] {
                    if let Ok(m) = MaugisDugdale::from_maugis_parameter(r, e, w, lam) {
                        laws.push(m.into());
                    }
                }
                for l in &laws {
                    for c in [Control::Load, Control::Displacement] {
                        let d = l.reach(c, REL).unwrap();
                        assert!(d.is_finite() && d <= 0.0, "{l:?} {c:?}: {d}");
                    }
                }
            }
        }
    }
}

#[test]
fn rel_force_is_checked() {
    let l: NormalLaw = Jkr::new(R, E, W).unwrap().into();
    for bad in [0.0, 1.0, -0.5, 2.0, f64::NAN, f64::INFINITY] {
        let e = l.reach(Control::Load, bad).unwrap_err();
        assert!(e.to_string().contains("`rel_force`"), "{e}");
        assert!(e.to_string().contains("(0, 1)"), "{e}");
    }
}

#[test]
fn c_abi_reach() {
    let mut law = std::mem::MaybeUninit::<AsperityNormalLaw>::zeroed();
    assert_eq!(
        unsafe { asperity_law_jkr(R, E, W, law.as_mut_ptr()) },
        ASPERITY_OK
    );
    let law = unsafe { law.assume_init() };
    let j = Jkr::new(R, E, W).unwrap();
    let mut d = 1.0;
    for (c, control) in [
        (ASPERITY_CONTROL_LOAD, Control::Load),
        (ASPERITY_CONTROL_DISPLACEMENT, Control::Displacement),
    ] {
        let s = unsafe { asperity_normal_reach(&law, c, REL, &mut d) };
        assert_eq!(s, ASPERITY_OK);
        assert_eq!(d, j.reach(control, REL).unwrap());
    }
    let s = unsafe { asperity_normal_reach(null(), ASPERITY_CONTROL_LOAD, REL, &mut d) };
    expect_error(s, ASPERITY_ERR_NULL_POINTER, "`law`");
    let s = unsafe { asperity_normal_reach(&law, ASPERITY_CONTROL_LOAD, REL, null_mut()) };
    expect_error(s, ASPERITY_ERR_NULL_POINTER, "`delta`");
    let s = unsafe { asperity_normal_reach(&law, 7, REL, &mut d) };
    expect_error(s, ASPERITY_ERR_INVALID_ARGUMENT, "`control`");
    let s = unsafe { asperity_normal_reach(&law, ASPERITY_CONTROL_LOAD, 1.5, &mut d) };
    expect_error(s, ASPERITY_ERR_INVALID_ARGUMENT, "`rel_force`");

    let mut table = null_mut();
    let s = unsafe { asperity_table_new_maugis_dugdale(R, E, W, 3e7, 1e-4, &mut table) };
    assert_eq!(s, ASPERITY_OK);
    for c in [ASPERITY_CONTROL_LOAD, ASPERITY_CONTROL_DISPLACEMENT] {
        let s = unsafe { asperity_table_reach(table, c, REL, &mut d) };
        assert_eq!(s, ASPERITY_OK);
        assert!(d.is_finite() && d < 0.0);
    }
    let s = unsafe { asperity_table_reach(null(), ASPERITY_CONTROL_LOAD, REL, &mut d) };
    expect_error(s, ASPERITY_ERR_NULL_POINTER, "`table`");
    let s = unsafe { asperity_table_reach(table, ASPERITY_CONTROL_LOAD, REL, null_mut()) };
    expect_error(s, ASPERITY_ERR_NULL_POINTER, "`delta`");
    let s = unsafe { asperity_table_reach(table, -3, REL, &mut d) };
    expect_error(s, ASPERITY_ERR_INVALID_ARGUMENT, "`control`");
    let s = unsafe { asperity_table_reach(table, ASPERITY_CONTROL_LOAD, f64::NAN, &mut d) };
    expect_error(s, ASPERITY_ERR_INVALID_ARGUMENT, "`rel_force`");
    unsafe { asperity_table_free(table) };
}
