"""GUI test of operations the toolpath core refuses, as a user meets them:

    HOME=<temp home> QTWEBENGINE_DISABLE_SANDBOX=1 xvfb-run -a freecad tests/gui/test_gate_gui.py

A plate with a pocket and a 3.5 mm slot: recognise, Machining chain, Build (nothing refused), then
the slot's roughing unit given the pocket's roughing tool by script, which does not fit the slot.
Before OK the panel marks that unit
"not ready" in red and lists it with the core's reason; after OK its operation carries Check "No
toolpath" and the reason in Note (the property editor shows them), and AeroNC's 840D post refuses
the Job, or with --skip-failed leaves the operation out with a comment, and never posts it as a
tool change with no moves. Screenshots go to env AERONC_ARTIFACTS (default /tmp).
Prints "N passed, N failed"; exits 0 when all checks pass.
"""
import os
import re
import sys

import FreeCAD
import FreeCADGui as Gui

# Without this preference a modal warning blocks the first activation of Path.
FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Mod/Path").SetBool("WarningSuppressVelocity", True)

_mod = os.environ.get("AERONC_MOD_DIR")
if _mod and os.path.isdir(os.path.join(_mod, "aeronc")) and _mod not in sys.path:
    sys.path.insert(0, _mod)

from PySide import QtCore, QtGui  # noqa: E402
from aeronc.tests.gui.harness import ARTIFACTS, check, click_ok, main, pump, window_shot  # noqa: E402

FAMILY, MATERIAL = "integral_panel", "7050-T7451"


def plate_with_a_narrow_slot():
    """120 x 80 x 20: a 60 x 40 pocket (R6 corners, 9.5 deep) and a 20 x 3.5 slot (5.5 deep)."""
    import Part
    V = FreeCAD.Vector

    def rounded(box, r):
        vertical = [e for e in box.Edges if abs(e.Vertexes[0].Point.x - e.Vertexes[1].Point.x) < 1e-9
                    and abs(e.Vertexes[0].Point.y - e.Vertexes[1].Point.y) < 1e-9]
        return box.makeFillet(r, vertical)
    plate = Part.makeBox(120, 80, 20)
    pocket = rounded(Part.makeBox(60, 40, 10, V(10, 20, 10.5)), 6)
    slot = rounded(Part.makeBox(20, 3.5, 6, V(90, 30, 14.5)), 1.74)
    return plate.cut(pocket).cut(slot).removeSplitter()


