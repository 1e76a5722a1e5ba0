"""MachiningFeatures: the root of a part's machining-domain tree in the document.

Holds the recognition settings, the core's JSON result (in a string property, so the tree's
data survives save/reopen without re-running recognition), the tool plan of Select tools, and
one SetupDirection child per setup, each holding its DomainElement subtree. The tree is made,
remade and removed by aeronc.makers.
"""
import json
import math

import FreeCAD

from aeronc.pipeline import recognition
from aeronc.objects.base import BaseProxy, declare_property, proxy_type

TYPE = "AeroNC::MachiningFeatures"
COUNTS = [("SetupCount", "setups"), ("ElementCount", "elements"),
          ("ClosedPocketCount", "closed_pocket"), ("OpenPocketCount", "open_pocket"),
          ("OpeningCount", "opening"), ("HoleCount", "hole"),
          ("FaceCount", "faces"), ("UnclaimedFaceCount", "unclaimed")]


class MachiningFeatures(BaseProxy):
    Type = TYPE

    def __init__(self, obj):
        super().__init__(obj)
        self.declare(obj)

    def declare(self, obj):
        g = "Recognition"
        declare_property(obj, "App::PropertyLinkGlobal", "Source", g, "The part whose features were recognised")
        declare_property(obj, "App::PropertyVectorList", "Directions", g,
                         "Requested setup directions; empty: found automatically")
        declare_property(obj, "App::PropertyLength", "Allowance", g,
                         "Blank = part bounding box grown by this, unless Blank is set")
        declare_property(obj, "App::PropertyFloatList", "Blank", g,
                         "Blank box xmin, ymin, zmin, xmax, ymax, zmax; empty: bounding box + allowance")
        declare_property(obj, "App::PropertyLength", "LinearTolerance", g, "Heights equal, points coincide",
                         recognition.DEFAULT_LINEAR_TOLERANCE)
        declare_property(obj, "App::PropertyAngle", "AngularTolerance", g, "Normal parallel / perpendicular to an axis",
                         math.degrees(recognition.DEFAULT_ANGULAR_TOLERANCE))
        declare_property(obj, "App::PropertyLength", "ChordTolerance", g, "Sagitta when curves become polylines",
                         recognition.DEFAULT_CHORD_TOLERANCE)
        g = "Result"
        declare_property(obj, "App::PropertyString", "Result", g, "Recognition result (JSON)", hidden=True)
        for prop, _ in COUNTS:
            declare_property(obj, "App::PropertyInteger", prop, g, "", read_only=True)
        declare_property(obj, "App::PropertyStringList", "Warnings", g, "Warnings of the recognition", read_only=True)
        declare_property(obj, "App::PropertyBool", "Outdated", g,
                         "The source part changed since recognition: recognise again", read_only=True)
        g = "Tools"  # filled by Select tools (aeronc.pipeline.tool_planning)
        declare_property(obj, "App::PropertyString", "Material", g, "Workpiece material of the tool plan",
                         read_only=True)
        declare_property(obj, "App::PropertyString", "Machine", g, "Machine of the tool plan (spindle limit)",
                         read_only=True)
        declare_property(obj, "App::PropertyInteger", "ToolChangesBefore", g, "Roughing tool changes before merging",
                         read_only=True)
        declare_property(obj, "App::PropertyInteger", "ToolChangesAfter", g, "Roughing tool changes after merging",
                         read_only=True)
        declare_property(obj, "App::PropertyFloat", "RoughingMinutesBefore", g,
                         "Estimated roughing time before merging", read_only=True)
        declare_property(obj, "App::PropertyFloat", "RoughingMinutesAfter", g,
                         "Estimated roughing time after merging", read_only=True)
        declare_property(obj, "App::PropertyString", "ToolPlan", g, "Tool plan (JSON); empty: no plan yet",
                         read_only=True, hidden=True)

    def execute(self, obj):
        # Recognition itself runs from the makers (it adds and removes objects, which a
        # recompute must not do). Recompute keeps the counts in step with Result and flags a
        # source that no longer matches the face numbers the tree refers to.
        result = result_of(obj)
        counts = recognition.summary(result)
        for prop, key in COUNTS:
            if getattr(obj, prop) != counts[key]:
                setattr(obj, prop, counts[key])
        src = obj.Source
        outdated = bool(src is not None and hasattr(src, "Shape") and result
                        and len(src.Shape.Faces) != result.get("faceCount"))
        if outdated != obj.Outdated:
            obj.Outdated = outdated
            if outdated:
                FreeCAD.Console.PrintWarning(
                    "AeroNC: {} changed since its features were recognised; recognise again\n"
                    .format(src.Label))


def result_of(obj):
    """The stored recognition result of a MachiningFeatures object as a dict ({} if none)."""
    return json.loads(obj.Result) if obj.Result else {}


def settings_of(obj):
    """Keyword arguments of the makers (and of recognise) that reproduce obj's recognition."""
    return dict(directions=[tuple(v) for v in obj.Directions],
                allowance=obj.Allowance.Value,
                blank=tuple(obj.Blank) if len(obj.Blank) == 6 else None,
                linear_tolerance=obj.LinearTolerance.Value,
                angular_tolerance=math.radians(obj.AngularTolerance.Value),
                chord_tolerance=obj.ChordTolerance.Value)


def is_machining_features(obj):
    return proxy_type(obj) == TYPE
