"""GUI test of the whole workflow on a real part, as a CAM programmer drives it:

    HOME=<temp home> AERONC_PART=nist/nist_ftc_10_asme1_rb.stp AERONC_SHARED_DATA=../shared/data \\
        QTWEBENGINE_DISABLE_SANDBOX=1 xvfb-run -a freecad tests/gui/test_workflow_gui.py

File > Import of the part (AERONC_PART, relative to AERONC_SHARED_DATA), Recognise (OK), look
at an element, Select tools, then Machining chain: OK on the fresh panel, the Jobs. Each step is
checked for what a person sees: the status bar's summary, the legend, the element's
properties, the chain panel's counts above its tree, the Combo View's width, the Jobs' post,
one setup shown at a time, nothing left to recompute. Screenshots go to AERONC_ARTIFACTS as
workflow_<part>_*.png. Prints "N passed, N failed"; exits 0 when all checks pass.
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
    check, click_ok, combo_view_width, main, pump, window_shot)

PART = os.path.join(os.environ.get("AERONC_SHARED_DATA", ""), os.environ.get("AERONC_PART", ""))
NAME = os.path.splitext(os.path.basename(PART))[0]


def visible(objs):
    """True when every one is shown, False when none is, None otherwise."""
    v = {o.ViewObject.Visibility for o in objs}
    return v.pop() if len(v) == 1 else None


def run():
    import ImportGui
    from aeronc import objects, pathcompat
    from aeronc.objects import machining_chain as chain_object
    from aeronc.pipeline import knowledge_base
    from aeronc.panels import machining_chain_panel, recognise_panel, select_tools_panel
    from aeronc.panels.machining_chain_panel import MachiningChainPanel
    from aeronc.panels.recognise_panel import RecognisePanel
    from aeronc.panels.select_tools_panel import SelectToolsPanel
    errors = []
    for module in (recognise_panel, select_tools_panel, machining_chain_panel):
        module.show_error = errors.append
    kb_path = knowledge_base.user_kb_path()
    if os.path.exists(kb_path):
        os.remove(kb_path)
    check("part present", os.path.isfile(PART), PART)

    Gui.activateWorkbench("PathWorkbench")
    pump()
    default_width = combo_view_width()
    doc = FreeCAD.newDocument("Workflow")
    ImportGui.insert(PART, doc.Name)  # what File > Import runs for a STEP file
    doc.recompute()
    pump()
    parts = [o for o in doc.Objects if hasattr(o, "Shape") and o.Shape.Solids and not o.InList]
    check("the part imported", len(parts) >= 1, [o.Name for o in doc.Objects])
    part = max(parts, key=lambda o: o.Shape.Volume)
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")

    # Recognise.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(part)
    pump()
    Gui.runCommand("AeroNC_RecogniseFeatures")
    pump()
    panel = RecognisePanel.current
    check("recognise panel open", panel is not None)
    swatches = panel.form.findChildren(QtGui.QLabel, QtCore.QRegExp("legend_.*")) if panel else []
    check("the panel shows the role colours", len(swatches) == len(recognise_panel.LEGEND), len(swatches))
    check("OK pressed", click_ok())
    # What the status bar says in the second after OK (moving over the 3-D view may clear it).
    said = []
    for _ in range(20):
        pump(0.05)
        said.append(Gui.getMainWindow().statusBar().currentMessage())
    check("recognised without error", not errors, errors)
    groups = [o for o in doc.Objects if objects.is_machining_features(o)]
    check("one Machining Features group", len(groups) == 1)
    if not groups:
        return
    group = groups[0]
    result = objects.result_of(group)
    check("elements recognised", len(result.get("elements", [])) > 0)
    first = next((k for k, m in enumerate(said) if m.startswith("AeroNC: ") and "domain elements" in m), None)
    check("the status bar shows the summary, and no warning after it", first is not None and
          all(not m or m == said[first] for m in said[first:]), sorted(set(said)))
    warnings = list(group.Warnings)
    check("each warning said once", len(warnings) == len(set(warnings)), warnings)
    window_shot(doc, "workflow_{}_recognised".format(NAME))

    # An element clicked: it alone is selected, its properties readable.
    element = next(o for o in doc.Objects if objects.proxy_type(o) == objects.DOMAIN_ELEMENT and o.Faces)
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(element)
    pump()
    check("an element clicked is selected alone", [o.Name for o in Gui.Selection.getSelection()] == [element.Name],
          [o.Name for o in Gui.Selection.getSelection()])

    # Select tools: Close makes the part's Job.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(group)
    pump()
    Gui.runCommand("AeroNC_SelectTools")
    pump()
    tools = SelectToolsPanel.current
    check("select tools panel open", tools is not None)
    tools.material.setCurrentIndex(tools.material.findText("7050-T7451"))
    tools.run_button.click()
    pump()
    check("Select tools does not refuse", not errors and tools.plan is not None, errors)
    check("Close pressed", click_ok(QtGui.QDialogButtonBox.Close))
    pump()

    # Machining chain: OK on the fresh panel builds the chain, then the Jobs.
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(group)
    pump()
    Gui.runCommand("AeroNC_MachiningChain")
    pump()
    chain_panel = MachiningChainPanel.current
    check("chain panel open", chain_panel is not None)
    chain_panel.material.setCurrentIndex(chain_panel.material.findText("7050-T7451"))
    chain_panel.build_button.click()
    pump()
    check("chain built", not errors and chain_panel.chain is not None, errors)
    recognised = len(result["elements"])
    machined = {u["element"] for u in chain_panel.chain["units"]}
    left = {e["element"] for e in chain_panel.chain.get("unmachined", [])}
    summary = chain_panel.summary.text()
    check("the summary counts the elements machined of those recognised",
          "{} of {} elements machined".format(len(machined), recognised) in summary, summary)
    check("the Not machined tab counts its elements",
          chain_panel.findings.tabText(0) == "Not machined ({})".format(len(left)), chain_panel.findings.tabText(0))
    if left:
        check("what is not machined shows first", chain_panel.findings.currentIndex() == 0 and
              chain_panel.unmachined.count() >= len(left))
    window_shot(doc, "workflow_{}_chain_panel".format(NAME))
    check("OK pressed", click_ok())
    pump(1.0)
    check("no error on OK", not errors, errors)
    check("the Combo View back to its width", abs((combo_view_width() or 0) - default_width) <= 2,
          (combo_view_width(), default_width))
    chains = [o for o in doc.Objects if chain_object.is_machining_chain(o)]
    check("one Machining chain", len(chains) == 1)
    if not chains:
        return
    chain = chains[0]
    jobs = list(chain.Jobs)
    check("a Job per setup", len(jobs) == len(chain_panel.chain["setups"]) > 0,
          (len(jobs), len(chain_panel.chain["setups"])))
    check("the Jobs post with the machine's post",
          all(j.PostProcessor == "aeronc_840d" for j in jobs), [j.PostProcessor for j in jobs])
    touched = [o.Name for o in doc.Objects if "Touched" in o.State]
    check("nothing left to recompute after OK", not touched, touched)
    check("only the first setup shown", visible(pathcompat.job_models(jobs[0])) and
          all(visible(pathcompat.job_models(j)) is False for j in jobs[1:]) and
          not part.ViewObject.Visibility)
    Gui.activeDocument().activeView().viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    window_shot(doc, "workflow_{}_paths".format(NAME))
    FreeCAD.closeDocument(doc.Name)


main(run)
