"""The main job end to end on a generated double-sided panel, headless."""
import json
import os
import shutil
import tempfile
import unittest

import FreeCAD
import Part

from aeronc import _core
from aeronc.runs import main_job

PANEL = {"pocketsX": 2, "pocketsY": 1, "islands": False, "openings": False, "lighteningHoles": False,
         "joggles": False, "lowerRibs": False, "flange": False, "bottomPockets": True, "boltHoles": True}


def _write_panel(folder):
    brep, truth = _core.make_panel(json.dumps(PANEL))
    shape = Part.Shape()
    shape.importBrepFromString(brep)
    path = os.path.join(folder, "panel.brep")
    shape.exportBrep(path)
    return path, json.loads(truth)


class MainJobTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="aeronc_mainjob_")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def test_panel_to_programs_report_and_verification(self):
        part, _ = _write_panel(self.tmp)
        out = os.path.join(self.tmp, "out")
        lines = []
        run = main_job.run(part, out, say=lines.append)
        chain = run["chain"]
        setups = [s["name"] for s in chain["setups"]]
        self.assertEqual(sorted(setups), ["+Z", "-Z"])
        # One 840D and one LinuxCNC program per setup, each with moves.
        for k in range(1, len(setups) + 1):
            for ext in ("mpf", "ngc"):
                with open(os.path.join(out, "panel_setup{}.{}".format(k, ext))) as f:
                    text = f.read()
                self.assertIn("G1", text)
        # Every enabled unit is in the report's tables, and every operation was re-read and simulated.
        with open(os.path.join(out, "report.html")) as f:
            html = f.read()
        for u in chain["units"]:
            self.assertIn("<td class='n'>{}</td>".format(u["id"]), html)
        with open(os.path.join(out, "verification.json")) as f:
            report = json.load(f)
        self.assertEqual(len(report["ops"]), len([u for u in chain["units"] if u.get("enabled", True)]))
        self.assertGreater(report["stock"]["blankVolume"], report["stock"]["finalVolume"])
        self.assertTrue(all(op["removedVolume"] >= 0 for op in report["ops"]))
        # The program neither gouges nor rapids through material, and finishes what the plan finishes.
        self.assertEqual(report["gouges"]["count"], 0, report["gouges"].get("worst"))
        self.assertEqual(report["collisions"]["count"], 0, report["collisions"].get("worst"))
        self.assertEqual([v["check"] for v in run["verification"] if not v["ok"]], [])
        # One progress line per stage, then the total.
        self.assertTrue(lines[0].startswith("AeroNC main job"))
        self.assertIn("total", lines[-1])
        # A second run replaces the first's outputs: the same files, no backup.
        first = sorted(os.listdir(out))
        main_job.run(part, out, say=lambda _: None)
        self.assertEqual(sorted(os.listdir(out)), first)
        self.assertFalse([n for n in first if n.endswith(".FCStd1") or ".part" in n])

    def test_part_modelled_far_from_its_origin_stands_centred_on_the_table(self):
        # 700 mm off in X and -500 mm in Y: with the part's origin as the table's centre every move
        # would leave the AC-5AX's +-325 mm; the blank stands centred instead (the post's part zero).
        part, _ = _write_panel(self.tmp)
        shape = Part.read(part)
        shape.translate(FreeCAD.Vector(700, -500, 40))
        far = os.path.join(self.tmp, "far.brep")
        shape.exportBrep(far)
        blank = shape.BoundBox
        self.assertEqual(main_job.part_zero((blank.XMin, blank.YMin, blank.ZMin, blank.XMax, blank.YMax, blank.ZMax),
                                            {"u": (1, 0, 0), "v": (0, 1, 0), "w": (0, 0, 1)}),
                         [-(blank.XMin + blank.XMax) / 2, -(blank.YMin + blank.YMax) / 2, -blank.ZMin])
        out = os.path.join(self.tmp, "far")
        run = main_job.run(far, out, say=lambda _: None)
        self.assertEqual(len(run["programs"]), 4)
        with open(os.path.join(out, "verification.json")) as f:
            report = json.load(f)
        self.assertEqual(report["gouges"]["count"], 0, report["gouges"].get("worst"))
        self.assertEqual(report["collisions"]["count"], 0, report["collisions"].get("worst"))

    def test_part_without_elements_names_the_stage(self):
        box = os.path.join(self.tmp, "box.brep")
        Part.makeBox(50, 40, 10).exportBrep(box)
        with self.assertRaises(main_job.MainJobError) as ctx:
            main_job.run(box, os.path.join(self.tmp, "out"), say=lambda _: None)
        self.assertIn("recognise", str(ctx.exception))


if __name__ == "__main__":
    unittest.main()
