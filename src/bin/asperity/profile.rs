//! `asperity profile FILE`: ISO 4287 parameters, spectrum and plots of a
//! measured line scan, or the ISO 25178 height parameters, spectra, isotropy
//! and scale-dependent slope and curvature of a map.
//!
//! Everything physical comes from `asperity::surface`: reading, form
//! removal, the Gaussian filter, the parameters, ACF, PSD, spectral moments,
//! the power-law fit and the material-ratio curve. This module only chooses
//! what to call, formats the results and draws them.

use asperity::surface::{
    acf_2d, areal_gaussian_filter, isotropy, psd_2d, scale_dependent_map, Acf2d, Isotropy, Psd2d,
    Radial, ScaleDependentMap,
};
use asperity::surface::{
    functional_parameters, hurst_estimate, material_ratio_parameters, psd_windowed,
    read_measurement, spectral_moments, Convention, FilterEnds, Form, FunctionalParameters,
    HurstFit, MapForm, MaterialRatioCurve, MaterialRatioParameters, ParameterOptions, Profile,
    RoughnessParameters, Spacing, SpectralMoments, Surface, Topography, Window,
};
use clap::{Args, ValueEnum};
use plotters::coord::Shift;
use plotters::prelude::*;
use serde_json::{json, Value};
use std::error::Error;
use std::path::{Path, PathBuf};

use crate::axis::ticks;

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

/// Everything computed for a line scan.
struct LineAnalysis {
    /// The profile as read (m).
    raw: Profile,
    /// The analysed profile: form removed, and with a cut-off the roughness
    /// profile on the retained samples (m).
    analysed: Profile,
    /// Index in `raw` of the first analysed sample.
    first: usize,
    /// Samples of `analysed` in the evaluation length (whole sampling
    /// lengths).
    evaluated: usize,
    params: RoughnessParameters,
    /// Spectral moments from the derivatives (seven-point slopes, three-point
    /// curvatures): the profile's own slope and curvature variances.
    moments: SpectralMoments,
    /// The q^p moments of the rectangular-window PSD: for a non-periodic
    /// scan they measure the jump between its ends.
    rectangular: SpectralMoments,
    /// ISO 13565-2 parameters of the evaluation length.
    material_ratio: MaterialRatioParameters,
    correlation_length: Option<f64>,
    fit: Option<HurstFit>,
    /// Why there is no power-law fit.
    no_fit: Option<&'static str>,
}

fn analyse_line(
    raw: Profile,
    detrend: Detrend,
    cutoff: Option<f64>,
    convention: Convention,
) -> Res<LineAnalysis> {
    let detrended = match detrend {
        Detrend::None => raw.clone(),
        Detrend::Mean => raw.remove_form(Form::Mean)?,
        Detrend::Linear => raw.remove_form(Form::Linear)?,
        Detrend::Quadratic => raw.remove_form(Form::Quadratic)?,
    };
    let (analysed, first) = match cutoff {
        None => (detrended, 0),
        Some(lc) => {
            let f = detrended
                .gaussian_filter(lc, FilterEnds::Discard)
                .map_err(|e| {
                    format!(
                        "--cutoff {lc:e} m (profile length {}): {e}",
                        length_text(raw.length())
                    )
                })?;
            if f.roughness.length() < lc {
                return Err(format!(
                    "--cutoff {lc:e} m is too long for this profile ({}): after discarding \
                     λc/2 at each end {} remain, less than one sampling length λc; the \
                     profile must be at least 2λc long",
                    length_text(raw.length()),
                    length_text(f.roughness.length())
                )
                .into());
            }
            (f.roughness, f.first_index)
        }
    };
    let options = ParameterOptions {
        sampling_length: cutoff,
        convention,
        ..ParameterOptions::default()
    };
    let params = analysed.parameters(&options)?;
    let dx = analysed.dx();
    let evaluated = params.sampling_lengths * (params.sampling_length / dx).round() as usize;
    let material_ratio = material_ratio_parameters(&analysed.heights()[..evaluated])?;
    let moments = spectral_moments(analysed.heights(), dx)?;
    let rectangular = analysed.psd()?.moments();
    let correlation_length = analysed
        .acf()?
        .correlation_length(std::f64::consts::E.recip())?;
    // The fit behind psd_hurst_exponent: its band, uncertainty and prefactor.
    let estimate = hurst_estimate(analysed.heights(), dx)?;
    Ok(LineAnalysis {
        raw,
        analysed,
        first,
        evaluated,
        params,
        moments,
        rectangular,
        material_ratio,
        correlation_length,
        fit: estimate.fit,
        no_fit: estimate.reason,
    })
}

