//! The study's statistics against values computed independently in Python (scipy 1.x and
//! statsmodels 0.14, commands in each test's comment) on fixed samples: Holm's correction,
//! the Hodges-Lehmann shift and its exact interval, the signed-rank test, order-statistic
//! intervals, and the resampled A12 interval and detectable effect.

use vsr_study::statistics::{
    a12_interval, detectable_a12, hodges_lehmann, holm, mann_whitney, median_interval,
    wilcoxon_signed_rank,
};

/// Two samples of 10 velocities (m/s; 3.14 is a velocity, not pi).
const X10: [f64; 10] = [1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30, 0.27];
#[allow(clippy::approx_constant)]
const Y10: [f64; 10] = [
    0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29, 0.11,
];

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

/// statsmodels.stats.multitest.multipletests(p, method="holm")[1] on the 9 raw p of the
/// paper study's biped RQ1 table: the smallest adjusted p is 0.0711 (9 x 0.0079).
#[test]
fn holm_matches_statsmodels() {
    let p = [
        0.0079, 0.0317, 0.0159, 0.0556, 0.5476, 0.0952, 0.1508, 0.2222, 0.0079,
    ];
    let want = [
        0.0711, 0.1902, 0.1113, 0.278, 0.5476, 0.3808, 0.4524, 0.4524, 0.0711,
    ];
    for (got, want) in holm(&p).iter().zip(want) {
        assert!(close(*got, want, 1e-12), "{got} vs {want}");
    }
    let with_nan = holm(&[0.01, f64::NAN, 0.04]);
    assert!(with_nan[1].is_nan());
    assert!(close(with_nan[0], 0.02, 1e-15) && close(with_nan[2], 0.04, 1e-15));
    assert_eq!(holm(&[0.9, 0.8]), vec![1.0, 1.0], "capped at 1");
    let monotone = holm(&[0.04, 0.03, 0.2]); // statsmodels: [0.09, 0.09, 0.2]
    for (got, want) in monotone.iter().zip([0.09, 0.09, 0.2]) {
        assert!(close(*got, want, 1e-15), "{monotone:?}");
    }
}

/// numpy: the median of the 25 pairwise differences is 1.17; the exact 95% interval of 5
/// against 5 cuts k = 3 (2 P(U <= 2) = 8/252 <= 0.05 < 2 P(U <= 3) = 14/252): the 3rd
/// smallest and largest differences, 0.10 and 2.05, coverage 1 - 8/252.
#[test]
fn hodges_lehmann_five_against_five() {
    let x = [3.95, 4.54, 3.57, 4.80, 3.20];
    let y = [3.22, 2.75, 3.35, 3.10, 2.40];
    let s = hodges_lehmann(&x, &y, 0.05).expect("samples");
    assert!(close(s.estimate, 1.17, 1e-12), "{}", s.estimate);
    assert!(close(s.interval.low, 0.10, 1e-12), "{:?}", s.interval);
    assert!(close(s.interval.high, 2.05, 1e-12), "{:?}", s.interval);
    assert!(close(s.interval.coverage, 1.0 - 8.0 / 252.0, 1e-12));
}

/// 10 against 10: median difference 0.55; k = 24 (scipy's exact null distribution of U:
/// 2 P(U <= 23) = 0.0433), the 24th smallest and largest differences -0.378 and 1.19,
/// coverage 0.95674.
#[test]
fn hodges_lehmann_ten_against_ten() {
    let (x, y) = (X10, Y10);
    let s = hodges_lehmann(&x, &y, 0.05).expect("samples");
    assert!(close(s.estimate, 0.55, 1e-12), "{}", s.estimate);
    assert!(close(s.interval.low, -0.378, 1e-12), "{:?}", s.interval);
    assert!(close(s.interval.high, 1.19, 1e-12), "{:?}", s.interval);
    assert!(close(s.interval.coverage, 0.9567429474550218, 1e-12));
    // The interval is the set of shifts the test does not reject: x shifted by the estimate
    // is far from significance, shifted just past an end it is rejected.
    let by = |d: f64| -> Vec<f64> { x.iter().map(|v| v - d).collect() };
    assert!(mann_whitney(&by(s.estimate), &y).p > 0.5);
    assert!(mann_whitney(&by(s.interval.high + 1e-9), &y).p <= 0.05);
    assert!(mann_whitney(&by(s.interval.low - 1e-9), &y).p <= 0.05);
    assert!(hodges_lehmann(&[], &y, 0.05).is_none());
}

