"""Impeller recognition through FreeCAD: a generated impeller crosses to the core as FreeCAD's
BREP text, and the roles come back as FaceN of the FreeCAD shape, as the generator's truth says;
parts that are no impellers are refused with the reason."""
import unittest

import Part

from aeronc.impeller import recognition

from aeronc.tests.parts import impeller_part
from aeronc.errors import RecognitionError

SPEC = {"bladeCount": 5, "filletRadius": 2.0, "bladeHeight": 11.0}


class ImpellerRecognitionTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.shape, cls.truth = impeller_part.make_test_impeller(SPEC)
        cls.result = recognition.recognise(cls.shape)

    def test_roles_match_truth(self):
        r, t = self.result, self.truth
        self.assertEqual(len(self.shape.Faces), r["faceCount"])
        self.assertEqual((r["bladeCount"], r["splitterCount"]), (5, 5))
        self.assertEqual((r["hub"], r["bore"]), (t["hub"], t["bore"]))
        self.assertEqual(sorted(r["planes"]), sorted(t["planes"]))
        truth_by_shroud = {b["shroud"]: b for b in t["blades"]}
        for b in r["blades"]:
            tb = truth_by_shroud.pop(b["shroud"])
            self.assertEqual(b["kind"] == "splitter", tb["splitter"])
            for key in ("pressure", "suction", "leading", "trailing"):
                self.assertEqual(b[key], tb[key], key)
            self.assertEqual(sorted(b["fillets"]), sorted(tb["fillets"]))
        self.assertEqual(truth_by_shroud, {})

    def test_faces_are_freecad_face_numbers(self):
        # The bore is FaceN's cylinder of the bore's radius, the hub the face of the most edges.
        bore = self.shape.Faces[self.result["bore"] - 1]
        self.assertAlmostEqual(bore.Surface.Radius, 10.0, places=9)
        hub = self.shape.Faces[self.result["hub"] - 1]
        self.assertEqual(max(len(f.Edges) for f in self.shape.Faces), len(hub.Edges))

    def test_dimensions_match_truth(self):
        d, t = self.result["dimensions"], self.truth
        for key in ("boreDiameter", "boreDepth", "filletRadius", "bladeHeight", "minChannelWidth"):
            self.assertAlmostEqual(d[key], t[key], delta=1e-3, msg=key)

    def test_roles_cover_every_face(self):
        roles = recognition.face_roles(self.result)
        self.assertEqual(sorted(roles), list(range(1, len(self.shape.Faces) + 1)))

    def test_blank_and_route(self):
        import os
        import tempfile
        with tempfile.TemporaryDirectory() as d:
            result, blank = recognition.program_data(self.shape, 3.0, kb_path=os.path.join(d, "kb.sqlite"))
        self.assertTrue(blank.isValid())
        # The blank holds the part and is the outer profile grown by the allowance.
        self.assertLess(self.shape.cut(blank).Volume, 1e-6 * self.shape.Volume)
        self.assertGreater(blank.Volume, self.shape.Volume)
        # (A revolved polygon: planes and cylinders, so its bounding box is tight.)
        box = blank.BoundBox
        self.assertAlmostEqual(box.ZLength, result["dimensions"]["axialLength"] + 6.0, delta=1e-2)
        self.assertAlmostEqual(box.XLength / 2, 60.0 + 3.0 + 0.02, delta=1e-2)
        self.assertAlmostEqual(max(result["blank"]["radius"]), 60.0 + 3.0 + 0.02, delta=1e-6)
        ops = [s["operation"] for s in result["route"]["steps"]]
        self.assertEqual(ops[:2], ["turn", "face"])
        self.assertIn("rough_channels", ops)
        rough = result["route"]["steps"][ops.index("rough_channels")]
        self.assertEqual(rough["tool"]["type"], "ball")
        self.assertLessEqual(rough["tool"]["diameter"], result["dimensions"]["minChannelWidth"])

    def test_not_an_impeller(self):
        with self.assertRaisesRegex(RecognitionError, "not an impeller: no rotational pattern"):
            recognition.recognise(Part.makeBox(10, 20, 30))

    def test_not_a_solid(self):
        with self.assertRaisesRegex(RecognitionError, "not a solid"):
            recognition.recognise(Part.makeBox(10, 20, 30).Faces[0])

    def test_bad_spec(self):
        with self.assertRaisesRegex(RecognitionError, "unknown key blades"):
            impeller_part.make_test_impeller({"blades": 4})


