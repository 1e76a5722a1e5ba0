"""The drilling run, headless: datum holes, camera program, measurements, compensated drilling.

    part -> photo-hole set (the datum holes, in camera order) -> camera program (APT and NC)
    -> measurement file (from the camera) -> measured-hole set -> compensated drilling
    -> drilling program -> compensation report -> document

run() writes into one output folder:
  <name>.FCStd                    the document: part, photo-hole set, measured-hole set, Job
  camera.apt, camera.mpf          the camera program (APT CL; NC posted for the camera machine)
  measured_datum_holes.csv        the measurement file the camera gave back
  compensation_report.html/.png   the compensation report and its picture of the deviations
  drilling.mpf, drilling.apt      the compensated drilling program (840D for the machine) and its APT
  freecad.log                     what FreeCAD printed meanwhile
A second run replaces the outputs of the first (the files listed in .aeronc-outputs).
"""
from aeronc.runs.stages import Run, RunError

__all__ = ["run", "RunError"]


def run(out, shape, datum_faces, camera, name="part", tolerance=None, machine="AC-HEAD", say=None):
    """Program the drilling of `shape` (a Part shape) with the datum holes `datum_faces` (face
    names, in camera order). camera(photo_set, camera_program_path) plays the camera: it returns
    the measurement file's text for the datum holes the camera program visits. tolerance (mm):
    corrections beyond it are flagged for a look. Returns the run's data; raises RunError naming
    the stage that failed."""
    r = Run(out, say)
    with r.console():
        r.say("AeroNC drilling run: {} ({} datum holes) -> {}".format(name, len(datum_faces), r.out))
        data = _stages(r, shape, datum_faces, camera, name, tolerance, machine)
        r.say("  {:>6.1f} s  total; report: {}".format(r.total(), r.path("compensation_report.html")))
    return data


def _stages(r, shape, datum_faces, camera, name, tolerance, machine):
    from aeronc import pathcompat
    from aeronc.drilling import compensation
    from aeronc.makers import datum_holes
    from aeronc.post import apt, nc_post
    from aeronc.reports import compensation_report

    with r.stage("part"):
        doc = r.new_document("Drilling")
        part = doc.addObject("Part::Feature", "Part")
        part.Label = name
        part.Shape = shape
        doc.recompute()
    r.report("{} faces".format(len(shape.Faces)))

    with r.stage("datum holes"):
        ps = datum_holes.create_photo_hole_set(doc, part, list(datum_faces))
    r.report("{} datum holes in {} rows ({}); spacing warnings: {}".format(
        len(ps.HoleIds), ps.RowCount, ", ".join(ps.HoleIds), "; ".join(ps.SpacingWarnings) or "none"))

    with r.stage("camera program"):
        apt_text, nc_text = compensation.camera_program(ps, r.path("camera.apt"), r.path("camera.mpf"))
        r.wrote("camera.apt", "camera.mpf")
    r.report("{} APT lines, {} NC lines (machine {})".format(len(apt_text.splitlines()), len(nc_text.splitlines()),
                                                            ps.Machine))

    with r.stage("measurements"):
        r.write("measured_datum_holes.csv", camera(ps, r.path("camera.apt")))
        ms = datum_holes.import_measurements(ps, r.path("measured_datum_holes.csv"))
        if tolerance is not None:
            ms.Tolerance = tolerance
        doc.recompute()
    r.report(ms.Status)
    for line in ms.DatumFlags:
        r.say("           datum hole " + line)
    for line in ms.LeaveOneOut:
        r.say("           leave-one-out " + line)

    with r.stage("compensated drilling"):
        job = pathcompat.create_job(doc, [part])
        doc.recompute()
        op = datum_holes.create_compensated_drilling(job, ps, ms)
        objects = pathcompat.job_post_objects(job)
        nc_post.export(objects, r.path("drilling.mpf"), "--machine {}".format(machine), "840d")
        apt.export(objects, r.path("drilling.apt"), "")
        r.wrote("drilling.mpf", "drilling.apt")
    r.report(op.Status)

    with r.stage("report"):
        report = compensation_report.write_report(op, r.path("compensation_report.html"),
                                                  r.path("compensation_report.png"))
        r.wrote("compensation_report.html", "compensation_report.png")
        r.save_document(doc, "{}.FCStd".format(name))
    r.report(report)
    r.finish()
    return {"datumHoles": list(ps.HoleIds), "leftOut": list(ms.LeftOut), "measurements": ms.Status,
            "drilling": op.Status, "flags": list(op.Flags), "report": report,
            "nominal": [tuple(v) for v in op.NominalPositions],
            "compensated": [tuple(v) for v in op.CompensatedPositions]}
