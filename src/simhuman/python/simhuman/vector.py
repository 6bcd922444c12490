"""A vectorized environment with Gymnasium's vector API over simhuman's C++ ``VecEnv``.

    envs = simhuman.vector.make("walk", num_envs=128, threads=2)
    obs, info = envs.reset(seed=42)
    for _ in range(1000):
        obs, reward, terminated, truncated, info = envs.step(envs.action_space.sample())
    envs.close()

The C++ worker threads step the envs with the GIL released. Observations, rewards and flags
are numpy views of the C++ buffers: no copy per step, and each step overwrites them in place
(pass ``copy=True`` to get fresh arrays instead, or copy what you keep).

Episodes reset automatically in the step that ends them (Gymnasium's "same-step" autoreset):
``obs`` then holds the new episode's first observation and ``info["final_obs"]`` (also under
Gymnasium 0.29's name ``"final_observation"``) the last observation of the episode that ended,
valid where ``info["_final_obs"]`` is True. ``info["episode"]`` holds the finished episodes'
return ``r``, length ``l`` and ``success``, valid where ``info["_episode"]`` is True (the format
of Gymnasium's RecordEpisodeStatistics), and ``info["final_info"]`` the same per env as dicts
(None where no episode ended; Gymnasium 0.29's form, as CleanRL reads it). Steps where no
episode ends return ``info == {}``.
"""

import operator

import numpy as np

from simhuman import _native
from simhuman.spaces import Box


class VectorEnv:
    """``num_envs`` copies of a training task with the Gymnasium ``VectorEnv`` interface.

    Args:
        task: "walk" (the humanoid walks to a target and stops facing a heading; 116 obs,
            28 actions clipped to +-3) or "reach" (a toy 2-D point mass).
        num_envs: parallel environments.
        threads: C++ worker threads stepping them.
        seed: seed of the episodes (reset(seed=...) replaces it).
        physics_solver: MuJoCo solver of the walk task, "newton" (as the runner) or "pgs".
        walk_gait: the walk task's reference gait, "" (the original) or "human"; a policy
            runs in the env of the gait it was trained with (``load_policy(...).walk_gait``).
        copy: return copies instead of views of the C++ buffers.
    """

    metadata = {"render_modes": [], "autoreset_mode": "SameStep"}
    render_mode = None
    spec = None

    def __init__(self, task="walk", num_envs=128, threads=2, seed=1, physics_solver="newton",
                 copy=False, walk_gait=""):
        self._env = _native.VecEnv(task, num_envs, threads, seed, physics_solver, walk_gait)
        self._copy = bool(copy)
        self._views = self._env.views()
        self._closed = False
        self.num_envs = self._env.num_envs
        limit = self._env.action_limit
        self.single_observation_space = Box(-np.inf, np.inf, (self._env.obs_dim,), np.float32)
        self.single_action_space = Box(-limit, limit, (self._env.act_dim,), np.float32)
        self.observation_space = Box(-np.inf, np.inf, (self.num_envs, self._env.obs_dim),
                                     np.float32)
        self.action_space = Box(-limit, limit, (self.num_envs, self._env.act_dim), np.float32)
        self._np_random = np.random.default_rng(seed)

    @property
    def task(self):
        """The task's name, e.g. "walk"."""
        return self._env.task

    @property
    def unwrapped(self):
        return self

    @property
    def np_random(self):
        """A numpy Generator for the caller's own use (seeded by reset(seed=...))."""
        return self._np_random

    @property
    def action_used(self):
        """Boolean mask [act_dim]: the entries the task uses (walk ignores the arm entries)."""
        return np.array(self._env.action_used, dtype=bool)

    @property
    def curriculum(self):
        """The task's curriculum level in [0, 1] (walk: how far targets turn away)."""
        return self._env.curriculum

    @curriculum.setter
    def curriculum(self, level):
        self._env.curriculum = float(level)

    def _out(self, name):
        a = self._views[name]
        return a.copy() if self._copy else a

    def reset(self, *, seed=None, options=None):
        """Starts new episodes in every env; returns (obs [num_envs, obs_dim], info {}).

        With ``seed`` the episodes are those of that seed (the same seed gives the same
        episodes, whatever the thread count); without, the episodes continue the sequence.
        ``options`` is accepted for API compatibility; it must be None or empty."""
        self._check_open()
        if options:
            raise ValueError(f"reset: options are not supported, got {sorted(options)}")
        if seed is not None:
            seed = operator.index(seed)  # Python or numpy integers
        self._env.reset(seed)
        if seed is not None:
            self._np_random = np.random.default_rng(seed)
        return self._out("obs"), {}

    def step(self, actions):
        """Steps every env; returns (obs, reward, terminated, truncated, info).

        ``actions`` is an array [num_envs, act_dim] of floats (float32 avoids a conversion);
        a wrong shape or a non-float dtype raises ValueError naming the expected shape."""
        self._check_open()
        self._env.step(actions)
        v = self._views
        terminated, truncated = self._out("terminated"), self._out("truncated")
        info = {}
        ended = v["terminated"] | v["truncated"]
        if ended.any():
            final_obs = v["final_obs"].copy() if self._copy else v["final_obs"]
            stats = self._env.episode_stats()
            r = np.zeros(self.num_envs, dtype=np.float64)
            length = np.zeros(self.num_envs, dtype=np.int64)
            success = np.zeros(self.num_envs, dtype=bool)
            r[ended], length[ended], success[ended] = stats["r"], stats["l"], stats["success"]
            # Gymnasium 0.29's per-env form, as CleanRL reads it: None where no episode ended
            final_info = np.full(self.num_envs, None, dtype=object)
            for i in np.flatnonzero(ended):
                final_info[i] = {"episode": {"r": np.array([r[i]]), "l": np.array([length[i]])},
                                 "success": bool(success[i])}
            info = {
                "final_obs": final_obs, "_final_obs": ended,
                "final_info": final_info, "_final_info": ended,
                "final_observation": final_obs, "_final_observation": ended,
                "episode": {"r": r, "l": length, "success": success,
                            "_r": ended, "_l": ended, "_success": ended},
                "_episode": ended,
            }
        return self._out("obs"), self._out("rewards"), terminated, truncated, info

    def close(self):
        """Frees the envs and their threads (further calls raise)."""
        if not self._closed:
            self._views = None
            self._env = None
            self._closed = True

    def _check_open(self):
        if self._closed:
            raise RuntimeError("the environment is closed")

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def __repr__(self):
        if self._closed:
            return "VectorEnv(closed)"
        return (f"VectorEnv({self.task!r}, num_envs={self.num_envs}, "
                f"obs {self.single_observation_space.shape}, "
                f"actions {self.single_action_space.shape})")


def make(task="walk", num_envs=128, threads=2, seed=1, physics_solver="newton", copy=False,
         walk_gait=""):
    """A ``VectorEnv`` of ``task`` (see VectorEnv for the arguments)."""
    return VectorEnv(task, num_envs=num_envs, threads=threads, seed=seed,
                     physics_solver=physics_solver, copy=copy, walk_gait=walk_gait)
