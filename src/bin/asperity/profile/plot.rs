//! The plotting helpers the line-scan and map plots share: decimation,
//! axis ranges, linear and logarithmic charts, SVG output.

use asperity::surface::MaterialRatioCurve;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::{Path, PathBuf};

use super::*;
use crate::axis::ticks;

/// Pixel columns of a plot: decimation keeps at most two points per column.
pub(super) const COLUMNS: usize = 1000;

pub(super) fn plot_prefix(prefix: &Path, file: &Path) -> PathBuf {
    if prefix.is_dir() {
        prefix.join(file.file_stem().unwrap_or(file.as_os_str()))
    } else {
        prefix.to_path_buf()
    }
}

pub(super) fn suffixed(prefix: &Path, suffix: &str) -> PathBuf {
    let mut s = prefix.as_os_str().to_owned();
    s.push(suffix);
    PathBuf::from(s)
}

/// Min/max decimation for plotting: of `pts` (x increasing), keeps in each of
/// `COLUMNS` equal bins of x (of ln x with `log_x`) only the lowest and the
/// highest point, in their original order, so that the polyline through them
/// draws the same envelope as the polyline through all points.
pub(super) fn decimate(pts: &[(f64, f64)], log_x: bool) -> Vec<(f64, f64)> {
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
pub(super) struct Line {
    name: String,
    pts: Vec<(f64, f64)>,
    color: RGBColor,
    width: u32,
}

pub(super) fn line(
    name: impl Into<String>,
    pts: Vec<(f64, f64)>,
    color: RGBColor,
    width: u32,
) -> Line {
    Line {
        name: name.into(),
        pts,
        color,
        width,
    }
}

/// Data range of `lines` along x (`x = true`) or y, padded by 5 % on y, never
/// empty.
pub(super) fn range(lines: &[Line], x: bool, pad: f64) -> (f64, f64) {
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
pub(super) fn linear_chart(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    caption: &str,
    x_desc: &str,
    y_desc: &str,
    lines: &[Line],
) -> Res<()> {
    let x = range(lines, true, 0.0);
    let y = range(lines, false, 0.05);
    let (fx, fy) = (ticks(x.0, x.1), ticks(y.0, y.1));
    cartesian(
        area,
        caption,
        (x_desc, y_desc),
        lines,
        (x, y),
        (&*fx, &*fy),
        None,
    )
}

/// Formats an axis value.
type Label = dyn Fn(&f64) -> String;

/// Draws `lines` in `area` over the ranges `x` and `y`, the axes labelled by
/// `labels`; `light_lines` caps plotters' minor grid lines.
fn cartesian(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    caption: &str,
    (x_desc, y_desc): (&str, &str),
    lines: &[Line],
    (x, y): ((f64, f64), (f64, f64)),
    labels: (&Label, &Label),
    light_lines: Option<usize>,
) -> Res<()> {
    let mut chart = ChartBuilder::on(area)
        .caption(caption, ("sans-serif", 20))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(75)
        .build_cartesian_2d(x.0..x.1, y.0..y.1)?;
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(x_desc)
        .y_desc(y_desc)
        .x_label_formatter(labels.0)
        .y_label_formatter(labels.1);
    if let Some(n) = light_lines {
        mesh.max_light_lines(n);
    }
    mesh.draw()?;
    draw_lines(&mut chart, lines)
}

pub(super) fn draw_lines<'a, 'b: 'a, X, Y>(
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
pub(super) fn write_svg(
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

/// Label of a log10 value: `1e-20` at whole decades, else the value.
pub(super) fn decade_label(v: &f64) -> String {
    if (v - v.round()).abs() < 1e-9 {
        format!("1e{}", v.round())
    } else {
        format!("{:.2e}", 10f64.powf(*v))
    }
}

/// A log–log chart of `lines` (values > 0), plotted as log10 on linear axes
/// labelled with the values (plotters' log axes drop labels below 2.2e-16).
pub(super) fn log_chart(
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
    let x = range(&lines, true, 0.0);
    let y = range(&lines, false, 0.03);
    cartesian(
        area,
        caption,
        (x_desc, y_desc),
        &lines,
        (x, y),
        (&decade_label, &decade_label),
        Some(0),
    )
}

/// The Abbott–Firestone curve of `heights` (m): level c from the mean line
/// against the material ratio Rmr.
pub(super) fn material_ratio_plot(path: &Path, heights: &[f64]) -> Res<()> {
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
