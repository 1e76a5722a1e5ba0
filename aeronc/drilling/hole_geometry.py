"""Holes of a part as drilling sees them: the cylindrical faces (a hole split into half
cylinders is one hole), where the hole's axis meets the surface it is drilled from (the entry
point), the surface normal there, the diameter and the depth.

A hole is found from a cylindrical face or from one of its circular edges. Its entry is the
end that opens onto the surface used for normals when one is given, otherwise the end facing
`up` most (the outside of a skin). All points here are in the frame of the shape given
(FreeCAD's global frame for obj.Shape).
"""
import math

import FreeCAD
import Part

from aeronc.errors import HoleError  # noqa: F401  (raised here; callers catch it as hole_geometry.HoleError)

LINEAR_TOLERANCE = 1e-4


def _vec(v):
    return FreeCAD.Vector(v[0], v[1], v[2])


def _is_cylinder(face):
    return isinstance(face.Surface, Part.Cylinder)


def _axis_of(face):
    s = face.Surface
    return FreeCAD.Vector(s.Center), FreeCAD.Vector(s.Axis).normalize(), s.Radius


def _is_concave(face):
    """True when the cylindrical face bounds empty space inside it (a hole, not a boss)."""
    centre, axis, _ = _axis_of(face)
    u0, u1, v0, v1 = face.ParameterRange
    u, v = 0.5 * (u0 + u1), 0.5 * (v0 + v1)
    p = face.valueAt(u, v)
    radial = p - centre
    radial = radial - axis * radial.dot(axis)
    return face.normalAt(u, v).dot(radial) < 0.0


def _axial_range(face, centre, axis):
    ts = [(v.Point - centre).dot(axis) for v in face.Vertexes]
    for e in face.Edges:  # the ends of a hole in a curved skin are not planar: sample them
        for k in range(5):
            p = e.valueAt(e.FirstParameter + (e.LastParameter - e.FirstParameter) * k / 4.0)
            ts.append((p - centre).dot(axis))
    return min(ts), max(ts)


def _face_name(shape, face):
    for i, f in enumerate(shape.Faces):
        if f.isSame(face):
            return "Face{}".format(i + 1)
    return None


def _solid_index(shape, face):
    for i, s in enumerate(shape.Solids):
        for f in s.Faces:
            if f.isSame(face):
                return i
    return 0


def _same_axis(a, b, tol):
    """Two cylindrical faces on the same axis line with the same radius."""
    ca, aa, ra = a
    cb, ab, rb = b
    if abs(ra - rb) > tol or abs(abs(aa.dot(ab)) - 1.0) > 1e-9:
        return False
    d = cb - ca
    return (d - aa * d.dot(aa)).Length <= tol


def hole_faces(shape, face_name):
    """Names of the faces that make the hole of face_name (the half cylinders of one hole)."""
    face = shape.getElement(face_name)
    if not isinstance(face, Part.Face) or not _is_cylinder(face):
        raise HoleError("{} is not a cylindrical face".format(face_name))
    if not _is_concave(face):
        raise HoleError("{} is a boss (convex cylinder), not a hole".format(face_name))
    ref = _axis_of(face)
    t0, t1 = _axial_range(face, ref[0], ref[1])
    names = [face_name]
    for i, f in enumerate(shape.Faces):
        name = "Face{}".format(i + 1)
        if name == face_name or not _is_cylinder(f) or not _same_axis(ref, _axis_of(f), LINEAR_TOLERANCE):
            continue
        s0, s1 = _axial_range(f, ref[0], ref[1])
        if s1 >= t0 - LINEAR_TOLERANCE and s0 <= t1 + LINEAR_TOLERANCE and _is_concave(f):
            names.append(name)
    return sorted(names, key=lambda n: int(n[4:]))


def face_of_edge(shape, edge_name):
    """The cylindrical hole face a circular edge bounds."""
    edge = shape.getElement(edge_name)
    if not isinstance(edge, Part.Edge):
        raise HoleError("{} is not an edge".format(edge_name))
    for f in shape.ancestorsOfType(edge, Part.Face):
        if _is_cylinder(f) and _is_concave(f):
            return _face_name(shape, f)
    raise HoleError("{} is not the edge of a hole".format(edge_name))


def _neighbours_at(shape, faces, centre, axis, t_end, depth):
    """Faces touching the hole faces at the end t_end of the hole (its entry or exit)."""
    out = []
    for face in faces:
        for e in face.Edges:
            if isinstance(e.Curve, Part.Line):
                continue  # the seam
            mid = e.valueAt(0.5 * (e.FirstParameter + e.LastParameter))
            if abs((mid - centre).dot(axis) - t_end) > 0.25 * max(depth, 1e-6) + 2 * LINEAR_TOLERANCE:
                continue
            for f in shape.ancestorsOfType(e, Part.Face):
                if not any(f.isSame(h) for h in faces) and not any(f.isSame(o) for o in out):
                    out.append(f)
    return out


def _meet(faces, point, direction, reach, rim):
    """Where the line through point along direction meets the surface of one of faces, nearest
    to point: (point, face), or (None, None). The hole itself is cut out of the face, so the
    line meets the face's untrimmed surface; the point must lie within `rim` of the face (on the
    hole's rim)."""
    line = Part.LineSegment(point + direction * reach, point - direction * reach)
    best = None
    for f in faces:
        try:
            points, _ = line.intersectCS(f.Surface)
        except (Part.OCCError, RuntimeError):
            continue
        for q in points:
            p = FreeCAD.Vector(q.X, q.Y, q.Z)
            gap = (p - point).Length
            if best is not None and gap >= best[0]:
                continue
            if Part.Vertex(p).distToShape(f)[0] <= rim:
                best = (gap, p, f)
    return (best[1], best[2]) if best else (None, None)


