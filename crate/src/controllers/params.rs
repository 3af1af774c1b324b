//! A controller's genome storage, and the one implementation of `params` / `set_params`
//! that every controller shares through the [`Controller`](super::Controller) trait's
//! default methods: a flat `f32` vector of fixed length, replaced only whole, and only by a
//! genome of the same length whose every value is finite.

use super::validate_params;
use crate::Result;
use std::ops::Deref;

/// A fixed-length genome; see the module doc. Reads as a `&[f32]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Params(Vec<f32>);

impl Params {
    /// `len` parameters, all zero.
    pub fn zeros(len: usize) -> Self {
        Params(vec![0.0; len])
    }

    /// Replaces every parameter. Fails, changing nothing, on a length mismatch or a
    /// non-finite value.
    pub fn set(&mut self, p: &[f32]) -> Result<()> {
        validate_params(self.0.len(), p)?;
        self.0.copy_from_slice(p);
        Ok(())
    }
}

impl Deref for Params {
    type Target = [f32];

    fn deref(&self) -> &[f32] {
        &self.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_refused_genome_changes_nothing() {
        let mut p = Params::zeros(2);
        p.set(&[0.5, -0.5]).unwrap();
        assert!(p.set(&[1.0]).is_err());
        assert!(p.set(&[1.0, f32::NAN]).is_err());
        assert_eq!(&p[..], [0.5, -0.5]);
    }
}
