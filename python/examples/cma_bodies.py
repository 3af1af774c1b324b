"""CMA-ES (pycma) against the paper's GA for a brain for any body, at equal evaluations.

The measurement behind the optimiser the fourth question's runs use (docs/ANALYSIS-PLAN.md):
attention for any body (attention-any) trained on campaigns/bodies/train-32.txt,
each evaluation the mean speed of 4 bodies drawn afresh on a fresh hilly-1-10 terrain, then
the final best walked on every body of heldout-random.txt on the ten unseen terrains; the GA's
figures come from the same setting in Rust (crate/engine/src/experiment/body_set/measure.rs, the
"neighbours+place" rows). Prints one line per seed. The plan's figures were measured when the
family read all seven local inputs (61 genes, the measurement's "neighbours+place"); run now, it
measures the family as it is (53 genes, the four neighbour flags).

    python python/examples/cma_bodies.py [--evaluations 2000] [--seconds 20] [--seeds 1 2]
"""

import argparse
import pathlib
import statistics

import numpy as np

import vsr

try:
    import cma
except ImportError as e:  # pragma: no cover - a message, not a trace
    raise SystemExit("this example needs pycma: pip install cma") from e

ROOT = pathlib.Path(__file__).resolve().parents[2]
CONTROLLER = "attention-any"


def bodies(name):
    lines = (ROOT / "campaigns" / "bodies" / name).read_text().splitlines()
    return [l.strip() for l in lines if l.strip() and not l.startswith("#")]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--evaluations", type=int, default=2000)
    p.add_argument("--seconds", type=float, default=20.0)
    p.add_argument("--per-evaluation", type=int, default=4)
    p.add_argument("--seeds", type=int, nargs="+", default=[1, 2])
    a = p.parse_args()
    train, heldout = bodies("train-32.txt"), bodies("heldout-random.txt")
    n = vsr.param_count("biped-4x3", CONTROLLER)
    print(f"CMA-ES, {CONTROLLER} ({n} genes), {a.evaluations} evaluations of "
          f"{a.per_evaluation} bodies, {a.seconds}-s episodes")
    print("seed  best training  held-out median (m/s)")
    for seed in a.seeds:
        rng = np.random.default_rng(seed)
        es = cma.CMAEvolutionStrategy(np.zeros(n), 0.5,
                                      {"seed": seed, "verbose": -9, "maxfevals": a.evaluations})
        best, best_f = None, -np.inf
        used = 0
        while used < a.evaluations:
            xs = es.ask()
            fs = []
            for x in xs:
                picked = rng.choice(len(train), a.per_evaluation, replace=False)
                terrain = f"hilly-1-10-{rng.integers(10000)}"
                v = vsr.evaluate_bodies([train[i] for i in picked], [x] * a.per_evaluation,
                                        CONTROLLER, terrain, seconds=a.seconds,
                                        noise_seed=int(rng.integers(2**31)))
                f = float(np.mean(v)) if np.all(np.isfinite(v)) else -10.0
                fs.append(f)
                if f > best_f:
                    best, best_f = np.array(x, dtype=np.float32), f
            used += len(xs)
            es.tell(xs, [-f for f in fs])
        # The distribution's mean is CMA-ES's own answer; keep the better of it and the best
        # seen by their held-out medians is NOT done (that would look at held-out data).
        means = [vsr.validate(best, b, CONTROLLER, set="unseen", seconds=a.seconds)["mean"]
                 for b in heldout]
        print(f"{seed:>4}  {best_f:>13.3f}  {statistics.median(means):>10.3f}")


if __name__ == "__main__":
    main()
