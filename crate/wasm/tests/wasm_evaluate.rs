//! `evaluate`, the web package's one-call episode (docs/embed.md), under Node
//! (`wasm-pack test --node`): a pretrained module's genome gives bit for bit the outcome of the
//! core's `experiment::evaluate::evaluate`, the episode `vsr evaluate` runs (with its default
//! noise seed 0); bad input is a JS `Error` that says what is wrong.
#![cfg(target_arch = "wasm32")]

mod wasm_common;

use vsr::controllers::ControllerKind;
use vsr::experiment::evaluate::evaluate as core_evaluate;
use vsr::experiment::RunFile;
use vsr::simulation::{Shape, Terrain};
use vsr_wasm::evaluate;
use wasm_bindgen_test::wasm_bindgen_test;
use wasm_common::{error_message, json};

const ATTENTION_RUN: &str = include_str!("../../../pretrained/biped-4x3-attention.json");

#[wasm_bindgen_test]
fn a_pretrained_genome_gives_the_cores_outcome_bit_for_bit() {
    let best = RunFile::from_json(ATTENTION_RUN).expect("valid").best;
    let terrain = "hilly-1-10-3";
    for (noise, seconds) in [(0u64, 10.0), (7, 4.0)] {
        let got = json(
            evaluate(
                "1111-1111-1001",
                "attention",
                terrain,
                &best.genome,
                seconds,
                noise as f64,
            )
            .expect("valid"),
        );
        let want = core_evaluate(
            &Shape::parse("biped-4x3").expect("preset"),
            Terrain::parse(terrain).expect("terrain"),
            ControllerKind::Attention,
            &best.genome,
            Some(noise),
            seconds,
        )
        .expect("stable");
        assert_eq!(
            got["velocity"].as_f64(),
            Some(want.velocity),
            "noise {noise}"
        );
        assert_eq!(got["distance"].as_f64(), Some(want.distance));
        assert_eq!(got["steps"].as_u64(), Some(want.steps));
        assert_eq!(got["seconds"].as_f64(), Some(want.seconds));
        assert_eq!(got["shape"], "1111-1111-1001");
        assert_eq!(got["controller"], "attention");
        assert_eq!(got["noiseSeed"].as_u64(), Some(noise));
        assert!(want.velocity > 1.0, "the biped walks: {}", want.velocity);
    }
}

/// Shape, controller, terrain, genome, seconds, noise, and a word the error must say.
type BadCase<'a> = (&'a str, &'a str, &'a str, &'a [f32], f64, f64, &'a str);

#[wasm_bindgen_test]
fn bad_input_is_a_js_error_that_says_what_is_wrong() {
    let best = RunFile::from_json(ATTENTION_RUN).expect("valid").best;
    let mut nan = best.genome.clone();
    nan[3] = f32::NAN;
    let cases: [BadCase; 6] = [
        (
            "biped-4x3",
            "attention",
            "flat",
            &best.genome[..10],
            5.0,
            0.0,
            "genes",
        ),
        ("biped-4x3", "attention", "flat", &nan, 5.0, 0.0, "finite"),
        (
            "101",
            "attention",
            "flat",
            &best.genome,
            5.0,
            0.0,
            "separate pieces",
        ),
        (
            "biped-4x3",
            "attention",
            "lava",
            &best.genome,
            5.0,
            0.0,
            "unknown terrain",
        ),
        (
            "biped-4x3",
            "attention",
            "flat",
            &best.genome,
            0.0,
            0.0,
            "seconds",
        ),
        (
            "biped-4x3",
            "brain",
            "flat",
            &best.genome,
            5.0,
            0.5,
            "brain",
        ),
    ];
    for (shape, controller, terrain, genome, seconds, noise, says) in cases {
        let error = evaluate(shape, controller, terrain, genome, seconds, noise)
            .err()
            .unwrap_or_else(|| panic!("{shape} {controller} {terrain} {seconds} is refused"));
        let text = error_message(error);
        assert!(text.contains(says), "{text:?} should say {says:?}");
    }
}
