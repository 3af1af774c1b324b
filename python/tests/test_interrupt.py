"""Ctrl-C during a large ``vsr.evaluate``: the batch runs in chunks with Python's signals
looked at between them, so KeyboardInterrupt comes within a chunk, not once the whole batch
is done; the velocities of a batch do not depend on its chunks."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import vsr


def test_ctrl_c_stops_a_large_batch_within_a_chunk():
    # 3-s episodes (a few seconds of work here); a chunk is 32 per thread, the batch 100
    # chunks of one thread.
    genomes = np.random.default_rng(1).uniform(-1, 1, (3200, 73)).astype(np.float32)
    started = time.monotonic()
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            vsr.evaluate(genomes, "biped-4x3", "attention", "flat", seconds=3.0, threads=1)
    finally:
        timer.cancel()  # a batch that ended first must not be followed by a stray Ctrl-C
    stopped = time.monotonic() - started
    # Alone the batch takes about 100 times one chunk; stopped, it ends within a few chunks.
    whole = time.monotonic()
    vsr.evaluate(genomes[:320], "biped-4x3", "attention", "flat", seconds=3.0, threads=1)
    ten_chunks = time.monotonic() - whole
    assert stopped < 0.5 + ten_chunks, f"stopped after {stopped:.2f} s; ten chunks take {ten_chunks:.2f} s"


def test_chunks_change_no_velocity():
    genomes = np.random.default_rng(2).uniform(-1, 1, (70, 73)).astype(np.float32)
    together = vsr.evaluate(genomes, "biped-4x3", "attention", "flat", seconds=1.0, threads=1)
    apart = np.concatenate([vsr.evaluate(genomes[i:i + 1], "biped-4x3", "attention", "flat",
                                         seconds=1.0, threads=1) for i in range(70)])
    assert np.array_equal(together, apart)
