"""The main job, headless: from a STEP part to posted, verified programs and a report.

    read part -> recognise -> choose the machine -> select tools -> machining chain (Jobs,
    ToolControllers at the optimiser's cutting data, operations) -> post -> re-read and
    simulate -> pictures -> save and report

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
import re

from aeronc.pipeline.setup_job import part_zero  # noqa: F401  (the main job's part zero, also for its callers)
from aeronc.runs.stages import Run, RunError

MainJobError = RunError  # the main job's failures name the stage (runs.stages)
AUTO_MACHINE = "auto"    # the machine argument that lets the main job choose


class MainJob:
    """The main job's run context: its settings, then what each stage adds."""

    def __init__(self, run, part_path, material, machine, family, cell_size):
        self.run = run
        self.part_path, self.material, self.family = part_path, material, family
        # The machine the user named, or None: the smallest that holds every setup (choose_machine).
        self.named = machine if machine and machine != AUTO_MACHINE else None
        self.machine = self.named
        self.candidates = []   # pipeline.machine_choice.candidates, smallest first
        self.cell_size = cell_size
        self.name = os.path.splitext(os.path.basename(part_path))[0]
        self.kb_path = run.path("knowledge.sqlite")
        self.data = {"part": self.name, "source": os.path.abspath(part_path), "pictures": []}
        self.doc = self.part = self.group = self.result = None
        self.chain_obj, self.chain, self.ops_by_label, self.programs, self.report = None, None, {}, [], None
        self.left_out = {}     # label -> why, in the order they were left out (pipeline.gate)
        self.left_kind = {}    # label -> "no toolpath", "gouge", "rapid" or "dependent"
        self.no_program = []   # the setups every operation of which is left out
        self.simulated = 0     # operations in the last simulation
        self.work = None       # a private folder for the programs the verification re-reads
        self.reread = {}       # what the verification read of each program, kept across the gate's rounds
        self.regrown = {}      # label -> how the gate re-made a gouging roughing (pipeline.gate.regrow)
        self.checked = {}      # label -> {"radial", "axial"}: the allowances its simulation checks it against


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


def choose_machine(job):
    """The machine named, or the smallest of the knowledge base's whose travel holds the blank in
    every setup (pipeline.machine_choice); the post stage checks it again against the toolpaths."""
    from aeronc.pipeline import knowledge_base, machine_choice, setup_job
    from aeronc.errors import from_core
    kb = knowledge_base.open_kb(job.kb_path)
    with from_core(machine_choice.MachineChoiceError, "the knowledge base's machines"):
        job.candidates = machine_choice.candidates(kb)
    needs = machine_choice.need_of_blank(setup_job.blank_box(job.group), job.result["setups"])
    choice = machine_choice.choose(job.candidates, needs, named=job.named)
    job.machine = choice["name"]
    job.data["machine"] = {"name": choice["name"], "why": choice["why"], "rejected": choice["rejected"],
                           "named": bool(job.named)}
    return "{}: {}".format(choice["name"], choice["why"])


def check_machine_travel(job):
    """Every setup's toolpaths, with the part zero of the setup, against the chosen machine's
    travel: a larger machine when they leave it (the tools' speeds and feeds, chosen for the
    smaller one, are within its limits), or the named machine's error."""
    from aeronc import pathcompat
    from aeronc.pipeline import machine_choice, setup_job
    from aeronc.post import machines
    if not job.candidates:
        return
    blank = setup_job.blank_box(job.group)
    setups = []
    for fc_job in job.chain_obj.Jobs:
        setup = _setup_of(job.chain, fc_job, setup_job.SETUP_TAG)
        ops = [op for op in _operations_of(fc_job) if pathcompat.op_active(op) and op.Label not in job.left_out]
        setups.append({"name": setup["name"], "operations": ops, "partZero": part_zero(blank, setup["frame"]),
                       "frame": setup["frame"], "job": fc_job})
    needs = machine_choice.need_of_paths(setups)
    choice = machine_choice.choose(job.candidates, needs, named=job.named, at_least=job.machine)
    if choice["name"] == job.machine:
        return
    was = job.machine
    job.machine = choice["name"]
    before = job.data.get("machine") or {}
    rejected = (before.get("rejected") or []) + choice["rejected"]
    job.data["machine"] = {"name": choice["name"], "rejected": rejected, "named": False,
                           "why": "the smallest machine whose travel holds every setup's toolpaths ({})".format(
                               "; ".join("{}: {}".format(r["name"], r["text"]) for r in rejected))}
    job.run.say("  machine: {} instead of {}: {}".format(job.machine, was, choice["rejected"][0]["text"]
                                                         if choice["rejected"] else ""))
    for s in setups:  # the Jobs post for it from FreeCAD too
        pathcompat.set_job_post(s["job"], machines.post_of(job.machine),
                                setup_job.post_arguments(job.machine, blank, s["frame"]))