class ImpellerProgramRequestTest(unittest.TestCase):
    """_core.impeller_program and impeller_check_apt refuse a bad request by name, before any
    geometry is read (the part here is a box: reaching recognition would say so instead)."""

    @classmethod
    def setUpClass(cls):
        import os
        import tempfile
        from aeronc import _core
        from aeronc.pipeline import knowledge_base
        cls.core = _core
        cls.dir = tempfile.mkdtemp(prefix="aeronc_impeller_request_")
        cls.kb = os.path.join(cls.dir, "kb.sqlite")
        cls.sql = knowledge_base.sql_folder()
        cls.brep = Part.makeBox(10, 20, 30).exportBrepToString()

    @classmethod
    def tearDownClass(cls):
        import shutil
        shutil.rmtree(cls.dir, ignore_errors=True)

    STEPS = {"rough_channels": (5, "EM-BALL8", 0.5), "finish_blades": (6, "TB-4-3", 0.0)}

    def request(self, steps=None, **changes):
        import json
        steps = dict(self.STEPS, **(steps or {}))
        r = {"steps": [{"position": p, "operation": op, "allowance": a, "tool": {"id": t} if t else None}
                       for op, (p, t, a) in steps.items()], "options": {}}
        r.update(changes)
        return json.dumps(r)

    def refused(self, text, message):
        with self.assertRaisesRegex(RuntimeError, message):
            self.core.impeller_program(self.brep, self.kb, self.sql, text)

    def test_bad_requests(self):
        self.refused("{not json", "the request is not JSON")
        self.refused('{"options": {}}', "steps must be a list")
        self.refused(self.request(steps={"rough_channels": (5, None, 0.5)}), "no channel roughing or no blade finishing")
        self.refused(self.request(steps={"rough_channels": (5, "NOPE", 0.5)}), "no tool NOPE")
        self.refused(self.request(steps={"rough_channels": (5, "FM-125", 0.5)}), "FM-125 is a face tool")
        self.refused(self.request(steps={"rough_channels": (5, "EM-BALL8", -1)}), "allowance must be >= 0")
        self.refused(self.request(options={"stations": 1}), "stations wants 2 to 200")
        self.refused(self.request(options={"stepOver": 1.5}), "step-over in \\(0, 1\\]")
        self.refused(self.request(material="unobtainium"), "unknown workpiece material 'unobtainium'")
        self.refused(self.request(machine="NO-MACHINE"), "unknown machine")
        # The fillet ball and the axial steps' tools, by role.
        self.refused(self.request(steps={"finish_fillets": (8, "EM-F16", 0.0)}), "filletBall: tool EM-F16 is a flat tool")
        self.refused(self.request(steps={"drill": (3, "EM-BALL4", 0.5)}),
                     "axial: drill: tool EM-BALL4 is a ball tool; this step needs a flat-bottomed tool")
        self.refused(self.request(steps={"bore": (4, "NOPE", 0.0)}), "no tool NOPE")
        self.refused(self.request(steps={"drill": (3, "DR-18", -1)}), "drillAllowance must be >= 0")
        # A good request reaches the part, which is no impeller.
        self.refused(self.request(), "not an impeller")
        self.refused(self.request(steps={"finish_fillets": (8, "EM-BALL4", 0.0), "drill": (3, "DR-18", 0.5)}),
                     "not an impeller")

    def test_tool_list(self):
        import json
        tools = {t["id"]: t for t in json.loads(self.core.impeller_tools(self.kb, self.sql))}
        self.assertEqual(tools["TB-4-3"]["type"], "tapered_ball")
        self.assertEqual((tools["TB-4-3"]["diameter"], tools["TB-4-3"]["taperDeg"]), (4.0, 3.0))
        self.assertEqual(tools["EM-BALL8"]["type"], "ball")

    def test_check_refuses_bad_cutters(self):
        with self.assertRaisesRegex(RuntimeError, "the cutters are not JSON"):
            self.core.impeller_check_apt(self.brep, "", "[{")
        with self.assertRaisesRegex(RuntimeError, "\"tipRadius\" must be a number"):
            self.core.impeller_check_apt(self.brep, "", '[{"number": 1}]')
