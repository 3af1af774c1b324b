//! `tanhf` over a slice, several values per vector instruction, with `libm::tanhf`'s bits.
//!
//! `libm::tanhf` (musl's) picks one of five formulas by the size of `|x|`, three of them
//! through `expm1f`, which itself picks its argument reduction and its last step by branches.
//! Branches keep a loop scalar. Here every formula is computed for every value and the one
//! `libm` would have picked is selected, with the same operations in the same order (no
//! fused multiply-add: the build disables FMA), so the compiler can run the loop in SIMD
//! lanes and every result is the bit pattern `libm::tanhf` returns. A NaN stays a NaN (its
//! payload may differ; nothing here depends on one). The tests below compare the two on a
//! sweep of every exponent (in `make test`) and on all 2^32 inputs (by hand, `--ignored`).

// `libm`'s constants for `expm1f`, written as libm writes them (the test checks their bits).
#[allow(clippy::excessive_precision)]
const LN2_HI: f32 = 6.9313812256e-01; // 0x3f317180
#[allow(clippy::excessive_precision)]
const LN2_LO: f32 = 9.0580006145e-06; // 0x3717f7d1
#[allow(clippy::excessive_precision)]
const INV_LN2: f32 = 1.4426950216e+00; // 0x3fb8aa3b
#[allow(clippy::excessive_precision)]
const Q1: f32 = -3.3333212137e-2; // -0x888868.0p-28
#[allow(clippy::excessive_precision)]
const Q2: f32 = 1.5807170421e-3; // 0xcf3010.0p-33

/// Replaces every value of `xs` by its `tanhf`, bit for bit as `libm::tanhf` (but NaN payloads).
pub(crate) fn tanhf_in_place(xs: &mut [f32]) {
    for x in xs.iter_mut() {
        *x = tanhf(*x);
    }
}

/// `libm::tanhf` without branches (selects only).
#[inline(always)]
fn tanhf(x: f32) -> f32 {
    let bits = x.to_bits();
    let w = bits & 0x7fff_ffff;
    let ax = f32::from_bits(w);
    // expm1f(2|x|) above log(5/3)/2, expm1f(-2|x|) below.
    let t = expm1f(if w > 0x3e82_c578 { 2.0 * ax } else { -2.0 * ax });
    // 1 + 0 / |x| for |x| > 10: 1, or the NaN.
    let huge = if ax.is_nan() { ax } else { 1.0 };
    let large = 1.0 - 2.0 / (t + 2.0); // |x| > log(3)/2
    let medium = t / (t + 2.0); // |x| > log(5/3)/2
    let small = -medium; // |x| normal: -t / (t + 2), the same bits (division rounds symmetrically)
    let tt = if w > 0x3f0c_9f54 {
        if w > 0x4120_0000 {
            huge
        } else {
            large
        }
    } else if w > 0x3e82_c578 {
        medium
    } else if w >= 0x0080_0000 {
        small
    } else {
        ax // subnormal or zero
    };
    f32::from_bits(tt.to_bits() ^ (bits & 0x8000_0000))
}

