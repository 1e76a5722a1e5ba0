"""What the chain's operations hand the toolpath generator, on units whose answer is known by
hand: the profile's walls (closed, open to the blank in places, islands) and sides, the keys of
each operation type, the heights; and the moves written as Path commands."""
import unittest

from aeronc.operations import moves
from aeronc.operations.profile import signed_area, wall_runs

SQUARE = [[0, 0], [10, 0], [10, 10], [0, 10]]  # counter-clockwise


class WallRunsTest(unittest.TestCase):
    def test_closed_contour_is_one_closed_wall(self):
        self.assertEqual(wall_runs(SQUARE, []), [(SQUARE, True)])
        self.assertGreater(signed_area(SQUARE), 0)
        self.assertLess(signed_area(SQUARE[::-1]), 0)

    def test_one_open_side_leaves_one_open_wall_round_the_other_three(self):
        runs = wall_runs(SQUARE, [[[0, 0], [10, 0]]])
        self.assertEqual(runs, [([[10, 0], [10, 10], [0, 10], [0, 0]], False)])

    def test_an_open_edge_longer_than_the_side_and_two_open_sides(self):
        # The open edge may run past the contour's corners (the blank's edge); opposite sides open.
        runs = wall_runs(SQUARE, [[[-5, 0], [15, 0]], [[0, 10], [10, 10]]])
        self.assertEqual(runs, [([[10, 0], [10, 10]], False), ([[0, 10], [0, 0]], False)])

    def test_all_open_is_no_wall(self):
        edges = [[SQUARE[i], SQUARE[(i + 1) % 4]] for i in range(4)]
        self.assertEqual(wall_runs(SQUARE, edges), [])


class PathProgramTest(unittest.TestCase):
    """The core's G-code of a unit as a FreeCAD Path reads it, and the cycle time."""

    DRILL = {"operation": "drill", "cutter": {"diameter": 5.0}, "clearance": 3.0, "peck": 0.0,
             "holes": [{"u": 7, "v": 8, "diameter": 5, "top": 0, "bottom": -10, "through": False}]}

    def test_drill_cycles_as_path_commands(self):
        import json
        from aeronc import _core
        from aeronc import pathcompat
        units = [json.dumps(self.DRILL), json.dumps(dict(self.DRILL, peck=2.5)),
                 json.dumps(dict(self.DRILL, dwell=0.5))]
        program = _core.toolpath_program(units, "Op (1)", 20.0, 5.0)
        path = pathcompat.path_from_gcode(program["gcode"])
        names = [c.Name for c in path.Commands]
        self.assertEqual(names[0], "(Op [1])")
        self.assertEqual([n for n in names if n.startswith("G8")], ["G81", "G80", "G83", "G80", "G82", "G80"])
        g81 = [c for c in path.Commands if c.Name == "G81"][0].Parameters
        self.assertEqual(g81, {"X": 7.0, "Y": 8.0, "Z": -10.0, "R": 3.0, "F": 5.0})
        self.assertEqual([c for c in path.Commands if c.Name == "G83"][0].Parameters["Q"], 2.5)
        self.assertEqual([c for c in path.Commands if c.Name == "G82"][0].Parameters["P"], 0.5)
        # Three 13 mm cycles at 5 mm/s in, rapids taking no time.
        self.assertAlmostEqual(program["seconds"], 3 * 13 / 5.0)
        self.assertEqual(program["moves"], len([n for n in names if n in ("G0", "G1", "G81", "G82", "G83")]))

    def test_pocket_feeds_and_time(self):
        import json
        from aeronc import _core
        from aeronc import pathcompat
        unit = {"operation": "pocket", "cutter": {"diameter": 6.0}, "top": 0.0, "bottom": -2.0, "stepDown": 2.0,
                "contour": [[0, 0], [30, 0], [30, 20], [0, 20]], "islands": []}
        program = _core.toolpath_program([json.dumps(unit)], "P", 20.0, 5.0, 100.0, 50.0)
        path = pathcompat.path_from_gcode(program["gcode"])
        # Words are modal: a feed is written where it changes, the first G1 has one.
        g1 = [c for c in path.Commands if c.Name == "G1"]
        self.assertIn("F", g1[0].Parameters)
        feeds = {c.Parameters["F"] for c in g1 if "F" in c.Parameters}
        self.assertIn(20.0, feeds)  # the helical entry and the rings at the horizontal feed
        self.assertLessEqual(feeds, {20.0, 5.0})
        self.assertTrue(all("F" not in c.Parameters for c in path.Commands if c.Name == "G0"))
        # At least the cut length at the horizontal feed, at most all of it at the vertical one.
        self.assertGreater(program["seconds"], program["cutLength"] / 20.0)
        self.assertLess(program["seconds"], program["cutLength"] / 5.0 + program["rapidLength"] / 50.0)
        self.assertEqual(path.Commands[-1].Name, "G0")

    def test_clock_text(self):
        self.assertEqual(moves.clock_text(3725.4), "01:02:05")


if __name__ == "__main__":
    unittest.main()
