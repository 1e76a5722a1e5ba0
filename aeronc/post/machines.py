"""Machine files: resources/machines/<name>.json, named like the machines of the knowledge base.

The knowledge base's machine table holds each machine's rotary limits but not yet its pivot
and offset vectors, so the posts read the whole geometry from the machine file; a test keeps
the file's limits equal to the knowledge base's."""
import os

from aeronc.errors import PostError

DEFAULT_MACHINE = "AC-5AX"


def machine_folder():
    import aeronc
    return os.path.join(aeronc.PACKAGE_DIR, "resources", "machines")


def known_machines():
    folder = machine_folder()
    if not os.path.isdir(folder):
        return []
    return sorted(f[:-5] for f in os.listdir(folder) if f.endswith(".json"))


def machine_path(name):
    path = os.path.join(machine_folder(), name + ".json")
    if os.path.sep in name or not os.path.isfile(path):
        raise PostError("unknown machine '{}'; known machines: {} (files in {})".format(
            name, ", ".join(known_machines()) or "none", machine_folder()))
    return path


def post_of(name):
    """The name of AeroNC's FreeCAD post for the machine's controller ("aeronc_840d" for a
    Sinumerik, "aeronc_linuxcnc" for LinuxCNC)."""
    import json
    text, _ = load(name)
    controller = str(json.loads(text).get("controller", ""))
    return "aeronc_linuxcnc" if "linuxcnc" in controller.lower() else "aeronc_840d"


def load(name=None, path=None):
    """(JSON text, source) of the machine given by name or by file path."""
    if path:
        if not os.path.isfile(path):
            raise PostError("machine file {} does not exist".format(path))
    else:
        path = machine_path(name or DEFAULT_MACHINE)
    with open(path, encoding="utf-8") as f:
        return f.read(), path
