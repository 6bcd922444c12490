"""simhuman.vector: the Gymnasium-style vector env over the C++ VecEnv."""

import unittest

import numpy as np

import simhuman
from simhuman import vector


class WalkVectorEnvTest(unittest.TestCase):
    def setUp(self):
        self.envs = vector.make("walk", num_envs=4, threads=2, seed=3)

    def tearDown(self):
        self.envs.close()

    def test_spaces_describe_shapes_and_bounds(self):
        e = self.envs
        self.assertEqual(e.num_envs, 4)
        self.assertEqual(e.single_observation_space.shape, (116,))
        self.assertEqual(e.single_action_space.shape, (28,))
        self.assertEqual(e.observation_space.shape, (4, 116))
        self.assertEqual(e.action_space.shape, (4, 28))
        self.assertEqual(e.action_space.dtype, np.float32)
        np.testing.assert_array_equal(e.single_action_space.high, np.full(28, 3.0, np.float32))
        np.testing.assert_array_equal(e.single_action_space.low, np.full(28, -3.0, np.float32))
        self.assertFalse(e.single_observation_space.is_bounded())
        self.assertIn(e.action_space.sample(), e.action_space)
        # the arm entries are not used by the walk task
        self.assertGreater(int(e.action_used.sum()), 0)
        self.assertLess(int(e.action_used.sum()), 28)

    def test_reset_and_step_return_gymnasium_tuples(self):
        obs, info = self.envs.reset(seed=5)
        self.assertEqual(obs.shape, (4, 116))
        self.assertEqual(obs.dtype, np.float32)
        self.assertEqual(info, {})
        self.assertTrue(np.all(np.isfinite(obs)))
        obs, reward, terminated, truncated, info = self.envs.step(self.envs.action_space.sample())
        self.assertEqual(obs.shape, (4, 116))
        self.assertEqual(reward.shape, (4,))
        self.assertEqual(terminated.dtype, bool)
        self.assertEqual(truncated.dtype, bool)
        self.assertIsInstance(info, dict)

    def test_observations_are_views_of_the_cpp_buffer(self):
        obs0, _ = self.envs.reset(seed=5)
        first = obs0.copy()
        obs1, *_ = self.envs.step(np.zeros((4, 28), np.float32))
        # the same memory, overwritten in place: no copy per step
        self.assertTrue(np.shares_memory(obs0, obs1))
        self.assertFalse(np.array_equal(first, obs1))
        copying = vector.make("walk", num_envs=4, threads=1, seed=3, copy=True)
        a, _ = copying.reset(seed=5)
        b, *_ = copying.step(np.zeros((4, 28), np.float32))
        self.assertFalse(np.shares_memory(a, b))
        np.testing.assert_array_equal(a, first)
        copying.close()

    def test_same_seed_same_trajectory_with_any_thread_count(self):
        rng = np.random.default_rng(0)
        actions = [rng.uniform(-3, 3, (4, 28)).astype(np.float32) for _ in range(10)]

        def rollout(threads):
            envs = vector.make("walk", num_envs=4, threads=threads, seed=11, copy=True)
            out = [envs.reset(seed=7)[0]]
            for a in actions:
                out.append(envs.step(a)[0])
            envs.close()
            return np.stack(out)

        one, two = rollout(1), rollout(2)
        np.testing.assert_array_equal(one, two)
        other = vector.make("walk", num_envs=4, threads=2, copy=True)
        self.assertFalse(np.array_equal(other.reset(seed=8)[0], one[0]))
        other.close()

    def test_bad_actions_are_value_errors_naming_the_expected_shape(self):
        self.envs.reset(seed=1)
        with self.assertRaisesRegex(ValueError, r"expected shape \(4, 28\).*got \(4, 27\)"):
            self.envs.step(np.zeros((4, 27), np.float32))
        with self.assertRaisesRegex(ValueError, r"expected shape \(4, 28\).*got \(112,\)"):
            self.envs.step(np.zeros(112, np.float32))
        with self.assertRaisesRegex(ValueError, r"dtype float32 and shape \(4, 28\).*int64"):
            self.envs.step(np.zeros((4, 28), np.int64))
        with self.assertRaisesRegex(ValueError, r"actions\[2, 5\] is nan"):
            a = np.zeros((4, 28), np.float32)
            a[2, 5] = np.nan
            self.envs.step(a)
        # other float dtypes and array-likes are converted
        self.envs.step(np.zeros((4, 28), np.float64))
        self.envs.step([[0.0] * 28] * 4)

    def test_bad_construction_names_the_argument(self):
        with self.assertRaisesRegex(simhuman.BadInputError, "unknown task 'swim'; valid: walk"):
            vector.make("swim", num_envs=2)
        with self.assertRaisesRegex(ValueError, "num_envs 0 is invalid"):
            vector.make("walk", num_envs=0)
        with self.assertRaisesRegex(ValueError, "physics_solver 'cg' is unknown; valid: newton"):
            vector.make("walk", num_envs=1, physics_solver="cg")
        with self.assertRaisesRegex(simhuman.BadInputError, "unknown walking gait 'brisk'"):
            vector.make("walk", num_envs=1, walk_gait="brisk")
        with self.assertRaisesRegex(simhuman.BadInputError, "walk_gait 'human' applies to the"):
            vector.make("reach", num_envs=1, walk_gait="human")

    def test_seeds(self):
        a, _ = self.envs.reset(seed=np.int64(5))
        a = a.copy()
        b, _ = self.envs.reset(seed=5)
        np.testing.assert_array_equal(a, b)
        c, _ = self.envs.reset()  # continues: new episodes
        self.assertFalse(np.array_equal(a, c))
        with self.assertRaisesRegex(ValueError, r"seed -1 is invalid; valid: an integer in"):
            self.envs.reset(seed=-1)
        with self.assertRaises(TypeError):
            self.envs.reset(seed=1.5)

    def test_closed_env_raises(self):
        self.envs.close()
        with self.assertRaisesRegex(RuntimeError, "closed"):
            self.envs.reset()


class ReachAutoresetTest(unittest.TestCase):
    def test_time_limit_truncates_and_resets_in_the_same_step(self):
        envs = vector.make("reach", num_envs=3, threads=2, seed=2)
        self.assertEqual(envs.single_action_space.high[0], 1.0)
        obs, _ = envs.reset(seed=4)
        returns = np.zeros(3)
        for t in range(100):
            obs, reward, terminated, truncated, info = envs.step(envs.action_space.sample())
            returns += reward
            if t < 99:
                self.assertEqual(info, {})
        self.assertTrue(np.all(truncated))
        self.assertFalse(np.any(terminated))
        np.testing.assert_array_equal(info["_final_obs"], [True, True, True])
        np.testing.assert_allclose(info["episode"]["r"], returns, rtol=1e-5)
        np.testing.assert_array_equal(info["episode"]["l"], [100, 100, 100])
        # obs is the new episode's first observation, final_obs the old episode's last
        self.assertFalse(np.array_equal(obs, info["final_obs"]))
        envs.close()


if __name__ == "__main__":
    unittest.main()
