"""Test-only readback of posted NC programs, apart from the posts' own formatting code.

It interprets the 840D and LinuxCNC text the way the controller would (modal words,
CYCLE800 frames, TRAORI, drilling cycles) and runs the machine positions through the forward
kinematics of the core, giving the tool tip and axis at the end of every move in the
workpiece frame. Also: building oriented Path objects, and comparing poses."""
import math
import re

import FreeCAD
import Path

TIP_TOL = 1e-6   # mm
AXIS_TOL = 1e-9  # rad


def angle_between(a, b):
    cx = a[1] * b[2] - a[2] * b[1]
    cy = a[2] * b[0] - a[0] * b[2]
    cz = a[0] * b[1] - a[1] * b[0]
    return math.atan2(math.sqrt(cx * cx + cy * cy + cz * cz), a[0] * b[0] + a[1] * b[1] + a[2] * b[2])


def dist(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def normalised(v):
    n = math.sqrt(sum(c * c for c in v))
    return tuple(c / n for c in v)


def axis_at(polar_deg, azimuth_deg):
    p, a = math.radians(polar_deg), math.radians(azimuth_deg)
    return (math.sin(p) * math.cos(a), math.sin(p) * math.sin(a), math.cos(p))


def stored(v):
    """A value as FreeCAD keeps it in a Path (6 decimals, as saved with the document)."""
    return float("%.6f" % v)


class OrientedPath:
    """Commands with a tool axis (U V W), and the poses the post must reproduce: the tip and
    the axis as FreeCAD stores them (6 decimals), the axis normalised."""

    def __init__(self):
        self.commands = []
        self.poses = []

    def move(self, name, tip, axis, feed=20.0):
        u = tuple(stored(c) for c in normalised(axis))
        t = tuple(stored(c) for c in tip)
        p = {"X": t[0], "Y": t[1], "Z": t[2], "U": u[0], "V": u[1], "W": u[2]}
        if name != "G0":
            p["F"] = feed
        self.commands.append(Path.Command(name, p))
        self.poses.append((t, normalised(u)))

    def drill(self, name, bottom, axis, retract, feed=2.0, peck=None):
        u = tuple(stored(c) for c in normalised(axis))
        b = tuple(stored(c) for c in bottom)
        p = {"X": b[0], "Y": b[1], "Z": b[2], "R": stored(b[2] + retract), "U": u[0], "V": u[1], "W": u[2], "F": feed}
        if peck:
            p["Q"] = peck
        self.commands.append(Path.Command(name, p))
        self.poses.append((b, normalised(u)))

    def raw(self, text):
        self.commands.append(Path.Command(text))


def add_operation(doc, job, label, commands, tool_controller):
    """A Path object standing for one of AeroNC's oriented operations, in the Job."""
    op = doc.addObject("Path::FeaturePython", label)
    op.Label = label
    op.addProperty("App::PropertyLink", "ToolController", "Path")
    op.addProperty("App::PropertyBool", "Active", "Path")
    op.addProperty("App::PropertyEnumeration", "CoolantMode", "Path")
    op.CoolantMode = ["None", "Flood", "Mist"]
    op.CoolantMode = "Flood"
    op.Active = True
    op.ToolController = tool_controller
    op.Path = Path.Path(commands)
    job.Operations.addObject(op)
    return op


class _Fk:
    def __init__(self, machine_json, tool_length=0.0):
        from aeronc import _core
        self.core = _core
        self.machine = machine_json
        self.length = tool_length

    def __call__(self, linear, rotary):
        return self.core.forward_kinematics(self.machine, list(linear), list(rotary), None, self.length)


def _lines(text):
    for n, raw in enumerate(text.splitlines(), 1):
        yield n, re.sub(r"^N\d+ ", "", raw)


def _rx(d):
    c, s = math.cos(math.radians(d)), math.sin(math.radians(d))
    return ((1, 0, 0), (0, c, -s), (0, s, c))


def _ry(d):
    c, s = math.cos(math.radians(d)), math.sin(math.radians(d))
    return ((c, 0, s), (0, 1, 0), (-s, 0, c))


def _rz(d):
    c, s = math.cos(math.radians(d)), math.sin(math.radians(d))
    return ((c, -s, 0), (s, c, 0), (0, 0, 1))


def _mul(a, b):
    return tuple(tuple(sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)) for i in range(3))


def _apply(m, v):
    return tuple(sum(m[i][k] * v[k] for k in range(3)) for i in range(3))


_IDENTITY = ((1, 0, 0), (0, 1, 0), (0, 0, 1))


