"""vsr.evaluate gives, row by row, exactly what `vsr evaluate` prints: random genomes of every
controller on random shapes and terrains, compared bit for bit."""

import numpy as np
import pytest

import vsr
from conftest import CONTROLLERS, cli_evaluate, random_shape

SECONDS = 4.0


@pytest.mark.parametrize("case", range(5))
def test_every_row_is_bit_identical_to_the_command_line(case, vsr_bin, tmp_path):
    rng = np.random.default_rng(100 + case)
    shape = random_shape(rng)
    controller = CONTROLLERS[case % len(CONTROLLERS)]
    terrain = ["flat", f"hilly-1-10-{case}", "steppy-1-10-7", "uphill-10"][case % 4]
    genomes = rng.uniform(-1, 1, (3, vsr.param_count(shape, controller))).astype(np.float32)
    velocities = vsr.evaluate(genomes, shape, controller, terrain, seconds=SECONDS, noise_seed=case)
    assert velocities.dtype == np.float64 and velocities.shape == (3,)
    for genome, velocity in zip(genomes, velocities):
        expected = cli_evaluate(vsr_bin, tmp_path, genome, shape, controller, terrain, SECONDS, case)
        assert velocity == expected["velocity"], (shape, controller, terrain)


def test_a_paper_robot_over_a_full_episode(vsr_bin, tmp_path):
    genome = np.random.default_rng(7).uniform(-1, 1, (1, 73))
    velocity = vsr.evaluate(genome, "biped-4x3", "attention", "hilly-1-10-0")[0]
    expected = cli_evaluate(vsr_bin, tmp_path, genome[0].astype(np.float32), "biped-4x3",
                            "attention", "hilly-1-10-0", 30.0)
    assert velocity == expected["velocity"] and expected["steps"] == 1801


def test_threads_never_change_the_result():
    rng = np.random.default_rng(3)
    genomes = rng.uniform(-1, 1, (5, vsr.param_count("comb-7x2", "mlp")))
    one = vsr.evaluate(genomes, "comb-7x2", "mlp", "hilly-1-10-2", seconds=2.0, threads=1)
    two = vsr.evaluate(genomes, "comb-7x2", "mlp", "hilly-1-10-2", seconds=2.0, threads=2)
    assert one.tobytes() == two.tobytes()
    # float64 rows are rounded to float32 once, as a run file stores genes
    f32 = vsr.evaluate(genomes.astype(np.float32), "comb-7x2", "mlp", "hilly-1-10-2", seconds=2.0)
    assert f32.tobytes() == one.tobytes()


def test_the_noise_seed_changes_the_episode_and_an_empty_batch_is_empty():
    genomes = np.random.default_rng(4).uniform(-1, 1, (1, 73))
    a, b = (vsr.evaluate(genomes, "biped-4x3", "attention", "flat", seconds=3.0, noise_seed=s)
            for s in (0, 1))
    assert a[0] != b[0]
    assert vsr.evaluate(np.zeros((0, 73)), "biped-4x3", "attention", "flat").shape == (0,)


def test_param_count_is_the_command_lines(vsr_bin):
    from conftest import cli
    for controller in CONTROLLERS:
        code, out, _ = cli(vsr_bin, "params", "--shape", "comb-7x2", "--controller", controller)
        assert code == 0 and int(out) == vsr.param_count("comb-7x2", controller)
