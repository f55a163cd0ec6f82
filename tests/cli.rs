//! The `asperity` command (feature `cli`), run as a user would: `curve` on a
//! JKR-like sphere, `indent --json` on the measured fused-silica curve when
//! `../shared/data/indentation` is present, and `profile` on a sine written
//! here and on every measured profile in `../shared/data/profiles`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

mod common;
use common::{binary, manifest};

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
        common::skip(format_args!(
            "{} is not present (the measured data live outside the project, in \
             ../shared/data next to the crate)",
            file.display()
        ));
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
    // Fused silica against diamond: E_r = 69.6 GPa (E = 72 GPa, ν = 0.17,
    // Oliver & Pharr 1992) within the 11.6 % this file's tip calibration
    // allows (tests/indentation.rs, `fused_silica_tolerance`), H ≈ 7–10 GPa
    // (known 9 GPa), unloading exponent ≈ 1.24 as the thesis quotes (d ≈ 4.1).
    let er = v["reduced_modulus"].as_f64().unwrap();
    let h = v["hardness"].as_f64().unwrap();
    assert!((61.5e9..77.7e9).contains(&er), "E_r = {er}");
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

// ------------------------------------------------------------------ profile

/// A fresh scratch directory for one test.
fn scratch(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("cli-profile")
        .join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn profile(args: &[&str]) -> Output {
    Command::new(binary())
        .arg("profile")
        .args(args)
        .output()
        .expect("run asperity profile")
}

fn profile_json(args: &[&str]) -> serde_json::Value {
    let mut all = args.to_vec();
    all.push("--json");
    let out = profile(&all);
    assert!(
        out.status.success(),
        "asperity profile {all:?} failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(text.trim().lines().count(), 1, "one JSON line: {text}");
    serde_json::from_str(text.trim()).expect("one JSON object")
}

/// Writes `x,z` lines (m) with a header, as the shared line scans.
fn write_profile(path: &Path, dx: f64, z: &[f64], x_offset: f64) {
    use std::fmt::Write;
    let mut s = String::from("x_m,z_m\n");
    for (j, v) in z.iter().enumerate() {
        writeln!(s, "{:.17e},{v:.17e}", (j as f64 + x_offset) * dx).unwrap();
    }
    std::fs::write(path, s).unwrap();
}

/// z = A sin(2πx/Λ) over `periods` whole periods of `per_period` samples,
/// sampled at x = (j + ½)·dx (no sample sits exactly on a zero crossing).
fn write_sine(path: &Path, a: f64, lambda: f64, periods: usize, per_period: usize) {
    let dx = lambda / per_period as f64;
    let z: Vec<f64> = (0..periods * per_period)
        .map(|j| a * (2.0 * std::f64::consts::PI * (j as f64 + 0.5) * dx / lambda).sin())
        .collect();
    write_profile(path, dx, &z, 0.5);
}

fn num(v: &serde_json::Value, key: &str) -> f64 {
    v.get(key)
        .and_then(|x| x.as_f64())
        .unwrap_or_else(|| panic!("`{key}` missing or not a number in {v}"))
}

fn assert_rel(got: f64, want: f64, tol: f64, what: &str) {
    assert!(
        ((got - want) / want).abs() <= tol,
        "{what}: got {got:e}, want {want:e} (relative tolerance {tol:e})"
    );
}

const ISO_KEYS: [&str; 11] = [
    "Rp",
    "Rv",
    "Rz",
    "Rt",
    "Ra",
    "Rq",
    "Rsk",
    "Rku",
    "RSm",
    "RDq",
    "psd_hurst_exponent",
];

#[test]
fn profile_json_of_a_sine_matches_closed_forms() {
    let dir = scratch("sine");
    let file = dir.join("sine.csv");
    let (a, lambda, periods) = (2e-6, 50e-6, 8);
    write_sine(&file, a, lambda, periods, 1000);
    let v = profile_json(&[file.to_str().unwrap(), "--detrend", "none"]);
    for key in ISO_KEYS.iter().chain(&[
        "points",
        "dx",
        "length",
        "m0",
        "m2",
        "m4",
        "nayak_alpha",
        "m0_rectangular_window",
        "m2_rectangular_window",
        "m4_rectangular_window",
        "nayak_alpha_rectangular_window",
        "psd_fit_reason",
        "sampling_length",
        "sampling_lengths",
    ]) {
        assert!(v.get(*key).is_some(), "missing `{key}` in {v}");
    }
    assert_eq!(v["kind"], "profile");
    assert_eq!(v["detrend"], "none");
    assert!(v["cutoff"].is_null());
    assert_eq!(v["points"], 8000);
    assert_eq!(v["sampling_lengths"], 1);
    assert_rel(num(&v, "dx"), lambda / 1000.0, 1e-12, "dx");
    assert_rel(num(&v, "length"), periods as f64 * lambda, 1e-12, "length");
    let pi = std::f64::consts::PI;
    // Sample means over whole periods: Rq, Rku and Rsk are exact. Ra, the
    // mean of |z| at the midpoints of M = 500 samples per half period, is
    // (2A/π)·(π/2M)/sin(π/2M) = (2A/π)(1 + 1.6e-6).
    let m = 500.0;
    assert_rel(num(&v, "Ra"), 2.0 * a / pi, 2e-6, "Ra = 2A/π");
    let ra_sampled = a / (m * (pi / (2.0 * m)).sin());
    assert_rel(num(&v, "Ra"), ra_sampled, 1e-12, "Ra of the samples");
    assert_rel(num(&v, "Rq"), a / 2f64.sqrt(), 1e-12, "Rq = A/√2");
    assert!(num(&v, "Rsk").abs() < 1e-12, "Rsk = {}", v["Rsk"]);
    assert_rel(num(&v, "Rku"), 1.5, 1e-12, "Rku = 1.5");
    assert_rel(
        num(&v, "RDq"),
        2f64.sqrt() * pi * a / lambda,
        1e-7,
        "RΔq = √2πA/Λ",
    );
    assert_rel(num(&v, "RSm"), lambda, 1e-10, "RSm = Λ");
    // The samples nearest the crests are half a spacing off them.
    let crest = 2.0 * a * (pi / (2.0 * m)).cos();
    assert_rel(num(&v, "Rt"), crest, 1e-12, "Rt = 2A cos(π/2M)");
    assert_rel(num(&v, "Rz"), crest, 1e-12, "Rz = Rt");
    assert_rel(num(&v, "Rp"), num(&v, "Rv"), 1e-12, "Rp = Rv");
    // A line spectrum is no power law.
    assert!(v["psd_hurst_exponent"].is_null(), "{v}");
    assert!(v["psd_fit"].is_null(), "{v}");
    // Whole periods are periodic: the rectangular window is exact.
    // Parseval: m0 = Rq²; a single line: m2 = Rq²(2π/Λ)², α = 1.
    let q2 = (2.0 * pi / lambda).powi(2);
    assert_rel(
        num(&v, "m0_rectangular_window"),
        a * a / 2.0,
        1e-10,
        "m0 = Rq²",
    );
    assert_rel(
        num(&v, "m2_rectangular_window"),
        a * a / 2.0 * q2,
        1e-10,
        "m2",
    );
    assert_rel(
        num(&v, "nayak_alpha_rectangular_window"),
        1.0,
        1e-9,
        "Nayak α of a sine",
    );
    // From the derivatives: the same to the stencils' errors ((qdx)²/12 =
    // 3e-6 for the curvature at 1000 samples a period) and the two end
    // samples the second difference leaves out (n/(n − 2) − 1 = 2.5e-4).
    assert_rel(num(&v, "m0"), a * a / 2.0, 1e-10, "m0 = Rq²");
    assert_rel(num(&v, "m2"), a * a / 2.0 * q2, 1e-4, "m2 from the slopes");
    assert_rel(num(&v, "m4"), a * a / 2.0 * q2 * q2, 5e-4, "m4");
    assert_rel(num(&v, "nayak_alpha"), 1.0, 5e-4, "Nayak α of a sine");
    assert!(v["psd_fit_reason"].is_string(), "{v}");
    assert!(v["plots"].as_array().unwrap().is_empty());
}

#[test]
fn profile_table_and_svg_plots() {
    let dir = scratch("plots");
    let file = dir.join("sine.csv");
    write_sine(&file, 1e-7, 20e-6, 10, 200);
    let prefix = dir.join("out");
    let out = profile(&[
        file.to_str().unwrap(),
        "--detrend",
        "none",
        "--svg",
        prefix.to_str().unwrap(),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let table = String::from_utf8(out.stdout).unwrap();
    // Aligned rows `name value unit description`, heights in a common unit.
    let row = |name: &str| -> Vec<String> {
        table
            .lines()
            .find(|l| l.split_whitespace().next() == Some(name))
            .unwrap_or_else(|| panic!("no `{name}` row in\n{table}"))
            .split_whitespace()
            .map(String::from)
            .collect()
    };
    assert_eq!(row("Rq")[2], "nm", "{table}");
    let rq: f64 = row("Rq")[1].parse().unwrap();
    assert!((rq - 70.71).abs() < 0.01, "Rq = {rq} nm\n{table}");
    assert_eq!(row("RSm")[2], "µm", "{table}");
    let col = |name: &str| {
        table
            .lines()
            .find(|l| l.trim_start().starts_with(name))
            .unwrap()
            .find(" nm")
            .unwrap()
    };
    assert_eq!(col("Ra "), col("Rq "), "value columns aligned:\n{table}");
    let labels: [(&str, &[&str]); 4] = [
        (
            "-profile.svg",
            &["position x / µm", "height z / nm", "mean line"],
        ),
        ("-acf.svg", &["lag δ / µm", "ACF R(δ) / R(0)"]),
        ("-psd.svg", &["wavenumber q / (rad/m)", "PSD G(q) / m³"]),
        (
            "-material-ratio.svg",
            &[
                "material ratio Rmr / %",
                "height c (from the mean line) / nm",
            ],
        ),
    ];
    for (suffix, wanted) in labels {
        let path = dir.join(format!("out{suffix}"));
        let svg = std::fs::read_to_string(&path)
            .unwrap_or_else(|e| panic!("{}: {e}\n{table}", path.display()));
        assert!(
            svg.starts_with("<svg"),
            "{suffix}: {}",
            &svg[..80.min(svg.len())]
        );
        assert!(svg.trim_end().ends_with("</svg>"), "{suffix} not closed");
        for w in wanted {
            assert!(svg.contains(w), "{suffix} lacks the label `{w}`");
        }
        assert!(table.contains(path.to_str().unwrap()), "{table}");
    }
    // A directory as PREFIX: the file's stem inside it.
    let v = profile_json(&[file.to_str().unwrap(), "--svg", dir.to_str().unwrap()]);
    let plots: Vec<&str> = v["plots"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p.as_str().unwrap())
        .collect();
    assert_eq!(plots.len(), 4, "{plots:?}");
    assert!(plots[0].ends_with("sine-profile.svg"), "{plots:?}");
    assert!(plots.iter().all(|p| Path::new(p).exists()));
}

#[test]
fn profile_of_a_long_self_affine_scan_fits_hurst_and_decimates_plots() {
    use asperity::surface::SelfAffine;
    let dir = scratch("large");
    let file = dir.join("self_affine.csv");
    let n = 200_000;
    let dx = 1e-8;
    let p = SelfAffine::new(0.8, 1e-7)
        .unwrap()
        .profile(n, dx, 7)
        .unwrap();
    write_profile(&file, dx, p.heights(), 0.0);
    let prefix = dir.join("sa");
    let v = profile_json(&[file.to_str().unwrap(), "--svg", prefix.to_str().unwrap()]);
    assert_eq!(v["points"], n);
    // The end-matched, weighted fit over the band from the data scatters by
    // ±0.005 at 2^16 points (tests/surface_topography.rs); the Hann fit over
    // a fixed band read 0.750 here.
    let h = num(&v, "psd_hurst_exponent");
    assert!((h - 0.8).abs() < 0.02, "H = {h}");
    let u = num(&v, "psd_hurst_uncertainty");
    assert!(u > 0.0 && u < 0.01, "± {u}");
    assert!(v["psd_fit"]["r_squared"].as_f64().unwrap() > 0.9, "{v}");
    assert!(v["psd_fit_reason"].is_null(), "{v}");
    assert_rel(num(&v, "Rq").powi(2), num(&v, "m0"), 1e-9, "Rq² = m0");
    for suffix in [
        "-profile.svg",
        "-acf.svg",
        "-psd.svg",
        "-material-ratio.svg",
    ] {
        let path = dir.join(format!("sa{suffix}"));
        let size = std::fs::metadata(&path).unwrap().len();
        // 200 000 points drawn one by one would take several MB.
        assert!(size < 300_000, "{suffix}: {size} bytes, not decimated");
    }
    let psd = std::fs::read_to_string(dir.join("sa-psd.svg")).unwrap();
    assert!(
        psd.contains("power law G ∝ q^"),
        "the fitted power law is drawn"
    );
}

fn assert_fails(args: &[&str], message: &str) {
    let out = profile(args);
    assert!(!out.status.success(), "{args:?} succeeded");
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains(message),
        "{args:?}: stderr `{err}` lacks `{message}`"
    );
    assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    assert!(err.starts_with("asperity: "), "{err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn profile_errors_are_one_line_messages() {
    let dir = scratch("errors");
    let missing = dir.join("missing.csv");
    assert_fails(&[missing.to_str().unwrap()], "cannot read");
    let garbage = dir.join("garbage.csv");
    std::fs::write(&garbage, "x_m,z_m\n0,1e-9\n1e-6,oops\n").unwrap();
    assert_fails(&[garbage.to_str().unwrap()], "line 3");
    std::fs::write(&garbage, [0xffu8, 0xfe, 0x00, 0x41]).unwrap();
    assert_fails(&[garbage.to_str().unwrap()], "cannot read");
    // 8 periods of 50 µm = 400 µm.
    let sine = dir.join("sine.csv");
    write_sine(&sine, 1e-6, 50e-6, 8, 100);
    let s = sine.to_str().unwrap();
    assert_fails(&[s, "--cutoff", "1e-3"], "--cutoff");
    assert_fails(&[s, "--cutoff", "4e-4", "--json"], "--cutoff");
    // Longer than half the profile: no sampling length λc is left.
    assert_fails(&[s, "--cutoff", "2.5e-4"], "too long");
    assert_fails(&[s, "--cutoff", "-1e-4"], "cutoff");
    // A map's areal cut-off must be shorter than the map.
    let map = dir.join("map.csv");
    std::fs::write(&map, "# dx_m=1e-6\n1e-9,2e-9,0\n0,3e-9,1e-9\n2e-9,0,1e-9\n").unwrap();
    assert_fails(&[map.to_str().unwrap(), "--cutoff", "1e-5"], "--cutoff");
    // With a valid cut-off the sampling length is λc.
    let v = profile_json(&[s, "--cutoff", "1e-4"]);
    assert_rel(num(&v, "sampling_length"), 1e-4, 1e-9, "sampling length λc");
    assert_eq!(v["sampling_lengths"], 3, "400 µm − λc = 300 µm: 3 λc");
    // Unknown detrend: clap's own error, non-zero.
    let out = profile(&[s, "--detrend", "cubic"]);
    assert!(!out.status.success());
}

#[test]
fn profile_on_every_measured_profile() {
    let dir = manifest().join("..").join("shared/data/profiles");
    let Ok(entries) = std::fs::read_dir(&dir) else {
        common::skip(format_args!(
            "{} is not present (the measured data live outside the project, in \
             ../shared/data next to the crate)",
            dir.display()
        ));
        return;
    };
    let mut files: Vec<PathBuf> = entries
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "csv"))
        .collect();
    files.sort();
    if files.is_empty() {
        common::skip(format_args!(
            "no .csv profile in {} (the measured profiles of ../shared/data/profiles)",
            dir.display()
        ));
        return;
    }
    let out = scratch("measured");
    for file in &files {
        let f = file.to_str().unwrap();
        let v = profile_json(&[f]);
        if v["kind"] == "map" {
            for key in [
                "Sa", "Sq", "Ssk", "Sku", "Sp", "Sv", "Sz", "Sdq", "nx", "ny",
            ] {
                assert!(v.get(key).is_some(), "{f}: missing `{key}`");
            }
            assert_rel(num(&v, "Sz"), num(&v, "Sp") + num(&v, "Sv"), 1e-12, "Sz");
            let plain = profile_json(&[f, "--detrend", "none"]);
            assert!(
                num(&plain, "Sq") > num(&v, "Sq"),
                "{f}: levelling lowers Sq"
            );
            let prefix = out.join(file.file_stem().unwrap());
            let p = profile_json(&[f, "--svg", prefix.to_str().unwrap()]);
            assert_eq!(p["plots"].as_array().unwrap().len(), 5, "{p}");
            for key in ["isotropy", "scale_dependent", "psd_radial", "acf_radial"] {
                assert!(p.get(key).is_some(), "{f}: missing `{key}`");
            }
            let str_ = p["isotropy"]["texture_aspect_ratio"].as_f64().unwrap();
            assert!(str_ > 0.0 && str_ <= 1.0, "{f}: Str {str_}");
            // The areal filter's roughness surface has less height.
            let r = profile_json(&[f, "--cutoff", "2e-6"]);
            assert!(num(&r, "Sq") < num(&p, "Sq"), "{f}: filtered Sq");
            continue;
        }
        assert_eq!(v["kind"], "profile", "{f}");
        for detrend in ["none", "linear", "quadratic"] {
            let v = profile_json(&[f, "--detrend", detrend]);
            for key in ISO_KEYS
                .iter()
                .chain(&["m0", "m2", "m4", "nayak_alpha", "points"])
            {
                assert!(v.get(*key).is_some(), "{f}: missing `{key}`");
            }
            assert!(num(&v, "Rz") <= num(&v, "Rt"), "{f} {detrend}: Rz > Rt");
            assert_rel(
                num(&v, "Rq").powi(2),
                num(&v, "m0"),
                1e-9,
                &format!("{f} {detrend}: Rq² = m0"),
            );
            assert!(num(&v, "nayak_alpha") >= 1.0, "{f} {detrend}: α < 1");
        }
        // ISO 4288-like: five cut-offs in the profile, roughness profile.
        let length = num(&v, "length");
        let lc = format!("{:e}", length / 6.0);
        let r = profile_json(&[f, "--detrend", "quadratic", "--cutoff", &lc]);
        assert!(num(&r, "Rz") <= num(&r, "Rt"), "{f} cut-off: Rz > Rt");
        assert!(r["sampling_lengths"].as_u64().unwrap() >= 4, "{r}");
        assert!(
            num(&r, "Rq") < num(&v, "Rq"),
            "{f}: the filter removes waviness"
        );
        let prefix = out.join(file.file_stem().unwrap());
        profile_json(&[f, "--svg", prefix.to_str().unwrap()]);
    }
}

/// A generated isotropic map: the map quantities of `asperity profile`
/// (isotropy, radial PSD and ACF, scale-dependent slope and curvature), its
/// five plots, and the ISO 16610-61 cut-off.
#[test]
fn profile_of_a_generated_map() {
    use asperity::surface::SelfAffine;
    let dir = scratch("map");
    let file = dir.join("map.csv");
    let (n, d) = (96usize, 1e-8);
    let m = SelfAffine::new(0.7, 1e-8)
        .unwrap()
        .with_roll_off(n as f64 * d / 6.0)
        .unwrap()
        .map(n, n, d, d, 3)
        .unwrap();
    let mut text = format!("# dx_m={d:e}\n");
    for j in 0..n {
        let row: Vec<String> = (0..n)
            .map(|i| format!("{:e}", m.z(i, j).unwrap()))
            .collect();
        text.push_str(&row.join(","));
        text.push('\n');
    }
    std::fs::write(&file, text).unwrap();
    let f = file.to_str().unwrap();
    let prefix = dir.join("gm");
    let v = profile_json(&[f, "--svg", prefix.to_str().unwrap()]);
    assert_eq!(v["kind"], "map");
    let iso = &v["isotropy"];
    assert!(iso["gradient_ratio"].as_f64().unwrap() > 0.8, "{iso}");
    assert!(iso["texture_aspect_ratio"].as_f64().unwrap() > 0.5, "{iso}");
    let q = v["psd_radial"]["q"].as_array().unwrap();
    assert_eq!(q.len(), v["psd_radial"]["c"].as_array().unwrap().len());
    assert!(q.len() > 40);
    let lag = v["acf_radial"]["lag"].as_array().unwrap();
    let r = v["acf_radial"]["r"].as_array().unwrap();
    assert_eq!(lag.len(), r.len());
    assert_rel(
        r[0].as_f64().unwrap(),
        num(&v, "Sq").powi(2),
        1e-9,
        "R(0) = Sq²",
    );
    let slope = v["scale_dependent"]["along_x"]["slope_rms"]
        .as_array()
        .unwrap();
    let slope: Vec<f64> = slope.iter().map(|x| x.as_f64().unwrap()).collect();
    assert!(slope.windows(2).all(|w| w[1] < w[0]), "{slope:?}");
    let plots = v["plots"].as_array().unwrap();
    assert_eq!(plots.len(), 5, "{v}");
    for p in plots {
        let size = std::fs::metadata(p.as_str().unwrap()).unwrap().len();
        assert!(size > 1000 && size < 2_000_000, "{p}: {size} bytes");
    }
    let c = profile_json(&[f, "--cutoff", "2e-7"]);
    assert_eq!(c["nx"], 76, "96 − 2·10 points after λc/2 at each edge");
    assert!(num(&c, "Sq") < num(&v, "Sq"));
    let out = profile(&[f]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("isotropy: Str"), "{text}");
    assert!(text.contains("scale-dependent rms slope"), "{text}");
}
