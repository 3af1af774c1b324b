//! Rigid pieces and the corner squares they are made of.
//!
//! A voxel's mass sits in four 1.2 m corner squares. Squares that are welded to their
//! neighbours' squares (SPEC 4) move as one rigid piece, so each piece is the union of
//! one to four squares meeting at a grid vertex. Pieces are stored as struct-of-arrays:
//! position of the centre of mass, angle, velocity `[vx, vy, w]` and inverse mass and
//! inertia. Squares keep their centre as an offset from their piece's centre of mass in
//! the piece frame (every piece starts at angle 0, so that frame is the world frame at
//! build time). Square index = 4 * voxel + corner, corners in order SW, SE, NE, NW.

/// Corner of a voxel, in the order used by every per-voxel array.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Corner {
    /// South-west (bottom left).
    Sw = 0,
    /// South-east (bottom right).
    Se = 1,
    /// North-east (top right).
    Ne = 2,
    /// North-west (top left).
    Nw = 3,
}

impl Corner {
    /// All corners in index order.
    pub(crate) const ALL: [Corner; 4] = [Corner::Sw, Corner::Se, Corner::Ne, Corner::Nw];

    /// Unit direction (+-1, +-1) from the voxel centre toward this corner.
    pub(crate) fn sign(self) -> (f64, f64) {
        match self {
            Corner::Sw => (-1.0, -1.0),
            Corner::Se => (1.0, -1.0),
            Corner::Ne => (1.0, 1.0),
            Corner::Nw => (-1.0, 1.0),
        }
    }
}

/// Velocity of a rigid piece: linear (vx, vy) and angular w.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Velocity {
    /// Linear velocity along x (m/s).
    pub vx: f64,
    /// Linear velocity along y (m/s).
    pub(crate) vy: f64,
    /// Angular velocity (rad/s, counter-clockwise).
    pub(crate) w: f64,
}

/// All rigid pieces of a robot, struct-of-arrays.
#[derive(Debug, Clone, Default)]
pub struct Pieces {
    /// Centre of mass x (m).
    pub x: Vec<f64>,
    /// Centre of mass y (m).
    pub y: Vec<f64>,
    /// Angle (rad).
    pub angle: Vec<f64>,
    /// Cached cos(angle).
    pub(crate) cos: Vec<f64>,
    /// Cached sin(angle).
    pub(crate) sin: Vec<f64>,
    /// Velocities.
    pub vel: Vec<Velocity>,
    /// 1 / mass (1/kg).
    pub inv_mass: Vec<f64>,
    /// 1 / moment of inertia about the centre of mass (1/(kg m^2)).
    pub(crate) inv_inertia: Vec<f64>,
}

impl Pieces {
    /// Number of pieces.
    pub fn len(&self) -> usize {
        self.x.len()
    }

    /// True if there is no piece.
    pub fn is_empty(&self) -> bool {
        self.x.is_empty()
    }

    /// Adds a piece at rest at angle 0.
    pub fn push(&mut self, x: f64, y: f64, mass: f64, inertia: f64) {
        self.x.push(x);
        self.y.push(y);
        self.angle.push(0.0);
        self.cos.push(1.0);
        self.sin.push(0.0);
        self.vel.push(Velocity::default());
        self.inv_mass.push(1.0 / mass);
        self.inv_inertia.push(1.0 / inertia);
    }

    /// Rotates a piece-frame offset into the world frame.
    #[inline]
    pub(crate) fn rotate(&self, p: usize, lx: f64, ly: f64) -> (f64, f64) {
        let (c, s) = (self.cos[p], self.sin[p]);
        (c * lx - s * ly, s * lx + c * ly)
    }

    /// World position of a piece-frame offset.
    #[inline]
    pub(crate) fn to_world(&self, p: usize, lx: f64, ly: f64) -> (f64, f64) {
        let (rx, ry) = self.rotate(p, lx, ly);
        (self.x[p] + rx, self.y[p] + ry)
    }

    /// Velocity of the material point at world offset (rx, ry) from the centre of mass.
    #[inline]
    pub(crate) fn point_velocity(&self, p: usize, rx: f64, ry: f64) -> (f64, f64) {
        let v = self.vel[p];
        (v.vx - v.w * ry, v.vy + v.w * rx)
    }

    /// Sets a piece's angle and refreshes its cached cos and sin.
    #[inline]
    pub(crate) fn set_angle(&mut self, p: usize, angle: f64) {
        self.angle[p] = angle;
        self.cos[p] = libm::cos(angle);
        self.sin[p] = libm::sin(angle);
    }

    /// Total kinetic energy (J).
    pub fn kinetic_energy(&self) -> f64 {
        (0..self.len())
            .map(|p| {
                let v = self.vel[p];
                0.5 * (v.vx * v.vx + v.vy * v.vy) / self.inv_mass[p]
                    + 0.5 * v.w * v.w / self.inv_inertia[p]
            })
            .sum()
    }
}

/// The corner squares: which piece each belongs to and where it sits in that piece.
#[derive(Debug, Clone, Default)]
pub(crate) struct Squares {
    /// Piece of each square.
    pub(crate) piece: Vec<usize>,
    /// Square centre offset from the piece's centre of mass, piece frame, x (m).
    pub(crate) lx: Vec<f64>,
    /// Square centre offset from the piece's centre of mass, piece frame, y (m).
    pub(crate) ly: Vec<f64>,
}

impl Squares {
    /// Number of squares (4 per voxel).
    pub(crate) fn len(&self) -> usize {
        self.piece.len()
    }

    /// World position of square `s`'s centre plus a square-frame offset.
    #[inline]
    pub(crate) fn point(&self, pieces: &Pieces, s: usize, ox: f64, oy: f64) -> (f64, f64) {
        pieces.to_world(self.piece[s], self.lx[s] + ox, self.ly[s] + oy)
    }
}

impl Pieces {
    /// Moves piece `p` as if hit by position impulse (px, py) at world offset (rx, ry)
    /// from its centre of mass (non-linear Gauss-Seidel position correction).
    #[inline]
    pub(crate) fn push_position(&mut self, p: usize, px: f64, py: f64, rx: f64, ry: f64) {
        let im = self.inv_mass[p];
        self.x[p] += im * px;
        self.y[p] += im * py;
        let dw = self.inv_inertia[p] * (rx * py - ry * px);
        if dw != 0.0 {
            let angle = self.angle[p] + dw;
            self.set_angle(p, angle);
        }
    }
}
