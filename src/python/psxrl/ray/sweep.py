"""Sweeps on Ray: every run of a sweep file is a Ray task that runs the C++ trainer (`psxrl train`)
in its own process and run folder, on whichever node of the cluster Ray picks.

A run folder says how far its run got, so a sweep started again (after a lost node, or ^C) only
does what is left: `done.json` marks a finished run, which is skipped; a folder with the trainer's
`checkpoint.psxrl` is an interrupted run, continued with `psxrl train --resume`. Ray itself runs a
task again when the worker process or node running it dies, and the retry resumes the same way.
The sweep folder must be one path that every node sees (a shared file system on a real cluster).
"""
import argparse
import ctypes
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import ray

from ..executable import find_executable
from . import report
from .sweep_config import load

DONE = "done.json"
CHECKPOINT = "checkpoint.psxrl"
LOG = "train.log"
_PR_SET_PDEATHSIG = 1


def finished(folder):
    return (Path(folder) / DONE).is_file()


def _die_with_parent():
    # The trainer must not outlive the Ray worker that started it: a retry of the task would
    # otherwise train into the same folder beside it.
    ctypes.CDLL(None, use_errno=True).prctl(_PR_SET_PDEATHSIG, signal.SIGKILL)


def train(exe, folder, args, resumable):
    """Runs one `psxrl train` to its end in `folder`, resuming from the checkpoint there if an
    earlier attempt was interrupted; returns what it did. A trainer failure raises."""
    folder = Path(folder)
    exe = os.environ.get("PSXRL_EXE", exe)
    resume = (folder / CHECKPOINT).is_file()
    if resume and not resumable:
        shutil.rmtree(folder)  # --envs > 1 or --start-states: this run cannot continue exactly
        resume = False
    folder.mkdir(parents=True, exist_ok=True)
    command = [exe, "train", *args] + (["--resume"] if resume else [])
    start = time.monotonic()
    with open(folder / LOG, "a") as log:
        log.write(f"$ {' '.join(command)}   # on {socket.gethostname()}, pid {os.getpid()}\n")
        log.flush()
        code = subprocess.run(command, stdout=log, stderr=subprocess.STDOUT, preexec_fn=_die_with_parent).returncode
    if code != 0:
        tail = (folder / LOG).read_text(errors="replace").splitlines()[-3:]
        raise RuntimeError(f"psxrl train exited with {code} in {folder}: " + " / ".join(tail))
    done = {"resumed": resume, "host": socket.gethostname(), "seconds": round(time.monotonic() - start, 3)}
    (folder / DONE).write_text(json.dumps(done) + "\n")
    return done


# The Ray task: run again (resuming) when its worker or node dies, not when the trainer fails.
train_run = ray.remote(max_retries=3)(train)


def run(sweep, address=None, log=print, cpus=None):
    """Runs what is left of `sweep` (psxrl.ray.sweep_config.Sweep) on the cluster at `address`
    (None: the one this process is connected to, else a new local one of `cpus` CPUs, default all
    the machine's) and writes the report. Returns the runs that failed, as (run, error) pairs."""
    if not ray.is_initialized():
        if address:
            ray.init(address=address, log_to_driver=False)
        else:
            # A local instance of its own, never one found running: every local instance has its
            # own session folder and ports, so sweeps side by side do not meet (docs/scaling.md).
            ray.init(address="local", num_cpus=cpus, include_dashboard=False, log_to_driver=False)
    exe = find_executable()
    sweep.out.mkdir(parents=True, exist_ok=True)
    pending = {}
    for r in sweep.runs:
        if finished(r.folder):
            log(f"skip   {r.config} seed {r.seed}: finished")
            continue
        envs = int(r.options.get("envs", 1))  # one CPU per environment the trainer steps
        ref = train_run.options(num_cpus=envs).remote(exe, str(r.folder), r.train_args(), r.resumable())
        pending[ref] = r
    # Nothing else is printed until a run ends, which on a loaded machine can take minutes: say
    # how many wait and how many can run at once, so a queue does not look like a stall.
    cpus = int(ray.cluster_resources().get("CPU", 0))
    log(f"queued {len(pending)} runs on Ray's {cpus} CPU{'' if cpus == 1 else 's'} (one CPU per environment of a "
        "run); a line as each run ends")
    failed = []
    while pending:
        [ref], _ = ray.wait(list(pending), num_returns=1)
        r = pending.pop(ref)
        try:
            done = ray.get(ref)
            log(f"done   {r.config} seed {r.seed}: {done['seconds']} s on {done['host']}"
                + (" (resumed)" if done["resumed"] else ""))
        except ray.exceptions.RayError as e:  # the trainer failed, or Ray gave up on the task
            failed.append((r, e))
            log(f"FAILED {r.config} seed {r.seed}: {e}")
    report.write(sweep)
    return failed


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # psxrl's exit codes: 1 for a usage error, 2 for a bad file
        self.print_usage(sys.stderr)
        self.exit(1, f"{self.prog}: {message}\n")


def main(argv=None):
    p = _Parser(prog="psxrl sweep", description="Runs a grid of psxrl train runs x seeds as Ray tasks "
                "(docs/scaling.md); exit codes: 0 all runs finished, 1 usage error or a run failed, 2 bad "
                "sweep file, psxrl executable or cluster address.")
    p.add_argument("config", help="the sweep file (TOML)")
    p.add_argument("--address", help="an existing Ray cluster (host:port, or auto); default: a local one")
    p.add_argument("--out", help="sweep folder (default: the file's out, else runs/ + the file's name)")
    p.add_argument("--cpus", type=int, help="CPUs of the local Ray instance, so runs at once (default: the "
                   "machine's); give each of two sweeps side by side its share")
    a = p.parse_args(argv)
    if a.cpus is not None and (a.cpus < 1 or a.address):
        p.error("--cpus sizes a local Ray instance: a whole number of at least 1, and no --address")
    try:
        sweep = load(a.config, a.out)
        failed = run(sweep, a.address, cpus=a.cpus)
    except (ValueError, FileNotFoundError, ConnectionError) as e:  # the file, the executable, the cluster
        print(f"psxrl sweep: {e}", file=sys.stderr)
        return 2
    print(f"{len(sweep.runs) - len(failed)} of {len(sweep.runs)} runs finished; "
          f"table {report.table_path(sweep)}, figure {report.figure_path(sweep)}")
    return 1 if failed else 0
