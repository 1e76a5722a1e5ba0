"""The main job's machine: the smallest of the knowledge base's whose travel holds every setup
(pipeline.machine_choice), on plates sized against the shipped machines' travel:
AC-5AX X +-325, Y +-325, Z -250...300; AC-5AX-L X +-500, Y +-550, Z -350...450;
AC-GANTRY X +-2000, Y +-1250, Z -250...1250."""
import json
import os
import shutil
import tempfile
import unittest

import FreeCAD
import Part
import Path

from aeronc.pipeline import knowledge_base, machine_choice
from aeronc.runs import main_job


def _plate(folder, name, length, width, height, pocket=(100, 80, 10)):
    """A plate with one pocket (R8 corners) in the middle of its top. The whole blank must stand
    within the travel, not only the toolpaths (a tool that cannot reach all of the part can
    neither face nor probe it); the long pockets make the toolpaths leave the smaller machines
    too."""
    plate = Part.makeBox(length, width, height)
    pl, pw, depth = pocket
    cut = Part.makeBox(pl, pw, depth + 1, FreeCAD.Vector((length - pl) / 2, (width - pw) / 2, height - depth))
    vertical = [e for e in cut.Edges if abs(e.Vertexes[0].Point.z - e.Vertexes[1].Point.z) > 1e-6]
    shape = plate.cut(cut.makeFillet(8, vertical))
    path = os.path.join(folder, name + ".brep")
    shape.exportBrep(path)
    return path


def _top(blank_x, blank_y, blank_z):
    return [{"name": "+Z", "direction": [0, 0, 1]}], (0.0, 0.0, 0.0, blank_x, blank_y, blank_z)


