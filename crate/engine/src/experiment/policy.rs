//! What drives a robot's voxels in an [`Episode`](super::Episode): an open-loop gait, a
//! controller fed by the voxels' sensors, or a caller outside the engine (e.g. Python) that
//! reads the sensors at every control point and sets the actuation itself.

use super::gait::PhaseGait;
use crate::controllers::Controller;

/// What drives the voxels.
pub enum Policy {
    /// An open-loop phase gait.
    Gait(PhaseGait),
    /// A controller fed by the voxels' sensors.
    Brain(Box<dyn Controller>),
    /// The caller: the sensors are read where a controller would be asked (every
    /// `ACTUATION_HOLD_STEPS` steps, from the first), see [`Episode::observation`](super::Episode::observation),
    /// and the caller sets the actuation with [`Episode::set_actuation`](super::Episode::set_actuation).
    External,
}

impl std::fmt::Debug for Policy {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Policy::Gait(g) => write!(f, "Gait({g:?})"),
            Policy::Brain(c) => write!(f, "Brain({} params)", c.param_count()),
            Policy::External => write!(f, "External"),
        }
    }
}