def _add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def read_sinumerik(text, machine_json, rotary_names=("A", "C"), vectors=False, tool_length=0.0):
    """[(tip, axis, kind, line)] of an 840D program; kind: rapid, feed, arc, hole."""
    fk = _Fk(machine_json, tool_length)
    out = []
    frame, origin, traori, motion = _IDENTITY, (0.0, 0.0, 0.0), False, 0
    pos, known, rot, vec = [0.0, 0.0, 0.0], [False] * 3, [0.0, 0.0], [0.0, 0.0, 1.0]
    for n, l in _lines(text):
        l = l.split(";")[0].strip()
        if not l or l.startswith("%"):
            continue
        if l == "TRAORI" or l == "TRAFOOF":
            traori = l == "TRAORI"
            continue
        m = re.match(r"(CYCLE\d+)\((.*)\)$", l)
        if m:
            args = m.group(2).split(",") if m.group(2) else []
            if m.group(1) == "CYCLE800":
                if not args:
                    frame, origin = _IDENTITY, (0.0, 0.0, 0.0)
                else:
                    assert len(args) == 16 and float(args[3]) == 57, l
                    assert all(float(x) == 0 for x in args[10:13]), "line {}: X1 Y1 Z1 not read".format(n)
                    a, b, c = (float(x) for x in args[7:10])
                    frame = _mul(_mul(_rx(a), _ry(b)), _rz(c))
                    origin = tuple(float(x) for x in args[4:7])  # the point the plane turns about
                known = [False] * 3
            elif m.group(1) in ("CYCLE81", "CYCLE82", "CYCLE83"):
                assert not traori and known[0] and known[1], "line {}: drilling without a position".format(n)
                rtp, rfp, dp = float(args[0]), float(args[1]), float(args[3])
                assert rtp >= rfp > dp, "line {}: cycle levels out of order".format(n)
                out.append((_add(origin, _apply(frame, (pos[0], pos[1], dp))), _apply(frame, (0, 0, 1)), "hole", n))
                pos[2], known[2] = rtp, True
            continue
        moved = False
        for w in l.split():
            if w in ("G0", "G1", "G2", "G3"):
                motion = int(w[1])
            elif re.match(r"[ABC]3=", w):
                vec["ABC".index(w[0])] = float(w[3:])
                moved = True
            elif w[0] in "XYZ":
                pos["XYZ".index(w[0])] = float(w[1:])
                known["XYZ".index(w[0])] = True
                moved = True
            elif w[0] in rotary_names and re.match(r"[A-Z]-?[\d.]", w):
                rot[rotary_names.index(w[0])] = float(w[1:])
                moved = True
            elif w[0] in "GMSTDFIJK" or w.startswith('T="'):
                continue
            else:
                raise AssertionError("line {}: unknown word {}".format(n, w))
        if not moved or not all(known):
            continue
        kind = ("rapid", "feed", "arc", "arc")[motion]
        if traori:
            assert motion < 2, "line {}: arc under TRAORI".format(n)
            axis = normalised(vec) if vectors else fk((0, 0, 0), rot)[1]
            out.append((tuple(pos), tuple(axis), kind, n))
        else:
            out.append((_add(origin, _apply(frame, pos)), _apply(frame, (0, 0, 1)), kind, n))
    return out


def read_linuxcnc(text, machine_json, rotary_names=("A", "C")):
    """[(tip, axis, kind, line, (a, c))] of a LinuxCNC program (machine coordinates -> FK)."""
    fk = _Fk(machine_json)
    out = []
    pos, known, rot, motion, old_z = [0.0, 0.0, 0.0], [False] * 3, [0.0, 0.0], 0, True
    for n, l in _lines(text):
        l = re.sub(r"\([^)]*\)", "", l).strip()
        words = re.findall(r"([A-Z])\s*([-+]?[\d.]+)", l.upper())
        moved, r = False, None
        z_before = pos[2]
        for letter, value in words:
            v = float(value)
            if letter == "G":
                if v in (0, 1, 2, 3, 73, 81, 82, 83):
                    motion = int(v)
                elif v == 80:
                    motion = -1
                elif v in (98, 99):
                    old_z = v == 98
            elif letter in "XYZ":
                pos["XYZ".index(letter)] = v
                known["XYZ".index(letter)] = True
                moved = True
            elif letter in rotary_names:
                rot[rotary_names.index(letter)] = v
                moved = True
            elif letter == "R":
                r = v
        if not moved or not all(known):
            continue
        if motion >= 73:
            tip, axis = fk(pos, rot)
            out.append((tuple(tip), tuple(axis), "hole", n, tuple(rot)))
            pos[2] = max(z_before, r) if old_z else r
            continue
        tip, axis = fk(pos, rot)
        out.append((tuple(tip), tuple(axis), ("rapid", "feed", "arc", "arc")[motion], n, tuple(rot)))
    return out


def match_in_order(test, expected, read, extras):
    """Every expected pose appears, in order, among the read-back ones, within 1e-6 mm and
    1e-9 rad; at most `extras` read-back poses are additions of the post."""
    j = skipped = 0
    for i, (tip, axis) in enumerate(expected):
        while j < len(read) and not (dist(read[j][0], tip) < TIP_TOL and angle_between(read[j][1], axis) < AXIS_TOL):
            j += 1
            skipped += 1
        test.assertLess(j, len(read), "input pose {} ({}, {}) not found in the posted program".format(i, tip, axis))
        j += 1
    skipped += len(read) - j
    test.assertLessEqual(skipped, extras)
