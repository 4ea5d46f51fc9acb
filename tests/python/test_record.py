"""psxrl.Recorder: an Env's emulated frames to a video or to PNG pictures. The picture counts
follow from the frames the Env reports (info["game_frames"] per move): every frame is recorded,
1 in N with every=N (the first always), which is how `psxrl play --record-every` counts."""
import struct
from pathlib import Path

import pytest

import psxrl

FORWARD, LOOKRIGHT = 0, 1


def play(env, moves):
    """Plays `moves` and returns the emulated frames they took."""
    return sum(env.step(a)[4]["game_frames"] for a in moves)


def test_records_every_frame_of_the_moves_to_mp4(tmp_path):
    env = psxrl.Env(obs="simple")
    env.reset(level=1, seed=0)
    target = tmp_path / "episode.mp4"
    rec = psxrl.Recorder(env, str(target))
    frames = play(env, [FORWARD, LOOKRIGHT, FORWARD])
    assert rec.recording and not target.exists()  # written to a temporary file until close()
    summary = rec.close()
    assert not rec.recording
    assert summary.startswith(f"{frames} pictures (320x240") and str(target) in summary
    data = target.read_bytes()
    assert data[4:8] == b"ftyp"  # an ISO base media (MP4) file
    assert rec.close() == summary  # closing again changes nothing
    play(env, [FORWARD])  # the Env plays on, unrecorded
    psxrl.Recorder(env, str(tmp_path / "again.mp4")).close()  # and can be recorded again


def test_records_one_picture_in_n_to_png_and_wav(tmp_path):
    env = psxrl.Env(obs="simple")
    env.reset(level=1, seed=0)
    folder = tmp_path / "frames"
    with psxrl.Recorder(env, str(folder), every=3):
        frames = play(env, [FORWARD, FORWARD])
    pictures = sorted(folder.glob("*.png"))
    assert len(pictures) == (frames + 2) // 3  # frames 1, 4, 7, ...
    assert all(p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" for p in pictures)
    wav = (folder / "audio.wav").read_bytes()
    assert wav[:4] == b"RIFF" and wav[8:12] == b"WAVE"
    channels, rate = struct.unpack_from("<HI", wav, 22)
    assert (channels, rate) == (2, 44100)  # the SPU's output (psx-spx "SPU"): 44.1 kHz stereo


def test_an_exception_in_the_with_block_leaves_no_video(tmp_path):
    env = psxrl.Env(obs="simple")
    env.reset(level=1, seed=0)
    target = tmp_path / "broken.mp4"
    with pytest.raises(KeyError):
        with psxrl.Recorder(env, str(target)):
            play(env, [FORWARD])
            raise KeyError("stop")
    assert not target.exists() and list(tmp_path.iterdir()) == []


def test_refuses_a_second_recorder_and_bad_targets(tmp_path):
    env = psxrl.Env(obs="simple")
    env.reset(level=1, seed=0)
    rec = psxrl.Recorder(env, str(tmp_path / "one.mp4"))
    with pytest.raises(RuntimeError, match="already being recorded"):
        psxrl.Recorder(env, str(tmp_path / "two.mp4"))
    rec.abandon()
    with pytest.raises(ValueError, match="at least 1"):
        psxrl.Recorder(env, str(tmp_path / "x.mp4"), every=0)
    (tmp_path / "file").write_text("not a folder")
    with pytest.raises(RuntimeError, match="file"):
        with psxrl.Recorder(env, str(tmp_path / "file" / "pictures")):
            play(env, [FORWARD])
