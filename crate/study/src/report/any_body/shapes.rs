//! The paper's four shapes one by one (a description, not tested): per condition, each
//! shape's mean speed on the unseen terrains as the runs' bests walked it in the body set
//! that holds it, the median over the runs and the slowest to the fastest run; a shape among
//! the condition's own training bodies is marked. The references
//! the plan names for these shapes (the study's specialists of RQ1 and the one-shot
//! transplants of RQ2) come from other campaigns' reports: docs/RESULTS.md puts them beside.

use super::pictures::trained_on;
use super::Condition;
use crate::statistics::Summary;
use std::fmt::Write;
use vsr::experiment::body_set::generate::PAPER_SHAPES;
use vsr::experiment::ValidationSet;
use vsr::simulation::Shape;

/// Each run's mean speed on `body` (unseen terrains), wherever its validations walked it.
fn on_body(c: &Condition, body: &Shape) -> Vec<f64> {
    c.runs
        .iter()
        .filter_map(|d| {
            d.validation
                .iter()
                .filter(|((_, set), _)| *set == ValidationSet::Unseen)
                .find_map(|(_, v)| v.per_body.iter().find(|b| b.body == *body))
                .map(|b| b.validation.mean)
        })
        .filter(|v| !v.is_nan())
        .collect()
}

/// The table, when some run walked one of the paper's shapes.
pub(super) fn paper_shapes(all: &[Condition], md: &mut String) {
    let shapes: Vec<(&str, Shape)> = PAPER_SHAPES
        .iter()
        .filter_map(|&name| Shape::parse(name).ok().map(|s| (name, s)))
        .collect();
    if !all
        .iter()
        .any(|c| shapes.iter().any(|(_, s)| !on_body(c, s).is_empty()))
    {
        return;
    }
    md.push_str(
        "### The paper's four shapes one by one (a description, not tested)\n\nEach shape's \
         mean speed on the ten unseen terrains, as each run's best walked it, never trained \
         on it except where marked: the median over the runs [the slowest run, the fastest] \
         (m/s).\n\n| condition |",
    );
    for (name, _) in &shapes {
        let _ = write!(md, " {name} |");
    }
    let _ = writeln!(md, "\n|{}", "---|".repeat(shapes.len() + 1));
    let mut own = false;
    for c in all {
        let trained = trained_on(c);
        let _ = write!(md, "| {} |", c.label);
        for (_, shape) in &shapes {
            let v = on_body(c, shape);
            if v.is_empty() {
                md.push_str(" - |");
                continue;
            }
            let s = Summary::of(&v);
            let mark = if trained.contains(&shape.to_rows()) {
                own = true;
                "†"
            } else {
                ""
            };
            let _ = write!(md, " {:.2} [{:.2}, {:.2}]{mark} |", s.median, s.min, s.max);
        }
        md.push('\n');
    }
    md.push('\n');
    if own {
        md.push_str("† One of the condition's own training bodies: not held out for it.\n\n");
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::campaign::{AnyBodyData, Campaign};
    use vsr::controllers::ControllerKind;
    use vsr::experiment::body_set::BodiesValidation;

    /// A run that walked the biped of `heldout-paper` at `mean` m/s on the unseen terrains.
    fn run(mean: f64) -> AnyBodyData {
        let body = serde_json::from_value(serde_json::json!({
            "body": "1111-1111-1001",
            "validation": {"set": "unseen", "terrains": [], "median": mean, "mean": mean},
        }))
        .unwrap();
        let mut d = AnyBodyData::default();
        let v = BodiesValidation {
            bodies: "heldout-paper.txt".into(),
            set: ValidationSet::Unseen,
            seconds: 30.0,
            median: mean,
            walking_share: 0.0,
            per_body: vec![body],
            exploded: 0,
        };
        d.validation
            .insert(("heldout-paper".to_string(), ValidationSet::Unseen), v);
        d
    }

    #[test]
    fn each_shape_over_the_runs_and_none_without_them() {
        let campaign = Campaign::parse(
            "output = \"out\"\nseeds = [1, 2, 3]\n[[any_body]]\nname = \"a\"\nbodies = \
             \"train.txt\"\ncontrollers = [\"attention-any\"]\nevals = 20\nheldout = \
             [\"heldout-paper.txt\"]\n",
        )
        .unwrap();
        let (a, b, c) = (run(1.0), run(3.0), run(2.5));
        let condition = Condition {
            label: "attention-any on train".into(),
            controller: ControllerKind::AttentionAny,
            group: &campaign.any_body[0],
            runs: vec![&a, &b, &c],
            planned: 3,
        };
        let mut md = String::new();
        paper_shapes(&[condition], &mut md);
        assert!(
            md.contains("| condition | biped-4x3 | comb-7x2 | biped-6x4 | comb-14x2 |"),
            "{md}"
        );
        assert!(
            md.contains("| attention-any on train | 2.50 [1.00, 3.00] | - | - | - |"),
            "{md}"
        );
        assert!(
            !md.contains('†'),
            "no run file read: no training body known"
        );
        let none = Condition {
            label: "attention-any on train".into(),
            controller: ControllerKind::AttentionAny,
            group: &campaign.any_body[0],
            runs: vec![],
            planned: 3,
        };
        let mut md = String::new();
        paper_shapes(&[none], &mut md);
        assert_eq!(md, "");
    }
}
