"""PhotoHoleSet: the datum (photo) holes of a part, an ordered and numbered list (the order
the camera visits them), with the surface their normals come from and the camera settings.

Each datum hole keeps an id for good (DH1, DH2, ...; the measurement file names holes by it),
its faces on the part, and its entry point, normal, diameter, depth and part segment (solid)
in the part frame (the part's own coordinates, before its placement). Datum holes are drilled
in advance: the compensated drilling leaves them out.

Spacing checks (recomputed with the set): at least two datum holes per part segment, and a
warning for every row of holes without a datum hole at one of its ends.
"""
import FreeCAD

from aeronc.drilling import hole_geometry
from aeronc.drilling.hole_pattern import drawn_rows, holes_of, pattern_rows  # noqa: F401  (the set's holes and rows)
from aeronc.objects.base import BaseProxy, add_property, declare_property, proxy_type
from aeronc.objects.transaction import in_transaction

TYPE = "AeroNC::PhotoHoleSet"
HOLE_LISTS = ("HoleIds", "HoleFaces", "Positions", "Normals", "Diameters", "Depths", "Segments")


class PhotoHoleSet(BaseProxy):
    Type = TYPE

    def __init__(self, obj):
        super().__init__(obj)
        g = "Datum holes"
        add_property(obj, "App::PropertyLinkGlobal", "Source", g, "The part the datum holes are in")
        add_property(obj, "App::PropertyStringList", "HoleIds", g, "Id of each datum hole, in camera order",
                     read_only=True)
        add_property(obj, "App::PropertyStringList", "HoleFaces", g,
                     "Faces of each datum hole on the part (space separated)", read_only=True)
        add_property(obj, "App::PropertyVectorList", "Positions", g,
                     "Entry point of each datum hole (part frame)", read_only=True)
        add_property(obj, "App::PropertyVectorList", "Normals", g,
                     "Surface normal at each datum hole (part frame)", read_only=True)
        add_property(obj, "App::PropertyFloatList", "Diameters", g, "Diameter of each datum hole, mm", read_only=True)
        add_property(obj, "App::PropertyFloatList", "Depths", g, "Depth of each datum hole, mm", read_only=True)
        add_property(obj, "App::PropertyIntegerList", "Segments", g,
                     "Part segment (solid of the part) of each datum hole", read_only=True)
        add_property(obj, "App::PropertyLinkSubListGlobal", "Surface", g,
                     "The surface used for the normals; empty: the face round each hole's entry")
        add_property(obj, "App::PropertyInteger", "NextNumber", g, "Number of the next new id", 1, hidden=True)
        add_property(obj, "App::PropertyVector", "Up", g,
                     "Without a surface, a hole is entered from its end facing this way", FreeCAD.Vector(0, 0, 1))
        g = "Checks"
        add_property(obj, "App::PropertyLength", "MaxHoleDiameter", g,
                     "Holes of the part up to this diameter make the rows of holes", 20.0)
        add_property(obj, "App::PropertyStringList", "SpacingWarnings", g, "Spacing rules not met", read_only=True)
        add_property(obj, "App::PropertyInteger", "RowCount", g, "Rows of holes on the part", read_only=True)
        add_property(obj, "App::PropertyVectorList", "PatternPositions", g,
                     "Entry point of every hole of the part up to MaxHoleDiameter (part frame): the rows "
                     "of holes are found over these", read_only=True)
        add_property(obj, "App::PropertyStringList", "PatternFaces", g, "Faces of each hole of the pattern",
                     read_only=True)
        add_property(obj, "App::PropertyVectorList", "PatternNormals", g, "Surface normal at each hole of the pattern",
                     read_only=True)
        add_property(obj, "App::PropertyFloatList", "PatternDiameters", g, "Diameter of each hole of the pattern",
                     read_only=True)
        add_property(obj, "App::PropertyFloatList", "PatternDepths", g, "Depth of each hole of the pattern",
                     read_only=True)
        g = "Camera"
        add_property(obj, "App::PropertyString", "Machine", g, "Machine file of the camera (resources/machines)",
                     "AC-HEAD")
        add_property(obj, "App::PropertyLength", "Standoff", g, "Camera height above each datum hole", 60.0)
        add_property(obj, "App::PropertyLength", "Approach", g, "Approach distance above the camera position", 20.0)
        add_property(obj, "App::PropertyDistance", "SafeHeight", g,
                     "Z of the moves between datum holes (workpiece frame)", 100.0)
        add_property(obj, "App::PropertyFloat", "Dwell", g, "Seconds at each datum hole for the picture", 0.5)
        add_property(obj, "App::PropertySpeed", "Feed", g, "Feed from the approach point to the camera position",
                     "3000 mm/min")
        self.declare(obj)

    def declare(self, obj):
        declare_property(obj, "App::PropertyStringList", "DrawnRows", "Checks",
                         "Rows of holes drawn by hand: the first face of each hole, in order along the row "
                         "(space separated); the other holes' rows are found automatically", read_only=True)

    def execute(self, obj):
        holes = pattern_holes(obj)
        faces = [" ".join(h["faces"]) for h in holes]
        if list(obj.PatternFaces) != faces or len(obj.PatternPositions) != len(holes):
            obj.PatternFaces = faces
            obj.PatternPositions = [h["entry"] for h in holes]
            obj.PatternNormals = [h["normal"] for h in holes]
            obj.PatternDiameters = [float(h["diameter"]) for h in holes]
            obj.PatternDepths = [float(h["depth"]) for h in holes]
        warnings, rows = spacing_checks(obj, holes)
        if list(obj.SpacingWarnings) != warnings:
            obj.SpacingWarnings = warnings
        if obj.RowCount != rows:
            obj.RowCount = rows


