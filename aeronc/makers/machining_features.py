"""Makers of AeroNC's document objects: the one place that creates, remakes and removes them.

  create_machining_features(doc, part, ...)   recognise part, add its machining-domain tree
  update_machining_features(group, ...)       recognise again, replace the group's tree
  remove_machining_features(group)            remove the group with its whole tree
  make_setup_direction(doc, setup, count)     one SetupDirection from a result's setup
  make_domain_element(doc, el, part)          one DomainElement from a result's element

Each change of the document is one undo step (objects/transaction.py); recognition runs
before the document is touched. The proxies (aeronc.objects) declare the properties; this
module fills them from the core's result. It runs headless; under the GUI the objects get
their view providers from whatever the GUI registered (objects.base.attach_views).
"""
import json
import math

import FreeCAD

from aeronc.pipeline import recognition
from aeronc.errors import RecognitionError
from aeronc.objects.base import attach_views, descendants
from aeronc.objects.domain_element import ELEMENT_TYPES, DomainElement
from aeronc.objects.machining_features import MachiningFeatures, settings_of
from aeronc.objects.setup_direction import SetupDirection
from aeronc.objects.transaction import in_transaction

TYPE_LABELS = {"closed_pocket": "Pocket", "open_pocket": "Open pocket", "opening": "Opening", "hole": "Hole"}


# --- One object from the result -----------------------------------------------------------------

def _num(d, key):
    """A number of the result; the core writes null where a measure does not apply."""
    v = d.get(key)
    return float(v) if v is not None else 0.0


def face_links(part, face_numbers):
    """PropertyLinkSubList value: [(part, ("Face3", ...))] for 1-based face numbers."""
    subs = tuple("Face{}".format(n) for n in sorted(set(face_numbers)))
    return [(part, subs)] if subs and part is not None else []


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


def make_domain_element(doc, el, part):
    """A DomainElement from one element of the result, its faces linked to part's."""
    obj = doc.addObject("App::DocumentObjectGroupPython", "DomainElement")
    hole = el.get("hole")
    DomainElement(obj, hole=bool(hole))
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
    if hole:
        obj.HoleDiameter, obj.HoleDepth = _num(hole, "diameter"), _num(hole, "depth")
        obj.Through = bool(hole.get("through"))
        obj.HoleAxis = FreeCAD.Vector(*hole.get("axis", (0, 0, 1)))
        obj.HoleLocation = FreeCAD.Vector(*hole.get("location", (0, 0, 0)))
        obj.CounterboreDiameter, obj.CounterboreDepth = _num(hole, "counterboreDiameter"), _num(hole, "counterboreDepth")
        obj.CountersinkDiameter, obj.CountersinkAngle = _num(hole, "countersinkDiameter"), _num(hole, "countersinkAngle")
    obj.Label = label_of(el)
    return obj


def make_setup_direction(doc, setup, element_count):
    """A SetupDirection from one setup of the result."""
    obj = doc.addObject("App::DocumentObjectGroupPython", "SetupDirection")
    SetupDirection(obj)
    obj.SetupId = setup["id"]
    obj.Direction = FreeCAD.Vector(*setup["direction"])
    obj.SetupName = setup.get("name", "")
    obj.ElementCount = element_count
    obj.Label = "Setup {}".format(obj.SetupName or setup["id"])
    return obj


# --- The tree ----------------------------------------------------------------------------------

def _build_tree(doc, group, part, result):
    """Create the SetupDirection and DomainElement objects under group; returns them."""
    elements = {el["id"]: el for el in result.get("elements", [])}
    made = []

    def build(el_id):
        el = elements[el_id]
        obj = make_domain_element(doc, el, part)
        made.append(obj)
        kids = [build(c) for c in el.get("children", []) if c in elements]
        if kids:
            obj.Group = kids
        return obj

    setups = []
    for setup in result.get("setups", []):
        count = sum(1 for el in elements.values() if el.get("setup") == setup["id"])
        sobj = make_setup_direction(doc, setup, count)
        made.append(sobj)
        sobj.Group = [build(i) for i in setup.get("elements", []) if i in elements]
        setups.append(sobj)
    group.Group = setups
    return made


