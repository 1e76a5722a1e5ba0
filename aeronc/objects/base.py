"""Common base of AeroNC's FeaturePython proxies.

The proxy keeps no state of its own: everything lives in document properties, so a saved
document reopens with the proxy rebuilt from its class path (`aeronc.objects.<module>.<class>`).
Each proxy declares every property its objects have (`declare`); a document saved by an
older version gets the ones it lacks when it is opened.

The App side never imports the GUI. View providers are given by whatever the GUI registers
with `set_view_attacher` at start-up (aeronc.viewproviders.install); headless, nothing is.
"""

_view_attacher = None


def set_view_attacher(attach):
    """Register attach(obj, restoring) as the one that gives AeroNC's objects their view
    providers (the GUI does, at start-up); None unregisters it."""
    global _view_attacher
    _view_attacher = attach


def attach_views(objs, restoring=False):
    """Ask the GUI, if it registered, for the view providers of objs."""
    if _view_attacher is not None:
        for obj in objs:
            _view_attacher(obj, restoring)


class BaseProxy:
    Type = "AeroNC::Base"  # subclasses: "AeroNC::<Concept>"

    def __init__(self, obj):
        obj.Proxy = self
        self.Type = type(self).Type

    def declare(self, obj):
        """Add the properties of this kind of object that obj lacks (all of them for a new
        object); existing ones keep their values."""

    def onDocumentRestored(self, obj):
        self.declare(obj)  # properties newer than the document
        # A document made headless (freecadcmd) has no view-provider proxies; give it some.
        attach_views([obj], restoring=True)

    # FreeCAD 0.20 pickles proxies with __getstate__/__setstate__, 0.21+ with dumps/loads.
    def __getstate__(self):
        return {"Type": type(self).Type}

    def __setstate__(self, state):
        self.Type = type(self).Type

    def dumps(self):
        return self.__getstate__()

    def loads(self, state):
        self.__setstate__(state)


PROP_OUTPUT = 8  # App::Prop_Output: setting the property does not touch (recompute) its object


def declare_property(obj, type_, name, group, doc, default=None, read_only=False, hidden=False, output=False):
    """Add a property obj lacks and give it its default; an existing one is left as it is.
    output: a result written about the object (a check's verdict) that must not make it recompute."""
    if name in obj.PropertiesList:
        return
    obj.addProperty(type_, name, group, doc, PROP_OUTPUT if output else 0, read_only, hidden)
    if default is not None:
        setattr(obj, name, default)


def add_property(obj, type_, name, group, doc, value=None, read_only=False, hidden=False):
    """Add a dynamic property once and set its value: for AeroNC's marks on objects it does not
    own (FreeCAD's ToolControllers)."""
    declare_property(obj, type_, name, group, doc, None, read_only, hidden)
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
