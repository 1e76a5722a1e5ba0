"""What AeroNC's commands share: their resources, when they are active, and one error dialog
for the failures the user can act on (AeroNCError)."""
import FreeCAD
import FreeCADGui

import aeronc
from aeronc.errors import AeroNCError


def show_error(title, text):
    """Report to the report view and a message box (tests may replace this)."""
    from PySide import QtGui
    FreeCAD.Console.PrintError("AeroNC: {}\n".format(text))
    QtGui.QMessageBox.critical(FreeCADGui.getMainWindow(), "AeroNC: {}".format(title), text)


class Command:
    """A FreeCAD command. A subclass sets ICON (a name in resources/icons), MENU_TEXT and
    TOOLTIP, and defines target() and run(target).

    It is active while no task dialog is open, a document is (unless NEEDS_DOCUMENT is False)
    and target() is not None; run(target) gets what target() returned. An AeroNCError from
    run is shown in a message box named after the command; anything else is a bug and goes
    to FreeCAD with its traceback."""
    ICON = "AeroNC"
    MENU_TEXT = ""
    TOOLTIP = ""
    NEEDS_DOCUMENT = True

    def target(self):
        """What the command works on (the selection, typically); None: it cannot run now."""
        return True

    def run(self, target):
        raise NotImplementedError

    def GetResources(self):
        return {"Pixmap": aeronc.icon(self.ICON), "MenuText": self.MENU_TEXT, "ToolTip": self.TOOLTIP}

    def IsActive(self):
        if self.NEEDS_DOCUMENT and FreeCADGui.ActiveDocument is None:
            return False
        return not FreeCADGui.Control.activeDialog() and self.target() is not None

    def Activated(self):
        target = self.target()
        if target is None:
            return
        try:
            self.run(target)
        except AeroNCError as e:
            show_error(self.MENU_TEXT.rstrip("."), str(e))
