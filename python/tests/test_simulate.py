"""vsr.simulate: one episode as vsr.evaluate runs it, its trajectory on request."""

import numpy as np

import vsr


def test_simulate_is_evaluate_and_records_every_step():
    genome = np.random.default_rng(5).uniform(-1, 1, 41)
    velocity = vsr.evaluate(genome[None, :], "biped-4x3", "mlp", "flat", seconds=2.0)[0]
    plain = vsr.simulate(genome, "biped-4x3", "mlp", "flat", seconds=2.0)
    assert plain["velocity"] == velocity and plain["steps"] == 121 and "time" not in plain
    run = vsr.simulate(genome, "biped-4x3", "mlp", "flat", seconds=2.0, trajectory=True)
    assert run["velocity"] == velocity
    assert run["time"].shape == (121,) and run["time"][-1] == run["seconds"]
    assert run["centre"].shape == (121, 2) and run["corners"].shape == (121, 10, 4, 2)
    # the centre is the mean of the voxel centres, near the mean of the corners
    assert np.allclose(run["corners"].mean(axis=(1, 2)), run["centre"], atol=0.05)
    distance = run["centre"][-1, 0] - run["centre"][0, 0]
    assert distance == plain["distance"]
