"""`python -m psxrl.ray sweep CONFIG.toml [--address HOST:PORT] [--out DIR]` (docs/scaling.md)."""
import sys

USAGE = "usage: python -m psxrl.ray sweep CONFIG.toml [--address HOST:PORT] [--out DIR]"


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] != "sweep":
        print(USAGE, file=sys.stderr)
        return 0 if argv and argv[0] in ("-h", "--help") else 2
    from .sweep import main as sweep_main

    return sweep_main(argv[1:])


if __name__ == "__main__":
    sys.exit(main())
