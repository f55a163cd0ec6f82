//! Errors users can act on (issue 8 §6): every interface names the argument
//! as its caller wrote it, and a failed call loses or half-writes nothing.
//!
//! * C names: the C functions whose Rust counterpart names an argument
//!   differently translate the name (`sigma0`, `parameter`, `known_load`,
//!   `known_depth`, `known_radius`); the Rust API keeps its own names.
//! * Outputs on failure: sentinels in every output of a failing C call are
//!   unchanged (scalars, structs, states), constructors set the handle to
//!   NULL, and batch calls write exactly the elements before the failing one.
//! * The command line (`--features cli`): bad values, a missing file, a bad
//!   scene give exit status 1 and one line on stderr naming the argument or
//!   field, nothing on stdout and no output file; a malformed option gives
//!   clap's usage error (status 2). The messages printed here are the ones in
//!   RELIABILITY.md's table.

use asperity::contact::{ContactState, MaugisDugdale, NormalResponse};
use asperity::ffi::contact::*;
use asperity::ffi::homogenised::*;
use asperity::ffi::indentation::*;
use asperity::ffi::material::*;
use asperity::ffi::statistics::*;
use asperity::ffi::tabulated::*;
use asperity::ffi::*;
use asperity::rescaling::{KnownSolution, Rescaling};
use std::process::Command;
use std::ptr::{null, null_mut};

mod common;
use common::c_errors::last_message;
use common::{binary, manifest};

/// The status and message of a failing call; the message must name `name`.
#[track_caller]
fn fails_naming(st: i32, name: &str) -> String {
    assert_ne!(st, ASPERITY_OK, "expected a failure naming `{name}`");
    let m = last_message();
    assert!(m.contains(&format!("`{name}`")), "`{name}` not in: {m}");
    println!("{st:>3}  {m}");
    m
}

#[test]
fn c_errors_name_the_c_arguments() {
    let mut law = unsafe { core::mem::zeroed::<AsperityNormalLaw>() };
    // asperity_law_maugis_dugdale(radius, e_star, work_of_adhesion, sigma0, out)
    let m = fails_naming(
        unsafe { asperity_law_maugis_dugdale(1e-6, 1e11, 0.5, -1.0, &mut law) },
        "sigma0",
    );
    assert!(!m.contains("cohesive_stress"), "{m}");
    // λ above 1e8: the combination bound names sigma0 too.
    fails_naming(
        unsafe { asperity_law_maugis_dugdale(1e-6, 1e11, 0.5, 1e30, &mut law) },
        "sigma0",
    );
    let mut table = null_mut();
    fails_naming(
        unsafe { asperity_table_new_maugis_dugdale(1e-6, 1e11, 0.5, f64::NAN, 1e-4, &mut table) },
        "sigma0",
    );
    assert!(table.is_null());
    // asperity_law_derjaguin(radius, work_of_adhesion, surface_law, parameter, out)
    for surface in [
        ASPERITY_SURFACE_LAW_LENNARD_JONES,
        ASPERITY_SURFACE_LAW_DUGDALE,
        ASPERITY_SURFACE_LAW_EXPONENTIAL,
    ] {
        for p in [-1.0, 0.0, f64::NAN, f64::INFINITY] {
            let m = fails_naming(
                unsafe { asperity_law_derjaguin(1e-6, 0.1, surface, p, &mut law) },
                "parameter",
            );
            for rust in ["equilibrium_separation", "cohesive_stress", "decay_length"] {
                assert!(!m.contains(rust), "{m}");
            }
        }
    }
    // The rescaling calls: `known_load`, `known_depth`, `known_radius`, and
    // `load`/`depth` only for the argument of that name.
    let mut x = 0.0;
    fails_naming(
        unsafe { asperity_rescaling_depth(1.0, 2.0, 1.0, 1e-3, -1.0, 1e-6, &mut x) },
        "known_load",
    );
    fails_naming(
        unsafe { asperity_rescaling_depth(1.0, 2.0, 1.0, 1e-3, 1e-3, 0.0, &mut x) },
        "known_depth",
    );
    fails_naming(
        unsafe { asperity_rescaling_depth(1.0, 2.0, 1.0, -1e-3, 1e-3, 1e-6, &mut x) },
        "load",
    );
    fails_naming(
        unsafe { asperity_rescaling_radius(1.0, 2.0, 1.0, 1e-3, 1e-3, f64::NAN, &mut x) },
        "known_radius",
    );
    fails_naming(
        unsafe { asperity_rescaling_load(1.0, 2.0, 1.0, 1e-6, f64::INFINITY, 1e-6, &mut x) },
        "known_load",
    );
    fails_naming(
        unsafe { asperity_rescaling_load(1.0, 2.0, 1.0, -1e-6, 1e-3, 1e-6, &mut x) },
        "depth",
    );
    // Overflow of the rescaled value names the most extreme argument of the
    // call: κ = 10, d = 100 give P ∝ (δ/δ₁)^{9.92}, here (1e37)^{9.92}.
    let m = fails_naming(
        unsafe { asperity_rescaling_load(10.0, 100.0, 1.0, 1e-3, 1e-3, 1e-40, &mut x) },
        "known_depth",
    );
    assert!(m.starts_with("out of domain"), "{m}");

    // The Rust API keeps its own names.
    let e = MaugisDugdale::new(1e-6, 1e11, 0.5, -1.0).unwrap_err();
    assert!(e.to_string().contains("`cohesive_stress`"), "{e}");
    let e = KnownSolution::new(-1.0, 1e-6, 1.0).unwrap_err();
    assert!(e.to_string().contains("`load`"), "{e}");
    let k = KnownSolution::new(1e-3, 1e-40, 1.0).unwrap();
    let e = Rescaling::new(10.0, 100.0)
        .unwrap()
        .load(1.0, 1e-3, &k)
        .unwrap_err();
    assert!(e.to_string().contains("`known.depth`"), "{e}");
}

