//! What the playground offers by default, in one place: the drawing grid, the presets, the
//! controllers it evolves, its quick and paper run settings, its terrains, the gait that
//! drives a body with no controller, and the simulation constants its renderer and animation
//! need (time step, area limits, corner size). The page reads them through the wasm boundary
//! (`wasm::defaults`) instead of copying them.

use super::config::{MAX_SEED, PAPER_SECONDS, PAPER_TERRAIN};
use crate::controllers::{ControllerKind, ATTENTION_PARAMS};
use crate::genetics::GaConfig;
use crate::simulation::constants::{AREA_RATIO_MAX_DELTA, CORNER_SIDE, DT};
use crate::simulation::Shape;
use crate::Result;
use serde::Serialize;

/// The drawing grid of the page's editor (cells).
const GRID: Grid = Grid {
    width: 20,
    height: 10,
};
/// Presets the editor offers, by name (each parses with [`Shape::parse`]).
const PRESETS: [&str; 5] = [
    "biped-4x3",
    "comb-7x2",
    "biped-6x4",
    "comb-14x2",
    "worm-6x1",
];
/// Controllers the page evolves: the paper's three, then their brains for any body.
pub const PAGE_CONTROLLERS: [ControllerKind; 6] = [
    ControllerKind::Attention,
    ControllerKind::Mlp,
    ControllerKind::MlpComm,
    ControllerKind::AttentionAny,
    ControllerKind::MlpAny,
    ControllerKind::MlpCommAny,
];
/// The page's quick run: progress within a minute or two on two cores.
const QUICK: RunPreset = RunPreset {
    population: 20,
    seconds: 10.0,
    budget: 2000,
};
/// The terrain the robot walks on in the viewer.
const VIEW_TERRAIN: &str = "hilly-1-10-0";
/// The seed of the viewer's sensor noise (a brain walks in the viewer as in this episode).
pub const VIEW_NOISE_SEED: u64 = 0;
/// The phase gait that drives a body with no controller yet: the reference biped's best
/// forward gait on flat ground (shared/reference/gaits-biped-flat.json).
const GAIT: Gait = Gait {
    frequency: 0.5,
    phase: 1.5,
};

/// The editor's grid.
#[derive(Serialize, Clone, Copy, Debug)]
pub struct Grid {
    width: usize,
    height: usize,
}

/// A run's settings as the page offers them.
#[derive(Serialize, Clone, Copy, Debug)]
pub struct RunPreset {
    population: usize,
    seconds: f64,
    budget: u64,
}

/// A phase gait (Hz, rad per column).
#[derive(Serialize, Clone, Copy, Debug)]
pub struct Gait {
    frequency: f64,
    phase: f64,
}

/// A preset body.
#[derive(Serialize, Debug)]
#[serde(rename_all = "camelCase")]
pub struct Preset {
    name: &'static str,
    rows: String,
}

/// The simulation constants the page's animation and drawing use.
#[derive(Serialize, Debug)]
#[serde(rename_all = "camelCase")]
pub struct Physics {
    /// Simulation time step (s).
    time_step: f64,
    /// Area ratio of a fully contracted voxel (u = +1).
    area_contracted: f64,
    /// Area ratio of a fully expanded voxel (u = -1).
    area_expanded: f64,
    /// Width of a rigid corner square (m).
    corner_side: f64,
}

/// Everything the page starts from; see the module doc.
#[derive(Serialize, Debug)]
#[serde(rename_all = "camelCase")]
pub struct Defaults {
    grid: Grid,
    presets: Vec<Preset>,
    controllers: Vec<&'static str>,
    quick: RunPreset,
    paper: RunPreset,
    training_terrain: &'static str,
    view_terrain: &'static str,
    gait: Gait,
    max_seed: f64,
    attention_genes: usize,
    /// [`VIEW_NOISE_SEED`] as a decimal string (a JS number cannot hold every 64-bit seed).
    view_noise_seed: String,
    physics: Physics,
}

/// The playground's defaults.
pub fn defaults() -> Result<Defaults> {
    let ga = GaConfig::default();
    let presets = PRESETS
        .iter()
        .map(|&name| {
            Ok(Preset {
                name,
                rows: Shape::parse(name)?.to_rows(),
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(Defaults {
        grid: GRID,
        presets,
        controllers: PAGE_CONTROLLERS.iter().map(|k| k.name()).collect(),
        quick: QUICK,
        paper: RunPreset {
            population: ga.population,
            seconds: PAPER_SECONDS,
            budget: ga.budget_evals,
        },
        training_terrain: PAPER_TERRAIN,
        view_terrain: VIEW_TERRAIN,
        gait: GAIT,
        max_seed: MAX_SEED as f64,
        attention_genes: ATTENTION_PARAMS,
        view_noise_seed: VIEW_NOISE_SEED.to_string(),
        physics: Physics {
            time_step: DT,
            area_contracted: 1.0 - AREA_RATIO_MAX_DELTA,
            area_expanded: 1.0 + AREA_RATIO_MAX_DELTA,
            corner_side: CORNER_SIDE,
        },
    })
}
