"""`python -m psxrl.experiments NAME [--out DIR] [--address HOST:PORT] [--tiny]` (docs/results.md):
runs one of the seed's studies through psxrl.ray's sweep. Exit codes as psxrl sweep's: 0 every run
finished, 1 usage error or a run failed, 2 unknown study, bad study file, missing psxrl executable
or Ray, or an unreachable cluster."""
import argparse
import os
import shlex
import sys

from . import load, names, write_commands


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # psxrl's exit code for a usage error
        self.print_usage(sys.stderr)
        self.exit(1, f"{self.prog}: {message}\n")


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    p = _Parser(prog="psxrl experiment", description="Runs one of the seed's studies as a sweep of psxrl train "
                "runs on Ray (docs/results.md); the studies: " + ", ".join(names()) + ".")
    p.add_argument("name", help="the study's name, or a study file (.toml)")
    p.add_argument("--out", help="results folder (default runs/experiments/NAME, NAME-tiny with --tiny)")
    p.add_argument("--address", help="an existing Ray cluster (host:port, or auto); default: a local one")
    p.add_argument("--tiny", action="store_true", help="the tests' configuration: 2 seeds, a few short episodes")
    p.add_argument("--cpus", type=int, help="CPUs of the local Ray instance, so runs at once (default: the "
                   "machine's); give each of two studies side by side its share")
    a = p.parse_args(argv)
    if a.cpus is not None and (a.cpus < 1 or a.address):
        p.error("--cpus sizes a local Ray instance: a whole number of at least 1, and no --address")
    os.environ.setdefault("RAY_USAGE_STATS_ENABLED", "0")  # as psxrl sweep: no usage reports from a local Ray
    try:
        from psxrl.ray import report, sweep as ray_sweep
    except ModuleNotFoundError as e:
        if e.name != "ray":
            raise
        print("psxrl experiment: the studies run on Ray, which this Python lacks: pip install .[ray], or use the "
              ".venv-ray that scripts/setup.sh makes (psxrl experiment runs the Python named by PSXRL_PYTHON)",
              file=sys.stderr)
        return 2
    try:
        study, path = load(a.name, a.out, a.tiny)
        exe = ray_sweep.find_executable()
        study.out.mkdir(parents=True, exist_ok=True)
        write_commands(study, path, exe, shlex.join(["psxrl", "experiment", *argv]))
        failed = ray_sweep.run(study, a.address, cpus=a.cpus)
    except (ValueError, FileNotFoundError, ConnectionError) as e:  # the file, the executable, the cluster
        print(f"psxrl experiment: {e}", file=sys.stderr)
        return 2
    print(f"{len(study.runs) - len(failed)} of {len(study.runs)} runs finished; table {report.table_path(study)} "
          f"and {study.out / 'runs.md'}, figure {report.figure_path(study)}, commands {study.out / 'commands.sh'}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
