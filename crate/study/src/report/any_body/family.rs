//! The tables of families 11 and 12 (docs/ANALYSIS-PLAN.md, the fourth question and its
//! amendments), from the runs' primary measures: each family Holm over its two one-sided
//! Mann-Whitney tests at [`ONE_SIDED_ALPHA`], a row per test with the Hodges-Lehmann shift
//! (two-sided 95% interval), A12 (95% bootstrap interval), p and Holm p, and the answer in
//! the plan's words. A superiority test that detects nothing gives the smallest A12 it
//! detects with 80% power (`detectable_a12` at two-sided 0.05, the same rejections in the
//! tested direction as one-sided 0.025). Family 11's non-inferiority test is worded as
//! family 8's ([`Verdict::words`]); where it is shown, its superiority is tested next at
//! 0.025 (the plan's closed step) and also at the level Holm leaves (amendment 3).

use crate::report::families::{ALPHA, POWER};
use crate::report::noninferiority::{Verdict, ONE_SIDED_ALPHA};
use crate::statistics::{
    a12_interval, detectable_a12, hodges_lehmann, holm, mann_whitney, mann_whitney_greater,
    noninferiority, Method, OneSidedU,
};
use std::fmt::Write;
use vsr::controllers::ControllerKind;

/// The non-inferiority margin of family 11 (m/s), fixed in the plan.
pub const MARGIN: f64 = 0.2;

/// What the tables say about their numbers, printed once above them.
pub(super) const LEGEND: &str =
    "Every test one-sided at alpha 0.025, Holm over the family's two tests. Shift: \
     Hodges-Lehmann, A - B (m/s), with its two-sided 95% interval (its lower end is the \
     one-sided 97.5% bound); A12 = P(A > B) with its 95% bootstrap interval; p: one-sided \
     Mann-Whitney U, (e) exact (both samples at most 20 values, no tie), (n) normal \
     approximation with tie correction; a \"no difference detected\" gives the smallest A12 \
     the test detects with 80% power at these sample sizes (one-sided 0.025).\n\n";

/// One sample: its label and the runs' primary measures.
pub(super) type Sample<'a> = (&'a str, &'a [f64]);

/// A p value with how it was computed: four decimals, or two significant digits below 0.001
/// (so a small exact p never reads 0.0000).
pub(super) fn p_text(p: f64) -> String {
    if p < 0.001 {
        format!("{p:.1e}")
    } else {
        format!("{p:.4}")
    }
}

fn method(u: &OneSidedU) -> &'static str {
    match u.method {
        Method::Exact => "e",
        Method::Normal => "n",
    }
}

/// "better" or "not shown better" of a superiority p at `level`.
fn better_at(p: f64, level: f64) -> &'static str {
    if p < level {
        "**better**"
    } else {
        "not shown better"
    }
}

/// The answer of a superiority test: "difference detected" where Holm allows, otherwise "no
/// difference detected" with the smallest effect the test detects.
fn faster(holm_p: f64, x: &[f64], y: &[f64]) -> String {
    if holm_p < ONE_SIDED_ALPHA {
        "**faster** (difference detected)".into()
    } else {
        let d = detectable_a12(x.len(), y.len(), ALPHA, POWER);
        if d.smallest_p >= ALPHA {
            "no difference detected (samples this small cannot reach p below 0.025)".into()
        } else {
            format!(
                "no difference detected (detects A12 of {:.2} or more with 80% power)",
                d.a12
            )
        }
    }
}

/// The row's cells up to its p: what, n, shift, A12 (A12 and shift of `x` against `y`).
fn cells(what: &str, x: &[f64], y: &[f64], u: &OneSidedU, holm_p: f64) -> String {
    let shift = hodges_lehmann(x, y, ALPHA).map_or("-".into(), |s| {
        format!(
            "{:+.2} [{:+.2}, {:+.2}]",
            s.estimate, s.interval.low, s.interval.high
        )
    });
    let a12 = a12_interval(x, y, ALPHA).map_or("-".into(), |i| {
        format!(
            "{:.2} [{:.2}, {:.2}]",
            mann_whitney(x, y).a12,
            i.low,
            i.high
        )
    });
    format!(
        "| {what} | {} against {} | {shift} | {a12} | {} ({}) | {} |",
        x.len(),
        y.len(),
        p_text(u.p),
        method(u),
        p_text(holm_p)
    )
}

