"""Verification of posted programs: re-read, then simulated against the blank.

A posted LinuxCNC program is re-read by LinuxCNC's own interpreter (`rs274`, Debian package
linuxcnc-uspace), an independent reading of what the machine will do. Its canonical moves
(machine coordinates) go back through the machine's forward kinematics to tool tips in the
Job's frame, then through the Job's placement to the part's frame, and every operation of every
setup runs, in program order, on one Z-dexel model of the blank (`_core.simulate`). The
report says whether any cutting move gouges the part beyond its allowance, whether any rapid
passes through material, and how much material is left on the faces the plan finishes.

An operation is recognised in the program by the "(operation: <label>)" comment the posts
write; its allowances and cutter come from the operation of that label in the Job.
"""
import json
import math
import os
import re
import shutil
import subprocess
import tempfile

from aeronc.errors import AeroNCError, from_core


class VerificationError(AeroNCError):
    """A program could not be re-read or simulated; the message says why."""


_CANON = re.compile(r"^\s*\d+\s+N\S*\s+([A-Z_]+)\((.*)\)\s*$")
_FINISHING_STEPS = ("w", "fs", "ff", "c", "e")


def rs274_path():
    path = shutil.which("rs274")
    if not path:
        raise VerificationError("LinuxCNC's rs274 interpreter is not installed (Debian package linuxcnc-uspace); "
                                "it re-reads the posted program for the verification")
    return path


def reread(program_path, tools, arc_step=0.5):
    """The program as LinuxCNC's interpreter reads it: [{"label", "tool", "moves": [[kind, x, y, z, a, c]]}]
    in machine coordinates, one entry per "(operation: ...)" comment. tools: {number: diameter}.
    Kinds: 0 rapid, 1 feed. Arcs come back as chords of at most arc_step mm."""
    work = tempfile.mkdtemp(prefix="aeronc_reread_")
    try:
        table = os.path.join(work, "tools.tbl")
        with open(table, "w") as f:
            for number, diameter in sorted(tools.items()):
                f.write("T{0} P{0} D{1:.4f} Z0.0\n".format(int(number), float(diameter)))
        # rs274 keeps its tool table in $HOME/.tool.mmap: a HOME of its own, so that no other rs274
        # (another program of this job, another job) reads or truncates this one's tools.
        run = subprocess.run([rs274_path(), "-t", table, "-g", program_path], capture_output=True, text=True,
                             timeout=600, env=dict(os.environ, HOME=work))
    finally:
        shutil.rmtree(work, ignore_errors=True)
    errors = [l for l in run.stderr.splitlines() if l.strip() and l.strip() != "executing"]
    if run.returncode != 0 or errors:
        raise VerificationError("{}: rs274 reported: {}".format(os.path.basename(program_path),
                                                             "; ".join(errors[:5]) or "exit {}".format(run.returncode)))
    ops, current, tool = [], None, None
    last = None
    for line in run.stdout.splitlines():
        m = _CANON.match(line)
        if not m:
            continue
        name, args = m.group(1), m.group(2)
        if name == "COMMENT":
            text = args.strip().strip('"')
            if text.startswith("operation: "):
                current = {"label": text[len("operation: "):], "tool": tool, "moves": []}
                ops.append(current)
        elif name == "CHANGE_TOOL":
            tool = int(float(args))
            if current is not None:
                current["tool"] = tool
        elif name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED"):
            v = [float(x) for x in args.split(",")]
            last = (v[0], v[1], v[2], v[3], v[5])
            if current is not None:
                current["moves"].append([0 if name == "STRAIGHT_TRAVERSE" else 1] + list(last))
        elif name == "ARC_FEED":
            v = [float(x) for x in args.split(",")]
            end = (v[0], v[1], v[5], v[6], v[8])
            if current is not None and last is not None:
                current["moves"].extend([1] + list(p) for p in _arc_points(last, end, (v[2], v[3]), int(v[4]),
                                                                            arc_step))
            last = end
    return ops


