"""LinuxCNC's own interpreter reads the LinuxCNC dialect: zero errors, and the positions it
interprets, run through AeroNC's forward kinematics, are the tool tips and axes the job asked
for. Plain python3 with the installed addon on the path (no FreeCAD needed):

    AERONC_MOD_DIR=build/stage/AeroNC python3 tests/post/rs274_check.py [rs274]

Exit 0: pass; 1: failure; 77: rs274 is not installed (package linuxcnc-uspace).
"""
import math
import os
import random
import re
import shutil
import subprocess
import sys
import tempfile

SKIP = 77
TIP_TOL = 2e-3    # mm: rs274 prints 4 decimals, the post writes 4 here
AXIS_TOL = 2e-5   # rad


def axis_at(polar, azimuth):
    p, a = math.radians(polar), math.radians(azimuth)
    return (math.sin(p) * math.cos(a), math.sin(p) * math.sin(a), math.cos(p))


class Job:
    """FreeCAD-style Path text (F in mm/s, tool axis as U V W) and the poses it asks for."""

    def __init__(self):
        self.lines, self.poses = [], []

    def move(self, g, tip, axis=None, feed=20):
        words = [g] + (["F%g" % feed] if g != "G0" else [])
        if axis:
            words += ["U%.9f" % axis[0], "V%.9f" % axis[1], "W%.9f" % axis[2]]
        words += ["X%.6f" % tip[0], "Y%.6f" % tip[1], "Z%.6f" % tip[2]]
        self.lines.append(" ".join(words))
        self.poses.append((tip, axis or self._last_axis()))

    def _last_axis(self):
        return self.poses[-1][1] if self.poses else (0.0, 0.0, 1.0)

    def raw(self, line, pose=None):
        self.lines.append(line)
        if pose:
            self.poses.append(pose)


def build_job():
    rng = random.Random(3)
    ops = []
    # A FreeCAD-like 3-axis profile with arcs (no tool axis words at all).
    j = Job()
    j.raw("G0 Z15.000000")
    j.move("G0", (10, 0, 15))
    j.move("G1", (10, 0, -2))
    j.raw("G2 F10 I-10.000000 J0.000000 K0.000000 X-10.000000 Y0.000000 Z-2.000000", ((-10, 0, -2), (0, 0, 1)))
    j.raw("G3 F10 I5.000000 J0.000000 X0.000000 Y0.000000 Z-3.000000", ((0, 0, -3), (0, 0, 1)))
    j.move("G0", (0, 0, 15))
    ops.append(("Profile", j))
    # Simultaneous 5-axis: random poses, through the pole, three turns (C unwinds).
    j = Job()
    for i in range(120):
        j.move("G0" if i % 20 == 0 else "G1", (rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-20, 20)),
               axis_at(rng.uniform(0, 105), rng.uniform(-180, 180)))
    for k in range(-30, 31, 3):
        j.move("G1", (k, 4, 12), axis_at(abs(k), 210 if k < 0 else 30))
    for k in range(0, 3 * 36 + 1):
        az = 10.0 * k
        j.move("G1", (30 * math.cos(math.radians(az)), 30 * math.sin(math.radians(az)), 5), axis_at(35, az))
    ops.append(("Swarf", j))
    # 3+2 on a tilted face with an arc in that plane.
    j = Job()
    u = axis_at(30, 60)
    e1 = (u[1], -u[0], 0.0)
    n1 = math.hypot(*e1)
    e1 = tuple(c / n1 for c in e1)
    e2 = (u[1] * e1[2] - u[2] * e1[1], u[2] * e1[0] - u[0] * e1[2], u[0] * e1[1] - u[1] * e1[0])
    at = lambda a, b, h: tuple(5 + a * x + b * y + h * z for x, y, z in zip(e1, e2, u))
    j.move("G0", at(0, -20, 20), u)
    j.move("G1", at(0, -20, 0), u)
    j.move("G1", at(20, -20, 0), u)
    start, end, centre = at(20, -20, 0), at(40, 0, -1), at(20, 0, 0)
    off = tuple(c - s for c, s in zip(centre, start))
    j.raw("G3 F10 I%.9f J%.9f K%.9f X%.9f Y%.9f Z%.9f" % (off + end), (end, u))
    j.move("G0", at(40, 0, 30), u)
    ops.append(("TiltedPocket", j))
    # Drilling normal to a surface, each cycle kind.
    j = Job()
    j.raw("G99")
    for h, g in enumerate(("G81", "G82", "G83", "G73")):
        a = axis_at(15.0 * h, 80.0 * h)
        bottom = (15.0 * h - 20, -10.0 + 5 * h, -4.0)
        j.move("G0", tuple(b + 25 * c for b, c in zip(bottom, a)), a)
        extra = {"G81": "", "G82": " P0.5", "G83": " Q2", "G73": " Q1.5"}[g]
        j.raw("%s F2 U%.9f V%.9f W%.9f X%.6f Y%.6f Z%.6f R%.6f%s" % ((g,) + a + bottom + (bottom[2] + 10,) + (extra,)),
              (bottom, a))
    j.raw("G80")
    ops.append(("NormalDrilling", j))
    return ops


