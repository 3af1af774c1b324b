"""Brains for any body from Python: one genome for every body in `vsr.evaluate_bodies`, each
body what `vsr evaluate` prints; `vsr.validate(..., bodies=...)` is `vsr validate --bodies`,
bit for bit; `vsr.read_bodies` reads a body-set file with the command line's messages."""

import json

import numpy as np
import pytest

import vsr
from conftest import ROOT, cli, cli_evaluate

BODIES = ROOT / "campaigns" / "bodies"
MIXED = ["biped-4x3", "11-11", "111-101", "1111111-1010101"]  # 10, 4, 5 and 11 voxels


def genome_for(controller, seed=3):
    n = vsr.param_count("biped-4x3", controller)
    return np.random.default_rng(seed).uniform(-1, 1, n).astype(np.float32)


def cli_json(vsr_bin, *args):
    code, out, err = cli(vsr_bin, *args, "--json")
    assert code == 0, err
    return json.loads(out)


def cli_message(vsr_bin, *args):
    code, _, err = cli(vsr_bin, *args)
    assert code == 2 and err.startswith("vsr: "), err
    return err[len("vsr: "):].strip()


@pytest.mark.parametrize("controller", ["attention-any", "mlp-any", "mlp-comm-any"])
def test_one_genome_drives_every_body_as_the_command_line(controller, vsr_bin, tmp_path):
    genome = genome_for(controller)
    assert {vsr.param_count(s, controller) for s in MIXED} == {genome.size}
    one = vsr.evaluate_bodies(MIXED, genome, controller, "hilly-1-10-2", seconds=2.0,
                              threads=2, noise_seed=7)
    listed = vsr.evaluate_bodies(MIXED, [genome] * len(MIXED), controller, "hilly-1-10-2",
                                 seconds=2.0, threads=1, noise_seed=7)
    as_list = vsr.evaluate_bodies(MIXED, genome.tolist(), controller, "hilly-1-10-2",
                                  seconds=2.0, noise_seed=7)
    assert one.tobytes() == listed.tobytes() == as_list.tobytes()
    for shape, velocity in zip(MIXED, one):
        theirs = cli_evaluate(vsr_bin, tmp_path, genome, shape, controller, "hilly-1-10-2", 2.0,
                              noise_seed=7)
        assert velocity == theirs["velocity"], shape


def test_one_genome_for_a_controller_tied_to_its_body():
    with pytest.raises(ValueError) as e:
        vsr.evaluate_bodies(MIXED, np.zeros(73), "attention", "flat")
    assert str(e.value) == (
        "invalid input: one genome for every body needs a controller for any body "
        "(attention-any, mlp-any, mlp-comm-any): the attention controller's genome length "
        "depends on the body's size, and robot 0 has 10 voxels but robot 1 has 4; give one "
        "genome per body")
    # bodies of one size share a genome of that size (each voxel's genes by its index)
    genome = np.random.default_rng(4).uniform(-1, 1, vsr.param_count("11-11", "mlp"))
    same = ["11-11", "1111"]
    assert np.array_equal(vsr.evaluate_bodies(same, genome, "mlp", "flat", seconds=2.0),
                          vsr.evaluate_bodies(same, [genome] * 2, "mlp", "flat", seconds=2.0))
    with pytest.raises(ValueError, match="the genome has 72 genes, but the attention controller "
                                         "of a 10-voxel robot has 73"):
        vsr.evaluate_bodies(["biped-4x3"], np.zeros(72), "attention", "flat")
    with pytest.raises(TypeError, match=r"^shapes must be a list of shapes .*vsr\.read_bodies"):
        vsr.evaluate_bodies("biped-4x3", np.zeros(61), "attention-any", "flat")


def assert_same_validation(mine, theirs):
    """`vsr.validate(..., bodies=...)` against `vsr validate --bodies --json`, every bit."""
    assert mine["set"] == theirs["set"] and mine["seconds"] == theirs["seconds"]
    assert [b["body"] for b in mine["per_body"]] == [b["body"] for b in theirs["per_body"]]
    for m, t in zip(mine["per_body"], theirs["per_body"]):
        t = t["validation"]
        assert mine["terrains"] == [x["terrain"] for x in t["terrains"]]
        assert m["velocities"].tolist() == [x["velocity"] for x in t["terrains"]]
        assert (m["median"], m["mean"]) == (t["median"], t["mean"])
    assert mine["means"].tolist() == [b["validation"]["mean"] for b in theirs["per_body"]]
    assert (mine["median"], mine["walking_share"]) == (theirs["median"], theirs["walking_share"])