fn line_scan(
    args: &ProfileArgs,
    raw: Profile,
    bar: &indicatif::ProgressBar,
    source: &Source,
) -> Res<()> {
    let a = analyse_line(raw, args.detrend, args.cutoff, args.convention.convention())?;
    let plots = match &args.svg {
        Some(prefix) => {
            bar.set_message("plotting");
            line_plots(&plot_prefix(prefix, &args.file), &a, args)?
        }
        None => Vec::new(),
    };
    bar.finish_and_clear();
    let p = &a.params;
    if args.json {
        let mut v = serde_json::to_value(p)?;
        let o = v
            .as_object_mut()
            .ok_or("RoughnessParameters is not a JSON object")?;
        if let Value::Object(k) = serde_json::to_value(a.material_ratio)? {
            o.extend(k);
        }
        let extra = json!({
            "file": args.file.display().to_string(),
            "format": source.format,
            "channel": source.channel,
            "kind": "profile",
            "detrend": args.detrend.name(),
            "cutoff": args.cutoff,
            "points_read": a.raw.len(),
            "points": a.analysed.len(),
            "dx": a.analysed.dx(),
            "x0": a.analysed.x0(),
            "length": a.analysed.length(),
            "evaluation_length": p.sampling_length * p.sampling_lengths as f64,
            "spacing_deviation": a.raw.spacing_deviation(),
            "moments_from": "derivatives (seven-point slopes, three-point second differences)",
            "m0": a.moments.m0,
            "m2": a.moments.m2,
            "m4": a.moments.m4,
            "nayak_alpha": a.moments.nayak_alpha(),
            "m0_rectangular_window": a.rectangular.m0,
            "m2_rectangular_window": a.rectangular.m2,
            "m4_rectangular_window": a.rectangular.m4,
            "nayak_alpha_rectangular_window": a.rectangular.nayak_alpha(),
            "correlation_length_1e": a.correlation_length,
            "psd_hurst_uncertainty": a.fit.map(|f| f.hurst_uncertainty),
            "psd_fit": a.fit,
            "psd_fit_reason": a.no_fit,
            "plots": plots,
        });
        if let Value::Object(extra) = extra {
            o.extend(extra);
        }
        outln!("{v}");
        return Ok(());
    }
    let (hs, hu) = length_unit(p.rt);
    let h = |v: f64| (sig(v / hs, 4), hu);
    let opt_h = |v: Option<f64>| v.map_or(("n/a".to_string(), ""), h);
    let len = |v: f64| {
        let (s, u) = length_unit(v);
        (sig(v / s, 4), u)
    };
    let num = |v: f64| (sig(v, 4), "");
    let pct = |v: f64| (sig(100.0 * v, 4), "%");
    let sci = |v: f64, u: &'static str| (format!("{v:.4e}"), u);
    outln!(
        "{}: line scan, {} points, dx = {}, length {}{}",
        args.file.display(),
        a.raw.len(),
        length_text(a.raw.dx()),
        length_text(a.raw.length()),
        if a.raw.spacing_deviation() > 1e-3 {
            format!(
                " (positions up to {:.2} dx off the uniform grid)",
                a.raw.spacing_deviation()
            )
        } else {
            String::new()
        }
    );
    let filter = match args.cutoff {
        Some(lc) => format!(
            "Gaussian cut-off λc = {} (roughness profile, {} points after discarding λc/2 at each end)",
            length_text(lc),
            a.analysed.len()
        ),
        None => "no cut-off".to_string(),
    };
    outln!(
        "detrend {}, {filter}; {} rules, {} file",
        args.detrend.name(),
        p.convention.name(),
        source.format
    );
    outln!(
        "evaluation length {} = {} sampling length{} of {}",
        length_text(p.sampling_length * p.sampling_lengths as f64),
        p.sampling_lengths,
        if p.sampling_lengths == 1 { "" } else { "s" },
        length_text(p.sampling_length)
    );
    let rows: Vec<(&str, (String, &str), &str)> = vec![
        ("Rp", h(p.rp), "maximum peak height"),
        ("Rv", h(p.rv), "maximum valley depth"),
        ("Rz", h(p.rz), "maximum height Rp + Rv"),
        ("Rc", opt_h(p.rc), "mean height of profile elements"),
        ("Rt", h(p.rt), "total height (evaluation length)"),
        ("Ra", h(p.ra), "arithmetic mean deviation"),
        ("Rq", h(p.rq), "root-mean-square deviation"),
        ("Rsk", num(p.rsk), "skewness"),
        ("Rku", num(p.rku), "kurtosis"),
        (
            "RSm",
            p.rsm.map_or(("n/a".to_string(), ""), len),
            "mean width of profile elements",
        ),
        ("RDq", num(p.rdq), "root-mean-square slope RΔq"),
        (
            "Rk",
            h(a.material_ratio.rk),
            "core roughness depth (ISO 13565-2)",
        ),
        ("Rpk", h(a.material_ratio.rpk), "reduced peak height"),
        ("Rvk", h(a.material_ratio.rvk), "reduced valley depth"),
        (
            "Mr1",
            pct(a.material_ratio.mr1),
            "material ratio at the top of the core",
        ),
        (
            "Mr2",
            pct(a.material_ratio.mr2),
            "material ratio at the bottom of the core",
        ),
        (
            "psd_hurst_exponent",
            p.psd_hurst_exponent.map_or(("n/a".to_string(), ""), num),
            match (&a.fit, a.no_fit) {
                (Some(_), _) => "Hurst exponent H of the PSD power law",
                (None, Some(reason)) => reason,
                (None, None) => "no power law",
            },
        ),
        (
            "psd_hurst_uncertainty",
            a.fit
                .map_or(("n/a".to_string(), ""), |f| num(f.hurst_uncertainty)),
            "standard error of H (statistical, in the band)",
        ),
        (
            "m0",
            sci(a.moments.m0, "m²"),
            "spectral moment: height variance",
        ),
        (
            "m2",
            sci(a.moments.m2, ""),
            "slope variance (seven-point slopes, as RΔq)",
        ),
        (
            "m4",
            sci(a.moments.m4, "m⁻²"),
            "curvature variance (three-point differences)",
        ),
        (
            "nayak_alpha",
            num(a.moments.nayak_alpha()),
            "Nayak bandwidth m0 m4 / m2²",
        ),
        (
            "m2_rectangular_window",
            sci(a.rectangular.m2, ""),
            "∫q²G dq, rectangular window (end jump for a non-periodic scan)",
        ),
        (
            "m4_rectangular_window",
            sci(a.rectangular.m4, "m⁻²"),
            "∫q⁴G dq, rectangular window",
        ),
        (
            "correlation_length_1e",
            a.correlation_length.map_or(("n/a".to_string(), ""), len),
            "lag where the ACF falls to 1/e",
        ),
    ];
    print_rows(&rows);
    if let Some(f) = &a.fit {
        outln!(
            "PSD power law G = A q^{:.4} over q = {:.3e} … {:.3e} rad/m (band from the data, \
             {} bins, χ²/ν = {:.2}): H = {:.3} ± {:.3}",
            f.slope,
            f.q_min,
            f.q_max,
            f.bins,
            f.chi2_per_dof,
            f.hurst,
            f.hurst_uncertainty
        );
    }
    for p in &plots {
        outln!("wrote {p}");
    }
    Ok(())
}

