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


def test_a_new_run_records_its_episodes_and_the_command_line_replays_them(vsr_bin, tmp_path):
    genome = vsr.load_run(ROOT / "pretrained" / "biped-4x3-attention.json")["best"]["genome"]
    paper = vsr.new_run(genome, "biped-4x3", "attention")
    assert (paper["config"]["seconds"], paper["config"]["terrain"]) == (30.0, "hilly-1-10")
    run = vsr.new_run(genome, "biped-4x3", "attention", seconds=2, terrain="flat")
    assert (run["config"]["seconds"], run["config"]["terrain"]) == (2.0, "flat")
    path = tmp_path / "short.json"
    vsr.save_run(path, run)
    code, out, err = cli(vsr_bin, "evaluate", "--genome", str(path), "--terrain", "flat")
    assert code == 0, err
    assert json.loads(out)["steps"] == 121  # the run's own 2 s, not 30
    velocity = vsr.evaluate(genome, "biped-4x3", "attention", "flat", seconds=2)[0]
    assert json.loads(out)["velocity"] == velocity
    expected = cli(vsr_bin, "evaluate", "--genome", str(path), "--terrain", "flat",
                   "--seconds", "-1")[2].removeprefix("vsr: ").strip()
    with pytest.raises(ValueError) as e:
        vsr.new_run(genome, "biped-4x3", "attention", seconds=-1)
    assert str(e.value) == expected
    with pytest.raises(ValueError, match="neither a terrain family"):
        vsr.new_run(genome, "biped-4x3", "attention", terrain="moon")


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


def test_saving_into_a_missing_folder_names_the_path_given(tmp_path):
    path = tmp_path / "no-such-folder" / "run.json"
    with pytest.raises(FileNotFoundError) as e:
        vsr.save_run(path, vsr.new_run(np.zeros(41), "biped-4x3", "mlp"))
    assert str(e.value) == (f"cannot write run file {path}: its folder {path.parent} "
                            "does not exist")
