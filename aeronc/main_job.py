"""The main job, headless: from a STEP part to posted, verified programs and a report.

    recognise -> select tools -> optimise cutting data -> machining chain -> Jobs -> post
    -> re-read and simulate -> pictures and report

run() writes into one output folder:
  <part>.FCStd                     the document (features tree, chain, one Job per setup)
  <part>_setup<k>.mpf / .ngc       each setup's program, Sinumerik 840D and LinuxCNC
  report.html                      the chain, times, checks and pictures for the programmer
  features.png, toolpaths.png, leftover.png   the pictures the report shows (leftover_<k>.png:
                                   each other setup that leaves a finished face unreached)
  recognition.json, chain.json, verification.json, knowledge.sqlite   the data behind it
  freecad.log                      what FreeCAD itself printed while the job ran
A second run replaces the outputs of the first (the files it listed in .aeronc-outputs).
"""
import contextlib
import json
import os
import sys
import time

from aeronc.errors import AeroNCError

MANIFEST = ".aeronc-outputs"


class MainJobError(AeroNCError):
    """A stage of the main job failed; the message names it."""


@contextlib.contextmanager
def _freecad_output_to(log_path):
    """FreeCAD's own console output (recompute percentages, Path's messages) goes to the log;
    the job's progress lines keep the terminal."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = os.dup(1), os.dup(2)
    with open(log_path, "ab") as log:
        os.dup2(log.fileno(), 1)
        os.dup2(log.fileno(), 2)
        try:
            yield os.fdopen(os.dup(saved[0]), "w", buffering=1)
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            os.close(saved[0])
            os.close(saved[1])


class _Stages:
    def __init__(self, say):
        self.say, self.times = say, []

    @contextlib.contextmanager
    def stage(self, name):
        t0 = time.perf_counter()
        try:
            yield
        except AeroNCError as e:
            raise MainJobError("{}: {}".format(name, e)) from None
        seconds = time.perf_counter() - t0
        self.times.append((name, seconds))

    def report(self, text):
        name, seconds = self.times[-1]
        self.say("  {:>6.1f} s  {:<20s} {}".format(seconds, name, text))


def _remove_previous(out):
    path = os.path.join(out, MANIFEST)
    if not os.path.exists(path):
        return
    with open(path) as f:
        for name in f.read().split("\n"):
            if name and os.path.basename(name) == name and os.path.isfile(os.path.join(out, name)):
                os.unlink(os.path.join(out, name))
    os.unlink(path)


def _save_document(doc, path):
    """Save under a temporary name, then rename: no backup file, never a half-written document."""
    tmp = os.path.join(os.path.dirname(path), "." + os.path.basename(path) + ".part.FCStd")
    doc.saveAs(tmp)
    os.replace(tmp, path)
    doc.FileName = path


def _counts(result):
    by_setup = {}
    for e in result["elements"]:
        by_setup[e["setup"]] = by_setup.get(e["setup"], 0) + 1
    return ", ".join("{} {}".format(s["name"], by_setup.get(s["id"], 0)) for s in result["setups"])


def part_zero(blank, frame):
    """Where the program zero (the part's origin, in the setup's frame) sits from the table's
    reference point when the blank stands centred on the table: minus the middle of the blank's
    underside in the frame. Parts modelled far from their origin then stay within the travel."""
    from aeronc import setup_job
    box = setup_job.box_in_frame(blank, frame)
    return [0.0 - (box[0] + box[3]) / 2, 0.0 - (box[1] + box[4]) / 2, 0.0 - box[2]]  # no -0.0


def run(part_path, out, material="7050-T7451", machine="AC-5AX", family="integral_panel", cell_size=0.5,
        say=None):
    """Run the main job on a STEP (or BREP) part; returns the report's data (dict).
    Raises MainJobError naming the stage that failed. say(line) receives the progress lines;
    by default they go to the terminal while FreeCAD's own output goes to freecad.log."""
    import FreeCAD

    out = os.path.abspath(out)
    os.makedirs(out, exist_ok=True)
    _remove_previous(out)
    name = os.path.splitext(os.path.basename(part_path))[0]
    kb_path = os.path.join(out, "knowledge.sqlite")
    if os.path.exists(kb_path):  # left by a failed run: this run starts from the shipped knowledge base
        os.unlink(kb_path)
    written = ["freecad.log"]
    log_path = os.path.join(out, "freecad.log")
    if os.path.exists(log_path):
        os.unlink(log_path)
    first = "AeroNC main job: {} ({} on {}, {}) -> {}".format(part_path, material, machine, family, out)
    (say or print)(first)
    st = _Stages(say)
    run_data = {"part": name, "source": os.path.abspath(part_path), "pictures": []}
    opened = []
    try:
        return _stages(st, run_data, opened, part_path, out, name, material, machine, family, cell_size,
                       kb_path, log_path, written)
    finally:
        for doc in opened:  # the job's own document, also when a stage failed
            FreeCAD.closeDocument(doc.Name)


