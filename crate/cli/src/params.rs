//! `vsr params --shape S --controller C`: prints a controller's parameter count for a shape.

use crate::args::RobotArgs;

/// Arguments of `vsr params`.
#[derive(clap::Args, Debug)]
pub struct Args {
    #[command(flatten)]
    robot: RobotArgs,
}

/// Runs the command.
pub fn run(args: Args) -> vsr::Result<()> {
    let (shape, kind) = args.robot.parse()?;
    say!("{}", kind.param_count(shape.voxel_count()));
    Ok(())
}
