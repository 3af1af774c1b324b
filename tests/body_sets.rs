//! The study's body sets (campaigns/bodies/) are exactly what the seeded generator makes
//! (`vsr bodies --seed 2026`), every file reads back as a body set, and one genome of a brain
//! for any body walks every one of their bodies.

use vsr::controllers::ControllerKind;
use vsr::experiment::body_set::generate::study_sets;
use vsr::experiment::evaluate::fitness;
use vsr::experiment::BodySet;
use vsr::simulation::Terrain;

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/campaigns/bodies");

#[test]
fn the_committed_sets_are_the_generators_to_the_byte() {
    for (stem, text) in study_sets(2026).files() {
        let path = format!("{DIR}/{stem}.txt");
        let committed = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        assert_eq!(
            committed, text,
            "{stem}.txt differs from `vsr bodies --seed 2026`"
        );
        BodySet::parse(&stem, &committed).unwrap();
    }
}

#[test]
fn one_genome_walks_every_body_of_every_set() {
    let kind = ControllerKind::AttentionAny;
    let genome: Vec<f32> = (0..kind.param_count(0))
        .map(|g| ((g * 7919) % 13) as f32 / 6.0 - 1.0)
        .collect();
    let flat = std::sync::Arc::new(Terrain::parse("flat").unwrap());
    for (stem, text) in study_sets(2026).files() {
        let set = BodySet::parse(&stem, &text).unwrap();
        for body in &set.bodies {
            let v = fitness(body, flat.clone(), kind, &genome, Some(1), 1.0);
            assert!(v.is_finite(), "{stem}: {}", body.to_rows());
        }
    }
}
