//! `asperity slide` (feature `cli`), run as a user would: the chapter-6
//! scene with `--json` (keys and ranges), the contact-area-against-load plot
//! (a load sweep, against separate library runs; per step at a fixed gap;
//! only with `--out`, and only with several loads), `--json` without `--out`
//! writing nothing but the JSON, the dynamic friction models a scene chooses
//! (the models' CSV, plot and summaries), and bad scenes (clear error, exit
//! code != 0).
//! The binary is found or built by `tests/common`.

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
    let want = [
        "chapter6_copper.csv",
        "chapter6_copper_cof.svg",
        "chapter6_copper_dissipation.svg",
    ];
    for f in want {
        assert!(out.join(f).is_file(), "{f}");
    }
    assert_eq!(
        v["files"].as_array().map(|f| f.len()),
        Some(want.len()),
        "{v}"
    );
    // No load sweep and one fixed load: the area against the load would be
    // one vertical column of points (issue 30 §5), so neither the plot nor
    // its JSON.
    assert!(!out.join("chapter6_copper_area_load.svg").exists());
    assert!(v.get("area_load").is_none(), "{v}");
    let csv = std::fs::read_to_string(out.join("chapter6_copper.csv")).unwrap();
    assert_eq!(csv.lines().count(), 101);
    assert!(csv.starts_with("position_m,"));
    // No friction models: nothing of them.
    assert!(v.get("friction_models").is_none(), "{v}");
    assert!(!out.join("chapter6_copper_models.csv").exists());
    assert!(!out.join("chapter6_copper_models_cof.svg").exists());
}

