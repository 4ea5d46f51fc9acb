"""Stable-Baselines3 smoke run over psxrl/Tumble-v0 (CTest python_sb3_smoke).

Run by the interpreter of .venv-sb3 (scripts/setup.sh: Debian's CPU-only python3-torch with
stable-baselines3), not by pytest: the interpreter the module is built for has no PyTorch. Checks
that SB3's own environment checker accepts the environment, that DQN and PPO train for a few
hundred moves, that every move SB3 counts is a move the psxrl environment made, that a saved
model predicts the same greedy actions after loading, and that psxrl.make_vec works there.
"""
import os
import sys
import tempfile

import gymnasium as gym
import numpy as np

import psxrl  # registers psxrl/Tumble-v0
from stable_baselines3 import DQN, PPO
from stable_baselines3.common.env_checker import check_env
from stable_baselines3.common.vec_env import DummyVecEnv

failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)


class CountMoves(gym.Wrapper):
    """Counts the moves the psxrl environment really made (steps that reached the console)."""

    def __init__(self, env):
        super().__init__(env)
        self.moves = 0

    def step(self, action):
        self.moves += 1
        return self.env.step(action)


def make(obs="local"):
    return CountMoves(gym.make("psxrl/Tumble-v0", obs=obs, level=1, max_moves=30))


def greedy_actions(model, observations):
    return [int(model.predict(o, deterministic=True)[0]) for o in observations]


def check_make_vec():
    """psxrl.make_vec needs Gymnasium 1.1's AutoresetMode (#61): setup.sh installs 1.1.1 here,
    with SB3 2.4.1, whose declared gymnasium<1.1 is overridden (everything below runs on it)."""
    try:
        vec = psxrl.make_vec("psxrl/Tumble-v0", num_envs=2, max_moves=5)
        obs, _ = vec.reset(seed=1)
        obs, rewards, terminated, truncated, _ = vec.step(np.array([1, 2]))
        check(obs.shape == (2, 1) and rewards.shape == (2,),
              f"psxrl.make_vec steps 2 environments on Gymnasium {gym.__version__}")
    except Exception as e:  # ImportError on Gymnasium 1.0
        check(False, f"psxrl.make_vec on Gymnasium {gym.__version__}: {type(e).__name__}: {e}")


def main():
    check_make_vec()
    for obs in ("local", "simple"):
        try:
            check_env(make(obs).unwrapped, warn=True)
            check(True, f"SB3 check_env accepts obs={obs}")
        except Exception as e:  # SB3's checker raises AssertionError or ValueError
            check(False, f"SB3 check_env accepts obs={obs}: {e}")

    env = make()
    dqn = DQN("MlpPolicy", env, learning_starts=50, buffer_size=1000, batch_size=32, seed=1,
              device="cpu", policy_kwargs=dict(net_arch=[32, 32]))
    dqn.learn(total_timesteps=200)
    check(dqn.num_timesteps == 200, f"DQN counted 200 moves (counted {dqn.num_timesteps})")
    check(env.moves == 200, f"the psxrl environment made 200 moves under DQN (made {env.moves})")

    envs = [make(), make()]
    ppo = PPO("MlpPolicy", DummyVecEnv([lambda e=e: e for e in envs]), n_steps=32, batch_size=32,
              n_epochs=2, seed=1, device="cpu", policy_kwargs=dict(net_arch=[32, 32]))
    ppo.learn(total_timesteps=128)
    check(ppo.num_timesteps == 128, f"PPO counted 128 moves (counted {ppo.num_timesteps})")
    check([e.moves for e in envs] == [64, 64],
          f"each of PPO's 2 environments made 64 moves (made {[e.moves for e in envs]})")

    probe = make()
    observations = [probe.reset(seed=s)[0] for s in range(4)]
    observations += [probe.step(a)[0] for a in (0, 1, 2, 3)]
    check(all(probe.observation_space.contains(o) for o in observations),
          "observations lie in the observation space")
    with tempfile.TemporaryDirectory() as d:
        for name, model, cls in (("dqn", dqn, DQN), ("ppo", ppo, PPO)):
            path = os.path.join(d, name)
            model.save(path)
            loaded = cls.load(path, device="cpu")
            before, after = greedy_actions(model, observations), greedy_actions(loaded, observations)
            check(before == after, f"{name}: a saved and loaded model acts the same ({before} / {after})")
            check(all(0 <= a < 4 for a in after), f"{name}: greedy actions are one of the 4 moves")

    print(f"{len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    np.set_printoptions(precision=3)
    sys.exit(main())
