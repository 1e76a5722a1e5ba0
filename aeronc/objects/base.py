"""Common base of AeroNC's FeaturePython proxies.

The proxy keeps no state of its own: everything lives in document properties, so a saved
document reopens with the proxy rebuilt from its class path (`aeronc.objects.<module>.<class>`).
"""
import FreeCAD


class BaseProxy:
    Type = "AeroNC::Base"  # subclasses: "AeroNC::<Concept>"

    def __init__(self, obj):
        obj.Proxy = self
        self.Type = type(self).Type

    def onDocumentRestored(self, obj):
        # A document made headless (freecadcmd) has no view-provider proxies; give it some.
        if FreeCAD.GuiUp:
            from aeronc import viewproviders
            viewproviders.attach(obj, restoring=True)

    # FreeCAD 0.20 pickles proxies with __getstate__/__setstate__, 0.21+ with dumps/loads.
    def __getstate__(self):
        return {"Type": type(self).Type}

    def __setstate__(self, state):
        self.Type = type(self).Type

    def dumps(self):
        return self.__getstate__()

    def loads(self, state):
        self.__setstate__(state)


def add_property(obj, type_, name, group, doc, value=None, read_only=False, hidden=False):
    """Add a dynamic property once (restored documents already have it) and set its value."""
    if name not in obj.PropertiesList:
        obj.addProperty(type_, name, group, doc, 0, read_only, hidden)
    if value is not None:
        setattr(obj, name, value)


def proxy_type(obj):
    """The AeroNC type of a document object ("AeroNC::DomainElement"...), or None."""
    return getattr(getattr(obj, "Proxy", None), "Type", None)


def descendants(obj):
    """Every object under obj's Group, at all depths, deepest first (a safe order to remove)."""
    out = []
    for child in getattr(obj, "Group", []):
        out += descendants(child) + [child]
    return out


def face_links(part, face_numbers):
    """PropertyLinkSubList value: [(part, ("Face3", ...))] for 1-based face numbers."""
    subs = tuple("Face{}".format(n) for n in sorted(set(face_numbers)))
    return [(part, subs)] if subs and part is not None else []
