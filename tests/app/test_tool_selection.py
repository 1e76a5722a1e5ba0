"""Tool planning from the user's knowledge base, headless."""
import json
import os
import unittest

import FreeCAD
import Part

from aeronc import _core, knowledge_base


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
        plan = knowledge_base.select_tools(_panel(), "7050-T7451", directions=[(0, 0, 1)])
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
        again = knowledge_base.select_tools(_panel(), "7050-T7451", directions=[(0, 0, 1)])
        self.assertEqual(again["elements"], plan["elements"])
        self.assertEqual(os.path.getmtime(path), stamp)  # opened, not rebuilt

    def test_unknown_material_is_a_clear_error(self):
        with self.assertRaises(knowledge_base.KnowledgeBaseError) as ctx:
            knowledge_base.select_tools(_panel(), "unobtainium", directions=[(0, 0, 1)])
        self.assertIn("material", str(ctx.exception))


if __name__ == "__main__":
    unittest.main()
