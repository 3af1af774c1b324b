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
fn bench_json_has_one_entry_per_shape_and_the_batch() {
    let (code, out, err) = vsr(&["bench", "--json", "--repeats", "1"]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).expect("JSON");
    let batch = &v["batch"];
    assert_eq!(batch["evaluations"], 100, "{batch}");
    assert_eq!(batch["threads"], 1, "{batch}");
    for key in ["ms_per_evaluation", "evaluations_per_second"] {
        assert!(
            batch[key].as_f64().is_some_and(|x| x > 0.0),
            "{key} in {batch}"
        );
    }
    let rows = v["simulation"].as_array().expect("array");
    let shapes: Vec<&str> = rows.iter().filter_map(|r| r["shape"].as_str()).collect();
    assert_eq!(shapes, ["biped-4x3", "comb-7x2", "biped-6x4", "comb-14x2"]);
    for r in rows {
        for key in ["steps_per_second", "ms_per_evaluation", "realtime_factor"] {
            assert!(r[key].as_f64().is_some_and(|x| x > 0.0), "{key} in {r}");
        }
    }
}

fn json(args: &[&str]) -> serde_json::Value {
    let (code, out, err) = vsr(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(&out).expect("one JSON object")
}

fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("vsr-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir.join(name)
}

const BIPED_5S: [&str; 8] = [
    "simulate",
    "--shape",
    "biped-4x3",
    "--gait",
    "1,0",
    "--seconds",
    "5",
    "--json",
];

#[test]
fn ensemble_runs_shifted_starts_and_reports_mean_and_sd() {
    let args = [&BIPED_5S[..], &["--ensemble", "3", "--start-offset", "0.5"]].concat();
    let e = json(&args);
    let v: Vec<f64> = e["velocities"]
        .as_array()
        .expect("velocities")
        .iter()
        .map(|x| x.as_f64().expect("number"))
        .collect();
    assert_eq!((e["runs"].as_u64(), v.len()), (Some(3), 3));
    // Run k is the single run started k x 1e-5 m further.
    for (k, vk) in v.iter().enumerate() {
        let offset = (0.5 + k as f64 * 1e-5).to_string();
        let single = json(&[&BIPED_5S[..], &["--start-offset", &offset]].concat());
        assert_eq!(single["velocity"].as_f64(), Some(*vk), "run {k}");
        assert_eq!(e["offsets"][k].as_f64(), Some(0.5 + k as f64 * 1e-5));
        // The simulated time, as a single run says it: 301 steps of 1/60 s.
        assert_eq!(e["seconds"], single["seconds"], "run {k}");
        let seconds = single["seconds"].as_f64().expect("seconds");
        assert!((seconds - 301.0 / 60.0).abs() < 1e-12, "{seconds}");
    }
    let mean = v.iter().sum::<f64>() / 3.0;
    let sd = (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / 2.0).sqrt();
    assert!((e["mean"].as_f64().expect("mean") - mean).abs() < 1e-12);
    assert!((e["sd"].as_f64().expect("sd") - sd).abs() < 1e-12);
    assert!(sd > 0.0, "shifted starts of a chaotic gait differ: {v:?}");
}

#[test]
fn start_offset_moves_the_robot_and_zero_is_the_reference_placement() {
    let plain = json(&BIPED_5S);
    let zero = json(&[&BIPED_5S[..], &["--start-offset", "0"]].concat());
    assert_eq!(plain["velocity"], zero["velocity"]);
    let first_x = |offset: &str| {
        let file = scratch(&format!("offset{offset}.jsonl"));
        let path = file.to_str().expect("utf-8");
        json(
            &[
                &BIPED_5S[..],
                &["--start-offset", offset, "--trajectory", path],
            ]
            .concat(),
        );
        let text = std::fs::read_to_string(&file).expect("written");
        let frame: serde_json::Value =
            serde_json::from_str(text.lines().next().expect("a line")).expect("a JSON line");
        frame["centre"][0].as_f64().expect("x")
    };
    // On flat ground the shifted robot is lowered the same way: it starts 2.5 m over.
    assert!((first_x("2.5") - first_x("0") - 2.5).abs() < 1e-9);
}

#[test]
fn trajectory_writes_one_documented_frame_per_step() {
    let file = scratch("biped.jsonl");
    let path = file.to_str().expect("utf-8");
    let run = json(&[&BIPED_5S[..], &["--trajectory", path]].concat());
    let text = std::fs::read_to_string(&file).expect("written");
    let frames: Vec<serde_json::Value> = text
        .lines()
        .map(|l| serde_json::from_str(l).expect("a JSON line"))
        .collect();
    assert_eq!(Some(frames.len() as u64), run["steps"].as_u64());
    let num = |v: &serde_json::Value| v.as_f64().expect("number");
    for (k, fr) in frames.iter().enumerate() {
        assert!(
            (num(&fr["t"]) - (k + 1) as f64 / 60.0).abs() < 1e-9,
            "t of {k}"
        );
        assert_eq!(fr["centre"].as_array().map(Vec::len), Some(2));
        assert_eq!(fr["area"].as_array().map(Vec::len), Some(10));
        assert_eq!(fr["actuation"].as_array().map(Vec::len), Some(10));
        let squares = fr["squares"].as_array().expect("squares");
        assert_eq!(squares.len(), 40);
        assert!(squares
            .iter()
            .all(|s| s.as_array().map(Vec::len) == Some(3)));
    }
    // The distance is the centre's x from the first frame to the last, exactly.
    let (first, last) = (&frames[0], &frames[frames.len() - 1]);
    let moved = num(&last["centre"][0]) - num(&first["centre"][0]);
    assert_eq!(Some(moved), run["distance"].as_f64());
    // Voxel 0's squares in the order SW, SE, NE, NW around its centre.
    let sq = |i: usize, c: usize| num(&first["squares"][i][c]);
    assert!(sq(0, 0) < sq(1, 0) && sq(1, 1) < sq(2, 1) && sq(2, 0) > sq(3, 0));
    assert!(
        (sq(3, 1) - sq(0, 1) - 1.8).abs() < 1e-6,
        "NW above SW by 1.8 m"
    );
}

#[test]
fn evaluate_writes_the_trajectory_of_the_episode_it_reports() {
    let run = format!(
        "{}/pretrained/biped-4x3-mlp.json",
        env!("CARGO_MANIFEST_DIR")
    );
    let base = [
        "evaluate",
        "--genome",
        &run,
        "--terrain",
        "flat",
        "--seconds",
        "3",
    ];
    let file = scratch("evaluate.jsonl");
    let path = file.to_str().expect("utf-8");
    let plain = json(&base);
    let recorded = json(&[&base[..], &["--trajectory", path]].concat());
    assert_eq!(plain, recorded, "recording changes nothing");
    let lines = std::fs::read_to_string(&file)
        .expect("written")
        .lines()
        .count();
    assert_eq!(Some(lines as u64), plain["steps"].as_u64());
}

#[test]
fn bad_ensembles_offsets_and_trajectory_files_exit_2() {
    let cases: [(&[&str], &str); 6] = [
        (&["--ensemble", "0"], "K >= 1"),
        (&["--ensemble", "-3"], "K >= 1"),
        (&["--start-offset", "-5"], "between the walls"),
        (&["--start-offset", "inf"], "finite"),
        (
            &["--trajectory", "/nonexistent-dir/run.jsonl"],
            "--trajectory",
        ),
        (&["--ensemble", "2", "--trajectory", "x.jsonl"], "one run"),
    ];
    for (extra, word) in cases {
        let (code, _, err) = vsr(&[&BIPED_5S[..], extra].concat());
        assert_eq!(code, 2, "{extra:?} exit code");
        assert!(
            err.contains(word),
            "{extra:?}: {err:?} should mention {word}"
        );
    }
}
