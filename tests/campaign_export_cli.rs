//! `vsr campaign export` end to end on campaigns/smoke.toml in a scratch directory: it
//! chooses each category's module by the paper set, replaces what is no longer chosen,
//! never removes a file outside the folder, and refuses to export over a malformed manifest.

use std::fs;

mod cli_util;
use cli_util::{files_in, smoke, text, vsr};

#[test]
fn export_chooses_by_the_paper_set_and_replaces_what_is_no_longer_chosen() {
    let (dir, file) = smoke("export");
    let pre = dir.join("pretrained");
    let to = pre.to_str().unwrap();
    // Before any run: every category is "not yet", nothing is written but an empty manifest.
    let empty = vsr(&["campaign", "export", &file, "--to", to]);
    assert!(empty.status.success(), "{}", text(&empty));
    assert!(
        text(&empty).contains("worm-3x1-mlp.json: not yet"),
        "{}",
        text(&empty)
    );
    // A module of an older (v1) manifest, to be replaced; a name outside the folder, never
    // to be removed.
    fs::write(pre.join("old.json"), "{}").unwrap();
    fs::write(dir.join("outside.json"), "{}").unwrap();
    fs::write(
        pre.join("manifest.json"),
        r#"{"modules": [{"file": "old.json"}, {"file": "../outside.json"}]}"#,
    )
    .unwrap();
    assert!(vsr(&["campaign", "run", &file]).status.success());
    let export = vsr(&["campaign", "export", &file, "--to", to]);
    assert!(export.status.success(), "{}", text(&export));
    assert!(!pre.join("old.json").exists(), "{}", text(&export));
    assert!(dir.join("outside.json").exists(), "{}", text(&export));
    assert!(
        text(&export).contains("is not a manifest of this format"),
        "an unreadable previous manifest is reported: {}",
        text(&export)
    );

    let manifest: serde_json::Value =
        serde_json::from_slice(&fs::read(pre.join("manifest.json")).unwrap()).unwrap();
    assert_eq!(manifest["version"], 2);
    let modules = manifest["modules"].as_array().unwrap();
    let files: Vec<&str> = modules
        .iter()
        .map(|m| m["file"].as_str().unwrap())
        .collect();
    // Default controllers: those the page runs (slow attention is not exported).
    assert_eq!(
        files,
        [
            "worm-3x1-attention.json",
            "worm-3x1-mlp.json",
            "worm-4x1-attention.json",
            "worm-3x1-attention-to-worm-4x1.json"
        ]
    );
    let out = dir.join("smoke-out");
    let paper_median = |stem: &str| {
        let path = out.join(format!("validation/{stem}.paper.json"));
        let v: serde_json::Value = serde_json::from_slice(&fs::read(path).unwrap()).unwrap();
        v["median"].as_f64().unwrap()
    };
    for m in modules {
        assert_eq!(m["chosen_from"], 3, "{m}");
        // The chosen seed has the highest paper median of its category's three runs.
        let stem = |seed: u64| match m["file"].as_str().unwrap() {
            "worm-3x1-attention.json" => format!("worm-3x1-attention-8-s{seed}"),
            "worm-3x1-mlp.json" => format!("worm-3x1-mlp-8-s{seed}"),
            "worm-4x1-attention.json" => format!("worm-4x1-attention-12-s{seed}"),
            _ => format!("worm-3x1-attention-8-to-worm-4x1-4-s{seed}"),
        };
        let chosen = m["seed"].as_u64().unwrap();
        for seed in 1..=3 {
            assert!(
                paper_median(&stem(seed)) <= paper_median(&stem(chosen)),
                "{m}"
            );
        }
        assert_eq!(
            m["validation"]["paper"]["median"].as_f64(),
            Some(paper_median(&stem(chosen)))
        );
        assert!(m["command"].as_str().unwrap().starts_with("vsr "), "{m}");
        assert!(
            m["code_version"].as_str().unwrap().starts_with("vsr "),
            "{m}"
        );
        // The module file is the run file, byte for byte.
        let run = out.join(format!("runs/{}.json", stem(chosen)));
        assert_eq!(
            fs::read(pre.join(m["file"].as_str().unwrap())).unwrap(),
            fs::read(run).unwrap()
        );
    }
    // Exporting a campaign that has not started (an empty output folder) loses nothing.
    let before = fs::read(pre.join("manifest.json")).unwrap();
    let fresh = dir.join("fresh").to_str().unwrap().to_string();
    let again = vsr(&["campaign", "export", &file, "--out-dir", &fresh, "--to", to]);
    assert!(
        text(&again).contains("previous export kept"),
        "{}",
        text(&again)
    );
    assert_eq!(fs::read(pre.join("manifest.json")).unwrap(), before);
    assert_eq!(files_in(&pre).len(), 4 + 2, "modules, manifest, README");
    // Exporting one family leaves the others' modules alone.
    let mlp = vsr(&[
        "campaign",
        "export",
        &file,
        "--to",
        to,
        "--controllers",
        "mlp",
    ]);
    assert!(mlp.status.success(), "{}", text(&mlp));
    assert!(!text(&mlp).contains("removed"), "{}", text(&mlp));
    let after: serde_json::Value =
        serde_json::from_slice(&fs::read(pre.join("manifest.json")).unwrap()).unwrap();
    assert_eq!(after["modules"].as_array().unwrap().len(), 4);
    assert_eq!(files_in(&pre).len(), 4 + 2);
    let readme = fs::read_to_string(pre.join("README.md")).unwrap();
    assert!(readme.contains(
        "| worm-3x1-attention-to-worm-4x1.json | worm-4x1 | attention fine-tuned from worm-3x1 |"
    ));
    let _ = fs::remove_dir_all(dir);
}

#[test]
fn a_malformed_manifest_is_an_error_that_names_it_and_loses_nothing() {
    let (dir, file) = smoke("export-malformed");
    let pre = dir.join("pretrained");
    fs::create_dir_all(&pre).unwrap();
    for bad in [
        "{\"modules\": [{\"file\": \"a.json\"",
        "{\"format\": 2}",
        "{\"modules\": [{}]}",
    ] {
        fs::write(pre.join("manifest.json"), bad).unwrap();
        fs::write(pre.join("a.json"), "{}").unwrap();
        let export = vsr(&["campaign", "export", &file, "--to", pre.to_str().unwrap()]);
        assert_eq!(export.status.code(), Some(2), "{bad}: {}", text(&export));
        let said = text(&export);
        assert!(said.contains("manifest.json"), "names the file: {said}");
        assert_eq!(fs::read_to_string(pre.join("manifest.json")).unwrap(), bad);
        assert!(pre.join("a.json").exists(), "{bad}: nothing removed");
    }
    let _ = fs::remove_dir_all(dir);
}
