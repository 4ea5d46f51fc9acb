"""`python -m psxrl.ray sweep CONFIG.toml [--address HOST:PORT] [--out DIR]` (docs/scaling.md)."""
import os
import sys

USAGE = "usage: python -m psxrl.ray sweep CONFIG.toml [--address HOST:PORT] [--out DIR]"


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] != "sweep":
        print(USAGE, file=sys.stderr)
        return 0 if argv and argv[0] in ("-h", "--help") else 1  # psxrl's usage-error code
    # A Ray instance this command starts reports no usage to Ray's developers unless asked to.
    os.environ.setdefault("RAY_USAGE_STATS_ENABLED", "0")
    try:
        from .sweep import main as sweep_main
    except ModuleNotFoundError as e:
        if e.name != "ray":
            raise
        print("psxrl sweep: psxrl.ray needs Ray, which this Python lacks: pip install .[ray], or use the "
              ".venv-ray that scripts/setup.sh makes (psxrl sweep runs the Python named by PSXRL_PYTHON)",
              file=sys.stderr)
        return 2
    return sweep_main(argv[1:])


if __name__ == "__main__":
    sys.exit(main())
