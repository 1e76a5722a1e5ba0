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


class MovesTest(unittest.TestCase):
    def test_moves_as_path_commands(self):
        mv = [[0, 1, 2, 30], [2, 1, 2, 5], [1, 4, 2, 5], [0, 4, 2, 30],
              [3, 7, 8, -10, 3, 0, 0], [3, 9, 8, -10, 3, 2.5, 0], [3, 11, 8, -10, 3, 0, 0.5], [0, 11, 8, 30]]
        cmds = moves.commands_of(mv, 20.0, 5.0, "Op")
        self.assertEqual([c[0] for c in cmds], ["(Op)", "G0", "G1", "G1", "G0", "G99", "G81", "G83", "G82", "G80", "G0"])
        self.assertEqual(cmds[2][1], {"X": 1, "Y": 2, "Z": 5, "F": 5.0})      # a plunge at the vertical feed
        self.assertEqual(cmds[3][1], {"X": 4, "Y": 2, "Z": 5, "F": 20.0})     # a feed at the horizontal one
        self.assertEqual(cmds[6][1], {"X": 7, "Y": 8, "Z": -10, "R": 3, "F": 5.0})
        self.assertEqual(cmds[7][1]["Q"], 2.5)
        self.assertEqual(cmds[8][1]["P"], 0.5)
        with self.assertRaises(ValueError):
            moves.commands_of([[7, 0, 0, 0]], 1, 1)

    def test_time_estimate_by_hand(self):
        # 3 mm plunge at 1 mm/s, 4 mm feed at 2 mm/s, a 10 mm drill cycle at 1 mm/s in, rapids off.
        mv = [[0, 0, 0, 3], [2, 0, 0, 0], [1, 4, 0, 0], [3, 4, 0, -8, 2, 0, 0]]
        self.assertAlmostEqual(moves.estimate_seconds(mv, 2.0, 1.0), 3 + 2 + 10)
        # With rapids of 10 mm/s: back up 10 mm from the bottom, and the first 3 mm are not a move.
        self.assertAlmostEqual(moves.estimate_seconds(mv, 2.0, 1.0, 10.0, 10.0), 3 + 2 + 10 + 1)
        self.assertEqual(moves.clock_text(3725.4), "01:02:05")


if __name__ == "__main__":
    unittest.main()
