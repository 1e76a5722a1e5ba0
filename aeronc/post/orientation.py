"""How a tool axis travels on a FreeCAD Path command (docs/post.md).

FreeCAD 0.20's operations are 3-axis. AeroNC's own operations put the tool axis on each
move as three extra parameters that Path.Command keeps (and FreeCAD saves with the
document, to 6 decimals like every parameter):

    U, V, W   unit tool axis in the Job's workpiece frame, pointing from the tool tip
              towards the spindle (APT's i, j, k)

Rules, checked by the post (each breach is an error naming the operation and the move):
  * all three of U, V, W or none; a command without them keeps the axis of the previous
    command of the same operation; each operation starts vertical (0, 0, 1), so FreeCAD's
    own operations post unchanged;
  * |(U, V, W)| = 1 within 1e-4 (rounding to 6 decimals is far inside that);
  * G2/G3 cannot change the axis; their centre is start + (I, J, K) and must lie in the plane
    normal to the axis; G2 turns clockwise seen from the spindle;
  * G81/G82/G83/G73: X Y Z is the hole bottom, R - Z the distance from the bottom to the R
    level along the axis.
"""
import math

AXIS_PARAMETERS = ("U", "V", "W")
UNIT_TOLERANCE = 1e-4


def oriented_command(name, params, axis):
    """A Path.Command carrying the tool axis `axis` (normalised here) on top of `params`."""
    from aeronc import pathcompat
    u = tuple(float(c) for c in axis)
    n = math.sqrt(sum(c * c for c in u))
    if not all(math.isfinite(c) for c in u) or n == 0.0:
        raise ValueError("tool axis {} is not a direction".format(axis))
    p = dict(params)
    p.update(zip(AXIS_PARAMETERS, (c / n for c in u)))
    return pathcompat.command(name, p)


def axis_of(command, previous=(0.0, 0.0, 1.0)):
    """The tool axis a command asks for under the convention (the previous one if it has none)."""
    p = command.Parameters
    given = [k for k in AXIS_PARAMETERS if k in p]
    if not given:
        return previous
    if len(given) != 3:
        raise ValueError("a tool axis needs all of U, V and W")
    return tuple(p[k] for k in AXIS_PARAMETERS)
