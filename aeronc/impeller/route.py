"""The impeller route with the user's edits, and the computation of the whole program without
the document: recognition, dimensions, blank and route from the knowledge base, then the core's
one impeller program (5-axis toolpaths with their gouge and holder checks, the axial steps, and
cutting data from the cutting-parameter optimiser; docs/impeller.md).

Edits of the route: {"steps": {"<position>": {"enabled": bool, "tool": id, "allowance": mm}}}.
"""
import json
import os
import time

from aeronc.errors import ImpellerError, from_core
from aeronc.impeller import recognition
from aeronc.pipeline import knowledge_base

MATERIAL = "7050-T7451"
MACHINE = "AC-5AX"
FIVE_AXIS_STEPS = ("rough_channels", "finish_blades", "finish_hub", "finish_fillets")
AXIAL_STEPS = ("turn", "face", "drill", "bore")  # flat tools (the lathe's insert is the core's own)
PATH_STEPS = FIVE_AXIS_STEPS + AXIAL_STEPS  # the steps the core makes toolpaths for


def core_module():
    """aeronc._core, imported when first needed (the package imports without the extension)."""
    from aeronc import _core
    return _core


def normalised_edits(edits):
    steps = {}
    for key, e in ((edits or {}).get("steps") or {}).items():
        e = {k: v for k, v in e.items() if k in ("enabled", "tool", "allowance")}
        if e:
            steps[str(int(key))] = e
    return {"steps": steps}


def edited_steps(route, edits):
    """The route's steps with the edits applied: each a copy with "enabled", and the tool and
    allowance the user chose (the knowledge base's tool record for a changed tool)."""
    out = []
    for s in route["steps"]:
        e = (edits.get("steps") or {}).get(str(s["position"]), {})
        step = dict(s)
        step["enabled"] = bool(e.get("enabled", True))
        if "allowance" in e:
            step["allowance"] = float(e["allowance"])
        if e.get("tool") and (s.get("tool") or {}).get("id") != e["tool"]:
            step["tool"] = {"id": e["tool"]}  # filled from the knowledge base by _steps_with_tools
        out.append(step)
    return out


def tool_library(kb_path=None):
    """{id: tool} of the tools the impeller route may choose (knowledge base)."""
    path = kb_path or knowledge_base.user_kb_path()
    os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
    with from_core(ImpellerError, "impeller tools"):
        return {t["id"]: t for t in json.loads(core_module().impeller_tools(path, knowledge_base.sql_folder()))}


def steps_with_tools(route, edits, kb_path):
    steps = edited_steps(route, edits)
    library = None
    for s in steps:
        tool = s.get("tool")
        if tool and "diameter" not in tool:
            library = library or tool_library(kb_path)
            if tool["id"] not in library:
                raise ImpellerError("step {} ({}): no tool {} in the knowledge base".format(
                    s["position"], s["operation"], tool["id"]))
            s["tool"] = library[tool["id"]]
    return steps


class Computed:
    """Everything the document objects are made from."""

    def __init__(self):
        self.result = None      # recognition + dimensions (+ "route", "blank")
        self.blank = None       # Part shape
        self.route = None       # as planned by the knowledge base
        self.steps = None       # with the edits
        self.paths = None       # the core's program JSON: operations, check, rapids, axial, toolNumbers
        self.cutting = {}       # tool id -> cutting data of its ToolController
        self.settings = {}
        self.seconds = {}       # stage -> seconds: recognise (with blank and route), toolpaths, cutting
        self.frame = None       # FreeCAD.Placement of the setup (setup_frame.py): blank and paths are in it
        self.setup_axis = (0.0, 0.0, 1.0)  # the impeller's axis in the setup frame


def compute(part_obj, allowance=2.0, edits=None, material=MATERIAL, machine=MACHINE, kb_path=None,
            stations=24, channels=0, route=None):
    """Recognise, plan and compute toolpaths; the document is not touched. route: the route
    as planned before (an update keeps it and applies the edits); None plans it."""
    edits = normalised_edits(edits)
    c = Computed()
    c.settings = dict(allowance=float(allowance), material=material, machine=machine, kb_path=kb_path or "",
                      stations=int(stations), channels=int(channels))
    t0 = time.perf_counter()
    c.result, c.blank = recognition.program_data(part_obj, allowance, kb_path=kb_path)
    c.seconds["recognise"] = time.perf_counter() - t0
    c.route = route or c.result["route"]
    c.steps = steps_with_tools(c.route, edits, kb_path)
    request = {"steps": c.steps, "material": material, "machine": machine,
               "options": {"stations": int(stations), "channels": int(channels)}}
    shape, label = part_obj.Shape, part_obj.Label
    with from_core(ImpellerError, label):
        c.paths = json.loads(core_module().impeller_program(shape.exportBrepToString(),
                                                      kb_path or knowledge_base.user_kb_path(),
                                                      knowledge_base.sql_folder(), json.dumps(request)))
    c.cutting = {d["tool"]: d for d in c.paths.pop("cutting")}
    c.seconds.update(c.paths.pop("seconds"))
    # The Job works in the setup frame: the impeller's axis along Z, the part on the table.
    import FreeCAD
    from aeronc.impeller import setup_frame
    c.frame = setup_frame.placement(c.result["axis"], shape)
    c.paths = setup_frame.paths_in(c.frame, c.paths)
    c.blank = setup_frame.shape_in(c.frame, c.blank)
    a = c.frame.Rotation.multVec(FreeCAD.Vector(*c.result["axis"]["direction"]))
    c.setup_axis = (a.x, a.y, a.z)
    return c


def path_tool(step, steps):
    """The tool that cuts a toolpath step: its own, but the blade finishing tool for the hub (the
    core finishes the blades and the hub with one cutter)."""
    if step["operation"] == "finish_hub":
        return next(s for s in steps if s["operation"] == "finish_blades")["tool"]
    return step["tool"]
