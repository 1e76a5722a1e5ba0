"""The impeller of the shared data (nine blades, no splitters, a bore of 8 mm, exported as
eleven bodies with a hub in a piece per channel and blades without root fillets): fused in
FreeCAD, then recognised with every role in place."""
import glob
import math
import os
import unittest

import FreeCAD
import Part

from aeronc.impeller import recognition
from aeronc.objects.fused_part import add_fused_part


def _shared_impeller():
    data = os.environ.get("AERONC_SHARED_DATA", "")
    found = sorted(glob.glob(os.path.join(data, "impeller", "*.st*p")))
    return found[0] if found else None


@unittest.skipUnless(_shared_impeller(), "no impeller in AERONC_SHARED_DATA")
class SharedImpellerTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.doc = FreeCAD.newDocument("SharedImpeller")
        cls.doc.UndoMode = 1
        part = cls.doc.addObject("Part::Feature", "Impeller")
        part.Shape = Part.read(_shared_impeller())
        cls.doc.recompute()
        cls.fused, cls.summary = add_fused_part(part)  # as Program impeller offers it
        cls.result = recognition.recognise(cls.fused)

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.doc.Name)

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


if __name__ == "__main__":
    unittest.main()