fn map(
    args: &ProfileArgs,
    t: Topography,
    bar: &indicatif::ProgressBar,
    source: &Source,
) -> Res<()> {
    let read = format!(
        "{}: height map ({} file{}), {} × {} points, dx = {}, dy = {}, {} × {}",
        args.file.display(),
        source.format,
        source
            .channel
            .as_deref()
            .map_or(String::new(), |c| format!(", channel {c}")),
        t.nx(),
        t.ny(),
        length_text(t.dx()),
        length_text(t.dy()),
        length_text(t.nx() as f64 * t.dx()),
        length_text(t.ny() as f64 * t.dy())
    );
    let t = match args.detrend {
        Detrend::None => t,
        Detrend::Mean => t.remove_form(MapForm::Mean)?,
        Detrend::Linear => t.remove_form(MapForm::Plane)?,
        Detrend::Quadratic => t.remove_form(MapForm::Quadratic)?,
    };
    // With a cut-off: the S-L (roughness) surface of the ISO 16610-61 areal
    // Gaussian filter, λc/2 dropped at every edge.
    let (t, first) = match args.cutoff {
        None => (t, None),
        Some(lc) => {
            let f = areal_gaussian_filter(&t, lc, FilterEnds::Discard).map_err(|e| {
                format!(
                    "--cutoff {lc:e} m (map {} × {}): {e}",
                    length_text(t.nx() as f64 * t.dx()),
                    length_text(t.ny() as f64 * t.dy())
                )
            })?;
            (f.roughness, Some(f.first_index))
        }
    };
    let ma = analyse_map(&t)?;
    let s = t.parameters()?;
    let f: FunctionalParameters = functional_parameters(&t)?;
    let plots = match &args.svg {
        Some(prefix) => {
            bar.set_message("plotting");
            let prefix = plot_prefix(prefix, &args.file);
            let mut written = map_plots(&prefix, &ma, args)?;
            let path = suffixed(&prefix, "-material-ratio.svg");
            material_ratio_plot(&path, t.heights())?;
            written.push(path.display().to_string());
            written
        }
        None => Vec::new(),
    };
    bar.finish_and_clear();
    if args.json {
        let mut v = serde_json::to_value(s)?;
        let o = v
            .as_object_mut()
            .ok_or("ArealParameters is not a JSON object")?;
        if let Value::Object(k) = serde_json::to_value(f)? {
            o.extend(k);
        }
        let extra = json!({
            "file": args.file.display().to_string(),
            "format": source.format,
            "channel": source.channel,
            "kind": "map",
            "detrend": args.detrend.name(),
            "points": t.heights().len(),
            "nx": t.nx(),
            "ny": t.ny(),
            "dx": t.dx(),
            "dy": t.dy(),
            "cutoff": args.cutoff,
            "first_index": first,
            "isotropy": ma.isotropy,
            "scale_dependent": ma.scale,
            "psd_radial": {
                "window": "hann",
                "q": ma.psd_radial.r,
                "c": ma.psd_radial.value,
            },
            "acf_radial": {
                "lag": ma.acf_radial.r,
                "r": ma.acf_radial.value,
            },
            "plots": plots,
        });
        if let Value::Object(extra) = extra {
            o.extend(extra);
        }
        outln!("{v}");
        return Ok(());
    }
    outln!("{read}");
    outln!(
        "detrend {}{}",
        args.detrend.name(),
        match args.detrend {
            Detrend::Linear => " (plane)",
            Detrend::Quadratic => " (quadric)",
            _ => "",
        }
    );
    let (hs, hu) = length_unit(s.sz);
    let h = |v: f64| (sig(v / hs, 4), hu);
    let num = |v: f64| (sig(v, 4), "");
    let pct = |v: f64| (sig(100.0 * v, 4), "%");
    // m³/m² shown as ml/m² (ISO 25178-2's unit): 1 m³/m² = 10⁶ ml/m².
    let vol = |v: f64| (sig(v * 1e6, 4), "ml/m²");
    let rows: Vec<(&str, (String, &str), &str)> = vec![
        ("Sa", h(s.sa), "arithmetic mean height"),
        ("Sq", h(s.sq), "root-mean-square height"),
        ("Ssk", num(s.ssk), "skewness"),
        ("Sku", num(s.sku), "kurtosis"),
        ("Sp", h(s.sp), "maximum peak height"),
        ("Sv", h(s.sv), "maximum pit depth"),
        ("Sz", h(s.sz), "maximum height Sp + Sv"),
        ("Sdq", num(s.sdq), "root-mean-square gradient"),
        ("Sk", h(f.sk), "core height (ISO 25178-2)"),
        ("Spk", h(f.spk), "reduced peak height"),
        ("Svk", h(f.svk), "reduced dale height"),
        ("Smr1", pct(f.smr1), "material ratio at the top of the core"),
        (
            "Smr2",
            pct(f.smr2),
            "material ratio at the bottom of the core",
        ),
        ("Vmp", vol(f.vmp), "peak material volume (p = 10 %)"),
        ("Vmc", vol(f.vmc), "core material volume (10 % to 80 %)"),
        ("Vvc", vol(f.vvc), "core void volume (10 % to 80 %)"),
        ("Vvv", vol(f.vvv), "dale void volume (q = 80 %)"),
    ];
    print_rows(&rows);
    if let Some(lc) = args.cutoff {
        outln!(
            "roughness (S-L) surface of the ISO 16610-61 Gaussian filter, λc = {}, {} × {} points after dropping λc/2 at each edge",
            length_text(lc),
            t.nx(),
            t.ny()
        );
    }
    print_map_analysis(&ma);
    for p in &plots {
        outln!("wrote {p}");
    }
    Ok(())
}

