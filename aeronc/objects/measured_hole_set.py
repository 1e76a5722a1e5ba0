"""MeasuredHoleSet: the camera's measurements of the datum holes of one photo-hole set.

Importing a measurement file maps each reading (U, V, height) through its picture's transform
chain into the part frame and keeps, per datum hole, the nominal and measured positions and
the deviation dP. The file's text is kept as it was imported. The set also holds the choice
of compensation method ("proposed" = the method with the lowest leave-one-out error) and, on
every recompute, each method's leave-one-out error over the datum holes used.

Datum readings out of line with the others (a camera that read a burr, a chip or a reflection)
are left out (the core's datum check, docs/compensation.md): `LeftOut` names them, `DatumFlags`
says why, and the console says so when they change. The user has the last word: `PutBack`
lists datum holes used although out of line, `LeftOutByHand` those never used; put_back() and
leave_out() change them, one undo step each.

A file with bad input (unknown or duplicate ids, missing datum holes, NaN, outliers, fewer
than two datum holes, a malformed line) is refused as a whole: the document stays as it was.
"""
import datetime
import json

import FreeCAD

from aeronc.drilling import compensation
from aeronc.objects.base import BaseProxy, add_property, declare_property, proxy_type
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
        add_property(obj, "App::PropertyLength", "Tolerance", g,
                     "A drilled hole whose correction is longer than this is flagged", 0.5)
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
        self.declare(obj)

    def declare(self, obj):
        g = "Datum check"
        declare_property(obj, "App::PropertyBool", "DatumCheck", g,
                         "Leave out datum readings out of line with the others", True)
        declare_property(obj, "App::PropertyFloat", "OutOfLineFactor", g,
                         "A reading is out of line when the other datum holes predict it (across its normal and whole) "
                         "worse than this many times the typical (median) miss of the others...", 5.0)
        declare_property(obj, "App::PropertyLength", "OutOfLineMinimum", g,
                         "...and worse than this", 0.1)
        declare_property(obj, "App::PropertyStringList", "PutBack", g,
                         "Datum holes put back: used although out of line")
        declare_property(obj, "App::PropertyStringList", "LeftOutByHand", g, "Datum holes never used")
        declare_property(obj, "App::PropertyStringList", "LeftOut", g,
                         "Datum holes left out of the compensation (out of line, or by hand)", read_only=True)
        declare_property(obj, "App::PropertyFloatList", "Misses", g,
                         "Per datum hole: how far the datum holes used predict its deviation from the measured one, "
                         "mm (-1: none can)", read_only=True)
        declare_property(obj, "App::PropertyStringList", "DatumFlags", g,
                         "Datum holes to look at, and why", read_only=True)
        declare_property(obj, "App::PropertyLength", "NeighbourTolerance", "Compensation",
                         "A drilled hole whose correction departs more than this from its neighbours' is flagged",
                         0.05)

    def execute(self, obj):
        status, used, proposed, loo, result = evaluate(obj)
        for prop, value in (("Status", status), ("MethodUsed", used), ("ProposedMethod", proposed),
                            ("Result", json.dumps(result, separators=(",", ":")) if result else "")):
            if getattr(obj, prop) != value:
                setattr(obj, prop, value)
        if list(obj.LeaveOneOut) != loo:
            obj.LeaveOneOut = loo
        verdicts = {d["id"]: d for d in result.get("datums", [])}
        left_out = [i for i in obj.HoleIds if i in verdicts and not verdicts[i]["used"]]
        misses = [-1.0 if verdicts.get(i, {}).get("miss") is None else verdicts[i]["miss"] for i in obj.HoleIds]
        flags = datum_flag_lines(result)
        if list(obj.Misses) != misses:
            obj.Misses = misses
        if list(obj.LeftOut) != left_out or list(obj.DatumFlags) != flags:
            obj.LeftOut = left_out
            obj.DatumFlags = flags
            for line in flags:  # said once, when they change
                console_warning("AeroNC: {}: datum hole {}\n".format(obj.Label, line))


def console_warning(text):
    FreeCAD.Console.PrintWarning(text)


def datum_flag_lines(result):
    """"DH13: left out: 0.800 mm from where the other datum holes put it (rigid); ..." per datum
    flag of a compensation result."""
    return ["{}: {}".format(f["id"], f["reason"]) for f in result.get("flags", []) if f["kind"].startswith("datum")]


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
    left_out = [d["id"] for d in result["datums"] if not d["used"]]
    check = result["check"]
    said = "; {} left out ({})".format(len(left_out), ", ".join(left_out)) if left_out else \
        ("; none out of line" if check["checked"] else "; not checked: " + check["note"])
    return ("{} datum holes{}; compensated by {}{}".format(len(obj.HoleIds), said, result["method"],
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


def _check_id(obj, hole_id):
    if hole_id not in obj.HoleIds:
        raise compensation.CompensationError("{} is not a measured datum hole of {} ({})".format(
            hole_id, obj.Label, ", ".join(obj.HoleIds)))


def put_back(obj, hole_id):
    """Use the datum hole again: off the hand-made list, and kept although out of line; one
    undo step."""
    _check_id(obj, hole_id)

    def work():
        obj.LeftOutByHand = [i for i in obj.LeftOutByHand if i != hole_id]
        if hole_id not in obj.PutBack:
            obj.PutBack = list(obj.PutBack) + [hole_id]
        obj.Document.recompute()

    in_transaction(obj.Document, "Put back datum hole {}".format(hole_id), work)


def leave_out(obj, hole_id):
    """Never use the datum hole (and no longer put back); one undo step."""
    _check_id(obj, hole_id)

    def work():
        obj.PutBack = [i for i in obj.PutBack if i != hole_id]
        if hole_id not in obj.LeftOutByHand:
            obj.LeftOutByHand = list(obj.LeftOutByHand) + [hole_id]
        obj.Document.recompute()

    in_transaction(obj.Document, "Leave out datum hole {}".format(hole_id), work)
