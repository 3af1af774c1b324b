//! The ground as the contact solver sees it: the terrain polyline with precomputed
//! per-segment normals and per-vertex convexity. Everything below the polyline is
//! solid, so a body can never tunnel through a thin line.

/// Solid ground under a polyline (x increasing), walls included.
#[derive(Debug, Clone)]
pub struct Ground {
    xs: Vec<f64>,
    ys: Vec<f64>,
    /// Upward unit normal of segment i (from vertex i to i + 1).
    normal: Vec<(f64, f64)>,
    /// n . p_i for segment i: points p above the segment's line have n . p > offset.
    offset: Vec<f64>,
    /// Whether vertex i is a peak (the polyline turns clockwise there).
    convex: Vec<bool>,
}

impl Ground {
    /// Builds the ground from a polyline with at least two vertices and increasing x.
    pub(crate) fn new(xs: &[f64], ys: &[f64]) -> Self {
        let n = xs.len();
        let mut normal = Vec::with_capacity(n - 1);
        let mut offset = Vec::with_capacity(n - 1);
        for i in 0..n - 1 {
            let (dx, dy) = (xs[i + 1] - xs[i], ys[i + 1] - ys[i]);
            let len = (dx * dx + dy * dy).sqrt();
            let nrm = (-dy / len, dx / len);
            normal.push(nrm);
            offset.push(nrm.0 * xs[i] + nrm.1 * ys[i]);
        }
        let convex = (0..n)
            .map(|i| {
                if i == 0 || i + 1 == n {
                    return false;
                }
                let (ax, ay) = (xs[i] - xs[i - 1], ys[i] - ys[i - 1]);
                let (bx, by) = (xs[i + 1] - xs[i], ys[i + 1] - ys[i]);
                ax * by - ay * bx < 0.0
            })
            .collect();
        Ground {
            xs: xs.to_vec(),
            ys: ys.to_vec(),
            normal,
            offset,
            convex,
        }
    }

    /// Number of segments.
    pub(crate) fn segments(&self) -> usize {
        self.xs.len() - 1
    }

    /// Vertex i.
    #[inline]
    pub(crate) fn vertex(&self, i: usize) -> (f64, f64) {
        (self.xs[i], self.ys[i])
    }

    /// Whether vertex i is a peak that can poke into a body.
    #[inline]
    pub(crate) fn is_convex(&self, i: usize) -> bool {
        self.convex[i]
    }

    /// Upward normal and offset of segment i.
    #[inline]
    pub(crate) fn plane(&self, i: usize) -> ((f64, f64), f64) {
        (self.normal[i], self.offset[i])
    }

    /// Segment containing x (xs[i] <= x < xs[i + 1], clamped), found by walking from a
    /// hint, which is cheap because bodies move little between steps.
    #[inline]
    pub(crate) fn segment_near(&self, x: f64, hint: usize) -> usize {
        let last = self.segments() - 1;
        let mut i = hint.min(last);
        while i > 0 && x < self.xs[i] {
            i -= 1;
        }
        while i < last && x >= self.xs[i + 1] {
            i += 1;
        }
        i
    }

    /// Highest vertex height over segments i0..=i1 (the segments' own extremes).
    /// Compare and select rather than f64::max, which is a libm call in wasm (heights
    /// are never NaN; a zero's sign is irrelevant to the callers' comparisons).
    #[inline]
    pub(crate) fn max_height(&self, i0: usize, i1: usize) -> f64 {
        self.ys[i0..=i1 + 1]
            .iter()
            .fold(f64::NEG_INFINITY, |m, &y| if y > m { y } else { m })
    }

    /// Height of the polyline at x (clamped at the ends).
    pub fn height_at(&self, x: f64) -> f64 {
        let i = self.segment_near(x, self.segments() / 2);
        let t = ((x - self.xs[i]) / (self.xs[i + 1] - self.xs[i])).clamp(0.0, 1.0);
        self.ys[i] + t * (self.ys[i + 1] - self.ys[i])
    }
}