/// The example scene choosing LuGre, Maxwell-slip and Prandtl–Tomlinson:
/// the per-model keys of the JSON (against the library's run of the same
/// scene and the models' closed forms), the models' CSV (its
/// energy-dissipation column is the slide's μ) and the plot (one line per
/// model and one for the energy-dissipation model, the names in the
/// legend).
#[test]
fn dynamic_models_scene_writes_and_reports_every_model() {
    use asperity::scene::Scene;
    let out = tmp("models");
    let scene = manifest().join("examples/scenes/dynamic_models.json");
    let o = Command::new(binary())
        .arg("slide")
        .arg(&scene)
        .arg("--json")
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let models = v["friction_models"]
        .as_array()
        .unwrap_or_else(|| panic!("friction_models: {v}"));
    let s = Scene::from_file(&scene).unwrap();
    let run = s
        .build()
        .unwrap()
        .slide(s.sliding.distance, s.sliding.step)
        .unwrap();
    let tracks = s.run_friction_models(&run).unwrap();
    let names = [
        "LuGre",
        "Maxwell-slip 4",
        "Prandtl-Tomlinson",
        "Prandtl-Tomlinson two-spring",
        "Burridge-Knopoff 8 blocks",
    ];
    let keys = [
        "lugre",
        "maxwell_slip",
        "prandtl_tomlinson",
        "prandtl_tomlinson_two_spring",
        "burridge_knopoff",
    ];
    assert_eq!(models.len(), 5);
    for (k, m) in models.iter().enumerate() {
        assert_eq!(m["name"], names[k], "{m}");
        assert_eq!(m["model"], keys[k], "{m}");
        let t = &tracks[k].summary;
        for (key, want) in [
            ("mean_cof", t.mean_cof),
            ("static_cof", t.static_cof),
            ("mean_friction_force", t.mean_friction_force),
            ("dissipation", t.dissipation),
        ] {
            let got = m[key].as_f64().unwrap_or_else(|| panic!("{key}: {m}"));
            assert!(
                (got - want).abs() <= 1e-12 * want.abs(),
                "{key}: {got} vs {want}"
            );
        }
        assert_eq!(
            m["stick_slip_events"].as_u64(),
            Some(t.stick_slip_events as u64)
        );
    }
    // Closed forms: LuGre slides steadily on its Stribeck curve at 1 mm/s,
    // Maxwell-slip's static coefficient is the sum of its capacities, and
    // the Prandtl-Tomlinson tip slips once in each of the 5 lattice periods.
    let num = |k: usize, key: &str| models[k][key].as_f64().unwrap();
    let stribeck = 0.9 + 0.3 * (-1.0f64).exp();
    assert!((num(0, "static_cof") - stribeck).abs() < 1e-9);
    assert!((num(1, "static_cof") - 1.05).abs() < 1e-12);
    assert_eq!(models[0]["stick_slip_events"].as_u64(), Some(0));
    assert_eq!(models[1]["stick_slip_events"].as_u64(), Some(0));
    assert_eq!(models[2]["stick_slip_events"].as_u64(), Some(5));
    let files: Vec<&str> = v["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f.as_str().unwrap())
        .collect();
    for f in ["dynamic_models_models.csv", "dynamic_models_models_cof.svg"] {
        assert!(out.join(f).is_file(), "{f}");
        assert!(files.iter().any(|p| p.ends_with(f)), "{f} in {files:?}");
    }
    // The CSV: distance, the slide's μ, one μ per model.
    let csv = std::fs::read_to_string(out.join("dynamic_models_models.csv")).unwrap();
    let rows: Vec<Vec<&str>> = csv.lines().map(|l| l.split(',').collect()).collect();
    assert_eq!(
        rows[0],
        [
            "distance_m",
            "energy_dissipation",
            "LuGre",
            "Maxwell-slip 4",
            "Prandtl-Tomlinson",
            "Prandtl-Tomlinson two-spring",
            "Burridge-Knopoff 8 blocks"
        ]
    );
    assert_eq!(rows.len(), 101);
    let slide = std::fs::read_to_string(out.join("dynamic_models.csv")).unwrap();
    for (k, line) in slide.lines().skip(1).enumerate() {
        let cols: Vec<&str> = line.split(',').collect();
        assert_eq!(rows[k + 1][0], cols[0], "position {k}");
        assert_eq!(rows[k + 1][1], cols[4], "cof {k}");
        for (j, t) in tracks.iter().enumerate() {
            let mu: f64 = rows[k + 1][2 + j].parse().unwrap();
            assert_eq!(mu, t.steps[k].cof, "{k}, model {j}");
        }
    }
    // The plot: a line of every increment for each of the four, and the
    // legend (line samples of two points) naming them.
    let svg = std::fs::read_to_string(out.join("dynamic_models_models_cof.svg")).unwrap();
    let lines: Vec<usize> = svg
        .split("<polyline")
        .skip(1)
        .filter(|p| p.contains("stroke-width=\"2\""))
        .map(|p| {
            let pts = p.split("points=\"").nth(1).unwrap();
            pts[..pts.find('"').unwrap()].split_whitespace().count()
        })
        .collect();
    // One line per model and the energy-dissipation model, each with its
    // legend mark.
    let lines_wanted = names.len() + 1;
    assert_eq!(
        lines.iter().filter(|&&n| n == 100).count(),
        lines_wanted,
        "{lines:?}"
    );
    assert_eq!(
        lines.iter().filter(|&&n| n == 2).count(),
        lines_wanted,
        "{lines:?}"
    );
    for name in names.iter().chain(&["energy dissipation"]) {
        // plotters writes a text's content on a line of its own.
        assert!(svg.lines().any(|l| l.trim() == *name), "legend: {name}");
    }
}

/// Without `--json` the models' table follows the summary.
#[test]
fn dynamic_models_table_in_the_human_output() {
    let dir = tmp("models-human");
    let scene = manifest().join("examples/scenes/dynamic_models.json");
    let o = Command::new(binary())
        .current_dir(&dir)
        .arg("slide")
        .arg(&scene)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = String::from_utf8(o.stdout).unwrap();
    assert!(text.contains("friction models at 1.0000e-3 m/s"), "{text}");
    for name in [
        "energy dissipation",
        "LuGre",
        "Maxwell-slip 4",
        "Prandtl-Tomlinson",
        "Prandtl-Tomlinson two-spring",
        "Burridge-Knopoff 8 blocks",
    ] {
        assert!(
            text.lines().any(|l| l.trim_start().starts_with(name)),
            "{name}: {text}"
        );
    }
    assert!(
        text.contains("wrote ./dynamic_models_models_cof.svg"),
        "{text}"
    );
    assert!(dir.join("dynamic_models_models.csv").is_file());
}

/// The scene's `load_sweep` (Table 6-1 fractions): one slide per load, the
/// mean true contact area plotted against the load with its line and R²;
/// the points are those of separate library runs, R² is recomputed here.
#[test]
fn load_sweep_plots_area_against_load() {
    use asperity::friction::Loading;
    use asperity::scene::Scene;
    let out = tmp("sweep");
    let scene = manifest().join("examples/scenes/chapter6_load_sweep.json");
    let o = Command::new(binary())
        .arg("slide")
        .arg(&scene)
        .arg("--json")
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let a = &v["area_load"];
    assert_eq!(a["source"], "load_sweep", "{a}");
    let nums = |k: &str| -> Vec<f64> {
        a[k].as_array()
            .unwrap_or_else(|| panic!("area_load.{k}: {a}"))
            .iter()
            .map(|x| x.as_f64().unwrap())
            .collect()
    };
    let (loads, areas) = (nums("loads"), nums("areas"));
    let s = Scene::from_file(&scene).unwrap();
    let slider = s.build().unwrap();
    let fractions = [0.05, 0.11, 0.25, 0.45];
    assert_eq!(loads.len(), fractions.len());
    for (k, f) in fractions.iter().enumerate() {
        let load = f * slider.capacity();
        let run = slider
            .with_loading(Loading::FixedLoad { load })
            .unwrap()
            .slide(s.sliding.distance, s.sliding.step)
            .unwrap();
        assert!((loads[k] - load).abs() <= 1e-12 * load, "{k}");
        let want = run.summary.mean_true_contact_area;
        assert!((areas[k] - want).abs() <= 1e-12 * want, "{k}");
    }
    // R² of the least-squares line, from the points.
    let n = loads.len() as f64;
    let (mx, my) = (loads.iter().sum::<f64>() / n, areas.iter().sum::<f64>() / n);
    let (mut sxy, mut sxx, mut syy) = (0.0, 0.0, 0.0);
    for (x, y) in loads.iter().zip(&areas) {
        sxy += (x - mx) * (y - my);
        sxx += (x - mx) * (x - mx);
        syy += (y - my) * (y - my);
    }
    let r2 = sxy * sxy / (sxx * syy);
    let got = a["r_squared"].as_f64().unwrap();
    assert!((got - r2).abs() < 1e-12, "{got} vs {r2}");
    assert!((a["slope"].as_f64().unwrap() - sxy / sxx).abs() <= 1e-9 * sxy / sxx);
    // Thesis 6.5.3: the true contact area is linear in the load.
    assert!(r2 >= 0.95, "R^2 = {r2}");
    let svg = std::fs::read_to_string(out.join("chapter6_load_sweep_area_load.svg")).unwrap();
    assert!(
        svg.contains("<svg") && svg.contains("R²"),
        "{}",
        &svg[..200]
    );
}

/// `--json` without `--out` (issue 30 §5): the JSON object on stdout and
/// nothing else, no CSV, no SVG in the current directory (nor the area
/// plot's slides); with `--out` the same scene writes its files there.
#[test]
fn json_without_out_writes_nothing() {
    for scene in ["chapter6_load_sweep", "dynamic_models"] {
        let dir = tmp(&format!("no-out-{scene}"));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        let file = manifest().join(format!("examples/scenes/{scene}.json"));
        let o = Command::new(binary())
            .current_dir(&dir)
            .arg("slide")
            .arg(&file)
            .arg("--json")
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        assert!(v.get("area_load").is_none(), "{v}");
        assert_eq!(v["files"], serde_json::json!([]), "{v}");
        let left: Vec<_> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert!(left.is_empty(), "{scene}: --json alone wrote {left:?}");
        // With `--out` the files are there.
        let o = Command::new(binary())
            .current_dir(&dir)
            .arg("slide")
            .arg(&file)
            .args(["--json", "--out", "out"])
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        assert!(dir.join(format!("out/{scene}.csv")).is_file());
        assert!(dir.join(format!("out/{scene}_cof.svg")).is_file());
    }
}

/// The area-against-load plot needs several loads (issue 30 §5): a fixed
/// gap (the load varies along the slide) draws it from the steps; a sweep
/// of one load, like a fixed load without a sweep, draws nothing.
#[test]
fn area_load_plot_only_with_several_loads() {
    let copper =
        std::fs::read_to_string(manifest().join("examples/scenes/chapter6_copper.json")).unwrap();
    let fixed_load = r#""fixed_load": { "load": 0.18 }"#;
    assert!(copper.contains(fixed_load));
    let gap = copper.replace(fixed_load, r#""fixed_gap": { "position": 5e-7 }"#);
    let one = copper.replace(
        r#""outputs""#,
        r#""load_sweep": { "fractions": [0.25] }, "outputs""#,
    );
    let dir = tmp("several-loads");
    for (name, text, plotted) in [("gap", &gap, true), ("one_load", &one, false)] {
        let scene = dir.join(format!("{name}.json"));
        std::fs::write(&scene, text).unwrap();
        let out = dir.join(format!("out-{name}"));
        let _ = std::fs::remove_dir_all(&out);
        let o = Command::new(binary())
            .arg("slide")
            .arg(&scene)
            .arg("--json")
            .arg("--out")
            .arg(&out)
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        let svg = out.join(format!("{name}_area_load.svg"));
        assert_eq!(svg.is_file(), plotted, "{name}: {v}");
        assert_eq!(v.get("area_load").is_some(), plotted, "{name}: {v}");
        assert!(out.join(format!("{name}_cof.svg")).is_file(), "{name}");
        if plotted {
            let a = &v["area_load"];
            assert_eq!(a["source"], "steps", "{a}");
            let loads: Vec<f64> = a["loads"]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect();
            assert_eq!(loads.len(), 100);
            let (lo, hi) = loads
                .iter()
                .fold((f64::INFINITY, 0.0f64), |(l, h), &x| (l.min(x), h.max(x)));
            assert!(hi > 1.5 * lo, "the load varies at a fixed gap: {lo}..{hi}");
            assert!(a["r_squared"].as_f64().is_some(), "{a}");
        }
    }
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
    fails(
        "sweep",
        &good.replace(
            "\"outputs\"",
            "\"load_sweep\": { \"fractions\": [0.1, 1.5] }, \"outputs\"",
        ),
        "fractions",
    );
    fails(
        "sweep_empty",
        &good.replace(
            "\"outputs\"",
            "\"load_sweep\": { \"loads\": [] }, \"outputs\"",
        ),
        "load_sweep",
    );
    // Friction models: the velocity they need, a parameter by its path, an
    // unknown model.
    let models =
        std::fs::read_to_string(manifest().join("examples/scenes/dynamic_models.json")).unwrap();
    fails(
        "velocity",
        &models.replace(", \"velocity\": 1e-3", ""),
        "velocity",
    );
    fails(
        "sigma1",
        &models.replace("\"sigma1\": 100", "\"sigma1\": 1e6"),
        "`friction_models[0].lugre`",
    );
    fails(
        "sigma1_name",
        &models.replace("\"sigma1\": 100", "\"sigma1\": 1e6"),
        "sigma1",
    );
    fails(
        "bristle",
        &models.replace("\"maxwell_slip\"", "\"bristle\""),
        "unknown variant `bristle`",
    );
    let o = Command::new(binary())
        .args(["slide", "/nonexistent/scene.json"])
        .output()
        .unwrap();
    assert!(!o.status.success());
}
