"""Task panel of a photo-hole set: the datum holes in camera order (reorder, remove, take the
surface for normals from the selection), the spacing checks, and from here the camera
program, the import of measurements and the compensated drilling.

Every change is one undo step and is made at once (the panel only has Close). Errors go to
the report view and a message box; the document is then unchanged."""
import os
import traceback

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from aeronc.panels.base import ask_open_file, ask_save_file, error_reporter  # noqa: F401  (tests replace them here)

COLUMNS = ["#", "Id", "Faces", "\u00d8 mm", "Position (part frame)", "Normal"]


show_error = error_reporter("datum holes")  # tests may replace it




def _vec(v, digits=3):
    return "{:.{d}f}, {:.{d}f}, {:.{d}f}".format(v.x, v.y, v.z, d=digits)


class PhotoHoleSetPanel:
    current = None  # the open panel, for scripts and tests

    def __init__(self, obj):
        self.obj = obj
        self.form = self._build_form()
        self.refresh()
        PhotoHoleSetPanel.current = self

    def _build_form(self):
        import aeronc
        w = QtGui.QWidget()
        w.setWindowTitle("Datum (photo) holes")
        w.setWindowIcon(QtGui.QIcon(aeronc.icon("PhotoHoleSet")))
        lay = QtGui.QVBoxLayout(w)
        self.info = QtGui.QLabel("")
        self.info.setWordWrap(True)
        lay.addWidget(self.info)
        self.table = QtGui.QTableWidget(0, len(COLUMNS))
        self.table.setHorizontalHeaderLabels(COLUMNS)
        self.table.setEditTriggers(QtGui.QAbstractItemView.NoEditTriggers)
        self.table.setSelectionBehavior(QtGui.QAbstractItemView.SelectRows)
        self.table.verticalHeader().setVisible(False)
        self.table.setMinimumHeight(220)
        self.table.itemSelectionChanged.connect(self._select_in_view)
        lay.addWidget(self.table)
        row = QtGui.QHBoxLayout()
        self.up_button = QtGui.QPushButton("Up")
        self.down_button = QtGui.QPushButton("Down")
        self.remove_button = QtGui.QPushButton("Remove")
        self.surface_button = QtGui.QPushButton("Surface from selection")
        self.surface_button.setToolTip("Take the normals from the faces selected in the 3-D view "
                                       "(none selected: the face round each hole's entry)")
        self.up_button.clicked.connect(lambda: self.move(-1))
        self.down_button.clicked.connect(lambda: self.move(1))
        self.remove_button.clicked.connect(self.remove)
        self.surface_button.clicked.connect(self.surface_from_selection)
        for b in (self.up_button, self.down_button, self.remove_button, self.surface_button):
            row.addWidget(b)
        lay.addLayout(row)
        row = QtGui.QHBoxLayout()
        self.draw_row_button = QtGui.QPushButton("Draw row from selection")
        self.draw_row_button.setToolTip("A row of holes through the holes selected in the 3-D view, in the order "
                                        "selected; the seed's method and the spacing checks use it instead of "
                                        "the rows found automatically")
        self.clear_rows_button = QtGui.QPushButton("Clear drawn rows")
        self.draw_row_button.clicked.connect(self.draw_row_from_selection)
        self.clear_rows_button.clicked.connect(self.clear_drawn_rows)
        row.addWidget(self.draw_row_button)
        row.addWidget(self.clear_rows_button)
        lay.addLayout(row)
        self.checks = QtGui.QLabel("")
        self.checks.setWordWrap(True)
        lay.addWidget(self.checks)
        box = QtGui.QGroupBox("Camera and measurements")
        col = QtGui.QVBoxLayout(box)
        self.camera_button = QtGui.QPushButton("Write camera program...")
        self.import_button = QtGui.QPushButton("Import measurements...")
        self.drill_button = QtGui.QPushButton("Compensated drilling")
        self.camera_button.clicked.connect(lambda: self.write_camera_program())
        self.import_button.clicked.connect(lambda: self.import_file())
        self.drill_button.clicked.connect(self.compensated_drilling)
        for b in (self.camera_button, self.import_button, self.drill_button):
            col.addWidget(b)
        lay.addWidget(box)
        return w

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Close)

    def reject(self):
        PhotoHoleSetPanel.current = None
        FreeCADGui.Control.closeDialog()
        return True

    # -- showing -----------------------------------------------------------------------------
    def refresh(self):
        from aeronc.objects import photo_hole_set as phs
        o = self.obj
        surface = phs.surface_faces(o)
        self.info.setText("{} datum holes of {} in camera order; normals from {}; camera on {} at {:g} mm.".format(
            len(o.HoleIds), o.Source.Label if o.Source else "?", ", ".join(surface) or "the face round each hole",
            o.Machine, o.Standoff.Value))
        self.table.setRowCount(len(o.HoleIds))
        for r, h in enumerate(phs.holes_of(o)):
            values = [str(r + 1), h["id"], " ".join(h["faces"]), "{:.3f}".format(h["diameter"]),
                      _vec(o.Positions[r]), _vec(o.Normals[r], 4)]
            for c, v in enumerate(values):
                self.table.setItem(r, c, QtGui.QTableWidgetItem(v))
        self.table.resizeColumnsToContents()
        warnings = list(o.SpacingWarnings)
        drawn = len(phs.drawn_rows(o))
        self.clear_rows_button.setEnabled(drawn > 0)
        rows = "{}, {} drawn by hand".format(o.RowCount, drawn) if drawn else str(o.RowCount)
        if warnings:
            self.checks.setText("<b>Spacing checks</b> ({} rows of holes):<br>{}".format(
                rows, "<br>".join("\u26a0 " + w for w in warnings)))
            self.checks.setStyleSheet("color: #b00020")
        else:
            self.checks.setText("Spacing checks: every part segment has at least two datum holes and every "
                                "row of holes ({}) a datum hole at both ends.".format(rows))
            self.checks.setStyleSheet("color: #1b5e20")

    def selected_ids(self):
        rows = sorted({i.row() for i in self.table.selectedIndexes()})
        return [self.obj.HoleIds[r] for r in rows if r < len(self.obj.HoleIds)]

    def _select_in_view(self):
        part = self.obj.Source
        if part is None:
            return
        FreeCADGui.Selection.clearSelection()
        faces = []
        for r in sorted({i.row() for i in self.table.selectedIndexes()}):
            if r < len(self.obj.HoleFaces):
                faces += self.obj.HoleFaces[r].split()
        if faces:
            FreeCADGui.Selection.addSelection(part, faces)

    # -- changing ----------------------------------------------------------------------------
    def _run(self, what):
        try:
            out = what()
        except Exception as e:
            FreeCAD.Console.PrintLog(traceback.format_exc())
            show_error(str(e))
            return None
        self.refresh()
        return out if out is not None else True

    def move(self, delta):
        from aeronc.objects import photo_hole_set as phs
        ids = list(self.obj.HoleIds)
        chosen = self.selected_ids()
        if not chosen:
            return False
        order = list(ids)
        span = sorted(order.index(i) for i in chosen)
        if (delta < 0 and span[0] == 0) or (delta > 0 and span[-1] == len(order) - 1):
            return False
        for i in (span if delta < 0 else reversed(span)):
            order[i], order[i + delta] = order[i + delta], order[i]
        done = self._run(lambda: phs.set_order(self.obj, order))
        self.table.clearSelection()
        for i in chosen:
            self.table.selectRow(list(self.obj.HoleIds).index(i))
        return bool(done)

    def remove(self):
        from aeronc.objects import photo_hole_set as phs
        chosen = self.selected_ids()
        return bool(chosen) and bool(self._run(lambda: phs.remove_datum_holes(self.obj, chosen)))

    def surface_from_selection(self):
        from aeronc.objects import photo_hole_set as phs
        faces = []
        for s in FreeCADGui.Selection.getSelectionEx():
            if s.Object is self.obj.Source:
                faces += [n for n in s.SubElementNames if n.startswith("Face")]
        return bool(self._run(lambda: phs.set_surface(self.obj, faces)))

    def draw_row_from_selection(self):
        from aeronc.objects import photo_hole_set as phs
        subs = []
        for s in FreeCADGui.Selection.getSelectionEx():
            if s.Object is self.obj.Source:
                subs += list(s.SubElementNames)
        return bool(self._run(lambda: phs.draw_row(self.obj, subs)))

    def clear_drawn_rows(self):
        from aeronc.objects import photo_hole_set as phs
        return bool(self._run(lambda: phs.clear_drawn_rows(self.obj)))

    def write_camera_program(self, path=None):
        """Write <name>.apt and <name>.mpf (840D for the set's machine); path: the APT file."""
        from aeronc.drilling import compensation
        if path is None:
            path = ask_save_file("Camera program (APT; the NC program is written beside it)", "APT CL (*.apt)",
                                 "camera.apt")
            if not path:
                return None
        nc = os.path.splitext(path)[0] + ".mpf"
        if self._run(lambda: compensation.camera_program(self.obj, path, nc)):
            FreeCAD.Console.PrintMessage("AeroNC: camera program written to {} and {}\n".format(path, nc))
            return path, nc
        return None

    def import_file(self, path=None):
        """Import a measurement file; on success the measured-hole set's panel replaces this one."""
        from aeronc.makers import datum_holes
        if path is None:
            path = ask_open_file("Measured datum holes (hole,u,v,height[,quality])", "CSV (*.csv *.txt);;All (*)")
            if not path:
                return None
        ms = self._run(lambda: datum_holes.import_measurements(self.obj, path))
        if ms is None:
            return None
        self.reject()
        from aeronc.panels.measured_hole_set_panel import MeasuredHoleSetPanel
        QtCore.QTimer.singleShot(0, lambda: FreeCADGui.Control.showDialog(MeasuredHoleSetPanel(ms)))
        return ms

    def compensated_drilling(self):
        from aeronc.makers import datum_holes
        return self._run(lambda: datum_holes.create_for_photo_set(self.obj))