def is_photo_hole_set(obj):
    return proxy_type(obj) == TYPE


def photo_hole_sets_of(doc, part):
    return [o for o in doc.Objects if is_photo_hole_set(o) and o.Source is part]


def surface_faces(obj):
    """Names of the faces of the set's surface for normals (on its source part)."""
    out = []
    for linked, subs in obj.Surface:
        if linked is obj.Source:
            out += [s for s in subs if s.startswith("Face")]
    return out


def _to_part(part, v, direction=False):
    inv = part.Placement.inverse()
    return inv.Rotation.multVec(v) if direction else inv.multVec(v)


def pattern_of(obj):
    """The stored hole pattern: [{faces, entry, normal, diameter, depth, datum}] (part frame)."""
    by_face = {}
    for hid, faces in zip(obj.HoleIds, obj.HoleFaces):
        for f in faces.split():
            by_face[f] = hid
    out = []
    for i, faces in enumerate(obj.PatternFaces):
        names = faces.split()
        out.append({"faces": names, "entry": obj.PatternPositions[i], "normal": obj.PatternNormals[i],
                    "diameter": obj.PatternDiameters[i], "depth": obj.PatternDepths[i],
                    "datum": next((by_face[f] for f in names if f in by_face), None)})
    return out


def datum_faces(obj):
    """Every face of every datum hole of the set."""
    return {f for faces in obj.HoleFaces for f in faces.split()}


def measure_hole(part, face, surface, up):
    h = hole_geometry.hole(part.Shape, face, surface or None, tuple(up))
    return {"faces": " ".join(h["faces"]), "position": _to_part(part, h["entry"]),
            "normal": _to_part(part, h["normal"], True), "diameter": h["diameter"], "depth": h["depth"],
            "segment": h["solid"]}


def write_holes(obj, rows):
    """Set every hole list from rows (dicts with id, faces, position, normal, ...), in order."""
    obj.HoleIds = [r["id"] for r in rows]
    obj.HoleFaces = [r["faces"] for r in rows]
    obj.Positions = [FreeCAD.Vector(*r["position"]) for r in rows]
    obj.Normals = [FreeCAD.Vector(*r["normal"]) for r in rows]
    obj.Diameters = [float(r["diameter"]) for r in rows]
    obj.Depths = [float(r["depth"]) for r in rows]
    obj.Segments = [int(r["segment"]) for r in rows]


def _rows(obj):
    return [{"id": h["id"], "faces": " ".join(h["faces"]), "position": h["position"], "normal": h["normal"],
             "diameter": h["diameter"], "depth": h["depth"], "segment": h["segment"]} for h in holes_of(obj)]


def _new_rows(obj, part, sub_names):
    """Measured rows for the holes named by sub_names (faces or circular edges), refusing
    holes already in the set; the document is not touched."""
    faces = hole_geometry.selected_hole_faces(part.Shape, sub_names)
    taken = {}
    for hid, hf in zip(obj.HoleIds, obj.HoleFaces):
        for f in hf.split():
            taken[f] = hid
    already = ["{} (datum hole {})".format(f, taken[f]) for f in faces if f in taken]
    if already:
        raise hole_geometry.HoleError("already datum holes of {}: {}".format(obj.Label, ", ".join(already)))
    return [measure_hole(part, f, surface_faces(obj), obj.Up) for f in faces]


def add_datum_holes(obj, sub_names):
    """Append the holes named by sub_names to the set (one undo step); returns their ids."""
    part = obj.Source
    new = _new_rows(obj, part, sub_names)

    def work():
        rows = _rows(obj)
        ids = []
        for r in new:
            r["id"] = "DH{}".format(obj.NextNumber + len(ids))
            ids.append(r["id"])
        obj.NextNumber = obj.NextNumber + len(ids)
        write_holes(obj, rows + new)
        obj.Document.recompute([obj])
        return ids

    return in_transaction(obj.Document, "Define datum (photo) holes", work)


def set_order(obj, ids):
    """Put the datum holes in the order of ids (a permutation of the set's ids); one undo step."""
    rows = {r["id"]: r for r in _rows(obj)}
    if sorted(ids) != sorted(rows):
        raise ValueError("the new order must list every datum hole of {} once: {}".format(
            obj.Label, ", ".join(rows)))

    def work():
        write_holes(obj, [rows[i] for i in ids])
        obj.Document.recompute([obj])

    in_transaction(obj.Document, "Reorder datum holes", work)


