"""ImpellerBlank: the blank of an impeller, its outer profile grown by the allowance and revolved
about the axis (docs/impeller.md §4), and the Stock of the impeller's Path Job.

A Part::FeaturePython so that Path's Job treats it like its own stock objects (their view
providers are Python ones). The shape is made by aeronc.impeller.programming from the core's
profile and saved with the document; recompute keeps it.
"""
from aeronc.objects.base import BaseProxy, declare_property, proxy_type

TYPE = "AeroNC::ImpellerBlank"


class ImpellerBlank(BaseProxy):
    Type = TYPE

    def __init__(self, obj):
        super().__init__(obj)
        self.declare(obj)

    def declare(self, obj):
        g = "Blank"
        declare_property(obj, "App::PropertyLength", "Allowance", g, "Stock added to the part's outer profile",
                         read_only=True)
        declare_property(obj, "App::PropertyFloatList", "ProfileAxial", g,
                         "Stations of the revolved profile along the axis, from the axis point", read_only=True)
        declare_property(obj, "App::PropertyFloatList", "ProfileRadius", g, "Radius of the profile at each station",
                         read_only=True)

    def execute(self, obj):
        pass  # the shape comes from the core's profile


def is_impeller_blank(obj):
    return proxy_type(obj) == TYPE
