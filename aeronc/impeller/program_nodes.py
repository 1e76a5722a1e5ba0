"""The document objects of an impeller program: the recognition nodes, the blank, the Job with
an operation per route step (and its tool controllers), and the program object's figures.

The core makes toolpaths for every step: channel roughing (its tool and allowance), blade and hub
finishing (one finishing cutter: the blade finishing step's tool), fillet finishing (its ball),
and the axial steps: turning, facing, drilling and boring. The milling moves from the front
(tool axis along the impeller's) are posted; the lathe's turning moves and what is cut from the
back face (a second setup, the part turned over: facing, drilling and boring from the back) are
operations kept out of the program, with the reason in their Note.
"""
import json
import math

import FreeCAD

from aeronc import pathcompat
from aeronc.impeller import recognition
from aeronc.impeller.route import AXIAL_STEPS, PATH_STEPS, path_tool
from aeronc.makers import face_links
from aeronc.objects.impeller_blank import ImpellerBlank
from aeronc.objects.impeller_features import DIMENSIONS, ImpellerFeature, ImpellerFeatures
from aeronc.operations import moves as move_text
from aeronc.operations.impeller_operation import ImpellerOperation

# Moves that are computed and checked but not posted through the 5-axis 840D post, and why.
NOT_POSTED_NOTE = {
    "turn": "lathe moves of the insert {} in one meridian plane (before the 5-axis setup): checked, "
            "not posted, the AC-5AX 840D post is for milling",
    "back": "second setup, the part turned over (tool axis against the impeller's, beyond the A axis's "
            "limits): checked, not posted with the first setup's program",
}
NO_PATH_NOTE = "no toolpath: {}"


def _cut_length(moves):
    length, prev = 0.0, None
    for m in moves:
        if prev is not None and not m[6]:
            length += math.dist(prev[:3], m[:3])
        prev = m
    return length


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


def add_features(doc, part, result):
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
    nodes.append(_node(doc, part, "hub", "Hub", recognition.hub_faces(result)))
    nodes.append(_node(doc, part, "root_fillets", "Root fillets", [f for b in result["blades"] for f in b["fillets"]]))
    nodes.append(_node(doc, part, "shroud", "Shroud", [f for b in result["blades"] for f in recognition.shroud_faces(b)]))
    if result.get("bore"):
        nodes.append(_node(doc, part, "bore", "Bore \u00d8{:g}".format(round(result["dimensions"]["boreDiameter"], 3)),
                           [result["bore"]]))
    for key, role, label in (("planes", "planes", "Planes"), ("turned", "turned", "Turned faces"),
                             ("holes", "holes", "Holes")):
        if result.get(key):
            nodes.append(_node(doc, part, role, label, result[key]))
    group.Group = nodes
    return group, nodes


def add_blank(doc, part, c):
    obj = doc.addObject("Part::FeaturePython", "Blank")
    ImpellerBlank(obj)
    fill_blank(obj, c)
    obj.Label = "Blank ({})".format(part.Label)
    return obj


def fill_blank(obj, c):
    obj.Shape = c.blank
    profile = c.result.get("blank") or {}
    obj.Allowance = c.settings["allowance"]
    obj.ProfileAxial = [float(v) for v in profile.get("axial", [])]
    obj.ProfileRadius = [float(v) for v in profile.get("radius", [])]


def add_job(doc, part, blank, frame=None):
    """The Job of the impeller, its model placed on the setup (frame: setup_frame.placement)."""
    job = pathcompat.create_job(doc, [part], "Job")
    job.Label = "Job impeller ({})".format(part.Label)
    if frame is not None:
        pathcompat.set_model_placement(job, frame)
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
    tc.CuttingOptimum = cutting_text(data)
    return tc


def cutting_text(d):
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


def add_operations(doc, job, steps, paths, cutting, axis=(0.0, 0.0, 1.0)):
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


def fill_program(prog, c, edits):
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
    prog.CuttingData = ["{} (steps {}): {}".format(tool, ", ".join(str(p) for p in d["steps"]), cutting_text(d))
                        for tool, d in c.cutting.items()]
    prog.Skipped = list(c.route.get("skipped", []))
    prog.Timings = json.dumps(c.seconds, separators=(",", ":"))
