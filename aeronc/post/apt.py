"""APT cutter-location files.

  export(objectslist, filename, argstring)   FreeCAD objects -> APT CL file (the
                                             aeronc_apt post): GOTO/x,y,z,i,j,k in the
                                             workpiece frame, before any kinematics
  post_apt_file(apt, nc, argstring, dialect) an APT file -> NC program, through the same
                                             kinematics and formatters as the NC posts

From a shell, with the built core on the path (no FreeCAD needed):
    PYTHONPATH=<Mod>/AeroNC python3 -m aeronc.post.apt in.apt out.mpf --machine AC-HEAD
"""
import os
import sys

from aeronc.errors import PostError, from_core
from aeronc.post.output import write_atomically

TOOLTIP = """AeroNC APT CL output: the tool tip and tool axis of every move (GOTO/x,y,z,i,j,k)
in the workpiece frame, with LOADTL, CUTTER, SPINDL, FEDRAT, RAPID, CIRCLE and CYCLE/DRILL.
Post the file to NC later with aeronc.post.apt.post_apt_file."""


def export(objectslist, filename, argstring):
    from aeronc import _core
    from aeronc.post import job, nc_post
    opts, a = nc_post.options(argstring, "840d", filename, nc_post._job_label(objectslist))
    sections = job.sections_for(objectslist, skip_failed=a.skip_failed)
    with from_core(PostError):
        text = _core.write_apt(sections, opts["program_name"])
    if filename and filename != "-":
        write_atomically(filename, text)
    return text


def post_apt_text(apt_text, argstring="", dialect="840d", program_name="AERONC"):
    """An APT CL text (str, or bytes as read from a file) -> (NC text, summary). Bytes that are
    not UTF-8 can reach the NC text only inside comments (PPRINT); they are shown as U+FFFD."""
    from aeronc import _core
    from aeronc.post import machines, nc_post
    opts, a = nc_post.options(argstring, dialect, None, program_name)
    machine_json, source = machines.load(a.machine, a.machine_file)
    with from_core(PostError):
        data, summary = _core.post_apt(apt_text, machine_json, source, __import__("json").dumps(opts))
    return data.decode("utf-8", errors="replace"), summary


def post_apt_file(apt_path, nc_path, argstring="", dialect="840d"):
    """Post an APT file to NC; writes nc_path (atomically) unless it is "-"; returns the text."""
    # As bytes: the core reads them and names the line of anything it cannot read.
    with open(apt_path, "rb") as f:
        apt_text = f.read()
    name = os.path.splitext(os.path.basename(nc_path if nc_path != "-" else apt_path))[0]
    text, _ = post_apt_text(apt_text, argstring, dialect, name)
    if nc_path != "-":
        write_atomically(nc_path, text)
    return text


def main(argv):
    if len(argv) < 2:
        print("usage: python3 -m aeronc.post.apt IN.apt OUT.nc|- [--dialect 840d|linuxcnc] [post options]", file=sys.stderr)
        return 2
    try:
        text = post_apt_file(argv[0], argv[1], " ".join(argv[2:]))
    except (PostError, OSError) as e:
        print("error: {}".format(e), file=sys.stderr)
        return 1
    if argv[1] == "-":
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
