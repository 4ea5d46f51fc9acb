"""psxrl: a PlayStation emulator and reinforcement-learning environments, in-process.

``psxrl.Console`` is the emulator (the seed's PSXPY surface, synchronous); ``psxrl.Env`` and
``psxrl.VecEnv`` (batched) and ``psxrl.AsyncVecEnv`` (EnvPool's send/recv) are the C++ environments; importing the package registers the Gymnasium ids
``psxrl/Tumble-v0``, ``psxrl/Kula-v0`` and ``psxrl/Game-v0`` (any integration: ``make_env``) when
Gymnasium is installed. See docs/python.md.
"""
import os as _os
from pathlib import Path as _Path

from . import _psxrl
from ._psxrl import (BUTTONS, Console, InputError, QueryError, Recorder, Search, Session, StateError, WatchEvent,
                     Window, display_problem, episode_seed)

__all__ = [
    "AsyncVecEnv", "BUTTONS", "Console", "Env", "InputError", "QueryError", "Recorder", "Search", "Session", "StateError", "VecEnv",
    "WatchEvent", "Window", "display_problem", "episode_seed", "make_env", "make_vec",
]

# `pip install .` puts the integrations and Tumble's program in psxrl/games; a module imported from
# the build tree has no such folder and uses the source tree's games/ and build/games, compiled in.
_PACKAGED_GAMES = _Path(__file__).parent / "games"


def _with_games(kwargs):
    if not _PACKAGED_GAMES.is_dir():
        return kwargs
    kwargs = dict(kwargs)
    if kwargs.get("games_dir") is None and "PSXRL_GAMES" not in _os.environ:
        kwargs["games_dir"] = str(_PACKAGED_GAMES)
    if kwargs.get("build_games_dir") is None:
        kwargs["build_games_dir"] = str(_PACKAGED_GAMES)
    return kwargs


def _rebuild(cls, args, kwargs):
    return cls(*args, **kwargs)


class _ByConfiguration:
    """Pickling by configuration: an environment pickles as the arguments that made it and unpickles
    as a new one booted from them (so SubprocVecEnv, AsyncVectorEnv with the spawn method and Ray
    can ship it); its episode is not carried over. A copy is refused: a console's state is copied
    with save states (``Console.save_state``, ``Env.snapshot`` in C++), not by deepcopy."""

    def _remember(self, args, kwargs):
        self._config = (tuple(args), dict(kwargs))

    def __reduce__(self):
        args, kwargs = self._config
        return (_rebuild, (type(self), args, kwargs))

    def __copy__(self):
        raise TypeError(f"a {type(self).__name__} cannot be copied: make another from the same arguments, or copy "
                        "the console's state with save states (Console.save_state / load_state)")

    def __deepcopy__(self, memo):
        self.__copy__()


class Env(_ByConfiguration, _psxrl.Env):
    __doc__ = _psxrl.Env.__doc__

    def __init__(self, **kwargs):
        super().__init__(**_with_games(kwargs))
        self._remember((), kwargs)


class VecEnv(_ByConfiguration, _psxrl.VecEnv):
    __doc__ = _psxrl.VecEnv.__doc__

    def __init__(self, num_envs, threads=0, **kwargs):
        super().__init__(num_envs, threads, **_with_games(kwargs))
        self._remember((num_envs, threads), kwargs)


class AsyncVecEnv(_ByConfiguration, _psxrl.AsyncVecEnv):
    __doc__ = _psxrl.AsyncVecEnv.__doc__

    def __init__(self, num_envs, batch_size=0, threads=0, **kwargs):
        super().__init__(num_envs, batch_size, threads, **_with_games(kwargs))
        self._remember((num_envs, batch_size, threads), kwargs)


def make_env(game, **kwargs):
    """Any integration as a Gymnasium environment, your own included:
    ``make_env(game="mygame", games_dir="mygames", bios="bios.bin", obs="visual")`` loads
    ``mygames/mygame/game.toml`` (``games_dir`` defaults to ``$PSXRL_GAMES``, else the built-in
    games). Other keywords: ``level``, ``render_mode`` and psxrl.Env's (``disc``, ``states``,
    ``maps``, ``reward``, ``gamma``, delimiter overrides...). Same as
    ``gymnasium.make("psxrl/Game-v0", game=..., ...)``."""
    import gymnasium

    return gymnasium.make("psxrl/Game-v0", game=game, **kwargs)


def make_vec(id="psxrl/Game-v0", num_envs=1, **kwargs):
    """A Gymnasium vector environment backed by the C++ VecEnv (one console per environment,
    stepped on a thread pool, same-step autoreset): ``make_vec("psxrl/Tumble-v0", num_envs=8)``,
    or for any integration ``make_vec(num_envs=8, game="mygame", games_dir="mygames")``."""
    import gymnasium

    return gymnasium.make_vec(id, num_envs=num_envs, vectorization_mode="vector_entry_point", **kwargs)


try:
    import gymnasium as _gymnasium
except ImportError:  # the console and the C++ environments work without Gymnasium
    _gymnasium = None
if _gymnasium is not None:
    from .gym_envs import register_envs as _register_envs

    _register_envs()
