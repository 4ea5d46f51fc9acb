"""psxrl.experiments: every study's command in its tiny configuration (2 seeds, 2 episodes of at
most 5 moves, the second a greedy test) on one local Ray instance (ctest python_experiment_tests,
in .venv-ray; without Ray, python_tests skips this file).

The expected rows are written out here from the study files' text, not taken from the module: each
study must give exactly these configurations x seeds, each run's own config.json must hold the
options that configuration is about, and the table must restate each run's metrics.csv.
"""
import csv
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

os.environ["RAY_USAGE_STATS_ENABLED"] = "0"
ray = pytest.importorskip("ray", reason="Ray is installed in .venv-ray: ctest python_experiment_tests runs this file")

from psxrl.experiments import load, names  # noqa: E402
from psxrl.experiments.__main__ import main  # noqa: E402
from psxrl.ray.report import read_metrics  # noqa: E402

DQN = {"agent": "dqn", "epsilon_moves": "2000"}
# Per study: configuration name -> what its runs' config.json must hold (psxrl train's keys).
EXPECTED = {
    "agents": {
        "agent=random,obs=simple,level=1": {"agent": "random", "obs": "simple", "level": "1"},
        "agent=q,obs=simple,level=1": {"agent": "q", "obs": "simple", "level": "1"},
        "agent=dqn,obs=local,epsilon-moves=2000,level=1": {**DQN, "obs": "local", "level": "1"},
        "agent=dqn,obs=visual,epsilon-moves=2000,level=1": {**DQN, "obs": "visual", "level": "1"},
        "agent=dqn,obs=multimodal,epsilon-moves=2000,level=1": {**DQN, "obs": "multimodal", "level": "1"},
    },
    "discount": {
        "gamma=0.8": {**DQN, "obs": "local", "gamma": "0.80000000000000004"},
        "gamma=0.9": {**DQN, "obs": "local", "gamma": "0.90000000000000002"},
    },
    "generalisation": {
        "base": {**DQN, "obs": "local", "level": "1", "start": "level",
                 "test_starts": "FORWARD;FORWARD,FORWARD;FORWARD,FORWARD,FORWARD;FORWARD,FORWARD,FORWARD,FORWARD;"
                                "FORWARD,FORWARD,FORWARD,FORWARD,FORWARD;FORWARD,FORWARD,FORWARD,FORWARD,FORWARD,LOOKRIGHT;"
                                "LOOKLEFT,JUMPFORWARD;LOOKRIGHT,JUMPFORWARD;LOOKLEFT,JUMPFORWARD,LOOKRIGHT;"
                                "LOOKRIGHT,JUMPFORWARD,LOOKLEFT;LOOKLEFT,JUMPFORWARD,LOOKRIGHT,FORWARD,FORWARD;"
                                "LOOKRIGHT,JUMPFORWARD,LOOKLEFT,FORWARD,FORWARD"},
    },
    "exploration": {
        "exploration=epsilon": {**DQN, "obs": "local", "level": "7", "exploration": "epsilon"},
        "exploration=q-weighted": {**DQN, "obs": "local", "level": "7", "exploration": "q-weighted"},
    },
    "output-layer": {
        "linear-output=false": {**DQN, "obs": "local", "linear_output": "false"},
        "linear-output=true": {**DQN, "obs": "local", "linear_output": "true"},
    },
    "stability": {
        "level=1,obs=visual": {**DQN, "obs": "visual", "target_network": "false", "double_dqn": "false"},
        "level=1,obs=visual,target-network=true": {**DQN, "obs": "visual", "target_network": "true",
                                                   "double_dqn": "false"},
        # --double-dqn bootstraps from a target network (dqn_agent.cpp): config.json says so.
        "level=1,obs=visual,double-dqn=true": {**DQN, "obs": "visual", "target_network": "true", "double_dqn": "true"},
    },
}
SEEDS = ["0", "1"]
TINY = {"test_every": "2", "max_moves": "5"}  # config.json; the 2 episodes: metrics.csv


