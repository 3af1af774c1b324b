//! docs/cli.md's command summary (the indented block at its top) names every option that
//! `vsr <command> --help` lists, so the summary cannot fall behind the binary.

use std::process::Command;

/// The summary's lines per command: `("campaign plan", "vsr campaign plan FILE [--out-dir ...")`,
/// continuation lines joined to the command they follow.
fn summary() -> Vec<(String, String)> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/cli.md");
    let text = std::fs::read_to_string(path).expect("docs/cli.md");
    let block = text
        .lines()
        .skip_while(|l| !l.starts_with("    vsr "))
        .take_while(|l| l.starts_with("    "));
    let mut commands: Vec<(String, String)> = Vec::new();
    for line in block {
        let line = line.trim();
        if let Some(rest) = line.strip_prefix("vsr ") {
            let words: Vec<&str> = rest.split_whitespace().collect();
            let name = match words[0] {
                "campaign" => format!("campaign {}", words[1]),
                first => first.to_string(),
            };
            commands.push((name, line.to_string()));
        } else if let Some((_, text)) = commands.last_mut() {
            text.push(' ');
            text.push_str(line);
        }
    }
    commands
}

/// The long options `vsr <command> --help` lists, `--help` aside.
fn options(command: &str) -> Vec<String> {
    let out = Command::new(env!("CARGO_BIN_EXE_vsr"))
        .args(command.split_whitespace())
        .arg("--help")
        .output()
        .expect("vsr runs");
    let help = String::from_utf8_lossy(&out.stdout).into_owned();
    help.lines()
        .filter_map(|l| {
            let l = l.trim_start();
            let l = l.strip_prefix("-h, ").unwrap_or(l);
            let name = l.strip_prefix("--")?;
            let name: String = name
                .chars()
                .take_while(|c| c.is_ascii_lowercase() || *c == '-')
                .collect();
            (name != "help").then(|| format!("--{name}"))
        })
        .collect()
}

#[test]
fn the_command_summary_names_every_option_of_every_command() {
    let commands = summary();
    let names: Vec<&str> = commands.iter().map(|(n, _)| n.as_str()).collect();
    for expected in [
        "simulate",
        "evaluate",
        "validate",
        "bench",
        "campaign merge",
        "report",
    ] {
        assert!(names.contains(&expected), "{expected} in {names:?}");
    }
    for (name, text) in &commands {
        for option in options(name) {
            let named = text
                .split(|c: char| !(c.is_ascii_lowercase() || c == '-'))
                .any(|word| word == option);
            assert!(
                named,
                "docs/cli.md's summary of `vsr {name}` leaves out {option}: {text}"
            );
        }
    }
}
