"""The machining chain in FreeCAD, headless: one Job per setup placed by the setup frame with
the blank as stock, an operation for every unit in chain order, every element machined or
listed with a reason, save and reopen, undo, bad input leaving the document as it was, the
user's edits surviving an update and a rebuild; on a generated double-sided panel (whose
geometry is known) and on the sample panel."""
import json
import os
import shutil
import tempfile
import unittest

import FreeCAD
import Part

import aeronc
from aeronc.pipeline import chain_edits, chain_building, setup_job
from aeronc import makers, operations, pathcompat
from aeronc.objects import machining_chain as chain_object
from aeronc.objects import machining_features
from aeronc.tests.app.support import make_panel_object, new_document, temp_fcstd

FAMILY = "integral_panel"
MATERIAL = "7050-T7451"
DOUBLE = {"pocketsX": 2, "pocketsY": 2, "bottomPockets": True, "joggles": False}
SAMPLE = os.path.join(aeronc.PACKAGE_DIR, "resources", "samples", "sample_panel.step")
SHARED_DATA = os.environ.get("AERONC_SHARED_DATA", "")
NIST_PARTS = ["nist_ftc_07_asme1_rd.stp", "nist_ctc_01_asme1_ap203.stp"]


def names(doc):
    return set(o.Name for o in doc.Objects)


def _inside(p, loop):
    inside = False
    for (x0, y0), (x1, y1) in zip(loop, loop[1:] + loop[:1]):
        if (y0 > p[1]) != (y1 > p[1]) and p[0] < x0 + (p[1] - y0) * (x1 - x0) / (y1 - y0):
            inside = not inside
    return inside


def _distance(p, loop):
    best = float("inf")
    for (x0, y0), (x1, y1) in zip(loop, loop[1:] + loop[:1]):
        dx, dy = x1 - x0, y1 - y0
        t = max(0.0, min(1.0, ((p[0] - x0) * dx + (p[1] - y0) * dy) / (dx * dx + dy * dy or 1.0)))
        best = min(best, ((p[0] - x0 - t * dx) ** 2 + (p[1] - y0 - t * dy) ** 2) ** 0.5)
    return best


def job_ops(job):
    return [op for op in pathcompat.job_operations(job) if operations.is_machining_operation(op)]


def moves_of(op):
    """(name, x, y, z) of the op's motion commands, the position carried over."""
    out, pos = [], [None, None, None]
    for c in op.Path.Commands:
        p = c.Parameters
        if c.Name in ("G0", "G1", "G81", "G82", "G83"):
            pos = [p.get(k, pos[i]) for i, k in enumerate("XYZ")]
            out.append((c.Name,) + tuple(pos))
    return out


class ChainFixture:
    """A document with a recognised part and a temporary knowledge base."""

    def make(self, part_maker, directions=None):
        self.tmp = tempfile.mkdtemp(prefix="aeronc_chain_")
        self.kb_path = os.path.join(self.tmp, "kb.sqlite")
        self.doc = new_document("AeroNCChain")
        self.part, self.truth = part_maker(self.doc)
        self.group = makers.create_machining_features(self.doc, self.part, directions=directions)

    def build(self, **kw):
        return chain_building.build(self.group, FAMILY, MATERIAL, kb_path=self.kb_path, **kw)

    def close(self):
        FreeCAD.closeDocument(self.doc.Name)
        shutil.rmtree(self.tmp, ignore_errors=True)


def _double_sided(doc):
    return make_panel_object(doc, DOUBLE)


def _sample(doc):
    part = doc.addObject("Part::Feature", "SamplePanel")
    part.Shape = Part.read(SAMPLE)
    doc.recompute()
    return part, None


