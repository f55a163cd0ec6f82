//! The homogenised friction law of FE integration points (issue 6 §4 (b)):
//! the monotone interpolation of the table, the regularised Coulomb
//! (Derjaguin) return mapping — stick, slip on the exact cone, force against
//! slip, dissipation F·Δs_p ≥ 0 split by the mechanisms' shares, tangents
//! against finite differences — zero load and no contact, 2-D direction
//! changes, bit-identical re-evaluation (old and new separate, in place,
//! blocks), named errors, the JSON round trip and no allocation per step,
//! through the one friction contract (`FrictionLaw`, flat states).
//!
//! Expected values are closed forms of the return mapping written out here,
//! never taken from the code.

mod common;
#[path = "common/tangents.rs"]
mod tangents;

use approx::assert_relative_eq;
use asperity::contact::BatchError;
use asperity::error::Error;
use asperity::friction::*;

// ------------------------------------------------- allocation counting

#[global_allocator]
static GLOBAL: common::counting::Counting = common::counting::Counting;

use common::counting::allocations;

// ------------------------------------------------------------- helpers

const MPA: f64 = 1e6;

fn shares(c: f64, v: f64, e: f64) -> Dissipation {
    Dissipation {
        chemical: c,
        van_der_waals: v,
        elastic: e,
        plastic: 1.0 - c - v - e,
    }
}

/// Copper-like: μ from 1.10 at 10 MPa down to 0.90 at 200 MPa, adhesion
/// about 9 % of the load, true contact p/H with H ≈ 1 GPa, chemical bonds
/// dominant.
fn copper_samples() -> Vec<HomogenisedSample> {
    let rows = [
        (10.0, 1.10, 0.90, 0.010, 0.930, 0.067, 0.002),
        (50.0, 1.02, 4.50, 0.050, 0.925, 0.066, 0.006),
        (100.0, 0.97, 9.00, 0.100, 0.920, 0.064, 0.010),
        (150.0, 0.93, 13.5, 0.150, 0.910, 0.062, 0.018),
        (200.0, 0.90, 18.0, 0.200, 0.900, 0.060, 0.025),
    ];
    rows.iter()
        .map(|&(p, mu, pa, fr, c, v, e)| HomogenisedSample {
            pressure: p * MPA,
            cof: mu,
            adhesion_pressure: pa * MPA,
            contact_fraction: fr,
            shares: shares(c, v, e),
        })
        .collect()
}

fn copper() -> HomogenisedFriction {
    HomogenisedFriction::from_samples(&copper_samples(), CofForm::Derjaguin).unwrap()
}

const AREA: f64 = 1e-6; // 1 mm² per point
const K: f64 = 1e8; // N/m

/// The copper table with the stick stiffness `k` (N/m).
fn law(k: f64) -> HomogenisedFriction {
    copper().with_stick_stiffness(k).unwrap()
}

fn inc(n: f64, sx: f64, sy: f64) -> FrictionIncrement {
    FrictionIncrement {
        normal_force: n,
        area: AREA,
        slip: [sx, sy],
        dt: 1e-6,
        ..Default::default()
    }
}

/// A point's state: `[D, S, F_x, F_y, plastic slip path, dissipation by
/// mechanism (4)]`.
type State = [f64; HomogenisedFriction::STATE_LEN];

const FORCE: usize = HomogenisedFriction::STATE_FORCE;
const PLASTIC: usize = HomogenisedFriction::STATE_PLASTIC_SLIP_PATH;
const MECHANISMS: usize = HomogenisedFriction::STATE_MECHANISMS;

/// A fresh point.
const FRESH: State = [0.0; HomogenisedFriction::STATE_LEN];

/// A fresh point carrying the stick force `f` (N).
fn with_force(f: [f64; 2]) -> State {
    let mut s = FRESH;
    s[FORCE] = f[0];
    s[FORCE + 1] = f[1];
    s
}

/// The stick force of a state (N).
fn force(s: &State) -> [f64; 2] {
    [s[FORCE], s[FORCE + 1]]
}

/// The dissipation by mechanism of a state (J).
fn dissipation(s: &State) -> Dissipation {
    let d = &s[MECHANISMS..];
    Dissipation {
        chemical: d[0],
        van_der_waals: d[1],
        elastic: d[2],
        plastic: d[3],
    }
}

fn step(h: &HomogenisedFriction, old: &State, i: &FrictionIncrement) -> (State, FrictionResponse) {
    let mut s = FRESH;
    let r = h.step(old, &mut s, i, &mut h.work()).unwrap();
    (s, r)
}

/// The plastic slip Δs_p of the step `i` from `old` (m): of the length Δλ
/// the state's plastic slip path grows by, against the force while
/// sliding, 0 otherwise. Δλ is read exactly from the same step from a
/// plastic path of 0 (the path is only booked: the step is otherwise the
/// same).
fn plastic_slip(h: &HomogenisedFriction, old: &State, i: &FrictionIncrement) -> [f64; 2] {
    let (new, r) = step(h, old, i);
    let mut probe = *old;
    probe[PLASTIC] = 0.0;
    let (p, rp) = step(h, &probe, i);
    assert_eq!(format!("{r:?}"), format!("{rp:?}"));
    let lam = p[PLASTIC];
    assert_eq!(new[PLASTIC], old[PLASTIC] + lam);
    let f = norm(r.force);
    if r.regime() == FrictionRegime::Slip && f > 0.0 {
        [-lam * r.force[0] / f, -lam * r.force[1] / f]
    } else {
        [0.0, 0.0]
    }
}

/// The slip limit of a response in the law's COF form (module
/// documentation): μ(N + A), μN or A + μN.
fn slip_limit(form: CofForm, r: &FrictionResponse) -> f64 {
    match form {
        CofForm::Derjaguin => r.cof * (r.normal_force + r.adhesion),
        CofForm::DerjaguinDoubleAdhesion => r.cof * (r.normal_force + 2.0 * r.adhesion),
        CofForm::Amontons => r.cof * r.normal_force,
        CofForm::Coulomb => r.adhesion + r.cof * r.normal_force,
    }
}

/// The slip limit μ(p)(N + p_adh(p)A_n) from the interpolated table.
fn limit(h: &HomogenisedFriction, n: f64) -> f64 {
    let s = h.sample_at(n / AREA).unwrap();
    s.cof * (n + s.adhesion_pressure * AREA)
}

#[track_caller]
fn invalid<T: std::fmt::Debug>(r: asperity::Result<T>, expect: &str) {
    match r {
        Err(e @ Error::InvalidArgument { name, .. }) if name == expect => {
            assert!(e.to_string().contains(expect), "{e}");
        }
        other => panic!("expected InvalidArgument `{expect}`, got {other:?}"),
    }
}

fn norm(v: [f64; 2]) -> f64 {
    (v[0] * v[0] + v[1] * v[1]).sqrt()
}

// ------------------------------------------------------- interpolation

#[test]
fn interpolation_reproduces_the_samples_exactly() {
    let h = copper();
    for s in copper_samples() {
        let q = h.sample_at(s.pressure).unwrap();
        assert_eq!(q, s, "at {} Pa", s.pressure);
    }
    assert_eq!(h.samples(), &copper_samples()[..]);
    assert_eq!(h.form(), CofForm::Derjaguin);
}

