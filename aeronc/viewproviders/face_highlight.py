"""Selecting a domain element in the tree also selects the faces of the source part it
machines, so the programmer sees which region it is; selecting a setup direction selects the
faces of all its elements."""
import FreeCADGui

_observer = None


class _FaceHighlighter:
    def addSelection(self, doc_name, obj_name, sub, pnt):
        import FreeCAD
        doc = FreeCAD.getDocument(doc_name)
        obj = doc.getObject(obj_name) if doc else None
        if obj is None or sub:
            return
        from aeronc.objects import DOMAIN_ELEMENT, SETUP_DIRECTION, descendants, proxy_type
        kind = proxy_type(obj)
        if kind not in (DOMAIN_ELEMENT, SETUP_DIRECTION):
            return
        links = {}
        for o in [obj] if kind == DOMAIN_ELEMENT else descendants(obj):
            for part, subs in getattr(o, "Faces", []):
                links.setdefault(part.Name, (part, set()))[1].update(subs)
        if links:
            # Selecting from inside a selection callback re-enters the selection code: defer.
            from PySide import QtCore
            QtCore.QTimer.singleShot(0, lambda: _select(links))


def _select(links):
    for part, subs in links.values():
        try:
            FreeCADGui.Selection.addSelection(part, sorted(subs, key=lambda s: int(s[4:])))
        except Exception:  # the part may be gone by now
            pass


def install():
    global _observer
    if _observer is None:
        _observer = _FaceHighlighter()
        FreeCADGui.Selection.addObserver(_observer)
