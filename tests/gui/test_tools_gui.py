"""GUI test of tool selection and the knowledge-base editor, as a user drives them:

    HOME=<temp home> QTWEBENGINE_DISABLE_SANDBOX=1 xvfb-run -a freecad tests/gui/test_tools_gui.py

Recognise a generated panel, right-click its Machining Features, Select tools, read the result
panel and the element properties, undo; open the knowledge base, edit a tool, save (a bad value
first), import FreeCAD's tool library. Screenshots go to env AERONC_ARTIFACTS (default /tmp).
Prints "N passed, N failed" and exits 0 when all checks pass.
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


def run():
    import json
    import tempfile
    from aeronc import _core, makers, pathcompat
    from aeronc.pipeline import knowledge_base
    from aeronc.panels import knowledge_base_panel, select_tools_panel
    from aeronc.panels.knowledge_base_panel import KnowledgeBasePanel
    from aeronc.panels.select_tools_panel import SelectToolsPanel
    import Part
    os.makedirs(ARTIFACTS, exist_ok=True)
    errors = []
    select_tools_panel.show_error = errors.append
    knowledge_base_panel.show_error = errors.append
    kb_path = knowledge_base.user_kb_path()
    if os.path.exists(kb_path):
        os.remove(kb_path)  # a fresh user knowledge base, built from the shipped SQL

    Gui.activateWorkbench("PathWorkbench")
    pump()
    doc = FreeCAD.newDocument("Tools")
    spec = {"pocketsX": 3, "pocketsY": 2, "boltHoles": True, "joggles": False, "bottomPockets": False}
    shape = Part.Shape()
    shape.importBrepFromString(_core.make_panel(json.dumps(spec))[0])
    part = doc.addObject("Part::Feature", "Panel")
    part.Shape = shape
    doc.recompute()
    group = makers.create_machining_features(doc, part, directions=[(0, 0, 1)])
    pump()

    cmd = Gui.Command.get("AeroNC_SelectTools")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(part)
    check("Select tools inactive on a part", not cmd.isActive())
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(group)
    pump()
    check("Select tools active on Machining Features", cmd.isActive())
    check("tree context menu offers Select tools", "Select tools" in tree_context_menu())
    menus = {a.text().replace("&", ""): [m.text() for m in a.menu().actions()]
             for a in Gui.getMainWindow().menuBar().actions() if a.menu()}
    check("AeroNC menu lists the new commands",
          {"Select tools", "Knowledge base..."} <= set(menus.get("AeroNC", [])), menus.get("AeroNC"))

    undo_before = doc.UndoCount
    names_before = set(o.Name for o in doc.Objects)
    Gui.runCommand("AeroNC_SelectTools")
    pump()
    panel = SelectToolsPanel.current
    check("Select tools panel open", Gui.Control.activeDialog() and panel is not None)
    kb = knowledge_base.open_kb(kb_path)
    shown = ([panel.material.itemText(i) for i in range(panel.material.count())],
             [panel.machine.itemText(i) for i in range(panel.machine.count())])
    check("materials and machines from the knowledge base", len(shown[0]) == 4 and
          "AC-GANTRY" in shown[1] and shown == (list(kb.workpiece_materials()), list(kb.machine_names())), shown)
    panel.material.setCurrentIndex(panel.material.findText("7050-T7451"))
    panel.run_button.click()
    pump()
    check("no error", not errors, errors)
    pockets = [o for o in doc.Objects if getattr(o, "ElementType", "") == "closed_pocket"]
    check("every pocket has its tools on the element",
          pockets and all(p.FinishingTool and p.RoughingTool and 0.85 <= p.MachinableRatio <= 1 for p in pockets),
          [(p.Label, getattr(p, "RoughingTool", None)) for p in pockets])
    holes = [o for o in doc.Objects if getattr(o, "ElementType", "") == "hole"]
    check("holes without a drill say which drill they need",
          holes and all(h.Drill or "no drill of diameter" in h.ToolError for h in holes),
          [(h.Label, h.Drill, h.ToolError) for h in holes])
    check("the plan on the group, no Job made (the machining chain makes them)",
          json.loads(group.ToolPlan) == panel.plan and panel.plan["toolSettings"] and
          not pathcompat.jobs_of_part(doc, part), [j.Label for j in pathcompat.jobs_of_part(doc, part)])
    check("result table filled", panel.table.rowCount() == len(panel.plan["elements"]) + len(panel.plan["holes"]),
          panel.table.rowCount())
    check("summary shows the merge", "tool changes" in panel.summary.text(), panel.summary.text())
    check("one undo step", doc.UndoCount == undo_before + 1, doc.UndoNames)
    for tree_view in Gui.getMainWindow().findChildren(QtGui.QTreeWidget):
        tree_view.expandAll()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(pockets[0])
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    shot = window_shot(doc, "aeronc_select_tools")
    check("select tools screenshot saved", os.path.getsize(shot) > 20000, shot)
    check("Close pressed", click_ok(QtGui.QDialogButtonBox.Close))
    pump()
    check("panel closed", not Gui.Control.activeDialog())
    doc.undo()
    pump()
    check("undo removes the Job and its controllers", set(o.Name for o in doc.Objects) == names_before,
          sorted(set(o.Name for o in doc.Objects) - names_before))

    # -- the knowledge-base editor --------------------------------------------------------
    # A knowledge base that cannot be opened: the command says why in a message box, opens nothing.
    from aeronc.commands import base as command_base
    shown = []
    original_show_error = command_base.show_error
    command_base.show_error = lambda title, text: shown.append((title, text))
    os.rename(kb_path, kb_path + ".good")
    try:
        with open(kb_path, "wb") as f:
            f.write(b"this is not a database" * 100)
        Gui.runCommand("AeroNC_EditKnowledgeBase")
        pump()
        check("unreadable knowledge base: the command shows why",
              len(shown) == 1 and shown[0][0] == "Knowledge base" and "not a database" in shown[0][1], shown)
        check("unreadable knowledge base: no panel", not Gui.Control.activeDialog())
    finally:
        command_base.show_error = original_show_error
        os.replace(kb_path + ".good", kb_path)
    Gui.runCommand("AeroNC_EditKnowledgeBase")
    pump()
    kbp = KnowledgeBasePanel.current
    check("knowledge base panel open", Gui.Control.activeDialog() and kbp is not None)
    names = [kbp.tabs.tabText(i) for i in range(kbp.tabs.count())]
    check("one tab per table", names[:3] == ["tool", "cutting condition", "machine"], names)
    tools = kbp.tables[0]
    col = tools.columns.index("diameter")
    row = next(r for r in range(tools.widget.rowCount()) if tools.widget.item(r, 0).text() == "EM-F10")
    tools.widget.item(row, col).setText("-4")  # as typing does: itemChanged fires
    check("bad value refused with a named row", not kbp.save() and errors and "EM-F10" in errors[-1], errors[-1:])
    check("nothing written after a refusal",
          [t["diameter"] for t in kbp.kb.tools() if t["id"] == "EM-F10"] == [10.0])
    tools.widget.item(row, col).setText("9.5")
    check("good value saved", kbp.save() and
          [t["diameter"] for t in kbp.kb.tools() if t["id"] == "EM-F10"] == [9.5])
    library = "/usr/share/freecad/Mod/Path/Tools/Library/Default.fctl"
    if os.path.isfile(library):
        n = kbp.import_library(library)
        check("FreeCAD library imported", n == 9 and any(t["id"] == "5mm_Endmill" for t in kbp.kb.tools()), n)
        out = tempfile.mkdtemp(prefix="aeronc_fctl_")
        written = kbp.export_library("Default", out)
        check("FreeCAD library exported unchanged", written and
              open(written[0]).read() == open(library).read(), written[:1])
    kbp.tabs.setCurrentIndex(0)
    shot = window_shot(doc, "aeronc_knowledge_base")
    check("knowledge base screenshot saved", os.path.getsize(shot) > 20000, shot)
    check("Close pressed", click_ok(QtGui.QDialogButtonBox.Close))
    pump()
    check("editor closed", not Gui.Control.activeDialog())
    FreeCAD.closeDocument(doc.Name)


main(run)
