"""The machining chain's operations posted as FreeCAD posts them: through AeroNC's LinuxCNC and
840D posts (loaded the way the Job's post dropdown does) and FreeCAD's own linuxcnc_post. Every
feed move and drill cycle of the operations' paths is read back, in order, from each program;
LinuxCNC's interpreter reads AeroNC's LinuxCNC program without error."""
import os
import re
import shutil
import subprocess
import tempfile
import unittest

import FreeCAD

from aeronc.pipeline import chain_building
from aeronc import makers, pathcompat
from aeronc.post import machines
from aeronc.tests.app import post_support as ps
from aeronc.tests import pathcompat as test_pathcompat
from aeronc.tests.app.support import make_panel_object, new_document

PANEL = {"pocketsX": 2, "pocketsY": 1, "bottomPockets": True, "joggles": False}
EXACT = "--precision 9 --angle-precision 10"
DRILL_CYCLES = ("G81", "G82", "G83")


def expected_poses(job):
    """(tip, axis) of every feed move and drill cycle of the Job's active operations, in order."""
    out = []
    for op in job.Operations.Group:
        if not pathcompat.op_active(op):
            continue
        pos = [None, None, None]
        for c in op.Path.Commands:
            p = c.Parameters
            if c.Name not in ("G0", "G1") + DRILL_CYCLES:
                continue
            pos = [p.get(k, pos[i]) for i, k in enumerate("XYZ")]
            if c.Name != "G0":
                out.append(((pos[0], pos[1], pos[2]), (0.0, 0.0, 1.0)))
    return out


class ChainPostTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="aeronc_chainpost_")
        cls.doc = new_document("AeroNCChainPost")
        part, _ = make_panel_object(cls.doc, PANEL)
        group = makers.create_machining_features(cls.doc, part)
        cls.chain = chain_building.build(group, "integral_panel", "7050-T7451",
                                          kb_path=os.path.join(cls.tmp, "kb.sqlite"))
        cls.machine_json, _ = machines.load("AC-5AX")

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.doc.Name)
        shutil.rmtree(cls.tmp, ignore_errors=True)

    def test_the_chain_has_jobs_with_cutting_and_drilling(self):
        self.assertEqual(len(self.chain.Jobs), 2)
        names = [c.Name for job in self.chain.Jobs for op in job.Operations.Group for c in op.Path.Commands]
        self.assertIn("G1", names)
        self.assertTrue(set(DRILL_CYCLES) & set(names))

    def _read_back(self, read, job):
        expected = expected_poses(job)
        self.assertGreater(len(expected), 10)
        cut = [r for r in read if r[2] != "rapid"]
        ps.match_in_order(self, expected, cut, 0)

    def test_aeronc_linuxcnc(self):
        post = test_pathcompat.post_processor("aeronc_linuxcnc")
        for job in self.chain.Jobs:
            text = post.export([job], "-", EXACT)
            self._read_back(ps.read_linuxcnc(text, self.machine_json), job)
            tcs = {pathcompat.tool_controller_of(op) for op in pathcompat.tooled_operations(job)}
            for tc in tcs:
                self.assertRegex(text, r"T{}\b.*M6|M6.*T{}\b".format(tc.ToolNumber, tc.ToolNumber))

    def test_aeronc_840d(self):
        post = test_pathcompat.post_processor("aeronc_840d")
        for job in self.chain.Jobs:
            text = post.export([job], "-", EXACT)
            self._read_back(ps.read_sinumerik(text, self.machine_json), job)
            cycles = sum(1 for op in job.Operations.Group for c in op.Path.Commands if c.Name in DRILL_CYCLES)
            self.assertEqual(len(re.findall(r"CYCLE8[123]\(", text)), cycles)

    def test_freecad_linuxcnc_post(self):
        post = test_pathcompat.builtin_post("linuxcnc")
        for job in self.chain.Jobs:
            text = post.export(pathcompat.job_post_objects(job), "-", "--no-show-editor --precision=6")
            read, pos, motion = [], [0.0, 0.0, 0.0], None
            for line in text.splitlines():
                words = dict(re.findall(r"([A-Z])([-+]?[\d.]+)", re.sub(r"\([^)]*\)", "", line)))
                if "G" in words:
                    motion = words["G"]
                for i, k in enumerate("XYZ"):
                    if k in words:
                        pos[i] = float(words[k])
                if motion in ("1", "81", "82", "83") and any(k in words for k in "XYZ"):
                    read.append((tuple(pos), (0.0, 0.0, 1.0), "feed"))
            expected = expected_poses(job)
            j = 0
            for tip, _ in expected:
                while j < len(read) and max(abs(a - b) for a, b in zip(read[j][0], tip)) > 1e-6:
                    j += 1
                self.assertLess(j, len(read), "{} not in FreeCAD's LinuxCNC program".format(tip))
                j += 1
            self.assertEqual(j, len(read))

    def test_rs274_reads_the_aeronc_linuxcnc_program(self):
        rs274 = shutil.which("rs274")
        if not rs274:
            self.skipTest("rs274 not installed (linuxcnc-uspace)")
        post = test_pathcompat.post_processor("aeronc_linuxcnc")
        for job in self.chain.Jobs:
            text = post.export([job], "-", "--precision 4 --angle-precision 4")
            table = os.path.join(self.tmp, "tools.tbl")
            with open(table, "w") as f:
                for tc in pathcompat.tool_controllers(job):
                    f.write("T{0} P{0} D{1} Z0.0 ;{2}\n".format(tc.ToolNumber, tc.Tool.Diameter.Value, tc.Label))
            program = os.path.join(self.tmp, "chain.ngc")
            with open(program, "w") as f:
                f.write(text)
            run = subprocess.run([rs274, "-t", table, "-g", program], capture_output=True, text=True, timeout=300)
            errors = [l for l in run.stderr.splitlines() if l.strip() and l.strip() != "executing"]
            self.assertEqual(run.returncode, 0, "\n".join(errors))
            self.assertEqual(errors, [])
            self.assertIn("STRAIGHT_FEED", run.stdout)


if __name__ == "__main__":
    unittest.main()
