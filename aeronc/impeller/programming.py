"""Program an impeller in the document: recognition nodes, blank, Path Job, posted program.

  create(doc, part, ...)                 recognise, plan, compute and post; add everything
  set_step_enabled / set_step_tool /     one edit of the route, the toolpaths computed again
  set_step_allowance / set_allowance     and the program posted again
  update(program, edits, allowance)      the same for any set of edits

compute() does all the work (recognition, dimensions, blank, route from the knowledge base; then
the core's one impeller program, _core.impeller_program as `aeronc impeller-program` makes it:
5-axis toolpaths with their gouge and holder checks, and cutting data from the cutting-parameter
optimiser, docs/impeller.md) without touching the document; the document is then changed in one
transaction, the program posted inside it, so a failure anywhere (not an impeller, unequal
blade groups, missing hub, no tool fits, the post refuses a move) leaves the document as it
was. The posted 840D program is kept in the program object and written next to the saved
document (or into out_dir).

Edits of the route: {"steps": {"<position>": {"enabled": bool, "tool": id, "allowance": mm}}}.
The core makes toolpaths for every step: channel roughing (its tool and allowance), blade and hub
finishing (one finishing cutter: the blade finishing step's tool), fillet finishing (its ball),
and the axial steps: turning, facing, drilling and boring. The milling moves from the front
(tool axis along the impeller's) are posted; the lathe's turning moves and what is cut from the
back face (a second setup, the part turned over: facing, drilling and boring from the back) are
operations kept out of the program, with the reason in their Note.
"""
import json
import math
import os
import time

import FreeCAD

from aeronc.impeller import recognition
from aeronc.pipeline import knowledge_base
from aeronc import pathcompat
from aeronc.errors import AeroNCError, ImpellerError, from_core
from aeronc.makers import face_links
from aeronc.objects.base import attach_views, descendants
from aeronc.objects.impeller_blank import ImpellerBlank
from aeronc.objects.impeller_features import DIMENSIONS, ImpellerFeature, ImpellerFeatures
from aeronc.objects.impeller_program import ImpellerProgram, edits_of, route_of
from aeronc.objects.transaction import in_transaction
from aeronc.operations import moves as move_text
from aeronc.operations.impeller_operation import ImpellerOperation, is_impeller_operation

MATERIAL = "7050-T7451"
MACHINE = "AC-5AX"
FIVE_AXIS_STEPS = ("rough_channels", "finish_blades", "finish_hub", "finish_fillets")
AXIAL_STEPS = ("turn", "face", "drill", "bore")  # flat tools (the lathe's insert is the core's own)
PATH_STEPS = FIVE_AXIS_STEPS + AXIAL_STEPS  # the steps the core makes toolpaths for
# Moves that are computed and checked but not posted through the 5-axis 840D post, and why.
NOT_POSTED_NOTE = {
    "turn": "lathe moves of the insert {} in one meridian plane (before the 5-axis setup): checked, "
            "not posted, the AC-5AX 840D post is for milling",
    "back": "second setup, the part turned over (tool axis against the impeller's, beyond the A axis's "
            "limits): checked, not posted with the first setup's program",
}
NO_PATH_NOTE = "no toolpath: {}"


def _core():
    from aeronc import _core as core
    return core


# --- The route with the user's edits ------------------------------------------------------------

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
        return {t["id"]: t for t in json.loads(_core().impeller_tools(path, knowledge_base.sql_folder()))}


def _steps_with_tools(route, edits, kb_path):
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


# --- The computation, without the document -------------------------------------------------------

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
    c.steps = _steps_with_tools(c.route, edits, kb_path)
    request = {"steps": c.steps, "material": material, "machine": machine,
               "options": {"stations": int(stations), "channels": int(channels)}}
    shape, label = part_obj.Shape, part_obj.Label
    with from_core(ImpellerError, label):
        c.paths = json.loads(_core().impeller_program(shape.exportBrepToString(),
                                                      kb_path or knowledge_base.user_kb_path(),
                                                      knowledge_base.sql_folder(), json.dumps(request)))
    c.cutting = {d["tool"]: d for d in c.paths.pop("cutting")}
    c.seconds.update(c.paths.pop("seconds"))
    return c


def path_tool(step, steps):
    """The tool that cuts a toolpath step: its own, but the blade finishing tool for the hub (the
    core finishes the blades and the hub with one cutter)."""
    if step["operation"] == "finish_hub":
        return next(s for s in steps if s["operation"] == "finish_blades")["tool"]
    return step["tool"]


