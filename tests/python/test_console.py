"""psxrl.Console against the seed's PSXPY operations (Appendix B's ProcPipe table, §3.1.5), one
test per operation, on Tumble, whose RAM contract (games/tumble/README.md) gives every expected
value: the magic word, state codes, ball position and facing, and the camera's turn per LOOK."""
import gc
import time

import numpy as np
import pytest

import psxrl
from conftest import (BALL_X, BALL_Y, CAMERA_ANGLE, FACING, LEVEL, MAGIC, PLAYING, REQUEST_LEVEL, STATE, TITLE,
                      boot_tumble, start_level, tumble_exe)

RAM_SIZE = 2 * 1024 * 1024
MOVE_FRAMES = 40  # every single move of level 1's first tiles ends within 16 + 22 frames (README)


def look_right(c):
    c.press_for("right", 2)
    c.run_frames(MOVE_FRAMES)


def test_pause_and_resume_are_the_gaps_between_run_calls(title_console):
    # PSXPY's Pause/Resume (IDs 2, 3): the console only runs inside a run call, so between calls it
    # is paused with a guarantee that nothing changes, and a run call resumes it for exactly n frames.
    c = title_console
    frames = c.frames
    before = bytes(c.ram())
    time.sleep(0.05)
    assert bytes(c.ram()) == before and c.frames == frames
    c.run_frames(7)
    assert c.frames == frames + 7
    c.run_frame()
    assert c.frames == frames + 8


