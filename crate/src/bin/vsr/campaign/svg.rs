//! Draws the report's figures as SVG with plotters' SVG backend. Text is written as SVG
//! `<text>` (plotters without its `ttf` / `ab_glyph` features lays text out by estimate and
//! needs no font file), so the viewer's sans-serif font renders it.

use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;
use vsr::study::report::figures::{Band, BoxData, Figure, Plot, Points};
use vsr::{Error, Result};

const SIZE: (u32, u32) = (800, 500);

/// The Okabe-Ito palette (Okabe and Ito 2008), safe for the common colour-vision
/// deficiencies; black first, yellow last (faint on white).
const OKABE_ITO: [RGBColor; 8] = [
    RGBColor(0, 114, 178),   // blue
    RGBColor(213, 94, 0),    // vermillion
    RGBColor(0, 158, 115),   // bluish green
    RGBColor(204, 121, 167), // reddish purple
    RGBColor(86, 180, 233),  // sky blue
    RGBColor(230, 159, 0),   // orange
    RGBColor(0, 0, 0),       // black
    RGBColor(240, 228, 66),  // yellow
];

/// The colour of series `i`.
fn pick(i: usize) -> RGBAColor {
    OKABE_ITO[i % OKABE_ITO.len()].to_rgba()
}

/// Height of one line of notes under the title (px).
const NOTE_LINE: u32 = 16;

/// The SVG text of `figure`.
pub fn draw(figure: &Figure) -> Result<String> {
    let mut svg = String::new();
    {
        let height = SIZE.1 + NOTE_LINE * figure.notes.len() as u32;
        let root = SVGBackend::with_string(&mut svg, (SIZE.0, height)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_error)?;
        // The notes go under the chart.
        let (root, notes) = root.split_vertically(SIZE.1);
        for (i, line) in figure.notes.iter().enumerate() {
            let at = (70, (i as u32 * NOTE_LINE) as i32);
            notes
                .draw_text(line, &("sans-serif", 13).into_font().color(&BLACK), at)
                .map_err(plot_error)?;
        }
        match &figure.plot {
            Plot::Lines(bands) => lines(&root, figure, bands)?,
            Plot::Boxes(boxes) => boxes_plot(&root, figure, boxes)?,
            Plot::Versus(series) => versus(&root, figure, series)?,
        }
        root.present().map_err(plot_error)?;
    }
    Ok(svg)
}

fn plot_error<E: std::fmt::Display>(e: E) -> Error {
    Error::Io(format!("cannot draw the figure: {e}"))
}