class DoubleSidedPanelTest(unittest.TestCase, ChainFixture):
    def setUp(self):
        self.make(_double_sided)

    def tearDown(self):
        self.close()

    def test_one_job_per_setup_placed_by_its_frame(self):
        chain = self.build()
        data = chain_object.chain_of(chain)
        setups = data["setups"]
        self.assertEqual(sorted(s["name"] for s in setups), ["+Z", "-Z"])
        self.assertEqual(len(chain.Jobs), 2)
        bb = self.part.Shape.BoundBox
        x0, y0, z0, x1, y1, z1 = bb.XMin, bb.YMin, bb.ZMin, bb.XMax, bb.YMax, bb.ZMax
        for job in chain.Jobs:
            setup = next(s for s in setups if s["id"] == getattr(job, setup_job.SETUP_TAG))
            model = pathcompat.job_models(job)[0].Shape.BoundBox
            stock = job.Stock.Shape.BoundBox
            got_model = (model.XMin, model.YMin, model.ZMin, model.XMax, model.YMax, model.ZMax)
            got_stock = (stock.XMin, stock.YMin, stock.ZMin, stock.XMax, stock.YMax, stock.ZMax)
            if setup["name"] == "+Z":
                want = (x0, y0, z0, x1, y1, z1)
            else:  # 180 degrees about X: (x, y, z) -> (x, -y, -z)
                want = (x0, -y1, -z1, x1, -y0, -z0)
            for g, w in zip(got_model, want):
                self.assertAlmostEqual(g, w, places=6)
            # The blank: the part's box (no allowance), seen in the same frame.
            for g, w in zip(got_stock, want):
                self.assertAlmostEqual(g, w, places=6)
            # FreeCAD's Post command writes what the main job writes: AeroNC's post for the
            # machine, the blank centred on the table.
            self.assertEqual(job.PostProcessor, "aeronc_840d")
            zero = [-(want[0] + want[3]) / 2, -(want[1] + want[4]) / 2, -want[2]]
            self.assertIn("--machine {} --part-zero=".format(chain.Machine), job.PostProcessorArgs)
            given = [float(v) for v in job.PostProcessorArgs.split("--part-zero=")[1].split(",")]
            for g, w in zip(given, zero):
                self.assertAlmostEqual(g, w, places=5)
        # The truth's -Z pockets: in the -Z Job just above the floor is air, just below is part.
        job = next(j for j in chain.Jobs if getattr(j, setup_job.SETUP_TAG) ==
                   next(s["id"] for s in setups if s["name"] == "-Z"))
        model = pathcompat.job_models(job)[0].Shape
        bottom = [t for t in self.truth["elements"] if t["setup"] == 1 and t["type"] == "closed_pocket"]
        self.assertTrue(bottom)
        for t in bottom:
            x, y = t["point"][0], -t["point"][1]
            floor = t["level"]  # height along -Z of the floor
            self.assertFalse(model.isInside(FreeCAD.Vector(x, y, floor + 0.5), 1e-6, True), t)
            self.assertTrue(model.isInside(FreeCAD.Vector(x, y, floor - 0.5), 1e-6, True), t)

    def test_an_operation_for_every_unit_in_chain_order(self):
        chain = self.build()
        data = chain_object.chain_of(chain)
        units = chain_edits.units_by_id(data)
        order = [int(u) for u in data["order"]]
        self.assertEqual(sorted(order), sorted(units))
        seen = []
        for job in chain.Jobs:
            sid = getattr(job, setup_job.SETUP_TAG)
            ops = job_ops(job)
            self.assertEqual([op.UnitId for op in ops], [u for u in order if units[u]["setup"] == sid])
            for op in ops:
                unit = units[op.UnitId]
                self.assertIs(type(op.Proxy), operations.operation_class(unit["operation"]))
                self.assertEqual(op.ElementId, unit["element"])
                self.assertTrue(op.Active)
                self.assertEqual(op.ToolController.AeroNCTool.split("/")[0], unit["tool"])
                self.assertIn(op.ToolController, pathcompat.tool_controllers(job))
                self.assertGreater(len(moves_of(op)), 1, op.Label)
                seen.append(op.UnitId)
        self.assertEqual(sorted(seen), sorted(units))

    def test_every_element_machined_or_unmachined_with_a_reason(self):
        chain = self.build()
        data = chain_object.chain_of(chain)
        elements = {e["id"] for e in machining_features.result_of(self.group)["elements"]}
        machined = {op.ElementId for op in chain_building.chain_operations(chain)}
        unmachined = {u["element"] for u in data["unmachined"]}
        self.assertEqual(machined | unmachined, elements)
        for entry in data["unmachined"]:
            self.assertTrue(entry["reason"].strip(), entry)
        self.assertEqual(len(chain.Unmachined), len(data["unmachined"]))

    def test_paths_stay_in_the_stock_and_above_the_units_floor(self):
        # Tool-centre positions: within the stock grown by the tool's diameter and the radial
        # allowance (its radius, a lead of that radius and the allowance outside a profiled
        # wall), never below the unit's floor plus its axial allowance, never
        # above the clearance height. A frame mix-up (-Z geometry in +Z) would leave the stock.
        chain = self.build()
        for job in chain.Jobs:
            bb = job.Stock.Shape.BoundBox
            for op in job_ops(job):
                unit = json.loads(op.Unit)
                d = op.ToolController.Tool.Diameter.Value + 1e-6
                d += max(0.0, op.RadialAllowance.Value) if hasattr(op, "RadialAllowance") else 0.0
                moves = moves_of(op)
                self.assertTrue([m for m in moves if m[0] != "G0"], op.Label)
                for name, x, y, z in moves:
                    self.assertTrue(bb.XMin - d <= x <= bb.XMax + d and bb.YMin - d <= y <= bb.YMax + d,
                                    (op.Label, name, x, y, bb))
                    self.assertLessEqual(z, op.ClearanceHeight.Value + 1e-6, (op.Label, name, z))
                    if name == "G1" and "bottom" in unit:
                        self.assertGreaterEqual(z, unit["bottom"] + unit.get("axialAllowance", 0) - 1e-6,
                                                (op.Label, z))

    def test_pockets_and_profiles_keep_off_the_walls(self):
        # A closed pocket's walls are its contour and islands: every cutting move of its pocket,
        # corner and profile units stays inside the contour and outside the islands, the tool's
        # radius and the radial allowance away: no gouge. Less 0.02 mm: the generator writes
        # offset arcs as chords within its chord tolerance (0.01 mm), and the region a tool
        # centre may reach is an offset of an offset (measured: 0.013 mm at worst).
        chain = self.build()
        checked = 0
        for op in chain_building.chain_operations(chain):
            unit = json.loads(op.Unit)
            if unit["operation"] not in ("pocket", "rest", "profile") or unit["openEdges"]:
                continue
            keep = op.ToolController.Tool.Diameter.Value / 2 + op.RadialAllowance.Value - 0.02
            contour, islands = unit["contour"], unit["islands"]
            # An island stopping short of the top is material to clear above its top plus the
            # floor's allowance; a floor unit faces such tops, so its moves reach up to them.
            tops = unit.get("islandTops") or [None] * len(islands)
            aa = op.AxialAllowance.Value if hasattr(op, "AxialAllowance") else 0.0
            top = unit["top"]
            if unit.get("faceIslandTops"):
                top = max([top] + [t + unit["top"] - unit["bottom"] for t in tops if t is not None])
            for name, x, y, z in moves_of(op):
                if name == "G0" or z > top - 1e-6:
                    continue
                self.assertTrue(_inside((x, y), contour), (op.Label, x, y, z))
                self.assertGreaterEqual(_distance((x, y), contour), keep, (op.Label, x, y, z))
                for island, t in zip(islands, tops):
                    if t is not None and z >= t + aa - 1e-6:
                        continue
                    self.assertFalse(_inside((x, y), island), (op.Label, x, y, z))
                    self.assertGreaterEqual(_distance((x, y), island), keep, (op.Label, x, y, z))
                checked += 1
        self.assertGreater(checked, 100)

    def test_save_reopen_keeps_everything_and_paths_recompute_identically(self):
        chain = self.build()
        gcode = {op.Name: op.Path.toGCode() for op in chain_building.chain_operations(chain)}
        self.assertTrue(gcode)
        props = (chain.Chain, chain.Built, chain.Edits, chain.UnitCount, [j.Name for j in chain.Jobs])
        name = chain.Name
        path = temp_fcstd("chain")
        self.doc.saveAs(path)
        FreeCAD.closeDocument(self.doc.Name)
        self.doc = FreeCAD.openDocument(path)
        chain = self.doc.getObject(name)
        self.assertTrue(chain_object.is_machining_chain(chain))
        self.assertEqual((chain.Chain, chain.Built, chain.Edits, chain.UnitCount, [j.Name for j in chain.Jobs]), props)
        ops = chain_building.chain_operations(chain)
        self.assertEqual(sorted(op.Name for op in ops), sorted(gcode))
        for op in ops:
            self.assertEqual(op.Path.toGCode(), gcode[op.Name])
            op.touch()
        self.doc.recompute()
        for op in ops:
            self.assertEqual(op.UserEdited, [])  # reopening is not an edit
            self.assertEqual(op.Path.toGCode(), gcode[op.Name], op.Label)

    def test_tool_controllers_optimised_once_and_kept_across_a_rebuild(self):
        """The chain's ToolControllers come with the optimiser's speeds and feeds (its record on
        each); a Job keeps its controllers across a rebuild, a speed set by hand included, and
        no value travels from one Job to another."""
        from aeronc.pipeline.cutting_optimisation import RESULT_PROPERTY
        built = chain_building.compute(self.group, FAMILY, MATERIAL, kb_path=self.kb_path)
        chain = self.build(built=built)
        tcs = [tc for job in chain.Jobs for tc in pathcompat.tool_controllers(job)]
        # Drills and chamfer mills keep the knowledge base's data: the optimiser's model is an end mill's.
        chamfer_mills = {u["tool"] for u in built["units"] if u["operation"] == "chamfer"}
        milled = [tc for tc in tcs if not tc.AeroNCTool.endswith("/drilling")
                  and tc.AeroNCTool.split("/")[0] not in chamfer_mills]
        self.assertTrue(milled)
        for tc in milled:
            self.assertIn(RESULT_PROPERTY, tc.PropertiesList, tc.Label)
        tags = [tc.AeroNCTool for tc in milled]
        shared = [t for t in tags if tags.count(t) > 1]
        self.assertTrue(shared, "a tool and operation in two setups")
        first, other = [tc for tc in milled if tc.AeroNCTool == shared[0]][:2]
        self.assertAlmostEqual(first.SpindleSpeed, other.SpindleSpeed)
        optimum = other.SpindleSpeed
        first.SpindleSpeed = 1234.5  # the programmer's value
        names = sorted(tc.Name for tc in tcs)
        chain = self.build(built=built)
        self.assertEqual(sorted(tc.Name for job in chain.Jobs for tc in pathcompat.tool_controllers(job)), names)
        self.assertAlmostEqual(first.SpindleSpeed, 1234.5)
        self.assertAlmostEqual(other.SpindleSpeed, optimum)

    def test_the_chain_takes_the_tools_select_tools_stored(self):
        """The chain reads the tool plan Select tools stored on the group (ToolPlan) instead of
        planning the tools again: a finishing tool changed in the stored plan finishes the walls."""
        from aeronc.pipeline import knowledge_base, tool_planning
        tool_planning.select_tools(self.group, MATERIAL, kb_path=self.kb_path)
        fresh = chain_building.compute(self.group, FAMILY, MATERIAL, kb_path=self.kb_path)
        plan = json.loads(self.group.ToolPlan)
        kb = knowledge_base.open_kb(self.kb_path)
        depth = {e["id"]: e["depth"] for e in machining_features.result_of(self.group)["elements"]}

        def finishes(t):
            try:
                return bool(kb.cutting_condition(MATERIAL, t["material"], "finishing", t["diameter"]))
            except RuntimeError:
                return False

        def walls(chain, element):
            return {u["tool"] for u in chain["units"] if u["element"] == element and u["step"] == "fs"}

        for e in plan["elements"]:
            if e["type"] != "closed_pocket" or not e["finishingTool"] or not e["roughingTool"]:
                continue
            was = e["finishingTool"]
            smaller = [t for t in kb.tools() if t["type"] == "flat" and 4 <= t["diameter"] < plan["tools"][was]["diameter"]
                       and min(t["fluteLength"], t["reach"]) > depth[e["id"]] + 1 and finishes(t)]
            if smaller:
                break
        else:
            self.fail("no pocket whose finishing tool has a smaller one to take its place")
        now = max(smaller, key=lambda t: t["diameter"])["id"]
        e["finishingTool"] = now
        self.group.ToolPlan = json.dumps(plan)
        stored = chain_building.compute(self.group, FAMILY, MATERIAL, kb_path=self.kb_path)
        self.assertEqual(walls(fresh, e["id"]), {was})
        self.assertEqual(walls(stored, e["id"]), {now})
        # A plan made for another material is not taken: the tools are planned for this one.
        other = chain_building.compute(self.group, FAMILY, "2024-T351", kb_path=self.kb_path)
        self.assertEqual(other["material"], "2024-T351")

    def test_undo_removes_it_all(self):
        before = names(self.doc)
        self.build()
        self.assertGreater(len(names(self.doc)), len(before))
        self.doc.undo()
        self.assertEqual(names(self.doc), before)

    def test_outdated_group_is_refused_and_nothing_changes(self):
        self.part.Shape = self.part.Shape.cut(Part.makeCylinder(2, 40, FreeCAD.Vector(6, 40, -10)))  # a hole in the border
        self.doc.recompute()
        before, undo = names(self.doc), self.doc.UndoCount
        with self.assertRaises(chain_building.MachiningChainError) as ctx:
            self.build()
        self.assertIn("changed since its features were recognised", str(ctx.exception))
        self.assertEqual(names(self.doc), before)
        self.assertEqual(self.doc.UndoCount, undo)

    def test_user_edits_survive_an_update_and_a_rebuild(self):
        chain = self.build()
        data = chain_object.chain_of(chain)
        pocket = next(op for op in chain_building.chain_operations(chain) if op.Operation == "pocket")
        step_down = pocket.StepDown.Value / 2
        pocket.StepDown = step_down
        self.assertEqual(pocket.UserEdited, ["StepDown"])
        # A program with two units or more to reorder, a unit to disable, another to give another tool.
        program = next(p for _, _, _, p in chain_edits.programs(data) if len(p["units"]) >= 2)
        first, second = [int(u) for u in program["units"][:2]]
        edits = chain_edits.moved(data, {}, second, -1)
        disabled = int(data["order"][-1])
        edits = chain_edits.with_enabled(edits, disabled, False)
        units = chain_edits.units_by_id(data)
        other = None
        for uid in data["order"]:
            u = units[int(uid)]
            smaller = [tid for tid, t in sorted(data["tools"].items()) if t["type"] in ("flat", "bull")
                       and t["diameter"] < u["cutter"]["diameter"]]
            if u["operation"] == "pocket" and smaller and int(uid) not in (first, second, disabled):
                other = (int(uid), smaller[0])
                break
        self.assertIsNotNone(other)
        edits = chain_edits.with_tool(edits, data, other[0], other[1])
        before_update = self.doc.UndoCount
        chain = chain_building.update(chain, edits)
        self.assertEqual(self.doc.UndoCount, before_update + 1)
        ops = {op.UnitId: op for op in chain_building.chain_operations(chain)}
        self.assertAlmostEqual(ops[pocket.UnitId].StepDown.Value, step_down)
        self.assertFalse(ops[disabled].Active)
        self.assertEqual(ops[other[0]].ToolController.AeroNCTool.split("/")[0], other[1])
        job = next(j for j in chain.Jobs if ops[first] in pathcompat.job_operations(j))
        ids = [op.UnitId for op in job_ops(job)]
        self.assertLess(ids.index(second), ids.index(first))

        # A rebuild from the group computes the chain again; the edits and the hand edit stay.
        chain = self.build()
        ops = {op.UnitId: op for op in chain_building.chain_operations(chain)}
        self.assertAlmostEqual(ops[pocket.UnitId].StepDown.Value, step_down)
        self.assertIn("StepDown", ops[pocket.UnitId].UserEdited)
        self.assertFalse(ops[disabled].Active)
        self.assertEqual(ops[other[0]].Tool, other[1])
        ids = [op.UnitId for op in job_ops(job)]
        self.assertLess(ids.index(second), ids.index(first))
        self.assertTrue(any("StepDown kept" in m for m in chain.Messages), chain.Messages)


class BadInputTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="aeronc_chain_")
        self.kb_path = os.path.join(self.tmp, "kb.sqlite")
        self.doc = new_document("AeroNCChainBad")

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)
        shutil.rmtree(self.tmp, ignore_errors=True)

    def test_a_part_with_no_domain_element(self):
        block = self.doc.addObject("Part::Feature", "Block")
        block.Shape = Part.makeBox(50, 40, 10)
        self.doc.recompute()
        group = makers.create_machining_features(self.doc, block, directions=[(0, 0, 1)])
        self.assertEqual(machining_features.result_of(group)["elements"], [])
        before, undo = names(self.doc), self.doc.UndoCount
        with self.assertRaises(chain_building.MachiningChainError) as ctx:
            chain_building.build(group, FAMILY, MATERIAL, kb_path=self.kb_path)
        self.assertIn("no domain element", str(ctx.exception))
        self.assertEqual(names(self.doc), before)
        self.assertEqual(self.doc.UndoCount, undo)

    def test_not_a_group_and_an_unknown_material(self):
        part, _ = make_panel_object(self.doc, {"pocketsX": 1, "pocketsY": 1})
        with self.assertRaises(chain_building.MachiningChainError) as ctx:
            chain_building.build(part, FAMILY, MATERIAL, kb_path=self.kb_path)
        self.assertIn("is not a Machining Features group", str(ctx.exception))
        group = makers.create_machining_features(self.doc, part, directions=[(0, 0, 1)])
        before = names(self.doc)
        with self.assertRaises(chain_building.MachiningChainError) as ctx:
            chain_building.build(group, FAMILY, "unobtainium", kb_path=self.kb_path)
        self.assertIn("unobtainium", str(ctx.exception))
        self.assertEqual(names(self.doc), before)


