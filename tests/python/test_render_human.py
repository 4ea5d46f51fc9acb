"""render_mode="human": the play window (psxrl.Window, the same SDL code as `psxrl play`) on a
virtual X display (conftest.py's `display` fixture starts Xvfb when no display is set). Expected
pictures are arithmetic on the console's own: each console pixel a 2x2 square in a 640x480
window."""
import time

import gymnasium as gym
import numpy as np
import pytest

import psxrl

# Level 1 (games/tumble/levels/level01.txt): east from the start, the third FORWARD leaves the map.
LOOKRIGHT, FORWARD = 1, 0
FALL_OFF = [LOOKRIGHT, FORWARD, FORWARD, FORWARD]
CONSOLE_FPS = 53693175 / (3413 * 263)  # psx-spx "GPU Timings": NTSC frames per second


def doubled(picture):
    return picture.repeat(2, axis=0).repeat(2, axis=1)


def test_window_shows_a_picture_at_twice_its_size(display):
    rng = np.random.default_rng(7)
    picture = rng.integers(0, 256, size=(240, 320, 3), dtype=np.uint8)
    window = psxrl.Window("psxrl test", 320, 240)
    window.show(picture, read_back=True)
    shown = window.picture()
    assert shown.shape == (480, 640, 3)
    np.testing.assert_array_equal(shown, doubled(picture))
    assert window.poll() is False  # nobody closed it


def test_window_refuses_a_picture_that_is_not_rgb(display):
    window = psxrl.Window("psxrl test", 320, 240)
    with pytest.raises(ValueError, match="height, width, 3"):
        window.show(np.zeros((240, 320), dtype=np.uint8))


def test_human_mode_shows_each_step_in_real_time(display):
    env = gym.make("psxrl/Tumble-v0", render_mode="human")
    assert "human" in env.metadata["render_modes"]
    env.reset(seed=3)
    start = time.monotonic()
    frames = 0
    for action in FALL_OFF:
        _, _, terminated, _, info = env.step(action)
        frames += info["game_frames"]
        # The window shows the console's picture after the move, doubled.
        np.testing.assert_array_equal(env.unwrapped.window.picture(), doubled(env.unwrapped.env.get_screen()))
    elapsed = time.monotonic() - start
    assert terminated and info["outcome"] == "lose"
    # Each picture stays up as long as its move lasted in the game: no faster than the console.
    assert elapsed >= frames / CONSOLE_FPS - 0.05
    assert env.render() is None
    env.close()
    assert env.unwrapped.window is None


def test_human_mode_without_a_display_says_so(monkeypatch):
    # A warning, not an error (#61): Gymnasium's check_env makes a "human" environment on every
    # server; the episode goes on without a picture (tests/python/test_robust.py checks "once").
    for name in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"):
        monkeypatch.delenv(name, raising=False)
    env = gym.make("psxrl/Tumble-v0", render_mode="human")
    with pytest.warns(RuntimeWarning, match="render_mode='human' shows nothing: no display"):
        env.reset(seed=0)
    assert env.unwrapped.window is None