def normal_at(face, point, outward):
    """The unit normal of face at (the projection of) point, turned to agree with outward."""
    u, v = face.Surface.parameter(point)
    n = face.normalAt(u, v)
    if n.dot(outward) < 0:
        n = n * -1.0
    return n.normalize()


def hole(shape, face_name, surface_faces=None, up=(0.0, 0.0, 1.0)):
    """The hole made by face_name (and its half-cylinder partners) as a dict:
        faces      names of its cylindrical faces
        diameter   mm
        entry      where its axis meets the surface it is drilled from
        normal     unit surface normal there, pointing out of the part
        axis       unit hole axis pointing out of the hole at the entry
        depth      length of the hole along its axis
        solid      index of the solid (part segment) it is in
        surface    name of the face its normal was taken from
    surface_faces: names of the faces used for normals; else the faces round the hole's end
    that faces `up` most."""
    names = hole_faces(shape, face_name)
    faces = [shape.getElement(n) for n in names]
    centre, axis, radius = _axis_of(faces[0])
    t0, t1 = None, None
    for f in faces:
        a, b = _axial_range(f, centre, axis)
        t0 = a if t0 is None else min(t0, a)
        t1 = b if t1 is None else max(t1, b)
    depth = t1 - t0
    ends = [(t1, axis), (t0, axis * -1.0)]  # (axial position, outward direction)
    if surface_faces:
        surface = [shape.getElement(n) for n in surface_faces]
        scored = []
        for t, out in ends:
            p, f = _meet(surface, centre + axis * t, out, depth + 2 * radius + 1.0, radius + 0.01)
            if p is not None:
                scored.append(((p - (centre + axis * t)).Length, t, out, p, f))
        if not scored:
            raise HoleError("hole {} does not open onto the surface for normals ({})".format(
                face_name, ", ".join(surface_faces)))
        _, t, out, entry, sface = min(scored, key=lambda s: s[0])
    else:
        upv = _vec(up)
        t, out = max(ends, key=lambda e: e[1].dot(upv))
        around = _neighbours_at(shape, faces, centre, axis, t, depth)
        entry, sface = _meet(around, centre + axis * t, out, 2 * radius + 1.0, radius + 0.01)
        if entry is None:  # nothing to meet (an open end): the axis point at the end
            entry, sface = centre + axis * t, None
    normal = normal_at(sface, entry, out) if sface is not None else FreeCAD.Vector(out)
    return {
        "faces": names,
        "diameter": 2.0 * radius,
        "entry": FreeCAD.Vector(entry),
        "normal": normal,
        "axis": FreeCAD.Vector(out),
        "depth": depth,
        "solid": _solid_index(shape, faces[0]),
        "surface": _face_name(shape, sface) if sface is not None else "",
    }


def find_holes(shape, max_diameter=None, surface_faces=None, up=(0.0, 0.0, 1.0)):
    """Every hole of the shape (up to max_diameter when given), one dict per hole as hole()
    gives it, in face order."""
    seen = set()
    out = []
    for i, f in enumerate(shape.Faces):
        name = "Face{}".format(i + 1)
        if name in seen or not _is_cylinder(f) or not _is_concave(f):
            continue
        if max_diameter is not None and 2.0 * f.Surface.Radius > max_diameter + LINEAR_TOLERANCE:
            continue
        # A cylinder that is not closed round its axis (a fillet, a slot end) is not a hole.
        names = hole_faces(shape, name)
        seen.update(names)
        if _angular_span(shape, names) < 2 * math.pi - 1e-3:
            continue
        try:
            out.append(hole(shape, name, surface_faces, up))
        except HoleError:
            continue  # not on the surface for normals
    return out


def _angular_span(shape, names):
    total = 0.0
    for n in names:
        u0, u1, _, _ = shape.getElement(n).ParameterRange
        total += u1 - u0
    return total


def selected_hole_faces(shape, sub_names):
    """The hole faces named by a selection of faces and circular edges (duplicates removed, in
    selection order); raises HoleError naming the first element that is no hole."""
    out = []
    for sub in sub_names:
        if sub.startswith("Edge"):
            name = face_of_edge(shape, sub)
        elif sub.startswith("Face"):
            name = sub
        else:
            raise HoleError("{} is neither a face nor an edge of a hole".format(sub))
        main = hole_faces(shape, name)[0]
        if main not in out:
            out.append(main)
    return out


def element_hole_face(element):
    """(part, face name) of a hole element of a Machining Features tree: the cylindrical wall
    of its drilled diameter (HoleDiameter), else its first hole wall. The element's face lists
    are sorted by number, so their first face can be a floor, a chamfer or a counterbore;
    raises HoleError when the element has no hole wall."""
    if getattr(element, "ElementType", None) != "hole":
        raise HoleError("{} is not a hole element".format(getattr(element, "Label", element)))
    diameter = float(getattr(element, "HoleDiameter", 0.0))
    walls = []
    for prop in ("WallFaces", "Faces"):
        for part, names in getattr(element, prop, None) or []:
            shape = part.Shape
            for n in names:
                f = shape.getElement(n) if n.startswith("Face") else None
                if f is not None and _is_cylinder(f) and _is_concave(f) and (part, n) not in walls:
                    walls.append((part, n))
    if not walls:
        raise HoleError("hole element {} has no cylindrical hole wall".format(element.Label))
    for part, n in walls:
        if abs(2.0 * part.Shape.getElement(n).Surface.Radius - diameter) <= 1e-3:
            return part, n
    return walls[0]
