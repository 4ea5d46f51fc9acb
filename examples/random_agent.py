#!/usr/bin/env python3
"""A random agent on Tumble through Gymnasium: one environment, then a C++-backed vector env.

  PYTHONPATH=build/python python3 examples/random_agent.py [--obs local] [--episodes 3]
"""
import argparse

import gymnasium as gym
import numpy as np

import psxrl  # registers psxrl/Tumble-v0 and psxrl/Kula-v0


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--obs", default="simple")
    p.add_argument("--level", type=int, default=1)
    p.add_argument("--episodes", type=int, default=3)
    p.add_argument("--envs", type=int, default=2)
    args = p.parse_args()

    env = gym.make("psxrl/Tumble-v0", obs=args.obs, level=args.level)
    print(f"observation space {env.observation_space}, actions {env.action_space}")
    for episode in range(args.episodes):
        obs, info = env.reset(seed=episode)
        total, done = 0.0, False
        while not done:
            obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
            total += reward
            done = terminated or truncated
        print(f"episode {episode}: {info['moves']} moves, return {total:+.3f}, score {info['score']}, "
              f"{info['outcome'] or 'truncated'}")
    env.close()

    venv = psxrl.make_vec("psxrl/Tumble-v0", num_envs=args.envs, obs=args.obs, level=args.level)
    venv.reset(seed=0)
    returns, finished = np.zeros(args.envs), []
    while len(finished) < args.episodes:
        _, rewards, terminated, truncated, info = venv.step(venv.action_space.sample())
        returns += rewards
        for i in np.flatnonzero(terminated | truncated):  # reset in the same step (SAME_STEP)
            finished.append(returns[i])
            returns[i] = 0
    print(f"vector env ({args.envs} consoles): returns of the first episodes {np.round(finished, 3).tolist()}")
    venv.close()


if __name__ == "__main__":
    main()
