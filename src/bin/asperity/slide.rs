//! `asperity slide SCENE.json [--json] [--out DIR]`: runs a sliding scene
//! (the scene format: `asperity::scene`), writes the per-step CSV and SVG
//! plots, prints a summary or, with `--json`, exactly one JSON object.
//!
//! Where the files go: into `--out DIR`; without `--out`, into the current
//! directory, except with `--json`, which then writes nothing but the JSON
//! object to stdout (its `files` is empty).
//!
//! With `--out DIR` (and SVG outputs on) it also plots the true contact area
//! against the load (thesis 6.5.3, Figure 6-60) with its least-squares line
//! and R²: the mean true contact area of one slide per load of the scene's
//! `load_sweep` when it has one, otherwise the true contact area of every
//! increment against its normal load (meaningful at a fixed gap, where the
//! load varies). When all those points share one load (a fixed-load scene
//! without a sweep, or a sweep of one load) the plot would be one vertical
//! column of points with no line: neither the plot nor the JSON's
//! `area_load` is written.
//!
//! Every axis is labelled in an SI prefix of its quantity (position in µm,
//! energy in nJ, …, chosen from the values) with distinct tick labels
//! (`axis.rs`).
//!
//! When the scene chooses dynamic friction models (`friction_models`, with
//! `sliding.velocity`; see `asperity::scene::models`), each runs along the
//! same track ([`Scene::run_friction_models`]: per increment the slide's
//! normal load, its step as slip, step/velocity as time) and the command
//! also writes
//!
//! * `{stem}_models.csv` (CSV outputs on): columns `distance_m`,
//!   `energy_dissipation` (the slide's μ) and one per model, headed by its
//!   name, holding its μ = F/N after each increment (F the friction force
//!   resisting the motion: negative while it drives the slider, as a
//!   Prandtl–Tomlinson tip overshooting after a slip);
//! * `{stem}_models_cof.svg` (SVG outputs on): μ against the sliding
//!   distance, one line per model and one for the energy-dissipation model,
//!   with a legend of the names;
//!
//! prints a table of the models next to the energy-dissipation model, and
//! adds to the `--json` object the key `friction_models`: an array, in scene
//! order, of objects with
//!
//! * `name`, `model` (the scene key: `lugre`, `maxwell_slip`,
//!   `prandtl_tomlinson`),
//! * `mean_cof` (mean μ over the increments), `static_cof` (the largest μ:
//!   the static coefficient),
//! * `mean_friction_force` (N), `dissipation` (total, J),
//! * `stick_slip_events` (bursts of dissipation: runs of increments each
//!   dissipating more than ten times the median increment,
//!   `asperity::scene::TrackSummary::stick_slip_events`).
//!
//! Without models nothing of this is computed, written or printed.

use asperity::friction::{Loading, SlideRun, SlideStep, Slider};
use asperity::scene::{Scene, TrackRun};

use crate::axis;
use plotters::prelude::*;
use std::error::Error;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};

type Res<T> = Result<T, Box<dyn Error>>;
/// A named, coloured line of a plot.
type Series<'a> = (&'a str, Vec<(f64, f64)>, RGBColor);

/// Arguments of `asperity slide`.
#[derive(clap::Args)]
pub struct SlideArgs {
    /// The scene (JSON; paths inside are relative to it).
    scene: PathBuf,
    /// Print one JSON object with the summary (no progress bar, no table).
    #[arg(long)]
    json: bool,
    /// Directory for the CSV and SVG outputs (default: the current one;
    /// with `--json` and no `--out`, no files are written).
    #[arg(long)]
    out: Option<PathBuf>,
}

