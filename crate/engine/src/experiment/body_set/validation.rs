//! One brain measured on many bodies: a body-independent best walked on every body of a set,
//! each on a validation set's 10 terrains (`vsr validate --bodies`). The per-body figure is
//! the mean speed over the 10 terrains (the paper's re-assessment figure); the set's summary
//! is the median of those means over the bodies and the share of bodies above
//! [`WALKS`] m/s.
//!
//! An episode that explodes (its state becomes non-finite) counts as 0 m/s: the body did not
//! walk there (docs/ANALYSIS-PLAN.md, amendment 1 to the fourth question). The validation
//! goes on and says how many exploded (`exploded`, written only when some did, so a file
//! without one reads as before). A single shape's validation still stops at such an episode.

use super::BodySet;
use crate::controllers::ControllerKind;
use crate::error::{Error, Result};
use crate::experiment::run::Best;
use crate::experiment::validation::{episodes_on, TerrainVelocity, Validation, ValidationSet};
use crate::quantiles::median;
use crate::random::rng_from;
use crate::simulation::Shape;
use rand::Rng;
use serde::{Deserialize, Serialize};

/// The speed (m/s) above which a body counts as walking in the summary.
pub const WALKS: f64 = 1.0;

/// One body's validation.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BodyValidation {
    /// The body (rows, top first).
    pub body: Shape,
    /// Its speeds on the set's terrains, median and mean (an exploded episode as 0 m/s).
    pub validation: Validation,
    /// How many of its episodes exploded (counted as 0 m/s).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub exploded: u32,
}

fn is_zero(n: &u32) -> bool {
    *n == 0
}

/// A brain's validation on a body set; see the module doc.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BodiesValidation {
    /// The body set's name (its file).
    pub bodies: String,
    /// The terrains.
    pub set: ValidationSet,
    /// Episode length (s).
    pub seconds: f64,
    /// Median over the bodies of each body's mean speed (m/s).
    pub median: f64,
    /// Share of the bodies whose mean speed is above [`WALKS`] m/s.
    pub walking_share: f64,
    /// One entry per body, in the set's order.
    pub per_body: Vec<BodyValidation>,
    /// How many episodes exploded over all the bodies (each counted as 0 m/s).
    #[serde(default, skip_serializing_if = "is_zero")]
    pub exploded: u32,
}

/// `best` on `body`: the same genome on another body, which only a body-independent
/// controller can (an error in words otherwise).
pub fn best_on(best: &Best, body: &Shape) -> Result<Best> {
    if !best.controller.is_body_independent() && *body != best.shape {
        return Err(Error::Input(format!(
            "this {} brain has genes for each voxel of its own body ({}), so it cannot walk \
             other bodies; only a brain for any body (attention-any, mlp-any, mlp-comm-any) \
             can be measured on a body set",
            best.controller,
            best.shape.to_rows()
        )));
    }
    Ok(Best {
        shape: body.clone(),
        ..best.clone()
    })
}

/// A random brain for any body: `controller`'s genome drawn uniformly in [-1, 1] (the GA's
/// initial range) from the project's generator seeded with `seed`, on `body` (its fitness
/// unknown: NaN). The floor a trained brain is measured against (`vsr validate
/// --random-brain`); a controller with genes for each voxel is refused in words.
pub fn random_brain(controller: ControllerKind, body: &Shape, seed: u64) -> Result<Best> {
    if !controller.is_body_independent() {
        return Err(Error::Input(format!(
            "a random brain for a body set needs a brain for any body (attention-any, mlp-any, \
             mlp-comm-any), not {controller}"
        )));
    }
    let mut rng = rng_from(seed);
    let genome = (0..controller.param_count(body.voxel_count()))
        .map(|_| -1.0 + 2.0 * rng.gen::<f32>())
        .collect();
    Ok(Best::new(controller, body.clone(), genome, f64::NAN))
}

/// Validates `best` on one body: every episode of the set, an exploded one as 0 m/s.
pub fn validate_body(
    best: &Best,
    body: &Shape,
    set: ValidationSet,
    seconds: f64,
) -> Result<BodyValidation> {
    let on_body = best_on(best, body)?;
    let episodes = episodes_on(&on_body, set, seconds)
        .map_err(|e| Error::Unstable(format!("{e} (body {})", body.to_rows())))?;
    let (terrains, exploded) = exploded_as_zero(episodes)
        .map_err(|e| Error::Unstable(format!("{e} (body {})", body.to_rows())))?;
    Ok(BodyValidation {
        body: body.clone(),
        validation: Validation::of(set, terrains),
        exploded,
    })
}

/// The episodes' velocities with an exploded episode (an [`Error::Unstable`]) as 0 m/s, and
/// how many exploded; any other error stops the validation.
fn exploded_as_zero(episodes: Vec<(String, Result<f64>)>) -> Result<(Vec<TerrainVelocity>, u32)> {
    let mut exploded = 0;
    let mut terrains = Vec::with_capacity(episodes.len());
    for (terrain, velocity) in episodes {
        let velocity = match velocity {
            Ok(v) => v,
            Err(Error::Unstable(_)) => {
                exploded += 1;
                0.0
            }
            Err(e) => return Err(e.about(format!("validation terrain {terrain}"))),
        };
        terrains.push(TerrainVelocity { terrain, velocity });
    }
    Ok((terrains, exploded))
}

