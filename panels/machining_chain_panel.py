"""Task panel of AeroNC_MachiningChain.

Choose the part family (the process template), the workpiece material and the machine, and
Build: the core fuses the template with the recognised domain tree into the NC machining
chain. The chain is shown as its eight levels, part -> machine -> setup -> process -> step ->
program -> tool -> unit, each unit with its element, operation, tool, top and bottom,
allowances and estimated time. The user can move a unit up or down within its program, give
it another tool, or switch it off; "Check rules" runs the construction rules again on the edited
chain and lists each rule's result, failures in red with the node at fault. The rapid travel
saved by ordering, and the elements the chain does not machine (with the reason), are shown.

Nothing is written until OK: OK makes or updates the chain's Jobs and operations in one undo
step; Cancel leaves the document as it was.
"""
import html
import traceback

import FreeCAD
import FreeCADGui
from PySide import QtCore, QtGui

from aeronc.pipeline import chain_edits, knowledge_base
from aeronc.panels.narrow import widen_dock
from aeronc.pipeline import chain_building as mc
from aeronc.panels.base import error_reporter

COLUMNS = ["Chain", "Element", "Operation", "Tool", "Top", "Bottom", "Radial", "Axial", "Est. time"]
TOOL_COLUMN = COLUMNS.index("Tool")
UNIT_ROLE = QtCore.Qt.UserRole + 1
STEP_NAMES = {"r": "rough", "w": "finish webs", "c": "corners", "ss": "semi-finish walls",
              "sf": "semi-finish flanges", "fs": "finish walls", "ff": "finish flanges", "t": "cut off",
              "d": "drill holes", "h": "mill holes"}
RED = "#b00020"
DOCK_WIDTH = 760


show_error = error_reporter("machining chain")  # tests may replace it


def _mm(v):
    return "" if v is None else "{:.2f}".format(float(v))


