"""psxrl.Session and psxrl.Search: the memory search from Python on Tumble's demo session (made by
`psxrl record` in CTest's fixture, or here when run by hand). Expected addresses are the RAM
contract's (games/tumble/README.md); score values are the HUD's (coins 250, fruit 500, key 1000)."""
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import psxrl
from conftest import SCORE, STATE, tumble_exe

SOURCE = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def session_dir(tmp_path_factory):
    made = os.environ.get("PSXRL_TUMBLE_SESSION")
    if made and Path(made, "session.toml").is_file():
        return made
    out = tmp_path_factory.mktemp("session") / "tumble"
    build = Path(os.environ.get("PSXRL_BUILD_DIR", SOURCE / "build"))
    subprocess.run([str(build / "psxrl"), "record", "--exe", tumble_exe(), "--input",
                    str(SOURCE / "games/tumble/demo/level1.txt"), "--marks",
                    str(SOURCE / "tests/data/memsearch/tumble_level1.marks"), "--frames", "700", "--out", str(out)],
                   check=True)
    return str(out)


def test_session_contents(session_dir):
    s = psxrl.Session(session_dir)
    assert s.frames == 700
    # Every 60th frame from 0 to 660 (12), the 33 marks (one at 660) and the last frame: 45.
    assert len(s.snapshot_frames) == 45
    assert s.snapshot_frames.dtype == np.uint64
    assert len(s.marks) == 33 and s.marks[0] == (31, "title")
    assert s.inputs.shape == (700, 2)
    snap = s.snapshot(0)
    assert snap.shape == (2 * 1024 * 1024 + 1024,) and not snap.flags.writeable
    with pytest.raises(IndexError):
        s.snapshot(45)


def test_score_found_from_hud_values(session_dir):
    s = psxrl.Session(session_dir)
    q = s.search()
    q.eq("level_start", 0)
    for i, score in enumerate([250, 500, 750, 1250], start=1):
        q.eq(f"score#{i}", score)
    top = q.ranked(3)
    assert SCORE in top["address"].tolist()
    i = top["address"].tolist().index(SCORE)
    assert top["encoding"][i] == "u32"
    values = s.values(SCORE, "u32")
    assert values[s.snapshot_at(94)] == 250 and values[-1] == 4000


def test_state_and_text_queries(session_dir):
    s = psxrl.Session(session_dir)
    q = s.search(["u32", "u16", "u8"])
    q.apply("changes-at title,select,level_start,complete")
    assert STATE in q.ranked(3)["address"].tolist()
    with pytest.raises(psxrl.QueryError, match="no mark is labelled 'fruit'"):
        q.eq("fruit", 1)
    with pytest.raises(psxrl.QueryError, match="unknown query"):
        q.apply("grows start end")


def test_replay_and_bad_folder(session_dir, tmp_path):
    assert psxrl.Session(session_dir).replay() is None
    with pytest.raises(psxrl.InputError, match="not a session folder"):
        psxrl.Session(str(tmp_path / "missing"))
