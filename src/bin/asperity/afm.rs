//! `asperity afm`: analyse a measured AFM force–distance curve (baseline,
//! contact point, jump-in, pull-off, adhesion energy, contact-law fits and
//! the recommended model); a report, `--json`, and `--svg PREFIX`.

use asperity::afm::{analyze, AfmAnalysis, AfmCurve, AfmModel, AfmOptions};
use std::error::Error;
use std::path::{Path, PathBuf};

/// Arguments of `asperity afm`.
#[derive(clap::Args)]
pub struct AfmArgs {
    /// The curve: CSV with `#` metadata lines (`# spring_constant_N_per_m=…`)
    /// and a header naming the columns: a position (z_sensor_m,
    /// height_measured_m, z_raw_m, height_piezo_m, position_m or z_m, m),
    /// force_N (N) or deflection_m (m), and optionally segment
    /// (approach/retract).
    pub file: PathBuf,
    /// Tip radius R (m); without it the fits give E*·√R and w·R.
    #[arg(long)]
    pub tip_radius: Option<f64>,
    /// auto (fit the models, recommend one) | hertz | dmt | jkr |
    /// maugis_dugdale | lj (the numerical Lennard-Jones sphere, tabulated:
    /// about 1–3 s; auto fits it only when the Maugis–Dugdale fit's
    /// λ = 1.157 μ lies between 0.1 and 5, where it differs from
    /// Maugis–Dugdale, and says so otherwise).
    #[arg(long, default_value = "auto")]
    pub model: String,
    /// Spring constant k (N/m), overriding the file's.
    #[arg(long)]
    pub spring_constant: Option<f64>,
    /// The position column to use instead of the first known one.
    #[arg(long)]
    pub position_column: Option<String>,
    /// Lennard-Jones equilibrium separation z₀ (m) of the Maugis–Dugdale
    /// stress, the Lennard-Jones sphere and the Tabor parameter.
    #[arg(long, default_value_t = 0.3e-9)]
    pub z0: f64,
    /// Print one JSON object instead of the report.
    #[arg(long)]
    pub json: bool,
    /// Write PREFIX-afm.svg: the data, the baseline, the contact point and
    /// each fitted model. If PREFIX is a directory, the file's stem is used
    /// inside it.
    #[arg(long)]
    pub svg: Option<PathBuf>,
}

pub fn run(args: &AfmArgs) -> Result<(), Box<dyn Error>> {
    let models = match args.model.as_str() {
        "auto" => Vec::new(),
        m => vec![AfmModel::from_name(m).ok_or_else(|| {
            format!("unknown model `{m}`: auto | hertz | dmt | jkr | maugis_dugdale | lj")
        })?],
    };
    let curve = AfmCurve::read(&args.file, args.position_column.as_deref())
        .map_err(|e| format!("{}: {e}", args.file.display()))?;
    let options = AfmOptions {
        tip_radius: args.tip_radius,
        spring_constant: args.spring_constant,
        models,
        equilibrium_separation: args.z0,
        ..AfmOptions::default()
    };
    let a = analyze(&curve, &options)?;
    if args.json {
        outln!("{}", a.to_json());
    } else {
        report(&a, &curve);
    }
    if let Some(prefix) = &args.svg {
        let prefix = if prefix.is_dir() {
            prefix.join(args.file.file_stem().unwrap_or(args.file.as_os_str()))
        } else {
            prefix.clone()
        };
        let mut s = prefix.into_os_string();
        s.push("-afm.svg");
        plot(Path::new(&s), &a, &curve)?;
    }
    Ok(())
}

fn opt(v: Option<f64>) -> String {
    v.map_or("-".into(), |v| format!("{v:.4e}"))
}

fn report(a: &AfmAnalysis, c: &AfmCurve) {
    outln!(
        "{} points ({} approach, {} retract), position column `{}`, k = {} N/m",
        c.len(),
        c.retract_start,
        c.len() - c.retract_start,
        c.position_column,
        a.spring_constant
    );
    outln!(
        "baseline (retract)   offset {:.4e} N, slope {:.4e} N/m, noise {:.3e} N, {} points",
        a.baseline.offset,
        a.baseline.slope,
        a.baseline.noise,
        a.baseline.points
    );
    outln!(
        "baseline (approach)  offset {:.4e} N, slope {:.4e} N/m, noise {:.3e} N, {} points",
        a.approach_baseline.offset,
        a.approach_baseline.slope,
        a.approach_baseline.noise,
        a.approach_baseline.points
    );
    outln!("contact point        {:.6e} m", a.contact_point);
    outln!(
        "jump-in              {:.4e} m (dip {:.4e} N)",
        a.jump_in_distance,
        a.jump_in_force
    );
    outln!(
        "pull-off force       {:.4e} N at {:.6e} m",
        a.pull_off_force,
        a.pull_off_position
    );
    outln!("adhesion energy      {:.4e} J", a.adhesion_energy);
    let known = a.radius_known;
    outln!(
        "{:<15} {:>12} {:>11} {:>12} {:>11} {:>9} {:>11} {:>5}",
        "model",
        if known { "E* / Pa" } else { "E*√R" },
        "± se",
        if known { "w / J/m²" } else { "wR / J/m" },
        "± se",
        "Tabor μ",
        "rms / N",
        "conv"
    );
    for f in &a.fits {
        let (e, se, w, wse) = if known {
            (
                f.e_star,
                f.e_star_stderr,
                f.work_of_adhesion,
                f.work_of_adhesion_stderr,
            )
        } else {
            (
                Some(f.e_star_times_sqrt_radius),
                f.e_star_times_sqrt_radius_stderr,
                f.work_of_adhesion_times_radius,
                f.work_of_adhesion_times_radius_stderr,
            )
        };
        outln!(
            "{:<15} {:>12} {:>11} {:>12} {:>11} {:>9} {:>11.3e} {:>5}",
            f.model,
            opt(e),
            opt(se),
            opt(w),
            opt(wse),
            f.tabor_parameter.map_or("-".into(), |m| format!("{m:.3}")),
            f.rms_residual,
            if f.converged { "yes" } else { "no" }
        );
    }
    for (m, e) in &a.failed_fits {
        outln!("{m:<15} not fitted: {e}");
    }
    for (m, e) in &a.skipped_fits {
        outln!("{m:<15} {e}");
    }
    outln!(
        "recommended model    {}",
        a.recommended_model.unwrap_or("none")
    );
    for f in &a.flag_details {
        outln!("flag {}: {}", f.code, f.message);
    }
}

