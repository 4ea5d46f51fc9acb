#!/usr/bin/env python3
"""Moves per second of Tumble environments stepped through Ray actors (psxrl.ray.RayVecEnv, 1 and
2 workers) against the same environments stepped in this process, and the per-batch cost of the
actor hop alone; from these, what a larger cluster should reach (docs/scaling.md):

  PYTHONPATH=build/python .venv-ray/bin/python bench/ray_bench.py [--envs 2] [--steps 150] [--obs local]

Every row steps `--envs` consoles per worker with one thread each, with the same pseudo-random
actions; episodes reset inside the step as in training. Ray runs a local instance of its own.
"""
import argparse
import os
import statistics
import time

import numpy as np

os.environ.setdefault("RAY_USAGE_STATS_ENABLED", "0")
import psxrl  # noqa: E402
import ray  # noqa: E402
from psxrl.ray import RayVecEnv  # noqa: E402


def action_rows(steps, n, seed=7):
    return np.random.default_rng(seed).integers(0, 4, size=(steps, n), dtype=np.int32)


def rate(step, steps, n):
    """Moves per second of `step` over `steps` batches of `n` environments (after one warm-up batch)."""
    acts = action_rows(steps + 1, n)
    step(acts[0])
    t0 = time.perf_counter()
    for a in acts[1:]:
        step(a)
    return steps * n / (time.perf_counter() - t0)


def in_process(workers, envs, steps, config):
    vec = psxrl.VecEnv(workers * envs, workers, **config)  # one thread per `envs` consoles
    vec.reset(1, 1)
    return rate(vec.step, steps, workers * envs)


def through_ray(workers, envs, steps, config):
    remote = RayVecEnv(workers, envs, threads=1, **config)
    try:
        remote.reset(1, list(range(1, workers + 1)))
        return rate(remote.step, steps, workers * envs)
    finally:
        remote.close()


def hop_microseconds(envs, config, calls=300):
    """(median round trip of one actor call carrying a batch's actions and returning them, the
    learner's own time per call when calls are pipelined: its ceiling in calls per second)."""
    remote = RayVecEnv(1, envs, threads=1, **config)
    try:
        actions = action_rows(1, envs)[0]
        worker = remote.workers[0]
        times = []
        for _ in range(calls):
            t0 = time.perf_counter()
            ray.get(worker.ping.remote(actions))
            times.append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        ray.get([worker.ping.remote(actions) for _ in range(calls)])
        return statistics.median(times) * 1e6, (time.perf_counter() - t0) / calls * 1e6
    finally:
        remote.close()


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--envs", type=int, default=2, help="consoles per worker (default 2)")
    p.add_argument("--steps", type=int, default=150, help="batches stepped per row (default 150)")
    p.add_argument("--obs", default="local", help="observation kind (default local)")
    a = p.parse_args()
    config = {"obs": a.obs}
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    print(f"Tumble level 1, obs={a.obs}, {a.envs} consoles per worker, {a.steps} batches a row; "
          f"{os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f} at the start")
    rows = {}
    for workers in (1, 2):
        rows[workers] = (in_process(workers, a.envs, a.steps, config), through_ray(workers, a.envs, a.steps, config))
        local, remote = rows[workers]
        print(f"{workers} worker{'s' if workers > 1 else ' '}: in-process {local:8.1f} moves/s   "
              f"through Ray actors {remote:8.1f} moves/s   ({remote / local:.2f} of in-process)")
    hop, per_call = hop_microseconds(a.envs, config)
    batch_us = a.envs / rows[1][0] * 1e6
    print(f"actor hop: {hop:.0f} us per batch (median round trip), against {batch_us:.0f} us to step a batch "
          f"of {a.envs} in-process: {hop / (hop + batch_us):.0%} of a synchronous Ray step")
    ceiling = a.envs / per_call * 1e6
    print(f"learner: {per_call:.0f} us of its own time per pipelined actor call, so one learner drives at most "
          f"{1e6 / per_call:.0f} batches/s = {ceiling:.0f} moves/s with {a.envs} consoles a batch")
    workers = max(1, int(ceiling // rows[1][1]))
    print(f"a larger cluster: about {rows[1][1]:.0f} moves/s per worker process (one core), adding up until "
          f"about {workers} workers share one learner; more consoles per batch raise that ceiling in proportion")
    ray.shutdown()


if __name__ == "__main__":
    main()
