"""The one place that imports FreeCAD's Path (CAM) modules.

FreeCAD 0.20 ships them as `PathScripts.*`; FreeCAD 1.x renamed the workbench to CAM and
moved them to `Path.Op.*`, `Path.Main.*`. Every other AeroNC module goes through the
functions here, so supporting another FreeCAD release means changing this file only.
Imports are lazy: loading the Path modules is slow and is not needed to recognise features.
"""
import contextlib

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
    """Create a Path Job for the given part objects with the default stock. In the GUI it gets
    Path's view provider, without the Job's own undo transaction or task panel, so that the
    caller's transaction holds it."""
    if FreeCAD.ActiveDocument is not doc:
        FreeCAD.setActiveDocument(doc.Name)
    with _app_tool_bit_factory():  # the Job's default ToolController makes a ToolBit
        job = _job_module().Create(name, list(models))
    if FreeCAD.GuiUp:
        try:
            from Path.Main.Gui import Job as JobGui  # FreeCAD 1.x
        except ImportError:
            from PathScripts import PathJobGui as JobGui  # FreeCAD 0.20
        job.ViewObject.Proxy = JobGui.ViewProvider(job.ViewObject)
        job.ViewObject.addExtension("Gui::ViewProviderGroupExtensionPython")
    return job


def _tool_bit_module():
    try:
        from Path.Tool import Bit  # FreeCAD 1.x
        return Bit
    except ImportError:
        from PathScripts import PathToolBit  # FreeCAD 0.20
        return PathToolBit


def _tool_controller_module():
    try:
        from Path.Tool import Controller  # FreeCAD 1.x
        return Controller
    except ImportError:
        from PathScripts import PathToolController  # FreeCAD 0.20
        return PathToolController


@contextlib.contextmanager
def _app_tool_bit_factory():
    """The GUI replaces the ToolBit module's factory with one that commits an undo transaction
    of its own; inside this block the App factory is used, so bits join the caller's one."""
    mod = _tool_bit_module()
    gui_factory = mod.Factory
    mod.Factory = mod.ToolBitFactory()
    try:
        yield
    finally:
        mod.Factory = gui_factory


def jobs_of_part(doc, part):
    """The Jobs whose model holds part (directly or as the clone a Job makes of it)."""
    out = []
    for job in find_jobs(doc):
        for m in job_models(job):
            if m is part or part in (getattr(m, "Objects", None) or []):
                out.append(job)
                break
    return out


def tool_controllers(job):
    tools = getattr(job, "Tools", None)
    return list(tools.Group) if tools is not None else []


def create_tool_controller(doc, job, label, bit_attrs, number, spindle_rpm, horiz_feed, vert_feed):
    """A ToolBit from a .fctb document (dict) and a ToolController for it in job.

    Feeds are in mm/min, the spindle speed in r/min."""
    if FreeCAD.ActiveDocument is not doc:
        FreeCAD.setActiveDocument(doc.Name)
    mod = _tool_bit_module()
    with _app_tool_bit_factory():
        bit = mod.Factory.CreateFromAttrs(bit_attrs, "ToolBit")
    _set_bit_attributes(bit, bit_attrs.get("attribute") or {})
    if FreeCAD.GuiUp:
        try:
            from Path.Base.Gui import IconViewProvider  # FreeCAD 1.x
        except ImportError:
            from PathScripts import PathIconViewProvider as IconViewProvider  # FreeCAD 0.20
        IconViewProvider.Attach(bit.ViewObject, "ToolBit")
        bit.ViewObject.Visibility = False
    tc = _tool_controller_module().Create(label, tool=bit, toolNumber=number)
    tc.SpindleSpeed = float(spindle_rpm)
    tc.HorizFeed = "{} mm/min".format(horiz_feed)
    tc.VertFeed = "{} mm/min".format(vert_feed)
    job.Proxy.addToolController(tc)
    return tc


def add_tool_controller(job, label, number):
    """A new ToolController with FreeCAD's default tool bit in the Job (the caller sets the bit's
    diameter, speeds and feeds)."""
    tc = _tool_controller_module().Create(label, toolNumber=number)
    job.Proxy.addToolController(tc)
    return tc


def _set_bit_attributes(bit, attributes):
    """FreeCAD 0.20's CreateFromAttrs drops a bit file's "attribute" section (Flutes, Material,
    ...): set the ones the bit's shape defines. An enumeration takes its option whatever the case."""
    for name, value in attributes.items():
        if name not in bit.PropertiesList:
            continue
        if bit.getTypeIdOfProperty(name) == "App::PropertyEnumeration":
            options = {o.lower(): o for o in bit.getEnumerationsOfProperty(name)}
            value = options.get(str(value).lower())
            if value is None:
                continue
        try:
            setattr(bit, name, value)
        except (TypeError, ValueError) as e:
            FreeCAD.Console.PrintWarning("AeroNC: tool bit {}: attribute {} = {!r} not set: {}\n".format(
                bit.Label, name, value, e))


def remove_tool_controller(doc, tc):
    """Remove a ToolController and its ToolBit."""
    bit = getattr(tc, "Tool", None)
    doc.removeObject(tc.Name)
    if bit is not None and doc.getObject(bit.Name) is not None and not bit.InList:
        doc.removeObject(bit.Name)


def tool_controller_in_use(tc):
    """True when an operation refers to this ToolController."""
    return any(hasattr(o, "ToolController") and o.ToolController is tc for o in tc.InList)


def default_tool_library_folder():
    """The folder holding FreeCAD's tool folders (Bit, Library, Shape) the user works with."""
    try:
        from Path import Preferences  # FreeCAD 1.x
    except ImportError:
        from PathScripts import PathPreferences as Preferences  # FreeCAD 0.20
    import os
    last = Preferences.lastPathToolLibrary()
    return os.path.dirname(last) if last else ""


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


