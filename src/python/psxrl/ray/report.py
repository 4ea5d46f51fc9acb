"""A sweep's gathered results: one table row per run from its own metrics.csv (runs.csv and
runs.md in the sweep folder, the Markdown with a mean and spread per configuration too) and one
figure of test-episode learning curves, the mean over seeds and the min-max band per configuration.
runs.md also gives, per configuration, how many runs diverged and the last test scores' distribution,
and for runs with held-out starts (psxrl train --test-start) the success from each start.
"""
import csv
import math
import statistics
from collections import Counter
from pathlib import Path

COLUMNS = ["episodes", "test_episodes", "moves", "training_moves", "best_test_score", "last_test_score",
           "mean_test_score", "test_wins", "first_test_win", "first_test_win_seconds", "seconds", "max_loss",
           "diverged", "heldout_tests", "heldout_wins"]

# A run diverged when a learner loss (metrics.csv `loss`: the mean squared TD error of the replay
# batch last trained on) is not finite or above this. Tumble's rewards are Table 3.3's units times
# 1 - gamma, so every return of levels 1-2 lies within [-1, 1] (level 1: -0.1 to 0.72 at gamma 0.9)
# and a target r + gamma Q' within [-1.1, 1.1] while Q stays in [-1, 1]: such a network's loss is at
# most 2.1 squared, 4.41. A loss above 10 needs Q values far outside every return (docs/results.md).
DIVERGED_LOSS = 10.0


def table_path(sweep):
    return sweep.out / "runs.csv"


def figure_path(sweep):
    return sweep.out / "learning_curves.png"


def read_metrics(folder):
    """The rows of a run's metrics.csv (psxrl train's columns), [] before its first episode."""
    path = Path(folder) / "metrics.csv"
    if not path.is_file():
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def diverged(rows):
    """Whether a run's learner loss ever left the bound (DIVERGED_LOSS) or became NaN or infinite."""
    return any(not math.isfinite(float(r["loss"])) or float(r["loss"]) > DIVERGED_LOSS for r in rows)


def summarise(rows):
    """The table's figures for one run's metrics rows (test scores: greedy test episodes only; the
    held-out tests of --test-start, which share their test's episode number, only in heldout_*)."""
    heldout = [r for r in rows if r["kind"] == "heldout"]
    rows = [r for r in rows if r["kind"] != "heldout"]
    tests = [r for r in rows if r["kind"] == "test"]
    scores = [int(r["score"]) for r in tests]
    wins = [int(r["episode"]) for r in tests if r["outcome"] == "win"]
    return {
        "episodes": len(rows),
        "test_episodes": len(tests),
        "moves": sum(int(r["moves"]) for r in rows),
        "training_moves": int(rows[-1]["total_moves"]) if rows else 0,
        "best_test_score": max(scores) if scores else "",
        "last_test_score": scores[-1] if scores else "",
        "mean_test_score": round(statistics.fmean(scores), 3) if scores else "",
        "test_wins": len(wins),
        "first_test_win": wins[0] if wins else "",
        # Host seconds of the run's episodes up to that test, itself included: the time to a first win.
        "first_test_win_seconds": round(sum(float(r["seconds"]) for r in rows if int(r["episode"]) <= wins[0]), 3)
        if wins else "",
        "seconds": round(sum(float(r["seconds"]) for r in rows), 3),
        "max_loss": max((float(r["loss"]) for r in rows), key=lambda v: math.inf if math.isnan(v) else v)
        if rows else "",
        "diverged": diverged(rows) if rows else "",
        "heldout_tests": len(heldout),
        "heldout_wins": sum(r["outcome"] == "win" for r in heldout),
    }


def gather(sweep):
    """One dict per run: configuration, seed, grid values, status and the summary figures."""
    from .sweep import finished

    table = []
    for r in sweep.runs:
        status = "finished" if finished(r.folder) else "incomplete"
        row = {"config": r.config, "seed": r.seed, **{k: r.grid.get(k, "") for k in sweep.grid_keys}, "status": status}
        row.update(summarise(read_metrics(r.folder)))
        row["folder"] = str(r.folder)
        table.append(row)
    return table


def _markdown(sweep, table):
    lines = [f"# {sweep.title or 'Sweep ' + sweep.path.name}", "", "## Per configuration (mean ± standard deviation over seeds)", "",
             "| configuration | runs | best test score | last test score | test wins | moves |",
             "| --- | --- | --- | --- | --- | --- |"]
    for config in dict.fromkeys(row["config"] for row in table):
        rows = [row for row in table if row["config"] == config]
        cells = []
        for key in ("best_test_score", "last_test_score", "test_wins", "moves"):
            values = [float(row[key]) for row in rows if row[key] != ""]
            spread = statistics.stdev(values) if len(values) > 1 else 0.0
            cells.append(f"{statistics.fmean(values):.1f} ± {spread:.1f}" if values else "-")
        lines.append(f"| {config} | {len(rows)} | " + " | ".join(cells) + " |")
    lines += _divergence(table) + _heldout(sweep)
    keys = ["config", "seed", "status"] + COLUMNS
    lines += ["", "## Runs", "", "| " + " | ".join(keys) + " |", "|" + " --- |" * len(keys)]
    lines += ["| " + " | ".join(str(row[k]) for k in keys) + " |" for row in table]
    return "\n".join(lines) + "\n"