/// The range of `values` (finite ones), padded by 5% (or 1 when flat).
fn range(values: impl Iterator<Item = f64>) -> std::ops::Range<f64> {
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

type Area<'a> = DrawingArea<SVGBackend<'a>, plotters::coord::Shift>;

type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// The figure's frame: its title, margins and axis areas around the ranges `xs` x `ys`.
fn chart<'a, 'b>(
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
fn legend<'b: 'a, 'a>(chart: &mut Chart<'a, 'b>, position: SeriesLabelPosition) -> Result<()> {
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .position(position)
        .draw()
        .map_err(plot_error)
}

fn lines(root: &Area, figure: &Figure, bands: &[Band]) -> Result<()> {
    let xs = range(bands.iter().flat_map(|b| b.x.iter().copied()));
    let ys = range(
        bands
            .iter()
            .flat_map(|b| b.q1.iter().chain(&b.q3).chain(&b.median).copied()),
    );
    // Headroom above the data for the legend, so that it hides no curve.
    let rows = bands.len() as f64;
    let ys = ys.start..ys.end + (ys.end - ys.start) * (0.08 + 0.06 * rows);
    let mut chart = chart(root, figure, xs, ys)?;
    chart
        .configure_mesh()
        .x_desc(&figure.x_label)
        .y_desc(&figure.y_label)
        // `5000`, not plotters' default `5000.0`.
        .x_label_formatter(&|x| format!("{x}"))
        .draw()
        .map_err(plot_error)?;
    for (i, b) in bands.iter().enumerate() {
        let color = pick(i);
        let mut area: Vec<(f64, f64)> = b.x.iter().copied().zip(b.q3.iter().copied()).collect();
        area.extend(b.x.iter().copied().zip(b.q1.iter().copied()).rev());
        chart
            .draw_series(std::iter::once(Polygon::new(area, color.mix(0.2).filled())))
            .map_err(plot_error)?;
        let line = b.x.iter().copied().zip(b.median.iter().copied());
        chart
            .draw_series(LineSeries::new(line, color.stroke_width(2)))
            .map_err(plot_error)?
            .label(format!("{} (median, IQR)", b.label))
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
    }
    legend(&mut chart, SeriesLabelPosition::UpperRight)
}

/// Box plots: box from q1 to q3, median line, whiskers to the smallest and largest value
/// (no outlier rule: with 5 runs every value is drawn as a dot anyway).
fn boxes_plot(root: &Area, figure: &Figure, boxes: &[BoxData]) -> Result<()> {
    let ys = range(boxes.iter().flat_map(|b| b.values.iter().copied()));
    let labels: Vec<&str> = boxes.iter().map(|b| b.label.as_str()).collect();
    let xs = -0.5..boxes.len() as f64 - 0.5;
    let mut chart = chart(root, figure, xs, ys)?;
    let name = |x: &f64| {
        let i = x.round();
        let at_box = (x - i).abs() < 1e-6 && i >= 0.0;
        let label = labels.get(i as usize).filter(|_| at_box);
        label.map_or(String::new(), |l| l.to_string())
    };
    chart
        .configure_mesh()
        .x_desc(&figure.x_label)
        .y_desc(&figure.y_label)
        .x_labels(boxes.len().max(2) * 2 - 1)
        .x_label_formatter(&name)
        .disable_x_mesh()
        .draw()
        .map_err(plot_error)?;
    for (i, b) in boxes.iter().enumerate() {
        let color = pick(i);
        let (x, w, s) = (i as f64, 0.2, &b.summary);
        let style = color.stroke_width(2);
        let shapes: Vec<PathElement<(f64, f64)>> = vec![
            PathElement::new(
                vec![
                    (x - w, s.q1),
                    (x + w, s.q1),
                    (x + w, s.q3),
                    (x - w, s.q3),
                    (x - w, s.q1),
                ],
                style,
            ),
            PathElement::new(
                vec![(x - w, s.median), (x + w, s.median)],
                color.stroke_width(3),
            ),
            PathElement::new(vec![(x, s.q3), (x, s.max)], style),
            PathElement::new(vec![(x, s.q1), (x, s.min)], style),
            PathElement::new(vec![(x - w / 2.0, s.max), (x + w / 2.0, s.max)], style),
            PathElement::new(vec![(x - w / 2.0, s.min), (x + w / 2.0, s.min)], style),
        ];
        chart.draw_series(shapes).map_err(plot_error)?;
        let dots = b
            .values
            .iter()
            .map(|&v| Circle::new((x, v), 3, color.filled()));
        chart.draw_series(dots).map_err(plot_error)?;
    }
    Ok(())
}

/// Points of y against x with their horizontal bars, over the grey line y = x; x and y share
/// one range so that the line is the diagonal.
fn versus(root: &Area, figure: &Figure, series: &[Points]) -> Result<()> {
    let ends = series.iter().flat_map(|s| {
        let bars = s
            .points
            .iter()
            .zip(s.x_error.iter().chain(std::iter::repeat(&0.0)));
        bars.flat_map(|(&(x, y), e)| [x - e, x + e, y])
    });
    let both = range(ends);
    let rows = series.len() as f64;
    let ys = both.start..both.end + (both.end - both.start) * (0.08 + 0.06 * rows);
    let mut chart = chart(root, figure, both.clone(), ys)?;
    chart
        .configure_mesh()
        .x_desc(&figure.x_label)
        .y_desc(&figure.y_label)
        .light_line_style(TRANSPARENT)
        .draw()
        .map_err(plot_error)?;
    let diagonal = vec![(both.start, both.start), (both.end, both.end)];
    chart
        .draw_series(std::iter::once(PathElement::new(
            diagonal,
            RGBColor(150, 150, 150).stroke_width(1),
        )))
        .map_err(plot_error)?;
    for (i, s) in series.iter().enumerate() {
        let color = pick(i);
        let bars = s.points.iter().zip(&s.x_error).map(|(&(x, y), &e)| {
            PathElement::new(vec![(x - e, y), (x + e, y)], color.mix(0.6).stroke_width(1))
        });
        chart.draw_series(bars).map_err(plot_error)?;
        // The first series filled, the others as rings, so that a point on top hides none.
        let style = if i == 0 {
            color.filled()
        } else {
            color.stroke_width(2)
        };
        let dots = s.points.iter().map(move |&p| Circle::new(p, 5, style));
        chart
            .draw_series(dots)
            .map_err(plot_error)?
            .label(s.label.clone())
            .legend(move |(x, y)| Circle::new((x + 10, y), 5, style));
    }
    legend(&mut chart, SeriesLabelPosition::UpperLeft)
}
