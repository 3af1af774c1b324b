//! Fidelity: this simulator against gait ensembles measured on the reference simulator (the
//! paper's 2D-VSR-Sim; files like `tests/fixtures/gaits-comb-flat.json`). For each open-loop
//! phase gait the reference ran 17 starts shifted by k x 1e-5 m (the dynamics are chaotic:
//! compare distributions, not single runs), and for some gaits the same on the reference with
//! its continuous collision detection (CCD) switched off, an artefact of the original that
//! this project does not reproduce (SPEC). [`measure`] runs the same ensembles here;
//! [`Agreement`] says how close they are. No I/O: the command line reads the reference and
//! writes the measurement.

use super::statistics::{spearman, wilcoxon_signed_rank, SignedRank};
use serde::{Deserialize, Serialize};
use vsr::experiment::{gait_ensemble, PhaseGait};
use vsr::simulation::{Shape, Terrain};
use vsr::{Error, Result};

/// The reference's episode length (s), the paper's.
pub const REFERENCE_SECONDS: f64 = 30.0;

/// A reference file: what was measured and one ensemble per gait.
#[derive(Debug, Clone, Deserialize)]
pub struct Reference {
    /// How the reference measured (copied into the measurement).
    pub what: String,
    /// One ensemble per gait.
    pub conditions: Vec<Condition>,
}

/// One gait's ensemble on the reference.
#[derive(Debug, Clone, Deserialize)]
pub struct Condition {
    /// The robot (a preset name).
    pub shape: String,
    /// The terrain's name.
    pub terrain: String,
    /// Gait frequency (Hz).
    pub f: f64,
    /// Gait phase per column (rad).
    pub phi: f64,
    /// Starts in the ensemble.
    pub n: usize,
    /// Mean velocity over the starts (m/s).
    pub mean_velocity: f64,
    /// Their sample standard deviation (m/s).
    pub sd_velocity: f64,
    /// The same ensemble with the reference's CCD off, where measured.
    #[serde(default)]
    pub ccd_free: Option<Variant>,
}

/// An ensemble of a variant of the reference.
#[derive(Debug, Clone, Deserialize)]
pub struct Variant {
    /// Starts.
    pub n: usize,
    /// Mean velocity (m/s).
    pub mean_velocity: f64,
    /// Sample standard deviation (m/s).
    pub sd_velocity: f64,
}

impl Reference {
    /// Parses a reference file's text; an error says what is wrong.
    pub fn parse(text: &str) -> Result<Reference> {
        let r: Reference = serde_json::from_str(text)
            .map_err(|e| Error::Input(format!("not a reference gait file: {e}")))?;
        if r.conditions.is_empty() {
            return Err(Error::Input("the reference lists no gait".into()));
        }
        Ok(r)
    }
}

/// An ensemble's size, mean and sample standard deviation (m/s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Moments {
    /// Starts.
    pub n: usize,
    /// Mean velocity.
    pub mean: f64,
    /// Sample standard deviation.
    pub sd: f64,
}

/// One gait measured here, beside the reference's numbers.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Gait {
    /// The robot.
    pub shape: String,
    /// The terrain.
    pub terrain: String,
    /// Gait frequency (Hz).
    pub f: f64,
    /// Gait phase per column (rad).
    pub phi: f64,
    /// Our ensemble.
    pub ours: Moments,
    /// Our velocity from each start (m/s), start k shifted by k x 1e-5 m.
    pub velocities: Vec<f64>,
    /// The reference's ensemble.
    pub reference: Moments,
    /// The reference's ensemble with CCD off, where measured.
    pub ccd_free: Option<Moments>,
}

/// A reference's gaits measured here (what `vsr fidelity` writes).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Fidelity {
    /// How the reference measured.
    pub what: String,
    /// Every gait, in the reference's order.
    pub gaits: Vec<Gait>,
}

/// Runs every gait of `reference` here: the same starts, terrain and length.
pub fn measure(reference: &Reference) -> Result<Fidelity> {
    let mut gaits = Vec::with_capacity(reference.conditions.len());
    for c in &reference.conditions {
        let shape = Shape::parse(&c.shape)?;
        let terrain = Terrain::parse(&c.terrain)?;
        let gait = PhaseGait::new(c.f, c.phi)?;
        let e = gait_ensemble(&shape, &terrain, gait, REFERENCE_SECONDS, c.n, 0.0)?;
        let moments = |n, mean, sd| Moments { n, mean, sd };
        gaits.push(Gait {
            shape: c.shape.clone(),
            terrain: c.terrain.clone(),
            f: c.f,
            phi: c.phi,
            ours: moments(c.n, e.mean, e.sd.unwrap_or(0.0)),
            velocities: e.velocities,
            reference: moments(c.n, c.mean_velocity, c.sd_velocity),
            ccd_free: c
                .ccd_free
                .as_ref()
                .map(|v| moments(v.n, v.mean_velocity, v.sd_velocity)),
        });
    }
    Ok(Fidelity {
        what: reference.what.clone(),
        gaits,
    })
}

/// How closely our ensembles follow the reference's.
#[derive(Debug, Clone, PartialEq)]
pub struct Agreement {
    /// Gaits compared.
    pub gaits: usize,
    /// Gaits whose mean here is within 2 reference sd of the reference's mean.
    pub within_2sd: usize,
    /// Spearman's rank correlation of the means (do the gaits rank alike?).
    pub rho: f64,
    /// Our mean velocity over the gaits (m/s).
    pub mean_ours: f64,
    /// The reference's (m/s).
    pub mean_reference: f64,
    /// On the gaits measured with CCD off too: which variant ours is closer to.
    pub ccd_free: Option<CcdComparison>,
}

/// Our means against both reference variants on the gaits measured with CCD off.
#[derive(Debug, Clone, PartialEq)]
pub struct CcdComparison {
    /// Gaits measured with CCD off.
    pub gaits: usize,
    /// Mean |ours - reference| (m/s).
    pub to_reference: f64,
    /// Mean |ours - reference with CCD off| (m/s).
    pub to_ccd_free: f64,
    /// Signed-rank test of |ours - reference| against |ours - CCD off|, paired by gait.
    pub test: SignedRank,
}

impl Fidelity {
    /// The agreement of our ensembles with the reference's.
    pub fn agreement(&self) -> Agreement {
        let n = self.gaits.len() as f64;
        let ours: Vec<f64> = self.gaits.iter().map(|g| g.ours.mean).collect();
        let theirs: Vec<f64> = self.gaits.iter().map(|g| g.reference.mean).collect();
        let inside = |g: &&Gait| (g.ours.mean - g.reference.mean).abs() <= 2.0 * g.reference.sd;
        let (mut to_ref, mut to_cf) = (vec![], vec![]);
        for g in &self.gaits {
            if let Some(cf) = g.ccd_free {
                to_ref.push((g.ours.mean - g.reference.mean).abs());
                to_cf.push((g.ours.mean - cf.mean).abs());
            }
        }
        let mean = |v: &[f64]| v.iter().sum::<f64>() / v.len() as f64;
        Agreement {
            gaits: self.gaits.len(),
            within_2sd: self.gaits.iter().filter(inside).count(),
            rho: spearman(&ours, &theirs),
            mean_ours: ours.iter().sum::<f64>() / n,
            mean_reference: theirs.iter().sum::<f64>() / n,
            ccd_free: (!to_ref.is_empty()).then(|| CcdComparison {
                gaits: to_ref.len(),
                to_reference: mean(&to_ref),
                to_ccd_free: mean(&to_cf),
                test: wilcoxon_signed_rank(&to_ref, &to_cf),
            }),
        }
    }
}
