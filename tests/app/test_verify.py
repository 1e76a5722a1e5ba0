"""Verification of a program against the part through aeronc._core.simulate, headless: a
plate with a sharp-cornered pocket made by FreeCAD's Part, machined by a flat end mill. The
report names the faces by FreeCAD's FaceN, the corners the tool cannot reach stay uncovered,
a path 0.1 mm too low gouges the floor, and bad input gets a clear VerifyError."""
import json
import math
import os
import unittest

import FreeCAD
import Part

from aeronc import _core

SHARED = os.environ.get("AERONC_SHARED_DATA", "")

R = 3.0  # the end mill's radius


def _plate():
    box = Part.makeBox(60, 40, 20)
    return box.cut(Part.makeBox(40, 20, 12, FreeCAD.Vector(10, 10, 8)))


def _pocket_moves(z):
    """Zig-zag over the tool-centre rectangle [13, 47] x [13, 27], then once round it."""
    moves = [[0, 13, 13, 25], [2, 13, 13, z]]
    y, forward = 13.0, True
    while y <= 27 + 1e-9:
        a, b = (13, 47) if forward else (47, 13)
        moves += [[1, a, y, z], [1, b, y, z]]
        y, forward = y + 2, not forward
    moves += [[1, 13, 13, z], [1, 47, 13, z], [1, 47, 27, z], [1, 13, 27, z], [1, 13, 13, z], [0, 13, 13, 25]]
    return moves


class VerifyTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.part = _plate()
        cls.brep = cls.part.exportBrepToString()
        cls.floor = cls.walls = None
        cls.walls = []
        for n, f in enumerate(cls.part.Faces, start=1):
            b = f.BoundBox
            inside = b.XMin > 9.99 and b.XMax < 50.01 and b.YMin > 9.99 and b.YMax < 30.01
            if inside and abs(b.ZMax - 8) < 1e-9:
                cls.floor = n
            elif inside and b.ZMin > 7.99 and b.ZMax > 19.99:
                cls.walls.append(n)

    def simulate(self, z, cell=0.25):
        ops = {"cellSize": cell, "blank": [0, 0, 0, 60, 40, 20],
               "ops": [{"label": "pocket", "axis": [0, 0, 1], "cutter": {"diameter": 2 * R, "cornerRadius": 0},
                        "moves": _pocket_moves(z)}],
               "finishedFaces": [self.floor] + self.walls,
               "elements": {"pocket": [self.floor] + self.walls}}
        return json.loads(_core.simulate(self.brep, json.dumps(ops), json.dumps({"leftoverMap": False})))

    def test_faces_found(self):
        self.assertIsNotNone(self.floor)
        self.assertEqual(len(self.walls), 4)

    def test_pocketing_leaves_only_the_corners(self):
        r = self.simulate(8, cell=0.1)
        self.assertEqual(r["gouges"]["count"], 0)
        self.assertEqual(r["collisions"]["count"], 0)
        floor = next(f for f in r["coverage"]["faces"] if f["face"] == self.floor)
        self.assertAlmostEqual(floor["floorArea"], 800, delta=8)
        self.assertAlmostEqual(floor["maxLeftover"], 12, places=6)
        # A flat end mill leaves R^2 (1 - pi/4) in each sharp corner.
        corners = 4 * R * R * (1 - math.pi / 4)
        self.assertAlmostEqual(floor["uncoveredArea"], corners, delta=0.25 * corners)
        pocket = r["coverage"]["elements"][0]
        self.assertEqual(pocket["id"], "pocket")
        self.assertGreater(pocket["uncoveredArea"], floor["uncoveredArea"])  # the walls at the corners
        self.assertIsNone(r["leftover"])

    def test_too_low_gouges_the_floor(self):
        r = self.simulate(7.9)
        worst = r["gouges"]["worst"]
        self.assertAlmostEqual(worst["depth"], 0.1, places=6)
        self.assertEqual(worst["kind"], "floor")
        self.assertEqual(worst["face"], self.floor)
        self.assertEqual(worst["op"], "pocket")
        # The gate's reason for leaving the operation out says where its worst gouge is.
        from aeronc.pipeline.verification import failing_operations
        op = r["ops"][0]
        self.assertEqual(op["worstGougeAt"]["face"], self.floor)
        why = failing_operations(r)["pocket"]
        self.assertIn("worst 0.10 mm beyond its allowance (move ", why)
        self.assertIn("the top of face {} at x ".format(self.floor), why)
        self.assertIn(" z 8.0)", why)  # the height of the part met: the floor

    def test_bad_input_is_named(self):
        with self.assertRaisesRegex(_core.VerifyError, "ops"):
            _core.simulate(self.brep, json.dumps({"cellSize": 0.5}), "")
        with self.assertRaisesRegex(_core.VerifyError, "not valid JSON"):
            _core.simulate(self.brep, "{", "")
        with self.assertRaisesRegex(_core.VerifyError, "deflection"):
            _core.simulate(self.brep, json.dumps({"ops": []}), json.dumps({"deflection": -1}))
        with self.assertRaisesRegex(_core.VerifyError, "floorTolerence"):
            _core.simulate(self.brep, json.dumps({"ops": []}), json.dumps({"floorTolerence": 0.1}))
        with self.assertRaises(RuntimeError):
            _core.simulate("not a shape", json.dumps({"ops": []}), "")



