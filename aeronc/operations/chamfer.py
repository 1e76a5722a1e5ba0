"""Chamfer: one pass of a chamfer mill along an edge, its cone on the chamfer (a countersink, or a
chamfer along a pocket's outline).

The chain gives the drive loop (the chamfer's lower line: the edge of the hole under a
countersink, or the pocket's outline with its open edges), the tip's height (the unit's bottom)
and how far from the loop the mill's axis runs (edgeOffset: the tip's radius and its clearance
off the wall, toolselect/EdgeTools.h). The pass is the profile generator's, for a cutter whose
radius is that offset: its path is the axis's path.
"""
from aeronc.operations.base import CLEARANCE, SAFE, unit_of
from aeronc.operations.profile import Profile

_SAME = 1e-6


class Chamfer(Profile):
    Type = "AeroNC::Chamfer"
    PARAMETERS = [SAFE, CLEARANCE]  # the depth and offset follow the mill and the chamfer
    GEOMETRY_KEYS = ("top", "bottom", "lead", "leadRadius")
    ICON = "Profile"

    def toolpath_input(self, obj):
        from aeronc.operations.base import cutter_of
        unit = unit_of(obj)
        data = super().toolpath_input(obj)
        planned = unit.get("cutter") or {}
        have = cutter_of(obj.ToolController)
        # The offset and depth were worked out for the chain's mill: another mill would cut another chamfer.
        if have and (have.get("type") != "chamfer" or
                     any(abs(float(have.get(k, 0.0)) - float(planned.get(k, 0.0))) > _SAME
                         for k in ("diameter", "tipDiameter", "includedAngle"))):
            raise ValueError("{}: the tool controller's bit is not the chamfer mill {} the pass was planned for".format(
                obj.Label, unit.get("tool", "")))
        data["operation"] = "profile"  # the generator's profile, for the axis's path
        data["cutter"] = {"diameter": 2 * float(unit["edgeOffset"]), "cornerRadius": 0.0}
        data["stepDown"] = max(float(unit["top"]) - float(unit["bottom"]), 0.01)  # one level, at the tip's height
        data["stepOver"] = 2 * float(unit["edgeOffset"])
        data["radialAllowance"] = data["axialAllowance"] = 0.0
        return data