pub fn run(args: &SlideArgs) -> Res<()> {
    let scene = Scene::from_file(&args.scene)?;
    let slider = scene.build()?;
    let hidden = args.json || !std::io::stderr().is_terminal();
    let bar = if hidden {
        indicatif::ProgressBar::hidden()
    } else {
        indicatif::ProgressBar::new(0)
    };
    let run = slider.slide_with(scene.sliding.distance, scene.sliding.step, |k, n| {
        if k == 1 {
            bar.set_length(n as u64);
        }
        bar.set_position(k as u64);
    })?;
    bar.finish_and_clear();
    let tracks = scene.run_friction_models(&run)?;
    let out = args.out.clone().unwrap_or_else(|| PathBuf::from("."));
    let stem = args
        .scene
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "slide".into());
    let mut written = vec![];
    // `--json` alone: the JSON object on stdout and nothing else.
    let files = !(args.json && args.out.is_none());
    let (csv, svg) = (files && scene.outputs.csv, files && scene.outputs.svg);
    if csv || svg {
        std::fs::create_dir_all(&out)
            .map_err(|e| format!("cannot create {}: {e}", out.display()))?;
    }
    if csv {
        let p = out.join(format!("{stem}.csv"));
        write_csv(&p, &run.steps)?;
        written.push(p);
        if !tracks.is_empty() {
            let p = out.join(format!("{stem}_models.csv"));
            models_csv(&p, &scene, &run, &tracks)?;
            written.push(p);
        }
    }
    if svg {
        let p = out.join(format!("{stem}_cof.svg"));
        cof_plot(&p, &run.steps)?;
        written.push(p);
        let p = out.join(format!("{stem}_dissipation.svg"));
        dissipation_plot(&p, &run.steps)?;
        written.push(p);
        if !tracks.is_empty() {
            let p = out.join(format!("{stem}_models_cof.svg"));
            models_plot(&p, &scene, &run, &tracks)?;
            written.push(p);
        }
    }
    let area_load = if svg && args.out.is_some() {
        let data = area_load_data(&scene, &slider, &run)?;
        if several_loads(&data.points) {
            let p = out.join(format!("{stem}_area_load.svg"));
            area_load_plot(&p, &data)?;
            written.push(p);
            Some(data)
        } else {
            None
        }
    } else {
        None
    };
    if args.json {
        outln!(
            "{}",
            summary_json(&scene, &run, &tracks, &written, area_load.as_ref())
        );
    } else {
        let s = &run.summary;
        outln!("steps                     {}", s.steps);
        outln!("normal load               {:.6e} N", s.normal_load);
        outln!("mean COF                  {:.4}", s.mean_cof);
        outln!("mean friction force       {:.6e} N", s.mean_friction_force);
        outln!(
            "mean true contact area    {:.6e} m^2",
            s.mean_true_contact_area
        );
        outln!(
            "adhesion share of area    {:.2} %",
            100.0 * s.mean_adhesion_area_share
        );
        let d = s.dissipation;
        outln!(
            "dissipation (J)           chemical {:.4e}, van der Waals {:.4e}, elastic {:.4e}, plastic {:.4e}",
            d.chemical, d.van_der_waals, d.elastic, d.plastic
        );
        if !tracks.is_empty() {
            print_models(&scene, &run, &tracks);
        }
        for p in &written {
            outln!("wrote {}", p.display());
        }
    }
    Ok(())
}

/// The table of the dynamic models next to the energy-dissipation model.
fn print_models(scene: &Scene, run: &SlideRun, tracks: &[TrackRun]) {
    let v = scene.sliding.velocity.unwrap_or(f64::NAN);
    outln!("friction models at {v:.4e} m/s along the same track:");
    let width = scene
        .friction_models
        .iter()
        .map(|m| m.name.chars().count())
        .chain([ENERGY_DISSIPATION.len()])
        .max()
        .unwrap_or(0);
    outln!(
        "  {:width$}  {:>9}  {:>10}  {:>15}  {:>17}",
        "model",
        "mean COF",
        "static COF",
        "dissipation (J)",
        "stick-slip events"
    );
    let s = &run.summary;
    let static_cof = run.steps.iter().map(|r| r.cof).fold(0.0, f64::max);
    outln!(
        "  {:width$}  {:>9.4}  {:>10.4}  {:>15.4e}  {:>17}",
        ENERGY_DISSIPATION,
        s.mean_cof,
        static_cof,
        s.dissipation.total(),
        "-"
    );
    for (spec, t) in scene.friction_models.iter().zip(tracks) {
        let m = &t.summary;
        outln!(
            "  {:width$}  {:>9.4}  {:>10.4}  {:>15.4e}  {:>17}",
            spec.name,
            m.mean_cof,
            m.static_cof,
            m.dissipation,
            m.stick_slip_events
        );
    }
}

/// The energy-dissipation model's label in the model outputs.
const ENERGY_DISSIPATION: &str = "energy dissipation";