def _cut_length(moves):
    length, prev = 0.0, None
    for m in moves:
        if prev is not None and not m[6]:
            length += math.dist(prev[:3], m[:3])
        prev = m
    return length


# --- Document objects --------------------------------------------------------------------------

def _node(doc, part, role, label, faces, blade=None, index=-1):
    obj = doc.addObject("App::FeaturePython", "ImpellerFeature")
    ImpellerFeature(obj)
    obj.Role = role
    obj.Label = label
    obj.FaceNumbers = sorted(set(faces))
    obj.Faces = face_links(part, faces)
    obj.BladeIndex = index
    if blade is not None:
        obj.AngleDeg = float(blade.get("angleDeg", 0.0))
        for prop, key in (("PressureFace", "pressure"), ("SuctionFace", "suction"), ("LeadingFace", "leading"),
                          ("TrailingFace", "trailing"), ("ShroudFace", "shroud")):
            setattr(obj, prop, int(blade.get(key) or 0))
        obj.FilletFaces = list(blade["fillets"])
    return obj


def _features(doc, part, result):
    group = doc.addObject("App::DocumentObjectGroupPython", "ImpellerFeatures")
    ImpellerFeatures(group)
    group.Label = "Impeller features ({})".format(part.Label)
    group.Source = part
    group.BladeCount, group.SplitterCount = result["bladeCount"], result["splitterCount"]
    axis = result["axis"]
    group.AxisPoint, group.AxisDirection = FreeCAD.Vector(*axis["point"]), FreeCAD.Vector(*axis["direction"])
    group.ClosestPair = list(result.get("closestPair") or [])
    for prop, key, _ in DIMENSIONS:
        setattr(group, prop, float(result["dimensions"].get(key) or 0.0))
    stored = {k: v for k, v in result.items() if k not in ("route", "blank")}
    stored["faceRoles"] = recognition.face_role_names(result)
    group.Result = json.dumps(stored, separators=(",", ":"))
    nodes = []
    for i, b in enumerate(result["blades"]):
        kind = b["kind"]
        nodes.append(_node(doc, part, kind + "_blade", "Blade {} ({})".format(i, kind),
                           recognition.blade_wall_faces(b), b, i))
    nodes.append(_node(doc, part, "hub", "Hub", [result["hub"]]))
    nodes.append(_node(doc, part, "root_fillets", "Root fillets", [f for b in result["blades"] for f in b["fillets"]]))
    nodes.append(_node(doc, part, "shroud", "Shroud", [b["shroud"] for b in result["blades"]]))
    if result.get("bore"):
        nodes.append(_node(doc, part, "bore", "Bore \u00d8{:g}".format(round(result["dimensions"]["boreDiameter"], 3)),
                           [result["bore"]]))
    for key, role, label in (("planes", "planes", "Planes"), ("turned", "turned", "Turned faces"),
                             ("holes", "holes", "Holes")):
        if result.get(key):
            nodes.append(_node(doc, part, role, label, result[key]))
    group.Group = nodes
    return group, nodes


def _blank(doc, part, c):
    obj = doc.addObject("Part::FeaturePython", "Blank")
    ImpellerBlank(obj)
    _fill_blank(obj, c)
    obj.Label = "Blank ({})".format(part.Label)
    return obj


def _fill_blank(obj, c):
    obj.Shape = c.blank
    profile = c.result.get("blank") or {}
    obj.Allowance = c.settings["allowance"]
    obj.ProfileAxial = [float(v) for v in profile.get("axial", [])]
    obj.ProfileRadius = [float(v) for v in profile.get("radius", [])]


def _job(doc, part, blank):
    job = pathcompat.create_job(doc, [part], "Job")
    job.Label = "Job impeller ({})".format(part.Label)
    for tc in pathcompat.tool_controllers(job):
        pathcompat.remove_tool_controller(doc, tc)
    pathcompat.set_job_stock_object(job, blank)
    return job


