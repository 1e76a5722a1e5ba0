"""The impeller's setup frame: whatever frame the part was drawn in, the Job has the impeller's
axis along Z through its origin and the part's lowest point on z = 0; moves keep their place on
the part and turn their tool axes with it."""
import math
import unittest

import FreeCAD
import Part

from aeronc.impeller import setup_frame


def part_along_y():
    """A disc of radius 30, 10 thick, on the axis +Y through (5, -39, 7): a stand-in for an
    impeller exported with its axis along Y; a post on it marks the tips' side."""
    disc = Part.makeCylinder(30, 10, FreeCAD.Vector(5, -39, 7), FreeCAD.Vector(0, 1, 0))
    post = Part.makeCylinder(4, 20, FreeCAD.Vector(5, -29, 7), FreeCAD.Vector(0, 1, 0))
    return disc.fuse(post)


class SetupFrameTest(unittest.TestCase):
    def test_axis_along_y_goes_to_z_with_the_back_on_the_table(self):
        shape = part_along_y()
        p = setup_frame.placement({"point": [5, -20, 7], "direction": [0, 1, 0]}, shape)
        placed = setup_frame.shape_in(p, shape)
        box = placed.BoundBox
        self.assertAlmostEqual(box.ZMin, 0.0, places=6)
        self.assertAlmostEqual(box.ZMax, 30.0, places=6)  # 10 of disc, 20 of post
        for v in (box.XMin, box.YMin):
            self.assertAlmostEqual(v, -30.0, places=6)  # the axis through the origin
        d = p.Rotation.multVec(FreeCAD.Vector(0, 1, 0))
        self.assertAlmostEqual(d.z, 1.0, places=12)
        # The post's tip, (5, -9, 7) in the part, is on the axis 30 above the table.
        tip = p.multVec(FreeCAD.Vector(5, -9, 7))
        self.assertAlmostEqual(tip.distanceToPoint(FreeCAD.Vector(0, 0, 30)), 0.0, places=9)

    def test_moves_keep_their_place_on_the_part(self):
        shape = part_along_y()
        p = setup_frame.placement({"point": [5, -39, 7], "direction": [0, 1, 0]}, shape)
        # A move on the disc's rim, the tool tilted 30 degrees off the axis towards +X.
        s, c = math.sin(math.radians(30)), math.cos(math.radians(30))
        (x, y, z, i, j, k, rapid), = setup_frame.moves_in(p, [[35, -34, 7, s, c, 0, 0]])
        self.assertAlmostEqual(math.hypot(x, y), 30.0, places=9)  # still on the rim
        self.assertAlmostEqual(z, 5.0, places=9)  # half the disc's thickness up
        self.assertAlmostEqual(k, c, places=12)  # 30 degrees off Z now
        self.assertAlmostEqual(i * i + j * j + k * k, 1.0, places=12)
        self.assertEqual(rapid, 0)

    def test_part_on_its_setup_already_is_left_alone(self):
        shape = Part.makeCylinder(30, 10)
        p = setup_frame.placement({"point": [0, 0, 4], "direction": [0, 0, 1]}, shape)
        self.assertTrue(setup_frame.is_identity(p))
        moves = [[1, 2, 3, 0, 0, 1, 1]]
        self.assertIs(setup_frame.moves_in(p, moves), moves)

    def test_axis_against_z_is_turned_over(self):
        shape = Part.makeCylinder(30, 10, FreeCAD.Vector(0, 0, 0), FreeCAD.Vector(0, 0, -1))
        p = setup_frame.placement({"point": [0, 0, 0], "direction": [0, 0, -1]}, shape)
        placed = setup_frame.shape_in(p, shape)
        self.assertAlmostEqual(placed.BoundBox.ZMin, 0.0, places=6)
        self.assertAlmostEqual(placed.BoundBox.ZMax, 10.0, places=6)
        self.assertAlmostEqual(p.Rotation.multVec(FreeCAD.Vector(0, 0, -1)).z, 1.0, places=12)


if __name__ == "__main__":
    unittest.main()