# --- Operations and their tool controllers ---------------------------------------------------

# Operations that make holes point by point; the milling force and roughness model does not
# describe them. Class names are the same in FreeCAD 0.20 (PathScripts) and 1.x (Path.Op).
_HOLE_OPERATIONS = {"ObjectDrilling", "ObjectHelix", "ObjectThreadMilling", "ObjectProbing", "ObjectTapping"}


def is_hole_operation(op):
    """True for drilling, helix, thread milling, tapping and probing (or a dressup of one)."""
    return any(type(getattr(o, "Proxy", None)).__name__ in _HOLE_OPERATIONS for o in _base_chain(op))


def job_of(obj):
    """The Job a ToolController or operation belongs to, or None."""
    for o in getattr(obj, "InListRecursive", []):
        if is_job(o):
            return o
    return None


def tooled_operations(job):
    """The Job's active operations (dressups as listed in the Job) that use a ToolController."""
    ops = getattr(job, "Operations", None)
    return [op for op in (ops.Group if ops is not None else [])
            if op_active(op) and tool_controller_of(op) is not None]


def add_scripted_operation(doc, name):
    """A new Path object whose Path an AeroNC proxy computes (FreeCAD 0.20 and 1.x both call
    the type Path::FeaturePython); the caller adds it to a Job's Operations."""
    return doc.addObject("Path::FeaturePython", name)


# --- Jobs and operations of the machining chain ---------------------------------------------

def command(name, params=None):
    """One Path command (a comment when name is in parentheses); parameters as FreeCAD's."""
    import Path
    return Path.Command(name, dict(params or {}))


def path_from_commands(commands=()):
    """A Path of Path commands (empty without them)."""
    import Path
    return Path.Path(list(commands))


def path_of(commands):
    """A Path from (name, parameters) pairs; parameters are FreeCAD's (lengths mm, feeds mm/s)."""
    import Path
    return Path.Path([Path.Command(name, params) for name, params in commands])


def path_from_gcode(text):
    """A Path from G-code text, one command per line (parsed by FreeCAD, not in Python)."""
    import Path
    p = Path.Path()
    p.setFromGCode(text)
    return p


def set_job_post(job, name, args=""):
    """Post the Job with the FreeCAD post `name` (as FreeCAD lists it, without "_post") and its
    arguments. False, and the Job unchanged, when FreeCAD does not list that post."""
    if name not in job.getEnumerationsOfProperty("PostProcessor"):
        return False
    job.PostProcessor = name
    job.PostProcessorArgs = args
    return True


def create_path_object(doc, name):
    """A new Path::FeaturePython object (an operation's container) in doc; in the GUI it gets
    Path's own view provider, which draws its Path."""
    import Path  # noqa: F401  registers the Path object types
    return doc.addObject("Path::FeaturePython", name)


def add_operation(job, op, before=None):
    """Put op into the Job's Operations (before another operation, or last)."""
    job.Proxy.addOperation(op, before)


def job_operations(job):
    ops = getattr(job, "Operations", None)
    return list(ops.Group) if ops is not None else []


def set_job_operations(job, ops):
    """Order the Job's Operations group (ops: the objects in their new order)."""
    job.Operations.Group = list(ops)


def set_model_placement(job, placement):
    """Place every model clone of the Job: placement applies to the part's own placement."""
    for clone in job_models(job):
        originals = getattr(clone, "Objects", None) or []
        base = originals[0].Placement if originals else FreeCAD.Placement()
        clone.Placement = placement.multiply(base)


def set_job_stock_box(job, box):
    """Replace the Job's stock by a box (xmin, ymin, zmin, xmax, ymax, zmax) in the Job's frame."""
    try:
        from Path.Main import Stock  # FreeCAD 1.x
    except ImportError:
        from PathScripts import PathStock as Stock  # FreeCAD 0.20
    doc = job.Document
    if FreeCAD.ActiveDocument is not doc:
        FreeCAD.setActiveDocument(doc.Name)
    old = job.Stock
    extent = FreeCAD.Vector(box[3] - box[0], box[4] - box[1], box[5] - box[2])
    stock = Stock.CreateBox(job, extent, FreeCAD.Placement(FreeCAD.Vector(box[0], box[1], box[2]), FreeCAD.Rotation()))
    stock.Label = old.Label if old is not None else "Stock"
    job.Stock = stock
    if FreeCAD.GuiUp and stock.ViewObject:
        stock.ViewObject.Visibility = False
    if old is not None and doc.getObject(old.Name) is not None:
        doc.removeObject(old.Name)
    return stock


def set_job_stock_object(job, stock):
    """Make a document object with a Shape (a revolved blank) the Job's Stock, removing the stock
    the Job had. Path's own stock kinds are boxes, cylinders and grown models; FreeCAD lists
    another object's kind as "Unknown" and uses its shape like theirs."""
    doc = job.Document
    old = job.Stock
    job.Stock = stock
    if old is not None and old is not stock and doc.getObject(old.Name) is not None:
        doc.removeObject(old.Name)
    return stock


def job_height_offsets(job):
    """(safe height offset, clearance height offset) of the Job's setup sheet, mm."""
    sheet = getattr(job, "SetupSheet", None)
    if sheet is None:
        return 3.0, 5.0
    return sheet.SafeHeightOffset.Value, sheet.ClearanceHeightOffset.Value


def remove_job(job):
    """Remove a Job with everything it holds (operations, tool controllers, stock, model
    clones, setup sheet), as Path's own Delete does."""
    doc = job.Document
    job.Proxy.onDelete(job)
    if doc.getObject(job.Name) is not None:
        doc.removeObject(job.Name)