def sections(ops):
    out = [{"kind": "offset", "label": "G54", "gcode": "G54\nG0 Z60.000000\n"},
           {"kind": "tool", "label": "TC", "tool": {"number": 3, "name": "EM10", "diameter": 10}, "rpm": 12000,
            "spindle_dir": 1}]
    for label, j in ops:
        out.append({"kind": "operation", "label": label, "gcode": "\n".join(j.lines) + "\n", "coolant": "flood"})
    return out


def canonical_positions(text):
    """(x, y, z, a, c, kind) at the end of every canonical motion rs274 interpreted."""
    out = []
    for line in text.splitlines():
        m = re.search(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED|ARC_FEED)\((.*)\)", line)
        if not m:
            continue
        v = [float(x) for x in m.group(2).split(",")]
        if m.group(1) == "ARC_FEED":  # first_end, second_end, centre x, centre y, rotation, axis_end, a, b, c
            out.append((v[0], v[1], v[5], v[6], v[8], "arc"))
        else:
            out.append((v[0], v[1], v[2], v[3], v[5], "rapid" if m.group(1) == "STRAIGHT_TRAVERSE" else "feed"))
    return out


def main():
    mod = os.environ.get("AERONC_MOD_DIR")
    if mod:
        sys.path.insert(0, mod)
    rs274 = sys.argv[1] if len(sys.argv) > 1 else shutil.which("rs274")
    if not rs274 or not os.path.exists(rs274):
        print("SKIP: rs274 not found (Debian package linuxcnc-uspace)")
        return SKIP
    from aeronc import _core
    from aeronc.post import machines, nc_post

    ops = build_job()
    machine_json, _ = machines.load("AC-5AX")
    failures = 0
    work = tempfile.mkdtemp(prefix="aeronc_rs274_")
    with open(os.path.join(work, "tools.tbl"), "w") as f:
        f.write("T3 P3 D10.0 Z0.0 ;EM10\n")
    for args in ("--precision 4 --angle-precision 4", "--precision 4 --angle-precision 4 --no-inverse-time --line-numbers"):
        text, summary = nc_post.post_sections(sections(ops), args, "linuxcnc", None, "RS274")
        program = os.path.join(work, "job.ngc")
        with open(program, "w") as f:
            f.write(text)
        run = subprocess.run([rs274, "-t", os.path.join(work, "tools.tbl"), "-g", program],
                             capture_output=True, text=True, timeout=300)
        errors = [l for l in run.stderr.splitlines() if l.strip() and l.strip() != "executing"]
        print("{}: rs274 exit {}, {} NC lines, {} branch changes".format(
            args, run.returncode, summary["lines"], summary["branch_changes"]))
        if run.returncode != 0 or errors:
            print("FAIL: rs274 reported:\n" + "\n".join(errors[:10]))
            failures += 1
            continue
        # Every pose of the job, in order, among the positions rs274 interpreted.
        moves = canonical_positions(run.stdout)
        j = 0
        expected = [p for _, job in ops for p in job.poses]
        for i, (tip, axis) in enumerate(expected):
            while j < len(moves):
                x, y, z, a, c, _ = moves[j]
                got_tip, got_axis = _core.forward_kinematics(machine_json, [x, y, z], [a, c], None, 0.0)
                d = math.dist(got_tip, tip)
                n = math.sqrt(sum(k * k for k in axis))
                cos = sum(p * q / n for p, q in zip(got_axis, axis))
                if d < TIP_TOL and math.acos(max(-1.0, min(1.0, cos))) < AXIS_TOL:
                    break
                j += 1
            if j >= len(moves):
                print("FAIL: pose {} {} not among rs274's positions".format(i, (tip, axis)))
                failures += 1
                break
            j += 1
        else:
            print("  all {} poses found in order among {} interpreted moves".format(len(expected), len(moves)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
