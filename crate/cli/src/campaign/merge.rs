//! `vsr campaign merge FILE`: the run files and assessments that exist, as one CSV.

use std::path::PathBuf;

use vsr::Result;
use vsr_study::campaign::merge;

use super::target::Target;

/// Arguments of `vsr campaign merge`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    target: Target,
    /// The CSV file (default: OUT/campaign.csv).
    #[arg(long)]
    csv: Option<PathBuf>,
}

/// Runs the command.
pub fn run(args: Args) -> Result<()> {
    let (results, out) = args.target.results()?;
    let path = args.csv.unwrap_or_else(|| out.join("campaign.csv"));
    crate::atomic::write(&path, merge::csv(&results).as_bytes(), "table")?;
    let found = results.data.iter().filter(|(_, d)| d.run.is_some()).count();
    let any_body = results.any_body.iter().filter(|(_, d)| d.run.is_some());
    let found = found + any_body.count();
    say!(
        "{} runs of {} in {}; {} planned outputs missing",
        found,
        results.data.len() + results.any_body.len(),
        path.display(),
        results.missing.len()
    );
    Ok(())
}
