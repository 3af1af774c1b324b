//! The fourth question's figures, drawn only once every planned run of every condition has
//! its primary validation (before, an earlier report's are withdrawn, so that no interim
//! result is read):
//! - `any-body-BODYSET-SET.svg`, one per held-out set: each condition's runs (one dot per
//!   seed: the run's median over the set's bodies), beside the random attention-any brains of
//!   the floor;
//! - `any-body-bodies-GROUP-CONTROLLER.svg`, one per condition: every held-out body drawn
//!   with the speed of the condition's chosen module on it (the run chosen by its
//!   training-set median, as `vsr campaign export` chooses), sorted fastest first.
//!
//! Exploded episodes (each counted as 0 m/s) are said in a figure's notes, and under a body
//! that had some.

use super::floor::{floor_label, floor_values};
use super::Condition;
use crate::campaign::any_body::{floor_sets, set_stem};
use crate::campaign::export::any_body::{choose_any_body, training_median};
use crate::campaign::Results;
use crate::report::figures::{box_of, BodyPicture, BodyRow, Figure, Plot};
use crate::report::Report;
use std::fmt::Write;
use vsr::controllers::ControllerKind;
use vsr::experiment::ValidationSet;

/// Bodies per row of a bodies figure.
const PER_ROW: usize = 11;

fn strata_file(stem: &str, set: ValidationSet) -> String {
    format!("any-body-{stem}-{set}.svg")
}

fn bodies_file(group: &str, controller: ControllerKind) -> String {
    format!("any-body-bodies-{group}-{controller}.svg")
}

/// Every figure's file name the campaign plans.
fn files(results: &Results) -> Vec<String> {
    let groups = &results.campaign.any_body;
    let strata = floor_sets(groups)
        .into_iter()
        .map(|(b, s)| strata_file(&set_stem(&b), s));
    let bodies = groups
        .iter()
        .flat_map(|g| g.controllers.iter().map(|&c| bodies_file(&g.name, c)));
    strata.chain(bodies).collect()
}

/// The figures and their links, or, while `ready` is false, every one withdrawn.
pub(super) fn figures(results: &Results, all: &[Condition], ready: bool, r: &mut Report) {
    if !ready {
        r.withdrawn.extend(files(results));
        return;
    }
    r.markdown.push_str("### Figures\n\n");
    for (bodies, set) in floor_sets(&results.campaign.any_body) {
        let stem = set_stem(&bodies);
        strata_figure(results, all, (&stem, set), r);
    }
    for c in all {
        bodies_figure(results, c, r);
    }
}

/// The rows of the bodies of `stem` in `c`'s training set (none when no run file is read).
pub(super) fn trained_on(c: &Condition) -> Vec<String> {
    let run = c.runs.iter().find_map(|d| d.run.as_ref());
    let set = run.and_then(|r| r.config.bodies.as_ref());
    set.map_or(Vec::new(), |b| {
        b.set.bodies.iter().map(|s| s.to_rows()).collect()
    })
}

fn strata_figure(
    results: &Results,
    all: &[Condition],
    (stem, set): (&str, ValidationSet),
    r: &mut Report,
) {
    let key = (stem.to_string(), set);
    let mut boxes: Vec<_> = all
        .iter()
        .map(|c| {
            let v = c.measure(|d| d.validation.get(&key).map(|v| v.median));
            box_of(&c.label, v)
        })
        .collect();
    let floor = floor_values(results, ControllerKind::AttentionAny, (stem, set));
    boxes.push(box_of(&floor_label(ControllerKind::AttentionAny), floor));
    boxes.retain(|b| !b.values.is_empty());
    if boxes.is_empty() {
        return;
    }
    // The set's bodies, from any run's validation on it.
    let bodies: Vec<String> = all
        .iter()
        .flat_map(|c| c.runs.iter())
        .find_map(|d| d.validation.get(&key))
        .map_or(Vec::new(), |v| {
            v.per_body.iter().map(|b| b.body.to_rows()).collect()
        });
    let mut notes = vec![format!(
        "dot: one run (seed): the median over the {} bodies of {stem} of each body's mean speed \
         on the {set} terrains; grey: random attention-any brains (the floor)",
        bodies.len()
    )];
    for c in all {
        let trained = trained_on(c);
        let k = bodies.iter().filter(|b| trained.contains(b)).count();
        if k > 0 {
            notes.push(format!(
                "{}: {k} of the {} bodies of {stem} are its training bodies (not held out for it)",
                c.label,
                bodies.len()
            ));
        }
    }
    let refs: Vec<&Condition> = all.iter().collect();
    for (c, most) in super::estimates::fewer_bodies(&refs) {
        notes.push(format!(
            "{}: {} bod{} per evaluation against {most} for the others, so {}/{most} of their \
             training episodes (stated, not corrected)",
            c.label,
            c.group.per_evaluation,
            if c.group.per_evaluation == 1 {
                "y"
            } else {
                "ies"
            },
            c.group.per_evaluation
        ));
    }
    for c in all {
        let runs = c.runs.iter().filter_map(|d| d.validation.get(&key));
        let n: u32 = runs.map(|v| v.exploded).sum();
        if n > 0 {
            notes.push(format!(
                "{}: {n} episodes on {stem} exploded, each counted as 0 m/s",
                c.label
            ));
        }
    }
    let file = strata_file(stem, set);
    let _ = writeln!(r.markdown, "![held-out speed on {stem}]({file})\n");
    r.figures.push(Figure {
        file,
        title: format!("{stem}: speed on bodies never trained on"),
        x_label: "condition (family on training set)".into(),
        y_label: "median over the bodies (m/s)".into(),
        plot: Plot::Boxes(boxes),
        notes,
    });
}

