"""What the GUI test scripts share: checks with a pass/fail tally, a watchdog against a modal
dialog nobody closes, event pumping, driving the tree's context menu and the task dialog's
buttons, main-window screenshots, and the exit code."""
import os
import sys
import traceback

import FreeCADGui as Gui
from PySide import QtCore, QtGui

ARTIFACTS = os.environ.get("AERONC_ARTIFACTS", "/tmp")
TIMEOUT_S = 300
results = []


def _watchdog():
    # A modal dialog nobody closes would hang the test; Qt timers still fire inside it.
    print("TIMEOUT after {} s\n{} passed, {} failed".format(TIMEOUT_S, sum(results), len(results) - sum(results) + 1))
    sys.stdout.flush()
    os._exit(1)


def check(name, cond, detail=""):
    results.append(bool(cond))
    print("{} {}{}".format("PASS" if cond else "FAIL", name, "" if cond else ": {}".format(detail)))
    sys.stdout.flush()


def pump(seconds=0.2):
    """Let Qt deliver events and timers for a while (the script runs outside the event loop)."""
    timer = QtCore.QElapsedTimer()
    timer.start()
    while timer.elapsed() < seconds * 1000:
        QtGui.QApplication.processEvents(QtCore.QEventLoop.AllEvents, 50)


def aeronc_objects(doc):
    from aeronc.objects import proxy_type
    return [o for o in doc.Objects if (proxy_type(o) or "").startswith("AeroNC::")]


def tree_labels():
    labels = set()
    for tree in Gui.getMainWindow().findChildren(QtGui.QTreeWidget):
        it = QtGui.QTreeWidgetItemIterator(tree)
        while it.value():
            labels.add(it.value().text(0))
            it += 1
    return labels


def tree_context_menu():
    """Texts of the tree view's real context menu (opened by an event, closed by a timer)."""
    found = []

    def grab():
        popup = QtGui.QApplication.activePopupWidget()
        if popup is None:
            QtCore.QTimer.singleShot(50, grab)
            return
        found.extend(a.text() for a in popup.actions())
        popup.close()
    tree = next(t for t in Gui.getMainWindow().findChildren(QtGui.QTreeWidget) if t.isVisible())
    QtCore.QTimer.singleShot(100, grab)
    event = QtGui.QContextMenuEvent(QtGui.QContextMenuEvent.Mouse, QtCore.QPoint(20, 20))
    QtGui.QApplication.sendEvent(tree.viewport(), event)  # runs the menu until grab closes it
    return found


def click_ok(which=QtGui.QDialogButtonBox.Ok):
    """Press OK (or which) of the task dialog the way a user does (the task panel's accept
    or reject path)."""
    for box in Gui.getMainWindow().findChildren(QtGui.QDialogButtonBox):
        button = box.button(which)
        if button is not None and button.isVisible() and button.isEnabled():
            button.click()
            return True
    return False


def combo_view_width():
    """Width of the Combo View dock, where the task panels show (FreeCAD's default is about 260 px
    on a 1280 px screen)."""
    docks = [d for d in Gui.getMainWindow().findChildren(QtGui.QDockWidget)
             if d.objectName() == "Combo View" and d.isVisible()]
    return docks[0].width() if docks else None


def fits_combo_view(panel_form, default_width):
    """(fits, detail): the open task panel left the Combo View at its default width, and its form
    is no wider than the view shows."""
    pump(0.3)
    width = combo_view_width()
    form = panel_form.width()
    view = panel_form.parentWidget()
    while view is not None and not isinstance(view, QtGui.QScrollArea):
        view = view.parentWidget()
    # The task view's content against what its viewport shows (less any vertical scroll bar).
    content = view.widget().width() if view is not None else form
    shown = view.viewport().width() if view is not None else width
    ok = width is not None and width <= default_width + 2 and content <= shown
    return ok, "combo view {} px (default {}), task panel {} px shown in {} px".format(
        width, default_width, content, shown)


def window_shot(doc, name):
    """The main window with doc's 3-D view painted in (a grab leaves it blank under Xvfb);
    saved as <ARTIFACTS>/<name>.png, whose path is returned."""
    os.makedirs(ARTIFACTS, exist_ok=True)
    mw = Gui.getMainWindow()
    pump(0.5)
    shot_all = mw.grab()
    subs = [w for w in mw.findChild(QtGui.QMdiArea).subWindowList() if doc.Name in w.windowTitle()]
    if subs:
        view_widget = subs[-1].widget()
        view_png = os.path.join(ARTIFACTS, name + "_view.png")
        Gui.activeDocument().activeView().saveImage(view_png, view_widget.width(), view_widget.height(), "Current")
        painter = QtGui.QPainter(shot_all)
        painter.drawImage(view_widget.mapTo(mw, QtCore.QPoint(0, 0)), QtGui.QImage(view_png))
        painter.end()
    path = os.path.join(ARTIFACTS, name + ".png")
    shot_all.save(path)
    print("screenshot:", path)
    return path


def main(run):
    """Run the test body under the watchdog and end FreeCAD: exit 0 when every check passed."""
    QtCore.QTimer.singleShot(TIMEOUT_S * 1000, _watchdog)
    try:
        run()
    except Exception:
        traceback.print_exc()
        results.append(False)
    passed = sum(results)
    print("{} passed, {} failed".format(passed, len(results) - passed))
    sys.stdout.flush()
    os._exit(0 if results and all(results) else 1)
