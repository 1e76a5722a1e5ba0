"""GUI test of a STEP part that holds free shapes besides its solid, as a new user meets it:

    HOME=<temp home> QTWEBENGINE_DISABLE_SANDBOX=1 xvfb-run -a freecad tests/gui/test_import_gui.py

File > Import of NIST CTC-04 (FreeCAD's Import module, as the GUI's import does) gives one
object whose shape is the solid plus free faces. Recognise it, Select tools on the new Machining
Features, build its machining chain, Optimise a chain Job's cutting parameters: no step refuses, and the faces of the result are
the object's own. Needs the NIST parts in env AERONC_SHARED_DATA. Prints "N passed, N failed";
exits 0 when all checks pass.
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
    ARTIFACTS, check, click_ok, combo_view_width, fits_combo_view, main, pump, window_shot)

PART = os.path.join(os.environ.get("AERONC_SHARED_DATA", ""), "nist", "nist_ctc_04_asme1_ap203.stp")


def run():
    import ImportGui
    from aeronc.pipeline import knowledge_base
    from aeronc import objects, pathcompat
    from aeronc.panels import optimise_cutting_panel, recognise_panel, select_tools_panel
    from aeronc.panels.optimise_cutting_panel import OptimiseCuttingPanel
    from aeronc.panels.recognise_panel import RecognisePanel
    from aeronc.panels.select_tools_panel import SelectToolsPanel
    from aeronc.viewproviders.view_machining_features import role_colours
    os.makedirs(ARTIFACTS, exist_ok=True)
    errors = []
    recognise_panel.show_error = errors.append
    select_tools_panel.show_error = errors.append
    optimise_cutting_panel.show_error = errors.append
    kb_path = knowledge_base.user_kb_path()
    if os.path.exists(kb_path):
        os.remove(kb_path)
    check("NIST part present", os.path.isfile(PART), PART)

    Gui.activateWorkbench("PathWorkbench")
    pump()
    default_width = combo_view_width()
    check("the combo view is at its default width", default_width and default_width < 400, default_width)
    doc = FreeCAD.newDocument("Imported")
    ImportGui.insert(PART, doc.Name)  # what File > Import runs for a STEP file
    doc.recompute()
    pump()
    parts = [o for o in doc.Objects if hasattr(o, "Shape") and len(o.Shape.Solids) == 1]
    check("one imported object with one solid", len(parts) == 1, [o.Name for o in doc.Objects])
    part = parts[0]
    faces = len(part.Shape.Faces)
    solid_faces = len(part.Shape.Solids[0].Faces)
    check("the object holds free faces besides its solid", faces > solid_faces, (faces, solid_faces))
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")

    # Recognise: the part selected, the command, OK.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(part)
    pump()
    check("Recognise active on the imported object", Gui.Command.get("AeroNC_RecogniseFeatures").isActive())
    Gui.runCommand("AeroNC_RecogniseFeatures")
    pump()
    check("recognise panel open", RecognisePanel.current is not None)
    RecognisePanel.current.direction.setCurrentIndex(len(recognise_panel.DIRECTION_CHOICES) - 1)  # all rows shown
    fits, detail = fits_combo_view(RecognisePanel.current.form, default_width)
    window_shot(doc, "aeronc_panel_recognise")
    check("the recognise panel fits the default combo view", fits, detail)
    RecognisePanel.current.direction.setCurrentIndex(0)
    check("OK pressed", click_ok())
    pump(0.5)
    check("recognised without error", not errors, errors)
    groups = [o for o in doc.Objects if objects.is_machining_features(o)]
    check("one Machining Features group", len(groups) == 1)
    if not groups:
        return
    group = groups[0]
    result = objects.result_of(group)
    check("the result counts the object's faces", result.get("faceCount") == faces, (result.get("faceCount"), faces))
    check("the free faces are named as left out", len(result.get("leftOutFaces", [])) == faces - solid_faces and
          any("left out" in w for w in group.Warnings), (result.get("leftOutFaces"), list(group.Warnings)))
    check("the group is up to date", not group.Outdated)
    warnings = list(group.Warnings)
    check("each warning said once", len(warnings) == len(set(warnings)), warnings)
    check("nothing selected after Recognise: the colours show", not Gui.Selection.getSelection(),
          [o.Label for o in Gui.Selection.getSelection()])
    window_shot(doc, "aeronc_recognised_ctc04")
    colours = [tuple(round(c, 3) for c in col[:3]) for col in part.ViewObject.DiffuseColor]
    want = [tuple(round(c, 3) for c in col[:3]) for col in role_colours(result["faceRoles"])]
    check("every face of the object coloured by its role", colours == want, (len(colours), len(want)))
    element = next(o for o in doc.Objects if objects.proxy_type(o) == objects.DOMAIN_ELEMENT and o.FloorFaces)
    floor = element.FloorFaces[0][1][0]
    number = int(floor[len("Face"):])
    check("an element's floor is that face of the object",
          result["faceRoles"][number - 1] in ("floor", "counterbore_floor") and
          part.Shape.getElement(floor).Surface.__class__.__name__ == "Plane", (element.Label, floor))

    # Select tools on the new group.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(group)
    pump()
    Gui.runCommand("AeroNC_SelectTools")
    pump()
    panel = SelectToolsPanel.current
    check("select tools panel open", panel is not None)
    panel.material.setCurrentIndex(panel.material.findText("7050-T7451"))
    panel.run_button.click()
    pump()
    check("Select tools does not refuse", not errors and panel.plan is not None, errors)
    check("the knowledge base path is elided, whole in its tooltip",
          panel.kb_label.toolTip() == knowledge_base.user_kb_path() and panel.kb_label.text() != panel.kb_label.toolTip(),
          (panel.kb_label.text(), panel.kb_label.toolTip()))
    fits, detail = fits_combo_view(panel.form, default_width)
    window_shot(doc, "aeronc_panel_select_tools")
    check("the Select tools panel fits the default combo view", fits, detail)
    check("its table scrolls sideways", panel.table.horizontalScrollBar().maximum() > 0,
          panel.table.horizontalScrollBar().maximum())
    check("Close pressed", click_ok(QtGui.QDialogButtonBox.Close))
    pump()
    check("Select tools makes no Job (the machining chain does)", not pathcompat.jobs_of_part(doc, part),
          [j.Label for j in pathcompat.jobs_of_part(doc, part)])
    from aeronc.pipeline import chain_building
    chain = chain_building.build(group, "integral_panel", group.Material, group.Machine)
    jobs = list(chain.Jobs)
    check("the machining chain's Jobs", jobs, chain.Messages)
    if not jobs:
        return

    # Optimise a chain Job's cutting parameters from its operations.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(jobs[0])
    pump()
    Gui.runCommand("AeroNC_OptimiseCutting")
    pump(0.5)
    opt = OptimiseCuttingPanel.current
    check("optimise panel open", opt is not None)
    opt.run_button.click()
    pump()
    answered = [p for p in opt.proposals if p.ok]
    check("Optimise answers for the milling tools", answered and not errors,
          (errors, [(p.tc.Label, p.error) for p in opt.proposals]))
    fits, detail = fits_combo_view(opt.form, default_width)
    window_shot(doc, "aeronc_panel_optimise")
    check("the Optimise panel fits the default combo view", fits, detail)
    check("OK pressed", click_ok())
    pump()
    check("no refusal on OK", not errors, errors)

    # The knowledge-base editor, with its long path and wide tables.
    Gui.runCommand("AeroNC_EditKnowledgeBase")
    pump()
    from aeronc.panels.knowledge_base_panel import KnowledgeBasePanel
    kbp = KnowledgeBasePanel.current
    check("knowledge base panel open", kbp is not None)
    fits, detail = fits_combo_view(kbp.form, default_width)
    window_shot(doc, "aeronc_panel_knowledge_base")
    check("the knowledge base panel fits the default combo view", fits, detail)
    check("Close pressed", click_ok(QtGui.QDialogButtonBox.Close))
    pump()
    FreeCAD.closeDocument(doc.Name)


main(run)
