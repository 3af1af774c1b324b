//! Contact constraints between two pieces (self-collision), solved like the ground
//! contacts in `contact.rs` but with both bodies moving: Coulomb friction between
//! corner squares (sqrt(10 x 10) = 10, SPEC 3), then a non-negative normal impulse with
//! restitution 0.1 above 1 m/s approach or, for a speculative contact, the speed that
//! just closes the gap; warm started by contact key; then Baumgarte-limited position
//! correction that pushes both pieces apart.

use super::body::Pieces;
use super::constants::SELF_FRICTION;
use super::contact_law::{bounce, correction, cross, resolved, Impulses, WarmStart};
use super::self_collide::{PairContact, PairGeometry};

/// A two-piece contact prepared for one step.
#[derive(Debug, Clone, Copy, Default)]
struct Row {
    a: usize,
    b: usize,
    /// Normal, from a toward b.
    n: (f64, f64),
    /// Offsets of the contact point from a's and b's centres of mass.
    ra: (f64, f64),
    rb: (f64, f64),
    normal_mass: f64,
    tangent_mass: f64,
    /// Target relative normal velocity ([`bounce`]).
    bounce: f64,
    impulses: Impulses,
}

/// The self-contact solver's state: this step's rows and last step's impulses by key.
#[derive(Debug, Clone, Default)]
pub(crate) struct SelfContactSolver {
    rows: Vec<Row>,
    keys: Vec<u64>,
    warm: WarmStart,
}

/// Inverse effective mass of the two pieces along direction d at the contact.
#[inline]
fn inverse_mass(pieces: &Pieces, row: &Row, d: (f64, f64)) -> f64 {
    let (ca, cb) = (cross(row.ra, d), cross(row.rb, d));
    pieces.inv_mass[row.a]
        + pieces.inv_inertia[row.a] * ca * ca
        + pieces.inv_mass[row.b]
        + pieces.inv_inertia[row.b] * cb * cb
}

/// Velocity of b's contact point relative to a's.
#[inline]
fn relative_velocity(pieces: &Pieces, row: &Row) -> (f64, f64) {
    let va = pieces.point_velocity(row.a, row.ra.0, row.ra.1);
    let vb = pieces.point_velocity(row.b, row.rb.0, row.rb.1);
    (vb.0 - va.0, vb.1 - va.1)
}

/// Applies impulse (px, py) to b and its opposite to a, at the contact point.
#[inline]
fn apply(pieces: &mut Pieces, row: &Row, px: f64, py: f64) {
    for (p, r, sign) in [(row.a, row.ra, -1.0), (row.b, row.rb, 1.0)] {
        let (im, ii) = (pieces.inv_mass[p], pieces.inv_inertia[p]);
        let v = &mut pieces.vel[p];
        v.vx += sign * im * px;
        v.vy += sign * im * py;
        v.w += sign * ii * (r.0 * py - r.1 * px);
    }
}

impl SelfContactSolver {
    /// Prepares the rows for `contacts` (sorted by key) and applies the warm-start
    /// impulses of contacts that persist from the previous step.
    pub(crate) fn prepare(&mut self, contacts: &[PairContact], pieces: &mut Pieces) {
        let last = self.keys.iter().zip(&self.rows);
        self.warm
            .remember(last.map(|(&key, row)| (key, row.impulses)));
        self.rows.clear();
        self.keys.clear();
        for c in contacts {
            let PairGeometry {
                n,
                ra,
                rb,
                separation,
            } = c.evaluate(pieces);
            let mut row = Row {
                a: c.a,
                b: c.b,
                n,
                ra,
                rb,
                ..Row::default()
            };
            let t = (n.1, -n.0);
            row.normal_mass = 1.0 / inverse_mass(pieces, &row, n);
            row.tangent_mass = 1.0 / inverse_mass(pieces, &row, t);
            let (vx, vy) = relative_velocity(pieces, &row);
            let vn = vx * n.0 + vy * n.1;
            row.bounce = bounce(separation, vn);
            // Unlike the ground's, a new self-contact applies nothing.
            if let Some(impulses) = self.warm.take(c.key) {
                row.impulses = impulses;
                let (ni, ti) = (impulses.normal, impulses.tangent);
                apply(pieces, &row, ni * n.0 + ti * t.0, ni * n.1 + ti * t.1);
            }
            self.rows.push(row);
            self.keys.push(c.key);
        }
    }

    /// One sweep: friction, then the normal impulse, for every contact.
    pub(crate) fn solve_velocity(&mut self, pieces: &mut Pieces) {
        for row in &mut self.rows {
            let t = (row.n.1, -row.n.0);
            let (vx, vy) = relative_velocity(pieces, row);
            let vt = vx * t.0 + vy * t.1;
            let d = row.impulses.friction(vt, row.tangent_mass, SELF_FRICTION);
            apply(pieces, row, d * t.0, d * t.1);

            let (vx, vy) = relative_velocity(pieces, row);
            let vn = vx * row.n.0 + vy * row.n.1;
            let d = row.impulses.normal(vn, row.bounce, row.normal_mass);
            apply(pieces, row, d * row.n.0, d * row.n.1);
        }
    }

    /// One position sweep over `contacts`; true when none penetrates by more than
    /// three times the slop.
    pub(crate) fn solve_position(contacts: &[PairContact], pieces: &mut Pieces) -> bool {
        let mut min_separation: f64 = 0.0;
        for c in contacts {
            let PairGeometry {
                n,
                ra,
                rb,
                separation,
            } = c.evaluate(pieces);
            min_separation = min_separation.min(separation);
            let correction = correction(separation);
            if correction == 0.0 {
                continue;
            }
            let row = Row {
                a: c.a,
                b: c.b,
                ra,
                rb,
                ..Row::default()
            };
            let impulse = -correction / inverse_mass(pieces, &row, n);
            let (px, py) = (impulse * n.0, impulse * n.1);
            pieces.push_position(c.a, -px, -py, ra.0, ra.1);
            pieces.push_position(c.b, px, py, rb.0, rb.1);
        }
        resolved(min_separation)
    }
}