/// The map quantities beyond the ISO height parameters.
struct MapAnalysis {
    /// Hann-windowed 2-D PSD (centred) and its radial average.
    psd: Psd2d,
    psd_radial: Radial,
    acf: Acf2d,
    acf_radial: Radial,
    isotropy: Isotropy,
    scale: ScaleDependentMap,
}

fn analyse_map(t: &Topography) -> Res<MapAnalysis> {
    // A measured map is not periodic: the Hann window keeps the edges' jump
    // out of the spectrum.
    let psd = psd_2d(t, Window::Hann)?;
    let psd_radial = psd.radial();
    let acf = acf_2d(t)?;
    let acf_radial = acf.radial();
    Ok(MapAnalysis {
        psd,
        psd_radial,
        acf,
        acf_radial,
        isotropy: isotropy(t, 0.2)?,
        scale: scale_dependent_map(t)?,
    })
}

fn print_map_analysis(m: &MapAnalysis) {
    let i = &m.isotropy;
    let len = |v: Option<f64>| v.map_or("n/a".to_string(), length_text);
    outln!(
        "isotropy: Str (ACF to {}) = {}, Sal = {}, longest decay {}, lay at {:.1}°; \
         directional rms slopes {:.4} … {:.4} (ratio {:.3}, steepest at {:.1}°)",
        i.s,
        i.texture_aspect_ratio
            .map_or("n/a (no decay in some direction)".to_string(), |v| sig(
                v, 3
            )),
        len(i.autocorrelation_length),
        len(i.longest_decay_length),
        i.texture_direction.to_degrees(),
        i.rms_slope_min,
        i.rms_slope_max,
        i.gradient_ratio,
        i.gradient_direction.to_degrees()
    );
    let s = &m.scale;
    outln!("scale-dependent rms slope / curvature (finite differences at step h):");
    outln!(
        "  {:>12} {:>10} {:>10} {:>14} {:>14}",
        "h",
        "slope x",
        "slope y",
        "curv. x (1/m)",
        "curv. y (1/m)"
    );
    for k in 0..s.along_x.scale.len().min(s.along_y.scale.len()) {
        outln!(
            "  {:>12} {:>10} {:>10} {:>14.4e} {:>14.4e}",
            length_text(s.along_x.scale[k]),
            sig(s.along_x.slope_rms[k], 4),
            sig(s.along_y.slope_rms[k], 4),
            s.along_x.curvature_rms[k],
            s.along_y.curvature_rms[k]
        );
    }
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

/// Pixel columns of a plot: decimation keeps at most two points per column.
const COLUMNS: usize = 1000;

fn plot_prefix(prefix: &Path, file: &Path) -> PathBuf {
    if prefix.is_dir() {
        prefix.join(file.file_stem().unwrap_or(file.as_os_str()))
    } else {
        prefix.to_path_buf()
    }
}

fn suffixed(prefix: &Path, suffix: &str) -> PathBuf {
    let mut s = prefix.as_os_str().to_owned();
    s.push(suffix);
    PathBuf::from(s)
}

/// Min/max decimation for plotting: of `pts` (x increasing), keeps in each of
/// `COLUMNS` equal bins of x (of ln x with `log_x`) only the lowest and the
/// highest point, in their original order, so that the polyline through them
/// draws the same envelope as the polyline through all points.
fn decimate(pts: &[(f64, f64)], log_x: bool) -> Vec<(f64, f64)> {
    if pts.len() <= 2 * COLUMNS {
        return pts.to_vec();
    }
    let t = |x: f64| if log_x { x.ln() } else { x };
    let t0 = t(pts[0].0);
    let span = t(pts[pts.len() - 1].0) - t0;
    if span.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
        return pts.to_vec();
    }
    let column = |x: f64| (((t(x) - t0) / span * COLUMNS as f64) as usize).min(COLUMNS - 1);
    let mut out = Vec::with_capacity(2 * COLUMNS + 2);
    let flush = |out: &mut Vec<(f64, f64)>, lo: usize, hi: usize| {
        let (a, b) = (lo.min(hi), lo.max(hi));
        out.push(pts[a]);
        if b != a {
            out.push(pts[b]);
        }
    };
    let (mut current, mut lo, mut hi) = (column(pts[0].0), 0, 0);
    for (i, &(x, y)) in pts.iter().enumerate().skip(1) {
        let c = column(x);
        if c != current {
            flush(&mut out, lo, hi);
            (current, lo, hi) = (c, i, i);
        } else if y < pts[lo].1 {
            lo = i;
        } else if y > pts[hi].1 {
            hi = i;
        }
    }
    flush(&mut out, lo, hi);
    out
}

