//! Draws the report's figures as SVG with plotters' SVG backend. Text is written as SVG
//! `<text>` (plotters without its `ttf` / `ab_glyph` features lays text out by estimate and
//! needs no font file), so the viewer's sans-serif font renders it. Colours: `palette`.
//! Boxes, bodies and intervals are drawn in their own files (`boxes`, `bodies`,
//! `intervals`), the frame every chart shares in `chart_frame`.

mod bodies;
mod boxes;
mod chart_frame;
mod intervals;
mod palette;

use chart_frame::{chart, legend, marked, plot_error, range, Area, FINE_GRID, GRID};
use palette::{looks, Look};
use plotters::prelude::*;
use vsr::Result;
use vsr_study::report::figures::{Band, Figure, Mark, Plot, Points};

const SIZE: (u32, u32) = (800, 500);

/// Height of one line of notes under the title (px).
const NOTE_LINE: u32 = 16;

/// What the marks of a kind of plot are, written under it.
fn key(plot: &Plot) -> Option<&'static str> {
    match plot {
        Plot::Lines { .. } => Some("line: median across runs; shaded: quartiles (25% to 75%)"),
        Plot::Boxes(_) => Some(
            "box: quartiles (25% to 75%); bar: median; whiskers: smallest to largest run \
             (no outlier rule); dots: one run each",
        ),
        _ => None,
    }
}

/// The figure's width: 800 px, or more for box plots whose labels would not fit under their
/// boxes (by an estimate of 6.5 px per character of the axis font, 20 px apart).
fn width(plot: &Plot) -> u32 {
    let Plot::Boxes(boxes) = plot else {
        return SIZE.0;
    };
    let longest = boxes.iter().map(|b| b.label.chars().count()).max();
    let per_box = longest.unwrap_or(0) as f64 * 6.5 + 20.0;
    SIZE.0
        .max((90.0 + per_box * boxes.len() as f64).ceil() as u32)
}

/// The SVG text of `figure`.
pub fn draw(figure: &Figure) -> Result<String> {
    if let Plot::Bodies(rows) = &figure.plot {
        return Ok(bodies::draw(figure, rows));
    }
    let mut svg = String::new();
    {
        let key = key(&figure.plot).map(str::to_string);
        let notes: Vec<&String> = key.iter().chain(&figure.notes).collect();
        let height = SIZE.1 + NOTE_LINE * notes.len() as u32;
        let root =
            SVGBackend::with_string(&mut svg, (width(&figure.plot), height)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_error)?;
        // The notes go under the chart.
        let (root, under) = root.split_vertically(SIZE.1);
        for (i, line) in notes.into_iter().enumerate() {
            let at = (70, (i as u32 * NOTE_LINE) as i32);
            under
                .draw_text(line, &("sans-serif", 13).into_font().color(&BLACK), at)
                .map_err(plot_error)?;
        }
        match &figure.plot {
            Plot::Lines { bands, marks } => lines(&root, figure, bands, marks)?,
            Plot::Boxes(boxes) => boxes::draw(&root, figure, boxes)?,
            Plot::Versus(series) => versus(&root, figure, series)?,
            Plot::Intervals { rows, marks } => intervals::draw(&root, figure, rows, marks)?,
            Plot::Bodies(_) => unreachable!("drawn above"),
        }
        root.present().map_err(plot_error)?;
    }
    Ok(svg)
}

fn lines(root: &Area, figure: &Figure, bands: &[Band], marks: &[Mark]) -> Result<()> {
    let xs = range(bands.iter().flat_map(|b| b.x.iter().copied()));
    let ys = range(
        bands
            .iter()
            .flat_map(|b| b.q1.iter().chain(&b.q3).chain(&b.median).copied()),
    );
    // Headroom above the data for the legend, so that it hides no curve.
    let rows = bands.len() as f64;
    let data = ys.clone();
    let ys = ys.start..ys.end + (ys.end - ys.start) * (0.08 + 0.06 * rows);
    let mut chart = chart(root, figure, xs, ys)?;
    chart
        .configure_mesh()
        .bold_line_style(GRID)
        .light_line_style(FINE_GRID)
        .x_desc(&figure.x_label)
        .y_desc(&figure.y_label)
        // `5000`, not plotters' default `5000.0`.
        .x_label_formatter(&|x| format!("{x}"))
        .draw()
        .map_err(plot_error)?;
    for m in marks {
        marked(&mut chart, m, &data, false)?;
    }
    let looks = looks(bands.iter().map(|b| b.role));
    for (b, &Look { colour, dashed }) in bands.iter().zip(&looks) {
        let mut area: Vec<(f64, f64)> = b.x.iter().copied().zip(b.q3.iter().copied()).collect();
        area.extend(b.x.iter().copied().zip(b.q1.iter().copied()).rev());
        chart
            .draw_series(std::iter::once(Polygon::new(
                area,
                colour.mix(0.2).filled(),
            )))
            .map_err(plot_error)?;
        let line: Vec<(f64, f64)> = b.x.iter().copied().zip(b.median.iter().copied()).collect();
        let style = colour.stroke_width(2);
        let drawn = if dashed {
            chart.draw_series(DashedLineSeries::new(line, 8, 5, style))
        } else {
            chart.draw_series(LineSeries::new(line, style))
        };
        drawn
            .map_err(plot_error)?
            .label(&b.label)
            .legend(move |(x, y)| {
                let dash = if dashed { 8 } else { 20 };
                let first = PathElement::new(vec![(x, y), (x + dash, y)], style);
                let second = PathElement::new(vec![(x + 20 - dash, y), (x + 20, y)], style);
                EmptyElement::at((0, 0)) + first + second
            });
    }
    legend(&mut chart, SeriesLabelPosition::UpperRight)
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
        .bold_line_style(GRID)
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
    let looks = looks(
        series
            .iter()
            .map(|_| vsr_study::report::figures::Role::Other),
    );
    for (i, (s, look)) in series.iter().zip(&looks).enumerate() {
        let color = look.colour;
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
