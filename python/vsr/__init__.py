"""VSR Playground's engine from Python: voxel-based soft robots whose every voxel runs the
same small controller (local self-attention, MLP, MLP-Comm), simulated as the paper's
simulator does (Pigozzi, Tang, Medvet, Ha, GECCO 2022), bit for bit as the `vsr` command.

- ``param_count(shape, controller)``: a controller's genome length.
- ``evaluate(genomes, shape, controller, terrain, ...)``: velocities of many genomes (one per
  row; a 1-D genome is one row), on every core with the GIL released, each what ``vsr
  evaluate`` prints.
- ``evaluate_bodies(shapes, genomes, controller, terrain, ...)``: one body per genome (a
  body search of your own), or one genome for every body (a brain for any body:
  ``attention-any``, ``mlp-any``, ``mlp-comm-any``), each what ``vsr evaluate`` prints.
- ``codesign(brain, evals, seed, ...)``: ``vsr codesign``, bit for bit: a gallery of bodies
  searched around a brain (a pretrained module frozen or fine-tuned, or one from scratch).
- ``simulate(genome, ...)``: one episode, with its trajectory on request.
- ``validate(genome, ...)``, ``ablate(genome, ...)``: ``vsr validate`` and ``vsr ablate``,
  bit for bit (validation uses each terrain's own noise seed, returned in ``noise_seeds``);
  ``validate(genome, controller=..., bodies=...)`` is ``vsr validate --bodies``: a brain for
  any body on every body of a set; ``read_bodies(path)`` reads a body-set file.
- ``Episode``: an episode stepped from Python (``reset`` / ``step``, gymnasium-style) for a
  controller of your own; ``Controller``: the engine's controllers, asked from Python;
  ``vsr.gym.WalkEnv``: a ``gymnasium.Env`` (the ``gym`` extra).
- ``load_run``, ``save_run``, ``new_run``: run files, the format of ``vsr`` and the page.

Bad input raises ``ValueError`` with the command line's message; an episode whose simulation
became non-finite raises ``UnstableError`` (``evaluate`` gives NaN for it instead).
"""

import json as _json
import os as _os

import numpy as _np

from . import _vsr
from ._arrays import genes as _genes
from ._arrays import text as _text
from ._vsr import Controller, Episode, UnstableError, param_count
from .runfile import load_run, new_run, save_run

__all__ = [
    "Controller",
    "Episode",
    "UnstableError",
    "ablate",
    "codesign",
    "evaluate",
    "evaluate_bodies",
    "load_run",
    "new_run",
    "param_count",
    "read_bodies",
    "save_run",
    "simulate",
    "validate",
]

__version__ = "0.1.0"


def _robot(shape, controller):
    """`shape` and `controller`, each a string (else a TypeError naming it)."""
    return _text(shape, "shape", "biped-4x3"), _text(controller, "controller", "attention")


def evaluate(genomes, shape, controller, terrain, seconds=30.0, threads=None, noise_seed=0):
    """Velocity (m/s, float64) of each row of `genomes` driving `controller` on `shape` over
    `terrain` for `seconds`, with sensor noise seeded by `noise_seed`: row i gives exactly
    what ``vsr evaluate`` prints for that genome (``--noise-seed`` defaults to 0 there too).
    A 1-D `genomes` is one genome: an array of one velocity. Runs on `threads` threads (all
    cores when None) with the GIL released; a large batch runs in chunks (32 episodes per
    thread), Ctrl-C stops it between two, and each logs its progress ("vsr" logger, INFO).
    Genes are float32 (a float64 array is rounded to float32 once, as a run file stores
    them). An episode whose simulation became non-finite gives NaN."""
    genomes = _np.asarray(genomes)
    if genomes.ndim == 1:
        genomes = genomes[None, :]
    genomes = _genes(genomes, 2, "genomes")
    return _vsr.evaluate(genomes, *_robot(shape, controller), _text(terrain, "terrain", "flat"),
                         seconds, threads, noise_seed)


