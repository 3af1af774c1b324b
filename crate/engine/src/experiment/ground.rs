//! The grounds evaluations run on, built once and shared read-only: a run with one fixed
//! training terrain builds it when it starts and hands the same [`Arc`] to every job, on every
//! thread; a job that crossed to a worker (the page's, which gets the job as data) reuses the
//! last ground its worker built when the name is the same. A family's grounds differ from one
//! evaluation to the next (a fresh seed each), so each of those is built when it runs. A
//! terrain's ground is a pure function of its name, so sharing never changes a result.

use super::config::TrainingTerrain;
use crate::error::Result;
use crate::simulation::Terrain;
use std::cell::RefCell;
use std::sync::Arc;

thread_local! {
    /// The last ground this thread (or worker) built.
    static LAST: RefCell<Option<Arc<Terrain>>> = const { RefCell::new(None) };
}

/// The ground named `name`: this thread's last one if it has that name, else built now (and
/// kept as this thread's last one). A bad name is an error naming it.
pub(crate) fn ground(name: &str) -> Result<Arc<Terrain>> {
    LAST.with(|last| {
        let mut last = last.borrow_mut();
        if let Some(kept) = last.as_ref().filter(|t| t.name() == name.trim()) {
            return Ok(Arc::clone(kept));
        }
        let built = Arc::new(Terrain::parse(name)?);
        *last = Some(Arc::clone(&built));
        Ok(built)
    })
}

/// The ground every evaluation of a run on `terrain` shares, built once: that of a fixed
/// terrain; `None` for a family, whose evaluations each get their own.
pub(crate) fn run_ground(terrain: &TrainingTerrain) -> Result<Option<Arc<Terrain>>> {
    match terrain {
        TrainingTerrain::Fixed(name) => Terrain::parse(name).map(|t| Some(Arc::new(t))),
        TrainingTerrain::Family(_) => Ok(None),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_same_name_shares_one_ground_and_another_name_builds_its_own() {
        let first = ground("hilly-1-10-3").unwrap();
        assert!(Arc::ptr_eq(&first, &ground(" hilly-1-10-3 ").unwrap()));
        let other = ground("hilly-1-10-4").unwrap();
        assert_eq!(other.name(), "hilly-1-10-4");
        assert!(!Arc::ptr_eq(&first, &ground("hilly-1-10-3").unwrap()));
        assert!(ground("hills").is_err());
    }

    #[test]
    fn a_fixed_terrain_is_built_once_per_run_and_a_worker_gets_the_same_fitness() {
        use crate::controllers::ControllerKind;
        use crate::experiment::{Evolution, EvolutionConfig, Job};
        use crate::simulation::Shape;
        let shape = Shape::parse("biped-4x3").unwrap();
        let mut config = EvolutionConfig::paper(shape, ControllerKind::Attention, 8, 5);
        (config.ga.population, config.seconds) = (4, 1.0);
        config.terrain = TrainingTerrain::parse("hilly-1-10-3").unwrap();
        let jobs = Evolution::new(config.clone()).unwrap().next_batch();
        let shared: Vec<_> = jobs.iter().map(|j| j.ground.clone().unwrap()).collect();
        assert!(shared.iter().all(|g| Arc::ptr_eq(g, &shared[0])));
        // As the page's worker gets it: the job as data, without the run's ground.
        let mut crossed: Job = serde_json::from_value(serde_json::json!(jobs[1])).unwrap();
        crossed.genome = jobs[1].genome.clone();
        assert!(crossed.ground.is_none());
        let (here, there) = (jobs[1].fitness().unwrap(), crossed.fitness().unwrap());
        assert_eq!(here.to_bits(), there.to_bits());
        config.terrain = TrainingTerrain::parse("hilly-1-10").unwrap();
        let family = Evolution::new(config).unwrap().next_batch();
        assert!(family.iter().all(|j| j.ground.is_none()));
    }
}
