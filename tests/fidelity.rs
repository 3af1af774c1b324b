#![cfg(not(target_arch = "wasm32"))]
//! Fidelity against numbers measured on the reference simulator (fixtures copied from
//! shared/reference): placement, a voxel's area-ratio response, and the distribution
//! of gait velocities (biped-4x3, and comb-7x2 against the reference with and without its
//! continuous collision detection). The dynamics are chaotic, so trajectories are compared only
//! before the first ground contact and gaits only as distributions.

use serde_json::Value;
use vsr::experiment::{gait_ensemble, GaitEpisode, PhaseGait};
use vsr::simulation::{Shape, Terrain, World};

fn fixture(name: &str) -> Value {
    let path = format!("{}/tests/fixtures/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("fixture present");
    serde_json::from_str(&text).expect("fixture is JSON")
}

fn f(v: &Value) -> f64 {
    v.as_f64().expect("number")
}

#[test]
fn placement_matches_the_reference() {
    for p in fixture("placements.json")["placements"]
        .as_array()
        .expect("list")
    {
        let shape = Shape::parse(p["shape"].as_str().expect("name")).expect("valid");
        let terrain = Terrain::parse(p["terrain"].as_str().expect("name")).expect("valid");
        let w = World::new(shape.voxels(), terrain.xs(), terrain.ys());
        let (cx, cy) = w.centre();
        let (x0, y0, x1, y1) = w.bounding_box();
        let want = |k: &str, i: usize| f(&p[k][i]);
        for (got, exp) in [
            (cx, want("centre", 0)),
            (cy, want("centre", 1)),
            (x0, want("bbox_min", 0)),
            (y0, want("bbox_min", 1)),
            (x1, want("bbox_max", 0)),
            (y1, want("bbox_max", 1)),
        ] {
            assert!(
                (got - exp).abs() < 1e-9,
                "{} on {}: {got} vs {exp}",
                p["shape"],
                p["terrain"]
            );
        }
    }
}

#[test]
fn area_ratio_response_matches_the_reference_before_landing() {
    let r = fixture("area-ratio-biped-flat.json");
    let reference: Vec<f64> = r["area_ratio"]
        .as_array()
        .expect("list")
        .iter()
        .map(f)
        .collect();
    let gait = PhaseGait::new(1.0, 0.0).expect("finite");
    let shape = Shape::parse("biped-4x3").expect("valid");
    let mut e = GaitEpisode::from_parts(&shape, Terrain::parse("flat").expect("valid"), gait);
    // The first 30 steps: released from rest, contraction at step 21 (u 0.10 -> 0.81).
    for (k, want) in reference.iter().take(30).enumerate() {
        e.step(1).expect("stable");
        let got = e.world().area_ratio(0);
        assert!(
            (got - want).abs() < 0.002,
            "step {}: area {got}, reference {want}",
            k + 1
        );
    }
}

#[test]
fn gait_velocities_fall_in_the_reference_distributions() {
    let r = fixture("gaits-biped-flat.json");
    let conditions = r["conditions"].as_array().expect("list");
    let shape = Shape::parse("biped-4x3").expect("valid");
    let mut inside = 0;
    let mut report = Vec::new();
    for c in conditions {
        let gait = PhaseGait::new(f(&c["f"]), f(&c["phi"])).expect("finite");
        let mut e = GaitEpisode::from_parts(&shape, Terrain::parse("flat").expect("valid"), gait);
        let v = e.run(30.0).expect("stable").velocity;
        let (mean, sd) = (f(&c["mean_velocity"]), f(&c["sd_velocity"]));
        if (v - mean).abs() <= 2.0 * sd {
            inside += 1;
        }
        report.push(format!(
            "f={} phi={}: {v:.3} vs {mean:.3} +- {sd:.3}",
            c["f"], c["phi"]
        ));
    }
    assert!(
        inside * 100 >= conditions.len() * 80,
        "only {inside} of {} gaits within the reference mean +- 2 sd:\n{}",
        conditions.len(),
        report.join("\n")
    );
}

/// Spearman rank correlation (no ties expected between velocities).
fn rank_correlation(a: &[f64], b: &[f64]) -> f64 {
    let ranks = |v: &[f64]| {
        let mut idx: Vec<usize> = (0..v.len()).collect();
        idx.sort_by(|&i, &j| v[i].total_cmp(&v[j]));
        let mut r = vec![0.0; v.len()];
        for (k, &i) in idx.iter().enumerate() {
            r[i] = k as f64;
        }
        r
    };
    let (ra, rb) = (ranks(a), ranks(b));
    let n = a.len() as f64;
    let d2: f64 = ra.iter().zip(&rb).map(|(x, y)| (x - y) * (x - y)).sum();
    1.0 - 6.0 * d2 / (n * (n * n - 1.0))
}

#[test]
fn gait_ensembles_match_the_reference_distributions() {
    // SPEC 12: compare distributions, not single chaotic runs. Each gait runs from 17
    // starts shifted by k x 1e-5 m, as the reference did; its ensemble mean must fall
    // within the reference mean +- 2 sd, the gaits must rank alike, the average speed
    // must match, and the ensembles must spread (chaos) on the scale of the reference.
    let r = fixture("gaits-biped-flat.json");
    let conditions = r["conditions"].as_array().expect("list");
    let shape = Shape::parse("biped-4x3").expect("valid");
    let flat = Terrain::parse("flat").expect("valid");
    let (mut ours, mut theirs, mut sd_ratios) = (vec![], vec![], vec![]);
    let (mut inside, mut report) = (0, vec![]);
    for c in conditions {
        let gait = PhaseGait::new(f(&c["f"]), f(&c["phi"])).expect("finite");
        let e = gait_ensemble(&shape, &flat, gait, 30.0, 17, 0.0).expect("stable");
        let (mean, sd) = (f(&c["mean_velocity"]), f(&c["sd_velocity"]));
        let our_sd = e.sd.expect("17 runs");
        inside += usize::from((e.mean - mean).abs() <= 2.0 * sd);
        ours.push(e.mean);
        theirs.push(mean);
        sd_ratios.push(our_sd / sd);
        report.push(format!(
            "f={} phi={}: {:.3} +- {our_sd:.3} vs {mean:.3} +- {sd:.3}",
            c["f"], c["phi"], e.mean
        ));
    }
    let n = conditions.len() as f64;
    let rho = rank_correlation(&ours, &theirs);
    let (avg, ref_avg) = (ours.iter().sum::<f64>() / n, theirs.iter().sum::<f64>() / n);
    sd_ratios.sort_by(f64::total_cmp);
    let median_ratio = sd_ratios[sd_ratios.len() / 2];
    let summary = format!(
        "{inside}/{n} within 2 sd, rank correlation {rho:.2}, mean {avg:.3} vs {ref_avg:.3}, \
         median sd ratio {median_ratio:.2}\n{}",
        report.join("\n")
    );
    assert!(inside as f64 >= 0.9 * n, "{summary}");
    assert!(rho >= 0.6, "{summary}");
    assert!((avg - ref_avg).abs() <= 0.1, "{summary}");
    assert!((0.25..=4.0).contains(&median_ratio), "{summary}");
}

/// Mean absolute difference between two lists of ensemble means.
fn mean_abs_difference(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).abs()).sum::<f64>() / a.len() as f64
}

