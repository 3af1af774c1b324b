//! The `vsr` binary's arguments: a negative number after a flag is that flag's value, refused
//! by the value's own check (exit code 2 and a message), never an unknown argument.

mod cli_util;

fn vsr(args: &[&str]) -> (i32, String, String) {
    let out = cli_util::vsr(args);
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn scratch(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("vsr-cli-values-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir.join(name)
}

/// `--evals -5` is a value refused by its own check, not an unknown argument `-5`.
#[test]
fn a_negative_number_after_a_flag_is_its_value() {
    let out = scratch("negative.json");
    let evolve = |flag: &str, value: &str| {
        let mut options = vec![
            ("--shape", "worm-3x1"),
            ("--controller", "mlp"),
            ("--evals", "100"),
            ("--seed", "1"),
            ("--out", out.to_str().expect("utf-8")),
        ];
        options.retain(|(f, _)| *f != flag);
        options.push((flag, value));
        let args: Vec<&str> = options.iter().flat_map(|(f, v)| [*f, *v]).collect();
        vsr(&[&["evolve"][..], &args].concat())
    };
    let cases = [
        (
            "--evals",
            "-5",
            "invalid value '-5' for '--evals <EVALS>': not a whole number, 0 or more",
        ),
        (
            "--seed",
            "-1",
            "invalid value '-1' for '--seed <SEED>': not a whole number, 0 or more",
        ),
        (
            "--seconds",
            "-3",
            "episode seconds must be in (0, 3600], got -3",
        ),
        (
            "--threads",
            "-2",
            "invalid value '-2' for '--threads <THREADS>'",
        ),
    ];
    for (flag, value, message) in cases {
        let (code, _, err) = evolve(flag, value);
        assert_eq!(code, 2, "{flag} {value}: {err}");
        assert!(err.contains(message), "{flag} {value}: {err}");
        assert!(
            !err.contains("unexpected argument"),
            "{flag} {value}: {err}"
        );
    }
    assert!(!out.exists());
}
