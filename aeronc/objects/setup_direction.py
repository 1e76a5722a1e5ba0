"""SetupDirection: one clamping of the part and its tool-axis direction (a node of the
machining-domain tree between the MachiningFeatures root and the domain elements)."""
import FreeCAD

from aeronc.objects.base import BaseProxy, add_property

TYPE = "AeroNC::SetupDirection"


class SetupDirection(BaseProxy):
    Type = TYPE

    def __init__(self, obj):
        super().__init__(obj)
        add_property(obj, "App::PropertyInteger", "SetupId", "Setup",
                     "Index of the setup in the recognition result", read_only=True)
        add_property(obj, "App::PropertyVector", "Direction", "Setup",
                     "Tool axis, pointing from the part towards the spindle", read_only=True)
        add_property(obj, "App::PropertyString", "SetupName", "Setup",
                     "+Z, -Z or the direction vector", read_only=True)
        add_property(obj, "App::PropertyInteger", "ElementCount", "Setup",
                     "Domain elements of this setup, at all depths of the tree", read_only=True)

    def execute(self, obj):
        pass


def make(doc, setup, element_count):
    obj = doc.addObject("App::DocumentObjectGroupPython", "SetupDirection")
    SetupDirection(obj)
    obj.SetupId = setup["id"]
    obj.Direction = FreeCAD.Vector(*setup["direction"])
    obj.SetupName = setup.get("name", "")
    obj.ElementCount = element_count
    obj.Label = "Setup {}".format(obj.SetupName or setup["id"])
    return obj
