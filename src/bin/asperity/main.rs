//! The `asperity` command: run the library's models from a terminal.
//!
//! Built with `cargo build --release --features cli`. Every subcommand calls
//! the public Rust API like any other user; tables go to stdout (or CSV/JSON
//! files), plots to SVG. One module per subcommand that needs more than a
//! few lines (`profile.rs`).
//!
//! Everything the command prints to stdout goes through [`outln!`]: when the
//! reader goes away (`asperity lj … | head -1`) the command exits quietly
//! with status 0 instead of panicking on the broken pipe, as `println!`
//! does. Plots label their axes through `axis.rs`.

use asperity::contact::{Dmt, Jkr, LjSphere, MaugisDugdale, NormalContact};
use asperity::{ContactState, Control};
use clap::{Parser, Subcommand};
use std::error::Error;
use std::path::PathBuf;

/// `println!` for the command's output on stdout, through [`out`]: a
/// reader that went away ends the command quietly (status 0); another
/// write error ends it with a one-line message (status 1). Never panics.
macro_rules! outln {
    () => {
        $crate::out(format_args!(""))
    };
    ($($arg:tt)*) => {
        $crate::out(format_args!($($arg)*))
    };
}

mod afm;
mod axis;
mod chart;
mod profile;
mod slide;

/// Writes one line to stdout (see [`outln!`]).
pub(crate) fn out(args: std::fmt::Arguments<'_>) {
    use std::io::Write;
    let mut stdout = std::io::stdout().lock();
    let written = stdout
        .write_fmt(args)
        .and_then(|()| stdout.write_all(b"\n"))
        .and_then(|()| stdout.flush());
    if let Err(e) = written {
        if e.kind() == std::io::ErrorKind::BrokenPipe {
            // `… | head`: the reader has all it wants.
            std::process::exit(0);
        }
        let _ = writeln!(std::io::stderr(), "asperity: cannot write the output: {e}");
        std::process::exit(1);
    }
}

#[derive(Parser)]
#[command(
    name = "asperity",
    version,
    about = "Dry contact between rough surfaces"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// An adhesive sphere, SI units.
#[derive(clap::Args, Clone, Copy)]
struct Sphere {
    /// Sphere radius R (m).
    #[arg(long)]
    radius: f64,
    /// Contact modulus E* (Pa).
    #[arg(long)]
    e_star: f64,
    /// Work of adhesion w (J/m²).
    #[arg(long)]
    work_of_adhesion: f64,
    /// Lennard-Jones equilibrium separation z₀ (m).
    #[arg(long, default_value_t = 0.3e-9)]
    z0: f64,
}

