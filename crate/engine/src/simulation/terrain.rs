//! Named terrains: parsing a name such as `hilly-1-10-3` into the ground polyline
//! the simulator collides with, and the height queries it needs.
//!
//! Layout: two parallel arrays `xs` (strictly increasing, from 0 to about 2000)
//! and `ys`, one entry per vertex, walls included (100 m high at both ends). The
//! ground is solid below the polyline. Hilly and steppy terrains replay Java's
//! `java.util.Random`, so a name means the same ground as in 2D-VSR-Sim.

use super::java_random::JavaRandom;
use crate::{Error, Result};

/// Height of the walls at both ends, in m.
const WALL_HEIGHT: f64 = 100.0;
/// Horizontal width of each wall ramp, in m.
const WALL_WIDTH: f64 = 10.0;
/// The random walk stops once its last x reaches this, in m.
const WALK_END: f64 = 1990.0;
/// Minimum horizontal spacing between random-walk vertices, in m.
const MIN_SPACING: f64 = 1.0;
/// Relative standard deviation of the spacing (sd = 0.25 W).
const SPACING_SD: f64 = 0.25;
/// Width of each steppy ramp, in m.
const STEP_RAMP: f64 = 0.5;
/// Height of the flat and sloped grounds above y = 0, in m.
const FLAT_LEVEL: f64 = 5.0;
/// Horizontal length over which `uphill` and `downhill` climb, in m.
const SLOPE_LENGTH: f64 = 1980.0;
/// Slopes must lie strictly within +-this many degrees.
const MAX_SLOPE_DEG: f64 = 89.0;

/// What every terrain error ends with.
const ACCEPTED: &str = "accepted forms: flat, hilly-H-W-SEED, steppy-H-W-SEED, uphill-DEG, \
    downhill-DEG (H height sd in m >= 0, W spacing in m > 0, SEED integer >= 0, \
    DEG in (-89, 89); e.g. hilly-1-10-0)";

/// A ground polyline with the name it was built from.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Terrain {
    name: String,
    xs: Vec<f64>,
    ys: Vec<f64>,
}

/// Parameters of a random-walk terrain (`hilly` or `steppy`).
struct Walk {
    height: f64,
    width: f64,
    seed: i64,
}

impl Terrain {
    /// Builds the terrain named `name` (surrounding whitespace ignored):
    /// `flat`, `hilly-H-W-SEED`, `steppy-H-W-SEED`, `uphill-DEG` or `downhill-DEG`.
    pub fn parse(name: &str) -> Result<Self> {
        let name = name.trim();
        let (xs, ys) = if name == "flat" {
            sloped(0.0)
        } else if let Some(rest) = name.strip_prefix("hilly-") {
            Walk::parse(name, rest)?.hilly()
        } else if let Some(rest) = name.strip_prefix("steppy-") {
            Walk::parse(name, rest)?.steppy()
        } else if let Some(rest) = name.strip_prefix("uphill-") {
            sloped(parse_slope(name, rest)?)
        } else if let Some(rest) = name.strip_prefix("downhill-") {
            let (xs, mut ys) = sloped(parse_slope(name, rest)?);
            ys.reverse();
            (xs, ys)
        } else {
            return Err(malformed(name, "unknown terrain"));
        };
        if ys.iter().any(|y| !y.is_finite()) {
            return Err(malformed(name, "heights overflow; use a smaller H"));
        }
        Ok(Self {
            name: name.to_string(),
            xs,
            ys,
        })
    }

    /// The name this terrain was parsed from (trimmed).
    pub fn name(&self) -> &str {
        &self.name
    }

    /// Vertex x coordinates in m, strictly increasing.
    pub fn xs(&self) -> &[f64] {
        &self.xs
    }

    /// Vertex heights in m, parallel to [`Terrain::xs`].
    pub fn ys(&self) -> &[f64] {
        &self.ys
    }

    /// Number of vertices (at least 4).
    pub fn len(&self) -> usize {
        self.xs.len()
    }

    /// Always false: every terrain has vertices.
    pub fn is_empty(&self) -> bool {
        self.xs.is_empty()
    }

    /// Index `i` of the segment `xs[i]..xs[i + 1]` holding `x`
    /// (`xs[i] <= x < xs[i + 1]`), clamped to the first or last segment outside.
    pub fn segment_index(&self, x: f64) -> usize {
        let at_or_left = self.xs.partition_point(|&v| v <= x);
        at_or_left.saturating_sub(1).min(self.xs.len() - 2)
    }

    /// Ground height at `x` by linear interpolation; the end heights outside.
    pub fn height_at(&self, x: f64) -> f64 {
        let last = self.xs.len() - 1;
        if x <= self.xs[0] {
            return self.ys[0];
        }
        if x >= self.xs[last] {
            return self.ys[last];
        }
        let i = self.segment_index(x);
        let t = (x - self.xs[i]) / (self.xs[i + 1] - self.xs[i]);
        self.ys[i] + t * (self.ys[i + 1] - self.ys[i])
    }