def _stages(st, run_data, opened, part_path, out, name, material, machine, family, cell_size, kb_path, log_path,
            written):
    import FreeCAD
    import Part

    from aeronc import chain_report, cutting_optimisation, machining_chain, pathcompat, picture, setup_job
    from aeronc import tool_planning, toolpath_picture, verification
    from aeronc.makers import create_machining_features
    from aeronc.objects import result_of
    from aeronc.operations import base as op_base
    from aeronc.post import machines, nc_post
    from aeronc.post.output import write_atomically

    with _freecad_output_to(log_path) as terminal:
        if st.say is None:
            st.say = lambda text: print(text, file=terminal)
        with st.stage("read part"):
            try:
                shape = Part.read(part_path)
            except Exception as e:  # FreeCAD raises its own types for unreadable files
                raise MainJobError("read part: {}: {}".format(part_path, e)) from None
            doc = FreeCAD.newDocument(name.replace("-", "_").replace(".", "_") or "Part")
            opened.append(doc)
            part = doc.addObject("Part::Feature", "Part")
            part.Label = name
            part.Shape = shape
            doc.recompute()
        st.report("{} faces".format(len(shape.Faces)))

        with st.stage("recognise"):
            # The blank the Jobs' stock and the verification use, stated to recognition too: on a
            # tilted setup its corner stands above the part, and the elements open to it start there.
            group = create_machining_features(doc, part, blank=setup_job.part_box(part.Shape))
            result = result_of(group)
        st.report("{} elements in {} setup(s): {}".format(len(result["elements"]), len(result["setups"]),
                                                           _counts(result)))
        if not result["elements"]:
            raise MainJobError("recognise: {} has no domain element to machine".format(name))
        run_data["recognition"] = result

        with st.stage("select tools"):
            plan, _, tcs = tool_planning.select_tools(group, material, machine, kb_path)
        st.report("{} ToolControllers; roughing tool changes {} -> {}".format(
            len(tcs), plan["toolChanges"]["before"], plan["toolChanges"]["after"]))

        with st.stage("cutting data"):
            jobs = pathcompat.jobs_of_part(doc, part)
            proposals = cutting_optimisation.propose(jobs[0], kb_path=kb_path) if jobs else []
            applied = cutting_optimisation.apply(proposals) if proposals else []
        st.report("{} of {} ToolControllers optimised".format(len(applied), len(proposals)))

        with st.stage("machining chain"):
            chain_obj = machining_chain.build(group, family, material, machine, kb_path)
            chain = json.loads(chain_obj.Chain)
        travel = chain.get("travel") or {}
        failed = machining_chain.failed_checks(chain)
        st.report("{} units, {} elements not machined, rules {}; rapid travel -{:.0f} %".format(
            len(chain.get("units", [])), chain_report.unmachined_text(chain),
            "all pass" if not failed else "{} FAIL".format(len(failed)), float(travel.get("savedPercent") or 0)))
        run_data["chain"] = chain

        ops_by_label, operations = {}, []
        for job in chain_obj.Jobs:
            for op in _operations_of(job):
                ops_by_label[op.Label] = (job, op)
                seconds = _clock_seconds(op.CycleTime)
                operations.append({"unit": op.UnitId, "setup": op.SetupId, "label": op.Label,
                                   "cutLength": op.CutLength.Value,
                                   "minutes": seconds / 60.0 if seconds is not None else None})
        run_data["operations"] = operations

        with st.stage("post"):
            programs = []
            blank = setup_job.blank_box(group)
            for k, job in enumerate(chain_obj.Jobs, start=1):
                setup = _setup_of(chain, job, setup_job.SETUP_TAG)
                objects = pathcompat.job_post_objects(job)
                stem = "{}_setup{}".format(name, k)
                zero = part_zero(blank, setup["frame"])
                for ext, dialect, label, args in (("mpf", "840d", "Sinumerik 840D", "--line-numbers"),
                                                   ("ngc", "linuxcnc", "LinuxCNC", "")):
                    path = os.path.join(out, stem + "." + ext)
                    options = "--machine {} --part-zero={} {}".format(machine, ",".join("{:.6f}".format(v) for v in zero),
                                                                       args).strip()
                    text = nc_post.export(objects, path, options, dialect)
                    programs.append({"setup": setup["name"], "dialect": label, "path": path, "partZero": zero,
                                     "lines": text.count("\n"), "job": job, "frame": setup["frame"]})
                    written.append(os.path.basename(path))
        st.report(", ".join(os.path.basename(p["path"]) for p in programs))
        run_data["programs"] = [{k: v for k, v in p.items() if k not in ("job", "frame")} for p in programs]

        with st.stage("verify"):
            machine_json, _ = machines.load(machine)
            tools = {}
            for job in chain_obj.Jobs:
                for tc in pathcompat.tool_controllers(job):
                    cutter = op_base.cutter_of(tc)
                    if cutter:
                        tools[tc.ToolNumber] = cutter["diameter"]
            sim_ops, setups = [], []
            for p in programs:
                if not p["path"].endswith(".ngc"):
                    continue
                read = verification.reread(p["path"], tools)
                to_part = setup_job.frame_placement(p["frame"]).inverse()
                placed = json.dumps(dict(json.loads(machine_json), partZero=list(p["partZero"])))
                in_part = verification.to_part_frame(read, placed, to_part)
                in_job = verification.to_part_frame(read, placed, FreeCAD.Placement())
                for op, op_job in zip(in_part, in_job):
                    job, fc_op = ops_by_label.get(op["label"], (None, None))
                    if fc_op is None:
                        raise MainJobError("verify: {} holds an operation '{}' that the Jobs do not".format(
                            os.path.basename(p["path"]), op["label"]))
                    cutter = op_base.cutter_of(fc_op.ToolController)
                    for o in (op, op_job):
                        o.update(cutter={"diameter": cutter["diameter"], "cornerRadius": cutter["cornerRadius"]},
                                 radialAllowance=_length(fc_op, "RadialAllowance"),
                                 axialAllowance=_length(fc_op, "AxialAllowance"))
                    sim_ops.append(op)
                setups.append({"name": p["setup"], "id": int(getattr(p["job"], setup_job.SETUP_TAG)),
                               "to_part": to_part, "ops": in_job})
            finished, elements = verification.finished_faces(chain, result)
            blank = setup_job.blank_box(group)
            if all(verification.axis_is_vertical(op["axis"]) for op in sim_ops):
                # One model for the whole part: what one setup removes, the next one finds gone.
                report = verification.simulate(part.Shape, sim_ops, blank, finished, elements, cell_size)
            else:
                setup_of_element = {"E{}".format(e["id"]): e.get("setup") for e in result.get("elements", [])}
                for s in setups:
                    s["elements"] = {k: v for k, v in elements.items() if setup_of_element.get(k) == s["id"]}
                report = verification.simulate_by_setup(part.Shape, setups, blank, cell_size)
        run_data["verification"], run_data["coverage"] = _checks_of(report, len(sim_ops))
        st.report("; ".join("{} {}".format(v["check"], "pass" if v["ok"] else "FAIL")
                            for v in run_data["verification"]))

        with st.stage("pictures"):
            pics = [("Part coloured by feature", picture.render(part.Shape, result, os.path.join(out, "features.png"),
                                                               title="{}: machining features".format(name)))]
            panels = []
            for job in chain_obj.Jobs:
                setup = _setup_of(chain, job, setup_job.SETUP_TAG)
                tps = []
                for op in _operations_of(job):
                    tps.append({"tool": op.Tool, "moves": _path_moves(op)})
                panels.append({"name": setup["name"], "edges": toolpath_picture.part_edges_in_frame(part.Shape,
                                                                                                  setup["frame"]),
                               "toolpaths": tps})
            pics.append(("Toolpaths over the part, per setup",
                         toolpath_picture.draw(panels, os.path.join(out, "toolpaths.png"),
                                               "{}: toolpaths by tool".format(name))))
            if report.get("leftover"):
                seen = "setup {}".format(report["leftoverSetup"]) if report.get("leftoverSetup") else "+Z"
                pics.append(("Material left after simulating the posted programs (seen from {})".format(seen),
                             toolpath_picture.draw_leftover(report["leftover"], os.path.join(out, "leftover.png"))))
            for k, (setup_name, leftover) in enumerate(report.get("leftovers") or [], 1):
                pics.append(("Material left in setup {}, which leaves a finished face unreached".format(setup_name),
                             toolpath_picture.draw_leftover(leftover, os.path.join(out, "leftover_{}.png".format(k)),
                                                            title="Setup {}: material left (blue: more than 0.2 mm)"
                                                            .format(setup_name))))
        st.report(", ".join(os.path.basename(p[1]) for p in pics))
        run_data["pictures"] = pics
        written += [os.path.basename(p[1]) for p in pics]

        with st.stage("save"):
            fcstd = os.path.join(out, name + ".FCStd")
            _save_document(doc, fcstd)
            for fname, data in (("recognition.json", result), ("chain.json", chain),
                                ("verification.json",
                                 {k: v for k, v in report.items() if k not in ("leftover", "leftovers")})):
                write_atomically(os.path.join(out, fname), json.dumps(data, indent=1))
            written += [os.path.basename(fcstd), "recognition.json", "chain.json", "verification.json",
                        "knowledge.sqlite"]
        st.report(os.path.basename(fcstd))
        run_data["stages"] = list(st.times)
        chain_report.write(os.path.join(out, "report.html"), run_data)
        written.append("report.html")
        write_atomically(os.path.join(out, MANIFEST), "\n".join(written) + "\n")
        total = sum(t for _, t in st.times)
        st.say("  {:>6.1f} s  total; report: {}".format(total, os.path.join(out, "report.html")))
    return run_data


def _length(obj, prop):
    """A length property's value in mm; 0 for an operation without it (drilling leaves nothing)."""
    v = getattr(obj, prop, 0.0)
    return float(getattr(v, "Value", v))


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
