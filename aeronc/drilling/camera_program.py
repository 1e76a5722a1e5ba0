"""The camera program of a photo-hole set (drilling seed, section 2.1): for each datum hole in
the set's order, the camera (a tool with its own offset on the head's tool mount) goes to the
safe height, down to an approach point on the hole's normal, to the camera position `standoff`
above the hole with its axis normal to the surface, takes the picture (a dwell) and leaves the
way it came.

Written in two forms from the same Path commands (AeroNC's U V W tool-axis convention):
  APT CL    GOTO/x,y,z,i,j,k in the workpiece (assembly) frame, by the APT writer of the posts
  NC        through the 5-axis post for the camera machine (AC-HEAD by default)

The poses also fix the tool-mount frame of each picture, the `machine_from_mount` link of the
transform chain (aeronc.drilling.compensation): the gauge point `length` above the camera position and
the head's orientation, chosen as the post chooses it (the solution moving least from the
previous hole's, from 0, 0).
"""
import json
import math

from aeronc.errors import CameraError
from aeronc.post import machines
from aeronc.post.output import write_atomically

DEFAULT_MACHINE = "AC-HEAD"


def _matrix(rows, name, source):
    from aeronc import _core
    try:
        m = [[float(v) for v in r] for r in rows]
        if len(m) != 4 or any(len(r) != 4 for r in m):
            raise ValueError
    except (TypeError, ValueError):
        raise CameraError("{}: camera.{} must be a 4x4 matrix (four rows of four numbers)".format(source, name))
    try:
        _core.check_rigid(m, "camera.{} of {}".format(name, source))
    except _core.CompensationError as e:
        raise CameraError(str(e)) from None
    return m


def camera_of(machine_name=DEFAULT_MACHINE):
    """The camera calibration stored with the machine file: dict with machine_json, source,
    tool_number, name, standoff, length (gauge point to camera, the tool offset),
    mount_from_camera and assembly_from_machine (4x4 row lists)."""
    text, source = machines.load(machine_name)
    m = json.loads(text)
    cam = m.get("camera")
    if not isinstance(cam, dict):
        raise CameraError("machine {} ({}) has no camera calibration: add a \"camera\" section "
                          "(docs/compensation.md)".format(machine_name, source))
    if any(a.get("carrier") != "head" for a in m.get("rotaryAxes", [])):
        raise CameraError("machine {} is not a head machine: the camera rides on the head's tool mount".format(
            machine_name))
    mount = _matrix(cam.get("mountFromCamera"), "mountFromCamera", source)
    assembly = _matrix(cam.get("assemblyFromMachine", [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]),
                       "assemblyFromMachine", source)
    length = -mount[2][3]
    if not length > 0:
        raise CameraError("{}: the camera must sit below the gauge point (mountFromCamera z offset negative)".format(
            source))
    return {"machine": m, "machine_json": text, "source": source, "tool_number": int(cam.get("toolNumber", 20)),
            "name": str(cam.get("name", "Camera")), "standoff": float(cam.get("standoff", 60.0)), "length": length,
            "mount_from_camera": mount, "assembly_from_machine": assembly}


def _rotation(direction, degrees):
    """3x3 rotation (row lists) about a unit direction, right-handed."""
    x, y, z = direction
    n = math.sqrt(x * x + y * y + z * z)
    x, y, z = x / n, y / n, z / n
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    t = 1 - c
    return [[t * x * x + c, t * x * y - s * z, t * x * z + s * y],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c]]


def _mul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]


def _apply(m, v):
    return [sum(m[i][k] * v[k] for k in range(3)) for i in range(3)]


def head_orientation(machine, angles):
    """The head's rotation for rotary angles (degrees, machine order): the first axis carries
    the second, each turning right-handed about its direction."""
    axes = machine["rotaryAxes"]
    return _mul(_rotation(axes[0]["direction"], angles[0]), _rotation(axes[1]["direction"], angles[1]))


def _wind(angle, previous, low, high):
    """The 360-degree equivalent of angle nearest previous within [low, high] (None if none),
    as the posts wind it (RotaryChoice.cpp)."""
    slack = 1e-9
    kmin = math.ceil((low - slack - angle) / 360.0)
    kmax = math.floor((high + slack - angle) / 360.0)
    if kmin > kmax:
        return None
    return angle + 360.0 * min(max(round((previous - angle) / 360.0), kmin), kmax)


