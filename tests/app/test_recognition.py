"""aeronc.pipeline.recognition: the App-side wrapper of the C++ core."""
import unittest

import FreeCAD
import Part

from aeronc.pipeline import recognition
from aeronc.tests.app import support


class TestRecognition(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.doc = support.new_document("AeroNCRecognition")
        cls.part, cls.truth = support.make_panel_object(cls.doc)

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.doc.Name)

    def test_result_schema(self):
        r = recognition.recognise(self.part, directions=[(0, 0, 1), (0, 0, -1)])
        n = len(self.part.Shape.Faces)
        self.assertEqual(r["faceCount"], n)
        self.assertEqual(len(r["faceRoles"]), n)
        self.assertEqual(len(r["faceElement"]), n)
        self.assertEqual([s["direction"] for s in r["setups"]], [[0, 0, 1], [0, 0, -1]])
        self.assertGreater(len(r["elements"]), 0)
        for el in r["elements"]:
            self.assertIn(el["type"], ("closed_pocket", "open_pocket", "opening", "hole"))
            for f in el["contourFaces"] + el["floorFaces"]:
                self.assertTrue(1 <= f <= n, f)

    def test_shape_and_object_give_the_same_result(self):
        a = recognition.recognise(self.part, directions=[(0, 0, 1)])
        b = recognition.recognise(self.part.Shape, directions=[(0, 0, 1)])
        self.assertEqual(a["faceRoles"], b["faceRoles"])
        self.assertEqual(len(a["elements"]), len(b["elements"]))

    def test_free_faces_beside_the_solid_keep_the_objects_face_numbers(self):
        # A free face first: the solid's faces are Face2... of the compound, as after File > Import.
        free = Part.makePlane(10, 10, FreeCAD.Vector(0, 0, 100))
        shape = Part.makeCompound([free, self.part.Shape])
        alone = recognition.recognise(self.part.Shape, directions=[(0, 0, 1)])
        r = recognition.recognise(shape, directions=[(0, 0, 1)])
        n = len(shape.Faces)
        self.assertEqual(r["faceCount"], n)
        self.assertEqual(r["leftOutFaces"], [1])
        self.assertEqual(r["faceRoles"][0], "stock")
        self.assertEqual(r["faceRoles"][1:], alone["faceRoles"])
        self.assertEqual([f + 1 for f in alone["elements"][0]["floorFaces"]], r["elements"][0]["floorFaces"])
        self.assertTrue(any("Face1" in w and "left out" in w for w in r["warnings"]), r["warnings"])

    def test_automatic_directions(self):
        r = recognition.recognise(self.part)
        self.assertGreaterEqual(len(r["setups"]), 1)

    def test_progress_is_reported(self):
        seen = []
        recognition.recognise(self.part, directions=[(0, 0, 1)],
                              progress=lambda f, stage: seen.append((f, stage)) or True)
        self.assertTrue(seen)
        self.assertTrue(all(0.0 <= f <= 1.0 for f, _ in seen))

    def test_cancel(self):
        with self.assertRaises(recognition.RecognitionCancelled) as ctx:
            recognition.recognise(self.part, progress=lambda f, stage: False)
        self.assertIn("cancelled", str(ctx.exception))

    def test_not_a_solid(self):
        with self.assertRaises(recognition.RecognitionError) as ctx:
            recognition.recognise(Part.makePlane(10, 10))
        self.assertIn("not a solid", str(ctx.exception))
        self.assertIsInstance(ctx.exception, RuntimeError)

    def test_several_solids(self):
        two = Part.makeCompound([Part.makeBox(1, 1, 1), Part.makeBox(1, 1, 1, FreeCAD.Vector(5, 0, 0))])
        with self.assertRaisesRegex(recognition.RecognitionError, "2 solids"):
            recognition.recognise(two)

    def test_empty_shape(self):
        with self.assertRaisesRegex(recognition.RecognitionError, "empty"):
            recognition.recognise(Part.Shape())

    def test_core_errors_are_wrapped(self):
        # No face of a box is normal to this direction: the core refuses it.
        with self.assertRaises(recognition.RecognitionError) as ctx:
            recognition.recognise(Part.makeBox(10, 10, 10), directions=[(1, 1, 1)])
        self.assertTrue(str(ctx.exception).startswith("shape: "), str(ctx.exception))

    def test_summary(self):
        r = recognition.recognise(self.part, directions=[(0, 0, 1)])
        c = recognition.summary(r)
        self.assertEqual(c["elements"], len(r["elements"]))
        self.assertEqual(c["closed_pocket"] + c["open_pocket"] + c["opening"] + c["hole"], c["elements"])
        self.assertIn("domain elements", recognition.summary_text(r))
