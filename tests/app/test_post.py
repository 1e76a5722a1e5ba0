"""The 5-axis posts inside FreeCAD, headless: listed and loaded the way the Job's post
dropdown does, posting oriented operations whose programs, read back independently and run
through the forward kinematics, give the input tip and axis again."""
import glob
import json
import re
import math
import os
import random
import sqlite3
import tempfile
import unittest

import FreeCAD
import Part
import Path

import aeronc
from aeronc import pathcompat
from aeronc.tests import pathcompat as test_pathcompat
from aeronc.post import PostError, apt, machines
from aeronc.tests.app import post_support as ps

EXACT = "--precision 9 --angle-precision 10"


def _load(name):
    return test_pathcompat.post_processor(name)  # FreeCAD's own loader, as the Job uses


class PostTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.machine_json, _ = machines.load("AC-5AX")
        cls.tmp = tempfile.mkdtemp(prefix="aeronc_post_")

    def setUp(self):
        self.doc = FreeCAD.newDocument("PostTest")
        box = self.doc.addObject("Part::Box", "Blank")
        box.Length, box.Width, box.Height = 100, 60, 20
        self.doc.recompute()
        self.job = pathcompat.create_job(self.doc, [box])
        self.doc.recompute()
        self.tc = self.job.Tools.Group[0]
        self.tc.HorizFeed = "1200 mm/min"
        self.tc.VertFeed = "300 mm/min"
        self.tc.SpindleSpeed = 12000

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)

    def post(self, name, argstring=EXACT, objects=None, filename="-"):
        return _load(name).export(objects if objects is not None else [self.job], filename, argstring)

    # -- listing -------------------------------------------------------------------------
    def test_posts_are_listed_in_the_job_dropdown_and_load(self):
        posts = test_pathcompat.available_posts()
        for name in ("aeronc_840d", "aeronc_linuxcnc", "aeronc_apt"):
            self.assertIn(name, posts)
            self.assertTrue(_load(name).tooltip)
        folder = pathcompat.post_folder()
        self.assertTrue(os.path.isfile(os.path.join(folder, "aeronc_840d_post.py")))

    # -- round trips ---------------------------------------------------------------------
    def _oriented_job(self):
        rng = random.Random(5)
        simultaneous = ps.OrientedPath()
        for i in range(150):
            tip = (rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-20, 20))
            simultaneous.move("G0" if i % 15 == 0 else "G1", tip, ps.axis_at(rng.uniform(0, 100), rng.uniform(-180, 180)))
        # Through the pole along one great circle, then three turns around the part (C unwinds).
        for k in range(-30, 31, 3):
            simultaneous.move("G1", (k, 4.0, 12.0), ps.axis_at(abs(k), 210 if k < 0 else 30))
        for k in range(0, 3 * 36 + 1):
            az = 10.0 * k
            simultaneous.move("G1", (30 * math.cos(math.radians(az)), 30 * math.sin(math.radians(az)), 5.0),
                              ps.axis_at(35, az))
        plane = ps.OrientedPath()
        u = ps.axis_at(40, -60)
        for p in ((0, 0, 30), (0, 0, 2), (20, 5, 2), (25, 25, 2), (0, 0, 30)):
            plane.move("G0" if p[2] > 10 else "G1", p, u)
        holes = ps.OrientedPath()
        holes.raw("G99")
        for h in range(5):
            a = ps.axis_at(12.0 * h, 70.0 * h)
            bottom = (15.0 * h - 30, -10.0 + 4 * h, -3.0)
            holes.move("G0", tuple(b + 25 * c for b, c in zip(bottom, a)), a)
            holes.drill("G83" if h % 2 else "G81", bottom, a, 10.0, peck=2.0 if h % 2 else None)
        holes.raw("G80")
        ops = [ps.add_operation(self.doc, self.job, "Swarf", simultaneous.commands, self.tc),
               ps.add_operation(self.doc, self.job, "TiltedPocket", plane.commands, self.tc),
               ps.add_operation(self.doc, self.job, "NormalDrilling", holes.commands, self.tc)]
        self.doc.recompute()
        return ops, simultaneous.poses + plane.poses + holes.poses

    def test_oriented_operations_round_trip_through_both_dialects(self):
        _, poses = self._oriented_job()
        nc = self.post("aeronc_840d")
        read = ps.read_sinumerik(nc, self.machine_json)
        # Added moves: retract + reposition at each branch change, a drilling approach per hole.
        changes = nc.count("branch change")
        ps.match_in_order(self, poses, read, 2 * changes + 5)
        self.assertTrue(nc.startswith("%_N_JOB_MPF\n"))
        self.assertEqual(nc.count("\nTRAORI\n"), 1)
        self.assertIn("CYCLE83(", nc)
        self.assertTrue(nc.rstrip().endswith("M30"))

        lc = self.post("aeronc_linuxcnc")
        read = ps.read_linuxcnc(lc, self.machine_json)
        ps.match_in_order(self, poses, read, 2 * lc.count("branch change") + 5)
        self.assertGreaterEqual(lc.count("branch change"), 1)  # three turns exceed C's +-360
        for _, _, _, n, (a, c) in read:
            self.assertLessEqual(abs(a), 120 + 1e-9, "A beyond its limit at line {}".format(n))
            self.assertLessEqual(abs(c), 360 + 1e-9, "C beyond its limit at line {}".format(n))

    def test_vector_output_round_trips(self):
        _, poses = self._oriented_job()
        nc = self.post("aeronc_840d", EXACT + " --orientation vectors --vector-precision 13")
        self.assertIn("A3=", nc)
        read = ps.read_sinumerik(nc, self.machine_json, vectors=True)
        ps.match_in_order(self, poses, read, 2 * nc.count("branch change") + 5)

    def test_reopened_document_posts_the_same_program(self):
        self._oriented_job()
        before = self.post("aeronc_840d", "")
        path = os.path.join(self.tmp, "reopen.FCStd")
        self.doc.saveAs(path)
        name = self.doc.Name
        FreeCAD.closeDocument(name)
        self.doc = FreeCAD.openDocument(path)
        self.job = pathcompat.find_jobs(self.doc)[0]
        self.assertEqual(self.post("aeronc_840d", ""), before)

    def test_freecad_profile_posts_where_freecads_linuxcnc_post_puts_it(self):
        linuxcnc_post = test_pathcompat.builtin_post("linuxcnc")
        test_pathcompat.create_profile("Profile")
        self.doc.recompute()
        ours = self.post("aeronc_linuxcnc", "--no-inverse-time")
        theirs = linuxcnc_post.export(pathcompat.job_post_objects(self.job), "-", "--no-show-editor")

        def positions(text):
            pos, out = {}, []
            for line in text.splitlines():
                line = line.split("(")[0]
                words = dict((w[0], float(w[1:])) for w in line.split() if w[0] in "XYZ")
                if words:
                    pos.update(words)
                    if len(pos) == 3:
                        out.append((pos["X"], pos["Y"], pos["Z"]))
            return out

        a, b = positions(ours), positions(theirs)
        # linuxcnc_post writes every command; ours drops repeated words: compare the distinct stops.
        dedup = lambda s: [p for i, p in enumerate(s) if i == 0 or p != s[i - 1]]
        a, b = dedup(a), dedup(b)
        self.assertGreater(len(b), 20)
        self.assertEqual(len(a), len(b))
        for p, q in zip(a, b):
            self.assertLess(ps.dist(p, q), 2e-3)

    # -- APT -----------------------------------------------------------------------------
    def test_apt_file_posts_to_the_same_moves(self):
        self._oriented_job()
        cl = os.path.join(self.tmp, "job.apt")
        text = self.post("aeronc_apt", "", filename=cl)
        self.assertTrue(os.path.isfile(cl))
        self.assertIn("GOTO/", text)
        self.assertIn("CYCLE/DEEP", text)
        self.assertIn("LOADTL/1", text)
        direct = self.post("aeronc_840d")
        via_apt = apt.post_apt_file(cl, os.path.join(self.tmp, "job.mpf"), EXACT)
        a = [(t, u) for t, u, _, _ in ps.read_sinumerik(direct, self.machine_json)]
        b = [(t, u) for t, u, _, _ in ps.read_sinumerik(via_apt, self.machine_json)]
        self.assertEqual(len(a), len(b))
        for (t1, u1), (t2, u2) in zip(a, b):
            self.assertLess(ps.dist(t1, t2), 1e-6)
            self.assertLess(ps.angle_between(u1, u2), 1e-9)

    def test_bad_apt_names_the_line(self):
        cl = os.path.join(self.tmp, "bad.apt")
        with open(cl, "w") as f:
            f.write("PARTNO/BAD\nLOADTL/1\nFEDRAT/100,MMPM\nGOTO/1,2,3,0,0,1\nGOTO/1,2,3,0,0,-1\n")
        out = os.path.join(self.tmp, "bad.mpf")
        with self.assertRaises(PostError) as ctx:
            apt.post_apt_file(cl, out, "")
        self.assertIn("APT line 5", str(ctx.exception))
        self.assertIn("out of reach", str(ctx.exception))
        self.assertFalse(os.path.exists(out))

    # -- bad input -----------------------------------------------------------------------
    def _expect_error(self, argstring, *fragments):
        target = os.path.join(self.tmp, "keep.mpf")
        with open(target, "w") as f:
            f.write("old program\n")
        with self.assertRaises(PostError) as ctx:
            self.post("aeronc_840d", argstring, filename=target)
        for fragment in fragments:
            self.assertIn(fragment, str(ctx.exception))
        with open(target) as f:
            self.assertEqual(f.read(), "old program\n")  # untouched
        self.assertEqual(glob.glob(os.path.join(self.tmp, ".keep.mpf.*")), [])  # no partial file

    def test_orientation_beyond_the_a_limits(self):
        p = ps.OrientedPath()
        p.move("G0", (0, 0, 50), (0, 0, 1))
        p.move("G1", (0, 0, 0), ps.axis_at(130, 0))
        ps.add_operation(self.doc, self.job, "Undercut", p.commands, self.tc)
        self._expect_error("", "operation 'Undercut', move 2", "A outside [-120.000, 120.000]")

    def test_nan(self):
        cmds = [Path.Command("G0", {"X": 0, "Y": 0, "Z": 10}), Path.Command("G1", {"X": float("nan"), "Y": 0, "Z": 0, "F": 5})]
        ps.add_operation(self.doc, self.job, "Broken", cmds, self.tc)
        self._expect_error("", "operation 'Broken', move 2", "not a finite number")

    def test_missing_tool_controller(self):
        ps.add_operation(self.doc, self.job, "NoTool", [Path.Command("G0", {"X": 0, "Y": 0, "Z": 10})], None)
        self._expect_error("", "operation 'NoTool'", "no tool controller")

    # -- operations that are not ready ---------------------------------------------------
    def _job_with_failed_operations(self):
        """Good (T1), Empty (T2, no path: a unit the toolpath core refused), Refused (T1, moves
        but marked No toolpath), Gouging (T3, marked Failed by a verification)."""
        from aeronc.operations.base import mark
        from aeronc.post import readiness
        t2 = pathcompat.add_tool_controller(self.job, "TC2", 2)
        t3 = pathcompat.add_tool_controller(self.job, "TC3", 3)
        cut = [Path.Command("G0", {"X": 0, "Y": 0, "Z": 10}), Path.Command("G1", {"X": 20, "Y": 0, "Z": -1, "F": 5})]
        ps.add_operation(self.doc, self.job, "Good", cut, self.tc)
        ps.add_operation(self.doc, self.job, "Empty", [], t2)
        refused = ps.add_operation(self.doc, self.job, "Refused", cut, self.tc)
        mark(refused, readiness.NO_TOOLPATH, "the cutter (D 2 mm) does not fit in the pocket")
        gouging = ps.add_operation(self.doc, self.job, "Gouging", cut, t3)
        mark(gouging, readiness.FAILED, "gouges the part: 3 moves, worst 0.52 mm beyond its allowance")
        self.doc.recompute()

    def test_posts_refuse_an_operation_without_a_toolpath_or_failing_its_check(self):
        self._job_with_failed_operations()
        for name in ("aeronc_840d", "aeronc_linuxcnc", "aeronc_apt"):
            target = os.path.join(self.tmp, "refused_" + name)
            with self.assertRaises(PostError) as ctx:
                self.post(name, "", filename=target)
            self.assertIn("operation 'Empty' is not ready to post: no toolpath", str(ctx.exception))
            self.assertIn("--skip-failed", str(ctx.exception))
            self.assertFalse(os.path.exists(target))  # no program at all, not half of one
        self.doc.getObject("Empty").Active = False  # switched off: the next one is named
        with self.assertRaises(PostError) as ctx:
            self.post("aeronc_840d", "")
        self.assertIn("operation 'Refused' is not ready to post: no toolpath: the cutter (D 2 mm) does not fit",
                      str(ctx.exception))

    def test_skip_failed_leaves_them_out_with_a_comment_and_no_idle_tool_change(self):
        self._job_with_failed_operations()
        nc = self.post("aeronc_840d", "--skip-failed")
        head = nc.split("G54")[0]
        self.assertIn("; INCOMPLETE PROGRAM: 3 operations left out", head)
        self.assertIn("; left out: Empty: no toolpath", head)
        self.assertIn("; left out: Refused: no toolpath: the cutter (D 2 mm) does not fit in the pocket", head)
        self.assertIn("; left out: Gouging: gouges the part: 3 moves, worst 0.52 mm", head)
        self.assertEqual(nc.count("; operation: "), 1)
        self.assertIn("; operation: Good", nc)
        # Only the good operation's tool is called; T2 and T3 served operations left out.
        self.assertEqual(re.findall(r"\bT(\d+) D1 M6", nc), ["1"])
        lc = self.post("aeronc_linuxcnc", "--skip-failed")
        self.assertIn("(left out: Gouging: gouges the part: 3 moves, worst 0.52 mm beyond its allowance)", lc)
        self.assertIn("(left out: Refused: no toolpath: the cutter [D 2 mm] does not fit in the pocket)", lc)
        self.assertEqual(re.findall(r"\bT(\d+) M6", lc), ["1"])
        self.assertEqual(lc.count("(operation: "), 1)
        apt_text = self.post("aeronc_apt", "--skip-failed")
        self.assertIn("Gouging", apt_text)
        self.assertEqual(re.findall(r"LOADTL/(\d+)", apt_text), ["1"])

    def test_a_long_reason_is_cut_into_comment_lines_a_controller_reads(self):
        from aeronc.operations.base import mark
        from aeronc.post import readiness
        self._job_with_failed_operations()
        where = "move {}, a wall of face 411 at x 577.0 y 23.4 z 254.3".format(112050)
        why = "; ".join(["gouges the part: 2416 moves, worst 1.51 mm beyond its allowance [{}]".format(where)] * 4)
        mark(self.doc.getObject("Gouging"), readiness.FAILED, why)
        for name, start in (("aeronc_linuxcnc", "("), ("aeronc_840d", "; ")):
            text = self.post(name, "--skip-failed")
            self.assertTrue(all(len(line) <= 130 for line in text.splitlines()), name)
            lines = [line for line in text.split("G54")[0].splitlines() if line.startswith(start)]
            # The reason is all there, read across its lines.
            strip = (lambda l: l[1:-1].strip()) if start == "(" else (lambda l: l[2:].strip())
            self.assertIn("left out: Gouging: " + why, " ".join(strip(l) for l in lines))

    def test_unknown_machine(self):
        self._expect_error("--machine NOPE-5AX", "unknown machine 'NOPE-5AX'", "AC-5AX", "AC-HEAD")

    def test_unknown_argument(self):
        self._expect_error("--frobnicate", "post arguments", "--frobnicate")

    # -- machine data --------------------------------------------------------------------
    def test_machine_file_limits_match_the_knowledge_base(self):
        kb = os.path.join(aeronc.PACKAGE_DIR, "resources", "kb")
        db = sqlite3.connect(":memory:")
        for name in ("schema.sql", "default_data.sql"):
            with open(os.path.join(kb, name), encoding="utf-8") as f:
                db.executescript(f.read())
        for name in machines.known_machines():
            row = db.execute("SELECT a_min, a_max, c_min, c_max, max_feed_mm_min, max_spindle_rpm FROM machine "
                             "WHERE name = ?", (name,)).fetchone()
            if row is None:
                continue  # not in the knowledge base yet (the drilling head)
            text, _ = machines.load(name)
            machine = json.loads(text)
            axes = {a["name"]: (a["min"], a["max"]) for a in machine["rotaryAxes"]}
            self.assertEqual((axes["A"][0], axes["A"][1], axes["C"][0], axes["C"][1],
                              machine["maxFeed"], machine["maxSpindleSpeed"]), row, name)


if __name__ == "__main__":
    unittest.main()
