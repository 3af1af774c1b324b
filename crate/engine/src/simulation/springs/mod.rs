//! The 18 soft springs of every voxel: their law, their actuation and their solver.
//!
//! # How a spring is solved
//!
//! **Law.** Each spring is a soft distance joint (SPEC 2) solved like the reference: a
//! Box2D / dyn4j soft constraint, i.e. an implicit-Euler spring-damper folded into the
//! sequential-impulse velocity solver. Its stiffness k = m_ref w^2 and damping
//! c = 2 m_ref zeta w (w = 2 pi f, f = 8 Hz, zeta = 0.3) come from the effective mass
//! m_ref of the two *single* corner squares it joins, recomputed every step from the
//! current geometry exactly as the reference does. With those k and c the soft terms
//! simplify to gamma = 1 / (dt (c + dt k)) = G / m_ref and bias = stretch dt k gamma =
//! stretch B, with G and B constants of the law ([`Springs::prepare`]). The impulse
//! acts on the merged rigid pieces, so the implicit spring is exact for the merged
//! system. Actuation only moves each spring's target length (`Springs::set_actuation`).
//!
//! **Row.** Spring j between anchors on pieces a and b, direction n_j (unit, from a's
//! anchor to b's), lever arms r_a, r_b from the pieces' centres of mass, has the
//! Jacobian J_j = (-n_j, -r_a x n_j, n_j, r_b x n_j) and the effective inverse mass
//! 1 / inv_k_j = J_j M^-1 J_j^T + gamma_j. Projecting it once with accumulated impulse
//! acc_j is lambda_j = -inv_k_j (J_j v + bias_j + gamma_j acc_j), then
//! v += M^-1 J_j^T lambda_j and acc_j += lambda_j.
//!
//! **Group.** The springs joining the same two corner squares (the 4 springs of a
//! side, or one diagonal: at most `MAX_ROWS` rows) form a group. Projecting row i
//! changes row j's relative velocity by K_ji lambda_i, K_ji = J_j M^-1 J_i^T, so one
//! Gauss-Seidel sweep over a group is, in closed form (`group`):
//!
//! ```text
//! base_j   = -inv_k_j (J_j v + bias_j + gamma_j acc_j)   (all j, from the group's v)
//! lambda_j = base_j + sum_{i<j} m_ji lambda_i,  m_ji = -inv_k_j K_ji
//! ```
//!
//! i.e. lambda = T base with T = (I - m)^-1 (unit lower triangular). J_j v depends on v
//! only through u = (vb - va, wa, wb), so with A = T diag(-inv_k) J (4 numbers per row)
//! and c_j = -inv_k_j (bias_j + gamma_j acc_j): lambda = A u + T c. Same sweep, same
//! order and impulses as one row at a time (up to rounding), but a short dependency
//! chain from the velocities to the impulses: T c depends only on earlier sweeps.
//!
//! **Batch.** Sequential impulses are latency-bound: each group reads the velocities the
//! previous one wrote. Groups that share no piece commute, so `packing` puts up to
//! `LANES` groups of equal length into a *batch* and every batch is prepared and swept
//! lane-parallel (`wide::f64x4`: SSE2 pairs natively, SIMD128 pairs in wasm), with the
//! same arithmetic per lane as one group alone: `LANES` chains in flight instead of one.
//! A batch with fewer groups fills its empty lanes with *padding*: no piece, zero
//! inverse masses and a zero `live` flag, so the lane reads zero velocities and its
//! (zero) results are dropped (`lanes`).
//!
//! **Step.** [`Springs::prepare`] computes every row's geometry, inv_k, bias and gamma
//! (`prepare`), builds each group's T and A (`group`) and applies the warm-start
//! impulses; [`Springs::solve_velocity`] is one sweep over every batch (`sweep`),
//! called once per velocity iteration.
//!
//! # Files
//! - `kind`: spring kinds, rest lengths, [`SpringDef`] (what the assembler describes);
//! - `lanes`: the lane width, one value per lane, velocities gathered per lane;
//! - `batch`: the packed data (`batch::Batches`), struct-of-arrays over the lanes;
//! - `packing`: springs into groups, groups into batches;
//! - `prepare`, `group`, `sweep`: the per-step work described above;
//! - `robots`: the same solver with one robot per lane, for robots of the same body
//!   stepped together ([`RobotLanes`]).

mod batch;
mod group;
mod kind;
mod lanes;
mod packing;
mod prepare;
mod robots;
mod sweep;

pub use kind::{SpringDef, SpringKind};
pub use lanes::LANES;
pub use robots::RobotLanes;

use super::body::{Pieces, Velocity};
use super::constants::{DT, SPRING_DAMPING_RATIO, SPRING_FREQUENCY};
use batch::Batches;
use prepare::Law;

/// Every spring of a robot.
#[derive(Debug, Clone, Default)]
pub struct Springs {
    /// Voxel whose actuation drives spring i.
    voxel: Vec<usize>,
    /// Rest lengths of spring i: [at rest, fully contracted, fully expanded].
    table: Vec<[f64; 3]>,
    batches: Batches,
}

impl Springs {
    /// Builds the spring set between `pieces`, all at their rest length.
    pub fn new(defs: &[SpringDef], pieces: &Pieces) -> Self {
        let table: Vec<[f64; 3]> = defs.iter().map(|d| d.kind.rest_table()).collect();
        let mut batches = Batches::new(defs, pieces);
        for (i, t) in table.iter().enumerate() {
            batches.set_target(i, t[0]);
        }
        Springs {
            voxel: defs.iter().map(|d| d.voxel).collect(),
            table,
            batches,
        }
    }

    /// Sets every spring's rest length from its voxel's actuation u in [-1, 1]
    /// (+1 contracts, -1 expands), moving linearly toward the range's end. NaN acts
    /// as 0.
    pub(crate) fn set_actuation(&mut self, actuation: &[f64]) {
        for (i, &v) in self.voxel.iter().enumerate() {
            let u = actuation[v];
            let u = if u.is_nan() { 0.0 } else { u.clamp(-1.0, 1.0) };
            let [rest, min, max] = self.table[i];
            let target = if u >= 0.0 {
                rest + u * (min - rest)
            } else {
                rest - u * (max - rest)
            };
            self.batches.set_target(i, target);
        }
    }

    /// Prepares every row for this step and applies the warm-start impulses.
    pub fn prepare(&mut self, pieces: &mut Pieces) {
        self.batches.prepare(pieces, law());
    }

    /// One sequential-impulse sweep over every spring.
    #[inline]
    pub fn solve_velocity(&mut self, vel: &mut [Velocity]) {
        self.batches.solve(vel);
    }

    /// Potential energy stored in the springs (J): sum of k x^2 / 2 with the stiffness
    /// and stretch of the last prepared step.
    pub(crate) fn potential_energy(&self) -> f64 {
        self.batches.potential_energy(law().omega2)
    }
}

/// The spring law's constants. With k = m_ref w^2 and c = 2 m_ref zeta w, the
/// soft-constraint terms simplify: gamma = 1 / (dt (c + dt k)) = (1 / m_ref) G and
/// bias = stretch dt k gamma = stretch B, with G and B constants of the spring law.
fn law() -> Law {
    let omega = 2.0 * std::f64::consts::PI * SPRING_FREQUENCY;
    let g = 1.0 / (DT * (2.0 * SPRING_DAMPING_RATIO * omega + DT * omega * omega));
    Law {
        g,
        b: DT * omega * omega * g,
        omega2: omega * omega,
    }
}
