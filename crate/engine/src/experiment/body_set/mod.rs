//! Body sets: many bodies in one file, for training one brain on many bodies and measuring it
//! on bodies it never saw (`vsr evolve --bodies`, `vsr validate --bodies`).
//!
//! The file format is text, one body per line in the row notation (`1111-1111-1001`, or a
//! preset name), with `#` starting a comment line that says where the set comes from (its
//! provenance); blank lines are ignored. The sets the study uses are made once by a seeded
//! generator ([`generate`]) and committed under `campaigns/bodies/`.

pub mod generate;
#[cfg(test)]
mod measure;
pub mod validation;

use crate::error::{Error, Result};
use crate::simulation::Shape;
use serde::{Deserialize, Serialize};

pub use validation::{
    random_brain, validate_bodies, validate_body, BodiesValidation, BodyValidation,
};

/// Most bodies a set may hold.
pub const MAX_BODIES: usize = 10_000;

/// A named list of bodies; see the module doc.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BodySet {
    /// Where the set comes from (its file name), for messages and run files.
    pub name: String,
    /// The bodies, in file order.
    pub bodies: Vec<Shape>,
}

impl BodySet {
    /// Parses a body-set file's text; `name` (e.g. the file name) is used in messages. An empty
    /// set, a line that is not a body, or too many bodies is an error naming the line.
    pub fn parse(name: &str, text: &str) -> Result<BodySet> {
        let mut bodies = Vec::new();
        for (k, line) in text.lines().enumerate() {
            let line = line.trim();
            if line.is_empty() || line.starts_with('#') {
                continue;
            }
            let shape = Shape::parse(line).map_err(|e| {
                Error::Input(format!(
                    "line {} of the body set {name} is not a body: {e}",
                    k + 1
                ))
            })?;
            bodies.push(shape);
            if bodies.len() > MAX_BODIES {
                return Err(Error::Input(format!(
                    "the body set {name} has more than {MAX_BODIES} bodies"
                )));
            }
        }
        if bodies.is_empty() {
            return Err(Error::Input(format!(
                "the body set {name} has no bodies: write one body per line in the row \
                 notation (e.g. 1111-1111-1001), with # before a comment"
            )));
        }
        Ok(BodySet {
            name: name.to_string(),
            bodies,
        })
    }

    /// Reads a body-set file; errors name the file.
    pub fn read(path: &std::path::Path) -> Result<BodySet> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| Error::Io(format!("cannot read the body set {}: {e}", path.display())))?;
        let name = path.file_name().map_or_else(
            || path.display().to_string(),
            |n| n.to_string_lossy().into(),
        );
        BodySet::parse(&name, &text)
    }

    /// The file text: `comments` (each line prefixed with `# `), then one body per line.
    pub fn to_text(&self, comments: &[String]) -> String {
        let mut out = String::new();
        for c in comments {
            out.push_str(&format!("# {c}\n"));
        }
        for b in &self.bodies {
            out.push_str(&b.to_rows());
            out.push('\n');
        }
        out
    }
}

/// A body's mirror image (left and right swapped), in the row notation.
pub fn mirror_rows(shape: &Shape) -> String {
    shape
        .to_rows()
        .split('-')
        .map(|row| row.chars().rev().collect::<String>())
        .collect::<Vec<_>>()
        .join("-")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn comments_and_blank_lines_are_skipped_and_bodies_read() {
        let set = BodySet::parse("t.txt", "# a set\n\n1111-1111-1001\n  biped-4x3 \n11\n").unwrap();
        assert_eq!(set.bodies.len(), 3);
        assert_eq!(set.bodies[0], set.bodies[1]);
        let back = BodySet::parse("t.txt", &set.to_text(&["made here".into()])).unwrap();
        assert_eq!(back, set);
    }

    #[test]
    fn bad_sets_are_refused_in_words() {
        let empty = BodySet::parse("e.txt", "# nothing\n\n")
            .unwrap_err()
            .to_string();
        assert!(
            empty.contains("no bodies") && empty.contains("e.txt"),
            "{empty}"
        );
        let bad = BodySet::parse("b.txt", "11\n1x1\n")
            .unwrap_err()
            .to_string();
        assert!(bad.contains("line 2") && bad.contains("b.txt"), "{bad}");
        let split = BodySet::parse("s.txt", "101\n").unwrap_err().to_string();
        assert!(split.contains("line 1"), "{split}");
        let huge = format!("{}\n", vec!["1".repeat(100); 5].join("-"));
        assert!(BodySet::parse("h.txt", &huge).is_err());
    }

    #[test]
    fn a_mirror_swaps_left_and_right() {
        let l = Shape::parse("10-11").unwrap();
        assert_eq!(mirror_rows(&l), "01-11");
        assert_eq!(
            mirror_rows(&Shape::parse("biped-4x3").unwrap()),
            "1111-1111-1001"
        );
    }
}
