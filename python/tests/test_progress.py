"""Progress of the long calls on Python's `logging` ("vsr" logger, INFO): a body search logs
the command line's line for each iteration; a batch of more than one chunk logs how many of
its episodes are done. Ctrl-C stops a body search between iterations and a batch of bodies
between chunks."""

import logging
import os
import signal
import threading

import numpy as np
import pytest

import vsr
from conftest import ROOT

MODULE = ROOT / "pretrained" / "biped-4x3-attention.json"


def test_a_body_search_logs_each_iteration(caplog):
    with caplog.at_level(logging.INFO, logger="vsr"):
        run = vsr.codesign("frozen", 36, 3, module=MODULE, start="box-3x3", seconds=1.0,
                           batch=12, threads=1)
    lines = [r.getMessage() for r in caplog.records if r.name == "vsr"]
    assert len(lines) == len(run["history"]) >= 2
    for line, record in zip(lines, run["history"]):
        assert line == (f"iteration {record['iteration']}: best {record['best']:.3f} m/s, "
                        f"{record['filled']} bodies in the archive")


def test_a_large_batch_logs_its_chunks_and_a_small_one_nothing(caplog):
    genomes = np.random.default_rng(1).uniform(-1, 1, (70, 73)).astype(np.float32)
    with caplog.at_level(logging.INFO, logger="vsr"):
        vsr.evaluate(genomes, "biped-4x3", "attention", "flat", seconds=0.5, threads=1)
    assert [r.getMessage() for r in caplog.records] == [
        "evaluated 32 of 70 episodes", "evaluated 64 of 70 episodes",
        "evaluated 70 of 70 episodes"]
    caplog.clear()
    with caplog.at_level(logging.INFO, logger="vsr"):
        vsr.evaluate(genomes[:32], "biped-4x3", "attention", "flat", seconds=0.5, threads=1)
    assert caplog.records == []


def interrupted(call):
    """Runs `call` with Ctrl-C after half a second; it must raise KeyboardInterrupt."""
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            call()
    finally:
        timer.cancel()


def test_ctrl_c_stops_a_body_search():
    # Alone, about a minute on one thread; stopped, within an iteration.
    interrupted(lambda: vsr.codesign("frozen", 100_000, 3, module=MODULE, start="box-3x3",
                                     seconds=1.0, batch=12, threads=1))


def test_ctrl_c_stops_a_batch_of_bodies():
    genome = vsr.load_run(MODULE)["best"]["genome"]
    count = 3200
    interrupted(lambda: vsr.evaluate_bodies(["biped-4x3"] * count, [genome] * count,
                                            "attention", "flat", seconds=3.0, threads=1))
