//! A body found by a body search is a module: `vsr finetune --from` and `vsr codesign --from`
//! start from its best body with its brain (or, for `vsr finetune`, from any archive entry:
//! `--entry I`), whose attention block they keep; an entry that is not there, or an entry of
//! a plain run file, is refused in words.

mod cli_util;

use cli_util::{text, vsr};
use std::path::Path;
use vsr::controllers::ATTENTION_PARAMS;
use vsr::experiment::{best_in_file, CodesignRun, RunFile};

fn pretrained(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("pretrained")
        .join(name)
}

/// The first `ATTENTION_PARAMS` genes of the body `entry` of `file` (its best for None).
fn block(file: &Path, entry: Option<usize>) -> Vec<f32> {
    let best = best_in_file(&std::fs::read_to_string(file).unwrap(), entry).unwrap();
    best.genome[..ATTENTION_PARAMS].to_vec()
}

/// A short run of `command` from `from`, written to `out`, with `extra` arguments.
fn short(command: &[&str], from: &Path, out: &Path) -> std::process::Output {
    let (from, out) = (from.to_str().unwrap(), out.to_str().unwrap());
    let small = ["--evals", "20", "--seconds", "2", "--seed", "1"];
    vsr(&[command, &["--from", from, "--out", out], &small[..]].concat())
}

#[test]
fn a_found_body_is_a_module_for_finetune_and_codesign() {
    let dir = std::env::temp_dir().join(format!("vsr-found-body-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let body = pretrained("bodies/rq3-frozen.json");
    let kept = block(&body, None);
    let out = dir.join("finetuned.json");
    let o = short(
        &["finetune", "--shape", "biped-4x3", "--population", "10"],
        &body,
        &out,
    );
    assert!(o.status.success(), "{}", text(&o));
    let run = RunFile::from_json(&std::fs::read_to_string(&out).unwrap()).unwrap();
    // fine-tuning never touches the attention block (SPEC 10)
    assert_eq!(run.best.genome[..ATTENTION_PARAMS], kept[..]);
    let out = dir.join("bodies.json");
    let o = short(
        &["codesign", "--brain", "frozen", "--batch", "10"],
        &body,
        &out,
    );
    assert!(o.status.success(), "{}", text(&o));
    let run = CodesignRun::from_json(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert!(run
        .archive
        .iter()
        .all(|e| e.genome[..ATTENTION_PARAMS] == kept[..]));
    std::fs::remove_dir_all(&dir).ok();
}

/// `vsr finetune --entry I` takes the attention block of entry I (in a search whose attention
/// evolved, every entry's differs), and says so in the run file's `config.source`.
#[test]
fn finetune_takes_any_entry_of_a_body_search() {
    let dir = std::env::temp_dir().join(format!("vsr-found-entry-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // a small search whose attention evolves with each body
    let bodies = dir.join("bodies.json");
    let module = pretrained("biped-4x3-attention.json");
    let o = short(
        &["codesign", "--brain", "finetune", "--batch", "10"],
        &module,
        &bodies,
    );
    assert!(o.status.success(), "{}", text(&o));
    let (best, second) = (block(&bodies, None), block(&bodies, Some(1)));
    assert_ne!(
        best, second,
        "the test needs two entries whose attention differs"
    );
    let out = dir.join("entry1.json");
    let finetune = [
        "finetune",
        "--shape",
        "comb-7x2",
        "--population",
        "10",
        "--entry",
    ];
    let o = short(&[&finetune[..], &["1"]].concat(), &bodies, &out);
    assert!(o.status.success(), "{}", text(&o));
    let run = RunFile::from_json(&std::fs::read_to_string(&out).unwrap()).unwrap();
    assert_eq!(run.best.genome[..ATTENTION_PARAMS], second[..]);
    let entry = best_in_file(&std::fs::read_to_string(&bodies).unwrap(), Some(1)).unwrap();
    let file: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&out).unwrap()).unwrap();
    let source = &file["config"]["source"];
    assert_eq!(source["shape"], serde_json::json!(entry.shape.to_rows()));
    let genome: Vec<f32> = serde_json::from_value(source["genome"].clone()).unwrap();
    assert_eq!(genome, entry.genome);
    // an entry that is not there, and an entry of a plain run file: refused in words
    let o = short(&[&finetune[..], &["999"]].concat(), &bodies, &out);
    assert!(
        text(&o).contains("entry 999 does not exist"),
        "{}",
        text(&o)
    );
    let plain = pretrained("biped-4x3-attention.json");
    let o = short(&[&finetune[..], &["2"]].concat(), &plain, &out);
    assert!(
        text(&o).contains("entries belong to co-design run files"),
        "{}",
        text(&o)
    );
    std::fs::remove_dir_all(&dir).ok();
}
