//! Tabulated Lennard-Jones sphere: the table against its own solver (same
//! grid and mesh), jump and pull-off points against `LjSolver::curve`,
//! hysteresis, far tail, storage and the C constructor.
//!
//! Cases: μ = 0.1 at N = 64, μ = 1 at N = 96, μ ∈ {0.1, 0.5, 1} at N = 128
//! with dense comparisons, and μ = 3 at N = 64 through the edge continuation
//! (`-- --nocapture` prints sizes, errors and build times), and μ = 10 at
//! N = 256; about 15 s with the test profile. μ = 10 on the default grid
//! (N = 512) is `#[ignore]`d (about 20 s in release).

use asperity::contact::curve::EquilibriumCurve;
use asperity::contact::lj_sphere::{rigid_force_bar, LjSolution, LjSolver, LjSphere};
use asperity::contact::{ContactState, Control, NormalContact, NormalResponse, TabulatedLaw};
use asperity::Error;
use core::f64::consts::PI;
use std::time::Instant;

/// Reference response of the solver (dimensionless sphere: δ = ᾱ, P = πP̄).
fn resp(s: &LjSolution) -> NormalResponse {
    NormalResponse {
        force: PI * s.force,
        delta: s.approach,
        contact_radius: s.contact_radius,
        ..Default::default()
    }
}

struct Report {
    worst: f64,
    worst_at: f64,
    count: usize,
}

/// Follow the solver along `alphas` from `start` (guess continuation) and
/// compare with the table on `branch`; returns the worst error.
fn follow(
    t: &TabulatedLaw,
    s: &LjSolver,
    start: LjSolution,
    alphas: &[f64],
    branch: i32,
    rep: &mut Report,
) -> LjSolution {
    let mut g = start;
    for &al in alphas {
        g = s.solve_at_approach(al, Some(&g)).unwrap();
        let st = ContactState {
            branch,
            ..Default::default()
        };
        let (r, ns) = t.eval(al, &st).unwrap();
        assert_eq!(ns.branch, branch, "ᾱ = {al}: left branch {branch}");
        let e = t.relative_error(&resp(&g), &r);
        rep.count += 1;
        if e > rep.worst {
            rep.worst = e;
            rep.worst_at = al;
        }
    }
    g
}

fn lin(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect()
}