def _tool_controller(doc, job, tool, number, data):
    shape = {"drill": "drill.fcstd", "face": "endmill.fcstd", "flat": "endmill.fcstd",
             "bull": "endmill.fcstd"}.get(tool.get("type"), "ballend.fcstd")
    bit = {"version": 2, "name": tool["id"], "shape": shape,
           "parameter": {"Diameter": "{} mm".format(tool["diameter"]),
                         "Length": "{} mm".format(tool.get("reach") or 50),
                         "CuttingEdgeHeight": "{} mm".format(tool.get("fluteLength") or 10),
                         "ShankDiameter": "{} mm".format(tool.get("shankDiameter") or tool["diameter"])},
           "attribute": {"Flutes": int(tool.get("flutes") or 2), "Material": "Carbide"}}
    if shape == "drill.fcstd":  # FreeCAD's drill bit has a point angle instead of flute and shank sizes
        bit["parameter"] = {"Diameter": bit["parameter"]["Diameter"], "Length": bit["parameter"]["Length"],
                            "TipAngle": "118 \u00b0"}
    tc = pathcompat.create_tool_controller(doc, job, "TC: {} {}".format(tool["id"], data["operation"]), bit, number,
                                           data["rpm"], data["feed"], data["plungeFeed"])
    tc.addProperty("App::PropertyString", "AeroNCTool", "AeroNC", "Tool and operation of the AeroNC tool plan", 0, True)
    tc.AeroNCTool = "{}/{}".format(tool["id"], data["operation"])
    tc.addProperty("App::PropertyString", "CuttingOptimum", "AeroNC",
                   "What the cutting-parameter optimiser chose, and why", 0, True)
    tc.CuttingOptimum = _cutting_text(data)
    return tc


def _cutting_text(d):
    return ("n {:.0f} r/min, f_z {:.4f} mm, v_f {:.0f} mm/min (a_p {:.2f}, a_e {:.2f} mm); active: {}".format(
        d["rpm"], d["fz"], d["feed"], d["ap"], d["ae"], ", ".join(d["active"]) or "none"))


def path_text(moves, feed_mm_s):
    """G-code of the core's moves: G0/G1 to the tool tip with the tool axis as U V W."""
    lines = []
    for x, y, z, i, j, k, rapid in moves:
        n = math.sqrt(i * i + j * j + k * k) or 1.0
        words = "X{:.6f} Y{:.6f} Z{:.6f} U{:.6f} V{:.6f} W{:.6f}".format(x, y, z, i / n, j / n, k / n)
        lines.append(("G0 " + words) if rapid else "G1 {} F{:.6f}".format(words, feed_mm_s))
    return "\n".join(lines) + "\n"


def _front_and_back(moves, axis):
    """The moves cut from the front (tool axis along the impeller's) and from the back face."""
    front, back = [], []
    for m in moves:
        (back if m[3] * axis[0] + m[4] * axis[1] + m[5] * axis[2] < 0 else front).append(m)
    return front, back


def _route_paths(steps, paths, axis):
    """[(step, operation, moves, note, posted)] in route order: each step's moves, and after a
    facing, drilling or boring step what it cuts from the back face (operation "<step>_back")."""
    by_name = {o["name"]: o for o in paths["operations"]}
    axial = paths.get("axial") or {}
    by_name.update({o["name"]: o for o in axial.get("operations", [])})
    notes = list(axial.get("notes") or [])
    out = []
    for s in steps:
        name = s["operation"]
        path = by_name.get(name) if name in PATH_STEPS else None
        if path is None:
            why = "; ".join(n for n in notes if name in n) or "the core made no moves for this step"
            out.append((s, name, None, NO_PATH_NOTE.format(why), False))
            continue
        if name == "turn":
            out.append((s, name, path, NOT_POSTED_NOTE["turn"].format(path["cutter"]["id"]), False))
            continue
        if name not in AXIAL_STEPS:
            out.append((s, name, path, "", True))
            continue
        front, back = _front_and_back(path["moves"], axis)
        back += (by_name.get(name + "_back") or {}).get("moves", [])
        if front:
            out.append((s, name, dict(path, moves=front), "; ".join(n for n in notes if name in n), True))
        if back:
            out.append((s, name + "_back", dict(path, moves=back), NOT_POSTED_NOTE["back"], False))
    return out


