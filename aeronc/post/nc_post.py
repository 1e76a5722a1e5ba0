"""The NC posts behind aeronc_840d_post.py and aeronc_linuxcnc_post.py.

export(objectslist, filename, argstring, dialect) follows FreeCAD's post contract: it
returns the program text and writes it to `filename` unless that is "-". The program is
written to a temporary file in the same folder and renamed, so a failed post leaves no
partial file and an old program stays whole until the new one is complete."""
import argparse
import json
import os
import shlex

from aeronc.errors import PostError, from_core
from aeronc.post import machines
from aeronc.post.output import write_atomically

TOOLTIP_840D = """AeroNC 5-axis post for a Siemens Sinumerik 840D: CYCLE800 planes for 3+2
machining, TRAORI for simultaneous 5-axis moves, CYCLE81/82/83 drilling, CYCLE832
smoothing. The tool axis of each move comes from AeroNC's U V W parameters (docs/post.md);
FreeCAD's own 3-axis operations post as vertical planes."""

TOOLTIP_LINUXCNC = """AeroNC 5-axis post for LinuxCNC (trivkins XYZAC table-table): machine
coordinates X Y Z A C computed by AeroNC's kinematics, inverse-time feeds on rotary moves,
G81/G82/G83/G73 drilling along the tilted tool axis."""


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # argparse would exit FreeCAD
        raise PostError("post arguments: {}".format(message))


def parser(dialect):
    p = _Parser(prog="aeronc_{}".format(dialect), add_help=False)
    p.add_argument("--machine", default=None,
                   help="machine by name (resources/machines/<name>.json), default {}".format(machines.DEFAULT_MACHINE))
    p.add_argument("--machine-file", default=None, help="a machine file elsewhere")
    p.add_argument("--dialect", choices=["840d", "linuxcnc"], default=dialect, help="NC dialect")
    p.add_argument("--orientation", choices=["axes", "vectors"], default="axes",
                   help="840D simultaneous moves: machine A/C words or A3= B3= C3= vectors")
    p.add_argument("--precision", type=int, default=3, help="decimals of lengths (mm), default 3")
    p.add_argument("--angle-precision", type=int, default=None, help="decimals of angles (degrees), default as --precision")
    p.add_argument("--vector-precision", type=int, default=7, help="decimals of A3= B3= C3=, default 7")
    p.add_argument("--no-comments", action="store_true", help="no comments in the program")
    p.add_argument("--line-numbers", action="store_true", help="N numbers on every block")
    p.add_argument("--inverse-time", dest="inverse_time", action="store_true", default=None,
                   help="G93 inverse-time feed on moves that turn a rotary axis (default on for LinuxCNC)")
    p.add_argument("--no-inverse-time", dest="inverse_time", action="store_false")
    p.add_argument("--tool-call", choices=["number", "name"], default="number",
                   help='840D tool call: T<n> D1 M6 or T="<tool name>" D1 M6')
    p.add_argument("--smoothing", choices=["finish", "semifinish", "rough", "off"], default="finish",
                   help="840D CYCLE832 machining type for milling")
    p.add_argument("--smoothing-tolerance", type=float, default=0.01, help="840D CYCLE832 tolerance, mm")
    p.add_argument("--program-name", default=None, help="program name (840D header), default from the file name")
    p.add_argument("--part-zero", default=None,
                   help="program zero relative to the table reference point, x,y,z mm (overrides the machine file)")
    p.add_argument("--retract", type=float, default=None,
                   help="retract distance along the tool axis at a branch change, mm (machine file default)")
    p.add_argument("--chord", type=float, default=0.001, help="chord tolerance for arcs under TRAORI, mm")
    p.add_argument("--skip-failed", action="store_true",
                   help="leave out operations that are not ready (no toolpath, a failed check) with a comment "
                        "naming each, instead of refusing the program")
    p.add_argument("--no-show-editor", action="store_true", help="accepted for FreeCAD habit; no editor is shown")
    return p


def tooltip_args(dialect):
    return parser(dialect).format_help()


def options(argstring, dialect, filename=None, default_name="AERONC"):
    """(options dict for the core, parsed arguments)."""
    try:
        words = shlex.split(argstring or "")
    except ValueError as e:
        raise PostError("post arguments: {}".format(e))
    a = parser(dialect).parse_args(words)
    name = a.program_name
    if not name:
        name = os.path.splitext(os.path.basename(filename))[0] if filename and filename != "-" else default_name
    opts = {
        "dialect": a.dialect,
        "vectors": a.orientation == "vectors",
        "precision": a.precision,
        "angle_precision": a.precision if a.angle_precision is None else a.angle_precision,
        "vector_precision": a.vector_precision,
        "comments": not a.no_comments,
        "line_numbers": a.line_numbers,
        "inverse_time": (a.dialect == "linuxcnc") if a.inverse_time is None else a.inverse_time,
        "tool_by_name": a.tool_call == "name",
        "smoothing": a.smoothing,
        "smoothing_tolerance": a.smoothing_tolerance,
        "program_name": name,
        "chord": a.chord,
    }
    if a.part_zero:
        try:
            p = [float(v) for v in a.part_zero.split(",")]
        except ValueError:
            p = []
        if len(p) != 3:
            raise PostError("--part-zero takes x,y,z in mm, not '{}'".format(a.part_zero))
        opts["part_zero"] = p
    if a.retract is not None:
        opts["retract"] = a.retract
    return opts, a


def _job_label(objectslist):
    from aeronc import pathcompat
    for o in objectslist:
        if pathcompat.is_job(o):
            return o.Label
    return "AERONC"


def post_sections(sections, argstring, dialect, filename=None, default_name="AERONC"):
    """Post prepared sections; returns (text, summary)."""
    from aeronc import _core
    opts, a = options(argstring, dialect, filename, default_name)
    machine_json, source = machines.load(a.machine, a.machine_file)
    with from_core(PostError):
        data, summary = _core.post_nc(sections, machine_json, source, json.dumps(opts))
    return data.decode("utf-8"), summary


def export(objectslist, filename, argstring, dialect="840d"):
    """FreeCAD's post contract: returns the program, written to filename unless it is "-"."""
    from aeronc.post import job
    try:
        _, a = options(argstring, dialect, filename)
        sections = job.sections_for(objectslist, skip_failed=a.skip_failed)
        text, _ = post_sections(sections, argstring, dialect, filename, _job_label(objectslist))
        if filename and filename != "-":
            write_atomically(filename, text)
        return text
    except PostError as e:
        try:
            import FreeCAD
            FreeCAD.Console.PrintError("AeroNC post: {}\n".format(e))
        except ImportError:
            pass
        raise
