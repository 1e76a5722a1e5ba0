"""Helpers shared by the headless tests: generated panels and tree checks."""
import json
import os
import tempfile

import FreeCAD
import Part

# A small panel keeps the suite quick; the generator's other features stay on.
SMALL_PANEL = {"pocketsX": 2, "pocketsY": 2}


def make_panel_object(doc, spec=None, name="Panel"):
    """Add a generated integral panel (Part::Feature) to doc; returns (obj, truth list)."""
    from aeronc import _core
    brep, truth = _core.make_panel(json.dumps(spec if spec is not None else SMALL_PANEL))
    shape = Part.Shape()
    shape.importBrepFromString(brep)
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = shape
    doc.recompute()
    return obj, json.loads(truth)


def new_document(name="AeroNCTest"):
    doc = FreeCAD.newDocument(name)
    doc.UndoMode = 1  # freecadcmd documents do not record undo unless asked
    return doc


def temp_fcstd(name):
    d = tempfile.mkdtemp(prefix="aeronc_test_")
    return os.path.join(d, name + ".FCStd")
