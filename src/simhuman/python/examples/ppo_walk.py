#!/usr/bin/env python3
"""A short PPO in Python (Debian's python3-torch) on simhuman's walk task.

    PYTHONPATH=build/python /usr/bin/python3 src/simhuman/python/examples/ppo_walk.py --minutes 5

Prints one line per iteration: env steps, the mean return of the episodes that finished in the
last iterations, the mean reward per step and the throughput. From scratch the return rises in
the first minutes (the walker learns to stay up and lean towards its target); a walker like
assets/policies/walk.pt takes `simhuman train` about an hour. The C++ trainer (`simhuman
train`) is the fast path; this file shows the Python loop a researcher would start from.
"""

import argparse
import collections
import time

import numpy as np
import torch

import simhuman
from simhuman.policy import GaussianPolicy


class RunningNorm:
    """Running mean and variance of observations (merged per batch, float64)."""

    def __init__(self, dim):
        self.mean, self.var, self.count = np.zeros(dim), np.ones(dim), 1e-4

    def update(self, x):
        m, v, n = x.mean(0), x.var(0), x.shape[0]
        delta, total = m - self.mean, self.count + n
        self.mean = self.mean + delta * n / total
        self.var = (self.var * self.count + v * n + delta ** 2 * self.count * n / total) / total
        self.count = total


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--task", default="walk")
    ap.add_argument("--minutes", type=float, default=5.0)
    ap.add_argument("--envs", type=int, default=64)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--horizon", type=int, default=32, help="steps per env per iteration")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--torch-threads", type=int, default=1,
                    help="1: OpenMP threads that spin between ops would take the cores from the "
                    "env's C++ workers (7x slower with 2 on a loaded 2-core machine)")
    ap.add_argument("--save", default="", help="write the policy's state_dict here")
    args = ap.parse_args()

    torch.manual_seed(args.seed)
    torch.set_num_threads(args.torch_threads)
    envs = simhuman.vector.make(args.task, num_envs=args.envs, threads=args.threads,
                                seed=args.seed, physics_solver="pgs" if args.task == "walk"
                                else "newton")
    obs_dim = envs.single_observation_space.shape[0]
    act_dim = envs.single_action_space.shape[0]
    limit = float(envs.single_action_space.high[0])
    used = torch.as_tensor(envs.action_used)  # unused entries stay out of log-probs and entropy
    hidden = [256, 128] if args.task == "walk" else [64, 64]
    actor = GaussianPolicy(obs_dim, act_dim, hidden)
    critic = torch.nn.Sequential(torch.nn.Linear(obs_dim, 256), torch.nn.ELU(),
                                 torch.nn.Linear(256, 256), torch.nn.ELU(),
                                 torch.nn.Linear(256, 1))
    opt = torch.optim.Adam(list(actor.parameters()) + list(critic.parameters()), lr=3e-4)
    norm = RunningNorm(obs_dim)
    gamma, lam, clip, epochs, minibatch = 0.99, 0.95, 0.2, 4, 512
    E, T = args.envs, args.horizon

    def normalized(o):
        return torch.as_tensor(np.clip((o - norm.mean) / np.sqrt(norm.var + 1e-8), -5, 5),
                               dtype=torch.float32)

    def log_prob(mean, std, a):
        lp = -0.5 * ((a - mean) / std) ** 2 - torch.log(std) - 0.5 * np.log(2 * np.pi)
        return (lp * used).sum(-1)

    obs, _ = envs.reset(seed=args.seed)
    obs = obs.copy()
    recent = collections.deque(maxlen=200)
    start, steps, it = time.time(), 0, 0
    while time.time() - start < 60 * args.minutes:
        it += 1
        b_obs = np.zeros((T, E, obs_dim), np.float32)
        b_act = torch.zeros(T, E, act_dim)
        b_logp, b_val = torch.zeros(T, E), torch.zeros(T + 1, E)
        b_rew, b_done = torch.zeros(T, E), torch.zeros(T, E)
        b_boot = torch.zeros(T, E)  # value of the final obs where the time limit cut an episode
        for t in range(T):
            b_obs[t] = obs
            with torch.no_grad():
                x = normalized(obs)
                mean, std = actor.net(x), actor.std()
                a = mean + std * torch.randn_like(mean)
                b_act[t], b_logp[t], b_val[t] = a, log_prob(mean, std, a), critic(x)[:, 0]
            obs, rew, term, trunc, info = envs.step(a.clamp(-limit, limit).numpy())
            obs = obs.copy()
            b_rew[t] = torch.as_tensor(rew)
            b_done[t] = torch.as_tensor(term | trunc, dtype=torch.float32)
            if trunc.any():
                with torch.no_grad():
                    v = critic(normalized(info["final_obs"]))[:, 0]
                b_boot[t] = torch.where(torch.as_tensor(trunc), v, torch.zeros(E))
            if "episode" in info:
                recent.extend(info["episode"]["r"][info["_episode"]].tolist())
        with torch.no_grad():
            b_val[T] = critic(normalized(obs))[:, 0]
        norm.update(b_obs.reshape(-1, obs_dim))
        steps += T * E

        # generalized advantage estimation, bootstrapping truncated episodes
        adv, last = torch.zeros(T, E), torch.zeros(E)
        for t in reversed(range(T)):
            nonterminal = 1.0 - b_done[t]
            next_v = b_val[t + 1] * nonterminal + b_boot[t]
            delta = b_rew[t] + gamma * next_v - b_val[t]
            last = delta + gamma * lam * nonterminal * last
            adv[t] = last
        ret = (adv + b_val[:T]).reshape(-1)
        x_all = normalized(b_obs.reshape(-1, obs_dim))
        a_all, lp_all = b_act.reshape(-1, act_dim), b_logp.reshape(-1)
        adv = adv.reshape(-1)
        adv = (adv - adv.mean()) / (adv.std() + 1e-8)
        for _ in range(epochs):
            for idx in torch.randperm(T * E).split(minibatch):
                mean, std = actor.net(x_all[idx]), actor.std()
                ratio = torch.exp(log_prob(mean, std, a_all[idx]) - lp_all[idx])
                pg = -torch.min(ratio * adv[idx], ratio.clamp(1 - clip, 1 + clip) * adv[idx])
                v_loss = 0.5 * (critic(x_all[idx])[:, 0] - ret[idx]).pow(2)
                entropy = (torch.log(std) * used).sum()
                loss = pg.mean() + v_loss.mean() - 1e-3 * entropy
                opt.zero_grad()
                loss.backward()
                torch.nn.utils.clip_grad_norm_(list(actor.parameters()) + list(critic.parameters()),
                                               1.0)
                opt.step()
        elapsed = time.time() - start
        mean_ret = f"{np.mean(recent):8.2f}" if recent else "     n/a"
        print(f"iter {it:4d}  steps {steps:8d}  episode return {mean_ret}  "
              f"reward/step {b_rew.mean():.3f}  {steps / elapsed:6.0f} steps/s  "
              f"{elapsed:5.0f} s", flush=True)
    if args.save:
        actor.obs_mean.copy_(torch.as_tensor(norm.mean))
        actor.obs_var.copy_(torch.as_tensor(norm.var))
        torch.save(actor.state_dict(), args.save)
        print(f"wrote {args.save}")
    envs.close()


if __name__ == "__main__":
    main()
