"""AeroNC_RecogniseFeatures: open the recognition task panel for the selected solid part."""
import FreeCADGui

from aeronc.commands.base import Command


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


class RecogniseFeatures(Command):
    ICON = "RecogniseFeatures"
    MENU_TEXT = "Recognise machining features"
    TOOLTIP = ("Recognise the pockets, openings and holes of the selected solid part "
               "by layered slicing, per setup direction, and add the machining-domain "
               "tree to the document")

    def target(self):
        return selected_solid()

    def run(self, part):
        from aeronc.panels.recognise_panel import RecognisePanel
        FreeCADGui.Control.showDialog(RecognisePanel(part=part))