def _arc_points(start, end, centre, rotation, step):
    """Points along an XY arc (rotation > 0: counter-clockwise, < 0: clockwise, |n| > 1: extra turns)."""
    r = math.hypot(start[0] - centre[0], start[1] - centre[1])
    a0 = math.atan2(start[1] - centre[1], start[0] - centre[0])
    a1 = math.atan2(end[1] - centre[1], end[0] - centre[0])
    sweep = a1 - a0
    if rotation > 0:
        while sweep <= 1e-12:
            sweep += 2 * math.pi
        sweep += 2 * math.pi * (rotation - 1)
    else:
        while sweep >= -1e-12:
            sweep -= 2 * math.pi
        sweep -= 2 * math.pi * (-rotation - 1)
    n = max(1, int(math.ceil(abs(sweep) * r / step)))
    pts = []
    for k in range(1, n + 1):
        t = k / n
        a = a0 + sweep * t
        pts.append((centre[0] + r * math.cos(a), centre[1] + r * math.sin(a),
                    start[2] + (end[2] - start[2]) * t, end[3], end[4]))
    return pts


def _reread_all(paths, tools, cache=None, workers=2):
    """[(key, reread(path))] in the order of paths, the rs274 processes two at a time (each with
    its own tool table file, see reread); key: the program's text and tools, under which cache (a
    dict, or None) keeps what was read."""
    import hashlib
    from concurrent.futures import ThreadPoolExecutor
    keys = []
    for path in paths:
        with open(path, "rb") as f:
            keys.append((hashlib.sha1(f.read()).hexdigest(), tuple(sorted(tools.items()))))
    todo = {k: p for k, p in zip(keys, paths) if cache is None or k not in cache}
    with ThreadPoolExecutor(max_workers=max(1, min(workers, len(todo)))) as pool:
        done = [(k, pool.submit(reread, p, tools)) for k, p in todo.items()]
        read = {k: f.result() for k, f in done}  # the first failure, in program order, is raised
    if cache is not None:
        cache.update(read)
        read = cache
    return [(k, read[k]) for k in keys]


def machine_tips(ops, machine_json):
    """[(tool tips, last tool axis)] per operation: the forward kinematics of every move, in the
    Job's frame (the machine read once per operation)."""
    from aeronc import _core
    out = []
    for op in ops:
        joints = [[m[1], m[2], m[3], m[4], m[5]] for m in op["moves"]]
        with from_core(VerificationError, "forward kinematics of " + op["label"]):
            tips, axes = _core.forward_kinematics_many(machine_json, joints) if joints else ([], [])
        out.append((tips, axes[-1] if axes else None))
    return out


def placed(ops, tips, placement):
    """ops with their moves at the tool tips of machine_tips, carried by a FreeCAD Placement
    (the Job's frame to the part's, for one); each op's "axis" the last move's tool axis so
    carried."""
    import FreeCAD
    m = placement.toMatrix()
    a11, a12, a13, a14 = m.A11, m.A12, m.A13, m.A14
    a21, a22, a23, a24 = m.A21, m.A22, m.A23, m.A24
    a31, a32, a33, a34 = m.A31, m.A32, m.A33, m.A34
    out = []
    for op, (points, axis) in zip(ops, tips):
        moves = [[mv[0], a11 * x + a12 * y + a13 * z + a14, a21 * x + a22 * y + a23 * z + a24,
                  a31 * x + a32 * y + a33 * z + a34] for mv, (x, y, z) in zip(op["moves"], points)]
        if axis is not None:
            d = placement.Rotation.multVec(FreeCAD.Vector(*axis))
            axis = [round(d.x, 9), round(d.y, 9), round(d.z, 9)]
        out.append(dict(op, moves=moves, axis=axis or [0.0, 0.0, 1.0]))
    return out


def plunges_marked(moves):
    """Feed moves straight down the tool axis become plunges (kind 2)."""
    out = []
    prev = None
    for m in moves:
        k = m[0]
        if k == 1 and prev is not None and abs(m[1] - prev[1]) < 1e-9 and abs(m[2] - prev[2]) < 1e-9:
            k = 2
        out.append([k] + list(m[1:]))
        prev = m
    return out


