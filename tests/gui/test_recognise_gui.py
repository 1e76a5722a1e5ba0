"""GUI test of AeroNC in FreeCAD's Path workbench. Runs inside the FreeCAD GUI:

    HOME=<temp home> QTWEBENGINE_DISABLE_SANDBOX=1 xvfb-run -a freecad tests/gui/test_recognise_gui.py

The installed addon is found on FreeCAD's Mod path (or in env AERONC_MOD_DIR). A screenshot
of the coloured part goes to env AERONC_ARTIFACTS (default /tmp). Prints "N passed, N failed"
and ends FreeCAD with exit code 0 when all checks pass, 1 otherwise.
"""
import os
import sys

import FreeCAD
import FreeCADGui as Gui

# Without this preference a modal warning blocks the first activation of Path.
FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Mod/Path").SetBool("WarningSuppressVelocity", True)

_mod = os.environ.get("AERONC_MOD_DIR")
if _mod and os.path.isdir(os.path.join(_mod, "aeronc")) and _mod not in sys.path:
    sys.path.insert(0, _mod)

from PySide import QtCore, QtGui  # noqa: E402
from aeronc.tests.gui.harness import (  # noqa: E402
    ARTIFACTS, aeronc_objects, check, click_ok, main, pump, tree_context_menu, tree_labels, window_shot)



HEADLESS_SCRIPT = """
import os, FreeCAD, Part
from aeronc import _core, makers
doc = FreeCAD.newDocument("Headless")
shape = Part.Shape()
shape.importBrepFromString(_core.make_panel('{{"pocketsX": 2, "pocketsY": 1}}')[0])
part = doc.addObject("Part::Feature", "Panel")
part.Shape = shape
doc.recompute()
makers.create_machining_features(doc, part, directions=[(0, 0, 1)])
doc.saveAs({path!r})
os._exit(0)
"""


def cancel_progress():
    """Press Cancel of the recognition progress dialog (runs from a timer during recognition)."""
    for dialog in Gui.getMainWindow().findChildren(QtGui.QProgressDialog):
        if dialog.isVisible():
            dialog.cancel()
            return
    QtCore.QTimer.singleShot(10, cancel_progress)


