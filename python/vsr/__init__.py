"""VSR Playground's engine from Python: voxel-based soft robots whose every voxel runs the
same small controller (local self-attention, MLP, MLP-Comm), simulated as the paper's
simulator does (Pigozzi, Tang, Medvet, Ha, GECCO 2022), bit for bit as the `vsr` command.

- ``param_count(shape, controller)``: a controller's genome length.
- ``evaluate(genomes, shape, controller, terrain, ...)``: velocities of many genomes (one per
  row), on every core with the GIL released, each what ``vsr evaluate`` prints.
- ``simulate(genome, ...)``: one episode, with its trajectory on request.
- ``Episode``: an episode stepped from Python (``reset`` / ``step``, gymnasium-style) for a
  controller of your own; ``Controller``: the engine's controllers, asked from Python.
- ``load_run``, ``save_run``, ``new_run``: run files, the format of ``vsr`` and the page.

Bad input raises ``ValueError`` with the command line's message; an episode whose simulation
became non-finite raises ``UnstableError`` (``evaluate`` gives NaN for it instead).
"""

import numpy as np

from . import _vsr
from ._vsr import Controller, Episode, UnstableError, param_count
from .runfile import load_run, new_run, save_run

__all__ = [
    "Controller",
    "Episode",
    "UnstableError",
    "evaluate",
    "load_run",
    "new_run",
    "param_count",
    "save_run",
    "simulate",
]

__version__ = "0.1.0"


def _genes(array, ndim, what):
    """`array` as C-contiguous float32 of `ndim` dimensions: no copy when it already is."""
    array = np.asarray(array)
    if array.ndim != ndim:
        shape = "a 2-D array, one genome per row" if ndim == 2 else "a 1-D array"
        raise ValueError(f"invalid input: {what} must be {shape}, got shape {array.shape}")
    return np.ascontiguousarray(array, dtype=np.float32)


def evaluate(genomes, shape, controller, terrain, seconds=30.0, threads=None, noise_seed=0):
    """Velocity (m/s, float64) of each row of `genomes` driving `controller` on `shape` over
    `terrain` for `seconds`, with sensor noise seeded by `noise_seed`: row i gives exactly
    what ``vsr evaluate`` prints for that genome (``--noise-seed`` defaults to 0 there too).
    Runs on `threads` threads (all cores when None) with the GIL released. Genes are float32
    (a float64 array is rounded to float32 once, as a run file stores them). An episode
    whose simulation became non-finite gives NaN."""
    genomes = _genes(genomes, 2, "genomes")
    return _vsr.evaluate(genomes, shape, controller, terrain, seconds, threads, noise_seed)


def simulate(genome, shape, controller, terrain, seconds=30.0, noise_seed=0, trajectory=False):
    """One episode of `genome`, as ``vsr evaluate`` runs it: a dict with ``velocity``,
    ``distance``, ``steps`` and ``seconds``; with `trajectory`, also ``time`` (steps,),
    ``centre`` (steps, 2) and ``corners`` (steps, voxels, 4, 2): every voxel's outer corners
    SW, SE, NE, NW after every step (m). Raises UnstableError if the simulation explodes."""
    genome = _genes(genome, 1, "the genome")
    return _vsr.simulate(genome, shape, controller, terrain, seconds, noise_seed, trajectory)