#[test]
fn interpolation_is_monotone_where_the_samples_are() {
    let h = copper();
    // μ decreasing, adhesion and fraction increasing over the whole range.
    let mut last = h.sample_at(10.0 * MPA).unwrap();
    for i in 1..=19_000 {
        let p = (10.0 + 0.01 * i as f64) * MPA;
        let q = h.sample_at(p).unwrap();
        assert!(q.cof <= last.cof, "μ rises at {p}");
        assert!(q.adhesion_pressure >= last.adhesion_pressure, "at {p}");
        assert!(q.contact_fraction >= last.contact_fraction, "at {p}");
        assert!(h.cof_slope(p).unwrap() <= 0.0);
        let sum = q.shares.total();
        assert!((sum - 1.0).abs() < 1e-12, "shares sum {sum} at {p}");
        last = q;
    }
    // Data with a maximum: monotone on each monotone stretch, flat at the
    // extremum (no overshoot above the largest sample).
    let mut s = copper_samples();
    for (x, mu) in s.iter_mut().zip([0.5, 0.8, 1.0, 0.8, 0.8]) {
        x.cof = mu;
    }
    let h = HomogenisedFriction::from_samples(&s, CofForm::Derjaguin).unwrap();
    let mut prev = 0.0;
    for i in 0..=9_000 {
        let p = (10.0 + 0.01 * i as f64) * MPA;
        let mu = h.sample_at(p).unwrap().cof;
        assert!(mu >= prev && mu <= 1.0, "at {p}: {mu}");
        prev = mu;
    }
    assert_eq!(h.cof_slope(100.0 * MPA).unwrap(), 0.0);
    for i in 0..=10_000 {
        let p = (100.0 + 0.01 * i as f64) * MPA;
        let mu = h.sample_at(p).unwrap().cof;
        assert!(mu <= prev && (0.8..=1.0).contains(&mu), "at {p}: {mu}");
        prev = mu;
    }
    // The last interval is flat: exactly 0.8.
    assert_eq!(h.sample_at(175.0 * MPA).unwrap().cof, 0.8);
}

#[test]
fn interpolation_is_c1_and_constant_beyond_the_ends() {
    let h = copper();
    let first = copper_samples()[0];
    let last = copper_samples()[4];
    for p in [0.0, 1.0, 5.0 * MPA, 10.0 * MPA - 1.0] {
        let q = h.sample_at(p).unwrap();
        assert_eq!(q.cof, first.cof);
        assert_eq!(q.adhesion_pressure, first.adhesion_pressure);
        assert_eq!(h.cof_slope(p).unwrap(), 0.0);
    }
    for p in [200.0 * MPA, 1e9, 1e15] {
        assert_eq!(h.sample_at(p).unwrap().cof, last.cof);
    }
    // C¹ at the interior knots: one-sided difference quotients agree.
    for p in [50.0 * MPA, 100.0 * MPA, 150.0 * MPA] {
        let e = 1.0;
        let left = (h.sample_at(p).unwrap().cof - h.sample_at(p - e).unwrap().cof) / e;
        let right = (h.sample_at(p + e).unwrap().cof - h.sample_at(p).unwrap().cof) / e;
        assert_relative_eq!(left, right, max_relative = 1e-5);
        assert_relative_eq!(h.cof_slope(p).unwrap(), right, max_relative = 1e-5);
    }
}

#[test]
fn zero_pressure_sample_and_from_fn() {
    let h =
        HomogenisedFriction::from_fn(&[0.0, 50.0 * MPA, 100.0 * MPA], CofForm::Derjaguin, |p| {
            Ok(HomogenisedSample {
                pressure: -1.0, // overwritten with p
                cof: 1.0 - p / (1000.0 * MPA),
                adhesion_pressure: 1e6,
                contact_fraction: p / 1e9,
                shares: shares(1.0, 0.0, 0.0),
            })
        })
        .unwrap();
    assert_eq!(h.samples()[0].pressure, 0.0);
    assert_eq!(h.sample_at(0.0).unwrap().cof, 1.0);
    assert_eq!(h.sample_at(100.0 * MPA).unwrap().cof, 0.9);
    // Errors of f pass through; bad pressures are named.
    let e = HomogenisedFriction::from_fn(&[1.0], CofForm::Derjaguin, |_| {
        Err(Error::InvalidArgument {
            name: "slider",
            value: 0.0,
            bound: "x",
        })
    });
    invalid(e, "slider");
    invalid(
        HomogenisedFriction::from_fn(&[f64::NAN], CofForm::Derjaguin, |_| unreachable!()),
        "pressure",
    );
}

// ------------------------------------------------------------ the step

#[test]
fn stick_then_slip_on_the_exact_cone() {
    let h = law(K);
    let n = 100.0; // 100 MPa on 1 mm²
    let lim = limit(&h, n);
    // μ(100 MPa) = 0.97, A = 9 N: F_lim = 0.97·109 N exactly as sampled.
    assert_eq!(lim, 0.97 * (100.0 + 9.0 * MPA * AREA));
    let ds = 1e-7; // 10 N per increment at k = 1e8
    let mut s = FRESH;
    let mut total = 0.0;
    let mut slipping_from = None;
    for i in 0..40 {
        let (s1, r) = step(&h, &s, &inc(n, ds, 0.0));
        total += ds;
        let trial = K * total;
        if trial <= lim {
            assert_eq!(r.regime(), FrictionRegime::Stick, "increment {i}");
            assert_relative_eq!(r.force[0], -trial, max_relative = 1e-12);
            assert_eq!(r.dissipated, 0.0);
            assert_eq!(s1[PLASTIC], s[PLASTIC], "no plastic slip in stick");
        } else {
            slipping_from.get_or_insert(i);
            assert_eq!(r.regime(), FrictionRegime::Slip, "increment {i}");
            // On the cone exactly (1-D: the direction is exactly −1).
            assert_eq!(r.force, [-lim, 0.0]);
            assert_eq!(r.force_magnitude, lim);
            assert_eq!(slip_limit(h.form(), &r), lim);
        }
        assert_eq!(r.force[1], 0.0);
        assert_eq!(r.cof, 0.97);
        assert_eq!(r.normal_force, n);
        assert_eq!(r.adhesion, 9.0 * MPA * AREA);
        assert_relative_eq!(r.true_contact_area, 0.1 * AREA, max_relative = 1e-15);
        // The elastic energy of the stick spring, |F|²/(2k).
        assert_relative_eq!(
            r.stored_energy,
            r.force_magnitude.powi(2) / (2.0 * K),
            max_relative = 1e-15
        );
        assert_eq!(force(&s1), r.force);
        s = s1;
    }
    // 105.73 N / 10 N per increment: stick for 10 increments.
    assert_eq!(slipping_from, Some(10));
    // Plastic slip = total slip − elastic slip lim/k; the slip path is the
    // total slip.
    assert_relative_eq!(s[PLASTIC], 40.0 * ds - lim / K, max_relative = 1e-12);
    assert_relative_eq!(s[1], 40.0 * ds, max_relative = 1e-12);
    assert_relative_eq!(
        dissipation(&s).total(),
        lim * (40.0 * ds - lim / K),
        max_relative = 1e-12
    );
    assert_relative_eq!(s[0], dissipation(&s).total(), max_relative = 1e-12);
}

