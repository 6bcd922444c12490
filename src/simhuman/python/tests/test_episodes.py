"""An episode from Python: "sit on the chair" in sit_demo, its arrays, files and frames."""

import contextlib
import io
import json
import os
import tempfile
import unittest

import numpy as np

import simhuman


class SitEpisodeTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.scene = simhuman.load_scene("sit_demo")
        cls.plan = simhuman.plan(cls.scene, "sit on the chair")
        cls.events = []
        cls.episode = simhuman.run(cls.plan, seed=1, settle_s=0.0, walk_policy=None,
                                   progress=cls.events.append)

    def test_result_matches_the_cli_keys(self):
        r = self.episode.result
        for key in ["success", "steps_completed", "steps_total", "contact_error_m", "fell",
                    "end_reason", "sim_time_s", "seed", "preset", "config", "git_revision"]:
            self.assertIn(key, r)
        self.assertEqual(r["steps_total"], len(self.plan))
        self.assertEqual(r["seed"], 1)
        self.assertEqual(self.episode.success, r["success"])
        self.assertTrue(self.events)
        self.assertIn("completed", self.events[0])

    def test_sitting_lowers_the_pelvis(self):
        ep = self.episode
        t = ep.time_s
        self.assertGreater(len(t), 10)
        self.assertEqual(ep.qpos.shape, (len(t), len(ep.qpos_names)))
        self.assertEqual(ep.step_index.shape, t.shape)
        pts = ep.body_points
        self.assertEqual(pts.shape, (len(t), 1, 15, 3))
        pelvis_z = ep.body_point("pelvis")[:, 2]
        np.testing.assert_array_equal(pelvis_z, pts[:, 0, simhuman.body_point_names().index(
            "pelvis"), 2])
        self.assertTrue(ep.success)
        self.assertLess(pelvis_z[-1], pelvis_z[0] - 0.2)
        with self.assertRaisesRegex(simhuman.BadInputError, "body point 'tail' is unknown; valid"):
            ep.body_point("tail")

    def test_save_writes_the_run_files(self):
        with tempfile.TemporaryDirectory() as d:
            self.episode.save(d)
            for name in ["result.json", "trajectory.csv", "scene.json", "plan.json"]:
                self.assertTrue(os.path.exists(os.path.join(d, name)), name)
            with open(os.path.join(d, "trajectory.csv")) as f:
                header = f.readline().strip().split(",")
            self.assertEqual(header[2:], self.episode.qpos_names)

    def test_same_episode_as_the_command_line(self):
        with tempfile.TemporaryDirectory() as d:
            with contextlib.redirect_stdout(io.StringIO()):
                code = simhuman.cli(["run", "--scene", "sit_demo", "--command", "sit on the chair",
                                     "--seed", "1", "--settle", "0", "--no-walk", "--out", d])
            self.assertEqual(code, 0)
            with open(os.path.join(d, "result.json")) as f:
                cli = json.load(f)
            qpos = np.loadtxt(os.path.join(d, "trajectory.csv"), delimiter=",", skiprows=1)
        mine = self.episode.result
        for key in ["success", "steps_completed", "contact_error_m", "end_reason", "sim_time_s",
                    "step_completion_s", "config"]:
            self.assertEqual(mine[key], cli[key], key)
        np.testing.assert_allclose(self.episode.qpos, qpos[:, 2:], atol=1e-6)

    def test_render_frames(self):
        try:
            frames = self.episode.render_frames([0, -1], width=64, height=48)
        except simhuman.UnavailableError as e:
            self.skipTest(f"no EGL display: {e}")
        self.assertEqual(frames.shape, (2, 48, 64, 3))
        self.assertEqual(frames.dtype, np.uint8)
        self.assertGreater(frames.std(), 1.0)  # not a blank image
        with self.assertRaisesRegex(ValueError, "frame index out of range"):
            self.episode.render_frames([10**6], width=64, height=48)

    def test_progress_callback_errors_reach_the_caller(self):
        def fail(event):
            raise KeyError("from the callback")

        with self.assertRaisesRegex(KeyError, "from the callback"):
            simhuman.run(self.plan, settle_s=0.0, walk_policy=None, progress=fail)

    def test_bad_run_arguments(self):
        with self.assertRaisesRegex(simhuman.BadInputError, "preset"):
            simhuman.run(self.plan, preset="turbo")
        with self.assertRaisesRegex(simhuman.BadInputError, "config"):
            simhuman.run(self.plan, config={"horizon_s": -1})
        with self.assertRaisesRegex(ValueError, "settle_s"):
            simhuman.run(self.plan, settle_s=float("nan"))


if __name__ == "__main__":
    unittest.main()
