"""Tool planning of a recognised tree from the user's knowledge base, headless."""
import json
import os
import unittest

import FreeCAD
import Part

from aeronc import _core
from aeronc.pipeline import knowledge_base, recognition


def _panel():
    brep, truth = _core.make_panel(json.dumps({"pocketsX": 2, "pocketsY": 1, "islands": False, "openings": False,
                                              "lighteningHoles": False, "joggles": False, "lowerRibs": False,
                                              "flange": False, "bottomPockets": False, "boltHoles": False}))
    shape = Part.Shape()
    shape.importBrepFromString(brep)
    return shape


class ToolSelectionTest(unittest.TestCase):
    def test_user_knowledge_base_is_built_once_and_plans_the_pockets(self):
        path = knowledge_base.user_kb_path()
        self.assertTrue(path.startswith(FreeCAD.getUserAppDataDir()))
        tree = recognition.recognise(_panel(), directions=[(0, 0, 1)])
        plan = knowledge_base.plan_tools(tree, "7050-T7451")
        self.assertTrue(os.path.isfile(path))
        stamp = os.path.getmtime(path)
        self.assertEqual(len(plan["elements"]), 2)
        for e in plan["elements"]:
            self.assertIsNone(e["error"])
            self.assertIsNotNone(e["roughingTool"])
            self.assertIsNotNone(e["finishingTool"])
            self.assertGreaterEqual(e["eta"], 0.85)
        # Both pockets are alike: one roughing group, no tool change.
        self.assertEqual(plan["toolChanges"]["after"], 0)
        again = knowledge_base.plan_tools(json.dumps(tree), "7050-T7451")  # the tree as stored text
        self.assertEqual(again, plan)
        self.assertEqual(os.path.getmtime(path), stamp)  # opened, not rebuilt

    def test_unknown_material_is_a_clear_error(self):
        tree = recognition.recognise(_panel(), directions=[(0, 0, 1)])
        with self.assertRaises(knowledge_base.KnowledgeBaseError) as ctx:
            knowledge_base.plan_tools(tree, "unobtainium")
        self.assertIn("material", str(ctx.exception))

    def test_malformed_tree_is_refused_naming_the_field(self):
        tree = recognition.recognise(_panel(), directions=[(0, 0, 1)])
        del tree["elements"][1]["contour"]
        with self.assertRaises(knowledge_base.KnowledgeBaseError) as ctx:
            knowledge_base.plan_tools(tree, "7050-T7451")
        self.assertIn("elements[1]: missing field 'contour'", str(ctx.exception))
        with self.assertRaises(knowledge_base.KnowledgeBaseError) as ctx:
            knowledge_base.plan_tools("{not json", "7050-T7451")
        self.assertIn("not valid JSON", str(ctx.exception))


if __name__ == "__main__":
    unittest.main()