#[test]
fn comb_ensembles_match_the_reference_and_its_ccd_free_variant_better() {
    // The comb-7x2 under 21 phase gaits, 17 starts each, against the reference (dyn4j with
    // continuous collision detection, the paper's simulator) and, for the gaits measured
    // there, the reference with CCD switched off (an artefact we do not reproduce, SPEC).
    // Like the biped: means within 2 sd, the gaits rank alike, the average speed matches.
    // And the finding docs/RESULTS.md builds on: our comb is closer to the CCD-free variant.
    let r = fixture("gaits-comb-flat.json");
    let conditions = r["conditions"].as_array().expect("list");
    let shape = Shape::parse("comb-7x2").expect("valid");
    let flat = Terrain::parse("flat").expect("valid");
    let (mut ours, mut theirs, mut report) = (vec![], vec![], vec![]);
    let (mut ours_cf, mut ccd_free, mut ref_cf) = (vec![], vec![], vec![]);
    let mut inside = 0;
    for c in conditions {
        let gait = PhaseGait::new(f(&c["f"]), f(&c["phi"])).expect("finite");
        let e = gait_ensemble(&shape, &flat, gait, 30.0, 17, 0.0).expect("stable");
        let (mean, sd) = (f(&c["mean_velocity"]), f(&c["sd_velocity"]));
        inside += usize::from((e.mean - mean).abs() <= 2.0 * sd);
        ours.push(e.mean);
        theirs.push(mean);
        let cf = c.get("ccd_free").map(|v| f(&v["mean_velocity"]));
        if let Some(cf) = cf {
            ours_cf.push(e.mean);
            ccd_free.push(cf);
            ref_cf.push(mean);
        }
        report.push(format!(
            "f={} phi={}: {:.3} vs {mean:.3} +- {sd:.3} (CCD-free {cf:?})",
            c["f"], c["phi"], e.mean
        ));
    }
    let n = conditions.len() as f64;
    let rho = rank_correlation(&ours, &theirs);
    let (avg, ref_avg) = (ours.iter().sum::<f64>() / n, theirs.iter().sum::<f64>() / n);
    let (to_ref, to_cf) = (
        mean_abs_difference(&ours_cf, &ref_cf),
        mean_abs_difference(&ours_cf, &ccd_free),
    );
    let summary = format!(
        "{inside}/{n} within 2 sd, rank correlation {rho:.2}, mean {avg:.3} vs {ref_avg:.3}; \
         on the {} CCD-free gaits mean |ours - reference| {to_ref:.3}, |ours - CCD-free| \
         {to_cf:.3}\n{}",
        ours_cf.len(),
        report.join("\n")
    );
    assert!(inside as f64 >= 0.9 * n, "{summary}");
    assert!(rho >= 0.6, "{summary}");
    assert!((avg - ref_avg).abs() <= 0.1, "{summary}");
    assert!(ours_cf.len() >= 10, "{summary}");
    assert!(to_cf < to_ref, "{summary}");
}
