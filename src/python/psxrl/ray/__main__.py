"""`python -m psxrl.ray sweep CONFIG.toml [--address HOST:PORT] [--out DIR]` (docs/scaling.md)."""
import sys

USAGE = "usage: python -m psxrl.ray sweep CONFIG.toml [--address HOST:PORT] [--out DIR]"


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] != "sweep":
        print(USAGE, file=sys.stderr)
        return 0 if argv and argv[0] in ("-h", "--help") else 2
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