impl BodiesValidation {
    /// The summary of per-body validations of `bodies` (in its order).
    pub fn new(
        bodies: &BodySet,
        set: ValidationSet,
        seconds: f64,
        per_body: Vec<BodyValidation>,
    ) -> Self {
        let means: Vec<f64> = per_body.iter().map(|b| b.validation.mean).collect();
        let walking = means.iter().filter(|&&m| m > WALKS).count();
        BodiesValidation {
            bodies: bodies.name.clone(),
            set,
            seconds,
            median: median(&means),
            walking_share: walking as f64 / means.len().max(1) as f64,
            exploded: per_body.iter().map(|b| b.exploded).sum(),
            per_body,
        }
    }
}

/// Validates `best` on every body of `bodies`, one after another (the CLI spreads the bodies
/// over threads with [`validate_body`]; the result is the same).
pub fn validate_bodies(
    best: &Best,
    bodies: &BodySet,
    set: ValidationSet,
    seconds: f64,
) -> Result<BodiesValidation> {
    let per_body = bodies
        .bodies
        .iter()
        .map(|b| validate_body(best, b, set, seconds))
        .collect::<Result<Vec<_>>>()?;
    Ok(BodiesValidation::new(bodies, set, seconds, per_body))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_random_brain_is_its_seed_s_for_every_body_and_refuses_a_per_voxel_brain() {
        let biped = Shape::parse("biped-4x3").unwrap();
        let comb = Shape::parse("comb-7x2").unwrap();
        let kind = ControllerKind::AttentionAny;
        let a = random_brain(kind, &biped, 3).unwrap();
        assert_eq!(a.genome, random_brain(kind, &comb, 3).unwrap().genome);
        assert_ne!(a.genome, random_brain(kind, &biped, 4).unwrap().genome);
        assert_eq!(a.genome.len(), kind.param_count(biped.voxel_count()));
        assert!(a.genome.iter().all(|g| (-1.0..=1.0).contains(g)));
        assert!(a.fitness.is_nan());
        let e = random_brain(ControllerKind::Attention, &biped, 3).unwrap_err();
        assert!(e.to_string().contains("brain for any body"), "{e}");
    }

    /// No genome found cheaply explodes (genes must be finite and every controller's output
    /// is bounded), so the counting is tested on made-up outcomes.
    #[test]
    fn an_exploded_episode_counts_as_zero_and_is_counted() {
        let unstable = || Err(Error::Unstable("non-finite state after 7 steps".into()));
        let episodes = vec![
            ("a".to_string(), Ok(1.5)),
            ("b".to_string(), unstable()),
            ("c".to_string(), Ok(-0.25)),
            ("d".to_string(), unstable()),
        ];
        let (terrains, exploded) = exploded_as_zero(episodes).unwrap();
        assert_eq!(exploded, 2);
        let v: Vec<f64> = terrains.iter().map(|t| t.velocity).collect();
        assert_eq!(v, [1.5, 0.0, -0.25, 0.0]);
        let validation = Validation::of(ValidationSet::Unseen, terrains);
        assert_eq!(validation.mean, 0.3125);
        assert_eq!(validation.median, 0.0);
        let other = vec![("e".to_string(), Err(Error::Input("no".into())))];
        let e = exploded_as_zero(other).unwrap_err();
        assert!(e.to_string().contains("validation terrain e"), "{e}");
    }

    #[test]
    fn a_count_of_zero_is_not_written_and_reads_back_as_zero() {
        let biped = Shape::parse("biped-4x3").unwrap();
        let best = random_brain(ControllerKind::AttentionAny, &biped, 1).unwrap();
        let body = validate_body(&best, &biped, ValidationSet::Unseen, 0.2).unwrap();
        assert_eq!(body.exploded, 0);
        let json = serde_json::to_string(&body).unwrap();
        assert!(!json.contains("exploded"), "{json}");
        let set = BodySet {
            name: "one".into(),
            bodies: vec![biped.clone()],
        };
        let all = BodiesValidation::new(&set, ValidationSet::Unseen, 0.2, vec![body.clone()]);
        assert!(!serde_json::to_string(&all).unwrap().contains("exploded"));
        let counted = BodyValidation {
            exploded: 3,
            ..body
        };
        let all = BodiesValidation::new(&set, ValidationSet::Unseen, 0.2, vec![counted.clone()]);
        assert_eq!(all.exploded, 3);
        let json = serde_json::to_string(&all).unwrap();
        assert!(json.contains("\"exploded\":3"), "{json}");
        let back: BodiesValidation = serde_json::from_str(&json).unwrap();
        assert_eq!(back, all);
    }
}
