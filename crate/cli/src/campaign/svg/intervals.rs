//! The intervals figure (`Plot::Intervals`): one row per estimate with its interval, over
//! dashed vertical marks (a non-inferiority test's margin and no difference). Frame, grid and
//! marks are svg.rs's.

use super::chart_frame::{chart, marked, plot_error, range, Area, FINE_GRID, GRID};
use super::palette::looks;
use plotters::prelude::*;
use vsr::Result;
use vsr_study::report::figures::{Figure, IntervalRow, Mark, Role};

/// One row per estimate, top to bottom: a dot at the estimate and a bar over its interval,
/// over the dashed vertical marks (which the horizontal range always includes).
pub(super) fn draw(
    root: &Area,
    figure: &Figure,
    rows: &[IntervalRow],
    marks: &[Mark],
) -> Result<()> {
    let ends = rows.iter().flat_map(|r| [r.low, r.high, r.estimate]);
    let xs = range(ends.chain(marks.iter().map(|m| m.x)));
    // Room on the left for the rows' names and the first mark's label.
    let xs = xs.start - 0.25 * (xs.end - xs.start)..xs.end;
    let n = rows.len() as f64;
    // Row i sits at y = n - 1 - i (the first on top); room below for the marks' labels.
    let ys = -0.7..n - 0.4;
    let mut chart = chart(root, figure, xs.clone(), ys.clone())?;
    chart
        .configure_mesh()
        .x_desc(&figure.x_label)
        .y_desc(&figure.y_label)
        .y_labels(0)
        .disable_y_mesh()
        .bold_line_style(GRID)
        .light_line_style(FINE_GRID)
        .draw()
        .map_err(plot_error)?;
    for (i, m) in marks.iter().enumerate() {
        marked(&mut chart, m, &(ys.start..ys.end), i + 1 < marks.len())?;
    }
    let colour = looks(std::iter::once(Role::Other))[0].colour;
    for (i, r) in rows.iter().enumerate() {
        let y = n - 1.0 - i as f64;
        let (tick, style) = (0.12, colour.stroke_width(2));
        let bar = vec![
            PathElement::new(vec![(r.low, y), (r.high, y)], style),
            PathElement::new(vec![(r.low, y - tick), (r.low, y + tick)], style),
            PathElement::new(vec![(r.high, y - tick), (r.high, y + tick)], style),
        ];
        chart.draw_series(bar).map_err(plot_error)?;
        // The row's name above its bar, at the left edge.
        let font = ("sans-serif", 15).into_font().color(&BLACK);
        let name = EmptyElement::at((xs.start, y)) + Text::new(r.label.clone(), (8, -30), font);
        chart
            .draw_series(std::iter::once(name))
            .map_err(plot_error)?;
        let dot = Circle::new((r.estimate, y), 6, colour.filled());
        chart
            .draw_series(std::iter::once(dot))
            .map_err(plot_error)?;
    }
    Ok(())
}
