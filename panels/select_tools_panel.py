"""Task panel of AeroNC_SelectTools: workpiece material and machine, then the plan.

"Select tools" plans from the stored tree (with a progress dialog), records the
tools on the elements and the plan on the group in one undo step (the machining chain makes
the ToolControllers in its Jobs), and lists the result here: per element its finishing and roughing tool, eta and any error, with the tool changes
and roughing time before and after merging. Errors go to the report view and a message box;
the document is then unchanged.
"""
import traceback

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from aeronc.pipeline import knowledge_base, tool_planning
from aeronc.errors import AeroNCError
from aeronc.panels.narrow import ElidedLabel, compact_combo, wrapping_form
from aeronc.panels.result_table import add_run_and_results
from aeronc.panels.base import error_reporter

COLUMNS = ["Element", "Type", "Finishing", "Roughing", "\u03b7", "Narrow", "Problem"]


show_error = error_reporter("tool selection failed")  # tests may replace it


class SelectToolsPanel:
    current = None  # the open panel, for scripts and tests

    def __init__(self, group, kb_path=None):
        self.group = group
        self.kb_path = kb_path
        self.plan = None
        self.form = self._build_form()
        SelectToolsPanel.current = self

    def _build_form(self):
        import aeronc
        w = QtGui.QWidget()
        w.setWindowTitle("Select tools")
        w.setWindowIcon(QtGui.QIcon(aeronc.icon("SelectTools")))
        lay = QtGui.QVBoxLayout(w)
        form = wrapping_form()
        self.material = compact_combo(QtGui.QComboBox())
        self.machine = compact_combo(QtGui.QComboBox())
        try:
            kb = knowledge_base.open_kb(self.kb_path)
            self.material.addItems(kb.workpiece_materials())
            self.machine.addItems(kb.machine_names())
            where = kb.path
        except Exception as e:  # the panel still opens and says why
            where = "cannot open: {}".format(e)
        previous = getattr(self.group, "Material", "")
        if previous and self.material.findText(previous) >= 0:
            self.material.setCurrentIndex(self.material.findText(previous))
        previous = getattr(self.group, "Machine", "")
        if previous and self.machine.findText(previous) >= 0:
            self.machine.setCurrentIndex(self.machine.findText(previous))
        form.addRow("Workpiece material", self.material)
        form.addRow("Machine", self.machine)
        self.kb_label = ElidedLabel(where)  # a path: the whole width, the middle elided
        form.addRow("Knowledge base", self.kb_label)
        lay.addLayout(form)
        self.run_button, self.summary, self.table = add_run_and_results(lay, "Select tools", self.run, COLUMNS)
        self.table.setMinimumHeight(260)
        return w

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Close)

    def reject(self):
        SelectToolsPanel.current = None
        FreeCADGui.Control.closeDialog()
        return True

    def run(self):
        progress = QtGui.QProgressDialog("Planning tools...", "Cancel", 0, 100,
                                         FreeCADGui.getMainWindow())
        progress.setWindowModality(QtCore.Qt.WindowModal)
        progress.setMinimumDuration(300)

        def report(fraction, stage):
            progress.setValue(int(100 * fraction))
            progress.setLabelText(stage)
            QtGui.QApplication.processEvents()
            return not progress.wasCanceled()

        try:
            self.plan = tool_planning.select_tools(self.group, self.material.currentText(),
                                                   self.machine.currentText(), self.kb_path, progress=report)
        except AeroNCError as e:
            show_error(str(e))
            return False
        except Exception as e:  # a bug: report it with its traceback, keep FreeCAD alive
            FreeCAD.Console.PrintError(traceback.format_exc())
            show_error("unexpected error: {}".format(e))
            return False
        finally:
            progress.close()
        self._show(self.plan)
        return True

    def _show(self, plan):
        rows = [(e["id"], e["type"], e["finishingTool"], e["roughingTool"],
                 "" if e["eta"] is None else "{:.3f}".format(e["eta"]), e["narrowPassages"] or "",
                 e["error"] or "") for e in plan["elements"]]
        rows += [(h["id"], "hole \u00d8{:g}".format(round(h["diameter"], 3)), h["drill"], "", "", "", h["error"] or "")
                 for h in plan["holes"]]
        self.table.setRowCount(len(rows))
        for r, row in enumerate(sorted(rows)):
            for c, value in enumerate(row):
                item = QtGui.QTableWidgetItem("" if value is None else str(value))
                if c == 6 and value:
                    item.setForeground(QtGui.QBrush(QtGui.QColor("#b00020")))
                    item.setToolTip(str(value))
                self.table.setItem(r, c, item)
        self.table.resizeColumnsToContents()
        tc, tm = plan["toolChanges"], plan["timeMin"]
        missing = sum(1 for e in plan["elements"] if e["error"]) + sum(1 for h in plan["holes"] if h["error"])
        self.summary.setText(
            "Roughing tool changes {} \u2192 {}; roughing time {:.1f} \u2192 {:.1f} min. "
            "{} tools and cutting operations planned. {}".format(
                tc["before"], tc["after"], tm["before"] or 0, tm["after"] or 0, len(plan.get("toolSettings", [])),
                "{} element(s) without a tool: see Problem.".format(missing) if missing else "Every element has its tools."))
