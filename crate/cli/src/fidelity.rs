//! `vsr fidelity --reference FILE`: every gait ensemble of a reference file (measured on the
//! paper's simulator) run here with the same starts, printed beside the reference's numbers
//! with how well they agree, and written as JSON with `--out` (see `vsr_study::fidelity`).

use std::path::PathBuf;

use vsr::{Error, Result};
use vsr_study::fidelity::{measure, Fidelity, Reference};

/// Arguments of `vsr fidelity`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// A reference file of gait ensembles, e.g. tests/fixtures/gaits-comb-flat.json.
    #[arg(long)]
    reference: PathBuf,
    /// Also write the measurement (ours beside the reference, each gait) to this JSON file.
    #[arg(long)]
    out: Option<PathBuf>,
}

/// Runs the command.
pub fn run(args: Args) -> Result<()> {
    let text = std::fs::read_to_string(&args.reference)
        .map_err(|e| Error::Io(format!("cannot read {}: {e}", args.reference.display())))?;
    let reference = Reference::parse(&text).map_err(|e| e.about(args.reference.display()))?;
    if let Some(out) = &args.out {
        crate::atomic::check_writable(out)?;
    }
    let fidelity = measure(&reference)?;
    if let Some(out) = &args.out {
        crate::atomic::write_json(out, &fidelity, "fidelity file")?;
    }
    print(&fidelity);
    Ok(())
}

fn print(f: &Fidelity) {
    say!("gait (f Hz, phi)   ours mean +- sd   reference mean +- sd   CCD off");
    for g in &f.gaits {
        let cf = g
            .ccd_free
            .map_or("-".to_string(), |c| format!("{:.3}", c.mean));
        say!(
            "{} {:>4}, {:<5}  {:>6.3} +- {:.3}     {:>6.3} +- {:.3}          {cf}",
            g.shape,
            g.f,
            g.phi,
            g.ours.mean,
            g.ours.sd,
            g.reference.mean,
            g.reference.sd
        );
    }
    let a = f.agreement();
    say!(
        "{}/{} means within 2 reference sd; rank correlation {:.2}; mean {:.3} m/s here, {:.3} \
         on the reference",
        a.within_2sd,
        a.gaits,
        a.rho,
        a.mean_ours,
        a.mean_reference
    );
    if let Some(c) = a.ccd_free {
        say!(
            "on the {} gaits measured with CCD off: mean |ours - reference| {:.3} m/s, \
             |ours - CCD off| {:.3} m/s (signed-rank p = {:.2e})",
            c.gaits,
            c.to_reference,
            c.to_ccd_free,
            c.test.p
        );
    }
}
