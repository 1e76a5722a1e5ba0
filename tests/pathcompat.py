"""The tests' side of aeronc.pathcompat, imported as aeronc.tests.pathcompat: FreeCAD Path
objects and posts that only tests, benchmarks (tools/) and scripts (scripts/) make or load.

It is the only module outside aeronc/pathcompat.py that imports FreeCAD's Path (CAM)
workbench modules (`PathScripts.*` in FreeCAD 0.20, `Path.Op.*`, `Path.Tool.*`, ... in 1.x);
the Path data types (`import Path` for Path.Command and Path.Path) are the same in both and
are used directly. Imports are lazy, as in the shipped module.
"""


def post_processor(name):
    """Load a post by its dropdown name the way the Job's Post command does; the result has
    export(objects, filename, argstring) and tooltip."""
    try:
        from Path.Post.Processor import PostProcessorFactory  # FreeCAD 1.x
        return PostProcessorFactory.get_post_processor(None, name)
    except ImportError:
        from PathScripts.PathPostProcessor import PostProcessor  # FreeCAD 0.20
        return PostProcessor.load(name)


def available_posts():
    """Names in the Job's post-processor dropdown (every *_post.py on the post search path)."""
    try:
        from Path import Preferences  # FreeCAD 1.x
    except ImportError:
        from PathScripts import PathPreferences as Preferences  # FreeCAD 0.20
    return Preferences.allAvailablePostProcessors()


def builtin_post(name):
    """One of the posts FreeCAD ships, as a module (e.g. "linuxcnc")."""
    import importlib
    try:
        return importlib.import_module("Path.Post.scripts.{}_post".format(name))  # FreeCAD 1.x
    except ImportError:
        return importlib.import_module("PathScripts.post.{}_post".format(name))  # FreeCAD 0.20


def create_profile(name="Profile"):
    """FreeCAD's Profile operation in the active document's Job (headless)."""
    try:
        from Path.Op import Profile  # FreeCAD 1.x
    except ImportError:
        from PathScripts import PathProfile as Profile  # FreeCAD 0.20
    return Profile.Create(name)


def add_tool_controller(job, label, number):
    """A new tool controller (FreeCAD's default tool bit) in the Job."""
    from aeronc import pathcompat
    return pathcompat.add_tool_controller(job, label, number)


def create_pocket_shape(name="Pocket", job=None):
    """FreeCAD's Pocket Shape operation in job, or in the active document's only Job (headless).
    The Job must hold exactly one ToolController: headless, Path cannot choose between several."""
    try:
        from Path.Op import PocketShape  # FreeCAD 1.x
    except ImportError:
        from PathScripts import PathPocketShape as PocketShape  # FreeCAD 0.20
    return PocketShape.Create(name, parentJob=job)


def create_adaptive(name="Adaptive", job=None):
    """FreeCAD's Adaptive clearing operation in job, or in the active document's only Job
    (headless; the Job must hold exactly one ToolController)."""
    try:
        from Path.Op import Adaptive  # FreeCAD 1.x
    except ImportError:
        from PathScripts import PathAdaptive as Adaptive  # FreeCAD 0.20
    return Adaptive.Create(name, parentJob=job)


def create_custom_operation(name, gcode):
    """FreeCAD's Custom operation (G-code lines given) in the active document's Job (headless)."""
    try:
        from Path.Op import Custom  # FreeCAD 1.x
    except ImportError:
        from PathScripts import PathCustom as Custom  # FreeCAD 0.20
    op = Custom.Create(name)
    op.Gcode = list(gcode)
    return op


def tool_bit_from_file(path, name="ToolBit"):
    """A ToolBit object in the active document from a .fctb file, as FreeCAD's tool library
    makes it."""
    try:
        from Path.Tool import Bit  # FreeCAD 1.x
    except ImportError:
        from PathScripts import PathToolBit as Bit  # FreeCAD 0.20
    return Bit.Factory.CreateFrom(path, name)
