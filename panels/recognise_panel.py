"""Task panel of AeroNC_RecogniseFeatures: setup directions, blank and tolerances.

OK recognises (with a progress dialog that can cancel) and adds the machining-domain tree,
or, for an existing MachiningFeatures group (double-click), recognises again into it.
Failures go to the report view and a message box, and leave the panel open.
"""
import math
import traceback

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from aeronc.pipeline import recognition
from aeronc.panels.narrow import ElidedLabel, compact_combo, wrapping_form
from aeronc.panels.base import error_reporter

DIRECTION_CHOICES = [  # (text, directions; None = custom vector)
    ("Automatic (from the part)", []),
    ("+Z", [(0.0, 0.0, 1.0)]),
    ("-Z", [(0.0, 0.0, -1.0)]),
    ("+Z and -Z (double-sided)", [(0.0, 0.0, 1.0), (0.0, 0.0, -1.0)]),
    ("Custom vector", None),
]


def _spin(value, lo, hi, decimals, suffix="", step=1.0):
    box = QtGui.QDoubleSpinBox()
    box.setRange(lo, hi)
    box.setDecimals(decimals)
    box.setSingleStep(step)
    box.setSuffix(suffix)
    box.setValue(value)
    return box


show_error = error_reporter("recognition failed")  # tests may replace it


# The roles the 3-D view colours the part by, in the words of the legend.
LEGEND = [("floor", "floor"), ("wall", "wall"), ("island_wall", "island wall"), ("hole_wall", "hole"),
          ("floor_fillet", "floor fillet"), ("corner_fillet", "corner fillet"), ("counterbore_floor", "counterbore floor"),
          ("countersink", "countersink"), ("chamfer", "chamfer"), ("open_bevel", "open bevel"),
          ("closed_bevel", "closed bevel"), ("rib_top", "rib top"), ("top", "top"), ("stock", "stock surface"),
          ("unclaimed", "no element")]


def colour_legend():
    """The legend of the role colours of the 3-D view, one swatch per row (two columns do not
    fit the default combo view); a face painted green belongs to the element selected in the tree."""
    from aeronc.feature_colours import ROLE_COLOURS
    box = QtGui.QGroupBox("Face colours")
    grid = QtGui.QGridLayout(box)
    grid.setSpacing(2)
    for k, (role, text) in enumerate(LEGEND):
        r, g, b = (int(round(255 * c)) for c in ROLE_COLOURS[role])
        swatch = QtGui.QLabel()
        swatch.setObjectName("legend_" + role)
        swatch.setFixedSize(14, 14)
        swatch.setStyleSheet("background-color: rgb({},{},{}); border: 1px solid #555;".format(r, g, b))
        label = QtGui.QLabel(text)
        grid.addWidget(swatch, k, 0)
        grid.addWidget(label, k, 1)
    grid.setColumnStretch(1, 1)
    return box


