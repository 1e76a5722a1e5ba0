"""The posts on the sample panel (post_sample_job.py): FreeCAD's own Profile, 3+2 bevels, a
5-axis chamfer and drilling along the recognised hole axes. Every pose of the job comes back
from the 840D and LinuxCNC programs through the forward kinematics, and LinuxCNC's rs274 (when
installed) reads the LinuxCNC program without an error at the same positions."""
import math
import os
import re
import shutil
import subprocess
import tempfile
import unittest

import FreeCAD
import Part

import aeronc
from aeronc import pathcompat
from aeronc.post import machines, nc_post
from aeronc.tests.app import post_sample_job
from aeronc.tests.app import post_support as ps


def expected_poses(job):
    """(tip, axis) of every move and hole bottom of the Job's operations, as FreeCAD stores
    them, once every coordinate is known (the post's convention: axis modal, +Z per operation)."""
    poses, pos, before = [], {}, {}
    for op in job.Operations.Group:
        axis = (0.0, 0.0, 1.0)
        for c in op.Path.Commands:
            p = c.Parameters
            if all(k in p for k in "UVW"):
                axis = ps.normalised(tuple(ps.stored(p[k]) for k in "UVW"))
            if c.Name in ("G0", "G1", "G2", "G3", "G81", "G82", "G83", "G73"):
                pos.update({k: ps.stored(p[k]) for k in "XYZ" if k in p})
                pose = ((pos.get("X"), pos.get("Y"), pos.get("Z")), axis)
                if len(pos) == 3 and (not poses or poses[-1] != pose):  # a repeated pose is one stop
                    poses.append(pose)
                if c.Name.startswith("G8") or c.Name == "G73":
                    pos = dict(before)  # G98: the cycle returns to where it started
            before = dict(pos)
    return poses


class SamplePanelPostTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.doc = FreeCAD.newDocument("SamplePost")
        part = cls.doc.addObject("Part::Feature", "Part")
        part.Shape = Part.read(os.path.join(aeronc.PACKAGE_DIR, "resources", "samples", "sample_panel.step"))
        cls.doc.recompute()
        cls.job, cls.holes = post_sample_job.build_job(cls.doc, part)
        cls.objects = pathcompat.job_post_objects(cls.job)
        cls.poses = expected_poses(cls.job)
        cls.machine_json, _ = machines.load("AC-5AX")

    @classmethod
    def tearDownClass(cls):
        FreeCAD.closeDocument(cls.doc.Name)

    def test_the_job_has_every_kind_of_operation(self):
        labels = [o.Label for o in self.job.Operations.Group]
        self.assertEqual(labels, ["Profile", "EndBevels", "EdgeChamfer", "Holes"])
        self.assertEqual(len(self.holes), 9)  # the 6.6 mm holes of the top setup
        self.assertGreater(len(self.poses), 100)

    def test_840d_program(self):
        nc = nc_post.export(self.objects, "-", "--precision 9 --angle-precision 10", "840d")
        read = ps.read_sinumerik(nc, self.machine_json)
        ps.match_in_order(self, self.poses, read, len(self.holes) + 2 * nc.count("branch change"))
        self.assertEqual(nc.count("\nTRAORI\n"), 1)       # the chamfer
        bevels = re.findall(r"CYCLE800\(1,\"TC1\",0,57,[^,]*,[^,]*,[^,]*,0,(-?30(?:\.\d+)?),0,0,0,0,(-?1),", nc)
        self.assertEqual([(round(float(b), 3), d) for b, d in bevels], [(-30.0, "-1"), (30.0, "1")])  # 3+2 bevels
        self.assertEqual(nc.count("CYCLE81(") + nc.count("CYCLE83("), len(self.holes))
        self.assertIn("T2 D1 M6", nc)

    def test_linuxcnc_program_passes_rs274(self):
        lc = nc_post.export(self.objects, "-", "--precision 4 --angle-precision 4", "linuxcnc")
        read = ps.read_linuxcnc(lc, self.machine_json)
        loose = [(t, u) for t, u in self.poses]
        # 4 decimals: compare to 2e-3 mm / 2e-5 rad here, exactly in the other tests.
        j = 0
        for tip, axis in loose:
            while j < len(read) and not (ps.dist(read[j][0], tip) < 2e-3 and ps.angle_between(read[j][1], axis) < 2e-5):
                j += 1
            self.assertLess(j, len(read), "pose {} not in the LinuxCNC program".format((tip, axis)))
            j += 1
        rs274 = shutil.which("rs274")
        if not rs274:
            self.skipTest("rs274 not installed (linuxcnc-uspace)")
        work = tempfile.mkdtemp(prefix="aeronc_rs274_")
        with open(os.path.join(work, "tools.tbl"), "w") as f:
            f.write("T1 P1 D5.0 Z0.0 ;end mill\nT2 P2 D6.6 Z0.0 ;drill\n")
        with open(os.path.join(work, "sample.ngc"), "w") as f:
            f.write(lc)
        run = subprocess.run([rs274, "-t", os.path.join(work, "tools.tbl"), "-g", os.path.join(work, "sample.ngc")],
                             capture_output=True, text=True, timeout=300)
        errors = [l for l in run.stderr.splitlines() if l.strip() and l.strip() != "executing"]
        self.assertEqual(run.returncode, 0, "\n".join(errors))
        self.assertEqual(errors, [])
        moves = []
        for line in run.stdout.splitlines():
            m = re.search(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED)\((.*)\)", line)
            if m:
                v = [float(x) for x in m.group(2).split(",")]
                moves.append((v[0], v[1], v[5], v[6], v[8]) if m.group(1) == "ARC_FEED" else (v[0], v[1], v[2], v[3], v[5]))
        j = 0
        for tip, axis in loose:
            while j < len(moves):
                x, y, z, a, c = moves[j]
                t, u = pathcompat_fk(self.machine_json, (x, y, z), (a, c))
                if ps.dist(t, tip) < 2e-3 and ps.angle_between(u, axis) < 2e-5:
                    break
                j += 1
            self.assertLess(j, len(moves), "pose {} not among rs274's positions".format((tip, axis)))
            j += 1


def pathcompat_fk(machine_json, linear, rotary):
    from aeronc import _core
    return _core.forward_kinematics(machine_json, list(linear), list(rotary), None, 0.0)


if __name__ == "__main__":
    unittest.main()
