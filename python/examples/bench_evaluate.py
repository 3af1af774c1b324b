"""Evaluations per second through vsr.evaluate against `vsr`, on the same batch.

The batch: random genomes of the attention controller on biped-4x3, 30-s episodes on
hilly-1-10-0 (sensor noise seed 0), on `--threads` threads. Three ways, all giving the same
velocities (checked bit for bit):
- vsr.evaluate, from Python;
- the engine in Rust without Python (examples/native_batch.rs: the same `fitness` per genome
  on a rayon pool of the same size): the Python overhead is measured against this;
- `vsr evaluate`, which takes one genome (a run file) per process: one process per genome, as
  many at a time as there are threads.
The rounds alternate the three and the best round of each is kept (the host is shared).

    cargo build --release --bin vsr
    cargo build --release -p vsr-python --example native_batch
    python python/examples/bench_evaluate.py [--batch 64] [--rounds 3] [--threads N]
"""

import argparse
import json
import os
import pathlib
import subprocess
import tempfile
import time

import numpy as np

import vsr

ROOT = pathlib.Path(__file__).resolve().parents[2]
SHAPE, CONTROLLER, TERRAIN = "biped-4x3", "attention", "hilly-1-10-0"


def run_cli(binary, paths, threads, seconds):
    """Wall seconds for `vsr evaluate` on every path, `threads` processes at a time, and
    the velocities in path order."""
    args = ["evaluate", "--terrain", TERRAIN, "--seconds", repr(seconds)]
    start, running, outputs = time.perf_counter(), [], {}
    queue = list(enumerate(paths))
    while queue or running:
        while queue and len(running) < threads:
            i, path = queue.pop(0)
            proc = subprocess.Popen([binary, *args, "--genome", path], stdout=subprocess.PIPE)
            running.append((i, proc))
        i, proc = running.pop(0)
        outputs[i] = json.loads(proc.communicate()[0])["velocity"]
    return time.perf_counter() - start, np.array([outputs[i] for i in range(len(paths))])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--batch", type=int, default=64)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--threads", type=int, default=os.cpu_count())
    parser.add_argument("--binary", default=str(ROOT / "target" / "release" / "vsr"))
    parser.add_argument("--native", default=str(ROOT / "target" / "release" / "examples" /
                                                "native_batch"))
    args = parser.parse_args()

    genes = vsr.param_count(SHAPE, CONTROLLER)
    genomes = np.random.default_rng(1).uniform(-1, 1, (args.batch, genes)).astype(np.float32)
    with tempfile.TemporaryDirectory() as folder:
        paths = []
        for i, genome in enumerate(genomes):
            paths.append(os.path.join(folder, f"{i}.json"))
            vsr.save_run(paths[-1], vsr.new_run(genome, SHAPE, CONTROLLER))
        raw = os.path.join(folder, "genomes.f32")
        genomes.astype("<f4").tofile(raw)
        native_args = [args.native, raw, str(genes), SHAPE, CONTROLLER, TERRAIN,
                       str(args.threads), "1"]
        python, native, cli = [], [], []
        for _ in range(args.rounds):
            t = time.perf_counter()
            ours = vsr.evaluate(genomes, SHAPE, CONTROLLER, TERRAIN, threads=args.threads)
            python.append(time.perf_counter() - t)
            out = json.loads(subprocess.run(native_args, capture_output=True, check=True).stdout)
            native.append(out["seconds"])
            assert ours.tobytes() == np.array(out["velocities"]).tobytes(), "native differs"
            wall, theirs = run_cli(args.binary, paths, args.threads, 30.0)
            cli.append(wall)
            assert ours.tobytes() == theirs.tobytes(), "vsr evaluate differs"
    rates = [args.batch / min(t) for t in (python, native, cli)]
    print(f"batch of {args.batch} x 30-s {SHAPE} {CONTROLLER} on {TERRAIN}, {args.threads} "
          f"threads, best of {args.rounds} rounds; the same velocities all three ways")
    for name, rate in zip(["vsr.evaluate (Python)", "engine in Rust (native_batch)",
                           "vsr evaluate (a process each)"], rates):
        print(f"  {name:32s} {rate:7.1f} evaluations/s")
    print(f"Python overhead vs the engine in Rust: {100 * (1 - rates[0] / rates[1]):+.1f}% "
          f"(rounds: Python {', '.join(f'{t:.2f}' for t in python)} s; "
          f"Rust {', '.join(f'{t:.2f}' for t in native)} s)")


if __name__ == "__main__":
    main()
