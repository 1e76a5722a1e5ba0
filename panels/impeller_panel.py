"""Task panel of AeroNC_ProgramImpeller.

Opened on a solid: the blank allowance and how fine the toolpaths are (stations along each
pass, channels to machine, 0 for all), then "Program": recognition, blank, Job with the route's
operations and the posted 840D program are made as one undo step; a part that is no impeller
(or has unequal blade groups, or no hub) leaves the document as it was and the core's message
is shown.

Opened on a program (or after "Program"): the process route, step by step, with its tool and
allowance. Unticking a step switches its operation off, choosing another tool or another
roughing allowance computes the toolpaths again and posts again: each change is one undo step.
"Apply allowance" makes the blank again; "Re-run" computes everything again with the edits.
The checks (deepest gouge, holder collisions), the cutting data and the program file are shown
under the route.
"""
import traceback

import FreeCADGui
from PySide import QtCore, QtGui

from aeronc.impeller import programming
from aeronc.panels.narrow import widen_dock
from aeronc.errors import AeroNCError
from aeronc.panels.base import error_reporter

COLUMNS = ["On", "Step", "Tool", "Allowance"]
DOCK_WIDTH = 520  # the route's four columns and the checks without a horizontal scroll bar
ON, STEP, TOOL, ALLOWANCE = range(4)


show_error = error_reporter("program impeller")  # tests may replace it


