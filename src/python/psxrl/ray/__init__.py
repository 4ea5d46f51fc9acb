"""psxrl on Ray (the optional `ray` extra, `pip install .[ray]`; docs/scaling.md).

- Sweeps: `psxrl sweep CONFIG.toml` or `python -m psxrl.ray sweep CONFIG.toml [--address HOST:PORT]` runs a grid of
  `psxrl train` configurations x seeds as Ray tasks, resumable, and gathers a table and a figure
  (psxrl.ray.sweep, psxrl.ray.sweep_config, psxrl.ray.report).
- Rollouts: `RayVecEnv` / `RayAsyncVecEnv`, environments hosted by Ray actors and stepped in
  batches with NumPy arrays (psxrl.ray.rollouts).
- RLlib: `psxrl.ray.rllib.ppo_config()` trains PPO on psxrl/Tumble-v0 with env runners on Ray workers.

Its names need Ray (imported with the first one used); `import psxrl` never imports this package.
"""
import importlib

# Ray is imported with the first name used, so `python -m psxrl.ray` can say that Ray is missing.
_EXPORTS = {"INFO_DTYPE": "rollouts", "RayAsyncVecEnv": "rollouts", "RayVecEnv": "rollouts",
            "RolloutWorker": "rollouts", "SweepConfigError": "sweep_config", "load_sweep": "sweep_config",
            "run_sweep": "sweep"}
_NAMES = {"load_sweep": "load", "run_sweep": "run"}
__all__ = sorted(_EXPORTS)


def __getattr__(name):
    if name not in _EXPORTS:
        raise AttributeError(f"module 'psxrl.ray' has no attribute {name!r}")
    return getattr(importlib.import_module(f".{_EXPORTS[name]}", __name__), _NAMES.get(name, name))
