"""Behavioural cloning from a human-played Tumble session (docs/offline.md): the session recorded by
`psxrl record` becomes a Minari dataset (psxrl.offline), a small network learns the player's move
for each observation, and the clone then plays the level greedily in the environment.

    psxrl record --game tumble --out session/          # play a level in the window, Escape to end
    psxrl record --game tumble --stdin --out session/ < examples/data/tumble_level1_typed.txt
                                                       # or typed moves, no display (docs/offline.md)
    python examples/bc_tumble.py session/ [--obs local] [--steps 2000] [--seed 0]

Needs Minari and PyTorch (.venv-sb3 of scripts/setup.sh has both). Prints the clone's accuracy on
the session's moves and the score and outcome of its own episode from each level's start.
"""
import argparse

import minari
import numpy as np
import torch

from psxrl import Env, offline


def dataset(session, obs):
    env, episodes = offline.session_episodes(session, obs=obs)
    dataset_id = f"psxrl/tumble-bc-{obs}-v0"
    if dataset_id in minari.list_local_datasets():
        minari.delete_dataset(dataset_id)
    offline.write_dataset(dataset_id, env, episodes, description="a recorded Tumble session, for behavioural cloning")
    return minari.load_dataset(dataset_id), [level for level, _ in offline.session_actions(session)]


def train(data, steps, seed):
    """An MLP from observation to move, trained with cross-entropy on every (observation, move) pair."""
    xs = np.concatenate([e.observations[:-1] for e in data.iterate_episodes()]).astype(np.float32)
    ys = np.concatenate([e.actions for e in data.iterate_episodes()])
    torch.manual_seed(seed)
    net = torch.nn.Sequential(torch.nn.Linear(xs.shape[1], 64), torch.nn.ReLU(), torch.nn.Linear(64, 64),
                              torch.nn.ReLU(), torch.nn.Linear(64, data.spec.action_space.n))
    opt = torch.optim.Adam(net.parameters(), lr=1e-3)
    x, y = torch.from_numpy(xs), torch.from_numpy(ys).long()
    for _ in range(steps):
        opt.zero_grad()
        loss = torch.nn.functional.cross_entropy(net(x), y)
        loss.backward()
        opt.step()
    with torch.no_grad():
        accuracy = (net(x).argmax(1) == y).float().mean().item()
    return net, accuracy, len(ys)


def play(net, obs, level, max_moves):
    env = Env(obs=obs, max_moves=max_moves)
    o, _ = env.reset(level, 0)
    done, info = False, {}
    while not done:
        with torch.no_grad():
            action = int(net(torch.from_numpy(np.asarray(o, dtype=np.float32))[None]).argmax())
        o, _, terminated, truncated, info = env.step(action)
        done = terminated or truncated
    return info


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("session")
    parser.add_argument("--obs", default="local", choices=["simple", "local"])
    parser.add_argument("--steps", type=int, default=2000)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--max-moves", type=int, default=100)
    args = parser.parse_args()
    data, levels = dataset(args.session, args.obs)
    net, accuracy, moves = train(data, args.steps, args.seed)
    print(f"session: {data.total_episodes} episode(s), {moves} moves; the clone repeats {accuracy:.0%} of them")
    for level in levels:
        info = play(net, args.obs, level, args.max_moves)
        print(f"level {level}: the clone scores {info['score']} in {info['moves']} moves ({info['outcome'] or 'cut'})")


if __name__ == "__main__":
    main()
