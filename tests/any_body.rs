//! Brains for any body trained on many bodies: the run is the same bits whatever the order
//! the evaluations are made in (threads, workers) and when continued from a checkpoint; the
//! run file replays alone (its bodies inside); a body-dependent brain, a bad body count or a
//! damaged body-set file is refused in words, by the library and by `vsr`.

use std::process::Command;

use vsr::controllers::ControllerKind;
use vsr::experiment::{BodySet, Checkpoint, Evolution, EvolutionConfig, Job, RunFile};

const SET: &str = "# three bodies\n1111-1111-1001\n111-101\n11-11\n";

/// Population 10, 50 evaluations of 2 bodies, 2-s episodes on hilly terrains.
fn tiny(kind: ControllerKind, seed: u64) -> EvolutionConfig {
    let set = BodySet::parse("t.txt", SET).unwrap();
    let mut config = EvolutionConfig::on_bodies(set, 2, kind, 50, seed).unwrap();
    config.ga.population = 10;
    config.seconds = 2.0;
    config
}

/// The run, each batch evaluated back to front (as another worker count might finish them),
/// stopped after `stop_after` generations and continued from a checkpoint through JSON.
fn run(config: EvolutionConfig, reversed: bool, stop_after: Option<usize>) -> RunFile {
    let mut evolution = Evolution::new(config.clone()).unwrap();
    let mut told = 0;
    loop {
        let jobs = evolution.next_batch();
        if jobs.is_empty() {
            break;
        }
        let mut fitness: Vec<f64> = if reversed {
            jobs.iter()
                .rev()
                .map(|j| Job::fitness(j).unwrap())
                .collect()
        } else {
            jobs.iter().map(|j| Job::fitness(j).unwrap()).collect()
        };
        if reversed {
            fitness.reverse();
        }
        evolution.tell(&fitness, 0.0).unwrap();
        told += 1;
        if Some(told) == stop_after {
            let text = evolution.checkpoint(None).unwrap().to_json().unwrap();
            let checkpoint = Checkpoint::from_json(&text).unwrap();
            evolution = Evolution::resume(config.clone(), checkpoint).unwrap();
        }
    }
    evolution.run_file(None).unwrap()
}

#[test]
fn the_same_bits_in_any_order_and_continued_from_a_checkpoint() {
    for kind in [ControllerKind::AttentionAny, ControllerKind::MlpCommAny] {
        let plain = run(tiny(kind, 3), false, None);
        assert_eq!(
            plain.to_json(),
            run(tiny(kind, 3), true, None).to_json(),
            "{kind}"
        );
        assert_eq!(
            plain.to_json(),
            run(tiny(kind, 3), false, Some(2)).to_json(),
            "{kind}"
        );
        assert_ne!(
            plain.best.genome,
            run(tiny(kind, 4), false, None).best.genome
        );
        // The run file holds its bodies and reads back whole.
        let back = RunFile::from_json(&plain.to_json()).unwrap();
        assert_eq!(back.config.bodies.unwrap().set.bodies.len(), 3);
    }
}

#[test]
fn each_evaluation_walks_distinct_bodies_drawn_by_its_own_seed() {
    let mut evolution = Evolution::new(tiny(ControllerKind::MlpAny, 1)).unwrap();
    let jobs = evolution.next_batch();
    let drawn: Vec<Vec<String>> = jobs
        .iter()
        .map(|j| {
            let json = serde_json::to_value(j).unwrap();
            let mut bodies = vec![json["shape"].as_str().unwrap().to_string()];
            for b in json["moreBodies"].as_array().unwrap() {
                bodies.push(b.as_str().unwrap().to_string());
            }
            bodies
        })
        .collect();
    assert!(drawn.iter().all(|b| b.len() == 2 && b[0] != b[1]));
    assert!(
        drawn.windows(2).any(|w| w[0] != w[1]),
        "draws differ between evaluations"
    );
}

#[test]
fn bad_settings_are_refused_in_words() {
    let set = BodySet::parse("t.txt", SET).unwrap();
    let small = |mut c: EvolutionConfig| {
        c.ga.population = 10;
        c
    };
    let tied = EvolutionConfig::on_bodies(set.clone(), 2, ControllerKind::Attention, 50, 1);
    let err = Evolution::new(small(tied.unwrap()))
        .unwrap_err()
        .to_string();
    assert!(
        err.contains("attention-any") && err.contains("body set"),
        "{err}"
    );
    let too_many = EvolutionConfig::on_bodies(set, 4, ControllerKind::AttentionAny, 50, 1);
    let err = Evolution::new(small(too_many.unwrap()))
        .unwrap_err()
        .to_string();
    assert!(err.contains("between 1 and the 3 bodies"), "{err}");
}

fn vsr(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_vsr"))
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn vsr_refuses_a_damaged_or_empty_body_file_and_a_brain_tied_to_its_body() {
    let dir = std::env::temp_dir().join(format!("vsr-any-body-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let write = |name: &str, text: &str| {
        let p = dir.join(name);
        std::fs::write(&p, text).unwrap();
        p.display().to_string()
    };
    let (empty, bad) = (
        write("empty.txt", "# nothing\n"),
        write("bad.txt", "11\n1x\n"),
    );
    let out = dir.join("run.json").display().to_string();
    let evolve = |bodies: &str, controller: &str| {
        vsr(&[
            "evolve",
            "--bodies",
            bodies,
            "--bodies-per-evaluation",
            "2",
            "--controller",
            controller,
            "--evals",
            "20",
            "--population",
            "10",
            "--seed",
            "1",
            "--seconds",
            "1",
            "--out",
            &out,
        ])
    };
    for (file, words) in [(&empty, "no bodies"), (&bad, "line 2")] {
        let o = evolve(file, "attention-any");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(!o.status.success() && err.contains(words), "{err}");
    }
    let good = write("good.txt", SET);
    let o = evolve(&good, "mlp");
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        !o.status.success() && err.contains("cannot train on a body set"),
        "{err}"
    );
    // A run, then its best on every body of a set.
    assert!(evolve(&good, "attention-any").status.success());
    let v = vsr(&[
        "validate",
        "--genome",
        &out,
        "--bodies",
        &good,
        "--seconds",
        "1",
        "--json",
    ]);
    assert!(v.status.success(), "{}", String::from_utf8_lossy(&v.stderr));
    let json: serde_json::Value = serde_json::from_slice(&v.stdout).unwrap();
    assert_eq!(json["per_body"].as_array().unwrap().len(), 3);
    assert!(json["median"].as_f64().unwrap().is_finite());
    std::fs::remove_dir_all(&dir).ok();
}
