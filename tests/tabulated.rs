//! Tabulated laws (src/contact/tabulated.rs, src/contact/curve.rs,
//! src/ffi/tabulated.rs) against the closed-form Maugis–Dugdale law:
//! accuracy on dense sweeps both ways, identical hysteresis, exact pull-off,
//! monotonicity, continuity, extremes, serde, corrupted input, threads, the
//! C ABI.

use asperity::contact::curve::EquilibriumCurve;
use asperity::contact::tabulated::DEFAULT_TOLERANCE;
use asperity::contact::{
    eval_batch, ContactState, Control, MaugisDugdale, NormalContact, TabulatedLaw,
};

const R: f64 = 1e-6;
const E_STAR: f64 = 1e9;
const W: f64 = 0.05;

fn md(lam: f64) -> MaugisDugdale {
    MaugisDugdale::from_maugis_parameter(R, E_STAR, W, lam).unwrap()
}

/// Overlaps (m) of a sweep from far to deep for `m`: dense through the
/// adhesive region, then log-spaced into the Hertz regime.
fn sweep(m: &MaugisDugdale, n: usize) -> Vec<f64> {
    let ds = m.length_scale();
    let lam = m.lambda();
    let jo = m.jump_out_point().delta_bar;
    let lo = jo - 0.2 * (jo.abs() + 1.0);
    let hi = 20.0;
    let mut v: Vec<f64> = (0..n)
        .map(|i| (lo + (hi - lo) * i as f64 / (n - 1) as f64) * ds)
        .collect();
    for i in 1..=60 {
        v.push(hi * 10f64.powf(i as f64 / 6.0) * ds);
    }
    // The exact jump points.
    let _ = lam;
    v.push(-m.range());
    v.push(m.jump_out_point().delta_bar * ds);
    v.sort_by(f64::total_cmp);
    v
}

/// Table and MD along the same sweep, approach then retraction.
fn compare(lam: f64, n: usize) {
    let m = md(lam);
    let t = TabulatedLaw::from_maugis_dugdale(&m, DEFAULT_TOLERANCE).unwrap();
    let mut d = sweep(&m, n);
    let mut worst = (0.0f64, 0.0f64);
    for pass in 0..2 {
        let (mut sm, mut st) = (ContactState::default(), ContactState::default());
        for &delta in &d {
            let (rm, nm) = m.eval(delta, &sm).unwrap();
            let (rt, nt) = t.eval(delta, &st).unwrap();
            assert_eq!(nm.branch, nt.branch, "λ = {lam}, δ = {delta:e}: branch");
            assert_eq!(
                nm.in_contact, nt.in_contact,
                "λ = {lam}, δ = {delta:e}: state in_contact"
            );
            assert_eq!(
                rm.in_contact, rt.in_contact,
                "λ = {lam}, δ = {delta:e}: in_contact {rm:?} {rt:?}"
            );
            let e = t.relative_error(&rm, &rt);
            if e > worst.0 {
                worst = (e, delta / m.length_scale());
            }
            assert!(
                e <= t.tolerance(),
                "λ = {lam}, pass {pass}, Δ̄ = {}: error {e:e}\n{rm:?}\n{rt:?}",
                delta / m.length_scale()
            );
            sm = nm;
            st = nt;
        }
        d.reverse();
    }
    println!(
        "λ = {lam}: worst {:e} at Δ̄ = {}; knots {}",
        worst.0,
        worst.1,
        t.knot_count()
    );
}

#[test]
fn dense_sweeps_match_maugis_dugdale() {
    for lam in LAMBDAS {
        compare(lam, 20000);
    }
}

const LAMBDAS: [f64; 7] = [0.01, 0.1, 0.5, 1.0, 2.0, 5.0, 100.0];

fn table(lam: f64) -> (MaugisDugdale, TabulatedLaw) {
    let m = md(lam);
    let t = TabulatedLaw::from_maugis_dugdale(&m, DEFAULT_TOLERANCE).unwrap();
    (m, t)
}

