#!/usr/bin/env python3
"""Makes a save state of Tumble in the middle of level 1 (tests/data/states/README.md).

Usage: make_state.py TUMBLE_EXE DEMO_SCRIPT FRAMES OUT
Boots the EXE without a BIOS, presses the demo script's buttons at their frames (the script format
of `psxrl run --input`: FRAME BUTTONS [HOLD_FRAMES], '+' joins buttons), runs FRAMES frames and
saves a compressed state. Needs the psxrl Python module (build/python on PYTHONPATH).
"""
import sys

import psxrl


def main() -> None:
    exe, script, frames, out = sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4]
    presses = {}
    for line in open(script, encoding="utf-8"):
        words = line.split("#", 1)[0].split()
        if words:
            hold = int(words[2]) if len(words) > 2 else 1
            presses.setdefault(int(words[0]), []).append((words[1].split("+"), hold))
    console = psxrl.Console()
    console.boot_exe(exe)
    for frame in range(frames):
        for buttons, hold in presses.get(frame, []):
            console.press_for(buttons, hold)
        console.run_frame()
    console.save_state_file(out, compress=True)


if __name__ == "__main__":
    main()
