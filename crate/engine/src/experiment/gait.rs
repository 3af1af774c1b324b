//! The open-loop phase gait (SPEC 7), the no-learning baseline and the physics
//! checks' workhorse: u(t) = sin(2 pi f t + phi x) for the voxel in grid column x.

use crate::error::{Error, Result};

/// A sinusoidal gait whose phase advances by `phase` radians per column.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PhaseGait {
    /// Frequency f (Hz).
    pub frequency: f64,
    /// Phase shift phi per grid column (rad).
    pub phase: f64,
}

impl PhaseGait {
    /// A gait; rejects non-finite numbers.
    pub fn new(frequency: f64, phase: f64) -> Result<Self> {
        if !frequency.is_finite() || !phase.is_finite() {
            return Err(Error::Input(format!(
                "gait frequency and phase must be finite numbers, got {frequency} and {phase}"
            )));
        }
        Ok(PhaseGait { frequency, phase })
    }

    /// Parses "F,PHI" (e.g. "1,0.5").
    pub fn parse(text: &str) -> Result<Self> {
        let bad = || {
            Error::Input(format!(
                "gait '{text}' is not F,PHI (frequency in Hz and phase per column in rad, e.g. 1,0.5)"
            ))
        };
        let (f, phi) = text.split_once(',').ok_or_else(bad)?;
        let f: f64 = f.trim().parse().map_err(|_| bad())?;
        let phi: f64 = phi.trim().parse().map_err(|_| bad())?;
        PhaseGait::new(f, phi)
    }

    /// Actuation of every voxel at time t, given each voxel's grid column.
    pub(crate) fn actuate(&self, t: f64, columns: &[usize], out: &mut [f64]) {
        let w = 2.0 * std::f64::consts::PI * self.frequency * t;
        for (u, &x) in out.iter_mut().zip(columns) {
            *u = libm::sin(w + self.phase * x as f64);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_rejects() {
        assert_eq!(
            PhaseGait::parse("1, 0.5").unwrap(),
            PhaseGait::new(1.0, 0.5).unwrap()
        );
        assert!(PhaseGait::parse("1").is_err());
        assert!(PhaseGait::parse("a,b").is_err());
        assert!(PhaseGait::parse("NaN,1").is_err());
    }

    #[test]
    fn phase_advances_per_column() {
        let g = PhaseGait::new(1.0, 0.5).unwrap();
        let mut out = [0.0; 2];
        g.actuate(0.0, &[0, 1], &mut out);
        assert_eq!(out[0], 0.0);
        assert!((out[1] - libm::sin(0.5)).abs() < 1e-15);
    }
}