#[test]
fn stated_accuracy_and_size() {
    for lam in LAMBDAS {
        let (_, t) = table(lam);
        assert_eq!(t.tolerance(), DEFAULT_TOLERANCE);
        assert!(t.measured_error() > 0.0 && t.measured_error() <= t.tolerance());
        assert!(t.source().contains("Maugis-Dugdale"));
        println!(
            "λ = {lam}: {} branches, {} knots, {} index entries, {} bytes, {} bytes of JSON, measured {:.2e}",
            t.branch_count(),
            t.knot_count(),
            t.index_len(),
            t.memory_bytes(),
            t.to_json().len(),
            t.measured_error()
        );
    }
    // A looser tolerance gives a smaller table, a tighter one a larger one.
    let m = md(1.0);
    let loose = TabulatedLaw::from_maugis_dugdale(&m, 1e-2).unwrap();
    let tight = TabulatedLaw::from_maugis_dugdale(&m, 1e-7).unwrap();
    let normal = TabulatedLaw::from_maugis_dugdale(&m, 1e-4).unwrap();
    assert!(loose.knot_count() <= normal.knot_count());
    assert!(tight.knot_count() > normal.knot_count());
    for (t, tol) in [(&loose, 1e-2), (&tight, 1e-7)] {
        let mut st = ContactState::default();
        let mut sm = ContactState::default();
        for d in sweep(&m, 3000) {
            let (rt, nt) = t.eval(d, &st).unwrap();
            let (rm, nm) = m.eval(d, &sm).unwrap();
            assert!(t.relative_error(&rm, &rt) <= tol, "tol {tol}: δ = {d:e}");
            st = nt;
            sm = nm;
        }
    }
    // Bad tolerances.
    for tol in [0.0, -1e-4, f64::NAN, 0.5] {
        assert!(TabulatedLaw::from_maugis_dugdale(&m, tol).is_err(), "{tol}");
    }
}

#[test]
fn jump_points_are_the_exact_turning_points() {
    for lam in LAMBDAS {
        let (m, t) = table(lam);
        let ds = m.length_scale();
        assert_eq!(t.branch_count(), 2);
        // Jump-in at δ = −h₀ (exactly, the same comparison as MD).
        let (_, hi0) = t.branch_range(0).unwrap();
        assert!((hi0 + m.range()).abs() <= 1e-14 * m.range(), "λ = {lam}");
        // Jump-out at the minimum of Δ̄ along the path.
        let (lo1, _) = t.branch_range(1).unwrap();
        let jo = m.jump_out_point().delta_bar * ds;
        assert!(
            (lo1 - jo).abs() <= 1e-12 * ds,
            "λ = {lam}: {lo1:e} vs {jo:e}"
        );
        // Around both thresholds, branch and contact agree with MD.
        let eps = 1e-9 * ds;
        for (d, from) in [
            (-m.range() - eps, 0),
            (-m.range() + eps, 0),
            (-m.range(), 0),
            (jo + eps, 1),
            (jo - eps, 1),
        ] {
            let old = ContactState {
                branch: from,
                in_contact: from,
                ..Default::default()
            };
            let (rm, nm) = m.eval(d, &old).unwrap();
            let (rt, nt) = t.eval(d, &old).unwrap();
            assert_eq!(nm.branch, nt.branch, "λ = {lam}, δ = {d:e}");
            assert_eq!(rm.in_contact, rt.in_contact, "λ = {lam}, δ = {d:e}");
        }
        // Hysteresis: inside the loop the force depends on the history.
        let mid = 0.5 * (jo - m.range());
        let (r0, _) = t.eval(mid, &ContactState::default()).unwrap();
        let on = ContactState {
            branch: 1,
            in_contact: 1,
            ..Default::default()
        };
        let (r1, _) = t.eval(mid, &on).unwrap();
        assert_eq!(r0.force, 0.0);
        assert!(r1.force < 0.0);
    }
}

#[test]
fn pull_off_forces_are_exact() {
    for lam in LAMBDAS {
        let (m, t) = table(lam);
        for c in [Control::Load, Control::Displacement] {
            let (pm, pt) = (m.pull_off_force(c).unwrap(), t.pull_off_force(c).unwrap());
            assert!(
                (pm - pt).abs() <= 1e-10 * pm.abs(),
                "λ = {lam}, {c:?}: {pt} vs {pm}"
            );
        }
        assert_eq!(t.length_scale(), m.length_scale());
        // Load control: below the pull-off is an error; above it, the
        // equilibrium agrees with MD and with eval at the returned overlap.
        let pc = t.pull_off_force(Control::Load).unwrap();
        assert!(t.eval_at_load(pc * 1.001).is_err());
        for f in [pc, 0.5 * pc, 0.0, -pc, -10.0 * pc, -1e6 * pc] {
            let rt = t.eval_at_load(f).unwrap();
            let rm = m.eval_at_load(f).unwrap();
            assert_eq!(rt.force, f);
            assert!(
                t.relative_error(&rm, &rt) <= t.tolerance(),
                "λ = {lam}, P = {f:e}"
            );
            let on = ContactState {
                branch: 1,
                in_contact: 1,
                ..Default::default()
            };
            let (back, _) = t.eval(rt.delta, &on).unwrap();
            assert!(
                (back.force - f).abs() <= 1e-9 * f.abs().max(pc.abs()),
                "λ = {lam}, P = {f:e}: {back:?}"
            );
        }
    }
}

