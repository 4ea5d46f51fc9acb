"""Distributed rollouts: psxrl environments hosted by Ray actors, stepped in batches by a learner
in another process or on another machine.

Each `RolloutWorker` actor owns a `psxrl.VecEnv` (or an `AsyncVecEnv`) of several consoles. A call
moves only NumPy arrays: actions in; observations, rewards and flags out, and the per-environment
infos as one structured array (`INFO_DTYPE`), so Ray ships buffers, not pickled Python objects
per step. `RayVecEnv` joins the workers into one batch of `workers * envs_per_worker` environments;
worker w's environments are the rows w*k .. w*k+k-1 and behave exactly as a local
`VecEnv(k).reset(level, seeds[w])` would.
"""
import numpy as np
import ray

OUTCOMES = {"": 0, "win": 1, "lose": -1}
INFO_DTYPE = np.dtype([("game_frames", np.uint64), ("score", np.int64), ("time_left", np.float64),
                       ("state", np.int64), ("level", np.int32), ("hit_upper_bound", np.bool_),
                       ("moves", np.uint32), ("episode_reward", np.float64), ("outcome", np.int8)])


def info_array(infos):
    """The C++ infos (a list of dicts) as one structured array; `outcome` is 1 win, -1 lose, 0 running.
    Host time (`real_seconds`) is left out: it is the one field that differs between runs."""
    out = np.zeros(len(infos), INFO_DTYPE)
    for i, info in enumerate(infos):
        out[i] = tuple(OUTCOMES[info[k]] if k == "outcome" else info[k] for k in INFO_DTYPE.names)
    return out


def _stack(parts):
    if isinstance(parts[0], dict):  # multimodal observations: a dict of arrays
        return {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}
    return np.concatenate(parts)


@ray.remote
class RolloutWorker:
    """One Ray actor: `num_envs` consoles in a VecEnv (`asynchronous=False`) or an AsyncVecEnv."""

    def __init__(self, num_envs, asynchronous=False, batch_size=0, threads=0, **config):
        import psxrl

        if asynchronous:
            self.env = psxrl.AsyncVecEnv(num_envs, batch_size, threads, **config)
        else:
            self.env = psxrl.VecEnv(num_envs, threads, **config)

    def spaces(self):
        return self.env.observation_spaces, self.env.action_count

    def reset(self, level, seed):
        """VecEnv: the first observations. AsyncVecEnv: starts every environment (recv() them)."""
        return self.env.reset(level, seed)

    def step(self, actions):
        """(obs, rewards, terminated, truncated, info array, final observations or None): the
        final observations are the last ones of the episodes that ended, in the rows that ended."""
        obs, rewards, terminated, truncated, infos = self.env.step(actions)
        final = self.env.final_observation() if (terminated | truncated).any() else None
        return obs, rewards, terminated, truncated, info_array(infos), final

    def send(self, actions, env_ids):
        self.env.send(actions, env_ids)

    def recv(self):
        """AsyncVecEnv: the next batch as (obs, rewards, terminated, truncated, info array, env_ids)."""
        obs, rewards, terminated, truncated, infos, env_ids = self.env.recv()
        return obs, rewards, terminated, truncated, info_array(infos), env_ids

    def ping(self, actions):
        """The actor hop alone (the benchmark's overhead figure): actions in, same-sized arrays out."""
        return actions

    def cpu_seconds(self):
        """CPU time of this worker process so far, all its threads (the benchmark's cost figure)."""
        import time

        return time.process_time()


