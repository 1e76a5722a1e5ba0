"""Profile: passes along a unit's drive loop (a closed contour, or the open edges of an open
pocket between their start and end limits), level by level, leaving the allowances; it
finishes walls and outer contours."""
from aeronc.operations.base import AXIAL, CLEARANCE, RADIAL, SAFE, STEP_DOWN, STEP_OVER, MachiningOperation


class Profile(MachiningOperation):
    Type = "AeroNC::Profile"
    PARAMETERS = [STEP_DOWN, STEP_OVER, RADIAL, AXIAL, SAFE, CLEARANCE]
    GEOMETRY_KEYS = ("top", "bottom", "contour", "closed", "side", "lead", "leadRadius", "startLimit",
                     "endLimit")
    ICON = "Profile"