def verify_programs(programs, ops_by_label, machine, chain, result, part_shape, blank, cell_size=0.5, cache=None,
                    checked=None):
    """Re-read each posted LinuxCNC program and simulate them all against the blank: (the core's
    report, the number of operations simulated). programs: [{"path", "setup", "partZero", "job",
    "frame"}] in machining order; ops_by_label: {label: (Job, operation)} of the chain's Jobs;
    blank: the part frame's box. One Z-dexel model for parts machined along +-Z only (what one
    setup removes, the next finds gone); otherwise each setup in its own frame (simulate_by_setup)."""
    import FreeCAD
    from aeronc import pathcompat
    from aeronc.operations import base as op_base
    from aeronc.pipeline import setup_job
    from aeronc.post import machines
    machine_json, _ = machines.load(machine)
    tools = {}
    for job in {id(p["job"]): p["job"] for p in programs}.values():
        for tc in pathcompat.tool_controllers(job):
            cutter = op_base.cutter_of(tc)
            if cutter:
                tools[tc.ToolNumber] = cutter["diameter"]
    sim_ops, setups = [], []
    reads = _reread_all([p["path"] for p in programs], tools, cache)
    for p, (key, read) in zip(programs, reads):
        to_part = setup_job.frame_placement(p["frame"]).inverse()
        machine_zero = json.dumps(dict(json.loads(machine_json), partZero=list(p["partZero"])))
        key = (key, machine_zero, tuple(to_part.toMatrix().A))
        if cache is not None and key in cache:
            in_part, in_job = cache[key]
        else:
            tips = machine_tips(read, machine_zero)
            in_part = placed(read, tips, to_part)
            in_job = placed(read, tips, FreeCAD.Placement())
            if cache is not None:
                cache[key] = (in_part, in_job)
        # Copies: the cutter and allowances are set on them below.
        in_part, in_job = [dict(o) for o in in_part], [dict(o) for o in in_job]
        for op, op_job in zip(in_part, in_job):
            job, fc_op = ops_by_label.get(op["label"], (None, None))
            if fc_op is None:
                raise VerificationError("{} holds an operation '{}' that the Jobs do not".format(
                    os.path.basename(p["path"]), op["label"]))
            cutter = op_base.cutter_of(fc_op.ToolController)
            allowances = (checked or {}).get(op["label"]) or {"radial": _length(fc_op, "RadialAllowance"),
                                                              "axial": _length(fc_op, "AxialAllowance")}
            for o in (op, op_job):
                o.update(cutter={k: cutter[k] for k in ("diameter", "cornerRadius", "tipDiameter", "includedAngle")
                                 if k in cutter},  # a chamfer mill's cone with its angle
                         radialAllowance=allowances["radial"], axialAllowance=allowances["axial"])
            sim_ops.append(op)
        setups.append({"name": p["setup"], "id": int(getattr(p["job"], setup_job.SETUP_TAG)),
                       "to_part": to_part, "ops": in_job})
    finished, elements = finished_faces(chain, result)
    # Coverage is measured on every face of the part inside the blank, not only on those the
    # plan finishes: what stands where the part has none is material_left's to name.
    against_part = faces_against_part(result)
    if all(axis_is_vertical(op["axis"]) for op in sim_ops):
        measured = sorted(set(finished) | set(against_part))
        return simulate(part_shape, sim_ops, blank, measured, elements, cell_size), len(sim_ops)
    setup_of_element = {"E{}".format(e["id"]): e.get("setup") for e in result.get("elements", [])}
    for s in setups:
        s["elements"] = {k: v for k, v in elements.items() if setup_of_element.get(k) == s["id"]}
        # Each setup measures every face of the part: what another setup removed is still stock in
        # this one's model, so a face is judged by the setup that left least on it (_merged).
        s["faces"] = sorted(set(against_part) | set().union(*[set(v) for v in s["elements"].values()]))
    return simulate_by_setup(part_shape, setups, blank, cell_size), len(sim_ops)


def faces_against_part(result):
    """Every face of the part inside the blank (1-based): those an element claims and those
    recognition left unclaimed; the faces on the blank's own surface are not among them."""
    faces = {i + 1 for i, e in enumerate(result.get("faceElement", [])) if e is not None and int(e) >= 0}
    faces.update(int(f) for f in result.get("unclaimedFaces", []))
    return sorted(faces)


