from aeronc.viewproviders.view_base import BaseView


class ViewSetupDirection(BaseView):
    ICON = "SetupDirection"