/// A CSV field, quoted when it holds a comma or a quote (RFC 4180).
fn csv_field(s: &str) -> String {
    if s.contains([',', '"']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

fn models_csv(path: &Path, scene: &Scene, run: &SlideRun, tracks: &[TrackRun]) -> Res<()> {
    let mut s = String::from("distance_m,energy_dissipation");
    for m in &scene.friction_models {
        s.push(',');
        s.push_str(&csv_field(&m.name));
    }
    s.push('\n');
    for (k, r) in run.steps.iter().enumerate() {
        s.push_str(&format!("{:e},{:e}", r.position, r.cof));
        for t in tracks {
            s.push_str(&format!(",{:e}", t.steps[k].cof));
        }
        s.push('\n');
    }
    std::fs::write(path, s).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(())
}

fn models_plot(path: &Path, scene: &Scene, run: &SlideRun, tracks: &[TrackRun]) -> Res<()> {
    let x: Vec<f64> = run.steps.iter().map(|r| r.position).collect();
    let mut series: Vec<Series<'_>> = vec![(
        ENERGY_DISSIPATION,
        x.iter().zip(&run.steps).map(|(&x, r)| (x, r.cof)).collect(),
        BLUE,
    )];
    const COLOURS: [RGBColor; 5] = [RED, GREEN, MAGENTA, CYAN, BLACK];
    for (i, (spec, t)) in scene.friction_models.iter().zip(tracks).enumerate() {
        let colour = COLOURS.get(i).copied().unwrap_or_else(|| {
            let (r, g, b) = Palette99::pick(i).rgb();
            RGBColor(r, g, b)
        });
        let pts = x.iter().zip(&t.steps).map(|(&x, r)| (x, r.cof)).collect();
        series.push((spec.name.as_str(), pts, colour));
    }
    plot(
        path,
        "Coefficient of friction: energy dissipation and dynamic models",
        "COF",
        "",
        &series,
    )
}

fn summary_json(
    scene: &Scene,
    run: &SlideRun,
    tracks: &[TrackRun],
    written: &[PathBuf],
    area_load: Option<&AreaLoad>,
) -> String {
    let mut v = scene.summary_json(run, tracks);
    v["files"] = written
        .iter()
        .map(|p| p.display().to_string())
        .collect::<Vec<_>>()
        .into();
    if let Some(a) = area_load {
        v["area_load"] = serde_json::json!({
            "source": if a.sweep { "load_sweep" } else { "steps" },
            "loads": a.points.iter().map(|p| p.0).collect::<Vec<_>>(),
            "areas": a.points.iter().map(|p| p.1).collect::<Vec<_>>(),
            "slope": a.fit.slope,
            "intercept": a.fit.intercept,
            "r_squared": a.fit.r_squared,
        });
    }
    v.to_string()
}

/// Least-squares line y = slope·x + intercept and its R² (NaN when x or y
/// does not vary).
struct Fit {
    slope: f64,
    intercept: f64,
    r_squared: f64,
}

fn fit(points: &[(f64, f64)]) -> Fit {
    let varies = |f: fn(&(f64, f64)) -> f64| {
        let first = points.first().map(f);
        points.iter().any(|p| Some(f(p)) != first)
    };
    if !varies(|p| p.0) {
        // One load (a fixed-load run): no line, whatever the rounding of
        // the mean would make of it.
        return Fit {
            slope: f64::NAN,
            intercept: f64::NAN,
            r_squared: f64::NAN,
        };
    }
    let y_varies = varies(|p| p.1);
    let n = points.len() as f64;
    let mx = points.iter().map(|p| p.0).sum::<f64>() / n;
    let my = points.iter().map(|p| p.1).sum::<f64>() / n;
    let (mut sxy, mut sxx, mut syy) = (0.0, 0.0, 0.0);
    for &(x, y) in points {
        sxy += (x - mx) * (y - my);
        sxx += (x - mx) * (x - mx);
        syy += (y - my) * (y - my);
    }
    let slope = sxy / sxx;
    Fit {
        slope,
        intercept: my - slope * mx,
        r_squared: if y_varies {
            sxy * sxy / (sxx * syy)
        } else {
            f64::NAN
        },
    }
}

/// Points (normal load N, true contact area m²) and their fit.
struct AreaLoad {
    /// Whether the points come from the scene's load sweep (else: steps).
    sweep: bool,
    points: Vec<(f64, f64)>,
    fit: Fit,
}

/// Whether `points` (load, area) hold more than one load: loads that differ
/// by more than a relative 1e-9 (the rounding of a fixed-load run).
fn several_loads(points: &[(f64, f64)]) -> bool {
    let lo = points.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
    let hi = points.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
    hi - lo > 1e-9 * lo.abs().max(hi.abs())
}

