"""The main job, headless: from a STEP part to posted, verified programs and a report.

    read part -> recognise -> select tools -> optimise cutting data -> machining chain -> Jobs
    -> post -> re-read and simulate -> pictures -> save and report

Each stage is a function of the one context, MainJob, that carries what the stages before it
made; runs.stages times and reports them. run() writes into one output folder:
  <part>.FCStd                     the document (features tree, chain, one Job per setup)
  <part>_setup<k>.mpf / .ngc       each setup's program, Sinumerik 840D and LinuxCNC
  report.html                      the chain, times, checks and pictures for the programmer
  features.png, toolpaths.png, leftover.png   the pictures the report shows (leftover_<k>.png:
                                   each other setup that leaves a finished face unreached)
  recognition.json, chain.json, verification.json, knowledge.sqlite   the data behind it
  freecad.log                      what FreeCAD itself printed while the job ran
A second run replaces the outputs of the first (the files it listed in .aeronc-outputs).
"""
import json
import os

from aeronc.pipeline.setup_job import part_zero  # noqa: F401  (the main job's part zero, also for its callers)
from aeronc.runs.stages import Run, RunError

MainJobError = RunError  # the main job's failures name the stage (runs.stages)


class MainJob:
    """The main job's run context: its settings, then what each stage adds."""

    def __init__(self, run, part_path, material, machine, family, cell_size):
        self.run = run
        self.part_path, self.material, self.machine, self.family = part_path, material, machine, family
        self.cell_size = cell_size
        self.name = os.path.splitext(os.path.basename(part_path))[0]
        self.kb_path = run.path("knowledge.sqlite")
        self.data = {"part": self.name, "source": os.path.abspath(part_path), "pictures": []}
        self.doc = self.part = self.group = self.result = None
        self.chain_obj, self.chain, self.ops_by_label, self.programs, self.report = None, None, {}, [], None


def _counts(result):
    by_setup = {}
    for e in result["elements"]:
        by_setup[e["setup"]] = by_setup.get(e["setup"], 0) + 1
    return ", ".join("{} {}".format(s["name"], by_setup.get(s["id"], 0)) for s in result["setups"])


def read_part(job):
    import Part
    try:
        shape = Part.read(job.part_path)
    except Exception as e:  # FreeCAD raises its own types for unreadable files
        raise RunError("{}: {}".format(job.part_path, e)) from None
    job.doc = job.run.new_document(job.name.replace("-", "_").replace(".", "_") or "Part")
    job.part = job.doc.addObject("Part::Feature", "Part")
    job.part.Label = job.name
    job.part.Shape = shape
    job.doc.recompute()
    return "{} faces".format(len(shape.Faces))


def recognise(job):
    from aeronc.makers import create_machining_features
    from aeronc.objects import result_of
    from aeronc.pipeline import setup_job
    # The blank the Jobs' stock and the verification use, stated to recognition too: on a
    # tilted setup its corner stands above the part, and the elements open to it start there.
    job.group = create_machining_features(job.doc, job.part, blank=setup_job.part_box(job.part.Shape))
    job.result = result = result_of(job.group)
    if not result["elements"]:
        raise RunError("{} has no domain element to machine".format(job.name))
    job.data["recognition"] = result
    return "{} elements in {} setup(s): {}".format(len(result["elements"]), len(result["setups"]), _counts(result))


def select_tools(job):
    from aeronc.pipeline import tool_planning
    plan, _, tcs = tool_planning.select_tools(job.group, job.material, job.machine, job.kb_path)
    return "{} ToolControllers; roughing tool changes {} -> {}".format(
        len(tcs), plan["toolChanges"]["before"], plan["toolChanges"]["after"])


def cutting_data(job):
    from aeronc import pathcompat
    from aeronc.pipeline import cutting_optimisation
    jobs = pathcompat.jobs_of_part(job.doc, job.part)
    proposals = cutting_optimisation.propose(jobs[0], kb_path=job.kb_path) if jobs else []
    applied = cutting_optimisation.apply(proposals) if proposals else []
    return "{} of {} ToolControllers optimised".format(len(applied), len(proposals))


