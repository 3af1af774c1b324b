"""Run files read and written from Python are the command line's, byte for byte."""

import json

import numpy as np
import pytest

import vsr
from conftest import ROOT, cli


def test_a_pretrained_run_reads_and_writes_back_unchanged(tmp_path):
    source = ROOT / "pretrained" / "biped-4x3-attention.json"
    run = vsr.load_run(source)
    assert run["best"]["genome"].dtype == np.float32 and run["best"]["genome"].shape == (73,)
    vsr.save_run(tmp_path / "copy.json", run)
    assert (tmp_path / "copy.json").read_text() == source.read_text()


def test_a_new_run_replays_in_the_command_line(vsr_bin, tmp_path):
    run = vsr.load_run(ROOT / "pretrained" / "biped-4x3-attention.json")
    genome = run["best"]["genome"]
    velocity = vsr.evaluate(genome[None, :], "biped-4x3", "attention", "hilly-1-10-1")[0]
    path = tmp_path / "mine.json"
    vsr.save_run(path, vsr.new_run(genome, "1111-1111-1001", "attention", velocity, seed=9))
    code, out, err = cli(vsr_bin, "evaluate", "--genome", str(path), "--terrain", "hilly-1-10-1")
    assert code == 0, err
    assert json.loads(out)["velocity"] == velocity
    assert vsr.load_run(path)["best"]["fitness"] == velocity


def test_a_broken_run_file_is_refused_and_nothing_is_written(tmp_path):
    path = tmp_path / "cut.json"
    path.write_text('{"format": "vsr-run", "version": 1, "config": {')
    with pytest.raises(ValueError, match="cut off"):
        vsr.load_run(path)
    run = vsr.new_run(np.zeros(41), "biped-4x3", "mlp")
    run["best"]["controller"] = "attention"
    with pytest.raises(ValueError, match="73"):
        vsr.save_run(tmp_path / "bad.json", run)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["cut.json"]
