"""The main job on a block whose pocket's mouth is chamfered all round (45 degrees x 2 mm): the
chamfer mill's pass cuts the chamfer, and the material simulation, which sees the mill's cone,
finds the chamfer faces finished but for the slivers a cone leaves in their sharp miters, and
nothing gouged."""
import json
import math
import os
import shutil
import tempfile
import unittest

import FreeCAD
import Part

from aeronc.runs import main_job


def _write_part(folder):
    block = Part.makeBox(100, 60, 20)
    pocket = Part.makeBox(60, 30, 20, FreeCAD.Vector(20, 15, 10))
    part = block.cut(pocket)

    def on_mouth(v):
        return abs(v.Point.z - 20) < 1e-6 and 19 < v.Point.x < 81 and 14 < v.Point.y < 46

    mouth = [e for e in part.Edges if all(on_mouth(v) for v in e.Vertexes)]
    assert len(mouth) == 4, len(mouth)
    part = part.makeChamfer(2, mouth)
    path = os.path.join(folder, "chamfered_pocket.brep")
    part.exportBrep(path)
    return path


class EdgeChamferTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="aeronc_chamfer_")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def test_pocket_mouth_chamfer_is_cut_and_seen_finished(self):
        run = main_job.run(_write_part(self.tmp), os.path.join(self.tmp, "out"), say=lambda _: None)
        chain = run["chain"]
        chamfers = [u for u in chain["units"] if u["operation"] == "chamfer"]
        self.assertEqual(len(chamfers), 1)
        unit = chamfers[0]
        self.assertEqual((unit["step"], unit["tool"]), ("e", "CM-90-D6"))
        self.assertAlmostEqual(unit["top"], 20.0, places=6)
        self.assertAlmostEqual(unit["bottom"], 18.0 - 0.2, places=6)
        self.assertFalse(any("chamfer" in g["reason"] for g in chain["unmachined"]))
        with open(os.path.join(self.tmp, "out", "verification.json")) as f:
            report = json.load(f)
        self.assertEqual(report["gouges"]["count"], 0, report["gouges"].get("worst"))
        self.assertEqual(report["collisions"]["count"], 0, report["collisions"].get("worst"))
        pocket = next(e for e in run["recognition"]["elements"] if e["id"] == unit["element"])
        self.assertEqual(len(pocket["chamferFaces"]), 4)
        faces = [f for f in report["coverage"]["faces"] if f["face"] in set(pocket["chamferFaces"])]
        self.assertEqual(len(faces), 4)
        # Uncut, each face stands whole, 2 x sin 45 = 1.41 mm deep. Cut, only the two sharp miters
        # where it meets its neighbours keep a sliver: a cone cannot enter a concave corner, and
        # misses it by (sqrt 2 - 1) x its radius there, 0.45 + h mm at h over the lower line
        # (0.72 mm deep at the top); over the 2 mm rise, on the sloping face, two such slivers.
        miss = math.sqrt(2) - 1
        slivers = 2 * math.sqrt(2) * miss * (0.45 * 2 + 2 ** 2 / 2)
        for f in faces:
            self.assertTrue(f["measured"], f)
            self.assertLess(f["uncoveredArea"], slivers, f)
            self.assertLess(f["maxLeftover"], miss * (0.45 + 2) * math.sqrt(0.5), f)


if __name__ == "__main__":
    unittest.main()
