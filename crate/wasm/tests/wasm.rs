//! The wasm boundary, run under Node by `wasm-pack test --node`: an `Episode` builds
//! from a shape string, steps, fills frame buffers of the documented lengths with
//! finite numbers, and reports bad input as a JS `Error` instead of trapping. The same
//! handle built from a pretrained run file walks and exposes its attention matrices (the
//! `Evolution` handle: wasm_evolution.rs).
#![cfg(target_arch = "wasm32")]

mod wasm_common;

use vsr_wasm::{bench_episode, Episode};
use wasm_bindgen_test::wasm_bindgen_test;
use wasm_common::error_message;

#[wasm_bindgen_test]
fn preset_and_row_string_build_the_same_biped() {
    let preset = Episode::new("biped-4x3", "flat", 1.0, 1.5).expect("preset builds");
    let rows = Episode::new("1111-1111-1001", "flat", 1.0, 1.5).expect("rows build");
    assert_eq!(preset.voxel_count(), 10);
    assert_eq!(rows.voxel_count(), 10);
    assert_eq!(preset.corners(), rows.corners());
}

#[wasm_bindgen_test]
fn frame_buffers_have_the_documented_lengths() {
    for (shape, n) in [("biped-4x3", 10), ("comb-7x2", 11), ("1", 1)] {
        let episode = Episode::new(shape, "hilly-1-10-0", 1.0, 1.5).expect("valid shape");
        assert_eq!(episode.voxel_count(), n, "{shape}");
        assert_eq!(episode.corners().len(), 8 * n, "{shape} corners");
        assert_eq!(episode.area_ratios().len(), n, "{shape} area ratios");
        assert_eq!(
            episode.corner_bodies().len(),
            12 * n,
            "{shape} corner bodies"
        );
    }
}

#[wasm_bindgen_test]
fn stepping_advances_time_and_keeps_numbers_finite() {
    let mut episode = Episode::new("biped-4x3", "hilly-1-10-0", 1.0, 1.5).expect("valid");
    let x0 = episode.centre_x();
    episode.step(120).expect("stable");
    assert!(
        (episode.time() - 2.0).abs() < 1e-9,
        "120 steps are 2 s, got {}",
        episode.time()
    );
    let frame = [
        episode.corners(),
        episode.area_ratios(),
        episode.corner_bodies(),
    ]
    .concat();
    assert!(
        frame.iter().all(|v| v.is_finite()),
        "a frame value is not finite"
    );
    assert!(episode.centre_x().is_finite() && episode.centre_y().is_finite());
    assert_ne!(episode.centre_x(), x0, "the robot moved");
    let ratios = episode.area_ratios();
    assert!(
        ratios.iter().all(|&a| (0.6..1.4).contains(&a)),
        "area ratios {ratios:?}"
    );
}

#[wasm_bindgen_test]
fn terrain_polyline_has_walls() {
    let episode = Episode::new("biped-4x3", "hilly-1-10-0", 1.0, 1.5).expect("valid");
    let (xs, ys) = (episode.terrain_xs(), episode.terrain_ys());
    assert_eq!(xs.len(), 205);
    assert_eq!(ys.len(), xs.len());
    assert_eq!((xs[0], ys[0]), (0.0, 100.0));
    assert_eq!(ys[ys.len() - 1], 100.0);
}

#[wasm_bindgen_test]
fn an_edited_walking_robot_keeps_its_posture() {
    let mut old = Episode::new("biped-4x3", "hilly-1-10-0", 1.5, 1.0).expect("valid");
    old.step(150).expect("stable");
    // The top-right voxel removed: the rows keep their bounding box.
    let left = old.left_edge();
    let mut edited =
        Episode::gait_at("1110-1111-1001", "hilly-1-10-0", 1.5, 1.0, left).expect("valid");
    edited.carry_pose(&old, 0, 0);
    let (before, after) = (old.corners(), edited.corners());
    // Voxels are ordered bottom row first, left to right: the removed one was the last.
    assert_eq!(after.len() + 8, before.len());
    for (a, b) in after.iter().zip(&before) {
        assert!((a - b).abs() < 1e-5, "{a} became {b}");
    }
    edited.step(60).expect("stable");
}

