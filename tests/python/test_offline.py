"""psxrl.offline: a `psxrl record` session and a policy's rollouts as Minari datasets, read back with
minari.load_dataset (ctest python_offline_tests, in .venv-sb3 where scripts/setup.sh installs Minari).

Expected values come from the session's input script and the game's rules, not from the module:
games/tumble/demo/level1.txt presses each of its 30 moves once (its comments: all 8 coins, 2 fruit
and the key, then the exit: 4000 points), and Tumble's Table 3.3 rewards are 0.5 a coin, 0.7 a
fruit, 0.8 the key and 1.0 the win, in units of 1 - gamma: 7.2 x 0.1 = 0.72 for the whole level.
"""
import csv
import json
import os
import re
import subprocess
from pathlib import Path

import numpy as np
import pytest

minari = pytest.importorskip("minari", reason="Minari is installed in .venv-sb3: ctest python_offline_tests")

from psxrl import Env, Session, offline  # noqa: E402

ROOT = Path(__file__).parents[2]
DEMO = ROOT / "games" / "tumble" / "demo" / "level1.txt"
# The demo's pad presses as the seed's actions (games/tumble/game.toml [[actions]]).
PRESSES = {"up": 0, "right": 1, "left": 2, "cross+up": 3}


def demo_actions():
    """The moves the demo presses once level 1 has started (after the Cross that starts it)."""
    presses = [line.split()[1] for line in DEMO.read_text().splitlines() if re.match(r"\d+ ", line)]
    return [PRESSES[p] for p in presses[presses.index("cross") + 1:]]


@pytest.fixture(scope="module")
def session(tmp_path_factory):
    out = tmp_path_factory.mktemp("offline") / "session"
    exe = Path(os.environ["PSXRL_BUILD_DIR"]) / "psxrl"
    subprocess.run([str(exe), "record", "--game", "tumble", "--input", str(DEMO), "--frames", "700", "--out", str(out)],
                   check=True, capture_output=True)
    return out


@pytest.fixture(autouse=True)
def datasets(tmp_path, monkeypatch):
    monkeypatch.setenv("MINARI_DATASETS_PATH", str(tmp_path / "datasets"))


def test_session_becomes_the_moves_pressed(session):
    assert offline.session_actions(session, games_dir=ROOT / "games") == [(1, demo_actions())]


@pytest.mark.parametrize("obs", ["local", "multimodal"])
def test_session_dataset_round_trip(session, obs):
    env, episodes = offline.session_episodes(session, games_dir=ROOT / "games", obs=obs)
    offline.write_dataset(f"psxrl/tumble-demo-{obs}-v0", env, episodes)
    data = minari.load_dataset(f"psxrl/tumble-demo-{obs}-v0")
    assert data.total_episodes == 1 and data.total_steps == len(demo_actions()) == 30
    (episode,) = list(data.iterate_episodes())
    assert episode.actions.tolist() == demo_actions()
    assert episode.rewards.sum() == pytest.approx(0.72)
    assert episode.terminations.tolist() == [False] * 29 + [True] and not episode.truncations.any()
    # The environment's episode: the session's final score, and the rewards it reports.
    _, info = episodes[0]
    assert info["outcome"] == "win" and info["score"] == 4000 == Session(str(session)).values(0x8001000C)[-1]
    assert info["episode_reward"] == pytest.approx(episode.rewards.sum())
    for space in Env(obs=obs).observation_spaces:
        parts = episode.observations if obs == "local" else episode.observations[space["name"]]
        assert parts.shape == (31, *space["shape"]) and parts.dtype == np.dtype(space["dtype"])


