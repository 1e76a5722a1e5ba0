"""The main job on the embedded sample part (or AERONC_PART), headless, against the installed addon:

    HOME=<a FreeCAD home with AeroNC installed> AERONC_OUT=out/demo freecadcmd scripts/demo.py

(`scripts/run.sh demo` does this.) Runs aeronc.runs.main_job on resources/samples/sample_panel.step,
an integral panel with pockets on both faces, islands, openings, lightening and bolt holes, a
flange and a joggle: recognise -> select tools -> machining chain (optimised cutting data) ->
one Path Job per setup -> Sinumerik 840D and LinuxCNC programs -> the LinuxCNC programs re-read
by LinuxCNC's interpreter and simulated against the blank -> pictures and report.html, all in
AERONC_OUT (see aeronc/runs/main_job.py for the list). AERONC_PART=<file.step> runs the same on
another part; AERONC_MATERIAL, AERONC_MACHINE, AERONC_FAMILY and AERONC_CELL (the verification's
cell size, mm) change the defaults (7050-T7451, the smallest machine whose travel holds every setup,
integral_panel, 0.5); AERONC_PICTURES=0 skips the pictures (the corpus test); AERONC_CRIB=<file> runs
with the user's own tool crib (a knowledge-base file or a FreeCAD .fctl library, docs/tool-crib.md). Exit code 0 on success, 1 with the failed stage named.
"""
import os


def main():
    import sys

    import aeronc
    from aeronc.runs import main_job
    from aeronc.errors import AeroNCError

    part = os.environ.get("AERONC_PART") or os.path.join(aeronc.PACKAGE_DIR, "resources", "samples",
                                                          "sample_panel.step")
    try:
        cell = float(os.environ.get("AERONC_CELL", "0.5"))
    except ValueError:
        print("main job failed: AERONC_CELL must be a cell size in mm, not {!r}".format(os.environ["AERONC_CELL"]),
              file=sys.stderr)
        sys.stderr.flush()
        os._exit(1)
    try:
        main_job.run(part, os.environ.get("AERONC_OUT", "out/demo"),
                     material=os.environ.get("AERONC_MATERIAL", "7050-T7451"),
                     machine=os.environ.get("AERONC_MACHINE") or None,
                     family=os.environ.get("AERONC_FAMILY", "integral_panel"),
                     cell_size=cell, pictures=os.environ.get("AERONC_PICTURES", "1") != "0",
                     crib=os.environ.get("AERONC_CRIB") or None)
    except AeroNCError as e:  # a stage failed for a reason the user can act on: one line, no traceback
        print("main job failed: {}".format(e), file=sys.stderr)
        sys.stderr.flush()
        os._exit(1)


from aeronc.tests.script import run  # noqa: E402  (on the path from the installed addon)

run(main)
