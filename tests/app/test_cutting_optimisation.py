"""Optimise cutting parameters on real Path Jobs, headless: the cut measured from a Pocket
operation's path, the ToolController written as one undo step and restored by undo, the
optimum checked against the plotted grid, and bad input leaving every ToolController as it was."""
import math
import os
import shutil
import tempfile
import unittest

import FreeCAD

from aeronc.pipeline import cutting_optimisation as co
from aeronc.pipeline import knowledge_base, tool_planning
from aeronc import makers, pathcompat
from aeronc.tests.app.support import end_mill, make_panel_object, make_pocket_job, new_document, temp_fcstd


def feeds(tc):
    return (tc.SpindleSpeed, tc.HorizFeed.getValueAs("mm/min").Value, tc.VertFeed.getValueAs("mm/min").Value)


class PocketJobTest(unittest.TestCase):
    """A 120 x 80 x 30 block with a 60 x 40 x 10 pocket, cleared by FreeCAD's Pocket Shape with
    a 10 mm three-flute carbide end mill: step-down 3 mm, step-over 50 %."""

    def setUp(self):
        self.doc = new_document("AeroNCOptimise")
        self.tmp = tempfile.mkdtemp(prefix="aeronc_opt_")
        self.kb_path = os.path.join(self.tmp, "kb.sqlite")
        self.part, self.job, self.pocket = make_pocket_job(self.doc)
        self.tc = pathcompat.create_tool_controller(self.doc, self.job, "TC: 10 mm end mill", end_mill(10), 2,
                                                    8000, 1200, 300)
        self.pocket.ToolController = self.tc
        self.doc.recompute()
        self.assertTrue(self.pocket.Path.Commands, "the pocket has a path")

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)
        shutil.rmtree(self.tmp, ignore_errors=True)

    def propose(self, target=None, **kw):
        kw.setdefault("material", "7050-T7451")
        kw.setdefault("machine", "AC-5AX")
        return co.propose(target or self.tc, kb_path=self.kb_path, **kw)

    def test_the_cut_is_measured_from_the_pocket_path(self):
        [p] = self.propose()
        self.assertEqual(p.error, "")
        [cut] = p.cuts
        self.assertIs(cut.op, self.pocket)
        # Levels 28, 25, 22 and the floor at 20 below the start depth 31 (the stock's top): the
        # largest step is 3.
        self.assertAlmostEqual(cut.a_p, 3.0, places=6)
        self.assertAlmostEqual(cut.a_e, 5.0, places=6)  # 50 % of 10 mm
        # Every level clears at least the 40 x 20 mm core of the pocket.
        self.assertEqual(self.pocket.StartDepth.Value, 31.0)
        self.assertGreater(cut.length, 4 * 2 * (40 + 20))
        self.assertEqual(p.params["cutter"]["teeth"], 3)
        self.assertEqual(p.tool_material, "carbide")
        self.assertEqual(p.operation, "roughing")  # a clearing operation
        self.assertAlmostEqual(p.params["cutter"]["corner_radius_mm"], 5.0)  # flat end: r = D/2

    def test_chip_load_from_the_knowledge_base_or_the_bit(self):
        kb = knowledge_base.open_kb(self.kb_path)
        fz = kb.cutting_condition("7050-T7451", "carbide", "roughing", 10.0)["fz"]
        [p] = self.propose()
        self.assertAlmostEqual(p.params["cutter"]["max_chip_load_mm"], co.CHIP_LOAD_FACTOR * fz)
        # Nothing else limits f_z of a 10 mm end mill in aluminium on a 25 kW spindle.
        self.assertIn("chip load (tool) f_z,max", p.optimum["active"])
        self.assertAlmostEqual(p.optimum["f_z_mm"], co.CHIP_LOAD_FACTOR * fz, places=9)
        self.tc.Tool.Chipload = "0.05 mm"  # the tool maker's figure wins
        [p] = self.propose()
        self.assertAlmostEqual(p.optimum["f_z_mm"], 0.05, places=9)

    def test_optimum_is_feasible_and_no_grid_point_beats_it(self):
        [p] = self.propose(map_points=81)
        best = p.optimum
        self.assertTrue(best["feasible"])
        for c in best["constraints"]:
            self.assertLessEqual(c["utilisation"], 1 + 1e-9, c["name"])
        self.assertTrue(best["active"])
        m = p.result["map"]
        feasible = [(v, n, fz) for row, oks, fz in zip(m["objective"], m["feasible"], m["f_z_mm"])
                    for v, ok, n in zip(row, oks, m["n_rpm"]) if ok]
        self.assertGreater(len(feasible), 50)
        self.assertGreaterEqual(min(v for v, _, _ in feasible), best["objective"] * (1 - 1e-3))
        # What is written is the optimum: n, v_f = f_z Z n, and the plunge at the knowledge base's ratio.
        kb = knowledge_base.open_kb(self.kb_path)
        self.assertAlmostEqual(p.horiz_feed, best["f_z_mm"] * 3 * best["n_rpm"], places=6)
        self.assertAlmostEqual(p.vert_feed, p.horiz_feed * kb.threshold("plunge_feed_ratio"), places=6)

    def test_writes_the_tool_controller_and_undo_restores_it(self):
        before = feeds(self.tc)
        [p] = self.propose()
        self.assertEqual(feeds(self.tc), before, "propose writes nothing")
        co.apply([p])
        after = feeds(self.tc)
        self.assertAlmostEqual(after[0], p.spindle_rpm, places=6)
        self.assertAlmostEqual(after[1], p.horiz_feed, places=3)
        self.assertAlmostEqual(after[2], p.vert_feed, places=3)
        self.assertNotAlmostEqual(after[0], before[0], places=0)
        self.assertIn("active:", self.tc.CuttingOptimum)
        # The pocket was recomputed with the new feed (Path's F is in mm/s).
        fs = {round(c.Parameters["F"], 6) for c in self.pocket.Path.Commands
              if c.Name in ("G1", "G2", "G3") and "F" in c.Parameters}
        self.assertIn(round(self.tc.HorizFeed.Value, 6), fs)
        self.assertEqual(self.doc.UndoNames[0], "Optimise cutting parameters")
        self.doc.undo()
        for a, b in zip(feeds(self.tc), before):
            self.assertAlmostEqual(a, b, places=6)
        self.doc.redo()
        self.assertAlmostEqual(feeds(self.tc)[0], p.spindle_rpm, places=6)

    def test_saved_and_reopened(self):
        co.optimise(self.tc, "7050-T7451", "AC-5AX", kb_path=self.kb_path)
        written, summary = feeds(self.tc), self.tc.CuttingOptimum
        path = temp_fcstd("optimised")
        self.doc.saveAs(path)
        FreeCAD.closeDocument(self.doc.Name)
        self.doc = FreeCAD.openDocument(path)
        tc = [o for o in self.doc.Objects if pathcompat.is_tool_controller(o) and o.Label == "TC: 10 mm end mill"][0]
        for a, b in zip(feeds(tc), written):
            self.assertAlmostEqual(a, b, places=3)
        self.assertEqual(tc.CuttingOptimum, summary)

    def test_infeasible_names_the_limit_and_writes_nothing(self):
        before = feeds(self.tc)
        [p] = self.propose(ra_max={"roughing": 0.0001})
        self.assertFalse(p.ok)
        self.assertIn("infeasible", p.error)
        self.assertIn("roughness", p.error)
        self.assertIn("raise R_a,max", p.error)
        with self.assertRaisesRegex(co.CuttingOptimisationError, "nothing to write.*roughness"):
            co.apply([p])
        self.assertEqual(feeds(self.tc), before)
        self.assertFalse(hasattr(self.tc, co.RESULT_PROPERTY))

    def test_missing_teeth_and_material_are_named(self):
        before = feeds(self.tc)
        self.tc.Tool.Flutes = 0
        [p] = self.propose()
        self.assertRegex(p.error, "no number of teeth; set Flutes")
        self.tc.Tool.Flutes = 3
        with self.assertRaisesRegex(co.CuttingOptimisationError, "unknown workpiece material 'unobtainium'"):
            self.propose(material="unobtainium")
        with self.assertRaisesRegex(co.CuttingOptimisationError, "no workpiece material"):
            self.propose(material="")
        self.assertEqual(feeds(self.tc), before)

    def test_non_physical_tool_is_refused(self):
        self.tc.Tool.Diameter = 0
        [p] = self.propose()
        self.assertRegex(p.error, "no positive Diameter")
        with self.assertRaises(co.CuttingOptimisationError):
            co.apply([p])

    def test_whole_job_skips_drilling_and_writes_one_step(self):
        drill = pathcompat.create_tool_controller(self.doc, self.job, "TC: 6.6 mm drill", {
            "version": 2, "name": "6.6 mm drill", "shape": "drill.fcstd",
            "parameter": {"Diameter": "6.6 mm", "Length": "60 mm", "TipAngle": "118 deg"},
            "attribute": {"Flutes": 2, "Material": "Carbide"}}, 3, 3000, 200, 200)
        proposals = self.propose(self.job)
        by_tc = {p.tc.Name: p for p in proposals}
        # The Job's default controller (5 mm, FreeCAD's bit without Flutes) cannot be optimised.
        default = [tc for tc in pathcompat.tool_controllers(self.job) if tc not in (self.tc, drill)]
        self.assertEqual(len(default), 1)
        self.assertIn("Flutes", by_tc[default[0].Name].error)
        self.assertTrue(by_tc[self.tc.Name].ok)
        self.assertTrue(by_tc[drill.Name].skipped)
        self.assertIn("drill", by_tc[drill.Name].error)
        snapshot = {tc.Name: feeds(tc) for tc in pathcompat.tool_controllers(self.job)}
        written = co.apply(proposals)
        self.assertIn(self.tc, written)
        self.assertEqual(feeds(default[0]), snapshot[default[0].Name])
        self.assertEqual(self.doc.UndoNames[0], "Optimise cutting parameters")
        self.doc.undo()
        for tc in pathcompat.tool_controllers(self.job):
            for a, b in zip(feeds(tc), snapshot[tc.Name]):
                self.assertAlmostEqual(a, b, places=6)


