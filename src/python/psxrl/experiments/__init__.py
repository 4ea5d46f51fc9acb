"""The seed's studies, one command each: `psxrl experiment NAME` or `python -m psxrl.experiments NAME`
(docs/results.md). A study is a sweep file (docs/scaling.md) in the repository's experiments/ folder,
copied beside this module by the build, with two tables of its own: [study] (its title) and [tiny]
(the tests' configuration: seeds, [train] values for every run, [grid] lists and configs that
replace the study's). Its runs go through psxrl.ray's sweep, on a local Ray instance unless given a cluster,
into a results folder: runs.csv, runs.md, learning_curves.png, every run's folder, the study file
(study.toml) and commands.sh, the exact `psxrl train` command of every run.
"""
import shlex
import shutil
from pathlib import Path

STUDY_DIR = Path(__file__).parent
STUDY_KEYS = {"study", "tiny"}
TINY_KEYS = {"seeds", "train", "grid", "configs"}


def names():
    """The studies beside this module, by name (the file's stem)."""
    return sorted(p.stem for p in STUDY_DIR.glob("*.toml"))


def study_path(name):
    """The study file for NAME (a study's name, or a path to a .toml file of the same form)."""
    if name.endswith(".toml"):
        return Path(name)
    path = STUDY_DIR / f"{name}.toml"
    if not path.is_file():
        from psxrl.ray.sweep_config import SweepConfigError

        raise SweepConfigError(f"no study named {name!r}; the studies are: {', '.join(names())}")
    return path


def _tiny(path, doc):
    """The study's document with its [tiny] table applied: a [train] value there replaces the same
    option wherever the study sets it ([train], [[configs]] or [grid])."""
    from psxrl.ray.sweep_config import SweepConfigError

    tiny = doc.get("tiny")
    if not isinstance(tiny, dict) or set(tiny) - TINY_KEYS:
        raise SweepConfigError(f"{path}: [tiny] must be a table of seeds, train, grid and configs")
    for key in ("train", "grid"):
        if not isinstance(tiny.get(key, {}), dict) or not isinstance(doc.get(key, {}), dict):
            raise SweepConfigError(f"{path}: [tiny] {key} and [{key}] must be tables of psxrl train options")
    for key in ("seeds", "configs"):
        if key in tiny:
            doc[key] = tiny[key]
    train = dict(doc.get("train", {}))
    for key, value in tiny.get("train", {}).items():
        for entry in doc.get("configs", []):
            if isinstance(entry, dict):  # anything else: from_doc says what configs must be
                entry.pop(key, None)
        doc.get("grid", {}).pop(key, None)
        train[key] = value
    doc["train"] = train
    doc["grid"] = {**doc.get("grid", {}), **tiny.get("grid", {})}
    return doc


def load(name, out=None, tiny=False):
    """The study NAME as a psxrl.ray sweep (its runs planned), and the study file's path. The results
    folder is `out`, else runs/experiments/NAME (NAME-tiny with `tiny`)."""
    from psxrl.ray.sweep_config import SweepConfigError, from_doc, read

    path = study_path(name)
    doc = read(path)
    if not isinstance(doc.get("study"), dict) or not isinstance(doc["study"].get("title"), str):
        raise SweepConfigError(f"{path}: expected a [study] table with a title")
    if set(doc["study"]) != {"title"}:
        key = sorted(set(doc["study"]) - {"title"})[0]
        raise SweepConfigError(f"{path}: [study] {key}: [study] holds only the title (the sweep's own keys, such as "
                               "seeds, go above it)")
    if tiny:
        doc = _tiny(path, doc)
    title = doc["study"]["title"] + (" (tiny)" if tiny else "")
    doc = {k: v for k, v in doc.items() if k not in STUDY_KEYS}
    default = Path("runs") / "experiments" / (path.stem + ("-tiny" if tiny else ""))
    sweep = from_doc(doc, path, out if out is not None else default)
    sweep.title = title
    return sweep, path


def write_commands(sweep, path, exe, invocation):
    """commands.sh in the results folder: the command that made it, then every run's `psxrl train`
    (a run that was interrupted also ran with --resume, to the same metrics)."""
    lines = ["#!/bin/sh", f"# {sweep.path.name}: every run of this results folder, one psxrl train each.",
             f"# The whole study, as it was run: {invocation}", "set -e"]
    lines += [shlex.join([exe, "train", *r.train_args()]) for r in sweep.runs]
    commands = sweep.out / "commands.sh"
    commands.write_text("\n".join(lines) + "\n")
    commands.chmod(0o755)
    shutil.copyfile(path, sweep.out / "study.toml")
    return commands