/// Results that used to leave `f64` with status OK (tests/sweeps.rs found
/// them) are now `ASPERITY_ERR_OUT_OF_DOMAIN` naming an argument, in C and
/// in Rust.
#[test]
fn overflowing_results_are_errors() {
    let mut x = -1.0;
    // A/(12πD₀²) with D₀² = 0.
    let m = fails_naming(
        unsafe { asperity_hamaker_work_of_adhesion(1e-19, 1e-200, &mut x) },
        "separation",
    );
    assert!(m.starts_with("out of domain"), "{m}");
    assert_eq!(x, -1.0);
    assert!(asperity::material::hamaker_work_of_adhesion(1e-19, 1e-200).is_err());
    // Weir: B = E/(3(1 − 2ν)) beyond f64.
    fails_naming(
        unsafe { asperity_weir_surface_energy(1e-26, 3500.0, 1e308, 0.4999, 6.0, 12.0, &mut x) },
        "youngs_modulus",
    );
    // (P/P₁)^{d/s} with κ = 0, d = 100: the power 50 of 1e10.
    fails_naming(
        unsafe { asperity_rescaling_depth(0.0, 100.0, 1.0, 1e3, 1e-7, 1e-6, &mut x) },
        "known_load",
    );
    // Greenwood–Williamson at a separation of −4e211 m.
    let gw = AsperityGwParams {
        distribution: ASPERITY_HEIGHTS_GAUSSIAN,
        reserved: 0,
        summit_count: 1e6,
        radius: 1e-5,
        sigma: 1e-7,
        e_star: 1e11,
    };
    let mut r = AsperityGwResponse {
        load: -1.0,
        ..Default::default()
    };
    fails_naming(
        unsafe { asperity_gw_eval(&gw, -4e211, &mut r) },
        "separation",
    );
    assert_eq!(r.load, -1.0);
    // Far above the summits: no contact, exactly (this took minutes before:
    // h² overflowed and the quadrature ran u32::MAX nodes).
    assert_eq!(unsafe { asperity_gw_eval(&gw, 1e200, &mut r) }, ASPERITY_OK);
    assert_eq!(
        (r.load, r.area, r.contacts, r.stiffness),
        (0.0, 0.0, 0.0, 0.0)
    );
}

