//! Narrow phase between two corner squares (oriented boxes of side 1.2 m): the
//! separating-axis test picks the face of least penetration, then the incident face of
//! the other square is clipped against that reference face's side planes, as in
//! Box2D's polygon-vs-polygon collider (and dyn4j's clipping manifold solver).
//!
//! Result: at most two contact points, each a vertex (or clipped end) of the incident
//! face, with its separation from the reference face along the reference normal
//! (negative when penetrating). Only IEEE +, -, x and comparisons: no trigonometry.

use super::constants::CORNER_SIDE;

/// Half the side of a corner square (m).
const HALF: f64 = CORNER_SIDE / 2.0;
/// Square-frame outward normals of the four faces: bottom, right, top, left (the same
/// order as the ground collider's faces).
pub(crate) const FACES: [(f64, f64); 4] = [(0.0, -1.0), (1.0, 0.0), (0.0, 1.0), (-1.0, 0.0)];
/// How much deeper B's best face must be than A's before B becomes the reference
/// (m): a hysteresis so near-ties do not flip the manifold between steps (Box2D).
const REFERENCE_TOLERANCE: f64 = 0.1 * super::constants::LINEAR_SLOP;

/// A square in the world: centre and the cos / sin of its angle.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct SquarePose {
    /// Centre x (m).
    pub(crate) x: f64,
    /// Centre y (m).
    pub(crate) y: f64,
    /// cos(angle).
    pub(crate) c: f64,
    /// sin(angle).
    pub(crate) s: f64,
}

impl SquarePose {
    /// World direction of a square-frame vector.
    #[inline]
    fn rotate(&self, v: (f64, f64)) -> (f64, f64) {
        (self.c * v.0 - self.s * v.1, self.s * v.0 + self.c * v.1)
    }

    /// The square-frame components of a world vector.
    #[inline]
    fn unrotate(&self, v: (f64, f64)) -> (f64, f64) {
        (self.c * v.0 + self.s * v.1, -self.s * v.0 + self.c * v.1)
    }
}

/// One contact point of a manifold.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ClipPoint {
    /// The point on the incident square (world, m).
    pub(crate) point: (f64, f64),
    /// Its distance from the reference face along the normal (m), negative inside.
    pub(crate) separation: f64,
    /// Which end of the clipped incident face (0 or 1), for warm starting.
    pub(crate) slot: u8,
}

/// The contact between two squares.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Manifold {
    /// True when square B holds the reference face (the normal points from B to A).
    pub(crate) flipped: bool,
    /// Reference face index (into [`FACES`], in the reference square's frame).
    pub(crate) reference_face: usize,
    /// Incident face index (in the incident square's frame).
    pub(crate) incident_face: usize,
    /// Points closer than the margin (the first `count` entries are valid).
    pub(crate) points: [ClipPoint; 2],
    /// Number of valid points (1 or 2).
    pub(crate) count: usize,
}

/// The face of `a` along which `b` is farthest out, and that separation (m).
fn best_face(a: &SquarePose, b: &SquarePose) -> (usize, f64) {
    let d = a.unrotate((b.x - a.x, b.y - a.y));
    // B's half extent along either axis of A: h (|cos| + |sin|) of the relative angle.
    let (rc, rs) = (a.c * b.c + a.s * b.s, a.c * b.s - a.s * b.c);
    let reach = HALF + HALF * (rc.abs() + rs.abs());
    let (sx, sy) = (d.0.abs() - reach, d.1.abs() - reach);
    if sx >= sy {
        (if d.0 >= 0.0 { 1 } else { 3 }, sx)
    } else {
        (if d.1 >= 0.0 { 2 } else { 0 }, sy)
    }
}

/// The face of `inc` whose outward normal is most opposed to the world normal `n`.
fn incident_face(inc: &SquarePose, n: (f64, f64)) -> usize {
    let local = inc.unrotate(n);
    let mut best = 0;
    let mut lowest = f64::INFINITY;
    for (f, &(fx, fy)) in FACES.iter().enumerate() {
        let dot = fx * local.0 + fy * local.1;
        if dot < lowest {
            (best, lowest) = (f, dot);
        }
    }
    best
}

/// The two world vertices of face `f` of square `q`, counter-clockwise.
fn face_vertices(q: &SquarePose, f: usize) -> [(f64, f64); 2] {
    let (nx, ny) = FACES[f];
    // Counter-clockwise along the face: the normal turned by +90 degrees.
    let (tx, ty) = (-ny, nx);
    [-1.0, 1.0].map(|k| {
        let local = (HALF * (nx + k * tx), HALF * (ny + k * ty));
        let (wx, wy) = q.rotate(local);
        (q.x + wx, q.y + wy)
    })
}

/// Keeps the part of segment `seg` where `t . p <= limit`.
fn clip(seg: [(f64, f64); 2], t: (f64, f64), limit: f64) -> Option<[(f64, f64); 2]> {
    let d0 = t.0 * seg[0].0 + t.1 * seg[0].1 - limit;
    let d1 = t.0 * seg[1].0 + t.1 * seg[1].1 - limit;
    match (d0 <= 0.0, d1 <= 0.0) {
        (true, true) => Some(seg),
        (false, false) => None,
        _ => {
            let k = d0 / (d0 - d1);
            let cut = (
                seg[0].0 + k * (seg[1].0 - seg[0].0),
                seg[0].1 + k * (seg[1].1 - seg[0].1),
            );
            Some(if d0 <= 0.0 {
                [seg[0], cut]
            } else {
                [cut, seg[1]]
            })
        }
    }
}

