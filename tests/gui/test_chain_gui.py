"""GUI test of the Machining chain panel, as a user drives it:

    HOME=<temp home> QTWEBENGINE_DISABLE_SANDBOX=1 xvfb-run -a freecad tests/gui/test_chain_gui.py

Recognise a generated double-sided panel, right-click its Machining Features, Machining chain;
choose the family and material, Build; read the eight-level tree; move a unit up, give a unit
another tool, untick a unit, Check rules; OK; then the Jobs follow the edits, their operations
draw their paths in the 3-D view, and one undo removes it all. Screenshots go to env
AERONC_ARTIFACTS (default /tmp). Prints "N passed, N failed"; exits 0 when all checks pass.
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
    ARTIFACTS, check, click_ok, main, pump, tree_context_menu, window_shot)

FAMILY, MATERIAL = "integral_panel", "7050-T7451"
LEVELS = ["Part", "Machine", "Setup", "Process", "Step", "Program", "Tool", "Unit"]


def depth_of(item):
    d = 1
    while item.parent() is not None:
        item, d = item.parent(), d + 1
    return d


def tool_node(item):
    """The text of the unit's tool node (its parent)."""
    return item.parent().text(0)


def run():
    import json
    from aeronc import _core, makers, pathcompat
    from aeronc.pipeline import chain_edits, knowledge_base, chain_building
    from aeronc.objects import machining_chain as chain_object
    from aeronc.panels import machining_chain_panel
    from aeronc.panels.machining_chain_panel import UNIT_ROLE, MachiningChainPanel
    import Part
    os.makedirs(ARTIFACTS, exist_ok=True)
    errors = []
    machining_chain_panel.show_error = errors.append
    kb_path = knowledge_base.user_kb_path()
    if os.path.exists(kb_path):
        os.remove(kb_path)  # a fresh user knowledge base, built from the shipped SQL

    Gui.activateWorkbench("PathWorkbench")
    pump()
    doc = FreeCAD.newDocument("Chain")
    spec = {"pocketsX": 2, "pocketsY": 2, "bottomPockets": True, "joggles": False}
    shape = Part.Shape()
    shape.importBrepFromString(_core.make_panel(json.dumps(spec))[0])
    part = doc.addObject("Part::Feature", "Panel")
    part.Shape = shape
    doc.recompute()
    group = makers.create_machining_features(doc, part)
    pump()

    cmd = Gui.Command.get("AeroNC_MachiningChain")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(part)
    check("Machining chain inactive on a part", not cmd.isActive())
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(group)
    pump()
    check("Machining chain active on Machining Features", cmd.isActive())
    check("tree context menu offers Machining chain", "Machining chain" in tree_context_menu())
    menus = {a.text().replace("&", ""): [m.text() for m in a.menu().actions()]
             for a in Gui.getMainWindow().menuBar().actions() if a.menu()}
    check("AeroNC menu lists Machining chain", "Machining chain" in menus.get("AeroNC", []), menus.get("AeroNC"))

    undo_before = doc.UndoCount
    names_before = set(o.Name for o in doc.Objects)
    mw = Gui.getMainWindow()
    combo_view = next((d for d in mw.findChildren(QtGui.QDockWidget)
                       if d.isVisible() and d.objectName() == "Combo View"), None)
    check("the Combo View is shown", combo_view is not None)
    width_before = combo_view.width() if combo_view else 0
    Gui.runCommand("AeroNC_MachiningChain")
    pump()
    panel = MachiningChainPanel.current
    check("Machining chain panel open", Gui.Control.activeDialog() and panel is not None)
    families = [panel.family.itemText(i) for i in range(panel.family.count())]
    check("part families from the knowledge base", FAMILY in families, families)
    panel.family.setCurrentIndex(panel.family.findText(FAMILY))
    panel.material.setCurrentIndex(panel.material.findText(MATERIAL))
    panel.build_button.click()
    pump()
    check("built without error", not errors and panel.chain is not None, errors)
    check("nothing written by Build", set(o.Name for o in doc.Objects) == names_before)
    from aeronc.objects.machining_features import result_of
    recognised = len(result_of(group)["elements"])
    left = {e["element"] for e in panel.chain.get("unmachined", [])}
    machined = {u["element"] for u in panel.chain["units"]}  # some perhaps with faces left
    summary = panel.summary.text()
    check("the summary counts the elements machined of those recognised",
          "{} of {} elements machined".format(len(machined), recognised) in summary, summary)
    check("the Not machined tab counts its elements",
          panel.findings.tabText(0) == "Not machined ({})".format(len(left)), panel.findings.tabText(0))
    check("the findings sit above the chain tree",
          panel.findings.mapTo(panel.form, QtCore.QPoint(0, 0)).y() <
          panel.tree.mapTo(panel.form, QtCore.QPoint(0, 0)).y())
    items = panel.unit_items()
    units = {u["id"]: u for u in panel.chain["units"]}
    check("a tree row per unit", sorted(items) == sorted(units), (len(items), len(units)))
    depths = {depth_of(i) for i in items.values()}
    check("units at the eighth level", depths == {8}, depths)
    sample = next(iter(items.values()))
    path, it = [], sample
    while it is not None:
        path.insert(0, it.text(0).split()[0])
        it = it.parent()
    check("levels part to unit", path == LEVELS, path)

    # Move up: a unit that is second in its program.
    program = next(p for _, _, _, p in chain_edits.programs(panel.chain) if len(p["units"]) >= 2)
    first, second = program["units"][0], program["units"][1]
    panel.tree.setCurrentItem(items[second])
    pump()
    check("Move up enabled for a second unit", panel.up_button.isEnabled())
    panel.up_button.click()
    pump()
    items = panel.unit_items()
    parent = items[second].parent()
    order = [parent.child(i).data(0, UNIT_ROLE) for i in range(parent.childCount())]
    check("unit moved up within its program", order.index(second) < order.index(first), order)
    check("the moved unit stays selected", panel.selected_unit() == second)

    # Another tool: the first unit whose combo offers one.
    changed = None
    for uid, item in panel.unit_items().items():
        if uid in (first, second):
            continue
        combo = panel.tree.itemWidget(item, machining_chain_panel.TOOL_COLUMN)
        others = [combo.itemText(i) for i in range(combo.count()) if combo.itemText(i) != units[uid]["tool"]]
        if others:
            changed = (uid, others[0])
            combo.setCurrentIndex(combo.findText(others[0]))
            break
    pump()
    check("a unit with a choice of tools", changed is not None)
    items = panel.unit_items()
    check("the unit moved under its new tool", changed and tool_node(items[changed[0]]) == "Tool " + changed[1],
          changed and tool_node(items[changed[0]]))

    # Untick a unit.
    disabled = next(uid for uid in reversed(panel.chain["order"]) if uid not in (first, second, changed[0]))
    items[disabled].setCheckState(0, QtCore.Qt.Unchecked)
    pump()
    check("the unit is disabled in the edits", disabled in panel.edits["disabled"], panel.edits)
    check("edits ask for a check", "Check rules" in panel.checks.item(0).text())
    panel.check_button.click()
    pump()
    texts = [panel.checks.item(i).text() for i in range(panel.checks.count())]
    check("each rule listed", len(texts) == len(panel.chain["checks"]) > 0, texts)
    red = [panel.checks.item(i).text() for i in range(panel.checks.count())
           if panel.checks.item(i).foreground().color().name() == machining_chain_panel.RED]
    failing = [c for c in panel.chain["checks"] if not c["ok"]]
    check("failing rules in red naming their node", len(red) == len(failing) and
          all(c["node"] in t for c, t in zip(failing, red)), (red, failing))
    check("travel saved shown", "saved" in panel.travel.text(), panel.travel.text())
    for tree_view in Gui.getMainWindow().findChildren(QtGui.QTreeWidget):
        tree_view.expandAll()
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    items = panel.unit_items()  # the tree was rebuilt by the edits
    panel.tree.setCurrentItem(items[second])
    panel.tree.scrollToTop()  # the eight levels from the part down, the moved unit among them
    shot = window_shot(doc, "machining_chain_panel")
    check("panel screenshot saved", os.path.getsize(shot) > 20000, shot)

    check("OK pressed", click_ok())
    pump(1.0)
    check("no error on OK", not errors, errors)
    check("panel closed", not Gui.Control.activeDialog())
    check("the Combo View back to its width", combo_view and abs(combo_view.width() - width_before) <= 2,
          combo_view and (combo_view.width(), width_before))
    chains = [o for o in doc.Objects if chain_object.is_machining_chain(o)]
    check("one Machining chain", len(chains) == 1, len(chains))
    chain = chains[0]
    check("one undo step", doc.UndoCount == undo_before + 1, doc.UndoNames)
    ops = {op.UnitId: op for op in chain_building.chain_operations(chain)}
    check("an operation per unit", sorted(ops) == sorted(units), (len(ops), len(units)))
    job = next(j for j in chain.Jobs if ops[first] in pathcompat.job_operations(j))
    ids = [op.UnitId for op in pathcompat.job_operations(job) if op.UnitId in ops]
    check("the Job follows the new order", ids.index(second) < ids.index(first), ids)
    check("the Job follows the new tool", ops[changed[0]].Tool == changed[1] and
          ops[changed[0]].ToolController.AeroNCTool.startswith(changed[1] + "/"),
          (ops[changed[0]].Tool, ops[changed[0]].ToolController.Label))
    check("the disabled unit's operation is inactive", not ops[disabled].Active and
          all(op.Active for uid, op in ops.items() if uid != disabled))
    view_types = {op.ViewObject.TypeId for op in ops.values()}
    check("Path's view provider draws the operations", view_types == {"PathGui::ViewProviderPathPython"}, view_types)
    first_ops = pathcompat.job_operations(chain.Jobs[0])
    check("the first setup's operations visible", first_ops and all(op.ViewObject.Visibility for op in first_ops))

    touched = [o.Name for o in doc.Objects if "Touched" in o.State]
    check("nothing left to recompute after OK", not touched, touched)
    doc.recompute(None, True, True)  # Ctrl+Shift+R: every object recomputed
    pump()
    touched = [o.Name for o in doc.Objects if "Touched" in o.State or "Invalid" in o.State]
    check("nothing touched after a forced recompute", not touched, touched)

    def shown(j):
        """(models, stock, operations) of Job j: True where every one is visible, False where none."""
        def state(objs):
            v = {o.ViewObject.Visibility for o in objs}
            return v.pop() if len(v) == 1 else None
        return (state(pathcompat.job_models(j)), state([j.Stock]), state(pathcompat.job_operations(j)))

    first_job, others = chain.Jobs[0], chain.Jobs[1:]
    check("after OK only the first setup's Job is shown", shown(first_job) == (True, True, True) and
          all(shown(j) == (False, False, False) for j in others), [shown(j) for j in chain.Jobs])
    check("the part in its original place is hidden", not part.ViewObject.Visibility and
          not group.ViewObject.Visibility)
    check("a chain with several setups", others, len(chain.Jobs))
    if others:
        Gui.Selection.clearSelection()
        Gui.Selection.addSelection(others[0])
        pump()
        check("a Job's context menu offers Show this setup only", "Show this setup only" in tree_context_menu())
        Gui.runCommand("AeroNC_ShowSetup")
        pump()
        check("Show this setup only switches the setups", shown(others[0]) == (True, True, True) and
              shown(first_job) == (False, False, False), [shown(j) for j in chain.Jobs])

    # The paths over the part in the 3-D view: the Job of the edited units.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(job)
    Gui.runCommand("AeroNC_ShowSetup")
    for m in pathcompat.job_models(job):
        m.ViewObject.Transparency = 60
    for tree_view in Gui.getMainWindow().findChildren(QtGui.QTreeWidget):
        tree_view.collapseAll()
    Gui.Selection.addSelection(job)
    mw = Gui.getMainWindow()
    for dock in mw.findChildren(QtGui.QDockWidget):
        if dock.isVisible() and dock.objectName() == "Combo View":
            mw.resizeDocks([dock], [380], QtCore.Qt.Horizontal)  # room for the view
    pump()
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    shot = window_shot(doc, "machining_chain_paths")
    check("paths screenshot saved", os.path.getsize(shot) > 20000, shot)

    # The chain reopens in the panel from its own context menu, with the edits.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(chain)
    pump()
    check("Machining chain active on the chain", cmd.isActive())
    Gui.runCommand("AeroNC_MachiningChain")
    pump()
    panel = MachiningChainPanel.current
    check("panel shows the stored edits", panel is not None and panel.edits["disabled"] == [disabled] and
          panel.chain_obj is chain)
    check("Cancel pressed", click_ok(QtGui.QDialogButtonBox.Cancel))
    pump()
    check("Cancel changes nothing", doc.UndoCount == undo_before + 1)

    doc.undo()
    pump()
    check("undo removes the chain and its Jobs", set(o.Name for o in doc.Objects) == names_before,
          sorted(set(o.Name for o in doc.Objects) - names_before))

    # OK on a freshly opened panel builds the chain with its settings, then makes the Jobs.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(group)
    Gui.runCommand("AeroNC_MachiningChain")
    pump()
    check("OK pressed on a fresh panel", click_ok())
    pump(1.0)
    check("no error on OK without Build", not errors, errors)
    fresh = [o for o in doc.Objects if chain_object.is_machining_chain(o)]
    check("OK alone built the chain and its Jobs", len(fresh) == 1 and len(fresh[0].Jobs) == 2 and
          fresh[0].UnitCount > 0, [(o.Label, len(o.Jobs)) for o in fresh])
    FreeCAD.closeDocument(doc.Name)


main(run)
