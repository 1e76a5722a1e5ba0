"""Task panel of a measured-hole set: the deviation dP of every datum hole (also drawn as
arrows in the 3-D view, scaled), whether it is used or left out (out of line with the others,
named in red with why; Put back / Leave out on the selected one), the compensation method with
every method's leave-one-out error (the proposed one marked), and from here a re-import, the
compensated drilling and the report. Every change is one undo step, made at once."""
import os
import traceback

import FreeCAD
import FreeCADGui
from PySide import QtGui

from aeronc.panels.base import ask_open_file, ask_save_file, error_reporter


DEVIATION_COLUMNS = ["Id", "Use", "dX", "dY", "dZ", "|dP| mm", "Miss mm", "Quality"]
OUT_COLOUR = "#b00020"
LOO_COLUMNS = ["Method", "RMS mm", "Max mm", "Note"]


show_error = error_reporter("measured holes")  # tests may replace it


def _table(columns):
    t = QtGui.QTableWidget(0, len(columns))
    t.setHorizontalHeaderLabels(columns)
    t.setEditTriggers(QtGui.QAbstractItemView.NoEditTriggers)
    t.verticalHeader().setVisible(False)
    return t


class MeasuredHoleSetPanel:
    current = None

    def __init__(self, obj):
        self.obj = obj
        self.form = self._build_form()
        self.refresh()
        MeasuredHoleSetPanel.current = self

    def _build_form(self):
        import aeronc
        from aeronc.objects import measured_hole_set as mhs
        w = QtGui.QWidget()
        w.setWindowTitle("Measured datum holes")
        w.setWindowIcon(QtGui.QIcon(aeronc.icon("MeasuredHoleSet")))
        lay = QtGui.QVBoxLayout(w)
        self.info = QtGui.QLabel("")
        self.info.setWordWrap(True)
        lay.addWidget(self.info)
        self.deviations = _table(DEVIATION_COLUMNS)
        self.deviations.setMinimumHeight(170)
        self.deviations.setSelectionBehavior(QtGui.QAbstractItemView.SelectRows)
        self.deviations.setSelectionMode(QtGui.QAbstractItemView.SingleSelection)
        lay.addWidget(self.deviations)
        self.flags = QtGui.QLabel("")
        self.flags.setWordWrap(True)
        self.flags.setStyleSheet("color: {}".format(OUT_COLOUR))
        lay.addWidget(self.flags)
        row = QtGui.QHBoxLayout()
        self.put_back_button = QtGui.QPushButton("Put back")
        self.put_back_button.setToolTip("Use the selected datum hole although it is out of line with the others")
        self.leave_out_button = QtGui.QPushButton("Leave out")
        self.leave_out_button.setToolTip("Never use the selected datum hole")
        self.put_back_button.clicked.connect(lambda: self.put_back())
        self.leave_out_button.clicked.connect(lambda: self.leave_out())
        row.addWidget(self.put_back_button)
        row.addWidget(self.leave_out_button)
        row.addStretch(1)
        lay.addLayout(row)
        form = QtGui.QFormLayout()
        self.scale = QtGui.QDoubleSpinBox()
        self.scale.setRange(1.0, 100000.0)
        self.scale.setDecimals(0)
        self.scale.setValue(self.obj.ArrowScale)
        self.scale.editingFinished.connect(self.set_scale)
        form.addRow("Arrows drawn x", self.scale)
        self.method = QtGui.QComboBox()
        self.method.addItems(mhs.method_names())
        self.method.setCurrentIndex(self.method.findText(self.obj.Method))
        self.method.currentIndexChanged.connect(lambda _i: self.choose(self.method.currentText()))
        form.addRow("Compensation method", self.method)
        lay.addLayout(form)
        self.loo = _table(LOO_COLUMNS)
        self.loo.setMinimumHeight(250)  # all seven methods without scrolling
        lay.addWidget(QtGui.QLabel("Leave-one-out error over the datum holes used (each predicted from the others):"))
        lay.addWidget(self.loo)
        self.status = QtGui.QLabel("")
        self.status.setWordWrap(True)
        lay.addWidget(self.status)
        row = QtGui.QHBoxLayout()
        self.reimport_button = QtGui.QPushButton("Re-import...")
        self.drill_button = QtGui.QPushButton("Compensated drilling")
        self.report_button = QtGui.QPushButton("Report...")
        self.reimport_button.clicked.connect(lambda: self.reimport())
        self.drill_button.clicked.connect(self.compensated_drilling)
        self.report_button.clicked.connect(lambda: self.write_report())
        for b in (self.reimport_button, self.drill_button, self.report_button):
            row.addWidget(b)
        lay.addLayout(row)
        return w

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Close)

    def reject(self):
        MeasuredHoleSetPanel.current = None
        FreeCADGui.Control.closeDialog()
        return True

    def refresh(self):
        o = self.obj
        self.info.setText("{} datum holes of {} from {} ({}), mapped through the calibration of {}.".format(
            len(o.HoleIds), o.PhotoHoleSet.Label if o.PhotoHoleSet else "?",
            os.path.basename(o.SourceFile) or "text", o.ImportedAt, o.Machine))
        from aeronc.objects import measured_hole_set as mhs
        verdicts = {d["id"]: d for d in mhs.result_of(o).get("datums", [])}
        self.deviations.setRowCount(len(o.HoleIds))
        for r, (hid, d) in enumerate(zip(o.HoleIds, o.Deviations)):
            q = o.Quality[r] if r < len(o.Quality) else -1
            v = verdicts.get(hid, {})
            miss = v.get("miss")
            values = [hid, v.get("use", ""), "{:.4f}".format(d.x), "{:.4f}".format(d.y), "{:.4f}".format(d.z),
                      "{:.4f}".format(d.Length), "" if miss is None else "{:.4f}".format(miss),
                      "" if q < 0 else "{:.3f}".format(q)]
            for c, text in enumerate(values):
                item = QtGui.QTableWidgetItem(text)
                if v.get("reason"):
                    item.setToolTip(v["reason"])
                if not v.get("used", True) or v.get("out_of_line"):
                    item.setForeground(QtGui.QBrush(QtGui.QColor(OUT_COLOUR)))
                    font = item.font()
                    font.setBold(True)
                    item.setFont(font)
                self.deviations.setItem(r, c, item)
        self.deviations.resizeColumnsToContents()
        self.flags.setText("\n".join("Datum hole " + line for line in o.DatumFlags))
        self.flags.setVisible(len(o.DatumFlags) > 0)
        figures = mhs.result_of(o).get("leave_one_out", [])
        self.loo.setRowCount(len(figures))
        for r, f in enumerate(figures):
            mark = []
            if f["method"] == o.ProposedMethod:
                mark.append("proposed")
            if f["method"] == o.MethodUsed:
                mark.append("used")
            values = [f["method"], "{:.4f}".format(f["rms"]) if f["available"] else "-",
                      "{:.4f}".format(f["max"]) if f["available"] else "-",
                      ", ".join(mark) if f["available"] else f["reason"]]
            for c, v in enumerate(values):
                item = QtGui.QTableWidgetItem(v)
                if f["method"] == o.ProposedMethod:
                    font = item.font()
                    font.setBold(True)
                    item.setFont(font)
                if not f["available"]:
                    item.setForeground(QtGui.QBrush(QtGui.QColor("#888888")))
                    item.setToolTip(f["reason"])
                self.loo.setItem(r, c, item)
        self.loo.resizeColumnsToContents()
        bad = o.Status.startswith("not compensated")
        from aeronc.operations import compensated_drilling
        ops = [op for op in compensated_drilling.operations_of(o.PhotoHoleSet) if op.MeasuredHoleSet is o] \
            if o.PhotoHoleSet is not None else []
        self.status.setText("\n".join([o.Status] + ["{}: {}".format(op.Label, op.Status) for op in ops]))
        self.status.setStyleSheet("color: #b00020" if bad else "")

    def _run(self, what):
        try:
            out = what()
        except Exception as e:
            FreeCAD.Console.PrintLog(traceback.format_exc())
            show_error(str(e))
            self.refresh()
            return None
        self.refresh()
        return out if out is not None else True

    def selected_id(self):
        rows = sorted({i.row() for i in self.deviations.selectedIndexes()})
        return self.obj.HoleIds[rows[0]] if rows else None

    def put_back(self, hole_id=None):
        from aeronc.objects import measured_hole_set as mhs
        hole_id = hole_id or self.selected_id()
        if hole_id is None:
            show_error("select a datum hole in the table first")
            return None
        return self._run(lambda: mhs.put_back(self.obj, hole_id))

    def leave_out(self, hole_id=None):
        from aeronc.objects import measured_hole_set as mhs
        hole_id = hole_id or self.selected_id()
        if hole_id is None:
            show_error("select a datum hole in the table first")
            return None
        return self._run(lambda: mhs.leave_out(self.obj, hole_id))

    def choose(self, method):
        from aeronc.objects import measured_hole_set as mhs
        if method == self.obj.Method:
            return True
        return bool(self._run(lambda: mhs.set_method(self.obj, method)))

    def set_scale(self):
        if abs(self.scale.value() - self.obj.ArrowScale) > 1e-9:
            self.obj.ArrowScale = self.scale.value()
            self.obj.Document.recompute()  # the drilling's correction arrows too

    def reimport(self, path=None):
        from aeronc.makers import datum_holes
        if path is None:
            path = ask_open_file("Measured datum holes (hole,u,v,height[,quality])", "CSV (*.csv *.txt);;All (*)")
            if not path:
                return None
        return self._run(lambda: datum_holes.import_measurements(self.obj.PhotoHoleSet, path, measured_set=self.obj))

    def compensated_drilling(self):
        from aeronc.makers import datum_holes
        return self._run(lambda: datum_holes.create_for_photo_set(self.obj.PhotoHoleSet, self.obj))

    def write_report(self, path=None):
        from aeronc.reports import compensation_report
        from aeronc.operations import compensated_drilling
        ops = [op for op in compensated_drilling.operations_of(self.obj.PhotoHoleSet) if op.MeasuredHoleSet is self.obj]
        if not ops:
            show_error("no compensated drilling uses these measurements yet: make one first")
            return None
        if path is None:
            path = ask_save_file("Compensation report", "HTML (*.html)", "compensation_report.html")
            if not path:
                return None
        return self._run(lambda: compensation_report.write_report(ops[0], path))