fn header(md: &mut String) {
    md.push_str(
        "| test (H1) | n | shift (m/s) [95%] | A12 [95%] | p (one-sided) | Holm p | answer |\n\
         |---|---|---|---|---|---|---|\n",
    );
}

/// Family 11: attention-any (`a`) faster than mlp-any (`m`); attention-any not slower than
/// mlp-comm-any (`c`, of family `comm`) by [`MARGIN`] or more, then better.
pub(super) fn family11(a: Sample, m: Sample, c: Sample, comm: ControllerKind, md: &mut String) {
    let (x, y, z) = (a.1, m.1, c.1);
    let sup = mann_whitney_greater(x, y);
    let ni = noninferiority(x, z, MARGIN);
    let adjusted = holm(&[sup.p, ni.p]);
    let high = hodges_lehmann(x, z, ALPHA).map_or(f64::NAN, |s| s.interval.high);
    let verdict = Verdict::of(adjusted[1], high, MARGIN);
    header(md);
    let what = format!("(i) {} faster than {}", a.0, m.0);
    let _ = writeln!(
        md,
        "{} {} |",
        cells(&what, x, y, &sup, adjusted[0]),
        faster(adjusted[0], x, y)
    );
    let what = format!(
        "(ii) {} not slower than {} by {MARGIN} m/s or more",
        a.0, c.0
    );
    let mut answer = verdict.words(comm, MARGIN);
    let step = (verdict == Verdict::NotWorse).then(|| mann_whitney_greater(x, z));
    if let Some(u) = &step {
        let _ = write!(
            answer,
            "; then faster than {} (one-sided p {} ({})): {} at 0.025",
            c.0,
            p_text(u.p),
            method(u),
            better_at(u.p, ONE_SIDED_ALPHA)
        );
    }
    let _ = writeln!(md, "{} {answer} |", cells(&what, x, z, &ni, adjusted[1]));
    md.push('\n');
    match step {
        Some(u) => {
            // Holm's first step is at alpha / 2; the second at alpha once (i) is rejected.
            let level = if adjusted[0] < ONE_SIDED_ALPHA {
                ONE_SIDED_ALPHA
            } else {
                ONE_SIDED_ALPHA / 2.0
            };
            let _ = writeln!(
                md,
                "The closed step of (ii), superiority once non-inferiority is shown: at 0.025 as \
                 planned, {}; at the level Holm leaves ({level}, as (i) is {}rejected), {}. Both are given because the planned step can raise the family's chance of \
                 a false finding above 0.025 (with no true difference, 10 against 10: 0.035 to \
                 0.044 in a simulation of the exact tests; the plan's amendment 3); \
                 docs/RESULTS.md words a \"better\" only where both agree.\n",
                better_at(u.p, ONE_SIDED_ALPHA),
                if adjusted[0] < ONE_SIDED_ALPHA { "" } else { "not " },
                better_at(u.p, level)
            );
        }
        None => md.push_str(
            "The closed step of (ii), superiority, is not tested: non-inferiority is not \
             shown.\n\n",
        ),
    }
}

/// Family 12: `larger` faster than `main`, `main` faster than `one` (superiority each).
pub(super) fn family12(larger: Sample, main: Sample, one: Sample, md: &mut String) {
    let t1 = mann_whitney_greater(larger.1, main.1);
    let t2 = mann_whitney_greater(main.1, one.1);
    let adjusted = holm(&[t1.p, t2.p]);
    header(md);
    for ((x, y, u), h) in [(larger, main, t1), (main, one, t2)].iter().zip(&adjusted) {
        let what = format!("{} faster than {}", x.0, y.0);
        let _ = writeln!(
            md,
            "{} {} |",
            cells(&what, x.1, y.1, u, *h),
            faster(*h, x.1, y.1)
        );
    }
    md.push('\n');
}

#[cfg(test)]
mod tests {
    use super::*;

    const ATTENTION: [f64; 5] = [1.0, 1.1, 1.2, 1.3, 1.4];

    fn table11(y: &[f64], z: &[f64]) -> String {
        let mut md = String::new();
        let a = ("att", &ATTENTION[..]);
        family11(
            a,
            ("mlp", y),
            ("comm", z),
            ControllerKind::MlpCommAny,
            &mut md,
        );
        md
    }

