//! The live boundary of the `Episode` handle under Node (`wasm-pack test --node`): an
//! attention brain built with `fromGenome` freezes and releases its attention mid-walk
//! (matrices held, then moving again) and slows down frozen; brains without attention and
//! run-file episodes refuse with a JS `Error`; `velocity` is the fitness so far; `stepsLeft`
//! counts the steps to an episode's end as `vsr evaluate` does; and
//! `attentionTerms` gives the four numbers behind the matrices or refuses a short genome.
#![cfg(target_arch = "wasm32")]

mod wasm_common;

use vsr::experiment::RunFile;
use vsr_wasm::{attention_terms, Episode};
use wasm_bindgen_test::wasm_bindgen_test;
use wasm_common::error_message;

const ATTENTION_RUN: &str = include_str!("../../../pretrained/biped-4x3-attention.json");
const MLP_RUN: &str = include_str!("../../../pretrained/biped-4x3-mlp.json");
const TERRAIN: &str = "hilly-1-10-0";

/// The run's best on its own body, built as the page's viewer builds it.
fn walking(text: &str) -> Episode {
    let best = RunFile::from_json(text).expect("a run file").best;
    let rows = best.shape.to_rows();
    let kind = best.controller.to_string();
    Episode::from_genome(&rows, TERRAIN, &kind, &best.genome, f64::NAN).expect("it builds")
}

#[wasm_bindgen_test]
fn an_attention_brain_freezes_mid_walk_slows_down_and_releases() {
    let mut ep = walking(ATTENTION_RUN);
    ep.step(300).unwrap();
    let (t5, x5) = (ep.time(), ep.centre_x());
    ep.step(300).unwrap();
    let before = (ep.centre_x() - x5) / (ep.time() - t5);
    assert!(!ep.attention_frozen());
    ep.freeze_attention(true).expect("attention freezes");
    assert!(ep.attention_frozen());
    let held = ep.attention();
    let (t10, x10) = (ep.time(), ep.centre_x());
    ep.step(600).unwrap();
    let after = (ep.centre_x() - x10) / (ep.time() - t10);
    assert_eq!(ep.attention(), held, "frozen matrices stay");
    assert!(
        before > 1.0 && after.abs() < before / 3.0,
        "{before} -> {after}"
    );
    ep.freeze_attention(false).expect("and releases");
    ep.step(60).unwrap();
    assert_ne!(ep.attention(), held, "released, the matrices move");
}

#[wasm_bindgen_test]
fn brains_without_attention_refuse_to_freeze_with_an_error() {
    let mut mlp = walking(MLP_RUN);
    let message = error_message(mlp.freeze_attention(true).unwrap_err());
    assert!(message.contains("no attention to freeze"), "{message}");
    let mut gait = Episode::new("biped-4x3", TERRAIN, 1.0, 1.5).unwrap();
    assert!(gait.freeze_attention(true).is_err());
    assert!(!gait.attention_frozen());
    let mut replayed = Episode::from_run_file(ATTENTION_RUN, TERRAIN, "").unwrap();
    assert!(
        replayed.freeze_attention(true).is_err(),
        "a replayed run file is plain attention"
    );
}

#[wasm_bindgen_test]
fn velocity_is_the_fitness_so_far() {
    let mut ep = walking(ATTENTION_RUN);
    assert_eq!(ep.velocity(), 0.0);
    ep.step(1).unwrap();
    let x1 = ep.centre_x();
    ep.step(599).unwrap();
    let expected = (ep.centre_x() - x1) / (599.0 / 60.0);
    assert!(
        (ep.velocity() - expected).abs() < 1e-9,
        "{} vs {expected}",
        ep.velocity()
    );
    assert_eq!(ep.steps_left(30.0), 1201.0, "1801 steps make 30 s");
    ep.step(1201).unwrap();
    assert_eq!(ep.steps_left(30.0), 0.0);
    assert_eq!(ep.steps_left(1.0), 0.0, "never negative");
}

#[wasm_bindgen_test]
fn attention_terms_are_the_genome_dot_products_and_short_genomes_are_refused() {
    let genome = RunFile::from_json(ATTENTION_RUN).unwrap().best.genome;
    let terms = attention_terms(&genome).expect("an attention genome");
    let part = |k: usize| &genome[8 * k..8 * k + 8];
    let dot = |x: &[f32], y: &[f32]| x.iter().zip(y).map(|(p, q)| p * q).sum::<f32>() / 8f32.sqrt();
    let expected = [
        dot(part(0), part(2)),
        dot(part(0), part(3)),
        dot(part(1), part(2)),
        dot(part(1), part(3)),
    ];
    for (t, e) in terms.iter().zip(expected) {
        assert!((t - e).abs() < 1e-5, "{terms:?} vs {expected:?}");
    }
    let message = error_message(attention_terms(&genome[..10]).unwrap_err());
    assert!(message.contains("32 attention genes"), "{message}");
}
