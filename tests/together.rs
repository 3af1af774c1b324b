//! Jobs evaluated together, their springs in SIMD lanes (`fitness_together`), give every
//! job's fitness bit for bit as evaluated alone (`Job::fitness`), on the paper's setup and
//! for each controller, with a last group smaller than the lanes.

use vsr::controllers::ControllerKind;
use vsr::experiment::{fitness_together, Evolution, EvolutionConfig};
use vsr::simulation::Shape;

fn check(shape: &str, kind: ControllerKind, population: usize, seconds: f64) {
    let mut config = EvolutionConfig::paper(Shape::parse(shape).unwrap(), kind, 1000, 3);
    config.ga.population = population;
    config.seconds = seconds;
    let jobs = Evolution::new(config).unwrap().next_batch();
    let alone: Vec<u64> = jobs
        .iter()
        .map(|j| j.fitness().unwrap().to_bits())
        .collect();
    let together: Vec<u64> = fitness_together(&jobs)
        .unwrap()
        .iter()
        .map(|f| f.to_bits())
        .collect();
    assert_eq!(alone, together, "{shape} {kind:?}");
}

#[test]
fn together_equals_alone_on_the_paper_setup() {
    check("biped-4x3", ControllerKind::Attention, 9, 30.0);
}

#[test]
fn together_equals_alone_for_every_controller_and_shape() {
    for kind in ControllerKind::ALL {
        check("comb-7x2", kind, 4, 8.0);
    }
    check("1111-1001", ControllerKind::Mlp, 5, 8.0);
}
