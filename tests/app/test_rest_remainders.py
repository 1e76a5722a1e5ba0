"""Finish what the crib reaches: a generated panel whose pockets have sharp (R0) vertical corners
runs through the main job. The pockets are finished with the smallest end mill that reaches
them, the corners it leaves are listed as remainders with their area (not the pockets as not
machined), and the delivered programs neither gouge nor lose an operation to the gate."""
import json
import os
import shutil
import tempfile
import unittest

import Part

from aeronc import _core
from aeronc.runs import main_job

SHARP = {"pocketsX": 2, "pocketsY": 1, "thickness": 20, "webZ": 8, "cornerRadius": 0, "islands": False,
         "openings": False, "lighteningHoles": False, "joggles": False, "lowerRibs": False, "flange": False,
         "bottomPockets": False, "boltHoles": False}


class RestRemaindersTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="aeronc_remainders_")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def test_sharp_cornered_pockets_are_finished_and_their_corners_listed(self):
        brep, truth = _core.make_panel(json.dumps(SHARP))
        shape = Part.Shape()
        shape.importBrepFromString(brep)
        part = os.path.join(self.tmp, "sharp.brep")
        shape.exportBrep(part)
        out = os.path.join(self.tmp, "out")
        run = main_job.run(part, out, say=lambda _: None)
        with open(os.path.join(out, "chain.json")) as f:
            chain = json.load(f)
        pockets = [e["id"] for e in chain["elements"] if e["featureType"] == "closed_pocket"]
        self.assertEqual(len(pockets), 2)
        self.assertEqual([u for u in chain["unmachined"] if u["element"] in pockets], [])
        for p in pockets:
            walls = [u for u in chain["units"] if u["element"] == p and u["step"] == "fs"]
            self.assertTrue(walls, p)
            left = [r for r in chain["remainders"] if r["element"] == p]
            self.assertEqual(len(left), 1, left)
            r = left[0]
            self.assertEqual((r["kind"], r["tool"]), ("corners", walls[-1]["tool"]))
            self.assertAlmostEqual(r["toolRadius"], walls[-1]["cutter"]["diameter"] / 2, places=9)
            self.assertAlmostEqual(r["depth"], 12.0, places=6)
            # Four 90-degree corners: 4 (1 - pi/4) r^2 in plan.
            self.assertAlmostEqual(r["area"], 4 * (1 - 3.141592653589793 / 4) * r["toolRadius"] ** 2,
                                   delta=0.1 * r["area"])
            self.assertIn("sharp", r["needs"])
        # Safe, and nothing the chain added was left out by the gate.
        with open(os.path.join(out, "verification.json")) as f:
            report = json.load(f)
        self.assertEqual(report["gouges"]["count"], 0, report["gouges"].get("worst"))
        self.assertEqual(report["collisions"]["count"], 0, report["collisions"].get("worst"))
        self.assertEqual(run["leftOut"], [])
        # What the corners keep is named with the remainder, against the pockets' faces.
        for entry in run["materialLeft"]:
            if entry["element"] in pockets:
                self.assertIn("left by", entry["reason"])
                self.assertIn("the corners", entry["reason"])
        self.assertNotIn("not machined", " ".join(e["reason"] for e in run["materialLeft"]))


if __name__ == "__main__":
    unittest.main()
