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

Minari is not a dependency of psxrl: ``write_dataset`` imports it (scripts/setup.sh installs it in
.venv-sb3).
"""
import os
import tomllib
from pathlib import Path

def _games_dir(games_dir):
    from . import _PACKAGED_GAMES

    if games_dir is not None:
        return Path(games_dir)
    if "PSXRL_GAMES" in os.environ:
        return Path(os.environ["PSXRL_GAMES"])
    return _PACKAGED_GAMES


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
