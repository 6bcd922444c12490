"""A script written for Gymnasium's vector API runs unchanged on simhuman.vector."""

import unittest

import numpy as np

import gymnasium_style_script
from simhuman import vector


class GymnasiumScriptTest(unittest.TestCase):
    def test_script_runs_unchanged(self):
        envs = vector.make("reach", num_envs=8, threads=2)
        returns, obs, act, rew, done = gymnasium_style_script.rollout(envs, num_steps=250)
        # reach episodes last 100 steps: two rounds of 8 finished episodes
        self.assertEqual(len(returns), 16)
        self.assertEqual(int(done.sum()), 16)
        self.assertTrue(np.all(np.isfinite(obs)))
        self.assertTrue(np.all(np.abs(act) <= 1.0))
        self.assertAlmostEqual(sum(returns), float(rew[:200].sum()), places=2)

    def test_walk_task_too(self):
        envs = vector.make("walk", num_envs=4, threads=2)
        _, obs, _, rew, _ = gymnasium_style_script.rollout(envs, num_steps=20)
        self.assertEqual(obs.shape, (20, 4, 116))
        self.assertTrue(np.all(np.isfinite(rew)))


if __name__ == "__main__":
    unittest.main()
