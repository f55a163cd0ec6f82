//! Maps: ISO 25178-2 height and functional parameters, 2-D PSD and ACF,
//! isotropy and the scale-dependent slope and curvature, printed, as JSON
//! and as SVG plots.

use asperity::surface::{
    acf_2d, areal_gaussian_filter, isotropy, psd_2d, scale_dependent_map, Acf2d, Isotropy, Psd2d,
    Radial, ScaleDependentMap,
};
use asperity::surface::{
    functional_parameters, FilterEnds, FunctionalParameters, MapForm, Topography, Window,
};
use plotters::prelude::*;
use serde_json::{json, Value};
use std::path::Path;

use super::plot::*;
use super::*;

/// `asperity profile` on a height map: analyses it, prints the table or the
/// JSON, and writes the plots.
pub(super) fn map(
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
pub(super) struct MapAnalysis {
    /// Hann-windowed 2-D PSD (centred) and its radial average.
    psd: Psd2d,
    psd_radial: Radial,
    acf: Acf2d,
    acf_radial: Radial,
    isotropy: Isotropy,
    scale: ScaleDependentMap,
}

pub(super) fn analyse_map(t: &Topography) -> Res<MapAnalysis> {
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

pub(super) fn print_map_analysis(m: &MapAnalysis) {
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

/// Colour of `t` in [0, 1] on a dark-blue → green → yellow ramp.
pub(super) fn ramp(t: f64) -> RGBColor {
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
pub(super) fn map_plots(prefix: &Path, m: &MapAnalysis, args: &ProfileArgs) -> Res<Vec<String>> {
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
