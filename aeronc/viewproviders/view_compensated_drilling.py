"""View provider of the compensated drilling operation: Path draws its moves; this gives the
operation its icon and opens its measurements' panel on a double-click."""
from aeronc.viewproviders.view_base import BaseView


class ViewCompensatedDrilling(BaseView):
    ICON = "CompensatedDrilling"

    def doubleClicked(self, vobj):
        import FreeCADGui
        ms = getattr(vobj.Object, "MeasuredHoleSet", None)
        if ms is None or FreeCADGui.Control.activeDialog():
            return False
        from aeronc.panels.measured_hole_set_panel import MeasuredHoleSetPanel
        FreeCADGui.Control.showDialog(MeasuredHoleSetPanel(ms))
        return True
