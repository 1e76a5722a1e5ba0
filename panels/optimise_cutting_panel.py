"""Task panel of AeroNC_OptimiseCutting.

It optimises as soon as it opens (the knowledge base's defaults, or what Select tools recorded)
and again on "Optimise" after the inputs change. Per ToolController the table gives the cut it
was measured from, the spindle speed and feed now and proposed, the active limits or why there
is no answer. The selected row's plot shows the objective over (n, f_z), the infeasible part
hatched, the limits, the optimum and the current setting; below it, the core's comparison
table. OK writes every proposal that has an answer as one undo step; Cancel writes nothing.
"""
import traceback

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from aeronc.pipeline import cutting_optimisation as co
from aeronc.pipeline import knowledge_base
from aeronc.errors import AeroNCError
from aeronc.panels.narrow import ScaledPicture, compact_combo, scrolling, wrapping_form
from aeronc.panels.result_table import add_run_and_results
from aeronc.panels.base import error_reporter

COLUMNS = ["ToolController", "Operation", "a_p \u00d7 a_e mm", "n r/min", "v_f mm/min", "Active limits / problem"]
METHOD_LABELS = [("nlopt", "Deterministic (scan + NLopt)"), ("ga", "Genetic algorithm"),
                 ("both", "Both, side by side")]
MAP_POINTS = 81
PLOT_SIZE_IN, PLOT_DPI = (5.4, 4.2), 80
PREFS = "User parameter:BaseApp/Preferences/Mod/AeroNC/Optimise"


show_error = error_reporter("cutting-parameter optimisation")  # tests may replace it


def _spin(value, low, high, decimals, suffix="", step=None):
    s = QtGui.QDoubleSpinBox()
    s.setRange(low, high)
    s.setDecimals(decimals)
    s.setValue(value)
    if suffix:
        s.setSuffix(" " + suffix)
    if step:
        s.setSingleStep(step)
    return s