#[test]
fn force_opposes_slip_and_dissipation_is_f_times_plastic_slip() {
    let mut x = 0x9E37_79B9_7F4A_7C15u64;
    let mut rnd = || {
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        (x >> 11) as f64 / (1u64 << 53) as f64
    };
    for k in [0.0, K] {
        let h = law(k);
        let mut s = FRESH;
        let mut acc = Dissipation::default();
        let mut path = 0.0;
        for _ in 0..2000 {
            let n = 5.0 + 250.0 * rnd();
            let a = 2.0 * std::f64::consts::PI * rnd();
            let m = 3e-6 * rnd();
            let i = inc(n, m * a.cos(), m * a.sin());
            let (s1, r) = step(&h, &s, &i);
            let dsp = plastic_slip(&h, &s, &i);
            let lim = slip_limit(h.form(), &r);
            assert!(r.dissipated >= 0.0);
            let d = &r.dissipation;
            for v in [d.chemical, d.van_der_waals, d.elastic, d.plastic] {
                assert!(v >= 0.0);
            }
            // Dissipation = −F·Δs_p = F_lim |Δs_p|.
            let fdot = -(r.force[0] * dsp[0] + r.force[1] * dsp[1]);
            assert_relative_eq!(r.dissipated, fdot, max_relative = 1e-12, epsilon = 1e-300);
            assert_relative_eq!(
                r.dissipated,
                lim * norm(dsp),
                max_relative = 1e-12,
                epsilon = 1e-300
            );
            assert_relative_eq!(r.dissipation.total(), r.dissipated, max_relative = 1e-14);
            // |F| ≤ F_lim; in slip the force is on the cone against slip.
            assert!(norm(r.force) <= lim * (1.0 + 1e-15));
            if r.regime() == FrictionRegime::Slip {
                assert_relative_eq!(norm(r.force), lim, max_relative = 1e-14);
                assert!(fdot > 0.0);
                if k == 0.0 {
                    // Rigid–plastic: exactly against the increment.
                    let dot = r.force[0] * i.slip[0] + r.force[1] * i.slip[1];
                    assert_relative_eq!(dot, -lim * m, max_relative = 1e-12);
                }
            }
            acc += r.dissipation;
            path += norm(dsp);
            s = s1;
        }
        assert_relative_eq!(dissipation(&s).total(), acc.total(), max_relative = 1e-12);
        assert_relative_eq!(s[PLASTIC], path, max_relative = 1e-12);
    }
}

#[test]
fn dissipation_shares_follow_the_table() {
    let h = law(0.0);
    for p in [10.0, 75.0, 120.0, 200.0, 300.0] {
        let n = p * MPA * AREA;
        let (_, r) = step(&h, &FRESH, &inc(n, 1e-5, 0.0));
        let sh = h.sample_at(n / AREA).unwrap().shares;
        let d = r.dissipated;
        assert_relative_eq!(d, limit(&h, n) * 1e-5, max_relative = 1e-14);
        assert_relative_eq!(
            r.dissipation.chemical,
            d * sh.chemical,
            max_relative = 1e-15
        );
        assert_relative_eq!(
            r.dissipation.van_der_waals,
            d * sh.van_der_waals,
            max_relative = 1e-15
        );
        assert_relative_eq!(r.dissipation.elastic, d * sh.elastic, max_relative = 1e-15);
        assert_relative_eq!(r.dissipation.plastic, d * sh.plastic, max_relative = 1e-12);
        // Chemical bonds dominate, as in the thesis.
        assert!(r.dissipation.chemical > 0.85 * d);
    }
}

#[test]
fn energy_balance_of_the_regularised_law() {
    // Backward Euler: −Σ F_new·Δs = ΔE_el + D + Σ|ΔF|²/(2k), exactly (to
    // rounding), with E_el = |F|²/(2k).
    let h = law(K);
    let mut s = FRESH;
    let (mut work, mut num) = (0.0, 0.0);
    for i in 0..400 {
        let a = 0.02 * i as f64;
        let n = 60.0 + 40.0 * (0.05 * i as f64).sin();
        let (s1, r) = step(&h, &s, &inc(n, 4e-7 * a.cos(), 4e-7 * a.sin()));
        let f0 = force(&s);
        let df = [r.force[0] - f0[0], r.force[1] - f0[1]];
        work -= r.force[0] * 4e-7 * a.cos() + r.force[1] * 4e-7 * a.sin();
        num += (df[0] * df[0] + df[1] * df[1]) / (2.0 * K);
        s = s1;
    }
    let e_el = norm(force(&s)).powi(2) / (2.0 * K);
    assert!(dissipation(&s).total() > 0.0);
    assert_relative_eq!(
        work,
        e_el + dissipation(&s).total() + num,
        max_relative = 1e-10
    );
}

/// The slip Δs of size along `dir` (a unit vector) at which the trial
/// force F_old − kΔs of `old` reaches `radius` (the larger root: moving
/// out of the cone).
fn slip_to_radius(old: &State, dir: [f64; 2], k: f64, radius: f64) -> [f64; 2] {
    let f = force(old);
    let fu = f[0] * dir[0] + f[1] * dir[1];
    let s = (fu + (fu * fu - norm(f).powi(2) + radius * radius).sqrt()) / k;
    [s * dir[0], s * dir[1]]
}

/// FD step sizes of the increment `i` from `old`: 1e-7 of N, and 1e-7 of
/// the slip over which the force turns (max(|F_tr|, F_lim)/k with a
/// stick stiffness, |Δs| rigid–plastic).
fn fd_steps(h: &HomogenisedFriction, old: &State, i: &FrictionIncrement) -> (f64, f64) {
    let k = h.stick_stiffness();
    let lim = step(h, &FRESH, &inc(i.normal_force, 1.0, 0.0))
        .1
        .force_magnitude;
    let hs = if k > 0.0 {
        let f = force(old);
        let tr = norm([f[0] - k * i.slip[0], f[1] - k * i.slip[1]]);
        1e-7 * tr.max(lim) / k
    } else {
        1e-7 * norm(i.slip)
    };
    (1e-7 * i.normal_force.max(1e-3), hs)
}

