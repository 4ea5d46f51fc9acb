"""Offline data for imitation learning and offline RL: episodes of a psxrl environment as Minari
datasets (docs/offline.md), from a policy's rollouts or from a play session recorded by
`psxrl record` (a person playing in the window, or an input script).

A session is frames of pad input; an environment step is one move. ``session_actions`` replays the
session in a Console and reads the integration's ``move`` variable (the move in progress: action
index + 1, 0 when idle, as Tumble's RAM contract has it) on every frame, so each move the player
started becomes one action; ``session_episodes`` then plays those actions in the environment from
each level's start, giving the observations, rewards and flags a policy would have had. Moves are
deterministic, so the environment's episode ends as the session's did (``psxrl record``'s clock is
the only difference: the player's pauses between moves are not replayed).

A policy trained by ``psxrl train`` lives in its run folder, and only the C++ player can run it:
``policy_episodes`` has ``psxrl play --rollout`` play it greedily and replays each episode's moves
here, in an environment of the run's observation, checking every reward against the player's.

Minari is not a dependency of psxrl: ``write_dataset`` imports it (scripts/setup.sh installs it in
.venv-sb3). ``python -m psxrl.offline`` exports from the command line (``--help``).
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile
import tomllib
from pathlib import Path

def _games_dir(games_dir):
    """The folder an Env finds the integration in: an installed module's psxrl/games, else (a module
    of the build tree) $PSXRL_GAMES or the source tree's games/."""
    from . import _PACKAGED_GAMES, _psxrl

    if games_dir is not None:
        return Path(games_dir)
    if "PSXRL_GAMES" not in os.environ and _PACKAGED_GAMES.is_dir():
        return _PACKAGED_GAMES
    return Path(_psxrl.default_games_dir())


def _addresses(game, games_dir):
    """The RAM addresses of the integration's state, level and move variables."""
    path = _games_dir(games_dir) / game / "game.toml"
    with open(path, "rb") as f:
        variables = tomllib.load(f).get("variables", {})
    missing = [v for v in ("state", "level", "move") if v not in variables]
    if missing:
        raise ValueError(f"{path}: a session becomes actions through the variables state, level and move; "
                         f"[variables] lacks {', '.join(missing)}")
    return {v: int(variables[v]["address"]) for v in ("state", "level", "move")}


def session_actions(session_dir, game="tumble", playing=48, games_dir=None):
    """The moves of a recorded session: a list of (level, [action indices]), one entry per level
    started (the game's state variable becoming ``playing``), in the order played."""
    from . import Console, Session

    session_dir = Path(session_dir)
    with open(session_dir / "session.toml", "rb") as f:
        source = tomllib.load(f)["source"]
    if not source.get("exe"):
        raise ValueError(f"{session_dir}/session.toml: the session must have booted an executable (psxrl record --game)")
    at = _addresses(game, games_dir)
    console = Console()
    console.boot_exe(source["exe"])
    console.load_state((session_dir / "start.state").read_bytes())
    episodes, was_playing, moving = [], False, 0
    for buttons in Session(str(session_dir)).inputs[:, 0]:
        console.set_buttons(int(buttons))
        console.run_frame()
        state, move = console.read32(at["state"]), console.read32(at["move"])
        if state == playing and not was_playing:
            episodes.append((console.read32(at["level"]), []))
        was_playing = state == playing
        if was_playing and move and not moving:
            episodes[-1][1].append(move - 1)
        moving = move
    console.close()
    return episodes


def _episode(env, first_obs, actions_or_policy, max_moves=None):
    """Steps ``env`` from ``first_obs`` with a list of actions or a policy (obs -> action) until
    the episode ends; returns Minari's episode buffer and the final info."""
    obs, actions, rewards, terms, truncs, info = [first_obs], [], [], [], [], {}
    scripted = not callable(actions_or_policy)
    while not (terms and (terms[-1] or truncs[-1])):
        if scripted and len(actions) == len(actions_or_policy):
            break  # the session's moves ran out before the episode ended (the recording stopped)
        action = actions_or_policy[len(actions)] if scripted else int(actions_or_policy(obs[-1]))
        o, r, term, trunc, info = env.step(action)
        obs.append(o)
        actions.append(action)
        rewards.append(r)
        terms.append(term)
        truncs.append(trunc)
    return {"observations": obs, "actions": actions, "rewards": rewards, "terminations": terms,
            "truncations": truncs}, info


def _parts(obs):
    """A list of observations as Minari keeps them: a list of arrays, or for a multimodal
    observation a dict of lists (one per part)."""
    if isinstance(obs[0], dict):
        return {k: [o[k] for o in obs] for k in obs[0]}
    return list(obs)


def session_episodes(session_dir, game="tumble", seed=0, games_dir=None, **env_config):
    """The session's levels as environment episodes (Minari buffers), each from its level's start
    with episode seed ``seed``; also the final info of each (score, outcome, episode_reward)."""
    from . import Env

    env = Env(game=game, games_dir=None if games_dir is None else str(games_dir), **env_config)
    out = []
    for level, actions in session_actions(session_dir, game, games_dir=games_dir):
        first, _ = env.reset(level, seed)
        out.append(_episode(env, first, actions))
    return env, out


def rollouts(policy, episodes, level=1, seed=0, game="tumble", **env_config):
    """``episodes`` episodes of ``policy`` (observation -> action), episode k with seed seed + k."""
    from . import Env

    env = Env(game=game, **env_config)
    out = []
    for k in range(episodes):
        first, _ = env.reset(level, seed + k)
        out.append(_episode(env, first, policy))
    return env, out