#[derive(Subcommand)]
enum Command {
    /// Force–approach cycle of DMT, JKR and Maugis–Dugdale (λ = 1.157 μ) under
    /// displacement control, and their pull-off forces.
    Curve {
        #[command(flatten)]
        sphere: Sphere,
        /// Points per direction.
        #[arg(long, default_value_t = 200)]
        points: usize,
        /// Write the curves as CSV.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Write an SVG plot.
        #[arg(long)]
        svg: Option<PathBuf>,
    },
    /// Fit a measured indentation curve: κ and d (Borodich), reduced modulus
    /// and hardness (Oliver–Pharr), validity flags; plot data and fits.
    Indent {
        /// The curve: CSV `time_s,depth_m,load_N,segment` (`#` comments) or
        /// two columns depth (m), load (N).
        file: PathBuf,
        /// sphere:radius=R (m) | cone:half_angle=DEG | berkovich | vickers |
        /// cube-corner | unknown.
        #[arg(long, default_value = "berkovich")]
        indenter: String,
        /// Area-function coefficients C0,C1,C2,… (NanoSuite convention: h_c in
        /// nm, A in nm²); the ideal area of the indenter when absent.
        #[arg(long, value_delimiter = ',')]
        area: Option<Vec<f64>>,
        /// Indenter Young's modulus (Pa); diamond 1141 GPa (Oliver & Pharr
        /// 1992). `--tip-modulus` is the same option.
        #[arg(long, alias = "tip-modulus", default_value_t = 1141e9)]
        e_indenter: f64,
        /// Indenter Poisson's ratio; diamond 0.07. `--tip-poisson` is the same
        /// option.
        #[arg(long, alias = "tip-poisson", default_value_t = 0.07)]
        nu_indenter: f64,
        /// Sample Poisson's ratio.
        #[arg(long, default_value_t = 0.3)]
        nu_sample: f64,
        /// Oliver–Pharr β of E_r = √π S/(2β√A); the indenter's when absent
        /// (King 1987: 1.034 Berkovich and cube corner, 1.012 Vickers, 1
        /// axisymmetric).
        #[arg(long)]
        beta: Option<f64>,
        /// ε of the contact depth h_c = h_max − ε P_max/S (0.75, paraboloid
        /// of revolution; Oliver & Pharr 1992, ISO 14577-1).
        #[arg(long, default_value_t = 0.75)]
        epsilon: f64,
        /// Load window LO,HI of the unloading fit, fractions of P_max
        /// (default 0.2,0.98).
        #[arg(long, value_delimiter = ',')]
        fit_window: Option<Vec<f64>>,
        /// Ignore the file's segment labels and detect the segments.
        #[arg(long)]
        detect_segments: bool,
        /// Print one JSON object instead of the report.
        #[arg(long)]
        json: bool,
        /// Write an SVG plot of the data with the fitted curves.
        #[arg(long)]
        svg: Option<PathBuf>,
    },
    /// Analyse a measured AFM force–distance curve: baseline, contact point,
    /// jump-in, pull-off, adhesion energy, contact-law fits (E*, w or E*√R,
    /// wR with standard errors, Tabor parameter) and the recommended model.
    Afm(afm::AfmArgs),
    /// ISO 21920-2 (or ISO 4287) parameters, spectrum and plots of a measured
    /// line scan (or the areal parameters of a height map).
    Profile(profile::ProfileArgs),
    /// Slide a hierarchical slider over a counter-surface (a scene, JSON):
    /// CSV of every step, SVG plots, a summary (`--json`: one JSON object).
    Slide(slide::SlideArgs),
    /// The numerical Lennard-Jones sphere: full force–approach curve, jump
    /// points, pull-off and hysteresis.
    Lj {
        #[command(flatten)]
        sphere: Sphere,
        /// Radial cells (0 = the converged default).
        #[arg(long, default_value_t = 0)]
        grid: usize,
        /// Write the curve as CSV.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Write an SVG plot.
        #[arg(long)]
        svg: Option<PathBuf>,
    },
}

fn main() {
    if let Err(e) = run(Cli::parse()) {
        use std::io::Write;
        // Not `eprintln!`: it panics when stderr is gone too.
        let _ = writeln!(std::io::stderr(), "asperity: {e}");
        std::process::exit(1);
    }
}

type Series = (String, Vec<(f64, f64)>);