/// A polyline of a chart.
struct Line {
    name: String,
    pts: Vec<(f64, f64)>,
    color: RGBColor,
    width: u32,
}

fn line(name: impl Into<String>, pts: Vec<(f64, f64)>, color: RGBColor, width: u32) -> Line {
    Line {
        name: name.into(),
        pts,
        color,
        width,
    }
}

/// Data range of `lines` along x (`x = true`) or y, padded by 5 % on y, never
/// empty.
fn range(lines: &[Line], x: bool, pad: f64) -> (f64, f64) {
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for v in lines
        .iter()
        .flat_map(|l| l.pts.iter().map(|p| if x { p.0 } else { p.1 }))
    {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if !(lo.is_finite() && hi.is_finite()) {
        return (0.0, 1.0);
    }
    if hi <= lo {
        let d = if lo == 0.0 { 1.0 } else { lo.abs() * 0.1 };
        return (lo - d, hi + d);
    }
    let p = pad * (hi - lo);
    (lo - p, hi + p)
}

/// Draws `lines` on linear axes in `area`.
fn linear_chart(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    caption: &str,
    x_desc: &str,
    y_desc: &str,
    lines: &[Line],
) -> Res<()> {
    let (x0, x1) = range(lines, true, 0.0);
    let (y0, y1) = range(lines, false, 0.05);
    let (fx, fy) = (ticks(x0, x1), ticks(y0, y1));
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 20))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(75)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(&*fx)
        .y_label_formatter(&*fy)
        .draw()?;
    draw_lines(&mut chart, lines)
}