class SamplePanelTest(unittest.TestCase, ChainFixture):
    @classmethod
    def setUpClass(cls):
        fixture = ChainFixture()
        fixture.make(_sample)
        cls.fixture = fixture
        cls.chain = fixture.build()

    @classmethod
    def tearDownClass(cls):
        cls.fixture.close()

    def test_every_element_machined_or_listed_and_ops_in_order(self):
        data = chain_object.chain_of(self.chain)
        elements = {e["id"] for e in machining_features.result_of(self.fixture.group)["elements"]}
        ops = chain_building.chain_operations(self.chain)
        unmachined = {u["element"] for u in data["unmachined"] if u.get("reason")}
        self.assertEqual({op.ElementId for op in ops} | unmachined, elements)
        self.assertEqual(len(ops), len(data["units"]))
        order = [int(u) for u in data["order"]]
        for job in self.chain.Jobs:
            ids = [op.UnitId for op in job_ops(job)]
            self.assertEqual(ids, [u for u in order if u in set(ids)])
        kinds = {type(op.Proxy).__name__ for op in ops}
        self.assertIn("GeneralisedPocket", kinds)
        self.assertEqual([op.Label for op in ops if "Invalid" in op.State or not op.Path.Commands], [],
                         self.chain.Messages)
        self.assertTrue(kinds & {"Drilling", "HelicalInterpolation"}, kinds)

    def test_drilling_writes_path_drill_cycles(self):
        drills = [op for op in chain_building.chain_operations(self.chain) if type(op.Proxy).__name__ == "Drilling"]
        self.assertTrue(drills)
        for op in drills:
            cycles = [c for c in op.Path.Commands if c.Name in ("G81", "G82", "G83")]
            self.assertTrue(cycles, op.Label)
            holes = json.loads(op.Unit)["holes"]
            self.assertEqual(len(cycles), len(holes), op.Label)
            for c in cycles:
                p = c.Parameters
                self.assertTrue({"X", "Y", "Z", "R", "F"} <= set(p), p)
                hole = next(h for h in holes if abs(h["u"] - p["X"]) < 1e-6 and abs(h["v"] - p["Y"]) < 1e-6)
                self.assertGreater(p["R"], hole["top"])  # the cycle starts above the hole
                self.assertLessEqual(p["Z"], hole["bottom"] + 1e-6)  # and reaches its bottom
            self.assertIn("G80", [c.Name for c in op.Path.Commands])