fn run(cli: Cli) -> Result<(), Box<dyn Error>> {
    match cli.command {
        Command::Curve {
            sphere: s,
            points,
            csv,
            svg,
        } => {
            let md = MaugisDugdale::from_tabor(s.radius, s.e_star, s.work_of_adhesion, s.z0)?;
            let dmt = Dmt::new(s.radius, s.e_star, s.work_of_adhesion)?;
            let jkr = Jkr::new(s.radius, s.e_star, s.work_of_adhesion)?;
            let scale = std::f64::consts::PI * s.radius * s.work_of_adhesion;
            let len = md.length_scale();
            let mu =
                asperity::material::tabor_parameter(s.radius, s.work_of_adhesion, s.e_star, s.z0)?;
            outln!(
                "Tabor mu = {mu:.5}, Maugis lambda = {:.5}, length scale = {len:.4e} m",
                md.lambda()
            );
            outln!(
                "{:<16} {:>16} {:>16}",
                "model",
                "P_c load / N",
                "P_c displ. / N"
            );
            for (name, l, d) in [
                (
                    "DMT",
                    dmt.pull_off_force(Control::Load)?,
                    dmt.pull_off_force(Control::Displacement)?,
                ),
                (
                    "JKR",
                    jkr.pull_off_force(Control::Load)?,
                    jkr.pull_off_force(Control::Displacement)?,
                ),
                (
                    "Maugis-Dugdale",
                    md.pull_off_force(Control::Load)?,
                    md.pull_off_force(Control::Displacement)?,
                ),
            ] {
                outln!("{name:<16} {l:>16.6e} {d:>16.6e}");
            }
            let lo = -3.0 * len - md.range();
            let hi = 4.0 * len;
            let path: Vec<f64> = (0..=points)
                .map(|i| lo + (hi - lo) * i as f64 / points as f64)
                .chain(
                    (0..=points)
                        .rev()
                        .map(|i| lo + (hi - lo) * i as f64 / points as f64),
                )
                .collect();
            let series: Vec<Series> = vec![
                ("DMT".into(), cycle(&dmt, &path)?),
                ("JKR".into(), cycle(&jkr, &path)?),
                ("Maugis-Dugdale".into(), cycle(&md, &path)?),
            ];
            if let Some(p) = csv {
                write_csv(&p, &series, "delta_m", "force_N")?;
            }
            if let Some(p) = svg {
                let norm: Vec<Series> = series
                    .iter()
                    .map(|(n, v)| {
                        (
                            n.clone(),
                            v.iter().map(|&(d, f)| (d / len, f / scale)).collect(),
                        )
                    })
                    .collect();
                plot(
                    &p,
                    "Force-approach cycle",
                    "approach / length scale",
                    "force / (pi w R)",
                    &norm,
                )?;
            }
        }
        Command::Indent {
            file,
            indenter,
            area,
            e_indenter,
            nu_indenter,
            nu_sample,
            beta,
            epsilon,
            fit_window,
            detect_segments,
            json,
            svg,
        } => indent(
            &file,
            &indenter,
            area,
            e_indenter,
            nu_indenter,
            nu_sample,
            OpChoices {
                beta,
                epsilon,
                fit_window,
            },
            detect_segments,
            json,
            svg,
        )?,
        Command::Afm(args) => afm::run(&args)?,
        Command::Profile(args) => profile::run(&args)?,
        Command::Slide(args) => slide::run(&args)?,
        Command::Lj {
            sphere: s,
            grid,
            csv,
            svg,
        } => {
            let lj = LjSphere::new(s.radius, s.e_star, s.work_of_adhesion, s.z0)?;
            let bar = indicatif::ProgressBar::new_spinner();
            bar.set_message(format!(
                "solving the Lennard-Jones sphere, mu = {:.4}",
                lj.tabor()
            ));
            bar.enable_steady_tick(std::time::Duration::from_millis(120));
            let curve = lj.solver(grid)?.curve()?;
            bar.finish_and_clear();
            let fs = lj.force_scale();
            outln!("Tabor mu = {:.5}, grid {} cells, {} points, {} Newton iterations, max residual {:.2e}",
                lj.tabor(), curve.n_grid, curve.points.len(), curve.iterations, curve.max_residual);
            outln!(
                "pull-off (load control)         = {:.6e} N ({:.6} pi w R)",
                curve.pull_off_load.force * fs,
                curve.pull_off_load.force
            );
            if let Some(p) = curve.pull_off_displacement {
                outln!(
                    "pull-off (displacement control) = {:.6e} N ({:.6} pi w R)",
                    p * fs,
                    p
                );
            }
            if let (Some(i), Some(o)) = (curve.jump_in, curve.jump_out) {
                outln!(
                    "jump-in at approach {:.5} z0, jump-out at {:.5} z0, hysteresis {:.5e} J",
                    i.approach,
                    o.approach,
                    curve.hysteresis_energy * lj.energy_scale()
                );
            } else {
                outln!("no jumps: the curve is single-valued (mu below the S-curve onset)");
            }
            let pts: Vec<(f64, f64)> = curve.points.iter().map(|p| (p.approach, p.force)).collect();
            let series = vec![("Lennard-Jones".to_string(), pts)];
            if let Some(p) = csv {
                let dim: Vec<Series> = vec![(
                    "Lennard-Jones".into(),
                    curve
                        .points
                        .iter()
                        .map(|p| (p.approach * s.z0, p.force * fs))
                        .collect(),
                )];
                write_csv(&p, &dim, "approach_m", "force_N")?;
            }
            if let Some(p) = svg {
                plot(
                    &p,
                    "Lennard-Jones sphere",
                    "approach / z0",
                    "force / (pi w R)",
                    &series,
                )?;
            }
        }
    }
    Ok(())
}

/// The Oliver–Pharr choices of `asperity indent`: β, ε and the unloading
/// fit window (`None`: the library's defaults).
struct OpChoices {
    beta: Option<f64>,
    epsilon: f64,
    fit_window: Option<Vec<f64>>,
}