def material_left(report, chain, result):
    """What the simulated programs leave standing where the part has none, beyond the coverage
    tolerance: [{"element": id or None (unclaimed faces), "faces", "area" (mm^2), "maxLeft"
    (mm), "reason"}], the largest area first. Elements the chain does not machine and unclaimed
    faces are listed also when the simulation could not measure their faces (area None): they
    are not known to be finished."""
    face_element = result.get("faceElement", [])
    measured = {int(f["face"]): f for f in report.get("coverage", {}).get("faces", [])}
    why, gap_faces = {}, {}  # element -> reasons; element -> the faces it leaves (None: all of them)
    for gap in chain.get("unmachined", []):
        step = " (step {})".format(gap["step"]) if gap.get("step") else ""
        text = "not machined{}: {}".format(step, gap.get("reason", ""))
        element = gap.get("element")
        if text not in why.setdefault(element, []):
            why[element].append(text)
        if not gap.get("faces"):
            gap_faces[element] = None
        elif gap_faces.get(element, set()) is not None:
            gap_faces[element] = gap_faces.get(element, set()) | set(int(f) for f in gap["faces"])
    remainders = {}  # element -> what its tools leave where no tool of the crib reaches
    for r in chain.get("remainders", []):
        remainders.setdefault(r.get("element"), []).append(remainder_text(r))
    finished, _ = finished_faces(chain, result)
    finished = set(finished)
    groups = {}
    for face in faces_against_part(result):
        owner = int(face_element[face - 1]) if face - 1 < len(face_element) and face_element[face - 1] >= 0 else None
        f = measured.get(face)
        left = f is not None and float(f.get("uncoveredArea", 0)) > 0
        listed = owner is None or (owner in gap_faces and (gap_faces[owner] is None or face in gap_faces[owner]))
        unknown = (f is None or not f.get("measured", True)) and listed
        if left or unknown:
            groups.setdefault(owner, []).append((face, f if left else None))
    out = []
    for owner, faces in groups.items():
        known = [f for _, f in faces if f is not None]
        if owner is None:
            reason = "unclaimed: no element machines these faces (recognition did not find the feature they bound)"
        elif owner in why:
            reason = "; ".join(why[owner])
        elif owner in remainders:
            reason = "; ".join(remainders[owner])
        elif any(face in finished for face, _ in faces):
            reason = "finished by the plan, but the programs leave material on it"
        else:
            reason = "no finishing step of the plan reaches these faces"
        out.append({"element": owner, "faces": sorted(face for face, _ in faces),
                    "area": sum(float(f["uncoveredArea"]) for f in known) if known else None,
                    "maxLeft": max(float(f["maxLeftover"]) for f in known) if known else None,
                    "reason": reason})
    out.sort(key=lambda e: -(e["area"] or 0))
    return out


def remainder_text(r):
    """"left by EM-F2x12 (step fs): the corners, 0.86 mm² 12 mm deep; needs ..." for one chain
    remainder (what a machined element keeps where no tool of the crib reaches)."""
    what = {"corners": "the corners", "depth": "the region below its reach"}.get(r.get("kind"), "the floor fillet's foot")
    area = r.get("area")
    return "left by {} (step {}): {}, {} {:.3g} mm deep; needs {}".format(
        r.get("tool"), r.get("step"), what,
        "{:,.2f} mm²".format(float(area)) if area is not None else "area not measured",
        float(r.get("depth") or 0), r.get("needs", ""))


def incomplete_text(left):
    """"incomplete: 2 elements not machined, 9 unclaimed faces; 11,000 mm² left, up to 28 mm"
    for material_left's entries, or None when there is none."""
    if not left:
        return None
    parts = []
    elements = [e for e in left if e["element"] is not None]
    unclaimed = sum(len(e["faces"]) for e in left if e["element"] is None)
    if elements:
        parts.append("{} element{} with material left ({})".format(
            len(elements), "" if len(elements) == 1 else "s",
            ", ".join("E{}".format(e["element"]) for e in elements[:8]) + (" ..." if len(elements) > 8 else "")))
    if unclaimed:
        parts.append("{} unclaimed face{}".format(unclaimed, "" if unclaimed == 1 else "s"))
    areas = [e["area"] for e in left if e["area"] is not None]
    thick = [e["maxLeft"] for e in left if e["maxLeft"] is not None]
    text = "incomplete: " + ", ".join(parts)
    if areas:
        text += "; {:,.0f} mm\u00b2 left, up to {:.2f} mm".format(sum(areas), max(thick))
    unmeasured = sum(1 for e in left if e["area"] is None)
    if unmeasured:
        text += "; {} not measured".format(unmeasured)
    return text


def failing_operations(report):
    """{operation label: why} for every operation of the simulated programs that gouges the
    part beyond its allowance or rapids through material."""
    out = {}
    for op in report.get("ops", []):
        why = []
        if int(op.get("gouges", 0)):
            why.append("gouges the part: {} move{}, worst {:.2f} mm beyond its allowance{}".format(
                op["gouges"], "" if int(op["gouges"]) == 1 else "s", float(op.get("worstGouge", 0)),
                _place(op.get("worstGougeAt"))))
        if int(op.get("collisions", 0)):
            why.append("rapids through material: {} move{}, {:.2f} mm deep{}".format(
                op["collisions"], "" if int(op["collisions"]) == 1 else "s", float(op.get("worstCollision", 0)),
                _place(op.get("worstCollisionAt"), "the material")))
        if why:
            out[op["label"]] = "; ".join(why)
    return out


