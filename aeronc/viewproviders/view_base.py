"""Common base of AeroNC's view providers."""
import aeronc


class BaseView:
    ICON = "AeroNC"

    def __init__(self, vobj):
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object
        from aeronc.viewproviders import face_highlight
        face_highlight.install()

    def getIcon(self):
        return aeronc.icon(self.ICON)

    # FreeCAD 0.20 pickles proxies with __getstate__/__setstate__, 0.21+ with dumps/loads.
    def __getstate__(self):
        return None

    def __setstate__(self, state):
        return None

    def dumps(self):
        return self.__getstate__()

    def loads(self, state):
        self.__setstate__(state)
