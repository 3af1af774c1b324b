//! Contact constraints between pieces and the (static) ground, solved by sequential
//! impulses like the reference: Coulomb friction (1.414) then a non-negative normal
//! impulse with restitution (0.1 above 1 m/s approach), warm started from the previous
//! step's impulses of the same contact key; then Baumgarte-limited position correction.

use super::body::{Pieces, Velocity};
use super::collide::Contact;
use super::constants::FRICTION;
use super::contact_law::{bounce, correction, cross, resolved, Impulses, WarmStart};

/// A contact prepared for one step.
#[derive(Debug, Clone, Copy, Default)]
struct Row {
    piece: usize,
    /// Push direction (toward the body).
    n: (f64, f64),
    /// Offset of the contact point from the piece's centre of mass.
    r: (f64, f64),
    normal_mass: f64,
    tangent_mass: f64,
    /// Target normal velocity ([`bounce`]).
    bounce: f64,
    impulses: Impulses,
}

/// The contact solver's state: this step's rows and last step's impulses by key.
#[derive(Debug, Clone)]
pub(crate) struct ContactSolver {
    /// Coulomb friction coefficient between the robot and the ground.
    pub(crate) friction: f64,
    rows: Vec<Row>,
    keys: Vec<u64>,
    warm: WarmStart,
}

impl Default for ContactSolver {
    fn default() -> Self {
        ContactSolver {
            friction: FRICTION,
            rows: Vec::new(),
            keys: Vec::new(),
            warm: WarmStart::default(),
        }
    }
}

impl ContactSolver {
    /// Prepares the rows for `contacts` and applies warm-start impulses of contacts
    /// that persist from the previous step.
    pub(crate) fn prepare(&mut self, contacts: &[Contact], pieces: &mut Pieces) {
        let last = self.keys.iter().zip(&self.rows);
        self.warm
            .remember(last.map(|(&key, row)| (key, row.impulses)));
        self.rows.clear();
        self.keys.clear();
        for c in contacts {
            let (n, r, separation) = c.evaluate(pieces);
            let p = c.piece;
            let (im, ii) = (pieces.inv_mass[p], pieces.inv_inertia[p]);
            let t = (n.1, -n.0);
            let (rn, rt) = (cross(r, n), cross(r, t));
            let (vx, vy) = pieces.point_velocity(p, r.0, r.1);
            let vn = vx * n.0 + vy * n.1;
            // A new contact applies zero impulses (as the reference does).
            let impulses = self.warm.take(c.key).unwrap_or_default();
            let (ni, ti) = (impulses.normal, impulses.tangent);
            let row = Row {
                piece: p,
                n,
                r,
                normal_mass: 1.0 / (im + ii * rn * rn),
                tangent_mass: 1.0 / (im + ii * rt * rt),
                bounce: bounce(separation, vn),
                impulses,
            };
            apply(pieces, &row, ni * n.0 + ti * t.0, ni * n.1 + ti * t.1);
            self.rows.push(row);
            self.keys.push(c.key);
        }
    }

    /// One sweep: friction, then the normal impulse, for every contact.
    pub(crate) fn solve_velocity(&mut self, pieces: &mut Pieces) {
        let friction = self.friction;
        for row in &mut self.rows {
            let t = (row.n.1, -row.n.0);
            let (vx, vy) = pieces.point_velocity(row.piece, row.r.0, row.r.1);
            let vt = vx * t.0 + vy * t.1;
            let d = row.impulses.friction(vt, row.tangent_mass, friction);
            apply(pieces, row, d * t.0, d * t.1);

            let (vx, vy) = pieces.point_velocity(row.piece, row.r.0, row.r.1);
            let vn = vx * row.n.0 + vy * row.n.1;
            let d = row.impulses.normal(vn, row.bounce, row.normal_mass);
            apply(pieces, row, d * row.n.0, d * row.n.1);
        }
    }

    /// One position sweep over `contacts`; true when none penetrates by more than
    /// three times the slop.
    pub(crate) fn solve_position(contacts: &[Contact], pieces: &mut Pieces) -> bool {
        let mut min_separation: f64 = 0.0;
        for c in contacts {
            let (n, r, separation) = c.evaluate(pieces);
            min_separation = min_separation.min(separation);
            let correction = correction(separation);
            if correction == 0.0 {
                continue;
            }
            let p = c.piece;
            let rn = cross(r, n);
            let k = pieces.inv_mass[p] + pieces.inv_inertia[p] * rn * rn;
            let impulse = -correction / k;
            pieces.push_position(p, impulse * n.0, impulse * n.1, r.0, r.1);
        }
        resolved(min_separation)
    }
}

/// Applies impulse (px, py) at the row's contact point.
#[inline]
fn apply(pieces: &mut Pieces, row: &Row, px: f64, py: f64) {
    let p = row.piece;
    let (im, ii) = (pieces.inv_mass[p], pieces.inv_inertia[p]);
    let v: &mut Velocity = &mut pieces.vel[p];
    v.vx += im * px;
    v.vy += im * py;
    v.w += ii * (row.r.0 * py - row.r.1 * px);
}
