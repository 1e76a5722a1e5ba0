"""The thin post files FreeCAD lists in the Job's post-processor dropdown.

FreeCAD 0.20 lists *_post.py files found in the Path preference folder, the user macro
folder and PathScripts/post; a post inside an addon can be imported but is not listed. So
AeroNC keeps three small files in the macro folder, each delegating to aeronc.post. They are
rewritten when their content changes (at FreeCAD start-up, from Init.py) and never written
over a user's own file of the same name (one without the marker line)."""
import os

MARKER = "# AeroNC post file"

_TEMPLATE = '''{marker}: written by AeroNC at FreeCAD start-up and rewritten when AeroNC changes it.
# Edit the post in the AeroNC addon (aeronc/post), not here; delete this line to keep your own copy.
"""{title}"""
from aeronc.post import {module} as _post

TOOLTIP = _post.{tooltip}
TOOLTIP_ARGS = {tooltip_args}
UNITS = "G21"
MACHINE_NAME = "AeroNC {title}"


def export(objectslist, filename, argstring):
    return _post.export(objectslist, filename, argstring{extra})
'''

POSTS = {
    "aeronc_840d_post.py": dict(title="Sinumerik 840D 5-axis", module="nc_post", tooltip="TOOLTIP_840D",
                                tooltip_args='_post.tooltip_args("840d")', extra=', dialect="840d"'),
    "aeronc_linuxcnc_post.py": dict(title="LinuxCNC 5-axis (XYZAC table-table)", module="nc_post",
                                    tooltip="TOOLTIP_LINUXCNC", tooltip_args='_post.tooltip_args("linuxcnc")',
                                    extra=', dialect="linuxcnc"'),
    "aeronc_apt_post.py": dict(title="APT CL file (5-axis GOTO/x,y,z,i,j,k)", module="apt", tooltip="TOOLTIP",
                               tooltip_args='""', extra=""),
}


def post_text(filename):
    return _TEMPLATE.format(marker=MARKER, **POSTS[filename])


def install_posts(folder=None):
    """Write the post files that are missing or out of date; returns the paths written."""
    if folder is None:
        from aeronc import pathcompat
        folder = pathcompat.post_folder()
    os.makedirs(folder, exist_ok=True)
    written = []
    for name in POSTS:
        path = os.path.join(folder, name)
        text = post_text(name)
        if os.path.exists(path):
            with open(path, encoding="utf-8") as f:
                current = f.read()
            if current == text or not current.startswith(MARKER):
                continue  # up to date, or the user's own file
        from aeronc.post.output import write_atomically
        write_atomically(path, text)
        written.append(path)
    return written