def remove_datum_holes(obj, ids):
    """Remove the datum holes with these ids (one undo step); their ids are not reused."""
    rows = _rows(obj)
    unknown = [i for i in ids if i not in {r["id"] for r in rows}]
    if unknown:
        raise ValueError("{} holds no datum hole {}".format(obj.Label, ", ".join(unknown)))

    def work():
        write_holes(obj, [r for r in rows if r["id"] not in set(ids)])
        obj.Document.recompute([obj])

    in_transaction(obj.Document, "Remove datum holes", work)


def set_surface(obj, face_names):
    """Take the normals (and entry points) of every datum hole from these faces of the part
    (empty: the face round each hole's entry); one undo step."""
    part = obj.Source
    rows = _rows(obj)
    for r in rows:
        m = measure_hole(part, r["faces"].split()[0], face_names, obj.Up)
        r.update({k: m[k] for k in ("position", "normal", "diameter", "depth", "segment")})

    def work():
        obj.Surface = [(part, tuple(face_names))] if face_names else []
        write_holes(obj, rows)
        obj.Document.recompute([obj])

    in_transaction(obj.Document, "Surface for the datum-hole normals", work)


def pattern_holes(obj):
    """Every hole of the source part up to MaxHoleDiameter (entry in the part frame), as
    hole_geometry gives them, with `datum` set to the datum hole's id or None."""
    part = obj.Source
    if part is None or not hasattr(part, "Shape"):
        return []
    by_face = {}
    for hid, faces in zip(obj.HoleIds, obj.HoleFaces):
        for f in faces.split():
            by_face[f] = hid
    out = []
    for h in hole_geometry.find_holes(part.Shape, obj.MaxHoleDiameter.Value, surface_faces(obj) or None,
                                      tuple(obj.Up)):
        h["entry"] = _to_part(part, h["entry"])
        h["normal"] = _to_part(part, h["normal"], True)
        h["datum"] = next((by_face[f] for f in h["faces"] if f in by_face), None)
        out.append(h)
    return out


def spacing_checks(obj, holes=None):
    """(warnings, number of rows): at least two datum holes per part segment; a datum hole at
    both ends of every row of holes."""
    part = obj.Source
    if part is None or not hasattr(part, "Shape"):
        return ["no source part"], 0
    warnings = []
    if holes is None:
        holes = pattern_holes(obj)
    counts = {}
    for s in obj.Segments:
        counts[s] = counts.get(s, 0) + 1
    segments = sorted({h["solid"] for h in holes} | set(counts))
    for s in segments:
        n = counts.get(s, 0)
        if n < 2:
            warnings.append("part segment {} (solid {} of {}) has {} datum hole{}: at least two are needed".format(
                s + 1, s + 1, part.Label, n, "" if n == 1 else "s"))
    if not holes:
        return warnings, 0
    _, _, members = pattern_rows(obj, [(h["entry"].x, h["entry"].y, h["entry"].z) for h in holes],
                                 [h["faces"][0] for h in holes])
    for r, m in enumerate(members):
        if len(m) < 2:
            continue
        first, last = holes[m[0]], holes[m[-1]]
        where = "row {} ({} holes, {} to {})".format(r + 1, len(m), first["faces"][0], last["faces"][0])
        datums = sum(1 for i in m if holes[i]["datum"])
        if datums == 0:
            warnings.append("{}: no datum hole".format(where))
            continue
        ends = [name for name, h in (("start", first), ("end", last)) if not h["datum"]]
        if ends:
            warnings.append("{}: no datum hole at its {}".format(where, " and ".join(ends)))
    return warnings, len(members)


def draw_row(obj, sub_names):
    """A row of holes drawn by hand through the holes named by sub_names (faces or circular
    edges of the part, in order along the row); one undo step. The seed's method and the
    spacing checks then use it instead of the rows found automatically. Refuses fewer than two
    holes, a hole that is not in the part's hole pattern and a hole already in a drawn row."""
    part = obj.Source
    faces = hole_geometry.selected_hole_faces(part.Shape, sub_names)
    pattern = {f.split()[0]: f.split() for f in obj.PatternFaces}
    first = []
    for f in faces:
        main = next((k for k, names in pattern.items() if f in names), None)
        if main is None:
            raise hole_geometry.HoleError("{} is not a hole of the pattern (holes up to {} mm)".format(
                f, obj.MaxHoleDiameter.Value))
        first.append(main)
    if len(first) < 2:
        raise hole_geometry.HoleError("a row needs at least two holes")
    taken = {f: n + 1 for n, r in enumerate(drawn_rows(obj)) for f in r}
    clash = [f for f in first if f in taken]
    if clash:
        raise hole_geometry.HoleError("{} is already in drawn row {}".format(clash[0], taken[clash[0]]))

    def work():
        obj.DrawnRows = list(obj.DrawnRows) + [" ".join(first)]
        obj.Document.recompute([obj])

    in_transaction(obj.Document, "Draw a row of holes", work)


def clear_drawn_rows(obj):
    """Forget the rows drawn by hand (all rows found automatically again); one undo step."""
    def work():
        obj.DrawnRows = []
        obj.Document.recompute([obj])

    in_transaction(obj.Document, "Clear the drawn rows", work)
