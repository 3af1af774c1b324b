//! Fidelity against numbers measured on the reference simulator (fixtures copied from
//! shared/reference): placement, a voxel's area-ratio response, and the distribution
//! of gait velocities (biped-4x3, and comb-7x2 against the reference with and without its
//! continuous collision detection). The dynamics are chaotic, so trajectories are compared only
//! before the first ground contact and gaits only as distributions.

use serde_json::Value;
use vsr::experiment::{GaitEpisode, PhaseGait};
use vsr::simulation::{Shape, Terrain, World};
use vsr_study::fidelity::{measure, Agreement, Fidelity, Reference};

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

/// The reference's ensembles in `name`, measured here (`vsr fidelity`), with the summary
/// printed when an assertion fails.
fn measured(name: &str) -> (Fidelity, Agreement, String) {
    let path = format!("{}/tests/fixtures/{name}", env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(&path).expect("fixture present");
    let f = measure(&Reference::parse(&text).expect("a reference file")).expect("stable");
    let a = f.agreement();
    let rows: Vec<String> = f
        .gaits
        .iter()
        .map(|g| {
            format!(
                "f={} phi={}: {:.3} +- {:.3} vs {:.3} +- {:.3} (CCD off {:?})",
                g.f,
                g.phi,
                g.ours.mean,
                g.ours.sd,
                g.reference.mean,
                g.reference.sd,
                g.ccd_free.map(|c| c.mean)
            )
        })
        .collect();
    let summary = format!("{a:?}\n{}", rows.join("\n"));
    (f, a, summary)
}

#[test]
fn gait_ensembles_match_the_reference_distributions() {
    // SPEC 12: compare distributions, not single chaotic runs. Each gait runs from 17
    // starts shifted by k x 1e-5 m, as the reference did; its ensemble mean must fall
    // within the reference mean +- 2 sd, the gaits must rank alike, the average speed
    // must match, and the ensembles must spread (chaos) on the scale of the reference.
    let (f, a, summary) = measured("gaits-biped-flat.json");
    let n = a.gaits as f64;
    let mut sd_ratios: Vec<f64> = f.gaits.iter().map(|g| g.ours.sd / g.reference.sd).collect();
    sd_ratios.sort_by(f64::total_cmp);
    let median_ratio = sd_ratios[sd_ratios.len() / 2];
    assert!(a.within_2sd as f64 >= 0.9 * n, "{summary}");
    assert!(a.rho >= 0.6, "{summary}");
    assert!((a.mean_ours - a.mean_reference).abs() <= 0.1, "{summary}");
    assert!(
        (0.25..=4.0).contains(&median_ratio),
        "{median_ratio}\n{summary}"
    );
}

#[test]
fn comb_ensembles_match_the_reference_and_its_ccd_free_variant_better() {
    // The comb-7x2 under 21 phase gaits, 17 starts each, against the reference (dyn4j with
    // continuous collision detection, the paper's simulator) and, for the gaits measured
    // there, the reference with CCD switched off (an artefact we do not reproduce, SPEC).
    // Like the biped: means within 2 sd, the gaits rank alike, the average speed matches.
    // And the finding docs/RESULTS.md builds on: our comb is closer to the CCD-free variant.
    let (_, a, summary) = measured("gaits-comb-flat.json");
    let n = a.gaits as f64;
    assert!(a.within_2sd as f64 >= 0.9 * n, "{summary}");
    assert!(a.rho >= 0.6, "{summary}");
    assert!((a.mean_ours - a.mean_reference).abs() <= 0.1, "{summary}");
    let c = a.ccd_free.expect("gaits measured with CCD off");
    assert!(c.gaits >= 10, "{summary}");
    assert!(c.to_ccd_free < c.to_reference, "{summary}");
}
