"""GUI side of the MachiningChain object: its icon; double-click opens the Machining chain
panel on it."""
from aeronc.viewproviders.view_base import BaseView


class ViewMachiningChain(BaseView):
    ICON = "MachiningChain"

    def attach(self, vobj):
        self.Object = vobj.Object

    def doubleClicked(self, vobj):
        import FreeCADGui
        obj = vobj.Object
        if FreeCADGui.Control.activeDialog() or obj.Features is None:
            return False
        from aeronc.panels.machining_chain_panel import MachiningChainPanel
        FreeCADGui.Control.showDialog(MachiningChainPanel(obj.Features, obj))
        return True

