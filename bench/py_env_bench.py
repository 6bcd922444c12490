#!/usr/bin/env python3
"""Env steps/s of the walk task from Python vs the same loop in C++, in one run.

    PYTHONPATH=build/python /usr/bin/python3 bench/py_env_bench.py [--envs 128] [--threads 2]
        [--seconds 3] [--rounds 10]

The C++ loop is build/simhuman_vec_env_bench (VecEnv::Step with uniform random actions in the
action bounds); the Python loop is `envs.step(envs.action_space.sample())` on
simhuman.vector.make("walk"). The two alternate in short slices for --rounds rounds so both see
the same machine load; printed as JSON (docs/BENCHMARKS.md): the per-round rates, the mean rates
and their ratio, and the median of the per-round ratios.
"""

import argparse
import json
import os
import statistics
import subprocess
import time

import simhuman

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))


class TimedNative:
    """Delegates to the native VecEnv, adding up the seconds spent in its step()."""

    def __init__(self, native):
        self.native, self.seconds = native, 0.0

    def step(self, actions):
        t = time.perf_counter()
        self.native.step(actions)
        self.seconds += time.perf_counter() - t

    def __getattr__(self, name):
        return getattr(self.native, name)


def python_loop(envs, threads, seconds, solver, overhead):
    """Env steps/s of the Python loop; appends to `overhead` the share of its time spent
    outside the C++ step (sampling, checks, info dicts), which machine load hardly moves."""
    e = simhuman.vector.make("walk", num_envs=envs, threads=threads, seed=1,
                             physics_solver=solver)
    timed = e._env = TimedNative(e._env)
    e.reset(seed=1)
    e.action_space.seed(7)
    for _ in range(5):  # warm-up, as the C++ loop
        e.step(e.action_space.sample())
    timed.seconds = 0.0
    steps, t0 = 0, time.perf_counter()
    elapsed = 0.0
    while elapsed < seconds:
        e.step(e.action_space.sample())
        steps += 1
        elapsed = time.perf_counter() - t0
    e.close()
    overhead.append(1.0 - timed.seconds / elapsed)
    return steps * envs / elapsed


def cpp_loop(binary, envs, threads, seconds, solver):
    out = subprocess.run([binary, str(envs), str(threads), str(seconds), solver], check=True,
                         capture_output=True, text=True).stdout
    return json.loads(out)["env_steps_per_s"]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--envs", type=int, default=128)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--seconds", type=float, default=3.0)
    ap.add_argument("--rounds", type=int, default=10)
    ap.add_argument("--physics-solver", default="newton")
    ap.add_argument("--binary", default=os.path.join(ROOT, "build", "simhuman_vec_env_bench"))
    args = ap.parse_args()
    cpp, py, overhead = [], [], []
    for _ in range(args.rounds):
        cpp.append(cpp_loop(args.binary, args.envs, args.threads, args.seconds,
                            args.physics_solver))
        py.append(python_loop(args.envs, args.threads, args.seconds, args.physics_solver,
                              overhead))
    c, p = statistics.mean(cpp), statistics.mean(py)
    print(json.dumps({"envs": args.envs, "threads": args.threads, "seconds": args.seconds,
                      "rounds": args.rounds, "physics_solver": args.physics_solver,
                      "cpp_env_steps_per_s": [round(x, 1) for x in cpp],
                      "python_env_steps_per_s": [round(x, 1) for x in py],
                      "cpp_mean": round(c, 1), "python_mean": round(p, 1),
                      "python_over_cpp": round(p / c, 4),
                      "median_round_ratio": round(statistics.median(
                          [b / a for a, b in zip(cpp, py)]), 4),
                      "python_time_outside_cpp_step": round(statistics.mean(overhead), 4)}))

if __name__ == "__main__":
    main()
