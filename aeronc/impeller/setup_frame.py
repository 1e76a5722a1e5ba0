"""The impeller's setup on the machine: its axis along the rotary table's (the Job's Z), the back
of the part on the table (z = 0 at its lowest point along the axis), the axis through the Job's
origin. The core computes in the part's own frame; the Job's model, its stock and toolpaths are
placed in this frame, so every channel is reached with the tool less than 90 degrees off Z and
the post's A axis holds it, whatever frame the part was drawn in (an exported impeller's axis is
often Y or -Z). A part drawn on its setup already (the generated impellers) gets the identity."""
import FreeCAD

_TOL = 1e-9


def placement(axis, shape):
    """FreeCAD.Placement taking the part's frame into the setup's: axis {point, direction} (the
    recognised impeller axis, direction towards the blades' tips), shape the part."""
    d = FreeCAD.Vector(*axis["direction"])
    d.normalize()
    rot = FreeCAD.Rotation(d, FreeCAD.Vector(0, 0, 1))
    turned = shape.copy()
    turned.Placement = FreeCAD.Placement(FreeCAD.Vector(), rot).multiply(turned.Placement)
    low = turned.BoundBox.ZMin  # a B-spline back may sit a little above the table: its poles bound it
    on_axis = rot.multVec(FreeCAD.Vector(*axis["point"]))
    p = FreeCAD.Placement(FreeCAD.Vector(-on_axis.x, -on_axis.y, -low), rot)
    return FreeCAD.Placement() if is_identity(p) else p


def is_identity(p, tol=1e-6):
    q = p.Rotation.Q
    return p.Base.Length <= tol and abs(abs(q[3]) - 1.0) <= tol * tol


def moves_in(p, moves):
    """The core's moves [x, y, z, i, j, k, rapid] (tool tip, tool axis) in the setup frame."""
    if is_identity(p):
        return moves
    out = []
    for x, y, z, i, j, k, rapid in moves:
        tip = p.multVec(FreeCAD.Vector(x, y, z))
        a = p.Rotation.multVec(FreeCAD.Vector(i, j, k))
        out.append([tip.x, tip.y, tip.z, a.x, a.y, a.z, rapid])
    return out


def paths_in(p, paths):
    """The core's program (route.compute's paths) with every operation's moves in the setup frame."""
    if is_identity(p):
        return paths
    for group in (paths.get("operations") or [], (paths.get("axial") or {}).get("operations") or []):
        for op in group:
            op["moves"] = moves_in(p, op["moves"])
    return paths


def shape_in(p, shape):
    """A copy of shape placed in the setup frame."""
    placed = shape.copy()
    placed.Placement = p.multiply(placed.Placement)
    return placed
