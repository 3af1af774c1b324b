"""`vsr.codesign`: the body search of `vsr codesign`, bit for bit, for any thread count;
a module that cannot be reassembled refused in words."""

import json

import numpy as np
import pytest

import vsr
from conftest import ROOT, cli

MODULE = ROOT / "pretrained" / "biped-4x3-attention.json"
TINY = dict(start="box-3x3", seconds=2.0, batch=12)


def without_timing(run):
    """The run without its wall-clock times (the only thing threads and machines change)."""
    history = [{k: v for k, v in r.items() if k != "wall_seconds"} for r in run["history"]]
    return {**{k: v for k, v in run.items() if k != "timing"}, "history": history}


def test_a_search_is_the_command_lines_bit_for_bit(vsr_bin, tmp_path):
    out = tmp_path / "cli.json"
    code, _, err = cli(
        vsr_bin, "codesign", "--brain", "frozen", "--from", str(MODULE), "--start", "box-3x3",
        "--evals", "60", "--seed", "3", "--seconds", "2", "--batch", "12", "--threads", "2",
        "--out", str(out),
    )
    assert code == 0, err
    ours = tmp_path / "python.json"
    run = vsr.codesign("frozen", 60, 3, module=MODULE, threads=1, out=ours, **TINY)
    assert without_timing(json.loads(ours.read_text())) == without_timing(
        json.loads(out.read_text()))
    assert run["best"]["genome"].dtype == np.float32
    assert len(run["archive"]) >= 2
    # the frozen block is the module's in every body
    block = vsr.load_run(MODULE)["best"]["genome"][:32]
    for entry in run["archive"]:
        assert np.array_equal(entry["genome"][:32], block)


def test_a_module_that_needs_its_neighbours_is_refused_in_words():
    with pytest.raises(ValueError, match="attention"):
        vsr.codesign("frozen", 20, 1, module=ROOT / "pretrained" / "biped-4x3-mlp-comm.json")
    with pytest.raises(ValueError, match="brain"):
        vsr.codesign("thawed", 20, 1)


def test_a_found_body_is_a_module_as_on_the_command_line(vsr_bin, tmp_path):
    """`entry=I` of a co-design run file is `vsr codesign --from FILE --entry I`: the search
    keeps that body's attention block and starts from that body."""
    bodies = tmp_path / "bodies.json"
    vsr.codesign("finetune", 48, 4, module=MODULE, threads=1, out=bodies, **TINY)
    found = json.loads(bodies.read_text())["archive"]
    i = len(found) - 1
    out = tmp_path / "cli.json"
    code, _, err = cli(
        vsr_bin, "codesign", "--brain", "frozen", "--from", str(bodies), "--entry", str(i),
        "--evals", "24", "--seed", "5", "--seconds", "2", "--batch", "12", "--threads", "1",
        "--out", str(out),
    )
    assert code == 0, err
    run = vsr.codesign("frozen", 24, 5, module=bodies, entry=i, seconds=2.0, batch=12, threads=1)
    assert without_timing({**run, "best": None, "archive": None}) == without_timing(
        {**json.loads(out.read_text()), "best": None, "archive": None})
    assert run["config"]["start"] == found[i]["shape"]
    block = np.asarray(found[i]["genome"][:32], dtype=np.float32)
    for entry in run["archive"]:
        assert np.array_equal(entry["genome"][:32], block)
    with pytest.raises(ValueError, match="entry 99 does not exist"):
        vsr.codesign("frozen", 24, 5, module=bodies, entry=99)
    with pytest.raises(ValueError, match="give module too"):
        vsr.codesign("frozen", 24, 5, entry=0)