    /// 5 against 5 without ties is exact: complete separation has p = 1 / C(10, 5) = 1/252
    /// (scipy: mannwhitneyu([1,2,3,4,5], [0,0.1,...], alternative="greater") 0.003968), and
    /// Holm over two equal p doubles both: 2/252 = 0.0079.
    #[test]
    fn not_worse_then_better_with_holm_p() {
        let y = [0.1, 0.2, 0.3, 0.4, 0.5];
        let z = [0.15, 0.25, 0.35, 0.45, 0.55];
        assert!((mann_whitney_greater(&ATTENTION, &y).p - 1.0 / 252.0).abs() < 1e-15);
        let md = table11(&y, &z);
        let rows: Vec<&str> = md.lines().filter(|l| l.starts_with("| (")).collect();
        assert_eq!(rows.len(), 2, "{md}");
        assert!(
            rows[0].contains("| 0.0040 (e) | 0.0079 | **faster**"),
            "{md}"
        );
        assert!(rows[1].contains("| 0.0040 (e) | 0.0079 | **not worse** than mlp-comm-any by 0.2 m/s or more (non-inferior); then faster than comm (one-sided p 0.0040 (e)): **better** at 0.025 |"), "{md}");
        assert!(
            md.contains("at 0.025 as planned, **better**; at the level Holm leaves (0.025, as (i) is rejected), **better**."),
            "{md}"
        );
    }

    #[test]
    fn not_worse_but_not_shown_better() {
        let y = [0.1, 0.2, 0.3, 0.4, 0.5];
        let z = [0.85, 0.95, 1.05, 1.15, 1.25];
        let md = table11(&y, &z);
        assert!(md.contains("(non-inferior); then faster than comm"), "{md}");
        assert!(md.contains("): not shown better at 0.025 |"), "{md}");
        assert!(
            md.contains("as planned, not shown better; at the level Holm leaves (0.025, as (i) is rejected), not shown better."),
            "{md}"
        );
    }

    #[test]
    fn worse_by_more_than_the_margin_and_no_closed_step() {
        let y: Vec<f64> = ATTENTION.iter().map(|v| v + 5.0).collect();
        let z = [3.0, 3.1, 3.2, 3.3, 3.4];
        let md = table11(&y, &z);
        assert!(md.contains("**worse** by more than the margin"), "{md}");
        assert!(
            md.contains("| 1.0000 (e) | 1.0000 | no difference detected (detects A12 of "),
            "{md}"
        );
        assert!(md.contains("superiority, is not tested"), "{md}");
    }

    /// Amendment 3: (i) not rejected leaves 0.0125 to the closed step; U1 = 23 of 25 has the
    /// exact p = 4/252 = 0.0159, below 0.025 but not 0.0125, so the two levels disagree.
    #[test]
    fn the_level_holm_leaves_can_disagree_with_the_planned_step() {
        let y: Vec<f64> = ATTENTION.iter().map(|v| v + 5.0).collect();
        let z = [0.1, 0.2, 0.3, 0.4, 1.15];
        let u = mann_whitney_greater(&ATTENTION, &z);
        assert_eq!((u.u1, u.method), (23.0, Method::Exact));
        assert!((u.p - 4.0 / 252.0).abs() < 1e-15);
        let md = table11(&y, &z);
        assert!(
            md.contains("(one-sided p 0.0159 (e)): **better** at 0.025 |"),
            "{md}"
        );
        assert!(md.contains("as planned, **better**; at the level Holm leaves (0.0125, as (i) is not rejected), not shown better."), "{md}");
    }

    #[test]
    fn family_12_and_a_small_p() {
        let ten: Vec<f64> = (0..10).map(|i| 2.0 + f64::from(i)).collect();
        let low: Vec<f64> = (0..10).map(f64::from).map(|v| v / 10.0).collect();
        let mut md = String::new();
        family12(("big", &ten), ("main", &low), ("one", &low), &mut md);
        // 10 against 10, complete separation: 1 / C(20, 10) = 1/184756 = 5.4e-6.
        assert!(
            md.contains("| big faster than main | 10 against 10 |"),
            "{md}"
        );
        assert!(md.contains("| 5.4e-6 (e) | 1.1e-5 | **faster**"), "{md}");
        assert!(md.contains("| main faster than one |"), "{md}");
        assert_eq!(p_text(0.0123456), "0.0123");
    }
}
