"""The gate before a program leaves: which operations are left out of it, and why.

The posted programs are simulated (pipeline.verification). Every operation that gouges the part
or rapids through material fails its check; so does every operation the toolpath core refused
(it has no toolpath). A failed operation is left out of the delivered program (the posts'
--skip-failed, aeronc.post.readiness), and with it what depends on it: the later operations of
the same element, those of the elements inside it when it is a roughing (they would cut, with a
finishing tool and its feeds, the material it was to remove), and any operation that, once the program is posted
again without them, removes far more material than it did with them. The programs are then
simulated again; this repeats until nothing fails.

Before a roughing operation that gouges is left out, it is re-made once (regrow): its allowances
grown by the gouge's depth and a margin, its toolpath computed again. It is then checked against
the allowances it was planned with, the ones its element's later units were planned for: what it
leaves must be at least that stock. Those units then take the thicker layer it leaves; what they
remove is measured again from there (rebased), not held against the amount they removed before.
Should it still gouge, it is left out with what depends on it.
"""
from aeronc.operations.base import mark
from aeronc.post import readiness

# An operation removing more than this much more material once others are left out carries
# their load: GROWTH times what it removed before, and at least GROWTH_MM3 more.
GROWTH = 1.5
GROWTH_MM3 = 100.0
# A roughing operation that gouges by g is re-made with its allowances grown by g + REGROW_MARGIN,
# when that growth is at most REGROW_MAX: more would leave the finishing tools a layer thicker
# than a finishing cut.
REGROW_MARGIN = 0.2
REGROW_MAX = 1.5


def not_ready(ops):
    """{label: why} of the operations the posts will leave out (no toolpath, failed, no move)."""
    out = {}
    for op in ops:
        if op.Check in readiness.NOT_READY:
            out[op.Label] = op.Note or op.Check.lower()
        elif not op.Path.Commands:
            out[op.Label] = "no toolpath"
    return out


def fail(op, why):
    """Mark an operation as failed (Check, Note): the posts then refuse it or leave it out."""
    mark(op, readiness.FAILED, why)


def passed(op, note=""):
    """Mark an operation whose simulation in the delivered program found nothing wrong (note: how
    the gate re-made it, if it did)."""
    mark(op, readiness.PASSED, note)


def short_of_floor(op):
    """Whether an operation is a roughing that stops short of its element's floor (deeper than
    every end mill reaches)."""
    from aeronc.operations.base import unit_of
    return bool(unit_of(op).get("shortOfFloor"))


def roughs(op):
    """Whether an operation is a roughing (step r): the one that clears the element's volume,
    where the elements inside it open."""
    return getattr(op, "Step", "") == "r"


def dependents(ops, left_out, result):
    """{label: why} of the operations (ops in program order, active ones) that follow a left-out
    operation of their own element, or a left-out roughing of an element that contains theirs.
    A finishing left out leaves its allowance on its own walls and floor only: what lies inside
    the element is still checked by the simulation (gouges, rapids) and by the load (grown). A
    roughing that stops short of its element's floor (deeper than every end mill reaches) takes
    nothing with it: nothing below relies on what it removes."""
    parent = {int(e["id"]): int(e.get("parent", -1)) for e in result.get("elements", [])}

    def ancestors(element):
        seen = []
        while element >= 0 and element not in seen:
            seen.append(element)
            element = parent.get(element, -1)
        return seen

    out = {}
    gone = []  # (element, label, roughing?) of the left-out operations met so far
    for op in ops:
        element = int(getattr(op, "ElementId", -1))
        if op.Label in left_out or op.Label in out:
            if not short_of_floor(op):
                gone.append((element, op.Label, roughs(op)))
            continue
        mine = ancestors(element)
        before = next((label for e, label, rough in gone if e == element or (rough and e in mine)), None)
        if before is not None:
            out[op.Label] = "left out with {}: it would cut the material that operation leaves".format(before)
            gone.append((element, op.Label, roughs(op)))
    return out


def grown(first, report, left_out):
    """{label: why} of the operations that remove far more material in report than in first
    (the reports of the simulation with and without the left-out operations)."""
    before = {op["label"]: float(op.get("removedVolume", 0)) for op in first.get("ops", [])}
    out = {}
    for op in report.get("ops", []):
        was = before.get(op["label"])
        now = float(op.get("removedVolume", 0))
        if was is not None and now > GROWTH * was and now - was > GROWTH_MM3:
            out[op["label"]] = ("it would remove {:,.0f} mm\u00b3 instead of {:,.0f} mm\u00b3 once {} {} left "
                                "out: the load of the operations left out".format(
                                    now, was, ", ".join(sorted(left_out)[:3]) + (" ..." if len(left_out) > 3 else ""),
                                    "is" if len(left_out) == 1 else "are"))
    return out


def regrow(op, depth):
    """Re-make a roughing operation that gouged depth mm beyond its allowances: both grown by
    depth + REGROW_MARGIN, its toolpath computed again. Returns {"radial", "axial"} of the
    allowances it was planned with (those it is to be checked against), or None when it is not
    re-made (not a roughing, a growth beyond REGROW_MAX, or no toolpath with the grown
    allowances: it is then as it was)."""
    grow = float(depth) + REGROW_MARGIN
    if not roughs(op) or grow > REGROW_MAX:
        return None
    planned = {"radial": float(op.RadialAllowance.Value), "axial": float(op.AxialAllowance.Value)}
    edited = list(op.UserEdited)

    def make(radial, axial):
        op.RadialAllowance, op.AxialAllowance = radial, axial
        op.UserEdited = edited  # the gate's choice, not a change by hand
        op.recompute()
        return op.Check != readiness.NO_TOOLPATH and bool(op.Path.Commands)

    if make(planned["radial"] + grow, planned["axial"] + grow):
        return planned
    make(planned["radial"], planned["axial"])
    return None


def regrown_note(op, planned, depth):
    """The note of a re-made roughing operation: its allowances, the planned ones and why."""
    return ("re-made with allowances {:.2f} mm radial, {:.2f} mm axial (planned {:.2f}, {:.2f}): with the "
            "planned ones it gouged {:.2f} mm; it leaves at least the planned stock, the later units "
            "of its element finish the rest".format(float(op.RadialAllowance.Value), float(op.AxialAllowance.Value),
                                                   planned["radial"], planned["axial"], float(depth)))


def rebased(first, report, labels):
    """first with the amounts the operations labels remove taken from report: the baseline
    grown() measures them against once a roughing before them was re-made."""
    now = {op["label"]: op for op in report.get("ops", []) if op["label"] in labels}
    return dict(first, ops=[now.get(op["label"], op) for op in first.get("ops", [])])
