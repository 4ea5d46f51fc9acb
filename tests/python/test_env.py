"""psxrl.Env and psxrl.VecEnv over the C++ environment layer, on Tumble's level 1 (map in
games/tumble/levels/level01.txt: width 5, start S at column 2 of row 5 facing north, coins at
columns 1 and 3, plain floor at column 4). Expected values follow from the map, the seed's simple
state 4*w*y + 4*x + z and Table 3.3 rewards in units of 1 - gamma (docs/environments.md)."""
import shutil
from pathlib import Path

import numpy as np
import pytest

import psxrl
from conftest import tumble_exe

FORWARD, LOOKRIGHT, LOOKLEFT, JUMPFORWARD = range(4)
INFO_FIELDS = {"game_frames", "real_seconds", "score", "time_left", "state", "level", "hit_upper_bound", "moves",
               "episode_reward", "outcome"}


def simple(x, y, facing, width=5):
    return 4 * width * y + 4 * x + facing


def test_env_walks_level_one():
    env = psxrl.Env(obs="simple", gamma=0.9)
    assert env.action_names == ["FORWARD", "LOOKRIGHT", "LOOKLEFT", "JUMPFORWARD"] and env.action_count == 4
    obs, info = env.reset(level=1, seed=7)
    assert obs.dtype == np.int64 and obs.tolist() == [simple(2, 5, 0)]
    assert set(info) == INFO_FIELDS and info["level"] == 1 and info["state"] == 48
    obs, reward, terminated, truncated, info = env.step(FORWARD)  # onto plain floor
    assert obs.tolist() == [simple(2, 4, 0)] and reward == 0 and not terminated and not truncated
    assert info["moves"] == 1 and info["outcome"] == ""
    env.step(LOOKRIGHT)
    obs, reward, *_ = env.step(FORWARD)  # east onto a coin: +250, 1/2 (1 - gamma)
    assert obs.tolist() == [simple(3, 4, 1)] and reward == pytest.approx(0.5 * (1 - 0.9))
    assert env.value("score") == 250
    env.step(FORWARD)  # column 4, floor
    obs, reward, terminated, truncated, info = env.step(FORWARD)  # off the east edge: a loss
    assert terminated and not truncated and info["outcome"] == "lose"
    assert reward == pytest.approx(-(1 - 0.9))
    assert info["episode_reward"] == pytest.approx(0.05 - 0.1)
    assert env.episode_over
    with pytest.raises(RuntimeError):
        env.step(FORWARD)


def test_reset_at_a_start_position():
    # psxrl train --start's walk: five FORWARDs from the start climb column 2 (all floor) to row 0;
    # the episode begins there, at move 0 with nothing scored.
    env = psxrl.Env(obs="simple", gamma=0.9)
    obs, info = env.reset(level=1, seed=7, start="FORWARD,forward,0,FORWARD,FORWARD")
    assert obs.tolist() == [simple(2, 0, 0)] and info["moves"] == 0 and info["score"] == 0
    obs, reward, terminated, _, info = env.step(LOOKRIGHT)
    assert obs.tolist() == [simple(2, 0, 1)] and info["moves"] == 1 and not terminated
    # LOOKRIGHT, FORWARD rolls east onto the coin at column 3 of row 5: a walk may not score.
    with pytest.raises(ValueError, match=r"move 2 \(FORWARD\) scores 250 points on level 1"):
        env.reset(level=1, seed=7, start="LOOKRIGHT,FORWARD")
    with pytest.raises(ValueError, match="start position 'BACK' is not an action"):
        env.reset(level=1, start="BACK")
    assert env.reset(level=1, start="")[0].tolist() == [simple(2, 5, 0)]


def test_observation_kinds_have_the_documented_shapes():
    expected = {
        "local": ((11,), np.float32),  # 3 rows x 3 squares + cumulative reward + time left
        "visual": ((3, 60, 80), np.uint8),
        "episode": ((3,), np.float32),
        "ram": ((2 * 1024 * 1024,), np.uint8),
        "rumble": ((2,), np.uint8),
        "audio": ((64, 13), np.float32),
    }
    for kind, (shape, dtype) in expected.items():
        env = psxrl.Env(obs=kind)
        obs, _ = env.reset(1, 0)
        assert obs.shape == shape and obs.dtype == dtype, kind
        assert env.observation_spaces[0]["shape"] == shape
    env = psxrl.Env(obs="multimodal", visual_gray=True)
    obs, _ = env.reset(1, 0)
    assert sorted(obs) == ["audio", "episode", "visual"] and obs["visual"].shape == (1, 60, 80)
    # local: the squares ahead of the start, facing north (rows 3-4 of columns 1-3 are c # c), then
    # the cumulative reward 0 and the whole level's time left (fraction 1).
    local, _ = psxrl.Env(obs="local").reset(1, 0)
    assert local[-2:].tolist() == [0.0, 1.0]


def test_errors_carry_the_cpp_messages():
    with pytest.raises(ValueError, match="simple, local, visual"):
        psxrl.Env(obs="pixels")
    with pytest.raises(TypeError, match="unexpected keyword argument 'colour'"):
        psxrl.Env(colour="red")
    with pytest.raises(psxrl.InputError, match="BIOS"):
        psxrl.Env(game="kula")
    env = psxrl.Env()
    env.reset(1, 0)
    with pytest.raises(IndexError):
        env.step(4)
    with pytest.raises(IndexError):
        env.reset(11, 0)  # Tumble has 10 levels


