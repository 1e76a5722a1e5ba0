"""GeneralisedPocket: pocket clearing of a unit's contour loop around its island loops, level by
level from the top to the bottom, leaving the radial and axial allowances; the same operation
clears the rest material of corners that a larger tool could not reach (the unit's contour is
then the corner region)."""
from aeronc.operations.base import AXIAL, CLEARANCE, RADIAL, RAMP, SAFE, STEP_DOWN, STEP_OVER, MachiningOperation


class GeneralisedPocket(MachiningOperation):
    Type = "AeroNC::GeneralisedPocket"
    PARAMETERS = [STEP_DOWN, STEP_OVER, RADIAL, AXIAL, SAFE, CLEARANCE, RAMP]
    GEOMETRY_KEYS = ("top", "bottom", "contour", "islands", "islandTops", "faceIslandTops", "openEdges",
                     "floorFilletRadius", "finishingPass",
                     "finishingAllowance", "previousCutter", "previousAllowance")
    ICON = "GeneralisedPocket"