def select_tools(job):
    from aeronc.pipeline import tool_planning
    plan = tool_planning.select_tools(job.group, job.material, job.machine, job.kb_path)
    crib = " (the crib of {})".format(os.path.basename(job.data["crib"])) if job.data.get("crib") else ""
    return "{} tools and cutting operations planned{}; roughing tool changes {} -> {}".format(
        len(plan.get("toolSettings", [])), crib, plan["toolChanges"]["before"], plan["toolChanges"]["after"])


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
    left = chain.get("remainders", [])
    return "{} units, {} elements not machined{}, rules {}; rapid travel -{:.0f} %; {}".format(
        len(chain.get("units", [])), chain_report.unmachined_text(chain),
        " ({} machined with corners or fillets no tool reaches)".format(len({r["element"] for r in left}))
        if left else "",
        "all pass" if not failed else "{} FAIL".format(len(failed)), float(travel.get("savedPercent") or 0),
        _optimised_text(job.chain_obj))


def _optimised_text(chain_obj):
    """How many of the Jobs' ToolControllers carry the optimiser's cutting data."""
    from aeronc import pathcompat
    from aeronc.pipeline.cutting_optimisation import RESULT_PROPERTY
    tcs = [tc for fc_job in chain_obj.Jobs for tc in pathcompat.tool_controllers(fc_job)]
    done = sum(1 for tc in tcs if RESULT_PROPERTY in tc.PropertiesList)
    return "cutting data optimised for {} of {} ToolControllers".format(done, len(tcs))


def post(job):
    """Each setup's programs, posted but not yet delivered (verify delivers them). An operation
    the toolpath core refused has no toolpath: it and what depends on it are left out."""
    from aeronc.pipeline import gate
    ops = _active_operations(job)
    _leave_out(job, gate.not_ready(ops), "no toolpath")
    _leave_out(job, gate.dependents(ops, job.left_out, job.result), "dependent")
    check_machine_travel(job)
    _post_programs(job)
    return ", ".join(os.path.basename(p["path"]) for p in job.programs) + (
        "; {} operation(s) without a toolpath left out".format(len(job.left_out)) if job.left_out else "")


def verify(job):
    """Simulate the posted programs; leave out every operation that gouges the part or rapids
    through material (and what depends on it), post again and simulate again until nothing
    fails; then deliver the programs and judge them against the part."""
    from aeronc.pipeline import gate, verification
    first = report = _simulate(job)
    while report is not None:
        failing = {k: v for k, v in verification.failing_operations(report).items() if k not in job.left_out}
        grown = gate.grown(first, report, job.left_out) if report is not first else {}
        if not failing and not grown:
            break
        regrown = _regrow(job, failing, report)
        _leave_out(job, {k: v + ("; " + job.regrown[k]["note"] if k in job.regrown else "")
                         for k, v in failing.items() if k not in regrown},
                   {op["label"]: "gouge" if int(op.get("gouges", 0)) else "rapid" for op in report.get("ops", [])})
        _leave_out(job, grown, "dependent")
        _leave_out(job, gate.dependents(_active_operations(job), job.left_out, job.result), "dependent")
        _post_programs(job)
        report = _simulate(job)
        # Without a roughing short of its floor the operations under it cut what they cut before
        # it was planned: their loads are measured afresh, not as grown.
        if failing and not grown and all(gate.short_of_floor(job.ops_by_label[k][1]) for k in failing
                                          if k in job.ops_by_label):
            first = report
        elif regrown and report is not None:
            # A roughing re-made leaves a thicker layer: what the operations after it remove is
            # measured from there.
            after = gate.dependents(_active_operations(job), regrown, job.result)
            first = gate.rebased(first, report, set(regrown) | set(after))
    job.report = report or {}
    for op in _active_operations(job):
        if op.Label not in job.left_out and report is not None:
            gate.passed(op, job.regrown[op.Label]["note"] if op.Label in job.regrown else "")
    job.data["regrown"] = [dict(r, label=label) for label, r in job.regrown.items() if label not in job.left_out]
    job.data["leftOut"] = [{"label": label, "setup": job.ops_by_label[label][0].Label if label in job.ops_by_label
                            else "", "kind": job.left_kind[label], "reason": why}
                           for label, why in job.left_out.items()]
    job.data["materialLeft"] = verification.material_left(job.report, job.chain, job.result) if report else []
    job.data["verificationReport"] = {k: {"count": int((job.report.get(k) or {}).get("count", 0)),
                                          "worst": float(((job.report.get(k) or {}).get("worst") or {}).get("depth", 0))}
                                      for k in ("gouges", "collisions")}
    job.data["verification"], job.data["coverage"] = _checks_of(job.report, job.simulated, job.data)
    _deliver(job)
    job.data["verdict"] = verdict_of(job.data)
    return job.data["verdict"]["text"]


