"""Profile: passes along the walls of a unit, level by level, leaving the allowances; it
semi-finishes and finishes walls.

The unit's contour is the pocket's boundary at its floor (counter-clockwise, the material
outside) and its islands the bosses inside (clockwise). The cutter runs inside the contour and
outside each island. Where the contour is open to the blank (the unit's open edges) there is
no wall: the walls between are profiled as open drives, the cutter on the pocket's side.
"""
from aeronc.operations.base import AXIAL, CLEARANCE, RADIAL, SAFE, STEP_DOWN, STEP_OVER, MachiningOperation, unit_of

_TOL = 1e-6


def signed_area(loop):
    return 0.5 * sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(loop, loop[1:] + loop[:1]))


def _on_segment(p, a, b):
    ab = (b[0] - a[0], b[1] - a[1])
    ap = (p[0] - a[0], p[1] - a[1])
    length2 = ab[0] ** 2 + ab[1] ** 2
    if length2 < _TOL ** 2:
        return abs(ap[0]) < 1e-4 and abs(ap[1]) < 1e-4
    cross = ab[0] * ap[1] - ab[1] * ap[0]
    t = (ab[0] * ap[0] + ab[1] * ap[1]) / length2
    return abs(cross) / length2 ** 0.5 < 1e-4 and -1e-6 <= t <= 1 + 1e-6


def wall_runs(contour, open_edges):
    """The stretches of a closed contour that are walls, as (points, closed): [] when all of
    it is open, [(contour, True)] when none of it is, else open polylines in the contour's
    direction."""
    n = len(contour)
    segments = [(contour[i], contour[(i + 1) % n]) for i in range(n)]
    is_open = [any(_on_segment(a, e[0], e[1]) and _on_segment(b, e[0], e[1]) for e in open_edges)
               for a, b in segments]
    if not any(is_open):
        return [(list(contour), True)]
    start = is_open.index(True)  # walk from an open segment so that no run wraps round
    runs, current = [], []
    for k in range(1, n + 1):
        i = (start + k) % n
        if is_open[i]:
            if current:
                runs.append((current, False))
            current = []
        else:
            a, b = segments[i]
            current = current + [b] if current else [a, b]
    if current:
        runs.append((current, False))
    return runs


class Profile(MachiningOperation):
    Type = "AeroNC::Profile"
    PARAMETERS = [STEP_DOWN, STEP_OVER, RADIAL, AXIAL, SAFE, CLEARANCE]
    GEOMETRY_KEYS = ("top", "bottom", "lead", "leadRadius", "floorFilletRadius")
    ICON = "Profile"

    def toolpath_inputs(self, obj):
        unit = unit_of(obj)
        base = self.toolpath_input(obj)
        contour = [list(p) for p in unit.get("contour") or []]
        out = []
        runs = wall_runs(contour, unit.get("openEdges") or []) if len(contour) >= 3 else []
        ccw = signed_area(contour) > 0 if len(contour) >= 3 else True
        walls = []  # (drive, closed, side)
        for run, closed in runs:
            side = "inside" if closed else "left" if ccw else "right"  # the pocket's side of the wall
            walls.append((run, closed, side))
        for island in unit.get("islands") or []:
            walls.append(([list(p) for p in island], True, "outside"))
        # Each wall's leads keep as clear of the element's other walls as of its own.
        as_polyline = [w + [w[0]] if closed else w for w, closed, _ in walls]
        for k, (run, closed, side) in enumerate(walls):
            others = [p for j, p in enumerate(as_polyline) if j != k]
            data = dict(base, contour=run, closed=closed, side=side)
            if others:
                data["clearOf"] = others
            out.append(data)
        if not out:
            raise ValueError("{}: no wall to profile (the contour is open all round)".format(obj.Label))
        for i, data in enumerate(out):
            data["name"] = "{} wall {}".format(obj.Label, i + 1) if len(out) > 1 else obj.Label
        return out
