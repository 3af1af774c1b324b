//! What every figure of the report shares, whatever it draws: the frame (title, margins, axis
//! areas), the grid's colours, the legend's box, the dashed marks at chosen x, the padded
//! range of the data, and the error of a failed drawing. The figures themselves: `svg`
//! (lines and points against points), `boxes`, `intervals`.

use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use vsr::{Error, Result};
use vsr_study::report::figures::{Figure, Mark};

/// The grid: major lines light, minor ones fainter, so that the data stand out.
pub(super) const GRID: RGBColor = RGBColor(225, 225, 225);
pub(super) const FINE_GRID: RGBColor = RGBColor(244, 244, 244);

pub(super) fn plot_error<E: std::fmt::Display>(e: E) -> Error {
    Error::Io(format!("cannot draw the figure: {e}"))
}

/// The range of `values` (finite ones), padded by 5% (or 1 when flat).
pub(super) fn range(values: impl Iterator<Item = f64>) -> std::ops::Range<f64> {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if lo > hi {
        return 0.0..1.0;
    }
    let pad = if hi > lo { 0.05 * (hi - lo) } else { 1.0 };
    (lo - pad)..(hi + pad)
}

pub(super) type Area<'a> = DrawingArea<SVGBackend<'a>, plotters::coord::Shift>;

pub(super) type Chart<'a, 'b> =
    ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// The figure's frame: its title, margins and axis areas around the ranges `xs` x `ys`.
pub(super) fn chart<'a, 'b>(
    root: &'a Area<'b>,
    figure: &Figure,
    xs: std::ops::Range<f64>,
    ys: std::ops::Range<f64>,
) -> Result<Chart<'a, 'b>> {
    ChartBuilder::on(root)
        .caption(&figure.title, ("sans-serif", 20))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d(xs, ys)
        .map_err(plot_error)
}

/// The chart's legend at `position`, on a light box that lets the grid show through.
pub(super) fn legend<'b: 'a, 'a>(
    chart: &mut Chart<'a, 'b>,
    position: SeriesLabelPosition,
) -> Result<()> {
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .position(position)
        .draw()
        .map_err(plot_error)
}

/// A vertical dashed grey line at the mark over the data's range `ys`, its label beside its
/// foot: to its right, or to its left (`left`, for a mark with another close on its right).
pub(super) fn marked(
    chart: &mut Chart,
    m: &Mark,
    ys: &std::ops::Range<f64>,
    left: bool,
) -> Result<()> {
    let grey = RGBColor(110, 110, 110);
    let line = [(m.x, ys.start), (m.x, ys.end)];
    chart
        .draw_series(DashedLineSeries::new(line, 6, 4, grey.stroke_width(1)))
        .map_err(plot_error)?;
    let font = ("sans-serif", 13).into_font().color(&grey);
    let (font, dx) = if left {
        (font.pos(Pos::new(HPos::Right, VPos::Top)), -6)
    } else {
        (font, 6)
    };
    let label = EmptyElement::at((m.x, ys.start)) + Text::new(m.label.clone(), (dx, -18), font);
    chart
        .draw_series(std::iter::once(label))
        .map_err(plot_error)?;
    Ok(())
}
