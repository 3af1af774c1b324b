//! Helpers shared by the physics test files (each test file includes this module).

use vsr::simulation::constants::GRAVITY;
use vsr::simulation::World;

/// Kinetic + gravitational potential + spring energy of the whole world.
pub fn mechanical_energy(w: &World) -> f64 {
    let p = w.pieces();
    let potential: f64 = (0..p.len())
        .map(|i| -GRAVITY * p.y[i] / p.inv_mass[i])
        .sum();
    p.kinetic_energy() + potential + w.spring_energy()
}
