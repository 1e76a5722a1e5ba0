"""View provider of a measured-hole set: each datum hole's measured deviation dP drawn in the
3-D view as an arrow from the nominal hole, ArrowScale times longer than it is; double-click
opens the set's task panel (the deviations, the method and its leave-one-out errors)."""
import FreeCAD

from aeronc.viewproviders.view_base import BaseView


def arrow_segments(obj):
    """[(start, end)] of the deviation arrows in the assembly (document) frame."""
    ps = getattr(obj, "PhotoHoleSet", None)
    part = getattr(ps, "Source", None) if ps is not None else None
    pl = part.Placement if part is not None else FreeCAD.Placement()
    out = []
    for n, d in zip(obj.Nominal, obj.Deviations):
        a = pl.multVec(n)
        out.append((a, a + pl.Rotation.multVec(d) * obj.ArrowScale))
    return out


class ViewMeasuredHoleSet(BaseView):
    ICON = "MeasuredHoleSet"

    def attach(self, vobj):
        super().attach(vobj)
        from pivy import coin
        self.root = coin.SoSeparator()
        style = coin.SoDrawStyle()
        style.lineWidth = 4
        colour = coin.SoBaseColor()
        colour.rgb = (0.55, 0.0, 0.75)  # apart from Path's red rapids
        self.root.addChild(style)
        self.root.addChild(colour)
        self.arrows = coin.SoSeparator()
        self.root.addChild(self.arrows)
        vobj.addDisplayMode(self.root, "Arrows")
        self.rebuild(vobj.Object)

    def getDisplayModes(self, vobj):
        return ["Arrows"]

    def getDefaultDisplayMode(self):
        return "Arrows"

    def setDisplayMode(self, mode):
        return mode

    def updateData(self, obj, prop):
        if prop in ("Deviations", "Nominal", "ArrowScale") and hasattr(self, "arrows"):
            self.rebuild(obj)

    def rebuild(self, obj):
        from pivy import coin
        self.arrows.removeAllChildren()
        for a, b in arrow_segments(obj):
            d = b - a
            length = d.Length
            if length < 1e-9:
                continue
            sep = coin.SoSeparator()
            coords = coin.SoCoordinate3()
            coords.point.setValues(0, 2, [(a.x, a.y, a.z), (b.x, b.y, b.z)])
            sep.addChild(coords)
            line = coin.SoLineSet()
            line.numVertices.setValue(2)
            sep.addChild(line)
            # The head: a cone along the arrow, its tip at the arrow's end.
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
            self.arrows.addChild(sep)

    def arrow_count(self):
        return self.arrows.getNumChildren() if hasattr(self, "arrows") else 0

    def setEdit(self, vobj, mode=0):
        import FreeCADGui
        from aeronc.panels.measured_hole_set_panel import MeasuredHoleSetPanel
        FreeCADGui.Control.showDialog(MeasuredHoleSetPanel(vobj.Object))
        return True

    def unsetEdit(self, vobj, mode=0):
        import FreeCADGui
        FreeCADGui.Control.closeDialog()
        return True

    def doubleClicked(self, vobj):
        import FreeCADGui
        if FreeCADGui.Control.activeDialog():
            FreeCAD.Console.PrintWarning("AeroNC: close the open task panel first\n")
            return True
        return self.setEdit(vobj)

