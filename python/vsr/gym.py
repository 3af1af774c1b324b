"""A gymnasium environment over the engine (the ``gym`` extra: ``pip install "./python[gym]"``).

``WalkEnv(shape="biped-4x3", terrain="hilly-1-10", seconds=30.0)`` is ``vsr.Episode`` as a
``gymnasium.Env``: the robot walks for `seconds`, one action every 20 steps (1/3 s).

- Observation: float32, shape (voxels, 4), the sensor readings a controller is fed, per voxel
  in voxel index order: area (0.5 + 0.5 tanh(4 (a - 1)), a the area ratio), vx and vy (the
  voxel's velocity in its own frame averaged over 0.5 s, each 0.5 + 0.5 tanh(v / 4)), touch
  (the fraction of the last 0.25 s a corner touched the ground), each in [0, 1] plus sensor
  noise of sd 0.01, which never exceeds 0.121: the space is Box(-0.125, 1.125).
- Action: float32, shape (voxels,), Box(-1, 1): each voxel's actuation, +1 contracts, held for
  20 steps. Values outside [-1, 1] act as -1 or 1 (the engine clamps); a NaN, a wrong count, a
  scalar or a 2-D array is a ValueError naming the expected shape.
- Reward: the robot centre's x advance during the step (m); the rewards add up to the
  distance, and ``info["velocity"]`` at the end is what ``vsr evaluate`` gives.
- Episode end: truncated after `seconds` (90 actions for 30 s), never terminated.
- Terrain: a family (``hilly-1-10``, ``steppy-1-10``) draws one of its 10,000 terrains per
  ``reset`` (the training pool of ``vsr evolve``); a name (``flat``, ``hilly-1-10-3``) is
  always that terrain; ``reset(options={"terrain": NAME})`` sets one episode's.
- Seeding, gymnasium's: ``reset(seed=s)`` seeds ``self.np_random``, from which each reset
  draws the terrain and the sensor-noise seed; ``reset()`` continues the generator, so it
  gives a new episode, never the last one again. The same seed replays the same episodes.
- ``info``: ``time`` (s), ``x`` (the centre, m), ``velocity`` (m/s so far), ``terrain``,
  ``noise_seed`` and ``grid``: each voxel's cell (column from the left, row from the
  bottom), shape (voxels, 2), in the observation's row order.

``gymnasium.make("vsr/Walk-v0", shape=..., terrain=...)`` works once this module is imported.
"""

try:
    import gymnasium
    from gymnasium import spaces
except ImportError as e:  # pragma: no cover - depends on the installation
    raise ImportError(
        'vsr.gym needs gymnasium: pip install "./python[gym]" (or pip install gymnasium)'
    ) from e

import numpy as np

from . import _vsr

# Draws of the terrain and of the noise seed per reset: integers in [0, 2^63).
_DRAWS = 2**63


class WalkEnv(gymnasium.Env):
    """A voxel robot walking on a terrain, one actuation per voxel (see the module doc)."""

    metadata = {"render_modes": []}

    def __init__(self, shape="biped-4x3", terrain="hilly-1-10", seconds=30.0, render_mode=None):
        if render_mode is not None:
            raise ValueError(f"render_mode must be None (WalkEnv does not render), got {render_mode!r}")
        first = _vsr.terrain_for(terrain, 0)  # a bad terrain fails here, with the engine's words
        probe = _vsr.Episode(shape, first, seconds)
        voxels = probe.voxel_count
        low, high = _vsr.Episode.observation_bounds
        self.shape, self.terrain_family, self.seconds = shape, terrain, seconds
        self.render_mode = None
        self.observation_space = spaces.Box(low, high, shape=(voxels, 4), dtype=np.float32)
        self.action_space = spaces.Box(-1.0, 1.0, shape=(voxels,), dtype=np.float32)
        self.grid = probe.grid
        self.terrain = None
        self._episode = None
        self._noise_seed = None

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        terrain_draw, noise_seed = (int(d) for d in self.np_random.integers(0, _DRAWS, size=2))
        terrain = (options or {}).get("terrain", self.terrain_family)
        self.terrain = _vsr.terrain_for(terrain, terrain_draw)
        self._noise_seed = noise_seed
        self._episode = _vsr.Episode(self.shape, self.terrain, self.seconds, noise_seed)
        observation, info = self._episode.reset()
        return observation, self._info(info)

    def step(self, action):
        if self._episode is None:
            raise gymnasium.error.ResetNeeded("call reset() before step()")
        observation, reward, terminated, truncated, info = self._episode.step(action)
        return observation, reward, terminated, truncated, self._info(info)

    def _info(self, info):
        info.update(terrain=self.terrain, noise_seed=self._noise_seed, grid=self.grid.copy())
        return info


if "vsr/Walk-v0" not in gymnasium.registry:
    gymnasium.register(id="vsr/Walk-v0", entry_point="vsr.gym:WalkEnv")
