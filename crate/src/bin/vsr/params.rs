//! `vsr params --shape S --controller C`: prints a controller's parameter count for a shape.

use vsr::controllers::ControllerKind;
use vsr::simulation::Shape;

/// Arguments of `vsr params`.
#[derive(clap::Args, Debug)]
pub struct Args {
    /// Shape: a preset (biped-4x3, comb-7x2, biped-6x4, comb-14x2, worm-WxH, box-WxH) or rows
    /// top first, e.g. 1111-1111-1001.
    #[arg(long)]
    shape: String,
    /// Controller: attention, mlp, mlp-comm or slow-attention.
    #[arg(long)]
    controller: String,
}

/// Runs the command.
pub fn run(args: Args) -> vsr::Result<()> {
    let shape = Shape::parse(&args.shape)?;
    let kind: ControllerKind = args.controller.parse()?;
    println!("{}", kind.param_count(shape.voxel_count()));
    Ok(())
}