#[test]
fn stable_branch_is_monotone_and_continuous() {
    for lam in LAMBDAS {
        let (m, t) = table(lam);
        let ds = m.length_scale();
        let (lo, _) = t.branch_range(1).unwrap();
        let on = ContactState {
            branch: 1,
            in_contact: 1,
            ..Default::default()
        };
        let pc = t.pull_off_force(Control::Load).unwrap();
        let d_pc = t.eval_at_load(pc).unwrap().delta;
        let n = 20000;
        let hi = 30.0 * ds;
        let mut prev: Option<(f64, f64, f64, f64)> = None;
        for i in 0..=n {
            // (δ = lo itself may round to either side of the reduced threshold.)
            let d = lo + (hi - lo) * (i as f64 + 1e-3) / n as f64;
            let (r, s) = t.eval(d, &on).unwrap();
            assert_eq!(s.branch, 1);
            assert!(r.force.is_finite() && r.stiffness.is_finite());
            if let Some((d0, f0, a0, k0)) = prev {
                // Decreasing down to the load-controlled pull-off, then
                // increasing; the radius never decreases.
                if d <= d_pc {
                    assert!(r.force <= f0, "λ = {lam}: not decreasing at δ = {d:e}");
                } else if d0 >= d_pc {
                    assert!(r.force >= f0, "λ = {lam}: not increasing at δ = {d:e}");
                }
                assert!(r.contact_radius >= a0, "λ = {lam}: radius at δ = {d:e}");
                // Continuity: the change over a step is bounded by the
                // stiffness the step can see.
                let jump = (r.force - f0).abs();
                let slope = r.stiffness.abs().max(k0.abs()).min(1e3 * pc.abs() / ds);
                assert!(
                    jump <= 2.0 * slope * (d - d0) + 1e-9 * pc.abs(),
                    "λ = {lam}: jump {jump:e} at δ = {d:e}"
                );
            }
            prev = Some((d, r.force, r.contact_radius, r.stiffness));
        }
    }
}

/// The stiffness a call returns is the derivative of the force it returns:
/// against one-sided differences of the table's own force, inside the knots,
/// at the load-controlled pull-off (a segment start where F − F_c ∝ u², the
/// finite-limit case) and beside the branch's start.
#[test]
fn stiffness_is_the_derivative_of_the_force() {
    for lam in LAMBDAS {
        let (m, t) = table(lam);
        let ds = m.length_scale();
        let on = ContactState {
            branch: 1,
            in_contact: 1,
            ..Default::default()
        };
        let (lo1, _) = t.branch_range(1).unwrap();
        let pc = t.pull_off_force(Control::Load).unwrap();
        let d_pc = t.eval_at_load(pc).unwrap().delta;
        let force = |d: f64| t.eval(d, &on).unwrap().0.force;
        let mut points: Vec<f64> = (1..400)
            .map(|i| lo1 + (30.0 * ds - lo1) * (i as f64 / 400.0).powi(2))
            .collect();
        // The load-controlled pull-off, and beside the branch's start (the
        // jump-out turning point, where dF/dδ → −∞; at small λ the point
        // where the radius reaches zero). δ = lo1 itself may round to
        // either side of the reduced threshold.
        points.extend([d_pc, lo1 + 1e-6 * ds, lo1 + 1e-4 * ds]);
        for d in points {
            let (r, _) = t.eval(d, &on).unwrap();
            // Step small against the distance to the turning point lo1,
            // where the force has a square-root singularity.
            let h = 1e-5 * (d - lo1).min(ds);
            // One-sided, second order: F'(δ) ≈ (4F(δ+h) − F(δ+2h) − 3F(δ))/(2h).
            let fd = (4.0 * force(d + h) - force(d + 2.0 * h) - 3.0 * r.force) / (2.0 * h);
            assert!(
                (r.stiffness - fd).abs() <= 1e-3 * r.stiffness.abs() + 1e-6 * pc.abs() / ds,
                "λ = {lam}, Δ̄ = {}: stiffness {:e} against {fd:e}",
                d / ds,
                r.stiffness
            );
        }
    }
}

