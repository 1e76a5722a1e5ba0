"""A generated wing-skin panel with rows of fastener holes, and its known truth.

The skin is curved chordwise (a cylinder of radius `radius` about an axis along Y, the span;
radius 0 makes it flat), its outer surface passing through the origin with normal +Z there.
Rows of holes follow the ribs: chordwise, at spanwise stations `row_pitch` apart, each with
`holes_per_row` holes `pitch` apart along the curved surface, drilled normal to the surface
through the skin. The truth lists every hole's entry point, normal, row and place in it.
"""
import math

import FreeCAD
import Part

DEFAULT = {
    "radius": 1200.0,        # mm, 0 = flat
    "thickness": 3.0,
    "rows": 4,
    "holes_per_row": 15,
    "pitch": 25.0,           # along the surface
    "row_pitch": 120.0,
    "margin": 30.0,          # edge distance round the pattern
    "diameter": 4.8,         # a 3/16 in rivet hole
}


def _outer(spec, s, y):
    """Point and outward normal of the outer surface at arc length s from the centre line."""
    r = spec["radius"]
    if r <= 0:
        return FreeCAD.Vector(s, y, 0.0), FreeCAD.Vector(0, 0, 1)
    t = s / r
    return (FreeCAD.Vector(r * math.sin(t), y, r * (math.cos(t) - 1.0)),
            FreeCAD.Vector(math.sin(t), 0.0, math.cos(t)))


def _section(spec, half_chord, thickness):
    """The skin's cross-section (a face in the XZ plane at y = 0)."""
    r = spec["radius"]
    if r <= 0:
        return Part.Face(Part.makePolygon([FreeCAD.Vector(-half_chord, 0, 0), FreeCAD.Vector(half_chord, 0, 0),
                                           FreeCAD.Vector(half_chord, 0, -thickness),
                                           FreeCAD.Vector(-half_chord, 0, -thickness),
                                           FreeCAD.Vector(-half_chord, 0, 0)]))
    def at(radius, s):
        t = s / r
        return FreeCAD.Vector(radius * math.sin(t), 0.0, radius * math.cos(t) - r)
    outer = Part.Arc(at(r, -half_chord), at(r, 0.0), at(r, half_chord)).toShape()
    inner = Part.Arc(at(r - thickness, half_chord), at(r - thickness, 0.0), at(r - thickness, -half_chord)).toShape()
    wire = Part.Wire([outer, Part.makeLine(at(r, half_chord), at(r - thickness, half_chord)), inner,
                      Part.makeLine(at(r - thickness, -half_chord), at(r, -half_chord))])
    return Part.Face(wire)


def make_wing_skin(spec=None):
    """(solid, truth): truth = {"spec", "holes": [{"entry", "normal", "row", "index", "diameter",
    "depth"}]}, rows numbered from 0 at y = 0, holes from 0 at the row's chordwise start."""
    s = dict(DEFAULT)
    s.update(spec or {})
    n, pitch = int(s["holes_per_row"]), float(s["pitch"])
    half = 0.5 * (n - 1) * pitch
    span = (s["rows"] - 1) * s["row_pitch"] + 2 * s["margin"]
    section = _section(s, half + s["margin"], s["thickness"])
    skin = section.extrude(FreeCAD.Vector(0, span, 0))
    skin.translate(FreeCAD.Vector(0, -s["margin"], 0))
    holes, cutters = [], []
    for row in range(int(s["rows"])):
        y = row * s["row_pitch"]
        for k in range(n):
            p, normal = _outer(s, -half + k * pitch, y)
            holes.append({"entry": p, "normal": normal, "row": row, "index": k, "diameter": s["diameter"],
                          "depth": s["thickness"]})
            start = p + normal * 2.0
            cutters.append(Part.makeCylinder(0.5 * s["diameter"], s["thickness"] + 4.0, start, normal * -1.0))
    solid = skin.cut(Part.makeCompound(cutters))
    solid = solid.Solids[0] if len(solid.Solids) == 1 else solid
    return solid, {"spec": s, "holes": holes}