def machining_chain(job):
    from aeronc.pipeline import chain_building
    from aeronc.reports import chain_report
    job.chain_obj = chain_building.build(job.group, job.family, job.material, job.machine, job.kb_path)
    job.chain = chain = json.loads(job.chain_obj.Chain)
    travel = chain.get("travel") or {}
    failed = chain_building.failed_checks(chain)
    job.data["chain"] = chain
    operations = []
    for fc_job in job.chain_obj.Jobs:
        for op in _operations_of(fc_job):
            job.ops_by_label[op.Label] = (fc_job, op)
            seconds = _clock_seconds(op.CycleTime)
            operations.append({"unit": op.UnitId, "setup": op.SetupId, "label": op.Label,
                               "cutLength": op.CutLength.Value,
                               "minutes": seconds / 60.0 if seconds is not None else None})
    job.data["operations"] = operations
    return "{} units, {} elements not machined, rules {}; rapid travel -{:.0f} %".format(
        len(chain.get("units", [])), chain_report.unmachined_text(chain),
        "all pass" if not failed else "{} FAIL".format(len(failed)), float(travel.get("savedPercent") or 0))


def post(job):
    from aeronc import pathcompat
    from aeronc.pipeline import setup_job
    from aeronc.post import nc_post
    blank = setup_job.blank_box(job.group)
    for k, fc_job in enumerate(job.chain_obj.Jobs, start=1):
        setup = _setup_of(job.chain, fc_job, setup_job.SETUP_TAG)
        objects = pathcompat.job_post_objects(fc_job)
        stem = "{}_setup{}".format(job.name, k)
        zero = part_zero(blank, setup["frame"])
        for ext, dialect, label, args in (("mpf", "840d", "Sinumerik 840D", "--line-numbers"),
                                           ("ngc", "linuxcnc", "LinuxCNC", "")):
            path = job.run.path(stem + "." + ext)
            options = "{} {}".format(setup_job.post_arguments(job.machine, blank, setup["frame"]), args).strip()
            text = nc_post.export(objects, path, options, dialect)
            job.programs.append({"setup": setup["name"], "dialect": label, "path": path, "partZero": zero,
                                 "lines": text.count("\n"), "job": fc_job, "frame": setup["frame"]})
            job.run.wrote(os.path.basename(path))
    job.data["programs"] = [{k: v for k, v in p.items() if k not in ("job", "frame")} for p in job.programs]
    return ", ".join(os.path.basename(p["path"]) for p in job.programs)


def verify(job):
    from aeronc.pipeline import setup_job, verification
    job.report, simulated = verification.verify_programs(
        [p for p in job.programs if p["path"].endswith(".ngc")], job.ops_by_label, job.machine, job.chain,
        job.result, job.part.Shape, setup_job.blank_box(job.group), job.cell_size)
    job.data["verification"], job.data["coverage"] = _checks_of(job.report, simulated)
    return "; ".join("{} {}".format(v["check"], "pass" if v["ok"] else "FAIL") for v in job.data["verification"])


def pictures(job):
    from aeronc.pipeline import setup_job
    from aeronc.reports import picture, toolpath_picture
    out, name, report = job.run.out, job.name, job.report
    pics = [("Part coloured by feature", picture.render(job.part.Shape, job.result, os.path.join(out, "features.png"),
                                                       title="{}: machining features".format(name)))]
    panels = []
    for fc_job in job.chain_obj.Jobs:
        setup = _setup_of(job.chain, fc_job, setup_job.SETUP_TAG)
        tps = [{"tool": op.Tool, "moves": _path_moves(op)} for op in _operations_of(fc_job)]
        panels.append({"name": setup["name"],
                       "edges": toolpath_picture.part_edges_in_frame(job.part.Shape, setup["frame"]),
                       "toolpaths": tps})
    pics.append(("Toolpaths over the part, per setup",
                 toolpath_picture.draw(panels, os.path.join(out, "toolpaths.png"), "{}: toolpaths by tool".format(name))))
    if report.get("leftover"):
        seen = "setup {}".format(report["leftoverSetup"]) if report.get("leftoverSetup") else "+Z"
        pics.append(("Material left after simulating the posted programs (seen from {})".format(seen),
                     toolpath_picture.draw_leftover(report["leftover"], os.path.join(out, "leftover.png"))))
    for k, (setup_name, leftover) in enumerate(report.get("leftovers") or [], 1):
        pics.append(("Material left in setup {}, which leaves a finished face unreached".format(setup_name),
                     toolpath_picture.draw_leftover(leftover, os.path.join(out, "leftover_{}.png".format(k)),
                                                    title="Setup {}: material left (blue: more than 0.2 mm)"
                                                    .format(setup_name))))
    job.data["pictures"] = pics
    job.run.wrote(*[os.path.basename(p[1]) for p in pics])
    return ", ".join(os.path.basename(p[1]) for p in pics)


