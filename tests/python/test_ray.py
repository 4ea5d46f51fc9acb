"""psxrl.ray on a Ray cluster of two nodes on this machine, bound to 127.0.0.1 (ctest python_ray_tests
runs these in .venv-ray, which scripts/setup.sh makes; without Ray, python_tests skips this file).

Expected values come from the runs' own files and from arithmetic on the options: a sweep's table
must restate each run's metrics.csv, a run killed and resumed must write the same metrics as an
uninterrupted one, and environments behind Ray actors must step exactly as local ones.
"""
import csv
import math
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

# Ray replaces 127.0.0.1 in a cluster address with the host's network address unless told that this
# is a one-host setup; it reads this when it is imported. Its usage reporting would reach out.
os.environ["RAY_ENABLE_WINDOWS_OR_OSX_CLUSTER"] = "0"
os.environ["RAY_USAGE_STATS_ENABLED"] = "0"
ray = pytest.importorskip("ray", reason="Ray is installed in .venv-ray: ctest python_ray_tests runs this file")

import psxrl  # noqa: E402
from psxrl.ray import RayAsyncVecEnv, RayVecEnv, load_sweep, run_sweep  # noqa: E402
from psxrl.ray.rollouts import info_array  # noqa: E402

LOOPBACK = "127.0.0.1"
# Two configurations x two seeds; every 3rd episode is a greedy test (--test-every 3).
SWEEP = """seeds = [0, 1]
[train]
agent = "q"
episodes = {episodes}
test-every = 3
[grid]
max-moves = [8, 16]
"""
EPISODES = 36
VARYING = "seconds"  # host time: the one metrics column that differs between identical runs
# Crumbling tiles, whose breaking time is Tumble's only randomness (games/tumble/game.lua): on this
# level an episode's seed shows in its trajectory.
CRUMBLE_LEVEL = 5


def assert_listening_on_loopback_only():
    """Every socket that this process and the cluster's processes (its descendants) listen on is
    bound to 127.0.0.1 (shown as ::ffff:127.0.0.1 on a dual-stack socket)."""
    import psutil

    ours = {os.getpid()} | {p.pid for p in psutil.Process().children(recursive=True)}
    listening = [c for c in psutil.net_connections(kind="inet") if c.status == psutil.CONN_LISTEN and c.pid in ours]
    assert listening
    assert all(c.laddr.ip in (LOOPBACK, "::ffff:" + LOOPBACK) for c in listening), listening


@pytest.fixture(scope="module")
def cluster():
    """A head and a second node (2 logical CPUs each), shut down after the tests, also on failure."""
    from ray.cluster_utils import Cluster

    c = Cluster(shutdown_at_exit=True)
    try:
        c.add_node(num_cpus=2, node_ip_address=LOOPBACK, include_dashboard=False)
        c.add_node(num_cpus=2, node_ip_address=LOOPBACK)
        ray.init(address=c.address, log_to_driver=False)
        assert len([n for n in ray.nodes() if n["Alive"]]) == 2
        assert all(n["NodeManagerAddress"] == LOOPBACK for n in ray.nodes())
        assert_listening_on_loopback_only()
        yield c
    finally:
        ray.shutdown()
        c.shutdown()


def write_sweep(folder, episodes=EPISODES):
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "sweep.toml"
    path.write_text(SWEEP.format(episodes=episodes))
    return path


def metrics(folder):
    with open(Path(folder) / "metrics.csv", newline="") as f:
        return list(csv.DictReader(f))


@pytest.fixture(scope="module")
def reference(cluster, tmp_path_factory):
    """A sweep run without interruption; its runs are the reference for the killed one."""
    folder = tmp_path_factory.mktemp("reference")
    sweep = load_sweep(write_sweep(folder), folder / "out")
    assert run_sweep(sweep, log=lambda line: None) == []
    return sweep


