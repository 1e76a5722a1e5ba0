"""Arrows, rings and labels in the 3-D view (coin nodes), for the deviations of the datum holes
and the corrections of the drilled holes."""
import FreeCAD


def arrow(a, b):
    """A separator: the line from a to b and a cone at b pointing along it; None when a = b."""
    from pivy import coin
    d = b - a
    length = d.Length
    if length < 1e-9:
        return None
    sep = coin.SoSeparator()
    coords = coin.SoCoordinate3()
    coords.point.setValues(0, 2, [(a.x, a.y, a.z), (b.x, b.y, b.z)])
    sep.addChild(coords)
    line = coin.SoLineSet()
    line.numVertices.setValue(2)
    sep.addChild(line)
    head = min(0.25 * length, 12.0)
    place = coin.SoTransform()
    u = FreeCAD.Vector(d).normalize()
    place.translation = tuple(b - u * (head / 2))
    place.rotation = coin.SbRotation(coin.SbVec3f(0, 1, 0), coin.SbVec3f(u.x, u.y, u.z))
    sep.addChild(place)
    cone = coin.SoCone()
    cone.height = head
    cone.bottomRadius = head * 0.35
    sep.addChild(cone)
    return sep


def coloured(rgb, *children, line_width=None, point_size=None):
    """A separator drawing its children in one colour (and line width, marker size)."""
    from pivy import coin
    sep = coin.SoSeparator()
    if line_width is not None or point_size is not None:
        style = coin.SoDrawStyle()
        if line_width is not None:
            style.lineWidth = line_width
        if point_size is not None:
            style.pointSize = point_size
        sep.addChild(style)
    colour = coin.SoBaseColor()
    colour.rgb = rgb
    sep.addChild(colour)
    for c in children:
        if c is not None:
            sep.addChild(c)
    return sep


def markers(points, kind="CIRCLE_LINE_9_9"):
    """A marker (coin's SoMarkerSet kind) at each point."""
    from pivy import coin
    sep = coin.SoSeparator()
    if not points:
        return sep
    coords = coin.SoCoordinate3()
    coords.point.setValues(0, len(points), [(p.x, p.y, p.z) for p in points])
    sep.addChild(coords)
    m = coin.SoMarkerSet()
    m.markerIndex = getattr(coin.SoMarkerSet, kind)
    m.startIndex = 0
    m.numPoints = len(points)
    sep.addChild(m)
    return sep


def label(at, text):
    """Screen-aligned text at a point."""
    from pivy import coin
    sep = coin.SoSeparator()
    move = coin.SoTranslation()
    move.translation = (at.x, at.y, at.z)
    sep.addChild(move)
    t = coin.SoText2()
    t.string = text
    sep.addChild(t)
    return sep
