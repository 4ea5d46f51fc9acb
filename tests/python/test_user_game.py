"""A user's own integration through Gymnasium (issue #62): a copy of Tumble's integration under
another name in a folder of the user's, loaded by psxrl.make_env / psxrl.make_vec with games_dir,
passes Gymnasium's check_env and plays the same as Tumble itself; an unknown name says where
games are looked for."""
import shutil
from pathlib import Path

import gymnasium as gym
import numpy as np
import pytest
from gymnasium.utils.env_checker import check_env

import psxrl
from conftest import tumble_exe

TUMBLE = Path(__file__).resolve().parents[2] / "games" / "tumble"
FORWARD, LOOKRIGHT = 0, 1


@pytest.fixture
def user_games(tmp_path):
    """mygames/rolling/: Tumble's manifest renamed, its script, maps and program beside it."""
    folder = tmp_path / "mygames" / "rolling"
    folder.mkdir(parents=True)
    manifest = (TUMBLE / "game.toml").read_text().replace('name = "tumble"', 'name = "rolling"', 1)
    assert 'name = "rolling"' in manifest
    (folder / "game.toml").write_text(manifest)
    shutil.copy(TUMBLE / "game.lua", folder / "game.lua")
    shutil.copytree(TUMBLE / "levels", folder / "levels")
    shutil.copy(tumble_exe(), folder / "tumble.exe")
    return tmp_path / "mygames"


@pytest.mark.parametrize("obs", ["visual", "local"])
def test_make_env_passes_check_env(user_games, obs, display):
    # display: check_env also renders in every mode of metadata["render_modes"], "human" included.
    env = psxrl.make_env(game="rolling", games_dir=user_games, obs=obs, render_mode="rgb_array")
    assert env.spec.id == "psxrl/Game-v0"
    check_env(env.unwrapped, skip_render_check=False)
    assert env.action_space == gym.spaces.Discrete(4)


def test_user_integration_plays_as_tumble(user_games):
    mine = psxrl.make_env(game="rolling", games_dir=user_games, obs="local")
    tumble = gym.make("psxrl/Tumble-v0", obs="local")
    a, _ = mine.reset(seed=7)
    b, _ = tumble.reset(seed=7)
    assert np.array_equal(a, b)
    for action in [LOOKRIGHT, FORWARD, FORWARD]:
        ra, rb = mine.step(action), tumble.step(action)
        assert np.array_equal(ra[0], rb[0]) and ra[1:4] == rb[1:4]


def test_make_vec_for_a_user_integration(user_games):
    venv = psxrl.make_vec(num_envs=2, game="rolling", games_dir=user_games, obs="episode")
    obs, _ = venv.reset(seed=3)
    assert obs.shape == (2, 3) and venv.single_action_space == gym.spaces.Discrete(4)
    obs, rewards, terminated, truncated, _ = venv.step(np.array([LOOKRIGHT, FORWARD]))
    assert obs in venv.observation_space and rewards.shape == (2,)
    venv.close()


def test_unknown_game_says_where_games_are_looked_for(user_games):
    with pytest.raises(psxrl.InputError, match=r"unknown game 'pong'.*looked for in .*mygames, which holds rolling"):
        psxrl.make_env(game="pong", games_dir=user_games)