#[allow(clippy::too_many_arguments)]
fn indent(
    file: &PathBuf,
    indenter: &str,
    area: Option<Vec<f64>>,
    e_indenter: f64,
    nu_indenter: f64,
    nu_sample: f64,
    op: OpChoices,
    detect_segments: bool,
    json: bool,
    svg: Option<PathBuf>,
) -> Result<(), Box<dyn Error>> {
    use asperity::indentation::{analyze, AreaFunction, Curve, IndentationOptions, Indenter};
    // Accept `sphere:radius=1e-6` and `cone:half_angle=70.3` as well as the
    // short `sphere:1e-6`, `cone:70.3`.
    let spec = indenter.replace("radius=", "").replace("half_angle=", "");
    let ind = Indenter::parse(&spec).ok_or_else(|| {
        format!("unknown indenter `{indenter}`: sphere:radius=R | cone:half_angle=DEG | berkovich | vickers | cube-corner | unknown")
    })?;
    let bar = indicatif::ProgressBar::new_spinner();
    bar.set_message(format!("reading {}", file.display()));
    bar.enable_steady_tick(std::time::Duration::from_millis(120));
    // Name the file: "reading the curve: No such file…" alone does not say
    // which.
    let curve = Curve::read(file).map_err(|e| {
        bar.finish_and_clear();
        format!("{}: {e}", file.display())
    })?;
    bar.set_message(format!("fitting {} points", curve.len()));
    let options = IndentationOptions {
        indenter: ind,
        area: area.map(|coefficients| AreaFunction::NanoSuite { coefficients }),
        e_indenter,
        nu_indenter,
        nu_sample,
        beta: op.beta,
        epsilon: op.epsilon,
        unloading_window: match op.fit_window.as_deref() {
            Some(&[lo, hi]) => [lo, hi],
            Some(_) => return Err("--fit-window takes two numbers LO,HI".into()),
            None => IndentationOptions::default().unloading_window,
        },
        use_labels: !detect_segments,
        ..IndentationOptions::default()
    };
    let r = analyze(&curve, &options)?;
    bar.finish_and_clear();
    if json {
        outln!("{}", r.to_json());
    } else {
        let gpa = |x: Option<f64>, e: Option<f64>| match (x, e) {
            (Some(x), Some(e)) => format!("{:.3} ± {:.3} GPa", x / 1e9, e / 1e9),
            (Some(x), None) => format!("{:.3} GPa", x / 1e9),
            _ => "n/a (no unloading)".to_string(),
        };
        outln!(
            "{}: {} points, segments {}",
            file.display(),
            curve.len(),
            if r.segmentation.from_labels {
                "from the file's labels"
            } else {
                "detected"
            }
        );
        outln!(
            "  kappa (hardening index)  {:.4} ± {:.4}  ({:?})",
            r.kappa,
            r.kappa_stderr,
            r.kappa_source
        );
        outln!(
            "  d (bluntness index)      {:.4} ± {:.4}  ({:?})",
            r.d,
            r.d_stderr,
            r.d_source
        );
        outln!(
            "  loading slope            {:.4} ± {:.4}  (R² {:.5})",
            r.loading.slope,
            r.loading.slope_stderr,
            r.loading.r_squared
        );
        outln!(
            "  reduced modulus E_r      {}",
            gpa(r.reduced_modulus, r.reduced_modulus_stderr)
        );
        outln!(
            "  sample modulus E         {}",
            gpa(r.sample_modulus, r.sample_modulus_stderr)
        );
        outln!(
            "  hardness H               {}",
            gpa(r.hardness, r.hardness_stderr)
        );
        if r.flag_details.is_empty() {
            outln!("  flags: none");
        }
        for f in &r.flag_details {
            outln!("  flag {}: {}", f.code, f.message);
        }
    }
    if let Some(p) = svg {
        // Depth and load in the SI prefixes of their largest values (nm and
        // mN for a Berkovich test, µm and N for a macro-indentation).
        let (hs, hp) = axis::si_prefix(axis::magnitude(curve.depth.iter().copied()));
        let (ps, pp) = axis::si_prefix(axis::magnitude(curve.load.iter().copied()));
        let in_depth_unit = |h: f64| h / hs;
        let in_load_unit = |p: f64| p / ps;
        let data: Vec<(f64, f64)> = curve
            .depth
            .iter()
            .zip(&curve.load)
            .map(|(&h, &p)| (in_depth_unit(h), in_load_unit(p)))
            .collect();
        let mut series: Vec<Series> = vec![("data".into(), data)];
        let lf = &r.loading;
        let [l0, l1] = r.segmentation.loading;
        let hmax = curve.depth[l0..l1.max(l0 + 1).min(curve.len())]
            .iter()
            .cloned()
            .fold(0.0, f64::max);
        let fit: Vec<(f64, f64)> = (1..=100)
            .map(|i| {
                let h = hmax * i as f64 / 100.0;
                (
                    in_depth_unit(h),
                    in_load_unit(lf.reference_load * (h / lf.reference_depth).powf(lf.slope)),
                )
            })
            .collect();
        series.push((format!("loading fit, slope {:.3}", lf.slope), fit));
        if let Some(op) = &r.unloading {
            let u = &op.fit;
            let fit: Vec<(f64, f64)> = (0..=100)
                .map(|i| {
                    let h = u.final_depth + (op.peak_depth - u.final_depth) * i as f64 / 100.0;
                    (
                        in_depth_unit(h),
                        in_load_unit(u.prefactor * (h - u.final_depth).max(0.0).powf(u.exponent)),
                    )
                })
                .collect();
            series.push((format!("unloading fit, m = {:.3}", u.exponent), fit));
        }
        plot(
            &p,
            "Indentation",
            &format!("depth / {hp}m"),
            &format!("load / {pp}N"),
            &series,
        )?;
    }
    Ok(())
}

