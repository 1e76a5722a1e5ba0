"""What keeps a task panel inside the combo view at FreeCAD's default width (about 260 px):
long paths elided in the middle, combo boxes that do not widen to their longest item, form
fields under their labels, tables that scroll and plots that scale instead of pushing the
dock wider."""
from PySide import QtCore, QtGui


def widen_dock(width):
    """Widen the visible combo view or task dock to `width` pixels when it is narrower (a panel
    whose table needs more than FreeCAD's default width). Returns restore(), which gives the
    docks their widths back: the panel calls it when it closes."""
    import FreeCADGui
    mw = FreeCADGui.getMainWindow()
    widened = []
    for dock in mw.findChildren(QtGui.QDockWidget):
        if dock.isVisible() and dock.objectName() in ("Combo View", "Tasks") and dock.width() < width:
            widened.append((dock, dock.width()))
            mw.resizeDocks([dock], [width], QtCore.Qt.Horizontal)

    def restore():
        for dock, was in widened:
            try:
                mw.resizeDocks([dock], [was], QtCore.Qt.Horizontal)
            except RuntimeError:  # the dock is gone (FreeCAD closing)
                pass
        widened.clear()
    return restore


class ElidedLabel(QtGui.QLabel):
    """A one-line label that shows as much of its text as fits, eliding the middle (where a
    path's least telling part is); the whole text is its tooltip and can be copied."""

    def __init__(self, text="", parent=None):
        super().__init__(parent)
        self.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        self.setSizePolicy(QtGui.QSizePolicy.Ignored, QtGui.QSizePolicy.Preferred)
        self.setMinimumWidth(40)
        self._full = ""
        self.set_full_text(text)

    def set_full_text(self, text):
        self._full = text
        self.setToolTip(text)
        self._elide()

    def full_text(self):
        return self._full

    def resizeEvent(self, event):
        super().resizeEvent(event)
        self._elide()

    def _elide(self):
        width = max(10, self.contentsRect().width())
        super().setText(self.fontMetrics().elidedText(self._full, QtCore.Qt.ElideMiddle, width))


def compact_combo(combo, characters=14):
    """A combo box as wide as `characters`, not as its longest item (the popup still is)."""
    combo.setSizeAdjustPolicy(QtGui.QComboBox.AdjustToMinimumContentsLengthWithIcon)
    combo.setMinimumContentsLength(characters)
    combo.view().setMinimumWidth(combo.view().sizeHintForColumn(0) + 24)
    return combo


def wrapping_form(parent=None):
    """A form layout with each field under its label: label and field side by side would set
    the panel's least width, and FreeCAD's task view does not count its vertical scroll bar
    in that width, so a tall panel would lose its right edge under the scroll bar."""
    form = QtGui.QFormLayout(parent) if parent is not None else QtGui.QFormLayout()
    form.setRowWrapPolicy(QtGui.QFormLayout.WrapAllRows)
    form.setFieldGrowthPolicy(QtGui.QFormLayout.AllNonFixedFieldsGrow)
    return form


def scrolling(view):
    """A table or text view that scrolls sideways rather than asking for its content's width."""
    policy = view.sizePolicy()
    policy.setHorizontalPolicy(QtGui.QSizePolicy.Ignored)
    view.setSizePolicy(policy)
    view.setMinimumWidth(60)
    view.setHorizontalScrollBarPolicy(QtCore.Qt.ScrollBarAsNeeded)
    return view


class ScaledPicture(QtGui.QLabel):
    """A picture shown at the label's width (never wider than drawn), keeping its aspect."""

    def __init__(self, parent=None):
        super().__init__(parent)
        self.setAlignment(QtCore.Qt.AlignCenter)
        self.setSizePolicy(QtGui.QSizePolicy.Ignored, QtGui.QSizePolicy.Preferred)
        self.setMinimumWidth(40)
        self._pixmap = None

    def set_picture(self, pixmap):
        self._pixmap = pixmap
        self._show()

    def picture(self):
        """The picture as drawn (None when there is none)."""
        return self._pixmap

    def clear(self):
        self._pixmap = None
        super().clear()

    def resizeEvent(self, event):
        super().resizeEvent(event)
        self._show()

    def _show(self):
        if self._pixmap is None or self._pixmap.isNull():
            return
        width = min(self._pixmap.width(), max(10, self.contentsRect().width()))
        super().setPixmap(self._pixmap.scaledToWidth(width, QtCore.Qt.SmoothTransformation))


def button_rows(layout, buttons, per_row=2):
    """Lays buttons (text, slot) out in rows of per_row; returns the buttons."""
    made = []
    grid = QtGui.QGridLayout()
    for i, (text, slot) in enumerate(buttons):
        b = QtGui.QPushButton(text)
        b.clicked.connect(slot)
        b.setMinimumWidth(20)
        b.setSizePolicy(QtGui.QSizePolicy.Ignored, QtGui.QSizePolicy.Fixed)
        b.setToolTip(text)
        grid.addWidget(b, i // per_row, i % per_row)
        made.append(b)
    layout.addLayout(grid)
    return made