class RecognisePanel:
    """part: the solid to recognise (new tree); group: a MachiningFeatures group to redo."""

    current = None  # the open panel, for scripts and tests

    def __init__(self, part=None, group=None):
        self.group = group
        self.part = group.Source if group is not None else part
        self.doc = (group or part).Document
        self.jobs = []
        self.result_group = None
        self.form = self._build_form()
        if group is not None:
            self._load(group)
        RecognisePanel.current = self

    # ---- form -------------------------------------------------------------------------
    def _build_form(self):
        import aeronc
        w = QtGui.QWidget()
        w.setWindowTitle("Recognise features")  # the task box header: short enough for the default width
        w.setWindowIcon(QtGui.QIcon(aeronc.icon("RecogniseFeatures")))
        lay = QtGui.QVBoxLayout(w)
        lay.addWidget(ElidedLabel("Part: {}".format(self.part.Label if self.part else "?")))

        box = QtGui.QGroupBox("Setup directions")
        f = wrapping_form(box)
        self.direction = QtGui.QComboBox()
        for text, _ in DIRECTION_CHOICES:
            self.direction.addItem(text)
        f.addRow("Directions", compact_combo(self.direction))
        # One row per component: three spin boxes side by side do not fit the default width.
        self.custom = [_spin(v, -1.0, 1.0, 4, step=0.1) for v in (0.0, 0.0, 1.0)]
        for axis, s in zip("XYZ", self.custom):
            f.addRow("Vector {}".format(axis), s)
        self.direction.currentIndexChanged.connect(self._directions_changed)
        self._directions_changed()
        lay.addWidget(box)

        box = QtGui.QGroupBox("Blank")
        f = wrapping_form(box)
        self.blank = compact_combo(QtGui.QComboBox())
        self.blank.addItem("Part bounding box + allowance")
        self.jobs = self._find_jobs()
        for job in self.jobs:
            self.blank.addItem("Stock of {}".format(job.Label))
        f.addRow("Blank", self.blank)
        self.allowance = _spin(0.0, 0.0, 1000.0, 3, " mm")
        f.addRow("Allowance", self.allowance)
        self.blank.currentIndexChanged.connect(
            lambda i: self.allowance.setEnabled(i == 0))
        lay.addWidget(box)

        box = QtGui.QGroupBox("Tolerances")
        f = wrapping_form(box)
        self.linear = _spin(recognition.DEFAULT_LINEAR_TOLERANCE, 1e-6, 1.0, 6, " mm", 1e-3)
        self.angular = _spin(math.degrees(recognition.DEFAULT_ANGULAR_TOLERANCE), 1e-4, 5.0, 4, " \u00b0", 0.01)
        self.chord = _spin(recognition.DEFAULT_CHORD_TOLERANCE, 1e-4, 10.0, 4, " mm", 0.01)
        f.addRow("Linear", self.linear)
        f.addRow("Angular", self.angular)
        f.addRow("Chord", self.chord)
        lay.addWidget(box)

        self.legend = colour_legend()
        lay.addWidget(self.legend)

        self.status = QtGui.QLabel("")
        self.status.setWordWrap(True)
        lay.addWidget(self.status)
        lay.addStretch()
        return w

    def _find_jobs(self):
        try:
            from aeronc import pathcompat
            return [j for j in pathcompat.find_jobs(self.doc) if pathcompat.job_stock_box(j)]
        except Exception as e:  # no usable Path module: offer the bounding box only
            FreeCAD.Console.PrintLog("AeroNC: no Path jobs: {}\n".format(e))
            return []

    def _directions_changed(self, *args):
        custom = DIRECTION_CHOICES[self.direction.currentIndex()][1] is None
        for s in self.custom:
            s.setEnabled(custom)

    def _load(self, group):
        """Fill the form from an existing group's settings."""
        from aeronc.objects import settings_of
        s = settings_of(group)
        dirs = [tuple(round(c, 9) for c in d) for d in s["directions"]]
        index = next((i for i, (_, d) in enumerate(DIRECTION_CHOICES) if d == dirs), None)
        if index is None:
            index = len(DIRECTION_CHOICES) - 1
            for box, c in zip(self.custom, dirs[0] if dirs else (0, 0, 1)):
                box.setValue(c)
        self.direction.setCurrentIndex(index)
        self.allowance.setValue(s["allowance"])
        self.linear.setValue(s["linear_tolerance"])
        self.angular.setValue(math.degrees(s["angular_tolerance"]))
        self.chord.setValue(s["chord_tolerance"])

    def settings(self):
        """The form as keyword arguments of makers.create/update_machining_features."""
        dirs = DIRECTION_CHOICES[self.direction.currentIndex()][1]
        if dirs is None:
            v = [s.value() for s in self.custom]
            if math.sqrt(sum(c * c for c in v)) < 1e-9:
                raise recognition.RecognitionError("the custom setup direction is the zero vector")
            dirs = [tuple(v)]
        blank = None
        if self.blank.currentIndex() > 0:
            from aeronc import pathcompat
            blank = pathcompat.job_stock_box(self.jobs[self.blank.currentIndex() - 1])
        return dict(directions=dirs, allowance=self.allowance.value(), blank=blank,
                    linear_tolerance=self.linear.value(),
                    angular_tolerance=math.radians(self.angular.value()),
                    chord_tolerance=self.chord.value())

    # ---- running ----------------------------------------------------------------------
    def run(self):
        """Recognise with the form's settings; returns the group, or None on failure or
        cancel (reported). Never raises."""
        from aeronc import makers, objects
        dialog = QtGui.QProgressDialog("Recognising machining features\u2026", "Cancel", 0, 1000,
                                       FreeCADGui.getMainWindow())
        dialog.setWindowTitle("AeroNC")
        dialog.setWindowModality(QtCore.Qt.WindowModal)
        dialog.setMinimumDuration(0)
        dialog.setValue(0)

        def progress(fraction, stage):
            dialog.setValue(int(max(0.0, min(1.0, fraction)) * 1000))
            dialog.setLabelText("Recognising machining features: {}".format(stage))
            QtGui.QApplication.processEvents()
            return not dialog.wasCanceled()

        try:
            settings = self.settings()
            if self.group is None:
                group = makers.create_machining_features(self.doc, self.part, progress=progress,
                                                          report=False, **settings)
            else:
                group = makers.update_machining_features(self.group, progress=progress,
                                                          report=False, **settings)
        except recognition.RecognitionCancelled:
            FreeCAD.Console.PrintMessage("AeroNC: recognition cancelled\n")
            self.status.setText("Cancelled.")
            return None
        except recognition.RecognitionError as e:
            self.status.setText("Failed: {}".format(e))
            show_error(str(e))
            return None
        except Exception as e:  # a bug: report it with its traceback, keep FreeCAD alive
            FreeCAD.Console.PrintError(traceback.format_exc())
            self.status.setText("Failed: {}".format(e))
            show_error("unexpected error: {}".format(e))
            return None
        finally:
            dialog.reset()
            dialog.close()
            dialog.deleteLater()
        text = recognition.summary_text(objects.result_of(group))
        FreeCAD.Console.PrintMessage("AeroNC: {}: {}\n".format(self.part.Label, text))
        # After the console's warnings, which reach the status bar through queued events.
        bar = FreeCADGui.getMainWindow().statusBar()
        QtCore.QTimer.singleShot(100, lambda: bar.showMessage("AeroNC: " + text, 15000))
        self.status.setText(text)
        self.result_group = group
        return group

    # ---- task dialog protocol -----------------------------------------------------------
    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)

    def accept(self):
        if self.run() is None:
            return False  # keep the panel open to change settings
        self._close()
        # The part stays selected after the command, and the selection colour would hide the
        # feature colours until the user clicks elsewhere: show the result.
        FreeCADGui.Selection.clearSelection()
        return True

    def reject(self):
        self._close()
        return True

    def _close(self):
        RecognisePanel.current = None
        if self.group is not None:
            FreeCADGui.ActiveDocument.resetEdit()  # unsetEdit closes the dialog
        else:
            FreeCADGui.Control.closeDialog()
