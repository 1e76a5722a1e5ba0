"""The impeller run, headless: an impeller part programmed in FreeCAD, with its report.

    part (its bodies fused into one solid when it has several) -> Program impeller (recognition
    nodes, blank, Job, 5-axis toolpaths, post)
    -> save -> re-read check of the Job's program -> pictures -> report

run() writes into one output folder:
  impeller.FCStd            the document: part, impeller features, blank, Job, program object
  IMPELLER.mpf              the posted Sinumerik 840D program (TRAORI), next to the document
  IMPELLER.apt              the Job's program as APT, the form the re-read check reads
  impeller.step             the part as programmed
  truth.json                the part's known truth, when the caller gives one (a generated part)
  report.html               dimensions (against the truth, when given), route, tools, cutting
                            data, checks
  features.png, toolpaths.png   the part coloured by feature; the toolpaths over the part
  impeller.json             the data behind the report
  kb.sqlite, freecad.log    the knowledge base used; what FreeCAD printed meanwhile
A second run replaces the outputs of the first (the files listed in .aeronc-outputs).
"""
import json
import os

from aeronc.runs.stages import Run, RunError

LIMIT_GOUGE_MM = 0.01
DIMENSION_KEYS = ("boreDiameter", "boreDepth", "filletRadius", "bladeHeight", "minChannelWidth")


def run(out, shape, truth=None, source="", allowance=2.0, stations=24, channels=0, say=None):
    """Program the impeller `shape` (a Part shape) and write the run into out; returns the
    report's data. truth: the part's known truth (a generated part's), compared in the report;
    source: what the part is, for the report. Raises RunError naming the stage that failed."""
    r = Run(out, say)
    with r.console():
        r.say("AeroNC impeller run: {} -> {}".format(source or "impeller", r.out))
        data = _stages(r, shape, truth, source, allowance, stations, channels)
        r.say("  {:>6.1f} s  total".format(r.total()))
    return data


def _stages(r, shape, truth, source, allowance, stations, channels):
    from aeronc import pathcompat
    from aeronc.impeller import programming
    from aeronc.reports import impeller_report

    data = {"source": source, "allowance": allowance, "stations": stations, "channels": channels, "pictures": [],
            "truth": truth}
    kb_path = r.path("kb.sqlite")
    with r.stage("part"):
        doc = r.new_document("impeller")
        doc.UndoMode = 1
        part = doc.addObject("Part::Feature", "Impeller")
        part.Shape = shape
        doc.recompute()
        if truth is not None:
            r.write("truth.json", json.dumps(truth, indent=1))
    if len(shape.Solids) > 1:
        # Exported as several bodies (a hub and a body per blade): fused as Program impeller
        # offers it, a new object, the original kept.
        from aeronc.objects.fused_part import add_fused_part
        with r.stage("fuse bodies"):
            part, data["fused"] = add_fused_part(part)
        r.report(data["fused"])
    with r.stage("part file"):
        part.Shape.exportStep(r.path("impeller.step"))
        r.wrote("impeller.step")
    shape = part.Shape
    data["faces"] = len(shape.Faces)
    r.report("{} faces".format(len(shape.Faces)) + (", {} + {} blades".format(
        truth["bladeCount"], sum(1 for b in truth["blades"] if b["splitter"])) if truth else ""))

    with r.stage("program impeller"):
        prog = programming.create(doc, part, allowance=allowance, kb_path=kb_path, stations=stations,
                                  channels=channels, out_dir=r.out)
    timings = json.loads(prog.Timings or "{}")
    data["seconds"] = timings
    r.report("recognise {:.1f} s, toolpaths {:.1f} s, cutting data {:.1f} s, post {:.1f} s; {} lines".format(
        timings.get("recognise", 0), timings.get("toolpaths", 0), timings.get("cutting", 0), timings.get("post", 0),
        prog.ProgramLines))
    r.wrote("IMPELLER.mpf", "kb.sqlite")

    with r.stage("save"):
        r.save_document(doc, "impeller.FCStd")
        programming.write_program(prog)
    r.report("impeller.FCStd")

    with r.stage("re-read check"):
        from aeronc.post import apt
        apt.export([prog.Job], r.path("IMPELLER.apt"), "--program-name IMPELLER")
        r.wrote("IMPELLER.apt")
        again = programming.check_posted(prog)
    data["recheck"] = again
    r.report("{} positions, deepest gouge {:.5f} mm, {} holder collisions".format(
        again["positions"], again["maxGougeMm"], again["holderCollisions"]))

    data.update(_program_data(prog, pathcompat))
    with r.stage("pictures"):
        data["pictures"] = _pictures(r.out, part, prog, pathcompat)
        r.wrote(*[os.path.basename(p) for _, p in data["pictures"]])
    r.report(", ".join(os.path.basename(p) for _, p in data["pictures"]))

    data["stages"] = list(r.times)
    r.write("impeller.json", json.dumps(data, indent=1, default=str))
    impeller_report.write(r.path("report.html"), data)
    r.wrote("report.html")
    r.finish()
    return data


