"""Selecting a domain element in the tree paints the faces of the source part it machines in
the selection colour, so the programmer sees which region it is; selecting a setup direction
paints the faces of all its elements. The faces are painted, not selected: the element stays
the only selected object, and the property editor shows its depth, width and tool. The part's
colours come back when the element is no longer selected."""
import FreeCADGui

HIGHLIGHT = (0.11, 0.68, 0.11)  # FreeCAD's default selection green (no AeroNC role uses green)

_observer = None


def _faces_of(obj):
    """{part name: (part, {"FaceN", ...})} of a domain element or setup direction, else {}."""
    from aeronc.objects import DOMAIN_ELEMENT, SETUP_DIRECTION, descendants, proxy_type
    kind = proxy_type(obj)
    if kind not in (DOMAIN_ELEMENT, SETUP_DIRECTION):
        return {}
    links = {}
    for o in [obj] if kind == DOMAIN_ELEMENT else descendants(obj):
        for part, subs in getattr(o, "Faces", []):
            links.setdefault(part.Name, (part, set()))[1].update(subs)
    return links


class _FaceHighlighter:
    def __init__(self):
        self.painted = {}  # (document, part name) -> (part, colours before, colours painted)

    def addSelection(self, doc_name, obj_name, sub, pnt):
        self._later(lambda: self._paint_selection(doc_name))

    def removeSelection(self, doc_name, obj_name, sub):
        self._later(lambda: self._paint_selection(doc_name))

    def setSelection(self, doc_name):
        self._later(lambda: self._paint_selection(doc_name))

    def clearSelection(self, doc_name):
        self._later(lambda: self._paint_selection(doc_name))

    @staticmethod
    def _later(work):
        # Painting from inside a selection callback re-enters the view's code: defer.
        from PySide import QtCore
        QtCore.QTimer.singleShot(0, work)

    def _paint_selection(self, doc_name):
        import FreeCAD
        self._restore()
        try:
            selected = FreeCADGui.Selection.getSelection()
        except Exception:
            return
        links = {}
        for obj in selected:
            for name, (part, subs) in _faces_of(obj).items():
                links.setdefault(name, (part, set()))[1].update(subs)
        for name, (part, subs) in links.items():
            try:
                vobj = part.ViewObject
                before = [tuple(c) for c in vobj.DiffuseColor] or [tuple(vobj.ShapeColor)]
                n = len(part.Shape.Faces)
                colours = list(before) if len(before) == n else [before[0]] * n
                for s in subs:
                    k = int(s[4:]) - 1
                    if 0 <= k < n:
                        colours[k] = HIGHLIGHT + tuple(colours[k][3:4] or (0.0,))
                vobj.DiffuseColor = colours
                self.painted[(part.Document.Name, name)] = (part, before, [tuple(c) for c in vobj.DiffuseColor])
            except Exception as e:  # the part may be gone by now
                FreeCAD.Console.PrintLog("AeroNC: face highlight: {}\n".format(e))

    def _restore(self):
        """Give each painted part its colours back, unless something else coloured it since."""
        for part, before, painted in self.painted.values():
            try:
                if [tuple(c) for c in part.ViewObject.DiffuseColor] == painted:
                    part.ViewObject.DiffuseColor = before
            except Exception:  # the part or its document is gone
                pass
        self.painted.clear()


def install():
    global _observer
    if _observer is None:
        _observer = _FaceHighlighter()
        FreeCADGui.Selection.addObserver(_observer)