def test_sweep_table_restates_each_runs_metrics(reference):
    with open(reference.out / "runs.csv", newline="") as f:
        table = list(csv.DictReader(f))
    assert [(row["max-moves"], row["seed"]) for row in table] == [("8", "0"), ("8", "1"), ("16", "0"), ("16", "1")]
    for row, run in zip(table, reference.runs):
        assert Path(row["folder"]) == run.folder and row["status"] == "finished"
        config = (run.folder / "config.json").read_text()
        assert f'"max_moves": "{row["max-moves"]}"' in config and f'"seed": "{row["seed"]}"' in config
        rows = metrics(run.folder)
        tests = [r for r in rows if r["kind"] == "test"]
        assert len(rows) == EPISODES and int(row["episodes"]) == EPISODES
        assert [int(r["episode"]) for r in tests] == list(range(3, EPISODES + 1, 3))
        assert int(row["test_episodes"]) == EPISODES // 3
        assert all(int(r["moves"]) <= int(row["max-moves"]) for r in rows)
        assert int(row["moves"]) == sum(int(r["moves"]) for r in rows)
        assert int(row["training_moves"]) == sum(int(r["moves"]) for r in rows if r["kind"] == "train")
        scores = [int(r["score"]) for r in tests]
        assert int(row["best_test_score"]) == max(scores) and int(row["last_test_score"]) == scores[-1]
        assert math.isclose(float(row["mean_test_score"]), sum(scores) / len(scores), abs_tol=5e-4)
        assert int(row["test_wins"]) == sum(r["outcome"] == "win" for r in tests)
        wins = [int(r["episode"]) for r in tests if r["outcome"] == "win"]
        expected = sum(float(r["seconds"]) for r in rows if int(r["episode"]) <= wins[0]) if wins else None
        assert (row["first_test_win_seconds"] == "") if expected is None else \
            math.isclose(float(row["first_test_win_seconds"]), expected, abs_tol=5e-4)
    markdown = (reference.out / "runs.md").read_text()
    assert "| max-moves=8 | 2 |" in markdown and "| max-moves=16 | 2 |" in markdown
    assert (reference.out / "learning_curves.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("text, message", [
    ("seeds = [0, -1]", "seeds must be a list of distinct non-negative integers"),
    ("[train]\nout = 'x'", "[train] out: the sweep sets --out itself"),
    ("[train]\nepisodes = [1, 2]", "[train] episodes: expected one value (lists of values go in [grid])"),
    ("[grid]\ngamma = 0.9", "[grid] gamma: expected a non-empty list of values"),
    ("[train]\ngamma = 0.9\n[grid]\ngamma = [0.5]", "gamma is in both [train] and [grid]"),
    ("sedes = [0]", "unknown key 'sedes'"),
    ("configs = 3", "configs must be a non-empty array of tables ([[configs]])"),
    ("[[configs]]\nseed = 1", "[configs 1] seed: the sweep sets --seed itself"),
    ("[[configs]]\nobs = 'local'\n[[configs]]\nepisodes = [1, 2]", "[[configs]] 2 episodes: expected one value"),
    ("[train]\nagent = 'q'\n[[configs]]\nagent = 'dqn'", "agent is in both [[configs]] and [train] or [grid]"),
    ("seeds = [0", "sweep.toml: "),
])
def test_sweep_file_errors_name_the_file_and_the_key(tmp_path, text, message):
    path = tmp_path / "sweep.toml"
    path.write_text(text)
    with pytest.raises(ValueError) as e:
        load_sweep(path)
    assert str(e.value).startswith(f"{path}: ") and message in str(e.value)


@pytest.mark.parametrize("front", ["python", "psxrl"])
def test_sweep_command_reports_a_bad_file_and_exits_2(tmp_path, front):
    """`python -m psxrl.ray sweep` and `psxrl sweep`, which runs it in $PSXRL_PYTHON."""
    (tmp_path / "sweep.toml").write_text("seeds = 3\n")
    command = [sys.executable, "-m", "psxrl.ray"] if front == "python" else \
        [str(Path(os.environ["PSXRL_BUILD_DIR"]) / "psxrl")]
    done = subprocess.run(command + ["sweep", str(tmp_path / "sweep.toml")], capture_output=True, text=True,
                          timeout=120, env=dict(os.environ, PSXRL_PYTHON=sys.executable))
    assert done.returncode == 2
    assert done.stderr.strip() == f"psxrl sweep: {tmp_path / 'sweep.toml'}: seeds must be a list of distinct " \
                                  "non-negative integers, got 3"


