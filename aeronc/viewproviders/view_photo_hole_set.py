"""View provider of a photo-hole set: each datum hole marked in the 3-D view with its number
in the camera order and its id; double-click opens the set's task panel."""
import FreeCAD

from aeronc.viewproviders.view_base import BaseView


class ViewPhotoHoleSet(BaseView):
    ICON = "PhotoHoleSet"

    def attach(self, vobj):
        super().attach(vobj)
        from pivy import coin
        self.root = coin.SoSeparator()
        self.markers = coin.SoSeparator()
        style = coin.SoDrawStyle()
        style.pointSize = 9
        style.lineWidth = 2
        colour = coin.SoBaseColor()
        colour.rgb = (0.0, 0.45, 0.2)
        self.root.addChild(style)
        self.root.addChild(colour)
        self.root.addChild(self.markers)
        vobj.addDisplayMode(self.root, "Markers")
        self.rebuild(vobj.Object)

    def getDisplayModes(self, vobj):
        return ["Markers"]

    def getDefaultDisplayMode(self):
        return "Markers"

    def setDisplayMode(self, mode):
        return mode

    def updateData(self, obj, prop):
        if prop in ("Positions", "Normals", "HoleIds") and hasattr(self, "markers"):
            self.rebuild(obj)

    def rebuild(self, obj):
        """A ring and a short normal at each datum hole, labelled 'n: id'."""
        from pivy import coin
        self.markers.removeAllChildren()
        part = getattr(obj, "Source", None)
        if part is None:
            return
        pl = part.Placement
        size = max(2.0, 1.5 * max(list(obj.Diameters) or [4.0]))
        for i, (hid, p, n) in enumerate(zip(obj.HoleIds, obj.Positions, obj.Normals)):
            a, d = pl.multVec(p), pl.Rotation.multVec(n)
            sep = coin.SoSeparator()
            coords = coin.SoCoordinate3()
            tip = a + d * (2 * size)
            coords.point.setValues(0, 2, [(a.x, a.y, a.z), (tip.x, tip.y, tip.z)])
            sep.addChild(coords)
            line = coin.SoLineSet()
            line.numVertices.setValue(2)
            sep.addChild(line)
            marker = coin.SoMarkerSet()
            marker.markerIndex = coin.SoMarkerSet.CIRCLE_LINE_9_9
            marker.startIndex = 0
            marker.numPoints = 1
            sep.addChild(marker)
            move = coin.SoTranslation()
            move.translation = (tip.x, tip.y, tip.z)
            sep.addChild(move)
            text = coin.SoText2()
            text.string = "{}: {}".format(i + 1, hid)
            sep.addChild(text)
            self.markers.addChild(sep)

    def setEdit(self, vobj, mode=0):
        import FreeCADGui
        from aeronc.panels.photo_hole_set_panel import PhotoHoleSetPanel
        FreeCADGui.Control.showDialog(PhotoHoleSetPanel(vobj.Object))
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
