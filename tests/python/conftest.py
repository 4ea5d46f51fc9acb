"""Shared fixtures for the Python tests: the module under test comes from PYTHONPATH (CTest sets
it to build/python), Tumble's program from the same build (or the installed package)."""
import os
import shutil
import subprocess
from pathlib import Path

import pytest

import psxrl

# Tumble's RAM contract (games/tumble/README.md): 32-bit little-endian words at 0x80010000.
CONTRACT = 0x80010000
MAGIC, STATE, SCORE = CONTRACT + 0x00, CONTRACT + 0x08, CONTRACT + 0x0C
CAMERA_ANGLE, BALL_X, BALL_Y, FACING = CONTRACT + 0x18, CONTRACT + 0x1C, CONTRACT + 0x20, CONTRACT + 0x24
LEVEL, REQUEST_LEVEL = CONTRACT + 0x28, CONTRACT + 0x48
TITLE, PLAYING = 50, 48


def tumble_exe():
    packaged = Path(psxrl.__file__).parent / "games" / "tumble" / "tumble.exe"
    if packaged.is_file():
        return str(packaged)
    build = Path(os.environ.get("PSXRL_BUILD_DIR", Path(psxrl.__file__).resolve().parents[2]))
    return str(build / "games" / "tumble" / "tumble.exe")


def boot_tumble():
    """A console at Tumble's title screen."""
    c = psxrl.Console()
    c.boot_exe(tumble_exe())
    assert c.run_until_equal(STATE, TITLE, max_frames=600)
    return c


def start_level(c, level=1):
    """Starts a level through the RAM contract's request word; returns when it is playing."""
    c.write32(REQUEST_LEVEL, level)
    assert c.run_until_equal(STATE, PLAYING, max_frames=30)
    assert c.read32(LEVEL) == level


@pytest.fixture
def title_console():
    return boot_tumble()


@pytest.fixture
def level1_console():
    c = boot_tumble()
    start_level(c, 1)
    return c


@pytest.fixture(scope="session")
def x_display():
    """An X display: the one set, else a private Xvfb for this test session (scripts/setup.sh
    installs it; a missing Xvfb fails, it is not skipped: render_mode="human" must be tested)."""
    if os.environ.get("DISPLAY"):
        yield os.environ["DISPLAY"]
        return
    if shutil.which("Xvfb") is None:
        pytest.fail("Xvfb is missing: run scripts/setup.sh (Debian package xvfb)")
    read, write = os.pipe()
    # -noreset: an X server resets when its last client disconnects, and a window opened during
    # the reset finds no display (each test's window is the only client while it lives).
    server = subprocess.Popen(["Xvfb", "-displayfd", str(write), "-screen", "0", "1024x768x24", "-nolisten", "tcp",
                               "-noreset"],
                              pass_fds=(write,), stderr=subprocess.DEVNULL)
    os.close(write)
    with os.fdopen(read) as f:
        number = f.readline().strip()  # Xvfb writes its display number once it accepts clients
    assert number, "Xvfb did not start"
    yield ":" + number
    server.terminate()
    server.wait()


@pytest.fixture
def display(x_display, monkeypatch):
    """DISPLAY set for one test, for render_mode="human" and psxrl.Window."""
    monkeypatch.setenv("DISPLAY", x_display)
    return x_display