@pytest.fixture(scope="module", autouse=True)
def local_ray():
    ray.init(address="local", num_cpus=2, include_dashboard=False, log_to_driver=False)
    yield
    ray.shutdown()


def test_every_study_has_a_test():
    assert names() == sorted(EXPECTED)


# The full studies as their files state them: configurations, seeds, episodes.
FULL = {"agents": (10, [0, 1, 2], "1000"), "discount": (2, [0, 1, 2, 3, 4], "300"),
        "exploration": (2, [0, 1, 2, 3, 4], "300"), "generalisation": (1, [0, 1, 2], "200"), "output-layer": (2, list(range(33)), "100"),
        "stability": (6, [1, 2, 3], "300")}


@pytest.mark.parametrize("study", sorted(FULL))
def test_full_study_plans_every_configuration_and_seed(study, tmp_path):
    configs, seeds, episodes = FULL[study]
    sweep, _ = load(study, tmp_path)
    assert sweep.seeds == seeds and len(sweep.runs) == configs * len(seeds)
    assert len({r.config for r in sweep.runs}) == configs
    assert all(r.options["episodes"] == int(episodes) and "test-every" not in r.options for r in sweep.runs)


@pytest.mark.parametrize("text, tiny, message", [
    ('[study]\ntitle = "t"\nseeds = [0, 1]\n', False, r"\[study\] seeds: \[study\] holds only the title"),
    ("seeds = [0]\n", False, r"expected a \[study\] table with a title"),
    ('[study]\ntitle = "t"\n', True, r"\[tiny\] must be a table of seeds, train, grid and configs"),
    ('[study]\ntitle = "t"\n[tiny]\ntrain = 2\n', True, r"\[tiny\] train and \[train\] must be tables"),
    ('configs = [1]\n[study]\ntitle = "t"\n[tiny]\ntrain = { episodes = 2 }\n', True,
     r"configs must be a non-empty array of tables"),
])
def test_bad_study_files_name_the_file_and_the_key(tmp_path, text, tiny, message):
    path = tmp_path / "s.toml"
    path.write_text(text)
    with pytest.raises(ValueError, match=r"s.toml: " + message):
        load(str(path), tmp_path, tiny)


