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