fn bodies_figure(results: &Results, c: &Condition, r: &mut Report) {
    let g = c.group;
    let controller = c.controller;
    let chosen = choose_any_body(results, &[controller]);
    let Some(choice) = chosen
        .into_iter()
        .find(|x| x.key.0 == g.name)
        .and_then(|x| x.choice)
    else {
        let _ = writeln!(
            r.markdown,
            "{}: no bodies figure (its runs are not all validated on every body set).\n",
            c.label
        );
        r.withdrawn.push(bodies_file(&g.name, controller));
        return;
    };
    let Some(&set) = g.sets.first() else { return };
    let trained = trained_on(c);
    let mut rows = Vec::new();
    for heldout in &g.heldout {
        let stem = set_stem(heldout);
        let Some(v) = choice.data.validation.get(&(stem.clone(), set)) else {
            continue;
        };
        let mut bodies: Vec<(f64, String, u32)> = v
            .per_body
            .iter()
            .map(|b| (b.validation.mean, b.body.to_rows(), b.exploded))
            .collect();
        let key = |m: f64| if m.is_nan() { f64::NEG_INFINITY } else { m };
        bodies.sort_by(|a, b| key(b.0).total_cmp(&key(a.0)));
        let walking = v.walking_share * v.per_body.len() as f64;
        for (i, chunk) in bodies.chunks(PER_ROW).enumerate() {
            let (label, note) = if i == 0 {
                (
                    format!("{controller}, {stem}"),
                    format!(
                        "median {:.2} m/s; {} of {} above 1 m/s{}",
                        v.median,
                        walking.round(),
                        v.per_body.len(),
                        if v.exploded > 0 {
                            format!("; {} episodes exploded (0 m/s)", v.exploded)
                        } else {
                            String::new()
                        }
                    ),
                )
            } else {
                (String::new(), String::new())
            };
            let pictures = chunk
                .iter()
                .map(|(mean, rows, exploded)| BodyPicture {
                    caption: match (trained.contains(rows), *exploded) {
                        (true, 0) => format!("{mean:.2} (trained)"),
                        (false, 0) => format!("{mean:.2}"),
                        (true, k) => format!("{mean:.2} (trained, {k} exploded)"),
                        (false, k) => format!("{mean:.2} ({k} exploded)"),
                    },
                    rows: rows.clone(),
                })
                .collect();
            rows.push(BodyRow {
                label,
                note,
                bodies: pictures,
            });
        }
    }
    if rows.is_empty() {
        return;
    }
    let file = bodies_file(&g.name, controller);
    let score = training_median(g, &choice.data).unwrap_or(f64::NAN);
    let _ = writeln!(
        r.markdown,
        "![{} on each held-out body]({file})\n\n{}: the module drawn is seed {}, chosen from {} \
         runs by its training-set median ({score:.2} m/s; no held-out set used to choose).\n",
        c.label, c.label, choice.spec.seed, choice.candidates
    );
    r.figures.push(Figure {
        file,
        title: format!("{}: its speed on each held-out body (m/s)", c.label),
        x_label: String::new(),
        y_label: String::new(),
        plot: Plot::Bodies(rows),
        notes: vec![
            format!(
                "the module: seed {}, the best of {} runs by its training-set median ({score:.2} \
                 m/s); held-out sets not used to choose",
                choice.spec.seed, choice.candidates
            ),
            format!(
                "under each body: its mean speed over the ten {set} terrains (m/s); fastest first"
            ),
        ],
    });
}
