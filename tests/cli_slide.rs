//! `asperity slide` (feature `cli`), run as a user would: the chapter-6
//! scene with `--json` (keys and ranges), and bad scenes (clear error, exit
//! code != 0). The binary is found or built by `tests/common`.

use std::path::PathBuf;
use std::process::Command;

mod common;
use common::{binary, manifest};

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("asperity-cli-slide-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn chapter6_scene_json() {
    let out = tmp("ch6");
    let scene = manifest().join("examples/scenes/chapter6_copper.json");
    let o = Command::new(binary())
        .arg("slide")
        .arg(&scene)
        .arg("--json")
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8(o.stdout).unwrap();
    assert_eq!(
        text.trim().lines().count(),
        1,
        "exactly one JSON object: {text}"
    );
    let v: serde_json::Value = serde_json::from_str(text.trim()).unwrap();
    let num = |k: &str| v[k].as_f64().unwrap_or_else(|| panic!("missing {k}: {v}"));
    assert_eq!(v["steps"].as_u64(), Some(100));
    assert!((num("normal_load") - 0.18).abs() < 1e-9);
    let mu = num("mean_cof");
    assert!(mu > 0.5 && mu < 2.0, "{mu}");
    let f = num("mean_friction_force");
    assert!((f / 0.18 - mu).abs() < 0.5);
    let a = num("mean_true_contact_area");
    assert!(a > 0.0 && a < 1822.5e-12);
    let d = &v["dissipation"];
    let parts: Vec<f64> = ["chemical", "van_der_waals", "elastic", "plastic"]
        .iter()
        .map(|k| d[k].as_f64().unwrap_or_else(|| panic!("dissipation.{k}")))
        .collect();
    assert!(parts.iter().all(|x| *x >= 0.0));
    assert!(parts[0] > parts[1] + parts[2] + parts[3]);
    for f in [
        "chapter6_copper.csv",
        "chapter6_copper_cof.svg",
        "chapter6_copper_dissipation.svg",
    ] {
        assert!(out.join(f).is_file(), "{f}");
    }
    let csv = std::fs::read_to_string(out.join("chapter6_copper.csv")).unwrap();
    assert_eq!(csv.lines().count(), 101);
    assert!(csv.starts_with("position_m,"));
}

fn fails(name: &str, text: &str, expect: &str) {
    let d = tmp(name);
    let p = d.join("scene.json");
    std::fs::write(&p, text).unwrap();
    let o = Command::new(binary())
        .arg("slide")
        .arg(&p)
        .arg("--json")
        .output()
        .unwrap();
    assert!(!o.status.success(), "{name} should fail");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains(expect), "{name}: {err}");
    assert!(o.stdout.is_empty(), "{name}: no JSON on failure");
}

#[test]
fn bad_scenes_fail_clearly() {
    let good =
        std::fs::read_to_string(manifest().join("examples/scenes/chapter6_copper.json")).unwrap();
    fails("syntax", "{", "invalid scene");
    fails(
        "unknown",
        &good.replacen("\"outputs\"", "\"output\"", 1),
        "unknown field `output`",
    );
    fails(
        "step",
        &good.replace("\"step\": 1.5e-6", "\"step\": -1"),
        "step",
    );
    fails(
        "load",
        &good.replace("\"load\": 0.18", "\"load\": 99"),
        "load",
    );
    fails(
        "file",
        &good.replacen(
            "{ \"hurst\": 0.8, \"rq\": 5e-7, \"roll_off_wavelength\": 1e-4, \"points\": 91, \"dx\": 1.5e-6, \"seed\": 6 }",
            "{ \"path\": \"missing.csv\" }",
            1,
        ).replacen("\"self_affine\": { \"path", "\"file\": { \"path", 1),
        "missing.csv",
    );
    let o = Command::new(binary())
        .args(["slide", "/nonexistent/scene.json"])
        .output()
        .unwrap();
    assert!(!o.status.success());
}
