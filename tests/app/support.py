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


def make_pocket_job(doc):
    """A 120 x 80 x 30 block with a 60 x 40 x 10 pocket, its Path Job and a Pocket Shape on the
    pocket's floor with step-down 3 mm and step-over 50 % (on the Job's default controller;
    headless, Path's operations cannot choose between several). Returns (part, job, pocket)."""
    import Part
    from aeronc import pathcompat
    from aeronc.tests import pathcompat as test_pathcompat
    block = Part.makeBox(120, 80, 30).cut(Part.makeBox(60, 40, 10, FreeCAD.Vector(30, 20, 20)))
    part = doc.addObject("Part::Feature", "Block")
    part.Shape = block
    doc.recompute()
    job = pathcompat.create_job(doc, [part])
    doc.recompute()
    floor = [i + 1 for i, f in enumerate(block.Faces)
             if abs(f.Surface.Axis.z) > 0.99 and abs(f.CenterOfMass.z - 20) < 1e-6]
    assert len(floor) == 1, floor
    pocket = test_pathcompat.create_pocket_shape("Pocket")
    pocket.Base = [(job.Model.Group[0], ["Face{}".format(floor[0])])]  # the Job's clone of the block
    pocket.setExpression("StepDown", None)  # the setup sheet's default is the tool diameter
    pocket.StepDown = "3 mm"
    pocket.StepOver = 50
    return part, job, pocket


def end_mill(diameter, flutes=3, material="Carbide", corner=None, length=60):
    """A .fctb document (dict) of an end mill, a bull nose when corner is given."""
    params = {"Diameter": "{} mm".format(diameter), "CuttingEdgeHeight": "30 mm", "Length": "{} mm".format(length),
              "ShankDiameter": "{} mm".format(diameter)}
    shape = "endmill.fcstd"
    if corner is not None:
        shape = "bullnose.fcstd"
        params["FlatRadius"] = "{} mm".format(diameter / 2 - corner)
    attrs = {}
    if flutes is not None:
        attrs["Flutes"] = flutes
    if material is not None:
        attrs["Material"] = material
    return {"version": 2, "name": "{:g} mm end mill".format(diameter), "shape": shape, "parameter": params,
            "attribute": attrs}