def _place(event, unnamed="the part"):
    """" (move 118, a wall of face 12 at x 10.0 y -4.5 z 20.0)": where an operation's worst
    gouge or colliding rapid is (face numbers as recognition's; the point in the part's frame
    when every setup is along +-Z, else in its setup's frame); "" when the report does not say."""
    if not event:
        return ""
    x, y, z = (float(v) for v in event.get("position", (0, 0, 0)))
    face = int(event.get("face", 0) or 0)
    what = "{} of face {}".format("a wall" if event.get("kind") == "wall" else "the top", face) if face else unnamed
    return " (move {}, {} at x {:.1f} y {:.1f} z {:.1f})".format(int(event.get("move", 0)), what, x, y, z)


def _length(obj, prop):
    """A length property's value in mm; 0 for an operation without it (drilling leaves nothing)."""
    v = getattr(obj, prop, 0.0)
    return float(getattr(v, "Value", v))


def finished_faces(chain, result):
    """(faces the plan finishes, {element label: its finished faces}): floors and walls of the
    elements with an enabled finishing unit (webs, walls, flanges, corners). The faces of an
    element the chain lists as not (completely) machined are left out, also where another
    element shares them (only the listed faces when the entry names them): the plan does not
    finish them, and the report says why."""
    elements = {e["id"]: e for e in result.get("elements", [])}
    not_finished = set()
    for gap in chain.get("unmachined", []):
        e = elements.get(gap.get("element"))
        if gap.get("faces"):  # only part of the element is left (an island's top)
            not_finished.update(gap["faces"])
        elif e is not None:
            not_finished.update(_element_faces(e))
    finished = {}
    for u in chain.get("units", []):
        if not u.get("enabled", True) or u.get("step") not in _FINISHING_STEPS:
            continue
        e = elements.get(u.get("element"))
        if e is None:
            continue
        faces = finished.setdefault("E{}".format(e["id"]), set())
        if u.get("step") == "w":
            faces.update(e.get("floorFaces", []))
        if u.get("step") == "e":  # a chamfer mill's pass finishes the element's chamfers and countersink
            faces.update(e.get("chamferFaces", []))
            for a in e.get("attached", []):
                if a.get("kind") == "countersink":
                    faces.update(a.get("faces", []))
        if u.get("step") in ("fs", "ff"):
            faces.update(e.get("contourFaces", []))
            for island in e.get("islandFaces", []):
                faces.update(island)
    finished = {k: v - not_finished for k, v in finished.items()}
    faces = sorted(set().union(*finished.values())) if finished else []
    return faces, {k: sorted(v) for k, v in finished.items() if v}


def _element_faces(e):
    faces = set(e.get("floorFaces", [])) | set(e.get("contourFaces", []))
    for island in e.get("islandFaces", []):
        faces.update(island)
    return faces


def simulate(part_shape, ops, blank, finished, elements, cell_size=0.5, options=None):
    """Run ops (part frame, see placed; each with "cutter", "radialAllowance",
    "axialAllowance") on the blank; returns the core's report dict."""
    from aeronc import _core
    program = _program(ops, blank, finished, elements, cell_size)
    with from_core(VerificationError, "simulation"):
        text = _core.simulate(part_shape.exportBrepToString(), json.dumps(program), json.dumps(options or {}))
    return json.loads(text)


def _program(ops, blank, finished, elements, cell_size):
    return {"cellSize": cell_size, "blank": list(blank), "finishedFaces": finished, "elements": elements,
            "ops": [{"label": o["label"], "axis": o["axis"], "cutter": o["cutter"],
                     "radialAllowance": o["radialAllowance"], "axialAllowance": o["axialAllowance"],
                     "moves": plunges_marked(o["moves"])} for o in ops if o["moves"]]}


def axis_is_vertical(axis):
    return abs(abs(float(axis[2])) - 1.0) < 1e-9


