#!/usr/bin/env python3
"""Moves per second of Tumble environments stepped through Ray actors (psxrl.ray.RayVecEnv, 1 and
2 workers) against the same environments stepped in this process, and the per-batch cost of the
actor hop; from these, what a larger cluster should reach (docs/scaling.md):

  PYTHONPATH=build/python .venv-ray/bin/python bench/ray_bench.py [--envs 2] [--steps 200] [--obs local]

Every row steps `--envs` consoles per worker with one thread each, with the same pseudo-random
actions; episodes reset inside the step as in training. Besides wall-clock moves per second, each
row gives moves per CPU-second (this process's CPU time, plus the Ray workers' own), which other
load on the machine changes far less. Ray runs a local instance of its own.
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


def measure(step, steps, n, worker_cpu=time.process_time):
    """For `steps` batches of `n` environments after one warm-up batch: (moves per wall second,
    moves per CPU-second of everything, moves per CPU-second of the workers, this process's CPU
    seconds per batch). In-process, this process is the worker."""
    acts = action_rows(steps + 1, n)
    step(acts[0])
    wall, cpu, workers = time.perf_counter(), time.process_time(), worker_cpu()
    for a in acts[1:]:
        step(a)
    wall, cpu, workers = time.perf_counter() - wall, time.process_time() - cpu, worker_cpu() - workers
    moves = steps * n
    if worker_cpu is time.process_time:
        return moves / wall, moves / cpu, moves / cpu, cpu / steps
    return moves / wall, moves / (cpu + workers), moves / workers, cpu / steps


def in_process(workers, envs, steps, config):
    vec = psxrl.VecEnv(workers * envs, workers, **config)  # one thread per `envs` consoles
    vec.reset(1, 1)
    return measure(vec.step, steps, workers * envs)


def through_ray(workers, envs, steps, config):
    remote = RayVecEnv(workers, envs, threads=1, **config)
    try:
        remote.reset(1, list(range(1, workers + 1)))
        cpu = lambda: sum(ray.get([w.cpu_seconds.remote() for w in remote.workers]))  # noqa: E731
        return measure(remote.step, steps, workers * envs, cpu)
    finally:
        remote.close()


def hop(envs, config, calls=300):
    """(median round trip of one actor call carrying a batch's actions and returning them, in us;
    this process's CPU time per call when calls are pipelined, in us: the learner's own cost)."""
    remote = RayVecEnv(1, envs, threads=1, **config)
    try:
        actions = action_rows(1, envs)[0]
        worker = remote.workers[0]
        times = []
        for _ in range(calls):
            t0 = time.perf_counter()
            ray.get(worker.ping.remote(actions))
            times.append(time.perf_counter() - t0)
        cpu = time.process_time()
        ray.get([worker.ping.remote(actions) for _ in range(calls)])
        return statistics.median(times) * 1e6, (time.process_time() - cpu) / calls * 1e6
    finally:
        remote.close()


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--envs", type=int, default=2, help="consoles per worker (default 2)")
    p.add_argument("--steps", type=int, default=200, help="batches stepped per row (default 200)")
    p.add_argument("--obs", default="local", help="observation kind (default local)")
    a = p.parse_args()
    config = {"obs": a.obs}
    ray.init(num_cpus=2, include_dashboard=False, log_to_driver=False)
    print(f"Tumble level 1, obs={a.obs}, {a.envs} consoles per worker, {a.steps} batches a row; "
          f"{os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f} at the start")
    rows = {}
    for workers in (1, 2):
        rows[workers] = (in_process(workers, a.envs, a.steps, config), through_ray(workers, a.envs, a.steps, config))
        (local, local_cpu, _, _), (remote, remote_cpu, worker_cpu, learner) = rows[workers]
        print(f"{workers} worker{'s' if workers > 1 else ' '}: in-process {local:6.0f} moves/s, "
              f"{local_cpu:4.0f} per CPU-s  |  Ray actors {remote:6.0f} moves/s, {remote_cpu:4.0f} per CPU-s in all, {worker_cpu:4.0f} per "
              f"worker CPU-s, learner CPU {learner * 1e6 / workers:.0f} us per worker call")
    round_trip, per_call = hop(a.envs, config)
    step_us = a.envs / rows[1][0][1] * 1e6  # CPU time to step one worker's batch in-process
    print(f"actor hop: {round_trip:.0f} us median round trip per call, the learner's CPU {per_call:.0f} us per "
          f"pipelined call; stepping {a.envs} consoles in-process takes {step_us:.0f} us of CPU")
    per_worker = rows[2][1][2]
    call_us = rows[2][1][3] * 1e6 / 2
    ceiling = a.envs / call_us * 1e6
    print(f"a larger cluster: each worker core adds about {per_worker:.0f} moves/s; one synchronous learner, at "
          f"{call_us:.0f} us of its CPU per worker call, binds at about {ceiling:.0f} moves/s "
          f"({ceiling / per_worker:.0f} worker cores) with {a.envs} consoles a call, more in proportion to them")
    ray.shutdown()


if __name__ == "__main__":
    main()