class OptimiseCuttingPanel:
    current = None  # the open panel, for scripts and tests

    def __init__(self, target, kb_path=None):
        self.target = target
        self.kb_path = kb_path
        self.proposals = []
        self.job, self.tcs = co.tool_controllers_of(target)
        self.form = self._build_form()
        OptimiseCuttingPanel.current = self
        QtCore.QTimer.singleShot(0, self.run)

    # -- the form ---------------------------------------------------------------------------
    def _build_form(self):
        import aeronc
        prefs = FreeCAD.ParamGet(PREFS)
        w = QtGui.QWidget()
        w.setWindowTitle("Optimise cutting")  # the task box header: short enough for the default width
        w.setWindowIcon(QtGui.QIcon(aeronc.icon("OptimiseCutting")))
        lay = QtGui.QVBoxLayout(w)
        what = "{} ToolControllers of {}".format(len(self.tcs), self.job.Label) if len(self.tcs) > 1 \
            else "{} in {}".format(self.tcs[0].Label, self.job.Label)
        head = QtGui.QLabel("<b>{}</b>".format(what))
        head.setWordWrap(True)
        lay.addWidget(head)

        form = wrapping_form()
        self.material = compact_combo(QtGui.QComboBox())
        self.machine = compact_combo(QtGui.QComboBox())
        finishing_ra = 3.2
        try:
            kb = knowledge_base.open_kb(self.kb_path)
            self.material.addItems(kb.workpiece_materials())
            self.machine.addItems(kb.machine_names())
            finishing_ra = kb.threshold("ra_max_um")
        except Exception as e:  # the panel still opens; Optimise will say why
            FreeCAD.Console.PrintError("AeroNC: {}\n".format(e))
        material, machine = co.defaults_for(self.job)
        material = material or prefs.GetString("material", "")
        machine = machine or prefs.GetString("machine", "")
        for combo, value in ((self.material, material), (self.machine, machine)):
            if value and combo.findText(value) >= 0:
                combo.setCurrentIndex(combo.findText(value))
        form.addRow("Workpiece material", self.material)
        form.addRow("Machine", self.machine)
        self.method = QtGui.QComboBox()
        for key, label in METHOD_LABELS:
            self.method.addItem(label, key)
        compact_combo(self.method)
        form.addRow("Method", self.method)
        self.ra_roughing = _spin(co.ROUGHING_RA_MAX_UM, 0.0001, 100, 4, "\u00b5m", 0.1)
        self.ra_finishing = _spin(finishing_ra, 0.0001, 100, 4, "\u00b5m", 0.1)
        form.addRow("R_a,max roughing", self.ra_roughing)
        form.addRow("R_a,max finishing", self.ra_finishing)
        lay.addLayout(form)

        econ = QtGui.QGroupBox("Economics")
        econ.setCheckable(True)
        econ.setChecked(False)  # folded: the defaults serve most shops
        ef = wrapping_form(econ)
        d = co.DEFAULT_ECONOMICS
        self.t0 = _spin(prefs.GetFloat("t_0_min", d["t_0_min"]), 0, 1000, 2, "min")
        self.c0 = _spin(prefs.GetFloat("c_0_per_min", d["c_0_per_min"]), 0, 1e6, 2, "/min")
        self.ct = _spin(prefs.GetFloat("c_t_per_tool_life", d["c_t_per_tool_life"]), 0, 1e6, 2)
        self.w_time = _spin(prefs.GetFloat("w_time", d["w_time"]), 0, 1, 2, step=0.1)
        ef.addRow("Auxiliary time per part t_0", self.t0)
        ef.addRow("Machine and operator c_0", self.c0)
        ef.addRow("Cost of one tool life c_t", self.ct)
        ef.addRow("Weight of time w1 (cost 1 \u2212 w1)", self.w_time)
        def fold(on):
            for child in econ.findChildren(QtGui.QWidget):
                child.setVisible(on)
            econ.setFlat(not on)
        fold(False)
        econ.toggled.connect(fold)
        lay.addWidget(econ)

        self.run_button, self.summary, self.table = add_run_and_results(lay, "Optimise", self.run, COLUMNS)
        self.table.setSelectionBehavior(QtGui.QAbstractItemView.SelectRows)
        self.table.setSelectionMode(QtGui.QAbstractItemView.SingleSelection)
        self.table.itemSelectionChanged.connect(self._show_selected)

        self.plot = ScaledPicture()  # drawn at its full size, shown at the panel's width
        self.plot.setAutoFillBackground(True)
        lay.addWidget(self.plot)
        self.report = QtGui.QPlainTextEdit()
        self.report.setReadOnly(True)
        self.report.setLineWrapMode(QtGui.QPlainTextEdit.NoWrap)
        self.report.setFont(QtGui.QFontDatabase.systemFont(QtGui.QFontDatabase.FixedFont))
        self.report.setMinimumHeight(120)
        lay.addWidget(scrolling(self.report))
        return w

    def _economics(self):
        w = self.w_time.value()
        return {"t_0_min": self.t0.value(), "c_0_per_min": self.c0.value(),
                "c_t_per_tool_life": self.ct.value(), "w_time": w, "w_cost": 1.0 - w}

    def _remember(self):
        prefs = FreeCAD.ParamGet(PREFS)
        prefs.SetString("material", self.material.currentText())
        prefs.SetString("machine", self.machine.currentText())
        for key, value in self._economics().items():
            if key != "w_cost":
                prefs.SetFloat(key, value)

    # -- running ------------------------------------------------------------------------------
    def run(self):
        """Optimise every ToolController of the target; returns True when it ran."""
        progress = QtGui.QProgressDialog("Optimising cutting parameters...", "", 0, len(self.tcs),
                                         FreeCADGui.getMainWindow())
        progress.setCancelButton(None)
        progress.setWindowModality(QtCore.Qt.WindowModal)
        progress.setMinimumDuration(500)

        def report(done, total, label):
            progress.setValue(done)
            progress.setLabelText("Optimising {}".format(label) if label else "Done")
            QtGui.QApplication.processEvents()

        try:
            self.proposals = co.propose(self.target, self.material.currentText(), self.machine.currentText(),
                                        self.kb_path, self.method.currentData(),
                                        {"roughing": self.ra_roughing.value(), "finishing": self.ra_finishing.value()},
                                        self._economics(), MAP_POINTS, report)
        except AeroNCError as e:
            self.proposals = []
            self._fill()
            show_error(str(e))
            return False
        except Exception as e:  # a bug: report it with its traceback, keep FreeCAD alive
            FreeCAD.Console.PrintError(traceback.format_exc())
            self.proposals = []
            self._fill()
            show_error("unexpected error: {}".format(e))
            return False
        finally:
            progress.close()
        self._remember()
        self._fill()
        return True

    def _fill(self):
        rows = []
        for p in self.proposals:
            now_n, now_f, _ = p.current
            if p.ok:
                o = p.optimum
                cut = p.result["parameters"]["cut"]  # as solved: a_p may come from the knowledge base
                rows.append((p.tc.Label, p.operation, "{:.3g} \u00d7 {:.3g}".format(cut["a_p_mm"], cut["a_e_mm"]),
                    "{:.0f} \u2192 {:.0f}".format(now_n, o["n_rpm"]),
                    "{:.0f} \u2192 {:.0f}".format(now_f, p.horiz_feed), ", ".join(o["active"]) or "none", False))
            else:
                rows.append((p.tc.Label, p.operation, "", "{:.0f}".format(now_n), "{:.0f}".format(now_f),
                             ("left as it is: " if p.skipped else "") + p.error, not p.skipped))
        self.table.setRowCount(len(rows))
        for r, row in enumerate(rows):
            for c, value in enumerate(row[:-1]):
                item = QtGui.QTableWidgetItem(value)
                if c == len(COLUMNS) - 1:
                    item.setToolTip(value)
                    if row[-1]:
                        item.setForeground(QtGui.QBrush(QtGui.QColor("#b00020")))
                self.table.setItem(r, c, item)
        self.table.resizeColumnsToContents()
        header = self.table.horizontalHeader().height()
        row_height = self.table.verticalHeader().defaultSectionSize()
        self.table.setFixedHeight(min(240, header + row_height * max(1, len(rows)) + 2 * self.table.frameWidth() + 18))
        good = sum(1 for p in self.proposals if p.ok)
        bad = sum(1 for p in self.proposals if p.error and not p.skipped)
        self.summary.setText("{} of {} ToolControllers optimised{}. OK writes their spindle speed and feeds "
                             "(one undo step).".format(good, len(self.proposals),
                                                       "; {} without an answer (see the table)".format(bad)
                                                       if bad else ""))
        first = next((i for i, p in enumerate(self.proposals) if p.ok), 0 if self.proposals else None)
        self.table.blockSignals(True)  # one plot, drawn below
        if first is not None:
            self.table.selectRow(first)
        self.table.blockSignals(False)
        self._show_selected()

    def selected_proposal(self):
        rows = self.table.selectionModel().selectedRows() if self.table.selectionModel() else []
        if not rows or rows[0].row() >= len(self.proposals):
            return None
        return self.proposals[rows[0].row()]

    def _show_selected(self):
        p = self.selected_proposal()
        self.plot.clear()
        if p is None:
            self.report.setPlainText("")
            return
        if not p.ok:
            self.plot.setText(p.error)
            self.plot.setWordWrap(True)
            self.report.setPlainText(p.error)
            return
        from aeronc.reports import optimisation_plot
        try:
            png = optimisation_plot.render(p.result, "{}: {} / {} / {}".format(
                p.tc.Label, p.params["kb"]["workpiece_material"], p.tool_material, p.operation), *PLOT_SIZE_IN, PLOT_DPI)
            pix = QtGui.QPixmap()
            pix.loadFromData(png, "PNG")
            self.plot.set_picture(pix)
        except Exception as e:  # a plot that cannot be drawn must not hide the answer
            FreeCAD.Console.PrintLog(traceback.format_exc())
            self.plot.setText("no plot: {}".format(e))
        cut = p.result["parameters"]["cut"]
        self.report.setPlainText("{}\n\nCut: {}\n\n{}".format(p.summary(), cut.get("source", ""), p.text))

    # -- task dialog ----------------------------------------------------------------------------
    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)

    def accept(self):
        try:
            written = co.apply(self.proposals)
        except AeroNCError as e:
            show_error(str(e))
            return False
        except Exception as e:  # a bug: report it with its traceback, keep FreeCAD alive
            FreeCAD.Console.PrintError(traceback.format_exc())
            show_error("unexpected error: {}".format(e))
            return False
        FreeCAD.Console.PrintMessage("AeroNC: cutting parameters written to {}\n".format(
            ", ".join(tc.Label for tc in written)))
        OptimiseCuttingPanel.current = None
        FreeCADGui.Control.closeDialog()
        return True

    def reject(self):
        OptimiseCuttingPanel.current = None
        FreeCADGui.Control.closeDialog()
        return True
