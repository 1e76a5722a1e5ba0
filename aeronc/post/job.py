"""FreeCAD objects -> the sections the C++ core posts.

A post receives what FreeCAD's Post command builds from a Job: work-offset objects (G54 and
a clearance move), tool controllers, operations (dressups and compounds included). A Job
itself in the list is expanded the same way. Every Path is handed over as its G-code text
(Path.toGCode(), the form FreeCAD saves), so the per-move work happens in C++."""
from aeronc import pathcompat
from aeronc.errors import PostError


def _quantity(v):
    return float(getattr(v, "Value", v) or 0.0)


def _tool_section(tc):
    tool = getattr(tc, "Tool", None)
    name = getattr(tool, "Label", None) or tc.Label
    direction = getattr(tc, "SpindleDir", "Forward")
    return {
        "kind": "tool",
        "label": tc.Label,
        "tool": {
            "number": int(tc.ToolNumber),
            "name": name,
            "diameter": _quantity(getattr(tool, "Diameter", 0.0)),
            "corner_radius": _quantity(getattr(tool, "CornerRadius", 0.0)),
            "length": _quantity(getattr(tool, "Length", 0.0)),
        },
        "rpm": float(tc.SpindleSpeed),
        "spindle_dir": {"Forward": 1, "Reverse": -1}.get(direction, 0),
    }


def _expand(objects):
    for obj in objects:
        if pathcompat.is_job(obj):
            yield from pathcompat.job_post_objects(obj)
        else:
            yield obj


def _has(obj, name):
    """Whether obj has a property, without reading it (reading a Path copies every command)."""
    props = getattr(obj, "PropertiesList", None)
    return name in props if props is not None else hasattr(obj, name)


def _operations(obj):
    """An operation, or the operations inside a compound (FreeCAD's posts walk Group the same way)."""
    if _has(obj, "Group"):
        for child in obj.Group:
            yield from _operations(child)
    elif _has(obj, "Path"):
        yield obj


def sections_for(objects, skip_failed=False):
    """The sections of a post's object list, in order. An operation that is not ready
    (aeronc.post.readiness: no toolpath, a failed check, no move) raises PostError, or with
    skip_failed is left out: a comment at the program's start names it and why, and its tool
    change goes too unless another operation uses it."""
    return prepared(objects, skip_failed)[0]


def prepared(objects, skip_failed=False):
    """(sections, [(label, why)] of the operations left out); see sections_for."""
    from aeronc.post import readiness
    sections, left_out = [], []
    for obj in _expand(objects):
        if pathcompat.is_tool_controller(obj):
            sections.append(_tool_section(obj))
            continue
        if not hasattr(obj, "TypeId") and getattr(obj, "Name", "") == "Fixture":
            sections.append({"kind": "offset", "label": obj.Label, "gcode": obj.Path.toGCode()})
            continue
        if not _has(obj, "Path") and not _has(obj, "Group"):
            raise PostError("'{}' is not a Path object; select a Job, operations or tool controllers".format(
                getattr(obj, "Label", obj)))
        for op in _operations(obj):
            if not pathcompat.op_active(op):
                continue
            gcode = op.Path.toGCode()
            why = readiness.not_ready_reason(op, gcode)
            if why is not None:
                if not skip_failed:
                    raise PostError("operation '{}' is not ready to post: {}. Change it until it has a toolpath "
                                    "that passes its check, switch it off (Active), or post with --skip-failed "
                                    "to leave it out with a comment in the program".format(op.Label, why))
                left_out.append((op.Label, why))
                continue
            needs = pathcompat.needs_tool_controller(op)
            sections.append({
                "kind": "operation",
                "label": op.Label,
                "gcode": gcode,
                "coolant": str(pathcompat.op_property(op, "CoolantMode") or "None").lower(),
                "has_tool_controller": (not needs) or pathcompat.tool_controller_of(op) is not None,
            })
    if left_out:
        sections = [left_out_section(left_out)] + _without_idle_tools(sections)
    return sections, left_out


def left_out_section(left_out):
    """The comment block at the program's start naming the operations left out and why."""
    lines = ["(INCOMPLETE PROGRAM: {} operation{} left out)".format(len(left_out), "" if len(left_out) == 1 else "s")]
    for label, why in left_out:
        lines += ["({})".format(piece) for piece in _comment_pieces("left out: {}: {}".format(label, why))]
    return {"kind": "offset", "label": "operations left out", "gcode": "\n".join(lines) + "\n"}


# Characters of a comment line's text: controllers and their simulators refuse longer blocks
# (LinuxCNC's interpreter takes 255 characters a line), and the reasons of an operation left out
# can run longer.
COMMENT_WIDTH = 120


def _comment_pieces(text):
    """text cut at spaces into pieces of at most COMMENT_WIDTH characters, the later ones
    indented: one comment line each."""
    import textwrap
    return textwrap.wrap(text, COMMENT_WIDTH, subsequent_indent="  ", break_long_words=True,
                         break_on_hyphens=False) or [""]


def _without_idle_tools(sections):
    """Sections without a tool change that no operation follows before the next tool change
    (the tool of an operation left out)."""
    out = []
    for k, s in enumerate(sections):
        if s["kind"] == "tool":
            following = next((t["kind"] for t in sections[k + 1:] if t["kind"] in ("tool", "operation")), None)
            if following != "operation":
                continue
        out.append(s)
    return out
