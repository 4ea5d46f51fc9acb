"""RLlib on psxrl: the Gymnasium environments registered with Ray Tune's registry (so every env
runner, on any node, builds them by name), and a PPO configuration with its env runners spread
over the cluster's workers.

    from psxrl.ray.rllib import ppo_config
    algo = ppo_config(env_runners=2, env_config={"obs": "local"}).build_algo()
    print(algo.train()["env_runners"]["episode_return_mean"])
"""
from ray.tune.registry import register_env

TUMBLE = "psxrl/Tumble-v0"
KULA = "psxrl/Kula-v0"


def _tumble(env_config):
    from psxrl.gym_envs import TumbleEnv

    return TumbleEnv(**env_config)


def _kula(env_config):
    from psxrl.gym_envs import KulaEnv

    return KulaEnv(**env_config)


def register():
    """Registers psxrl/Tumble-v0 and psxrl/Kula-v0 with Ray; env_config holds the environments'
    keyword arguments (obs, reward, gamma, max_moves, level, ...)."""
    register_env(TUMBLE, _tumble)
    register_env(KULA, _kula)


def ppo_config(env=TUMBLE, env_runners=2, envs_per_env_runner=1, cpus_per_env_runner=1, env_config=None,
               **training):
    """A PPOConfig (RLlib's new API stack, PyTorch) for a psxrl environment: `env_runners` Ray
    actors of `cpus_per_env_runner` CPUs each sample it in parallel (Ray places them on whichever
    nodes have those CPUs free), the learner updates in this process. `env_config` defaults to the
    agent-local observation (obs="local"); `training` goes to PPOConfig.training()."""
    from ray.rllib.algorithms.ppo import PPOConfig

    register()
    settings = {"train_batch_size_per_learner": 400, "minibatch_size": 100, "num_epochs": 4, **training}
    return (PPOConfig()
            .environment(env, env_config={"obs": "local", **(env_config or {})})
            .framework("torch")
            .env_runners(num_env_runners=env_runners, num_envs_per_env_runner=envs_per_env_runner,
                         num_cpus_per_env_runner=cpus_per_env_runner)
            .training(**settings))
