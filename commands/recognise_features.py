"""AeroNC_RecogniseFeatures: open the recognition task panel for the selected solid part."""
import FreeCADGui

import aeronc


def selected_solid():
    """The selected part object if exactly one object with one solid is selected, else None."""
    sel = FreeCADGui.Selection.getSelection()
    if len(sel) != 1:
        return None
    shape = getattr(sel[0], "Shape", None)
    if shape is None or not hasattr(shape, "Solids"):
        return None
    try:
        return sel[0] if not shape.isNull() and len(shape.Solids) == 1 else None
    except Exception:
        return None


class RecogniseFeatures:
    def GetResources(self):
        return {"Pixmap": aeronc.icon("RecogniseFeatures"),
                "MenuText": "Recognise machining features",
                "ToolTip": "Recognise the pockets, openings and holes of the selected solid part "
                           "by layered slicing, per setup direction, and add the machining-domain "
                           "tree to the document"}

    def IsActive(self):
        return FreeCADGui.ActiveDocument is not None and not FreeCADGui.Control.activeDialog() \
            and selected_solid() is not None

    def Activated(self):
        part = selected_solid()
        if part is None:
            return
        from aeronc.panels.recognise_panel import RecognisePanel
        FreeCADGui.Control.showDialog(RecognisePanel(part=part))
