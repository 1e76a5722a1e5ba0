"""The machine a part is cut on: the smallest whose travel holds every setup with the part placed
for it (docs/machine-choice.md).

The main job stands each setup's blank centred on the table, its underside on the table
reference (setup_job.part_zero); the tool tip then travels, from the table reference, over what
the setup's toolpaths reach plus that part zero. A machine holds a setup when all of it lies in
the machine file's linearTravel (the post's own check, kinematics/Planner.cpp).

Two measures of what a setup needs:
  need_of_blank   before tools and toolpaths exist: the blank in the setup, a lower bound (the
                  tool reaches the blank's sides and top at least). Its in-plane orientation is
                  the chain's to fix, so either way round is allowed.
  need_of_paths   after the chain: every tool tip of the setup's operations, what the post checks.
The candidates are the knowledge base's machines that have a machine file (a post), smallest
travel first; the main job chooses by the blank first (tool selection and the cutting data are
for that machine), then steps up by the toolpaths if they need more.
"""
from aeronc.errors import AeroNCError

AXES = "XYZ"


class MachineChoiceError(AeroNCError):
    """No machine holds the part, or the machine named cannot."""


def candidates(kb):
    """[{"name", "travel": {"X": (lo, hi), ...}, "volume"}] of the knowledge base's machines that
    have a machine file, the smallest travel first (ties by name)."""
    import json
    from aeronc.post import machines
    files = set(machines.known_machines())
    out = []
    for name in kb.machine_names():
        if name not in files:
            continue  # no post for it: the main job cannot program it
        travel = json.loads(machines.load(name)[0]).get("linearTravel")
        if not travel:
            continue
        t = {a: (float(travel[a][0]), float(travel[a][1])) for a in AXES}
        volume = 1.0
        for a in AXES:
            volume *= t[a][1] - t[a][0]
        out.append({"name": name, "travel": t, "volume": volume})
    return sorted(out, key=lambda c: (c["volume"], c["name"]))


def need_of_blank(blank, setups):
    """[{"setup", "boxes": [(lo, hi), ...]}]: per recognised setup ({"name", "direction"}), the
    blank standing centred on the table along the setup's direction, in either in-plane
    orientation for a principal direction (height only for a tilted one)."""
    d = [blank[3] - blank[0], blank[4] - blank[1], blank[5] - blank[2]]
    out = []
    for s in setups:
        w = [float(c) for c in s["direction"]]
        height = sum(abs(w[k]) * d[k] for k in range(3))  # the blank's extent along w
        principal = [k for k in range(3) if abs(abs(w[k]) - 1.0) < 1e-9]
        boxes = []
        if principal:
            p, q = [d[k] for k in range(3) if k != principal[0]]
            for a, b in ((p, q), (q, p)):
                boxes.append(([-a / 2, -b / 2, 0.0], [a / 2, b / 2, height]))
        else:
            boxes.append(([0.0, 0.0, 0.0], [0.0, 0.0, height]))
        out.append({"setup": s["name"], "boxes": boxes, "measure": "blank"})
    return out


def need_of_paths(setups):
    """[{"setup", "boxes": [(lo, hi)]}]: per setup ({"name", "operations": [FreeCAD operations in
    the setup's Job], "partZero"}), the box of every tool tip its toolpaths reach, from the table
    reference. Arcs count with their whole circle; drilling cycles with their R level and bottom."""
    out = []
    for s in setups:
        lo, hi = [float("inf")] * 3, [float("-inf")] * 3
        for op in s["operations"]:
            for p in tip_points(op.Path.Commands):
                for k in range(3):
                    lo[k], hi[k] = min(lo[k], p[k]), max(hi[k], p[k])
        if lo[0] == float("inf"):
            continue  # no move with a full position
        zero = s["partZero"]
        out.append({"setup": s["name"], "measure": "toolpaths",
                    "boxes": [([lo[k] + zero[k] for k in range(3)], [hi[k] + zero[k] for k in range(3)])]})
    return out


