"""Select tools on a Machining Features tree, headless: element properties, the plan with the
knowledge base's speeds and feeds on the group (no Path Job made), one undo step, save/reopen,
bad input leaving the document as it was; planning from the stored tree, with the plan the
command line makes from the part; and the FreeCAD tool library round trip."""
import contextlib
import filecmp
import json
import math
import os
import shutil
import subprocess
import tempfile
import unittest

import FreeCAD
import Part

import aeronc
from aeronc import _core, makers, pathcompat
from aeronc.pipeline import knowledge_base, recognition, tool_planning
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

    def test_tools_and_plan_recorded_without_a_job(self):
        plan = tool_planning.select_tools(self.group, "7050-T7451", kb_path=self.kb_path)
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
        self.assertEqual(json.loads(self.group.ToolPlan), plan)

        # The plan goes to the machining chain through the group: no Job, no ToolController here.
        self.assertEqual(pathcompat.jobs_of_part(self.doc, self.part), [])
        self.assertFalse([o for o in self.doc.Objects if hasattr(o, tool_planning.TC_TAG)])
        machine = kb.machine_names()[0]
        self.assertTrue(plan["toolSettings"])
        for s in plan["toolSettings"]:
            t = [x for x in kb.tools() if x["id"] == s["tool"]][0]
            cc = kb.cutting_condition("7050-T7451", t["material"], s["operation"], t["diameter"])
            # By hand: n = 1000 v_c / (pi D) capped by the machine, feed = f_z Z n.
            n = 1000 * cc["vc"] / (math.pi * t["diameter"])
            n = min(n, {"AC-5AX": 18000, "XA5032": 1800}[machine])
            self.assertAlmostEqual(s["spindleRpm"], n, places=6)
            self.assertAlmostEqual(s["feedMmMin"], cc["fz"] * t["flutes"] * n, places=3)
            ratio = 1.0 if s["operation"] == "drilling" else kb.threshold("plunge_feed_ratio")
            self.assertAlmostEqual(s["plungeFeedMmMin"], cc["fz"] * t["flutes"] * n * ratio, places=3)

        # Again: the same plan, still no Job.
        count = len(self.doc.Objects)
        self.assertEqual(tool_planning.select_tools(self.group, "7050-T7451", kb_path=self.kb_path), plan)
        self.assertEqual(len(self.doc.Objects), count)

        # Saved and reopened, the plan is still there.
        path = temp_fcstd("select_tools")
        tools = sorted(p.RoughingTool for p in pockets)
        self.doc.saveAs(path)
        FreeCAD.closeDocument(self.doc.Name)
        self.doc = FreeCAD.openDocument(path)
        again = [o for o in self.doc.Objects if getattr(o, "ElementType", "") == "closed_pocket"]
        self.assertEqual(sorted(o.RoughingTool for o in again), tools)
        group = [o for o in self.doc.Objects if hasattr(o, "ToolPlan")][0]
        self.assertEqual(json.loads(group.ToolPlan), plan)

    def test_one_undo_step(self):
        before = set(o.Name for o in self.doc.Objects)
        tool_planning.select_tools(self.group, "7050-T7451", kb_path=self.kb_path)
        self.assertTrue(self.group.ToolPlan)
        self.assertTrue(any(getattr(o, "RoughingTool", "") for o in self.doc.Objects))
        self.doc.undo()
        self.assertEqual(set(o.Name for o in self.doc.Objects), before)
        self.assertEqual((self.group.Material, self.group.ToolPlan), ("", ""))
        self.assertFalse(any(getattr(o, "RoughingTool", "") for o in self.doc.Objects))

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


@contextlib.contextmanager
def recognition_unavailable():
    """Every way into recognition fails while inside: a plan made here came from a stored tree."""
    def refuse(*args, **kwargs):
        raise AssertionError("recognition ran again")

    saved = [(m, name, getattr(m, name)) for m, name in
             ((_core, "recognise_brep"), (_core, "recognise_file"), (recognition, "recognise"))]
    for m, name, _ in saved:
        setattr(m, name, refuse)
    try:
        yield
    finally:
        for m, name, f in saved:
            setattr(m, name, f)


