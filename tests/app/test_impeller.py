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


class ImpellerToolpathRequestTest(unittest.TestCase):
    """_core.impeller_toolpaths and impeller_check_apt refuse a bad request by name, before any
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

    def request(self, **changes):
        import json
        r = {"rougher": {"tool": "EM-BALL8", "number": 1, "rpm": 10000, "feed": 1000},
             "finisher": {"tool": "TB-4-3", "number": 2, "rpm": 10000, "feed": 1000}, "options": {}}
        r.update(changes)
        return json.dumps(r)

    def refused(self, text, message):
        with self.assertRaisesRegex(RuntimeError, message):
            self.core.impeller_toolpaths(self.brep, self.kb, self.sql, text)

    def test_bad_requests(self):
        self.refused("{not json", "the request is not JSON")
        self.refused('{"finisher": {}}', "no rougher")
        self.refused(self.request(rougher={"tool": "NOPE", "number": 1, "rpm": 1, "feed": 1}), "no tool NOPE")
        self.refused(self.request(rougher={"tool": "FM-125", "number": 1, "rpm": 1, "feed": 1}),
                     "FM-125 is a face tool")
        self.refused(self.request(finisher={"tool": "TB-4-3", "rpm": 1, "feed": 1}), "\"number\" must be a number")
        self.refused(self.request(options={"stations": 1}), "stations wants 2 to 200")
        self.refused(self.request(options={"stepOver": 1.5}), "step-over in \\(0, 1\\]")
        # The fillet ball and the axial steps' tools, by role.
        self.refused(self.request(filletBall={"tool": "EM-F16", "number": 3, "rpm": 1, "feed": 1}),
                     "filletBall: tool EM-F16 is a flat tool")
        self.refused(self.request(filletBall="EM-BALL4"), "filletBall must be an object")
        self.refused(self.request(axial={"drill": {"tool": "EM-BALL4", "number": 4, "rpm": 1, "feed": 1}}),
                     "axial: drill: tool EM-BALL4 is a ball tool; this step needs a flat-bottomed tool")
        self.refused(self.request(axial={"boringMill": {"tool": "NOPE", "number": 4, "rpm": 1, "feed": 1}}),
                     "axial: boringMill: no tool NOPE")
        self.refused(self.request(axial={"drillAllowance": -1}), "drillAllowance must be >= 0")
        self.refused(self.request(axial=[]), "axial must be an object")
        # A good request reaches the part, which is no impeller.
        self.refused(self.request(), "not an impeller")
        self.refused(self.request(filletBall={"tool": "EM-BALL4", "number": 3, "rpm": 1, "feed": 1},
                                  axial={"drill": {"tool": "DR-18", "number": 4, "rpm": 1, "feed": 1}}),
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