@pytest.mark.parametrize("controller, which", [("attention-any", "unseen"), ("mlp-any", "paper")])
def test_validate_over_a_body_set_is_the_command_lines(controller, which, vsr_bin, tmp_path):
    genome = genome_for(controller, seed=11)
    run = tmp_path / "any.json"
    vsr.save_run(run, vsr.new_run(genome, "biped-4x3", controller, seconds=3.0))
    path = BODIES / "heldout-paper.txt"
    theirs = cli_json(vsr_bin, "validate", "--genome", str(run), "--bodies", str(path),
                      "--set", which, "--threads", "2")
    mine = vsr.validate(genome, controller=controller, bodies=path, set=which, seconds=3.0,
                        threads=2)
    assert mine["name"] == theirs["bodies"] == "heldout-paper.txt"
    assert_same_validation(mine, theirs)
    # the same bodies as a list, on one thread; each body is vsr.validate on that body
    listed = vsr.validate(genome, controller=controller, bodies=vsr.read_bodies(str(path)),
                          set=which, seconds=3.0, threads=1)
    assert listed["name"] == "a list of 4 bodies"
    assert_same_validation(listed, theirs)
    alone = vsr.validate(genome, "111111-111111-100011-100011", controller, set=which,
                         seconds=3.0)
    assert alone["velocities"].tolist() == mine["per_body"][2]["velocities"].tolist()
    assert (alone["median"], alone["mean"]) == (mine["per_body"][2]["median"],
                                                mine["per_body"][2]["mean"])
    assert mine["noise_seeds"] == alone["noise_seeds"]


def test_the_share_above_one_metre_per_second():
    best = vsr.load_run(ROOT / "pretrained" / "biped-4x3-attention.json")["best"]
    # a body-dependent brain on a set of its own body only: as the command line allows
    mine = vsr.validate(best["genome"], best["shape"], "attention", bodies=["biped-4x3"] * 2,
                        seconds=10.0)
    alone = vsr.validate(best["genome"], best["shape"], "attention", seconds=10.0)
    assert mine["means"].tolist() == [alone["mean"]] * 2 and alone["mean"] > 1
    assert mine["walking_share"] == 1.0 and mine["median"] == alone["mean"]


def test_a_brain_tied_to_its_body_is_refused_as_the_command_line_refuses_it(vsr_bin, tmp_path):
    genome = genome_for("mlp")[:41]
    run = tmp_path / "mlp.json"
    vsr.save_run(run, vsr.new_run(genome, "biped-4x3", "mlp"))
    path = BODIES / "heldout-paper.txt"
    expected = cli_message(vsr_bin, "validate", "--genome", str(run), "--bodies", str(path))
    with pytest.raises(ValueError) as e:
        vsr.validate(genome, "biped-4x3", "mlp", bodies=path)
    assert str(e.value) == expected and "only a brain for any body" in expected
    with pytest.raises(ValueError, match=r"^invalid input: this mlp genome has genes for each "
                                         r"voxel of one body, so it cannot walk a body set"):
        vsr.validate(genome, controller="mlp", bodies=path)


def test_read_bodies_reads_the_files_the_command_line_reads():
    assert vsr.read_bodies(BODIES / "heldout-paper.txt") == [
        "1111-1111-1001", "1111111-1010101", "111111-111111-100011-100011",
        "11111111111111-10101010101010"]
    for name in ["train-32.txt", "heldout-random.txt", "heldout-combs.txt"]:
        lines = (BODIES / name).read_text().splitlines()
        rows = [l.strip() for l in lines if l.strip() and not l.startswith("#")]
        assert vsr.read_bodies(str(BODIES / name)) == rows


def test_damaged_body_sets_are_refused_in_the_command_lines_words(vsr_bin, tmp_path):
    run = tmp_path / "any.json"
    genome = genome_for("attention-any")
    vsr.save_run(run, vsr.new_run(genome, "biped-4x3", "attention-any"))
    files = {"empty.txt": ("# nothing here\n\n", "the body set empty.txt has no bodies"),
             "damaged.txt": ("# a set\n11\n1x1\n", "line 3 of the body set damaged.txt"),
             "split.txt": ("11\n101\n", "line 2 of the body set split.txt")}
    for name, (text, words) in files.items():
        path = tmp_path / name
        path.write_text(text)
        expected = cli_message(vsr_bin, "validate", "--genome", str(run), "--bodies", str(path))
        assert words in expected, expected
        for call in (lambda: vsr.read_bodies(path),
                     lambda: vsr.validate(genome, controller="attention-any", bodies=path)):
            with pytest.raises(ValueError) as e:
                call()
            assert str(e.value) == expected, name
    missing = tmp_path / "missing.txt"
    with pytest.raises(FileNotFoundError, match="cannot read the body set .*missing.txt"):
        vsr.read_bodies(missing)
    with pytest.raises(FileNotFoundError, match="cannot read the body set"):
        vsr.validate(genome, controller="attention-any", bodies=str(missing))


@pytest.mark.parametrize("bodies, message", [
    ([], r"bodies is an empty list"),
    (["11", "101"], r"body 1 of the list is not a body: invalid shape: the shape is in 2 "
                    r"separate pieces"),
    (["11", 3], r"body 1 of the list must be a string"),
    (5, r"bodies must be a body-set file's path or a list of bodies"),
    ("1111-1111-1001", r"bodies is a body-set file's path or a list of bodies: "
                       r"'1111-1111-1001' is a body, not a file; give a list, "
                       r"bodies=\['1111-1111-1001'\]"),
])
def test_bad_bodies_are_named(bodies, message):
    with pytest.raises(ValueError, match=rf"^invalid input: {message}"):
        vsr.validate(genome_for("attention-any"), controller="attention-any", bodies=bodies)