fn draw_lines<'a, 'b: 'a, X, Y>(
    chart: &mut ChartContext<'a, SVGBackend<'b>, Cartesian2d<X, Y>>,
    lines: &[Line],
) -> Res<()>
where
    X: Ranged<ValueType = f64>,
    Y: Ranged<ValueType = f64>,
{
    for l in lines {
        let style = l.color.stroke_width(l.width);
        chart
            .draw_series(LineSeries::new(l.pts.iter().copied(), style))?
            .label(l.name.as_str())
            .legend(move |(a, b)| PathElement::new(vec![(a, b), (a + 20, b)], style));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .border_style(BLACK)
        .background_style(WHITE.mix(0.8))
        .draw()?;
    Ok(())
}

/// Renders an SVG of `size` pixels with `draw` and writes it to `path`.
fn write_svg(
    path: &Path,
    size: (u32, u32),
    draw: impl FnOnce(&DrawingArea<SVGBackend<'_>, Shift>) -> Res<()>,
) -> Res<()> {
    let mut buf = String::new();
    {
        let root = SVGBackend::with_string(&mut buf, size).into_drawing_area();
        root.fill(&WHITE)?;
        draw(&root)?;
        root.present()?;
    }
    std::fs::write(path, buf).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(())
}

/// The four plots of a line scan; returns the paths written.
fn line_plots(prefix: &Path, a: &LineAnalysis, args: &ProfileArgs) -> Res<Vec<String>> {
    let dx = a.analysed.dx();
    let n = a.analysed.len();
    let z = a.analysed.heights();
    // The mean line is the level z̄ of the analysed profile over the
    // evaluation length; in the coordinates of the measured profile it is
    // raw − (analysed − z̄): the removed form, plus the Gaussian mean line
    // with a cut-off.
    let zbar = z[..a.evaluated].iter().sum::<f64>() / a.evaluated as f64;
    let raw = &a.raw.heights()[a.first..a.first + n];
    let raw_mean = raw.iter().sum::<f64>() / n as f64;
    let xs: Vec<f64> = (0..n).map(|j| a.analysed.x(j)).collect();
    let (xs_scale, xu) = length_unit(xs[0].abs().max(xs[n - 1].abs()));
    let measured: Vec<(f64, f64)> = xs
        .iter()
        .zip(raw)
        .map(|(&x, &r)| (x, r - raw_mean))
        .collect();
    let mean_line: Vec<(f64, f64)> = xs
        .iter()
        .zip(raw.iter().zip(z))
        .map(|(&x, (&r, &h))| (x, r - (h - zbar) - raw_mean))
        .collect();
    let rough: Vec<(f64, f64)> = xs.iter().zip(z).map(|(&x, &h)| (x, h - zbar)).collect();
    let top_span = measured
        .iter()
        .chain(&mean_line)
        .fold(0.0f64, |m, p| m.max(p.1.abs()));
    let bottom_span = rough.iter().fold(0.0f64, |m, p| m.max(p.1.abs()));
    let scaled = |pts: &[(f64, f64)], ys: f64| -> Vec<(f64, f64)> {
        decimate(pts, false)
            .into_iter()
            .map(|(x, y)| (x / xs_scale, y / ys))
            .collect()
    };
    let (ts, tu) = length_unit(top_span);
    let (bs, bu) = length_unit(bottom_span);
    let mean_name = match (args.cutoff, args.detrend) {
        (Some(lc), _) => format!("mean line (Gaussian, λc = {})", length_text(lc)),
        (None, Detrend::None | Detrend::Mean) => "mean line (mean height)".to_string(),
        (None, d) => format!("mean line (least-squares {})", d.name()),
    };
    let name = args
        .file
        .file_name()
        .map_or(String::new(), |s| s.to_string_lossy().into_owned());
    let x_desc = format!("position x / {xu}");
    let mut written = Vec::new();

    let path = suffixed(prefix, "-profile.svg");
    write_svg(&path, (1000, 900), |root| {
        let panels = root.split_evenly((2, 1));
        linear_chart(
            &panels[0],
            &format!("{name}: measured profile (about its mean) and mean line"),
            &x_desc,
            &format!("height z / {tu}"),
            &[
                line("measured", scaled(&measured, ts), BLUE, 1),
                line(mean_name.as_str(), scaled(&mean_line, ts), RED, 2),
            ],
        )?;
        let x_end = [xs[0] / xs_scale, xs[n - 1] / xs_scale];
        linear_chart(
            &panels[1],
            "profile about its mean line (analysed)",
            &x_desc,
            &format!("height Z / {bu}"),
            &[
                line("Z = z − mean line", scaled(&rough, bs), BLUE, 1),
                line(
                    "mean line",
                    x_end.iter().map(|&x| (x, 0.0)).collect(),
                    RED,
                    2,
                ),
            ],
        )
    })?;
    written.push(path.display().to_string());

    // ACF up to half the analysed length (beyond it the biased estimator
    // rests on fewer than half the pairs).
    let acf = a.analysed.acf()?;
    let rho = acf.normalized();
    let half = (n / 2).max(2);
    let (ls, lu) = length_unit(acf.lag(half - 1));
    let pts: Vec<(f64, f64)> = (0..half).map(|k| (acf.lag(k), rho[k])).collect();
    let pts: Vec<(f64, f64)> = decimate(&pts, false)
        .into_iter()
        .map(|(d, r)| (d / ls, r))
        .collect();
    let path = suffixed(prefix, "-acf.svg");
    let caption = match a.correlation_length {
        Some(c) => format!(
            "{name}: autocorrelation, R(0) = Rq² = {:.4e} m², 1/e length {}",
            acf.r[0],
            length_text(c)
        ),
        None => format!("{name}: autocorrelation, R(0) = {:.4e} m²", acf.r[0]),
    };
    write_svg(&path, (900, 600), |root| {
        linear_chart(
            root,
            &caption,
            &format!("lag δ / {lu}"),
            "ACF R(δ) / R(0)",
            &[
                line("normalised ACF", pts, BLUE, 1),
                line(
                    "1/e",
                    vec![
                        (0.0, (-1.0f64).exp()),
                        (acf.lag(half - 1) / ls, (-1.0f64).exp()),
                    ],
                    RGBColor(150, 150, 150),
                    1,
                ),
            ],
        )
    })?;
    written.push(path.display().to_string());

    // PSD: the Hann-windowed periodogram, which the power law is fitted to
    // (the rectangular one leaks the end jump ∝ q⁻² for a non-periodic scan).
    let g = psd_windowed(z, dx, Window::Hann)?;
    let gmax = g.c.iter().skip(1).fold(0.0f64, |m, &c| m.max(c));
    let floor = gmax * 1e-16;
    let pts: Vec<(f64, f64)> =
        g.q.iter()
            .zip(&g.c)
            .skip(1)
            .filter(|&(_, &c)| c > floor)
            .map(|(&q, &c)| (q, c))
            .collect();
    // Plotted as log10 q, log10 G on linear axes, labelled with q and G
    // (plotters' log axes drop every label below 2.2e-16).
    let log = |pts: &[(f64, f64)]| -> Vec<(f64, f64)> {
        pts.iter().map(|&(q, g)| (q.log10(), g.log10())).collect()
    };
    let mut lines = vec![line(
        "PSD G(q), Hann window",
        log(&decimate(&pts, true)),
        BLUE,
        1,
    )];
    if let Some(f) = &a.fit {
        let fit = [f.q_min, f.q_max].map(|q| (q, f.prefactor * q.powf(f.slope)));
        lines.push(line(
            format!(
                "power law G ∝ q^{:.3}, H = {:.3} ± {:.3}",
                f.slope, f.hurst, f.hurst_uncertainty
            ),
            log(&fit),
            RED,
            2,
        ));
    }
    let (q0, q1) = range(&lines, true, 0.0);
    let (g0, g1) = range(&lines, false, 0.03);
    let path = suffixed(prefix, "-psd.svg");
    write_svg(&path, (900, 600), |root| {
        let mut chart = ChartBuilder::on(root)
            .caption(
                format!("{name}: power spectral density (one-sided)"),
                ("sans-serif", 20),
            )
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(75)
            .build_cartesian_2d(q0..q1, g0..g1)?;
        chart
            .configure_mesh()
            .x_desc("wavenumber q / (rad/m)")
            .y_desc("PSD G(q) / m³")
            .max_light_lines(0)
            .x_label_formatter(&decade_label)
            .y_label_formatter(&decade_label)
            .draw()?;
        draw_lines(&mut chart, &lines)
    })?;
    written.push(path.display().to_string());

    let path = suffixed(prefix, "-material-ratio.svg");
    material_ratio_plot(&path, &z[..a.evaluated])?;
    written.push(path.display().to_string());
    Ok(written)
}

/// Label of a log10 value: `1e-20` at whole decades, else the value.
fn decade_label(v: &f64) -> String {
    if (v - v.round()).abs() < 1e-9 {
        format!("1e{}", v.round())
    } else {
        format!("{:.2e}", 10f64.powf(*v))
    }
}

/// The Abbott–Firestone curve of `heights` (m): level c from the mean line
/// against the material ratio Rmr.
fn material_ratio_plot(path: &Path, heights: &[f64]) -> Res<()> {
    let curve = MaterialRatioCurve::new(heights)?.curve(COLUMNS + 1);
    let span = curve.iter().fold(0.0f64, |m, p| m.max(p.1.abs()));
    let (s, u) = length_unit(span);
    let pts: Vec<(f64, f64)> = curve.iter().map(|&(r, c)| (100.0 * r, c / s)).collect();
    write_svg(path, (900, 600), |root| {
        linear_chart(
            root,
            "material-ratio (Abbott–Firestone) curve",
            "material ratio Rmr / %",
            &format!("height c (from the mean line) / {u}"),
            &[line("c(Rmr)", pts, BLUE, 2)],
        )
    })
}

/// A log–log chart of `lines` (values > 0), plotted as log10 on linear axes
/// labelled with the values (plotters' log axes drop labels below 2.2e-16).
fn log_chart(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    caption: &str,
    x_desc: &str,
    y_desc: &str,
    lines: Vec<Line>,
) -> Res<()> {
    let lines: Vec<Line> = lines
        .into_iter()
        .map(|l| Line {
            pts: l
                .pts
                .iter()
                .filter(|p| p.0 > 0.0 && p.1 > 0.0)
                .map(|&(x, y)| (x.log10(), y.log10()))
                .collect(),
            ..l
        })
        .collect();
    let (x0, x1) = range(&lines, true, 0.0);
    let (y0, y1) = range(&lines, false, 0.03);
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 20))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(75)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .max_light_lines(0)
        .x_label_formatter(&decade_label)
        .y_label_formatter(&decade_label)
        .draw()?;
    draw_lines(&mut chart, &lines)
}