/// The consistent tangents (stick, gross slip, on both sides of the
/// stick–slip switch, either side of the table's ends, in every COF form,
/// regularised and rigid–plastic, in 2-D, from a loaded and a fresh state;
/// N = 0 with and without contact) against central differences of the step
/// (`common/tangents.rs`), to 1e-6.
#[test]
fn tangents_match_finite_differences() {
    // Stick (k > 0): dF/dΔs = −k I, dF/dN = 0, exactly.
    let old = with_force([-30.0, 20.0]);
    let (_, r) = step(&law(K), &old, &inc(75.0, 1e-7, 2e-8));
    assert_eq!(r.regime(), FrictionRegime::Stick);
    assert_eq!(r.dforce_dslip, [[-K, 0.0], [0.0, -K]]);
    assert_eq!(r.dforce_dnormal, [0.0, 0.0]);
    let dirs = [[1.0, 0.0], [0.6, -0.8], [-0.28, 0.96]];
    // N inside table intervals, right next to the table's ends (p = 10 and
    // 200 MPa, where μ' jumps to 0) on either side.
    let loads = [
        33.0,
        75.0,
        120.0,
        170.0,
        10.0 * (1.0 - 1e-5),
        10.0 * (1.0 + 1e-5),
        200.0 * (1.0 - 1e-5),
        200.0 * (1.0 + 1e-5),
    ];
    let mut checked = 0;
    for form in [
        CofForm::Derjaguin,
        CofForm::Amontons,
        CofForm::Coulomb,
        CofForm::DerjaguinDoubleAdhesion,
    ] {
        let table = HomogenisedFriction::from_samples(&copper_samples(), form).unwrap();
        for k in [K, 0.0] {
            let h = table.clone().with_stick_stiffness(k).unwrap();
            for old in [with_force([-30.0, 20.0]), FRESH] {
                for &n in &loads {
                    let lim = step(&h, &FRESH, &inc(n, 1.0, 0.0)).1.force_magnitude;
                    let mut points: Vec<(&str, [f64; 2], bool)> = vec![];
                    for d in dirs {
                        // Gross slip.
                        points.push(("slip", [2e-6 * d[0], 2e-6 * d[1]], true));
                        if k > 0.0 {
                            // Stick, and either side of the switch |F_tr| =
                            // F_lim (1e-5 of F_lim away; the steps move
                            // |F_tr| and F_lim by 1e-7).
                            points.push(("stick", [1e-8 * d[0], 1e-8 * d[1]], true));
                            for (what, f) in
                                [("below switch", 1.0 - 1e-5), ("above switch", 1.0 + 1e-5)]
                            {
                                points.push((what, slip_to_radius(&old, d, k, lim * f), true));
                            }
                        }
                    }
                    if k == 0.0 {
                        // Rigid stick without slip: dF/dΔs has no meaning
                        // (any slip jumps to the rim); dF/dN is checked
                        // where the old force is capped by the cone.
                        points.push(("rigid stick", [0.0, 0.0], false));
                    }
                    for (what, slip, both) in points {
                        if !(slip[0].is_finite() && slip[1].is_finite()) {
                            // The trial force never crosses that radius.
                            continue;
                        }
                        let i = inc(n, slip[0], slip[1]);
                        let (hn, hs) = fd_steps(&h, &old, &i);
                        let label = format!("{form:?} k = {k:e} N = {n} {what} {slip:?}");
                        let fd = tangents::fd_check(
                            &h,
                            &old,
                            &i,
                            hn,
                            if hs > 0.0 { hs } else { 1e-12 },
                            &label,
                        );
                        // The regime the trial force predicts.
                        let f = force(&old);
                        let tr = norm([f[0] - k * slip[0], f[1] - k * slip[1]]);
                        let want = if (k > 0.0 && tr <= lim) || slip == [0.0, 0.0] {
                            FrictionRegime::Stick
                        } else {
                            FrictionRegime::Slip
                        };
                        assert_eq!(fd.response.regime(), want, "{label}");
                        match what {
                            "below switch" => assert_eq!(want, FrictionRegime::Stick),
                            "above switch" => assert_eq!(want, FrictionRegime::Slip),
                            _ => {}
                        }
                        if both {
                            assert!(fd.both(), "{label}: a kink within the steps {fd:?}");
                        } else if norm(force(&old)) > lim {
                            assert!(fd.normal.is_some(), "{label}");
                        }
                        checked += 1;
                    }
                }
            }
        }
    }
    assert!(checked > 300, "{checked}");
    // N = 0: with adhesion at zero load (contact), the cone is μ(0)A; with
    // none, no contact, and dF/dN is the derivative from above (the point
    // slides on a cone that grows from 0).
    let mut bare = copper_samples();
    bare[0].pressure = 0.0;
    bare[0].adhesion_pressure = 0.0;
    for (samples, contact) in [(copper_samples(), true), (bare, false)] {
        for form in [
            CofForm::Derjaguin,
            CofForm::Amontons,
            CofForm::Coulomb,
            CofForm::DerjaguinDoubleAdhesion,
        ] {
            let table = HomogenisedFriction::from_samples(&samples, form).unwrap();
            for k in [K, 0.0] {
                let h = table.clone().with_stick_stiffness(k).unwrap();
                for (old, slip) in [
                    (with_force([-30.0, 20.0]), [2e-6, -1e-6]),
                    (with_force([-30.0, 20.0]), [0.0, 0.0]),
                    (FRESH, [-1e-6, 3e-6]),
                ] {
                    let i = inc(0.0, slip[0], slip[1]);
                    let label = format!("{form:?} k = {k:e} N = 0 {slip:?} contact {contact}");
                    let hs = if k > 0.0 {
                        1e-7 * 40.0 / k
                    } else {
                        1e-7 * norm(slip)
                    };
                    let fd = tangents::fd_check(&h, &old, &i, 1e-6, hs.max(1e-15), &label);
                    let r = fd.response;
                    if contact {
                        assert_ne!(r.regime(), FrictionRegime::NoContact, "{label}");
                    } else {
                        assert_eq!(r.regime(), FrictionRegime::NoContact, "{label}");
                        assert_eq!(r.force, [0.0, 0.0]);
                        assert_eq!(r.dforce_dslip, [[0.0; 2]; 2], "{label}");
                        assert!(norm(r.dforce_dnormal) > 0.0, "{label}: {r:?}");
                        // Form by form, dF_lim/dN at 0: μ(0)(1 + p_adh'(0)),
                        // μ(0), μ(0) + p_adh'(0).
                        let mu = samples[0].cof;
                        assert!(norm(r.dforce_dnormal) >= mu * (1.0 - 1e-12), "{label}");
                    }
                    assert!(fd.normal.is_some(), "{label}: {fd:?}");
                }
            }
        }
    }
}

#[test]
fn cof_forms_set_the_slip_limit() {
    let s = copper_samples();
    let a = 9.0 * MPA * AREA;
    let n = 100.0;
    for (form, expect) in [
        (CofForm::Derjaguin, 0.97 * (n + a)),
        (CofForm::Amontons, 0.97 * n),
        (CofForm::Coulomb, a + 0.97 * n),
        (CofForm::DerjaguinDoubleAdhesion, 0.97 * (n + 2.0 * a)),
    ] {
        let h = HomogenisedFriction::from_samples(&s, form).unwrap();
        let (_, r) = step(&h, &FRESH, &inc(n, 1e-3, 0.0));
        assert_eq!(r.regime(), FrictionRegime::Slip, "{form:?}");
        assert_eq!(r.force_magnitude, expect, "{form:?}");
        assert_eq!(slip_limit(form, &r), expect, "{form:?}");
        assert_eq!(r.force, [-expect, 0.0]);
    }
}