def evaluate_bodies(shapes, genomes, controller, terrain, seconds=30.0, threads=None, noise_seed=0):
    """Velocity (m/s, float64) of each robot: ``genomes[i]`` driving `controller` on
    ``shapes[i]`` (a preset or rows, e.g. ``"110-111"``) over `terrain` for `seconds`, each
    exactly what ``vsr evaluate`` prints for that body and genome. For a body search of your
    own: bodies differ, so genomes differ in length (``param_count(shape, controller)``).
    `genomes` may also be ONE genome (a 1-D array) that drives every body: a brain for any
    body (``attention-any``, ``mlp-any``, ``mlp-comm-any``: the same length on every body),
    or, for the other controllers, bodies of one size only (else a ValueError that says so).
    Runs on `threads` threads (all cores when None) with the GIL released, in chunks as
    ``evaluate`` (Ctrl-C, progress on the "vsr" logger); NaN where an episode exploded."""
    shapes = _shapes(shapes)
    controller = _text(controller, "controller", "attention-any")
    terrain = _text(terrain, "terrain", "flat")
    if _is_one_genome(genomes):
        genome = _genes(genomes, 1, "the genome")
        return _vsr.evaluate_bodies(shapes, [genome], controller, terrain, seconds, threads,
                                    noise_seed, True)
    genomes = [_genes(g, 1, f"genome {i}") for i, g in enumerate(genomes)]
    return _vsr.evaluate_bodies(shapes, genomes, controller, terrain, seconds, threads,
                                noise_seed, False)


def _shapes(shapes):
    """`shapes` as a list of strings (a TypeError naming the first that is not one)."""
    if isinstance(shapes, (str, bytes)) or not hasattr(shapes, "__iter__"):
        raise TypeError(f"shapes must be a list of shapes (presets or rows such as '110-111'), "
                        f"got {shapes!r:.60}; a body-set file's: vsr.read_bodies(path)")
    return [_text(s, f"shape {i}", "110-111") for i, s in enumerate(shapes)]


def _is_one_genome(genomes):
    """True when `genomes` is one genome (a 1-D array, or a list of numbers), not one per
    body (a 2-D array, or a list of arrays)."""
    if isinstance(genomes, _np.ndarray):
        return genomes.ndim == 1
    if isinstance(genomes, (list, tuple)):
        return len(genomes) > 0 and all(_np.ndim(g) == 0 for g in genomes)
    return False


def read_bodies(path):
    """The bodies of the body-set file at `path` (a list of rows, top first, e.g.
    ``"1111-1111-1001"``), read as ``vsr evolve --bodies`` and ``vsr validate --bodies``
    read it: one body per line (a preset or rows), ``#`` before a comment, blank lines
    skipped. An empty or damaged file raises ValueError with the command line's message
    (naming the file and the line); a missing one FileNotFoundError."""
    return _vsr.read_bodies(_os.fspath(path))


def validate(genome, shape=None, controller=None, set="paper", seconds=30.0, bodies=None,
             threads=None):
    """``vsr validate`` of `genome`, bit for bit: its velocity on the set's ten terrains,
    ``paper`` (hilly-1-10-0..9) or ``unseen`` (hilly-1-10-10000..10009), each with the
    sensor-noise seed the command line gives that terrain (not 0). A dict: ``set``,
    ``terrains`` (names), ``noise_seeds`` (``evaluate(..., terrain, noise_seed=s)`` repeats
    one episode), ``velocities`` (float64 array), ``median``, ``mean``. Raises UnstableError
    if an episode explodes.

    With `bodies` (a body-set file's path, or a list of bodies: presets or rows), ``vsr
    validate --bodies``: a brain for any body (``attention-any``, ``mlp-any``,
    ``mlp-comm-any``; `shape` not needed) walked on every body of the set, the bodies spread
    over `threads` threads (all cores when None; the figures never depend on it). A dict:
    ``name`` (the file's name), ``set``, ``terrains``, ``noise_seeds``, ``seconds``,
    ``per_body`` (one dict per body, in the set's order: ``body`` as rows, ``velocities``,
    ``median``, ``mean``), ``means`` (float64 array, each body's mean), ``median`` (the median
    of those means) and ``walking_share`` (the share of bodies whose mean is above 1 m/s).
    A controller tied to its body (attention, mlp, ...) is refused in words unless every
    body of the set is `shape`, its own body."""
    genome = _genes(genome, 1, "the genome")
    controller = _text(controller, "controller", "attention")
    set = _text(set, "set", "unseen")
    if bodies is None:
        return _vsr.validate(genome, _text(shape, "shape", "biped-4x3"), controller, set,
                             seconds)
    if shape is not None:
        shape = _text(shape, "shape", "biped-4x3")
    if isinstance(bodies, _os.PathLike):
        bodies = _os.fspath(bodies)
    return _vsr.validate_bodies(genome, shape, controller, bodies, set, seconds, threads)


