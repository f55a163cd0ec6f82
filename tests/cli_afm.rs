//! `asperity afm` (feature `cli`), run as a user would: `--json` with the
//! keys the issue fixes on a synthetic JKR curve written here (always) and on
//! the measured SiN curve of `../shared/data/afm` (skipped when absent),
//! `--svg PREFIX`, and the error messages.

use std::path::PathBuf;
use std::process::Command;

mod common;
use common::{binary, manifest};

fn scratch(name: &str) -> PathBuf {
    let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("cli-afm")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn run(args: &[&str]) -> std::process::Output {
    Command::new(binary())
        .args(args)
        .output()
        .expect("run asperity")
}

/// A JKR curve (R = 50 nm, E* = 0.5 GPa, w = 0.5 J/m², k = 40 N/m) in the
/// data format: deflection column, metadata line, segment labels, position
/// decreasing towards the sample.
fn write_jkr_csv(path: &PathBuf) {
    use asperity::contact::{Control, Jkr, NormalContact};
    let law = Jkr::new(50e-9, 0.5e9, 0.5).unwrap();
    let pc = law.pull_off_force(Control::Load).unwrap();
    let k = 40.0;
    let branch = |f: f64| {
        let f = if f <= pc { pc * (1.0 - 1e-9) } else { f };
        1e-6 + law.eval_at_load(f).unwrap().delta + f / k
    };
    let mut rows = Vec::new();
    let u0 = branch(0.0);
    for i in 0..400 {
        rows.push((u0 - 200e-9 + 200e-9 * i as f64 / 400.0, 0.0, "approach"));
    }
    for i in 0..150 {
        let f = 200e-9 * i as f64 / 149.0;
        rows.push((branch(f), f, "approach"));
    }
    for i in 0..300 {
        let f = 200e-9 + (pc - 200e-9) * i as f64 / 299.0;
        rows.push((branch(f), f, "retract"));
    }
    let upo = rows.last().unwrap().0;
    for i in 1..=400 {
        rows.push((upo - 200e-9 * i as f64 / 400.0, 0.0, "retract"));
    }
    let mut s = String::from(
        "# synthetic JKR curve\n# spring_constant_N_per_m=40\nheight_measured_m,deflection_m,segment\n",
    );
    for (i, (u, f, seg)) in rows.iter().enumerate() {
        let x = ((i as f64 * 12.9898).sin() * 43758.5453).fract();
        let raw = f + 0.2e-9 * (2.0 * x - 1.0) * 3f64.sqrt() - 30e-9;
        s.push_str(&format!("{:.12e},{:.12e},{seg}\n", -u, raw / k));
    }
    std::fs::write(path, s).unwrap();
}

fn json(out: &std::process::Output) -> serde_json::Value {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("one JSON object")
}

/// The keys the issue fixes.
fn check_contract(v: &serde_json::Value, radius_known: bool) {
    for key in [
        "pull_off_force",
        "jump_in_distance",
        "adhesion_energy",
        "contact_point",
        "recommended_model",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    assert!(v["pull_off_force"].as_f64().unwrap() < 0.0);
    assert!(v["baseline"]["offset"].is_f64() && v["baseline"]["slope"].is_f64());
    let fits = v["fits"].as_array().unwrap();
    assert!(!fits.is_empty());
    for f in fits {
        assert!(f["model"].is_string() && f["rms_residual"].is_f64());
        for key in [
            "e_star",
            "e_star_stderr",
            "work_of_adhesion",
            "work_of_adhesion_stderr",
        ] {
            assert!(f.get(key).is_some(), "missing {key}");
        }
        if f["model"] != "hertz" {
            let wr = &f["work_of_adhesion_times_radius"];
            assert!(wr.is_f64(), "{f}");
            assert!(
                f["work_of_adhesion_times_radius_stderr"].is_f64()
                    || !f["converged"].as_bool().unwrap()
            );
            assert_eq!(f["work_of_adhesion"].is_f64(), radius_known);
        }
        assert_eq!(f["e_star"].is_f64(), radius_known);
    }
}

#[test]
fn afm_json_on_a_synthetic_jkr_curve() {
    let dir = scratch("jkr");
    let csv = dir.join("jkr.csv");
    write_jkr_csv(&csv);
    let prefix = dir.join("jkr");
    let v = json(&run(&[
        "afm",
        csv.to_str().unwrap(),
        "--tip-radius",
        "50e-9",
        "--json",
        "--svg",
        prefix.to_str().unwrap(),
    ]));
    check_contract(&v, true);
    // Auto at μ ≈ 12: the four closed forms, the LJ sphere skipped.
    assert_eq!(v["fits"].as_array().unwrap().len(), 4);
    assert_eq!(v["skipped_fits"][0][0], "lj");
    assert_eq!(v["recommended_model"], "jkr");
    // JKR pull-off −(3/2)πwR = −117.81 nN.
    let po = v["pull_off_force"].as_f64().unwrap();
    assert!((po + 117.81e-9).abs() < 1e-9, "{po}");
    let jkr = v["fits"]
        .as_array()
        .unwrap()
        .iter()
        .find(|f| f["model"] == "jkr")
        .unwrap();
    let (e, se) = (
        jkr["e_star"].as_f64().unwrap(),
        jkr["e_star_stderr"].as_f64().unwrap(),
    );
    assert!((e - 0.5e9).abs() <= 3.0 * se, "E* {e} ± {se}");
    let (w, sw) = (
        jkr["work_of_adhesion"].as_f64().unwrap(),
        jkr["work_of_adhesion_stderr"].as_f64().unwrap(),
    );
    assert!((w - 0.5).abs() <= 3.0 * sw, "w {w} ± {sw}");
    let svg = std::fs::read_to_string(dir.join("jkr-afm.svg")).expect("the plot");
    for label in [
        "baseline",
        "contact point",
        "jkr fit",
        "dmt fit",
        "maugis_dugdale fit",
    ] {
        assert!(svg.contains(label), "plot lacks {label}");
    }

    // One model, unknown radius: the products.
    let v = json(&run(&[
        "afm",
        csv.to_str().unwrap(),
        "--model",
        "dmt",
        "--json",
    ]));
    assert_eq!(v["fits"].as_array().unwrap().len(), 1);
    assert!(v["fits"][0]["e_star"].is_null());
    assert!(v["fits"][0]["work_of_adhesion_times_radius"].is_f64());
    assert!(v["flags"]
        .as_array()
        .unwrap()
        .iter()
        .any(|f| f == "radius_unknown"));

    // The report names the recommended model.
    let out = run(&["afm", csv.to_str().unwrap(), "--tip-radius", "50e-9"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("recommended model    jkr"), "{text}");
}

#[test]
fn afm_model_lj_json_and_plot() {
    // The JKR curve (μ ≈ 12) with `--model lj`: the contract keys, the
    // Lennard-Jones sphere close to JKR's E*, w, its curve on the plot; the
    // text report of auto names the skipped fit.
    let dir = scratch("lj");
    let csv = dir.join("jkr.csv");
    write_jkr_csv(&csv);
    let prefix = dir.join("lj");
    let v = json(&run(&[
        "afm",
        csv.to_str().unwrap(),
        "--tip-radius",
        "50e-9",
        "--model",
        "lj",
        "--json",
        "--svg",
        prefix.to_str().unwrap(),
    ]));
    check_contract(&v, true);
    let fits = v["fits"].as_array().unwrap();
    assert_eq!(fits.len(), 1);
    let lj = &fits[0];
    assert_eq!(lj["model"], "lj");
    assert_eq!(v["recommended_model"], "lj");
    let e = lj["e_star"].as_f64().unwrap();
    let w = lj["work_of_adhesion"].as_f64().unwrap();
    assert!(
        (e / 0.5e9 - 1.0).abs() < 0.1 && (w / 0.5 - 1.0).abs() < 0.1,
        "{lj}"
    );
    for key in [
        "e_star_stderr",
        "work_of_adhesion_stderr",
        "work_of_adhesion_times_radius",
        "rms_residual",
        "tabor_parameter",
    ] {
        assert!(lj[key].as_f64().unwrap().is_finite(), "{key}");
    }
    let svg = std::fs::read_to_string(dir.join("lj-afm.svg")).expect("the plot");
    assert!(svg.contains("lj fit"));
    let out = run(&["afm", csv.to_str().unwrap(), "--tip-radius", "50e-9"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("lj              not fitted by auto"),
        "{text}"
    );
}

#[test]
fn afm_errors_are_one_line_messages() {
    let out = run(&["afm", "no-such-file.csv"]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("no-such-file.csv"), "{err}");
    let dir = scratch("errors");
    let csv = dir.join("jkr.csv");
    write_jkr_csv(&csv);
    let out = run(&["afm", csv.to_str().unwrap(), "--model", "foo"]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("unknown model `foo`"));
    let out = run(&["afm", csv.to_str().unwrap(), "--tip-radius=-1"]);
    assert!(String::from_utf8_lossy(&out.stderr).contains("tip_radius"));
}

#[test]
fn afm_json_on_the_measured_sin_curve() {
    let p = manifest().join("../shared/data/afm/afm_force_curve_asylum_mfp3d_SiN.csv");
    if !p.exists() {
        common::skip(format_args!("{} is not present", p.display()));
        return;
    }
    let v = json(&run(&["afm", p.to_str().unwrap(), "--json"]));
    check_contract(&v, false);
    // README: ≈ 12.9 nN above the baseline.
    let po = v["pull_off_force"].as_f64().unwrap();
    assert!((po / -12.9e-9 - 1.0).abs() < 0.02, "{po}");
    assert!(v["jump_in_distance"].as_f64().unwrap() > 0.0);
}
