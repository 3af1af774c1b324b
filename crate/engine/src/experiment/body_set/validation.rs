//! One brain measured on many bodies: a body-independent best walked on every body of a set,
//! each on a validation set's 10 terrains (`vsr validate --bodies`). The per-body figure is
//! the mean speed over the 10 terrains (the paper's re-assessment figure); the set's summary
//! is the median of those means over the bodies and the share of bodies above
//! [`WALKS`] m/s.

use super::BodySet;
use crate::error::{Error, Result};
use crate::experiment::run::Best;
use crate::experiment::validation::{validate_on, Validation, ValidationSet};
use crate::quantiles::median;
use crate::simulation::Shape;
use serde::{Deserialize, Serialize};

/// The speed (m/s) above which a body counts as walking in the summary.
pub const WALKS: f64 = 1.0;

/// One body's validation.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BodyValidation {
    /// The body (rows, top first).
    pub body: Shape,
    /// Its speeds on the set's terrains, median and mean.
    pub validation: Validation,
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

/// Validates `best` on one body (see [`validate_on`]).
pub fn validate_body(
    best: &Best,
    body: &Shape,
    set: ValidationSet,
    seconds: f64,
) -> Result<BodyValidation> {
    let on_body = best_on(best, body)?;
    let validation = validate_on(&on_body, set, seconds)
        .map_err(|e| Error::Unstable(format!("{e} (body {})", body.to_rows())))?;
    Ok(BodyValidation {
        body: body.clone(),
        validation,
    })
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