def _regrow(job, failing, report):
    """Re-make, once each, the failing roughing operations that gouge (and rapid through nothing)
    with grown allowances (pipeline.gate.regrow); returns the labels re-made now. Each is then
    checked against the allowances it was planned with (job.checked)."""
    from aeronc.pipeline import gate
    out = []
    for op in report.get("ops", []):
        label = op["label"]
        if label not in failing or label in job.regrown or label not in job.ops_by_label:
            continue
        if not int(op.get("gouges", 0)) or int(op.get("collisions", 0)):
            continue
        fc_op = job.ops_by_label[label][1]
        depth = float(op.get("worstGouge", 0))
        planned = gate.regrow(fc_op, depth)
        if planned is None:
            continue
        job.checked[label] = planned
        job.regrown[label] = {"planned": planned, "gouge": depth,
                              "radial": float(fc_op.RadialAllowance.Value), "axial": float(fc_op.AxialAllowance.Value),
                              "note": gate.regrown_note(fc_op, planned, depth)}
        out.append(label)
    return out


def _active_operations(job):
    from aeronc import pathcompat
    return [op for fc_job in job.chain_obj.Jobs for op in _operations_of(fc_job) if pathcompat.op_active(op)]


def _leave_out(job, why_by_label, kind):
    """Leave operations out: {label: why}; kind: "no toolpath", "gouge", "rapid" or "dependent"
    (or {label: kind}); a roughing short of its element's floor is of its own kind whatever the
    reason."""
    from aeronc.pipeline import gate
    for label, why in why_by_label.items():
        if label in job.left_out:
            continue
        job.left_out[label] = why
        job.left_kind[label] = kind.get(label, "dependent") if isinstance(kind, dict) else kind
        if label in job.ops_by_label and gate.short_of_floor(job.ops_by_label[label][1]):
            job.left_kind[label] = SHORT_OF_FLOOR
        if label in job.ops_by_label and job.left_kind[label] != "no toolpath":  # that one keeps its own mark
            gate.fail(job.ops_by_label[label][1], why)


def _post_programs(job):
    """Post every setup in both dialects, into job.programs (text in memory; the LinuxCNC one
    also in the work folder for the re-reading). The operations that are not ready are left out
    with a comment (--skip-failed); a setup left with no operation gets no program."""
    from aeronc import pathcompat
    from aeronc.pipeline import setup_job
    from aeronc.post import nc_post
    blank = setup_job.blank_box(job.group)
    job.programs, job.no_program = [], []
    for k, fc_job in enumerate(job.chain_obj.Jobs, start=1):
        setup = _setup_of(job.chain, fc_job, setup_job.SETUP_TAG)
        labels = [op.Label for op in _operations_of(fc_job) if pathcompat.op_active(op)]
        left = [label for label in labels if label in job.left_out]
        stem = "{}_setup{}".format(job.name, k)
        if len(left) == len(labels):
            job.no_program.append({"setup": setup["name"], "stem": stem, "leftOut": left})
            continue
        objects = pathcompat.job_post_objects(fc_job)
        zero = part_zero(blank, setup["frame"])
        for ext, dialect, label, args in (("mpf", "840d", "Sinumerik 840D", "--line-numbers"),
                                           ("ngc", "linuxcnc", "LinuxCNC", "")):
            # The program name as the file name gives it: the same program whatever the gate does.
            options = "{} --program-name {} --skip-failed {}".format(
                setup_job.post_arguments(job.machine, blank, setup["frame"]), stem, args).strip()
            text = nc_post.export(objects, "-", options, dialect)
            job.programs.append({"setup": setup["name"], "dialect": label, "path": job.run.path(stem + "." + ext),
                                 "text": text, "partZero": zero, "lines": text.count("\n"), "job": fc_job,
                                 "frame": setup["frame"], "leftOut": left, "operations": len(labels) - len(left)})
            if ext == "ngc":
                job.programs[-1]["reread"] = os.path.join(job.work, stem + ".ngc")
                with open(job.programs[-1]["reread"], "w", encoding="utf-8") as f:
                    f.write(text)


