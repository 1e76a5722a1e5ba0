"""View provider of the compensated drilling operation: Path draws its moves; this draws each
drilled hole's correction as an arrow from its nominal position (blue, as long as the measured
set's ArrowScale makes the datum deviations), rings round the flagged holes (orange: beyond the
tolerance; red, filled: against their neighbours' corrections; the Flags list names them), gives
the operation its icon and opens its measurements' panel on a double-click."""
import json

import FreeCAD

from aeronc.viewproviders import arrows
from aeronc.viewproviders.view_base import BaseView

CORRECTION = (0.12, 0.37, 0.75)
BEYOND = (0.88, 0.5, 0.0)
AGAINST = (0.85, 0.0, 0.0)


def correction_arrows(obj):
    """[(start, end, hole)] of the correction arrows in the document frame; hole is the core's
    result for the hole (correction, flags)."""
    result = json.loads(obj.Report) if obj.Report else {}
    part = obj.Source
    pl = part.Placement if part is not None else FreeCAD.Placement()
    ms = obj.MeasuredHoleSet
    scale = ms.ArrowScale if ms is not None else 100.0
    out = []
    for h in result.get("holes", []):
        a = pl.multVec(FreeCAD.Vector(*h["nominal"]))
        out.append((a, a + pl.Rotation.multVec(FreeCAD.Vector(*h["correction"])) * scale, h))
    return out


class ViewCompensatedDrilling(BaseView):
    ICON = "CompensatedDrilling"

    def attach(self, vobj):
        super().attach(vobj)
        from pivy import coin
        # Path's view provider owns the display modes; this switch sits beside them in the root
        # and follows the operation's visibility.
        self.switch = coin.SoSwitch()
        self.corrections = coin.SoSeparator()
        self.flagged = coin.SoSeparator()
        self.switch.addChild(self.corrections)
        self.switch.addChild(self.flagged)
        vobj.RootNode.addChild(self.switch)
        self.onChanged(vobj, "Visibility")
        self.rebuild(vobj.Object)

    def onChanged(self, vobj, prop):
        if prop == "Visibility" and hasattr(self, "switch"):
            from pivy import coin
            self.switch.whichChild = coin.SO_SWITCH_ALL if vobj.Visibility else coin.SO_SWITCH_NONE

    def updateData(self, obj, prop):
        if prop in ("Report", "Corrections", "Flagged") and hasattr(self, "corrections"):
            self.rebuild(obj)

    def rebuild(self, obj):
        self.corrections.removeAllChildren()
        self.flagged.removeAllChildren()
        drawn = correction_arrows(obj)
        heads = [n for n in (arrows.arrow(a, b) for a, b, _ in drawn) if n is not None]
        self.drawn = len(heads)
        self.corrections.addChild(arrows.coloured(CORRECTION, *heads, line_width=2))
        beyond = [a for a, _, h in drawn if h["exceeds_tolerance"]]
        against = [a for a, _, h in drawn if h["against_neighbours"]]
        self.rings = (len(beyond), len(against))
        if beyond:
            self.flagged.addChild(arrows.coloured(BEYOND, arrows.markers(beyond, "CIRCLE_LINE_9_9")))
        if against:
            self.flagged.addChild(arrows.coloured(AGAINST, arrows.markers(against, "CIRCLE_FILLED_9_9")))

    def correction_count(self):
        """Correction arrows drawn (a hole without a correction draws none)."""
        return getattr(self, "drawn", 0)

    def flagged_count(self):
        """Holes ringed: (beyond the tolerance, against their neighbours)."""
        return getattr(self, "rings", (0, 0))

    def doubleClicked(self, vobj):
        import FreeCADGui
        ms = getattr(vobj.Object, "MeasuredHoleSet", None)
        if ms is None or FreeCADGui.Control.activeDialog():
            return False
        from aeronc.panels.measured_hole_set_panel import MeasuredHoleSetPanel
        FreeCADGui.Control.showDialog(MeasuredHoleSetPanel(ms))
        return True
