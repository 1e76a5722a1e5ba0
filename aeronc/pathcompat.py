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
