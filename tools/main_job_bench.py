"""The main job on the sample panel, stage by stage (a benchmark, not a test):

    HOME=<a FreeCAD home with AeroNC installed> freecadcmd tools/main_job_bench.py

Runs aeronc.runs.main_job AERONC_BENCH_RUNS times (default 2) into a temporary folder and
prints each stage's time (min / median / max over the runs), pictures and verification among
them, and the total. docs/benchmarks.md holds the figures.
"""
import os
import statistics
import tempfile


def main():
    import aeronc
    from aeronc.runs import main_job
    part = os.path.join(aeronc.PACKAGE_DIR, "resources", "samples", "sample_panel.step")
    runs = int(os.environ.get("AERONC_BENCH_RUNS", "2"))
    times = {}
    for _ in range(runs):
        with tempfile.TemporaryDirectory(prefix="aeronc_main_job_bench_") as out:
            data = main_job.run(part, out, say=lambda _: None)
        for name, seconds in data["stages"]:
            times.setdefault(name, []).append(seconds)
        times.setdefault("total", []).append(sum(s for _, s in data["stages"]))
    print("main job on the sample panel, {} run(s): stage  min / median / max (s)".format(runs))
    for name, ts in times.items():
        print("  {:<16s} {:7.2f} {:7.2f} {:7.2f}".format(name, min(ts), statistics.median(ts), max(ts)))


from aeronc.tests.script import run  # noqa: E402  (on the path from the installed addon)

run(main)