class ImpellerPanel:
    current = None  # the open panel, for scripts and tests

    def __init__(self, program=None, part=None, kb_path=None):
        self.program = program
        self.part = part if program is None else program.Features.Source
        self.kb_path = kb_path or (program.KnowledgeBase if program is not None else "") or None
        self._filling = False
        self.form = self._build_form()
        self._show_program()
        ImpellerPanel.current = self
        self._restore_dock = lambda: None
        QtCore.QTimer.singleShot(0, self._widen)

    # --- the form ----------------------------------------------------------------------------

    def _build_form(self):
        import aeronc
        form = QtGui.QWidget()
        form.setWindowTitle("Program impeller")
        form.setWindowIcon(QtGui.QIcon(aeronc.icon("Impeller")))
        layout = QtGui.QVBoxLayout(form)
        self.part_label = QtGui.QLabel()
        self.part_label.setWordWrap(True)
        layout.addWidget(self.part_label)

        grid = QtGui.QFormLayout()
        self.allowance = QtGui.QDoubleSpinBox()
        self.allowance.setRange(0.0, 50.0)
        self.allowance.setDecimals(2)
        self.allowance.setSuffix(" mm")
        self.allowance.setValue(self.program.Allowance.Value if self.program is not None else 2.0)
        self.allowance.setToolTip("Stock added to the revolved outer profile of the part to make the blank")
        grid.addRow("Blank allowance", self.allowance)
        self.stations = QtGui.QSpinBox()
        self.stations.setRange(2, 200)
        self.stations.setValue(self.program.Stations if self.program is not None else 24)
        self.stations.setToolTip("Positions along each pass; fewer for a quick look")
        grid.addRow("Stations a pass", self.stations)
        self.channels = QtGui.QSpinBox()
        self.channels.setRange(0, 1000)
        self.channels.setSpecialValueText("all")
        self.channels.setValue(self.program.Channels if self.program is not None else 0)
        self.channels.setToolTip("Channels to machine (all, or the first few for a quick look)")
        grid.addRow("Channels", self.channels)
        layout.addLayout(grid)

        buttons = QtGui.QHBoxLayout()
        self.program_button = QtGui.QPushButton("Program")
        self.program_button.setToolTip("Recognise the impeller, make the blank, the Job with the route's operations "
                                       "and the posted program (one undo step)")
        self.program_button.clicked.connect(self.program_part)
        self.allowance_button = QtGui.QPushButton("Apply allowance")
        self.allowance_button.clicked.connect(self.apply_allowance)
        self.rerun_button = QtGui.QPushButton("Re-run")
        self.rerun_button.setToolTip("Compute the toolpaths again with the route's edits and post again")
        self.rerun_button.clicked.connect(self.rerun)
        for b in (self.program_button, self.allowance_button, self.rerun_button):
            buttons.addWidget(b)
        layout.addLayout(buttons)

        self.table = QtGui.QTableWidget(0, len(COLUMNS))
        self.table.setHorizontalHeaderLabels(COLUMNS)
        self.table.verticalHeader().setVisible(False)
        self.table.horizontalHeader().setStretchLastSection(True)
        self.table.setSelectionMode(QtGui.QAbstractItemView.NoSelection)
        self.table.itemChanged.connect(self._item_changed)
        self.table.setMinimumHeight(300)  # the shipped route's eight steps without scrolling
        layout.addWidget(self.table, 1)

        self.summary = QtGui.QLabel()
        self.summary.setWordWrap(True)
        self.summary.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        layout.addWidget(self.summary)
        return form

    def _show_program(self):
        try:
            self.program is not None and self.program.Name
        except ReferenceError:  # undone or deleted meanwhile: back to programming the part
            self.program = None
        p = self.program
        self.part_label.setText("Part: <b>{}</b>".format(self.part.Label if self.part is not None else "?"))
        has = p is not None
        self.program_button.setEnabled(not has)
        self.stations.setEnabled(not has)
        self.channels.setEnabled(not has)
        self.allowance_button.setEnabled(has)
        self.rerun_button.setEnabled(has)
        self._filling = True
        try:
            self.table.setRowCount(0)
            if not has:
                self.summary.setText("Choose the blank allowance and press Program.")
                return
            steps = programming.steps_of(p)
            # The channel roughing and blade finishing take balls and tapered balls only.
            library = sorted(k for k, t in programming.tool_library(self.kb_path).items()
                             if t["type"] in ("ball", "tapered_ball"))
            self.table.setRowCount(len(steps))
            for row, s in enumerate(steps):
                self._fill_row(row, s, library)
            self.table.resizeColumnsToContents()
            g = p.Features
            self.summary.setText(
                "{} main + {} splitter blades; channel {:.3f} mm, fillet {:.3f} mm, blade {:.3f} mm.<br>"
                "Checks: deepest gouge <b>{:.4f} mm</b> (limit 0.01), holder collisions <b>{}</b>, {} positions "
                "checked, {} tilted.<br>Cutting data (optimiser):<br>{}<br>Program: {} lines{}".format(
                    g.BladeCount, g.SplitterCount, g.MinChannelWidth.Value, g.FilletRadius.Value,
                    g.BladeHeight.Value, p.MaxGouge, p.HolderCollisions, p.PositionsChecked, p.Tilted,
                    "<br>".join(p.CuttingData), p.ProgramLines,
                    ", " + p.ProgramFile if p.ProgramFile else " (save the document to write it next to it)"))
        finally:
            self._filling = False

    def _fill_row(self, row, s, library):
        on = QtGui.QTableWidgetItem()
        on.setFlags(QtCore.Qt.ItemIsUserCheckable | QtCore.Qt.ItemIsEnabled)
        on.setCheckState(QtCore.Qt.Checked if s["enabled"] else QtCore.Qt.Unchecked)
        on.setData(QtCore.Qt.UserRole, s["position"])
        self.table.setItem(row, ON, on)
        step = QtGui.QTableWidgetItem("{} {}".format(s["position"], s["operation"].replace("_", " ")))
        step.setFlags(QtCore.Qt.ItemIsEnabled)
        step.setToolTip("{} ({}){}".format(s.get("description", ""), s.get("strategy", ""),
                                           "\nTool: " + s["toolReason"] if s.get("toolReason") else ""))
        self.table.setItem(row, STEP, step)
        tool = (s.get("tool") or {}).get("id", "")
        if s["operation"] in ("rough_channels", "finish_blades"):
            combo = QtGui.QComboBox()
            combo.addItems(library)
            combo.setCurrentIndex(max(0, combo.findText(tool)))
            combo.currentIndexChanged.connect(lambda _i, c=combo, pos=s["position"]: self.choose_tool(pos, c.currentText()))
            self.table.setCellWidget(row, TOOL, combo)
        else:
            item = QtGui.QTableWidgetItem(tool or "-")
            item.setFlags(QtCore.Qt.ItemIsEnabled)
            if s["operation"] == "finish_hub":
                item.setToolTip("finished with the blade finishing tool")
            self.table.setItem(row, TOOL, item)
        if s["operation"] == "rough_channels":
            spin = QtGui.QDoubleSpinBox()
            spin.setRange(0.0, 10.0)
            spin.setDecimals(2)
            spin.setSingleStep(0.1)
            spin.setSuffix(" mm")
            spin.setValue(float(s["allowance"]))
            spin.editingFinished.connect(lambda sp=spin, pos=s["position"]: self.change_allowance(pos, sp.value()))
            self.table.setCellWidget(row, ALLOWANCE, spin)
        else:
            item = QtGui.QTableWidgetItem("{:.2f} mm".format(float(s.get("allowance") or 0.0)))
            item.setFlags(QtCore.Qt.ItemIsEnabled)
            self.table.setItem(row, ALLOWANCE, item)

    # --- actions (each one undo step) --------------------------------------------------------

    def _run(self, work):
        """Run an action with a wait cursor; AeroNCError is shown, the document is unchanged."""
        QtGui.QApplication.setOverrideCursor(QtCore.Qt.WaitCursor)
        try:
            work()
            return True
        except AeroNCError as e:
            show_error(str(e))
            return False
        except Exception:
            show_error(traceback.format_exc())
            return False
        finally:
            QtGui.QApplication.restoreOverrideCursor()
            self._show_program()
            if FreeCADGui.ActiveDocument is not None:
                FreeCADGui.ActiveDocument.ActiveView.fitAll()

    def program_part(self):
        doc = self.part.Document

        def work():
            self.program = programming.create(doc, self.part, allowance=self.allowance.value(),
                                                   kb_path=self.kb_path, stations=self.stations.value(),
                                                   channels=self.channels.value())
        return self._run(work)

    def _item_changed(self, item):
        if self._filling or item.column() != ON or self.program is None:
            return
        position = item.data(QtCore.Qt.UserRole)
        on = item.checkState() == QtCore.Qt.Checked
        # After the table is rebuilt: this item is deleted when the change is applied.
        QtCore.QTimer.singleShot(0, lambda: self.set_enabled(position, on))

    def set_enabled(self, position, on):
        return self._run(lambda: programming.set_step_enabled(self.program, position, on))

    def choose_tool(self, position, tool_id):
        if self._filling or self.program is None:
            return False
        return self._run(lambda: programming.set_step_tool(self.program, position, tool_id))

    def change_allowance(self, position, value):
        if self._filling or self.program is None:
            return False
        current = next(s for s in programming.steps_of(self.program) if s["position"] == position)
        if abs(float(current["allowance"]) - value) < 1e-9:
            return False
        return self._run(lambda: programming.set_step_allowance(self.program, position, value))

    def apply_allowance(self):
        if self.program is None:
            return False
        return self._run(lambda: programming.set_allowance(self.program, self.allowance.value()))

    def rerun(self):
        if self.program is None:
            return False
        return self._run(lambda: programming.update(self.program, title="Re-run impeller program"))

    # --- task dialog -------------------------------------------------------------------------

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Close)

    def _widen(self):
        self._restore_dock = widen_dock(DOCK_WIDTH)

    def reject(self):
        FreeCADGui.Control.closeDialog()
        ImpellerPanel.current = None
        self._restore_dock()
        return True