def tip_points(commands):
    """The tool tips (x, y, z) a Path's commands reach, in the Job's frame. A move before X, Y
    and Z are all known is not one (the post does not check it either)."""
    pos = [None, None, None]
    for c in commands:
        name, p = c.Name, c.Parameters
        if name in ("G0", "G00", "G1", "G01", "G2", "G02", "G3", "G03"):
            start = list(pos)
            for k, a in enumerate(AXES):
                if a in p:
                    pos[k] = float(p[a])
            if None in pos:
                continue
            yield tuple(pos)
            if name in ("G2", "G02", "G3", "G03") and None not in start:
                # The whole circle about the centre, a bound of the arc's bulge.
                cx, cy = start[0] + float(p.get("I", 0.0)), start[1] + float(p.get("J", 0.0))
                r = ((start[0] - cx) ** 2 + (start[1] - cy) ** 2) ** 0.5
                for dx, dy in ((r, 0), (-r, 0), (0, r), (0, -r)):
                    yield (cx + dx, cy + dy, pos[2])
        elif name in ("G73", "G81", "G82", "G83"):
            for k, a in enumerate(AXES):
                if a in p:
                    pos[k] = float(p[a])
            if None in pos:
                continue
            yield tuple(pos)
            if "R" in p:
                yield (pos[0], pos[1], float(p["R"]))


def shortfall(travel, box):
    """{axis: mm} by which the box (lo, hi) leaves the travel; empty when it holds it."""
    lo, hi = box
    out = {}
    for k, a in enumerate(AXES):
        t = travel[a]
        excess = max(t[0] - lo[k], hi[k] - t[1], 0.0)
        if excess > 1e-6:
            out[a] = excess
    return out


def misfits(candidate, needs):
    """[{"setup", "short": {axis: mm}, "box"}] of the setups the machine does not hold (for a
    setup with boxes either way round, the way that leaves least)."""
    out = []
    for n in needs:
        best = None
        for box in n["boxes"]:
            short = shortfall(candidate["travel"], box)
            if best is None or sum(short.values()) < sum(best[0].values()):
                best = (short, box)
        if best and best[0]:
            out.append({"setup": n["setup"], "short": best[0], "box": best[1], "measure": n.get("measure", "")})
    return out


def misfit_text(candidate, misses):
    """"setup +Z needs X -350.0...350.0 (blank), beyond its -325...325 by 25.0 mm; ..."."""
    parts = []
    for m in misses:
        lo, hi = m["box"]
        axes = []
        for a, mm in sorted(m["short"].items()):
            k = AXES.index(a)
            t = candidate["travel"][a]
            axes.append("{} {:.1f}...{:.1f}, beyond its {:g}...{:g} by {:.1f} mm".format(
                a, lo[k], hi[k], t[0], t[1], mm))
        parts.append("setup {} needs {} ({})".format(m["setup"], "; ".join(axes), m["measure"] or "its moves"))
    return "; ".join(parts)


def worst_text(candidate, misses):
    """The setup that leaves the machine by most, and how many others leave it too."""
    worst = max(misses, key=lambda m: max(m["short"].values()))
    more = len(misses) - 1
    return misfit_text(candidate, [worst]) + ("; {} other setup{} too".format(more, "" if more == 1 else "s")
                                              if more else "")


def choose(cands, needs, named=None, at_least=None):
    """{"name", "why", "rejected": [{"name", "text"}]}: the machine named (if it holds every
    setup), else the smallest candidate that does, no smaller than at_least (a machine already
    chosen). Raises MachineChoiceError saying which setup the named machine or the largest one
    leaves and by how much."""
    if not cands:
        raise MachineChoiceError("the knowledge base has no machine with a machine file (resources/machines) "
                                 "to program the part for")
    if named:
        match = [c for c in cands if c["name"] == named]
        if not match:
            return {"name": named, "why": "named by the user (its travel is the post's to check: it is not "
                                          "one of the knowledge base's machines with a machine file)",
                    "rejected": []}
        misses = misfits(match[0], needs)
        if misses:
            holds = [c["name"] for c in cands if not misfits(c, needs)]
            raise MachineChoiceError("machine {} (named) does not hold the part: {}{}".format(
                named, misfit_text(match[0], misses),
                "; {} would".format(holds[0]) if holds else "; no machine of the knowledge base does"))
        return {"name": named, "why": "named by the user; its travel holds every setup", "rejected": []}
    start = 0
    if at_least is not None:
        start = next((i for i, c in enumerate(cands) if c["name"] == at_least), 0)
    rejected = []
    for c in cands[start:]:
        misses = misfits(c, needs)
        if not misses:
            why = "the smallest machine whose travel holds every setup"
            if rejected:
                why += " ({})".format("; ".join("{}: {}".format(r["name"], r["text"]) for r in rejected))
            return {"name": c["name"], "why": why, "rejected": rejected}
        rejected.append({"name": c["name"], "text": worst_text(c, misses)})
    largest = cands[-1]
    raise MachineChoiceError("no machine of the knowledge base holds the part: the largest, {}: {}".format(
        largest["name"], rejected[-1]["text"]))
