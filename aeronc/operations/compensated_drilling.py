"""CompensatedDrilling: a Path operation in the Job that drills the holes of a part at their
compensated positions, each along its surface normal (AeroNC's U V W tool axis, posted by the
5-axis posts).

The nominal holes (entry point, normal, diameter, depth in the part frame) are stored on the
operation when it is made; the part itself is never changed. On every recompute the
operation compensates them from its measured-hole set (by the set's method) and rewrites its
Path, so importing new measurements updates it. Datum holes of its photo-hole set are always
left out: they are drilled in advance. Without measurements it drills the nominal positions
and says so; when the compensation fails it writes no Path at all and says why.

`Flags` lists what to look at before drilling, each with its reason (docs/compensation.md):
the datum readings left out or put back, the holes whose correction departs from their
neighbours', the holes whose correction is longer than the tolerance. `Flagged` indexes the
drilled holes among them.
"""
import json

import FreeCAD

from aeronc import pathcompat
from aeronc.drilling import compensation
from aeronc.objects import photo_hole_set
from aeronc.objects.base import BaseProxy, add_property, declare_property, proxy_type

TYPE = "AeroNC::CompensatedDrilling"
NOT_MEASURED = "nominal positions: no measurements imported, not compensated"


class CompensatedDrilling(BaseProxy):
    Type = TYPE

    def __init__(self, obj):
        super().__init__(obj)
        g = "Path"
        add_property(obj, "App::PropertyBool", "Active", g, "Make False to keep this operation out of the program",
                     True)
        add_property(obj, "App::PropertyLink", "ToolController", g, "The drill's tool controller")
        add_property(obj, "App::PropertyEnumeration", "CoolantMode", g, "Coolant", ["None", "Flood", "Mist"])
        obj.CoolantMode = "Flood"
        g = "Holes"
        add_property(obj, "App::PropertyLinkGlobal", "Source", g, "The part whose holes are drilled")
        add_property(obj, "App::PropertyLinkGlobal", "PhotoHoleSet", g, "Datum holes (left out of the drilling)")
        add_property(obj, "App::PropertyLinkGlobal", "MeasuredHoleSet", g, "Measurements the holes are compensated by")
        add_property(obj, "App::PropertyStringList", "HoleIds", g, "Id of each hole to drill", read_only=True)
        add_property(obj, "App::PropertyStringList", "HoleFaces", g, "Faces of each hole on the part", read_only=True)
        add_property(obj, "App::PropertyVectorList", "NominalPositions", g, "Nominal entry points (part frame)",
                     read_only=True)
        add_property(obj, "App::PropertyVectorList", "NominalNormals", g, "Nominal surface normals (part frame)",
                     read_only=True)
        add_property(obj, "App::PropertyFloatList", "Diameters", g, "Hole diameters, mm", read_only=True)
        add_property(obj, "App::PropertyFloatList", "Depths", g, "Hole depths along the normal, mm", read_only=True)
        g = "Drilling"
        add_property(obj, "App::PropertyDistance", "SafeHeight", g, "Z of the moves between holes (workpiece frame)",
                     100.0)
        add_property(obj, "App::PropertyLength", "Clearance", g, "R level above the surface along the normal", 3.0)
        add_property(obj, "App::PropertyLength", "ExtraDepth", g, "Drilled beyond the hole's depth (through holes)",
                     1.0)
        add_property(obj, "App::PropertyLength", "PeckDepth", g, "0: one feed (G81); else peck drilling (G83)", 0.0)
        g = "Compensation"
        add_property(obj, "App::PropertyString", "Status", g, "What was drilled and why", read_only=True)
        add_property(obj, "App::PropertyString", "MethodUsed", g, "Compensation method of the drilled positions",
                     read_only=True)
        add_property(obj, "App::PropertyVectorList", "Corrections", g, "Correction dP of each hole (part frame)",
                     read_only=True)
        add_property(obj, "App::PropertyVectorList", "CompensatedPositions", g, "Drilled entry points (part frame)",
                     read_only=True)
        add_property(obj, "App::PropertyIntegerList", "Flagged", g,
                     "Holes (index) flagged: correction against the neighbours' or beyond the tolerance",
                     read_only=True)
        add_property(obj, "App::PropertyString", "Report", g, "The last compensation (JSON)", hidden=True)
        self.declare(obj)

    def declare(self, obj):
        declare_property(obj, "App::PropertyStringList", "Flags", "Compensation",
                         "What to look at before drilling, and why", read_only=True)

    def execute(self, obj):
        try:
            holes, result, status = _compensated(obj)
        except Exception as e:  # the compensation refused: drill nothing rather than the wrong places
            obj.Status = "not compensated: {}".format(e)
            obj.MethodUsed = ""
            obj.Corrections, obj.CompensatedPositions, obj.Flagged, obj.Flags = [], [], [], []
            obj.Report = ""
            obj.Path = pathcompat.path_from_commands()
            FreeCAD.Console.PrintError("AeroNC: {}: {}\n".format(obj.Label, obj.Status))
            return
        obj.Status = status
        obj.MethodUsed = result["method"] if result else "none"
        obj.Corrections = [FreeCAD.Vector(*h["correction"]) for h in result["holes"]] if result else []
        obj.CompensatedPositions = [FreeCAD.Vector(*h["compensated"]) for h in holes]
        obj.Flagged = [i for i, h in enumerate(holes) if h.get("exceeds_tolerance") or h.get("against_neighbours")]
        flags = flag_lines(result) if result else []
        if list(obj.Flags) != flags:
            obj.Flags = flags
        obj.Report = json.dumps(result, separators=(",", ":")) if result else ""
        obj.Path = pathcompat.path_from_commands(drilling_commands(obj, holes))


