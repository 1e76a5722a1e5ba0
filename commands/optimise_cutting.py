"""AeroNC_OptimiseCutting: spindle speed and feeds of the selected ToolController, or of every
ToolController of the selected Job, by the cutting-parameter optimiser."""
import FreeCADGui

from aeronc.commands.base import Command


def selected_target():
    """The selected ToolController or Job (an operation stands for its ToolController); with
    nothing selected, the document's only Job. None otherwise."""
    from aeronc import pathcompat
    sel = FreeCADGui.Selection.getSelection()
    if len(sel) == 1:
        obj = sel[0]
        if pathcompat.is_tool_controller(obj) or pathcompat.is_job(obj):
            return obj
        if pathcompat.needs_tool_controller(obj):
            return pathcompat.tool_controller_of(obj)
        return None
    doc = FreeCADGui.ActiveDocument
    if not sel and doc is not None:
        jobs = pathcompat.find_jobs(doc.Document)
        return jobs[0] if len(jobs) == 1 else None
    return None


class OptimiseCutting(Command):
    ICON = "OptimiseCutting"
    MENU_TEXT = "Optimise cutting parameters"
    TOOLTIP = ("Choose the spindle speed and feed per tooth of the selected ToolController (or of every "
               "ToolController of the selected Job) for least time and cost, within the machine's force, "
               "power, feed and speed limits and the roughness limit; a_p and a_e come from the "
               "operations' paths")

    def target(self):
        return selected_target()

    def run(self, target):
        from aeronc.panels.optimise_cutting_panel import OptimiseCuttingPanel
        FreeCADGui.Control.showDialog(OptimiseCuttingPanel(target))
