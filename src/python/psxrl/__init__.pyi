"""Type stubs for the psxrl package (docs/python.md)."""
from typing import Any

import gymnasium

from ._psxrl import (BUTTONS as BUTTONS, Console as Console, InputError as InputError, QueryError as QueryError,
                     Recorder as Recorder, Search as Search, Session as Session, StateError as StateError, WatchEvent as WatchEvent,
                     Window as Window, display_problem as display_problem,
                     episode_seed as episode_seed)
from ._psxrl import Env as _Env
from ._psxrl import VecEnv as _VecEnv
from ._psxrl import AsyncVecEnv as _AsyncVecEnv

class Env(_Env): ...
class VecEnv(_VecEnv): ...
class AsyncVecEnv(_AsyncVecEnv): ...

def make_env(game: str, **kwargs: Any) -> gymnasium.Env: ...
def make_vec(id: str = "psxrl/Game-v0", num_envs: int = 1, **kwargs: Any) -> gymnasium.vector.VectorEnv: ...
