#![cfg(not(target_arch = "wasm32"))]
//! The `vsr` binary's simulator commands: JSON outputs carry the documented fields, bad
//! arguments exit with code 2 and a message that says what is wrong.

use std::process::Command;

fn vsr(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_vsr"))
        .args(args)
        .output()
        .expect("vsr runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn simulate_json_has_the_documented_fields() {
    let (code, out, err) = vsr(&[
        "simulate",
        "--shape",
        "biped-4x3",
        "--terrain",
        "flat",
        "--gait",
        "1,0.5",
        "--seconds",
        "5",
        "--json",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("one JSON object");
    for key in [
        "velocity",
        "distance",
        "steps",
        "voxels",
        "seconds",
        "wall_seconds",
    ] {
        assert!(
            v.get(key).is_some_and(|x| x.is_number()),
            "missing {key} in {out}"
        );
    }
    assert_eq!(v["steps"], 301);
    assert_eq!(v["voxels"], 10);
}

#[test]
fn terrain_json_is_the_polyline_with_walls() {
    let (code, out, _) = vsr(&["terrain", "hilly-1-10-0", "--json"]);
    assert_eq!(code, 0);
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let xs = v["xs"].as_array().expect("xs");
    assert_eq!(xs.len(), 205);
    assert_eq!(v["ys"][0], 100.0);
    assert!((xs[2].as_f64().expect("number") - 22.006333).abs() < 1e-6);
}

#[test]
fn bad_arguments_exit_2_with_a_message() {
    let cases: [(&[&str], &str); 6] = [
        (&["simulate", "--shape", "11-0x", "--gait", "1,0"], "shape"),
        (
            &["simulate", "--shape", "1001", "--gait", "1,0"],
            "separate",
        ),
        (
            &[
                "simulate",
                "--shape",
                "biped-4x3",
                "--terrain",
                "hill",
                "--gait",
                "1,0",
            ],
            "terrain",
        ),
        (
            &["simulate", "--shape", "biped-4x3", "--gait", "fast"],
            "gait",
        ),
        (
            &[
                "simulate",
                "--shape",
                "biped-4x3",
                "--gait",
                "1,0",
                "--seconds",
                "-3",
            ],
            "seconds",
        ),
        (&["terrain", "steppy-1-10"], "terrain"),
    ];
    for (args, word) in cases {
        let (code, _, err) = vsr(args);
        assert_eq!(code, 2, "{args:?} exit code");
        assert!(
            err.contains(word),
            "{args:?}: message {err:?} should mention {word}"
        );
    }
    let (code, _, err) = vsr(&["simulate", "--gait", "1,0"]);
    assert_eq!(code, 2, "missing --shape: {err}");
}

#[test]
fn bench_json_has_one_entry_per_shape() {
    let (code, out, err) = vsr(&["bench", "--json", "--repeats", "1"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let rows = v.as_array().expect("array");
    let shapes: Vec<&str> = rows.iter().filter_map(|r| r["shape"].as_str()).collect();
    assert_eq!(shapes, ["biped-4x3", "comb-7x2", "biped-6x4", "comb-14x2"]);
    for r in rows {
        for key in ["steps_per_second", "ms_per_evaluation", "realtime_factor"] {
            assert!(r[key].as_f64().is_some_and(|x| x > 0.0), "{key} in {r}");
        }
    }
}
