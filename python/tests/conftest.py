"""Shared helpers: the `vsr` binary the package is checked against, random robots."""

import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

import vsr

ROOT = pathlib.Path(__file__).resolve().parents[2]
CONTROLLERS = ["attention", "mlp", "mlp-comm", "slow-attention", "mlp-comm-latched"]


@pytest.fixture(scope="session")
def vsr_bin():
    """The command line built from this checkout (`make test-python` builds it)."""
    path = pathlib.Path(os.environ.get("VSR_BIN", ROOT / "target" / "release" / "vsr"))
    if not path.exists():
        pytest.fail(f"{path} is missing: build it with `cargo build --release --bin vsr`")
    return str(path)


def cli(vsr_bin, *args):
    """Runs `vsr ARGS`; returns (exit code, stdout, stderr)."""
    done = subprocess.run([vsr_bin, *args], capture_output=True, text=True, timeout=300)
    return done.returncode, done.stdout, done.stderr


def cli_evaluate(vsr_bin, tmp_path, genome, shape, controller, terrain, seconds, noise_seed=0):
    """The JSON `vsr evaluate` prints for `genome`, given to it as a run file."""
    path = tmp_path / f"run-{abs(hash(genome.tobytes()))}.json"
    vsr.save_run(path, vsr.new_run(genome, shape, controller))
    code, out, err = cli(
        vsr_bin, "evaluate", "--genome", str(path), "--terrain", terrain,
        "--seconds", repr(seconds), "--noise-seed", str(noise_seed),
    )
    assert code == 0, err
    return json.loads(out)


def random_shape(rng, max_voxels=9):
    """A random 4-connected shape of 2..max_voxels voxels, grown cell by cell, as rows."""
    cells = {(0, 0)}
    target = int(rng.integers(2, max_voxels + 1))
    while len(cells) < target:
        x, y = list(cells)[int(rng.integers(len(cells)))]
        dx, dy = [(1, 0), (-1, 0), (0, 1), (0, -1)][int(rng.integers(4))]
        cells.add((x + dx, y + dy))
    xs, ys = [c[0] for c in cells], [c[1] for c in cells]
    rows = []
    for y in range(max(ys), min(ys) - 1, -1):
        rows.append("".join("1" if (x, y) in cells else "0" for x in range(min(xs), max(xs) + 1)))
    return "-".join(rows)
