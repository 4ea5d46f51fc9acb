"""Console.press_for as docs/python.md describes it (issue #62): it runs no frames, the buttons stay
down for the next `frames` frame ends; two presses in a row are two presses only when a frame with
the button up lies between them. Tumble's level-select screen counts presses: each down edge of
RIGHT moves the highlighted level (contract word menu_level) on by one (games/tumble/logic/flow.c)."""
from conftest import CONTRACT, STATE

MENU_LEVEL = CONTRACT + 0x58
LEVEL_SELECT = 56


def test_press_for_runs_no_frames_and_presses_in_a_row(title_console):
    c = title_console
    frames = c.frames
    c.press_for("start", 2)
    assert c.frames == frames  # nothing ran
    c.run_frames(3)
    assert c.read32(STATE) == LEVEL_SELECT and c.read32(MENU_LEVEL) == 1
    # Two presses with the release frame between them: two steps.
    c.press_for("right", 2)
    c.run_frames(3)
    c.press_for("right", 2)
    c.run_frames(3)
    assert c.read32(MENU_LEVEL) == 3
    # Pressed again while still down: the count restarts, one long press, one step.
    c.press_for("right", 2)
    c.run_frames(1)
    c.press_for("right", 2)
    c.run_frames(3)
    assert c.read32(MENU_LEVEL) == 4
