"""vsr.Episode, stepped from Python: driven by the engine's own controller through
vsr.Controller it walks exactly as vsr.evaluate; its rewards add up to the distance; it
refuses what it cannot do."""

import numpy as np
import pytest

import vsr

SHAPE, TERRAIN, SECONDS = "biped-4x3", "hilly-1-10-5", 5.0


def drive(controller, noise_seed=0):
    episode = vsr.Episode(SHAPE, TERRAIN, seconds=SECONDS, noise_seed=noise_seed)
    observation, info = episode.reset()
    assert observation.shape == (10, 4) and observation.dtype == np.float32
    rewards, truncated, actions = [], False, 0
    while not truncated:
        action = controller(observation)
        observation, reward, terminated, truncated, info = episode.step(action)
        assert not terminated
        rewards.append(reward)
        actions += 1
    return episode, rewards, actions, info


@pytest.mark.parametrize("kind", ["attention", "mlp"])
def test_the_engines_controller_from_python_walks_as_evaluate(kind):
    genome = np.random.default_rng(11).uniform(-1, 1, vsr.param_count(SHAPE, kind))
    brain = vsr.Controller(SHAPE, kind, genome)
    assert not brain.needs_every_step
    episode, rewards, actions, info = drive(brain.control, noise_seed=3)
    expected = vsr.simulate(genome, SHAPE, kind, TERRAIN, seconds=SECONDS, noise_seed=3)
    assert actions == 15  # 301 steps: the first, then 15 holds of 20
    assert episode.velocity == expected["velocity"] == info["velocity"]
    assert sum(rewards) == pytest.approx(expected["distance"], abs=1e-12)


def test_a_python_gait_moves_the_robot_and_observations_are_readings():
    columns = np.array([0, 1, 2, 3, 0, 1, 2, 3, 0, 3])
    clock = {"t": 0.0}

    def gait(observation):
        assert np.all((observation > -0.1) & (observation < 1.1))
        clock["t"] += 20 / 60
        return np.sin(2 * np.pi * clock["t"] - 1.5 * columns)

    episode, rewards, _, _ = drive(gait)
    assert abs(sum(rewards)) > 0.01
    assert episode.corners().shape == (10, 4, 2)
    assert episode.time == pytest.approx(301 / 60)


def test_the_episode_refuses_what_it_cannot_do():
    episode = vsr.Episode(SHAPE, "flat", seconds=1.0)
    with pytest.raises(ValueError, match="call reset"):
        episode.step(np.zeros(10))
    episode.reset(seed=4)
    with pytest.raises(ValueError, match="expected 10 actuations"):
        episode.step(np.zeros(9))
    with pytest.raises(ValueError, match="actuation 2 is NaN"):
        episode.step([0, 0, np.nan, 0, 0, 0, 0, 0, 0, 0])
    with pytest.raises(ValueError, match=r"must be a 1-D array of 10 actuations in \[-1, 1\], "
                                         r"one per voxel, got an array of shape \(10, 1\)"):
        episode.step(np.zeros((10, 1)))
    with pytest.raises(ValueError, match=r"got an array of shape \(\)"):
        episode.step(np.float32(0.5))
    with pytest.raises(ValueError, match=r"seed must be an integer in \[0, 2\^64 - 1\].*got -1"):
        episode.reset(seed=-1)
    truncated = False
    while not truncated:
        *_, truncated, _ = episode.step(np.ones(10))
    with pytest.raises(ValueError, match="the episode is over"):
        episode.step(np.zeros(10))
    with pytest.raises(ValueError, match="unknown terrain"):
        vsr.Episode(SHAPE, "moon")
    whole = r"noise_seed must be an integer in \[0, 2\^64 - 1\], got -1"
    with pytest.raises(ValueError, match=whole):
        vsr.Episode(SHAPE, "flat", noise_seed=-1)


def test_the_controller_takes_any_array_of_numbers_and_refuses_the_rest():
    brain = vsr.Controller(SHAPE, "mlp", np.linspace(-1, 1, 41))
    readings = np.random.default_rng(5).uniform(0, 1, (10, 4))
    expected = brain.control(readings.astype(np.float32))
    assert expected.dtype == np.float32 and np.all(np.abs(expected) <= 1)
    assert np.array_equal(brain.control(readings), expected)  # float64, rounded once
    assert np.array_equal(brain.control(readings.astype(np.float32).tolist()), expected)
    assert np.array_equal(brain.control(np.asfortranarray(readings)), expected)
    shape = (r"the observation must be an array of shape \(10, 4\): 4 readings \(area, vx, vy, "
             r"touch\) per voxel, got ")
    with pytest.raises(ValueError, match=shape + r"shape \(9, 4\)"):
        brain.control(np.zeros((9, 4), dtype=np.float32))
    with pytest.raises(ValueError, match=shape + r"shape \(40,\)"):
        brain.control(np.zeros(40))
    with pytest.raises(ValueError, match=shape + "'fast'"):
        brain.control("fast")
    readings[3, 2] = np.nan
    with pytest.raises(ValueError, match="reading 2 of voxel 3 in the observation is NaN"):
        brain.control(readings)
    with pytest.raises(ValueError, match="the genome has 40 genes"):
        vsr.Controller(SHAPE, "mlp", [0.0] * 40)