#[test]
fn failed_calls_leave_outputs_untouched() {
    // Constructors of by-value laws: `out` keeps its bytes.
    let mut law = unsafe { core::mem::zeroed::<AsperityNormalLaw>() };
    assert_eq!(
        unsafe { asperity_law_hertz(1e-6, 1e11, &mut law) },
        ASPERITY_OK
    );
    let before: [u8; core::mem::size_of::<AsperityNormalLaw>()] =
        unsafe { core::mem::transmute_copy(&law) };
    fails_naming(
        unsafe { asperity_law_jkr(-1.0, 1e11, 0.1, &mut law) },
        "radius",
    );
    let after: [u8; core::mem::size_of::<AsperityNormalLaw>()] =
        unsafe { core::mem::transmute_copy(&law) };
    assert_eq!(before, after);

    // A single evaluation: response and new state untouched.
    let sentinel_r = NormalResponse {
        force: -7.5,
        delta: -7.5,
        contact_radius: -7.5,
        stiffness: -7.5,
        in_contact: 9,
        reserved: 9,
    };
    let sentinel_s = ContactState {
        contact_radius: -7.5,
        cohesive_radius: -7.5,
        branch: 9,
        in_contact: 9,
    };
    let (mut r, mut s) = (sentinel_r, sentinel_s);
    fails_naming(
        unsafe { asperity_normal_eval(&law, f64::NAN, null(), &mut s, &mut r) },
        "delta",
    );
    assert_eq!((r, s), (sentinel_r, sentinel_s));
    fails_naming(
        unsafe { asperity_normal_eval(&law, 1e300, null(), &mut s, &mut r) },
        "delta",
    );
    assert_eq!((r, s), (sentinel_r, sentinel_s));
    fails_naming(
        unsafe { asperity_normal_eval_at_load(&law, f64::NAN, &mut r) },
        "force",
    );
    assert_eq!(r, sentinel_r);
    let mut f = -7.5;
    fails_naming(
        unsafe { asperity_pull_off_force(&law, 7, &mut f) },
        "control",
    );
    assert_eq!(f, -7.5);

    // A batch: elements before the failing one written, the rest untouched.
    let delta = [1e-9, 2e-9, f64::NAN, 3e-9];
    let mut force = [-7.5; 4];
    let mut states = [sentinel_s; 4];
    let m = fails_naming(
        unsafe {
            asperity_normal_eval_batch(
                &law,
                4,
                delta.as_ptr(),
                null(),
                states.as_mut_ptr(),
                force.as_mut_ptr(),
                null_mut(),
                null_mut(),
            )
        },
        "delta",
    );
    assert!(m.starts_with("element 2: "), "{m}");
    for i in 0..2 {
        let mut one = NormalResponse::default();
        assert_eq!(
            unsafe { asperity_normal_eval(&law, delta[i], null(), null_mut(), &mut one) },
            ASPERITY_OK
        );
        assert_eq!(force[i], one.force);
        assert_ne!(states[i], sentinel_s);
    }
    assert_eq!(force[2..], [-7.5, -7.5]);
    assert_eq!(states[2..], [sentinel_s, sentinel_s]);

    // The same through the vectorised JKR batch (groups of sixteen): a bad
    // element in the second group.
    let mut jkr = unsafe { core::mem::zeroed::<AsperityNormalLaw>() };
    assert_eq!(
        unsafe { asperity_law_jkr(1e-6, 1e11, 0.1, &mut jkr) },
        ASPERITY_OK
    );
    let mut delta: Vec<f64> = (0..40).map(|i| (i as f64 - 10.0) * 1e-10).collect();
    delta[21] = f64::INFINITY;
    let mut force = vec![-7.5; 40];
    let mut radius = vec![-7.5; 40];
    let m = fails_naming(
        unsafe {
            asperity_normal_eval_batch(
                &jkr,
                40,
                delta.as_ptr(),
                null(),
                null_mut(),
                force.as_mut_ptr(),
                radius.as_mut_ptr(),
                null_mut(),
            )
        },
        "delta",
    );
    assert!(m.starts_with("element 21: "), "{m}");
    for i in 0..40 {
        if i < 21 {
            let mut one = NormalResponse::default();
            assert_eq!(
                unsafe { asperity_normal_eval(&jkr, delta[i], null(), null_mut(), &mut one) },
                ASPERITY_OK
            );
            assert_eq!(
                (force[i], radius[i]),
                (one.force, one.contact_radius),
                "{i}"
            );
        } else {
            assert_eq!((force[i], radius[i]), (-7.5, -7.5), "{i}");
        }
    }
    delta[21] = 0.0;

    // Handles: NULL on failure.
    let mut table = 1usize as *mut AsperityTable;
    fails_naming(
        unsafe { asperity_table_new_maugis_dugdale(-1e-6, 1e11, 0.5, 1e9, 1e-4, &mut table) },
        "radius",
    );
    assert!(table.is_null());
    let mut hf = 1usize as *mut AsperityHomogenisedFriction;
    fails_naming(
        unsafe { asperity_homogenised_friction_new(null(), 0, &mut hf) },
        "samples",
    );
    assert!(hf.is_null());
    let mut gw = 1usize as *mut AsperityGwEmpirical;
    let h = [0.0, f64::NAN];
    fails_naming(
        unsafe { asperity_gw_empirical_new(10.0, 1e-5, 1e11, 2, h.as_ptr(), null(), &mut gw) },
        "heights",
    );
    assert!(gw.is_null());
}

