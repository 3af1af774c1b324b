//! Statistics for comparing runs (the paper's "5 runs per configuration, Mann-Whitney U"):
//! summaries of small samples and the two-sided Mann-Whitney U test with an effect
//! size. Plain functions over `&[f64]`; no I/O, no randomness.

mod mann_whitney;
mod summary;

pub use crate::quantiles::{median, quantile};
pub use mann_whitney::{mann_whitney, Method, UTest};
pub use summary::Summary;
