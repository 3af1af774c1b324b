//! Order statistics of a sample: the median and linear quantiles. One definition for the
//! GA's generation statistics, the validation medians recorded in run files and the study's
//! reports. Quantiles interpolate linearly between order statistics (numpy's default).

/// Median of `values` (any order; the mean of the middle two for an even count, computed as
/// 0.5 (a + b)); NaN when empty. Validation medians (recorded in run and manifest files) and
/// the reports' medians are this one function.
pub fn median(values: &[f64]) -> f64 {
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len();
    match n {
        0 => f64::NAN,
        _ if n % 2 == 1 => sorted[n / 2],
        _ => 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]),
    }
}

/// Quantile `q` in [0, 1] of an ascending `sorted` sample, linear between order statistics
/// (the lower one next to an infinite one: interpolating towards it would give NaN); NaN
/// when empty.
pub fn quantile(sorted: &[f64], q: f64) -> f64 {
    let Some(last) = sorted.len().checked_sub(1) else {
        return f64::NAN;
    };
    let h = q.clamp(0.0, 1.0) * last as f64;
    let (lo, hi) = (h.floor() as usize, h.ceil() as usize);
    if lo == hi || !(sorted[lo].is_finite() && sorted[hi].is_finite()) {
        return sorted[lo];
    }
    sorted[lo] + (h - lo as f64) * (sorted[hi] - sorted[lo])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn medians_and_quantiles_of_known_samples() {
        assert_eq!(median(&[3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&[4.0, 1.0, 3.0, 2.0]), 2.5);
        assert!(median(&[]).is_nan());
        // numpy.quantile([1, 2, 3, 4], 0.25) = 1.75
        assert_eq!(quantile(&[1.0, 2.0, 3.0, 4.0], 0.25), 1.75);
    }
}
