"""The impeller program's output: the Job posted for the machine (AeroNC's 840D post, TRAORI for
the 5-axis moves), the program file written next to the document, and the posted program read
back and checked for gouges and holder collisions against the blades and hub."""
import json
import os

from aeronc import pathcompat
from aeronc.errors import ImpellerError, from_core
from aeronc.impeller.route import MACHINE, core_module, tool_library


def post_into(prog):
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
    # The program is in the Job's frame: checked against the Job's model, the part as placed there.
    models = pathcompat.job_models(job)
    shape = models[0].Shape if models else prog.Features.Source.Shape
    with from_core(ImpellerError, "checking {}".format(prog.Label)):
        return json.loads(core_module().impeller_check_apt(shape.exportBrepToString(), text, json.dumps(cutters)))