def ablate(genome, shape, controller, terrain="hilly-1-10-0", last_second=30, seconds=30.0):
    """``vsr ablate`` of an attention or slow-attention `genome`, bit for bit: ``unfrozen``,
    its velocity (m/s) over `seconds` on `terrain` with its attention live; ``velocities``
    (float64 array), one per second s in ``freeze_seconds`` (0..last_second), the velocity of
    a fresh walk with every voxel's attention matrix held at what it was s seconds into the
    unfrozen walk. The sensor noise of every walk is seeded as ``validate`` seeds
    hilly-1-10-K for `terrain` hilly-1-10-K, as it seeds hilly-1-10-0 for any other."""
    genome = _genes(genome, 1, "the genome")
    return _vsr.ablate(genome, *_robot(shape, controller), _text(terrain, "terrain", "flat"),
                       last_second, seconds)


def simulate(genome, shape, controller, terrain, seconds=30.0, noise_seed=0, trajectory=False):
    """One episode of `genome`, as ``vsr evaluate`` runs it: a dict with ``velocity``,
    ``distance``, ``steps`` and ``seconds``; with `trajectory`, also ``time`` (steps,),
    ``centre`` (steps, 2) and ``corners`` (steps, voxels, 4, 2): every voxel's outer corners
    SW, SE, NE, NW after every step (m). Raises UnstableError if the simulation explodes."""
    genome = _genes(genome, 1, "the genome")
    return _vsr.simulate(genome, *_robot(shape, controller), _text(terrain, "terrain", "flat"),
                         seconds, noise_seed, trajectory)


def codesign(brain, evals, seed, module=None, controller="attention", start=None, seconds=30.0,
             terrain="hilly-1-10", grid=None, voxels=None, batch=None, threads=None, out=None,
             entry=None):
    """``vsr codesign`` from Python, bit for bit: a body search around a brain, ``brain``
    ``"frozen"`` (the attention block of `module`, a pretrained attention module's run file
    path, held fixed; bodies and per-voxel genes evolve; a co-design run file's best body, or
    its archive `entry`), ``"finetune"`` (the module as the
    start, every gene evolves) or ``"scratch"`` (a `controller` from random). The search
    starts from `start` (a preset or rows; default the module's own body, or a 3 x 3 box),
    inside a `grid` of (width, height) cells, bodies of `voxels` (min, max); `batch` new
    bodies per iteration; `evals` evaluations of `seconds` on `terrain`. Runs on `threads`
    threads (all cores when None) with the GIL released: any count gives the same result.
    Each iteration logs the command line's progress line ("vsr" logger, INFO: shown after
    ``logging.basicConfig(level=logging.INFO)``); Ctrl-C stops it between iterations.
    Returns the co-design run file as a dict (``archive``: the gallery, each entry with
    ``shape``, ``genome``, ``fitness``, ``cell``; ``best``; ``history``), genomes as float32
    arrays; with `out`, also writes it there (``vsr evaluate --genome OUT --entry I``
    replays entry I). Bad settings, or a module that cannot drive other bodies (not
    attention), raise ValueError in words."""
    text = None
    if module is not None:
        with open(_os.fspath(module), encoding="utf-8") as f:
            text = f.read()
    run_text = _vsr.codesign(_text(brain, "brain", "frozen"), evals, seed, text,
                             _text(controller, "controller", "attention"),
                             None if start is None else _text(start, "start", "box-3x3"),
                             seconds, _text(terrain, "terrain", "hilly-1-10"), grid, voxels,
                             batch, threads, entry)
    if out is not None:
        with open(_os.fspath(out), "w", encoding="utf-8") as f:
            f.write(run_text)
    run = _json.loads(run_text)
    for entry in [run["best"], *run["archive"]]:
        entry["genome"] = _np.asarray(entry["genome"], dtype=_np.float32)
    return run
