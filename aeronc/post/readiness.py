"""Whether an operation may reach a program: the mark an operation carries and what the posts read.

AeroNC's operations carry a check state (property Check) and the reason (Note):
  Not checked   its toolpath is computed; no simulation has judged it yet
  Passed        the posted program was simulated and the operation neither gouges nor rapids
                through material
  No toolpath   the toolpath core refused it (the Note says why): it has no moves
  Failed        the simulation of the posted program found it gouging the part or rapiding
                through material (the Note says where and how deep)
An operation that is "No toolpath" or "Failed", or whose Path has no move at all (any
operation, FreeCAD's own too), is not ready: the posts refuse it, or with --skip-failed leave it
out of the program with a comment naming it and why. It never reaches a program as a tool
change with no moves.
"""
import re

CHECK_STATES = ["Not checked", "Passed", "No toolpath", "Failed"]
NOT_CHECKED, PASSED, NO_TOOLPATH, FAILED = CHECK_STATES
NOT_READY = (NO_TOOLPATH, FAILED)

# A move or a drilling cycle of FreeCAD's G-code (Path.toGCode()): G0 to G3, G73, G81 to G89.
_MOVE = re.compile(r"^\s*G0*(?:[0-3]|73|8[1-9])(?![0-9.])", re.MULTILINE)


def has_moves(gcode):
    return _MOVE.search(gcode) is not None


def not_ready_reason(op, gcode):
    """Why the operation must not be posted (str), or None when it may. gcode: its Path's text."""
    from aeronc import pathcompat
    state = str(pathcompat.op_property(op, "Check") or "")
    note = str(pathcompat.op_property(op, "Note") or "")
    if state == NO_TOOLPATH:
        return "no toolpath: {}".format(note) if note else "no toolpath"
    if state == FAILED:
        return note or "its simulation failed"
    if not has_moves(gcode):
        return "no toolpath: its Path has no move"
    return None