#[test]
fn zero_load_and_no_contact() {
    // Zero load with adhesion: the cone is μ(0)·A (first sample held).
    let h = law(K);
    let (s, r) = step(&h, &FRESH, &inc(0.0, 1e-5, 0.0));
    let a = 0.9 * MPA * AREA;
    assert_eq!(r.adhesion, a);
    assert_eq!(slip_limit(h.form(), &r), 1.10 * a);
    assert_eq!(r.force, [-1.10 * a, 0.0]);
    assert_eq!(r.regime(), FrictionRegime::Slip);
    assert!(r.dissipated > 0.0);
    assert_eq!(force(&s), r.force);
    // No load, no adhesion: no contact, no friction, nothing is NaN.
    let mut samples = copper_samples();
    samples[0].pressure = 0.0;
    samples[0].adhesion_pressure = 0.0;
    samples[0].contact_fraction = 0.0;
    let table = HomogenisedFriction::from_samples(&samples, CofForm::Derjaguin).unwrap();
    let mut old = with_force([-5.0, 1.0]);
    old[0] = 1.1;
    old[1] = 2e-3;
    old[PLASTIC] = 1e-3;
    old[MECHANISMS] = 1.0;
    old[MECHANISMS + 1] = 0.1;
    for k in [0.0, K] {
        let h = table.clone().with_stick_stiffness(k).unwrap();
        let (s, r) = step(&h, &old, &inc(0.0, 1e-5, -2e-5));
        assert_eq!(r.regime(), FrictionRegime::NoContact);
        assert_eq!(r.regime, 3);
        assert_eq!(r.force, [0.0, 0.0]);
        assert_eq!(r.force_magnitude, 0.0);
        // The stick force is released: its stored energy |F|²/2k is lost,
        // booked as dissipated (nothing with k = 0).
        let released = if k > 0.0 {
            0.5 * norm(force(&old)).powi(2) / k
        } else {
            0.0
        };
        assert_relative_eq!(r.dissipated, released, max_relative = 1e-15);
        assert_relative_eq!(r.dissipation.total(), released, max_relative = 1e-12);
        assert_eq!(r.stored_energy, 0.0);
        assert_eq!(r.dforce_dslip, [[0.0; 2]; 2]);
        assert_eq!(r.true_contact_area, 0.0);
        assert_eq!(r.cof, 1.10);
        assert_eq!(force(&s), [0.0, 0.0]);
        assert_eq!(s[PLASTIC], old[PLASTIC]);
        assert_relative_eq!(
            dissipation(&s).total(),
            dissipation(&old).total() + released,
            max_relative = 1e-15
        );
        assert_eq!(s[0], old[0] + r.dissipated);
        let (s2, r2) = step(&h, &s, &inc(0.0, 0.0, 0.0));
        assert_eq!(r2.regime(), FrictionRegime::NoContact);
        assert_eq!(r2.dissipated, 0.0, "nothing left to release");
        assert!(s2.iter().all(|f| f.is_finite()));
    }
    // Frictionless contact (μ = 0): slips with zero force, no dissipation.
    for s in samples.iter_mut() {
        s.cof = 0.0;
    }
    let h = HomogenisedFriction::from_samples(&samples, CofForm::Derjaguin)
        .unwrap()
        .with_stick_stiffness(K)
        .unwrap();
    let (_, r) = step(&h, &old, &inc(50.0, 1e-6, 0.0));
    assert_eq!(r.regime(), FrictionRegime::Slip);
    assert_eq!(r.force, [0.0, 0.0]);
    assert_eq!(r.dissipated, 0.0);
    // Rigid stick with no slip keeps the old force inside the cone.
    let h = law(0.0);
    let (s, r) = step(&h, &old, &inc(50.0, 0.0, 0.0));
    assert_eq!(r.regime(), FrictionRegime::Stick);
    assert_eq!(r.force, force(&old));
    assert_eq!(force(&s), force(&old));
    // ... and caps it without dissipation when the cone shrinks.
    let big = with_force([-300.0, 0.0]);
    let (_, r) = step(&h, &big, &inc(50.0, 0.0, 0.0));
    assert_eq!(r.force, [-slip_limit(h.form(), &r), 0.0]);
    assert_eq!(r.dissipated, 0.0);
}

/// An open gap (A_n = 0 with N = 0), what an FE host passes for a node
/// that is not touching: no contact even with the table's adhesive
/// pressure (which holds a touching point under zero load), the stick
/// force released without dissipation, no tangents; the slip path still
/// counts the motion. N > 0 on no area stays an error.
#[test]
fn open_gap_is_no_contact() {
    let h = law(K);
    let mut old = with_force([-40.0, 12.0]);
    old[0] = 0.5;
    old[PLASTIC] = 2e-6;
    for slip in [[0.0, 0.0], [3e-7, -1e-7]] {
        let gap = FrictionIncrement {
            normal_force: 0.0,
            area: 0.0,
            slip,
            dt: 1e-6,
            tangents: TANGENT_NORMAL | TANGENT_SLIP,
            ..Default::default()
        };
        let (s, r) = step(&h, &old, &gap);
        assert_eq!(r.regime(), FrictionRegime::NoContact);
        assert_eq!(r.force, [0.0, 0.0]);
        assert_eq!((r.adhesion, r.true_contact_area), (0.0, 0.0));
        // The released stick energy |F|²/2k is dissipated; nothing stays
        // stored.
        let released = 0.5 * norm(force(&old)).powi(2) / K;
        assert_relative_eq!(r.dissipated, released, max_relative = 1e-15);
        assert_eq!(r.stored_energy, 0.0);
        assert_eq!(r.dforce_dslip, [[0.0; 2]; 2]);
        assert_eq!(r.dforce_dnormal, [0.0; 2]);
        assert_eq!(force(&s), [0.0, 0.0]);
        assert_eq!(s[0], old[0] + r.dissipated);
        assert_eq!(s[1], old[1] + norm(slip));
        assert_eq!(s[PLASTIC], old[PLASTIC]);
    }
    // The same zero load on a touching point (A_n > 0): adhesive contact.
    let (_, r) = step(&h, &old, &inc(0.0, 0.0, 0.0));
    assert_ne!(r.regime(), FrictionRegime::NoContact);
    assert_eq!(r.adhesion, 0.9 * MPA * AREA);
    assert_relative_eq!(
        r.force_magnitude,
        1.10 * 0.9 * MPA * AREA,
        max_relative = 1e-15
    );
    // A load on no area has no pressure.
    invalid(
        h.step(
            &old,
            &mut FRESH.clone(),
            &FrictionIncrement {
                normal_force: 1.0,
                area: 0.0,
                ..Default::default()
            },
            &mut h.work(),
        ),
        "area",
    );
}

