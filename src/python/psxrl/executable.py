"""Finding the `psxrl` executable from Python: the sweeps run its trainer (psxrl.ray) and the
offline exporter its player (psxrl.offline export-policy)."""
import os
import shutil
from pathlib import Path


def find_executable():
    """The `psxrl` executable: $PSXRL_EXE, else $PSXRL_BUILD_DIR/psxrl, else the build tree's beside
    a module imported from build/python, else `psxrl` on PATH."""
    if os.environ.get("PSXRL_EXE"):
        exe = Path(os.environ["PSXRL_EXE"])
        if not exe.is_file():
            raise FileNotFoundError(f"PSXRL_EXE={exe}: no such file")
        return str(exe.resolve())
    import psxrl

    candidates = [Path(os.environ["PSXRL_BUILD_DIR"]) / "psxrl"] if os.environ.get("PSXRL_BUILD_DIR") else []
    candidates.append(Path(psxrl.__file__).resolve().parents[2] / "psxrl")  # build/python/psxrl/__init__.py
    for exe in candidates:
        if exe.is_file():
            return str(exe.resolve())
    on_path = shutil.which("psxrl")
    if on_path:
        return on_path
    raise FileNotFoundError("cannot find the psxrl executable: set PSXRL_EXE or PSXRL_BUILD_DIR, or put psxrl "
                            "on PATH")
