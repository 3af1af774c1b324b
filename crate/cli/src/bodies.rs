//! `vsr bodies --seed S --out DIR`: writes the study's body sets (training and held
//! out, with their provenance) as text files, one body per line
//! (`vsr::experiment::body_set::generate` says how they are made). The files the study uses
//! are in campaigns/bodies/, made once with `--seed 2026` and committed before any run.

use std::path::PathBuf;

use vsr::experiment::body_set::generate::study_sets;
use vsr::Result;

/// Arguments of `vsr bodies`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Seed of the generator (the study's sets: 2026).
    #[arg(long)]
    seed: u64,
    /// Folder to write the sets to (made if missing); existing files are replaced.
    #[arg(long)]
    out: PathBuf,
}

/// Runs the command.
pub fn run(args: Args) -> Result<()> {
    std::fs::create_dir_all(&args.out).map_err(|e| {
        vsr::Error::Io(format!(
            "cannot make the folder {}: {e}",
            args.out.display()
        ))
    })?;
    for (stem, text) in study_sets(args.seed).files() {
        let path = args.out.join(format!("{stem}.txt"));
        crate::atomic::write(&path, text.as_bytes(), "body set")?;
        let bodies = text.lines().filter(|l| !l.starts_with('#')).count();
        say!("{:<28} {bodies:>4} bodies", path.display());
    }
    Ok(())
}