#[test]
fn slip_reversal_and_direction_changes() {
    let (h, rigid) = (law(K), law(0.0));
    let n = 80.0;
    let lim = limit(&h, n);
    // Slide along +x into steady sliding.
    let mut s = FRESH;
    for _ in 0..20 {
        s = step(&h, &s, &inc(n, 1e-6, 0.0)).0;
    }
    assert_eq!(force(&s), [-lim, 0.0]);
    // Reverse: elastic unloading through zero (stick) for 2 F_lim/k, then
    // sliding the other way with the force flipped.
    let ds = 1e-7;
    let mut stick = 0;
    let mut x = 0.0;
    loop {
        let (s1, r) = step(&h, &s, &inc(n, -ds, 0.0));
        x += ds;
        s = s1;
        if r.regime() == FrictionRegime::Stick {
            stick += 1;
            assert_relative_eq!(r.force[0], -lim + K * x, max_relative = 1e-9);
        } else {
            assert_eq!(r.force, [lim, 0.0]);
            break;
        }
    }
    assert_eq!(stick, (2.0 * lim / (K * ds)).floor() as usize);
    // Turn by 90°: with k > 0 the force rotates towards −y over a few
    // increments, always on or inside the cone; with k = 0 at once.
    for _ in 0..200 {
        let (s1, r) = step(&h, &s, &inc(n, 0.0, 1e-6));
        assert!(norm(r.force) <= lim * (1.0 + 1e-15));
        s = s1;
    }
    let f = force(&s);
    assert!(f[0].abs() < 1e-9 * lim && (f[1] + lim).abs() < 1e-9 * lim);
    let (_, r) = step(&rigid, &s, &inc(n, 1e-6, 0.0));
    assert_eq!(r.force, [-lim, 0.0]);
    // Reversal in one large increment (rigid–plastic): flips at once.
    let (_, r) = step(&rigid, &s, &inc(n, 0.0, -1e-6));
    assert_eq!(r.force, [0.0, lim]);
}

#[test]
fn re_evaluation_is_bit_identical() {
    let h = law(K);
    let mut old = with_force([-12.5, 3.25]);
    old[0] = 1.101e-4;
    old[1] = 3e-6;
    old[PLASTIC] = 2e-6;
    old[MECHANISMS..].copy_from_slice(&[1e-4, 1e-5, 1e-7, 0.0]);
    let i = inc(77.7, 3e-7, -1e-7);
    let (s1, r1) = step(&h, &old, &i);
    // Another step in between (cut back and redo) does not matter.
    let _ = step(&h, &s1, &inc(10.0, 1.0, 1.0));
    let (s2, r2) = step(&h, &old, &i);
    assert_eq!(format!("{s1:?}{r1:?}"), format!("{s2:?}{r2:?}"));
    assert_eq!(s1, s2);
    assert_eq!(r1.force[0].to_bits(), r2.force[0].to_bits());
    // In place agrees with old and new separate.
    let mut st = old;
    let r3 = h.step_in_place(&mut st, &i, &mut h.work()).unwrap();
    assert_eq!(format!("{st:?}{r3:?}"), format!("{s1:?}{r1:?}"));
}

// ------------------------------------------------------------- blocks

fn block_inputs(n: usize) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
    let nf: Vec<f64> = (0..n).map(|i| 10.0 + 190.0 * i as f64 / n as f64).collect();
    let a = vec![AREA; n];
    let s: Vec<f64> = (0..2 * n)
        .map(|j| 1e-7 * ((j as f64) * 0.37).sin())
        .collect();
    (nf, a, s)
}

/// A block of the points `normal_force`, `area`, `slip` at Δt = 1e-6 s.
fn block<'a>(
    normal_force: &'a [f64],
    area: &'a [f64],
    slip: &'a [f64],
    states: BlockStates<'a>,
    tangential_force: &'a mut [f64],
    dissipation: Option<&'a mut [f64]>,
) -> FrictionBlock<'a> {
    FrictionBlock {
        normal_force,
        area: Some(area),
        slip,
        dt: 1e-6,
        tangents: 0,
        states,
        tangential_force: Some(tangential_force),
        dissipation,
        responses: None,
    }
}

/// Old and new states separate.
fn sep<'a>(old: &'a [f64], new: &'a mut [f64]) -> BlockStates<'a> {
    BlockStates::Separate { old, new }
}

#[test]
fn block_equals_scalar_steps() {
    let h = law(K);
    let mut w = h.work();
    let n = 64;
    let m = HomogenisedFriction::STATE_LEN;
    let (nf, a, sl) = block_inputs(n);
    let mut old = vec![0.0; n * m];
    let mut new = old.clone();
    let mut in_place = old.clone();
    let mut f = vec![0.0; 2 * n];
    let mut d = vec![0.0; n];
    let mut f2 = vec![0.0; 2 * n];
    let mut d2 = vec![0.0; n];
    for round in 0..30 {
        let states = BlockStates::Separate {
            old: &old,
            new: &mut new,
        };
        h.step_block(block(&nf, &a, &sl, states, &mut f, Some(&mut d)), &mut w)
            .unwrap();
        let states = BlockStates::InPlace(&mut in_place);
        h.step_block(block(&nf, &a, &sl, states, &mut f2, Some(&mut d2)), &mut w)
            .unwrap();
        for i in 0..n {
            let o: State = old[i * m..(i + 1) * m].try_into().unwrap();
            let (s, r) = step(&h, &o, &inc(nf[i], sl[2 * i], sl[2 * i + 1]));
            assert_eq!(new[i * m..(i + 1) * m], s, "round {round}, point {i}");
            assert_eq!([f[2 * i], f[2 * i + 1]], r.force);
            assert_eq!(d[i], r.dissipated);
        }
        assert_eq!((&in_place, &f2, &d2), (&new, &f, &d), "round {round}");
        std::mem::swap(&mut old, &mut new);
    }
    // Empty blocks are fine.
    let states = BlockStates::InPlace(&mut []);
    h.step_block(block(&[], &[], &[], states, &mut [], None), &mut w)
        .unwrap();
}

