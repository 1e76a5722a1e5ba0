"""The drilling demo, headless:

    AERONC_OUT=out/drill freecadcmd <Mod>/AeroNC/aeronc/drill_demo.py

A generated wing-skin panel (curved chordwise, radius 1.2 m) with four rows of fifteen
4.8 mm holes; its photo-hole set (the first, middle and last hole of every row, twelve datum
holes); the camera programs (APT, and NC posted for the AC-HEAD); a synthetic measurement
file (the part moved, scaled and bent as an assembly would leave it, plus 10 um of camera
noise); the
import through the transform chain; the compensation of the 48 other holes (the method with
the lowest leave-one-out error); the report; the compensated drilling program. Writes to
AERONC_OUT:
  wing_skin.FCStd                 the document: part, photo-hole set, measured-hole set, Job
  camera.apt, camera.mpf          the camera program
  measured_datum_holes.csv        the synthetic measurement file
  compensation_report.html/.png   the compensation report and its picture of the deviations
  drilling.mpf, drilling.apt      the compensated drilling program (AC-HEAD, 840D) and its APT
Exit code 0 on success.
"""
import math
import os
import random
import time


def assembled(p):
    """Where assembly put a point p of the nominal skin (part frame, mm): a rigid offset and a
    small turn, a 0.3 per mille scale, and a sag of the skin between its ends."""
    x, y, z = p
    turn = math.radians(0.03)
    x, y = x * math.cos(turn) - y * math.sin(turn), x * math.sin(turn) + y * math.cos(turn)
    sag = 0.6 * math.sin(math.pi * (x + 200.0) / 400.0) * (0.5 + y / 720.0)
    return (1.0003 * x + 0.42, 1.0003 * y - 0.25 + 0.1 * math.sin(x / 150.0), z + 0.15 + sag)


def measured(seed=3, noise=0.01):
    """assembled() as the camera sees it: with a measurement noise of `noise` mm."""
    rng = random.Random(seed)

    def see(p):
        return tuple(c + rng.gauss(0.0, noise) for c in assembled(p))
    return see


def main():
    import FreeCAD

    from aeronc import compensation, compensation_report, pathcompat, wing_skin
    from aeronc.objects import compensated_drilling, measured_hole_set, photo_hole_set
    from aeronc.post import apt, nc_post
    from aeronc.post.output import write_atomically

    out = os.path.abspath(os.environ.get("AERONC_OUT", "out/drill"))
    os.makedirs(out, exist_ok=True)
    t0 = time.perf_counter()
    doc = FreeCAD.newDocument("WingSkin")
    solid, truth = wing_skin.make_wing_skin()
    part = doc.addObject("Part::Feature", "WingSkin")
    part.Label = "Wing skin"
    part.Shape = solid
    doc.recompute()
    holes = photo_hole_set.hole_geometry.find_holes(part.Shape, 20.0)
    spec = truth["spec"]
    last = spec["holes_per_row"] - 1

    def place(h):  # (row, index) of a found hole, from the generator's truth
        t = min(truth["holes"], key=lambda t: (t["entry"] - h["entry"]).Length)
        return t["row"], t["index"]
    # Datum holes in camera order: each row's first, middle and last hole, rows in turn.
    datum = sorted((h for h in holes if place(h)[1] in (0, last // 2, last)), key=place)
    ps = photo_hole_set.create_photo_hole_set(doc, part, [h["faces"][0] for h in datum])
    apt_text, nc_text = compensation.camera_program(ps, os.path.join(out, "camera.apt"),
                                                    os.path.join(out, "camera.mpf"))
    csv_path = os.path.join(out, "measured_datum_holes.csv")
    write_atomically(csv_path, compensation.synthetic_measurements(ps, measured()))
    ms = measured_hole_set.import_measurements(ps, csv_path)
    ms.Tolerance = 0.7  # corrections larger than this are flagged for a look
    doc.recompute()
    job = pathcompat.create_job(doc, [part])
    doc.recompute()
    op = compensated_drilling.create_compensated_drilling(job, ps, ms)
    report = compensation_report.write_report(op, os.path.join(out, "compensation_report.html"),
                                              os.path.join(out, "compensation_report.png"))
    objects = pathcompat.job_post_objects(job)
    nc_post.export(objects, os.path.join(out, "drilling.mpf"), "--machine AC-HEAD", "840d")
    apt.export(objects, os.path.join(out, "drilling.apt"), "")
    saved = os.path.join(out, "wing_skin.FCStd")
    if os.path.exists(saved):
        os.remove(saved)  # FreeCAD would keep the old one as a backup beside it
    doc.saveAs(saved)
    seconds = time.perf_counter() - t0

    def rms(pairs):
        return math.sqrt(sum((FreeCAD.Vector(*assembled(tuple(n))) - c).Length ** 2 for n, c in pairs) / len(pairs))
    compensated_error = rms(list(zip(op.NominalPositions, op.CompensatedPositions)))
    nominal_error = rms([(n, n) for n in op.NominalPositions])
    print("wing skin: {} holes in {} rows, {} datum holes ({}); spacing warnings: {}".format(
        len(holes), ps.RowCount, len(ps.HoleIds), ", ".join(ps.HoleIds), list(ps.SpacingWarnings) or "none"))
    print("camera program: {} APT lines, {} NC lines (machine {})".format(
        len(apt_text.splitlines()), len(nc_text.splitlines()), ps.Machine))
    print("measurements: {}".format(ms.Status))
    for line in ms.LeaveOneOut:
        print("  leave-one-out " + line)
    print("drilling: {}".format(op.Status))
    print("  RMS distance of the drilled holes from where assembly put them: {:.3f} mm compensated, "
          "{:.3f} mm nominal".format(compensated_error, nominal_error))
    print("done in {:.1f} s; wrote {} to {}".format(seconds, ", ".join(sorted(os.listdir(out))), out))
    print("report: " + report)


# freecadcmd runs a script as a module named after the file; an import must not run it.
if __name__ in ("__main__", "drill_demo"):
    from aeronc.script import run
    run(main)