#[test]
fn far_and_deep_extremes() {
    for lam in LAMBDAS {
        let (m, t) = table(lam);
        let ds = m.length_scale();
        // Far: exactly zero below −h₀ when fresh, below the jump-out point
        // when coming from contact.
        let jo = m.jump_out_point().delta_bar * ds;
        let from_contact = t.eval(ds, &ContactState::default()).unwrap().1;
        for (d, old) in [
            (-m.range() * (1.0 + 1e-12), ContactState::default()),
            (-m.range() - ds, ContactState::default()),
            (-1e300, ContactState::default()),
            (jo - 1e-9 * ds, from_contact),
            (jo - ds, from_contact),
            (-1e300, from_contact),
        ] {
            let (r, s) = t.eval(d, &old).unwrap();
            assert_eq!(
                (r.force, r.contact_radius, r.stiffness, r.in_contact),
                (0.0, 0.0, 0.0, 0),
                "λ = {lam}, δ = {d:e}"
            );
            assert_eq!(s, ContactState::default());
        }
        // Deep: finite, Hertz-like, and equal to MD where MD converges.
        let hertz = |d: f64| 4.0 / 3.0 * E_STAR * R.sqrt() * d.powf(1.5);
        for k in [1e2, 1e4, 1e6, 1e8, 1e10] {
            let d = k * ds;
            let (rt, _) = t.eval(d, &ContactState::default()).unwrap();
            let (rm, _) = m.eval(d, &ContactState::default()).unwrap();
            assert!(rt.force.is_finite() && rt.stiffness > 0.0);
            assert!(
                t.relative_error(&rm, &rt) <= t.tolerance(),
                "λ = {lam}, Δ̄ = {k:e}"
            );
            if k >= 1e6 {
                assert!((rt.force / hertz(d) - 1.0).abs() < 0.01);
            }
        }
        // Overflow is an error, not an infinity.
        assert!(t.eval(1e300, &ContactState::default()).is_err());
        assert!(t.eval(f64::NAN, &ContactState::default()).is_err());
        assert!(t.eval(f64::INFINITY, &ContactState::default()).is_err());
        let bad = ContactState {
            branch: 2,
            ..Default::default()
        };
        assert!(t.eval(0.0, &bad).is_err());
        let bad = ContactState {
            branch: -1,
            ..Default::default()
        };
        assert!(t.eval(0.0, &bad).is_err());
    }
}

#[test]
fn serde_round_trip_is_bit_identical() {
    for lam in [0.1, 2.0] {
        let (m, t) = table(lam);
        let json = t.to_json();
        let back = TabulatedLaw::from_json(&json).unwrap();
        assert_eq!(back.to_json(), json);
        let via_serde: TabulatedLaw =
            serde_json::from_str(&serde_json::to_string(&t).unwrap()).unwrap();
        for u in [&back, &via_serde] {
            let (mut s1, mut s2) = (ContactState::default(), ContactState::default());
            let mut d = sweep(&m, 2000);
            let r: Vec<f64> = d.iter().rev().copied().collect();
            d.extend(r);
            for &x in &d {
                let (r1, n1) = t.eval(x, &s1).unwrap();
                let (r2, n2) = u.eval(x, &s2).unwrap();
                assert_eq!(r1.force.to_bits(), r2.force.to_bits());
                assert_eq!(r1.contact_radius.to_bits(), r2.contact_radius.to_bits());
                assert_eq!(r1.stiffness.to_bits(), r2.stiffness.to_bits());
                assert_eq!(n1, n2);
                s1 = n1;
                s2 = n2;
            }
            assert_eq!(u.tolerance(), t.tolerance());
            assert_eq!(u.measured_error(), t.measured_error());
            assert_eq!(
                u.pull_off_force(Control::Load).unwrap(),
                t.pull_off_force(Control::Load).unwrap()
            );
        }
        // The curve round-trips too, and rebuilds the same table.
        let c = EquilibriumCurve::from_maugis_dugdale(&m, DEFAULT_TOLERANCE).unwrap();
        let c2 = EquilibriumCurve::from_json(&c.to_json()).unwrap();
        assert_eq!(c, c2);
        assert_eq!(
            TabulatedLaw::from_curve(&c2, DEFAULT_TOLERANCE)
                .unwrap()
                .to_json(),
            json
        );
    }
}