def test_policy_rollouts_round_trip():
    # LOOK RIGHT only: the ball stays on the start tile, so nothing is collected until the cap.
    env, episodes = offline.rollouts(lambda obs: 1, episodes=3, max_moves=4, obs="simple")
    offline.write_dataset("psxrl/tumble-look-v0", env, episodes)
    data = minari.load_dataset("psxrl/tumble-look-v0")
    assert data.total_episodes == 3 and data.total_steps == 12
    for episode in data.iterate_episodes():
        assert episode.actions.tolist() == [1] * 4 and episode.rewards.tolist() == [0.0] * 4
        assert episode.truncations.tolist() == [False] * 3 + [True] and not episode.terminations.any()
        assert episode.observations.shape == (5, *Env(obs="simple").observation_spaces[0]["shape"])


def test_typed_play_is_recorded_like_any_session(tmp_path):
    # The demo's 30 moves typed on standard input (names, numbers, lower case, several a line, a
    # comment and a typing error between them): the game sees exactly those moves, so the session
    # holds them, replays bit for bit, and wins level 1 with all 4000 points.
    exe = Path(os.environ["PSXRL_BUILD_DIR"]) / "psxrl"
    names = ["FORWARD", "LOOKRIGHT", "lookleft", "3"]
    moves = demo_actions()
    typed = "# level 1\n" + "\n".join(names[m] for m in moves[:10]) + "\nBACK\n"
    typed += ",".join(names[m] for m in moves[10:]) + "\n"
    out, frames = tmp_path / "typed", tmp_path / "frames"
    done = subprocess.run([str(exe), "record", "--game", "tumble", "--stdin", "--out", str(out), "--frames-dir",
                           str(frames)], input=typed, capture_output=True, text=True, check=True)
    assert "line 12: 'BACK' is not a move; the actions are FORWARD (0)" in done.stdout
    assert "episode over: win after 30 moves, score 4000" in done.stdout
    assert sorted(p.name for p in frames.iterdir()) == [f"move{i:04d}.png" for i in range(31)]
    # The last text view: the ball on the exit, top left (games/tumble/levels/level01.txt), every
    # item taken.
    last_map = done.stdout.split("move 30:")[1].splitlines()[2:8]
    assert [row.strip() for row in last_map] == ["@####", "#####", "#####", "#####", "#####", "##S##"]
    assert offline.session_actions(out, games_dir=ROOT / "games") == [(1, moves)]
    verify = subprocess.run([str(exe), "memsearch", str(out), "--verify"], capture_output=True, text=True)
    assert verify.returncode == 0 and "snapshots identical" in verify.stdout


def test_the_hand_played_example_session_still_wins(tmp_path):
    # examples/data/tumble_level1_typed.txt, played by looking at the pictures: its 28 moves
    # collect all 8 coins, 2 fruit and the key (3000 + 1000 points) and end on the exit.
    exe = Path(os.environ["PSXRL_BUILD_DIR"]) / "psxrl"
    typed = ROOT / "examples" / "data" / "tumble_level1_typed.txt"
    moves = [line for line in typed.read_text().splitlines() if line and not line.startswith("#")]
    out = tmp_path / "session"
    subprocess.run([str(exe), "record", "--game", "tumble", "--stdin", "--interval", "0", "--out", str(out)],
                   input=typed.read_text(), text=True, check=True, capture_output=True)
    names = ["FORWARD", "LOOKRIGHT", "LOOKLEFT", "JUMPFORWARD"]
    assert offline.session_actions(out, games_dir=ROOT / "games") == [(1, [names.index(m) for m in moves])]
    _, [(episode, info)] = offline.session_episodes(out, games_dir=ROOT / "games", obs="local")
    assert len(episode["actions"]) == 28 and info["outcome"] == "win" and info["score"] == 4000


# Five FORWARDs from level 1's start climb column 2 (all floor) to row 0, facing north: simple
# state 4*5*0 + 4*2 + 0 = 8 (tests/python/test_env.py), where the trained run's episodes start.
WALK = "FORWARD,FORWARD,FORWARD,FORWARD,FORWARD"