def run():
    import aeronc
    from aeronc import _core, objects
    from aeronc.commands import path_workbench
    from aeronc.panels import recognise_panel
    from aeronc.panels.recognise_panel import RecognisePanel
    from aeronc.viewproviders.view_machining_features import role_colours
    print("aeronc from", os.path.dirname(aeronc.__file__))
    mw = Gui.getMainWindow()
    original_show_error = recognise_panel.show_error

    # -- the hook into the Path workbench ---------------------------------------------
    Gui.activateWorkbench("PathWorkbench")
    pump()
    check("Path workbench active", Gui.activeWorkbench().name() == "PathWorkbench")
    wb = Gui.getWorkbench("PathWorkbench")
    check("AeroNC toolbar listed", "AeroNC" in wb.listToolbars(), wb.listToolbars())
    bars = [t for t in mw.findChildren(QtGui.QToolBar) if t.objectName() == "AeroNC"]
    check("AeroNC toolbar shown", bars and bars[0].isVisible() and
          any(a.text() == "Recognise machining features" for a in bars[0].actions()))
    if bars:
        pump(1.0)  # the toolbar moves to its row after the workbench is shown
        hidden = [a.text() for a in bars[0].actions()
                  if not a.isSeparator() and not (bars[0].widgetForAction(a) and bars[0].widgetForAction(a).isVisible())]
        check("every AeroNC button on the toolbar, none in its overflow menu", not hidden,
              (hidden, mw.toolBarBreak(bars[0]), bars[0].geometry(), mw.width()))
    menus = {a.text().replace("&", ""): [m.text() for m in a.menu().actions()]
             for a in mw.menuBar().actions() if a.menu()}
    check("AeroNC menu in Path's menu bar", "Recognise machining features" in menus.get("AeroNC", []),
          sorted(menus))
    # the hook survives switching workbenches and back, without duplicating
    Gui.activateWorkbench("PartWorkbench")
    pump()
    check("no AeroNC toolbar outside Path", not any(t.isVisible() for t in mw.findChildren(QtGui.QToolBar)
                                                     if t.objectName() == "AeroNC"))
    Gui.activateWorkbench("PathWorkbench")
    pump()
    check("toolbar back once", wb.listToolbars().count("AeroNC") == 1 and
          sum(1 for t in mw.findChildren(QtGui.QToolBar) if t.objectName() == "AeroNC" and t.isVisible()) == 1)

    # -- a generated integral panel -------------------------------------------------------
    import Part
    doc = FreeCAD.newDocument("AeroNCGui")
    brep, _truth = _core.make_panel("{}")
    shape = Part.Shape()
    shape.importBrepFromString(brep)
    part = doc.addObject("Part::Feature", "Panel")
    part.Shape = shape
    doc.recompute()
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    cmd = Gui.Command.get("AeroNC_RecogniseFeatures")
    Gui.Selection.clearSelection()
    pump()
    check("command inactive without selection", not cmd.isActive())
    Gui.Selection.addSelection(part)
    pump()
    check("command active with a solid selected", cmd.isActive())

    # context menu of the 3-D view: run Path's ContextMenu as FreeCAD does, capture the items
    appended = []
    wb.appendContextMenu = lambda menu, cmds: appended.append(cmds)
    try:
        wb.ContextMenu("View")
    except Exception:
        pass  # Path 0.20's own ContextMenu fails on objects without Proxy; ours still runs
    finally:
        del wb.appendContextMenu
    check("3-D view context menu entry for a solid", any("AeroNC_RecogniseFeatures" in c for c in appended),
          appended)
    check("tree context menu entry for a solid", "Recognise machining features" in tree_context_menu())

    # -- the command opens the panel; OK recognises ------------------------------------------
    undo_before = doc.UndoCount
    Gui.runCommand("AeroNC_RecogniseFeatures")
    pump()
    panel = RecognisePanel.current
    check("task panel open", Gui.Control.activeDialog() and panel is not None)
    from aeronc.feature_colours import ROLE_COLOURS as _roles
    swatches = panel.form.findChildren(QtGui.QLabel, QtCore.QRegExp("legend_.*")) if panel else []
    check("the panel's legend shows the role colours", len(swatches) == len(recognise_panel.LEGEND) and
          all(r in _roles for r, _ in recognise_panel.LEGEND) and
          {"wall", "floor", "unclaimed"} <= {s.objectName()[len("legend_"):] for s in swatches},
          [s.objectName() for s in swatches])
    shot = window_shot(doc, "aeronc_recognise_panel")
    check("panel screenshot saved", os.path.getsize(shot) > 20000, shot)
    panel.direction.setCurrentIndex(3)  # +Z and -Z

    # Cancel in the progress dialog: nothing added, no error box, the panel stays open.
    errors = []
    recognise_panel.show_error = errors.append
    QtCore.QTimer.singleShot(0, cancel_progress)
    check("OK pressed (to cancel)", click_ok())
    pump()
    check("cancel adds nothing", not aeronc_objects(doc) and not errors and Gui.Control.activeDialog(),
          (aeronc_objects(doc), errors))
    recognise_panel.show_error = original_show_error

    check("OK pressed", click_ok())
    pump(0.5)
    groups = [o for o in doc.Objects if objects.is_machining_features(o)]
    check("one MachiningFeatures group", len(groups) == 1, [o.Name for o in doc.Objects])
    check("task panel closed", not Gui.Control.activeDialog())
    if not groups:
        return
    group = groups[0]
    result = objects.result_of(group)
    setups = [o for o in group.Group]
    elements = [o for o in doc.Objects if objects.proxy_type(o) == objects.DOMAIN_ELEMENT]
    check("setups in tree", len(setups) == len(result["setups"]) == 2, len(setups))
    check("elements in tree", len(elements) == len(result["elements"]) == group.ElementCount > 0,
          (len(elements), len(result["elements"])))
    labels = tree_labels()
    check("tree view shows the group and elements", group.Label in labels and
          all(e.Label in labels for e in elements), [group.Label] + [e.Label for e in elements[:3]])
    check("one undo step", doc.UndoCount == undo_before + 1, doc.UndoNames)
    check("group has its view provider and icon", group.ViewObject.Proxy is not None and
          os.path.isfile(group.ViewObject.Proxy.getIcon()))
    colours = [tuple(round(c, 3) for c in col[:3]) for col in part.ViewObject.DiffuseColor]
    expected = [tuple(round(c, 3) for c in col[:3]) for col in role_colours(result["faceRoles"])]
    check("part faces coloured by role", colours == expected, (len(colours), len(expected)))

    # undo takes the whole tree and the colours away in one step; redo brings them back
    doc.undo()
    pump()
    check("undo removes the tree and the colours", not aeronc_objects(doc) and
          len(part.ViewObject.DiffuseColor) == 1, (len(aeronc_objects(doc)), len(part.ViewObject.DiffuseColor)))
    doc.redo()
    pump()
    group = doc.getObject(group.Name)
    check("redo restores them", len(aeronc_objects(doc)) == 1 + len(setups) + len(elements) and
          len(part.ViewObject.DiffuseColor) == len(part.Shape.Faces) and group.ViewObject.Proxy is not None,
          (len(aeronc_objects(doc)), len(part.ViewObject.DiffuseColor)))
    elements = [o for o in doc.Objects if objects.proxy_type(o) == objects.DOMAIN_ELEMENT]

    Gui.Selection.clearSelection()
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    pump(0.5)
    os.makedirs(ARTIFACTS, exist_ok=True)
    shot = os.path.join(ARTIFACTS, "aeronc_recognised_panel.png")
    Gui.activeDocument().activeView().saveImage(shot, 1280, 960, "White")
    check("screenshot saved", os.path.getsize(shot) > 10000, shot)
    print("screenshot:", shot)

    # selecting an element selects the faces it machines
    el = next(e for e in elements if e.Faces)
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(el)
    pump()
    pump()
    want = set(el.Faces[0][1])
    check("selecting an element selects the element alone (its properties in the editor)",
          [o.Name for o in Gui.Selection.getSelection()] == [el.Name], [o.Name for o in Gui.Selection.getSelection()])
    from aeronc.viewproviders.face_highlight import HIGHLIGHT
    painted = {"Face{}".format(i + 1) for i, c in enumerate(part.ViewObject.DiffuseColor)
               if all(abs(a - b) < 1e-3 for a, b in zip(c[:3], HIGHLIGHT))}
    check("element selection paints its faces in the selection colour", painted == want, (painted, want))
    # FreeCAD's selection green is no role colour: selected faces stand out on any role.
    from aeronc.feature_colours import ROLE_COLOURS
    check("no role has the selection colour", all(max(abs(a - b) for a, b in zip(c, HIGHLIGHT)) > 0.2
                                                  for c in ROLE_COLOURS.values()))
    # What a person sees: the tree opened on the machining-domain tree, an element selected.
    for tree_view in Gui.getMainWindow().findChildren(QtGui.QTreeWidget):
        tree_view.expandAll()
    window = window_shot(doc, "aeronc_main_window")
    check("main window screenshot saved", os.path.getsize(window) > 20000, window)
    Gui.Selection.clearSelection()
    pump()
    painted = [i for i, c in enumerate(part.ViewObject.DiffuseColor)
               if all(abs(a - b) < 1e-3 for a, b in zip(c[:3], HIGHLIGHT))]
    check("the role colours come back when the element is no longer selected", not painted, painted)

    # double-click: the panel edits the group; OK recognises again into it
    count = group.ElementCount
    group.ViewObject.doubleClicked()
    pump()
    check("edit panel open", Gui.Control.activeDialog() and RecognisePanel.current is not None
          and RecognisePanel.current.group == group)
    check("edit panel shows the stored directions", RecognisePanel.current.direction.currentIndex() == 3)
    check("OK pressed in edit mode", click_ok())
    pump(0.5)
    check("edit closed, tree rebuilt", not Gui.Control.activeDialog() and group.ElementCount == count and
          len([o for o in doc.Objects if objects.proxy_type(o) == objects.DOMAIN_ELEMENT]) == count)

    # a failure shows an error, keeps the panel open and leaves the document unchanged
    face = doc.addObject("Part::Feature", "JustAFace")
    face.Shape = Part.makePlane(10, 10)
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(face)
    pump()
    check("command inactive for a face", not cmd.isActive())
    errors = []
    recognise_panel.show_error = errors.append
    try:
        names = [o.Name for o in doc.Objects]
        Gui.Control.showDialog(RecognisePanel(part=face))
        pump()
        click_ok()
        pump()
        check("error reported", errors and "not a solid" in errors[0], errors)
        check("panel stays open after an error", Gui.Control.activeDialog())
        check("document unchanged after an error", [o.Name for o in doc.Objects] == names)
        Gui.Control.closeDialog()
        pump()
    finally:
        recognise_panel.show_error = original_show_error

    # save and reopen: the view providers come back with the part's own colours kept
    doc.removeObject("JustAFace")
    path = os.path.join(ARTIFACTS, "aeronc_gui_test.FCStd")
    saved_colours = group.ViewObject.Proxy.saved_colours
    group_name = group.Name
    doc.saveAs(path)
    FreeCAD.closeDocument(doc.Name)
    pump()
    doc = FreeCAD.openDocument(path)
    pump()
    group, part = doc.getObject(group_name), doc.getObject("Panel")
    check("reopened group has its view provider", group.ViewObject.Proxy is not None and
          group.ViewObject.Proxy.saved_colours == saved_colours)
    check("reopened elements have view providers", all(o.ViewObject.Proxy is not None for o in aeronc_objects(doc)))
    check("reopened part still coloured", len(part.ViewObject.DiffuseColor) == len(part.Shape.Faces))

    # deleting the group removes its tree and gives the part its colours back
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(group)
    Gui.runCommand("Std_Delete")
    pump()
    check("delete removes the whole tree", not aeronc_objects(doc), [o.Name for o in aeronc_objects(doc)])
    check("part colours restored", len(part.ViewObject.DiffuseColor) == 1, len(part.ViewObject.DiffuseColor))
    FreeCAD.closeDocument(doc.Name)

    # a document made under freecadcmd opens with the tree shown and the part coloured
    path = os.path.join(ARTIFACTS, "aeronc_headless.FCStd")
    script = os.path.join(ARTIFACTS, "aeronc_make_headless.py")
    with open(script, "w") as f:
        f.write(HEADLESS_SCRIPT.format(path=path))
    import subprocess
    run = subprocess.run(["freecadcmd", script], capture_output=True, text=True, timeout=120)
    check("headless document made", run.returncode == 0 and os.path.isfile(path), run.stdout[-500:])
    doc = FreeCAD.openDocument(path)
    pump(0.5)
    group, part = doc.getObject("MachiningFeatures"), doc.getObject("Panel")
    check("headless document: view providers attached",
          all(o.ViewObject.Proxy is not None for o in aeronc_objects(doc)))
    check("headless document: tree shown, part coloured", group.ViewObject.Visibility and
          len(part.ViewObject.DiffuseColor) == len(part.Shape.Faces))

    # removed from a script (the App side, no view provider called): the part gets its colours
    # back, and undo brings the tree and the colours back
    from aeronc import makers
    count = len(aeronc_objects(doc))
    doc.UndoMode = 1
    makers.remove_machining_features(group)
    pump()
    check("script removal removes the tree", not aeronc_objects(doc), [o.Name for o in aeronc_objects(doc)])
    check("script removal restores the part colours", len(part.ViewObject.DiffuseColor) == 1,
          len(part.ViewObject.DiffuseColor))
    doc.undo()
    pump()
    group = doc.getObject("MachiningFeatures")
    check("undo of the removal brings the tree and the colours back", len(aeronc_objects(doc)) == count and
          group.ViewObject.Visibility and len(part.ViewObject.DiffuseColor) == len(part.Shape.Faces),
          (len(aeronc_objects(doc)), count, len(part.ViewObject.DiffuseColor)))

    # the panel offers the stock of a Path Job as the blank; Cancel closes it
    from aeronc import pathcompat
    job = pathcompat.create_job(doc, [part])
    doc.recompute()
    before = len(aeronc_objects(doc))
    panel = RecognisePanel(part=part)
    Gui.Control.showDialog(panel)
    pump()
    items = [panel.blank.itemText(i) for i in range(panel.blank.count())]
    panel.blank.setCurrentIndex(1)
    check("blank from the Job's stock", items == ["Part bounding box + allowance", "Stock of " + job.Label]
          and panel.settings()["blank"] == pathcompat.job_stock_box(job), items)
    check("Cancel pressed", click_ok(QtGui.QDialogButtonBox.Cancel))
    pump()
    check("Cancel closes the panel, adds nothing", not Gui.Control.activeDialog() and
          RecognisePanel.current is None and len(aeronc_objects(doc)) == before)
    FreeCAD.closeDocument(doc.Name)


main(run)
