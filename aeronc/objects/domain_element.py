"""DomainElement: the closed 3-D material region one generalised pocket, opening or hole
removes. Elements nest by parent/child (a pocket in the floor of another is its child)."""
import FreeCAD

from aeronc.objects.base import BaseProxy, add_property, face_links

TYPE = "AeroNC::DomainElement"
ELEMENT_TYPES = ["closed_pocket", "open_pocket", "opening", "hole"]
TYPE_LABELS = {"closed_pocket": "Pocket", "open_pocket": "Open pocket",
               "opening": "Opening", "hole": "Hole"}


class DomainElement(BaseProxy):
    Type = TYPE

    def __init__(self, obj):
        super().__init__(obj)
        g = "Element"
        add_property(obj, "App::PropertyInteger", "ElementId", g, "Id in the recognition result", read_only=True)
        add_property(obj, "App::PropertyInteger", "SetupId", g, "Setup direction it is machined from", read_only=True)
        add_property(obj, "App::PropertyInteger", "ParentId", g, "Parent element id, -1 under the setup", read_only=True)
        add_property(obj, "App::PropertyEnumeration", "ElementType", g, "Kind of domain element", ELEMENT_TYPES)
        obj.setEditorMode("ElementType", 1)
        g = "Geometry"
        add_property(obj, "App::PropertyDistance", "Level", g, "Floor height along the setup direction", read_only=True)
        add_property(obj, "App::PropertyDistance", "Top", g, "Height of the top constraint", read_only=True)
        add_property(obj, "App::PropertyLength", "Depth", g, "Top minus level", read_only=True)
        add_property(obj, "App::PropertyArea", "FloorArea", g, "Area of the bottom constraint faces", read_only=True)
        add_property(obj, "App::PropertyArea", "Area", g, "Area of the pocket region at the slicing level", read_only=True)
        add_property(obj, "App::PropertyLength", "MinWidth", g, "Narrowest passage of the region", read_only=True)
        add_property(obj, "App::PropertyLength", "MinCornerRadius", g,
                     "Smallest concave corner radius (0: sharp corner, or no corner)", read_only=True)
        add_property(obj, "App::PropertyLength", "FloorFilletRadius", g, "Fillet between floor and walls", read_only=True)
        add_property(obj, "App::PropertyInteger", "IslandCount", g, "Island loops in the pocket", read_only=True)
        add_property(obj, "App::PropertyStringList", "Attached", g,
                     "Attached features on the side walls: kind, size, faces", read_only=True)
        g = "Faces"
        # Global links: the part may sit in a Body or Part container outside this tree.
        add_property(obj, "App::PropertyLinkSubListGlobal", "Faces", g, "All faces of the source part this element machines")
        add_property(obj, "App::PropertyLinkSubListGlobal", "FloorFaces", g, "Bottom constraint faces")
        add_property(obj, "App::PropertyLinkSubListGlobal", "WallFaces", g, "Contour and island side-wall faces")

    def execute(self, obj):
        pass

    @staticmethod
    def add_hole_properties(obj, hole):
        g = "Hole"
        add_property(obj, "App::PropertyLength", "HoleDiameter", g, "Drill diameter", _num(hole, "diameter"), True)
        add_property(obj, "App::PropertyLength", "HoleDepth", g, "Depth of the hole", _num(hole, "depth"), True)
        add_property(obj, "App::PropertyBool", "Through", g, "Goes through the part", bool(hole.get("through")), True)
        add_property(obj, "App::PropertyVector", "HoleAxis", g, "Axis, pointing out of the hole towards the tool",
                     FreeCAD.Vector(*hole.get("axis", (0, 0, 1))), True)
        add_property(obj, "App::PropertyPosition", "HoleLocation", g, "Axis point at the top of the hole",
                     FreeCAD.Vector(*hole.get("location", (0, 0, 0))), True)
        add_property(obj, "App::PropertyLength", "CounterboreDiameter", g, "0: none",
                     _num(hole, "counterboreDiameter"), True)
        add_property(obj, "App::PropertyLength", "CounterboreDepth", g, "", _num(hole, "counterboreDepth"), True)
        add_property(obj, "App::PropertyLength", "CountersinkDiameter", g, "0: none",
                     _num(hole, "countersinkDiameter"), True)
        add_property(obj, "App::PropertyAngle", "CountersinkAngle", g, "Included angle",
                     _num(hole, "countersinkAngle"), True)


def element_faces(el):
    """Face numbers an element machines: its walls, floor, blends and attached features
    (not the top constraint, which it shares with the part)."""
    faces = set(el.get("contourFaces", [])) | set(el.get("floorFaces", []))
    faces |= set(el.get("filletFaces", [])) | set(el.get("chamferFaces", []))
    for loop in el.get("islandFaces", []):
        faces |= set(loop)
    for att in el.get("attached", []):
        faces |= set(att.get("faces", []))
    return faces


def attached_text(att):
    parts = [att.get("kind", "?")]
    if att.get("radius"):
        parts.append("r={:g}".format(att["radius"]))
    if att.get("size"):
        parts.append("size={:g}".format(att["size"]))
    if att.get("element", -1) >= 0:
        parts.append("element={}".format(att["element"]))
    parts += ["Face{}".format(f) for f in att.get("faces", [])]
    return " ".join(parts)


def label_of(el):
    text = "{} {}".format(TYPE_LABELS.get(el["type"], el["type"]), el["id"])
    hole = el.get("hole")
    if hole:
        text += " \u00d8{:g}".format(round(_num(hole, "diameter"), 3))
    return text


def _num(d, key):
    """A number of the result; the core writes null where a measure does not apply."""
    v = d.get(key)
    return float(v) if v is not None else 0.0


def make(doc, el, part):
    obj = doc.addObject("App::DocumentObjectGroupPython", "DomainElement")
    DomainElement(obj)
    if el["type"] not in ELEMENT_TYPES:  # a type newer than this file: keep it, don't fail
        obj.ElementType = ELEMENT_TYPES + [el["type"]]
    obj.ElementType = el["type"]
    obj.ElementId, obj.SetupId, obj.ParentId = el["id"], el["setup"], el.get("parent", -1)
    obj.Level, obj.Top = _num(el, "level"), _num(el, "top")
    obj.Depth = max(0.0, _num(el, "depth"))
    obj.FloorArea, obj.Area = _num(el, "floorArea"), _num(el, "area")
    obj.MinWidth = _num(el, "minWidth")
    obj.MinCornerRadius = _num(el, "minCornerRadius")
    obj.FloorFilletRadius = _num(el, "floorFilletRadius")
    obj.IslandCount = len(el.get("islands", [])) or len(el.get("islandFaces", []))
    obj.Attached = [attached_text(a) for a in el.get("attached", [])]
    obj.Faces = face_links(part, element_faces(el))
    obj.FloorFaces = face_links(part, el.get("floorFaces", []))
    walls = list(el.get("contourFaces", []))
    for loop in el.get("islandFaces", []):
        walls += loop
    obj.WallFaces = face_links(part, walls)
    if el.get("hole"):
        DomainElement.add_hole_properties(obj, el["hole"])
    obj.Label = label_of(el)
    return obj
