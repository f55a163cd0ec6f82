//! `asperity profile FILE`: ISO 21920-2 (or ISO 4287) parameters, spectrum
//! and plots of a measured line scan (`line`), or the ISO 25178 height
//! parameters, spectra, isotropy and scale-dependent slope and curvature of
//! a map (`map`); `plot` holds the chart helpers both share.
//!
//! Everything physical comes from `asperity::surface`: reading, form
//! removal, the Gaussian filter, the parameters, ACF, PSD, spectral moments,
//! the power-law fit and the material-ratio curve. This module only chooses
//! what to call, formats the results and draws them.

use asperity::surface::{read_measurement, Convention, Profile, Spacing, Surface, Topography};
use clap::{Args, ValueEnum};
use std::error::Error;
use std::path::PathBuf;

mod line;
mod map;
mod plot;

use line::line_scan;
use map::map;

type Res<T> = Result<T, Box<dyn Error>>;

/// Form removed by least squares before the analysis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Detrend {
    /// Nothing: heights are taken about their mean.
    None,
    /// The mean height (the parameters are the same as with `none`; the
    /// plotted profile is centred).
    Mean,
    /// A least-squares straight line (a plane for maps): ISO practice.
    Linear,
    /// A least-squares parabola (a quadric for maps): tilt and bow.
    Quadratic,
}

impl Detrend {
    fn name(self) -> &'static str {
        match self {
            Detrend::None => "none",
            Detrend::Mean => "mean",
            Detrend::Linear => "linear",
            Detrend::Quadratic => "quadratic",
        }
    }
}

/// Which standard's evaluation rules the profile parameters follow.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ConventionArg {
    /// ISO 21920-2:2021: Ra, Rq, Rsk, Rku, RΔq, Rc, RSm over the evaluation
    /// length; Rp, Rv, Rz averaged over the sections.
    Iso21920,
    /// ISO 4287:1997 / ISO 4288: every parameter but Rt averaged over the
    /// sampling lengths.
    Iso4287,
}

impl ConventionArg {
    fn convention(self) -> Convention {
        match self {
            ConventionArg::Iso21920 => Convention::Iso21920,
            ConventionArg::Iso4287 => Convention::Iso4287,
        }
    }
}

/// Arguments of `asperity profile`.
#[derive(Args)]
pub struct ProfileArgs {
    /// A line scan or a height map: an instrument file (X3P `.x3p`,
    /// Nanoscope `.di`/`.spm`/`.001`, Dektak CSV, Hommel `.hfm`, chosen by
    /// extension or content) or plain text in metres (two columns `x z`, a
    /// grid with `# dx_m=` metadata, or `x y z` triplets; comma, semicolon
    /// or whitespace separated, `#` comments).
    file: PathBuf,
    /// Evaluation rules of the profile parameters (named in the output):
    /// ISO 21920-2 (default) or ISO 4287/4288.
    #[arg(long, value_enum, default_value_t = ConventionArg::Iso21920)]
    convention: ConventionArg,
    /// Print one JSON object (SI units, ISO names Rp … RDq) instead of the
    /// table.
    #[arg(long)]
    json: bool,
    /// Form removed by least squares before the analysis (for maps: linear
    /// is a plane, quadratic a quadric).
    #[arg(long, value_enum, default_value_t = Detrend::Linear)]
    detrend: Detrend,
    /// Cut-off wavelength λc (m) of the ISO 16610-21 Gaussian filter: the
    /// parameters are those of the roughness profile (profile minus the
    /// Gaussian mean line), λc/2 is discarded at each end and the sampling
    /// length is λc (ISO 4288). For a map: the roughness (S-L) surface of
    /// the ISO 16610-61 areal Gaussian filter, λc/2 dropped at every edge.
    #[arg(long, value_name = "METRES", allow_hyphen_values = true)]
    cutoff: Option<f64>,
    /// Write SVG plots PREFIX-profile.svg, PREFIX-acf.svg, PREFIX-psd.svg and
    /// PREFIX-material-ratio.svg (maps: PREFIX-psd.svg radial PSD,
    /// PREFIX-psd2d.svg, PREFIX-acf.svg, PREFIX-scale.svg slope and
    /// curvature against scale, PREFIX-material-ratio.svg). If PREFIX
    /// is a directory, the file's stem is used inside it.
    #[arg(long, value_name = "PREFIX")]
    svg: Option<PathBuf>,
}

/// Runs `asperity profile`.
pub fn run(args: &ProfileArgs) -> Res<()> {
    let file = &args.file;
    let bar = indicatif::ProgressBar::new_spinner();
    bar.set_message(format!("reading {}", file.display()));
    bar.enable_steady_tick(std::time::Duration::from_millis(120));
    let read = read_measurement(file, Spacing::Tolerant).map_err(|e| {
        bar.finish_and_clear();
        format!("{}: {e}", file.display())
    });
    let m = read?;
    let source = Source {
        format: m.format.name(),
        channel: m.channel,
    };
    let data = match m.surface {
        Surface::Map(t) => Data::Map(t),
        Surface::Profile(p) => Data::Line(p),
    };
    bar.set_message("analysing");
    let result = match data {
        Data::Line(p) => line_scan(args, p, &bar, &source),
        Data::Map(t) => map(args, t, &bar, &source),
    };
    bar.finish_and_clear();
    result
}

enum Data {
    Line(Profile),
    Map(Topography),
}

/// The file's format and channel, for the output.
struct Source {
    format: &'static str,
    channel: Option<String>,
}

fn print_rows(rows: &[(&str, (String, &str), &str)]) {
    for (name, (value, unit), what) in rows {
        outln!("  {name:<22} {value:>12} {unit:<4} {what}");
    }
}

// ---------------------------------------------------------------- formatting

/// Scale and unit that show a length of magnitude `v` (m) with one to three
/// integer digits.
fn length_unit(v: f64) -> (f64, &'static str) {
    let a = v.abs();
    if a >= 1.0 {
        (1.0, "m")
    } else if a >= 1e-3 {
        (1e-3, "mm")
    } else if a >= 1e-6 {
        (1e-6, "µm")
    } else if a >= 1e-9 {
        (1e-9, "nm")
    } else {
        (1e-12, "pm")
    }
}

/// `v` with `digits` (≥ 1) significant digits: fixed notation, scientific
/// below 10⁻³ and from 10⁶.
fn sig(v: f64, digits: usize) -> String {
    if v == 0.0 || !v.is_finite() {
        return format!("{v}");
    }
    // The decimal exponent after rounding (99.999 → 1.000e2).
    let s = format!("{v:.*e}", digits - 1);
    let e: i32 = s[s.find('e').map_or(s.len(), |i| i + 1)..]
        .parse()
        .unwrap_or(0);
    if !(-3..6).contains(&e) {
        return s;
    }
    let dec = (digits as i32 - 1 - e).max(0) as usize;
    format!("{v:.dec$}")
}

/// A length with 4 significant digits and a suitable unit, e.g. `1.500 mm`.
fn length_text(v: f64) -> String {
    let (s, u) = length_unit(v);
    format!("{} {u}", sig(v / s, 4))
}

// --------------------------------------------------------------------- plots
