from aeronc.viewproviders.view_base import BaseView

ICONS = {"closed_pocket": "ClosedPocket", "open_pocket": "OpenPocket", "opening": "Opening", "hole": "Hole"}


class ViewDomainElement(BaseView):
    def getIcon(self):
        import aeronc
        obj = getattr(self, "Object", None)
        return aeronc.icon(ICONS.get(getattr(obj, "ElementType", ""), "ClosedPocket"))