def test_a_run_that_cannot_resume_starts_over(tmp_path):
    """An interrupted --envs 2 run: psxrl train refuses --resume for it, so the sweep's task clears
    the folder and trains it again, ending with the metrics of one uninterrupted run."""
    from psxrl.ray.sweep import find_executable, train

    exe = find_executable()
    options = ["--agent", "q", "--episodes", "8", "--max-moves", "8", "--envs", "2", "--seed", "4", "--quiet"]
    subprocess.run([exe, "train", *options, "--out", str(tmp_path / "whole")], check=True, capture_output=True)
    subprocess.run([exe, "train", *options[:3], "3", *options[4:], "--out", str(tmp_path / "cut")], check=True,
                   capture_output=True)  # a checkpoint after 3 episodes stands for an interrupted run
    done = train(exe, tmp_path / "cut", options + ["--out", str(tmp_path / "cut")], resumable=False)
    assert not done["resumed"] and (tmp_path / "cut" / "done.json").is_file()
    attempts = [line for line in (tmp_path / "cut" / "train.log").read_text().splitlines() if line.startswith("$ ")]
    assert len(attempts) == 1 and "--resume" not in attempts[0]
    assert without_host_time(metrics(tmp_path / "cut")) == without_host_time(metrics(tmp_path / "whole"))


def trainer_processes(folder):
    """(parent pid, run folder) of each `psxrl train` process writing under `folder`."""
    found = []
    for entry in Path("/proc").iterdir():
        try:
            command = (entry / "cmdline").read_bytes().split(b"\0")
            parent = int((entry / "stat").read_text().rsplit(")", 1)[1].split()[1])
        except (OSError, ValueError, IndexError):  # not a process, or one that just ended
            continue
        if b"train" in command and b"--out" in command:
            run = Path(command[command.index(b"--out") + 1].decode())
            if run.is_relative_to(folder):
                found.append((parent, run))
    return found


def kill_a_worker_mid_run(folder, proc):
    """Kills (SIGKILL) the Ray worker process running a sweep task once its run has written some
    episodes; returns that run's folder."""
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and proc.poll() is None:
        for worker, run in trainer_processes(folder):
            if (run / "metrics.csv").is_file() and 3 <= len(metrics(run)) < EPISODES - 3:
                os.kill(worker, signal.SIGKILL)
                return run
        time.sleep(0.02)
    pytest.fail("no sweep run was caught mid-way to kill its worker")


def without_host_time(rows):
    return [{k: v for k, v in r.items() if k != VARYING} for r in rows]