    /// Highest ground point over the closed interval between `x0` and `x1`
    /// (either order): the interpolated ends and every vertex in between.
    pub fn max_height_in(&self, x0: f64, x1: f64) -> f64 {
        let (lo, hi) = if x0 <= x1 { (x0, x1) } else { (x1, x0) };
        let first = self.xs.partition_point(|&v| v < lo);
        let end = self.xs.partition_point(|&v| v <= hi);
        let ends = self.height_at(lo).max(self.height_at(hi));
        self.ys
            .get(first..end)
            .unwrap_or(&[])
            .iter()
            .fold(ends, |m, &y| m.max(y))
    }
}

impl Walk {
    /// Parses `H-W-SEED` (the part of `name` after the kind).
    fn parse(name: &str, rest: &str) -> Result<Self> {
        let parts: Vec<&str> = rest.split('-').collect();
        let [h, w, seed] = parts[..] else {
            let what = if parts.iter().any(|p| p.is_empty()) {
                "H, W and SEED must be non-negative numbers separated by single '-'"
            } else {
                "expected three numbers H-W-SEED"
            };
            return Err(malformed(name, what));
        };
        let height = parse_number(name, "height H", h)?;
        if height < 0.0 {
            return Err(malformed(name, &format!("height H must be >= 0, got {h}")));
        }
        let width = parse_number(name, "width W", w)?;
        if width <= 0.0 {
            return Err(malformed(name, &format!("width W must be > 0, got {w}")));
        }
        let seed = seed.parse::<i64>().map_err(|_| {
            malformed(
                name,
                &format!("SEED must be a non-negative integer, got '{seed}'"),
            )
        })?;
        Ok(Self {
            height,
            width,
            seed,
        })
    }

    /// The reference hilly loop: one vertex per pair of Gaussian draws.
    fn hilly(&self) -> (Vec<f64>, Vec<f64>) {
        let mut rng = JavaRandom::new(self.seed);
        let (mut xs, mut ys) = walk_start();
        while last(&xs) < WALK_END {
            let x = last(&xs) + self.spacing(rng.next_gaussian());
            xs.push(x);
            ys.push(last(&ys) + rng.next_gaussian() * self.height);
        }
        walk_finish(xs, ys)
    }

    /// As hilly, but each step is a flat run then a 0.5 m ramp.
    fn steppy(&self) -> (Vec<f64>, Vec<f64>) {
        let mut rng = JavaRandom::new(self.seed);
        let (mut xs, mut ys) = walk_start();
        while last(&xs) < WALK_END {
            let x = last(&xs) + self.spacing(rng.next_gaussian());
            let y = last(&ys);
            xs.push(x);
            ys.push(y);
            xs.push(x + STEP_RAMP);
            ys.push(y + rng.next_gaussian() * self.height);
        }
        walk_finish(xs, ys)
    }

    /// Horizontal step for Gaussian draw `g`, same expression order as Java.
    fn spacing(&self, g: f64) -> f64 {
        MIN_SPACING.max((g * SPACING_SD + 1.0) * self.width)
    }
}

/// Left wall of a random-walk terrain: xs [0, 10], ys [100, 0].
fn walk_start() -> (Vec<f64>, Vec<f64>) {
    (vec![0.0, WALL_WIDTH], vec![WALL_HEIGHT, 0.0])
}

/// Appends the right wall, 10 m after the last vertex.
fn walk_finish(mut xs: Vec<f64>, mut ys: Vec<f64>) -> (Vec<f64>, Vec<f64>) {
    xs.push(last(&xs) + WALL_WIDTH);
    ys.push(WALL_HEIGHT);
    (xs, ys)
}

/// Last element of a polyline array that is never empty.
fn last(v: &[f64]) -> f64 {
    v.last().copied().unwrap_or(0.0)
}

/// Flat ground rising by D = 1980 sin(DEG) from left to right (`flat` is DEG 0).
fn sloped(degrees: f64) -> (Vec<f64>, Vec<f64>) {
    let rise = SLOPE_LENGTH * libm::sin(degrees.to_radians());
    let end = 2.0 * WALL_WIDTH + SLOPE_LENGTH;
    (
        vec![0.0, WALL_WIDTH, end - WALL_WIDTH, end],
        vec![
            WALL_HEIGHT,
            FLAT_LEVEL,
            FLAT_LEVEL + rise,
            WALL_HEIGHT + rise,
        ],
    )
}

/// Parses the DEG of `uphill-DEG` / `downhill-DEG`.
fn parse_slope(name: &str, text: &str) -> Result<f64> {
    let degrees = parse_number(name, "slope DEG", text)?;
    if degrees.abs() >= MAX_SLOPE_DEG {
        return Err(malformed(
            name,
            &format!("slope DEG must be strictly between -89 and 89 degrees, got {text}"),
        ));
    }
    Ok(degrees)
}

/// Parses a finite decimal number named `what`.
fn parse_number(name: &str, what: &str, text: &str) -> Result<f64> {
    match text.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(malformed(
            name,
            &format!("{what} must be a finite number, got '{text}'"),
        )),
    }
}

/// A terrain error naming the input, what is wrong and the accepted forms.
fn malformed(name: &str, what: &str) -> Error {
    Error::Terrain(format!("'{name}': {what}; {ACCEPTED}"))
}
