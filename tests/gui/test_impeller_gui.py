"""GUI test of Program impeller, as a user drives it:

    HOME=<temp home> QTWEBENGINE_DISABLE_SANDBOX=1 xvfb-run -a freecad tests/gui/test_impeller_gui.py

A box: Program impeller refuses it with the core's message, the document unchanged. A generated
impeller (3 + 3 blades): select it, AeroNC > Program impeller, coarse toolpaths (4 stations, one
channel), Program; the part is coloured by role, the tree shows the blades, hub and the Job, the
route panel lists the steps; untick hub finishing, give the roughing another tool: each is one
undo step and the Job follows. Screenshots go to env AERONC_ARTIFACTS (default /tmp). Prints
"N passed, N failed"; exits 0 when all checks pass.
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

from PySide import QtCore  # noqa: E402
from aeronc.tests.gui import harness  # noqa: E402
from aeronc.tests.gui.harness import ARTIFACTS, check, main, pump, tree_context_menu, tree_labels, window_shot  # noqa: E402

SPEC = {"bladeCount": 3, "filletRadius": 2.0, "bladeHeight": 11.0}


def wait_for(cond, seconds=240):
    timer = QtCore.QElapsedTimer()
    timer.start()
    while not cond() and timer.elapsed() < seconds * 1000:
        pump(0.2)
    return cond()


def run():
    import Part
    from aeronc.tests.parts import impeller_part
    from aeronc.pipeline import knowledge_base
    from aeronc import pathcompat
    from aeronc.feature_colours import ROLE_COLOURS
    from aeronc.objects.impeller_program import is_impeller_program
    from aeronc.panels import impeller_panel
    from aeronc.panels.impeller_panel import ALLOWANCE, ON, STEP, TOOL, ImpellerPanel
    os.makedirs(ARTIFACTS, exist_ok=True)
    errors = []
    impeller_panel.show_error = errors.append
    kb_path = knowledge_base.user_kb_path()
    if os.path.exists(kb_path):
        os.remove(kb_path)

    Gui.activateWorkbench("PathWorkbench")
    pump()
    doc = FreeCAD.newDocument("Impeller")
    cmd = Gui.Command.get("AeroNC_ProgramImpeller")
    menus = {a.text().replace("&", ""): [m.text() for m in a.menu().actions()]
             for a in Gui.getMainWindow().menuBar().actions() if a.menu()}
    check("AeroNC menu lists Program impeller", "Program impeller" in menus.get("AeroNC", []), menus.get("AeroNC"))

    # A box is no impeller: the message, and nothing added.
    box = doc.addObject("Part::Feature", "Box")
    box.Shape = Part.makeBox(40, 30, 20)
    doc.recompute()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(box)
    pump()
    check("Program impeller active on a solid", cmd.isActive())
    names, undo = sorted(o.Name for o in doc.Objects), list(doc.UndoNames)
    Gui.runCommand("AeroNC_ProgramImpeller")
    pump()
    panel = ImpellerPanel.current
    check("the panel opens on the solid", panel is not None and panel.part is box)
    panel.stations.setValue(4)
    panel.channels.setValue(1)
    panel.program_button.click()
    pump()
    check("a box is refused with the core's message",
          len(errors) == 1 and "not an impeller: no rotational pattern" in errors[0], errors)
    check("the refused box leaves the document unchanged",
          sorted(o.Name for o in doc.Objects) == names and list(doc.UndoNames) == undo)
    panel.reject()
    pump()
    doc.removeObject(box.Name)
    del errors[:]

    shape, truth = impeller_part.make_test_impeller(SPEC)
    part = doc.addObject("Part::Feature", "Impeller")
    part.Shape = shape
    doc.recompute()
    Gui.SendMsgToActiveView("ViewFit")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(part)
    pump()
    check("tree context menu offers Program impeller", "Program impeller" in tree_context_menu())
    undo = list(doc.UndoNames)
    Gui.runCommand("AeroNC_ProgramImpeller")
    pump()
    panel = ImpellerPanel.current
    panel.allowance.setValue(2.5)
    panel.stations.setValue(4)
    panel.channels.setValue(1)
    ok = panel.program_button.click() or True
    pump(0.5)
    progs = [o for o in doc.Objects if is_impeller_program(o)]
    check("Program makes one impeller program", ok and len(progs) == 1 and not errors, errors)
    if not progs:
        return
    prog = progs[0]
    check("one undo step: Program impeller", list(doc.UndoNames) == ["Program impeller"] + undo, doc.UndoNames)
    check("the blank is the Job's stock", prog.Job.Stock is prog.Blank and abs(prog.Allowance.Value - 2.5) < 1e-9)
    labels = tree_labels()
    check("tree shows blades, hub, fillets, shroud, bore",
          {"Blade 0 (main)", "Blade 1 (splitter)", "Hub", "Root fillets", "Shroud"} <= labels
          and any(t.startswith("Bore") for t in labels), sorted(labels)[:30])
    colours = part.ViewObject.DiffuseColor
    hub = truth["hub"]
    check("the part is coloured by role", len(colours) == len(shape.Faces)
          and all(abs(a - b) < 0.01 for a, b in zip(colours[hub - 1][:3], ROLE_COLOURS["hub"]))
          and all(abs(a - b) < 0.01 for a, b in zip(colours[truth["blades"][0]["fillets"][0] - 1][:3],
                                                    ROLE_COLOURS["root_fillet"])),
          colours[:3])
    table = panel.table
    rows = {table.item(r, STEP).text(): r for r in range(table.rowCount())}
    check("the route panel lists the eight steps", table.rowCount() == 8, list(rows))
    check("the panel shows the checks", "deepest gouge" in panel.summary.text() and "holder collisions" in
          panel.summary.text(), panel.summary.text())
    ops = {o.Operation: o for o in pathcompat.job_operations(prog.Job)}
    steps = [k for k in ops if not k.endswith("_back")]  # what a step cuts from the back: an operation after it
    check("the Job holds the route's operations, each with its path",
          len(steps) == 8 and all(len(o.Path.Commands) > 0 for o in ops.values())
          and all(ops[k].Active for k in ("rough_channels", "finish_blades", "finish_hub", "finish_fillets",
                                          "face", "drill", "bore")) and not ops["turn"].Active,
          [(k, len(o.Path.Commands), o.Active) for k, o in ops.items()])
    Gui.Selection.clearSelection()
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    window_shot(doc, "impeller_panel")

    # Untick hub finishing: one undo step, its operation off, the program without it.
    undo = list(doc.UndoNames)
    table.item(rows["7 finish hub"], ON).setCheckState(QtCore.Qt.Unchecked)
    done = wait_for(lambda: len(doc.UndoNames) > len(undo))
    ops = {o.Operation: o for o in pathcompat.job_operations(prog.Job)}
    check("unticking a step is one undo step", done and list(doc.UndoNames) == ["Switch impeller step off"] + undo,
          doc.UndoNames)
    check("the step's operation is off and left out of the program",
          not ops["finish_hub"].Active and "finish hub" not in prog.Posted and not errors, errors)
    pump(0.3)
    table = panel.table
    rows = {table.item(r, STEP).text(): r for r in range(table.rowCount())}
    check("the panel shows the step off", table.item(rows["7 finish hub"], ON).checkState() == QtCore.Qt.Unchecked)

    # Another roughing tool: one undo step, the Job's roughing uses it.
    undo = list(doc.UndoNames)
    combo = table.cellWidget(rows["5 rough channels"], TOOL)
    check("the roughing tool is chosen in a list", combo is not None and combo.findText("EM-BALL8") >= 0)
    combo.setCurrentIndex(combo.findText("EM-BALL8"))
    done = wait_for(lambda: len(doc.UndoNames) > len(undo))
    ops = {o.Operation: o for o in pathcompat.job_operations(prog.Job)}
    check("another tool is one undo step", done and list(doc.UndoNames) == ["Change impeller step tool"] + undo,
          doc.UndoNames)
    check("the roughing uses the new tool", ops["rough_channels"].Tool == "EM-BALL8"
          and ops["rough_channels"].ToolController.Tool.Diameter.Value == 8.0 and "EM-BALL8" in prog.Posted)
    check("the roughing allowance is editable", panel.table.cellWidget(rows["5 rough channels"], ALLOWANCE)
          is not None)
    window_shot(doc, "impeller_route_edited")

    # Undo the tool change: the previous roughing comes back.
    doc.undo()
    pump()
    ops = {o.Operation: o for o in pathcompat.job_operations(prog.Job)}
    check("undo gives the previous roughing tool back", ops["rough_channels"].Tool != "EM-BALL8")
    panel.reject()
    pump()

    # Save and reopen: the program, its Job and the colours come back; double-click edits it.
    import tempfile
    path = os.path.join(tempfile.mkdtemp(prefix="aeronc_impeller_gui_"), "impeller.FCStd")
    doc.saveAs(path)
    posted = prog.Posted
    FreeCAD.closeDocument(doc.Name)
    pump()
    doc = FreeCAD.openDocument(path)
    pump(1.0)
    progs = [o for o in doc.Objects if is_impeller_program(o)]
    check("reopened: the program with its posted text and Job", len(progs) == 1 and progs[0].Posted == posted
          and progs[0].Job.Stock is progs[0].Blank)
    if progs:
        part = progs[0].Features.Source
        colours = part.ViewObject.DiffuseColor
        check("reopened: the part is coloured by role", len(colours) == len(part.Shape.Faces)
              and all(abs(a - b) < 0.01 for a, b in zip(colours[hub - 1][:3], ROLE_COLOURS["hub"])), colours[:2])
        opened = progs[0].ViewObject.Proxy.doubleClicked(progs[0].ViewObject)
        pump()
        panel = ImpellerPanel.current
        check("reopened: double-click opens the route panel", opened and panel is not None
              and panel.program is progs[0] and panel.table.rowCount() == 8)
        if panel is not None:
            panel.reject()
            pump()
    FreeCAD.closeDocument(doc.Name)


# Three programs of the impeller take a minute or two on a loaded machine.
harness.TIMEOUT_S = 600
main(run)
