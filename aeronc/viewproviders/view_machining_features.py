"""View provider of the MachiningFeatures group.

While the group is visible it colours the source part's faces by the role recognition gave
them (DiffuseColor, one colour per face); it keeps the part's own colours in its state
(saved with the document) and puts them back when hidden or deleted.
"""
import FreeCAD
import FreeCADGui

from aeronc.viewproviders.view_base import BaseView

from aeronc.feature_colours import ROLE_COLOURS, UNKNOWN_ROLE


def role_colours(roles):
    """DiffuseColor list for a faceRoles list ((r, g, b, transparency) per face)."""
    return [ROLE_COLOURS.get(r, UNKNOWN_ROLE) + (0.0,) for r in roles]


class ViewMachiningFeatures(BaseView):
    ICON = "MachiningFeatures"

    def __init__(self, vobj):
        self.saved_colours = None  # the source part's DiffuseColor before colouring
        self.source_name = None
        super().__init__(vobj)

    def attach(self, vobj):
        super().attach(vobj)
        if not hasattr(self, "saved_colours"):
            self.saved_colours, self.source_name = None, None

    def updateData(self, obj, prop):
        if prop == "Result" and obj.ViewObject.Visibility:
            self.colour_source(obj)

    def onChanged(self, vobj, prop):
        if prop == "Visibility":
            if vobj.Visibility:
                self.colour_source(vobj.Object)
            else:
                self.restore_source()

    def colour_source(self, obj):
        try:
            from aeronc.objects import result_of
            result = result_of(obj)
            src = obj.Source
            vsrc = getattr(src, "ViewObject", None)
            roles = result.get("faceRoles", [])
            if vsrc is None or not roles:
                return
            if len(roles) != len(src.Shape.Faces):
                FreeCAD.Console.PrintWarning(
                    "AeroNC: {} has {} faces, the result {}: not colouring it\n"
                    .format(src.Label, len(src.Shape.Faces), len(roles)))
                return
            if self.saved_colours is None or self.source_name != src.Name:
                self.restore_source()
                self.saved_colours = [tuple(c) for c in vsrc.DiffuseColor] or [tuple(vsrc.ShapeColor)]
                self.source_name = src.Name
            vsrc.DiffuseColor = role_colours(roles)
        except Exception as e:  # colouring is a courtesy: never break the document
            FreeCAD.Console.PrintWarning("AeroNC: could not colour the part: {}\n".format(e))

    def restore_source(self):
        if self.saved_colours is None:
            return
        try:
            src = self.Object.Document.getObject(self.source_name)
            vsrc = getattr(src, "ViewObject", None)
            if vsrc is not None:
                vsrc.DiffuseColor = self.saved_colours
        except Exception as e:
            FreeCAD.Console.PrintWarning("AeroNC: could not restore the part colours: {}\n".format(e))
        self.saved_colours, self.source_name = None, None

    def onDelete(self, vobj, subelements):
        # Deleting the root deletes the whole tree, and the part gets its colours back
        # (makers.remove_machining_features hides the group first, which does the same).
        self.restore_source()
        obj = vobj.Object
        doc = obj.Document
        from aeronc.objects import descendants
        for child in descendants(obj):
            if doc.getObject(child.Name) is not None:
                doc.removeObject(child.Name)
        return True

    def doubleClicked(self, vobj):
        FreeCADGui.ActiveDocument.setEdit(vobj.Object.Name, 0)
        return True

    def setEdit(self, vobj, mode=0):
        if mode != 0:
            return None  # let FreeCAD handle transform etc.
        from aeronc.panels.recognise_panel import RecognisePanel
        FreeCADGui.Control.showDialog(RecognisePanel(group=vobj.Object))
        return True

    def unsetEdit(self, vobj, mode=0):
        if mode != 0:
            return None
        FreeCADGui.Control.closeDialog()
        return True

    def __getstate__(self):
        return {"saved_colours": self.saved_colours, "source_name": self.source_name}

    def __setstate__(self, state):
        state = state or {}
        colours = state.get("saved_colours")
        self.saved_colours = [tuple(c) for c in colours] if colours is not None else None
        self.source_name = state.get("source_name")
