"""MachiningChain: the NC machining chain of a part in the document.

Holds the chain as the core built it (Built), the user's edits of it (Edits: unit order, tool
overrides, disabled units), the chain with the edits applied and the rules checked again
(Chain), the settings it was built with (family, material, machine, knowledge base), and links
to the Machining Features group it was built from and to the Path Jobs made from it, one per
setup. All JSON lives in string properties, so the chain survives save and reopen. The chain
is built and updated by aeronc.pipeline.chain_building, which also makes the Jobs.
"""
import json

from aeronc.objects.base import BaseProxy, declare_property, proxy_type

TYPE = "AeroNC::MachiningChain"


class MachiningChain(BaseProxy):
    Type = TYPE

    def __init__(self, obj):
        super().__init__(obj)
        self.declare(obj)

    def declare(self, obj):
        g = "Machining chain"
        declare_property(obj, "App::PropertyLink", "Features", g, "The Machining Features group the chain machines")
        declare_property(obj, "App::PropertyLinkList", "Jobs", g, "Path Jobs of the chain, one per setup")
        declare_property(obj, "App::PropertyString", "Family", g, "Part family of the process template", read_only=True)
        declare_property(obj, "App::PropertyString", "Material", g, "Workpiece material", read_only=True)
        declare_property(obj, "App::PropertyString", "Machine", g, "Machine of the process plan", read_only=True)
        declare_property(obj, "App::PropertyString", "KnowledgeBase", g,
                         "Knowledge base the chain was built from (empty: the user's)", read_only=True)
        g = "Result"
        declare_property(obj, "App::PropertyInteger", "UnitCount", g, "Machining units", read_only=True)
        declare_property(obj, "App::PropertyInteger", "DisabledCount", g, "Units the user disabled", read_only=True)
        declare_property(obj, "App::PropertyFloat", "TravelSavedPercent", g,
                         "Rapid travel saved by ordering, against the rules-only order", read_only=True)
        declare_property(obj, "App::PropertyInteger", "FailedChecks", g, "Construction rules that fail", read_only=True)
        declare_property(obj, "App::PropertyStringList", "Unmachined", g, "Elements no unit machines, and why",
                         read_only=True)
        declare_property(obj, "App::PropertyStringList", "Messages", g,
                         "What the last update kept of the user's edits, and what it could not keep", read_only=True)
        g = "Data"
        declare_property(obj, "App::PropertyString", "Built", g, "The chain as the core built it (JSON)", hidden=True)
        declare_property(obj, "App::PropertyString", "Edits", g, "The user's edits of the chain (JSON)", hidden=True)
        declare_property(obj, "App::PropertyString", "Chain", g, "The chain with the edits, checked (JSON)", hidden=True)

    def execute(self, obj):
        pass


def is_machining_chain(obj):
    return proxy_type(obj) == TYPE


def chain_of(obj):
    """The stored chain (with the edits) of a MachiningChain object, as a dict."""
    return json.loads(obj.Chain) if obj.Chain else {}


def built_of(obj):
    return json.loads(obj.Built) if obj.Built else {}


def edits_of(obj):
    return json.loads(obj.Edits) if obj.Edits else {}


def chains_of_features(group):
    """The MachiningChain objects built from a Machining Features group."""
    return [o for o in group.InList if is_machining_chain(o) and o.Features is group]
