"""GUI side of the impeller objects: the ImpellerFeatures group colours its source solid by
role while it is visible (as the Machining Features group does, from the roles stored in its
Result); the nodes and the program have their icons; double-clicking the group or the program
opens the impeller route panel on the program."""
from aeronc.viewproviders.view_base import BaseView
from aeronc.viewproviders.view_machining_features import ViewMachiningFeatures


def _open_route_panel(program):
    import FreeCADGui
    if program is None or FreeCADGui.Control.activeDialog():
        return False
    from aeronc.panels.impeller_panel import ImpellerPanel
    FreeCADGui.Control.showDialog(ImpellerPanel(program))
    return True


def _program_of(group):
    from aeronc.objects.impeller_program import is_impeller_program
    for o in group.InList:
        if is_impeller_program(o) and o.Features is group:
            return o
    return None


class ViewImpellerFeatures(ViewMachiningFeatures):
    ICON = "Impeller"

    def doubleClicked(self, vobj):
        return _open_route_panel(_program_of(vobj.Object))

    def setEdit(self, vobj, mode=0):
        return None if mode != 0 else _open_route_panel(_program_of(vobj.Object))


class ViewImpellerFeature(BaseView):
    ICON = "Impeller"

    def attach(self, vobj):
        self.Object = vobj.Object


class ViewImpellerProgram(BaseView):
    ICON = "Impeller"

    def attach(self, vobj):
        self.Object = vobj.Object

    def doubleClicked(self, vobj):
        return _open_route_panel(vobj.Object)
