"""A user's own tool crib in place of the shipped one (docs/tool-crib.md): a knowledge-base file
or a FreeCAD tool library given to the main job; the run uses its tools and nothing else, and
the user's file is not written."""
import hashlib
import json
import os
import shutil
import tempfile
import unittest

import FreeCAD
import Part

from aeronc.errors import KnowledgeBaseError
from aeronc.pipeline import knowledge_base
from aeronc.runs import main_job

FREECAD_LIBRARY = "/usr/share/freecad/Mod/Path/Tools/Library/Default.fctl"


def _digest(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def _plate(folder):
    """A 120 x 80 x 20 plate with one 60 x 40 x 8 pocket of R8 corners in its top."""
    plate = Part.makeBox(120, 80, 20)
    cut = Part.makeBox(60, 40, 9, FreeCAD.Vector(30, 20, 12))
    vertical = [e for e in cut.Edges if abs(e.Vertexes[0].Point.z - e.Vertexes[1].Point.z) > 1e-6]
    path = os.path.join(folder, "plate.brep")
    plate.cut(cut.makeFillet(8, vertical)).exportBrep(path)
    return path


def _own_crib(folder, keep):
    """A knowledge-base file of the user's: the shipped one with only the tools `keep`."""
    path = os.path.join(folder, "my_crib.sqlite")
    kb = knowledge_base.open_kb(path)
    t = kb.table("tool")
    kb.edit_table("tool", deletes=[rid for rid, row in zip(t["rowIds"], t["rows"]) if row[0] not in keep])
    del kb
    return path


class CribTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="aeronc_crib_")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def test_a_users_knowledge_base_file_replaces_the_shipped_crib(self):
        crib = _own_crib(self.tmp, {"EM-F12", "EM-F6"})
        before = _digest(crib)
        kb = knowledge_base.use_crib(os.path.join(self.tmp, "run.sqlite"), crib)
        self.assertEqual(sorted(t["id"] for t in kb.tools()), ["EM-F12", "EM-F6"])
        self.assertEqual(_digest(crib), before)  # a copy is used, the user's file is not written

    @unittest.skipUnless(os.path.isfile(FREECAD_LIBRARY), "FreeCAD's tool library is not installed")
    def test_a_freecad_tool_library_replaces_the_shipped_crib(self):
        kb = knowledge_base.use_crib(os.path.join(self.tmp, "run.sqlite"), FREECAD_LIBRARY)
        tools = kb.tools()
        self.assertEqual(len(tools), 9)  # the library's bits, none of the shipped tools
        self.assertFalse([t for t in tools if t["id"].startswith(("EM-", "DR-"))])
        self.assertEqual(kb.table("edge_tool")["rows"], [])
        self.assertIn("7050-T7451", kb.workpiece_materials())  # the rest of the knowledge base stays

    def test_a_missing_crib_is_named(self):
        with self.assertRaises(KnowledgeBaseError) as e:
            knowledge_base.use_crib(os.path.join(self.tmp, "run.sqlite"), os.path.join(self.tmp, "nope.sqlite"))
        self.assertIn("nope.sqlite", str(e.exception))
        self.assertIn("is not a file", str(e.exception))

    def test_the_main_job_machines_with_the_users_crib_only(self):
        part = _plate(self.tmp)
        crib = _own_crib(self.tmp, {"EM-F12", "EM-F6"})
        before = _digest(crib)
        out = os.path.join(self.tmp, "out")
        run = main_job.run(part, out, cell_size=2.0, pictures=False, say=lambda _: None, crib=crib)
        self.assertEqual(run["crib"], os.path.abspath(crib))
        with open(os.path.join(out, "chain.json")) as f:
            chain = json.load(f)
        self.assertEqual(set(chain["tools"]), {"EM-F12", "EM-F6"})
        with open(os.path.join(out, "run.json")) as f:
            self.assertEqual(json.load(f)["crib"], os.path.abspath(crib))
        self.assertTrue(run["programs"])
        self.assertEqual(run["verificationReport"]["gouges"]["count"], 0)
        self.assertEqual(_digest(crib), before)
        # Without the crib the same plate takes the shipped tools (EM-F16 and larger fit the pocket).
        out2 = os.path.join(self.tmp, "out2")
        main_job.run(part, out2, cell_size=2.0, pictures=False, say=lambda _: None)
        with open(os.path.join(out2, "chain.json")) as f:
            self.assertNotEqual(set(json.load(f)["tools"]), {"EM-F12", "EM-F6"})


class LongReachTest(unittest.TestCase):
    """The optimiser's chip load for a long-reach tool is the reduced f_z (docs/tool-crib.md)."""

    def test_only_a_necked_tool_beyond_the_ratio_is_reduced(self):
        from aeronc.pipeline import cutting_optimisation
        tmp = tempfile.mkdtemp(prefix="aeronc_long_reach_")
        try:
            kb = knowledge_base.open_kb(os.path.join(tmp, "kb.sqlite"))
            self.assertEqual(cutting_optimisation.long_reach_fz_factor(kb, "EM-F6x30"), 0.8)
            self.assertEqual(cutting_optimisation.long_reach_fz_factor(kb, "EM-F6"), 1.0)  # no neck
            self.assertEqual(cutting_optimisation.long_reach_fz_factor(kb, "EM-F1.5"), 0.8)  # 5.3 x D
            # The threshold decides: at 6 diameters the 5 x D tool is no longer reduced.
            t = kb.table("threshold")
            row = t["rowIds"][[r[0] for r in t["rows"]].index("long_reach_ratio")]
            kb.edit_table("threshold", edits=[(row, "value", "6")])
            self.assertEqual(cutting_optimisation.long_reach_fz_factor(kb, "EM-F6x30"), 1.0)
        finally:
            shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    unittest.main()
