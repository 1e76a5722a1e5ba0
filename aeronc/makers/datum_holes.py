"""Makers of the drilling objects: the photo-hole set, the measured-hole set and the
compensated drilling operation. Each is one undo step; the holes and the measurements are read
and checked before the document is touched, so a refused selection or file leaves it as it was.
Under the GUI the new objects get their views through the registered attacher.
"""
import os

import FreeCAD

from aeronc import pathcompat
from aeronc.drilling import compensation, hole_geometry
from aeronc.errors import CompensationError, HoleError
from aeronc.objects import measured_hole_set, photo_hole_set
from aeronc.objects.base import attach_views
from aeronc.objects.transaction import in_transaction
from aeronc.operations import compensated_drilling


def create_photo_hole_set(doc, part, sub_names, surface=None, label=None):
    """A new photo-hole set on part with the holes named by sub_names (faces or circular
    edges, in order) and the surface for normals (face names), in one undo step."""
    if surface:
        for s in surface:
            if not s.startswith("Face"):
                raise HoleError("the surface for normals must be faces, not {}".format(s))
    faces = hole_geometry.selected_hole_faces(part.Shape, sub_names)
    rows = [photo_hole_set.measure_hole(part, f, surface, (0, 0, 1)) for f in faces]  # fails before the document changes

    def work():
        obj = doc.addObject("App::FeaturePython", "PhotoHoleSet")
        photo_hole_set.PhotoHoleSet(obj)
        obj.Label = label or "Photo holes ({})".format(part.Label)
        obj.Source = part
        if surface:
            obj.Surface = [(part, tuple(surface))]
        for i, r in enumerate(rows):
            r["id"] = "DH{}".format(i + 1)
        obj.NextNumber = len(rows) + 1
        photo_hole_set.write_holes(obj, rows)
        # Clear of the part with the camera on its way to every datum hole.
        obj.SafeHeight = part.Shape.BoundBox.ZMax + obj.Standoff.Value + obj.Approach.Value + 30.0
        obj.Visibility = True
        attach_views([obj])
        doc.recompute([obj])
        return obj

    return in_transaction(doc, "Define datum (photo) holes", work)


def define_datum_holes(doc, part, sub_names):
    """The command: add the holes to the part's photo-hole set, or make one. Returns the set."""
    existing = photo_hole_set.photo_hole_sets_of(doc, part)
    if existing:
        photo_hole_set.add_datum_holes(existing[0], sub_names)
        return existing[0]
    return create_photo_hole_set(doc, part, sub_names)


def import_measurements(photo_set, path=None, text=None, measured_set=None, max_deviation=None, min_quality=None):
    """Import a measurement file (path, or its text) for photo_set into measured_set (updated in
    place, keeping its settings), or into the set's measured-hole set, or a new one; one undo
    step. Drilling operations of the photo-hole set without measurements are linked to it.
    Bad input raises CompensationError and leaves the document as it was. Returns the set."""
    if text is None:
        if not path:
            raise CompensationError("no measurement file given")
        text = compensation.read_measurement_file(path)
    if measured_set is None:
        existing = measured_hole_set.measured_sets_of(photo_set)
        measured_set = existing[0] if existing else None
    if max_deviation is None:
        max_deviation = measured_set.MaxDeviation.Value if measured_set is not None else 5.0
    if min_quality is None:
        min_quality = measured_set.MinQuality if measured_set is not None else 0.0
    imported = compensation.import_readings(photo_set, text, max_deviation, min_quality)
    doc = photo_set.Document

    def work():
        obj = measured_set
        if obj is None:
            obj = doc.addObject("App::FeaturePython", "MeasuredHoleSet")
            measured_hole_set.MeasuredHoleSet(obj)
            obj.Label = "Measured holes ({})".format(os.path.basename(path) if path else photo_set.Label)
            obj.Visibility = True
            attach_views([obj])
        obj.MaxDeviation = max_deviation
        obj.MinQuality = min_quality
        measured_hole_set.store_readings(obj, photo_set, imported, text, path)
        for op in compensated_drilling.operations_of(photo_set):
            if op.MeasuredHoleSet is None:
                op.MeasuredHoleSet = obj
        doc.recompute()
        return obj

    return in_transaction(doc, "Import datum-hole measurements", work)


def create_for_photo_set(photo_set, measured_set=None):
    """The compensated drilling of the set's part: the existing operation, or a new one in the
    part's Job (made when the part has none); one undo step."""
    existing = compensated_drilling.operations_of(photo_set)
    if existing:
        return existing[0]
    jobs = pathcompat.jobs_of_part(photo_set.Document, photo_set.Source)
    return create_compensated_drilling(jobs[0] if jobs else None, photo_set, measured_set)


def create_compensated_drilling(job, photo_set, measured_set=None, tool_controller=None, holes=None,
                                label="Compensated drilling"):
    """A compensated drilling operation in job (None: a new Job for the part) for the holes of
    photo_set's part (default: every hole of the part's pattern that is not a datum hole), with
    a drill tool controller made for the holes' diameter unless one is given; one undo step."""
    part = photo_set.Source
    if holes is None:
        holes = [h for h in photo_hole_set.pattern_of(photo_set) if not h["datum"]]
    if not holes:
        raise CompensationError("{} has no holes to drill besides its datum holes".format(part.Label))
    if measured_set is None:
        sets = measured_hole_set.measured_sets_of(photo_set)
        measured_set = sets[0] if sets else None
    doc = photo_set.Document

    def work():
        nonlocal job
        if job is None:
            job = pathcompat.create_job(doc, [part])
            doc.recompute()
        tc = tool_controller
        if tc is None:
            number = max([int(t.ToolNumber) for t in pathcompat.tool_controllers(job)] + [0]) + 1
            d = max(h["diameter"] for h in holes)
            tc = pathcompat.add_tool_controller(job, "TC: {:g} mm drill".format(round(d, 3)), number)
            tc.Tool.Diameter = d
            tc.Tool.Label = "Drill {:g}".format(round(d, 3))
            tc.VertFeed, tc.HorizFeed, tc.SpindleSpeed = "300 mm/min", "300 mm/min", 4000
        op = pathcompat.add_scripted_operation(doc, "CompensatedDrilling")
        compensated_drilling.CompensatedDrilling(op)
        op.Label = label
        op.ToolController = tc
        op.Source = part
        op.PhotoHoleSet = photo_set
        op.MeasuredHoleSet = measured_set
        op.HoleIds = ["H{}".format(i + 1) for i in range(len(holes))]
        op.HoleFaces = [" ".join(h["faces"]) for h in holes]
        op.NominalPositions = [FreeCAD.Vector(*h["entry"]) for h in holes]
        op.NominalNormals = [FreeCAD.Vector(*h["normal"]) for h in holes]
        op.Diameters = [float(h["diameter"]) for h in holes]
        op.Depths = [float(h["depth"]) for h in holes]
        op.SafeHeight = part.Shape.BoundBox.ZMax + 20.0
        job.Operations.addObject(op)
        attach_views([op])
        doc.recompute()
        return op

    return in_transaction(doc, "Compensated drilling", work)