class ChainToolControllersTest(unittest.TestCase):
    """The ToolControllers the machining chain makes in its Jobs carry the optimiser's speeds and
    feeds for their tool and operation at the knowledge base's a_p and a_e, the same in every
    Job; optimising a chain Job afterwards takes the cut from its operations' paths."""

    def test_chain_jobs_carry_the_optimum_then_optimise_from_their_paths(self):
        from aeronc.pipeline import chain_building
        doc = new_document("AeroNCOptimiseChain")
        tmp = tempfile.mkdtemp(prefix="aeronc_opt_")
        material, machine = "7050-T7451", "AC-5AX"
        try:
            kb_path = os.path.join(tmp, "kb.sqlite")
            part, _ = make_panel_object(doc, {"pocketsX": 2, "pocketsY": 1, "bottomPockets": True})
            group = makers.create_machining_features(doc, part, directions=[(0, 0, 1), (0, 0, -1)])
            tool_planning.select_tools(group, material, machine=machine, kb_path=kb_path)
            chain = chain_building.build(group, "integral_panel", material, machine, kb_path)
            self.assertGreaterEqual(len(chain.Jobs), 2)
            kb = knowledge_base.open_kb(kb_path)
            tools = {t["id"]: t for t in kb.tools()}
            by_tag, moved = {}, set()
            for job in chain.Jobs:
                for tc in pathcompat.tool_controllers(job):
                    by_tag.setdefault(tc.AeroNCTool, []).append(tc)
            milled = [tag for tag in by_tag if not tag.endswith("/drilling")]
            self.assertTrue(milled)
            self.assertTrue(any(len(tcs) > 1 for tcs in by_tag.values()), "a tool used in both setups")
            for tag, tcs in by_tag.items():
                tool_id, op = tag.split("/")
                if tool_id not in tools:  # a chamfer mill (the edge tools' own table): the optimiser's
                    for tc in tcs:        # model is an end mill's, so it keeps the knowledge base's data
                        self.assertNotIn(co.RESULT_PROPERTY, tc.PropertiesList)
                    continue
                t = tools[tool_id]
                if op == "drilling":  # the milling model does not describe a drill: the knowledge base's
                    for tc in tcs:
                        self.assertNotIn(co.RESULT_PROPERTY, tc.PropertiesList)
                    continue
                # By hand: the optimiser's answer for a controller no operation uses.
                expected = co.propose_one(tcs[0], [], kb, material, machine)
                self.assertTrue(expected.ok, expected.error)
                cc = kb.cutting_condition(material, t["material"], op, t["diameter"])
                self.assertAlmostEqual(expected.result["parameters"]["cut"]["a_p_mm"], cc["ap"])
                self.assertAlmostEqual(expected.params["cut"]["a_e_mm"], cc["aeRatio"] * t["diameter"])
                n = 1000 * cc["vc"] / (math.pi * t["diameter"])
                for tc in tcs:
                    self.assertIn(co.RESULT_PROPERTY, tc.PropertiesList)
                    self.assertAlmostEqual(tc.SpindleSpeed, expected.spindle_rpm, places=6)
                    self.assertAlmostEqual(feeds(tc)[1], expected.horiz_feed, places=3)
                    self.assertLessEqual(tc.SpindleSpeed, 18000 * (1 + 1e-9))
                    if abs(tc.SpindleSpeed - min(n, 18000)) > 1e-6:
                        moved.add(tag)
            self.assertTrue(moved, "the optimiser moved some spindle speed off the knowledge base's n")
            # The paths were computed at those feeds: the first cutting move's F is the controller's.
            job = chain.Jobs[0]
            op = [o for o in pathcompat.tooled_operations(job) if not pathcompat.is_hole_operation(o)][0]
            tc = pathcompat.tool_controller_of(op)
            fs = [c.Parameters["F"] for c in op.Path.Commands if c.Name in ("G1", "G01") and "F" in c.Parameters]
            self.assertTrue(fs)
            self.assertAlmostEqual(max(fs) * 60.0, max(feeds(tc)[1:]), places=3)

            # Optimised again from its operations: the cut comes from the paths.
            proposals = co.propose(job, kb_path=kb_path)
            used = [p for p in proposals if p.ok and p.cuts]
            self.assertTrue(used)
            before = {p.tc.Name: feeds(p.tc) for p in proposals}
            co.apply(proposals)
            self.assertTrue([p for p in used if abs(feeds(p.tc)[0] - before[p.tc.Name][0]) > 1e-6])
            doc.undo()
            for p in proposals:
                self.assertEqual(feeds(p.tc), before[p.tc.Name])
        finally:
            FreeCAD.closeDocument(doc.Name)
            shutil.rmtree(tmp, ignore_errors=True)


if __name__ == "__main__":
    unittest.main()
