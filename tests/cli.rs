//! The `asperity` command (feature `cli`), built by this test in its own
//! target directory and run as a user would: `curve` on a JKR-like sphere and
//! `indent --json` on the measured fused-silica curve when
//! `../shared/data/indentation` is present.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

fn manifest() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Build the binary once per test run; its own target dir keeps the
/// library artifacts the C-example tests link against untouched.
fn binary() -> &'static Path {
    static BIN: OnceLock<PathBuf> = OnceLock::new();
    BIN.get_or_init(|| {
        let target = manifest().join("target").join("cli-test");
        let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
        let out = Command::new(cargo)
            .current_dir(manifest())
            .args([
                "build",
                "--features",
                "cli",
                "--bin",
                "asperity",
                "--target-dir",
            ])
            .arg(&target)
            .output()
            .expect("run cargo build");
        assert!(
            out.status.success(),
            "cargo build --features cli failed:\n{}",
            String::from_utf8_lossy(&out.stderr)
        );
        target.join("debug").join("asperity")
    })
}

fn run(args: &[&str]) -> String {
    let out = Command::new(binary())
        .args(args)
        .output()
        .expect("run asperity");
    assert!(
        out.status.success(),
        "asperity {args:?} failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8(out.stdout).expect("utf-8")
}

#[test]
fn curve_reports_reference_pull_offs_and_writes_csv_and_svg() {
    let dir = manifest().join("target").join("cli-test").join("out");
    std::fs::create_dir_all(&dir).unwrap();
    let csv = dir.join("curve.csv");
    let svg = dir.join("curve.svg");
    let text = run(&[
        "curve",
        "--radius",
        "1e-6",
        "--e-star",
        "1e9",
        "--work-of-adhesion",
        "0.05",
        "--csv",
        csv.to_str().unwrap(),
        "--svg",
        svg.to_str().unwrap(),
    ]);
    // REFERENCE.md §8: DMT 3.14159e-7 N, JKR 2.35619e-7 N (load control),
    // μ = 4.52403.
    assert!(text.contains("Tabor mu = 4.52403"), "{text}");
    let row = |name: &str| -> Vec<f64> {
        let line = text.lines().find(|l| l.starts_with(name)).unwrap();
        line.split_whitespace()
            .skip(1)
            .map(|x| x.parse().unwrap())
            .collect()
    };
    assert!((row("DMT")[0] + 3.14159e-7).abs() < 1e-12);
    assert!((row("JKR")[0] + 2.35619e-7).abs() < 1e-12);
    assert!((row("JKR")[1] + 2.35619e-7 * 5.0 / 9.0).abs() < 1e-12);
    let csv_text = std::fs::read_to_string(&csv).unwrap();
    assert!(csv_text.starts_with("model,step,delta_m,force_N"));
    assert!(csv_text.lines().count() > 3 * 400);
    assert!(std::fs::read_to_string(&svg).unwrap().contains("<svg"));
}

#[test]
fn indent_json_on_measured_fused_silica() {
    let file = manifest()
        .join("..")
        .join("shared/data/indentation/fused_silica_berkovich_agilent_calibration_test001.csv");
    if !file.exists() {
        println!("SKIPPED: {} not present", file.display());
        return;
    }
    let text = run(&[
        "indent",
        file.to_str().unwrap(),
        "--indenter",
        "berkovich",
        "--area",
        "27.3136,152.6988585,-494.1823171",
        "--nu-sample",
        "0.18",
        "--json",
    ]);
    let v: serde_json::Value = serde_json::from_str(text.trim()).expect("one JSON object");
    for key in [
        "kappa",
        "kappa_stderr",
        "d",
        "d_stderr",
        "reduced_modulus",
        "hardness",
        "flags",
    ] {
        assert!(v.get(key).is_some(), "missing `{key}` in {text}");
    }
    // Fused silica: E_r ≈ 60–75 GPa and H ≈ 7–10 GPa (known E 72 GPa, H 9 GPa;
    // this curve gives ~10 % less, see the closing note of issue 4), unloading
    // exponent ≈ 1.24 as the thesis quotes (d ≈ 4.1).
    let er = v["reduced_modulus"].as_f64().unwrap();
    let h = v["hardness"].as_f64().unwrap();
    assert!((55e9..80e9).contains(&er), "E_r = {er}");
    assert!((7e9..10e9).contains(&h), "H = {h}");
    assert!((3.8..4.4).contains(&v["d"].as_f64().unwrap()));
    let flags: Vec<&str> = v["flags"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f.as_str().unwrap())
        .collect();
    assert!(
        flags.contains(&"sharp_indenter") && flags.contains(&"d_above_three"),
        "{flags:?}"
    );
}

#[test]
fn bad_indenter_is_a_clear_error() {
    let out = Command::new(binary())
        .args(["indent", "nonexistent.csv", "--indenter", "pyramid"])
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("unknown indenter `pyramid`"), "{err}");
}
