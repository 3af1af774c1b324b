"""Run files: the JSON document ``vsr evolve`` writes and ``vsr evaluate`` and the page read.
The engine checks and prints them (``vsr._vsr.check_run``), so a file written here is
byte for byte what ``vsr`` would write for the same run; genomes come back as float32
arrays."""

import json
import os
import tempfile

import numpy as np

from . import _vsr
from ._arrays import genes


def _arrays(run):
    """`run` with its genomes as float32 arrays (best and, for fine-tuning, the source)."""
    run["best"]["genome"] = np.asarray(run["best"]["genome"], dtype=np.float32)
    source = run["config"].get("source")
    if source is not None:
        source["genome"] = np.asarray(source["genome"], dtype=np.float32)
    return run


def _lists(value):
    """JSON-ready copy: arrays as lists of Python floats (exact for float32 genes)."""
    if isinstance(value, dict):
        return {k: _lists(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [_lists(v) for v in value]
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    return value


def load_run(path):
    """The run file at `path` as a dict, checked as ``vsr evaluate`` checks it."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    try:
        checked = _vsr.check_run(text)
    except ValueError as e:
        # worded as `vsr` words it: the file, then the engine's message ("invalid input" once)
        message = str(e).removeprefix("invalid input: ")
        raise ValueError(f"invalid input: {path}: {message}") from None
    return _arrays(json.loads(checked))


def save_run(path, run):
    """Writes the run `run` (a dict as load_run or new_run give) to `path`, checked first,
    atomically: a temporary file in the same folder, then renamed. The folder must exist."""
    text = _vsr.check_run(json.dumps(_lists(run), allow_nan=False))
    folder = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(folder):
        # said of the path given, not of the temporary file mkstemp would name
        raise FileNotFoundError(f"cannot write run file {os.fspath(path)}: its folder {folder} "
                                "does not exist")
    fd, tmp = tempfile.mkstemp(prefix=".run-", suffix=".tmp", dir=folder)
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


def new_run(genome, shape, controller, fitness=None, seed=0, evaluations=0, seconds=30.0,
            terrain="hilly-1-10"):
    """A run (dict) for a genome found outside the engine, e.g. by CMA-ES: the paper's set-up
    for `shape` and `controller` as its configuration (seed `seed`, a budget of `evaluations`,
    at least one GA population), its episodes `seconds` long on `terrain` (a family such as
    hilly-1-10, or one terrain such as flat), no generation records, `genome` as its best with
    `fitness`. ``vsr evaluate --genome FILE`` and the page replay it once saved, for
    `seconds` unless told otherwise."""
    values = [float(g) for g in genes(np.ravel(genome), 1, "the genome")]
    text = _vsr.new_run(values, shape, controller, fitness, seed, evaluations, seconds, terrain)
    return _arrays(json.loads(text))