/// `libm::expm1f` without branches (selects only); for `tanhf`'s arguments and all others.
#[inline(always)]
fn expm1f(x: f32) -> f32 {
    let hx_signed = x.to_bits();
    let negative = (hx_signed >> 31) != 0;
    let hx = hx_signed & 0x7fff_ffff;

    // Argument reduction: x = hi - lo + k ln2 (c the rounding error of hi - lo).
    // k = (INV_LN2 x +- 0.5) as i32, where it is used (|k| <= 128). `as i32` saturates, which
    // keeps the loop scalar; this truncates in lanes and reads the integer from the bits of
    // 1.5 2^23 + k (exact for |k| < 2^22; the clamp keeps NaN and the rest away).
    let v = INV_LN2 * x + if negative { -0.5 } else { 0.5 };
    #[allow(clippy::manual_clamp)] // max/min, not clamp: a NaN becomes -1024, not NaN
    let v = v.max(-1024.0).min(1024.0).trunc();
    let kf = ((v + 12_582_912.0).to_bits() as i32).wrapping_sub(0x4b40_0000);
    let tk = kf as f32;
    let near = hx < 0x3f85_1592; // |x| < 1.5 ln2: k = +-1
    let (hi, lo, k) = if near {
        if negative {
            (x + LN2_HI, -LN2_LO, -1)
        } else {
            (x - LN2_HI, LN2_LO, 1)
        }
    } else {
        (x - tk * LN2_HI, tk * LN2_LO, kf)
    };
    let reduced = hx > 0x3eb1_7218; // |x| > 0.5 ln2
    let xr_reduced = hi - lo;
    let c_reduced = (hi - xr_reduced) - lo;
    let (xr, c, k) = if reduced {
        (xr_reduced, c_reduced, k)
    } else {
        (x, 0.0, 0)
    };

    // x is now in the primary range.
    let hfx = 0.5 * xr;
    let hxs = xr * hfx;
    let r1 = 1.0 + hxs * (Q1 + hxs * Q2);
    let t = 3.0 - r1 * hfx;
    let e0 = hxs * ((r1 - t) / (6.0 - xr * t));
    let k_zero = xr - (xr * e0 - hxs);
    let e = xr * (e0 - c) - c;
    let e = e - hxs;
    let k_minus_one = 0.5 * (xr - e) - 0.5;
    let k_one = if xr < -0.25 {
        -2.0 * (e - (xr + 0.5))
    } else {
        1.0 + 2.0 * (xr - e)
    };
    let twopk = f32::from_bits((0x7f_i32.wrapping_add(k) as u32).wrapping_shl(23));
    let x1p127 = f32::from_bits(0x7f00_0000);
    let y = xr - e + 1.0;
    let far = if k == 128 {
        y * 2.0 * x1p127
    } else {
        y * twopk
    } - 1.0;
    let uf = f32::from_bits((0x7f_i32.wrapping_sub(k) as u32).wrapping_shl(23));
    let below_23 = (xr - e + (1.0 - uf)) * twopk;
    let from_23 = (xr - (e + uf) + 1.0) * twopk;
    let general = if !(0..=56).contains(&k) {
        far
    } else if k < 23 {
        below_23
    } else {
        from_23
    };
    let result = if k == 0 {
        k_zero
    } else if k == -1 {
        k_minus_one
    } else if k == 1 {
        k_one
    } else {
        general
    };

    // The early returns, in libm's order.
    if hx >= 0x4195_b844 {
        // |x| >= 27 ln2
        if hx > 0x7f80_0000 {
            return x; // NaN
        }
        if negative {
            return -1.0;
        }
        if hx > 0x42b1_7217 {
            return x * x1p127; // overflow
        }
    }
    if !reduced && hx < 0x3300_0000 {
        return x; // |x| < 2^-25
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn constants_are_libms_bits() {
        let bits = [LN2_HI, LN2_LO, INV_LN2, Q1, Q2].map(f32::to_bits);
        assert_eq!(
            bits,
            [
                0x3f31_7180,
                0x3717_f7d1,
                0x3fb8_aa3b,
                0xbd08_8868,
                0x3acf_3010
            ]
        );
    }

    /// Bit-identical to libm over a sweep of every exponent and both signs.
    #[test]
    fn matches_libm_bit_for_bit() {
        let mut xs = Vec::new();
        let mut bits = 0u32;
        while let Some(next) = bits.checked_add(4093) {
            xs.push(f32::from_bits(bits));
            bits = next;
        }
        for b in [
            0x7f80_0000u32,
            0xff80_0000,
            0x7fc0_0000,
            0x4120_0000,
            0x3f0c_9f54,
        ] {
            xs.push(f32::from_bits(b));
            xs.push(f32::from_bits(b + 1));
            xs.push(f32::from_bits(b - 1));
        }
        let mut ys = xs.clone();
        tanhf_in_place(&mut ys);
        for (x, y) in xs.iter().zip(&ys) {
            let want = libm::tanhf(*x);
            if want.is_nan() {
                assert!(y.is_nan(), "tanhf({x:e}) = {y:e}, libm NaN");
            } else {
                assert_eq!(
                    y.to_bits(),
                    want.to_bits(),
                    "tanhf({x:e}) = {y:e}, libm {want:e}"
                );
            }
        }
    }

    /// Every one of the 2^32 inputs (about a minute in release; run by hand:
    /// `cargo test --release -p vsr --lib tanh_lanes -- --ignored`).
    #[test]
    #[ignore]
    fn matches_libm_on_every_input() {
        let mut chunk = vec![0.0f32; 1 << 16];
        for high in 0..=u16::MAX as u32 {
            for (low, x) in chunk.iter_mut().enumerate() {
                *x = f32::from_bits(high << 16 | low as u32);
            }
            let mut ys = chunk.clone();
            tanhf_in_place(&mut ys);
            for (x, y) in chunk.iter().zip(&ys) {
                let want = libm::tanhf(*x);
                assert!(
                    y.to_bits() == want.to_bits() || (want.is_nan() && y.is_nan()),
                    "tanhf({x:e}) = {y:e}, libm {want:e}"
                );
            }
        }
    }
}