fn area_load_data(scene: &Scene, slider: &Slider, run: &SlideRun) -> Res<AreaLoad> {
    let (sweep, points) = match scene.sweep_loads(slider) {
        Some(loads) => {
            let mut pts = Vec::with_capacity(loads.len());
            for load in loads {
                let r = slider
                    .with_loading(Loading::FixedLoad { load })
                    .map_err(|e| format!("load_sweep: {e}"))?
                    .slide(scene.sliding.distance, scene.sliding.step)?;
                pts.push((r.summary.normal_load, r.summary.mean_true_contact_area));
            }
            (true, pts)
        }
        None => (
            false,
            run.steps
                .iter()
                .map(|r| (r.normal_load, r.true_contact_area))
                .collect(),
        ),
    };
    let fit = fit(&points);
    Ok(AreaLoad { sweep, points, fit })
}

fn area_load_plot(path: &Path, data: &AreaLoad) -> Res<()> {
    // Plot in SI prefixes of the largest load and area (mN and µm² for the
    // chapter-6 scenes).
    let (ls, lp) = axis::si_prefix(axis::magnitude(data.points.iter().map(|p| p.0)));
    let (s2, ap) = axis::si_prefix_squared(axis::magnitude(data.points.iter().map(|p| p.1)));
    let pts: Vec<(f64, f64)> = data.points.iter().map(|&(p, a)| (p / ls, a / s2)).collect();
    let f = &data.fit;
    // The fit in plot units: A/s2 = slope·ls/s2 · P/ls + intercept/s2.
    let line = |x: f64| f.slope * ls / s2 * x + f.intercept / s2;
    let lo = pts.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
    let hi = pts.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
    let (x0, x1) = if hi > lo {
        (lo.min(0.0), hi + 0.05 * (hi - lo.min(0.0)))
    } else {
        // One load only: centre it.
        let w = (lo.abs() * 0.1).max(1e-3);
        (lo - w, lo + w)
    };
    let mut ys: Vec<f64> = pts.iter().map(|p| p.1).collect();
    if f.slope.is_finite() {
        ys.extend([line(x0), line(x1)]);
    }
    let y0 = ys.iter().copied().fold(0.0, f64::min);
    let top = ys.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let y1 = if top > y0 {
        top + 0.05 * (top - y0)
    } else {
        y0 + 1.0
    };
    let title = if f.r_squared.is_finite() {
        format!(
            "True contact area against load: A = {:.4e} m²/N · P {:+.3e} m², R² = {:.5}",
            f.slope, f.intercept, f.r_squared
        )
    } else if f.slope.is_finite() {
        "True contact area against load (constant area: R² undefined)".to_string()
    } else {
        "True contact area against load (one load: no fit)".to_string()
    };
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, (900, 500)).into_drawing_area();
        root.fill(&WHITE)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        let (fx, fy) = (axis::ticks(x0, x1), axis::ticks(y0, y1));
        chart
            .configure_mesh()
            .x_desc(format!("normal load ({lp}N)"))
            .y_desc(format!("true contact area ({ap}m²)"))
            .x_label_formatter(&*fx)
            .y_label_formatter(&*fy)
            .draw()?;
        let label = if data.sweep {
            "mean over a slide, per load"
        } else {
            "per increment"
        };
        chart
            .draw_series(
                pts.iter()
                    .map(|&(x, y)| Circle::new((x, y), 4, BLUE.filled())),
            )?
            .label(label)
            .legend(|(x, y)| Circle::new((x + 9, y), 4, BLUE.filled()));
        if f.slope.is_finite() {
            chart
                .draw_series(LineSeries::new(
                    [(x0, line(x0)), (x1, line(x1))],
                    RED.stroke_width(2),
                ))?
                .label("least-squares line")
                .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 18, y)], RED.stroke_width(2)));
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()?;
        root.present()?;
    }
    std::fs::write(path, buf).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(())
}

