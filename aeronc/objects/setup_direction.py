"""SetupDirection: one clamping of the part and its tool-axis direction (a node of the
machining-domain tree between the MachiningFeatures root and the domain elements)."""
from aeronc.objects.base import BaseProxy, declare_property

TYPE = "AeroNC::SetupDirection"


class SetupDirection(BaseProxy):
    Type = TYPE

    def __init__(self, obj):
        super().__init__(obj)
        self.declare(obj)

    def declare(self, obj):
        g = "Setup"
        declare_property(obj, "App::PropertyInteger", "SetupId", g,
                         "Index of the setup in the recognition result", read_only=True)
        declare_property(obj, "App::PropertyVector", "Direction", g,
                         "Tool axis, pointing from the part towards the spindle", read_only=True)
        declare_property(obj, "App::PropertyString", "SetupName", g, "+Z, -Z or the direction vector", read_only=True)
        declare_property(obj, "App::PropertyInteger", "ElementCount", g,
                         "Domain elements of this setup, at all depths of the tree", read_only=True)

    def execute(self, obj):
        pass
