"""HelicalInterpolation: a hole that no drill of the knowledge base fits, milled with an end
mill down a helix round the hole's axis, then a full circle at the bottom, leaving the radial
allowance on the wall."""
from aeronc.operations.base import AXIAL, CLEARANCE, RADIAL, RAMP, SAFE, STEP_DOWN, STEP_OVER, MachiningOperation


class HelicalInterpolation(MachiningOperation):
    Type = "AeroNC::HelicalInterpolation"
    PARAMETERS = [STEP_DOWN, STEP_OVER, RADIAL, AXIAL, SAFE, CLEARANCE, RAMP]
    GEOMETRY_KEYS = ("holes", "finishingAllowance", "breakThrough")
    ICON = "HelicalInterpolation"