#[wasm_bindgen_test]
fn invalid_shapes_are_js_errors_not_traps() {
    for shape in ["", "11x1-1001", "1111-11", "101", "not-a-preset"] {
        let error = Episode::new(shape, "flat", 1.0, 1.5)
            .err()
            .unwrap_or_else(|| panic!("{shape:?} should be rejected"));
        let message = error_message(error);
        assert!(message.contains("shape"), "{shape:?}: {message}");
    }
}

#[wasm_bindgen_test]
fn invalid_terrain_and_gait_are_js_errors() {
    let terrain = Episode::new("biped-4x3", "hilly-one", 1.0, 1.5).err();
    assert!(error_message(terrain.expect("rejected")).contains("terrain"));
    let gait = Episode::new("biped-4x3", "flat", f64::NAN, 1.5).err();
    assert!(error_message(gait.expect("rejected")).contains("gait"));
}

#[wasm_bindgen_test]
fn bench_episode_runs_and_reports_a_finite_displacement() {
    let dx = bench_episode("biped-4x3", "hilly-1-10-0", 1.0, 1.5, 60).expect("valid");
    assert!(dx.is_finite());
    assert!(bench_episode("", "flat", 1.0, 1.5, 60).is_err());
}

const ATTENTION_RUN: &str = include_str!("../../../pretrained/biped-4x3-attention.json");
const MLP_RUN: &str = include_str!("../../../pretrained/biped-4x3-mlp.json");

#[wasm_bindgen_test]
fn pretrained_attention_biped_walks_and_has_16_attention_floats_per_voxel() {
    let mut episode = Episode::from_run_file(ATTENTION_RUN, "hilly-1-10-0", "").expect("valid");
    assert_eq!(episode.controller(), "attention");
    assert_eq!(episode.shape(), "1111-1111-1001");
    assert_eq!(episode.voxel_count(), 10);
    assert_eq!(episode.voxel_cells().len(), 20);
    let x0 = episode.centre_x();
    episode.step(300).expect("stable");
    // Validation on hilly-1-10-0 gives 5.4 m/s over 30 s: 5 s must cover well over 2 m.
    assert!(
        episode.centre_x() - x0 > 2.0,
        "moved {}",
        episode.centre_x() - x0
    );
    let attention = episode.attention();
    assert_eq!(attention.len(), 16 * 10);
    assert!(
        attention.iter().all(|a| (-1.0..=1.0).contains(a)),
        "{attention:?}"
    );
    assert!(
        attention.iter().any(|&a| a != 0.0),
        "the matrices were computed"
    );
}

#[wasm_bindgen_test]
fn the_same_shape_by_preset_is_accepted_and_another_shape_is_a_js_error() {
    let preset = Episode::from_run_file(ATTENTION_RUN, "flat", "biped-4x3").expect("same shape");
    assert_eq!(preset.shape(), "1111-1111-1001");
    let error = Episode::from_run_file(ATTENTION_RUN, "flat", "comb-7x2").err();
    let message = error_message(error.expect("another shape is refused"));
    assert!(message.contains("needs shape 1111-1111-1001"), "{message}");
}

#[wasm_bindgen_test]
fn controllers_without_attention_and_the_gait_give_an_empty_attention() {
    let mlp = Episode::from_run_file(MLP_RUN, "flat", "").expect("valid");
    assert_eq!(mlp.controller(), "mlp");
    assert!(mlp.attention().is_empty());
    let gait = Episode::new("biped-4x3", "flat", 1.0, 1.5).expect("valid");
    assert_eq!(gait.controller(), "phase gait");
    assert!(gait.attention().is_empty());
}

#[wasm_bindgen_test]
fn malformed_and_wrong_version_run_files_are_js_errors() {
    let cut = &ATTENTION_RUN[..ATTENTION_RUN.len() / 2];
    let message = error_message(
        Episode::from_run_file(cut, "flat", "")
            .err()
            .expect("refused"),
    );
    assert!(message.contains("cut off"), "{message}");
    let v2 = ATTENTION_RUN.replacen("\"version\": 1", "\"version\": 2", 1);
    let message = error_message(
        Episode::from_run_file(&v2, "flat", "")
            .err()
            .expect("refused"),
    );
    assert!(message.contains("version 2 is not supported"), "{message}");
    let terrain = Episode::from_run_file(ATTENTION_RUN, "hilly-one", "").err();
    assert!(error_message(terrain.expect("refused")).contains("terrain"));
}
