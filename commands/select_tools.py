"""AeroNC_SelectTools: plan the tools of the selected Machining Features tree."""
import FreeCADGui

from aeronc.commands.base import Command


def selected_machining_features():
    """The selected MachiningFeatures group (or the group of a selected element), else None."""
    from aeronc.objects import machining_features
    from aeronc.objects.base import descendants
    sel = FreeCADGui.Selection.getSelection()
    if len(sel) != 1:
        return None
    obj = sel[0]
    if machining_features.is_machining_features(obj):
        return obj
    # An element or setup: its group holds it (the part only links to the group, via Source).
    for candidate in getattr(obj, "InListRecursive", []):
        if machining_features.is_machining_features(candidate) and obj in descendants(candidate):
            return candidate
    return None


class SelectTools(Command):
    ICON = "SelectTools"
    MENU_TEXT = "Select tools"
    TOOLTIP = ("Choose the finishing and roughing tool of every pocket and the drill of every hole "
               "of the selected Machining Features from the knowledge base, merge roughing tool "
               "groups, and make the ToolControllers in the part's Job")

    def target(self):
        return selected_machining_features()

    def run(self, group):
        from aeronc.panels.select_tools_panel import SelectToolsPanel
        FreeCADGui.Control.showDialog(SelectToolsPanel(group))
