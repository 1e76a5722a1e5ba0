"""Program impeller in the document, headless: the recognition nodes against the generator's
truth, the blank as the Job's stock, the route's operations with their 5-axis paths, the posted
program, one undo step per change, bad parts refused leaving the document as it was, and the
whole program kept by save and reopen.

A small impeller (3 + 3 blades) and coarse toolpaths (4 stations a pass, one channel) keep the
suite quick; `scripts/run.sh impeller` programs the full 2 x 9 one."""
import glob
import json
import math
import os
import shutil
import tempfile
import unittest

import FreeCAD
import Part

from aeronc.impeller import recognition, programming

from aeronc.tests.parts import impeller_part
from aeronc import pathcompat
from aeronc.errors import ImpellerError, RecognitionError
from aeronc.objects.impeller_features import is_impeller_feature, is_impeller_features
from aeronc.objects.impeller_program import cutting_of, is_impeller_program
from aeronc.operations.impeller_operation import is_impeller_operation
from aeronc.tests.app.support import new_document

SPEC = {"bladeCount": 3, "filletRadius": 2.0, "bladeHeight": 11.0}
QUICK = {"stations": 4, "channels": 1}


def _part(doc, spec, name="Impeller"):
    shape, truth = impeller_part.make_test_impeller(spec)
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = shape
    doc.recompute()
    return obj, truth


def _state(doc):
    return sorted(o.Name for o in doc.Objects), list(doc.UndoNames)


class ProgramImpellerTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp(prefix="aeronc_impeller_")
        cls.kb = os.path.join(cls.dir, "kb.sqlite")
        cls.doc = new_document("ImpellerProgram")
        cls.part, cls.truth = _part(cls.doc, SPEC)
        cls.before = len(cls.doc.Objects)
        cls.prog = programming.create(cls.doc, cls.part, allowance=2.5, kb_path=cls.kb, out_dir=cls.dir, **QUICK)

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.doc.Name)
        shutil.rmtree(cls.dir, ignore_errors=True)

    def nodes(self):
        return [o for o in self.prog.Features.Group if is_impeller_feature(o)]

    def test_nodes_match_the_truth(self):
        t = self.truth
        nodes = {}
        for n in self.nodes():
            nodes.setdefault(n.Role, []).append(n)
        self.assertEqual(len(nodes["main_blade"]), 3)
        self.assertEqual(len(nodes["splitter_blade"]), 3)
        truth_by_shroud = {b["shroud"]: b for b in t["blades"]}
        for n in nodes["main_blade"] + nodes["splitter_blade"]:
            tb = truth_by_shroud.pop(n.ShroudFace)
            self.assertEqual(n.Role == "splitter_blade", tb["splitter"])
            walls = sorted(tb[k] for k in ("pressure", "suction", "leading", "trailing"))
            self.assertEqual(list(n.FaceNumbers), walls)
            self.assertEqual((n.PressureFace, n.SuctionFace), (tb["pressure"], tb["suction"]))
            self.assertEqual(sorted(n.FilletFaces), sorted(tb["fillets"]))
            # The links name the same faces of the source solid.
            self.assertEqual(n.Faces[0][0], self.part)
            self.assertEqual(sorted(int(s[4:]) for s in n.Faces[0][1]), walls)
        self.assertEqual(truth_by_shroud, {})
        single = {role: list(ns[0].FaceNumbers) for role, ns in nodes.items() if len(ns) == 1}
        self.assertEqual(single["hub"], [t["hub"]])
        self.assertEqual(single["bore"], [t["bore"]])
        self.assertEqual(single["planes"], sorted(t["planes"]))
        self.assertEqual(single["turned"], sorted(t["rim"]) if isinstance(t["rim"], list) else [t["rim"]])
        self.assertEqual(single["root_fillets"], sorted(f for b in t["blades"] for f in b["fillets"]))
        self.assertEqual(single["shroud"], sorted(b["shroud"] for b in t["blades"]))
        # Every face of the part has a colour role, none left unclaimed.
        roles = recognition.face_role_names(impeller_program_result(self.prog))
        self.assertEqual(len(roles), len(self.part.Shape.Faces))
        self.assertNotIn("unclaimed", roles)

    def test_dimensions_on_the_group(self):
        g = self.prog.Features
        self.assertTrue(is_impeller_features(g))
        for prop, key in (("FilletRadius", "filletRadius"), ("BladeHeight", "bladeHeight"),
                          ("BoreDiameter", "boreDiameter"), ("MinChannelWidth", "minChannelWidth")):
            self.assertAlmostEqual(getattr(g, prop).Value, self.truth[key], delta=1e-3, msg=prop)

    def test_blank_is_the_job_stock(self):
        job, blank = self.prog.Job, self.prog.Blank
        self.assertTrue(pathcompat.is_job(job))
        self.assertIs(job.Stock, blank)
        self.assertEqual(blank.TypeId, "Part::FeaturePython")
        self.assertEqual(blank.Allowance.Value, 2.5)
        self.assertAlmostEqual(max(blank.ProfileRadius), blank.Shape.BoundBox.XMax, delta=0.05)
        self.assertEqual(self.prog.Allowance.Value, 2.5)
        shape = self.part.Shape
        self.assertLess(shape.cut(blank.Shape).Volume, 1e-6 * shape.Volume)
        outer = max(impeller_program_result(self.prog)["dimensions"]["outerRadius"], 0)
        self.assertAlmostEqual(blank.Shape.BoundBox.XMax, outer + 2.5, delta=0.05)
        self.assertEqual([m.Objects[0] if hasattr(m, "Objects") else m for m in pathcompat.job_models(job)],
                         [self.part])

    def test_operations_in_route_order_with_5_axis_paths(self):
        ops = [o for o in pathcompat.job_operations(self.prog.Job) if is_impeller_operation(o)]
        route = programming.route_of(self.prog)["steps"]
        # Each route step in order, what a step cuts from the back face right after it.
        self.assertEqual([o.Position for o in ops if not o.Operation.endswith("_back")],
                         [s["position"] for s in route])
        self.assertEqual([o.Operation for o in ops if not o.Operation.endswith("_back")],
                         [s["operation"] for s in route])
        for o in ops:
            if o.Operation.endswith("_back"):
                self.assertEqual(o.Position, ops[ops.index(o) - 1].Position)
                self.assertEqual(o.Operation, ops[ops.index(o) - 1].Operation + "_back")
        # Every step of the route has its toolpath now.
        self.assertTrue(all(len(o.Path.Commands) and o.MoveCount == len(o.Path.Commands) for o in ops),
                        [(o.Label, o.MoveCount) for o in ops])
        five = [o for o in ops if o.Operation in programming.FIVE_AXIS_STEPS]
        self.assertEqual([o.Operation for o in five], ["rough_channels", "finish_blades", "finish_hub",
                                                       "finish_fillets"])
        axis = impeller_program_result(self.prog)["axis"]["direction"]
        for o in ops:
            axial = o.Operation not in programming.FIVE_AXIS_STEPS
            tilted, against = 0, 0
            for cmd in o.Path.Commands:
                p = cmd.Parameters
                self.assertTrue(all(k in p for k in "XYZUVW"), cmd)
                self.assertAlmostEqual(p["U"] ** 2 + p["V"] ** 2 + p["W"] ** 2, 1.0, delta=1e-5)
                dot = p["U"] * axis[0] + p["V"] * axis[1] + p["W"] * axis[2]
                tilted += abs(dot) < 0.9999
                against += dot < 0
            if not axial:
                self.assertGreater(tilted, 0, o.Label)  # 5-axis: the axis leaves the impeller's
                self.assertTrue(o.Active, o.Label)
                self.assertIsNotNone(o.ToolController)
                self.assertIn(o.Label, self.prog.Posted)
            elif o.Operation == "turn":  # the lathe: in a meridian plane, not posted
                self.assertFalse(o.Active)
                self.assertIn("not posted", o.Note)
                self.assertNotIn(o.Label, self.prog.Posted)
            elif o.Operation.endswith("_back"):  # second setup: every axis against the impeller's
                self.assertEqual(against, len(o.Path.Commands), o.Label)
                self.assertFalse(o.Active)
                self.assertIn("second setup", o.Note)
                self.assertNotIn(o.Label, self.prog.Posted)
            else:  # facing, drilling, boring from the front: a fixed axis along the impeller's, posted
                self.assertEqual((tilted, against), (0, 0), o.Label)
                self.assertTrue(o.Active, o.Label)
                self.assertIsNotNone(o.ToolController)
                self.assertIn(o.Label, self.prog.Posted)

    def test_new_steps_checked_without_gouge(self):
        checks = json.loads(self.prog.Checks)
        five, axial, rapids = checks["fiveAxis"], checks["axial"], checks["rapids"]
        # The fillet finishing is among the 5-axis positions: more than roughing, blades and hub alone.
        fillets = [o for o in pathcompat.job_operations(self.prog.Job) if o.Operation == "finish_fillets"][0]
        self.assertGreater(fillets.MoveCount, 0)
        self.assertLessEqual(five["maxGougeMm"], 0.002)
        self.assertEqual(five["holderCollisions"], 0)
        self.assertGreater(five["links"], 0)
        self.assertEqual(five["linkCollisions"], 0)
        self.assertGreater(rapids["checked"], 0)
        self.assertEqual(rapids["collisions"], 0)
        axial_moves = sum(o.MoveCount for o in pathcompat.job_operations(self.prog.Job)
                          if o.Operation not in programming.FIVE_AXIS_STEPS)
        self.assertGreater(axial["positions"], 0)
        self.assertLessEqual(axial["positions"], axial_moves)
        self.assertLessEqual(axial["maxGougeMm"], 0.002)
        self.assertEqual(axial["holderCollisions"], 0)
        self.assertEqual(self.prog.PositionsChecked, five["positions"] + axial["positions"])
        self.assertEqual(self.prog.LinkCollisions, 0)
        self.assertEqual(self.prog.LinksChecked, five["links"] + rapids["checked"])
        # The bore is bored to its size: the boring tool's tip runs at the bore radius less its own.
        bore = [o for o in pathcompat.job_operations(self.prog.Job) if o.Operation == "bore"][0]
        r_tool = programming.tool_library(self.kb)[bore.Tool]["diameter"] / 2
        r_bore = self.truth["boreDiameter"] / 2
        radii = [math.hypot(c.Parameters["X"], c.Parameters["Y"]) for c in bore.Path.Commands if c.Name == "G1"]
        self.assertAlmostEqual(max(radii), r_bore - r_tool, delta=1e-3)

    def test_cutting_data_from_the_optimiser(self):
        cutting = cutting_of(self.prog)
        tcs = pathcompat.tool_controllers(self.prog.Job)
        self.assertEqual(sorted(cutting), sorted(tc.AeroNCTool.split("/")[0] for tc in tcs))
        for tc in tcs:
            data = cutting[tc.AeroNCTool.split("/")[0]]
            self.assertAlmostEqual(float(tc.SpindleSpeed), data["rpm"], places=6)
            self.assertAlmostEqual(FreeCAD.Units.Quantity(tc.HorizFeed).getValueAs("mm/min"), data["feed"], places=3)
            self.assertIn("f_z", tc.CuttingOptimum)
            # The optimiser's answer stays inside the chip load it was given (1.5 x the KB's f_z).
            self.assertLessEqual(data["fz"], 1.5 * data["kbFz"] + 1e-9)

    def test_checks_and_posted_program(self):
        p = self.prog
        self.assertGreater(p.PositionsChecked, 0)
        self.assertLessEqual(p.MaxGouge, 0.01)
        self.assertEqual(p.HolderCollisions, 0)
        self.assertIn("TRAORI", p.Posted)
        self.assertIn("%_N_IMPELLER_MPF", p.Posted)
        path = os.path.join(self.dir, "IMPELLER.mpf")
        self.assertEqual(p.ProgramFile, path)
        with open(path) as f:
            self.assertEqual(f.read(), p.Posted)
        # The program as FreeCAD holds it (6 decimals), written as APT, read back and checked.
        again = programming.check_posted(p)
        cutting = sum(1 for o in pathcompat.job_operations(p.Job) if o.Active
                      for c in o.Path.Commands if c.Name == "G1")
        self.assertEqual(again["positions"], cutting)
        self.assertLessEqual(again["maxGougeMm"], 0.01)
        self.assertEqual(again["holderCollisions"], 0)

    def test_bad_edits_are_refused_unchanged(self):
        before = _state(self.doc), self.prog.Edits, self.prog.Posted
        rough = [o for o in pathcompat.job_operations(self.prog.Job) if o.Operation == "rough_channels"][0]
        blades = [o for o in pathcompat.job_operations(self.prog.Job) if o.Operation == "finish_blades"][0]
        with self.assertRaisesRegex(ImpellerError, "needs a ball or tapered ball end mill; FM-125 is a face tool"):
            programming.set_step_tool(self.prog, rough.Position, "FM-125")
        with self.assertRaisesRegex(ImpellerError, "no tool NO-SUCH-TOOL"):
            programming.set_step_tool(self.prog, rough.Position, "NO-SUCH-TOOL")
        with self.assertRaisesRegex(ImpellerError, "only the channel roughing's allowance"):
            programming.set_step_allowance(self.prog, blades.Position, 0.3)
        with self.assertRaisesRegex(ImpellerError, "must be zero or more"):
            programming.set_step_allowance(self.prog, rough.Position, -0.1)
        with self.assertRaisesRegex(ImpellerError, "the route has no step 99"):
            programming.set_step_enabled(self.prog, 99, False)
        with self.assertRaisesRegex(ImpellerError, "blank allowance must be zero or more"):
            programming.set_allowance(self.prog, float("nan"))
        self.assertEqual((_state(self.doc), self.prog.Edits, self.prog.Posted), before)

    def test_save_and_reopen(self):
        path = os.path.join(self.dir, "impeller.FCStd")
        self.doc.saveCopy(path)  # the class's document stays open for the other tests
        expected = {o.Name: (o.Label, len(o.Path.Commands)) for o in pathcompat.job_operations(self.prog.Job)}
        nodes = {n.Name: list(n.FaceNumbers) for n in self.nodes()}
        posted = self.prog.Posted
        first_move = [o for o in pathcompat.job_operations(self.prog.Job) if len(o.Path.Commands)][0].Path.Commands[1]
        doc = FreeCAD.openDocument(path)
        try:
            progs = [o for o in doc.Objects if is_impeller_program(o)]
            self.assertEqual(len(progs), 1)
            prog = progs[0]
            self.assertIs(prog.Job.Stock, prog.Blank)
            self.assertEqual({o.Name: (o.Label, len(o.Path.Commands)) for o in pathcompat.job_operations(prog.Job)},
                             expected)
            self.assertEqual({n.Name: list(n.FaceNumbers) for n in prog.Features.Group}, nodes)
            self.assertEqual(prog.Posted, posted)
            move = [o for o in pathcompat.job_operations(prog.Job) if len(o.Path.Commands)][0].Path.Commands[1]
            self.assertEqual(move.Parameters, first_move.Parameters)
            self.assertEqual(len(programming.route_of(prog)["steps"]),
                             len([o for o in pathcompat.job_operations(prog.Job) if not o.Operation.endswith("_back")]))
            self.assertEqual(prog.Checks, self.prog.Checks)
        finally:
            FreeCAD.closeDocument(doc.Name)


