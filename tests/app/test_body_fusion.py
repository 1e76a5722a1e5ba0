"""A part of several bodies: impeller recognition refuses it with the reason, and the fused copy
is added as one undo step with the original kept."""
import unittest

import FreeCAD
import Part

from aeronc.errors import RecognitionError
from aeronc.impeller import recognition
from aeronc.objects.fused_part import add_fused_part


def bodies():
    """A plate, a rib touching it to 5e-4 mm, a rib overlapping it, and a sliver of no volume."""
    plate = Part.makeBox(40, 40, 10)
    touching = Part.makeBox(10, 2, 20, FreeCAD.Vector(5, 5, 9.9995))
    overlapping = Part.makeBox(10, 2, 20, FreeCAD.Vector(20, 5, 5))
    sliver = Part.makeBox(1e-3, 1e-3, 1e-3, FreeCAD.Vector(30, 30, 10))
    return Part.makeCompound([plate, touching, overlapping, sliver])


class BodyFusionTest(unittest.TestCase):
    def setUp(self):
        self.doc = FreeCAD.newDocument("BodyFusion")
        self.doc.UndoMode = 1
        self.part = self.doc.addObject("Part::Feature", "Bodies")
        self.part.Shape = bodies()
        self.doc.recompute()

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)

    def test_recognition_names_the_bodies(self):
        with self.assertRaisesRegex(RecognitionError, "holds 4 solids .* fuse them first"):
            recognition.recognise(self.part)

    def test_fused_copy_is_one_undo_step(self):
        fused, summary = add_fused_part(self.part)
        self.assertEqual(len(fused.Shape.Solids), 1)
        self.assertTrue(fused.Shape.isValid())
        volume = 40 * 40 * 10 + 10 * 2 * 20 + 10 * 2 * 15  # the second rib overlaps the plate by 5
        self.assertAlmostEqual(fused.Shape.Volume, volume, delta=1.0)
        self.assertIn("4 bodies: 3 fused into one solid, 1 degenerate", summary)
        self.assertEqual(len(self.part.Shape.Solids), 4)  # the original is kept
        self.assertIsNotNone(self.doc.getObject(self.part.Name))
        name = fused.Name
        self.doc.undo()
        self.assertIsNone(self.doc.getObject(name))
        self.assertIsNotNone(self.doc.getObject(self.part.Name))


if __name__ == "__main__":
    unittest.main()
