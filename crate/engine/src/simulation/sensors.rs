//! The four sensors of every voxel (SPEC 6), read after every step, in this order:
//! area, vx, vy, touch.
//!
//! 1. area: 0.5 + 0.5 tanh(4 (a - 1)), a the area ratio.
//! 2. vx, 3. vy: the voxel's velocity in its own frame, averaged over the last 0.5 s of
//!    steps (30 samples), each mapped to 0.5 + 0.5 tanh(v / 4).
//! 4. touch: 1 if a corner square touches the ground, averaged over the last 0.25 s
//!    (15 samples); no normalization, as in the reference.
//!
//! Then Gaussian noise with sd 0.01 from an independent seeded stream is added to
//! every reading. Readings are f32, 4 per voxel in voxel index order.

use super::constants::DT;
use super::world::World;
use crate::random::NormalStream;

/// Readings per voxel.
pub(crate) const READINGS: usize = 4;
/// Standard deviation of the sensor noise.
pub(crate) const NOISE_SD: f64 = 0.01;
/// Every reading lies in this range: the normalized value is in [0, 1], and the noise's
/// polar-method draw is at most sqrt(-2 ln s) <= 12.01 sd, s >= 2^-104 being the smallest
/// nonzero sum of two squared 53-bit uniforms (`random::NormalStream`), so at most 0.121.
pub const READING_BOUNDS: [f32; 2] = [-0.125, 1.125];
/// Samples in the velocity average (0.5 s).
const VELOCITY_WINDOW: usize = (0.5 / DT + 0.5) as usize;
/// Samples in the touch average (0.25 s).
const TOUCH_WINDOW: usize = (0.25 / DT + 0.5) as usize;

/// A moving average over the last `N` samples of several channels (ring buffer).
#[derive(Debug, Clone)]
struct Window {
    size: usize,
    samples: Vec<f64>,
    sums: Vec<f64>,
    filled: usize,
    next: usize,
    /// Whether `sums` lags behind `samples` (a push since the last [`Window::sum`]).
    stale: bool,
}

impl Window {
    fn new(size: usize, channels: usize) -> Self {
        Window {
            size,
            samples: vec![0.0; size * channels],
            sums: vec![0.0; channels],
            filled: 0,
            next: 0,
            stale: false,
        }
    }

    /// Pushes one sample per channel.
    fn push(&mut self, values: impl Iterator<Item = f64>) {
        let channels = self.sums.len();
        let row = &mut self.samples[self.next * channels..(self.next + 1) * channels];
        for (slot, v) in row.iter_mut().zip(values) {
            *slot = v;
        }
        self.next = (self.next + 1) % self.size;
        self.filled = (self.filled + 1).min(self.size);
        self.stale = true;
    }

    /// Brings the sums up to date: recomputed from the samples (slot order), so rounding
    /// never accumulates. Only when read: controllers that act every 20 steps skip the
    /// sums of the 19 steps between, with the same numbers.
    fn sum(&mut self) {
        if !self.stale {
            return;
        }
        let channels = self.sums.len();
        self.sums.iter_mut().for_each(|s| *s = 0.0);
        for chunk in self.samples.chunks_exact(channels).take(self.filled) {
            for (s, v) in self.sums.iter_mut().zip(chunk) {
                *s += v;
            }
        }
        self.stale = false;
    }

    /// The mean of a channel as of the last [`Window::sum`].
    fn mean(&self, channel: usize) -> f64 {
        debug_assert!(!self.stale, "Window::sum before Window::mean");
        if self.filled == 0 {
            0.0
        } else {
            self.sums[channel] / self.filled as f64
        }
    }
}

/// Sensor state of a whole robot: averaging windows, noise stream and readings.
#[derive(Debug, Clone)]
pub struct Sensors {
    velocity: Window,
    touch: Window,
    noise: Option<NormalStream>,
    readings: Vec<f32>,
}

impl Sensors {
    /// Sensors for `voxels` voxels; `noise_seed` None turns the noise off.
    pub fn new(voxels: usize, noise_seed: Option<u64>) -> Self {
        Sensors {
            velocity: Window::new(VELOCITY_WINDOW, 2 * voxels),
            touch: Window::new(TOUCH_WINDOW, voxels),
            noise: noise_seed.map(NormalStream::new),
            readings: vec![0.0; READINGS * voxels],
        }
    }

    /// Records the averaged channels (frame velocity, touch) of the world's current
    /// state: call once after every step.
    pub fn sense(&mut self, world: &World) {
        let n = world.voxel_count();
        self.velocity.push((0..n).flat_map(|v| {
            let (vx, vy) = world.voxel_velocity(v);
            let (c, s) = world.voxel_frame(v);
            [c * vx + s * vy, -s * vx + c * vy]
        }));
        self.touch
            .push((0..n).map(|v| if world.touching(v) { 1.0 } else { 0.0 }));
    }

    /// Computes the readings of the current state (normalized, with noise): call when
    /// a controller needs them. Returns 4 per voxel, voxel index order.
    pub fn read(&mut self, world: &World) -> &[f32] {
        self.velocity.sum();
        self.touch.sum();
        for v in 0..world.voxel_count() {
            let raw = [
                0.5 + 0.5 * libm::tanh(4.0 * (world.area_ratio(v) - 1.0)),
                0.5 + 0.5 * libm::tanh(self.velocity.mean(2 * v) / 4.0),
                0.5 + 0.5 * libm::tanh(self.velocity.mean(2 * v + 1) / 4.0),
                self.touch.mean(v),
            ];
            for (r, value) in raw.into_iter().enumerate() {
                let noise = match &mut self.noise {
                    Some(stream) => NOISE_SD * stream.draw(),
                    None => 0.0,
                };
                self.readings[READINGS * v + r] = (value + noise) as f32;
            }
        }
        &self.readings
    }

    /// The readings of the last [`Sensors::read`]: 4 per voxel (area, vx, vy, touch).
    pub(crate) fn readings(&self) -> &[f32] {
        &self.readings
    }
}
