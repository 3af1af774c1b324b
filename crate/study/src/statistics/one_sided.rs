//! The one-sided Mann-Whitney U test: H1 "`x` tends to be larger than `y`" against H0 "it
//! does not". The p-value is P(U1' >= U1) under the null distribution of U1 (the pairs with
//! x > y, ties one half), computed as the two-sided test does (`mann_whitney`):
//! - [`Method::Exact`] when neither sample has more than [`EXACT_MAX`] values and there is no
//!   tie: the exact upper tail of U1;
//! - [`Method::Normal`] otherwise: z = (U1 - n1 n2 / 2 - 1/2) / sigma with the tie-corrected
//!   sigma and a continuity correction of 1/2, p = 1 - Phi(z) (scipy's
//!   `mannwhitneyu(x, y, alternative="greater", method="asymptotic")`).
//!
//! A non-inferiority test of "`x` is not worse than `y` by `margin` or more" is this test of
//! x + margin against y (H0: x's location is below y's by the margin or more).

use super::mann_whitney::{exact_upper_tail, rank_sum, tie_corrected_sigma, EXACT_MAX};
use super::Method;
use serde::Serialize;

/// The outcome of a one-sided test; see the module doc.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct OneSidedU {
    /// Size of `x`.
    pub n1: usize,
    /// Size of `y`.
    pub n2: usize,
    /// U of `x`: the pairs with x > y, ties counted one half.
    pub u1: f64,
    /// One-sided p-value of H1 "x is larger" (NaN when a sample is empty).
    pub p: f64,
    /// How `p` was computed.
    pub method: Method,
}

/// The one-sided Mann-Whitney U test of H1 "`x` is larger than `y`" (NaN values dropped).
pub fn mann_whitney_greater(x: &[f64], y: &[f64]) -> OneSidedU {
    let x: Vec<f64> = x.iter().copied().filter(|v| !v.is_nan()).collect();
    let y: Vec<f64> = y.iter().copied().filter(|v| !v.is_nan()).collect();
    let (n1, n2) = (x.len(), y.len());
    let (r1, ties) = rank_sum(&x, &y);
    let u1 = r1 - (n1 * (n1 + 1)) as f64 / 2.0;
    let exact = ties.is_empty() && n1 <= EXACT_MAX && n2 <= EXACT_MAX;
    let p = match (n1 == 0 || n2 == 0, exact) {
        (true, _) => f64::NAN,
        (false, true) => exact_upper_tail(n1, n2, u1.round() as usize),
        (false, false) => match tie_corrected_sigma(n1, n2, &ties) {
            // Every value equal: no evidence that x is larger.
            None => 1.0,
            Some(sigma) => {
                let z = (u1 - (n1 * n2) as f64 / 2.0 - 0.5) / sigma;
                super::normal::cdf(-z)
            }
        },
    };
    OneSidedU {
        n1,
        n2,
        u1,
        p,
        method: if exact { Method::Exact } else { Method::Normal },
    }
}

