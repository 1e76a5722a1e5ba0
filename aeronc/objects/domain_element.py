"""DomainElement: the closed 3-D material region one generalised pocket, opening or hole
removes. Elements nest by parent/child (a pocket in the floor of another is its child).

A hole has the Hole properties besides; Select tools fills the Tools properties (a milled
element's finishing and roughing tool, a hole's drill)."""
from aeronc.objects.base import BaseProxy, declare_property

TYPE = "AeroNC::DomainElement"
ELEMENT_TYPES = ["closed_pocket", "open_pocket", "opening", "hole"]


class DomainElement(BaseProxy):
    Type = TYPE

    def __init__(self, obj, hole=False):
        super().__init__(obj)
        self.declare(obj, hole)

    def declare(self, obj, hole=None):
        """hole: give obj the Hole properties; None (a restored element): as it has them."""
        if hole is None:
            hole = "HoleDiameter" in obj.PropertiesList
        g = "Element"
        declare_property(obj, "App::PropertyInteger", "ElementId", g, "Id in the recognition result", read_only=True)
        declare_property(obj, "App::PropertyInteger", "SetupId", g, "Setup direction it is machined from",
                         read_only=True)
        declare_property(obj, "App::PropertyInteger", "ParentId", g, "Parent element id, -1 under the setup",
                         read_only=True)
        if "ElementType" not in obj.PropertiesList:
            declare_property(obj, "App::PropertyEnumeration", "ElementType", g, "Kind of domain element", ELEMENT_TYPES)
            obj.setEditorMode("ElementType", 1)
        g = "Geometry"
        for type_, name, doc in (
                ("App::PropertyDistance", "Level", "Floor height along the setup direction"),
                ("App::PropertyDistance", "Top", "Height of the top constraint"),
                ("App::PropertyLength", "Depth", "Top minus level"),
                ("App::PropertyArea", "FloorArea", "Area of the bottom constraint faces"),
                ("App::PropertyArea", "Area", "Area of the pocket region at the slicing level"),
                ("App::PropertyLength", "MinWidth", "Narrowest passage of the region"),
                ("App::PropertyLength", "MinCornerRadius", "Smallest concave corner radius (0: sharp corner, or no corner)"),
                ("App::PropertyLength", "FloorFilletRadius", "Fillet between floor and walls"),
                ("App::PropertyInteger", "IslandCount", "Island loops in the pocket"),
                ("App::PropertyStringList", "Attached", "Attached features on the side walls: kind, size, faces")):
            declare_property(obj, type_, name, g, doc, read_only=True)
        g = "Faces"
        # Global links: the part may sit in a Body or Part container outside this tree.
        declare_property(obj, "App::PropertyLinkSubListGlobal", "Faces", g,
                         "All faces of the source part this element machines")
        declare_property(obj, "App::PropertyLinkSubListGlobal", "FloorFaces", g, "Bottom constraint faces")
        declare_property(obj, "App::PropertyLinkSubListGlobal", "WallFaces", g, "Contour and island side-wall faces")
        if hole:
            g = "Hole"
            for type_, name, doc in (
                    ("App::PropertyLength", "HoleDiameter", "Drill diameter"),
                    ("App::PropertyLength", "HoleDepth", "Depth of the hole"),
                    ("App::PropertyBool", "Through", "Goes through the part"),
                    ("App::PropertyVector", "HoleAxis", "Axis, pointing out of the hole towards the tool"),
                    ("App::PropertyPosition", "HoleLocation", "Axis point at the top of the hole"),
                    ("App::PropertyLength", "CounterboreDiameter", "0: none"),
                    ("App::PropertyLength", "CounterboreDepth", ""),
                    ("App::PropertyLength", "CountersinkDiameter", "0: none"),
                    ("App::PropertyAngle", "CountersinkAngle", "Included angle")):
                declare_property(obj, type_, name, g, doc, read_only=True)
        g = "Tools"
        if hole:
            declare_property(obj, "App::PropertyString", "Drill", g, "Drill of the hole's diameter", read_only=True)
        else:
            declare_property(obj, "App::PropertyString", "FinishingTool", g, "Largest tool that finishes the element",
                             read_only=True)
            declare_property(obj, "App::PropertyString", "RoughingTool", g,
                             "First tool, largest down, whose machinable ratio meets eta_min", read_only=True)
            declare_property(obj, "App::PropertyFloat", "MachinableRatio", g, "eta = A_m / A of the roughing tool",
                             read_only=True)
            declare_property(obj, "App::PropertyInteger", "NarrowPassages", g,
                             "Passages narrower than the roughing tool", read_only=True)
        declare_property(obj, "App::PropertyString", "ToolError", g, "Why a tool is missing", read_only=True)

    def execute(self, obj):
        pass
