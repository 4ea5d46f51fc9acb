"""Gymnasium environments over psxrl.Env: ``psxrl/Tumble-v0``, ``psxrl/Kula-v0`` and
``psxrl/Game-v0`` (any integration named by ``game=`` and ``games_dir=``).

Each ``step`` is one move of the game, delimited the seed's way in C++ (docs/environments.md);
observations, rewards, flags and ``info`` are the C++ environment's, unchanged.
"""
import time
import warnings

import gymnasium as gym
import numpy as np
from gymnasium import spaces

TUMBLE_ID = "psxrl/Tumble-v0"
KULA_ID = "psxrl/Kula-v0"
GAME_ID = "psxrl/Game-v0"  # any integration, by game= and games_dir= (psxrl.make_env)


def observation_space(spaces_list):
    """The Gymnasium space of an observation described by ``Env.observation_spaces``: a Box for a
    single array, a Dict of Boxes (by part name) for ``multimodal``."""
    boxes = {}
    for s in spaces_list:
        dtype = np.dtype(s["dtype"])
        low, high = s["low"], s["high"]
        if dtype.kind in "iu":
            low, high = int(low), int(high)
        boxes[s["name"]] = spaces.Box(low=low, high=high, shape=tuple(s["shape"]), dtype=dtype)
    if len(boxes) == 1:
        return next(iter(boxes.values()))
    return spaces.Dict(boxes)


def deterministic_info(info):
    """The C++ info without ``real_seconds``: host time differs between runs, and Gymnasium expects
    a seeded episode to repeat exactly, info included (psxrl.Env keeps it)."""
    info.pop("real_seconds", None)
    return info


def _seed_for_cpp(env_rng, seed):
    # An explicit seed goes to C++ as is, so a Gymnasium episode equals psxrl.Env.reset(level, seed);
    # without one the environment's own generator (seeded by Gymnasium) draws it.
    if seed is None:
        return int(env_rng.integers(0, 2**63))
    if not 0 <= seed < 2**64:
        raise ValueError(f"seed must be in [0, 2**64), got {seed}")
    return int(seed)


class PsxrlEnv(gym.Env):
    """One game integration as a Gymnasium environment (actions: the integration's, Discrete)."""

    # "human" shows each step's last picture in the play window of `psxrl play` (psxrl.Window),
    # held for as long as the move took in the game: the console's 59.82 frames per second.
    metadata = {"render_modes": ["rgb_array", "human"], "render_fps": 60}
    _CONSOLE_FPS = 53693175 / (3413 * 263)  # psx-spx "GPU Timings", NTSC

    def __init__(self, game="tumble", level=1, render_mode=None, **config):
        from . import Env

        if render_mode is not None and render_mode not in self.metadata["render_modes"]:
            raise ValueError(f"render_mode must be one of {self.metadata['render_modes']}, got {render_mode!r}")
        self.render_mode = render_mode
        self.level = level
        self.window = None  # the human-mode window, opened at the first picture
        self._window_closed = False
        self._due = 0.0  # host time when the picture shown may be replaced
        self.env = Env(game=game, **config)
        self.observation_space = observation_space(self.env.observation_spaces)
        self.action_space = spaces.Discrete(self.env.action_count)

    def reset(self, *, seed=None, options=None):
        super().reset(seed=seed)
        level = (options or {}).get("level", self.level)
        obs, info = self.env.reset(level, _seed_for_cpp(self.np_random, seed))
        if self.render_mode == "human":
            self._show(0)
        return obs, deterministic_info(info)

    def step(self, action):
        obs, reward, terminated, truncated, info = self.env.step(int(action))
        if self.render_mode == "human":
            self._show(info["game_frames"])
        return obs, reward, terminated, truncated, deterministic_info(info)

    def render(self):
        if self.render_mode == "rgb_array":
            return self.env.get_screen()
        if self.render_mode == "human":
            self._show(0)
        return None

    def _show(self, frames):
        """Human mode: shows the console's picture once the previous one has been up as long as the
        move between them lasted in the game (``frames`` at the console's rate). Closing the window
        (or Escape) stops showing; the environment goes on."""
        from . import Window, display_problem

        if self._window_closed:
            return
        picture = self.env.get_screen()
        if self.window is None:
            # Gymnasium's check_env makes an environment for every render mode the metadata lists,
            # also on headless servers: without a display, say so once and go on showing nothing.
            problem = display_problem()
            if not problem:
                title = f"psxrl: {self.spec.id if self.spec else type(self).__name__}"
                try:
                    self.window = Window(title, picture.shape[1], picture.shape[0])
                except RuntimeError as e:  # DISPLAY names a server that is not there
                    problem = str(e)
            if problem:
                warnings.warn(f"render_mode='human' shows nothing: {problem}", RuntimeWarning, stacklevel=3)
                self._window_closed = True
                return
            self._due = time.monotonic()
        self._due += frames / self._CONSOLE_FPS
        time.sleep(max(0.0, self._due - time.monotonic()))
        self.window.show(picture, read_back=True)  # window.picture() shows what the user saw
        self._due = max(self._due, time.monotonic())  # a slow host does not bank time to rush later
        if self.window.poll():
            self.window = None  # the window closes; the environment goes on
            self._window_closed = True

    def close(self):
        """Closes the window and releases the console at once; a later reset or step raises
        RuntimeError("Env is closed")."""
        self.window = None  # the window closes when its last reference goes
        self.env.close()
        super().close()


class TumbleEnv(PsxrlEnv):
    """Tumble, the built-in game. ``obs``: simple, local, visual, audio, episode, ram, rumble or
    multimodal; ``reward``: table, score or script; delimiter settings override the integration's."""

    def __init__(self, level=1, obs="simple", reward="table", gamma=0.9, visual_gray=False, initial_delay=None,
                 delay=None, max_move_frames=None, max_moves=None, render_mode=None):
        super().__init__(game="tumble", level=level, render_mode=render_mode, obs=obs, reward=reward, gamma=gamma,
                         visual_gray=visual_gray, initial_delay=initial_delay, delay=delay,
                         max_move_frames=max_move_frames, max_moves=max_moves)


class KulaEnv(PsxrlEnv):
    """Kula World from the user's own disc image and BIOS (games/kula/README.md); ``states`` and
    ``maps`` are folders of per-level save states and level maps."""

    def __init__(self, disc=None, bios=None, level=1, states=None, maps=None, obs="simple", reward="table",
                 gamma=0.9, visual_gray=False, initial_delay=None, delay=None, max_move_frames=None, max_moves=None,
                 render_mode=None):
        super().__init__(game="kula", level=level, render_mode=render_mode, disc=disc, bios=bios, states=states,
                         maps=maps, obs=obs, reward=reward, gamma=gamma, visual_gray=visual_gray,
                         initial_delay=initial_delay, delay=delay, max_move_frames=max_move_frames,
                         max_moves=max_moves)


def register_envs():
    for env_id, entry, vector_entry in (
        (TUMBLE_ID, "psxrl.gym_envs:TumbleEnv", "psxrl.vector:TumbleVectorEnv"),
        (KULA_ID, "psxrl.gym_envs:KulaEnv", "psxrl.vector:KulaVectorEnv"),
        (GAME_ID, "psxrl.gym_envs:PsxrlEnv", "psxrl.vector:PsxrlVectorEnv"),
    ):
        if env_id not in gym.registry:
            gym.register(id=env_id, entry_point=entry, vector_entry_point=vector_entry)