/// Table vs solver on every stable branch, both sides of the jumps; jump
/// points and pull-off forces vs the curve.
fn check(mu: f64, n: usize, samples: usize, verbose: bool) -> TabulatedLaw {
    let lj = LjSphere::from_tabor(mu).unwrap();
    let t0 = Instant::now();
    let t = TabulatedLaw::from_lj_sphere(&lj, n, 1e-4).unwrap();
    let build = t0.elapsed();
    assert_eq!(t.tolerance(), 1e-4);
    assert!(t.measured_error() <= t.tolerance());
    let s = lj.solver(n).unwrap();
    let c = s.curve().unwrap();
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    // Pull-off forces: the curve's, to ~1e-9.
    let po = t.pull_off_force(Control::Load).unwrap() / PI;
    assert!(
        rel(po, c.pull_off_load.force) < 1e-9,
        "{po} vs {:?}",
        c.pull_off_load
    );
    let mut rep = Report {
        worst: 0.0,
        worst_at: f64::NAN,
        count: 0,
    };
    let far0 = -6.0;
    // Deep end of the comparison: P̄ ≈ 9, inside the sampled range (the
    // table's last point is the first continuation point with P̄ ≥ 10).
    let deep = c.points.iter().find(|p| p.force >= 9.0).unwrap().approach;
    match (c.jump_in, c.jump_out) {
        (Some(ji), Some(jo)) => {
            assert_eq!(t.branch_count(), 2);
            let (lo0, hi0) = t.branch_range(0).unwrap();
            let (lo1, hi1) = t.branch_range(1).unwrap();
            assert!(lo0 == f64::NEG_INFINITY && hi1 == f64::INFINITY);
            assert!(
                rel(hi0, ji.approach) < 1e-9,
                "jump-in {hi0} vs {}",
                ji.approach
            );
            assert!(
                rel(lo1, jo.approach) < 1e-9,
                "jump-out {lo1} vs {}",
                jo.approach
            );
            let pd = t.pull_off_force(Control::Displacement).unwrap() / PI;
            assert!(rel(pd, c.pull_off_displacement.unwrap()) < 1e-9);
            // Far branch up to just below the jump-in.
            let eps = 1e-6;
            let start = s.solve_at_approach(far0, None).unwrap();
            let mut a = lin(far0, ji.approach - 0.02, samples);
            a.extend(lin(ji.approach - 0.02, ji.approach - eps, samples / 4));
            follow(&t, &s, start, &a, 0, &mut rep);
            // Contact branch from deep contact down to just above the jump-out.
            let start = s.solve_at_approach(deep, None).unwrap();
            let mut a = lin(deep, jo.approach + 0.02, samples);
            a.extend(lin(jo.approach + 0.02, jo.approach + eps, samples / 4));
            follow(&t, &s, start, &a, 1, &mut rep);
            // Hysteresis: approach from far, jump in past hi0, retract,
            // jump out below lo1.
            let mut st = ContactState::default();
            let mut seq = Vec::new();
            for al in [
                far0,
                hi0 - 1e-9,
                hi0 + 1e-9,
                0.0,
                lo1 + 1e-9,
                lo1 - 1e-9,
                far0,
            ] {
                let (r, ns) = t.eval(al, &st).unwrap();
                seq.push((ns.branch, ns.in_contact, r.contact_radius > 0.0));
                st = ns;
            }
            let br: Vec<i32> = seq.iter().map(|q| q.0).collect();
            assert_eq!(br, [0, 0, 1, 1, 1, 0, 0]);
            let ic: Vec<i32> = seq.iter().map(|q| q.1).collect();
            // The contact radius leaves zero after the jump-out on the contact
            // branch here (h̄₀ = 1 on the stable contact piece) for μ = 1.
            assert_eq!(&ic[..3], &[0, 0, 1]);
            assert_eq!(ic[6], 0);
        }
        (None, None) => {
            assert_eq!(t.branch_count(), 1);
            let start = s.solve_at_approach(far0, None).unwrap();
            let a = lin(far0, deep, 2 * samples);
            follow(&t, &s, start, &a, 0, &mut rep);
            let pd = t.pull_off_force(Control::Displacement).unwrap() / PI;
            assert!(pd < 0.0 && pd >= po);
        }
        _ => panic!("a single turning point"),
    }
    assert!(
        rep.worst <= t.tolerance(),
        "μ = {mu}: error {} at ᾱ = {}",
        rep.worst,
        rep.worst_at
    );
    // Far away: the rigid law, smoothly.
    for al in [-30.0, -100.0, -1000.0] {
        let (r, _) = t.eval(al, &ContactState::default()).unwrap();
        let want = PI * rigid_force_bar(al);
        assert!(rel(r.force, want) < 1e-4, "ᾱ = {al}: {} vs {want}", r.force);
        assert_eq!(r.contact_radius, 0.0);
    }
    if verbose {
        // Beyond the last point (outside the mesh's design range): report.
        let mut g = s.solve_at_approach(deep, None).unwrap();
        let mut dev = 0.0f64;
        for al in lin(deep, deep + 4.0, 40) {
            g = s.solve_at_approach(al, Some(&g)).unwrap();
            let (r, _) = t
                .eval(
                    al,
                    &ContactState {
                        branch: t.branch_count() as i32 - 1,
                        ..Default::default()
                    },
                )
                .unwrap();
            dev = dev.max(t.relative_error(&resp(&g), &r));
        }
        eprintln!(
            "μ = {mu}, N = {n}: build {build:?}, knots {}, {} bytes, measured {:.3e}, \
             worst vs solver {:.3e} at ᾱ = {:.4} over {} approaches; deep tail (to ᾱ = {:.2}) {:.2e}",
            t.knot_count(),
            t.memory_bytes(),
            t.measured_error(),
            rep.worst,
            rep.worst_at,
            rep.count,
            deep + 4.0,
            dev
        );
    }
    t
}