def impeller_program_result(prog):
    from aeronc.objects.impeller_features import result_of
    return result_of(prog.Features)


class EditAndUndoTest(unittest.TestCase):
    def test_each_change_is_one_undo_step(self):
        d = tempfile.mkdtemp(prefix="aeronc_impeller_")
        doc = new_document("ImpellerUndo")
        try:
            part, _ = _part(doc, SPEC)
            names, undo = _state(doc)
            prog = programming.create(doc, part, kb_path=os.path.join(d, "kb.sqlite"), **QUICK)
            self.assertEqual(doc.UndoNames[: len(undo) + 1], ["Program impeller"] + undo)
            hub = [o for o in pathcompat.job_operations(prog.Job) if o.Operation == "finish_hub"][0]
            self.assertIn("finish hub", prog.Posted)
            programming.set_step_enabled(prog, hub.Position, False)
            self.assertEqual(doc.UndoNames[0], "Switch impeller step off")
            self.assertEqual(len(doc.UndoNames), len(undo) + 2)
            hub = [o for o in pathcompat.job_operations(prog.Job) if o.Operation == "finish_hub"][0]
            self.assertFalse(hub.Active)
            self.assertNotIn("finish hub", prog.Posted)
            doc.undo()
            hub = [o for o in pathcompat.job_operations(prog.Job) if o.Operation == "finish_hub"][0]
            self.assertTrue(hub.Active)
            self.assertIn("finish hub", prog.Posted)
            # A switched-off fillet finishing or drilling step keeps its moves, leaves the program,
            # and the other steps are posted as before.
            for operation in ("finish_fillets", "drill"):
                op = [o for o in pathcompat.job_operations(prog.Job) if o.Operation == operation][0]
                self.assertIn(op.Label, prog.Posted)
                programming.set_step_enabled(prog, op.Position, False)
                ops = pathcompat.job_operations(prog.Job)
                op = [o for o in ops if o.Operation == operation][0]
                self.assertFalse(op.Active)
                self.assertGreater(len(op.Path.Commands), 0)
                self.assertNotIn(op.Label, prog.Posted)
                for o in ops:
                    if o.Active:
                        self.assertIn(o.Label, prog.Posted)
                doc.undo()
            doc.undo()
            self.assertEqual(sorted(o.Name for o in doc.Objects), names)
        finally:
            FreeCAD.closeDocument(doc.Name)
            shutil.rmtree(d, ignore_errors=True)