def test_gpu_snapshot(title_console, tmp_path):
    # GPU Snapshot (ID 11): Tumble displays 320x240 (README), as an RGB frame.
    title_console.run_frames(30)  # the title's first frames are black until the display is on
    screen = title_console.get_screen()
    assert screen.shape == (240, 320, 3) and screen.dtype == np.uint8
    assert len(np.unique(screen.reshape(-1, 3), axis=0)) > 1  # the title is drawn, not blank
    title_console.save_screenshot(str(tmp_path / "title.png"))
    assert (tmp_path / "title.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    vram = title_console.vram()
    assert vram.shape == (512, 1024) and vram.dtype == np.uint16


def test_get_screen_is_a_view_refreshed_by_run_calls(level1_console):
    c = level1_console
    screen = c.get_screen()
    assert not screen.flags.writeable and not screen.flags.owndata
    assert np.shares_memory(screen, c.get_screen())  # the same buffer every time: no copy
    before = screen.copy()
    look_right(c)  # the camera turns a quarter: the picture changes under the same view
    assert np.array_equal(screen, c.get_screen())
    assert not np.array_equal(screen, before)


def test_views_keep_the_console_alive():
    # An array over the console's buffers holds its own reference to the console (not to the
    # Python object, which close() may empty): the console outlives both the object and close().
    c = boot_tumble()
    screen, ram = c.get_screen(), c.ram()
    expected = screen.copy(), bytes(ram)
    c.close()
    del c
    gc.collect()
    assert np.array_equal(screen, expected[0]) and bytes(ram) == expected[1]


def test_memory_snapshot_reads(title_console):
    # Memory Snapshot (ID 21): the contract's magic "TMBL" = 0x4C424D54 little-endian, version 2.
    c = title_console
    assert c.read32(MAGIC) == 0x4C424D54
    assert c.read_bytes(MAGIC, 4) == b"TMBL"
    assert c.read16(MAGIC) == 0x4D54 and c.read16(MAGIC + 2) == 0x4C42 and c.read8(MAGIC) == ord("T")
    assert c.read32(MAGIC + 4) == 2
    assert c.read32(STATE) == TITLE
    # Any segment and mirror of RAM reads the same word.
    for alias in (0x00010000, 0xA0010000, 0x80210000):
        assert c.read32(alias) == 0x4C424D54
    assert c.ram()[0x10000:0x10004].tobytes() == b"TMBL"
    with pytest.raises(ValueError):
        c.read32(0x1F000000)  # expansion region: not RAM or scratchpad


def test_copy_memory_to_disk(title_console, tmp_path):
    # Copy Memory to Disk (ID 22): the whole RAM.
    path = tmp_path / "ram.bin"
    title_console.dump_ram(str(path))
    data = path.read_bytes()
    assert len(data) == RAM_SIZE
    assert data == bytes(title_console.ram())
    assert data[0x10000:0x10004] == b"TMBL"


def test_write_byte_starts_a_level(title_console):
    # Write Byte (ID 26): writing 1 to request_level starts level 1 on the next frame (contract).
    c = title_console
    c.write_byte(REQUEST_LEVEL, 1)
    assert c.read8(REQUEST_LEVEL) == 1
    c.run_frames(2)
    assert c.read32(STATE) == PLAYING and c.read32(LEVEL) == 1
    assert c.read32(REQUEST_LEVEL) == 0  # the game clears the request
    # Level 1's start tile is S at column 2 of the last row (row 5), facing north.
    assert (c.read32(BALL_X), c.read32(BALL_Y), c.read32(FACING)) == (2, 5, 0)
    c.write_bytes(0x80100000, b"\x01\x02\x03\x04")
    assert c.read32(0x80100000) == 0x04030201


def test_memory_listeners_sleep_and_wake(level1_console):
    # Silence/Wake Memory Notification (IDs 24, 25) on listeners with keys, fresh-only and flow limit.
    c = level1_console
    c.watch("facing", FACING, 4)
    c.watch("camera", CAMERA_ANGLE, 4, fresh_only=True)
    c.watch("camera_limited", CAMERA_ANGLE, 4, fresh_only=True, flow_limit_frames=6)
    c.take_watch_events()
    look_right(c)
    events = c.take_watch_events()
    facing = [e for e in events if e.key == "facing"]
    camera = [e for e in events if e.key == "camera"]
    limited = [e for e in events if e.key == "camera_limited"]
    assert facing and facing[-1].new_value == 1  # east
    assert all(e.address == FACING & 0x1FFFFFFF and e.width == 4 for e in facing)
    # A LOOK turns the camera on each of its 12 frames, north (0) to east (1024).
    assert len(camera) == 12 and camera[-1].new_value == 1024
    assert all(e.old_value != e.new_value for e in camera)
    assert [e.frame for e in camera] == sorted(e.frame for e in camera)
    # Two events per 6-frame window, the rest coalesced into one ending on the same value.
    assert len(limited) < len(camera) and limited[-1].new_value == 1024

    c.sleep_watch("facing")
    look_right(c)
    events = c.take_watch_events()
    assert not [e for e in events if e.key == "facing"]
    assert [e for e in events if e.key == "camera"][-1].new_value == 2048  # south: others still report
    assert c.read32(FACING) == 2

    c.wake_watch("facing")
    look_right(c)
    facing = [e for e in c.take_watch_events() if e.key == "facing"]
    assert facing and facing[-1].new_value == 3  # west

    c.unwatch("facing")
    with pytest.raises(ValueError):
        c.watch("camera", CAMERA_ANGLE, 4)  # the key is in use


def test_audio_record_with_cropping(level1_console):
    # Start/Stop Audio Record (IDs 31, 32) with the seed's early and late amplitude-based cropping.
    c = level1_console
    threshold, tail = 64, 441
    c.start_audio_capture(threshold=threshold, silence_samples=4410, tail_samples=tail)
    assert c.audio_capture_state == "waiting"
    c.press_for("up", 2)  # FORWARD: the roll sound
    c.run_frames(90)
    samples = c.stop_audio_capture()
    assert samples.dtype == np.int16 and samples.ndim == 2 and samples.shape[1] == 2
    loud = np.flatnonzero(np.abs(samples.astype(np.int32)).max(axis=1) >= threshold)
    assert len(loud) > 0 and loud[0] == 0  # early cropping: the recording starts on a loud sample
    assert len(samples) - 1 - loud[-1] == tail  # late cropping: exactly the tail after the last one
    assert c.audio_capture_state == "idle"


def test_take_audio_is_44100_hz(title_console):
    c = title_console
    c.take_audio()
    c.run_frames(60)
    samples = c.take_audio()
    assert samples.shape[1] == 2
    # NTSC frames are 1/59.94 s (docs/console.md): 60 frames hold 44100 * 60 / 59.94 samples.
    assert abs(len(samples) - 44100 * 60 / 59.94) < 44100 / 59.94


def run_script(c):
    """A fixed input sequence: look right, roll onto the coin, look left; then RAM and screen."""
    look_right(c)
    c.press_for("up", 2)
    c.run_frames(MOVE_FRAMES)
    c.press_for(psxrl.BUTTONS["left"], 2)
    c.run_frames(MOVE_FRAMES)
    return bytes(c.ram()), c.get_screen().copy()


def test_save_and_load_state_bytes_and_files(level1_console, tmp_path):
    # Save State / Load State (IDs 41, 42): a round trip gives the same future.
    c = level1_console
    state = c.save_state()
    assert isinstance(state, bytes) and state[:8] == b"PSXRLSAV"
    ram1, screen1 = run_script(c)
    assert c.read32(BALL_X) == 3  # rolled east onto the coin
    c.load_state(state)
    ram2, screen2 = run_script(c)
    assert ram1 == ram2 and np.array_equal(screen1, screen2)

    c.load_state(state)
    c.save_state_file(str(tmp_path / "s.state"))
    other = boot_tumble()
    other.load_state_file(str(tmp_path / "s.state"))
    ram3, _ = run_script(other)
    assert ram3 == ram1
    compressed = c.save_state(compress=True)
    assert len(compressed) < len(state)
    other.load_state(compressed)
    assert bytes(other.ram()) == bytes(c.ram())


def test_bad_state_is_refused_and_changes_nothing(level1_console):
    c = level1_console
    state = bytearray(c.save_state())
    frames, ram = c.frames, bytes(c.ram())
    state[-1] ^= 0xFF
    with pytest.raises(psxrl.StateError) as err:
        c.load_state(bytes(state))
    assert isinstance(err.value, ValueError) and "checksum" in str(err.value)
    with pytest.raises(psxrl.StateError):
        c.load_state(b"PSXRLSAV")
    assert c.frames == frames and bytes(c.ram()) == ram


def test_run_until_a_python_condition(title_console):
    c = title_console
    c.write32(REQUEST_LEVEL, 1)
    frames = c.frames
    assert c.run_until(lambda: c.read32(STATE) == PLAYING, max_frames=30)
    assert c.frames == frames + 1  # the request is taken on the next frame
    assert not c.run_until(lambda: False, max_frames=3) and c.frames == frames + 4

    def fails():
        raise KeyError("from the condition")

    with pytest.raises(KeyError, match="from the condition"):
        c.run_until(fails, max_frames=5)


def test_buttons_by_name_and_bit():
    # psx-spx bit order (src/core/sio/pad.h): select 0, start 3, up 4, cross 14, square 15.
    b = psxrl.BUTTONS
    assert (b["select"], b["start"], b["up"], b["cross"], b["square"]) == (1, 8, 16, 1 << 14, 1 << 15)
    c = psxrl.Console()
    c.set_buttons("cross+up")
    c.press(["start", b["select"]], port=2)
    c.release(0)
    with pytest.raises(ValueError, match="unknown button 'jump'"):
        c.press("jump")
    with pytest.raises(ValueError):
        c.press(0x10000)
    c.plug_pad(1, "dualshock")
    c.set_axes(left_x=0, left_y=255)
    assert c.rumble() == (0, 0)
    with pytest.raises(ValueError):
        c.plug_pad(1, "keyboard")


def test_bad_files_raise_input_error_with_the_message(tmp_path):
    c = psxrl.Console()
    with pytest.raises(psxrl.InputError, match="nonexistent.exe: cannot open file"):
        c.boot_exe("nonexistent.exe")
    short = tmp_path / "short_bios.bin"
    short.write_bytes(b"\0" * 22)
    with pytest.raises(ValueError, match="524288 bytes"):
        c.load_bios(str(short))
    # The core reports an unwritable dump as a runtime error naming the file (docs/python.md).
    with pytest.raises(RuntimeError, match="/nonexistent-dir/ram.bin"):
        c.dump_ram("/nonexistent-dir/ram.bin")


def test_gl_renderer_draws_tumble_larger_with_the_same_native_vram():
    """renderer='gl' (OSMesa): at scale 2 the picture is 640x480, VRAM and RAM equal the
    software renderer's (docs/renderer.md)."""
    consoles = [psxrl.Console(), psxrl.Console(renderer="gl", scale=2)]
    for c in consoles:
        c.boot_exe(tumble_exe())
        assert c.run_until_equal(STATE, TITLE, max_frames=600)
        c.run_frames(30)
    sw, gl = consoles
    assert sw.get_screen().shape == (240, 320, 3)
    assert gl.get_screen().shape == (480, 640, 3)
    assert np.array_equal(sw.vram(), gl.vram())
    assert bytes(sw.ram()) == bytes(gl.ram())


def test_bad_renderer_arguments_are_refused():
    with pytest.raises(ValueError, match="'software' or 'gl'"):
        psxrl.Console(renderer="vulkan")
    with pytest.raises(ValueError, match="1 to 8"):
        psxrl.Console(renderer="gl", scale=9)


def test_gl_renderer_without_opengl_says_so(monkeypatch):
    monkeypatch.setenv("PSXRL_OSMESA_LIBRARY", "/nonexistent/libOSMesa.so.8")
    with pytest.raises(RuntimeError, match="OpenGL is not available"):
        psxrl.Console(renderer="gl")
