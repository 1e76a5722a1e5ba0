"""The run button, summary line and read-only result table that AeroNC's task panels share."""
from PySide import QtGui

from aeronc.panels.narrow import scrolling


def add_run_and_results(layout, button_text, on_run, columns):
    """Add a button (calls on_run), a wrapped summary label and a read-only table with the
    given column titles to layout; returns (button, summary, table). The table scrolls
    sideways inside the panel's width."""
    button = QtGui.QPushButton(button_text)
    button.clicked.connect(on_run)
    layout.addWidget(button)
    summary = QtGui.QLabel("")
    summary.setWordWrap(True)
    layout.addWidget(summary)
    table = QtGui.QTableWidget(0, len(columns))
    table.setHorizontalHeaderLabels(columns)
    table.setEditTriggers(QtGui.QAbstractItemView.NoEditTriggers)
    table.verticalHeader().setVisible(False)
    layout.addWidget(scrolling(table))
    return button, summary, table
