"""MachiningFeatures: the root of a part's machining-domain tree in the document.

Holds the recognition settings, the core's JSON result (in a string property, so the tree's
data survives save/reopen without re-running recognition) and one SetupDirection child per
setup, each holding its DomainElement subtree.
"""
import json
import math

import FreeCAD

from aeronc import recognition
from aeronc.objects import domain_element, setup_direction
from aeronc.objects.base import BaseProxy, add_property, descendants, proxy_type
from aeronc.objects.transaction import in_transaction

TYPE = "AeroNC::MachiningFeatures"
COUNTS = [("SetupCount", "setups"), ("ElementCount", "elements"),
          ("ClosedPocketCount", "closed_pocket"), ("OpenPocketCount", "open_pocket"),
          ("OpeningCount", "opening"), ("HoleCount", "hole"),
          ("FaceCount", "faces"), ("UnclaimedFaceCount", "unclaimed")]


class MachiningFeatures(BaseProxy):
    Type = TYPE

    def __init__(self, obj):
        super().__init__(obj)
        g = "Recognition"
        add_property(obj, "App::PropertyLinkGlobal", "Source", g, "The part whose features were recognised")
        add_property(obj, "App::PropertyVectorList", "Directions", g,
                     "Requested setup directions; empty: found automatically")
        add_property(obj, "App::PropertyLength", "Allowance", g,
                     "Blank = part bounding box grown by this, unless Blank is set")
        add_property(obj, "App::PropertyFloatList", "Blank", g,
                     "Blank box xmin, ymin, zmin, xmax, ymax, zmax; empty: bounding box + allowance")
        add_property(obj, "App::PropertyLength", "LinearTolerance", g, "Heights equal, points coincide",
                     recognition.DEFAULT_LINEAR_TOLERANCE)
        add_property(obj, "App::PropertyAngle", "AngularTolerance", g, "Normal parallel / perpendicular to an axis",
                     math.degrees(recognition.DEFAULT_ANGULAR_TOLERANCE))
        add_property(obj, "App::PropertyLength", "ChordTolerance", g, "Sagitta when curves become polylines",
                     recognition.DEFAULT_CHORD_TOLERANCE)
        g = "Result"
        add_property(obj, "App::PropertyString", "Result", g, "Recognition result (JSON)", hidden=True)
        for prop, _ in COUNTS:
            add_property(obj, "App::PropertyInteger", prop, g, "", read_only=True)
        add_property(obj, "App::PropertyStringList", "Warnings", g, "Warnings of the recognition", read_only=True)
        add_property(obj, "App::PropertyBool", "Outdated", g,
                     "The source part changed since recognition: recognise again", read_only=True)

    def execute(self, obj):
        # Recognition itself runs from create/update (it adds and removes objects, which a
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
    """Keyword arguments of create/update that reproduce obj's recognition."""
    return dict(directions=[tuple(v) for v in obj.Directions],
                allowance=obj.Allowance.Value,
                blank=tuple(obj.Blank) if len(obj.Blank) == 6 else None,
                linear_tolerance=obj.LinearTolerance.Value,
                angular_tolerance=math.radians(obj.AngularTolerance.Value),
                chord_tolerance=obj.ChordTolerance.Value)


def _build_tree(doc, group, part, result):
    """Create the SetupDirection and DomainElement objects under group; returns them."""
    elements = {el["id"]: el for el in result.get("elements", [])}
    made = []

    def build(el_id):
        el = elements[el_id]
        obj = domain_element.make(doc, el, part)
        made.append(obj)
        kids = [build(c) for c in el.get("children", []) if c in elements]
        if kids:
            obj.Group = kids
        return obj

    setups = []
    for setup in result.get("setups", []):
        count = sum(1 for el in elements.values() if el.get("setup") == setup["id"])
        sobj = setup_direction.make(doc, setup, count)
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


def _attach_view(objs):
    if FreeCAD.GuiUp:
        from aeronc import viewproviders
        for obj in objs:
            viewproviders.attach(obj)


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
        _attach_view([group] + made)
        doc.recompute([group] + made)
        return group

    return in_transaction(doc, "Recognise machining features", work)


def update_machining_features(group, progress=None, report=False, **settings):
    """Recognise group's source again (with settings overriding the stored ones) and
    replace the group's tree, as one undo step. Returns the group."""
    doc = group.Document
    part = group.Source
    if part is None:
        raise recognition.RecognitionError("{}: no source part to recognise".format(group.Label))
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
        _attach_view(made)
        doc.recompute([group] + made)
        return group

    return in_transaction(doc, "Recognise machining features again", work)


def remove_machining_features(group):
    """Remove a MachiningFeatures group with its whole tree (one undo step)."""
    doc = group.Document
    proxy = getattr(getattr(group, "ViewObject", None), "Proxy", None)
    if proxy is not None:
        proxy.restore_source()  # the GUI's Delete does this in onDelete; App removal does not

    def work():
        for obj in descendants(group) + [group]:
            doc.removeObject(obj.Name)

    in_transaction(doc, "Remove machining features", work)


def is_machining_features(obj):
    return proxy_type(obj) == TYPE