fn plot(path: &Path, a: &AfmAnalysis, c: &AfmCurve) -> Result<(), Box<dyn Error>> {
    use plotters::prelude::*;
    let nm = |z: f64| z * 1e9;
    let nn = |f: f64| f * 1e9;
    let rs = c.retract_start;
    let approach: Vec<(f64, f64)> = (0..rs)
        .map(|i| (nm(c.position[i]), nn(c.force[i] * scale(a, c))))
        .collect();
    let retract: Vec<(f64, f64)> = (rs..c.len())
        .map(|i| (nm(c.position[i]), nn(c.force[i] * scale(a, c))))
        .collect();
    let f_max = a.fit_range[0] - rs;
    let f_top = c.force[rs + f_max] * scale(a, c) - a.baseline.at(c.position[rs + f_max]);
    let mut models = Vec::new();
    for f in &a.fits {
        let pts = a.model_curve(f, f_top, 200)?;
        models.push((
            f.model,
            pts.into_iter()
                .map(|(z, f)| (nm(z), nn(f)))
                .collect::<Vec<_>>(),
        ));
    }
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for &(x, y) in approach.iter().chain(&retract) {
        x0 = x0.min(x);
        x1 = x1.max(x);
        y0 = y0.min(y);
        y1 = y1.max(y);
    }
    let pad = 0.05 * (y1 - y0).max(1e-12);
    let (y0, y1) = (y0 - pad, y1 + pad);
    let base: Vec<(f64, f64)> = [x0, x1]
        .iter()
        .map(|&x| (x, nn(a.baseline.at(x * 1e-9))))
        .collect();
    let root = SVGBackend::new(path, (1000, 650)).into_drawing_area();
    root.fill(&WHITE)?;
    let title = format!(
        "AFM force curve: pull-off {:.2} nN, recommended {}",
        nn(a.pull_off_force),
        a.recommended_model.unwrap_or("none")
    );
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 20))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(65)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    chart
        .configure_mesh()
        .x_desc(format!("{} / nm", c.position_column))
        .y_desc("force / nN")
        .draw()?;
    let grey = RGBColor(120, 120, 120);
    let blue = RGBColor(70, 110, 200);
    chart
        .draw_series(approach.iter().map(|&p| Circle::new(p, 1, blue.filled())))?
        .label("approach")
        .legend(move |(x, y)| Circle::new((x + 10, y), 3, blue.filled()));
    chart
        .draw_series(retract.iter().map(|&p| Circle::new(p, 1, grey.filled())))?
        .label("retract")
        .legend(move |(x, y)| Circle::new((x + 10, y), 3, grey.filled()));
    chart
        .draw_series(LineSeries::new(base, BLACK.stroke_width(1)))?
        .label("baseline (retract)")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(1)));
    let cp = nm(a.contact_point);
    let red = RGBColor(200, 30, 30);
    chart
        .draw_series(LineSeries::new(
            vec![(cp, y0), (cp, y1)],
            red.stroke_width(1),
        ))?
        .label("contact point")
        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], red.stroke_width(1)));
    let fits = models.into_iter().map(|(name, pts)| {
        let inside = pts
            .into_iter()
            .filter(|&(x, y)| x >= x0 && x <= x1 && y >= y0 && y <= y1)
            .collect();
        (format!("{name} fit"), inside)
    });
    super::chart::lines_with_legend(&mut chart, fits, 2)?;
    root.present()?;
    Ok(())
}

/// The factor the analysis applied to the file's forces (a spring constant
/// given on the command line rescales them).
fn scale(a: &AfmAnalysis, c: &AfmCurve) -> f64 {
    match c.spring_constant {
        Some(k) => a.spring_constant / k,
        None => 1.0,
    }
}
