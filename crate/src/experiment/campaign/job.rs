//! One job of a campaign: a `vsr` command that writes one file, with the files it needs; its
//! command line for a shell, and the selection of a part of a plan (`--only`).

use std::path::PathBuf;

/// One job: a `vsr` command (without the program name) and the file it writes.
#[derive(Debug, Clone, PartialEq)]
pub struct Job {
    /// 1, 2 or 3; see the module doc.
    pub stage: u32,
    /// The arguments after `vsr`.
    pub args: Vec<String>,
    /// The one file the command writes.
    pub out: PathBuf,
    /// Files that must exist before it starts.
    pub needs: Vec<PathBuf>,
    /// True when the command takes `--threads` (evolution and fine-tuning).
    pub threaded: bool,
}

impl Job {
    /// The whole command line for `program`, `--threads threads` added to evolutions,
    /// arguments quoted for a POSIX shell where needed.
    pub fn command_line(&self, program: &str, threads: usize) -> String {
        let mut words = vec![quote(program)];
        let args = self.args_with_threads(threads);
        words.extend(args.iter().map(|a| quote(a)));
        words.join(" ")
    }

    /// The arguments for `threads` threads (what `command_line` prints, unquoted).
    pub fn args_with_threads(&self, threads: usize) -> Vec<String> {
        let mut args = self.args.clone();
        if self.threaded {
            args.extend(["--threads".to_string(), threads.to_string()]);
        }
        args
    }
}

/// Quotes `word` for a POSIX shell unless it is made of safe characters only.
fn quote(word: &str) -> String {
    let safe = |c: char| c.is_ascii_alphanumeric() || "-_./=:+,".contains(c);
    if !word.is_empty() && word.chars().all(safe) {
        return word.to_string();
    }
    format!("'{}'", word.replace('\'', r"'\''"))
}

/// The jobs of `jobs` (a plan, in dependency order) whose output file name contains one of
/// `patterns`, with every job they need, in the same order; all of them when `patterns` is
/// empty. `--only to-comb-7x2` selects the fine-tunings onto comb-7x2, their source runs
/// and their validations.
pub fn select(jobs: Vec<Job>, patterns: &[String]) -> Vec<Job> {
    if patterns.is_empty() {
        return jobs;
    }
    let named = |j: &Job| {
        let name = j
            .out
            .file_name()
            .map_or(String::new(), |n| n.to_string_lossy().into_owned());
        patterns.iter().any(|p| name.contains(p.as_str()))
    };
    let mut keep: Vec<bool> = jobs.iter().map(named).collect();
    // Needs come earlier in a plan: one backward pass closes the selection over them.
    for i in (0..jobs.len()).rev() {
        if keep[i] {
            for need in &jobs[i].needs {
                if let Some(k) = jobs[..i].iter().position(|j| &j.out == need) {
                    keep[k] = true;
                }
            }
        }
    }
    jobs.into_iter()
        .zip(keep)
        .filter_map(|(j, k)| k.then_some(j))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::experiment::campaign::plan::{plan, tests::CAMPAIGN};
    use crate::experiment::campaign::Campaign;
    use std::path::Path;

    #[test]
    fn a_selection_brings_the_jobs_it_needs() {
        let c = Campaign::parse(CAMPAIGN).unwrap();
        let all = plan(&c, Path::new("o"));
        assert_eq!(select(all.clone(), &[]), all);
        let only = select(all.clone(), &["to-biped-4x3-100-s2.paper".to_string()]);
        let names: Vec<String> = only
            .iter()
            .map(|j| j.out.file_name().unwrap().to_string_lossy().into_owned())
            .collect();
        assert_eq!(
            names,
            [
                "comb-7x2-attention-200-s2.json",
                "comb-7x2-attention-200-to-biped-4x3-100-s2.json",
                "comb-7x2-attention-200-to-biped-4x3-100-s2.paper.json",
            ]
        );
        assert!(select(all, &["no-such-run".to_string()]).is_empty());
    }

    #[test]
    fn words_are_quoted_for_a_shell() {
        assert_eq!(quote("it's"), r"'it'\''s'");
        assert_eq!(quote("plain-word_1.json"), "plain-word_1.json");
    }
}
