"""Program an impeller in the document: recognition nodes, blank, Path Job, posted program.

  create(doc, part, ...)                 recognise, plan, compute and post; add everything
  set_step_enabled / set_step_tool /     one edit of the route, the toolpaths computed again
  set_step_allowance / set_allowance     and the program posted again
  update(program, edits, allowance)      the same for any set of edits

route.compute() does all the work (recognition, dimensions, blank, route from the knowledge base;
then the core's one impeller program, as `aeronc impeller-program` makes it) without touching
the document (program_nodes.py makes the objects, program_output.py posts, writes and checks);
the document is then changed in one
transaction, the program posted inside it, so a failure anywhere (not an impeller, unequal
blade groups, missing hub, no tool fits, the post refuses a move) leaves the document as it
was. The posted 840D program is kept in the program object and written next to the saved
document (or into out_dir).
"""
import json
import time

from aeronc.errors import AeroNCError, ImpellerError
from aeronc.impeller.program_nodes import add_blank, add_features, add_job, add_operations, fill_blank, fill_program
from aeronc.impeller.program_output import check_posted, post_into, program_path, write_program
from aeronc.impeller.route import (FIVE_AXIS_STEPS, MACHINE, MATERIAL, compute, normalised_edits, steps_with_tools,
                                   tool_library)
from aeronc import pathcompat
from aeronc.objects.base import attach_views, descendants
from aeronc.objects.impeller_program import ImpellerProgram, edits_of, route_of
from aeronc.objects.transaction import in_transaction
from aeronc.operations.impeller_operation import is_impeller_operation

def create(doc, part_obj, allowance=2.0, material=MATERIAL, machine=MACHINE, kb_path=None, stations=24, channels=0,
           out_dir=None):
    """Program the impeller part_obj: recognition nodes, blank, Job with the route's operations,
    posted program, as one undo step. Returns the ImpellerProgram object. Raises AeroNCError
    (RecognitionError: not an impeller, unequal blade groups, missing hub; ImpellerError,
    PostError, ...) leaving the document as it was."""
    c = compute(part_obj, allowance, None, material, machine, kb_path, stations, channels)

    def work():
        group, nodes = add_features(doc, part_obj, c.result)
        blank = add_blank(doc, part_obj, c)
        job = add_job(doc, part_obj, blank, c.frame)
        ops = add_operations(doc, job, c.steps, c.paths, c.cutting, c.setup_axis)
        prog = doc.addObject("App::FeaturePython", "ImpellerProgram")
        ImpellerProgram(prog)
        prog.Label = "Impeller program ({})".format(part_obj.Label)
        prog.Features, prog.Blank, prog.Job = group, blank, job
        fill_program(prog, c, normalised_edits(None))
        made = [group] + nodes + [prog] + ops
        for obj in made:
            obj.Visibility = True
        blank.Visibility = False
        attach_views(made)
        doc.recompute()
        t0 = time.perf_counter()
        post_into(prog)
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
                fill_blank(prog.Blank, c)
            else:
                prog.Blank = add_blank(doc, part, c)
                pathcompat.set_job_stock_object(job, prog.Blank)
        pathcompat.set_model_placement(job, c.frame)
        ops = add_operations(doc, job, c.steps, c.paths, c.cutting, c.setup_axis)
        fill_program(prog, c, edits)
        for obj in ops:
            obj.Visibility = True
        attach_views(ops)
        doc.recompute()
        post_into(prog)
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
    return steps_with_tools(route_of(prog), normalised_edits(edits_of(prog)), prog.KnowledgeBase or None)


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
           "set_allowance", "check_posted", "write_program", "program_path", "steps_of", "remove", "tool_library",
           "edits_of", "route_of", "FIVE_AXIS_STEPS", "MACHINE", "MATERIAL", "AeroNCError"]