@unittest.skipUnless(os.path.isdir(os.path.join(SHARED_DATA, "nist")), "the NIST parts (env AERONC_SHARED_DATA)")
class NistPartsTest(unittest.TestCase):
    """Real parts: an operation for every unit in chain order, every element machined or listed
    with a reason, every path in its Job's stock (grown by the tool) and Job frame."""

    def test_nist_parts(self):
        for name in NIST_PARTS:
            with self.subTest(part=name):
                fixture = ChainFixture()

                def read(doc, name=name):
                    part = doc.addObject("Part::Feature", "Nist")
                    part.Shape = Part.read(os.path.join(SHARED_DATA, "nist", name))
                    doc.recompute()
                    return part, None

                fixture.make(read)
                try:
                    chain = fixture.build()
                    data = chain_object.chain_of(chain)
                    ops = chain_building.chain_operations(chain)
                    self.assertEqual(sorted(op.UnitId for op in ops), sorted(u["id"] for u in data["units"]))
                    order = [int(u) for u in data["order"]]
                    for job in chain.Jobs:
                        ids = [op.UnitId for op in job_ops(job)]
                        self.assertEqual(ids, [u for u in order if u in set(ids)])
                    elements = {e["id"] for e in machining_features.result_of(fixture.group)["elements"]}
                    self.assertEqual({op.ElementId for op in ops} | {u["element"] for u in data["unmachined"]}, elements)
                    for job in chain.Jobs:
                        bb = job.Stock.Shape.BoundBox
                        for op in job_ops(job):
                            a = max(0.0, op.RadialAllowance.Value if hasattr(op, "RadialAllowance") else 0.0)
                            # The tool's axis runs R + a off the wall, more near a floor fillet wider than
                            # its corner; a quarter-arc lead of radius R reaches at most sqrt(2) R further.
                            unit = json.loads(op.Unit)
                            corner = float((unit.get("cutter") or {}).get("cornerRadius", 0.0))
                            fillet = max(0.0, float(unit.get("floorFilletRadius") or 0.0) - corner - a)
                            radius = op.ToolController.Tool.Diameter.Value / 2
                            d = radius + a + fillet + 2 ** 0.5 * radius + 1e-6
                            for _, x, y, z in moves_of(op):
                                self.assertTrue(bb.XMin - d <= x <= bb.XMax + d and bb.YMin - d <= y <= bb.YMax + d
                                                and z <= op.ClearanceHeight.Value + 1e-6, (name, op.Label, x, y, z))
                finally:
                    fixture.close()


if __name__ == "__main__":
    unittest.main()
