"""`vsr.evaluate_bodies`: robots of different bodies in one call, each what `vsr evaluate`
prints for that body of a `vsr codesign` gallery; mismatched inputs named."""

import json

import numpy as np
import pytest

import vsr
from conftest import ROOT, cli


def test_a_gallery_replays_body_by_body_as_the_command_line(vsr_bin, tmp_path):
    out = tmp_path / "bodies.json"
    code, _, err = cli(
        vsr_bin, "codesign", "--brain", "frozen", "--from",
        str(ROOT / "pretrained" / "biped-4x3-attention.json"), "--start", "box-3x3",
        "--evals", "60", "--seed", "2", "--seconds", "2", "--batch", "12", "--out", str(out),
    )
    assert code == 0, err
    archive = json.loads(out.read_text())["archive"]
    assert len(archive) >= 2
    shapes = [e["shape"] for e in archive]
    genomes = [np.array(e["genome"], dtype=np.float32) for e in archive]
    assert len({g.size for g in genomes}) >= 2, "bodies of different sizes"
    ours = vsr.evaluate_bodies(shapes, genomes, "attention", "flat", seconds=2.0, threads=2)
    for i, velocity in enumerate(ours):
        code, text, err = cli(vsr_bin, "evaluate", "--genome", str(out), "--entry", str(i),
                              "--terrain", "flat", "--seconds", "2")
        assert code == 0, err
        assert velocity == json.loads(text)["velocity"], f"entry {i}"
    one = vsr.evaluate_bodies(shapes, genomes, "attention", "flat", seconds=2.0, threads=1)
    assert np.array_equal(ours, one)


def test_mismatches_name_the_robot():
    with pytest.raises(ValueError, match="2 shapes but 1 genomes"):
        vsr.evaluate_bodies(["1", "11"], [np.zeros(37, np.float32)], "attention", "flat")
    with pytest.raises(ValueError, match="robot 1"):
        vsr.evaluate_bodies(["1", "11"], [np.zeros(37, np.float32)] * 2, "attention", "flat")
