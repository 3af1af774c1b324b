//! Statistics for comparing runs (the paper's "5 runs per configuration, Mann-Whitney U"):
//! summaries and order statistics of small samples, the two-sided Mann-Whitney U test with
//! its effect size and its one-sided form (non-inferiority by a margin), Holm's correction,
//! the Hodges-Lehmann shift with its exact interval, the paired signed-rank test, Spearman's
//! rank correlation, and bootstrap intervals and power from fixed seeds. Plain functions over
//! `&[f64]`; no I/O.

mod correlation;
mod holm;
mod mann_whitney;
mod normal;
mod one_sided;
mod order_ci;
mod resample;
mod shift;
mod summary;
mod wilcoxon;

pub use correlation::spearman;
pub use holm::holm;
pub use mann_whitney::{mann_whitney, Method, UTest};
pub use one_sided::{mann_whitney_greater, noninferiority, OneSidedU};
pub use order_ci::{median_interval, Interval};
pub use resample::{a12_interval, detectable_a12, Detectable};
pub use shift::{hodges_lehmann, Shift};
pub use summary::Summary;
pub use vsr::quantiles::{median, quantile};
pub use wilcoxon::{wilcoxon_signed_rank, SignedRank};
