"""Robustness of the Python front (#61): two threads on one environment get a clear error and the
environment stays usable; close(); argument errors name the argument; environments pickle by
configuration and refuse to be copied; Gymnasium's checker passes on a machine without a display."""
import copy
import pickle
import threading
import time
import warnings

import gymnasium as gym
import numpy as np
import pytest

import psxrl
from conftest import STATE, boot_tumble

IN_USE = r"is in use by another thread"


def hammer(calls, rounds=40):
    """Runs `calls` (one callable per thread) `rounds` times each, all threads at once; returns the
    errors other than "in use" and how many calls were refused as in use."""
    refused, other = [], []
    start = threading.Barrier(len(calls))

    def worker(call):
        start.wait()
        for _ in range(rounds):
            try:
                call()
            except RuntimeError as e:
                (refused if "is in use by another thread" in str(e) else other).append(e)
            except Exception as e:  # anything else is a failure of the guard
                other.append(e)

    threads = [threading.Thread(target=worker, args=(c,)) for c in calls]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    return other, len(refused)


def test_console_refuses_a_second_thread_and_runs_on():
    c = boot_tumble()
    inside, go = threading.Event(), threading.Event()
    # The first thread is held inside run_until by its condition (a Python callback) until the
    # second thread has tried: deterministic.
    first = threading.Thread(target=lambda: c.run_until(lambda: inside.set() or go.wait() or True, 10))
    first.start()
    inside.wait()
    with pytest.raises(RuntimeError, match="Console " + IN_USE):
        c.run_frame()
    go.set()
    first.join()
    frames = c.frames
    c.run_frames(3)
    assert c.frames == frames + 3


def step_or_reset(env):
    _, _, terminated, truncated, _ = env.step(0)
    if terminated or truncated:
        env.reset(1, 1)


def test_env_from_two_threads_is_refused_and_stays_usable():
    env = psxrl.Env(max_moves=1000)
    env.reset(1, 1)
    other, refused = hammer([lambda: step_or_reset(env), lambda: step_or_reset(env)])
    assert other == []
    assert refused > 0  # each call releases the GIL, so the two threads meet
    obs, info = env.reset(1, 1)  # usable afterwards; no error blaming the game's files
    assert info["level"] == 1 and env.step(1)[4]["moves"] == 1


def test_observation_is_not_read_while_another_thread_steps():
    """step() holds the environment until its observation is copied, and observation() holds it too:
    a thread reading the observation while another steps is refused instead of copying a half-written
    array."""
    env = psxrl.Env(max_moves=1000)
    env.reset(1, 1)

    def read_often():
        for _ in range(50):
            env.observation()
            time.sleep(0)  # lets the stepping thread take the GIL and enter step()

    other, refused = hammer([lambda: step_or_reset(env), read_often], rounds=20)
    assert other == []
    assert refused > 0  # without the hold, observation() never meets the stepping thread
    assert env.observation().shape == env.observation_spaces[0]["shape"]


def test_vector_envs_from_two_threads_are_refused():
    vec = psxrl.VecEnv(2, threads=2)
    vec.reset(1, 1)
    other, refused = hammer([lambda: vec.step([0, 1]), lambda: vec.step([1, 0])], rounds=20)
    assert other == [] and refused > 0
    vec.reset(1, 2)
    assert vec.step([0, 0])[4][0]["moves"] == 1

    # reset() waits for the resets in flight, so the other thread's reset meets it.
    a = psxrl.AsyncVecEnv(2, batch_size=2, threads=2)
    other, refused = hammer([lambda: a.reset(1, 1), lambda: a.reset(1, 2)], rounds=10)
    assert other == [] and refused > 0
    a.reset(1, 3)
    assert sorted(a.recv()[5]) == [0, 1]


def test_close_releases_env_and_console():
    env = psxrl.Env()
    env.reset(1, 1)
    env.close()
    assert env.closed
    for call in (lambda: env.step(0), lambda: env.reset(1, 1), env.get_screen):
        with pytest.raises(RuntimeError, match="Env is closed"):
            call()
    env.close()  # twice is allowed

    c = boot_tumble()
    screen, ram = c.get_screen(), c.ram()
    c.close()
    assert c.closed
    with pytest.raises(RuntimeError, match="Console is closed"):
        c.run_frame()
    with pytest.raises(RuntimeError, match="Console is closed"):
        c.read32(STATE)
    # Views taken before close() keep their memory: reading them is safe.
    assert screen.shape[2] == 3 and int(np.asarray(ram).sum()) >= 0


