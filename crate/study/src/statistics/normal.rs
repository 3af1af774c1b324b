//! The standard normal distribution: its CDF (from `libm::erfc`) and its quantile (by
//! bisection on the CDF: slow, exact to 1e-12, used only to size intervals).

/// P(Z <= z).
pub fn cdf(z: f64) -> f64 {
    0.5 * libm::erfc(-z / std::f64::consts::SQRT_2)
}

/// The z with P(Z <= z) = `p`, for 0 < p < 1.
pub fn quantile(p: f64) -> f64 {
    let (mut low, mut high) = (-40.0f64, 40.0f64);
    while high - low > 1e-12 {
        let mid = 0.5 * (low + high);
        if cdf(mid) < p {
            low = mid;
        } else {
            high = mid;
        }
    }
    0.5 * (low + high)
}
