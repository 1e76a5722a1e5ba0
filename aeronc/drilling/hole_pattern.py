"""The datum holes and hole pattern of a photo-hole set, read as plain data for the camera
program and the compensation: the holes in camera order, the part's placement as a map from the
part frame to the assembly frame, and the rows of the pattern (drawn by hand, or found).
Reads the set's properties; knows no proxy and no view."""
import FreeCAD


def assembly_from_part(part):
    """(position, normal) in the part frame -> the same in the assembly (document) frame."""
    pl = part.Placement

    def convert(p, n):
        a = pl.multVec(FreeCAD.Vector(*p))
        b = pl.Rotation.multVec(FreeCAD.Vector(*n))
        return [a.x, a.y, a.z], [b.x, b.y, b.z]
    return convert


def holes_of(obj):
    """The datum holes as dicts (id, faces, position, normal, diameter, depth, segment), in order."""
    out = []
    for i, hid in enumerate(obj.HoleIds):
        p, n = obj.Positions[i], obj.Normals[i]
        out.append({"id": hid, "faces": obj.HoleFaces[i].split(), "position": (p.x, p.y, p.z),
                    "normal": (n.x, n.y, n.z), "diameter": obj.Diameters[i], "depth": obj.Depths[i],
                    "segment": obj.Segments[i]})
    return out


def drawn_rows(obj):
    """The rows drawn by hand: lists of hole face names (each hole's first face), in order."""
    return [r.split() for r in getattr(obj, "DrawnRows", [])]


def pattern_rows(obj, points, faces):
    """(row per point, station per point, members per row) of the pattern holes at `points`
    (part frame) whose first faces are `faces`: the rows drawn by hand first, each in its drawn
    order with stations along it; the rows of the other holes found automatically."""
    from aeronc import _core
    index = {f: i for i, f in enumerate(faces)}
    rows, stations, members = [None] * len(points), [0.0] * len(points), []
    for drawn in drawn_rows(obj):
        m = [index[f] for f in drawn if f in index]
        if len(m) < 2:
            continue  # a hole of the row is no longer in the pattern (MaxHoleDiameter changed)
        s = 0.0
        for k, i in enumerate(m):
            if k:
                s += sum((a - b) ** 2 for a, b in zip(points[i], points[m[k - 1]])) ** 0.5
            rows[i], stations[i] = len(members), s
        members.append(m)
    rest = [i for i in range(len(points)) if rows[i] is None]
    if rest:
        r, st, mem = _core.find_rows([points[i] for i in rest])
        offset = len(members)
        for k, i in enumerate(rest):
            rows[i], stations[i] = offset + r[k], st[k]
        members += [[rest[k] for k in m] for m in mem]
    return rows, stations, members