def test_a_lua_error_in_an_integration_names_the_script(tmp_path):
    # Tumble's integration with a script that does not parse: the error names file and line.
    source = Path(__file__).resolve().parents[2] / "games" / "tumble"
    game = tmp_path / "tumble"
    shutil.copytree(source / "levels", game / "levels")
    shutil.copy(source / "game.toml", game / "game.toml")
    (game / "game.lua").write_text("-- broken\nfunction on_reset(seed\n")
    with pytest.raises(psxrl.InputError, match=r"game\.lua:\d+:"):
        psxrl.Env(games_dir=tmp_path, build_games_dir=Path(tumble_exe()).parents[1])


def test_delays_are_settable():
    env = psxrl.Env(initial_delay=9, delay=5)
    assert env.delimiter["initial_delay"] == 9 and env.delimiter["delay"] == 5
    env.set_delays(6, 4)
    assert env.delimiter["initial_delay"] == 6 and env.delimiter["delay"] == 4


def test_vec_env_equals_single_envs_and_views_its_batch():
    k, seed = 2, 11
    vec = psxrl.VecEnv(k, threads=2, obs="simple")
    obs = vec.reset(1, seed)
    assert obs.shape == (k, 1) and not obs.flags.writeable
    # Environment 0 falls off on its 4th move and is reset in the same step; 1 keeps walking.
    plans = [[LOOKRIGHT, FORWARD, FORWARD, FORWARD, FORWARD, LOOKLEFT], [FORWARD, LOOKLEFT, FORWARD, LOOKRIGHT,
                                                                         FORWARD, FORWARD]]
    singles = [psxrl.Env(obs="simple") for _ in range(k)]
    episodes = [0] * k
    expected = [s.reset(1, psxrl.episode_seed(seed, i, 0))[0] for i, s in enumerate(singles)]
    assert np.array_equal(obs, np.stack(expected))
    for t in range(len(plans[0])):
        obs, rewards, terminated, truncated, infos = vec.step(np.array([p[t] for p in plans]))
        assert np.shares_memory(obs, vec.observation())  # a view of the batch, not a copy
        for i, s in enumerate(singles):
            o, r, term, trunc, info = s.step(plans[i][t])
            assert rewards[i] == r and terminated[i] == term and truncated[i] == trunc and infos[i]["score"] == info[
                "score"]
            if term or trunc:
                assert np.array_equal(vec.final_observation()[i], o)
                episodes[i] += 1
                o, _ = s.reset(1, psxrl.episode_seed(seed, i, episodes[i]))
            assert np.array_equal(obs[i], o)
    assert episodes == [1, 0]


def test_async_vec_env_gives_each_env_its_single_env_trajectory():
    k, seed = 2, 11
    # Environment 0 falls off on its 4th move and is reset at once; 1 keeps walking.
    plans = [[LOOKRIGHT, FORWARD, FORWARD, FORWARD, FORWARD], [FORWARD, LOOKLEFT, FORWARD, LOOKRIGHT, FORWARD]]
    env = psxrl.AsyncVecEnv(k, batch_size=1, threads=2, obs="simple")
    assert (env.num_envs, env.batch_size, env.threads) == (k, 1, 2)
    env.reset(1, seed)
    got = [[] for _ in range(k)]  # (observation, reward, terminated, truncated) in the order returned
    sent, finished = [0] * k, set()
    while len(finished) < k:
        obs, rewards, terminated, truncated, infos, ids = env.recv()
        i = int(ids[0])
        got[i].append((obs[0].copy(), rewards[0], terminated[0], truncated[0]))
        if not any(got[1 - i]):
            with pytest.raises(ValueError, match="in flight"):
                env.send([FORWARD], [1 - i])  # the other environment is still out
        if sent[i] == len(plans[i]):
            finished.add(i)
            continue
        env.send([plans[i][sent[i]]], [i])
        sent[i] += 1
    for i in range(k):
        single = psxrl.Env(obs="simple")
        episode = 0
        expected = [(single.reset(1, psxrl.episode_seed(seed, i, 0))[0], 0.0, False, False)]
        for a in plans[i]:
            o, r, term, trunc, _ = single.step(a)
            if term or trunc:
                episode += 1
                o, _ = single.reset(1, psxrl.episode_seed(seed, i, episode))
            expected.append((o, r, term, trunc))
        assert len(got[i]) == len(expected)
        for (go, gr, gterm, gtrunc), (eo, er, eterm, etrunc) in zip(got[i], expected):
            assert np.array_equal(go, eo) and (gr, gterm, gtrunc) == (er, eterm, etrunc)
    assert episode == 0 and any(e[2] for e in got[0])  # environment 0's episode ended and was reset


def test_gl_renderer_scales_the_screen_but_not_the_observations():
    """renderer='gl', scale=2 (docs/renderer.md): get_screen() is 480x640, the visual
    observations and rewards are the software renderer's, move for move."""
    sw = psxrl.Env(obs="visual")
    gl = psxrl.Env(obs="visual", renderer="gl", scale=2)
    obs_sw, _ = sw.reset(1, 7)
    obs_gl, _ = gl.reset(1, 7)
    assert np.array_equal(obs_sw, obs_gl)
    for action in (0, 1, 0, 3):
        a = sw.step(action)
        b = gl.step(action)
        assert np.array_equal(a[0], b[0])
        assert a[1:4] == b[1:4]
    assert sw.get_screen().shape == (240, 320, 3)
    assert gl.get_screen().shape == (480, 640, 3)
    with pytest.raises(ValueError, match="'software' or 'gl'"):
        psxrl.Env(obs="visual", renderer="vulkan")