def train(out, agent, obs):
    exe = Path(os.environ["PSXRL_BUILD_DIR"]) / "psxrl"
    subprocess.run([str(exe), "train", "--agent", agent, "--obs", obs, "--episodes", "4", "--test-every", "2",
                    "--max-moves", "5", "--seed", "2", "--start", WALK, "--quiet", "--out", str(out)],
                   check=True, capture_output=True)
    return out


def play(run, episodes, rollout):
    exe = Path(os.environ["PSXRL_BUILD_DIR"]) / "psxrl"
    done = subprocess.run([str(exe), "play", "--policy", str(run), "--headless", "--episodes", str(episodes),
                           "--max-moves", "5", "--rollout", str(rollout)], check=True, capture_output=True, text=True)
    return done.stdout, [json.loads(line) for line in rollout.read_text().splitlines()]


@pytest.mark.parametrize("agent,obs", [("q", "simple"), ("dqn", "local")])
def test_trained_policy_round_trip(tmp_path, agent, obs):
    run = train(tmp_path / "run", agent, obs)
    # The player's own account of its episodes, the metrics the dataset must reproduce.
    stdout, played = play(run, 2, tmp_path / "played.jsonl")
    assert f"each episode starts after the walk {WALK} (the policy's training start)" in stdout
    ends = re.findall(r"episode \d+: score (\d+), (\w+), (\d+) moves", stdout)
    assert offline.main(["export-policy", str(run), "--episodes", "2", "--max-moves", "5",
                         "--dataset", f"psxrl/trained-{agent}-v0"]) == 0
    data = minari.load_dataset(f"psxrl/trained-{agent}-v0")
    assert data.total_episodes == 2 == len(played) == len(ends)
    # The run's own metrics: its last episode (the 4th, a greedy test, after which the policy did
    # not change) had the seed play gives its 4th episode with the run's seed (episode_seed(2, 0, 3)).
    with open(run / "metrics.csv", newline="") as f:
        last = list(csv.DictReader(f))[-1]
    assert offline.main(["export-policy", str(run), "--episodes", "4", "--seed", "2", "--max-moves", "5",
                         "--dataset", f"psxrl/trained-{agent}-seed2-v0"]) == 0
    fourth = list(minari.load_dataset(f"psxrl/trained-{agent}-seed2-v0").iterate_episodes())[3]
    assert last["kind"] == "test" and len(fourth.actions) == int(last["moves"])
    assert fourth.rewards.sum() == pytest.approx(float(last["reward"]))
    assert fourth.terminations[-1] == (last["outcome"] in ("win", "lose"))
    (space,) = Env(obs=obs).observation_spaces
    for episode, line, (score, outcome, moves) in zip(data.iterate_episodes(), played, ends):
        assert line["start"] == [0] * 5 and int(score) == line["score"] and outcome == line["outcome"]
        assert episode.actions.tolist() == line["actions"] and len(line["actions"]) == int(moves)
        assert episode.rewards.tolist() == line["rewards"]
        assert episode.rewards.sum() == pytest.approx(line["episode_reward"])
        assert episode.terminations[-1] == (outcome in ("win", "lose"))
        assert episode.truncations[-1] == (outcome == "truncated")
        assert episode.observations.shape == (int(moves) + 1, *space["shape"])
        assert episode.observations.dtype == np.dtype(space["dtype"])
    if obs == "simple":
        assert episode.observations[0].tolist() == [8]


def test_export_policy_refuses_a_folder_without_a_run(tmp_path, capsys):
    assert offline.main(["export-policy", str(tmp_path), "--dataset", "psxrl/none-v0"]) == 2
    assert "not a psxrl train run folder (no config.json)" in capsys.readouterr().err


def test_a_session_of_another_program_is_refused(tmp_path):
    (tmp_path / "session.toml").write_text("format = 1\n[source]\nexe = ''\ndisc = 'x.cue'\n")
    with pytest.raises(ValueError, match="session.toml: the session must have booted an executable"):
        offline.session_actions(tmp_path, games_dir=ROOT / "games")