def _store(group, part, result, settings):
    group.Source = part
    group.Directions = [FreeCAD.Vector(*d) for d in (settings.get("directions") or [])]
    group.Allowance = settings.get("allowance", 0.0)
    group.Blank = list(settings["blank"]) if settings.get("blank") else []
    group.LinearTolerance = settings.get("linear_tolerance", recognition.DEFAULT_LINEAR_TOLERANCE)
    group.AngularTolerance = math.degrees(settings.get("angular_tolerance", recognition.DEFAULT_ANGULAR_TOLERANCE))
    group.ChordTolerance = settings.get("chord_tolerance", recognition.DEFAULT_CHORD_TOLERANCE)
    group.Warnings = list(result.get("warnings", []))
    group.Result = json.dumps(result, separators=(",", ":"))


def create_machining_features(doc, part_obj, directions=None, allowance=0.0, blank=None,
                              linear_tolerance=recognition.DEFAULT_LINEAR_TOLERANCE,
                              angular_tolerance=recognition.DEFAULT_ANGULAR_TOLERANCE,
                              chord_tolerance=recognition.DEFAULT_CHORD_TOLERANCE,
                              progress=None, report=False):
    """Recognise part_obj's machining features and add the machining-domain tree to doc.

    Recognition runs before the document is touched; the objects are then created in one
    transaction (one undo step). On any failure the document is left as it was and the
    exception (RecognitionError for recognition failures) propagates. Angular tolerance is
    in radians, like the core's. Returns the MachiningFeatures group.
    """
    settings = dict(directions=directions, allowance=allowance, blank=blank,
                    linear_tolerance=linear_tolerance, angular_tolerance=angular_tolerance,
                    chord_tolerance=chord_tolerance)
    result = recognition.recognise(part_obj, progress=progress, report=report, **settings)

    def work():
        group = doc.addObject("App::DocumentObjectGroupPython", "MachiningFeatures")
        MachiningFeatures(group)
        group.Label = "Machining features ({})".format(part_obj.Label)
        made = _build_tree(doc, group, part_obj, result)
        _store(group, part_obj, result, settings)
        for obj in [group] + made:
            obj.Visibility = True  # freecadcmd leaves new objects hidden; the GUI shows them
        attach_views([group] + made)
        doc.recompute([group] + made)
        return group

    return in_transaction(doc, "Recognise machining features", work)


def update_machining_features(group, progress=None, report=False, **settings):
    """Recognise group's source again (with settings overriding the stored ones) and
    replace the group's tree, as one undo step. Returns the group."""
    doc = group.Document
    part = group.Source
    if part is None:
        raise RecognitionError("{}: no source part to recognise".format(group.Label))
    merged = settings_of(group)
    merged.update(settings)
    result = recognition.recognise(part, progress=progress, report=report, **merged)

    def work():
        old = descendants(group)
        group.Group = []
        for obj in old:
            doc.removeObject(obj.Name)
        made = _build_tree(doc, group, part, result)
        _store(group, part, result, merged)
        for obj in made:
            obj.Visibility = True
        attach_views(made)
        doc.recompute([group] + made)
        return group

    return in_transaction(doc, "Recognise machining features again", work)


def remove_machining_features(group):
    """Remove a MachiningFeatures group with its whole tree (one undo step)."""
    doc = group.Document

    def work():
        # Hidden first: under the GUI the group's view gives the part its own colours back
        # (the GUI's Delete does that in onDelete; removing from here does not call it).
        group.Visibility = False
        for obj in descendants(group) + [group]:
            doc.removeObject(obj.Name)

    in_transaction(doc, "Remove machining features", work)