def _simulate(job):
    """The verification's report of the programs as posted now, or None when there is none."""
    from aeronc.pipeline import setup_job, verification
    programs = [dict(p, path=p["reread"]) for p in job.programs if "reread" in p]
    if not programs:
        job.simulated = 0
        return None
    report, job.simulated = verification.verify_programs(
        programs, job.ops_by_label, job.machine, job.chain, job.result, job.part.Shape,
        setup_job.blank_box(job.group), job.cell_size, cache=job.reread, checked=job.checked)
    return report


def _deliver(job):
    """Write the verified programs under their names (each complete or not at all). Should the
    last simulation still find a gouge or a colliding rapid, they are written as
    <stem>.FAILED.<ext> with a first line saying so, never under the name of a program ready to
    run."""
    from aeronc.post.output import write_atomically
    unsafe = _unsafe(job.report)
    for p in job.programs:
        text = p["text"]
        if unsafe:
            stem, ext = os.path.splitext(p["path"])
            p["path"] = stem + ".FAILED" + ext
            line = "FAILED VERIFICATION, DO NOT RUN: {}".format(unsafe)
            text = ("; {}\n" if ext == ".mpf" else "({})\n").format(line.replace("(", "[").replace(")", "]")) + text
        write_atomically(p["path"], text)
        job.run.wrote(os.path.basename(p["path"]))
    job.data["programs"] = [{k: v for k, v in p.items() if k not in ("job", "frame", "text", "reread")}
                            for p in job.programs]
    job.data["noProgram"] = job.no_program
    job.data["unsafe"] = unsafe


def _unsafe(report):
    gouges = int((report.get("gouges") or {}).get("count", 0))
    collisions = int((report.get("collisions") or {}).get("count", 0))
    if not gouges and not collisions:
        return None
    return "{} gouging move(s), {} rapid(s) through material".format(gouges, collisions)


# The kind of a left-out roughing that stops short of its element's floor.
SHORT_OF_FLOOR = "short of floor"
LEFT_OUT_KINDS = {"gouge": ("gouges the part", "gouge the part"),
                  "rapid": ("rapids through material", "rapid through material"),
                  "no toolpath": ("has no toolpath", "have no toolpath"),
                  "dependent": ("depends on those", "depend on those"),
                  SHORT_OF_FLOOR: ("is a roughing short of its floor", "are roughings short of their floors")}


