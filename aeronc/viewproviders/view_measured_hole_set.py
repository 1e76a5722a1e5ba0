"""View provider of a measured-hole set: each datum hole's measured deviation dP drawn in the
3-D view as an arrow from the nominal hole, ArrowScale times longer than it is (purple); a datum
hole left out crossed out in red with its id and "left out"; double-click opens the set's task
panel (the deviations, the datum check, the method and its leave-one-out errors)."""
import FreeCAD

from aeronc.viewproviders import arrows
from aeronc.viewproviders.view_base import BaseView

USED = (0.55, 0.0, 0.75)  # apart from Path's red rapids
LEFT_OUT = (0.85, 0.0, 0.0)


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
        self.arrows = coin.SoSeparator()  # one child per arrow drawn
        self.left_out = coin.SoSeparator()
        self.root.addChild(self.arrows)
        self.root.addChild(self.left_out)
        vobj.addDisplayMode(self.root, "Arrows")
        self.rebuild(vobj.Object)

    def getDisplayModes(self, vobj):
        return ["Arrows"]

    def getDefaultDisplayMode(self):
        return "Arrows"

    def setDisplayMode(self, mode):
        return mode

    def updateData(self, obj, prop):
        if prop in ("Deviations", "Nominal", "ArrowScale", "LeftOut") and hasattr(self, "arrows"):
            self.rebuild(obj)

    def rebuild(self, obj):
        self.arrows.removeAllChildren()
        self.left_out.removeAllChildren()
        out = set(getattr(obj, "LeftOut", []))
        size = 6.0
        for hid, (a, b) in zip(obj.HoleIds, arrow_segments(obj)):
            left_out = hid in out
            node = arrows.arrow(a, b)
            if node is not None:
                self.arrows.addChild(arrows.coloured(LEFT_OUT if left_out else USED, node, line_width=4))
            if left_out:
                self.left_out.addChild(arrows.coloured(
                    LEFT_OUT, arrows.markers([a], "CROSS_9_9"), arrows.label(a + FreeCAD.Vector(size, size, size),
                                                                            "{} left out".format(hid)),
                    point_size=9))

    def arrow_count(self):
        return self.arrows.getNumChildren() if hasattr(self, "arrows") else 0

    def left_out_count(self):
        return self.left_out.getNumChildren() if hasattr(self, "left_out") else 0

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

