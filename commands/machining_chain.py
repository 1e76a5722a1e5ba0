"""AeroNC_MachiningChain: build or edit the NC machining chain of the selected Machining
Features (or of the selected chain) and make its Path Jobs."""
import FreeCADGui

from aeronc.commands.base import Command


def selected_chain_source():
    """(Machining Features group, MachiningChain or None) of the selection, or None: a selected
    chain, or a group (or one of its elements) with the chain built from it, if any."""
    from aeronc.commands.select_tools import selected_machining_features
    from aeronc.objects import machining_chain
    sel = FreeCADGui.Selection.getSelection()
    if len(sel) == 1 and machining_chain.is_machining_chain(sel[0]):
        return (sel[0].Features, sel[0]) if sel[0].Features is not None else None
    group = selected_machining_features()
    if group is None:
        return None
    chains = machining_chain.chains_of_features(group)
    return group, (chains[0] if chains else None)


class MachiningChain(Command):
    ICON = "MachiningChain"
    MENU_TEXT = "Machining chain"
    TOOLTIP = ("Fuse a process template with the selected Machining Features into the NC machining chain "
               "(setups, processes, steps, programs, tools, units), review and edit it, and make a Path Job "
               "per setup with an operation for every unit")

    def target(self):
        return selected_chain_source()

    def run(self, found):
        from aeronc.panels.machining_chain_panel import MachiningChainPanel
        FreeCADGui.Control.showDialog(MachiningChainPanel(*found))
