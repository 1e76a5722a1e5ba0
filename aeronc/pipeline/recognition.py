"""App-side wrapper of the C++ recognition core (layered slicing).

Takes a Part shape or a document object, passes the shape to `aeronc._core` as BREP text
(unchanged, so the core's face numbers are FreeCAD's FaceN), and returns the machining-domain
tree as a dict (schema: see `recognise`). Every failure becomes `RecognitionError`.
"""
import json

import FreeCAD

from aeronc.errors import RecognitionCancelled, RecognitionError, from_core

DEFAULT_LINEAR_TOLERANCE = 1e-3   # mm
DEFAULT_ANGULAR_TOLERANCE = 1e-3  # rad
DEFAULT_CHORD_TOLERANCE = 0.01    # mm


def _core():
    # Imported on first use: the extension pulls in OCCT, which start-up does not need.
    try:
        from aeronc import _core
    except ImportError as e:
        raise RecognitionError(
            "the AeroNC recognition core (aeronc._core) is not installed or does not load: {}".format(e))
    return _core


def shape_of(source):
    """(shape, label) of a Part shape or of a document object with a Shape."""
    if hasattr(source, "isDerivedFrom") and hasattr(source, "Shape"):
        return source.Shape, source.Label
    if hasattr(source, "exportBrepToString"):
        return source, "shape"
    raise RecognitionError("{!r} is neither a Part shape nor an object with a shape".format(source))


def check_solid(shape, label="shape"):
    """Raise RecognitionError unless shape holds exactly one solid (the core's input)."""
    if shape.isNull():
        raise RecognitionError("{}: the shape is empty".format(label))
    solids = len(shape.Solids)
    if solids == 0:
        raise RecognitionError(
            "{}: not a solid ({} faces, no closed volume); select the machined part as one solid"
            .format(label, len(shape.Faces)))
    if solids > 1:
        raise RecognitionError(
            "{}: {} solids; recognition needs exactly one solid part".format(label, solids))


def recognise(source, directions=None, allowance=0.0, blank=None,
              linear_tolerance=DEFAULT_LINEAR_TOLERANCE,
              angular_tolerance=DEFAULT_ANGULAR_TOLERANCE,
              chord_tolerance=DEFAULT_CHORD_TOLERANCE,
              progress=None, report=False):
    """Recognise the machining features of a solid part.

    source      Part shape or document object (its Shape, with placement, is used)
    directions  setup directions as 3-tuples / FreeCAD.Vector; None or [] = automatic
    allowance   blank = part bounding box grown by this (mm), unless `blank` is given
    blank       (xmin, ymin, zmin, xmax, ymax, zmax) in world coordinates, or None
    progress    callable(fraction, stage) -> bool; returning False cancels
    report      also print the error to the report view (for GUI commands)

    Returns the core's JSON result as a dict: faceCount, setups, elements, faceRoles,
    faceElement, warnings. Face numbers are 1-based FaceN of the source shape.
    """
    try:
        shape, label = shape_of(source)
        check_solid(shape, label)
        core = _core()
        cancelled = []

        def on_progress(fraction, stage):
            # Remember a cancel so it is reported as such, whatever message the core uses.
            try:
                go = progress(fraction, stage)
            except Exception as e:  # a broken callback must not leave the core half-way
                FreeCAD.Console.PrintWarning("AeroNC: progress callback failed: {}\n".format(e))
                return True
            if go is False:
                cancelled.append(True)
                return False
            return True

        kwargs = dict(
            directions=[tuple(float(c) for c in d) for d in (directions or [])],
            allowance=float(allowance),
            blank=tuple(float(c) for c in blank) if blank is not None else None,
            linear_tolerance=float(linear_tolerance),
            angular_tolerance=float(angular_tolerance),
            chord_tolerance=float(chord_tolerance),
            progress=on_progress if progress is not None else None)
        try:
            with from_core(RecognitionError, label):
                text = core.recognise_brep(shape.exportBrepToString(), **kwargs)
        except RecognitionError:
            if cancelled:
                raise RecognitionCancelled("{}: recognition cancelled".format(label)) from None
            raise
        result = json.loads(text)
        for w in result.get("warnings", []):
            FreeCAD.Console.PrintWarning("AeroNC: {}: {}\n".format(label, w))
        return result
    except RecognitionError as e:
        if report and not isinstance(e, RecognitionCancelled):
            FreeCAD.Console.PrintError("AeroNC: {}\n".format(e))
        raise


def summary(result):
    """Counts of a result: {'setups', 'elements', 'closed_pocket', 'open_pocket', 'opening',
    'hole', 'faces', 'unclaimed'}; unclaimed: faces inside the blank that no element machines
    (results written before the core listed them count faces without a role)."""
    if "unclaimedFaces" in result:
        unclaimed = len(result["unclaimedFaces"])
    else:
        unclaimed = sum(1 for r in result.get("faceRoles", []) if r == "unclaimed")
    counts = {"setups": len(result.get("setups", [])), "elements": len(result.get("elements", [])),
              "closed_pocket": 0, "open_pocket": 0, "opening": 0, "hole": 0,
              "faces": result.get("faceCount", 0), "unclaimed": unclaimed}
    for el in result.get("elements", []):
        counts[el["type"]] = counts.get(el["type"], 0) + 1
    return counts


def summary_text(result):
    c = summary(result)
    return ("{setups} setups, {elements} domain elements: {closed_pocket} closed pockets, "
            "{open_pocket} open pockets, {opening} openings, {hole} holes; "
            "{unclaimed} of {faces} faces inside the blank left without an element").format(**c)