def verdict_of(data):
    """The one line that says whether the programs are ready: READY, INCOMPLETE (safe, but
    material stands where the part has none), NOT READY (operations left out, or unsafe) or
    NO PROGRAM. {"ready", "status", "text"}. A roughing short of its element's floor (an element
    deeper than every end mill reaches, listed as not machined anyway) left out alone leaves the
    programs incomplete, not unready: nothing else was planned on it."""
    from aeronc.pipeline import verification
    left_out = data.get("leftOut") or []
    blocking = [e for e in left_out if e.get("kind") != SHORT_OF_FLOOR]
    incomplete = verification.incomplete_text(data.get("materialLeft") or [])
    delivered = [p for p in data.get("programs") or []]
    parts = []
    if data.get("unsafe"):
        parts.append("the programs still gouge or rapid through material ({}): written as .FAILED".format(
            data["unsafe"]))
    if left_out:
        kinds = {}
        for e in left_out:
            kinds[e.get("kind")] = kinds.get(e.get("kind"), 0) + 1
        parts.append("{} operation{} left out of the programs ({}): {}".format(
            len(left_out), "" if len(left_out) == 1 else "s",
            ", ".join("{} {}".format(n, LEFT_OUT_KINDS.get(k, (k, k))[0 if n == 1 else 1]) for k, n in kinds.items()),
            ", ".join(e["label"] for e in left_out[:6]) + (" ..." if len(left_out) > 6 else "")))
    if incomplete:
        parts.append(incomplete)
    if not delivered:
        status = "NO PROGRAM"
        parts.insert(0, "no operation of {} can be posted safely".format(data.get("part", "the part")))
    elif data.get("unsafe") or blocking:
        status = "NOT READY"
    elif incomplete or left_out:
        status = "INCOMPLETE"
        parts = ([incomplete[len("incomplete: "):]] if incomplete else []) + parts[:1 if left_out else 0] + [
            "the programs neither gouge nor rapid through material"]
    else:
        status = "READY"
        parts.append("no gouge, no rapid through material, every face of the part within tolerance")
    return {"ready": status == "READY", "status": status, "text": "{}: {}".format(status, "; ".join(parts))}


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
        from aeronc.pipeline import verification
        seen = "setup {}".format(report["leftoverSetup"]) if report.get("leftoverSetup") else "+Z"
        incomplete = verification.incomplete_text(job.data.get("materialLeft") or [])
        pics.append(("Material left after simulating the delivered programs (seen from {}): {}".format(
                        seen, incomplete or "every face of the part within tolerance"),
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


STAGES = (("read part", read_part), ("recognise", recognise), ("machine", choose_machine),
          ("select tools", select_tools),
          ("machining chain", machining_chain), ("post", post),
          ("verify", verify), ("pictures", pictures), ("save", save))


def run(part_path, out, material="7050-T7451", machine=None, family="integral_panel", cell_size=0.5,
        say=None, pictures=True, crib=None):
    """Run the main job on a STEP (or BREP) part; returns the report's data (dict), whose
    "verdict" says whether the programs are ready. Raises RunError (MainJobError) naming the
    stage that failed, or saying that no program could be delivered; report.html and run.json
    are written in either case, and no program is left that the gate did not pass.
    machine: a machine of the knowledge base, or None (or "auto") for the smallest whose travel
    holds every setup; report.html and run.json name it and say why. say(line) receives the progress lines; by default they go to the terminal while FreeCAD's
    own output goes to freecad.log. pictures=False skips the pictures (a corpus run's time).
    crib: the user's own tool crib in place of the shipped one, a knowledge-base file or a FreeCAD
    tool library (.fctl; knowledge_base.use_crib); the run works on a copy in its folder."""
    import shutil
    import tempfile
    run_ = Run(out, say)
    job = MainJob(run_, part_path, material, machine, family, cell_size)
    if os.path.exists(job.kb_path):  # left by a failed run: this run starts from the shipped knowledge base
        os.unlink(job.kb_path)
    if crib:
        from aeronc.pipeline import knowledge_base
        knowledge_base.use_crib(job.kb_path, crib)
        job.data["crib"] = os.path.abspath(crib)
    (say or print)("AeroNC main job: {} ({} on {}, {}) -> {}".format(
        part_path, material, job.named or "the smallest machine that holds it", family, run_.out))
    job.work = tempfile.mkdtemp(prefix="aeronc_main_job_")
    try:
        with run_.console():
            try:
                for name, stage in STAGES:
                    if name == "pictures" and not pictures:
                        continue
                    with run_.stage(name):
                        text = stage(job)
                    run_.report(text)
            except RunError as e:
                job.data["failed"] = {"stage": str(e).split(":", 1)[0], "error": str(e)}
                job.data["verdict"] = {"ready": False, "status": "FAILED",
                                       "text": "FAILED at {}: no program".format(e)}
                _write_reports(job)
                run_.say("  FAILED: {}; report: {}".format(e, run_.path("report.html")))
                raise
            _write_reports(job)
            run_.say("  {:>6.1f} s  total; report: {}".format(run_.total(), run_.path("report.html")))
            run_.say("  " + job.data["verdict"]["text"])
    finally:
        shutil.rmtree(job.work, ignore_errors=True)
    if not job.data.get("programs"):
        raise RunError(job.data["verdict"]["text"])
    return job.data


def _write_reports(job):
    """report.html and run.json (the figures of the run, for the corpus table), then the list
    of what the run wrote."""
    from aeronc.reports import chain_report
    job.data["stages"] = list(job.run.times)
    chain_report.write(job.run.path("report.html"), job.data)
    job.run.wrote("report.html")
    job.run.write("run.json", json.dumps(run_summary(job.data), indent=1))
    job.run.finish()


def _element_of_label(label):
    """"15" for an operation label such as "Pocket E15 r U0", or None."""
    m = re.search(r"\bE(\d+)\b", label or "")
    return m.group(1) if m else None


def run_summary(data):
    """The run's figures in one small dict: what was recognised and machined, what is left
    against the part, what the gate left out, the simulation of the delivered programs, the
    stage times, and whether a program was delivered (or the stage that failed)."""
    recognition = data.get("recognition") or {}
    chain = data.get("chain") or {}
    report_ops = data.get("verificationReport") or {}
    not_machined = {}
    for gap in chain.get("unmachined", []):
        not_machined.setdefault(str(gap.get("element")), gap.get("reason", ""))
    # An element one of whose operations the gate left out is not machined either.
    for op in data.get("leftOut") or []:
        element = _element_of_label(op.get("label", ""))
        if element is not None:
            not_machined.setdefault(element, "{} left out of the programs: {}".format(
                op.get("label"), op.get("reason", "")))
    left = data.get("materialLeft") or []
    areas = [e["area"] for e in left if e.get("area") is not None]
    thick = [e["maxLeft"] for e in left if e.get("maxLeft") is not None]
    return {"part": data.get("part"), "source": data.get("source"), "crib": data.get("crib"),
            "machine": {k: v for k, v in (data.get("machine") or {}).items() if k in ("name", "why")},
            "verdict": data.get("verdict"), "failed": data.get("failed"),
            "elements": len(recognition.get("elements", [])),
            "notMachined": not_machined,
            "unclaimedFaces": len(recognition.get("unclaimedFaces", [])),
            "units": len(chain.get("units", [])),
            "leftOut": data.get("leftOut") or [],
            "programs": [os.path.basename(p["path"]) for p in data.get("programs") or []],
            "noProgram": data.get("noProgram") or [],
            "regrown": [{k: r.get(k) for k in ("label", "gouge", "planned", "radial", "axial")}
                        for r in data.get("regrown") or []],
            "gouges": report_ops.get("gouges"), "collisions": report_ops.get("collisions"),
            "materialLeft": {"entries": len(left), "area": sum(areas) if areas else 0.0,
                             "maxLeft": max(thick) if thick else 0.0},
            "stages": data.get("stages") or []}


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


def _checks_of(report, op_count, data=None):
    """The report's verification rows and per-element coverage rows."""
    data = data or {}
    gouges = report.get("gouges", {})
    collisions = report.get("collisions", {})
    coverage = report.get("coverage", {})
    rows = []
    left_out = data.get("leftOut") or []
    if left_out:
        rows.append({"check": "operations left out", "node": "all setups", "ok": False,
                     "detail": "; ".join("{}: {}".format(e["label"], e["reason"]) for e in left_out[:12]) +
                     (" ..." if len(left_out) > 12 else "")})
    rows += [{"check": "gouge", "node": "delivered programs", "ok": int(gouges.get("count", 0)) == 0,
              "detail": _worst_text(gouges, "every cutting move of {} operations within its allowance".format(op_count))},
             {"check": "collision of rapids", "node": "delivered programs", "ok": int(collisions.get("count", 0)) == 0,
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
    from aeronc.pipeline import verification
    incomplete = verification.incomplete_text(data.get("materialLeft") or [])
    rows.append({"check": "coverage against the part", "node": "every face inside the blank", "ok": not incomplete,
                 "detail": incomplete or "every face of the part within tolerance"})
    return rows, per_element


def _worst_text(section, clean):
    if int(section.get("count", 0)) == 0:
        return clean
    w = section.get("worst") or {}
    return "{} move(s); worst {:.3f} mm ({}) in {} move {} at {}".format(
        section.get("count"), float(w.get("depth", 0)), w.get("kind", ""), w.get("op", ""), w.get("move", ""),
        w.get("position", ""))
