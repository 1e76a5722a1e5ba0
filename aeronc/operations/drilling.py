"""Drilling: the unit's holes as drill cycles, G81 (plain), G82 (dwell) or G83 (peck), with the
parameters FreeCAD's Drilling writes (X Y Z R Q P), so posts read them alike. Each cycle
starts and ends at its R plane, the hole's top plus the clearance; the moves between holes run
at the safe height."""
from aeronc.operations.base import CLEARANCE, DWELL, PECK, SAFE, MachiningOperation


class Drilling(MachiningOperation):
    Type = "AeroNC::Drilling"
    PARAMETERS = [PECK, DWELL, SAFE, CLEARANCE]
    GEOMETRY_KEYS = ("holes", "retractHeight", "pointAngle", "breakThrough")
    ICON = "Drilling"
