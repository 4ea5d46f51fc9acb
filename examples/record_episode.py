#!/usr/bin/env python3
"""Records one Tumble episode, every emulated frame with its sound, to a video through Gymnasium.

  PYTHONPATH=build/python python3 examples/record_episode.py --out episode.mp4 [--level 1] [--seed 0]

The moves come from the level's scripted route (games/tumble/demo/) when there is one, so the
video shows a whole level being won; --random plays random moves instead. A folder name instead
of a .mp4/.mkv/.mov file gives PNG pictures and audio.wav.
"""
import argparse
from pathlib import Path

import gymnasium as gym
import numpy as np

import psxrl  # registers psxrl/Tumble-v0

ACTIONS = {"FORWARD": 0, "LOOKRIGHT": 1, "LOOKLEFT": 2, "JUMPFORWARD": 3}
# Level 1's route to 4000 points (games/tumble/levels/level01.txt): left column up, across the
# top to the key, down the right edge, up the right column, then west along the top to the exit.
LEVEL1_ROUTE = (["LOOKLEFT", "FORWARD", "LOOKRIGHT"] + ["FORWARD"] * 5 + ["LOOKRIGHT"] + ["FORWARD"] * 3 +
                ["LOOKRIGHT"] + ["FORWARD"] * 5 + ["LOOKRIGHT", "FORWARD", "LOOKRIGHT"] + ["FORWARD"] * 5 +
                ["LOOKLEFT"] + ["FORWARD"] * 3)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[1])
    p.add_argument("--out", default="episode.mp4")
    p.add_argument("--level", type=int, default=1)
    p.add_argument("--seed", type=int, default=0)
    p.add_argument("--random", action="store_true", help="random moves instead of the level 1 route")
    args = p.parse_args()

    env = gym.make("psxrl/Tumble-v0", level=args.level, obs="simple")
    env.reset(seed=args.seed)
    rng = np.random.default_rng(args.seed)
    route = [ACTIONS[a] for a in LEVEL1_ROUTE] if args.level == 1 and not args.random else []
    with psxrl.Recorder(env.unwrapped.env, args.out) as recorder:
        done, move = False, 0
        while not done:
            action = route[move] if move < len(route) else int(rng.integers(0, 4))
            _, _, terminated, truncated, info = env.step(action)
            done, move = terminated or truncated, move + 1
    print(f"score {info['score']}, {info['outcome'] or 'truncated'} after {info['moves']} moves")
    print(f"recorded {recorder.close()}")


if __name__ == "__main__":
    main()