def _operations(doc, job, steps, paths, cutting, axis=(0.0, 0.0, 1.0)):
    numbers = {int(p): n for p, n in paths["toolNumbers"].items()}  # the core's: one per tool, in route order
    number_of_tool = {s["tool"]["id"]: numbers[s["position"]] for s in steps if s.get("tool")}
    tcs = {}
    made = []
    for s, name, path, note, posted in _route_paths(steps, paths, axis):
        op = pathcompat.create_path_object(doc, "ImpellerOperation")
        ImpellerOperation(op)
        op.Label = "{} {}".format(s["position"], name.replace("_", " "))
        op.Position, op.Operation, op.Strategy = s["position"], name, s.get("strategy", "")
        op.StepAllowance = float(s.get("allowance") or 0.0)
        op.FaceNumbers = list(s.get("faces") or [])
        op.Note = note
        if path is None:
            op.Tool = (s.get("tool") or {}).get("id", "")
            op.Active = False
        else:
            tool = path_tool(s, steps) if s.get("tool") else None
            if tool is not None and tool["id"] in cutting:
                op.Tool = tool["id"]
                data = cutting[tool["id"]]
                if tool["id"] not in tcs:
                    tcs[tool["id"]] = _tool_controller(doc, job, tool, number_of_tool[tool["id"]], data)
                op.ToolController = tcs[tool["id"]]
                feed = data["feed"]
            else:  # the lathe's insert: the core's own, not in the knowledge base
                op.Tool = path["cutter"]["id"]
                feed = float(path["cutter"].get("feed") or 1.0)
            op.Path = pathcompat.path_from_gcode(path_text(path["moves"], feed / 60.0))
            op.MoveCount = len(path["moves"])
            length = _cut_length(path["moves"])
            op.CutLength = length
            op.CycleTime = move_text.clock_text(60.0 * length / feed)
            op.Active = bool(s["enabled"]) and posted
            if name == "finish_hub" and s.get("tool") and s["tool"]["id"] != tool["id"]:
                op.Note = "finished with the blade finishing tool {} (the core uses one finishing cutter)".format(
                    tool["id"])
        pathcompat.add_operation(job, op)
        made.append(op)
    return made


def _fill_program(prog, c, edits):
    s = c.settings
    prog.Allowance = s["allowance"]
    prog.Material, prog.Machine, prog.KnowledgeBase = s["material"], s["machine"], s["kb_path"]
    prog.Stations, prog.Channels = s["stations"], s["channels"]
    # Over the 5-axis operations and the axial steps' moves (all of them checked, posted or not).
    check = c.paths["check"]
    axial = (c.paths.get("axial") or {}).get("check") or {}
    rapids = c.paths.get("rapids") or {}
    prog.MaxGouge = max(float(check["maxGougeMm"]), float(axial.get("maxGougeMm", 0.0)))
    prog.HolderCollisions = int(check["holderCollisions"]) + int(axial.get("holderCollisions", 0))
    prog.Tilted = int(check["tilted"])
    prog.PositionsChecked = int(check["positions"]) + int(axial.get("positions", 0))
    prog.LinksChecked = int(check.get("links", 0)) + int(rapids.get("checked", 0))
    prog.LinkCollisions = int(check.get("linkCollisions", 0)) + int(rapids.get("collisions", 0))
    prog.Checks = json.dumps({"fiveAxis": check, "rapids": rapids, "axial": axial,
                              "axialNotes": (c.paths.get("axial") or {}).get("notes", [])}, separators=(",", ":"))
    prog.Route = json.dumps(c.route, separators=(",", ":"))
    prog.Edits = json.dumps(edits, separators=(",", ":"))
    prog.Cutting = json.dumps(c.cutting, separators=(",", ":"))
    prog.CuttingData = ["{} (steps {}): {}".format(tool, ", ".join(str(p) for p in d["steps"]), _cutting_text(d))
                        for tool, d in c.cutting.items()]
    prog.Skipped = list(c.route.get("skipped", []))
    prog.Timings = json.dumps(c.seconds, separators=(",", ":"))


def _post_into(prog):
    """Post the Job for the machine (AeroNC's 840D post, TRAORI for the 5-axis moves); the text
    is kept in the program object."""
    from aeronc.post import nc_post
    text = nc_post.export([prog.Job], "-", "--machine {} --program-name {}".format(
        prog.Machine or MACHINE, prog.ProgramName or "IMPELLER"))
    prog.Posted = text
    prog.ProgramLines = text.count("\n")
    return text


def program_path(prog, out_dir=None):
    """Where the posted program goes: out_dir, or next to the saved document; None if neither."""
    folder = out_dir or (os.path.dirname(prog.Document.FileName) if prog.Document.FileName else "")
    if not folder:
        return None
    return os.path.join(folder, "{}.mpf".format(prog.ProgramName or "IMPELLER"))