class MachiningChainPanel:
    current = None  # the open panel, for scripts and tests

    def __init__(self, group, chain_obj=None, kb_path=None):
        from aeronc.objects import machining_chain as chain_object
        self.group = group
        if chain_obj is None and group is not None:
            found = chain_object.chains_of_features(group)
            chain_obj = found[0] if found else None
        self.chain_obj = chain_obj
        self.kb_path = kb_path or (chain_obj.KnowledgeBase if chain_obj is not None else "") or None
        self.built = chain_object.built_of(chain_obj) if chain_obj is not None else None
        self.edits = chain_object.edits_of(chain_obj) if chain_obj is not None else chain_edits.normalised({})
        self.rebuilt = False   # Build pressed: OK builds the Jobs from the new chain
        self.checked = True    # the shown checks belong to the shown chain
        self.chain = None
        self.notes = []
        self.refused = {}  # unit JSON -> the toolpath core's reason or None: computed once per unit
        self.refused_count = 0  # enabled units the posts would refuse, as last shown
        self.form = self._build_form()
        MachiningChainPanel.current = self
        self._restore_dock = lambda: None
        QtCore.QTimer.singleShot(0, self._widen)
        if self.built:
            self.chain = mc.check(chain_edits.apply(self.built, self.edits)[0])
            self._refresh()

    # -- the form ---------------------------------------------------------------------------
    def _build_form(self):
        import aeronc
        w = QtGui.QWidget()
        w.setWindowTitle("Machining chain")
        w.setWindowIcon(QtGui.QIcon(aeronc.icon("MachiningChain")))
        lay = QtGui.QVBoxLayout(w)
        form = QtGui.QFormLayout()
        self.family, self.material, self.machine = QtGui.QComboBox(), QtGui.QComboBox(), QtGui.QComboBox()
        try:
            kb = knowledge_base.open_kb(self.kb_path)
            self.family.addItems(mc.part_families(kb))
            self.material.addItems(kb.workpiece_materials())
            self.machine.addItems(kb.machine_names())
            where = kb.path
        except Exception as e:  # the panel still opens and says why
            where = "cannot open: {}".format(e)
        src = self.chain_obj if self.chain_obj is not None else self.group
        for combo, prop in ((self.family, "Family"), (self.material, "Material"), (self.machine, "Machine")):
            previous = getattr(src, prop, "") if src is not None else ""
            if previous and combo.findText(previous) >= 0:
                combo.setCurrentIndex(combo.findText(previous))
        form.addRow("Part family", self.family)
        form.addRow("Workpiece material", self.material)
        form.addRow("Machine", self.machine)
        kb_label = QtGui.QLabel(where)
        kb_label.setWordWrap(True)
        kb_label.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        form.addRow("Knowledge base", kb_label)
        lay.addLayout(form)
        self.build_button = QtGui.QPushButton("Build chain")
        self.build_button.clicked.connect(self.build)
        lay.addWidget(self.build_button)
        self.summary = QtGui.QLabel("")
        self.summary.setWordWrap(True)
        lay.addWidget(self.summary)
        # What is not machined and what the posts refuse sit right under the summary, each tab
        # titled with its count: below the tree they were out of sight.
        self.findings = QtGui.QTabWidget()
        self.unmachined = QtGui.QListWidget()
        self.not_ready = QtGui.QListWidget()
        self.checks = QtGui.QListWidget()
        for lst in (self.unmachined, self.not_ready, self.checks):
            lst.setWordWrap(True)
            self.findings.addTab(lst, "")
        self.findings.setMinimumHeight(130)
        self.findings.setMaximumHeight(180)
        self._title_findings()
        lay.addWidget(self.findings, 1)

        self.tree = QtGui.QTreeWidget()
        self.tree.setColumnCount(len(COLUMNS))
        self.tree.setHeaderLabels(COLUMNS)
        self.tree.setMinimumHeight(300)
        self.tree.setAlternatingRowColors(True)
        self.tree.setIndentation(12)  # eight levels deep: keep the columns in view
        self.tree.itemChanged.connect(self._item_changed)
        self.tree.itemSelectionChanged.connect(self._selection_changed)
        lay.addWidget(self.tree, 3)

        row = QtGui.QHBoxLayout()
        self.up_button = QtGui.QPushButton("Move up")
        self.down_button = QtGui.QPushButton("Move down")
        self.check_button = QtGui.QPushButton("Check rules")
        self.up_button.clicked.connect(lambda: self.move_selected(-1))
        self.down_button.clicked.connect(lambda: self.move_selected(1))
        self.check_button.clicked.connect(self.check_rules)
        for b in (self.up_button, self.down_button):
            b.setEnabled(False)
            row.addWidget(b)
        row.addStretch(1)
        row.addWidget(self.check_button)
        lay.addLayout(row)

        self.travel = QtGui.QLabel("")
        self.travel.setWordWrap(True)
        lay.addWidget(self.travel)
        return w

    # -- building -----------------------------------------------------------------------------
    def build(self):
        """Build the chain with the chosen settings (the document is not touched)."""
        progress = QtGui.QProgressDialog("Building the machining chain...", "", 0, 0, FreeCADGui.getMainWindow())
        progress.setCancelButton(None)
        progress.setWindowModality(QtCore.Qt.WindowModal)
        progress.setMinimumDuration(300)
        progress.setValue(0)
        QtGui.QApplication.processEvents()
        try:
            built = mc.compute(self.group, self.family.currentText(), self.material.currentText(),
                               self.machine.currentText(), self.kb_path)
        except Exception as e:
            FreeCAD.Console.PrintLog(traceback.format_exc())
            show_error(str(e))
            return False
        finally:
            progress.close()
        self.built = built
        self.rebuilt = True
        self.chain, self.notes = chain_edits.apply(self.built, self.edits)
        self.chain = mc.check(self.chain)
        self.checked = True
        self._refresh()
        return True

    def _apply_edits(self, select=None):
        self.chain, self.notes = chain_edits.apply(self.built, self.edits)
        self.checked = False
        self._refresh(select=select)

    def check_rules(self):
        """Run the construction rules on the edited chain and list their results."""
        if self.chain is None:
            return False
        try:
            self.chain = mc.check(chain_edits.apply(self.built, self.edits)[0])
        except Exception as e:
            FreeCAD.Console.PrintLog(traceback.format_exc())
            show_error(str(e))
            return False
        self.checked = True
        self._refresh(select=self.selected_unit())  # the check arranges the tree again
        return True

    # -- the tree -----------------------------------------------------------------------------
    def _times(self):
        """Estimated time of each unit's operation, where the chain has one built already."""
        out = {}
        if self.chain_obj is not None and not self.rebuilt:
            for op in mc.chain_operations(self.chain_obj):
                out[op.UnitId] = op.CycleTime
        return out

    def _refresh(self, select=None):
        chain = self.chain
        self.tree.blockSignals(True)
        self.tree.clear()
        units = chain_edits.units_by_id(chain)
        times = self._times()
        not_ready = self.not_ready_units()
        part = self.group.Source.Label if self.group is not None and self.group.Source is not None else "part"
        root = QtGui.QTreeWidgetItem(self.tree, ["Part {}".format(part)])
        machine = QtGui.QTreeWidgetItem(root, ["Machine {}".format(chain.get("machine", ""))])
        selected_item = None
        for setup in chain.get("setups", []):
            s_item = QtGui.QTreeWidgetItem(machine, ["Setup {}".format(setup.get("name") or setup["id"])])
            for process in setup.get("processes", []):
                p_item = QtGui.QTreeWidgetItem(s_item, ["Process {}".format(process.get("id", ""))])
                p_item.setText(TOOL_COLUMN, str(process.get("tool", "") or ""))
                for step in process.get("steps", []):
                    code = step.get("code", "")
                    st_item = QtGui.QTreeWidgetItem(p_item, ["Step {} ({})".format(code, STEP_NAMES.get(code, code))])
                    for k, program in enumerate(step.get("programs", [])):
                        pr_item = QtGui.QTreeWidgetItem(st_item, ["Program {}".format(k + 1)])
                        t_item = QtGui.QTreeWidgetItem(pr_item, ["Tool {}".format(program.get("tool", ""))])
                        for uid in program.get("units", []):
                            unit = units.get(int(uid))
                            if unit is None:
                                continue
                            item = self._unit_item(t_item, unit, times.get(int(uid), ""), not_ready.get(int(uid)))
                            if select is not None and int(uid) == select:
                                selected_item = item
        self.tree.expandAll()
        self._add_tool_combos(units)
        for c in range(len(COLUMNS)):
            self.tree.resizeColumnToContents(c)
        self.tree.blockSignals(False)
        if selected_item is not None:
            self.tree.setCurrentItem(selected_item)
            self.tree.scrollToItem(selected_item)
        self._selection_changed()
        self.summary.setText(self._summary_text(chain, units, not_ready))
        travel = chain.get("travel") or {}
        if travel:
            self.travel.setText("Rapid travel: {:.0f} mm in the rules' order, {:.0f} mm ordered; {:.1f} % saved."
                                .format(float(travel.get("rulesOnly") or 0), float(travel.get("optimised") or 0),
                                        float(travel.get("savedPercent") or 0)))
        self.unmachined.clear()
        for u in chain.get("unmachined", []):
            item = QtGui.QListWidgetItem(mc.unmachined_text(u).capitalize())
            item.setForeground(QtGui.QBrush(QtGui.QColor(RED)))
            self.unmachined.addItem(item)
        if not chain.get("unmachined"):
            self.unmachined.addItem("Every element has a unit.")
        self.not_ready.clear()
        self.refused_count = len(not_ready)
        for uid, why in sorted(not_ready.items()):
            item = QtGui.QListWidgetItem("\u2718 Unit {} ({}): {}".format(uid, mc.operation_label(units[uid]), why)
                                        if uid in units else "\u2718 Unit {}: {}".format(uid, why))
            item.setForeground(QtGui.QBrush(QtGui.QColor(RED)))
            item.setToolTip(why)
            self.not_ready.addItem(item)
        if not not_ready:
            self.not_ready.addItem("Every enabled unit has a toolpath.")
        self._fill_checks()
        # The first tab with something to look at comes to the front.
        for k, n in enumerate((len(self._unmachined_elements(chain)), len(not_ready))):
            if n:
                self.findings.setCurrentIndex(k)
                break

    def _recognised_elements(self):
        """The ids of the group's elements: one the chain neither machines nor lists still counts."""
        from aeronc.objects.machining_features import result_of
        try:
            return {e.get("id") for e in result_of(self.group).get("elements", [])}
        except Exception:  # no group or no stored result: count what the chain names
            return set()

    @staticmethod
    def _unmachined_elements(chain):
        return {e.get("element") for e in (chain or {}).get("unmachined", [])}

    def _summary_text(self, chain, units, not_ready):
        """Rich text: elements machined and not, units and setups, units the posts refuse; the
        counts that need a look in red."""
        left = self._unmachined_elements(chain)
        machined = {u.get("element") for u in units.values()}
        elements = len(machined | left | self._recognised_elements())
        whole = left - machined
        setups = len(chain.get("setups", []))
        disabled = sum(1 for u in units.values() if not u.get("enabled", True))
        parts = ["<b>{} of {} elements machined</b> by {} unit{} in {} setup{}".format(
            len(machined), elements, len(units), "" if len(units) == 1 else "s",
            setups, "" if setups == 1 else "s")]
        if whole:
            parts.append("<span style='color:{}'><b>{} not machined</b></span>".format(RED, len(whole)))
        partly = left & machined
        if partly:
            parts.append("<span style='color:{}'>{} with faces left</span>".format(RED, len(partly)))
        if not_ready:
            parts.append("<span style='color:{}'><b>{} unit{} not ready</b> (the posts refuse {})</span>".format(
                RED, len(not_ready), "" if len(not_ready) == 1 else "s", "it" if len(not_ready) == 1 else "them"))
        if disabled:
            parts.append("{} disabled".format(disabled))
        parts += [html.escape(str(n)) for n in self.notes]
        return "; ".join(parts) + ".{}".format(" Reasons in the tabs below." if (left or not_ready) else "")

    def not_ready_units(self):
        """{unit id: why} of the enabled units that would get no toolpath (the toolpath core
        refuses them), and of the operations already made whose check failed or that have no
        toolpath (their Check and Note), while the chain is the one they were made from."""
        import json
        from aeronc.post import readiness
        out = {}
        if self.chain is None:
            return out
        units = [u for u in self.chain.get("units", []) if u.get("enabled", True)]
        fresh = [u for u in units if json.dumps(u, sort_keys=True) not in self.refused]
        if fresh:
            found = mc.draft_refusals({"units": fresh})
            for u in fresh:
                self.refused[json.dumps(u, sort_keys=True)] = found.get(int(u["id"]))
        for u in units:
            why = self.refused.get(json.dumps(u, sort_keys=True))
            if why:
                out[int(u["id"])] = "no toolpath: " + why
        if self.chain_obj is not None and not self.rebuilt:
            enabled = {int(u["id"]) for u in units}
            for op in mc.chain_operations(self.chain_obj):
                if op.UnitId in enabled and op.UnitId not in out and getattr(op, "Check", "") in readiness.NOT_READY:
                    out[op.UnitId] = op.Note or op.Check
        return out

    def _unit_item(self, parent, unit, est, not_ready=None):
        item = QtGui.QTreeWidgetItem(parent, [
            "Unit {}{}".format(unit["id"], " \u2718 not ready" if not_ready else ""), str(unit.get("element", "")),
            str(unit.get("operation", "")), str(unit.get("tool", "")), _mm(unit.get("top")), _mm(unit.get("bottom")),
            _mm(unit.get("radialAllowance")), _mm(unit.get("axialAllowance")), est or ""])
        item.setData(0, UNIT_ROLE, int(unit["id"]))
        item.setFlags(item.flags() | QtCore.Qt.ItemIsUserCheckable)
        item.setCheckState(0, QtCore.Qt.Checked if unit.get("enabled", True) else QtCore.Qt.Unchecked)
        if not_ready:
            for c in range(len(COLUMNS)):
                item.setForeground(c, QtGui.QBrush(QtGui.QColor(RED)))
            item.setToolTip(0, "Not ready: {}. The posts refuse it (or leave it out with --skip-failed); change "
                               "its tool or untick it".format(not_ready))
        else:
            item.setToolTip(0, "Untick to leave the unit out of the program")
        return item

    def unit_items(self):
        """{unit id: tree item}."""
        out = {}
        it = QtGui.QTreeWidgetItemIterator(self.tree)
        while it.value():
            uid = it.value().data(0, UNIT_ROLE)
            if uid is not None:
                out[int(uid)] = it.value()
            it += 1
        return out

    def suitable_tools(self, unit):
        """Tools of the chain a unit can take instead of its own: drills for a drilling unit,
        milling tools otherwise, no larger than the unit's tool (a smaller one reaches wherever
        it does), largest first."""
        tools = self.chain.get("tools") or []
        items = [(t.get("id"), t) for t in tools] if isinstance(tools, list) else list(tools.items())
        drilling = str(unit.get("operation", "")).lower().startswith("drill")
        size = float((unit.get("cutter") or {}).get("diameter") or 0.0)
        found = [(float(t.get("diameter", 0)), tid) for tid, t in items
                 if (str(t.get("type", "")).lower() == "drill") == drilling
                 and float(t.get("diameter", 0)) <= size + 1e-9]
        names = [tid for _, tid in sorted(found, reverse=True)]
        if unit.get("tool") not in names:
            names.insert(0, unit.get("tool"))
        return names

    def _add_tool_combos(self, units):
        for uid, item in self.unit_items().items():
            unit = units[uid]
            combo = QtGui.QComboBox()
            combo.addItems(self.suitable_tools(unit))
            combo.setCurrentIndex(max(0, combo.findText(unit.get("tool", ""))))
            combo.currentIndexChanged.connect(lambda _i, u=uid, c=combo: self.set_tool(u, c.currentText()))
            self.tree.setItemWidget(item, TOOL_COLUMN, combo)

    def _title_findings(self):
        """Each tab's title with its count, so the numbers show even on the tab behind."""
        left = len(self._unmachined_elements(self.chain))
        refused = self.refused_count
        broken = sum(1 for c in (self.chain or {}).get("checks", []) if not c.get("ok", True))
        self.findings.setTabText(0, "Not machined ({})".format(left))
        self.findings.setTabText(1, "Not ready ({})".format(refused))
        self.findings.setTabText(2, "Construction rules" + (" ({} broken)".format(broken) if broken else ""))
        for k, n in enumerate((left, refused, broken)):
            self.findings.tabBar().setTabTextColor(k, QtGui.QColor(RED if n else "#000000"))

    def _fill_checks(self):
        self.checks.clear()
        if not self.checked:
            item = QtGui.QListWidgetItem("The chain was edited: press Check rules.")
            item.setForeground(QtGui.QBrush(QtGui.QColor("#8a6d00")))
            self.checks.addItem(item)
        for c in (self.chain or {}).get("checks", []):
            ok = c.get("ok", True)
            text = "{} {}: {}{}".format("\u2714" if ok else "\u2718", c.get("rule", ""), c.get("node", ""),
                                        "" if ok or not c.get("message") else " \u2014 " + c["message"])
            item = QtGui.QListWidgetItem(text)
            if not ok:
                item.setForeground(QtGui.QBrush(QtGui.QColor(RED)))
            item.setToolTip(c.get("message", ""))
            self.checks.addItem(item)
        self._title_findings()

    # -- the user's edits -----------------------------------------------------------------------
    def selected_unit(self):
        items = self.tree.selectedItems()
        uid = items[0].data(0, UNIT_ROLE) if items else None
        return int(uid) if uid is not None else None

    def _selection_changed(self):
        uid = self.selected_unit()
        for b, delta in ((self.up_button, -1), (self.down_button, 1)):
            b.setEnabled(uid is not None and chain_edits.moved(self.chain, self.edits, uid, delta) is not None)

    def move_selected(self, delta):
        uid = self.selected_unit()
        if uid is None:
            return False
        edits = chain_edits.moved(self.chain, self.edits, uid, delta)
        if edits is None:
            return False
        self.edits = edits
        self._apply_edits(select=uid)
        return True

    def set_tool(self, unit_id, tool_id):
        if not tool_id:
            return
        self.edits = chain_edits.with_tool(self.edits, self.built, unit_id, tool_id)
        QtCore.QTimer.singleShot(0, lambda: self._apply_edits(select=unit_id))  # not inside the combo's signal

    def set_enabled(self, unit_id, enabled):
        self.edits = chain_edits.with_enabled(self.edits, unit_id, enabled)
        self._apply_edits(select=unit_id)

    def _item_changed(self, item, column):
        uid = item.data(0, UNIT_ROLE)
        if uid is None or column != 0:
            return
        enabled = item.checkState(0) == QtCore.Qt.Checked
        unit = chain_edits.units_by_id(self.chain).get(int(uid), {})
        if enabled != unit.get("enabled", True):
            QtCore.QTimer.singleShot(0, lambda: self.set_enabled(int(uid), enabled))

    # -- task dialog ----------------------------------------------------------------------------
    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)

    def _widen(self):
        self._restore_dock = widen_dock(DOCK_WIDTH)

    def _close(self):
        MachiningChainPanel.current = None
        FreeCADGui.Control.closeDialog()
        self._restore_dock()

    def accept(self):
        if self.built is None and not self.build():  # OK on a fresh panel builds the chain first
            return False
        progress = QtGui.QProgressDialog("Making the Jobs...", "Cancel", 0, 100, FreeCADGui.getMainWindow())
        progress.setWindowModality(QtCore.Qt.WindowModal)
        progress.setMinimumDuration(300)

        def report(fraction, stage):
            progress.setValue(int(100 * fraction))
            progress.setLabelText(stage)
            QtGui.QApplication.processEvents()
            return not progress.wasCanceled()

        try:
            if self.chain_obj is not None and not self.rebuilt:
                obj = mc.update(self.chain_obj, self.edits, progress=report)
            else:
                obj = mc.build(self.group, self.family.currentText(), self.material.currentText(),
                               self.machine.currentText(), self.kb_path, edits=self.edits, built=self.built,
                               progress=report)
        except Exception as e:
            FreeCAD.Console.PrintLog(traceback.format_exc())
            show_error(str(e))
            return False
        finally:
            progress.close()
        for m in obj.Messages:
            FreeCAD.Console.PrintMessage("AeroNC: {}\n".format(m))
        FreeCAD.Console.PrintMessage("AeroNC: {}: {} units in {}\n".format(
            obj.Label, obj.UnitCount, ", ".join(j.Label for j in obj.Jobs)))
        if obj.Jobs:  # one setup at a time; the Job's context menu shows another
            from aeronc.commands.show_setup import show_setup
            show_setup(obj, obj.Jobs[0])
        self._close()
        return True

    def reject(self):
        self._close()
        return True
