//! Line scans: ISO 21920-2 / ISO 4287 parameters, material ratio, spectra
//! and the power-law fit of a profile, printed, as JSON and as SVG plots.

use asperity::surface::{
    hurst_estimate, material_ratio_parameters, psd_windowed, spectral_moments, Convention,
    FilterEnds, Form, HurstFit, MaterialRatioParameters, ParameterOptions, Profile,
    RoughnessParameters, SpectralMoments, Window,
};
use plotters::prelude::*;
use serde_json::{json, Value};
use std::path::Path;

use super::plot::*;
use super::*;

/// Everything computed for a line scan.
pub(super) struct LineAnalysis {
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

pub(super) fn analyse_line(
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

/// `asperity profile` on a line scan: analyses it, prints the table or the
/// JSON, and writes the plots.
pub(super) fn line_scan(
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
            "profile_elements_reason": p.profile_elements_reason(),
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
    if let Some(reason) = p.profile_elements_reason() {
        outln!("Rc, RSm: {reason}");
    }
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

/// The four plots of a line scan; returns the paths written.
pub(super) fn line_plots(prefix: &Path, a: &LineAnalysis, args: &ProfileArgs) -> Res<Vec<String>> {
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