def write_program(prog, out_dir=None):
    """Write the posted program next to the document (or into out_dir), atomically; returns the
    path, or None for an unsaved document without out_dir."""
    from aeronc.post.output import write_atomically
    path = program_path(prog, out_dir)
    if path is None or not prog.Posted:
        return None
    write_atomically(path, prog.Posted)
    if prog.ProgramFile != path:
        prog.ProgramFile = path
    return path


def create(doc, part_obj, allowance=2.0, material=MATERIAL, machine=MACHINE, kb_path=None, stations=24, channels=0,
           out_dir=None):
    """Program the impeller part_obj: recognition nodes, blank, Job with the route's operations,
    posted program, as one undo step. Returns the ImpellerProgram object. Raises AeroNCError
    (RecognitionError: not an impeller, unequal blade groups, missing hub; ImpellerError,
    PostError, ...) leaving the document as it was."""
    c = compute(part_obj, allowance, None, material, machine, kb_path, stations, channels)

    def work():
        group, nodes = _features(doc, part_obj, c.result)
        blank = _blank(doc, part_obj, c)
        job = _job(doc, part_obj, blank)
        ops = _operations(doc, job, c.steps, c.paths, c.cutting, c.result["axis"]["direction"])
        prog = doc.addObject("App::FeaturePython", "ImpellerProgram")
        ImpellerProgram(prog)
        prog.Label = "Impeller program ({})".format(part_obj.Label)
        prog.Features, prog.Blank, prog.Job = group, blank, job
        _fill_program(prog, c, normalised_edits(None))
        made = [group] + nodes + [prog] + ops
        for obj in made:
            obj.Visibility = True
        blank.Visibility = False
        attach_views(made)
        doc.recompute()
        t0 = time.perf_counter()
        _post_into(prog)
        prog.Timings = json.dumps(dict(c.seconds, post=time.perf_counter() - t0), separators=(",", ":"))
        return prog

    prog = in_transaction(doc, "Program impeller", work)
    write_program(prog, out_dir)
    return prog


def update(prog, edits=None, allowance=None, title="Edit impeller route", out_dir=None):
    """Apply edits (replacing the stored ones) and/or a new blank allowance: compute again and
    replace the blank, the operations and their tool controllers, post again; one undo step."""
    doc = prog.Document
    part = prog.Features.Source if prog.Features is not None else None
    if part is None or prog.Job is None:
        raise ImpellerError("{}: its impeller features or Job are gone; program the part again".format(prog.Label))
    edits = normalised_edits(edits_of(prog) if edits is None else edits)
    allowance = prog.Allowance.Value if allowance is None else float(allowance)
    c = compute(part, allowance, edits, prog.Material or MATERIAL, prog.Machine or MACHINE,
                prog.KnowledgeBase or None, prog.Stations or 24, prog.Channels, route=route_of(prog))

    def work():
        job = prog.Job
        old_ops = [o for o in pathcompat.job_operations(job) if is_impeller_operation(o)]
        old_tcs = [tc for tc in pathcompat.tool_controllers(job) if hasattr(tc, "AeroNCTool")]  # ours only
        pathcompat.set_job_operations(job, [o for o in pathcompat.job_operations(job) if o not in old_ops])
        for o in old_ops:
            doc.removeObject(o.Name)
        for tc in old_tcs:
            pathcompat.remove_tool_controller(doc, tc)
        if abs(prog.Allowance.Value - allowance) > 1e-12 or prog.Blank is None:
            if prog.Blank is not None:
                _fill_blank(prog.Blank, c)
            else:
                prog.Blank = _blank(doc, part, c)
                pathcompat.set_job_stock_object(job, prog.Blank)
        ops = _operations(doc, job, c.steps, c.paths, c.cutting, c.result["axis"]["direction"])
        _fill_program(prog, c, edits)
        for obj in ops:
            obj.Visibility = True
        attach_views(ops)
        doc.recompute()
        _post_into(prog)
        return prog

    in_transaction(doc, title, work)
    write_program(prog, out_dir)
    return prog


def _edit_step(prog, position, key, value, title):
    edits = normalised_edits(edits_of(prog))
    positions = [s["position"] for s in route_of(prog)["steps"]]
    if int(position) not in positions:
        raise ImpellerError("{}: the route has no step {}".format(prog.Label, position))
    edits["steps"].setdefault(str(int(position)), {})[key] = value
    return update(prog, edits, title=title)


def set_step_enabled(prog, position, enabled):
    """Switch a route step on or off (one undo step)."""
    return _edit_step(prog, position, "enabled", bool(enabled), "Switch impeller step {}".format(
        "on" if enabled else "off"))


