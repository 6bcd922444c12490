#!/usr/bin/env python3
"""Drives the walk env with the shipped policy (assets/policies/walk.pt) loaded in PyTorch, and
with random actions for comparison.

    PYTHONPATH=build/python /usr/bin/python3 src/simhuman/python/examples/walk_policy.py
"""

import argparse
import os

import numpy as np

import simhuman
from simhuman.policy import load_policy

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "..", ".."))


def drive(act, walk_gait="", envs=32, seconds=25.0, seed=1):
    """Returns (episodes finished, successes, falls, mean return of finished episodes)."""
    e = simhuman.vector.make("walk", num_envs=envs, threads=2, seed=seed, walk_gait=walk_gait)
    obs, _ = e.reset(seed=seed)
    finished, success, falls, returns = 0, 0, 0, []
    for _ in range(int(seconds * 30)):  # the policy runs at 30 Hz
        obs, _, terminated, _, info = e.step(act(obs))
        falls += int(terminated.sum())
        if "episode" in info:
            mask = info["_episode"]
            finished += int(mask.sum())
            success += int(info["episode"]["success"][mask].sum())
            returns += info["episode"]["r"][mask].tolist()
    e.close()
    return finished, success, falls, (np.mean(returns) if returns else float("nan"))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--policy", default=os.path.join(ROOT, "assets", "policies", "walk.pt"))
    ap.add_argument("--seconds", type=float, default=25.0)
    args = ap.parse_args()
    policy = load_policy(args.policy)
    rng = np.random.default_rng(0)
    for name, act in [("walk.pt", policy.act),
                      ("random", lambda o: rng.uniform(-3, 3, (len(o), 28)).astype(np.float32))]:
        n, s, f, r = drive(act, walk_gait=policy.walk_gait, seconds=args.seconds)
        print(f"{name:8s}: 32 walkers for {args.seconds:.0f} s: falls {f}, episodes ended {n}, "
              f"successes {s}, mean return of ended episodes {r:.2f}")


if __name__ == "__main__":
    main()