def _program_data(prog, pathcompat):
    """What the report shows of the program object, its features and its Job."""
    from aeronc.impeller import programming
    from aeronc.objects.impeller_features import result_of
    from aeronc.objects.impeller_program import cutting_of
    result = result_of(prog.Features)
    ops = []
    for o in pathcompat.job_operations(prog.Job):
        tc = o.ToolController
        ops.append({"label": o.Label, "position": o.Position, "operation": o.Operation, "strategy": o.Strategy,
                    "tool": o.Tool, "allowance": o.StepAllowance.Value, "active": bool(o.Active),
                    "moves": o.MoveCount, "cutLength": o.CutLength.Value, "cycleTime": o.CycleTime, "note": o.Note,
                    "toolNumber": int(tc.ToolNumber) if tc is not None else None})
    library = programming.tool_library(prog.KnowledgeBase or None)
    used = []
    for s in programming.steps_of(prog):
        tool = s.get("tool")
        if tool and tool["id"] not in [t["id"] for t in used]:
            used.append(dict(library.get(tool["id"], tool), reason=s.get("toolReason", ""),
                             steps=[x["position"] for x in programming.steps_of(prog)
                                    if (x.get("tool") or {}).get("id") == tool["id"]]))
    return {
        "result": {k: v for k, v in result.items() if k != "faceRoles"},
        "route": programming.route_of(prog),
        "edits": programming.edits_of(prog),
        "operations": ops,
        "tools": used,
        "cutting": cutting_of(prog),
        "check": {"maxGougeMm": prog.MaxGouge, "holderCollisions": prog.HolderCollisions, "tilted": prog.Tilted,
                  "positions": prog.PositionsChecked, "links": prog.LinksChecked,
                  "linkCollisions": prog.LinkCollisions, "parts": json.loads(prog.Checks or "{}")},
        "program": {"file": prog.ProgramFile, "lines": prog.ProgramLines, "head": prog.Posted.split("\n")[:60]},
        "material": prog.Material, "machine": prog.Machine,
        "blank": {"allowance": prog.Blank.Allowance.Value, "volume": prog.Blank.Shape.Volume,
                  "diameter": prog.Blank.Shape.BoundBox.XLength, "length": prog.Blank.Shape.BoundBox.ZLength},
    }


def _path_moves(op):
    """[[kind, x, y, z]] of an operation's Path: 0 rapid, 1 feed."""
    moves, last = [], {"X": 0.0, "Y": 0.0, "Z": 0.0}
    for c in op.Path.Commands:
        p = c.Parameters
        for k in "XYZ":
            if k in p:
                last[k] = p[k]
        moves.append([0 if c.Name in ("G0", "G00") else 1, last["X"], last["Y"], last["Z"]])
    return moves


def _pictures(out, part, prog, pathcompat):
    from aeronc.impeller import recognition
    from aeronc.reports import picture, toolpath_picture
    from aeronc.objects.impeller_features import result_of
    result = result_of(prog.Features)
    roles = result.get("faceRoles") or recognition.face_role_names(result)
    shots = []
    path = picture.render(part.Shape, {"faceRoles": roles}, os.path.join(out, "features.png"),
                          title="{}: impeller features by role".format(part.Label),
                          views=(("from above", 40, -60), ("from the side", 8, -60)))
    shots.append(("The part coloured by feature", path))
    top = {"u": (1.0, 0.0, 0.0), "v": (0.0, 1.0, 0.0), "w": (0.0, 0.0, 1.0)}
    side = {"u": (1.0, 0.0, 0.0), "v": (0.0, 0.0, 1.0), "w": (0.0, -1.0, 0.0)}
    setups = []
    models = pathcompat.job_models(prog.Job)  # the part as the Job holds it: the toolpaths' frame
    placed = models[0].Shape if models else part.Shape
    for name, frame in (("along the axis", top), ("from the side", side)):
        toolpaths = []
        for op in pathcompat.job_operations(prog.Job):
            if not op.Active or not len(op.Path.Commands):
                continue
            moves = []
            for kind, x, y, z in _path_moves(op):
                u = x * frame["u"][0] + y * frame["u"][1] + z * frame["u"][2]
                v = x * frame["v"][0] + y * frame["v"][1] + z * frame["v"][2]
                moves.append([kind, u, v, 0.0])
            toolpaths.append({"tool": "{} ({})".format(op.Operation.replace("_", " "), op.Tool), "moves": moves})
        setups.append({"name": name, "edges": toolpath_picture.part_edges_in_frame(placed, frame),
                       "toolpaths": toolpaths})
    path = toolpath_picture.draw(setups, os.path.join(out, "toolpaths.png"),
                                 title="Tool tip paths over the part (the tool axis is on every move, not drawn)",
                                 panel_title="{}")
    shots.append(("The toolpaths over the part", path))
    return shots


__all__ = ["run", "RunError"]
