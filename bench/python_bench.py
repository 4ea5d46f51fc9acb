#!/usr/bin/env python3
"""Moves per second through Python against the same work in C++ (Tumble level 1, a fixed pseudo-
random action sequence, episodes reset as in training), so the binding's overhead is a figure:

  PYTHONPATH=build/python python3 bench/python_bench.py [--moves 300] [--envs 2]

For psxrl.Env each step's info["real_seconds"] is the host time spent inside the C++ Env::step,
(and of reset, after an episode ends), so "C++ moves/s" and the overhead per step come from the same run, unaffected by other load on
the machine. The vector rows compare the C++-backed psxrl.make_vec with Gymnasium's own
SyncVectorEnv and AsyncVectorEnv over the same environments. build/bench/env_bench prints the
pure C++ figures for comparison.
"""
import argparse
import time

import gymnasium as gym
import numpy as np

import psxrl


def actions(n, seed=7):
    return np.random.default_rng(seed).integers(0, 4, size=n)


def bench_env(obs, moves):
    env = psxrl.Env(obs=obs)
    seed = 1
    env.reset(1, seed)
    inside = 0.0  # host seconds inside the C++ step and reset calls
    t0 = time.perf_counter()
    for a in actions(moves):
        _, _, terminated, truncated, info = env.step(int(a))
        inside += info["real_seconds"]
        if terminated or truncated:
            seed += 1
            inside += env.reset(1, seed)[1]["real_seconds"]
    wall = time.perf_counter() - t0
    return moves / wall, moves / inside, (wall - inside) / moves * 1e6


def bench_gym(obs, moves):
    env = gym.make("psxrl/Tumble-v0", obs=obs)
    env.reset(seed=1)
    t0 = time.perf_counter()
    for a in actions(moves):
        _, _, terminated, truncated, _ = env.step(int(a))
        if terminated or truncated:
            env.reset()
    return moves / (time.perf_counter() - t0)


def bench_vector(venv, k, steps):
    venv.reset(seed=1)
    acts = actions(steps * k).reshape(steps, k)
    t0 = time.perf_counter()
    for a in acts:
        venv.step(a)  # same-step autoreset in all three
    rate = steps * k / (time.perf_counter() - t0)
    venv.close()
    return rate


def bench_calls(n=20000):
    """Cost of crossing the binding without emulation: a memory read, and an observation copy."""
    env = psxrl.Env(obs="simple")
    env.reset(1, 1)
    c = psxrl.Console()
    t0 = time.perf_counter()
    for _ in range(n):
        c.read32(0x80010000)
    read_us = (time.perf_counter() - t0) / n * 1e6
    t0 = time.perf_counter()
    for _ in range(n):
        env.observation()
    obs_us = (time.perf_counter() - t0) / n * 1e6
    return read_us, obs_us


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--moves", type=int, default=300, help="moves per single-environment row")
    p.add_argument("--envs", type=int, default=2, help="environments in the vector rows")
    args = p.parse_args()
    k, steps = args.envs, max(1, args.moves // args.envs)

    print(f"Tumble level 1, {args.moves} moves per row")
    print(f"{'psxrl.Env':24} {'obs':8} {'Python moves/s':>15} {'C++ moves/s':>12} {'overhead us/move':>17}")
    for obs in ("simple", "visual", "multimodal"):
        py_rate, cpp_rate, overhead = bench_env(obs, args.moves)
        print(f"{'':24} {obs:8} {py_rate:15.1f} {cpp_rate:12.1f} {overhead:17.1f}")
    print(f"{'gymnasium.make':24} {'simple':8} {bench_gym('simple', args.moves):15.1f}")
    read_us, obs_us = bench_calls()
    print(f"\nbinding calls: Console.read32 {read_us:.2f} us, Env.observation() (simple, a copy) {obs_us:.2f} us")

    print(f"\nvector, {k} environments x {steps} steps (moves/s over all environments)")
    sync_env = gym.vector.SyncVectorEnv([lambda: gym.make("psxrl/Tumble-v0") for _ in range(k)],
                                        autoreset_mode=gym.vector.AutoresetMode.SAME_STEP)
    async_env = gym.vector.AsyncVectorEnv([lambda: gym.make("psxrl/Tumble-v0") for _ in range(k)],
                                          autoreset_mode=gym.vector.AutoresetMode.SAME_STEP)
    rows = [("psxrl.make_vec (C++ pool)", psxrl.make_vec("psxrl/Tumble-v0", num_envs=k)),
            ("gymnasium SyncVectorEnv", sync_env), ("gymnasium AsyncVectorEnv", async_env)]
    for name, venv in rows:
        print(f"{name:28} {bench_vector(venv, k, steps):10.1f}")


if __name__ == "__main__":
    main()
