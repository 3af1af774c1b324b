//! Collision detection between the corner squares and the ground.
//!
//! Two features make a contact (the manifold a polygon-vs-polygon clipper would give
//! for a convex square on a polyline): a square vertex below the segment under it
//! (pushed out along that segment's normal), and a terrain peak inside a square
//! (pushed out through the square's nearest face). Contacts are produced in a fixed
//! order (square, then feature) with a stable key for warm starting.

use super::body::{Pieces, Squares};
use super::constants::{CONTACT_MARGIN, CORNER_SIDE};
use super::ground::Ground;

/// Half the side of a corner square (m).
const HALF: f64 = CORNER_SIDE / 2.0;
/// Half the diagonal of a corner square (m): the radius of its bounding circle.
const RADIUS: f64 = HALF * std::f64::consts::SQRT_2;
/// Square-frame offsets of the four vertices.
const VERTICES: [(f64, f64); 4] = [(-HALF, -HALF), (HALF, -HALF), (HALF, HALF), (-HALF, HALF)];
/// Square-frame outward normals of the four faces: bottom, right, top, left.
const FACES: [(f64, f64); 4] = [(0.0, -1.0), (1.0, 0.0), (0.0, 1.0), (-1.0, 0.0)];

/// Geometry of a contact, enough to recompute its separation after bodies move.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Feature {
    /// A body point (piece-frame offset from the centre of mass) under a ground plane
    /// (upward normal, offset).
    Vertex {
        /// Piece-frame offset of the vertex.
        local: (f64, f64),
        /// Ground plane normal.
        normal: (f64, f64),
        /// Ground plane offset.
        offset: f64,
    },
    /// A ground point inside a body face (piece-frame outward normal and a piece-frame
    /// point on that face).
    Peak {
        /// The terrain vertex (world).
        point: (f64, f64),
        /// Outward face normal, piece frame.
        face_normal: (f64, f64),
        /// A point on the face, piece frame offset from the centre of mass.
        face_point: (f64, f64),
    },
}

/// One contact point between a corner square and the ground.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Contact {
    /// Stable identity across steps: square and feature.
    pub key: u64,
    /// The square touching the ground.
    pub square: usize,
    /// The piece it belongs to.
    pub piece: usize,
    /// Geometry.
    pub feature: Feature,
    /// Separation when detected (m): negative when penetrating, at most the margin.
    pub separation: f64,
}

impl Contact {
    /// Push direction (unit, toward the body), offset of the contact point from the
    /// piece's centre of mass (world) and separation (negative when penetrating).
    #[inline]
    pub(crate) fn evaluate(&self, pieces: &Pieces) -> ((f64, f64), (f64, f64), f64) {
        let p = self.piece;
        match self.feature {
            Feature::Vertex {
                local,
                normal,
                offset,
            } => {
                let r = pieces.rotate(p, local.0, local.1);
                let (wx, wy) = (pieces.x[p] + r.0, pieces.y[p] + r.1);
                (normal, r, normal.0 * wx + normal.1 * wy - offset)
            }
            Feature::Peak {
                point,
                face_normal,
                face_point,
            } => {
                let f = pieces.rotate(p, face_normal.0, face_normal.1);
                let (fx, fy) = pieces.to_world(p, face_point.0, face_point.1);
                let separation = f.0 * (point.0 - fx) + f.1 * (point.1 - fy);
                let r = (point.0 - pieces.x[p], point.1 - pieces.y[p]);
                ((-f.0, -f.1), r, separation)
            }
        }
    }
}

/// Finds every contact between the squares and the ground. `hints` holds one segment
/// index per square, updated in place, so the search is a short walk.
pub(crate) fn detect(
    pieces: &Pieces,
    squares: &Squares,
    ground: &Ground,
    hints: &mut [usize],
    out: &mut Vec<Contact>,
) {
    out.clear();
    for (s, hint) in hints.iter_mut().enumerate() {
        let p = squares.piece[s];
        let (lx, ly) = (squares.lx[s], squares.ly[s]);
        let (cx, cy) = pieces.to_world(p, lx, ly);
        let i0 = ground.segment_near(cx - RADIUS, *hint);
        let i1 = ground.segment_near(cx + RADIUS, i0);
        *hint = i0;
        if cy - RADIUS - CONTACT_MARGIN > ground.max_height(i0, i1) {
            continue;
        }
        for (v, &(ox, oy)) in VERTICES.iter().enumerate() {
            let local = (lx + ox, ly + oy);
            let (wx, wy) = pieces.to_world(p, local.0, local.1);
            let i = ground.segment_near(wx, i0);
            let (normal, offset) = ground.plane(i);
            let separation = normal.0 * wx + normal.1 * wy - offset;
            if separation < CONTACT_MARGIN {
                out.push(Contact {
                    separation,
                    key: ((s as u64) << 32) | v as u64,
                    square: s,
                    piece: p,
                    feature: Feature::Vertex {
                        local,
                        normal,
                        offset,
                    },
                });
            }
        }
        for j in i0 + 1..=i1 {
            if ground.is_convex(j) {
                if let Some(c) = peak_contact(pieces, s, p, (lx, ly), (cx, cy), ground, j) {
                    out.push(c);
                }
            }
        }
    }
}

/// A contact if terrain vertex j lies strictly inside square s.
fn peak_contact(
    pieces: &Pieces,
    s: usize,
    p: usize,
    local_centre: (f64, f64),
    centre: (f64, f64),
    ground: &Ground,
    j: usize,
) -> Option<Contact> {
    let q = ground.vertex(j);
    let (c, sn) = (pieces.cos[p], pieces.sin[p]);
    let (dx, dy) = (q.0 - centre.0, q.1 - centre.1);
    let (qx, qy) = (c * dx + sn * dy, -sn * dx + c * dy);
    if qx.abs() >= HALF + CONTACT_MARGIN || qy.abs() >= HALF + CONTACT_MARGIN {
        return None;
    }
    let depths = [HALF + qy, HALF - qx, HALF - qy, HALF + qx];
    let mut face = 0;
    for f in 1..4 {
        if depths[f] < depths[face] {
            face = f;
        }
    }
    let n = FACES[face];
    Some(Contact {
        separation: -depths[face],
        key: ((s as u64) << 32) | (4 + j as u64),
        square: s,
        piece: p,
        feature: Feature::Peak {
            point: q,
            face_normal: n,
            face_point: (local_centre.0 + n.0 * HALF, local_centre.1 + n.1 * HALF),
        },
    })
}
