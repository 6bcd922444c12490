"""A rollout loop written against Gymnasium's vector API (as in Gymnasium's docs and CleanRL),
with nothing simhuman-specific below the construction: the test runs it unchanged on
simhuman.vector. Only the API surface is used, so it runs on any gymnasium.vector.VectorEnv.
"""

import numpy as np


def rollout(envs, num_steps=64, seed=42):
    """Random-action rollout with CleanRL-style buffers; returns the finished episodes' returns
    and the buffers."""
    obs_shape = envs.single_observation_space.shape
    act_shape = envs.single_action_space.shape
    obs_buf = np.zeros((num_steps, envs.num_envs) + obs_shape, dtype=np.float32)
    act_buf = np.zeros((num_steps, envs.num_envs) + act_shape, dtype=np.float32)
    rew_buf = np.zeros((num_steps, envs.num_envs), dtype=np.float32)
    done_buf = np.zeros((num_steps, envs.num_envs), dtype=np.float32)
    episode_returns, final_info_returns = [], []

    envs.action_space.seed(seed)
    next_obs, infos = envs.reset(seed=seed)
    for step in range(num_steps):
        obs_buf[step] = next_obs
        actions = envs.action_space.sample()
        actions = np.clip(actions, envs.single_action_space.low, envs.single_action_space.high)
        act_buf[step] = actions
        next_obs, rewards, terminations, truncations, infos = envs.step(actions)
        rew_buf[step] = rewards
        done_buf[step] = np.logical_or(terminations, truncations)
        if "final_obs" in infos:
            for idx in np.flatnonzero(infos["_final_obs"]):
                assert infos["final_obs"][idx].shape == obs_shape
        if "episode" in infos:
            for idx in np.flatnonzero(infos["_episode"]):
                episode_returns.append(float(infos["episode"]["r"][idx]))
        if "final_info" in infos:  # Gymnasium 0.29 / CleanRL style
            for info in infos["final_info"]:
                if info and "episode" in info:
                    assert info["episode"]["r"].shape == (1,)
                    final_info_returns.append(float(info["episode"]["r"][0]))
    envs.close()
    assert final_info_returns == episode_returns
    return episode_returns, obs_buf, act_buf, rew_buf, done_buf