#[test]
fn corrupted_tables_are_errors() {
    let (_, t) = table(2.0);
    let json = t.to_json();
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    let edit = |f: &dyn Fn(&mut serde_json::Value)| {
        let mut w = v.clone();
        f(&mut w);
        serde_json::to_string(&w).unwrap()
    };
    let seg = |w: &mut serde_json::Value| -> serde_json::Value {
        w["branches"][1]["segments"][0].clone()
    };
    let _ = seg;
    let cases: Vec<(&str, String)> = vec![
        ("truncated", json[..json.len() / 2].to_string()),
        ("empty", String::new()),
        ("not json", "hello".to_string()),
        (
            "wrong format",
            json.replacen("asperity-tabulated-law-1", "asperity-tabulated-law-9", 1),
        ),
        (
            "wrong length",
            edit(&|w| {
                w["branches"][1]["segments"][0]["force"]
                    .as_array_mut()
                    .unwrap()
                    .pop();
            }),
        ),
        (
            "NaN",
            edit(&|w| w["branches"][1]["segments"][0]["force"][1] = "NaN".into()),
        ),
        (
            "inf",
            edit(&|w| w["branches"][1]["segments"][0]["d_force"][1] = "inf".into()),
        ),
        (
            "number instead of string",
            edit(&|w| w["force_scale"] = 1.0.into()),
        ),
        ("not a number", edit(&|w| w["force_scale"] = "abc".into())),
        (
            "negative scale",
            edit(&|w| w["force_scale"] = "-1e-7".into()),
        ),
        (
            "non-monotone knots",
            edit(&|w| {
                let u = w["branches"][1]["segments"][0]["u"].as_array_mut().unwrap();
                u.swap(2, 3);
            }),
        ),
        (
            "non-monotone force",
            edit(&|w| {
                let f = w["branches"][1]["segments"][0]["force"]
                    .as_array_mut()
                    .unwrap();
                let x = 0.0;
                let n = f.len();
                f.swap(n - 2, n - 1);
                let _ = x;
            }),
        ),
        (
            "missing field",
            edit(&|w| {
                w.as_object_mut().unwrap().remove("deep");
            }),
        ),
        (
            "no branches",
            edit(&|w| w["branches"] = serde_json::Value::Array(vec![])),
        ),
        (
            "bounded far branch",
            edit(&|w| w["branches"][0]["lo"] = "-1e0".into()),
        ),
        ("tolerance", edit(&|w| w["tolerance"] = "2e0".into())),
        (
            "measured above tolerance",
            edit(&|w| w["measured_error"] = "1e-3".into()),
        ),
        (
            "pull-off off its knot",
            edit(&|w| w["load_pull_off"] = "-1e0".into()),
        ),
        (
            "segment range",
            edit(&|w| w["branches"][1]["segments"][0]["hi"] = "1e300".into()),
        ),
        ("origin", edit(&|w| w["approach_origin"] = "inf".into())),
    ];
    for (what, text) in cases {
        match TabulatedLaw::from_json(&text) {
            Err(e) => println!("{what}: {e}"),
            Ok(_) => panic!("{what}: a corrupted table was accepted"),
        }
    }
    // The untouched text still loads.
    assert!(TabulatedLaw::from_json(&edit(&|_| {})).is_ok());
    // Extreme but valid units and origins (the overlap thresholds and
    // references overflow to ±∞): every call is a response or an error,
    // never a panic.
    for (scale, origin) in [
        ("1e300", "0e0"),
        ("1e307", "0e0"),
        ("1e-300", "0e0"),
        ("1e0", "1.7e308"),
    ] {
        let text = edit(&|w| {
            w["approach_scale"] = scale.into();
            w["approach_origin"] = origin.into();
        });
        let u = TabulatedLaw::from_json(&text).unwrap();
        for delta in [
            -f64::MAX,
            -1e300,
            -1.0,
            -1e-300,
            0.0,
            1e-9,
            1.0,
            1e300,
            f64::MAX,
        ] {
            for branch in [0, 1] {
                let old = ContactState {
                    branch,
                    in_contact: branch,
                    ..Default::default()
                };
                if let Ok((r, _)) = u.eval(delta, &old) {
                    assert!(r.force.is_finite() && r.stiffness.is_finite());
                }
            }
        }
    }
    // A curve with an unresolved turning point is refused.
    let m = md(2.0);
    let mut c = EquilibriumCurve::from_maugis_dugdale(&m, DEFAULT_TOLERANCE).unwrap();
    let i = (0..c.points.len())
        .min_by(|&a, &b| c.points[a].delta.total_cmp(&c.points[b].delta))
        .unwrap();
    assert_eq!(c.points[i].d_delta, 0.0);
    c.points.remove(i);
    assert!(TabulatedLaw::from_curve(&c, DEFAULT_TOLERANCE).is_err());
    assert!(EquilibriumCurve::from_json("{}").is_err());
}

