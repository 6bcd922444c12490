"""The cores of the other subcommands: cli(), eval(), clip_gait(), train()."""

import contextlib
import io
import json
import os
import tempfile
import unittest

import simhuman


class CommandsTest(unittest.TestCase):
    def test_cli_exit_codes_and_output(self):
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            self.assertEqual(simhuman.cli(["scenes"]), 0)
        self.assertIn("sit_demo", out.getvalue())
        err = io.StringIO()
        with contextlib.redirect_stderr(err):
            self.assertEqual(simhuman.cli(["run", "--scene", "nowhere", "--plan", "x.json"]), 2)
        self.assertIn("nowhere", err.getvalue())
        self.assertIn("simhuman", simhuman.version())

    def test_eval_language_suite_returns_the_summary(self):
        with tempfile.TemporaryDirectory() as d:
            r = simhuman.eval("language", out_dir=d, verbose=False)
            self.assertEqual(r["out_dir"], d)
            self.assertGreater(r["summary"]["plan_cases"], 10)
            with open(os.path.join(d, "summary.json")) as f:
                self.assertEqual(json.load(f), r["summary"])

    def test_eval_errors_carry_the_cli_message(self):
        with self.assertRaisesRegex(simhuman.BadInputError, "unknown suite 'nope'; valid suites"):
            simhuman.eval("nope")
        with self.assertRaisesRegex(simhuman.BadInputError, "--episodes 0 is invalid"):
            simhuman.eval("sit", episodes=0)

    def test_clip_gait_and_train(self):
        with tempfile.TemporaryDirectory() as d:
            clip = os.path.join(d, "gait.clip.json")
            with contextlib.redirect_stdout(io.StringIO()):
                simhuman.clip_gait(clip, seconds=1.0)
            self.assertTrue(os.path.getsize(clip) > 100)
            run = os.path.join(d, "run")
            with contextlib.redirect_stdout(io.StringIO()):
                r = simhuman.train(task="reach", steps="8k", out=run, envs=16, threads=2,
                                   quiet=True)
            self.assertEqual(r["run_dir"], run)
            self.assertGreaterEqual(len(r["log"]), 1)
            with self.assertRaisesRegex(simhuman.BadInputError, "steps"):
                simhuman.train(task="reach", steps="lots", out=os.path.join(d, "r2"))


if __name__ == "__main__":
    unittest.main()
