//! `vsr params --shape S --controller C`: prints a controller's parameter count for a shape.
//! Also owns the `--shape` / `--controller` pair that `vsr evolve` shares.

use vsr::controllers::ControllerKind;
use vsr::simulation::Shape;

/// A robot to control: its shape and its controller kind.
#[derive(clap::Args, Debug)]
pub struct RobotArgs {
    /// Shape: a preset (biped-4x3, comb-7x2, biped-6x4, comb-14x2, worm-WxH, box-WxH) or rows
    /// top first, e.g. 1111-1111-1001.
    #[arg(long)]
    shape: String,
    /// Controller: attention, mlp, mlp-comm, slow-attention or mlp-comm-latched (MLP-Comm
    /// exchanging messages only every 20 steps, as the original code).
    #[arg(long)]
    controller: String,
}

impl RobotArgs {
    /// The parsed shape and controller kind, or the error that says which is wrong.
    pub fn parse(&self) -> vsr::Result<(Shape, ControllerKind)> {
        Ok((Shape::parse(&self.shape)?, self.controller.parse()?))
    }
}

/// Arguments of `vsr params`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    robot: RobotArgs,
}

/// Runs the command.
pub fn run(args: Args) -> vsr::Result<()> {
    let (shape, kind) = args.robot.parse()?;
    println!("{}", kind.param_count(shape.voxel_count()));
    Ok(())
}
