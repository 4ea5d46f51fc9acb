#!/usr/bin/env python3
"""The seed's memory listeners (§3.1.2-3.1.3) on Tumble: listen to the score, the camera and the
ball's facing while a scripted player moves, putting a listener to sleep and waking it again.

  PYTHONPATH=build/python python3 examples/memory_listener.py   (or after scripts/setup.sh)
"""
from pathlib import Path

import psxrl

# Tumble's RAM contract (games/tumble/README.md).
STATE, SCORE, CAMERA_ANGLE, FACING, REQUEST_LEVEL = 0x80010008, 0x8001000C, 0x80010018, 0x80010024, 0x80010048


def tumble_exe():
    for p in (Path(psxrl.__file__).parent / "games/tumble/tumble.exe",
              Path(__file__).resolve().parents[1] / "build/games/tumble/tumble.exe"):
        if p.is_file():
            return str(p)
    raise SystemExit("tumble.exe not found: run scripts/setup.sh first")


def move(c, button, frames=40):
    c.press_for(button, 2)
    c.run_frames(frames)
    for e in c.take_watch_events():
        print(f"  frame {e.frame:5}  {e.key:7} {e.old_value:6} -> {e.new_value}")


def main():
    c = psxrl.Console()
    c.boot_exe(tumble_exe())
    c.run_until_equal(STATE, 50, max_frames=600)  # the title screen
    c.write32(REQUEST_LEVEL, 1)
    c.run_until_equal(STATE, 48, max_frames=30)  # level 1 is playing

    # Listeners: key, start, length, fresh_only, flow limit (the seed's 2 per 0.4 s = 24 frames).
    c.watch("score", SCORE, 4, fresh_only=True)
    c.watch("camera", CAMERA_ANGLE, 4, fresh_only=True, flow_limit_frames=24)
    c.watch("facing", FACING, 4, fresh_only=True)

    print("LOOK RIGHT (the camera turns, facing becomes east):")
    move(c, "right")
    print("FORWARD onto a coin (the score counts up 250):")
    move(c, "up")
    c.sleep_watch("camera")
    print("LOOK LEFT with the camera listener asleep:")
    move(c, "left")
    c.wake_watch("camera")
    print("LOOK LEFT with it awake again:")
    move(c, "left")


if __name__ == "__main__":
    main()
