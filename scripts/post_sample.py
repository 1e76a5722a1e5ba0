"""The posts on the embedded sample panel, headless, against the installed addon:

    HOME=<a FreeCAD home with AeroNC installed> AERONC_OUT=out/post freecadcmd scripts/post_sample.py

(`scripts/run.sh post` does this.) Builds the sample Job (aeronc.tests.app.post_sample_job:
FreeCAD's Profile, 3+2 bevels, a 5-axis chamfer, holes drilled along their axes) and writes
to AERONC_OUT
  sample_panel.mpf   Sinumerik 840D program (machine AC-5AX)
  sample_panel.ngc   LinuxCNC program (machine AC-5AX)
  sample_panel.apt   APT CL file of the same job
  camera.apt, camera.mpf   camera positions over four datum holes, normal to the surface,
                     as APT and posted through the drilling/camera head (machine AC-HEAD)
  sample_panel_post.FCStd  the document
Exit code 0 on success.
"""
import os


def main():
    import FreeCAD
    import Part

    import aeronc
    from aeronc import pathcompat
    from aeronc.post import apt, nc_post
    from aeronc.post.output import write_atomically
    from aeronc.tests.app.post_sample_job import build_job, camera_apt

    out = os.path.abspath(os.environ.get("AERONC_OUT", "out/post"))
    os.makedirs(out, exist_ok=True)
    path = os.path.join(aeronc.PACKAGE_DIR, "resources", "samples", "sample_panel.step")
    doc = FreeCAD.newDocument("SamplePanel")
    part = doc.addObject("Part::Feature", "Part")
    part.Label = "sample_panel"
    part.Shape = Part.read(path)
    doc.recompute()
    job, holes = build_job(doc, part)
    objects = pathcompat.job_post_objects(job)

    written = []
    for name, post in (("sample_panel.mpf", lambda f: nc_post.export(objects, f, "--line-numbers", "840d")),
                       ("sample_panel.ngc", lambda f: nc_post.export(objects, f, "", "linuxcnc")),
                       ("sample_panel.apt", lambda f: apt.export(objects, f, ""))):
        post(os.path.join(out, name))
        written.append(name)
    datum = [h for h in holes if h["through"]][:4]
    cl = os.path.join(out, "camera.apt")
    write_atomically(cl, camera_apt(datum))
    apt.post_apt_file(cl, os.path.join(out, "camera.mpf"), "--machine AC-HEAD")
    written += ["camera.apt", "camera.mpf"]
    doc.saveAs(os.path.join(out, "sample_panel_post.FCStd"))
    print("sample panel: {} holes drilled along their axes, {} datum holes for the camera".format(len(holes), len(datum)))
    print("wrote " + ", ".join(os.path.join(out, n) for n in written))


from aeronc.tests.script import run  # noqa: E402  (on the path from the installed addon)

run(main)
