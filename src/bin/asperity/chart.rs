//! The plots' shared tail: named line series in palette colours and the
//! legend box.

use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use std::error::Error;

/// A chart of the command: f64 axes on an SVG backend.
pub type Chart<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Draw each named series as a 2-px line, colour `Palette99::pick(first_colour + i)`,
/// with its legend entry, then the legend box.
pub fn lines_with_legend<'a, 'b: 'a>(
    chart: &mut Chart<'a, 'b>,
    series: impl IntoIterator<Item = (String, Vec<(f64, f64)>)>,
    first_colour: usize,
) -> Result<(), Box<dyn Error>> {
    for (i, (name, pts)) in series.into_iter().enumerate() {
        let color = Palette99::pick(first_colour + i).to_rgba();
        chart
            .draw_series(LineSeries::new(pts, color.stroke_width(2)))?
            .label(name)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
    }
    chart
        .configure_series_labels()
        .border_style(BLACK)
        .background_style(WHITE.mix(0.8))
        .draw()?;
    Ok(())
}