def simulate_by_setup(part_shape, setups, blank, cell_size=0.5, options=None):
    """Each setup on its own, in its Job's frame, where its tool axis is +Z: for parts machined
    along other axes than +-Z, which the dexel model cannot take in one frame.
    setups: [{"name", "to_part": Placement Job -> part, "ops": ops in the Job's frame (see
    simulate), "elements": {label: finished faces of the setup's elements}}], in the order they
    are machined; blank: the part frame's box. Each setup starts from the whole blank; its rapids
    collide only with material that the setups before it left too. The reports are merged:
    gouges and collisions of all setups, coverage of each setup's own faces, the leftover map of
    the setup with the most operations."""
    import FreeCAD
    from aeronc import _core
    runs, names = [], []
    for s in setups:
        if not s["ops"]:
            continue
        to_job = s["to_part"].inverse()
        corners = [to_job.multVec(FreeCAD.Vector(x, y, z)) for x in (blank[0], blank[3])
                   for y in (blank[1], blank[4]) for z in (blank[2], blank[5])]
        box = (min(c.x for c in corners), min(c.y for c in corners), min(c.z for c in corners),
               max(c.x for c in corners), max(c.y for c in corners), max(c.z for c in corners))
        own = s["elements"]
        faces = s.get("faces")
        if faces is None:
            faces = sorted(set().union(*[set(v) for v in own.values()])) if own else []
        m = s["to_part"].toMatrix()
        runs.append({"name": s["name"],
                     "rotation": [m.A11, m.A12, m.A13, m.A21, m.A22, m.A23, m.A31, m.A32, m.A33],
                     "translation": [m.A14, m.A24, m.A34],
                     "program": _program(s["ops"], box, faces, own, cell_size)})
        names.append(s)
    if not runs:
        raise VerificationError("no setup has an operation to simulate")
    with from_core(VerificationError, "simulation"):
        texts = _core.simulate_setups(part_shape.exportBrepToString(), json.dumps(runs), json.dumps(options or {}))
    reports = []
    for s, r in zip(names, json.loads(texts)):
        for op in r.get("ops", []):
            op["setup"] = s["name"]
        reports.append((s, r))
    return _merged(reports)


def _merged(reports):
    first = reports[0][1]
    out = {"perSetup": [s["name"] for s, _ in reports], "grid": first.get("grid"),
           "ops": [op for _, r in reports for op in r.get("ops", [])]}
    for key in ("gouges", "collisions"):
        sections = [(s, r.get(key, {})) for s, r in reports]
        listed = []
        for s, sec in sections:
            for x in sec.get("list", []):
                listed.append(dict(x, setup=s["name"]))
        worst = None
        for s, sec in sections:
            w = sec.get("worst")
            if w and (worst is None or float(w.get("depth", 0)) > float(worst.get("depth", 0))):
                worst = dict(w, setup=s["name"])
        out[key] = {"count": sum(int(sec.get("count", 0)) for _, sec in sections),
                    "cells": sum(int(sec.get("cells", 0)) for _, sec in sections),
                    "tolerance": sections[0][1].get("tolerance"), "worst": worst, "list": listed}
    coverage = dict(first.get("coverage", {}))
    # A face more than one setup measures (an unclaimed one) is as the setup that left least on it.
    faces = {}
    for _, r in reports:
        for f in r.get("coverage", {}).get("faces", []):
            seen = faces.get(f["face"])
            if seen is None or _left_on(f) < _left_on(seen):
                faces[f["face"]] = f
    coverage["faces"] = [faces[k] for k in sorted(faces)]
    coverage["elements"] = [e for _, r in reports for e in r.get("coverage", {}).get("elements", [])]
    out["coverage"] = coverage
    out["stock"] = {"blankVolume": max(float(r["stock"]["blankVolume"]) for _, r in reports),
                    "finalVolume": min(float(r["stock"]["finalVolume"]) for _, r in reports)}
    out["timings"] = {k: sum(float(r.get("timings", {}).get(k, 0.0)) for _, r in reports)
                      for k in first.get("timings", {})}
    s, biggest = max(reports, key=lambda sr: len(sr[1].get("ops", [])))
    if biggest.get("leftover"):
        out["leftover"] = biggest["leftover"]
        out["leftoverSetup"] = s["name"]
    # The other setups' maps where a face they finish is not reached: where to look.
    out["leftovers"] = [(x["name"], r["leftover"]) for x, r in reports
                        if x is not s and r.get("leftover") and _uncovered(r, x)]
    return out


def _left_on(face):
    return (float(face.get("uncoveredArea", 0)), float(face.get("maxLeftover", 0)), not face.get("measured", True))


def _uncovered(report, setup):
    """Whether the setup leaves material on a face it finishes."""
    own = set().union(*[set(v) for v in setup.get("elements", {}).values()])
    return any(float(f.get("uncoveredArea", 0)) > 0 for f in report.get("coverage", {}).get("faces", [])
               if f["face"] in own)
