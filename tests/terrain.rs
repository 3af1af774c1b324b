//! Terrain names: exact replay of the reference polylines, the simple shapes,
//! height queries, and error messages for bad names.

use vsr::simulation::Terrain;
use vsr::Error;

/// Tolerance for golden coordinates, in m.
const TOL: f64 = 1e-9;
/// Tolerance for the 6-decimal check values quoted from the reference.
const TOL_6: f64 = 5e-7;

fn terrain(name: &str) -> Terrain {
    match Terrain::parse(name) {
        Ok(t) => t,
        Err(e) => panic!("{name} should parse: {e}"),
    }
}

fn error_message(name: &str) -> String {
    match Terrain::parse(name) {
        Err(Error::Terrain(m)) => m,
        other => panic!("{name} should be a terrain error, got {other:?}"),
    }
}

fn assert_close(got: &[f64], want: &[f64], tol: f64, what: &str) {
    assert_eq!(got.len(), want.len(), "{what}: length");
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        assert!((g - w).abs() <= tol, "{what}[{i}]: got {g}, want {w}");
    }
}

#[test]
fn hilly_1_10_0_matches_reference_check_values() {
    let t = terrain("hilly-1-10-0");
    assert_eq!(t.len(), 205);
    assert_close(
        &t.xs()[2..5],
        &[22.006333, 37.208635, 49.670071],
        TOL_6,
        "xs",
    );
    assert_close(
        &t.ys()[2..5],
        &[-0.901546, -0.137775, -1.821188],
        TOL_6,
        "ys",
    );
}

#[test]
fn hilly_1_10_1_matches_reference_check_values() {
    let t = terrain("hilly-1-10-1");
    assert_close(
        &t.xs()[2..5],
        &[23.903953, 31.175883, 38.380175],
        TOL_6,
        "xs",
    );
    assert_close(
        &t.ys()[2..5],
        &[-0.608183, -1.232723, -2.891045],
        TOL_6,
        "ys",
    );
}

#[test]
fn hilly_1_10_0_matches_reference_fixture() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/fixtures/terrain-hilly-1-10-0.json"
    );
    let text = std::fs::read_to_string(path).expect("fixture readable");
    let fixture: serde_json::Value = serde_json::from_str(&text).expect("fixture is JSON");
    let column = |key: &str| -> Vec<f64> {
        let values = fixture[key].as_array().expect("array");
        values.iter().map(|v| v.as_f64().expect("number")).collect()
    };
    let t = terrain("hilly-1-10-0");
    assert_close(t.xs(), &column("xs"), TOL, "xs");
    assert_close(t.ys(), &column("ys"), TOL, "ys");
}

#[test]
fn hilly_has_walls_and_ends_past_1990() {
    let t = terrain("hilly-2.5-7.5-3");
    let (xs, ys) = (t.xs(), t.ys());
    assert_eq!((xs[0], xs[1], ys[0], ys[1]), (0.0, 10.0, 100.0, 0.0));
    let n = t.len();
    assert!(xs[n - 2] >= 1990.0 && xs[n - 3] < 1990.0);
    assert_eq!((xs[n - 1] - xs[n - 2], ys[n - 1]), (10.0, 100.0));
    assert!(xs.windows(2).all(|w| w[1] - w[0] >= 1.0));
    assert_eq!(t.name(), "hilly-2.5-7.5-3");
}

#[test]
fn flat_is_the_spec_polyline() {
    let t = terrain("flat");
    assert_eq!(t.xs(), [0.0, 10.0, 1990.0, 2000.0]);
    assert_eq!(t.ys(), [100.0, 5.0, 5.0, 100.0]);
}

#[test]
fn uphill_30_rises_by_1980_sin_30() {
    let d = 1980.0 * 30f64.to_radians().sin();
    assert!((d - 990.0).abs() < 1e-9);
    let t = terrain("uphill-30");
    assert_eq!(t.xs(), [0.0, 10.0, 1990.0, 2000.0]);
    assert_close(t.ys(), &[100.0, 5.0, 5.0 + d, 100.0 + d], TOL, "ys");
}

#[test]
fn downhill_mirrors_uphill_heights() {
    let t = terrain("downhill-12.5");
    let d = 1980.0 * 12.5f64.to_radians().sin();
    assert_close(t.ys(), &[100.0 + d, 5.0 + d, 5.0, 100.0], TOL, "ys");
}

