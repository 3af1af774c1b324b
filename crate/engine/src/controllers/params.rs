//! A controller's genome storage, and the one implementation of `params` / `set_params`
//! that every controller shares through the [`Controller`](super::Controller) trait's
//! default methods: a flat `f32` vector of fixed length, replaced only whole, and only by a
//! genome of the same length whose every value is finite. Also the one genome check
//! ([`check_genes`]) that `ControllerKind::check_genome` applies to a family and a body.

use crate::{Error, Result};
use std::ops::Deref;

/// A fixed-length genome; see the module doc. Reads as a `&[f32]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Params(Vec<f32>);

impl Params {
    /// `len` parameters, all zero.
    pub(crate) fn zeros(len: usize) -> Self {
        Params(vec![0.0; len])
    }

    /// Replaces every parameter. Fails, changing nothing, on a length mismatch or a
    /// non-finite value.
    pub(crate) fn set(&mut self, p: &[f32]) -> Result<()> {
        check_genes("the new genome", "this controller", self.0.len(), p)?;
        self.0.copy_from_slice(p);
        Ok(())
    }
}

/// The one genome check: `genome` (named `what` in messages, e.g. "the best genome") must have
/// exactly the `expected` genes of `whose` (the controller that reads it, in words), every
/// one finite.
pub(crate) fn check_genes(what: &str, whose: &str, expected: usize, genome: &[f32]) -> Result<()> {
    if genome.len() != expected {
        return Err(Error::Input(format!(
            "{what} has {} genes, but {whose} has {expected}",
            genome.len()
        )));
    }
    match genome.iter().position(|g| !g.is_finite()) {
        Some(i) => Err(Error::Input(format!(
            "gene {i} of {what} is {}, genes must be finite numbers",
            genome[i]
        ))),
        None => Ok(()),
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

    #[test]
    fn the_genome_check_names_the_problem() {
        let err = check_genes("g", "c", 3, &[0.0, 1.0])
            .unwrap_err()
            .to_string();
        assert!(err.ends_with("g has 2 genes, but c has 3"), "{err}");
        let err = check_genes("g", "c", 2, &[0.0, f32::INFINITY]);
        assert!(err.unwrap_err().to_string().contains("gene 1 of g is inf"));
        assert!(check_genes("g", "c", 2, &[0.0, -1.0]).is_ok());
    }
}
