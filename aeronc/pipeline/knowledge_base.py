"""App-side access to the machining knowledge base and the tool planner of the core.

The user's knowledge base lives in FreeCAD's user data folder (AeroNC/knowledge.sqlite);
it is built from the SQL shipped in resources/kb the first time it is needed, and migrated
by the core when an older version is opened, so a user's edits survive an upgrade. The
planner works on a recognised machining-domain tree (recognition's result), never on the
part itself.
"""
import json
import os

import FreeCAD

from aeronc.errors import KnowledgeBaseError, from_core


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


def use_crib(kb_path, crib):
    """Make kb_path (a file that does not exist yet) the knowledge base of the user's own tool crib
    (docs/tool-crib.md), in place of the shipped one:
      a knowledge-base file (.sqlite)   a copy of it, migrated if older; the user's file is not written;
      a FreeCAD tool library (.fctl)    the shipped knowledge base (machines, materials, cutting data,
                                        templates) with its tools replaced by the library's bits.
    Returns the open KnowledgeBase. Raises KnowledgeBaseError naming the file when it is missing or
    is no knowledge base or library."""
    import shutil
    if not crib or not os.path.isfile(crib):
        raise KnowledgeBaseError("the tool crib {!r} is not a file (give a knowledge-base file or a FreeCAD "
                                 "tool library, .fctl)".format(crib))
    if os.path.exists(kb_path):
        raise KnowledgeBaseError("the knowledge base {!r} exists already: a crib is only put in a new one"
                                 .format(kb_path))
    if crib.lower().endswith(".fctl"):
        kb = open_kb(kb_path)
        with from_core(KnowledgeBaseError, "the tool crib {!r}".format(crib)):
            for table in ("tool", "edge_tool"):
                rows = kb.table(table)["rowIds"]
                if rows:
                    kb.edit_table(table, deletes=rows)
            kb.import_freecad_library(crib)
        return kb
    tmp = kb_path + ".copying"
    shutil.copyfile(crib, tmp)
    os.replace(tmp, kb_path)
    try:
        return open_kb(kb_path)
    except KnowledgeBaseError as e:
        raise KnowledgeBaseError("the tool crib {!r}: {}".format(crib, e)) from None


def plan_tools(tree, material, machine="", kb_path=None):
    """Plan finishing and roughing tools, drills and merged tool groups for a recognised
    machining-domain tree from the knowledge base at kb_path (default: the user's).

    tree is recognition's result, as a dict or as its JSON text (a Machining Features group's
    stored result). Returns the plan as a dict. Raises KnowledgeBaseError with the core's
    message for a malformed tree (naming the field at fault), an unknown material or machine,
    or a knowledge base that cannot be opened."""
    from aeronc import _core
    text = tree if isinstance(tree, str) else json.dumps(tree)
    path = kb_path or user_kb_path()
    folder = os.path.dirname(path)
    if folder:
        os.makedirs(folder, exist_ok=True)
    with from_core(KnowledgeBaseError):
        plan = _core.select_tools_tree(text, path, material, sql_folder(), machine)
    return json.loads(plan)