// ------------------------------------------------------------ the CLI

/// Runs the binary; returns (exit code, stdout, stderr).
fn cli(args: &[&str]) -> (i32, String, String) {
    let o = Command::new(binary())
        .args(args)
        .output()
        .expect("run asperity");
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

/// A failing command: exit status `code`, nothing on stdout, stderr naming
/// `expect`; prints the row for RELIABILITY.md.
#[track_caller]
fn cli_fails(args: &[&str], code: i32, expect: &str) -> String {
    let (c, out, err) = cli(args);
    assert_eq!(c, code, "asperity {args:?}: {err}");
    assert!(out.is_empty(), "asperity {args:?} printed: {out}");
    assert!(
        err.contains(expect),
        "asperity {args:?}: `{expect}` not in: {err}"
    );
    let first = err.lines().next().unwrap_or("");
    println!("{c}  asperity {}  →  {first}", args.join(" "));
    err
}

fn scratch(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("asperity-errors-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn cli_errors_name_the_argument() {
    let dir = scratch("cli");
    let csv = dir.join("lj.csv");
    let csv_s = csv.to_str().unwrap();
    // Bad values: the library's message, prefixed `asperity:`, status 1, and
    // no output file.
    let sphere = ["--e-star", "1e9", "--work-of-adhesion", "0.05"];
    let mut args = vec!["lj", "--radius=-1e-6", "--csv", csv_s];
    args.extend(sphere);
    cli_fails(
        &args,
        1,
        "invalid argument `radius` = -1e-6: must be finite and > 0",
    );
    assert!(!csv.exists(), "output written on failure");
    // Written with a space, a negative number reads as an option (clap):
    // usage error, status 2, naming the value.
    let mut args = vec!["lj", "--radius", "-1e-6"];
    args.extend(sphere);
    cli_fails(&args, 2, "unexpected argument '-1' found");
    let mut args = vec!["curve", "--radius", "1e-6", "--z0", "NaN"];
    args.extend(sphere);
    cli_fails(&args, 1, "`equilibrium_separation` = NaN");
    let mut args = vec!["lj", "--radius", "1e-6", "--work-of-adhesion=-0.05"];
    args.extend(["--e-star", "1e9"]);
    cli_fails(&args, 1, "`work_of_adhesion`");
    // A malformed number: clap's usage error, status 2.
    let mut args = vec!["lj", "--radius", "one"];
    args.extend(sphere);
    cli_fails(&args, 2, "invalid value 'one' for '--radius <RADIUS>'");
    // Missing files.
    cli_fails(
        &["profile", "/nonexistent/scan.csv"],
        1,
        "/nonexistent/scan.csv",
    );
    cli_fails(
        &["indent", "/nonexistent/curve.csv"],
        1,
        "/nonexistent/curve.csv",
    );
    cli_fails(
        &["slide", "/nonexistent/scene.json"],
        1,
        "/nonexistent/scene.json",
    );
    // A profile that is not numbers.
    let bad = dir.join("bad.csv");
    std::fs::write(&bad, "x z\n0 1\nfoo bar\n").unwrap();
    cli_fails(&["profile", bad.to_str().unwrap()], 1, "line 3");
    cli_fails(&["indent", bad.to_str().unwrap()], 1, "bad.csv: line");
    // Scenes: an unknown field, a negative load.
    let good =
        std::fs::read_to_string(manifest().join("examples/scenes/chapter6_copper.json")).unwrap();
    let scene = dir.join("unknown.json");
    std::fs::write(&scene, good.replacen("\"outputs\"", "\"output\"", 1)).unwrap();
    cli_fails(
        &["slide", scene.to_str().unwrap(), "--json"],
        1,
        "unknown field `output`",
    );
    let scene = dir.join("negative.json");
    std::fs::write(&scene, good.replace("\"load\": 0.18", "\"load\": -0.18")).unwrap();
    cli_fails(&["slide", scene.to_str().unwrap(), "--json"], 1, "load");
    let _ = std::fs::remove_dir_all(&dir);
}
