"""The pycma example runs end to end (a tiny budget) and writes a run file vsr replays; its
validation is `vsr validate`'s on that file."""

import json
import subprocess
import sys

import vsr
from conftest import ROOT, cli


def test_the_cma_example_evolves_validates_and_writes_a_run(tmp_path, vsr_bin):
    out = tmp_path / "cma.json"
    done = subprocess.run(
        [sys.executable, str(ROOT / "python" / "examples" / "cma_evolve.py"),
         "--evaluations", "30", "--seconds", "1", "--out", str(out)],
        capture_output=True, text=True, timeout=600,
    )
    assert done.returncode == 0, done.stderr
    assert "validation on hilly-1-10-0..9: mean" in done.stdout
    run = vsr.load_run(out)
    assert run["best"]["genome"].shape == (73,) and run["config"]["ga"]["budget_evals"] == 100
    # the file says the 1-s episodes it was evolved with, so vsr validates it at 1 s unasked
    assert (run["config"]["seconds"], run["config"]["terrain"]) == (1.0, "hilly-1-10")
    code, text, err = cli(vsr_bin, "validate", "--genome", str(out), "--json")
    assert code == 0, err
    mean = json.loads(text)["mean"]
    assert run["best"]["fitness"] == mean
    assert f"validation on hilly-1-10-0..9: mean {mean:.3f} m/s" in done.stdout


def test_the_body_search_example_runs_and_every_body_it_keeps_is_one_piece():
    done = subprocess.run(
        [sys.executable, str(ROOT / "python" / "examples" / "body_search.py")],
        capture_output=True, text=True, timeout=600, cwd=ROOT,
    )
    assert done.returncode == 0, done.stderr
    lines = done.stdout.strip().splitlines()
    assert len(lines) == 5, done.stdout
    for line in lines:
        body = line.split("best ")[1].split(" at ")[0]
        assert vsr.param_count(body, "attention") > 32, body