#[test]
fn steppy_alternates_flat_runs_and_half_metre_ramps() {
    let t = terrain("steppy-1-10-0");
    let (xs, ys) = (t.xs(), t.ys());
    let n = t.len();
    assert_eq!(n % 2, 1, "2 start vertices, pairs, 1 end vertex");
    // Same first draws as hilly-1-10-0: run to x = 22.006, then a ramp down 0.9015.
    assert_close(
        &xs[2..4],
        &[22.006332659347578, 22.506332659347578],
        TOL,
        "xs",
    );
    assert_close(&ys[2..4], &[0.0, -0.9015460884175122], TOL, "ys");
    for k in (2..n - 1).step_by(2) {
        assert_eq!(ys[k], ys[k - 1], "vertex {k} starts a flat run");
        assert!(
            (xs[k + 1] - xs[k] - 0.5).abs() < 1e-9,
            "vertex {k} ramp width"
        );
    }
    assert!(xs[n - 2] >= 1990.0 && xs[n - 4] < 1990.0);
    assert_eq!(ys[n - 1], 100.0);
}

#[test]
fn height_at_interpolates_and_clamps() {
    let t = terrain("flat");
    assert_eq!(t.height_at(5.0), 52.5);
    assert_eq!(t.height_at(500.0), 5.0);
    assert_eq!(t.height_at(-3.0), 100.0);
    assert_eq!(t.height_at(2500.0), 100.0);
    let h = terrain("hilly-1-10-0");
    let mid = 0.5 * (h.xs()[2] + h.xs()[3]);
    assert!((h.height_at(mid) - 0.5 * (h.ys()[2] + h.ys()[3])).abs() < 1e-12);
    assert_eq!(h.height_at(h.xs()[3]), h.ys()[3]);
}

#[test]
fn segment_index_finds_and_clamps() {
    let t = terrain("flat");
    assert_eq!(t.segment_index(-1.0), 0);
    assert_eq!(t.segment_index(0.0), 0);
    assert_eq!(t.segment_index(10.0), 1);
    assert_eq!(t.segment_index(1989.9), 1);
    assert_eq!(t.segment_index(1990.0), 2);
    assert_eq!(t.segment_index(2000.0), 2);
    assert_eq!(t.segment_index(1e9), 2);
}

#[test]
fn max_height_in_sees_vertices_and_interpolated_ends() {
    let t = terrain("uphill-30");
    // Ends only: the slope between x = 100 and 200.
    assert!((t.max_height_in(100.0, 200.0) - t.height_at(200.0)).abs() < 1e-12);
    // Order of the ends does not matter.
    assert_eq!(t.max_height_in(200.0, 100.0), t.max_height_in(100.0, 200.0));
    // A vertex inside: the top of the right wall.
    assert_eq!(t.max_height_in(1980.0, 2100.0), t.ys()[3]);
    let h = terrain("hilly-1-10-0");
    let (a, b) = (h.xs()[2] - 0.1, h.xs()[30] + 0.1);
    let peak = h.ys()[2..=30].iter().fold(f64::MIN, |m, &y| m.max(y));
    let want = peak.max(h.height_at(a)).max(h.height_at(b));
    assert_eq!(h.max_height_in(a, b), want);
    // A point interval is the height there.
    assert_eq!(h.max_height_in(50.0, 50.0), h.height_at(50.0));
}

#[test]
fn bad_names_list_the_accepted_forms() {
    for name in [
        "",
        "mountain",
        "hilly",
        "hilly-1-10",
        "uphill-",
        "flat-1",
        "hilly-1-10-0-0",
    ] {
        let m = error_message(name);
        assert!(
            m.contains("accepted forms: flat, hilly-H-W-SEED"),
            "{name}: {m}"
        );
    }
}

#[test]
fn bad_parameters_say_what_is_wrong() {
    let cases = [
        ("hilly-1-0-3", "width W must be > 0"),
        ("hilly-1-nan-3", "width W must be a finite number"),
        ("steppy-inf-10-3", "height H must be a finite number"),
        ("hilly--1-10-3", "non-negative"),
        ("hilly-1-10--3", "non-negative"),
        ("hilly-1-10-2.5", "SEED must be a non-negative integer"),
        ("uphill-90", "strictly between -89 and 89"),
        ("downhill--89", "strictly between -89 and 89"),
        ("uphill-x", "slope DEG must be a finite number"),
        ("hilly-1e308-10-0", "heights overflow"),
    ];
    for (name, want) in cases {
        let m = error_message(name);
        assert!(m.contains(want), "{name}: {m}");
    }
}

#[test]
fn names_are_trimmed_and_serialized() {
    let t = terrain("  flat \n");
    assert_eq!(t.name(), "flat");
    let json = serde_json::to_value(&t).expect("serializes");
    assert_eq!(json["name"], "flat");
    assert_eq!(json["ys"][1], 5.0);
}
