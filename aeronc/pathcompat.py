"""The one place that imports FreeCAD's Path (CAM) modules.

FreeCAD 0.20 ships them as `PathScripts.*`; FreeCAD 1.x renamed the workbench to CAM and
moved them to `Path.Op.*`, `Path.Main.*`. Every other AeroNC module goes through the
functions here, so supporting another FreeCAD release means changing this file only.
Imports are lazy: loading the Path modules is slow and is not needed to recognise features.
"""
import FreeCAD


def _job_module():
    try:
        from Path.Main import Job  # FreeCAD 1.x
        return Job
    except ImportError:
        from PathScripts import PathJob  # FreeCAD 0.20
        return PathJob


def is_job(obj):
    """True when obj is a Path Job."""
    proxy = getattr(obj, "Proxy", None)
    if proxy is None or not hasattr(obj, "Stock"):
        return False  # cheap test first: keeps Path unloaded for documents without jobs
    return isinstance(proxy, _job_module().ObjectJob)


def find_jobs(doc):
    """The Path Jobs of a document, in document order."""
    return [o for o in doc.Objects if is_job(o)]


def job_stock_box(job):
    """The blank of a Job as (xmin, ymin, zmin, xmax, ymax, zmax), or None without stock."""
    stock = getattr(job, "Stock", None)
    if stock is None or stock.Shape.isNull():
        return None
    bb = stock.Shape.BoundBox
    return (bb.XMin, bb.YMin, bb.ZMin, bb.XMax, bb.YMax, bb.ZMax)


def job_models(job):
    """The model objects (clones of the parts) of a Job."""
    model = getattr(job, "Model", None)
    return list(model.Group) if model is not None else []


def create_job(doc, models, name="Job"):
    """Create a Path Job for the given part objects with the default stock (headless)."""
    if FreeCAD.ActiveDocument is not doc:
        FreeCAD.setActiveDocument(doc.Name)
    return _job_module().Create(name, list(models))


# --- Posts ---------------------------------------------------------------------------------

def post_folder():
    """The user folder where FreeCAD looks for *_post.py files (listed in the Job's
    post-processor dropdown): the macro folder. 0.20 and 1.x both search it; read from the
    preferences directly so that start-up does not load the Path modules."""
    grp = FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Macro")
    return grp.GetString("MacroPath", FreeCAD.getUserMacroDir())


def _path_util():
    try:
        from Path.Base import Util  # FreeCAD 1.x
        return Util
    except ImportError:
        from PathScripts import PathUtil  # FreeCAD 0.20
        return PathUtil


def _base_chain(op):
    """The operation and, for a dressup, the operations it is based on."""
    while op is not None:
        yield op
        base = getattr(op, "Base", None)
        # An operation's Base is its geometry (a list); a dressup's Base is the operation.
        op = base if base is not None and not isinstance(base, (list, tuple)) and hasattr(base, "Path") else None


def op_active(op):
    """False when the operation (or the operation a dressup is based on) is switched off."""
    value = _path_util().opProperty(op, "Active")
    return True if value is None else bool(value)


def tool_controller_of(op):
    """The tool controller an operation (or the base of a dressup) uses, or None."""
    return _path_util().toolControllerForOp(op)


def needs_tool_controller(op):
    """True when the object is an operation that has (or should have) a tool controller."""
    return any(hasattr(o, "ToolController") for o in _base_chain(op))


def is_tool_controller(obj):
    return hasattr(obj, "ToolNumber") and hasattr(obj, "SpindleDir") and hasattr(obj, "Path")


def job_post_objects(job):
    """What FreeCAD's Post command hands a post for a Job, ordered by fixture (FreeCAD's
    default): for every work offset, an object holding it and the clearance move, then the
    active operations, each tool controller just before its first operation."""

    class _WorkOffset:
        Name = "Fixture"

        def __init__(self, label, path):
            self.Label = label
            self.Path = path

    import Path
    clearance = job.Stock.Shape.BoundBox.ZMax + job.SetupSheet.ClearanceHeightOffset.Value
    out = []
    for fixture in job.Fixtures:
        out.append(_WorkOffset(fixture, Path.Path([Path.Command(fixture), Path.Command("G0", {"Z": clearance})])))
        current = None
        for op in job.Operations.Group:
            if not op_active(op):
                continue
            tc = tool_controller_of(op)
            if tc is not None and tc is not current:
                out.append(tc)
                current = tc
            out.append(op)
    return out


def op_property(op, name):
    """A property of an operation, or of the operation a dressup is based on (None if absent)."""
    return _path_util().opProperty(op, name)


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
    try:
        from Path.Tool import Controller  # FreeCAD 1.x
    except ImportError:
        from PathScripts import PathToolController as Controller  # FreeCAD 0.20
    tc = Controller.Create(label, toolNumber=number)
    job.Proxy.addToolController(tc)
    return tc
