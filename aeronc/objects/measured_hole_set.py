"""MeasuredHoleSet: the camera's measurements of the datum holes of one photo-hole set.

Importing a measurement file maps each reading (U, V, height) through its picture's transform
chain into the part frame and keeps, per datum hole, the nominal and measured positions and
the deviation dP. The file's text is kept as it was imported. The set also holds the choice
of compensation method ("proposed" = the method with the lowest leave-one-out error) and, on
every recompute, each method's leave-one-out error over the datum holes.

A file with bad input (unknown or duplicate ids, missing datum holes, NaN, outliers, fewer
than two datum holes, a malformed line) is refused as a whole: the document stays as it was.
"""
import datetime
import json

import FreeCAD

from aeronc.drilling import compensation
from aeronc.objects.base import BaseProxy, add_property, proxy_type
from aeronc.objects.transaction import in_transaction

TYPE = "AeroNC::MeasuredHoleSet"


def method_names():
    from aeronc import _core
    return ["proposed"] + list(_core.compensation_methods())


class MeasuredHoleSet(BaseProxy):
    Type = TYPE

    def __init__(self, obj):
        super().__init__(obj)
        g = "Measurements"
        add_property(obj, "App::PropertyLinkGlobal", "PhotoHoleSet", g, "The datum holes these measurements are of")
        add_property(obj, "App::PropertyString", "SourceFile", g, "The measurement file imported", read_only=True)
        add_property(obj, "App::PropertyString", "ImportedAt", g, "When it was imported", read_only=True)
        add_property(obj, "App::PropertyString", "FileText", g, "The measurement file as imported", hidden=True)
        add_property(obj, "App::PropertyString", "Machine", g, "Machine whose calibration mapped the readings",
                     read_only=True)
        add_property(obj, "App::PropertyStringList", "HoleIds", g, "Datum holes, in the photo-hole set's order",
                     read_only=True)
        add_property(obj, "App::PropertyVectorList", "Nominal", g, "Nominal datum-hole positions (part frame)",
                     read_only=True)
        add_property(obj, "App::PropertyVectorList", "Measured", g, "Measured datum-hole positions (part frame)",
                     read_only=True)
        add_property(obj, "App::PropertyVectorList", "Deviations", g, "dP = measured - nominal", read_only=True)
        add_property(obj, "App::PropertyFloatList", "Quality", g, "Quality figure per datum hole (-1: none given)",
                     read_only=True)
        add_property(obj, "App::PropertyString", "Readings", g, "U, V, height and file line per datum hole (JSON)",
                     hidden=True)
        g = "Import"
        add_property(obj, "App::PropertyLength", "MaxDeviation", g,
                     "A datum hole farther than this from nominal is an outlier and refuses the file", 5.0)
        add_property(obj, "App::PropertyFloat", "MinQuality", g, "A quality figure below this refuses the file", 0.0)
        g = "Compensation"
        add_property(obj, "App::PropertyEnumeration", "Method", g,
                     "Compensation method; proposed = the lowest leave-one-out error", method_names())
        add_property(obj, "App::PropertyLength", "Tolerance", g, "A correction longer than this is flagged", 0.5)
        add_property(obj, "App::PropertyString", "ProposedMethod", g, "Method with the lowest leave-one-out error",
                     read_only=True)
        add_property(obj, "App::PropertyString", "MethodUsed", g, "The method the drilling is compensated by",
                     read_only=True)
        add_property(obj, "App::PropertyStringList", "LeaveOneOut", g,
                     "Each method's leave-one-out error over the datum holes", read_only=True)
        add_property(obj, "App::PropertyString", "Status", g, "What the compensation says", read_only=True)
        add_property(obj, "App::PropertyString", "Result", g, "Leave-one-out, fit and datum residuals (JSON)",
                     hidden=True)
        g = "View"
        add_property(obj, "App::PropertyFloat", "ArrowScale", g, "Deviation arrows drawn this many times longer",
                     100.0)

    def execute(self, obj):
        status, used, proposed, loo, result = evaluate(obj)
        for prop, value in (("Status", status), ("MethodUsed", used), ("ProposedMethod", proposed),
                            ("Result", json.dumps(result, separators=(",", ":")) if result else "")):
            if getattr(obj, prop) != value:
                setattr(obj, prop, value)
        if list(obj.LeaveOneOut) != loo:
            obj.LeaveOneOut = loo


def loo_lines(result):
    out = []
    for f in result.get("leave_one_out", []):
        if f["available"]:
            out.append("{}: RMS {:.4f} mm, max {:.4f} mm".format(f["method"], f["rms"], f["max"]))
        else:
            out.append("{}: not available ({})".format(f["method"], f["reason"]))
    return out


def evaluate(obj):
    """(status, method used, proposed method, leave-one-out lines, result dict) of the set's
    datum holes alone."""
    if len(obj.HoleIds) == 0:
        return "no measurements", "", "", [], {}
    try:
        survey = compensation.compensate(obj, [], "proposed")
    except compensation.CompensationError as e:
        return "not compensated: {}".format(e), "", "", [], {}
    proposed = survey["proposed"] or ""
    result = survey
    if obj.Method != "proposed":
        try:
            result = compensation.compensate(obj, [], obj.Method)
        except compensation.CompensationError as e:
            return ("not compensated: method {}: {}".format(obj.Method, e), "", proposed,
                    loo_lines(survey), dict(survey, method=""))
    return ("{} datum holes; compensated by {}{}".format(len(obj.HoleIds), result["method"],
                                                         " (proposed)" if obj.Method == "proposed" else ""),
            result["method"], proposed, loo_lines(survey), result)


def is_measured_hole_set(obj):
    return proxy_type(obj) == TYPE


def measured_sets_of(photo_set):
    return [o for o in photo_set.Document.Objects if is_measured_hole_set(o) and o.PhotoHoleSet is photo_set]


def result_of(obj):
    return json.loads(obj.Result) if obj.Result else {}


def store_readings(obj, photo_set, imported, text, path):
    obj.PhotoHoleSet = photo_set
    obj.SourceFile = path or ""
    obj.ImportedAt = datetime.datetime.now().isoformat(timespec="seconds")
    obj.FileText = text
    obj.Machine = photo_set.Machine
    obj.HoleIds = [d["id"] for d in imported]
    obj.Nominal = [FreeCAD.Vector(*d["nominal"]) for d in imported]
    obj.Measured = [FreeCAD.Vector(*d["measured"]) for d in imported]
    obj.Deviations = [FreeCAD.Vector(*d["deviation"]) for d in imported]
    obj.Quality = [-1.0 if d["quality"] is None else float(d["quality"]) for d in imported]
    obj.Readings = json.dumps([{"id": d["id"], "u": d["u"], "v": d["v"], "height": d["height"], "line": d["line"]}
                               for d in imported], separators=(",", ":"))


def set_method(obj, method):
    """Choose the compensation method (a name of method_names()); one undo step."""
    if method not in method_names():
        raise compensation.CompensationError("unknown compensation method '{}' ({})".format(
            method, ", ".join(method_names())))

    def work():
        obj.Method = method
        obj.Document.recompute()

    in_transaction(obj.Document, "Compensation method", work)
