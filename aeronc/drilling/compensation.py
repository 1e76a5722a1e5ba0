"""Datum holes and compensation, App side (drilling seed; docs/compensation.md).

  camera_program(photo_set, apt_path, nc_path)   the camera program, APT and NC
  datum_frames(photo_set)                        each datum hole's transform chain
  read_measurement_file(path)                    the camera's file as text (clear errors)
  synthetic_measurements(photo_set, moved)       a camera file for holes moved by `moved`
  compensate(measured_set, holes, method)        the core's compensation of holes

The transform chain of a picture (camera -> tool mount -> machine -> assembly -> part):
  mount_from_camera      calibrated, from the machine file's "camera" section
  machine_from_mount     the tool mount where the camera program put it for that hole
  assembly_from_machine  calibrated, from the machine file's "camera" section
  part_from_assembly     the part's placement in the document, inverted
"""
import FreeCAD

from aeronc.drilling import camera_program as cp
from aeronc.drilling import hole_pattern
from aeronc.errors import CompensationError


def _matrix(rows):
    m = FreeCAD.Matrix()
    m.A = [float(v) for r in rows for v in r]
    return m


def _rows(m):
    a = m.A
    return [list(a[4 * i:4 * i + 4]) for i in range(4)]


def _rigid_inverse(rows):
    r = [[rows[j][i] for j in range(3)] for i in range(3)]
    t = [-sum(r[i][k] * rows[k][3] for k in range(3)) for i in range(3)]
    return [r[0] + [t[0]], r[1] + [t[1]], r[2] + [t[2]], [0.0, 0.0, 0.0, 1.0]]


def _mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def camera_of(photo_set):
    try:
        return cp.camera_of(photo_set.Machine or cp.DEFAULT_MACHINE)
    except cp.CameraError as e:
        raise CompensationError(str(e)) from None
    except Exception as e:  # an unknown machine (PostError)
        raise CompensationError(str(e)) from None


def poses(photo_set, camera=None):
    """The camera pose of every datum hole of the set, in order (camera_program.camera_poses)."""
    camera = camera or camera_of(photo_set)
    if photo_set.Source is None:
        raise CompensationError("{} has no source part".format(photo_set.Label))
    try:
        return cp.camera_poses(hole_pattern.holes_of(photo_set), camera, photo_set.Standoff.Value, photo_set.Approach.Value,
                               photo_set.SafeHeight.Value, hole_pattern.assembly_from_part(photo_set.Source))
    except cp.CameraError as e:
        raise CompensationError(str(e)) from None


def datum_frames(photo_set):
    """[{id, nominal, normal, chain}] for the core's import: nominal and normal in the part frame,
    chain the four 4x4s (row lists) of each datum hole's picture."""
    camera = camera_of(photo_set)
    machine_from_assembly = _rigid_inverse(camera["assembly_from_machine"])
    part_from_assembly = _rows(photo_set.Source.Placement.toMatrix().inverse())
    out = []
    for h, pose in zip(hole_pattern.holes_of(photo_set), poses(photo_set, camera)):
        out.append({"id": h["id"], "nominal": list(h["position"]), "normal": list(h["normal"]),
                    "chain": {"mount_from_camera": camera["mount_from_camera"],
                              "machine_from_mount": _mul(machine_from_assembly, pose["mount"]),
                              "assembly_from_machine": camera["assembly_from_machine"],
                              "part_from_assembly": part_from_assembly}})
    return out


def camera_program(photo_set, apt_path=None, nc_path=None, argstring="", dialect="840d"):
    """(APT text, NC text) of the set's camera program; each written when a path is given."""
    camera = camera_of(photo_set)
    if len(photo_set.HoleIds) == 0:
        raise CompensationError("{} has no datum holes".format(photo_set.Label))
    secs = cp.sections(poses(photo_set, camera), camera, "Datum holes of {}".format(photo_set.Label),
                       photo_set.Feed.Value, photo_set.Dwell)
    import os
    name = os.path.splitext(os.path.basename(nc_path or apt_path or "CAMERA"))[0].upper() or "CAMERA"
    return cp.write_programs(secs, camera, apt_path, nc_path, argstring, dialect, name)


def read_measurement_file(path):
    """The text of a measurement file; a missing or unreadable file gets a clear message."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise CompensationError("cannot read the measurement file {}: {}".format(path, e.strerror or e)) from None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        raise CompensationError("the measurement file {} is not UTF-8 text".format(path)) from None


def import_readings(photo_set, text, max_deviation=5.0, min_quality=0.0):
    """The core's import of a camera file for the set: [{id, u, v, height, quality, line,
    nominal, measured, deviation}] in the set's order. Raises CompensationError."""
    from aeronc import _core
    try:
        return _core.import_measurements(text, datum_frames(photo_set), max_deviation, min_quality)
    except _core.CompensationError as e:
        raise CompensationError(str(e)) from None


