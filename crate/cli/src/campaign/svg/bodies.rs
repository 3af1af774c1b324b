//! Draws a picture of bodies (`Plot::Bodies`) as plain SVG: a row per label (with its note on
//! a second, smaller line), each body a grid of square voxels standing on a ground line, its
//! caption under it, each row in the colour its label's role has in every other figure
//! (`palette`); a row with an empty label continues the row above it, in its colour. The
//! labels' column is as wide as its longest line, by an estimate of the
//! viewer's sans-serif font (no font file is read), so that no label runs into a body.

use super::palette::look;
use vsr_study::report::figures::{BodyRow, Figure, Role};

/// Width of one body's column and height of one row (px).
const COLUMN: f64 = 112.0;
const ROW: f64 = 110.0;
/// Narrowest labels' column, height of the title (px).
const LABELS: f64 = 120.0;
const TITLE: f64 = 44.0;
/// Font sizes of a label and of its note (px).
const LABEL_FONT: f64 = 15.0;
const NOTE_FONT: f64 = 12.0;
/// A generous estimate of a sans-serif character's width, in font sizes (DejaVu Sans, the
/// widest common default, averages about 0.6 on these labels).
const CHAR_WIDTH: f64 = 0.62;

/// Width of the labels' column: the widest label or note, with margins.
fn labels_width(rows: &[BodyRow]) -> f64 {
    let text = |s: &str, size: f64| s.chars().count() as f64 * size * CHAR_WIDTH;
    let widest = rows
        .iter()
        .map(|r| text(&r.label, LABEL_FONT).max(text(&r.note, NOTE_FONT)))
        .fold(0.0, f64::max);
    LABELS.max((widest + 30.0).ceil())
}
/// Largest voxel side (px).
const VOXEL: f64 = 14.0;

/// The SVG text of a figure of body rows.
pub fn draw(figure: &Figure, rows: &[BodyRow]) -> String {
    let columns = rows
        .iter()
        .map(|r| r.bodies.len())
        .max()
        .unwrap_or(0)
        .max(1);
    let labels = labels_width(rows);
    let width = labels + COLUMN * columns as f64 + 10.0;
    let notes = 18.0 * figure.notes.len() as f64;
    let height = TITLE + ROW * rows.len() as f64 + notes + 10.0;
    let mut svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{height}\" \
         viewBox=\"0 0 {width} {height}\" font-family=\"sans-serif\">\n\
         <rect width=\"{width}\" height=\"{height}\" fill=\"#ffffff\"/>\n\
         <text x=\"{}\" y=\"28\" font-size=\"20\" text-anchor=\"middle\">{}</text>\n",
        width / 2.0,
        escape(&figure.title)
    );
    let mut colour_of = 0;
    for (i, row) in rows.iter().enumerate() {
        let top = TITLE + ROW * i as f64;
        if !row.label.is_empty() {
            colour_of = i;
        }
        let c = look(Role::of(&rows[colour_of].label), colour_of).colour;
        let colour = format!("#{:02x}{:02x}{:02x}", c.0, c.1, c.2);
        svg += &format!(
            "<text x=\"10\" y=\"{}\" font-size=\"{LABEL_FONT}\" fill=\"{colour}\">{}</text>\n",
            top + ROW / 2.0 - 6.0,
            escape(&row.label)
        );
        if !row.note.is_empty() {
            svg += &format!(
                "<text x=\"10\" y=\"{}\" font-size=\"{NOTE_FONT}\" fill=\"#555555\">{}</text>\n",
                top + ROW / 2.0 + 12.0,
                escape(&row.note)
            );
        }
        for (j, body) in row.bodies.iter().enumerate() {
            let left = labels + COLUMN * j as f64;
            svg += &picture(&body.rows, left, top, &colour);
            svg += &format!(
                "<text x=\"{}\" y=\"{}\" font-size=\"12\" text-anchor=\"middle\" fill=\"{}\">{}</text>\n",
                left + COLUMN / 2.0,
                top + ROW - 12.0,
                if body.rows.is_empty() { "#888888" } else { "#000000" },
                escape(&body.caption)
            );
        }
    }
    for (k, line) in figure.notes.iter().enumerate() {
        svg += &format!(
            "<text x=\"10\" y=\"{}\" font-size=\"13\">{}</text>\n",
            TITLE + ROW * rows.len() as f64 + 14.0 + 18.0 * k as f64,
            escape(line)
        );
    }
    svg + "</svg>\n"
}

/// One body's voxels in the cell whose top left is (`left`, `top`), standing on a ground
/// line; nothing for an empty `rows`.
fn picture(rows: &str, left: f64, top: f64, colour: &str) -> String {
    let grid: Vec<&[u8]> = rows
        .split('-')
        .filter(|r| !r.is_empty())
        .map(str::as_bytes)
        .collect();
    let (w, h) = (grid.iter().map(|r| r.len()).max().unwrap_or(0), grid.len());
    if w == 0 {
        return String::new();
    }
    let side = VOXEL
        .min((COLUMN - 16.0) / w as f64)
        .min((ROW - 34.0) / h as f64);
    let ground = top + ROW - 28.0;
    let x0 = left + (COLUMN - side * w as f64) / 2.0;
    let mut svg = format!(
        "<line x1=\"{}\" y1=\"{ground}\" x2=\"{}\" y2=\"{ground}\" stroke=\"#999999\"/>\n",
        left + 6.0,
        left + COLUMN - 6.0
    );
    for (y, row) in grid.iter().enumerate() {
        for (x, &c) in row.iter().enumerate() {
            if c != b'1' {
                continue;
            }
            svg += &format!(
                "<rect x=\"{:.1}\" y=\"{:.1}\" width=\"{side:.1}\" height=\"{side:.1}\" \
                 fill=\"{colour}\" stroke=\"#ffffff\" stroke-width=\"1\"/>\n",
                x0 + side * x as f64,
                ground - side * (h - y) as f64
            );
        }
    }
    svg
}

/// `text` safe inside an SVG element.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;
    use vsr_study::report::figures::{BodyPicture, Plot};

    #[test]
    fn a_voxel_per_one_and_a_caption_per_body() {
        let rows = vec![BodyRow {
            label: "frozen".into(),
            note: "1 of 2 runs finished, and a note longer than the label".into(),
            bodies: vec![
                BodyPicture {
                    rows: "11-01".into(),
                    caption: "s1: 2.50".into(),
                },
                BodyPicture {
                    rows: String::new(),
                    caption: "s2: not finished".into(),
                },
            ],
        }];
        let figure = Figure {
            file: "x.svg".into(),
            title: "bodies <&>".into(),
            x_label: String::new(),
            y_label: String::new(),
            plot: Plot::Bodies(rows.clone()),
            notes: vec![],
        };
        let svg = draw(&figure, &rows);
        assert_eq!(svg.matches("<rect x=").count(), 3, "{svg}");
        assert!(svg.contains("s2: not finished") && svg.contains("bodies &lt;&amp;&gt;"));
        assert!(svg.contains(">1 of 2 runs finished, and a note longer than the label</text>"));
        // The labels' column holds the longest line (55 characters at 12 px): the first body
        // starts to its right.
        let first = svg.find("<line x1=\"").expect("a ground line");
        let x1: f64 = svg[first + 10..]
            .split('"')
            .next()
            .unwrap()
            .parse()
            .unwrap();
        assert!(x1 - 6.0 >= 55.0 * NOTE_FONT * CHAR_WIDTH + 10.0, "{x1}");
    }
}
