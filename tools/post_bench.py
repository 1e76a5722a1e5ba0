"""Post speed inside FreeCAD: lines/second of AeroNC's posts and of FreeCAD's linuxcnc_post on
the same Job of >= 200,000 moves, in one run (a benchmark, not a test):

    HOME=<a FreeCAD home with AeroNC installed> freecadcmd tools/post_bench.py

AERONC_BENCH_MOVES sets the number of moves (default 200000). Each post writes its program to
a file, as in the GUI; times are the post's export() call alone (building the Job is not
counted). Prints one line per post and the ratio to linuxcnc_post.
"""
import math
import os
import tempfile
import time


def build(doc, moves, oriented):
    import Path
    from aeronc import pathcompat
    box = doc.addObject("Part::Box", "Blank")
    box.Length, box.Width, box.Height = 100, 100, 20
    doc.recompute()
    job = pathcompat.create_job(doc, [box])
    doc.recompute()
    tc = job.Tools.Group[0]
    tc.HorizFeed, tc.VertFeed, tc.SpindleSpeed = "1200 mm/min", "300 mm/min", 12000
    cmds = [Path.Command("G0", {"Z": 30.0})]
    for i in range(moves):
        t = i * 0.002
        az = math.fmod(t, 2 * math.pi)
        p = {"X": 40 * math.cos(az), "Y": 40 * math.sin(az), "Z": -5 + 3 * math.sin(t), "F": 20.0}
        if oriented:  # a swarf-like sweep with the tool tilted 20..40 degrees
            tilt = math.radians(30 + 10 * math.sin(t * 0.37))
            p.update(U=math.sin(tilt) * math.cos(az), V=math.sin(tilt) * math.sin(az), W=math.cos(tilt))
        cmds.append(Path.Command("G1" if i % 500 else "G0", p))
    op = doc.addObject("Path::FeaturePython", "Sweep")
    op.addProperty("App::PropertyLink", "ToolController", "Path")
    op.ToolController = tc
    op.Path = Path.Path(cmds)
    job.Operations.addObject(op)
    doc.recompute()
    return job


def timed(post, objects, filename, args):
    t0 = time.perf_counter()
    text = post.export(objects, filename, args)
    return time.perf_counter() - t0, text.count("\n")


def main():
    import FreeCAD
    from aeronc import pathcompat
    from aeronc.tests import pathcompat as test_pathcompat
    linuxcnc_post = test_pathcompat.builtin_post("linuxcnc")

    moves = int(os.environ.get("AERONC_BENCH_MOVES", "200000"))
    out = tempfile.mkdtemp(prefix="aeronc_post_bench_")
    for oriented in (False, True):
        doc = FreeCAD.newDocument("Bench")
        job = build(doc, moves, oriented)
        objects = pathcompat.job_post_objects(job)
        print("{} moves, {}:".format(moves, "5-axis (tool axis U V W on every move)" if oriented
                                     else "3-axis (FreeCAD's own kind)"))
        base_t, base_lines = timed(linuxcnc_post, objects, os.path.join(out, "linuxcnc_post.ngc"), "--no-show-editor")
        base = base_lines / base_t
        note = " (ignores the tool axis)" if oriented else ""
        print("  {:<34} {:>8} lines {:7.2f} s {:>10.0f} lines/s{}".format("FreeCAD linuxcnc_post", base_lines, base_t, base, note))
        for name, args, ext in (("aeronc_linuxcnc", "", "ngc"), ("aeronc_840d", "", "mpf")):
            t, lines = timed(test_pathcompat.post_processor(name), objects, os.path.join(out, name + "." + ext), args)
            print("  {:<34} {:>8} lines {:7.2f} s {:>10.0f} lines/s  {:5.1f}x linuxcnc_post".format(
                name, lines, t, lines / t, (lines / t) / base))
        FreeCAD.closeDocument(doc.Name)


from aeronc.tests.script import run  # noqa: E402  (on the path from the installed addon)

run(main)