/// The one-sided test of H1 "`x` is not worse than `y` by `margin` or more": the test of
/// x + margin against y.
pub fn noninferiority(x: &[f64], y: &[f64], margin: f64) -> OneSidedU {
    let shifted: Vec<f64> = x.iter().map(|v| v + margin).collect();
    mann_whitney_greater(&shifted, y)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: f64, b: f64, tol: f64) -> bool {
        (a - b).abs() <= tol
    }

    /// 3 against 3, complete separation: U1 = 9, the one arrangement of C(6, 3) = 20 with
    /// U = 9, p = 1/20; the reverse order has U1 = 0 and p = 1 (every arrangement has
    /// U >= 0).
    #[test]
    fn exact_by_hand() {
        let t = mann_whitney_greater(&[4.0, 5.0, 6.0], &[1.0, 2.0, 3.0]);
        assert_eq!((t.u1, t.method), (9.0, Method::Exact));
        assert!(close(t.p, 1.0 / 20.0, 1e-15), "{}", t.p);
        assert_eq!(
            mann_whitney_greater(&[1.0, 2.0, 3.0], &[4.0, 5.0, 6.0]).p,
            1.0
        );
        // x = [2, 5, 6], y = [1, 3, 4]: U1 = 1 + 3 + 3 = 7; U >= 7 in 4 of the 20
        // arrangements (U = 9 and 8 once each, U = 7 twice: x's ranks {2, 5, 6} and
        // {3, 4, 6}): p = 4/20 (scipy: 0.2).
        let t = mann_whitney_greater(&[2.0, 5.0, 6.0], &[1.0, 3.0, 4.0]);
        assert_eq!(t.u1, 7.0);
        assert!(close(t.p, 4.0 / 20.0, 1e-15), "{}", t.p);
    }

    /// scipy's documented example (males against females, see `mann_whitney`): U1 = 17,
    /// one-sided exact p = 7/126 = 0.0556, half the two-sided p; the other direction has
    /// U1 = 3, P(U >= 3) = 1 - 4/126 (U in 0..=2: 1, 1, 2 arrangements) = 0.96825 (scipy,
    /// exact: 0.05555555555555555 and 0.9682539682539683).
    #[test]
    fn half_the_two_sided_exact_p() {
        let males = [19.0, 22.0, 16.0, 29.0, 24.0];
        let females = [20.0, 11.0, 17.0, 12.0];
        let t = mann_whitney_greater(&males, &females);
        assert!(close(t.p, 7.0 / 126.0, 1e-12), "{}", t.p);
        let two = super::super::mann_whitney(&males, &females);
        assert!(close(2.0 * t.p, two.p, 1e-12));
        let back = mann_whitney_greater(&females, &males);
        assert!(close(back.p, 1.0 - 4.0 / 126.0, 1e-12), "{}", back.p);
    }

    /// Ties (the two-sided test's example): x = [1, 2, 2, 3], y = [2, 3, 4, 5], U1 = 2.5,
    /// sigma^2 = 11.2857. Greater: z = (2.5 - 8 - 0.5) / 3.3594 = -1.7860, p = 0.96295;
    /// the reverse: U1 = 13.5, z = 1.4884, p = 0.068331 (half the two-sided 0.13666).
    /// scipy: mannwhitneyu(x, y, alternative="greater", method="asymptotic") gives
    /// 0.9629521255093261 and, reversed, 0.06832912386907375.
    #[test]
    fn ties_use_the_normal_approximation() {
        let (x, y) = ([1.0, 2.0, 2.0, 3.0], [2.0, 3.0, 4.0, 5.0]);
        let t = mann_whitney_greater(&x, &y);
        assert_eq!((t.u1, t.method), (2.5, Method::Normal));
        assert!(close(t.p, 0.9629521255093261, 1e-9), "{}", t.p);
        let r = mann_whitney_greater(&y, &x);
        assert!(close(r.p, 0.06832912386907375, 1e-9), "{}", r.p);
    }

    /// The margin shifts `x`: 21 against 21 (normal approximation), y = 0..21 and
    /// x = y - 0.25: with a margin of 0.5, x + margin = y + 0.25 wins every pair
    /// (i, j) with i >= j, U1 = 21 * 22 / 2 = 231 of 441; sigma^2 = 441 * 43 / 12, so
    /// z = (231 - 220.5 - 0.5) / 39.7523 = 0.25156 and p = 0.40069. Without the margin
    /// x loses those pairs: U1 = 210, z = -0.27671, p = 0.60900 (scipy, asymptotic:
    /// 0.4006915941542464 and 0.6089998100375804).
    #[test]
    fn noninferiority_shifts_by_the_margin() {
        let y: Vec<f64> = (0..21).map(f64::from).collect();
        let x: Vec<f64> = y.iter().map(|v| v - 0.25).collect();
        let t = noninferiority(&x, &y, 0.5);
        assert_eq!((t.u1, t.method), (231.0, Method::Normal));
        assert!(close(t.p, 0.4006915941542464, 1e-9), "{}", t.p);
        let plain = mann_whitney_greater(&x, &y);
        assert_eq!(plain.u1, 210.0);
        assert!(close(plain.p, 0.6089998100375804, 1e-9), "{}", plain.p);
    }

    /// 30 against 30, the plan's design: x = 2.0 + i / 10, y = 2.33 + i / 10 (i < 30). With
    /// the margin of 0.5, x + 0.5 = 2.5 + i / 10 beats y_j when i >= j - 1: U1 = 494; without
    /// it, x_i beats y_j when i >= j + 4: U1 = 351. scipy (asymptotic, "greater"):
    /// 0.2600723060808019 and 0.9293612467797542.
    #[test]
    fn thirty_against_thirty_as_scipy() {
        let x: Vec<f64> = (0..30).map(|i| 2.0 + f64::from(i) / 10.0).collect();
        let y: Vec<f64> = (0..30).map(|i| 2.33 + f64::from(i) / 10.0).collect();
        let t = noninferiority(&x, &y, 0.5);
        assert_eq!((t.u1, t.method), (494.0, Method::Normal));
        assert!(close(t.p, 0.2600723060808019, 1e-9), "{}", t.p);
        let plain = mann_whitney_greater(&x, &y);
        assert_eq!(plain.u1, 351.0);
        assert!(close(plain.p, 0.9293612467797542, 1e-9), "{}", plain.p);
    }

    #[test]
    fn identical_and_empty_samples() {
        assert_eq!(mann_whitney_greater(&[1.0; 25], &[1.0; 25]).p, 1.0);
        assert!(mann_whitney_greater(&[], &[1.0]).p.is_nan());
    }
}
