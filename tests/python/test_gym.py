"""The Gymnasium front: registered ids, check_env for every observation kind, equality with
psxrl.Env for the same seed, and the vector env against K single environments."""
import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env
from gymnasium.vector import AutoresetMode

import psxrl

OBS_KINDS = ["simple", "local", "visual", "audio", "episode", "ram", "rumble", "multimodal"]
FORWARD, LOOKRIGHT, LOOKLEFT, JUMPFORWARD = range(4)
# Level 1 (games/tumble/levels/level01.txt): east from the start, the third FORWARD leaves the map.
FALL_OFF = [LOOKRIGHT, FORWARD, FORWARD, FORWARD]


def test_ids_are_registered_on_import():
    assert "psxrl/Tumble-v0" in gym.registry and "psxrl/Kula-v0" in gym.registry
    with pytest.raises(psxrl.InputError, match="BIOS"):
        gym.make("psxrl/Kula-v0")  # Kula World needs the user's disc and BIOS


@pytest.mark.parametrize("obs", OBS_KINDS)
def test_check_env(obs, display):
    # display: check_env also renders in every mode of metadata["render_modes"], "human" included.
    env = gym.make("psxrl/Tumble-v0", obs=obs, render_mode="rgb_array").unwrapped
    check_env(env, skip_render_check=False)
    expected = gym.spaces.Dict if obs == "multimodal" else gym.spaces.Box
    assert isinstance(env.observation_space, expected) and env.action_space == gym.spaces.Discrete(4)


def test_render_rgb_array():
    env = gym.make("psxrl/Tumble-v0", render_mode="rgb_array")
    env.reset(seed=1)
    frame = env.render()
    assert frame.shape == (240, 320, 3) and frame.dtype == np.uint8


def test_gymnasium_episode_equals_the_cpp_env():
    env = gym.make("psxrl/Tumble-v0", obs="local", gamma=0.8)
    ref = psxrl.Env(obs="local", gamma=0.8)
    obs, info = env.reset(seed=1234, options={"level": 2})
    ref_obs, ref_info = ref.reset(level=2, seed=1234)
    assert np.array_equal(obs, ref_obs) and info["level"] == ref_info["level"] == 2
    for action in [FORWARD, LOOKLEFT, FORWARD, JUMPFORWARD, LOOKRIGHT, LOOKRIGHT, FORWARD, FORWARD, FORWARD, FORWARD]:
        obs, reward, terminated, truncated, info = env.step(action)
        r_obs, r_reward, r_terminated, r_truncated, r_info = ref.step(action)
        assert np.array_equal(obs, r_obs) and reward == r_reward
        assert (terminated, truncated) == (r_terminated, r_truncated)
        assert {k: v for k, v in info.items() if k != "real_seconds"} == {
            k: v for k, v in r_info.items() if k != "real_seconds"}
        if terminated or truncated:
            break


def test_make_vec_equals_single_envs_with_same_step_autoreset():
    k, seed = 2, 99
    venv = psxrl.make_vec("psxrl/Tumble-v0", num_envs=k, obs="simple")
    assert venv.metadata["autoreset_mode"] == AutoresetMode.SAME_STEP
    assert venv.num_envs == k and venv.single_action_space == gym.spaces.Discrete(4)
    singles = [psxrl.Env(obs="simple") for _ in range(k)]
    episodes = [0] * k
    obs, _ = venv.reset(seed=seed)
    for i, s in enumerate(singles):
        assert np.array_equal(obs[i], s.reset(1, psxrl.episode_seed(seed, i, 0))[0])
    plans = [FALL_OFF + [FORWARD], [FORWARD, LOOKLEFT, LOOKRIGHT, LOOKRIGHT, FORWARD]]
    for t in range(len(plans[0])):
        obs, rewards, terminated, truncated, info = venv.step(np.array([p[t] for p in plans]))
        assert obs in venv.observation_space
        for i, s in enumerate(singles):
            o, r, term, trunc, single_info = s.step(plans[i][t])
            assert rewards[i] == r and terminated[i] == term and truncated[i] == trunc
            if term or trunc:
                assert info["_final_obs"][i] and np.array_equal(info["final_obs"][i], o)
                assert info["final_info"]["outcome"][i] == single_info["outcome"] == "lose"
                episodes[i] += 1
                o, _ = s.reset(1, psxrl.episode_seed(seed, i, episodes[i]))
            else:
                assert info["score"][i] == single_info["score"]
            assert np.array_equal(obs[i], o)
    assert episodes == [1, 0]
    venv.close()


def test_vector_reset_seeding():
    venv = psxrl.make_vec("psxrl/Tumble-v0", num_envs=2, obs="episode")
    a, _ = venv.reset(seed=5)
    b, _ = venv.reset(seed=5)
    assert np.array_equal(a, b)
    with pytest.raises(TypeError):
        venv.reset(seed=[1, 2])
