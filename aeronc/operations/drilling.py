"""Drilling: the unit's holes as drill cycles, G81 (plain), G82 (dwell) or G83 (peck), with the
parameters FreeCAD's Drilling writes (X Y Z R Q P), so posts read them alike. The retract
plane R is the safe height."""
from aeronc.operations.base import AXIAL, CLEARANCE, DWELL, PECK, SAFE, MachiningOperation


class Drilling(MachiningOperation):
    Type = "AeroNC::Drilling"
    PARAMETERS = [PECK, DWELL, AXIAL, SAFE, CLEARANCE]
    ICON = "Drilling"