def nominal_holes(obj):
    """The holes to drill: [{id, faces, position, normal, diameter, depth}] (part frame), datum
    holes of the photo-hole set left out."""
    datum = photo_hole_set.datum_faces(obj.PhotoHoleSet) if obj.PhotoHoleSet is not None else set()
    out = []
    for i, hid in enumerate(obj.HoleIds):
        faces = obj.HoleFaces[i].split()
        if datum & set(faces):
            continue
        p, n = obj.NominalPositions[i], obj.NominalNormals[i]
        out.append({"id": hid, "faces": faces, "position": (p.x, p.y, p.z), "normal": (n.x, n.y, n.z),
                    "diameter": obj.Diameters[i], "depth": obj.Depths[i]})
    return out


def _compensated(obj):
    """(holes with compensated position and normal, core result or None, status)."""
    holes = nominal_holes(obj)
    ms = obj.MeasuredHoleSet
    if ms is None or len(ms.HoleIds) == 0:
        for h in holes:
            h["compensated"], h["drill_normal"] = h["position"], h["normal"]
        return holes, None, NOT_MEASURED
    result = compensation.compensate(ms, [{"id": h["id"], "position": h["position"], "normal": h["normal"]}
                                          for h in holes])
    for h, c in zip(holes, result["holes"]):
        h["compensated"], h["drill_normal"] = tuple(c["compensated"]), tuple(c["normal"])
        h["correction"], h["exceeds_tolerance"], h["note"] = c["correction"], c["exceeds_tolerance"], c["note"]
        h["against_neighbours"] = c["against_neighbours"]
    return holes, result, status_of(result, len(holes), ms)


def status_of(result, count, ms):
    """What was drilled and what to look at, in a line."""
    left_out = [d["id"] for d in result["datums"] if not d["used"]]
    against = sum(1 for h in result["holes"] if h["against_neighbours"])
    beyond = sum(1 for h in result["holes"] if h["exceeds_tolerance"])
    return ("{} holes compensated by {} from {}; datum holes left out: {}; {} holes flagged: {} against their "
            "neighbours' corrections (beyond {:g} mm), {} beyond the {:g} mm tolerance").format(
        count, result["method"], ms.Label, ", ".join(left_out) or "none", result["flagged_holes"], against,
        ms.NeighbourTolerance.Value, beyond, ms.Tolerance.Value)


def flag_lines(result):
    """"<id>: <reason>" per flag of a compensation result, datum holes first."""
    return ["{}: {}".format(f["id"], f["reason"]) for f in result["flags"]]


def drilling_commands(obj, holes):
    """Each hole drilled along its normal: rapid at the safe height above it, down its normal to
    the R level, G81 (G83 with a peck depth) to the depth plus the extra, back up (G98)."""
    from aeronc.post.orientation import oriented_command
    part = obj.Source
    pl = part.Placement if part is not None else FreeCAD.Placement()
    cmds = [pathcompat.command("G98")]
    for h in holes:
        entry = pl.multVec(FreeCAD.Vector(*h["compensated"]))
        n = pl.Rotation.multVec(FreeCAD.Vector(*h["drill_normal"]))
        n.normalize()
        reach = h["depth"] + obj.ExtraDepth.Value
        bottom = entry - n * reach
        lift = max(obj.SafeHeight.Value - entry.z, obj.Clearance.Value)
        above = entry + n * (lift / n.z if n.z > 0.2 else lift)
        cmds.append(pathcompat.command("(hole {})".format(h["id"])))
        cmds.append(oriented_command("G0", {"X": above.x, "Y": above.y, "Z": above.z}, n))
        # R - Z is the distance from the bottom to the R level along the axis (docs/post.md).
        p = {"X": bottom.x, "Y": bottom.y, "Z": bottom.z, "R": bottom.z + reach + obj.Clearance.Value,
             "F": _feed(obj)}
        if obj.PeckDepth.Value > 0:
            p["Q"] = obj.PeckDepth.Value
        cmds.append(oriented_command("G83" if "Q" in p else "G81", p, n))
    cmds.append(pathcompat.command("G80"))
    return cmds


def _feed(obj):
    tc = obj.ToolController
    return float(tc.VertFeed.Value) if tc is not None and tc.VertFeed.Value > 0 else 5.0  # mm/s


def is_compensated_drilling(obj):
    return proxy_type(obj) == TYPE


def operations_of(photo_set):
    return [o for o in photo_set.Document.Objects if is_compensated_drilling(o) and o.PhotoHoleSet is photo_set]