def synthetic_measurements(photo_set, moved, quality=0.95, decimals=6):
    """A camera file of the set's datum holes as the camera would see them if the part had
    moved every point p (part frame, a tuple) to moved(p)."""
    from aeronc import _core
    lines = ["# AeroNC measured datum holes: hole id, U and V in the camera frame, camera height, quality",
             "hole,u,v,height,quality"]
    fmt = "{},{:.%df},{:.%df},{:.%df},{:.3f}" % (decimals, decimals, decimals)
    for f in datum_frames(photo_set):
        u, v, h = _core.part_to_camera(f["chain"], list(moved(tuple(f["nominal"]))))
        lines.append(fmt.format(f["id"], u, v, h, quality))
    return "\n".join(lines) + "\n"


def datums_of(measured_set):
    """The measured datum holes of a measured-hole set for the core: [{id, nominal, measured,
    normal}]; the normal (the camera's axis, from the photo-hole set) is None when not known."""
    ps = getattr(measured_set, "PhotoHoleSet", None)
    normals = dict(zip(ps.HoleIds, ps.Normals)) if ps is not None and len(ps.Normals) == len(ps.HoleIds) else {}
    out = []
    for i, n, m in zip(measured_set.HoleIds, measured_set.Nominal, measured_set.Measured):
        a = normals.get(i)
        out.append({"id": i, "nominal": (n.x, n.y, n.z), "measured": (m.x, m.y, m.z),
                    "normal": (a.x, a.y, a.z) if a is not None else None})
    return out


def _key(p):
    return (round(p[0], 3), round(p[1], 3), round(p[2], 3))


def assign_rows(photo_set, items, field):
    """Give every item (dicts with a position under `field`) the row and station of its hole in
    the photo-hole set's pattern (drawn by hand or found), so that the seed's method sees the
    part's rows whichever holes are compensated. A hole that is not in the pattern gets a row of
    its own."""
    pattern = [(p.x, p.y, p.z) for p in photo_set.PatternPositions] if photo_set is not None else []
    if not pattern:
        return items
    faces = [f.split()[0] for f in photo_set.PatternFaces]
    rows, stations, members = hole_pattern.pattern_rows(photo_set, pattern, faces)
    where = {_key(p): (r, s) for p, r, s in zip(pattern, rows, stations)}
    spare = len(members)
    for it in items:
        p = tuple(it[field])
        found = where.get(_key(p))
        if found is None:
            near = min(range(len(pattern)), key=lambda i: sum((a - b) ** 2 for a, b in zip(pattern[i], p)))
            if sum((a - b) ** 2 for a, b in zip(pattern[near], p)) < 1e-6:
                found = (rows[near], stations[near])
        if found is None:
            found, spare = (spare, 0.0), spare + 1
        it["row"], it["station"] = found
    return items


def check_options(measured_set):
    """The datum check's settings of a measured-hole set, for the core."""
    return {"enabled": bool(measured_set.DatumCheck), "factor": float(measured_set.OutOfLineFactor),
            "minimum": float(measured_set.OutOfLineMinimum.Value)}


def compensate(measured_set, holes, method=None, tolerance=None):
    """The core's compensation of holes ([{id, position, normal}], part frame) from the
    measured set, by `method` (default: the set's Method; "proposed" = lowest leave-one-out).
    Rows (for the seed's method) are those of the photo-hole set's hole pattern. Datum readings
    out of line with the others are left out unless the set puts them back (PutBack); those
    the set leaves out by hand (LeftOutByHand) are never used."""
    from aeronc import _core
    if method is None:
        method = measured_set.Method
    if tolerance is None:
        tolerance = measured_set.Tolerance.Value
    ps = measured_set.PhotoHoleSet
    datums = assign_rows(ps, datums_of(measured_set), "nominal")
    holes = assign_rows(ps, [dict(h) for h in holes], "position")
    try:
        return _core.compensate(datums, holes, "" if method == "proposed" else method, tolerance,
                                measured_set.NeighbourTolerance.Value, list(measured_set.PutBack),
                                list(measured_set.LeftOutByHand), check_options(measured_set))
    except _core.CompensationError as e:
        raise CompensationError(str(e)) from None
