"""vsr.gym.WalkEnv is a gymnasium environment: check_env passes, its spaces' bounds hold, a
terrain family is drawn per reset, seeding is gymnasium's, and driven by the engine's own
controller it walks as vsr.evaluate does."""

import numpy as np
import pytest

gymnasium = pytest.importorskip(
    "gymnasium", reason='gymnasium is not installed: pip install "./python[gym]"')
from gymnasium.utils.env_checker import check_env  # noqa: E402

import vsr  # noqa: E402
from vsr.gym import WalkEnv  # noqa: E402


@pytest.mark.parametrize("terrain", ["hilly-1-10", "flat"])
def test_check_env_passes(terrain):
    check_env(WalkEnv("biped-4x3", terrain, seconds=2.0), skip_render_check=True)


def test_made_by_id_with_true_bounds_and_each_voxels_cell():
    env = gymnasium.make("vsr/Walk-v0", shape="comb-7x2", terrain="steppy-1-10", seconds=3.0)
    assert env.observation_space.shape == (11, 4) and env.action_space.shape == (11,)
    assert (env.observation_space.low.min(), env.observation_space.high.max()) == (-0.125, 1.125)
    observation, info = env.reset(seed=3)
    # comb-7x2 is 1111111-1010101: the legs in the bottom row (y = 0), the back above
    assert info["grid"][:4].tolist() == [[0, 0], [2, 0], [4, 0], [6, 0]]
    assert info["grid"][4:].tolist() == [[x, 1] for x in range(7)]
    truncated, readings = False, [observation]
    while not truncated:
        observation, _, terminated, truncated, info = env.step(env.action_space.sample())
        assert not terminated
        readings.append(observation)
    assert all(env.observation_space.contains(r) for r in readings)
    assert info["terrain"].startswith("steppy-1-10-") and info["time"] == pytest.approx(181 / 60)


def test_seeding_replays_a_seed_and_never_the_last_episode():
    env = WalkEnv(seconds=1.0)
    first, info = env.reset(seed=7)
    again, info_again = env.reset(seed=7)
    assert first.tobytes() == again.tobytes() and info["terrain"] == info_again["terrain"]
    _, fresh = env.reset()
    assert (fresh["terrain"], fresh["noise_seed"]) != (info["terrain"], info["noise_seed"])
    _, fixed = env.reset(options={"terrain": "hilly-1-10-42"})
    assert fixed["terrain"] == "hilly-1-10-42"
    with pytest.raises(gymnasium.error.Error, match="-1"):
        env.reset(seed=-1)


def test_the_engines_controller_walks_as_evaluate():
    env = WalkEnv("biped-4x3", "hilly-1-10", seconds=4.0)
    genome = np.random.default_rng(2).uniform(-1, 1, vsr.param_count("biped-4x3", "mlp"))
    brain = vsr.Controller("biped-4x3", "mlp", genome)
    observation, info = env.reset(seed=11)
    truncated, distance = False, 0.0
    while not truncated:
        observation, reward, _, truncated, info = env.step(brain.control(observation))
        distance += reward
    expected = vsr.evaluate(genome, "biped-4x3", "mlp", info["terrain"], seconds=4.0,
                            noise_seed=info["noise_seed"])
    assert info["velocity"] == expected[0]


def test_bad_actions_are_named_and_out_of_range_ones_clamp():
    env = WalkEnv(seconds=1.0)
    env.reset(seed=1)
    with pytest.raises(ValueError, match=r"a 1-D array of 10 actuations in \[-1, 1\], one per "
                                         r"voxel, got an array of shape \(10, 1\)"):
        env.step(np.zeros((10, 1), dtype=np.float32))
    with pytest.raises(ValueError, match=r"got an array of shape \(\)"):
        env.step(np.float32(0.5))
    with pytest.raises(ValueError, match="expected 10 actuations"):
        env.step(np.zeros(9))
    with pytest.raises(ValueError, match="actuation 4 is NaN"):
        env.step(np.where(np.arange(10) == 4, np.nan, 0.0))
    with pytest.raises(ValueError, match=r"a 1-D array of 10 actuations.*got 'walk'"):
        env.step("walk")
    # 2.0 and 100 act as 1: the engine clamps, as it clamps a controller's output
    outcomes = []
    for value in (1.0, 2.0, 100.0):
        env.reset(seed=1)
        outcomes.append(env.step(np.full(10, value))[0].tobytes())
    assert outcomes[0] == outcomes[1] == outcomes[2]
