"""The impeller run, headless: a generated impeller programmed in FreeCAD, with its report.

    generate -> Program impeller (recognition nodes, blank, Job, 5-axis toolpaths, post)
    -> save -> re-read check of the Job's program -> pictures -> report

run() writes into one output folder:
  impeller.FCStd            the document: part, impeller features, blank, Job, program object
  IMPELLER.mpf              the posted Sinumerik 840D program (TRAORI), next to the document
  IMPELLER.apt              the Job's program as APT, the form the re-read check reads
  impeller.step, truth.json the generated part and the generator's truth
  report.html               dimensions against the truth, route, tools, cutting data, checks
  features.png, toolpaths.png   the part coloured by feature; the toolpaths over the part
  impeller.json             the data behind the report
  kb.sqlite, freecad.log    the knowledge base used; what FreeCAD printed meanwhile
A second run replaces the outputs of the first (the files listed in .aeronc-outputs).
"""
import json
import os

from aeronc.main_job import MANIFEST, MainJobError, _freecad_output_to, _remove_previous, _save_document, _Stages

# The test part: 9 main and 9 splitter blades (testparts::ImpellerSpec defaults).
DEFAULT_SPEC = {}
LIMIT_GOUGE_MM = 0.01
DIMENSION_KEYS = ("boreDiameter", "boreDepth", "filletRadius", "bladeHeight", "minChannelWidth")


def run(out, spec=None, allowance=2.0, stations=24, channels=0, say=None):
    """Program a generated impeller and write the run into out; returns the report's data.
    Raises MainJobError naming the stage that failed."""
    import FreeCAD

    out = os.path.abspath(out)
    os.makedirs(out, exist_ok=True)
    _remove_previous(out)
    log_path = os.path.join(out, "freecad.log")
    if os.path.exists(log_path):
        os.unlink(log_path)
    spec = dict(DEFAULT_SPEC if spec is None else spec)
    with _freecad_output_to(log_path) as terminal:
        say = say or (lambda line: print(line, file=terminal, flush=True))
        say("AeroNC impeller run: spec {} -> {}".format(json.dumps(spec) if spec else "2 x 9 blades (default)", out))
        st = _Stages(say)
        opened = []
        try:
            data = _stages(st, opened, out, spec, allowance, stations, channels)
        finally:
            for doc in opened:
                FreeCAD.closeDocument(doc.Name)
        total = sum(t for _, t in st.times)
        say("  {:>6.1f} s  total".format(total))
    return data


def _stages(st, opened, out, spec, allowance, stations, channels):
    import FreeCAD

    from aeronc import impeller, impeller_program, impeller_report, pathcompat
    from aeronc.post.output import write_atomically

    written = ["freecad.log"]
    data = {"spec": spec, "allowance": allowance, "stations": stations, "channels": channels, "pictures": []}
    kb_path = os.path.join(out, "kb.sqlite")
    with st.stage("generate"):
        shape, truth = impeller.make_test_impeller(spec)
        doc = FreeCAD.newDocument("impeller")
        opened.append(doc)
        doc.UndoMode = 1
        part = doc.addObject("Part::Feature", "Impeller")
        part.Shape = shape
        doc.recompute()
        shape.exportStep(os.path.join(out, "impeller.step"))
        write_atomically(os.path.join(out, "truth.json"), json.dumps(truth, indent=1))
        written += ["impeller.step", "truth.json"]
    data["truth"] = truth
    data["faces"] = len(shape.Faces)
    st.report("{} faces, {} + {} blades".format(len(shape.Faces), truth["bladeCount"],
                                                  sum(1 for b in truth["blades"] if b["splitter"])))

    with st.stage("program impeller"):
        prog = impeller_program.create(doc, part, allowance=allowance, kb_path=kb_path, stations=stations,
                                       channels=channels, out_dir=out)
    timings = json.loads(prog.Timings or "{}")
    data["seconds"] = timings
    st.report("recognise {:.1f} s, toolpaths {:.1f} s, cutting data {:.1f} s, post {:.1f} s; {} lines".format(
        timings.get("recognise", 0), timings.get("toolpaths", 0), timings.get("cutting", 0), timings.get("post", 0),
        prog.ProgramLines))
    written += ["IMPELLER.mpf", "kb.sqlite"]

    with st.stage("save"):
        _save_document(doc, os.path.join(out, "impeller.FCStd"))
        impeller_program.write_program(prog)
    written.append("impeller.FCStd")
    st.report("impeller.FCStd")

    with st.stage("re-read check"):
        from aeronc.post import apt
        apt_text = apt.export([prog.Job], os.path.join(out, "IMPELLER.apt"), "--program-name IMPELLER")
        written.append("IMPELLER.apt")
        again = impeller_program.check_posted(prog)
    data["recheck"] = again
    st.report("{} positions, deepest gouge {:.5f} mm, {} holder collisions".format(
        again["positions"], again["maxGougeMm"], again["holderCollisions"]))
    del apt_text

    data.update(_program_data(prog, pathcompat))
    with st.stage("pictures"):
        data["pictures"] = _pictures(out, part, prog, pathcompat)
        written += [os.path.basename(p) for _, p in data["pictures"]]
    st.report(", ".join(os.path.basename(p) for _, p in data["pictures"]))

    data["stages"] = list(st.times)
    write_atomically(os.path.join(out, "impeller.json"), json.dumps(data, indent=1, default=str))
    written.append("impeller.json")
    impeller_report.write(os.path.join(out, "report.html"), data)
    written.append("report.html")
    write_atomically(os.path.join(out, MANIFEST), "\n".join(written) + "\n")
    return data


def _program_data(prog, pathcompat):
    """What the report shows of the program object, its features and its Job."""
    from aeronc import impeller_program
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
    library = impeller_program.tool_library(prog.KnowledgeBase or None)
    used = []
    for s in impeller_program.steps_of(prog):
        tool = s.get("tool")
        if tool and tool["id"] not in [t["id"] for t in used]:
            used.append(dict(library.get(tool["id"], tool), reason=s.get("toolReason", ""),
                             steps=[x["position"] for x in impeller_program.steps_of(prog)
                                    if (x.get("tool") or {}).get("id") == tool["id"]]))
    return {
        "result": {k: v for k, v in result.items() if k != "faceRoles"},
        "route": impeller_program.route_of(prog),
        "edits": impeller_program.edits_of(prog),
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
    from aeronc import impeller, picture, toolpath_picture
    from aeronc.objects.impeller_features import result_of
    result = result_of(prog.Features)
    roles = result.get("faceRoles") or impeller.face_role_names(result)
    shots = []
    path = picture.render(part.Shape, {"faceRoles": roles}, os.path.join(out, "features.png"),
                          title="{}: impeller features by role".format(part.Label),
                          views=(("from above", 40, -60), ("from the side", 8, -60)))
    shots.append(("The part coloured by feature", path))
    top = {"u": (1.0, 0.0, 0.0), "v": (0.0, 1.0, 0.0), "w": (0.0, 0.0, 1.0)}
    side = {"u": (1.0, 0.0, 0.0), "v": (0.0, 0.0, 1.0), "w": (0.0, -1.0, 0.0)}
    setups = []
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
        setups.append({"name": name, "edges": toolpath_picture.part_edges_in_frame(part.Shape, frame),
                       "toolpaths": toolpaths})
    path = toolpath_picture.draw(setups, os.path.join(out, "toolpaths.png"),
                                 title="Tool tip paths over the part (the tool axis is on every move, not drawn)",
                                 panel_title="{}")
    shots.append(("The toolpaths over the part", path))
    return shots


__all__ = ["run", "MainJobError"]