class FinishedFacesTest(unittest.TestCase):
    """What the coverage check holds the plan to: the faces its finishing units finish, less
    those of elements the chain lists as not machined."""

    RESULT = {"elements": [
        {"id": 1, "floorFaces": [10], "contourFaces": [11, 12], "islandFaces": [[13]]},
        {"id": 2, "floorFaces": [20], "contourFaces": [12, 21], "islandFaces": []},
    ]}

    def chain(self, unmachined):
        units = [{"element": 1, "step": "w"}, {"element": 1, "step": "fs"}, {"element": 2, "step": "w"},
                 {"element": 2, "step": "r"}, {"element": 1, "step": "fs", "enabled": False}]
        return {"units": units, "unmachined": unmachined}

    def test_floors_and_walls_of_the_finishing_units(self):
        from aeronc.pipeline import verification
        faces, elements = verification.finished_faces(self.chain([]), self.RESULT)
        self.assertEqual(faces, [10, 11, 12, 13, 20])
        self.assertEqual(elements, {"E1": [10, 11, 12, 13], "E2": [20]})

    def test_an_unmachined_element_takes_its_faces_out_even_where_shared(self):
        from aeronc.pipeline import verification
        faces, elements = verification.finished_faces(
            self.chain([{"element": 2, "reason": "no tool", "step": "fs"}]), self.RESULT)
        self.assertEqual(faces, [10, 11, 13])  # 12 is element 2's wall too
        self.assertEqual(elements, {"E1": [10, 11, 13]})

    def test_an_entry_naming_faces_takes_out_only_those(self):
        from aeronc.pipeline import verification
        faces, elements = verification.finished_faces(
            self.chain([{"element": 1, "reason": "island top", "step": None, "faces": [13]}]), self.RESULT)
        self.assertEqual(faces, [10, 11, 12, 20])
        self.assertEqual(elements, {"E1": [10, 11, 12], "E2": [20]})



class PartBoxTest(unittest.TestCase):
    """The blank's box (setup_job.part_box) hugs the part: FreeCAD's BoundBox stands off some
    parts, which would put stock round them that no tool has to cut."""

    def test_arcs_extremes_are_bounded_within_the_deflection(self):
        from aeronc.pipeline import setup_job
        shape = Part.makeCylinder(10, 5, FreeCAD.Vector(3, 4, 1))
        box = setup_job.part_box(shape)
        for got, want in zip(box, (-7, -6, 1, 13, 14, 6)):
            self.assertAlmostEqual(got, want, delta=2e-6)

    def test_an_arc_on_a_side_plane_still_bounds_the_other_axes(self):
        """A cylinder lying along X: its circles stand in the planes x = 0 and x = 5, sides of
        the box, where x never varies; their y and z extremes still need the fine walk."""
        from aeronc.pipeline import setup_job
        shape = Part.makeCylinder(10, 5, FreeCAD.Vector(0, 2, 3), FreeCAD.Vector(1, 0, 0))
        box = setup_job.part_box(shape)
        for got, want in zip(box, (0, -8, -7, 5, 12, 13)):
            self.assertAlmostEqual(got, want, delta=2e-6)

    @unittest.skipUnless(os.path.isfile(os.path.join(SHARED, "nist", "nist_ftc_10_asme1_rb.stp")),
                         "no NIST parts in AERONC_SHARED_DATA")
    def test_nist_ftc_10_gets_its_drawn_size(self):
        from aeronc.pipeline import setup_job
        box = setup_job.part_box(Part.read(os.path.join(SHARED, "nist", "nist_ftc_10_asme1_rb.stp")))
        for got, want in zip(box, (-79, 0, -37.5, 79, 31, 37.5)):
            self.assertAlmostEqual(got, want, delta=2e-6)


if __name__ == "__main__":
    unittest.main()