#[test]
fn s_shaped_mu_1_matches_solver_coarse_grid() {
    check(1.0, 96, 30, false);
}

#[test]
fn small_mu_matches_solver_coarse_grid() {
    check(0.1, 64, 40, false);
}

#[test]
fn mu_0_1_0_5_1_at_n128() {
    for mu in [0.1, 0.5, 1.0] {
        check(mu, 128, 400, true);
    }
    check(1.0, 96, 200, true);
}

/// Above μ = 1 the solver follows the contact edge on a moving mesh (neck
/// phase on a fixed mesh, then the edge phase, see `lj_sphere::edge`), so no
/// single fixed-grid solve reproduces its path: the table is checked against
/// every stable point of `LjSolver::curve` (the same discrete model), and
/// its jump and pull-off points against the curve's.
///
/// `folds`: the discrete model has small folds near the jump-out (kept as
/// extra branches), so the table has more than two branches and its
/// jump-out (the first turn met retracting from deep contact) need not be
/// the one `LjSolver::curve` reports.
fn check_edge_table(mu: f64, n: usize, folds: bool) {
    let lj = LjSphere::from_tabor(mu).unwrap();
    let t0 = Instant::now();
    let t = TabulatedLaw::from_lj_sphere(&lj, n, 1e-4).unwrap();
    let build = t0.elapsed();
    assert!(t.measured_error() <= t.tolerance());
    let nbr = t.branch_count();
    if folds {
        assert!(nbr >= 2, "μ = {mu}: {nbr} branches");
    } else {
        assert_eq!(nbr, 2, "μ = {mu}: one hysteresis loop");
    }
    let c = lj.solver(n).unwrap().curve().unwrap();
    let rel = |a: f64, b: f64| (a - b).abs() / b.abs();
    let po = t.pull_off_force(Control::Load).unwrap() / PI;
    if folds {
        // The force along the contact branch has several local minima
        // (lattice trapping of the coarse grid): the table pulls off at the
        // last one (first met retracting from deep contact), the curve
        // reports the lowest.
        assert!(
            po >= c.pull_off_load.force * (1.0 + 1e-7),
            "pull-off {po} below the curve's lowest force {:?}",
            c.pull_off_load
        );
    } else {
        assert!(
            rel(po, c.pull_off_load.force) < 1e-7,
            "pull-off {po} vs {:?}",
            c.pull_off_load
        );
    }
    let ji = c.jump_in.unwrap();
    let jo = c.jump_out.unwrap();
    let (_, hi0) = t.branch_range(0).unwrap();
    let (lo1, _) = t.branch_range(nbr - 1).unwrap();
    assert!(
        rel(hi0, ji.approach) < 1e-7,
        "jump-in {hi0} vs {}",
        ji.approach
    );
    if !folds {
        assert!(
            rel(lo1, jo.approach) < 1e-7,
            "jump-out {lo1} vs {}",
            jo.approach
        );
    }
    // Every stable curve point: the far piece before the jump-in and the
    // contact piece after the jump-out (the curve's points are ordered
    // along the path).
    let i_in = c
        .points
        .iter()
        .position(|p| p.approach >= ji.approach)
        .unwrap();
    // With folds: past the table's own jump-out (the folds before it are
    // other branches).
    let jump_out = if folds { lo1 } else { jo.approach };
    let i_out = c
        .points
        .iter()
        .rposition(|p| p.approach <= jump_out)
        .unwrap();
    let mut worst = (0.0f64, f64::NAN);
    let mut count = 0;
    for (i, p) in c.points.iter().enumerate() {
        let branch = if i < i_in {
            0
        } else if i > i_out && p.force <= 9.0 {
            nbr as i32 - 1
        } else {
            continue;
        };
        let st = ContactState {
            branch,
            ..Default::default()
        };
        let (r, _) = t.eval(p.approach, &st).unwrap();
        let want = NormalResponse {
            force: PI * p.force,
            delta: p.approach,
            contact_radius: p.contact_radius,
            ..Default::default()
        };
        let e = t.relative_error(&want, &r);
        count += 1;
        if e > worst.0 {
            worst = (e, p.approach);
        }
    }
    assert!(count > 100, "{count} points compared");
    assert!(
        worst.0 <= t.tolerance(),
        "μ = {mu}: error {} at ᾱ = {}",
        worst.0,
        worst.1
    );
    // Far away: the rigid law.
    for al in [-30.0 - 4.0 * mu, -1000.0] {
        let (r, _) = t.eval(al, &ContactState::default()).unwrap();
        let want = PI * rigid_force_bar(al);
        assert!(rel(r.force, want) < 1e-4, "ᾱ = {al}: {} vs {want}", r.force);
    }
    eprintln!(
        "μ = {mu}, N = {n}: build {build:?}, knots {}, measured {:.3e}, worst vs curve {:.3e} \
         at ᾱ = {:.4} over {count} points",
        t.knot_count(),
        t.measured_error(),
        worst.0,
        worst.1
    );
}

