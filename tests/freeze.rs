//! Freezing the attention of a walking robot (experiment::freeze): until frozen, the
//! freezable brain walks exactly as `vsr evaluate`'s; frozen mid-walk, the pretrained
//! biped's attention stops changing and its speed falls by more than two thirds (the
//! paper's Fig. 6, live); released, the matrices move again; other brains refuse.

use vsr::experiment::evaluate::controller_for;
use vsr::experiment::{freezable_policy, steps_for, Episode, Policy, RunFile};
use vsr::simulation::Terrain;

/// The viewer's terrain and the sensor-noise seed its episodes use.
const TERRAIN: &str = "hilly-1-10-0";
const NOISE: Option<u64> = Some(0);

fn pretrained(file: &str) -> RunFile {
    let full = format!("{}/pretrained/{file}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&full).unwrap_or_else(|e| panic!("{full}: {e}"));
    RunFile::from_json(&text).expect("a run file")
}

fn episode(run: &RunFile, freezable: bool) -> Episode {
    let best = &run.best;
    let policy = if freezable {
        freezable_policy(best.controller, &best.shape, &best.genome).unwrap()
    } else {
        Policy::Brain(controller_for(best.controller, &best.shape, &best.genome).unwrap())
    };
    Episode::with_policy(&best.shape, Terrain::parse(TERRAIN).unwrap(), policy, NOISE)
}

/// Steps to `seconds` and returns the centre's x there.
fn x_at(ep: &mut Episode, seconds: f64) -> f64 {
    let target = steps_for(seconds);
    ep.step((target - ep.world().steps()) as usize).unwrap();
    ep.centre_x()
}

#[test]
fn a_freezable_brain_walks_bit_for_bit_as_the_plain_one() {
    let run = pretrained("biped-4x3-attention.json");
    let (mut plain, mut freezable) = (episode(&run, false), episode(&run, true));
    assert_eq!(plain.run(8.0).unwrap(), freezable.run(8.0).unwrap());
    assert_eq!(plain.attention(), freezable.attention());
    assert!(!freezable.attention_frozen());
}

#[test]
fn freezing_a_walking_attention_biped_stops_it_and_releasing_lets_the_matrices_move() {
    let run = pretrained("biped-4x3-attention.json");
    let mut ep = episode(&run, true);
    let x5 = x_at(&mut ep, 5.0);
    let x10 = x_at(&mut ep, 10.0);
    let before = (x10 - x5) / 5.0;
    ep.set_attention_frozen(true).unwrap();
    assert!(ep.attention_frozen());
    let held = ep.attention().unwrap().to_vec();
    let x20 = x_at(&mut ep, 20.0);
    let after = (x20 - x10) / 10.0;
    assert_eq!(ep.attention().unwrap(), &held[..], "frozen matrices stay");
    println!("# pretrained attention biped on {TERRAIN}: {before:.3} m/s over 5-10 s, {after:.3} m/s over the 10 s after freezing");
    assert!(before > 1.0, "it walks before: {before}");
    assert!(
        after.abs() < before / 3.0,
        "frozen it slows by more than two thirds: {before} -> {after}"
    );
    ep.set_attention_frozen(false).unwrap();
    assert!(!ep.attention_frozen());
    x_at(&mut ep, 21.0);
    assert_ne!(
        ep.attention().unwrap(),
        &held[..],
        "released, the matrices move again"
    );
}

#[test]
fn brains_without_attention_and_the_gait_refuse_to_freeze() {
    for file in ["biped-4x3-mlp.json", "biped-4x3-mlp-comm.json"] {
        let mut ep = episode(&pretrained(file), true);
        let err = ep.set_attention_frozen(true).unwrap_err().to_string();
        assert!(err.contains("no attention to freeze"), "{file}: {err}");
        assert!(!ep.attention_frozen());
    }
    let mut gait = Episode::new("biped-4x3", TERRAIN, 1.0, 1.5).unwrap();
    assert!(gait.set_attention_frozen(true).is_err());
}