@pytest.mark.parametrize("study", sorted(EXPECTED))
def test_tiny_study_writes_its_table_figure_runs_and_commands(study, tmp_path):
    out = tmp_path / study
    assert main([study, "--tiny", "--out", str(out)]) == 0
    with open(out / "runs.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert sorted((r["config"], r["seed"]) for r in rows) == sorted((c, s) for c in EXPECTED[study] for s in SEEDS)
    for row in rows:
        folder = Path(row["folder"])
        assert folder.parent.parent == out and folder.name == f"s{row['seed']}"
        config = json.loads((folder / "config.json").read_text())
        assert {k: config[k] for k in EXPECTED[study][row["config"]]} == EXPECTED[study][row["config"]]
        assert {k: config[k] for k in TINY} == TINY and config["seed"] == row["seed"]
        with open(folder / "metrics.csv", newline="") as f:
            metrics = list(csv.DictReader(f))
        heldout = len(EXPECTED[study][row["config"]].get("test_starts", "").split(";")) if study == "generalisation" else 0
        # 2 episodes, every 2nd a test, then one held-out test per --test-start
        assert [m["kind"] for m in metrics] == ["train", "test"] + ["heldout"] * heldout
        assert [m["start"] for m in metrics[2:]] == [f"heldout-{k}" for k in range(1, heldout + 1)]
        assert row["heldout_tests"] == str(heldout)
        assert row["heldout_wins"] == str(sum(m["outcome"] == "win" for m in metrics[2:]))
        losses = [float(m["loss"]) for m in metrics]
        assert row["diverged"] == str(any(v > 10 or v != v for v in losses)) and float(row["max_loss"]) == max(losses)
        assert row["status"] == "finished" and row["episodes"] == "2" and row["test_episodes"] == "1"
        assert row["last_test_score"] == metrics[1]["score"]
    table = (out / "runs.md").read_text()
    assert table.startswith("# ") and table.splitlines()[0].endswith(" (tiny)")  # the study's title
    for config in EXPECTED[study]:
        assert f"| {config} | 2 |" in table  # its per-configuration row: 2 runs
        for seed in SEEDS:
            assert f"| {config} | {seed} | finished | 2 | 1 |" in table
        assert f"| {config} | 0 of 2 |" in table  # no run diverges in 2 short episodes
    if study == "generalisation":  # one held-out test per start and run: its win is also the last test's
        for k in range(1, 13):
            won = [m["outcome"] == "win" for r in rows for m in read_metrics(r["folder"]) if m["start"] == f"heldout-{k}"]
            assert len(won) == 2 and f"| base | heldout-{k} | {sum(won)} / 2 | {sum(won)} of 2 |" in table
    assert (out / "learning_curves.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    commands = (out / "commands.sh").read_text().splitlines()
    trains = [c for c in commands if not c.startswith("#") and " train " in c]
    assert len(trains) == len(rows)
    for row in rows:
        assert sum(f"--seed {row['seed']} --out {row['folder']} --quiet" in c for c in trains) == 1
    assert "--tiny" in commands[2] and (out / "study.toml").read_text() == \
        (Path(__file__).parents[2] / "experiments" / f"{study}.toml").read_text()


def test_unknown_study_names_the_studies():
    env = {**os.environ, "PSXRL_PYTHON": sys.executable}
    exe = Path(os.environ["PSXRL_BUILD_DIR"]) / "psxrl"
    p = subprocess.run([str(exe), "experiment", "nosuch"], env=env, capture_output=True, text=True)
    assert p.returncode == 2
    assert "no study named 'nosuch'" in p.stderr and "discount" in p.stderr and "stability" in p.stderr
    p = subprocess.run([str(exe), "experiment"], env=env, capture_output=True, text=True)
    assert p.returncode == 1 and "usage: psxrl experiment" in p.stderr


def test_two_studies_side_by_side(tmp_path):
    # Without --address each study starts a Ray instance of its own (its own session folder,
    # ports and object store), never one found running, so two at once both finish; --cpus 1
    # gives each its share of the machine.
    env = {**os.environ, "PSXRL_PYTHON": sys.executable}
    exe = Path(os.environ["PSXRL_BUILD_DIR"]) / "psxrl"
    runs = [subprocess.Popen([str(exe), "experiment", "discount", "--tiny", "--cpus", "1", "--out", str(tmp_path / n)],
                             env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True) for n in "ab"]
    outputs = [r.communicate(timeout=400)[0] for r in runs]
    for run, output, name in zip(runs, outputs, "ab"):
        assert run.returncode == 0 and "4 of 4 runs finished" in output, output
        assert "queued 4 runs on Ray's 1 CPU (" in output  # --cpus 1: its own instance, one run at a time
        assert "| gamma=0.9 | 1 | finished | 2 | 1 |" in (tmp_path / name / "runs.md").read_text()


def test_cpus_is_for_a_local_instance():
    env = {**os.environ, "PSXRL_PYTHON": sys.executable}
    exe = Path(os.environ["PSXRL_BUILD_DIR"]) / "psxrl"
    for command in (["experiment", "discount"], ["sweep", "x.toml"]):
        for bad in (["--cpus", "0"], ["--cpus", "1", "--address", "auto"]):
            p = subprocess.run([str(exe), *command, *bad], env=env, capture_output=True, text=True)
            assert p.returncode == 1 and "--cpus sizes a local Ray instance" in p.stderr
