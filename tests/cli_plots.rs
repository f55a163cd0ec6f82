//! Every plot the `asperity` command writes (feature `cli`) has readable
//! axes (issue 30 §5: the dissipation plot of the chapter-6 scene read "0.0"
//! at every tick of its energy axis, the energies being about 1e-7 J). Each
//! subcommand that plots runs into a scratch directory; in the text of every
//! SVG it writes, each axis's tick labels must be numbers, at least two, all
//! distinct (so not all "0.0"), and dimensional axes name an SI-prefixed
//! unit. The binary is found or built by `tests/common`.

use std::path::{Path, PathBuf};
use std::process::Command;

mod common;
use common::{binary, manifest};

/// A fresh scratch directory for one test.
fn scratch(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR"))
        .join("cli-plots")
        .join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn run(dir: &Path, args: &[&str]) -> String {
    let out = Command::new(binary())
        .current_dir(dir)
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

/// One `<text>` element of an SVG: its attributes and its text.
struct Text {
    x: String,
    y: String,
    anchor: String,
    body: String,
}

fn texts(svg: &str) -> Vec<Text> {
    let mut out = Vec::new();
    let mut rest = svg;
    while let Some(i) = rest.find("<text") {
        rest = &rest[i..];
        let close = rest.find('>').expect("an unclosed <text");
        let attrs = &rest[..close];
        let end = rest.find("</text>").expect("a <text> without </text>");
        let body = rest[close + 1..end].trim().to_string();
        let attr = |name: &str| -> String {
            let key = format!(" {name}=\"");
            attrs
                .find(&key)
                .map(|k| {
                    let v = &attrs[k + key.len()..];
                    v[..v.find('"').unwrap()].to_string()
                })
                .unwrap_or_default()
        };
        out.push(Text {
            x: attr("x"),
            y: attr("y"),
            anchor: attr("text-anchor"),
            body,
        });
        rest = &rest[end..];
    }
    out
}

/// The tick labels of each axis of an SVG that plotters drew: a chart writes
/// the labels of its y axis in a run of right-aligned (`text-anchor="end"`)
/// texts at one x, those of its x axis in a run of centred texts at one y;
/// captions, axis titles and legends stand alone or are left-aligned.
/// Returns (axis, labels) with axis "x@{y}" or "y@{x}".
fn axes(svg: &str) -> Vec<(String, Vec<String>)> {
    let mut groups: Vec<(String, Vec<String>)> = Vec::new();
    let mut last_key: Option<String> = None;
    for t in texts(svg) {
        let key = match t.anchor.as_str() {
            "end" => Some(format!("y@{}", t.x)),
            "middle" => Some(format!("x@{}", t.y)),
            _ => None,
        };
        match (&key, &last_key) {
            (Some(k), Some(l)) if k == l => groups.last_mut().unwrap().1.push(t.body),
            (Some(k), _) => groups.push((k.clone(), vec![t.body])),
            _ => {}
        }
        last_key = key;
    }
    groups.retain(|g| g.1.len() >= 2);
    groups
}

/// Every axis of the SVG at `path` reads: at least `min_axes` axes, each
/// with at least two labels, all numbers and all distinct. Returns the SVG.
fn assert_readable(path: &Path, min_axes: usize) -> String {
    let svg = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let axes = axes(&svg);
    assert!(
        axes.len() >= min_axes,
        "{}: {} axes with tick labels, want {min_axes}: {axes:?}",
        path.display(),
        axes.len()
    );
    for (axis, labels) in &axes {
        for l in labels {
            assert!(
                l.parse::<f64>().is_ok_and(f64::is_finite),
                "{} {axis}: tick label `{l}` is not a number: {labels:?}",
                path.display()
            );
        }
        let mut distinct = labels.clone();
        distinct.sort();
        distinct.dedup();
        assert_eq!(
            distinct.len(),
            labels.len(),
            "{} {axis}: repeated tick labels {labels:?}",
            path.display()
        );
    }
    svg
}

#[test]
fn the_svg_parser_sees_a_bad_axis() {
    // The axis of the issue, as plotters' default labels drew it.
    let svg = r##"<svg>
<text x="450" y="17" dy="0.76em" text-anchor="middle">Energy dissipated</text>
<text x="12" y="243" dy="0.76em" text-anchor="middle">energy (J)</text>
<text x="485" y="488" dy="-0.5ex" text-anchor="middle">slider position (µm)</text>
<text x="72" y="447" dy="0.5ex" text-anchor="end">0.0</text>
<text x="72" y="383" dy="0.5ex" text-anchor="end">0.0</text>
<text x="72" y="319" dy="0.5ex" text-anchor="end">0.0</text>
<text x="182" y="458" dy="0.76em" text-anchor="middle">20.0</text>
<text x="290" y="458" dy="0.76em" text-anchor="middle">40.0</text>
<text x="802" y="215" dy="0.76em" text-anchor="start">chemical</text>
</svg>"##;
    let a = axes(svg);
    assert_eq!(a.len(), 2, "{a:?}");
    assert_eq!(a[0], ("y@72".to_string(), vec!["0.0".to_string(); 3]));
    assert_eq!(a[1].1, ["20.0", "40.0"]);
}

#[test]
fn slide_plots_read() {
    let dir = scratch("slide");
    let scenes = manifest().join("examples/scenes");
    for scene in ["chapter6_copper", "chapter6_load_sweep", "dynamic_models"] {
        let file = scenes.join(format!("{scene}.json"));
        run(&dir, &["slide", file.to_str().unwrap(), "--out", "out"]);
    }
    let out = dir.join("out");
    let svg = assert_readable(&out.join("chapter6_copper_dissipation.svg"), 2);
    // Energies of about 1e-7 J: in nJ.
    assert!(svg.contains("energy (nJ)"), "{svg}");
    assert!(svg.contains("slider position (µm)"));
    assert_readable(&out.join("chapter6_copper_cof.svg"), 2);
    let svg = assert_readable(&out.join("chapter6_load_sweep_area_load.svg"), 2);
    assert!(svg.contains("normal load (mN)") && svg.contains("true contact area (µm²)"));
    assert_readable(&out.join("chapter6_load_sweep_dissipation.svg"), 2);
    assert_readable(&out.join("dynamic_models_models_cof.svg"), 2);
    // Every SVG written, whichever it is.
    for e in std::fs::read_dir(&out).unwrap() {
        let p = e.unwrap().path();
        if p.extension().is_some_and(|x| x == "svg") {
            assert_readable(&p, 2);
        }
    }
}

#[test]
fn curve_and_lj_plots_read() {
    let dir = scratch("curve-lj");
    let sphere = [
        "--radius",
        "1e-6",
        "--e-star",
        "1e9",
        "--work-of-adhesion",
        "0.05",
    ];
    let mut args = vec!["curve"];
    args.extend(sphere);
    args.extend(["--svg", "curve.svg"]);
    run(&dir, &args);
    assert_readable(&dir.join("curve.svg"), 2);
    let mut args = vec!["lj"];
    args.extend(sphere);
    args.extend(["--svg", "lj.svg"]);
    run(&dir, &args);
    assert_readable(&dir.join("lj.svg"), 2);
}

/// A load–unload curve: P = Pmax (h/hmax)² up, a 1.5 power law down to the
/// final depth hf = 0.6 hmax; two columns depth (m), load (N).
fn write_indentation(path: &Path, hmax: f64, pmax: f64) {
    use std::fmt::Write;
    let hf = 0.6 * hmax;
    let mut s = String::new();
    for i in 0..=100 {
        let h = hmax * i as f64 / 100.0;
        writeln!(s, "{h:.10e},{:.10e}", pmax * (h / hmax).powi(2)).unwrap();
    }
    for i in 1..=100 {
        let h = hmax - (hmax - hf) * i as f64 / 100.0;
        writeln!(
            s,
            "{h:.10e},{:.10e}",
            pmax * ((h - hf) / (hmax - hf)).powf(1.5)
        )
        .unwrap();
    }
    std::fs::write(path, s).unwrap();
}

#[test]
fn indent_plots_read_at_any_scale() {
    let dir = scratch("indent");
    // A nano-indentation to 1 µm and 10 mN, and one to 50 nm and 20 µN
    // (whose loads read "0.0" in fixed mN).
    for (name, hmax, pmax, depth, load) in [
        ("micro", 1e-6, 1e-2, "depth / µm", "load / mN"),
        ("nano", 50e-9, 20e-6, "depth / nm", "load / µN"),
    ] {
        let csv = dir.join(format!("{name}.csv"));
        write_indentation(&csv, hmax, pmax);
        let svg = format!("{name}.svg");
        run(&dir, &["indent", csv.to_str().unwrap(), "--svg", &svg]);
        let text = assert_readable(&dir.join(&svg), 2);
        assert!(
            text.contains(depth) && text.contains(load),
            "{name}: {text}"
        );
    }
}

#[test]
fn profile_plots_read() {
    let dir = scratch("profile");
    // z = A sin(2πx/Λ) + a 1 nm ripple, A = 20 nm, Λ = 50 µm, 8 periods.
    let (a, lambda, n) = (20e-9, 50e-6, 8000);
    let dx = 8.0 * lambda / n as f64;
    let mut s = String::from("x_m,z_m\n");
    for j in 0..n {
        let x = (j as f64 + 0.5) * dx;
        let t = 2.0 * std::f64::consts::PI * x / lambda;
        s.push_str(&format!(
            "{x:.17e},{:.17e}\n",
            a * t.sin() + 1e-9 * (37.0 * t).sin()
        ));
    }
    let file = dir.join("sine.csv");
    std::fs::write(&file, s).unwrap();
    run(&dir, &["profile", file.to_str().unwrap(), "--svg", "plots"]);
    for (suffix, axes) in [
        ("-profile.svg", 4),
        ("-acf.svg", 2),
        ("-psd.svg", 2),
        ("-material-ratio.svg", 2),
    ] {
        assert_readable(&dir.join(format!("plots{suffix}")), axes);
    }
}