#[test]
fn shareable_between_threads() {
    fn assert_send_sync<T: Send + Sync + 'static>() {}
    assert_send_sync::<TabulatedLaw>();
    assert_send_sync::<EquilibriumCurve>();
    let (m, t) = table(5.0);
    let ds = m.length_scale();
    fn run(
        t: &TabulatedLaw,
        ds: f64,
        pairs: std::ops::Range<usize>,
    ) -> Vec<(u64, u64, ContactState)> {
        let mut out = Vec::new();
        for i in pairs {
            let mut st = ContactState::default();
            for s in 0..400 {
                let d = (1.0 + 3.0 * (s as f64 * 0.11 + i as f64 * 0.37).sin()) * ds;
                let (r, n) = t.eval(d, &st).unwrap();
                out.push((r.force.to_bits(), r.contact_radius.to_bits(), n));
                st = n;
            }
        }
        out
    }
    let serial = run(&t, ds, 0..64);
    let shared = std::sync::Arc::new(t);
    let handles: Vec<_> = (0..8)
        .map(|k| {
            let t = shared.clone();
            std::thread::spawn(move || run(&t, ds, k * 8..(k + 1) * 8))
        })
        .collect();
    let threaded: Vec<_> = handles
        .into_iter()
        .flat_map(|h| h.join().unwrap())
        .collect();
    assert_eq!(serial, threaded);
}

#[test]
fn batch_equals_scalar() {
    let (m, t) = table(1.0);
    let d: Vec<f64> = sweep(&m, 500);
    let n = d.len();
    let old: Vec<ContactState> = (0..n)
        .map(|i| ContactState {
            branch: (i % 2) as i32,
            in_contact: (i % 2) as i32,
            ..Default::default()
        })
        .collect();
    let mut new = vec![ContactState::default(); n];
    let (mut f, mut a, mut k) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    eval_batch(
        &t,
        &d,
        Some(&old),
        Some(&mut new),
        &mut f,
        Some(&mut a),
        Some(&mut k),
    )
    .unwrap();
    for i in 0..n {
        let (r, s) = t.eval(d[i], &old[i]).unwrap();
        assert_eq!(
            (
                r.force.to_bits(),
                r.contact_radius.to_bits(),
                r.stiffness.to_bits(),
                s
            ),
            (f[i].to_bits(), a[i].to_bits(), k[i].to_bits(), new[i])
        );
    }
    // An error names its element.
    let mut bad = d.clone();
    bad[7] = f64::NAN;
    let e = eval_batch(&t, &bad, None, None, &mut f, None, None).unwrap_err();
    assert_eq!(e.index, 7);
}

