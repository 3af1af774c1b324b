//! The data of the report's figures, ready to draw: lines with a band across seeds, box
//! plots, and points against the line y = x (the runs' series they are drawn from: `series`). The command line draws them (SVG); nothing here
//! knows about pixels.

use crate::statistics::{quantile, Summary};
use vsr::controllers::ControllerKind;

pub use super::series::{ablation_series, best_series, rate_series, unfrozen_series};

/// What a series is, which fixes its colour in every figure: a controller evolved from
/// scratch, an attention module frozen, a module fine-tuned, or something that is no brain
/// (alpha and eta, the reference physics).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Role {
    /// A controller (from scratch, or walking unfrozen).
    Controller(ControllerKind),
    /// A controller with its attention frozen (the ablation, a frozen pretrained module).
    Frozen(ControllerKind),
    /// A transplanted module fine-tuned.
    FineTuned,
    /// No brain.
    Other,
}

impl Role {
    /// The role a label names by its first word (words end at a space, comma or
    /// parenthesis): a controller's name (a `scratch-` prefix dropped); `frozen`, then the
    /// controller's name (attention when none follows); `fine-tuned` or `finetune`; anything
    /// else is `Other`. Every figure's series are labelled this way, so a series' colour
    /// follows from its label alone.
    pub fn of(label: &str) -> Role {
        let mut words = label.split([' ', ',', '(']).filter(|w| !w.is_empty());
        let kind = |w: Option<&str>| w?.parse::<ControllerKind>().ok();
        let first = words.next().unwrap_or("");
        match first.strip_prefix("scratch-").unwrap_or(first) {
            "frozen" => Role::Frozen(kind(words.next()).unwrap_or(ControllerKind::Attention)),
            "fine-tuned" | "finetune" => Role::FineTuned,
            other => kind(Some(other)).map_or(Role::Other, Role::Controller),
        }
    }
}

/// A line over x: the median across seeds and the interquartile band.
#[derive(Debug, Clone, PartialEq)]
pub struct Band {
    /// Legend entry.
    pub label: String,
    /// What it is ([`Role::of`] its label).
    pub role: Role,
    /// x of each point.
    pub x: Vec<f64>,
    /// Median across seeds at each x.
    pub median: Vec<f64>,
    /// Lower quartile across seeds.
    pub q1: Vec<f64>,
    /// Upper quartile across seeds.
    pub q3: Vec<f64>,
}

/// One box of a box plot: a label and its sample.
#[derive(Debug, Clone, PartialEq)]
pub struct BoxData {
    /// The box's label.
    pub label: String,
    /// What it is ([`Role::of`] its label).
    pub role: Role,
    /// The sample.
    pub values: Vec<f64>,
    /// Its summary.
    pub summary: Summary,
}

/// What a figure shows.
#[derive(Debug, Clone, PartialEq)]
pub enum Plot {
    /// Lines with bands (best fitness, ablation, alpha and eta against time or evaluations),
    /// and vertical marks at some x.
    Lines {
        /// The lines.
        bands: Vec<Band>,
        /// The marks.
        marks: Vec<Mark>,
    },
    /// Box plots (validation velocities).
    Boxes(Vec<BoxData>),
    /// Points of y against x, with the line y = x (ours against the reference).
    Versus(Vec<Points>),
    /// Differences with their intervals, one row each (top to bottom), over vertical marks
    /// (a non-inferiority margin, no difference).
    Intervals {
        /// The rows.
        rows: Vec<IntervalRow>,
        /// The marks.
        marks: Vec<Mark>,
    },
    /// Bodies drawn as voxel grids, one row of pictures per label (the best bodies of each
    /// condition of a body search).
    Bodies(Vec<BodyRow>),
}

/// A row of body pictures.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyRow {
    /// The row's label (e.g. a condition; its colour is its [`Role::of`]).
    pub label: String,
    /// A second, smaller line under the label (e.g. how many runs finished); may be empty.
    pub note: String,
    /// Its pictures, left to right.
    pub bodies: Vec<BodyPicture>,
}

/// One body to draw: its rows notation (top row first, `1` a voxel; empty: no body, only
/// the caption) and a caption under it.
#[derive(Debug, Clone, PartialEq)]
pub struct BodyPicture {
    /// The body in rows notation, e.g. `1111-1001`; empty when there is none yet.
    pub rows: String,
    /// The caption.
    pub caption: String,
}