def head_angles(machine_json, machine, axis, previous):
    """The rotary angles the posts choose for a tool axis: of the inverse kinematics' solutions
    wound within the limits, the first that moves least from `previous`."""
    from aeronc import _core
    best, cost = None, math.inf
    for s in _core.inverse_kinematics(machine_json, list(axis), list(previous)):
        wound = [_wind(a, p, ax["min"], ax["max"]) for a, p, ax in zip(s, previous, machine["rotaryAxes"])]
        if None in wound:
            continue
        c = sum(abs(w - p) for w, p in zip(wound, previous))
        if c < cost:
            best, cost = wound, c
    if best is None:
        raise CameraError("the camera axis {} is out of the reach of machine {}".format(
            tuple(round(c, 4) for c in axis), machine["name"]))
    return best


def _sub(a, b):
    return [a[i] - b[i] for i in range(3)]


def _add(a, b, k=1.0):
    return [a[i] + k * b[i] for i in range(3)]


def camera_poses(holes, camera, standoff, approach, safe_z, assembly_from_part=None):
    """One pose per datum hole, in order. holes: dicts with id, position and normal in the part
    frame. Returns dicts: id, entry and normal (assembly frame), tip (camera position), approach,
    safe (points), angles (head), mount (4x4 of the tool mount in the assembly frame)."""
    from aeronc import _core
    m = camera["machine"]
    poses = []
    previous = [0.0, 0.0]
    for h in holes:
        p, n = list(h["position"]), list(h["normal"])
        if assembly_from_part is not None:
            p, n = assembly_from_part(p, n)
        length = math.sqrt(sum(c * c for c in n))
        n = [c / length for c in n]
        tip = _add(p, n, standoff)
        near = _add(tip, n, approach)
        safe = [near[0], near[1], max(safe_z, near[2])]
        angles = head_angles(camera["machine_json"], m, n, previous)
        rot = head_orientation(m, angles)
        x_dir = _apply(rot, [1.0, 0.0, 0.0])
        mount = _core.frame_at(_add(tip, n, camera["length"]), n, x_dir)
        poses.append({"id": h["id"], "entry": p, "normal": n, "tip": tip, "approach": near, "safe": safe,
                      "angles": list(angles), "mount": [list(r) for r in mount]})
        previous = list(angles)
    return poses


def path_commands(poses, feed, dwell):
    """Path commands of the camera program (AeroNC's U V W tool axis on every move)."""
    from aeronc.pathcompat import command
    from aeronc.post.orientation import oriented_command
    cmds = []
    for p in poses:
        n = p["normal"]
        cmds.append(command("(datum hole {})".format(p["id"])))
        high = p["safe"][2] > p["approach"][2] + 1e-6  # the safe height is above the approach point
        for point in ([p["safe"]] if high else []) + [p["approach"]]:
            cmds.append(oriented_command("G0", {"X": point[0], "Y": point[1], "Z": point[2]}, n))
        cmds.append(oriented_command("G1", {"X": p["tip"][0], "Y": p["tip"][1], "Z": p["tip"][2], "F": feed}, n))
        cmds.append(command("G4", {"P": dwell}))
        for point in [p["approach"]] + ([p["safe"]] if high else []):
            cmds.append(oriented_command("G0", {"X": point[0], "Y": point[1], "Z": point[2]}, n))
    return cmds


def sections(poses, camera, label, feed, dwell):
    """The sections the posts take: the camera as a tool (its offset as the tool length), then
    the camera moves."""
    from aeronc.pathcompat import path_from_commands
    gcode = path_from_commands(path_commands(poses, feed, dwell)).toGCode()
    return [
        {"kind": "tool", "label": camera["name"],
         "tool": {"number": camera["tool_number"], "name": camera["name"], "diameter": 0.0, "corner_radius": 0.0,
                  "length": camera["length"]},
         "rpm": 0.0, "spindle_dir": 0},
        {"kind": "operation", "label": label, "gcode": gcode, "coolant": "none", "has_tool_controller": True},
    ]


def write_programs(secs, camera, apt_path=None, nc_path=None, argstring="", dialect="840d", name="CAMERA"):
    """APT and NC text of the camera program; each written (atomically) when a path is given.
    The NC is posted for the camera's machine unless argstring names another."""
    from aeronc import _core
    from aeronc.post import PostError, nc_post
    try:
        apt_text = _core.write_apt(secs, name)
    except _core.PostError as e:
        raise PostError(str(e)) from None
    args = argstring if "--machine" in (argstring or "") else "--machine {} {}".format(
        camera["machine"]["name"], argstring or "").strip()
    nc_text, _ = nc_post.post_sections(secs, args, dialect, nc_path, name)
    if apt_path:
        write_atomically(apt_path, apt_text)
    if nc_path:
        write_atomically(nc_path, nc_text)
    return apt_text, nc_text
