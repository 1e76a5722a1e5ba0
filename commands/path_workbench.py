"""Puts AeroNC's commands into FreeCAD 0.20's Path workbench (0.20 has no
WorkbenchManipulator): an "AeroNC" menu in Path's menu bar, an "AeroNC" toolbar, and the
context menu of the 3-D view and tree: the commands for a selected solid, Select tools and
Machining chain for Machining Features, Machining chain for a chain, Optimise cutting
parameters for a Job, ToolController or operation, Define as datum (photo) hole for
selected holes, and the camera program, measurements and compensated drilling for a
photo-hole or measured-hole set.

Path's workbench object is set up lazily on its first activation, so the menu and toolbar
are added when the main window reports that Path has been activated, and the workbench is
then reloaded to show them. The context menu is extended by wrapping the workbench
object's ContextMenu, which FreeCAD looks up on the object each time it builds a menu.
"""
import FreeCAD
import FreeCADGui

PATH_WORKBENCH = "PathWorkbench"
MENU = "AeroNC"
TOOLBAR = "AeroNC"


def install():
    """Register the commands and the view providers, and hook into the Path workbench (called
    from InitGui)."""
    from aeronc import commands, viewproviders
    viewproviders.install()
    commands.register()
    FreeCADGui.getMainWindow().workbenchActivated.connect(_on_workbench_activated)


def _on_workbench_activated(name):
    if name != PATH_WORKBENCH:
        return
    try:
        wb = FreeCADGui.getWorkbench(PATH_WORKBENCH)
        if extend(wb):
            wb.reloadActive()
        from PySide import QtCore
        QtCore.QTimer.singleShot(0, own_row)
    except Exception as e:
        FreeCAD.Console.PrintError("AeroNC: could not extend the Path workbench: {}\n".format(e))


def own_row():
    """Start the AeroNC toolbar on a row of its own: behind Path's nine toolbars it would fall
    into the overflow menu of a 1600 px window. A toolbar the user moved to another area or
    row stays where it is."""
    from PySide import QtCore, QtGui
    mw = FreeCADGui.getMainWindow()
    bar = next((t for t in mw.findChildren(QtGui.QToolBar) if t.objectName() == TOOLBAR and t.isVisible()), None)
    if bar is None or mw.toolBarArea(bar) != QtCore.Qt.TopToolBarArea:
        return
    tops = [t for t in mw.findChildren(QtGui.QToolBar)
            if t.isVisible() and mw.toolBarArea(t) == QtCore.Qt.TopToolBarArea and t is not bar]
    if all(t.y() != bar.y() for t in tops):
        return  # already alone on its row
    mw.addToolBarBreak(QtCore.Qt.TopToolBarArea)
    mw.addToolBar(QtCore.Qt.TopToolBarArea, bar)  # moved behind the break: the last row, its own
    bar.show()


def extend(wb):
    """Add AeroNC's menu, toolbar and context menu to workbench wb; True if anything was
    added (it is idempotent)."""
    from aeronc.commands import COMMANDS, DRILLING_COMMANDS
    changed = False
    if TOOLBAR not in wb.listToolbars():
        wb.appendToolbar(TOOLBAR, COMMANDS + DRILLING_COMMANDS)
        changed = True
    if MENU not in wb.listMenus():
        wb.appendMenu(MENU, COMMANDS + ["Separator"] + DRILLING_COMMANDS)
        changed = True
    if not getattr(wb, "_aeronc_context_menu", False):
        original = wb.ContextMenu

        def context_menu(recipient):
            try:
                original(recipient)  # Path's own items (its errors still reach FreeCAD)
            finally:
                from aeronc.commands.machining_chain import selected_chain_source
                from aeronc.commands.program_impeller import selected_program
                from aeronc.commands.optimise_cutting import selected_target
                from aeronc.commands.recognise_features import selected_solid
                from aeronc.commands.select_tools import selected_machining_features
                from aeronc.commands import datum_holes
                from aeronc.commands.show_setup import selected_chain_job
                if selected_chain_job() is not None:
                    wb.appendContextMenu("", ["Separator", "AeroNC_ShowSetup"])
                elif datum_holes.selected_holes() is not None:
                    wb.appendContextMenu("", ["Separator", "AeroNC_DefineDatumHoles"])
                elif datum_holes.selected_photo_set() is not None or datum_holes.selected_measured_set() is not None:
                    wb.appendContextMenu("", ["Separator"] + DRILLING_COMMANDS[1:])
                elif selected_machining_features() is not None:
                    wb.appendContextMenu("", ["Separator", "AeroNC_SelectTools", "AeroNC_MachiningChain"])
                elif selected_program() is not None:
                    wb.appendContextMenu("", ["Separator", "AeroNC_ProgramImpeller"])
                elif selected_chain_source() is not None:
                    wb.appendContextMenu("", ["Separator", "AeroNC_MachiningChain"])
                elif FreeCADGui.Selection.getSelection() and selected_target() is not None:
                    wb.appendContextMenu("", ["Separator", "AeroNC_OptimiseCutting"])
                elif selected_solid() is not None:
                    wb.appendContextMenu("", ["Separator"] + COMMANDS)

        wb.ContextMenu = context_menu
        wb._aeronc_context_menu = True
    return changed
