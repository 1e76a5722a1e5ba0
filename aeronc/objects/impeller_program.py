"""ImpellerProgram: the NC program of an impeller in the document.

Links the recognised impeller (ImpellerFeatures), the blank (a Part object, the Job's Stock)
and the Path Job whose operations are the process route's steps in route order. Holds the
route as the knowledge base planned it (Route), the user's edits of it (Edits: disabled steps,
other tools, other allowances), the settings (blank allowance, material, machine, knowledge
base, stations and channels of the toolpaths), the cutting data the optimiser chose, the
checks of the toolpaths and the posted 840D program. All JSON lives in string properties, so
the program survives save and reopen. Made and updated by aeronc.impeller.programming.
"""
import json

from aeronc.objects.base import BaseProxy, declare_property, proxy_type

TYPE = "AeroNC::ImpellerProgram"


class ImpellerProgram(BaseProxy):
    Type = TYPE

    def __init__(self, obj):
        super().__init__(obj)
        self.declare(obj)

    def declare(self, obj):
        g = "Impeller program"
        declare_property(obj, "App::PropertyLink", "Features", g, "The recognised impeller")
        declare_property(obj, "App::PropertyLink", "Blank", g, "The blank: the Job's stock")
        declare_property(obj, "App::PropertyLink", "Job", g, "The Path Job with the route's operations")
        declare_property(obj, "App::PropertyLength", "Allowance", g,
                         "Stock added to the revolved outer profile to make the blank", read_only=True)
        declare_property(obj, "App::PropertyString", "Material", g, "Workpiece material", read_only=True)
        declare_property(obj, "App::PropertyString", "Machine", g, "Machine of the program", read_only=True)
        declare_property(obj, "App::PropertyString", "KnowledgeBase", g,
                         "Knowledge base of the route and tools (empty: the user's)", read_only=True)
        declare_property(obj, "App::PropertyInteger", "Stations", g, "Positions along each pass", read_only=True)
        declare_property(obj, "App::PropertyInteger", "Channels", g, "Channels machined (0: all)", read_only=True)
        g = "Checks"
        declare_property(obj, "App::PropertyFloat", "MaxGouge", g,
                         "Deepest cut into the blades and hub over every cutting position (mm)", read_only=True)
        declare_property(obj, "App::PropertyInteger", "HolderCollisions", g,
                         "Positions where the shank or holder touches the part", read_only=True)
        declare_property(obj, "App::PropertyInteger", "Tilted", g, "Positions tilted to clear the holder",
                         read_only=True)
        declare_property(obj, "App::PropertyInteger", "PositionsChecked", g, "Cutting positions checked",
                         read_only=True)
        declare_property(obj, "App::PropertyInteger", "LinksChecked", g,
                         "Links checked: feed approaches and retracts against the part, rapids against the blank",
                         read_only=True)
        declare_property(obj, "App::PropertyInteger", "LinkCollisions", g,
                         "Feed links that touch the part and rapids that enter the blank", read_only=True)
        declare_property(obj, "App::PropertyString", "Checks", g,
                         "The core's check figures: 5-axis, rapids, axial steps (JSON)", hidden=True)
        g = "Program"
        declare_property(obj, "App::PropertyString", "ProgramName", g, "Name of the posted program", "IMPELLER")
        declare_property(obj, "App::PropertyString", "ProgramFile", g,
                         "Where the posted program was last written (next to the document)", read_only=True)
        declare_property(obj, "App::PropertyInteger", "ProgramLines", g, "Lines of the posted program",
                         read_only=True)
        declare_property(obj, "App::PropertyStringList", "CuttingData", g,
                         "Spindle speed and feed of each tool, from the cutting-parameter optimiser", read_only=True)
        declare_property(obj, "App::PropertyStringList", "Skipped", g, "Route rules that do not apply, and why",
                         read_only=True)
        g = "Data"
        declare_property(obj, "App::PropertyString", "Route", g, "The route as the knowledge base planned it (JSON)",
                         hidden=True)
        declare_property(obj, "App::PropertyString", "Edits", g, "The user's edits of the route (JSON)", hidden=True)
        declare_property(obj, "App::PropertyString", "Cutting", g, "Cutting data per tool (JSON)", hidden=True)
        declare_property(obj, "App::PropertyString", "Posted", g, "The posted 840D program", hidden=True)
        declare_property(obj, "App::PropertyString", "Timings", g,
                         "Seconds of the last computation's stages (JSON)", hidden=True)

    def execute(self, obj):
        pass


def is_impeller_program(obj):
    return proxy_type(obj) == TYPE


def route_of(obj):
    return json.loads(obj.Route) if obj.Route else {"steps": [], "skipped": []}


def edits_of(obj):
    return json.loads(obj.Edits) if obj.Edits else {}


def cutting_of(obj):
    return json.loads(obj.Cutting) if obj.Cutting else {}


def programs_of_part(doc, part):
    """The ImpellerProgram objects made for a part."""
    return [o for o in doc.Objects if is_impeller_program(o) and o.Features is not None
            and o.Features.Source is part]