fn write_csv(path: &Path, steps: &[SlideStep]) -> Res<()> {
    let mut s = String::from(
        "position_m,rod_position_m,normal_load_n,friction_force_n,cof,no_contact,adhesion_n,\
         chemical_j,van_der_waals_j,elastic_j,plastic_j,true_contact_area_m2,\
         adhesion_area_share,nano_contacts,adhesive_contacts,rods_in_contact,yielded_rods\n",
    );
    for r in steps {
        let d = r.dissipation;
        s.push_str(&format!(
            "{:e},{:e},{:e},{:e},{:e},{},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{},{},{},{}\n",
            r.position,
            r.rod_position,
            r.normal_load,
            r.friction_force,
            r.cof,
            r.no_contact as u8,
            r.adhesion,
            d.chemical,
            d.van_der_waals,
            d.elastic,
            d.plastic,
            r.true_contact_area,
            r.adhesion_area_share,
            r.nano_contacts,
            r.adhesive_contacts,
            r.rods_in_contact,
            r.yielded_rods
        ));
    }
    std::fs::write(path, s).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(())
}

fn bounds(series: &[Vec<(f64, f64)>]) -> (f64, f64, f64, f64) {
    let (mut x0, mut x1, mut y0, mut y1) =
        (f64::INFINITY, f64::NEG_INFINITY, 0.0f64, f64::NEG_INFINITY);
    for s in series {
        for &(x, y) in s {
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
    }
    if x1.is_nan() || x1 <= x0 {
        x1 = x0 + 1.0;
    }
    if y1.is_nan() || y1 <= y0 {
        y1 = y0 + 1.0;
    }
    (x0, x1, y0, y1 + 0.05 * (y1 - y0))
}

/// Plots `series` (x: slider position in m; y: the quantity in `unit`, or
/// dimensionless when `unit` is empty) against the slider position, both
/// axes in SI prefixes of their largest values: "energy (nJ)".
fn plot(path: &Path, title: &str, quantity: &str, unit: &str, series: &[Series<'_>]) -> Res<()> {
    let all = || series.iter().flat_map(|s| s.1.iter());
    let (xs, xp) = axis::si_prefix(axis::magnitude(all().map(|p| p.0)));
    let (ys, yp) = if unit.is_empty() {
        (1.0, "")
    } else {
        axis::si_prefix(axis::magnitude(all().map(|p| p.1)))
    };
    let y_label = if unit.is_empty() {
        quantity.to_string()
    } else {
        format!("{quantity} ({yp}{unit})")
    };
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, (900, 500)).into_drawing_area();
        root.fill(&WHITE)?;
        let data: Vec<Vec<(f64, f64)>> = series
            .iter()
            .map(|s| s.1.iter().map(|&(x, y)| (x / xs, y / ys)).collect())
            .collect();
        let (x0, x1, y0, y1) = bounds(&data);
        let (fx, fy) = (axis::ticks(x0, x1), axis::ticks(y0, y1));
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 20))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(x0..x1, y0..y1)?;
        chart
            .configure_mesh()
            .x_desc(format!("slider position ({xp}m)"))
            .y_desc(y_label)
            .x_label_formatter(&*fx)
            .y_label_formatter(&*fy)
            .draw()?;
        for ((name, _, color), pts) in series.iter().zip(&data) {
            let c = *color;
            chart
                .draw_series(LineSeries::new(pts.iter().copied(), c.stroke_width(2)))?
                .label(*name)
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 18, y)], c.stroke_width(2))
                });
        }
        if series.len() > 1 {
            chart
                .configure_series_labels()
                .background_style(WHITE.mix(0.8))
                .border_style(BLACK)
                .draw()?;
        }
        root.present()?;
    }
    std::fs::write(path, buf).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(())
}

fn cof_plot(path: &Path, steps: &[SlideStep]) -> Res<()> {
    let pts = steps.iter().map(|r| (r.position, r.cof)).collect();
    plot(
        path,
        "Coefficient of friction",
        "COF",
        "",
        &[("COF", pts, BLUE)],
    )
}

fn dissipation_plot(path: &Path, steps: &[SlideStep]) -> Res<()> {
    let pick = |f: fn(&SlideStep) -> f64| -> Vec<(f64, f64)> {
        steps.iter().map(|r| (r.position, f(r))).collect()
    };
    plot(
        path,
        "Energy dissipated per step, by mechanism",
        "energy",
        "J",
        &[
            ("chemical", pick(|r| r.dissipation.chemical), RED),
            ("van der Waals", pick(|r| r.dissipation.van_der_waals), BLUE),
            ("elastic", pick(|r| r.dissipation.elastic), GREEN),
            ("plastic", pick(|r| r.dissipation.plastic), MAGENTA),
        ],
    )
}