def _run_config(run_dir):
    """The run's settings (config.json of psxrl train: every value is text)."""
    path = Path(run_dir) / "config.json"
    try:
        return json.loads(path.read_text())
    except FileNotFoundError:
        raise ValueError(f"{run_dir}: not a psxrl train run folder (no config.json)") from None


def policy_episodes(run_dir, episodes, seed=0, level=None, max_moves=None, exe=None):
    """``episodes`` greedy episodes of the policy that ``psxrl train`` saved in ``run_dir``: played
    by ``psxrl play --rollout`` (episode seeds from ``seed`` as play derives them, each from the
    run's start position) and replayed in an Env of the run's game, observation, reward, gamma and
    picture settings. Returns ``(env, episodes, lines)``: Minari buffers with each episode's final
    info, and play's own records. Raises RuntimeError if a replayed reward differs from play's."""
    from . import Env
    from .executable import find_executable

    config = _run_config(run_dir)
    level = int(config["level"]) if level is None else level
    with tempfile.TemporaryDirectory(prefix="psxrl-rollout-") as tmp:
        rollout = Path(tmp) / "rollout.jsonl"
        command = [exe or find_executable(), "play", "--policy", str(run_dir), "--headless", "--episodes",
                   str(episodes), "--seed", str(seed), "--level", str(level), "--rollout", str(rollout)]
        if max_moves is not None:
            command += ["--max-moves", str(max_moves)]
        done = subprocess.run(command, capture_output=True, text=True)
        if done.returncode != 0:
            raise RuntimeError(f"psxrl play exited with {done.returncode}: {done.stderr.strip()}")
        lines = [json.loads(line) for line in rollout.read_text().splitlines()]
    env_config = {"obs": config["obs"], "reward": config["reward"], "gamma": float(config["gamma"]),
                  "visual_gray": config.get("visual_gray") == "true"}
    if max_moves is not None:
        env_config["max_moves"] = max_moves
    env = Env(game=config["game"], **env_config)
    out = []
    for line in lines:
        first, _ = env.reset(line["level"], line["seed"], start=",".join(map(str, line["start"])))
        buffer, info = _episode(env, first, line["actions"])
        if buffer["rewards"] != line["rewards"]:
            raise RuntimeError(f"episode {line['episode']}: the replay's rewards {buffer['rewards']} differ from "
                               f"psxrl play's {line['rewards']}")
        out.append((buffer, info))
    return env, out, lines


def write_dataset(dataset_id, env, episodes, description="", **metadata):
    """A Minari dataset of ``episodes`` (buffers as ``rollouts`` and ``session_episodes`` return
    them) with ``env``'s observation and action spaces; returns it (minari.load_dataset(dataset_id)
    reads it back from Minari's datasets folder, $MINARI_DATASETS_PATH)."""
    import minari
    from gymnasium import spaces
    from minari.data_collector import EpisodeBuffer

    from .gym_envs import observation_space

    buffers = [EpisodeBuffer(id=i, observations=_parts(b["observations"]), actions=list(b["actions"]),
                             rewards=list(b["rewards"]), terminations=list(b["terminations"]),
                             truncations=list(b["truncations"])) for i, (b, _) in enumerate(episodes)]
    return minari.create_dataset_from_buffers(
        dataset_id=dataset_id, buffer=buffers, observation_space=observation_space(env.observation_spaces),
        action_space=spaces.Discrete(env.action_count), algorithm_name=metadata.pop("algorithm_name", None),
        description=description or f"psxrl {env.game}, observation {env.obs}", author="psxrl", **metadata)


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # psxrl's exit code for a usage error
        self.print_usage(sys.stderr)
        self.exit(1, f"{self.prog}: {message}\n")


def main(argv=None):
    p = _Parser(prog="python -m psxrl.offline", description="Exports play as a Minari dataset "
                                "(docs/offline.md); exit codes: 0 written, 1 usage error, 2 bad input.")
    sub = p.add_subparsers(dest="command", required=True)
    pol = sub.add_parser("export-policy", help="greedy episodes of a psxrl train run's saved policy")
    pol.add_argument("run", help="the run folder (config.json, checkpoint.psxrl)")
    pol.add_argument("--episodes", type=int, default=10, help="episodes to play (default 10)")
    pol.add_argument("--seed", type=int, default=0, help="seed of the episodes (default 0)")
    pol.add_argument("--level", type=int, help="level (default: the run's)")
    pol.add_argument("--max-moves", type=int, help="move cap per episode (default: the game's)")
    ses = sub.add_parser("export-session", help="a session recorded by psxrl record")
    ses.add_argument("session", help="the session folder")
    ses.add_argument("--obs", default="local", help="observation (default local)")
    for s in (pol, ses):
        s.add_argument("--dataset", required=True, help="Minari dataset id, e.g. psxrl/tumble-level1-v0")
    a = p.parse_args(argv)
    try:
        if a.command == "export-policy":
            env, episodes, _ = policy_episodes(a.run, a.episodes, a.seed, a.level, a.max_moves)
            source, algorithm = f"psxrl play --policy {a.run}", "psxrl train --agent " + _run_config(a.run)["agent"]
        else:
            env, episodes = session_episodes(a.session, obs=a.obs)
            source, algorithm = f"the session {a.session}", "recorded play"
        data = write_dataset(a.dataset, env, episodes, description=f"psxrl {env.game}, observation {env.obs}, "
                             f"from {source}", algorithm_name=algorithm)
    except (ValueError, RuntimeError, OSError) as e:
        print(f"python -m psxrl.offline: {e}", file=sys.stderr)
        return 2
    rewards = [sum(b["rewards"]) for b, _ in episodes]
    print(f"{a.dataset}: {data.total_episodes} episodes, {data.total_steps} steps, observation {env.obs}, "
          f"episode rewards {min(rewards):.4g} to {max(rewards):.4g}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
