"""The sweep file (TOML): which `psxrl train` options every run gets, which are crossed in a grid,
and the seeds; expanded into one planned run (options, seed, run folder) per grid point and seed.

    out = "runs/sweep-gamma"          # the sweep folder (default: runs/ + the file's name)
    seeds = [0, 1]
    [train]                           # every run: `psxrl train` long options without "--"
    agent = "q"
    episodes = 200
    [grid]                            # crossed: one configuration per combination
    gamma = [0.9, 0.99]
    exploration = ["epsilon", "q-weighted"]

Options that only make sense together (an agent and its observation) are listed as configurations
instead, each crossed with the grid:

    [[configs]]
    agent = "q"
    obs = "simple"
    [[configs]]
    agent = "dqn"
    obs = "local"

A value true is a flag (`--double-dqn`), false leaves it out; everything else is passed as text. A
repeatable option (--test-start) may be a list of strings in [train]: one --test-start per string.
"""
import itertools
import re
from dataclasses import dataclass, field
from pathlib import Path

try:
    import tomllib
except ImportError:  # Python before 3.11
    import tomli as tomllib

# Options the sweep sets itself for each run.
RESERVED = {"out", "seed", "resume", "quiet"}
TOP_LEVEL = {"out", "seeds", "train", "grid", "configs"}
# Options psxrl train takes several times; [train] may give them as a list of strings.
REPEATABLE = {"test-start"}


class SweepConfigError(ValueError):
    """A sweep file that cannot be used: the message names the file and what was expected."""


@dataclass
class Run:
    """One `psxrl train` run of the sweep: a configuration (a grid point) and a seed."""
    config: str                 # the configuration's name: "agent=q,gamma=0.9" ("base" without a grid)
    grid: dict                  # the [[configs]] entry's and the grid's values, in the file's order
    seed: int
    folder: Path
    options: dict = field(default_factory=dict)  # every option but --out, --seed, --resume

    def train_args(self):
        """The `psxrl train` arguments of this run, less --resume."""
        args = []
        for key, value in self.options.items():
            if isinstance(value, list):  # a repeatable option (REPEATABLE), once per value
                for v in value:
                    args += ["--" + key, _text(v)]
            elif value is True:
                args.append("--" + key)
            elif value is not False:
                args += ["--" + key, _text(value)]
        return args + ["--seed", str(self.seed), "--out", str(self.folder), "--quiet"]

    def resumable(self):
        """`psxrl train --resume` needs one environment, no saved start states and no held-out starts."""
        return int(self.options.get("envs", 1)) == 1 and float(self.options.get("start-states", 0)) == 0 \
            and not self.options.get("test-start")


@dataclass
class Sweep:
    path: Path
    out: Path
    seeds: list
    runs: list
    grid_keys: list
    title: str = ""             # the report's heading (psxrl.experiments gives its study's title)


def _text(value):
    return str(value).lower() if isinstance(value, bool) else str(value)


def _folder_name(grid):
    if not grid:
        return "base"
    return "_".join(f"{k}-{re.sub(r'[^A-Za-z0-9.+-]', '-', _text(v))}" for k, v in grid.items())


def _check_options(path, table, name):
    if not isinstance(table, dict):
        raise SweepConfigError(f"{path}: [{name}] must be a table of psxrl train options")
    for key, value in table.items():
        if key in RESERVED:
            raise SweepConfigError(f"{path}: [{name}] {key}: the sweep sets --{key} itself for each run")
        if not re.fullmatch(r"[a-z][a-z0-9-]*", key):
            raise SweepConfigError(f"{path}: [{name}] {key}: expected a psxrl train long option without '--' "
                                   "(such as episodes or max-moves)")
        repeated = key in REPEATABLE and isinstance(value, list) and all(isinstance(v, str) for v in value)
        if isinstance(value, (dict, list)) and name == "train" and not repeated:
            raise SweepConfigError(f"{path}: [train] {key}: expected one value (lists of values go in [grid])")


def read(path):
    """The TOML document of a sweep file (a dict); a missing or malformed file raises SweepConfigError."""
    try:
        with open(path, "rb") as f:
            return tomllib.load(f)
    except OSError as e:
        raise SweepConfigError(f"{path}: cannot read the sweep file ({e.strerror})") from e
    except tomllib.TOMLDecodeError as e:
        raise SweepConfigError(f"{path}: {e}") from e


def _configs(path, doc, train, grid):
    """The [[configs]] entries (one empty entry without them), checked like [grid] options."""
    configs = doc.get("configs", [{}])
    if not (isinstance(configs, list) and configs and all(isinstance(c, dict) for c in configs)):
        raise SweepConfigError(f"{path}: configs must be a non-empty array of tables ([[configs]])")
    for i, entry in enumerate(configs):
        _check_options(path, entry, f"configs {i + 1}")
        for key, value in entry.items():
            if isinstance(value, (dict, list)):
                raise SweepConfigError(f"{path}: [[configs]] {i + 1} {key}: expected one value")
            if key in train or key in grid:
                raise SweepConfigError(f"{path}: {key} is in both [[configs]] and [train] or [grid]")
    return configs


def load(path, out=None):
    """Reads and checks a sweep file; `out` overrides the file's sweep folder."""
    return from_doc(read(path), path, out)


def from_doc(doc, path, out=None):
    """Checks a sweep file's document (as read()) and plans its runs; `path` names it in errors."""
    path = Path(path)
    unknown = sorted(set(doc) - TOP_LEVEL)
    if unknown:
        raise SweepConfigError(f"{path}: unknown key {unknown[0]!r}; expected out, seeds, [train], [grid] and [[configs]]")
    seeds = doc.get("seeds", [0])
    if not (isinstance(seeds, list) and seeds and all(isinstance(s, int) and s >= 0 for s in seeds)) \
            or len(set(seeds)) != len(seeds):
        raise SweepConfigError(f"{path}: seeds must be a list of distinct non-negative integers, got {seeds!r}")
    train, grid = doc.get("train", {}), doc.get("grid", {})
    _check_options(path, train, "train")
    _check_options(path, grid, "grid")
    for key, values in grid.items():
        if not isinstance(values, list) or not values:
            raise SweepConfigError(f"{path}: [grid] {key}: expected a non-empty list of values")
        if key in train:
            raise SweepConfigError(f"{path}: {key} is in both [train] and [grid]")
    configs = _configs(path, doc, train, grid)
    # Absolute: the runs' trainers start in whatever folder Ray's workers have.
    folder = Path(out if out is not None else doc.get("out", Path("runs") / path.stem)).absolute()
    runs = []
    for entry, point in itertools.product(configs, itertools.product(*grid.values())):
        values = {**entry, **dict(zip(grid, point))}
        name = ",".join(f"{k}={_text(v)}" for k, v in values.items()) or "base"
        for seed in seeds:
            runs.append(Run(config=name, grid=values, seed=seed, folder=folder / _folder_name(values) / f"s{seed}",
                            options={**train, **values}))
    keys = list(dict.fromkeys(k for entry in configs for k in entry)) + list(grid)
    return Sweep(path=path, out=folder, seeds=seeds, runs=runs, grid_keys=keys)
