"""A Gymnasium vector environment backed by the C++ VecEnv: K consoles stepped on a C++ thread
pool in one call, with Gymnasium's same-step autoreset (the C++ side resets a finished
environment inside the step that ended it; its last observation and info arrive in
``info["final_obs"]`` and ``info["final_info"]``, masked by ``info["_final_obs"]``).
"""
import copy as _copy

import gymnasium as gym
import numpy as np
from gymnasium.vector import AutoresetMode
from gymnasium.vector.utils import batch_space

from .gym_envs import deterministic_info, observation_space


def _row(obs, i):
    if isinstance(obs, dict):
        return {k: np.array(v[i]) for k, v in obs.items()}
    return np.array(obs[i])


class PsxrlVectorEnv(gym.vector.VectorEnv):
    """``num_envs`` environments of one integration. Observations are copies unless ``copy=False``,
    which returns read-only views of the C++ batch, overwritten by the next reset or step."""

    metadata = {"render_modes": [], "autoreset_mode": AutoresetMode.SAME_STEP}

    def __init__(self, num_envs, game="tumble", level=1, threads=0, copy=True, **config):
        from . import VecEnv

        self.vec = VecEnv(num_envs, threads, game=game, **config)
        self.num_envs = num_envs
        self.level = level
        self.copy = copy
        self.single_observation_space = observation_space(self.vec.observation_spaces)
        self.single_action_space = gym.spaces.Discrete(self.vec.action_count)
        self.observation_space = batch_space(self.single_observation_space, num_envs)
        self.action_space = batch_space(self.single_action_space, num_envs)

    def _out(self, obs):
        return _copy.deepcopy(obs) if self.copy else obs

    def reset(self, *, seed=None, options=None):
        """``seed`` (an int) seeds every environment: environment i's k-th episode uses
        ``psxrl.episode_seed(seed, i, k)``; ``options={"level": n}`` picks the level."""
        if seed is not None and not isinstance(seed, (int, np.integer)):
            raise TypeError("seed must be one int (environment i then uses psxrl.episode_seed(seed, i, k))")
        super().reset(seed=None if seed is None else int(seed))
        cpp_seed = int(seed) if seed is not None else int(self.np_random.integers(0, 2**63))
        level = (options or {}).get("level", self.level)
        return self._out(self.vec.reset(level, cpp_seed)), {}

    def step(self, actions):
        obs, rewards, terminated, truncated, infos = self.vec.step(np.asarray(actions, dtype=np.int32))
        done = terminated | truncated
        final = self.vec.final_observation() if done.any() else None
        vector_info = {}
        for i, info in enumerate(infos):
            info = deterministic_info(info)
            if done[i]:
                vector_info = self._add_info(vector_info, {"final_obs": _row(final, i), "final_info": info}, i)
            else:
                vector_info = self._add_info(vector_info, info, i)
        return self._out(obs), rewards, terminated, truncated, vector_info


class TumbleVectorEnv(PsxrlVectorEnv):
    def __init__(self, num_envs, level=1, obs="simple", reward="table", gamma=0.9, visual_gray=False,
                 initial_delay=None, delay=None, max_move_frames=None, max_moves=None, threads=0, copy=True):
        super().__init__(num_envs, game="tumble", level=level, threads=threads, copy=copy, obs=obs, reward=reward,
                         gamma=gamma, visual_gray=visual_gray, initial_delay=initial_delay, delay=delay,
                         max_move_frames=max_move_frames, max_moves=max_moves)


class KulaVectorEnv(PsxrlVectorEnv):
    def __init__(self, num_envs, disc=None, bios=None, level=1, states=None, maps=None, obs="simple",
                 reward="table", gamma=0.9, visual_gray=False, initial_delay=None, delay=None, max_move_frames=None,
                 max_moves=None, threads=0, copy=True):
        super().__init__(num_envs, game="kula", level=level, threads=threads, copy=copy, disc=disc, bios=bios,
                         states=states, maps=maps, obs=obs, reward=reward, gamma=gamma, visual_gray=visual_gray,
                         initial_delay=initial_delay, delay=delay, max_move_frames=max_move_frames,
                         max_moves=max_moves)