#[test]
fn above_mu_1_the_edge_continuation_is_tabulated() {
    check_edge_table(3.0, 64, false);
}

/// μ = 10 at N = 256: the contact radius jumps in the neck, and the neck
/// phase's fixed mesh leaves a small fold near the jump-in (three
/// branches). About 3 s in release. (Until session 13 the jump-out was a
/// corner of the edge family and the test took 20 s; it was ignored.)
#[test]
fn mu_10_at_n256_is_tabulated() {
    check_edge_table(10.0, 256, true);
}

/// μ = 10 on the library's default grid (N = 512): until session 13 its
/// sampled curve had 13 branches (spurious folds of the banded meshes) and
/// `from_curve` refused it after 5 min. About 20 s in release
/// (`cargo test --release --test tabulated_lj -- --ignored`).
#[test]
#[ignore]
fn mu_10_on_the_default_grid_is_tabulated() {
    check_edge_table(10.0, 0, true);
}

#[test]
fn serde_round_trip_is_bit_identical() {
    let lj = LjSphere::from_tabor(0.5).unwrap();
    let t = TabulatedLaw::from_lj_sphere(&lj, 48, 1e-3).unwrap();
    let j = t.to_json();
    let u = TabulatedLaw::from_json(&j).unwrap();
    assert_eq!(u.to_json(), j);
    let mut st = (ContactState::default(), ContactState::default());
    for al in lin(-20.0, 8.0, 700).into_iter().chain(lin(8.0, -20.0, 700)) {
        let (a, sa) = t.eval(al, &st.0).unwrap();
        let (b, sb) = u.eval(al, &st.1).unwrap();
        assert_eq!(a.force.to_bits(), b.force.to_bits());
        assert_eq!(a.contact_radius.to_bits(), b.contact_radius.to_bits());
        assert_eq!(a.stiffness.to_bits(), b.stiffness.to_bits());
        assert_eq!(sa, sb);
        st = (sa, sb);
    }
    // The curve round-trips too.
    let c = EquilibriumCurve::from_lj_sphere(&lj, 48, 1e-3).unwrap();
    assert_eq!(EquilibriumCurve::from_json(&c.to_json()).unwrap(), c);
}