class BadPartsTest(unittest.TestCase):
    """Each bad part gets the core's message and leaves the document as it was."""

    def refused(self, make, message):
        d = tempfile.mkdtemp(prefix="aeronc_impeller_")
        doc = new_document("ImpellerBad")
        try:
            part = make(doc)
            before = _state(doc)
            with self.assertRaisesRegex(RecognitionError, message):
                programming.create(doc, part, kb_path=os.path.join(d, "kb.sqlite"), **QUICK)
            self.assertEqual(_state(doc), before)
        finally:
            FreeCAD.closeDocument(doc.Name)
            shutil.rmtree(d, ignore_errors=True)

    def test_not_an_impeller(self):
        def make(doc):
            obj = doc.addObject("Part::Feature", "Box")
            obj.Shape = Part.makeBox(40, 30, 20)
            return obj
        self.refused(make, "^Box: not an impeller: no rotational pattern")

    def test_unequal_blade_groups(self):
        self.refused(lambda doc: _part(doc, dict(SPEC, omitSplitter=1))[0], "^Impeller: unequal blade groups")

    def test_blades_without_root_fillets_are_recognised(self):
        # Once refused as "missing hub"; exported impellers often have sharp blade roots.
        doc = new_document("ImpellerNoFillets")
        try:
            part, truth = _part(doc, dict(SPEC, filletRadius=0.0))
            result = recognition.recognise(part)
            self.assertEqual(result["bladeCount"], truth["bladeCount"])
            self.assertEqual(result["splitterCount"], truth["bladeCount"])
            self.assertEqual(recognition.hub_faces(result), [truth["hub"]])
            self.assertEqual(result["bore"], truth["bore"])
            self.assertEqual(sorted(b["shroud"] for b in result["blades"]),
                             sorted(b["shroud"] for b in truth["blades"]))
            self.assertTrue(all(not b["fillets"] for b in result["blades"]))
        finally:
            FreeCAD.closeDocument(doc.Name)

    def test_a_real_part_is_refused(self):
        data = os.environ.get("AERONC_SHARED_DATA", "")
        parts = sorted(glob.glob(os.path.join(data, "nist", "*.stp")))
        if not parts:
            self.skipTest("no NIST parts in AERONC_SHARED_DATA")

        def make(doc):
            obj = doc.addObject("Part::Feature", "Nist")
            obj.Shape = Part.read(parts[0])
            return obj
        self.refused(make, "^Nist: (not an impeller|unequal blade groups|missing hub)")
