//! The two-sided Mann-Whitney U test (Wilcoxon rank-sum) with its effect size.
//!
//! U1 = R1 - n1 (n1 + 1) / 2, where R1 is the sum of the ranks of `x` in the pooled sample
//! (ties share their mean rank); U1 counts the pairs with x > y, ties as one half. The
//! p-value is two-sided, for U = max(U1, U2):
//! - [`Method::Exact`] when neither sample has more than [`EXACT_MAX`] values and there is no
//!   tie: p = 2 P(U' >= U) under the null distribution of U, counted by the recursion
//!   c(i, j, u) = c(i - 1, j, u - j) + c(i, j - 1, u) (the largest value is an x or a y);
//! - [`Method::Normal`] otherwise: z = (U - n1 n2 / 2 - 1/2) / sigma with the tie-corrected
//!   sigma^2 = n1 n2 / 12 ((n + 1) - sum(t^3 - t) / (n (n - 1))) and a continuity correction
//!   of 1/2, p = 2 (1 - Phi(z)) (scipy's `method="asymptotic"`).
//!
//! Effect size: Vargha and Delaney's A12 = U1 / (n1 n2), the probability that a value of `x`
//! exceeds one of `y` (ties count one half): 0.5 is no effect, 0.71 or more (0.29 or less) is
//! conventionally "large". The rank-biserial correlation is 2 A12 - 1.

use libm::erfc;
use serde::Serialize;

/// Largest sample size for which the exact distribution is used (without ties).
pub const EXACT_MAX: usize = 20;

/// How a p-value was computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// The exact null distribution of U (small samples without ties).
    Exact,
    /// The tie-corrected normal approximation with continuity correction.
    Normal,
}

/// The outcome of one test; see the module doc.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct UTest {
    /// Size of `x`.
    pub n1: usize,
    /// Size of `y`.
    pub n2: usize,
    /// U of `x`: the pairs with x > y, ties counted one half.
    pub u1: f64,
    /// Two-sided p-value (NaN when a sample is empty).
    pub p: f64,
    /// How `p` was computed.
    pub method: Method,
    /// Vargha-Delaney A12 = U1 / (n1 n2).
    pub a12: f64,
    /// Rank-biserial correlation 2 A12 - 1.
    pub rank_biserial: f64,
}

/// The two-sided Mann-Whitney U test of `x` against `y` (NaN values are dropped).
pub fn mann_whitney(x: &[f64], y: &[f64]) -> UTest {
    let x: Vec<f64> = x.iter().copied().filter(|v| !v.is_nan()).collect();
    let y: Vec<f64> = y.iter().copied().filter(|v| !v.is_nan()).collect();
    let (n1, n2) = (x.len(), y.len());
    let (r1, ties) = rank_sum(&x, &y);
    let u1 = r1 - (n1 * (n1 + 1)) as f64 / 2.0;
    let pairs = (n1 * n2) as f64;
    let exact = ties.is_empty() && n1 <= EXACT_MAX && n2 <= EXACT_MAX;
    let u = u1.max(pairs - u1);
    let p = match (n1 == 0 || n2 == 0, exact) {
        (true, _) => f64::NAN,
        (false, true) => (2.0 * exact_upper_tail(n1, n2, u.round() as usize)).min(1.0),
        (false, false) => normal_p(n1, n2, u, &ties),
    };
    let a12 = u1 / pairs;
    UTest {
        n1,
        n2,
        u1,
        p,
        method: if exact { Method::Exact } else { Method::Normal },
        a12,
        rank_biserial: 2.0 * a12 - 1.0,
    }
}

/// The rank sum of `x` in the pooled sample (mean ranks for ties) and the size of every
/// group of tied values.
pub(super) fn rank_sum(x: &[f64], y: &[f64]) -> (f64, Vec<usize>) {
    let mut pooled: Vec<(f64, bool)> = x.iter().map(|&v| (v, true)).collect();
    pooled.extend(y.iter().map(|&v| (v, false)));
    pooled.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (mut r1, mut ties, mut start) = (0.0, Vec::new(), 0);
    while start < pooled.len() {
        let end = start
            + pooled[start..]
                .iter()
                .take_while(|p| p.0 == pooled[start].0)
                .count();
        // Ranks start + 1 ..= end share their mean.
        let rank = (start + 1 + end) as f64 / 2.0;
        r1 += rank * pooled[start..end].iter().filter(|p| p.1).count() as f64;
        if end - start > 1 {
            ties.push(end - start);
        }
        start = end;
    }
    (r1, ties)
}

/// P(U >= u) under the null hypothesis for samples of `n1` and `n2` distinct values.
pub(super) fn exact_upper_tail(n1: usize, n2: usize, u: usize) -> f64 {
    let all = exact_null_counts(n1, n2);
    let total: f64 = all.iter().sum();
    all[u.min(n1 * n2)..].iter().sum::<f64>() / total
}

/// The null distribution of U for samples of `n1` and `n2` distinct values: entry `v` counts
/// the arrangements with U = v (0 ..= n1 n2), of C(n1 + n2, n1) in all.
pub(crate) fn exact_null_counts(n1: usize, n2: usize) -> Vec<f64> {
    let max_u = n1 * n2;
    // counts[i][j][v]: arrangements of i x's and j y's with U = v.
    let mut counts = vec![vec![vec![0.0f64; max_u + 1]; n2 + 1]; n1 + 1];
    for i in 0..=n1 {
        for j in 0..=n2 {
            if i == 0 || j == 0 {
                counts[i][j][0] = 1.0;
                continue;
            }
            for v in 0..=i * j {
                let x_last = if v >= j { counts[i - 1][j][v - j] } else { 0.0 };
                counts[i][j][v] = x_last + counts[i][j - 1][v];
            }
        }
    }
    counts.swap_remove(n1).swap_remove(n2)
}