/// Contact between squares `a` and `b` when they are closer than `margin` (m); the
/// normal points from the reference square to the other one.
pub(crate) fn collide(a: &SquarePose, b: &SquarePose, margin: f64) -> Option<Manifold> {
    let (face_a, sep_a) = best_face(a, b);
    if sep_a > margin {
        return None;
    }
    let (face_b, sep_b) = best_face(b, a);
    if sep_b > margin {
        return None;
    }
    let flipped = sep_b > sep_a + REFERENCE_TOLERANCE;
    let (reference, incident, face) = match flipped {
        true => (b, a, face_b),
        false => (a, b, face_a),
    };
    let n = reference.rotate(FACES[face]);
    let inc_face = incident_face(incident, n);
    let [v1, v2] = face_vertices(reference, face);
    let t = (v2.0 - v1.0, v2.1 - v1.1);
    let seg = face_vertices(incident, inc_face);
    let seg = clip(seg, (-t.0, -t.1), -(t.0 * v1.0 + t.1 * v1.1))?;
    let seg = clip(seg, t, t.0 * v2.0 + t.1 * v2.1)?;
    let offset = n.0 * v1.0 + n.1 * v1.1;
    let mut points = [ClipPoint {
        point: (0.0, 0.0),
        separation: 0.0,
        slot: 0,
    }; 2];
    let mut count = 0;
    for (slot, &p) in seg.iter().enumerate() {
        let separation = n.0 * p.0 + n.1 * p.1 - offset;
        if separation <= margin {
            points[count] = ClipPoint {
                point: p,
                separation,
                slot: slot as u8,
            };
            count += 1;
        }
    }
    (count > 0).then_some(Manifold {
        flipped,
        reference_face: face,
        incident_face: inc_face,
        points,
        count,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pose(x: f64, y: f64, angle: f64) -> SquarePose {
        SquarePose {
            x,
            y,
            c: libm::cos(angle),
            s: libm::sin(angle),
        }
    }

    #[test]
    fn apart_squares_do_not_touch() {
        assert_eq!(
            collide(&pose(0.0, 0.0, 0.0), &pose(1.3, 0.0, 0.0), 0.01),
            None
        );
        assert_eq!(
            collide(&pose(0.0, 0.0, 0.3), &pose(0.0, 1.9, 0.0), 0.01),
            None
        );
    }

    #[test]
    fn stacked_squares_touch_along_a_face_with_two_points() {
        // B sits on A, 2 cm deep, shifted right by 0.4: the overlap runs x in [-0.2, 0.6].
        let m = collide(&pose(0.0, 0.0, 0.0), &pose(0.4, 1.18, 0.0), 0.01).unwrap();
        assert!(!m.flipped);
        assert_eq!((m.reference_face, m.incident_face, m.count), (2, 0, 2));
        let mut xs: Vec<f64> = m.points.iter().map(|p| p.point.0).collect();
        xs.sort_by(f64::total_cmp);
        assert!((xs[0] + 0.2).abs() < 1e-12 && (xs[1] - 0.6).abs() < 1e-12);
        for p in &m.points {
            assert!((p.separation + 0.02).abs() < 1e-12, "{p:?}");
            assert!((p.point.1 - 0.58).abs() < 1e-12, "{p:?}");
        }
    }

    #[test]
    fn a_corner_poking_into_a_face_gives_one_point() {
        // B turned 45 degrees, its lowest vertex 5 cm into A's top face.
        let r = HALF * std::f64::consts::SQRT_2;
        let m = collide(
            &pose(0.0, 0.0, 0.0),
            &pose(0.1, 0.55 + r, std::f64::consts::FRAC_PI_4),
            0.01,
        )
        .unwrap();
        assert_eq!((m.flipped, m.reference_face), (false, 2));
        let deepest = m.points[..m.count]
            .iter()
            .map(|p| p.separation)
            .fold(f64::INFINITY, f64::min);
        assert!((deepest + 0.05).abs() < 1e-6, "deepest {deepest}");
    }

    #[test]
    fn the_deeper_face_owner_becomes_the_reference() {
        // A turned 45 degrees pokes its vertex into B's left face: B is the reference.
        let r = HALF * std::f64::consts::SQRT_2;
        let m = collide(
            &pose(0.0, 0.0, std::f64::consts::FRAC_PI_4),
            &pose(r + 0.57, 0.0, 0.0),
            0.01,
        )
        .unwrap();
        assert_eq!((m.flipped, m.reference_face, m.count), (true, 3, 1));
        assert!((m.points[0].separation + 0.03).abs() < 1e-6);
    }

    #[test]
    fn a_gap_within_the_margin_is_a_speculative_contact() {
        let m = collide(&pose(0.0, 0.0, 0.0), &pose(1.205, 0.0, 0.0), 0.01).unwrap();
        assert_eq!(m.count, 2);
        assert!(m
            .points
            .iter()
            .all(|p| (p.separation - 0.005).abs() < 1e-12));
    }
}