def set_step_tool(prog, position, tool_id):
    """Give a route step another tool of the knowledge base (one undo step). The channel
    roughing and blade finishing tools shape the toolpaths; the hub is finished with the blade
    finishing tool."""
    step = _step(prog, position)
    tool = tool_library(prog.KnowledgeBase or None).get(tool_id)
    if tool is None:
        raise ImpellerError("no tool {} in the knowledge base".format(tool_id))
    if step["operation"] in ("rough_channels", "finish_blades") and tool["type"] not in ("ball", "tapered_ball"):
        raise ImpellerError("step {} ({}) needs a ball or tapered ball end mill; {} is a {} tool".format(
            position, step["operation"], tool_id, tool["type"]))
    return _edit_step(prog, position, "tool", tool_id, "Change impeller step tool")


def set_step_allowance(prog, position, allowance):
    """Change the stock a step leaves (one undo step). The core's finishing passes leave none,
    so only channel roughing's allowance can change."""
    step = _step(prog, position)
    if step["operation"] != "rough_channels":
        raise ImpellerError("step {} ({}): only the channel roughing's allowance shapes the toolpaths".format(
            position, step["operation"]))
    if not float(allowance) >= 0:
        raise ImpellerError("an allowance must be zero or more, not {}".format(allowance))
    return _edit_step(prog, position, "allowance", float(allowance), "Change impeller step allowance")


def set_allowance(prog, allowance):
    """A new blank allowance: the blank is made again (one undo step)."""
    if not float(allowance) >= 0:
        raise ImpellerError("the blank allowance must be zero or more, not {}".format(allowance))
    return update(prog, allowance=float(allowance), title="Change blank allowance")


def _step(prog, position):
    for s in route_of(prog)["steps"]:
        if s["position"] == int(position):
            return s
    raise ImpellerError("{}: the route has no step {}".format(prog.Label, position))


def steps_of(prog):
    """The route's steps with the stored edits applied (for panels and reports)."""
    return _steps_with_tools(route_of(prog), normalised_edits(edits_of(prog)), prog.KnowledgeBase or None)


def check_posted(prog):
    """The gouge and holder check of the Job's program as FreeCAD holds it: written as APT by
    AeroNC's APT post, read back and measured against the blades and hub (docs/impeller.md)."""
    from aeronc.post import apt
    job = prog.Job
    text = apt.export([job], "-", "--program-name {}".format(prog.ProgramName or "IMPELLER"))
    cutters = []
    library = tool_library(prog.KnowledgeBase or None)
    for tc in pathcompat.tool_controllers(job):
        tool = library.get(getattr(tc, "AeroNCTool", "").split("/")[0])
        if tool is None:
            continue
        r = tool["diameter"] / 2
        if tool["type"] in ("ball", "tapered_ball"):
            cutters.append({"id": tool["id"], "number": int(tc.ToolNumber), "tipRadius": r,
                            "taperDeg": tool["taperDeg"], "fluteLength": tool["fluteLength"],
                            "shankRadius": tool["shankDiameter"] / 2, "reach": tool["reach"]})
        else:  # a flat tool as the core's axial steps measure it (impellerpath::flatCutter)
            flutes = max(tool["fluteLength"], r + 1)
            cutters.append({"id": tool["id"], "number": int(tc.ToolNumber), "tipRadius": r, "taperDeg": 0,
                            "fluteLength": flutes, "shankRadius": r, "reach": max(tool["reach"], flutes),
                            "flat": True})
    part = prog.Features.Source
    with from_core(ImpellerError, "checking {}".format(prog.Label)):
        return json.loads(_core().impeller_check_apt(part.Shape.exportBrepToString(), text, json.dumps(cutters)))


def remove(prog):
    """Remove the program with its Job, blank and impeller features (one undo step)."""
    doc = prog.Document

    def work():
        job, blank, group = prog.Job, prog.Blank, prog.Features
        doc.removeObject(prog.Name)
        if job is not None:
            pathcompat.remove_job(job)
        if blank is not None and doc.getObject(blank.Name) is not None:
            doc.removeObject(blank.Name)
        if group is not None:
            for obj in descendants(group) + [group]:
                doc.removeObject(obj.Name)

    in_transaction(doc, "Remove impeller program", work)


__all__ = ["create", "update", "compute", "set_step_enabled", "set_step_tool", "set_step_allowance",
           "set_allowance", "check_posted", "write_program", "steps_of", "remove", "AeroNCError"]