def test_a_folder_where_a_state_file_is_expected_is_named(tmp_path):
    # It was libstdc++'s "basic_filebuf::underflow error reading the file: Is a directory".
    c = boot_tumble()
    with pytest.raises(psxrl.InputError, match="is a folder, expected a file"):
        c.load_state_file(str(tmp_path))
    c.run_frame()  # the console is unchanged and runs on


def test_gymnasium_refuses_to_step_after_close():
    env = gym.make("psxrl/Tumble-v0")
    env.reset(seed=0)
    env.close()
    with pytest.raises(RuntimeError, match="Env is closed"):
        env.step(0)


def test_argument_errors_name_the_argument():
    with pytest.raises(ValueError, match="max_moves"):
        psxrl.Env(max_moves=-1)
    with pytest.raises(TypeError, match="obs: expected a str, got int"):
        psxrl.Env(obs=3)
    with pytest.raises(TypeError, match="gamma: expected a number, got str"):
        psxrl.Env(gamma="0.9")
    env = psxrl.Env()
    with pytest.raises(ValueError, match="level"):
        env.reset(level=10**12)
    with pytest.raises(ValueError, match="seed"):
        env.reset(1, -1)
    env.reset(1, 1)
    with pytest.raises(TypeError, match="action: expected an int, got float"):
        env.step(1.5)
    with pytest.raises(TypeError, match="action: expected an int, got str"):
        env.step("FORWARD")
    with pytest.raises(IndexError, match="action 7"):
        env.step(7)
    assert env.step(np.int64(1))[4]["moves"] == 1  # NumPy integers are ints


def test_environments_pickle_by_configuration():
    env = psxrl.Env(max_moves=2, obs="local")
    again = pickle.loads(pickle.dumps(env))
    assert isinstance(again, psxrl.Env) and again.obs == "local"
    again.reset(1, 1)
    assert again.step(1)[3] is False and again.step(1)[3] is True  # its max_moves=2 came along
    vec = pickle.loads(pickle.dumps(psxrl.VecEnv(2, obs="episode")))
    assert vec.num_envs == 2 and vec.observation_spaces[0]["name"] == "episode"
    gym_env = pickle.loads(pickle.dumps(gym.make("psxrl/Tumble-v0", max_moves=3)))
    gym_env.reset(seed=1)
    assert gym_env.unwrapped.env.obs == "simple"


def test_a_copy_is_refused_pointing_at_save_states():
    env = psxrl.Env()
    for make_copy in (copy.copy, copy.deepcopy):
        with pytest.raises(TypeError, match="save states"):
            make_copy(env)
    with pytest.raises(TypeError, match="save states"):
        copy.deepcopy(gym.make("psxrl/Tumble-v0"))


def test_async_vector_env_ships_environments_with_the_spawn_method():
    # Each function returns an environment made here, so the environment itself is pickled (by
    # its configuration) into the spawned process, as Ray or SubprocVecEnv ship one.
    made = [gym.make("psxrl/Tumble-v0", max_moves=5) for _ in range(2)]
    envs = gym.vector.AsyncVectorEnv([lambda e=e: e for e in made], context="spawn")
    try:
        obs, _ = envs.reset(seed=1)
        assert obs.shape == (2, 1)
        obs, rewards, terminated, truncated, _ = envs.step(np.array([1, 2]))
        assert obs.shape == (2, 1) and rewards.shape == (2,)
    finally:
        envs.close()


def test_human_render_mode_without_a_display_warns_once_and_shows_nothing(monkeypatch):
    for name in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"):
        monkeypatch.delenv(name, raising=False)
    env = gym.make("psxrl/Tumble-v0", render_mode="human")
    with pytest.warns(RuntimeWarning, match="shows nothing: no display"):
        env.reset(seed=0)
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a second warning would fail here
        env.step(1)
        assert env.render() is None
    assert env.unwrapped.window is None
    env.close()


def test_check_env_passes_headless(monkeypatch):
    """Gymnasium's checker makes an environment for every render mode the metadata lists ("human"
    included): it must pass on a server without a display."""
    from gymnasium.utils.env_checker import check_env

    for name in ("DISPLAY", "WAYLAND_DISPLAY", "SDL_VIDEODRIVER"):
        monkeypatch.delenv(name, raising=False)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        check_env(gym.make("psxrl/Tumble-v0"))
