"""Optimise cutting parameters of a whole Job inside FreeCAD (a benchmark, not a test):

    HOME=<a FreeCAD home with AeroNC installed> freecadcmd tools/optimise_job_bench.py

Builds a Job on a pocketed block with AERONC_BENCH_TCS ToolControllers (default 25, end mills
of 6 to 30 mm) and AERONC_BENCH_OPS operations (default 500): one real Pocket Shape and copies
of its path as Custom operations, spread over the controllers. Times propose() over the Job
(measuring every operation's path, one optimisation per controller) and apply() (writing every
controller in one undo step and recomputing the operations). Building the Job is not counted.
"""
import os
import time


def build(doc, tcs, ops):
    from aeronc import pathcompat
    from aeronc.tests import pathcompat as test_pathcompat
    from aeronc.tests.app.support import end_mill, make_pocket_job
    _, job, pocket = make_pocket_job(doc)
    controllers = []
    for i in range(tcs):
        d = 6 + 24 * i / max(1, tcs - 1)
        bit = end_mill(round(d, 1), length=80)
        controllers.append(pathcompat.create_tool_controller(doc, job, "TC {}".format(i), bit, i + 2, 8000, 1000, 300))
    pocket.ToolController = controllers[0]
    doc.recompute()
    gcode = [line for line in pocket.Path.toGCode().splitlines() if line and not line.startswith("(")]
    for k in range(ops - 1):
        op = test_pathcompat.create_custom_operation("Copy{}".format(k), gcode)
        op.ToolController = controllers[(k + 1) % tcs]
    doc.recompute()
    return job, sum(len(o.Path.Commands) for o in job.Operations.Group)


def main():
    import tempfile
    import FreeCAD
    from aeronc.pipeline import cutting_optimisation as co
    tcs = int(os.environ.get("AERONC_BENCH_TCS", "25"))
    ops = int(os.environ.get("AERONC_BENCH_OPS", "500"))
    doc = FreeCAD.newDocument("OptimiseBench")
    doc.UndoMode = 1
    t0 = time.perf_counter()
    job, commands = build(doc, tcs, ops)
    t_build = time.perf_counter() - t0
    kb_path = os.path.join(tempfile.mkdtemp(prefix="aeronc_bench_"), "kb.sqlite")
    co.propose(job.Tools.Group[1], "7050-T7451", "AC-5AX", kb_path)  # builds the knowledge base once
    times = []
    for _ in range(3):
        t0 = time.perf_counter()
        proposals = co.propose(job, "7050-T7451", "AC-5AX", kb_path)
        times.append(time.perf_counter() - t0)
    good = sum(1 for p in proposals if p.ok)
    t0 = time.perf_counter()
    co.apply(proposals)
    t_apply = time.perf_counter() - t0
    print("optimise job: {} operations ({} path commands), {} ToolControllers ({} optimised); built in {:.1f} s"
          .format(len(job.Operations.Group), commands, len(proposals), good, t_build))
    print("optimise job: propose {:.2f} s (best of 3; runs {}), target < 5 s".format(
        min(times), ", ".join("{:.2f}".format(t) for t in times)))
    print("optimise job: apply (write + recompute {} operations) {:.2f} s".format(len(job.Operations.Group), t_apply))
    FreeCAD.closeDocument(doc.Name)


main()
