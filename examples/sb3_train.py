#!/usr/bin/env python3
"""Stable-Baselines3 DQN or PPO on a Tumble level through Gymnasium, with its learning curve.

Trains on the agent-local observation (the seed's 11 numbers) with the seed's Table 3.3 rewards,
then plays greedy test episodes and writes the run folder: ``curve.png`` (training episode scores
and their 20-episode moving average), ``episodes.csv`` and ``model.zip``.

  .venv-sb3/bin/python examples/sb3_train.py --algo dqn --steps 20000 --out runs/sb3-dqn
  .venv-sb3/bin/python examples/sb3_train.py --algo ppo --steps 20000 --envs 2 --out runs/sb3-ppo

Stable-Baselines3 needs PyTorch; ``scripts/setup.sh`` makes ``.venv-sb3``, a virtual environment
over Debian's python3-torch (CPU only) with SB3 installed, and the module comes from the build
tree (``PYTHONPATH=build/python``) or from ``pip install .``.
"""
import argparse
import csv
import os
import time

import gymnasium as gym
import numpy as np

import psxrl  # registers psxrl/Tumble-v0

from stable_baselines3 import DQN, PPO
from stable_baselines3.common.callbacks import BaseCallback
from stable_baselines3.common.monitor import Monitor
from stable_baselines3.common.vec_env import DummyVecEnv


class EpisodeLog(BaseCallback):
    """Collects each finished training episode's game score, moves and outcome from ``info``."""

    def __init__(self):
        super().__init__()
        self.rows = []

    def _on_step(self):
        for done, info in zip(self.locals["dones"], self.locals["infos"]):
            if done:
                self.rows.append({"timestep": self.num_timesteps, "score": info["score"],
                                  "moves": info["moves"], "outcome": info["outcome"]})
        return True


def make_env(args, rank):
    def thunk():
        env = gym.make("psxrl/Tumble-v0", obs="local", level=args.level, max_moves=args.max_moves)
        env.reset(seed=args.seed + rank)
        return Monitor(env)
    return thunk


def build_model(args, env):
    common = dict(seed=args.seed, verbose=0, device="cpu", gamma=0.9)
    if args.algo == "dqn":
        return DQN("MlpPolicy", env, learning_rate=1e-3, buffer_size=5000, learning_starts=200,
                   batch_size=64, train_freq=1, target_update_interval=250,
                   exploration_fraction=0.5, exploration_final_eps=0.05,
                   policy_kwargs=dict(net_arch=[64, 64]), **common)
    return PPO("MlpPolicy", env, learning_rate=3e-4, n_steps=256, batch_size=64, n_epochs=10,
               ent_coef=0.01, policy_kwargs=dict(net_arch=[64, 64]), **common)


def greedy_scores(model, args, episodes):
    env = gym.make("psxrl/Tumble-v0", obs="local", level=args.level, max_moves=args.max_moves)
    scores = []
    for i in range(episodes):
        obs, info = env.reset(seed=10_000 + i)
        done = False
        while not done:
            action, _ = model.predict(obs, deterministic=True)
            obs, _, terminated, truncated, info = env.step(int(action))
            done = terminated or truncated
        scores.append((info["score"], info["outcome"], info["moves"]))
    return scores


def write_curve(rows, path, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    scores = np.array([r["score"] for r in rows], dtype=float)
    window = min(20, max(1, len(scores)))
    average = np.convolve(scores, np.ones(window) / window, mode="valid")
    fig, ax = plt.subplots(figsize=(8, 4.5), dpi=100)
    ax.plot(np.arange(1, len(scores) + 1), scores, color="tab:red", alpha=0.3, label="training episode")
    ax.plot(np.arange(window, len(scores) + 1), average, color="tab:red", label=f"{window}-episode average")
    ax.set_xlabel("episode")
    ax.set_ylabel("game score")
    ax.set_title(title)
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--algo", choices=["dqn", "ppo"], default="dqn")
    p.add_argument("--level", type=int, default=1)
    p.add_argument("--steps", type=int, default=20000, help="environment moves to train for")
    p.add_argument("--envs", type=int, default=1, help="environments (DummyVecEnv)")
    p.add_argument("--max-moves", type=int, default=100, help="move cap per episode")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--test-episodes", type=int, default=3)
    p.add_argument("--out", default=None, help="run folder (default runs/sb3-ALGO-lLEVEL-sSEED)")
    args = p.parse_args()
    out = args.out or f"runs/sb3-{args.algo}-l{args.level}-s{args.seed}"
    os.makedirs(out, exist_ok=True)

    env = DummyVecEnv([make_env(args, i) for i in range(args.envs)])
    model = build_model(args, env)
    log = EpisodeLog()
    start = time.perf_counter()
    model.learn(total_timesteps=args.steps, callback=log)
    seconds = time.perf_counter() - start
    model.save(os.path.join(out, "model.zip"))

    with open(os.path.join(out, "episodes.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["timestep", "score", "moves", "outcome"])
        w.writeheader()
        w.writerows(log.rows)
    title = f"SB3 {args.algo.upper()} on Tumble level {args.level}, seed {args.seed}"
    write_curve(log.rows, os.path.join(out, "curve.png"), title)

    wins = [i + 1 for i, r in enumerate(log.rows) if r["outcome"] == "win"]
    first = wins[0] if wins else None
    last = [r["score"] for r in log.rows[-20:]]
    print(f"{args.algo}: {args.steps} moves, {len(log.rows)} training episodes in {seconds:.0f} s "
          f"({args.steps / seconds:.1f} moves/s); first win at training episode {first}; "
          f"mean score of the last {len(last)} episodes {np.mean(last) if last else 0:.0f}")
    for score, outcome, moves in greedy_scores(model, args, args.test_episodes):
        print(f"greedy test: score {score}, {outcome}, {moves} moves")


if __name__ == "__main__":
    main()