/// Colour of `t` in [0, 1] on a dark-blue → green → yellow ramp.
fn ramp(t: f64) -> RGBColor {
    const STOPS: [(f64, f64, f64); 5] = [
        (68.0, 1.0, 84.0),
        (59.0, 82.0, 139.0),
        (33.0, 145.0, 140.0),
        (94.0, 201.0, 98.0),
        (253.0, 231.0, 37.0),
    ];
    let t = t.clamp(0.0, 1.0) * (STOPS.len() - 1) as f64;
    let i = (t.floor() as usize).min(STOPS.len() - 2);
    let f = t - i as f64;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    let mix = |x: f64, y: f64| (x + (y - x) * f).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// The plots of a map (besides the material ratio); returns the paths.
fn map_plots(prefix: &Path, m: &MapAnalysis, args: &ProfileArgs) -> Res<Vec<String>> {
    let name = args
        .file
        .file_name()
        .map_or(String::new(), |s| s.to_string_lossy().into_owned());
    let mut written = Vec::new();

    // Radial PSD (the zero wavevector left out).
    let r = &m.psd_radial;
    let pts: Vec<(f64, f64)> =
        r.r.iter()
            .copied()
            .zip(r.value.iter().copied())
            .skip(1)
            .collect();
    let path = suffixed(prefix, "-psd.svg");
    write_svg(&path, (900, 600), |root| {
        log_chart(
            root,
            &format!("{name}: radially averaged PSD (Hann window)"),
            "wavenumber |q| / (rad/m)",
            "PSD C(|q|) / m⁴",
            vec![line("C(|q|), mean over annuli", pts, BLUE, 2)],
        )
    })?;
    written.push(path.display().to_string());

    // 2-D PSD as a heat map of log10 C, block-averaged to at most 96 cells a side.
    let g = &m.psd;
    let (bx, by) = (g.nx.div_ceil(96), g.ny.div_ceil(96));
    let (cx, cy) = (g.nx / bx, g.ny / by);
    let mut cells = vec![0.0; cx * cy];
    for j in 0..cy * by {
        for i in 0..cx * bx {
            cells[(j / by) * cx + i / bx] += g.c[j * g.nx + i] / (bx * by) as f64;
        }
    }
    let logs: Vec<f64> = cells
        .iter()
        .map(|&c| if c > 0.0 { c.log10() } else { f64::NAN })
        .collect();
    let hi = logs
        .iter()
        .copied()
        .filter(|v| v.is_finite())
        .fold(f64::NEG_INFINITY, f64::max);
    let lo = hi - 8.0;
    let q_at = |i: usize, n: usize, b: usize, dq: f64| ((i * b) as f64 - (n / 2) as f64) * dq;
    let path = suffixed(prefix, "-psd2d.svg");
    write_svg(&path, (800, 760), |root| {
        let (xa, xb) = (q_at(0, g.nx, bx, g.dqx), q_at(cx, g.nx, bx, g.dqx));
        let (ya, yb) = (q_at(0, g.ny, by, g.dqy), q_at(cy, g.ny, by, g.dqy));
        let mut chart = ChartBuilder::on(root)
            .caption(
                format!("{name}: 2-D PSD log10 C(qx, qy) (8 decades below the peak)"),
                ("sans-serif", 18),
            )
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(75)
            .build_cartesian_2d(xa..xb, ya..yb)?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("qx / (rad/m)")
            .y_desc("qy / (rad/m)")
            .x_label_formatter(&|v| format!("{v:.1e}"))
            .y_label_formatter(&|v| format!("{v:.1e}"))
            .draw()?;
        chart.draw_series(
            (0..cy)
                .flat_map(|j| (0..cx).map(move |i| (i, j)))
                .map(|(i, j)| {
                    let v = logs[j * cx + i];
                    let t = if v.is_finite() {
                        (v - lo) / (hi - lo)
                    } else {
                        0.0
                    };
                    Rectangle::new(
                        [
                            (q_at(i, g.nx, bx, g.dqx), q_at(j, g.ny, by, g.dqy)),
                            (q_at(i + 1, g.nx, bx, g.dqx), q_at(j + 1, g.ny, by, g.dqy)),
                        ],
                        ramp(t).filled(),
                    )
                }),
        )?;
        Ok(())
    })?;
    written.push(path.display().to_string());

    // ACF: radial average and the cuts along x and y, normalised.
    let a = &m.acf;
    let r0 = a.r0();
    let norm = |v: f64| if r0 > 0.0 { v / r0 } else { 0.0 };
    let reach = m.acf_radial.r.last().copied().unwrap_or(0.0);
    let (ls, lu) = length_unit(reach.max(a.dx));
    let radial: Vec<(f64, f64)> = m
        .acf_radial
        .r
        .iter()
        .zip(&m.acf_radial.value)
        .map(|(&t, &v)| (t / ls, norm(v)))
        .collect();
    let (ci, cj) = (a.nx / 2, a.ny / 2);
    let along_x: Vec<(f64, f64)> = (ci..a.nx)
        .take_while(|&i| a.tau_x(i) <= reach)
        .map(|i| (a.tau_x(i) / ls, norm(a.r[cj * a.nx + i])))
        .collect();
    let along_y: Vec<(f64, f64)> = (cj..a.ny)
        .take_while(|&j| a.tau_y(j) <= reach)
        .map(|j| (a.tau_y(j) / ls, norm(a.r[j * a.nx + ci])))
        .collect();
    let s = m.isotropy.s;
    let path = suffixed(prefix, "-acf.svg");
    let caption = match m.isotropy.texture_aspect_ratio {
        Some(str_) => format!("{name}: autocorrelation, Str = {}", sig(str_, 3)),
        None => format!("{name}: autocorrelation (Str undefined)"),
    };
    write_svg(&path, (900, 600), |root| {
        linear_chart(
            root,
            &caption,
            &format!("lag / {lu}"),
            "ACF R / R(0)",
            &[
                line("radial average", radial, BLUE, 2),
                line("along x", along_x, RED, 1),
                line("along y", along_y, GREEN, 1),
                line(
                    format!("s = {s}"),
                    vec![(0.0, s), (reach / ls, s)],
                    RGBColor(150, 150, 150),
                    1,
                ),
            ],
        )
    })?;
    written.push(path.display().to_string());

    // Scale-dependent slope and curvature.
    let sc = &m.scale;
    let pair = |s: &asperity::surface::ScaleDependent, v: &[f64]| -> Vec<(f64, f64)> {
        s.scale.iter().copied().zip(v.iter().copied()).collect()
    };
    let path = suffixed(prefix, "-scale.svg");
    write_svg(&path, (900, 1000), |root| {
        let panels = root.split_evenly((2, 1));
        log_chart(
            &panels[0],
            &format!("{name}: rms slope at scale h"),
            "scale h / m",
            "rms slope",
            vec![
                line("along x", pair(&sc.along_x, &sc.along_x.slope_rms), BLUE, 2),
                line("along y", pair(&sc.along_y, &sc.along_y.slope_rms), RED, 2),
            ],
        )?;
        log_chart(
            &panels[1],
            "rms curvature at scale h",
            "scale h / m",
            "rms curvature / (1/m)",
            vec![
                line(
                    "along x",
                    pair(&sc.along_x, &sc.along_x.curvature_rms),
                    BLUE,
                    2,
                ),
                line(
                    "along y",
                    pair(&sc.along_y, &sc.along_y.curvature_rms),
                    RED,
                    2,
                ),
            ],
        )
    })?;
    written.push(path.display().to_string());
    Ok(written)
}
