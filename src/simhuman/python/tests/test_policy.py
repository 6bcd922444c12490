"""The shipped walking policy loaded in PyTorch drives the vector env."""

import os
import unittest

import numpy as np

from simhuman import vector

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "..", ".."))
WALK_PT = os.path.join(ROOT, "assets", "policies", "walk.pt")

try:
    import torch  # noqa: F401
    from simhuman import policy
except ImportError:  # python3-torch missing
    policy = None


def falls(act, walk_gait="", steps=90, envs=8):
    """Episodes ended by a fall in `steps` policy steps (3 s) of `envs` walkers."""
    e = vector.make("walk", num_envs=envs, threads=2, seed=5, walk_gait=walk_gait)
    obs, _ = e.reset(seed=9)
    fell = 0
    for _ in range(steps):
        obs, _, terminated, _, _ = e.step(act(obs))
        fell += int(terminated.sum())
    e.close()
    return fell


@unittest.skipIf(policy is None, "python3-torch is not installed")
class WalkPolicyTest(unittest.TestCase):
    def test_load(self):
        p = policy.load_policy(WALK_PT)
        self.assertEqual(p.task, "walk")
        self.assertEqual(p.walk_gait, "human")  # assets/policies/walk.json
        out = p.act(np.zeros((3, 116), np.float32))
        self.assertEqual(out.shape, (3, 28))
        self.assertEqual(out.dtype, np.float32)

    def test_policy_keeps_walkers_up_where_random_actions_fall(self):
        p = policy.load_policy(WALK_PT)
        rng = np.random.default_rng(1)
        self.assertEqual(falls(p.act, p.walk_gait), 0)
        self.assertGreater(falls(lambda o: rng.uniform(-3, 3, (8, 28)).astype(np.float32)), 4)

    def test_not_a_policy_file(self):
        with self.assertRaisesRegex(ValueError, "walk.json: not a simhuman policy file"):
            policy.load_policy(os.path.join(ROOT, "assets", "policies", "walk.json"))


if __name__ == "__main__":
    unittest.main()
