"""Evolves a controller with CMA-ES (pycma) through vsr.evaluate, then validates it.

Each generation, CMA-ES's candidates walk 30 s on one fresh hilly terrain (hilly-1-10-G for
generation G, sensor noise seeded by G), all of them at once on every core; the velocity is
the fitness (cma minimises, so it is told -velocity). At the end, the mean of the search
distribution (CMA-ES's estimate of the optimum) is validated by `vsr.validate` on the paper's
ten terrains (hilly-1-10-0..9 with the command line's noise seeds: exactly what `vsr validate
--set paper` prints for the run file), and is written as a run file that `vsr evaluate
--genome` and the page replay.

    python python/examples/cma_evolve.py                      # 73 genes, 3000 evaluations
    python python/examples/cma_evolve.py --evaluations 30000 --out best.json
"""

import argparse
import time
import warnings

import numpy as np

warnings.filterwarnings("ignore", message="Could not import matplotlib")  # pycma's plots
import cma  # noqa: E402

import vsr


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--shape", default="biped-4x3")
    parser.add_argument("--controller", default="attention")
    parser.add_argument("--evaluations", type=int, default=3000)
    parser.add_argument("--seconds", type=float, default=30.0)
    parser.add_argument("--sigma", type=float, default=0.5, help="CMA-ES's initial step size")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--threads", type=int, default=None, help="default: all cores")
    parser.add_argument("--out", default=None, help="write the result as a run file")
    args = parser.parse_args()

    genes = vsr.param_count(args.shape, args.controller)
    options = {"seed": args.seed, "maxfevals": args.evaluations, "verbose": -9}
    es = cma.CMAEvolutionStrategy(np.zeros(genes), args.sigma, options)
    start, generation, evaluations = time.perf_counter(), 0, 0
    while not es.stop():
        candidates = np.array(es.ask())
        velocities = vsr.evaluate(
            candidates, args.shape, args.controller, f"hilly-1-10-{generation}",
            seconds=args.seconds, threads=args.threads, noise_seed=generation,
        )
        # an exploded episode (NaN) is the worst
        es.tell(list(candidates), list(-np.nan_to_num(velocities, nan=-np.inf)))
        generation, evaluations = generation + 1, evaluations + len(candidates)
        if generation % 20 == 0:
            print(f"generation {generation:4d}  evaluations {evaluations:6d}  "
                  f"best {np.nanmax(velocities):.3f} m/s  median {np.nanmedian(velocities):.3f}")
    wall = time.perf_counter() - start

    mean = es.result.xfavorite
    result = vsr.validate(mean, args.shape, args.controller, set="paper", seconds=args.seconds)
    validation = result["velocities"]
    print(f"{args.shape} {args.controller} ({genes} genes), CMA-ES popsize {es.popsize}: "
          f"{evaluations} evaluations in {generation} generations, {wall:.1f} s "
          f"({evaluations / wall:.0f} evaluations/s)")
    print(f"validation on hilly-1-10-0..9: mean {result['mean']:.3f} m/s, "
          f"median {result['median']:.3f}, min {validation.min():.3f}, "
          f"max {validation.max():.3f}")
    if args.out:
        # its episodes as evolved: `seconds` long on the hilly-1-10 family's terrains
        run = vsr.new_run(mean, args.shape, args.controller, fitness=result["mean"],
                          seed=args.seed, evaluations=evaluations, seconds=args.seconds,
                          terrain="hilly-1-10")
        vsr.save_run(args.out, run)
        print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
