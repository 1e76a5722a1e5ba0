"""Select tools on a Machining Features tree, headless: element properties, ToolControllers
in the part's Job with the knowledge base's speeds and feeds, one undo step, save/reopen,
bad input leaving the document as it was; and the FreeCAD tool library round trip."""
import filecmp
import json
import math
import os
import shutil
import tempfile
import unittest

import FreeCAD

from aeronc import knowledge_base, pathcompat, tool_planning
from aeronc import makers
from aeronc.tests import pathcompat as test_pathcompat
from aeronc.tests.app.support import make_panel_object, new_document, temp_fcstd

PLAIN = {"pocketsX": 2, "pocketsY": 1, "islands": False, "openings": False, "lighteningHoles": False,
         "joggles": False, "lowerRibs": False, "flange": False, "bottomPockets": False, "boltHoles": False}
FREECAD_LIBRARY = "/usr/share/freecad/Mod/Path/Tools/Library/Default.fctl"


class SelectToolsTest(unittest.TestCase):
    def setUp(self):
        self.doc = new_document("AeroNCSelectTools")
        self.tmp = tempfile.mkdtemp(prefix="aeronc_kb_")
        self.kb_path = os.path.join(self.tmp, "kb.sqlite")
        self.part, _ = make_panel_object(self.doc, PLAIN)
        self.group = makers.create_machining_features(self.doc, self.part, directions=[(0, 0, 1)])

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)
        shutil.rmtree(self.tmp, ignore_errors=True)

    def test_tools_recorded_and_tool_controllers_made(self):
        plan, job, tcs = tool_planning.select_tools(self.group, "7050-T7451", kb_path=self.kb_path)
        kb = knowledge_base.open_kb(self.kb_path)
        pockets = [o for o in self.doc.Objects if getattr(o, "ElementType", "") == "closed_pocket"]
        self.assertEqual(len(pockets), 2)
        for p in pockets:
            self.assertTrue(p.FinishingTool)
            self.assertTrue(p.RoughingTool)
            self.assertGreaterEqual(p.MachinableRatio, kb.threshold("eta_min"))
            self.assertLessEqual(p.MachinableRatio, 1.0)
            self.assertEqual(p.ToolError, "")
        self.assertEqual(self.group.Material, "7050-T7451")
        self.assertEqual(self.group.ToolChangesAfter, plan["toolChanges"]["after"])

        # The part had no Job: one was made, holding a controller per tool and operation.
        self.assertTrue(pathcompat.is_job(job))
        self.assertEqual(pathcompat.jobs_of_part(self.doc, self.part), [job])
        ours = [tc for tc in pathcompat.tool_controllers(job) if hasattr(tc, tool_planning.TC_TAG)]
        self.assertEqual(sorted(tc.AeroNCTool for tc in ours),
                         sorted("{}/{}".format(s["tool"], s["operation"]) for s in plan["toolSettings"]))
        machine = kb.machine_names()[0]
        for tc in ours:
            tool_id, op = tc.AeroNCTool.split("/")
            t = [x for x in kb.tools() if x["id"] == tool_id][0]
            cc = kb.cutting_condition("7050-T7451", t["material"], op, t["diameter"])
            # By hand: n = 1000 v_c / (pi D) capped by the machine, feed = f_z Z n.
            n = 1000 * cc["vc"] / (math.pi * t["diameter"])
            n = min(n, {"AC-5AX": 18000, "XA5032": 1800}[machine])
            self.assertAlmostEqual(tc.SpindleSpeed, n, places=6)
            self.assertAlmostEqual(tc.HorizFeed.getValueAs("mm/min").Value, cc["fz"] * t["flutes"] * n, places=3)
            ratio = 1.0 if op == "drilling" else kb.threshold("plunge_feed_ratio")
            self.assertAlmostEqual(tc.VertFeed.getValueAs("mm/min").Value, cc["fz"] * t["flutes"] * n * ratio,
                                   places=3)
            self.assertAlmostEqual(tc.Tool.Diameter.Value, t["diameter"], places=4)
            # The bit's attributes are kept too (FreeCAD 0.20's factory drops them).
            self.assertEqual(tc.Tool.Flutes, t["flutes"])
            self.assertEqual(tc.Tool.Material.lower(), t["material"].lower())

        # Again: the same controllers, updated, not duplicated.
        count = len(pathcompat.tool_controllers(job))
        tool_planning.select_tools(self.group, "7050-T7451", kb_path=self.kb_path)
        self.assertEqual(len(pathcompat.tool_controllers(job)), count)

        # Saved and reopened, the plan is still there.
        path = temp_fcstd("select_tools")
        tools = sorted(p.RoughingTool for p in pockets)
        self.doc.saveAs(path)
        FreeCAD.closeDocument(self.doc.Name)
        self.doc = FreeCAD.openDocument(path)
        again = [o for o in self.doc.Objects if getattr(o, "ElementType", "") == "closed_pocket"]
        self.assertEqual(sorted(o.RoughingTool for o in again), tools)
        self.assertEqual(len([o for o in self.doc.Objects if hasattr(o, tool_planning.TC_TAG)]), len(ours))

    def test_one_undo_step(self):
        before = set(o.Name for o in self.doc.Objects)
        tool_planning.select_tools(self.group, "7050-T7451", kb_path=self.kb_path)
        self.assertGreater(len(self.doc.Objects), len(before))
        self.doc.undo()
        self.assertEqual(set(o.Name for o in self.doc.Objects), before)

    def test_bad_input_leaves_the_document_as_it_was(self):
        before = set(o.Name for o in self.doc.Objects)
        with self.assertRaises(knowledge_base.KnowledgeBaseError) as ctx:
            tool_planning.select_tools(self.group, "unobtainium", kb_path=self.kb_path)
        self.assertIn("unknown workpiece material 'unobtainium'", str(ctx.exception))
        with self.assertRaises(knowledge_base.KnowledgeBaseError) as ctx:
            tool_planning.select_tools(self.group, "7050-T7451", machine="NO-SUCH", kb_path=self.kb_path)
        self.assertIn("unknown machine 'NO-SUCH'", str(ctx.exception))
        corrupt = os.path.join(self.tmp, "corrupt.sqlite")
        with open(corrupt, "wb") as f:
            f.write(b"this is not a database" * 100)
        with self.assertRaises(knowledge_base.KnowledgeBaseError) as ctx:
            tool_planning.select_tools(self.group, "7050-T7451", kb_path=corrupt)
        self.assertIn("not a database", str(ctx.exception))
        self.assertEqual(set(o.Name for o in self.doc.Objects), before)
        self.assertEqual((self.group.Material, self.group.ToolPlan), ("", ""))
        self.assertFalse(any(getattr(o, "RoughingTool", "") for o in self.doc.Objects))


class ToolLibraryBridgeTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="aeronc_fctl_")
        self.kb = knowledge_base.open_kb(os.path.join(self.tmp, "kb.sqlite"))

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    @unittest.skipUnless(os.path.isfile(FREECAD_LIBRARY), "FreeCAD's tool library is not installed")
    def test_freecad_library_round_trips_unchanged_and_loads_in_freecad(self):
        before = len(self.kb.tools())
        self.assertEqual(self.kb.import_freecad_library(FREECAD_LIBRARY), 9)
        self.assertEqual(len(self.kb.tools()), before + 9)
        out = os.path.join(self.tmp, "out")
        written = self.kb.export_freecad_library("Default", out)
        src = os.path.dirname(os.path.dirname(FREECAD_LIBRARY))
        self.assertTrue(filecmp.cmp(written[0], FREECAD_LIBRARY, shallow=False))
        for p in written[1:]:
            self.assertTrue(filecmp.cmp(p, os.path.join(src, "Bit", os.path.basename(p)), shallow=False), p)
        # FreeCAD itself reads an exported AeroNC tool as a ToolBit with the same diameter.
        doc = new_document("AeroNCBits")
        try:
            files = self.kb.export_tools("Chosen", ["EM-B16R2"], out)
            bit = test_pathcompat.tool_bit_from_file(files[1])
            self.assertAlmostEqual(bit.Diameter.Value, 16.0, places=6)
            self.assertAlmostEqual(bit.FlatRadius.Value, 8.0 - 2.0, places=6)
        finally:
            FreeCAD.closeDocument(doc.Name)

    def test_editor_edits_are_all_or_nothing(self):
        t = self.kb.table("tool")
        row = t["rowIds"][[r[0] for r in t["rows"]].index("EM-F10")]
        with self.assertRaises(RuntimeError) as ctx:
            self.kb.edit_table("tool", [(row, "diameter", "9"), (row, "corner_radius", "7")])
        self.assertIn("row 'EM-F10'", str(ctx.exception))
        self.assertEqual([x["diameter"] for x in self.kb.tools() if x["id"] == "EM-F10"], [10.0])
        self.kb.edit_table("tool", [(row, "diameter", "9")])
        self.assertEqual([x["diameter"] for x in self.kb.tools() if x["id"] == "EM-F10"], [9.0])


if __name__ == "__main__":
    unittest.main()
