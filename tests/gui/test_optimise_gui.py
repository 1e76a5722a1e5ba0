"""GUI test of Optimise cutting parameters, as a user drives it:

    HOME=<temp home> QTWEBENGINE_DISABLE_SANDBOX=1 xvfb-run -a freecad tests/gui/test_optimise_gui.py

A block with a pocket, a Path Job, FreeCAD's Pocket Shape with a 10 mm carbide end mill. Right-click
the ToolController, Optimise cutting parameters; read the table, the plot and the report; try an
impossible roughness limit (nothing written), then OK; undo. Then the whole Job. Screenshots go to
env AERONC_ARTIFACTS (default /tmp). Prints "N passed, N failed"; exits 0 when all checks pass.
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

from PySide import QtGui  # noqa: E402
from aeronc.tests.gui.harness import (  # noqa: E402
    ARTIFACTS, check, click_ok, main, pump, tree_context_menu, window_shot)


def feeds(tc):
    return (tc.SpindleSpeed, tc.HorizFeed.getValueAs("mm/min").Value, tc.VertFeed.getValueAs("mm/min").Value)


def run():
    from aeronc.pipeline import knowledge_base
    from aeronc import pathcompat
    from aeronc.panels import optimise_cutting_panel
    from aeronc.panels.optimise_cutting_panel import OptimiseCuttingPanel
    from aeronc.tests.app.support import end_mill, make_pocket_job
    os.makedirs(ARTIFACTS, exist_ok=True)
    errors = []
    optimise_cutting_panel.show_error = errors.append
    kb_path = knowledge_base.user_kb_path()
    if os.path.exists(kb_path):
        os.remove(kb_path)

    Gui.activateWorkbench("PathWorkbench")
    pump()
    doc = FreeCAD.newDocument("Optimise")
    part, job, pocket = make_pocket_job(doc)
    tc = pathcompat.create_tool_controller(doc, job, "TC: 10 mm end mill", end_mill(10), 2, 8000, 1200, 300)
    pocket.ToolController = tc
    doc.recompute()
    pump()
    check("pocket has a path", len(pocket.Path.Commands) > 10, len(pocket.Path.Commands))

    cmd = Gui.Command.get("AeroNC_OptimiseCutting")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(part)
    check("inactive on a plain part", not cmd.isActive())
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(tc)
    pump()
    check("active on a ToolController", cmd.isActive())
    check("tree context menu offers it", "Optimise cutting parameters" in tree_context_menu())
    menus = {a.text().replace("&", ""): [m.text() for m in a.menu().actions()]
             for a in Gui.getMainWindow().menuBar().actions() if a.menu()}
    check("AeroNC menu lists it", "Optimise cutting parameters" in menus.get("AeroNC", []), menus.get("AeroNC"))

    before = feeds(tc)
    undo_before = doc.UndoCount
    Gui.runCommand("AeroNC_OptimiseCutting")
    pump(0.5)
    panel = OptimiseCuttingPanel.current
    check("panel open", Gui.Control.activeDialog() and panel is not None)
    panel.material.setCurrentIndex(panel.material.findText("7050-T7451"))
    panel.machine.setCurrentIndex(panel.machine.findText("AC-5AX"))
    panel.method.setCurrentIndex(panel.method.findData("both"))
    panel.run_button.click()
    pump()
    check("no error", not errors, errors)
    p = panel.proposals[0] if panel.proposals else None
    check("one row with an answer", panel.table.rowCount() == 1 and p is not None and p.ok,
          p.error if p is not None else panel.proposals)
    check("a_p and a_e measured from the pocket", panel.table.item(0, 2).text() == "3 \u00d7 5",
          panel.table.item(0, 2).text())
    active = panel.table.item(0, 5).text()
    check("active limits shown", active and active == ", ".join(p.optimum["active"]), active)
    pix = panel.plot.picture()
    check("plot drawn", pix is not None and not pix.isNull() and pix.width() > 300, pix)
    shown = panel.plot.pixmap()
    check("plot shown within the panel", shown is not None and 0 < shown.width() <= panel.plot.width(),
          (shown.width() if shown else None, panel.plot.width()))
    check("report compares both methods", "GA" in panel.report.toPlainText() and "SLSQP" in panel.report.toPlainText(),
          panel.report.toPlainText()[:300])
    check("nothing written yet", feeds(tc) == before)

    # An impossible roughness limit: the row says why, OK refuses, nothing is written.
    panel.ra_roughing.setValue(0.0001)
    panel.run_button.click()
    pump()
    problem = panel.table.item(0, 5).text()
    check("infeasible names the limit", "infeasible" in problem and "R_a" in problem, problem)
    check("OK refuses", not panel.accept() and errors and "nothing to write" in errors[-1], errors[-1:])
    check("still nothing written", feeds(tc) == before and doc.UndoCount == undo_before)
    check("panel still open", Gui.Control.activeDialog())

    panel.ra_roughing.setValue(12.5)
    panel.method.setCurrentIndex(panel.method.findData("nlopt"))
    panel.run_button.click()
    pump()
    proposal = panel.proposals[0]
    for tree_view in Gui.getMainWindow().findChildren(QtGui.QTreeWidget):
        tree_view.expandAll()
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    shot = window_shot(doc, "aeronc_optimise_cutting")
    check("screenshot saved", os.path.getsize(shot) > 20000, shot)
    check("OK pressed", click_ok())
    pump()
    check("panel closed", not Gui.Control.activeDialog())
    after = feeds(tc)
    check("ToolController written", abs(after[0] - proposal.spindle_rpm) < 1e-6
          and abs(after[1] - proposal.horiz_feed) < 1e-3 and abs(after[2] - proposal.vert_feed) < 1e-3, after)
    check("one undo step", doc.UndoCount == undo_before + 1 and doc.UndoNames[0] == "Optimise cutting parameters",
          doc.UndoNames)
    doc.undo()
    pump()
    check("undo restores the ToolController", all(abs(a - b) < 1e-6 for a, b in zip(feeds(tc), before)),
          (feeds(tc), before))

    # The whole Job: FreeCAD's default controller has no teeth and is named as such.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(job)
    pump()
    Gui.runCommand("AeroNC_OptimiseCutting")
    pump(0.5)
    panel = OptimiseCuttingPanel.current
    rows = {panel.table.item(r, 0).text(): panel.table.item(r, 5).text() for r in range(panel.table.rowCount())}
    check("a row per ToolController of the Job", len(rows) == len(pathcompat.tool_controllers(job)), rows)
    check("default controller: Flutes missing", any("Flutes" in v for v in rows.values()), rows)
    check("material remembered from the last run", panel.material.currentText() == "7050-T7451",
          panel.material.currentText())
    shot = window_shot(doc, "aeronc_optimise_job")
    check("job screenshot saved", os.path.getsize(shot) > 20000, shot)
    check("Cancel pressed", click_ok(QtGui.QDialogButtonBox.Cancel))
    pump()
    check("Cancel writes nothing", all(abs(a - b) < 1e-6 for a, b in zip(feeds(tc), before)))
    FreeCAD.closeDocument(doc.Name)


main(run)
