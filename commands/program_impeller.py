"""AeroNC_ProgramImpeller: program the selected impeller solid (or edit a program's route)."""
import FreeCADGui

from aeronc.commands.base import Command


def selected_program():
    """The ImpellerProgram of the selection: a program, or its impeller features group or one of
    their nodes; else None."""
    from aeronc.objects.impeller_features import is_impeller_feature, is_impeller_features
    from aeronc.objects.impeller_program import is_impeller_program
    sel = FreeCADGui.Selection.getSelection()
    if len(sel) != 1:
        return None
    obj = sel[0]
    if is_impeller_program(obj):
        return obj
    if is_impeller_feature(obj):
        obj = next((g for g in obj.InList if is_impeller_features(g)), None)
    if obj is not None and is_impeller_features(obj):
        return next((p for p in obj.InList if is_impeller_program(p) and p.Features is obj), None)
    return None


def selected_bodies():
    """The selected object if exactly one object holding several solids (a part exported as
    separate bodies) is selected, else None."""
    sel = FreeCADGui.Selection.getSelection()
    if len(sel) != 1:
        return None
    shape = getattr(sel[0], "Shape", None)
    try:
        return sel[0] if shape is not None and not shape.isNull() and len(shape.Solids) > 1 else None
    except Exception:
        return None


def selected_target():
    """("program", obj), ("part", solid) or ("bodies", obj of several solids) for the selection,
    else None."""
    prog = selected_program()
    if prog is not None:
        return "program", prog
    from aeronc.commands.recognise_features import selected_solid
    part = selected_solid()
    if part is not None:
        return "part", part
    bodies = selected_bodies()
    return ("bodies", bodies) if bodies is not None else None


def ask_fuse(obj):
    """Whether the user wants obj's bodies fused into one solid (tests may replace this)."""
    from PySide import QtGui
    text = ("{} holds {} solids (bodies exported separately, e.g. a hub and its blades); impeller "
            "recognition needs one solid.\n\nFuse them into a new solid? The original is kept, hidden; "
            "one undo step removes the fused copy.").format(obj.Label, len(obj.Shape.Solids))
    answer = QtGui.QMessageBox.question(FreeCADGui.getMainWindow(), "AeroNC: Program impeller", text,
                                        QtGui.QMessageBox.Yes | QtGui.QMessageBox.No)
    return answer == QtGui.QMessageBox.Yes


class ProgramImpeller(Command):
    ICON = "Impeller"
    MENU_TEXT = "Program impeller"
    TOOLTIP = ("Recognise the selected impeller's blades, hub, fillets, shroud, bore and planes, make its blank "
               "and a Path Job with the process route's 5-axis operations, and post the 840D program; "
               "on a program: review and edit its route")

    def target(self):
        return selected_target()

    def run(self, found):
        from aeronc.panels.impeller_panel import ImpellerPanel
        kind, obj = found
        if kind == "bodies":
            if not ask_fuse(obj):
                return
            from aeronc.objects.fused_part import add_fused_part
            obj, _ = add_fused_part(obj)
            kind = "part"
        panel = ImpellerPanel(program=obj) if kind == "program" else ImpellerPanel(part=obj)
        FreeCADGui.Control.showDialog(panel)
