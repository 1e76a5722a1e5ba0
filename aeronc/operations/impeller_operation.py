"""ImpellerOperation: one step of an impeller's process route as a Path operation.

Its Path is the core's 5-axis toolpath: G0/G1 to the tool tip (X Y Z) with the tool axis on
every move as U V W (aeronc/post/orientation.py), which Path.Command keeps and the document
saves; AeroNC's posts read the axis from there. FreeCAD's 3-D view draws X Y Z only: the
tip's path, not the axis. Every step has its toolpath; the lathe's turning and what a step cuts
from the back face in a second setup (Operation "<step>_back") are switched off and kept out of
the 5-axis program, with the reason in Note. The Path is made by aeronc.impeller.programming, never by recompute: the toolpaths come
from the whole route at once and take seconds to minutes.
"""
from aeronc.objects.base import BaseProxy, declare_property, proxy_type
from aeronc.operations.base import declare_path_properties

TYPE = "AeroNC::ImpellerOperation"


class ImpellerOperation(BaseProxy):
    Type = TYPE
    ICON = "MachiningOperation"

    def __init__(self, obj):
        super().__init__(obj)
        self.declare(obj)

    def declare(self, obj):
        declare_path_properties(obj)
        g = "Route step"
        declare_property(obj, "App::PropertyInteger", "Position", g, "Position in the process route", read_only=True)
        declare_property(obj, "App::PropertyString", "Operation", g, "Operation of the route step", read_only=True)
        declare_property(obj, "App::PropertyString", "Strategy", g, "Strategy of the route step", read_only=True)
        declare_property(obj, "App::PropertyString", "Tool", g, "Tool of the step in the knowledge base",
                         read_only=True)
        declare_property(obj, "App::PropertyLength", "StepAllowance", g, "Stock the step leaves", read_only=True)
        declare_property(obj, "App::PropertyIntegerList", "FaceNumbers", g, "FaceN of the part the step machines",
                         read_only=True)
        declare_property(obj, "App::PropertyString", "Note", g, "Why the step is not posted or has no toolpath",
                         read_only=True)
        g = "Result"
        declare_property(obj, "App::PropertyInteger", "MoveCount", g, "Moves of the toolpath", read_only=True)
        declare_property(obj, "App::PropertyLength", "CutLength", g, "Length of the feed moves (tool tip)",
                         read_only=True)

    def execute(self, obj):
        pass  # the Path is set by aeronc.impeller.programming; recompute keeps it


def is_impeller_operation(obj):
    return proxy_type(obj) == TYPE