#[test]
fn c_abi_handles_null_and_errors() {
    use asperity::contact::NormalResponse;
    use asperity::ffi::tabulated::*;
    use asperity::ffi::{
        asperity_last_error_message, ASPERITY_ERR_INVALID_ARGUMENT, ASPERITY_ERR_NULL_POINTER,
        ASPERITY_OK,
    };
    use std::ptr::{null, null_mut};
    let msg = || {
        let mut buf = vec![0u8; 512];
        let n = unsafe { asperity_last_error_message(buf.as_mut_ptr().cast(), buf.len()) };
        String::from_utf8_lossy(&buf[..n.min(511)]).into_owned()
    };
    let m = md(2.0);
    unsafe {
        let mut t: *mut AsperityTable = null_mut();
        assert_eq!(
            asperity_table_new_maugis_dugdale(
                R,
                E_STAR,
                W,
                m.params().cohesive_stress,
                1e-4,
                null_mut()
            ),
            ASPERITY_ERR_NULL_POINTER
        );
        assert!(msg().contains("out"));
        assert_eq!(
            asperity_table_new_maugis_dugdale(
                -R,
                E_STAR,
                W,
                m.params().cohesive_stress,
                1e-4,
                &mut t
            ),
            ASPERITY_ERR_INVALID_ARGUMENT
        );
        assert!(t.is_null() && msg().contains("radius"), "{}", msg());
        assert_eq!(
            asperity_table_new_maugis_dugdale(
                R,
                E_STAR,
                W,
                m.params().cohesive_stress,
                0.0,
                &mut t
            ),
            ASPERITY_ERR_INVALID_ARGUMENT
        );
        assert!(msg().contains("tolerance"));
        assert_eq!(
            asperity_table_new_maugis_dugdale(
                R,
                E_STAR,
                W,
                m.params().cohesive_stress,
                1e-4,
                &mut t
            ),
            ASPERITY_OK
        );
        assert!(!t.is_null());
        let mut r = NormalResponse::default();
        let mut s = ContactState::default();
        assert_eq!(
            asperity_table_eval(null(), 0.0, null(), null_mut(), &mut r),
            ASPERITY_ERR_NULL_POINTER
        );
        assert!(msg().contains("table"));
        assert_eq!(
            asperity_table_eval(t, 0.0, null(), null_mut(), null_mut()),
            ASPERITY_ERR_NULL_POINTER
        );
        assert_eq!(
            asperity_table_eval(t, f64::NAN, null(), &mut s, &mut r),
            ASPERITY_ERR_INVALID_ARGUMENT
        );
        assert!(msg().contains("delta"));
        assert_eq!(
            asperity_table_eval(t, m.length_scale(), null(), &mut s, &mut r),
            ASPERITY_OK
        );
        let (rr, ss) = m.eval(m.length_scale(), &ContactState::default()).unwrap();
        assert_eq!(s.branch, ss.branch);
        assert!((r.force - rr.force).abs() <= 1e-4 * rr.force.abs().max(1e-9));
        // Batch: NULL arrays, an error index.
        let d = [m.length_scale(), f64::NAN];
        let mut f = [0.0; 2];
        assert_eq!(
            asperity_table_eval_batch(
                t,
                2,
                null(),
                null(),
                null_mut(),
                f.as_mut_ptr(),
                null_mut(),
                null_mut()
            ),
            ASPERITY_ERR_NULL_POINTER
        );
        assert_eq!(
            asperity_table_eval_batch(
                t,
                2,
                d.as_ptr(),
                null(),
                null_mut(),
                f.as_mut_ptr(),
                null_mut(),
                null_mut()
            ),
            ASPERITY_ERR_INVALID_ARGUMENT
        );
        assert!(msg().contains("element 1"), "{}", msg());
        // Aliased arrays (force over δ, states in place) give what separate
        // arrays give.
        let d: Vec<f64> = (0..9)
            .map(|i| m.length_scale() * (i as f64 - 4.0) / 2.0)
            .collect();
        let n = d.len();
        let mut f_sep = vec![0.0; n];
        let mut s_sep = vec![ContactState::default(); n];
        let zero = vec![ContactState::default(); n];
        assert_eq!(
            asperity_table_eval_batch(
                t,
                n,
                d.as_ptr(),
                zero.as_ptr(),
                s_sep.as_mut_ptr(),
                f_sep.as_mut_ptr(),
                null_mut(),
                null_mut()
            ),
            ASPERITY_OK
        );
        let mut buf = d.clone();
        let mut states = zero.clone();
        let (p, sp) = (buf.as_mut_ptr(), states.as_mut_ptr());
        assert_eq!(
            asperity_table_eval_batch(t, n, p, sp, sp, p, null_mut(), null_mut()),
            ASPERITY_OK
        );
        assert_eq!(buf, f_sep);
        assert_eq!(states, s_sep);
        assert_eq!(
            asperity_table_eval_batch(
                t,
                0,
                null(),
                null(),
                null_mut(),
                null_mut(),
                null_mut(),
                null_mut()
            ),
            ASPERITY_OK
        );
        // Pull-off, accuracy.
        let mut p = 0.0;
        assert_eq!(
            asperity_table_pull_off_force(t, 7, &mut p),
            ASPERITY_ERR_INVALID_ARGUMENT
        );
        assert_eq!(
            asperity_table_pull_off_force(t, 0, null_mut()),
            ASPERITY_ERR_NULL_POINTER
        );
        assert_eq!(asperity_table_pull_off_force(t, 0, &mut p), ASPERITY_OK);
        assert_eq!(p, m.pull_off_force(Control::Load).unwrap());
        let (mut e, mut me) = (0.0, 0.0);
        assert_eq!(asperity_table_max_error(t, &mut e, &mut me), ASPERITY_OK);
        assert_eq!(e, 1e-4);
        assert!(me > 0.0 && me <= e);
        assert_eq!(
            asperity_table_max_error(t, null_mut(), null_mut()),
            ASPERITY_ERR_NULL_POINTER
        );
        assert_eq!(asperity_table_eval_at_load(t, 2.0 * p, &mut r), -4);
        assert_eq!(asperity_table_eval_at_load(t, 0.0, &mut r), ASPERITY_OK);
        // JSON through C.
        let mut needed = 0usize;
        assert_eq!(
            asperity_table_to_json(t, null_mut(), 0, null_mut()),
            ASPERITY_ERR_NULL_POINTER
        );
        assert_eq!(
            asperity_table_to_json(t, null_mut(), 0, &mut needed),
            ASPERITY_OK
        );
        let mut buf = vec![0u8; needed + 1];
        let mut small = [0u8; 8];
        assert_eq!(
            asperity_table_to_json(t, small.as_mut_ptr().cast(), small.len(), &mut needed),
            ASPERITY_OK
        );
        assert_eq!(small[7], 0);
        assert_eq!(
            asperity_table_to_json(t, buf.as_mut_ptr().cast(), buf.len(), &mut needed),
            ASPERITY_OK
        );
        let mut t2: *mut AsperityTable = null_mut();
        assert_eq!(
            asperity_table_from_json(null(), 5, &mut t2),
            ASPERITY_ERR_NULL_POINTER
        );
        assert_eq!(
            asperity_table_from_json(buf.as_ptr().cast(), needed / 2, &mut t2),
            ASPERITY_ERR_INVALID_ARGUMENT
        );
        assert!(t2.is_null() && msg().contains("json"), "{}", msg());
        let invalid = [0xffu8, 0xfe];
        assert_eq!(
            asperity_table_from_json(invalid.as_ptr().cast(), 2, &mut t2),
            ASPERITY_ERR_INVALID_ARGUMENT
        );
        assert_eq!(
            asperity_table_from_json(buf.as_ptr().cast(), needed, &mut t2),
            ASPERITY_OK
        );
        let mut r2 = NormalResponse::default();
        asperity_table_eval(t, 0.3 * m.length_scale(), null(), null_mut(), &mut r);
        asperity_table_eval(t2, 0.3 * m.length_scale(), null(), null_mut(), &mut r2);
        assert_eq!(r, r2);
        asperity_table_free(t2);
        asperity_table_free(t);
        asperity_table_free(null_mut());
    }
}