def run():
    from aeronc import makers, pathcompat
    from aeronc.pipeline import chain_building, knowledge_base
    from aeronc.objects import machining_chain as chain_object
    from aeronc.panels import machining_chain_panel
    from aeronc.panels.machining_chain_panel import MachiningChainPanel
    from aeronc.post import PostError
    from aeronc.tests import pathcompat as test_pathcompat
    os.makedirs(ARTIFACTS, exist_ok=True)
    errors = []
    machining_chain_panel.show_error = errors.append
    kb_path = knowledge_base.user_kb_path()
    if os.path.exists(kb_path):
        os.remove(kb_path)

    Gui.activateWorkbench("PathWorkbench")
    pump()
    doc = FreeCAD.newDocument("Gate")
    part = doc.addObject("Part::Feature", "Plate")
    part.Shape = plate_with_a_narrow_slot()
    doc.recompute()
    group = makers.create_machining_features(doc, part)
    pump()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(group)
    Gui.runCommand("AeroNC_MachiningChain")
    pump()
    panel = MachiningChainPanel.current
    check("Machining chain panel open", panel is not None)
    panel.family.setCurrentIndex(panel.family.findText(FAMILY))
    panel.material.setCurrentIndex(panel.material.findText(MATERIAL))
    panel.build_button.click()
    pump()
    check("built without error", not errors and panel.chain is not None, errors)

    # The knowledge base's small tools finish the slot now; a tool set on its roughing unit by
    # script (the panel's list offers only smaller ones) that does not fit is what the core refuses.
    check("nothing refused as built", not panel.not_ready_units(), panel.not_ready_units())
    rough = [u for u in panel.chain["units"] if u.get("step") == "r"]
    slot_unit = min(rough, key=lambda u: float((u.get("cutter") or {}).get("diameter") or 0.0))
    big = max(rough, key=lambda u: float((u.get("cutter") or {}).get("diameter") or 0.0))["tool"]
    panel.set_tool(int(slot_unit["id"]), big)
    pump(0.5)

    # Before OK: the unit the core refuses is marked in the tree and listed with the reason.
    refused = panel.not_ready_units()
    check("one unit refused by the toolpath core", len(refused) == 1, refused)
    uid, why = next(iter(refused.items()))
    check("the reason is the core's", "does not fit" in why, why)
    items = panel.unit_items()
    item = items[uid]
    check("its row says not ready", "not ready" in item.text(0), item.text(0))
    check("its row is red", item.foreground(0).color().name() == machining_chain_panel.RED,
          item.foreground(0).color().name())
    check("the other rows are not", all("not ready" not in i.text(0) for u, i in items.items() if u != uid))
    listed = [panel.not_ready.item(i).text() for i in range(panel.not_ready.count())]
    check("listed under Not ready with the reason", len(listed) == 1 and "Unit {}".format(uid) in listed[0]
          and "does not fit" in listed[0], listed)
    panel.tree.clearSelection()  # the row's red, not the selection's blue
    panel.tree.scrollToItem(item, QtGui.QAbstractItemView.PositionAtBottom)
    scroll = panel.form.parentWidget()
    while scroll is not None and not isinstance(scroll, QtGui.QScrollArea):
        scroll = scroll.parentWidget()
    if scroll is not None:
        scroll.ensureWidgetVisible(panel.not_ready)  # the list under the rules, below the fold
    shot = window_shot(doc, "gate_chain_panel_not_ready")
    check("panel screenshot saved", os.path.getsize(shot) > 20000, shot)

    check("OK pressed", click_ok())
    pump(1.0)
    check("no error on OK", not errors, errors)
    chain = next(o for o in doc.Objects if chain_object.is_machining_chain(o))
    ops = {op.UnitId: op for op in chain_building.chain_operations(chain)}
    op = ops[uid]
    check("the operation is marked No toolpath", op.Check == "No toolpath", op.Check)
    check("its Note says why", "does not fit" in op.Note, op.Note)
    check("it has no path (not a stale one)", len(op.Path.Commands) == 0, len(op.Path.Commands))
    others = [o for u, o in ops.items() if u != uid and o.Active]
    check("the others are computed, not yet checked", all(o.Check == "Not checked" and o.Path.Commands
                                                         for o in others), [(o.Label, o.Check) for o in others])
    check("the chain's messages name it", any(op.Label in m and "no toolpath" in m for m in chain.Messages),
          list(chain.Messages))

    # The operation selected: the property editor shows its Check and Note.
    job = next(j for j in chain.Jobs if op in pathcompat.job_operations(j))
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(op)
    for tree_view in Gui.getMainWindow().findChildren(QtGui.QTreeWidget):
        tree_view.expandAll()
    pump(0.5)
    shown, check_row = set(), None
    for view in Gui.getMainWindow().findChildren(QtGui.QTreeView):
        model = view.model()
        if model is None or not view.isVisible():
            continue
        stack = [QtCore.QModelIndex()]
        while stack:
            parent = stack.pop()
            for r in range(model.rowCount(parent)):
                index = model.index(r, 0, parent)
                shown.add(str(model.data(index)))
                if str(model.data(index)) == "Check":
                    check_row = (view, index)
                value = model.index(r, 1, parent)
                shown.add(str(model.data(value)))
                stack.append(index)
    check("the property editor shows Check = No toolpath", "Check" in shown and "No toolpath" in shown,
          sorted(s for s in shown if s and len(s) < 30)[:40])
    if check_row is not None:
        check_row[0].scrollTo(check_row[1], QtGui.QAbstractItemView.PositionAtCenter)
    shot = window_shot(doc, "gate_operation_no_toolpath")
    check("operation screenshot saved", os.path.getsize(shot) > 20000, shot)

    # AeroNC's post refuses the Job, or leaves the operation out on request.
    post = test_pathcompat.post_processor("aeronc_840d")
    try:
        post.export([job], "-", "")
        refusal = None
    except PostError as e:
        refusal = str(e)
    check("the 840D post refuses the Job", refusal is not None and "'{}' is not ready to post".format(op.Label)
          in refusal and "does not fit" in refusal, refusal)
    text = post.export([job], "-", "--skip-failed")
    check("--skip-failed names it in a comment", "; left out: {}: no toolpath".format(op.Label) in text,
          text[:600])
    check("and posts it not at all", "; operation: {}".format(op.Label) not in text)
    posted = text.count("; operation: ")
    changes = len(re.findall(r"\bT\d+ D1 M6", text))
    check("no tool change without moves", 0 < changes <= posted, (changes, posted))
    FreeCAD.closeDocument(doc.Name)


main(run)
