"""vsr.validate and vsr.ablate are `vsr validate` and `vsr ablate`, bit for bit: the same ten
terrains with the same noise seeds, the same frozen walks and the same unfrozen one."""

import json

import numpy as np
import pytest

import vsr
from conftest import ROOT, cli

RUN = ROOT / "pretrained" / "biped-4x3-attention.json"


def cli_json(vsr_bin, *args):
    code, out, err = cli(vsr_bin, *args, "--json")
    assert code == 0, err
    return json.loads(out)


@pytest.mark.parametrize("which", ["paper", "unseen"])
def test_validate_is_the_command_lines(which, vsr_bin):
    best = vsr.load_run(RUN)["best"]
    mine = vsr.validate(best["genome"], best["shape"], best["controller"], set=which)
    theirs = cli_json(vsr_bin, "validate", "--genome", str(RUN), "--set", which)
    assert mine["set"] == theirs["set"] == which
    assert mine["terrains"] == [t["terrain"] for t in theirs["terrains"]]
    assert mine["velocities"].tolist() == [t["velocity"] for t in theirs["terrains"]]
    assert (mine["median"], mine["mean"]) == (theirs["median"], theirs["mean"])
    # each episode is vsr.evaluate's on that terrain with that noise seed (not 0)
    terrain, seed = mine["terrains"][3], mine["noise_seeds"][3]
    again = vsr.evaluate(best["genome"], best["shape"], best["controller"], terrain, noise_seed=seed)
    assert again[0] == mine["velocities"][3] and seed != 0


def test_validate_on_another_robot_with_short_episodes(vsr_bin, tmp_path):
    genome = np.random.default_rng(5).uniform(-1, 1, vsr.param_count("comb-7x2", "mlp"))
    path = tmp_path / "mlp.json"
    vsr.save_run(path, vsr.new_run(genome, "comb-7x2", "mlp"))
    mine = vsr.validate(genome, "comb-7x2", "mlp", set="unseen", seconds=3.0)
    theirs = cli_json(vsr_bin, "validate", "--genome", str(path), "--set", "unseen",
                      "--seconds", "3")
    assert mine["velocities"].tolist() == [t["velocity"] for t in theirs["terrains"]]
    with pytest.raises(ValueError, match="unknown validation set 'test'"):
        vsr.validate(genome, "comb-7x2", "mlp", set="test")


def test_ablate_is_the_command_lines_with_its_unfrozen_walk(vsr_bin):
    best = vsr.load_run(RUN)["best"]
    mine = vsr.ablate(best["genome"], "biped-4x3", "attention", last_second=4, seconds=10.0)
    theirs = cli_json(vsr_bin, "ablate", "--genome", str(RUN), "--last-second", "4",
                      "--seconds", "10")
    assert mine["freeze_seconds"].tolist() == [p["freeze_second"] for p in theirs] == [0, 1, 2, 3, 4]
    assert mine["velocities"].tolist() == [p["velocity"] for p in theirs]
    code, text, err = cli(vsr_bin, "ablate", "--genome", str(RUN), "--last-second", "4",
                          "--seconds", "10")
    assert code == 0, err
    unfrozen = next(line.split()[1] for line in text.splitlines()
                    if line.strip().startswith("unfrozen"))
    assert unfrozen == f"{mine['unfrozen']:.3f}"
    # the unfrozen walk is the validation episode on the same terrain
    validation = vsr.validate(best["genome"], "biped-4x3", "attention", seconds=10.0)
    assert mine["unfrozen"] == validation["velocities"][0]
    with pytest.raises(ValueError, match="is a mlp controller"):
        vsr.ablate(np.zeros(41), "biped-4x3", "mlp")


def test_a_1d_genome_is_one_row():
    genome = np.random.default_rng(8).uniform(-1, 1, 73)
    one = vsr.evaluate(genome, "biped-4x3", "attention", "flat", seconds=2.0)
    rows = vsr.evaluate(genome[None, :], "biped-4x3", "attention", "flat", seconds=2.0)
    assert one.shape == (1,) and one.tobytes() == rows.tobytes()
    with pytest.raises(ValueError, match=r"must be a 2-D array, one genome per row \(or a 1-D"):
        vsr.evaluate(np.zeros((1, 1, 73)), "biped-4x3", "attention", "flat")
