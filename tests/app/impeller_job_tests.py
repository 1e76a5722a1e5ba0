"""The impeller run (scripts/run.sh impeller) on a small impeller with coarse toolpaths: every
output is written, the report states the dimensions against the truth and the checks, the
saved document reopens with its program."""
import json
import os
import shutil
import tempfile
import unittest

import FreeCAD

from aeronc.runs import impeller_run
from aeronc.tests.parts import impeller_part
from aeronc.objects.impeller_program import is_impeller_program

SPEC = {"bladeCount": 3, "filletRadius": 2.0, "bladeHeight": 11.0}
OUTPUTS = ["impeller.FCStd", "IMPELLER.mpf", "IMPELLER.apt", "report.html", "features.png", "toolpaths.png",
           "impeller.step", "truth.json", "impeller.json", "kb.sqlite", "freecad.log"]


class ImpellerJobTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.out = tempfile.mkdtemp(prefix="aeronc_impeller_job_")
        cls.lines = []
        shape, truth = impeller_part.make_test_impeller(SPEC)
        cls.data = impeller_run.run(cls.out, shape, truth, source="generated impeller", allowance=2.0, stations=4,
                                    channels=1, say=cls.lines.append)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.out, ignore_errors=True)

    def test_outputs(self):
        for name in OUTPUTS:
            path = os.path.join(self.out, name)
            self.assertTrue(os.path.isfile(path) and os.path.getsize(path) > 0, name)
        with open(os.path.join(self.out, "IMPELLER.mpf")) as f:
            program = f.read()
        self.assertIn("TRAORI", program)
        self.assertTrue(program.startswith("%_N_IMPELLER_MPF"))
        with open(os.path.join(self.out, "truth.json")) as f:
            self.assertEqual(json.load(f), self.data["truth"])
        self.assertTrue(any("program impeller" in line for line in self.lines), self.lines)

    def test_report(self):
        with open(os.path.join(self.out, "report.html")) as f:
            page = f.read()
        for text in ("Dimensions against the generator's truth", "Process route", "Cutting data from the "
                     "cutting-parameter optimiser", "Gouge, holder and link checks", "features.png", "toolpaths.png",
                     "TB-4-3"):
            self.assertIn(text, page)
        # The channels are roughed with a ball of the knowledge base that fits the narrowest
        # channel, and the report's tools table names it.
        rough = [o for o in self.data["operations"] if o["operation"] == "rough_channels"]
        self.assertEqual(len(rough), 1, [o["operation"] for o in self.data["operations"]])
        tool = [t for t in self.data["tools"] if t["id"] == rough[0]["tool"]][0]
        self.assertEqual(tool["type"], "ball")
        self.assertLess(tool["diameter"], self.data["truth"]["minChannelWidth"])
        self.assertIn("<td>{}</td><td>ball</td>".format(tool["id"]), page)
        # Every dimension within 1e-3 mm of the truth, features exact, both checks pass.
        self.assertNotIn("FAIL", page)
        # 5 dimensions, the features verdict, 6 blades, hub, bore, planes, 4 checks (5-axis, their
        # rapids, the axial steps, the program read back).
        self.assertEqual(page.count('<span class="ok">pass</span>'), 5 + 1 + 6 + 3 + 4)
        self.assertEqual(self.data["check"]["linkCollisions"], 0)
        self.assertGreater(self.data["check"]["links"], 0)
        d, t = self.data["result"]["dimensions"], self.data["truth"]
        for key in impeller_run.DIMENSION_KEYS:
            self.assertAlmostEqual(d[key], t[key], delta=1e-3, msg=key)
        self.assertLessEqual(self.data["recheck"]["maxGougeMm"], impeller_run.LIMIT_GOUGE_MM)
        self.assertEqual(self.data["recheck"]["holderCollisions"], 0)
        self.assertGreater(self.data["recheck"]["positions"], 0)

    def test_document_reopens(self):
        doc = FreeCAD.openDocument(os.path.join(self.out, "impeller.FCStd"))
        try:
            progs = [o for o in doc.Objects if is_impeller_program(o)]
            self.assertEqual(len(progs), 1)
            self.assertIs(progs[0].Job.Stock, progs[0].Blank)
            self.assertEqual(progs[0].ProgramFile, os.path.join(self.out, "IMPELLER.mpf"))
            with open(progs[0].ProgramFile) as f:
                self.assertEqual(f.read(), progs[0].Posted)
        finally:
            FreeCAD.closeDocument(doc.Name)
