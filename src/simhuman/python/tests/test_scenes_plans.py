"""Scenes and plans from Python: the CLI's errors cross as exceptions with the same messages."""

import json
import os
import unittest

import simhuman

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "..", ".."))


class SceneTest(unittest.TestCase):
    def test_builtin_scene(self):
        self.assertIn("sit_demo", simhuman.scene_names())
        scene = simhuman.load_scene("sit_demo")
        self.assertEqual(scene.name, "sit_demo")
        self.assertGreaterEqual(len(scene.object_ids), 1)
        self.assertEqual(len(scene.humans), 1)
        chair = scene.object_ids[0]
        self.assertIn("seat surface", scene.parts(chair))

    def test_unihsi_sceneplan_file(self):
        path = os.path.join(ROOT, "assets", "scenes", "unihsi_table7_plan.json")
        scene = simhuman.load_scene(path)
        self.assertEqual(scene.object_ids, ["chair000", "table001", "laptop002", "bed003"])

    def test_unknown_scene_lists_the_names(self):
        with self.assertRaises(simhuman.NotFoundError) as cm:
            simhuman.load_scene("no_such_scene")
        self.assertIsInstance(cm.exception, FileNotFoundError)
        self.assertIn("sit_demo", str(cm.exception))
        self.assertEqual(cm.exception.code, "NOT_FOUND")

    def test_scene_json_round_trip_and_json_pointer_errors(self):
        scene = simhuman.load_scene("sit_demo")
        again = simhuman.Scene.from_json(scene.to_dict(), source="mine")
        self.assertEqual(again.to_dict(), scene.to_dict())
        self.assertEqual(json.loads(scene.to_json()), scene.to_dict())
        bad = scene.to_dict()
        bad["objects"][0]["type"] = "spaceship"
        with self.assertRaises(simhuman.BadInputError) as cm:
            simhuman.Scene.from_json(bad, source="mine.json")
        msg = str(cm.exception)
        self.assertIn("mine.json", msg)
        self.assertIn("/objects/0/type", msg)
        self.assertIn("chair", msg)  # the valid types are listed
        self.assertIsInstance(cm.exception, ValueError)
        with self.assertRaisesRegex(simhuman.BadInputError, "x.json"):
            simhuman.Scene.from_json("{not json", source="x.json")


class PlanTest(unittest.TestCase):
    def setUp(self):
        self.scene = simhuman.load_scene("sit_demo")

    def test_offline_planner(self):
        plan = simhuman.plan(self.scene, "sit on the chair")
        self.assertGreaterEqual(len(plan), 1)
        self.assertEqual(len(plan.explanation), len(plan))
        self.assertEqual(len(plan.step_texts), len(plan))
        d = plan.to_dict()
        again = simhuman.Plan.from_json(d, self.scene)
        self.assertEqual(again.to_dict(), d)

    def test_ambiguous_command_raises_the_question(self):
        # sit_demo with a second chair beside the first
        d = self.scene.to_dict()
        chair = dict(d["objects"][0], id="chair001")
        chair["pos"] = [chair["pos"][0], chair["pos"][1] + 1.5] + chair["pos"][2:]
        d["objects"].append(chair)
        scene = simhuman.Scene.from_json(d)
        with self.assertRaises(simhuman.ClarificationNeeded) as cm:
            simhuman.plan(scene, "sit on the chair")
        self.assertTrue(cm.exception.question.endswith("?"), cm.exception.question)
        self.assertEqual(cm.exception.question, str(cm.exception))

    def test_not_understood_and_unknown_planner(self):
        with self.assertRaises(simhuman.BadInputError):
            simhuman.plan(self.scene, "lie on the chair")
        with self.assertRaisesRegex(simhuman.BadInputError, "valid planners are: offline, llm"):
            simhuman.plan(self.scene, "sit on the chair", planner="oracle")
        with self.assertRaisesRegex(simhuman.BadInputError, "llm: unknown key 'modle'"):
            simhuman.plan(self.scene, "sit", planner="llm", llm={"modle": "x"})

    def test_plan_json_errors_name_the_pointer_and_valid_names(self):
        d = simhuman.plan(self.scene, "sit on the chair").to_dict()
        d["steps"][-1]["pairs"][0]["object"] = "sofa999"
        with self.assertRaises(simhuman.BadInputError) as cm:
            simhuman.Plan.from_json(json.dumps(d), self.scene, source="p.json")
        msg = str(cm.exception)
        self.assertIn("p.json", msg)
        self.assertIn("sofa999", msg)
        self.assertIn(self.scene.object_ids[0], msg)


if __name__ == "__main__":
    unittest.main()