/// At μ = 1 a grid of 64 cells does not resolve the edge zone well enough:
/// the contact branch dips again by ~1e-4 beyond its force minimum. The
/// table refuses that curve as too coarse (`NotConverged`, naming the grid),
/// not as an invalid argument the caller never passed, with the dip
/// relative to the pull-off force as the residual; 96 cells build.
#[test]
fn a_grid_too_coarse_for_the_pull_off_is_not_converged() {
    let lj = LjSphere::from_tabor(1.0).unwrap();
    match TabulatedLaw::from_lj_sphere(&lj, 64, 1e-4) {
        Err(Error::NotConverged { what, residual, .. }) => {
            assert!(what.contains("raise n_grid"), "{what}");
            assert!(residual > 1e-6 && residual < 1e-3, "{residual}");
        }
        other => panic!("{other:?}"),
    }
    assert!(TabulatedLaw::from_lj_sphere(&lj, 96, 1e-3).is_ok());
}

#[test]
fn invalid_arguments() {
    let lj = LjSphere::from_tabor(1.0).unwrap();
    assert!(TabulatedLaw::from_lj_sphere(&lj, 64, 0.0).is_err());
    assert!(TabulatedLaw::from_lj_sphere(&lj, 64, 0.5).is_err());
    assert!(TabulatedLaw::from_lj_sphere(&lj, 8, 1e-4).is_err());
    let rigid = LjSphere::from_tabor(0.0).unwrap();
    assert!(TabulatedLaw::from_lj_sphere(&rigid, 64, 1e-4).is_err());
}

#[test]
fn c_constructor() {
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
    // R = 1 µm, z0 = 0.3 nm, Δγ = 0.05 J/m², E* chosen for μ = 0.5.
    let (r0, w, z0): (f64, f64, f64) = (1e-6, 0.05, 3e-10);
    let e = (r0 * w * w / z0.powi(3)).sqrt() / 0.5f64.powf(1.5);
    unsafe {
        let mut t: *mut AsperityTable = null_mut();
        assert_eq!(
            asperity_table_new_lj(r0, e, w, z0, 48, 1e-3, null_mut()),
            ASPERITY_ERR_NULL_POINTER
        );
        assert!(msg().contains("out"));
        for (args, name) in [
            ((-r0, e, w, z0, 48, 1e-3), "radius"),
            ((r0, f64::NAN, w, z0, 48, 1e-3), "e_star"),
            ((r0, e, 0.0, z0, 48, 1e-3), "work_of_adhesion"),
            ((r0, e, w, -1.0, 48, 1e-3), "z0"),
            ((r0, e, w, z0, 48, 0.0), "tolerance"),
            ((r0, e, w, z0, 7, 1e-3), "n_grid"),
        ] {
            t = 1usize as *mut AsperityTable;
            let (a, b, c, d, n, tol) = args;
            assert_eq!(
                asperity_table_new_lj(a, b, c, d, n, tol, &mut t),
                ASPERITY_ERR_INVALID_ARGUMENT,
                "{name}"
            );
            assert!(t.is_null());
            assert!(msg().contains(name), "{name}: {}", msg());
        }
        assert_eq!(
            asperity_table_new_lj(r0, e, w, z0, 48, 1e-3, &mut t),
            ASPERITY_OK
        );
        assert!(!t.is_null());
        // Same as the Rust table.
        let lj = LjSphere::new(r0, e, w, z0).unwrap();
        assert!((lj.tabor() - 0.5).abs() < 1e-12);
        let rt = TabulatedLaw::from_lj_sphere(&lj, 48, 1e-3).unwrap();
        let mut r = NormalResponse::default();
        let mut s = ContactState::default();
        assert_eq!(
            asperity_table_eval(t, 0.5 * z0, null(), &mut s, &mut r),
            ASPERITY_OK
        );
        let (rr, ss) = rt.eval(0.5 * z0, &ContactState::default()).unwrap();
        assert_eq!(r.force.to_bits(), rr.force.to_bits());
        assert_eq!(s, ss);
        asperity_table_free(t);
    }
}