class RayVecEnv:
    """`workers` RolloutWorker actors of `envs_per_worker` environments each, stepped as one batch:
    `step()` sends every worker its slice of the actions, then gathers all the results."""

    def __init__(self, workers, envs_per_worker, threads=0, actor_options=None, **config):
        options = actor_options or {}
        self.workers = [RolloutWorker.options(**options).remote(envs_per_worker, threads=threads, **config)
                        for _ in range(workers)]
        self.envs_per_worker = envs_per_worker
        self.num_envs = workers * envs_per_worker
        self.observation_spaces, self.action_count = ray.get(self.workers[0].spaces.remote())

    def reset(self, level=1, seeds=None):
        """Worker w resets with `seeds[w]` (default: w); its environment i then uses
        psxrl.episode_seed(seeds[w], i, k) for its k-th episode, as in a local VecEnv."""
        seeds = list(range(len(self.workers))) if seeds is None else list(seeds)
        if len(seeds) != len(self.workers):
            raise ValueError(f"reset needs one seed per worker ({len(self.workers)}), got {len(seeds)}")
        return _stack(ray.get([w.reset.remote(level, s) for w, s in zip(self.workers, seeds)]))

    def step(self, actions):
        """Actions for all `num_envs` environments -> (obs, rewards, terminated, truncated, infos,
        final_obs), each batched over all environments; `final_obs` rows are valid where an episode
        ended (the C++ side already reset those environments), None if none ended."""
        actions = np.ascontiguousarray(actions, dtype=np.int32)
        if actions.shape != (self.num_envs,):
            raise ValueError(f"step needs {self.num_envs} actions, got shape {actions.shape}")
        k = self.envs_per_worker
        parts = ray.get([w.step.remote(actions[i * k:(i + 1) * k]) for i, w in enumerate(self.workers)])
        obs, rewards, terminated, truncated, infos, finals = zip(*parts)
        final = None
        if any(f is not None for f in finals):
            final = _stack([f if f is not None else o for f, o in zip(finals, obs)])
        return (_stack(obs), np.concatenate(rewards), np.concatenate(terminated), np.concatenate(truncated),
                np.concatenate(infos), final)

    def close(self):
        for w in self.workers:
            ray.kill(w)
        self.workers = []


class RayAsyncVecEnv:
    """`workers` actors each hosting an AsyncVecEnv of `envs_per_worker` environments (batches of
    `batch_size`), driven EnvPool-style: `recv()` returns the first worker batch ready, with global
    environment ids (worker w's environment i is id w*envs_per_worker + i); `send()` takes actions
    for any of them. Each environment's trajectory is deterministic; the order of batches is not."""

    def __init__(self, workers, envs_per_worker, batch_size=0, threads=0, actor_options=None, **config):
        options = actor_options or {}
        self.workers = [RolloutWorker.options(**options).remote(envs_per_worker, asynchronous=True,
                                                                batch_size=batch_size, threads=threads, **config)
                        for _ in range(workers)]
        self.envs_per_worker = envs_per_worker
        self.num_envs = workers * envs_per_worker
        self.observation_spaces, self.action_count = ray.get(self.workers[0].spaces.remote())
        self._waiting = {}  # an outstanding recv() per worker: ObjectRef -> worker index

    def reset(self, level=1, seeds=None):
        seeds = list(range(len(self.workers))) if seeds is None else list(seeds)
        ray.get([w.reset.remote(level, s) for w, s in zip(self.workers, seeds)])
        self._waiting = {w.recv.remote(): i for i, w in enumerate(self.workers)}

    def recv(self):
        [ref], _ = ray.wait(list(self._waiting), num_returns=1)
        worker = self._waiting.pop(ref)
        obs, rewards, terminated, truncated, infos, env_ids = ray.get(ref)
        return obs, rewards, terminated, truncated, infos, env_ids + worker * self.envs_per_worker

    def send(self, actions, env_ids):
        actions = np.asarray(actions, dtype=np.int32)
        env_ids = np.asarray(env_ids, dtype=np.int32)
        owners = env_ids // self.envs_per_worker
        for w in np.unique(owners):
            mine = owners == w
            worker = self.workers[w]
            worker.send.remote(actions[mine], env_ids[mine] - w * self.envs_per_worker)
            if int(w) not in self._waiting.values():  # actor calls run in order: after this send
                self._waiting[worker.recv.remote()] = int(w)

    def close(self):
        for w in self.workers:
            ray.kill(w)
        self.workers = []
