"""psxrl on Ray (the optional `ray` extra, `pip install .[ray]`; docs/scaling.md).

- Sweeps: `python -m psxrl.ray sweep CONFIG.toml [--address HOST:PORT]` runs a grid of
  `psxrl train` configurations x seeds as Ray tasks, resumable, and gathers a table and a figure
  (psxrl.ray.sweep, psxrl.ray.sweep_config, psxrl.ray.report).
- Rollouts: `RayVecEnv` / `RayAsyncVecEnv`, environments hosted by Ray actors and stepped in
  batches with NumPy arrays (psxrl.ray.rollouts).
- RLlib: `psxrl.ray.rllib.ppo_config()` trains PPO on psxrl/Tumble-v0 with env runners on Ray workers.

Importing this package needs Ray; `import psxrl` never imports it.
"""
from .rollouts import INFO_DTYPE, RayAsyncVecEnv, RayVecEnv, RolloutWorker
from .sweep_config import SweepConfigError, load as load_sweep
from .sweep import run as run_sweep

__all__ = ["INFO_DTYPE", "RayAsyncVecEnv", "RayVecEnv", "RolloutWorker", "SweepConfigError", "load_sweep",
           "run_sweep"]