def save(job):
    fcstd = job.name + ".FCStd"
    job.run.save_document(job.doc, fcstd)
    for fname, data in (("recognition.json", job.result), ("chain.json", job.chain),
                        ("verification.json",
                         {k: v for k, v in job.report.items() if k not in ("leftover", "leftovers")})):
        job.run.write(fname, json.dumps(data, indent=1))
    job.run.wrote("knowledge.sqlite")
    return fcstd


STAGES = (("read part", read_part), ("recognise", recognise), ("select tools", select_tools),
          ("cutting data", cutting_data), ("machining chain", machining_chain), ("post", post),
          ("verify", verify), ("pictures", pictures), ("save", save))


def run(part_path, out, material="7050-T7451", machine="AC-5AX", family="integral_panel", cell_size=0.5,
        say=None):
    """Run the main job on a STEP (or BREP) part; returns the report's data (dict).
    Raises RunError (MainJobError) naming the stage that failed. say(line) receives the progress
    lines; by default they go to the terminal while FreeCAD's own output goes to freecad.log."""
    from aeronc.reports import chain_report
    run_ = Run(out, say)
    job = MainJob(run_, part_path, material, machine, family, cell_size)
    if os.path.exists(job.kb_path):  # left by a failed run: this run starts from the shipped knowledge base
        os.unlink(job.kb_path)
    (say or print)("AeroNC main job: {} ({} on {}, {}) -> {}".format(part_path, material, machine, family, run_.out))
    with run_.console():
        for name, stage in STAGES:
            with run_.stage(name):
                text = stage(job)
            run_.report(text)
        job.data["stages"] = list(run_.times)
        chain_report.write(run_.path("report.html"), job.data)
        run_.wrote("report.html")
        run_.finish()
        run_.say("  {:>6.1f} s  total; report: {}".format(run_.total(), run_.path("report.html")))
    return job.data


def _operations_of(job):
    """The chain's operations of one Job, in program order."""
    from aeronc import operations, pathcompat
    return [op for op in pathcompat.job_operations(job) if operations.is_machining_operation(op)]


def _clock_seconds(text):
    try:
        h, m, s = (float(x) for x in str(text).split(":"))
        return h * 3600 + m * 60 + s
    except ValueError:
        return None


def _setup_of(chain, job, tag):
    sid = int(getattr(job, tag))
    for s in chain.get("setups", []):
        if int(s["id"]) == sid:
            return s
    raise MainJobError("{}: no setup {} in the chain".format(job.Label, sid))


def _path_moves(op):
    """[kind, x, y, z] of an operation's Path in its Job's frame, for the picture."""
    moves = []
    for c in op.Path.Commands:
        p = c.Parameters
        if c.Name in ("G0", "G00"):
            kind = 0
        elif c.Name in ("G1", "G01", "G2", "G02", "G3", "G03"):
            kind = 1
        elif c.Name in ("G81", "G82", "G83", "G73"):
            kind = 3
        else:
            continue
        last = moves[-1] if moves else [0, 0.0, 0.0, 0.0]
        moves.append([kind, p.get("X", last[1]), p.get("Y", last[2]), p.get("Z", last[3])])
    return moves


def _checks_of(report, op_count):
    """The report's verification rows and per-element coverage rows."""
    gouges = report.get("gouges", {})
    collisions = report.get("collisions", {})
    coverage = report.get("coverage", {})
    rows = [{"check": "gouge", "node": "all setups", "ok": int(gouges.get("count", 0)) == 0,
             "detail": _worst_text(gouges, "every cutting move of {} operations within its allowance".format(op_count))},
            {"check": "collision of rapids", "node": "all setups", "ok": int(collisions.get("count", 0)) == 0,
             "detail": _worst_text(collisions, "rapids clear of the material")}]
    per_element = []
    bad = []
    for e in coverage.get("elements", []):
        left = float(e.get("uncoveredArea", 0.0))
        per_element.append({"element": e["id"], "area": float(e.get("area", 0.0)), "leftArea": left,
                            "maxLeft": e.get("maxLeftover")})
        if left > 0:
            bad.append(str(e["id"]))
    rows.append({"check": "coverage of finished floors and walls", "node": "all elements", "ok": not bad,
                 "detail": "every finished face within tolerance" if not bad else
                 "material left on {}".format(", ".join(bad[:12]) + (" ..." if len(bad) > 12 else ""))})
    return rows, per_element


def _worst_text(section, clean):
    if int(section.get("count", 0)) == 0:
        return clean
    w = section.get("worst") or {}
    return "{} move(s); worst {:.3f} mm ({}) in {} move {} at {}".format(
        section.get("count"), float(w.get("depth", 0)), w.get("kind", ""), w.get("op", ""), w.get("move", ""),
        w.get("position", ""))
