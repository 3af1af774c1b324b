//! `vsr evolve --keep-checkpoint` and `--continue`: a longer run continues a shorter run's kept
//! checkpoint and gives the run from generation 0 bit for bit; a missing checkpoint is a note
//! and a checkpoint past the budget is refused, the file left as it is.

mod checkpoint_util;
use checkpoint_util::{comparable, evolve_with, scratch};

#[test]
fn a_longer_run_continues_a_shorter_runs_kept_checkpoint_bit_for_bit() {
    let (short, long, whole) = (
        scratch("s30.json"),
        scratch("l50.json"),
        scratch("w50.json"),
    );
    assert!(evolve_with(&short, 30, "--keep-checkpoint")
        .status
        .success());
    let kept = format!("{short}.checkpoint");
    assert!(
        std::path::Path::new(&kept).exists(),
        "the final checkpoint is kept"
    );
    let out = evolve_with(&long, 50, &format!("--continue {kept}"));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success() && stderr.contains("generation 2"),
        "{stderr}"
    );
    assert!(evolve_with(&whole, 50, "").status.success());
    assert_eq!(comparable(&long), comparable(&whole));
    let gens = |path: &str| comparable(path)["generations"].as_array().unwrap().clone();
    assert_eq!(gens(&short)[..], gens(&whole)[..2]);

    // A smaller budget that the kept state still lies on (generation 1 of the 30-evaluation
    // run ends at 30 >= 25): accepted, and the 25-evaluation run from generation 0.
    let (cut, cut_whole) = (scratch("c25.json"), scratch("w25.json"));
    assert!(evolve_with(&cut, 25, &format!("--continue {kept}"))
        .status
        .success());
    assert!(evolve_with(&cut_whole, 25, "").status.success());
    assert_eq!(comparable(&cut), comparable(&cut_whole));

    // Given again, a finished run with its kept checkpoint is left alone.
    let before = std::fs::read_to_string(&short).unwrap();
    let out = evolve_with(&short, 30, "--keep-checkpoint");
    assert!(String::from_utf8_lossy(&out.stdout).contains("nothing to do"));
    assert_eq!(std::fs::read_to_string(&short).unwrap(), before);

    // A missing --continue file: a note, and the run from generation 0.
    let fresh = scratch("f50.json");
    let out = evolve_with(
        &fresh,
        50,
        &format!("--continue {}", scratch("none.checkpoint")),
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        out.status.success() && stderr.contains("does not exist"),
        "{stderr}"
    );
    assert_eq!(comparable(&fresh), comparable(&whole));

    // A checkpoint the run never reaches (past its budget): exit 2, nothing written.
    let longer = scratch("k50.json");
    assert!(evolve_with(&longer, 50, "--keep-checkpoint")
        .status
        .success());
    let past = scratch("p30.json");
    let out = evolve_with(&past, 30, &format!("--continue {longer}.checkpoint"));
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    assert!(stderr.contains("past this run's budget"), "{stderr}");
    assert!(!std::path::Path::new(&past).exists());
    // The file given may be another run's: the advice is to leave out --continue, never to
    // delete it, and it is left as it is.
    assert!(
        stderr.contains("leave out --continue") && !stderr.contains("delete"),
        "{stderr}"
    );
    assert!(std::path::Path::new(&format!("{longer}.checkpoint")).exists());
}