/// One estimate with its interval.
#[derive(Debug, Clone, PartialEq)]
pub struct IntervalRow {
    /// What it compares (e.g. a shape).
    pub label: String,
    /// The estimate.
    pub estimate: f64,
    /// The interval's ends.
    pub low: f64,
    /// See `low`.
    pub high: f64,
}

/// A vertical line at `x` with a short label beside it (e.g. a shorter budget in a longer
/// run's curve).
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    /// Where.
    pub x: f64,
    /// What.
    pub label: String,
}

/// A series of points, optionally with a horizontal error bar on each.
#[derive(Debug, Clone, PartialEq)]
pub struct Points {
    /// Legend entry.
    pub label: String,
    /// (x, y) of each point.
    pub points: Vec<(f64, f64)>,
    /// Half-width of each point's horizontal bar (empty: no bars).
    pub x_error: Vec<f64>,
}

/// A figure to draw into `file` (an SVG name, no folder).
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// File name, e.g. `fig3-rq1-biped-4x3-30000.svg`.
    pub file: String,
    /// Title.
    pub title: String,
    /// Label of the x axis.
    pub x_label: String,
    /// Label of the y axis.
    pub y_label: String,
    /// The content.
    pub plot: Plot,
    /// Lines of text written under the title (e.g. the tests between the boxes).
    pub notes: Vec<String>,
}

/// The band of several series of (x, y) points: point i of every series is aggregated (the
/// series are cut to the shortest); x is taken from the first series. `None` when empty.
pub fn band(label: &str, series: &[Vec<(f64, f64)>]) -> Option<Band> {
    let len = series.iter().map(Vec::len).min().filter(|&n| n > 0)?;
    let mut b = Band {
        label: label.to_string(),
        role: Role::of(label),
        x: Vec::with_capacity(len),
        median: Vec::with_capacity(len),
        q1: Vec::with_capacity(len),
        q3: Vec::with_capacity(len),
    };
    for i in 0..len {
        let mut ys: Vec<f64> = series
            .iter()
            .map(|s| s[i].1)
            .filter(|y| y.is_finite())
            .collect();
        ys.sort_by(f64::total_cmp);
        b.x.push(series[0][i].0);
        b.median.push(quantile(&ys, 0.5));
        b.q1.push(quantile(&ys, 0.25));
        b.q3.push(quantile(&ys, 0.75));
    }
    Some(b)
}

/// A box of `values`.
pub fn box_of(label: &str, values: Vec<f64>) -> BoxData {
    BoxData {
        label: label.to_string(),
        role: Role::of(label),
        summary: Summary::of(&values),
        values,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bands_aggregate_point_by_point_over_the_shortest_series() {
        let series = vec![
            vec![(100.0, 1.0), (300.0, 2.0)],
            vec![(100.0, 3.0), (300.0, 4.0), (500.0, 9.0)],
            vec![(100.0, 2.0), (300.0, 6.0)],
        ];
        let b = band("x", &series).unwrap();
        assert_eq!(b.x, [100.0, 300.0]);
        assert_eq!(b.median, [2.0, 4.0]);
        assert_eq!((b.q1[0], b.q3[0]), (1.5, 2.5));
        assert!(band("none", &[]).is_none());
    }

    #[test]
    fn a_label_names_its_role_by_its_first_word() {
        let attention = Role::Controller(ControllerKind::Attention);
        assert_eq!(Role::of("attention"), attention);
        assert_eq!(Role::of("attention, not frozen"), attention);
        assert_eq!(Role::of("scratch-attention (n=10)"), attention);
        assert_eq!(Role::of("attention from scratch (30000)"), attention);
        let comm = Role::Controller(ControllerKind::MlpComm);
        assert_eq!(Role::of("mlp-comm"), comm);
        assert_eq!(
            Role::of("frozen attention"),
            Role::Frozen(ControllerKind::Attention)
        );
        assert_eq!(
            Role::of("frozen (n=3)"),
            Role::Frozen(ControllerKind::Attention)
        );
        let slow = Role::Frozen(ControllerKind::SlowAttention);
        assert_eq!(Role::of("frozen slow-attention"), slow);
        assert_eq!(
            Role::of("fine-tuned from comb-7x2 (20000 + 10000)"),
            Role::FineTuned
        );
        assert_eq!(Role::of("finetune"), Role::FineTuned);
        assert_eq!(Role::of("alpha"), Role::Other);
        assert_eq!(Role::of("from scratch (30000)"), Role::Other);
    }
}