/// The tie-corrected standard deviation of U under the null hypothesis, given the size of
/// every group of tied values; None when it is 0 (every value equal).
pub(super) fn tie_corrected_sigma(n1: usize, n2: usize, ties: &[usize]) -> Option<f64> {
    let (a, b) = (n1 as f64, n2 as f64);
    let n = a + b;
    let tie_term: f64 = ties.iter().map(|&t| (t * t * t - t) as f64).sum();
    let variance = a * b / 12.0 * ((n + 1.0) - tie_term / (n * (n - 1.0)));
    (variance > 0.0).then(|| variance.sqrt())
}

/// Two-sided p of the normal approximation for U = `u` (the larger of U1, U2).
fn normal_p(n1: usize, n2: usize, u: f64, ties: &[usize]) -> f64 {
    let Some(sigma) = tie_corrected_sigma(n1, n2, ties) else {
        return 1.0; // every value equal: no evidence of a difference
    };
    let z = (u - (n1 * n2) as f64 / 2.0 - 0.5) / sigma;
    erfc(z / std::f64::consts::SQRT_2).min(1.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol
    }

    /// scipy's documented example (mannwhitneyu docs): males [19, 22, 16, 29, 24] against
    /// females [20, 11, 17, 12]: U1 = 17, exact p = 14/126 = 0.1111 (7 of the 126
    /// arrangements have U <= 3), asymptotic p = 0.11134688653314041.
    #[test]
    fn scipy_documented_example() {
        let males = [19.0, 22.0, 16.0, 29.0, 24.0];
        let females = [20.0, 11.0, 17.0, 12.0];
        let t = mann_whitney(&males, &females);
        assert_eq!((t.u1, t.method), (17.0, Method::Exact));
        assert!(close(t.p, 14.0 / 126.0, 1e-12), "{}", t.p);
        assert!(close(t.a12, 17.0 / 20.0, 1e-12));
        let z = normal_p(5, 4, 17.0, &[]);
        assert!(close(z, 0.11134688653314041, 1e-9), "{z}");
    }

    /// Complete separation of 5 against 5 (the paper's design): the smallest possible
    /// two-sided p is 2 / C(10, 5) = 2 / 252 = 0.0079; by hand, the normal approximation
    /// gives z = (25 - 12.5 - 0.5) / sqrt(25 * 11 / 12) = 2.5067, p = 0.012186.
    #[test]
    fn five_against_five_separated() {
        let low = [1.0, 2.0, 3.0, 4.0, 5.0];
        let high = [6.0, 7.0, 8.0, 9.0, 10.0];
        let t = mann_whitney(&high, &low);
        assert_eq!((t.u1, t.a12, t.rank_biserial), (25.0, 1.0, 1.0));
        assert!(close(t.p, 2.0 / 252.0, 1e-12), "{}", t.p);
        assert_eq!(mann_whitney(&low, &high).p, t.p, "symmetric");
        assert_eq!(mann_whitney(&low, &high).a12, 0.0);
        assert!(close(normal_p(5, 5, 25.0, &[]), 0.012186, 1e-5));
    }

    /// Ties: x = [1, 2, 2, 3], y = [2, 3, 4, 5]. Pooled ranks: 1 -> 1, the three 2s -> 3,
    /// the two 3s -> 5.5, 4 -> 7, 5 -> 8; R1 = 1 + 3 + 3 + 5.5 = 12.5, U1 = 2.5, U = 13.5.
    /// Tie term: (27 - 3) + (8 - 2) = 30; sigma^2 = 16 / 12 (9 - 30 / 56) = 11.2857;
    /// z = (13.5 - 8 - 0.5) / 3.3594 = 1.4884, p = 0.13666.
    #[test]
    fn ties_use_mid_ranks_and_the_corrected_variance() {
        let t = mann_whitney(&[1.0, 2.0, 2.0, 3.0], &[2.0, 3.0, 4.0, 5.0]);
        assert_eq!((t.u1, t.method), (2.5, Method::Normal));
        assert!(close(t.p, 0.13666, 2e-5), "{}", t.p);
    }

    /// The recursion agrees with enumerating every split of 1..=n1+n2 into two groups.
    #[test]
    fn exact_distribution_matches_enumeration() {
        let (n1, n2) = (4usize, 6usize);
        let n = n1 + n2;
        let mut tail = vec![0usize; n1 * n2 + 1];
        let mut total = 0;
        for mask in 0u32..(1 << n) {
            if mask.count_ones() as usize != n1 {
                continue;
            }
            total += 1;
            let x: Vec<usize> = (0..n).filter(|i| mask & (1 << i) != 0).collect();
            let u: usize = x
                .iter()
                .map(|&v| (0..n).filter(|&w| mask & (1 << w) == 0 && w < v).count())
                .sum();
            tail[..=u].iter_mut().for_each(|t| *t += 1);
        }
        for (u, &count) in tail.iter().enumerate() {
            let p = exact_upper_tail(n1, n2, u);
            assert!(close(p, count as f64 / total as f64, 1e-12), "u = {u}");
        }
    }

    #[test]
    fn identical_and_empty_samples() {
        let same = mann_whitney(&[1.0; 6], &[1.0; 6]);
        assert_eq!((same.p, same.a12), (1.0, 0.5));
        assert!(mann_whitney(&[], &[1.0]).p.is_nan());
        let large = mann_whitney(&[0.0; 30], &[1.0; 30]);
        assert_eq!(large.method, Method::Normal, "more than 20 values");
    }
}
