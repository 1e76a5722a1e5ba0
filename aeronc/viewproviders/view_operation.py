"""GUI side of AeroNC's operations: Path's own view provider (PathGui::ViewProviderPathPython,
which every Path::FeaturePython object has) draws the Path; this proxy gives the icon and lets
the Job delete the operation. Parameters are edited in the property editor or the Machining
chain panel."""
from aeronc.viewproviders.view_base import BaseView


class ViewOperation(BaseView):
    ICON = "MachiningOperation"

    def attach(self, vobj):
        self.Object = vobj.Object
        self.ICON = getattr(getattr(vobj.Object, "Proxy", None), "ICON", self.ICON)

    def onDelete(self, vobj, subelements):
        return True

    def doubleClicked(self, vobj):
        return False  # no task panel of its own: the property editor shows the parameters