class ChoiceTest(unittest.TestCase):
    """The choice itself on blanks, with the shipped machines."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="aeronc_machine_choice_")
        cls.cands = machine_choice.candidates(knowledge_base.open_kb(os.path.join(cls.tmp, "kb.sqlite")))

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def choose(self, x, y, z, **kw):
        setups, blank = _top(x, y, z)
        return machine_choice.choose(self.cands, machine_choice.need_of_blank(blank, setups), **kw)

    def test_candidates_are_the_machines_with_a_post_smallest_first(self):
        # XA5032 has no machine file, AC-HEAD no knowledge-base row: neither can be chosen.
        self.assertEqual([c["name"] for c in self.cands], ["AC-5AX", "AC-5AX-L", "AC-GANTRY"])
        self.assertEqual(self.cands[2]["travel"]["X"], (-2000.0, 2000.0))

    def test_smallest_machine_that_holds_the_blank(self):
        self.assertEqual(self.choose(640, 300, 30)["name"], "AC-5AX")
        larger = self.choose(700, 300, 30)
        self.assertEqual(larger["name"], "AC-5AX-L")
        # Why: the AC-5AX leaves 25 mm of it out in X (700 / 2 - 325).
        self.assertIn("AC-5AX: setup +Z needs X -350.0...350.0", larger["why"])
        self.assertIn("by 25.0 mm", larger["why"])
        self.assertEqual(self.choose(1500, 300, 30)["name"], "AC-GANTRY")
        # Z: the blank stands on the table reference; 460 mm is beyond the AC-5AX-L's 450.
        self.assertEqual(self.choose(400, 300, 440)["name"], "AC-5AX-L")
        self.assertEqual(self.choose(400, 300, 460)["name"], "AC-GANTRY")
        # The chain turns the part in its setup: 300 x 1080 stands across the AC-5AX-L's X.
        self.assertEqual(self.choose(300, 1080, 30)["name"], "AC-5AX-L")

    def test_every_setup_counts(self):
        # 200 x 200 x 700: on its side (+X) the blank is 700 mm tall, beyond the AC-5AX-L's Z.
        setups = [{"name": "+Z", "direction": [0, 0, 1]}, {"name": "+X", "direction": [1, 0, 0]}]
        needs = machine_choice.need_of_blank((0, 0, 0, 700, 200, 200), setups)
        choice = machine_choice.choose(self.cands, needs)
        self.assertEqual(choice["name"], "AC-GANTRY")
        self.assertIn("setup +X needs Z 0.0...700.0, beyond its -350...450 by 250.0 mm", choice["why"])
        # Each smaller machine is named with the setup that leaves it by most.
        self.assertIn("AC-5AX: setup +X needs Z 0.0...700.0, beyond its -250...300 by 400.0 mm (blank); "
                      "1 other setup too", choice["why"])

    def test_too_big_for_every_machine_says_by_how_much(self):
        with self.assertRaises(machine_choice.MachineChoiceError) as ctx:
            self.choose(4500, 300, 30)
        text = str(ctx.exception)
        self.assertIn("no machine of the knowledge base holds the part: the largest, AC-GANTRY", text)
        self.assertIn("X -2250.0...2250.0, beyond its -2000...2000 by 250.0 mm", text)

    def test_named_machine_is_kept_or_refused_naming_one_that_holds(self):
        self.assertEqual(self.choose(700, 300, 30, named="AC-GANTRY")["name"], "AC-GANTRY")
        with self.assertRaises(machine_choice.MachineChoiceError) as ctx:
            self.choose(700, 300, 30, named="AC-5AX")
        self.assertIn("machine AC-5AX (named) does not hold the part", str(ctx.exception))
        self.assertIn("AC-5AX-L would", str(ctx.exception))

    def test_toolpaths_step_up_but_never_down(self):
        # The blank fits the AC-5AX; a move 8 mm above its 300 mm Z does not.
        setups = [{"name": "+Z", "partZero": [0, 0, 0], "operations": [_op(
            "G0 X0 Y0 Z308\nG1 X10 Y0 Z280 F5\nG2 X-10 Y0 Z280 I-10 J0 F5\nG81 X5 Y5 Z250 R290\n")]}]
        needs = machine_choice.need_of_paths(setups)
        # The arc about (0, 0) counts with its circle of radius 10; the cycle with its R level.
        self.assertEqual(needs[0]["boxes"], [([-10.0, -10.0, 250.0], [10.0, 10.0, 308.0])])
        self.assertEqual(machine_choice.choose(self.cands, needs, at_least="AC-5AX")["name"], "AC-5AX-L")
        self.assertEqual(machine_choice.choose(self.cands, needs, at_least="AC-GANTRY")["name"], "AC-GANTRY")


class _Op:
    """What need_of_paths reads of an operation: its Path."""

    def __init__(self, gcode):
        self.Path = Path.Path(gcode)


def _op(gcode):
    return _Op(gcode)


class MainJobMachineTest(unittest.TestCase):
    """The main job on plates each of which needs another machine."""

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="aeronc_main_job_machine_")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def run_job(self, part, **kw):
        out = os.path.join(self.tmp, "out")
        run = main_job.run(part, out, cell_size=2.0, pictures=False, say=lambda _: None, **kw)
        with open(os.path.join(out, "run.json")) as f:
            summary = json.load(f)
        with open(os.path.join(out, "report.html")) as f:
            html = f.read()
        return run, summary, html, out

    def assert_posted_and_safe(self, run, out, machine):
        self.assertTrue(run["programs"])
        for p in run["programs"]:
            self.assertTrue(os.path.exists(p["path"]), p["path"])
            with open(p["path"]) as f:
                text = f.read()
            self.assertIn("machine " + machine, text)
        self.assertEqual(run["verificationReport"]["gouges"]["count"], 0)
        self.assertEqual(run["verificationReport"]["collisions"]["count"], 0)

    def test_plate_too_long_for_the_ac5ax_goes_on_the_ac5ax_l(self):
        # The pocket runs nearly the plate's length: its toolpaths leave the AC-5AX's X too.
        part = _plate(self.tmp, "plate700", 700, 200, 25, pocket=(680, 120, 10))
        run, summary, html, out = self.run_job(part)
        self.assertEqual(run["machine"]["name"], "AC-5AX-L")
        self.assertEqual(summary["machine"]["name"], "AC-5AX-L")
        self.assertIn("by 25.0 mm", summary["machine"]["why"])
        self.assertIn("<b>AC-5AX-L</b>: the smallest machine whose travel holds every setup", html)
        self.assert_posted_and_safe(run, out, "AC-5AX-L")
        # The part zero stands the plate centred on the table: X from -350 to 350.
        self.assertEqual([round(v, 6) for v in run["programs"][0]["partZero"]], [-350.0, -100.0, 0.0])

    def test_plate_only_the_gantry_holds_is_posted_and_verified_on_it(self):
        part = _plate(self.tmp, "plate1400", 1400, 200, 25, pocket=(1380, 120, 10))
        run, summary, html, out = self.run_job(part)
        self.assertEqual(summary["machine"]["name"], "AC-GANTRY")
        # Turned across, the plate leaves the AC-5AX-L's Y by less than it leaves its X, and still does.
        self.assertIn("AC-5AX-L: setup +Z needs Y -700.0...700.0, beyond its -550...550 by 150.0 mm",
                      summary["machine"]["why"])
        self.assert_posted_and_safe(run, out, "AC-GANTRY")
        self.assertTrue(any(p["path"].endswith(".ngc") for p in run["programs"]))
        self.assertEqual(run["verdict"]["status"], "READY", run["verdict"]["text"])

    def test_plate_too_long_for_every_machine_fails_saying_by_how_much(self):
        part = _plate(self.tmp, "plate4500", 4500, 200, 25)
        with self.assertRaises(main_job.MainJobError) as ctx:
            self.run_job(part)
        text = str(ctx.exception)
        self.assertTrue(text.startswith("machine: no machine of the knowledge base holds the part"), text)
        self.assertIn("X -2250.0...2250.0, beyond its -2000...2000 by 250.0 mm", text)
        out = os.path.join(self.tmp, "out")
        self.assertFalse([n for n in os.listdir(out) if n.endswith((".mpf", ".ngc"))])
        with open(os.path.join(out, "run.json")) as f:
            self.assertEqual(json.load(f)["failed"]["stage"], "machine")

    def test_named_machine_is_used_or_refused(self):
        part = _plate(self.tmp, "plate700", 700, 200, 25)
        with self.assertRaises(main_job.MainJobError) as ctx:
            self.run_job(part, machine="AC-5AX")
        self.assertIn("machine AC-5AX (named) does not hold the part", str(ctx.exception))
        self.assertIn("AC-5AX-L would", str(ctx.exception))
        run, summary, _, out = self.run_job(part, machine="AC-GANTRY")
        self.assertEqual(summary["machine"]["name"], "AC-GANTRY")
        self.assert_posted_and_safe(run, out, "AC-GANTRY")

    def test_toolpaths_above_the_ac5ax_travel_step_up(self):
        # 298 mm tall: the blank fits the AC-5AX's Z (up to 300), the clearance moves above it do not.
        part = _plate(self.tmp, "block298", 200, 150, 298)
        run, summary, _, out = self.run_job(part)
        self.assertEqual(summary["machine"]["name"], "AC-5AX-L")
        self.assertIn("toolpaths", summary["machine"]["why"])
        self.assertIn("AC-5AX: setup +Z needs Z", summary["machine"]["why"])
        self.assert_posted_and_safe(run, out, "AC-5AX-L")


if __name__ == "__main__":
    unittest.main()
