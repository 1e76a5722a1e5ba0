"""Task panel of AeroNC_EditKnowledgeBase: one tab per table of the knowledge base.

Cells are edited in place; "Save" writes the edits, added rows and deleted rows of every
table, each table in one transaction, so a rule the database enforces (a positive diameter,
a known tool material...) refuses the whole table's changes with a message naming the row
and column. FreeCAD tool libraries are imported and exported from here too.
"""
import os
import traceback

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from aeronc.pipeline import knowledge_base
from aeronc.errors import KnowledgeBaseError, from_core
from aeronc.panels.narrow import ElidedLabel, button_rows, scrolling
from aeronc.panels.base import error_reporter


show_error = error_reporter("knowledge base")  # tests may replace it


class _TableTab:
    """One table: its widget, what was loaded, and the pending changes."""

    def __init__(self, kb, name):
        self.name = name
        self.widget = scrolling(QtGui.QTableWidget())
        self.widget.verticalHeader().setVisible(False)
        self.load(kb)
        self.widget.itemChanged.connect(self._changed)

    def load(self, kb):
        data = kb.table(self.name)
        self.columns = [c["name"] for c in data["columns"]]
        self.row_ids = list(data["rowIds"])
        self.edits, self.deletes, self.new_rows = {}, set(), 0
        w = self.widget
        w.blockSignals(True)
        w.clear()
        w.setColumnCount(len(self.columns))
        w.setHorizontalHeaderLabels(self.columns)
        w.setRowCount(len(data["rows"]))
        for r, row in enumerate(data["rows"]):
            for c, value in enumerate(row):
                w.setItem(r, c, QtGui.QTableWidgetItem("" if value is None else value))
        w.resizeColumnsToContents()
        w.blockSignals(False)

    def _changed(self, item):
        r = item.row()
        if r < len(self.row_ids):
            self.edits[(self.row_ids[r], self.columns[item.column()])] = item.text().strip() or None
            item.setBackground(QtGui.QBrush(QtGui.QColor("#fff3b0")))

    def add_row(self):
        w = self.widget
        w.blockSignals(True)
        w.insertRow(w.rowCount())
        for c in range(len(self.columns)):
            item = QtGui.QTableWidgetItem("")
            item.setBackground(QtGui.QBrush(QtGui.QColor("#d9f2d9")))
            w.setItem(w.rowCount() - 1, c, item)
        w.blockSignals(False)
        self.new_rows += 1

    def delete_selected(self):
        for r in sorted({i.row() for i in self.widget.selectedItems()}, reverse=True):
            if r < len(self.row_ids):
                self.deletes.add(self.row_ids[r])
                for c in range(len(self.columns)):
                    self.widget.item(r, c).setBackground(QtGui.QBrush(QtGui.QColor("#f4c7c3")))

    def pending(self):
        return bool(self.edits or self.deletes or self.new_rows)

    def save(self, kb):
        w = self.widget
        inserts = []
        for r in range(len(self.row_ids), w.rowCount()):
            values = [(w.item(r, c).text().strip() or None) if w.item(r, c) else None
                      for c in range(len(self.columns))]
            if any(values):
                inserts.append(values)
        edits = [(row, col, value) for (row, col), value in self.edits.items() if row not in self.deletes]
        kb.edit_table(self.name, edits, inserts, sorted(self.deletes))


class KnowledgeBasePanel:
    current = None

    def __init__(self, kb_path=None):
        self.kb = knowledge_base.open_kb(kb_path)
        self.form = self._build_form()
        KnowledgeBasePanel.current = self

    def _build_form(self):
        import aeronc
        w = QtGui.QWidget()
        w.setWindowTitle("Knowledge base")
        w.setWindowIcon(QtGui.QIcon(aeronc.icon("KnowledgeBase")))
        lay = QtGui.QVBoxLayout(w)
        self.where = ElidedLabel("{} (schema {})".format(self.kb.path, self.kb.schema_version))
        lay.addWidget(self.where)
        self.tabs = QtGui.QTabWidget()
        self.tables = []
        for name in self.kb.editable_tables():
            tab = _TableTab(self.kb, name)
            self.tables.append(tab)
            self.tabs.addTab(tab.widget, name.replace("_", " "))
        self.tabs.setMinimumHeight(380)
        lay.addWidget(self.tabs)
        button_rows(lay, (("Add row", lambda: self.tab().add_row()),
                          ("Delete rows", lambda: self.tab().delete_selected()),
                          ("Save", self.save), ("Revert", self.revert)))
        button_rows(lay, (("Import FreeCAD library...", self.import_library),
                          ("Export FreeCAD library...", self.export_library)), per_row=1)
        return w

    def tab(self):
        return self.tables[self.tabs.currentIndex()]

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Close)

    def reject(self):
        if any(t.pending() for t in self.tables):
            answer = QtGui.QMessageBox.question(FreeCADGui.getMainWindow(), "AeroNC: knowledge base",
                                                "Discard the changes that are not saved?")
            if answer != QtGui.QMessageBox.Yes:
                return False
        KnowledgeBasePanel.current = None
        FreeCADGui.Control.closeDialog()
        return True

    def save(self):
        """Save every table with changes; True when all saved. A refused table keeps its edits."""
        ok = True
        for t in self.tables:
            if not t.pending():
                continue
            try:
                with from_core(KnowledgeBaseError):
                    t.save(self.kb)
                    t.load(self.kb)
            except KnowledgeBaseError as e:
                ok = False
                self.tabs.setCurrentWidget(t.widget)
                show_error(str(e))
        return ok

    def revert(self):
        for t in self.tables:
            t.load(self.kb)

    def import_library(self, path=None, tool_material="carbide"):
        from aeronc import pathcompat
        if path is None:
            path, _ = QtGui.QFileDialog.getOpenFileName(FreeCADGui.getMainWindow(), "FreeCAD tool library",
                                                        pathcompat.default_tool_library_folder(),
                                                        "Tool library (*.fctl)")
            if not path:
                return 0
        try:
            with from_core(KnowledgeBaseError):
                n = self.kb.import_freecad_library(path, tool_material)
        except KnowledgeBaseError as e:
            show_error(str(e))
            return 0
        FreeCAD.Console.PrintMessage("AeroNC: imported {} tools from {}\n".format(n, path))
        self.revert()
        return n

    def export_library(self, name=None, folder=None):
        names = self.kb.freecad_library_names()
        if name is None:
            if not names:
                show_error("No FreeCAD library has been imported yet; select tools in the tool tab "
                           "and use Select tools to make ToolControllers instead.")
                return []
            name, ok = QtGui.QInputDialog.getItem(FreeCADGui.getMainWindow(), "Export FreeCAD library",
                                                  "Library", names, 0, False)
            if not ok:
                return []
        if folder is None:
            folder = QtGui.QFileDialog.getExistingDirectory(FreeCADGui.getMainWindow(),
                                                            "Folder holding Bit/ and Library/")
            if not folder:
                return []
        try:
            with from_core(KnowledgeBaseError):
                written = self.kb.export_freecad_library(name, folder)
        except KnowledgeBaseError as e:
            FreeCAD.Console.PrintLog(traceback.format_exc())
            show_error(str(e))
            return []
        FreeCAD.Console.PrintMessage("AeroNC: wrote {}\n".format(os.path.join(folder, "Library", name + ".fctl")))
        return written