class MachineTipsTest(unittest.TestCase):
    """The tool tips of a re-read program: one forward-kinematics call per operation gives what a
    call per move gives, carried into the part's frame by the setup's placement."""

    def test_batch_kinematics_matches_a_call_per_move_and_the_placement(self):
        from aeronc.pipeline import verification
        from aeronc.post import machines
        machine_json, _ = machines.load("AC-5AX")
        placed_json = json.dumps(dict(json.loads(machine_json), partZero=[12.0, -30.0, 85.0]))
        moves = [[0, 10.0, 20.0, 50.0, 0.0, 0.0], [1, -35.5, 60.25, 12.0, 30.0, 45.0],
                 [1, 100.0, -80.0, 5.0, -20.0, 190.0], [0, 0.0, 0.0, 120.0, 90.0, -90.0]]
        ops = [{"label": "Pocket E1 r U0", "moves": moves}]
        turn = FreeCAD.Placement(FreeCAD.Vector(5, -7, 11), FreeCAD.Rotation(FreeCAD.Vector(1, 1, 0), 35))
        (got,) = verification.placed(ops, verification.machine_tips(ops, placed_json), turn)
        self.assertEqual(len(got["moves"]), len(moves))
        for m, g in zip(moves, got["moves"]):
            tip, axis = _core.forward_kinematics(placed_json, m[1:4], m[4:6], None, 0.0)
            want = turn.multVec(FreeCAD.Vector(*tip))
            self.assertEqual(g[0], m[0])
            self.assertLess((FreeCAD.Vector(*g[1:4]) - want).Length, 1e-9, (m, g, want))
        last = turn.Rotation.multVec(FreeCAD.Vector(*axis))
        self.assertLess((FreeCAD.Vector(*got["axis"]) - last).Length, 1e-8)
        self.assertGreater(abs(got["axis"][2] - 1.0), 0.1)  # a tilted axis: the rotaries count


class RereadRoundsTest(unittest.TestCase):
    """The gate posts and verifies again after leaving operations out: the programs whose text is
    unchanged are not re-read by rs274 again, a changed one is, and the reads come back in the
    programs' order."""

    def _program(self, folder, name, depth):
        path = os.path.join(folder, name)
        with open(path, "w") as f:
            f.write("(operation: Pocket {0})\nG21 G90\nT1 M6\nG0 X0 Y0 Z10\nG1 Z{1} F100\nG1 X{2} F300\n"
                    "G0 Z10\nM2\n".format(name, -depth, 10 + depth))
        return path

    def test_an_unchanged_program_is_not_read_again(self):
        import tempfile
        from unittest import mock
        from aeronc.pipeline import verification
        folder = tempfile.mkdtemp(prefix="aeronc_reread_test_")
        paths = [self._program(folder, "p{}.ngc".format(k), k + 1) for k in range(3)]
        tools = {1: 10.0}
        calls = []
        real = verification.reread

        def counted(path, t):
            calls.append(os.path.basename(path))
            return real(path, t)

        cache = {}
        with mock.patch.object(verification, "reread", counted):
            first = verification._reread_all(paths, tools, cache)
            self.assertEqual(sorted(calls), ["p0.ngc", "p1.ngc", "p2.ngc"])
            for path, (_, read) in zip(paths, first):
                self.assertEqual(read, real(path, tools))
            del calls[:]
            again = verification._reread_all(paths, tools, cache)
            self.assertEqual(calls, [])
            self.assertEqual([r for _, r in again], [r for _, r in first])
            self._program(folder, "p1.ngc", 5)  # the gate left something out of this one
            changed = verification._reread_all(paths, tools, cache)
            self.assertEqual(calls, ["p1.ngc"])
        self.assertEqual(changed[1][1][0]["label"], "Pocket p1.ngc")
        self.assertEqual(changed[1][1][0]["moves"][-2][3], -5.0)  # the new depth, read
        self.assertEqual(changed[0][1], first[0][1])

    def test_rs274_keeps_its_tool_table_out_of_the_users_home(self):
        # rs274 writes its tool table to $HOME/.tool.mmap: two under one HOME (two programs read
        # at once, two jobs) read each other's tools. Each re-read has a HOME of its own.
        import tempfile
        from unittest import mock
        from aeronc.pipeline import verification
        home = tempfile.mkdtemp(prefix="aeronc_reread_home_")
        path = self._program(home, "p.ngc", 2)
        with mock.patch.dict(os.environ, {"HOME": home}):
            read = verification.reread(path, {1: 10.0})
        self.assertEqual(read[0]["tool"], 1)
        self.assertFalse(os.path.exists(os.path.join(home, ".tool.mmap")))