def test_sweep_survives_a_killed_worker(cluster, reference, tmp_path):
    out = tmp_path / "out"
    proc = subprocess.Popen([sys.executable, "-m", "psxrl.ray", "sweep", str(write_sweep(tmp_path)), "--out", str(out),
                             "--address", cluster.address], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        killed = kill_a_worker_mid_run(out, proc)
        output, _ = proc.communicate(timeout=300)
    finally:
        if proc.poll() is None:
            proc.kill()
    assert proc.returncode == 0, output
    assert "4 of 4 runs finished" in output and "(resumed)" in output
    attempts = [line for line in (killed / "train.log").read_text().splitlines() if line.startswith("$ ")]
    assert len(attempts) == 2 and "--resume" not in attempts[0] and "--resume" in attempts[1]
    for mine, theirs in zip(load_sweep(tmp_path / "sweep.toml", out).runs, reference.runs):
        assert without_host_time(metrics(mine.folder)) == without_host_time(metrics(theirs.folder)), mine.folder


def local_vec_envs(seeds, envs, config):
    vecs = [psxrl.VecEnv(envs, **config) for _ in seeds]
    return vecs, np.concatenate([v.reset(CRUMBLE_LEVEL, s) for v, s in zip(vecs, seeds)])


def test_rollouts_through_actors_equal_local_stepping(cluster):
    config = {"obs": "local", "max_moves": 8}
    seeds = [5, 9]
    remote = RayVecEnv(2, 2, actor_options={"scheduling_strategy": "SPREAD"}, **config)
    try:
        local, local_obs = local_vec_envs(seeds, 2, config)
        assert remote.reset(CRUMBLE_LEVEL, seeds).tobytes() == local_obs.tobytes()
        actions = np.random.default_rng(7).integers(0, remote.action_count, size=(30, 4), dtype=np.int32)
        ended = 0
        for a in actions:
            obs, rewards, terminated, truncated, infos, final = remote.step(a)
            parts = [v.step(a[2 * i:2 * i + 2]) for i, v in enumerate(local)]
            assert obs.tobytes() == np.concatenate([p[0] for p in parts]).tobytes()
            assert rewards.tobytes() == np.concatenate([p[1] for p in parts]).tobytes()
            assert (terminated == np.concatenate([p[2] for p in parts])).all()
            assert (truncated == np.concatenate([p[3] for p in parts])).all()
            assert infos.tobytes() == info_array([i for p in parts for i in p[4]]).tobytes()
            done = terminated | truncated
            if done.any():
                finals = np.concatenate([v.final_observation() for v in local])
                assert final[done].tobytes() == finals[done].tobytes()
                ended += int(done.sum())
        assert ended >= 4  # with at most 8 moves an episode, every environment ended at least once
    finally:
        remote.close()


def trajectories(recv, send, envs, steps, action_count):
    """Per environment id: its first `steps` (obs, reward, terminated, truncated), stepped with an
    action that depends only on the id and the step, so the order of the batches does not matter."""
    seen = {}
    while len(seen) < envs or min(len(t) for t in seen.values()) < steps:
        obs, rewards, terminated, truncated, _, ids = recv()
        for row, i in enumerate(ids):
            seen.setdefault(int(i), []).append((obs[row].tobytes(), rewards[row], terminated[row], truncated[row]))
        send(np.array([(len(seen[int(i)]) * 3 + int(i)) % action_count for i in ids], np.int32), ids)
    return {i: t[:steps] for i, t in seen.items()}


def test_async_rollouts_through_actors_equal_local_stepping(cluster):
    config = {"obs": "local", "max_moves": 8}
    seeds = [3, 4]
    remote = RayAsyncVecEnv(2, 2, batch_size=1, actor_options={"scheduling_strategy": "SPREAD"}, **config)
    try:
        remote.reset(CRUMBLE_LEVEL, seeds)
        got = trajectories(remote.recv, remote.send, 4, 20, remote.action_count)
    finally:
        remote.close()
    expected = {}
    for w, seed in enumerate(seeds):  # worker w's environments have ids 2w and 2w+1
        local = psxrl.AsyncVecEnv(2, 1, **config)
        local.reset(CRUMBLE_LEVEL, seed)

        def recv(local=local, w=w):
            *batch, ids = local.recv()
            return (*batch, ids + 2 * w)

        def send(actions, ids, local=local, w=w):
            local.send(actions, ids - 2 * w)

        expected.update(trajectories(recv, send, 2, 20, remote.action_count))
    assert got == expected


def test_rllib_ppo_trains_on_tumble_with_two_env_runners(cluster):
    from psxrl.ray.rllib import ppo_config

    # Two CPUs per env runner fill a node of this cluster, so the two runners land on both nodes.
    config = ppo_config(env_runners=2, cpus_per_env_runner=2, env_config={"max_moves": 20},
                        train_batch_size_per_learner=200, minibatch_size=50, num_epochs=1)
    algo = config.build_algo()
    try:
        nodes = algo.env_runner_group.foreach_env_runner(lambda runner: ray.get_runtime_context().get_node_id(),
                                                         local_env_runner=False)
        results = [algo.train() for _ in range(2)]
    finally:
        algo.stop()
    assert len(set(nodes)) == 2
    assert sum(r["env_runners"]["num_episodes"] for r in results) > 0
    assert math.isfinite(results[-1]["env_runners"]["episode_return_mean"])