/// scipy.stats.wilcoxon(x, y, method="approx"): the 10 pairs above, p = 0.02182427562605354
/// (W+ = 50 of 55); 12 pairs with one zero difference dropped and tied ranks,
/// p = 0.05023302822033748 (W+ = 55 of 66).
#[test]
fn signed_rank_matches_scipy() {
    let (x, y) = (X10, Y10);
    let t = wilcoxon_signed_rank(&x, &y);
    assert_eq!((t.n, t.w_plus), (10, 50.0));
    assert!(close(t.p, 0.02182427562605354, 1e-9), "{}", t.p);
    let xs = [1.1, 2.3, 0.4, 5.0, 3.3, 2.2, 1.8, 0.9, 4.1, 2.7, 3.9, 1.4];
    let ys = [1.0, 2.0, 0.6, 4.1, 3.3, 2.9, 1.0, 0.7, 3.0, 2.6, 3.5, 1.0];
    let t = wilcoxon_signed_rank(&xs, &ys);
    assert_eq!((t.n, t.w_plus), (11, 55.0));
    assert!(close(t.p, 0.05023302822033748, 1e-9), "{}", t.p);
}

/// The sign-test interval of a median: 10 values cut k = 2 (2 P(B <= 1) = 22/1024), 5
/// values cannot reach 95% and give the range with coverage 1 - 2/32.
#[test]
fn median_intervals_from_order_statistics() {
    let ten: Vec<f64> = (1..=10).map(f64::from).collect();
    let i = median_interval(&ten, 0.05).expect("values");
    assert_eq!((i.low, i.high), (2.0, 9.0));
    assert!(close(i.coverage, 1.0 - 22.0 / 1024.0, 1e-12));
    let i = median_interval(&[5.0, 1.0, 3.0, 2.0, 4.0], 0.05).expect("values");
    assert_eq!((i.low, i.high), (1.0, 5.0));
    assert!(close(i.coverage, 1.0 - 2.0 / 32.0, 1e-12));
    assert!(median_interval(&[], 0.05).is_none());
}

/// The bootstrap interval holds the observed A12 and is reproducible; complete separation
/// gives [1, 1]. The detectable effect of 5 against 5 is larger than of 10 against 10, and
/// the smallest p of 5 against 5 is 2/252.
#[test]
fn resampled_intervals_and_power() {
    let (x, y) = (X10, Y10);
    let a12 = mann_whitney(&x, &y).a12;
    let i = a12_interval(&x, &y, 0.05).expect("samples");
    assert!(i.low < a12 && a12 < i.high, "{i:?} around {a12}");
    assert_eq!(Some(i), a12_interval(&x, &y, 0.05), "fixed seed");
    let sep = a12_interval(&[5.0, 6.0, 7.0], &[1.0, 2.0], 0.05).expect("samples");
    assert_eq!((sep.low, sep.high), (1.0, 1.0));
    let five = detectable_a12(5, 5, 0.05, 0.8);
    let ten = detectable_a12(10, 10, 0.05, 0.8);
    assert!(close(five.smallest_p, 2.0 / 252.0, 1e-12));
    assert!(ten.a12 < five.a12 && ten.a12 > 0.7, "{ten:?} {five:?}");
    // Normal theory for the t-test at 10 against 10 needs delta = 1.32 for 80% power; the
    // rank test needs a little more (asymptotic relative efficiency 0.955).
    assert!((1.25..1.6).contains(&ten.delta), "{ten:?}");
}
