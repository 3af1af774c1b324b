//! `vsr report FILE`: the campaign's statistics (`report.md`: medians, Mann-Whitney U tests,
//! effect sizes, what is missing), its figures (SVG) and its data files (the
//! non-inferiority test's `noninferiority.json`, for the page) in one folder, from whatever runs
//! exist so far (see `vsr_study::report`).

use std::fs;
use std::path::PathBuf;

use vsr::{Error, Result};
use vsr_study::report::{noninferiority::summary as noninferiority_summary, report};

use super::target::Target;

/// Arguments of `vsr report`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    target: Target,
    /// Folder of report.md and the figures (default: OUT/report).
    #[arg(long)]
    dir: Option<PathBuf>,
}

/// Runs the command.
pub fn run(args: Args) -> Result<()> {
    let (results, out) = args.target.results()?;
    let dir = args.dir.unwrap_or_else(|| out.join("report"));
    fs::create_dir_all(&dir)
        .map_err(|e| Error::Io(format!("cannot create {}: {e}", dir.display())))?;
    let built = report(&results);
    for file in &built.withdrawn {
        let path = dir.join(file);
        if path.exists() {
            fs::remove_file(&path)
                .map_err(|e| Error::Io(format!("cannot remove {}: {e}", path.display())))?;
        }
    }
    for figure in &built.figures {
        let svg = super::svg::draw(figure)?;
        crate::atomic::write(&dir.join(&figure.file), svg.as_bytes(), "figure")?;
    }
    if let Some(summary) = &built.noninferiority {
        let path = dir.join(noninferiority_summary::FILE);
        crate::atomic::write(&path, summary.json().as_bytes(), "report data")?;
    }
    let path = dir.join("report.md");
    crate::atomic::write(&path, built.markdown.as_bytes(), "report")?;
    say!(
        "wrote {} and {} figures; {} planned outputs missing",
        path.display(),
        built.figures.len(),
        results.missing.len()
    );
    if let Some(summary) = &built.noninferiority {
        say!("{}", summary.line());
    }
    Ok(())
}
