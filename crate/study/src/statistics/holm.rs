//! Holm's step-down correction for a family of tests: the familywise error rate stays at
//! alpha for any dependence between the tests, and it is uniformly more powerful than
//! Bonferroni's.
//!
//! With the m raw p-values sorted p(1) <= ... <= p(m), the adjusted p(i) is
//! max over j <= i of min(1, (m - j + 1) p(j)); a test is rejected at familywise alpha when
//! its adjusted p is below alpha (statsmodels' `multipletests(method="holm")`).

/// The Holm-adjusted p-values of `p`, in the order of `p` (NaN stays NaN and is not
/// counted in the family).
pub fn holm(p: &[f64]) -> Vec<f64> {
    let mut order: Vec<usize> = (0..p.len()).filter(|&i| !p[i].is_nan()).collect();
    order.sort_by(|&a, &b| p[a].total_cmp(&p[b]));
    let m = order.len();
    let mut adjusted = vec![f64::NAN; p.len()];
    let mut running = 0.0f64;
    for (rank, &i) in order.iter().enumerate() {
        let scaled = ((m - rank) as f64 * p[i]).min(1.0);
        running = running.max(scaled);
        adjusted[i] = running;
    }
    adjusted
}
