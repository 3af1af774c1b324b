"""Power of the fourth question's tests (docs/ANALYSIS-PLAN.md, "One brain for every body").

Stdlib only, fixed seed. Samples are normal with unit spread; the true effect is given as A12
(the probability that a run of the first condition beats one of the second), i.e. a shift of
sqrt(2) Phi^-1(A12) spreads. The test is the one-sided Mann-Whitney U (normal approximation
with continuity correction; no ties in continuous data) at Holm's first step, 0.0125
(one-sided, two tests at 0.025), and at its last, 0.025.

    python3 study/plan/any_body_power.py
"""

import math
import random
from statistics import NormalDist

N = NormalDist()


def p_greater(x, y):
    n1, n2 = len(x), len(y)
    u = sum((a > b) + 0.5 * (a == b) for a in x for b in y)
    sd = math.sqrt(n1 * n2 * (n1 + n2 + 1) / 12)
    return 1 - N.cdf((u - n1 * n2 / 2 - 0.5) / sd)


def power(a12, n, alpha, reps=4000):
    shift = math.sqrt(2) * N.inv_cdf(a12)
    hits = 0
    for _ in range(reps):
        x = [random.gauss(shift, 1) for _ in range(n)]
        y = [random.gauss(0, 1) for _ in range(n)]
        hits += p_greater(x, y) < alpha
    return hits / reps


if __name__ == "__main__":
    random.seed(2026)
    print("seeds  A12   power at 0.0125  power at 0.025")
    for n in (8, 10, 12, 15):
        for a12 in (0.75, 0.8, 0.85, 0.9):
            print(f"{n:>5}  {a12:.2f}  {power(a12, n, 0.0125):>15.2f}  {power(a12, n, 0.025):>14.2f}")
