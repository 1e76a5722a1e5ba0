"""App-side access to the machining knowledge base and the tool planner of the core.

The user's knowledge base lives in FreeCAD's user data folder (AeroNC/knowledge.sqlite);
it is built from the SQL shipped in resources/kb the first time it is needed, and migrated
by the core when an older version is opened, so a user's edits survive an upgrade.
"""
import json
import os

import FreeCAD

from aeronc.errors import KnowledgeBaseError, from_core
from aeronc.recognition import check_solid, shape_of


def user_kb_path():
    return os.path.join(FreeCAD.getUserAppDataDir(), "AeroNC", "knowledge.sqlite")


def sql_folder():
    import aeronc
    return os.path.join(aeronc.PACKAGE_DIR, "resources", "kb")


def open_kb(kb_path=None):
    """The knowledge base at kb_path (default: the user's), built or migrated as needed.

    Returns the core's KnowledgeBase: tools(), table(), edit_table(), import_freecad_library(),
    export_freecad_library(), export_tools(), bit_document(), cutting_condition(), ...;
    its methods raise the core's exception (call them inside errors.from_core)."""
    from aeronc import _core
    path = kb_path or user_kb_path()
    folder = os.path.dirname(path)
    if folder:
        os.makedirs(folder, exist_ok=True)
    with from_core(KnowledgeBaseError):
        return _core.KnowledgeBase(path, sql_folder())


def select_tools(source, material, directions=None, machine="", kb_path=None, allowance=0.0, blank=None,
                 linear_tolerance=1e-3, angular_tolerance=1e-3, chord_tolerance=0.01, progress=None):
    """Recognise `source` (shape or document object) and plan finishing and roughing tools,
    drills and merged tool groups from the knowledge base; returns the plan as a dict."""
    from aeronc import _core
    shape, label = shape_of(source)
    check_solid(shape, label)
    path = kb_path or user_kb_path()
    os.makedirs(os.path.dirname(path), exist_ok=True)
    try:
        text = _core.select_tools_brep(shape.exportBrepToString(), path, material, sql_folder(),
                                       [tuple(float(c) for c in d) for d in (directions or [])], machine,
                                       allowance, tuple(blank) if blank else None, linear_tolerance,
                                       angular_tolerance, chord_tolerance, progress)
    except RuntimeError as e:
        raise KnowledgeBaseError("{}: {}".format(label, e))
    return json.loads(text)