def _divergence(table):
    """Per configuration: the runs that diverged and the distribution of the last test scores."""
    lines = ["", f"## Divergence (a learner loss not finite or above {DIVERGED_LOSS:g}) and last test scores", "",
             "| configuration | runs diverged | largest loss (median, max) | last test score: runs |", "| --- | --- | --- | --- |"]
    for config in dict.fromkeys(row["config"] for row in table):
        rows = [row for row in table if row["config"] == config and row["max_loss"] != ""]
        if not rows:
            continue
        losses = [row["max_loss"] for row in rows]
        finite = sorted(v for v in losses if math.isfinite(v))
        top = max(losses, key=lambda v: math.inf if math.isnan(v) else v)
        median = f"{statistics.median(finite):.3g}" if finite else "-"
        scores = Counter(row["last_test_score"] for row in rows if row["last_test_score"] != "")
        spread = ", ".join(f"{s}: {n}" for s, n in sorted(scores.items(), reverse=True))
        lines.append(f"| {config} | {sum(row['diverged'] for row in rows)} of {len(rows)} | {median}, {top:.3g} | {spread} |")
    return lines


def heldout_success(sweep):
    """{config: {start: (wins, tests, last_wins, runs)}} over the held-out tests (kind heldout) of
    every run: all of them, and each run's last one from that start."""
    outcomes = {}  # config -> start -> one list of won flags per run
    for r in sweep.runs:
        per_start = {}
        for row in read_metrics(r.folder):
            if row["kind"] == "heldout":
                per_start.setdefault(row["start"], []).append(row["outcome"] == "win")
        for start, won in per_start.items():
            outcomes.setdefault(r.config, {}).setdefault(start, []).append(won)
    return {config: {start: (sum(map(sum, runs)), sum(map(len, runs)), sum(run[-1] for run in runs), len(runs))
                     for start, runs in starts.items()} for config, starts in outcomes.items()}


def _heldout(sweep):
    success = heldout_success(sweep)
    if not success:
        return []
    lines = ["", "## Held-out starts (greedy tests from starts never trained from)", "",
             "| configuration | start | wins / held-out tests | last test won (runs) |", "| --- | --- | --- | --- |"]
    for config, starts in success.items():
        for start in sorted(starts, key=lambda s: int(s.rsplit("-", 1)[-1])):
            wins, tests, last_wins, runs = starts[start]
            lines.append(f"| {config} | {start} | {wins} / {tests} | {last_wins} of {runs} |")
    return lines


def _figure(sweep, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(8, 4.5), dpi=100)
    for config in dict.fromkeys(r.config for r in sweep.runs):
        curves = []
        for r in (r for r in sweep.runs if r.config == config):
            tests = [row for row in read_metrics(r.folder) if row["kind"] == "test"]
            curves.append({int(row["episode"]): int(row["score"]) for row in tests})
        episodes = sorted(set().union(*curves))
        if not episodes:
            continue
        # Runs of one configuration test at the same episodes; a shorter run just stops adding.
        scores = [[c[e] for c in curves if e in c] for e in episodes]
        mean = [statistics.fmean(s) for s in scores]
        line, = ax.plot(episodes, mean, label=config)
        ax.fill_between(episodes, [min(s) for s in scores], [max(s) for s in scores], color=line.get_color(),
                        alpha=0.2, linewidth=0)
    ax.set_xlabel("episode")
    ax.set_ylabel("test episode score (mean over seeds, band: min to max)")
    ax.set_title(f"{sweep.path.name}: {len(sweep.seeds)} seeds per configuration")
    ax.grid(alpha=0.3)
    if ax.lines:
        ax.legend(fontsize="small")
    fig.tight_layout()
    fig.savefig(path)
    plt.close(fig)


def write(sweep):
    """Writes runs.csv, runs.md and learning_curves.png into the sweep folder; returns the table."""
    table = gather(sweep)
    keys = ["config", "seed", *sweep.grid_keys, "status", *COLUMNS, "folder"]
    with open(table_path(sweep), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=keys)
        writer.writeheader()
        writer.writerows(table)
    (sweep.out / "runs.md").write_text(_markdown(sweep, table))
    _figure(sweep, figure_path(sweep))
    return table