class PlanFromStoredTreeTest(unittest.TestCase):
    """Select tools plans the tree stored in the group, without recognising the part again, and
    gets the plan the command line makes from the part itself (and from the stored tree)."""
    MATERIAL = "7050-T7451"
    MACHINE = "AC-5AX"

    def setUp(self):
        self.doc = new_document("AeroNCStoredTree")
        self.tmp = tempfile.mkdtemp(prefix="aeronc_tree_")
        self.kb_path = os.path.join(self.tmp, "kb.sqlite")
        self.cli = os.path.join(os.path.dirname(aeronc.PACKAGE_DIR), "bin", "aeronc")

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)
        shutil.rmtree(self.tmp, ignore_errors=True)

    def _cli_plan(self, *args):
        out = os.path.join(self.tmp, "cli_plan.json")
        run = subprocess.run([self.cli, "select-tools"] + list(args) +
                             ["--kb", self.kb_path, "--material", self.MATERIAL, "--machine", self.MACHINE,
                              "--json", out], stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
        self.assertEqual(run.returncode, 0, run.stderr)
        with open(out) as f:
            return json.load(f)

    def _check(self, path, directions, cli_directions):
        self.assertTrue(os.path.isfile(self.cli), self.cli)
        part = self.doc.addObject("Part::Feature", "Part")
        part.Shape = Part.read(path)
        self.doc.recompute()
        group = makers.create_machining_features(self.doc, part, directions=directions)
        with recognition_unavailable():
            plan = tool_planning.select_tools(group, self.MATERIAL, machine=self.MACHINE, kb_path=self.kb_path)
        # Not an empty plan: elements with tools, a setting per tool and operation.
        self.assertGreaterEqual(len(plan["elements"]) + len(plan["holes"]), 10)
        self.assertGreater(sum(1 for e in plan["elements"] if e["roughingTool"]), 0)
        self.assertEqual(len(plan["elements"]) + len(plan["holes"]), group.ElementCount)
        self.assertTrue(plan["toolSettings"])

        # The command line's part form recognises the same shape itself and plans the same.
        brep = os.path.join(self.tmp, "part.brep")
        part.Shape.exportBrep(brep)
        self.assertEqual(plan, self._cli_plan(brep, "--directions", cli_directions))
        # And its --tree form plans the tree the group stored to the same result.
        stored = os.path.join(self.tmp, "stored.json")
        with open(stored, "w") as f:
            f.write(group.Result)
        self.assertEqual(plan, self._cli_plan("--tree", stored))
        return group

    def test_sample_panel_both_sides(self):
        self._check(os.path.join(aeronc.PACKAGE_DIR, "resources", "samples", "sample_panel.step"),
                    [(0, 0, 1), (0, 0, -1)], "+Z,-Z")

    def test_nist_part(self):
        path = os.path.join(os.environ.get("AERONC_SHARED_DATA", ""), "nist", "nist_ftc_07_asme1_rd.stp")
        if not os.path.isfile(path):
            self.skipTest("no {} (set AERONC_SHARED_DATA)".format(path))
        self._check(path, None, "auto")

    def test_changed_or_damaged_tree_is_refused(self):
        part, _ = make_panel_object(self.doc, PLAIN)
        group = makers.create_machining_features(self.doc, part, directions=[(0, 0, 1)])
        before = set(o.Name for o in self.doc.Objects)
        # A stored tree the core cannot read: the error names the field, nothing is recorded.
        good = group.Result
        tree = json.loads(good)
        tree["elements"][0]["parent"] = 7
        group.Result = json.dumps(tree)
        with self.assertRaises(knowledge_base.KnowledgeBaseError) as ctx:
            tool_planning.select_tools(group, self.MATERIAL, kb_path=self.kb_path)
        self.assertIn("elements[0].parent", str(ctx.exception))
        self.assertIn(group.Label, str(ctx.exception))
        group.Result = ""
        with self.assertRaises(knowledge_base.KnowledgeBaseError) as ctx:
            tool_planning.select_tools(group, self.MATERIAL, kb_path=self.kb_path)
        self.assertIn("no stored recognition", str(ctx.exception))
        group.Result = good
        # A part changed since recognition: refused before planning.
        part.Shape = Part.makeBox(10, 10, 10)
        self.doc.recompute()
        with self.assertRaises(knowledge_base.KnowledgeBaseError) as ctx:
            tool_planning.select_tools(group, self.MATERIAL, kb_path=self.kb_path)
        self.assertIn("changed since its features were recognised", str(ctx.exception))
        self.assertEqual(set(o.Name for o in self.doc.Objects), before)
        self.assertEqual((group.Material, group.ToolPlan), ("", ""))

    def test_cancel_leaves_the_document_as_it_was(self):
        part, _ = make_panel_object(self.doc, PLAIN)
        group = makers.create_machining_features(self.doc, part, directions=[(0, 0, 1)])
        before = set(o.Name for o in self.doc.Objects)
        stages = []

        def progress(fraction, stage):
            stages.append(stage)
            return fraction < 0.5  # go on planning, stop before recording

        with self.assertRaises(knowledge_base.KnowledgeBaseError) as ctx:
            tool_planning.select_tools(group, self.MATERIAL, kb_path=self.kb_path, progress=progress)
        self.assertIn("cancelled", str(ctx.exception))
        self.assertEqual(stages, ["Planning tools", "Recording the plan"])
        self.assertEqual(set(o.Name for o in self.doc.Objects), before)
        self.assertEqual((group.Material, group.ToolPlan), ("", ""))


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


class MachinesAgreeTest(unittest.TestCase):
    """The knowledge base's machines that have a machine file (the posts' kinematics) state the
    same limits in both: tool selection and the optimiser read one, the post checks the other."""

    def test_knowledge_base_rows_match_their_machine_files(self):
        from aeronc.post import machines
        tmp = tempfile.mkdtemp(prefix="aeronc_machines_")
        try:
            kb = knowledge_base.open_kb(os.path.join(tmp, "kb.sqlite"))
            t = kb.table("machine")
            cols = [c["name"] for c in t["columns"]]
            rows = [dict(zip(cols, r)) for r in t["rows"]]
        finally:
            shutil.rmtree(tmp, ignore_errors=True)
        known = set(machines.known_machines())
        checked = [r for r in rows if r["name"] in known]
        self.assertIn("AC-5AX-L", [r["name"] for r in checked])
        for r in checked:
            m = json.loads(machines.load(r["name"])[0])
            travel = m["linearTravel"]
            for axis in "xyz":
                lo, hi = travel[axis.upper()]
                self.assertAlmostEqual(float(r["travel_" + axis]), hi - lo, places=6, msg=(r["name"], axis))
            limits = {a["name"]: (a["min"], a["max"]) for a in m["rotaryAxes"]}
            for axis in "ac":
                self.assertEqual((float(r[axis + "_min"]), float(r[axis + "_max"])),
                                 tuple(float(v) for v in limits[axis.upper()]), (r["name"], axis))
            self.assertAlmostEqual(float(r["max_spindle_rpm"]), m["maxSpindleSpeed"], msg=r["name"])
            self.assertAlmostEqual(float(r["max_feed_mm_min"]), m["maxFeed"], msg=r["name"])


if __name__ == "__main__":
    unittest.main()