#[test]
fn block_errors_name_the_slice_and_the_element() {
    let h = law(K);
    let mut w = h.work();
    let n = 8;
    let m = HomogenisedFriction::STATE_LEN;
    let (mut nf, a, sl) = block_inputs(n);
    let old = vec![0.0; n * m];
    let mut new = old.clone();
    let mut f = vec![0.0; 2 * n];
    let mut d = vec![0.0; n];
    let name = |e: BatchError| match e.error {
        Error::InvalidArgument { name, .. } => (e.index, name),
        other => panic!("{other:?}"),
    };
    let e = h
        .step_block(
            block(&nf, &a[..7], &sl, sep(&old, &mut new), &mut f, Some(&mut d)),
            &mut w,
        )
        .unwrap_err();
    assert_eq!(name(e), (0, "area.len()"));
    let e = h
        .step_block(
            block(&nf, &a, &sl[..8], sep(&old, &mut new), &mut f, Some(&mut d)),
            &mut w,
        )
        .unwrap_err();
    assert_eq!(name(e), (0, "slip.len()"));
    let e = h
        .step_block(
            block(
                &nf,
                &a,
                &sl,
                sep(&old[..2 * m], &mut new),
                &mut f,
                Some(&mut d),
            ),
            &mut w,
        )
        .unwrap_err();
    assert_eq!(name(e), (0, "old.len()"));
    let e = h
        .step_block(
            block(&nf, &a, &sl, sep(&old, &mut new[..3]), &mut f, Some(&mut d)),
            &mut w,
        )
        .unwrap_err();
    assert_eq!(name(e), (0, "new.len()"));
    let e = h
        .step_block(
            block(
                &nf,
                &a,
                &sl,
                BlockStates::InPlace(&mut new[1..]),
                &mut f,
                None,
            ),
            &mut w,
        )
        .unwrap_err();
    assert_eq!(name(e), (0, "states.len()"));
    let e = h
        .step_block(
            block(&nf, &a, &sl, sep(&old, &mut new), &mut f[..3], Some(&mut d)),
            &mut w,
        )
        .unwrap_err();
    assert_eq!(name(e), (0, "tangential_force.len()"));
    let e = h
        .step_block(
            block(&nf, &a, &sl, sep(&old, &mut new), &mut f, Some(&mut d[..1])),
            &mut w,
        )
        .unwrap_err();
    assert_eq!(name(e), (0, "dissipation.len()"));
    // A bad element: earlier ones written, later ones untouched.
    nf[5] = f64::NAN;
    let mut f = vec![-99.0; 2 * n];
    let e = h
        .step_block(
            block(&nf, &a, &sl, sep(&old, &mut new), &mut f, Some(&mut d)),
            &mut w,
        )
        .unwrap_err();
    assert!(e.to_string().contains("element 5"));
    assert_eq!(name(e), (5, "normal_force"));
    assert!(f[..10].iter().all(|&x| x != -99.0));
    assert!(f[10..].iter().all(|&x| x == -99.0));
    nf[5] = 10.0;
    let mut b = block(&nf, &a, &sl, sep(&old, &mut new), &mut f, Some(&mut d));
    b.dt = -1.0;
    let e = h.step_block(b, &mut w).unwrap_err();
    assert_eq!(name(e), (0, "dt"));
    // No areas: 0 for every point, which this law refuses.
    let mut b = block(&nf, &a, &sl, sep(&old, &mut new), &mut f, Some(&mut d));
    b.area = None;
    let e = h.step_block(b, &mut w).unwrap_err();
    assert_eq!(name(e), (0, "area"));
}

// ---------------------------------------------------------- bad input

#[test]
fn bad_step_input_is_named() {
    let h = law(K);
    let o = FRESH;
    let sentinel = [-7.0; HomogenisedFriction::STATE_LEN];
    let call = |old: &State, i: FrictionIncrement| {
        let mut s = sentinel;
        let res = h.step(old, &mut s, &i, &mut h.work());
        assert_eq!(s, sentinel, "new state untouched on error");
        let mut st = *old;
        let res2 = h.step_in_place(&mut st, &i, &mut h.work());
        assert_eq!(
            st.map(f64::to_bits),
            old.map(f64::to_bits),
            "state untouched"
        );
        assert_eq!(res.is_err(), res2.is_err());
        res
    };
    let good = inc(50.0, 1e-7, 0.0);
    invalid(
        call(
            &o,
            FrictionIncrement {
                normal_force: f64::NAN,
                ..good
            },
        ),
        "normal_force",
    );
    invalid(
        call(
            &o,
            FrictionIncrement {
                normal_force: -1.0,
                ..good
            },
        ),
        "normal_force",
    );
    invalid(
        call(
            &o,
            FrictionIncrement {
                area: -1e-6,
                ..good
            },
        ),
        "area",
    );
    invalid(call(&o, FrictionIncrement { area: 0.0, ..good }), "area");
    invalid(
        call(
            &o,
            FrictionIncrement {
                area: f64::INFINITY,
                ..good
            },
        ),
        "area",
    );
    invalid(
        call(
            &o,
            FrictionIncrement {
                slip: [f64::NAN, 0.0],
                ..good
            },
        ),
        "slip",
    );
    invalid(
        call(
            &o,
            FrictionIncrement {
                slip: [0.0, f64::INFINITY],
                ..good
            },
        ),
        "slip",
    );
    invalid(call(&o, FrictionIncrement { dt: -1.0, ..good }), "dt");
    invalid(
        call(
            &o,
            FrictionIncrement {
                dt: f64::NAN,
                ..good
            },
        ),
        "dt",
    );
    match call(
        &o,
        FrictionIncrement {
            tangents: 4,
            ..good
        },
    ) {
        Err(Error::UnknownSelector {
            name: "tangents", ..
        }) => {}
        other => panic!("{other:?}"),
    }
    // The stick stiffness is the law's, checked when it is set.
    invalid(copper().with_stick_stiffness(-1.0), "stick_stiffness");
    invalid(copper().with_stick_stiffness(f64::NAN), "stick_stiffness");
    invalid(
        copper().with_stick_stiffness(f64::INFINITY),
        "stick_stiffness",
    );
    assert_eq!(law(K).stick_stiffness(), K);
    assert_eq!(copper().stick_stiffness(), 0.0);
    let bad = |i: usize, v: f64| {
        let mut s = o;
        s[i] = v;
        s
    };
    invalid(call(&bad(FORCE, f64::NAN), good), "old.force");
    invalid(call(&bad(FORCE + 1, f64::INFINITY), good), "old.force");
    invalid(call(&bad(PLASTIC, -1.0), good), "old.plastic_slip_path");
    invalid(call(&bad(MECHANISMS + 3, -1.0), good), "old.mechanisms");
    invalid(call(&bad(0, -1.0), good), "old.dissipation");
    invalid(call(&bad(1, f64::NAN), good), "old.slip_path");
    // Overflow is an error, never an infinity.
    let e = call(
        &o,
        FrictionIncrement {
            slip: [1e300, 1e300],
            ..good
        },
    )
    .unwrap_err();
    assert!(
        matches!(e, Error::OutOfDomain { name: "slip", .. }),
        "{e:?}"
    );
    // A huge pressure is beyond the table (constant), not an error...
    let (_, r) = step(
        &h,
        &o,
        &FrictionIncrement {
            normal_force: 1e308,
            area: 1e-300,
            ..good
        },
    );
    assert_eq!(r.cof, 0.9);
    // ... but a slip limit beyond f64 is.
    let mut one = copper_samples()[0];
    one.cof = 2.0;
    let h2 = HomogenisedFriction::from_samples(&[one], CofForm::Derjaguin)
        .unwrap()
        .with_stick_stiffness(K)
        .unwrap();
    let mut s = o;
    let e = h2
        .step(
            &o,
            &mut s,
            &FrictionIncrement {
                normal_force: 1.7e308,
                ..good
            },
            &mut h2.work(),
        )
        .unwrap_err();
    assert!(
        matches!(
            e,
            Error::OutOfDomain {
                name: "normal_force",
                ..
            }
        ),
        "{e:?}"
    );
}

