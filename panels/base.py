"""What AeroNC's task panels share: one way to report an error the user can act on, and the
file dialogs. Each panel module binds its own `show_error` (and the file dialogs it uses) as a
module attribute, so a test can replace it there."""
import FreeCAD
import FreeCADGui
from PySide import QtGui


def error_reporter(title):
    """show_error(text) for a panel: the report view and a message box titled "AeroNC: <title>"."""
    def show_error(text):
        FreeCAD.Console.PrintError("AeroNC: {}\n".format(text))
        QtGui.QMessageBox.critical(FreeCADGui.getMainWindow(), "AeroNC: {}".format(title), text)
    return show_error


def ask_open_file(caption, pattern):
    """A file to read, or ''."""
    return QtGui.QFileDialog.getOpenFileName(FreeCADGui.getMainWindow(), caption, "", pattern)[0]


def ask_save_file(caption, pattern, default):
    """A file to write, or ''."""
    return QtGui.QFileDialog.getSaveFileName(FreeCADGui.getMainWindow(), caption, default, pattern)[0]
