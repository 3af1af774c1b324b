//! Box plots (`Plot::Boxes`): one box per label, its runs as dots. Frame and grid are
//! svg.rs's; colours `palette`'s.

use super::chart_frame::{chart, plot_error, range, Area, FINE_GRID, GRID};
use super::palette::looks;
use plotters::prelude::*;
use vsr::Result;
use vsr_study::report::figures::{BoxData, Figure};

/// Box plots: box from q1 to q3, median line, whiskers to the smallest and largest value
/// (no outlier rule: with 5 runs every value is drawn as a dot anyway).
pub(super) fn draw(root: &Area, figure: &Figure, boxes: &[BoxData]) -> Result<()> {
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
        .bold_line_style(GRID)
        .light_line_style(FINE_GRID)
        .draw()
        .map_err(plot_error)?;
    let looks = looks(boxes.iter().map(|b| b.role));
    for (i, (b, look)) in boxes.iter().zip(&looks).enumerate() {
        let color = look.colour;
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