#[test]
fn bad_tables_are_named() {
    let f = |s: &[HomogenisedSample]| HomogenisedFriction::from_samples(s, CofForm::Derjaguin);
    invalid(f(&[]), "samples");
    let base = copper_samples();
    let with = |k: usize, g: &dyn Fn(&mut HomogenisedSample)| {
        let mut s = base.clone();
        g(&mut s[k]);
        s
    };
    invalid(f(&with(2, &|s| s.pressure = 50.0 * MPA)), "pressure");
    invalid(f(&with(2, &|s| s.pressure = 40.0 * MPA)), "pressure");
    invalid(f(&with(0, &|s| s.pressure = -1.0)), "pressure");
    invalid(f(&with(3, &|s| s.pressure = f64::NAN)), "pressure");
    invalid(f(&with(1, &|s| s.cof = -0.1)), "cof");
    invalid(f(&with(1, &|s| s.cof = f64::INFINITY)), "cof");
    invalid(
        f(&with(1, &|s| s.adhesion_pressure = -1.0)),
        "adhesion_pressure",
    );
    invalid(
        f(&with(4, &|s| s.contact_fraction = 1.5)),
        "contact_fraction",
    );
    invalid(
        f(&with(4, &|s| s.contact_fraction = f64::NAN)),
        "contact_fraction",
    );
    invalid(f(&with(0, &|s| s.shares.chemical = 0.5)), "shares");
    invalid(f(&with(0, &|s| s.shares.plastic = -0.01)), "shares.plastic");
    invalid(
        f(&with(0, &|s| s.shares.elastic = f64::NAN)),
        "shares.elastic",
    );
    // Within 1e-9 is accepted.
    f(&with(0, &|s| s.shares.chemical += 5e-10)).unwrap();
    invalid(f(&with(0, &|s| s.shares.chemical += 5e-9)), "shares");
}

// ------------------------------------------------------------- storage

#[test]
fn json_round_trip_is_bit_exact() {
    let mut samples = copper_samples();
    // Values that plain JSON numbers would not round-trip.
    samples[1].cof = 1.0 / 3.0 + 1e-17;
    samples[2].adhesion_pressure = 9.000000000000002e6;
    for form in [
        CofForm::Derjaguin,
        CofForm::Amontons,
        CofForm::Coulomb,
        CofForm::DerjaguinDoubleAdhesion,
    ] {
        let h = HomogenisedFriction::from_samples(&samples, form).unwrap();
        let json = h.to_json();
        let g = HomogenisedFriction::from_json(&json).unwrap();
        assert_eq!(g.to_json(), json);
        assert_eq!(g.form(), form);
        for (a, b) in h.samples().iter().zip(g.samples()) {
            for (x, y) in [
                (a.pressure, b.pressure),
                (a.cof, b.cof),
                (a.adhesion_pressure, b.adhesion_pressure),
                (a.contact_fraction, b.contact_fraction),
                (a.shares.van_der_waals, b.shares.van_der_waals),
            ] {
                assert_eq!(x.to_bits(), y.to_bits());
            }
        }
        // The stick stiffness is the host's penalty, not the table's: not
        // serialised.
        let hk = h.clone().with_stick_stiffness(K).unwrap();
        assert_eq!(hk.to_json(), json);
        assert_eq!(g.stick_stiffness(), 0.0);
        let gk = g.clone().with_stick_stiffness(K).unwrap();
        let mut s = FRESH;
        for i in 0..200 {
            let n = 1.0 + i as f64;
            let incr = inc(n, 1e-7 * (i as f64).cos(), 1e-7 * (i as f64).sin());
            let (s1, r1) = step(&hk, &s, &incr);
            let (s2, r2) = step(&gk, &s, &incr);
            assert_eq!(format!("{s1:?}{r1:?}"), format!("{s2:?}{r2:?}"));
            s = s1;
        }
        // Through serde directly as well.
        let v = serde_json::to_string(&h).unwrap();
        let g2: HomogenisedFriction = serde_json::from_str(&v).unwrap();
        assert_eq!(g2.to_json(), json);
    }
}

#[test]
fn json_is_validated_on_load() {
    let h = copper();
    let json = h.to_json();
    invalid(HomogenisedFriction::from_json("{"), "json");
    invalid(
        HomogenisedFriction::from_json(&json.replace("\"cof\"", "\"mu\"")),
        "json",
    );
    invalid(
        HomogenisedFriction::from_json(&json.replace("asperity-homogenised-friction-1", "v0")),
        "format",
    );
    // A decreasing pressure is caught by the same validation as from_samples.
    let bad = json.replacen("\"1e7\"", "\"3e8\"", 1);
    assert_ne!(bad, json);
    invalid(HomogenisedFriction::from_json(&bad), "pressure");
    // Hand-written with plain numbers.
    let hand = r#"{"format": "asperity-homogenised-friction-1", "form": "Derjaguin",
        "samples": [{"pressure": 0, "cof": 1.0, "adhesion_pressure": 0,
                     "contact_fraction": 0, "shares": {"chemical": 1, "van_der_waals": 0,
                     "elastic": 0, "plastic": 0}}]}"#;
    let g = HomogenisedFriction::from_json(hand).unwrap();
    assert_eq!(g.sample_at(5e6).unwrap().cof, 1.0);
}

// ------------------------------------------------- no allocation, threads

#[test]
fn no_allocation_per_step() {
    let h = law(K);
    let mut w = h.work();
    let n = 64;
    let m = HomogenisedFriction::STATE_LEN;
    let (nf, a, sl) = block_inputs(n);
    let mut old = vec![0.0; n * m];
    let mut new = old.clone();
    let mut f = vec![0.0; 2 * n];
    let mut d = vec![0.0; n];
    let mut s = FRESH;
    let mut s1 = s;
    let mut acc = 0.0;
    let before = allocations();
    for i in 0..10_000 {
        let x = i as f64;
        let incr = inc(1.0 + (x * 0.01) % 250.0, 1e-7 * x.cos(), 1e-7 * x.sin());
        let r = h.step(&s, &mut s1, &incr, &mut w).unwrap();
        s = s1;
        acc += r.dissipated;
        h.step_in_place(&mut s1, &incr, &mut w).unwrap();
        h.step_block(
            block(&nf, &a, &sl, sep(&old, &mut new), &mut f, Some(&mut d)),
            &mut w,
        )
        .unwrap();
        std::mem::swap(&mut old, &mut new);
        h.step_block(
            block(&nf, &a, &sl, BlockStates::InPlace(&mut new), &mut f, None),
            &mut w,
        )
        .unwrap();
        // The error path does not allocate either.
        let bad = FrictionIncrement { area: -1.0, ..incr };
        assert!(h.step(&s, &mut s1, &bad, &mut w).is_err());
    }
    let after = allocations();
    assert_eq!(
        after - before,
        0,
        "allocations during 10^4 step + step_in_place + step_block calls"
    );
    // The counter does count.
    let v = std::hint::black_box(vec![1u8; 16]);
    assert!(allocations() > after && v.len() == 16);
    assert!(acc > 0.0 && old[3 * m] > 0.0);
}

#[test]
fn one_law_shared_by_threads() {
    let h = law(K);
    let reference: Vec<_> = (0..100)
        .map(|i| step(&h, &FRESH, &inc(i as f64, 1e-6, 0.0)).1)
        .collect();
    std::thread::scope(|sc| {
        for _ in 0..2 {
            sc.spawn(|| {
                for (i, r0) in reference.iter().enumerate() {
                    let r = step(&h, &FRESH, &inc(i as f64, 1e-6, 0.0)).1;
                    assert_eq!(&r, r0);
                }
            });
        }
    });
}
