//! What the ground contacts (`contact.rs`, one moving body) and the self-contacts
//! (`self_contact.rs`, two) share: the contact law of one row, the reference's
//! sequential impulses. Per step a row gets its target normal velocity
//! ([`bounce`]) and its warm-start impulses by contact key ([`WarmStart`]); per
//! velocity iteration, friction then the normal impulse ([`Impulses`]); per position
//! iteration, a Baumgarte-limited correction ([`correction`]). The solvers own only
//! their geometry: which bodies, which lever arms, which effective masses.

use super::constants::{
    BAUMGARTE, DT, LINEAR_SLOP, MAX_LINEAR_CORRECTION, RESTITUTION, RESTITUTION_VELOCITY,
};

/// The 2-D cross product r x n.
#[inline]
pub(crate) fn cross(r: (f64, f64), n: (f64, f64)) -> f64 {
    r.0 * n.1 - r.1 * n.0
}

/// Target (relative) normal velocity of a contact: for a speculative contact (still
/// `separation` apart) the negative speed that just closes the gap in one step,
/// otherwise restitution's bounce of an approach `vn` faster than 1 m/s, otherwise 0.
#[inline]
pub(crate) fn bounce(separation: f64, vn: f64) -> f64 {
    if separation > 0.0 {
        -separation / DT
    } else if vn < -RESTITUTION_VELOCITY {
        -RESTITUTION * vn
    } else {
        0.0
    }
}

/// Position correction along the normal (m, <= 0) for a contact `separation` apart:
/// Baumgarte's fraction of the penetration beyond the slop, at most the maximum.
#[inline]
pub(crate) fn correction(separation: f64) -> f64 {
    (BAUMGARTE * (separation + LINEAR_SLOP)).clamp(-MAX_LINEAR_CORRECTION, 0.0)
}

/// True when no contact penetrates by more than three times the slop.
#[inline]
pub(crate) fn resolved(min_separation: f64) -> bool {
    min_separation >= -3.0 * LINEAR_SLOP
}

/// A row's accumulated impulses (N s): along the normal and along the tangent.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct Impulses {
    pub(crate) normal: f64,
    pub(crate) tangent: f64,
}

impl Impulses {
    /// Coulomb friction for tangential velocity `vt`: the accumulated tangent impulse
    /// stays within `friction` times the normal impulse. Returns the change.
    #[inline]
    pub(crate) fn friction(&mut self, vt: f64, tangent_mass: f64, friction: f64) -> f64 {
        let max = friction * self.normal;
        let old = self.tangent;
        self.tangent = (old - vt * tangent_mass).clamp(-max, max);
        self.tangent - old
    }

    /// The non-negative normal impulse toward normal velocity `bounce`, for normal
    /// velocity `vn`. Returns the change.
    #[inline]
    pub(crate) fn normal(&mut self, vn: f64, bounce: f64, normal_mass: f64) -> f64 {
        let old = self.normal;
        self.normal = (old - (vn - bounce) * normal_mass).max(0.0);
        self.normal - old
    }
}

/// Last step's impulses by contact key, for warm starting this step's rows.
#[derive(Debug, Clone, Default)]
pub(crate) struct WarmStart {
    /// (key, impulses), ascending by key.
    previous: Vec<(u64, Impulses)>,
    /// Where the lookup of the next (larger) key starts.
    next: usize,
}

impl WarmStart {
    /// Remembers the last step's rows, `(key, impulses)` in ascending key order.
    pub(crate) fn remember(&mut self, rows: impl Iterator<Item = (u64, Impulses)>) {
        self.previous.clear();
        self.previous.extend(rows);
        self.next = 0;
    }

    /// The remembered impulses of `key`; keys must be asked for in ascending order.
    #[inline]
    pub(crate) fn take(&mut self, key: u64) -> Option<Impulses> {
        let previous = &self.previous;
        while self.next < previous.len() && previous[self.next].0 < key {
            self.next += 1;
        }
        match previous.get(self.next) {
            Some(&(k, impulses)) if k == key => Some(impulses),
            _ => None,
        }
    }
}
