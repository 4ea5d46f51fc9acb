"""Consoles on Python threads: run calls release the GIL, so K consoles on K threads run in
parallel, and since each console is self-contained they give exactly what running them one by
one gives. Only equality is asserted; the timing is printed (pytest -s), not tested."""
import threading
import time

import numpy as np

import psxrl
from conftest import boot_tumble, start_level


def play(c, level):
    """Level `level` with a fixed input pattern; returns RAM, screen and audio at the end."""
    start_level(c, level)
    c.take_audio()
    for i, button in enumerate(["right", "up", "left", "up"]):
        c.press_for(button, 2)
        c.run_frames(25 + i)
    return bytes(c.ram()), c.get_screen().copy(), c.take_audio()


def test_threads_equal_sequential_runs():
    k = 2
    levels = [1, 2]
    t0 = time.perf_counter()
    sequential = [play(boot_tumble(), levels[i]) for i in range(k)]
    t_seq = time.perf_counter() - t0

    threaded = [None] * k
    errors = []

    def worker(i):
        try:
            threaded[i] = play(boot_tumble(), levels[i])
        except Exception as e:  # surfaced below; a thread's exception would otherwise be lost
            errors.append(e)

    t0 = time.perf_counter()
    threads = [threading.Thread(target=worker, args=(i,)) for i in range(k)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    t_par = time.perf_counter() - t0
    assert not errors
    for (ram_a, screen_a, audio_a), (ram_b, screen_b, audio_b) in zip(sequential, threaded):
        assert ram_a == ram_b and np.array_equal(screen_a, screen_b) and np.array_equal(audio_a, audio_b)
    assert sequential[0][0] != sequential[1][0]  # two different levels: the comparison has teeth
    print(f"\n{k} consoles: one by one {t_seq:.2f} s, on {k} threads {t_par:.2f} s")


def test_vec_env_threads_do_not_change_results():
    actions = np.array([[0, 1], [1, 0], [0, 0], [3, 2]])
    results = []
    for threads in (1, 2):
        vec = psxrl.VecEnv(2, threads=threads, obs="local")
        obs = [vec.reset(1, 3).copy()]
        for a in actions:
            obs.append(vec.step(a)[0].copy())
        results.append(np.stack(obs))
    assert np.array_equal(results[0], results[1])