/// Forces along a displacement-controlled path, keeping the law's state.
fn cycle<L: NormalContact>(law: &L, path: &[f64]) -> Result<Vec<(f64, f64)>, asperity::Error> {
    let mut state = ContactState::default();
    path.iter()
        .map(|&d| {
            let (r, s) = law.eval(d, &state)?;
            state = s;
            Ok((d, r.force))
        })
        .collect()
}

fn write_csv(path: &PathBuf, series: &[Series], x: &str, y: &str) -> std::io::Result<()> {
    use std::io::Write;
    let mut f = std::io::BufWriter::new(std::fs::File::create(path)?);
    writeln!(f, "model,step,{x},{y}")?;
    for (name, pts) in series {
        for (i, (a, b)) in pts.iter().enumerate() {
            writeln!(f, "{name},{i},{a:.10e},{b:.10e}")?;
        }
    }
    Ok(())
}

/// `lo..hi` when it is a finite, non-empty range; otherwise a range of some
/// width around `lo` (one value, or none: 0..1).
fn widen(lo: f64, hi: f64) -> (f64, f64) {
    if lo.is_finite() && hi.is_finite() && hi > lo {
        (lo, hi)
    } else if lo.is_finite() {
        let w = if lo == 0.0 { 1.0 } else { 0.1 * lo.abs() };
        (lo - w, lo + w)
    } else {
        (0.0, 1.0)
    }
}

fn plot(
    path: &PathBuf,
    title: &str,
    x: &str,
    y: &str,
    series: &[Series],
) -> Result<(), Box<dyn Error>> {
    use plotters::prelude::*;
    let (mut x0, mut x1, mut y0, mut y1) = (
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
    );
    for (_, pts) in series {
        for &(a, b) in pts {
            x0 = x0.min(a);
            x1 = x1.max(a);
            y0 = y0.min(b);
            y1 = y1.max(b);
        }
    }
    let (x0, x1) = widen(x0, x1);
    let (y0, y1) = widen(y0, y1);
    let pad = 0.05 * (y1 - y0);
    let (fx, fy) = (axis::ticks(x0, x1), axis::ticks(y0 - pad, y1 + pad));
    let root = SVGBackend::new(path, (900, 600)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 22))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(65)
        .build_cartesian_2d(x0..x1, (y0 - pad)..(y1 + pad))?;
    chart
        .configure_mesh()
        .x_desc(x)
        .y_desc(y)
        .x_label_formatter(&*fx)
        .y_label_formatter(&*fy)
        .draw()?;
    chart::lines_with_legend(&mut chart, series.iter().cloned(), 0)?;
    root.present()?;
    Ok(())
}
