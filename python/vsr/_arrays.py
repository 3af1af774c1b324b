"""Genomes from Python to the engine: any array-like of numbers as C-contiguous float32 (the
engine's and the run files' gene type), rounded once, with no copy when it already is one.
One rule for every entry point (``vsr.evaluate`` and the others, ``vsr.new_run``,
``vsr.Controller``): a finite number beyond float32's range, which would round to inf, is
refused with its value; NaN and inf are left to the engine's genome check, which names them."""

import numpy as np

FLOAT32_MAX = float(np.finfo(np.float32).max)


def genes(array, ndim, what):
    """`array` as C-contiguous float32 of `ndim` dimensions (2: one genome per row), named
    `what` in messages ("genomes", "the genome", "genome 3")."""
    if isinstance(array, dict):
        # a run file's dict (vsr.load_run) given where its genes belong
        raise TypeError(f"{what} must be an array of genes, got a dict (a run file? its genes are "
                        "run['best']['genome'])")
    array = np.asarray(array)
    if array.ndim != ndim:
        shape = ("a 2-D array, one genome per row (or a 1-D array, one genome)" if ndim == 2
                 else "a 1-D array")
        raise ValueError(f"invalid input: {what} must be {shape}, got shape {array.shape}")
    if array.dtype != np.float32 and array.size:
        _check_range(array, ndim, what)
    return np.ascontiguousarray(array, dtype=np.float32)


def _check_range(array, ndim, what):
    """A ValueError naming the first finite gene beyond float32's range, if any."""
    try:
        wide = np.asarray(array, dtype=np.float64)
    except (TypeError, ValueError):
        return  # not numbers: the float32 conversion says so
    too_big = np.flatnonzero(np.isfinite(wide) & (np.abs(wide) > FLOAT32_MAX))
    if too_big.size:
        at = np.unravel_index(too_big[0], wide.shape)
        where = f"gene {at[1]} of genome {at[0]}" if ndim == 2 else f"gene {at[0]} of {what}"
        raise ValueError(f"invalid input: {where} is {float(wide[at])!r}, out of float32's range "
                         f"(genes are float32: at most {FLOAT32_MAX:.7g} in magnitude)")


def text(value, what, example):
    """`value` if it is a string, else a TypeError that names the argument `what` (the
    engine's own conversion names none)."""
    if not isinstance(value, str):
        raise TypeError(f"{what} must be a string such as {example!r}, got {value!r}")
    return value
