"""The impeller of the shared data (nine blades, no splitters, a bore of 8 mm, exported as
eleven bodies with a hub in a piece per channel and blades without root fillets): programmed end
to end by the impeller run (its bodies fused in FreeCAD, recognised with every role in place,
blank, route, 5-axis toolpaths, the posted 840D program read back and checked, the report).
The run is made once for every test (one channel, four stations a pass)."""
import glob
import math
import os
import shutil
import tempfile
import unittest

import FreeCAD
import Part

from aeronc.impeller import recognition
from aeronc.objects.impeller_features import result_of
from aeronc.runs import impeller_run


def _shared_impeller():
    data = os.environ.get("AERONC_SHARED_DATA", "")
    found = sorted(glob.glob(os.path.join(data, "impeller", "*.st*p")))
    return found[0] if found else None


@unittest.skipUnless(_shared_impeller(), "no impeller in AERONC_SHARED_DATA")
class SharedImpellerTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.out = tempfile.mkdtemp(prefix="aeronc-shared-impeller-")
        # The exported bodies as they are: the run fuses them as Program impeller offers it.
        cls.data = impeller_run.run(cls.out, Part.read(_shared_impeller()), source="shared impeller",
                                    stations=4, channels=1, say=lambda text: None)
        cls.summary = cls.data["fused"]
        cls.doc = FreeCAD.openDocument(os.path.join(cls.out, "impeller.FCStd"))
        cls.fused = cls.doc.getObject("FusedPart")
        cls.prog = [o for o in cls.doc.Objects if o.Name.startswith("ImpellerProgram")][0]
        cls.result = result_of(cls.prog.Features)

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.doc.Name)
        shutil.rmtree(cls.out, ignore_errors=True)

    def test_fused_from_its_bodies(self):
        self.assertIn("11 bodies: 10 fused into one solid, 1 degenerate", self.summary)
        self.assertTrue(self.fused.Shape.isValid())

    def test_blade_counts_and_bore(self):
        r = self.result
        self.assertEqual(r["bladeCount"], 9)
        self.assertEqual(r["splitterCount"], 0)
        self.assertEqual(len(r["blades"]), 9)
        self.assertAlmostEqual(r["dimensions"]["boreDiameter"], 8.0, delta=1e-3)
        bore = self.fused.Shape.Faces[r["bore"] - 1]
        self.assertEqual(bore.Surface.__class__.__name__, "Cylinder")
        axis = FreeCAD.Vector(*r["axis"]["direction"])
        self.assertAlmostEqual(abs(axis.dot(bore.Surface.Axis)), 1.0, places=6)
        # The bore runs the hub's length: its pieces (the faces on the 4 mm cylinder about the
        # axis), by their area, are about 40 mm long; a short piece taken for the bore is not.
        faces = self.fused.Shape.Faces
        pieces = [i for i, f in enumerate(faces) if f.Surface.__class__.__name__ == "Cylinder"
                  and abs(f.Surface.Radius - 4.0) < 1e-3 and abs(axis.dot(f.Surface.Axis)) > 1 - 1e-6]
        length = sum(faces[i].Area for i in pieces) / (2 * math.pi * 4.0)
        self.assertGreater(length, 39.0)
        self.assertAlmostEqual(r["dimensions"]["boreDepth"], length, delta=0.5)
        self.assertIn(r["bore"] - 1, pieces)

    def test_blades_are_nine_copies_forty_degrees_apart(self):
        angles = sorted(b["angleDeg"] for b in self.result["blades"])
        for a, b in zip(angles, angles[1:] + [angles[0] + 360]):
            self.assertAlmostEqual(b - a, 40.0, delta=0.5)
        sizes = {(len(b["walls"]), len(recognition.shroud_faces(b)), len(b["fillets"])) for b in self.result["blades"]}
        self.assertEqual(len(sizes), 1, sizes)  # every blade the same set of faces

    def test_hub_is_a_piece_per_channel_under_the_blades(self):
        r = self.result
        hub = recognition.hub_faces(r)
        self.assertEqual(len(hub), 9)
        axis = FreeCAD.Vector(*r["axis"]["direction"])
        base = FreeCAD.Vector(*r["axis"]["point"])
        shape = self.fused.Shape

        def height(face_no):
            return (shape.Faces[face_no - 1].CenterOfMass - base).dot(axis)
        for b in r["blades"]:
            # the side walls run round the axis; the shroud lies above the hub
            self.assertNotEqual(b["pressure"], b["suction"])
            for f in (b["pressure"], b["suction"]):
                self.assertIn(f, b["walls"])
            self.assertGreater(max(height(f) for f in recognition.shroud_faces(b)), max(height(f) for f in hub))

    def test_every_face_but_slivers_has_a_role(self):
        roles = recognition.face_role_names(self.result)
        shape = self.fused.Shape
        unclaimed = [i + 1 for i, role in enumerate(roles) if role == "unclaimed" and shape.Faces[i].Area > 1.0]
        self.assertEqual(unclaimed, [])
        self.assertEqual(roles.count("hub"), 9)
        self.assertTrue(math.isclose(self.result["dimensions"]["outerRadius"], 50.1, abs_tol=0.05))

    def test_programmed_from_its_bodies(self):
        self.assertEqual(self.prog.Features.Source, self.fused)  # the fused part is what was programmed

    def test_channel_width_where_the_channel_is_deep(self):
        # The gap at the nose, where the blades stand a fraction of a millimetre tall, is the
        # narrowest; the roughing ball fits the channel where it is as deep as its radius.
        d = self.result["dimensions"]
        self.assertLess(d["minChannelWidth"], 2.5)
        self.assertLess(d["minChannelDepth"], 1.0)
        rough = [s for s in self.data["route"]["steps"] if s["operation"] == "rough_channels"][0]
        self.assertEqual(rough["tool"]["id"], "EM-BALL3x30")
        deep = min(w for r, depth, w in d["channelProfile"] if depth >= rough["tool"]["diameter"] / 2)
        self.assertLessEqual(rough["tool"]["diameter"] + 2 * rough["allowance"] + rough["clearance"], deep + 1e-9)

    def test_read_back_program_neither_gouges_nor_collides(self):
        again = self.data["recheck"]
        self.assertGreater(again["positions"], 100)
        self.assertLessEqual(again["maxGougeMm"], impeller_run.LIMIT_GOUGE_MM)
        self.assertEqual(again["holderCollisions"], 0)
        self.assertGreater(again["minHolderGapMm"], 0.0)
        check = self.data["check"]
        self.assertEqual(check["holderCollisions"], 0)
        self.assertEqual(check["linkCollisions"], 0)

    def test_job_holds_the_impeller_on_its_setup(self):
        # Exported with its axis along +Y: the Job's model stands on the table with the axis
        # along Z, so every 5-axis move has its tool axis above the table (A within reach).
        from aeronc import pathcompat
        model = pathcompat.job_models(self.prog.Job)[0].Shape
        self.assertAlmostEqual(model.BoundBox.ZMin, 0.0, delta=0.5)
        bore = model.Faces[self.result["bore"] - 1].Surface
        self.assertAlmostEqual(abs(bore.Axis.z), 1.0, places=9)
        self.assertAlmostEqual(math.hypot(bore.Center.x, bore.Center.y), 0.0, places=6)
        checked = 0
        for op in pathcompat.job_operations(self.prog.Job):
            if not op.Active or op.Operation not in ("rough_channels", "finish_blades", "finish_hub"):
                continue
            for cmd in op.Path.Commands:
                if "W" in cmd.Parameters:
                    self.assertGreater(cmd.Parameters["W"], 0.2, op.Label)
                    checked += 1
        self.assertGreater(checked, 100)

    def test_posted_840d_program_with_the_operations(self):
        posted = open(os.path.join(self.out, "IMPELLER.mpf")).read()
        self.assertIn("TRAORI", posted)
        ops = {o["operation"]: o for o in self.data["operations"]}
        self.assertNotIn("finish_fillets", ops)  # no root fillets on this part
        for op in ("rough_channels", "finish_blades", "finish_hub"):
            self.assertTrue(ops[op]["active"], op)
            self.assertGreater(ops[op]["moves"], 0, op)
            self.assertIn("; operation: {}".format(ops[op]["label"]), posted)
        self.assertIn("; tool: EM-BALL3x30", posted)
        self.assertTrue(os.path.exists(os.path.join(self.out, "report.html")))


if __name__ == "__main__":
    unittest.main()