/// Fuzzing regression (fuzz/regressions/c_abi/md_table_tolerance_below_range,
/// an out-of-memory of the `c_abi` target): the Maugis–Dugdale curve accepted
/// tolerances down to 1e-12 while the table takes [1e-10, 0.1], so
/// `asperity_table_new_maugis_dugdale` with 2.3e-12 sampled a curve of 10⁸
/// points (6 GB, 14 s) before rejecting the tolerance; at 1e-12 the
/// bisection did not end. Below 1e-10 the interpolation test meets f64
/// rounding. Now both reject such a tolerance before sampling (the error
/// names `tolerance`), and a curve is bounded by `MAX_CURVE_POINTS`.
#[test]
fn md_tolerances_below_the_table_range_are_rejected_before_sampling() {
    use asperity::contact::curve::MAX_CURVE_POINTS;
    use asperity::error::Error;
    use asperity::ffi::tabulated::*;
    use asperity::ffi::{asperity_last_error_message, ASPERITY_ERR_INVALID_ARGUMENT};
    // The fuzzer's input: λ ≈ 1383.
    let extreme = MaugisDugdale::new(2.6875e24, 26.98, 2e12, 1.0).unwrap();
    let tolerance_error = |r: asperity::Result<usize>| match r {
        Err(Error::InvalidArgument { name, .. }) => assert_eq!(name, "tolerance"),
        other => panic!("expected an error naming tolerance, got {other:?}"),
    };
    for m in [&extreme, &md(0.1), &md(10.0)] {
        for tol in [9.9e-11, 2.34375e-12, 1e-12] {
            tolerance_error(EquilibriumCurve::from_maugis_dugdale(m, tol).map(|c| c.points.len()));
            tolerance_error(TabulatedLaw::from_maugis_dugdale(m, tol).map(|_| 0));
        }
        // The finest tolerance accepted is reached well within the bound.
        let n = EquilibriumCurve::from_maugis_dugdale(m, 1e-10)
            .unwrap()
            .points
            .len();
        assert!(n > 1000 && n < MAX_CURVE_POINTS / 16, "{n} points");
    }
    let mut t: *mut AsperityTable = 1usize as *mut AsperityTable;
    let st = unsafe {
        asperity_table_new_maugis_dugdale(2.6875e24, 26.98, 2e12, 1.0, 2.34375e-12, &mut t)
    };
    let mut buf = vec![0u8; 512];
    let n = unsafe { asperity_last_error_message(buf.as_mut_ptr().cast(), buf.len()) };
    let msg = String::from_utf8_lossy(&buf[..n.min(511)]).into_owned();
    assert_eq!(st, ASPERITY_ERR_INVALID_ARGUMENT, "{msg}");
    assert!(t.is_null() && msg.contains("tolerance"), "{msg}");
}
