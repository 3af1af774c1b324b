//! `vsr terrain T [--json]`: prints a terrain's polyline, walls included.

use vsr::simulation::Terrain;

/// Arguments of `vsr terrain`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Terrain name: flat, hilly-H-W-SEED, steppy-H-W-SEED, uphill-DEG, downhill-DEG.
    terrain: String,
    /// Print {"xs": [...], "ys": [...]} instead of one "x y" line per vertex.
    #[arg(long)]
    json: bool,
}

/// Runs the command.
pub fn run(args: Args) -> vsr::Result<()> {
    let t = Terrain::parse(&args.terrain)?;
    if args.json {
        let body = serde_json::json!({ "xs": t.xs(), "ys": t.ys() });
        say!("{body}");
    } else {
        for (x, y) in t.xs().iter().zip(t.ys()) {
            say!("{x} {y}");
        }
    }
    Ok(())
}
