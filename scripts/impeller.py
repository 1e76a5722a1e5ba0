"""The impeller run on a generated impeller, headless, against the installed addon:

    HOME=<a FreeCAD home with AeroNC installed> AERONC_OUT=out/impeller freecadcmd scripts/impeller.py

(`scripts/run.sh impeller` does this.) Generates a 2 x 9 impeller with its truth
(aeronc.tests.parts.impeller_part) and runs aeronc.runs.impeller_run on it:
programmed in FreeCAD by Program impeller (recognition nodes, blank as the Job's stock, the
route's operations with 5-axis toolpaths, cutting data from the optimiser, the 840D program),
the document saved, the program re-read and checked, pictures and report.html in AERONC_OUT
(see aeronc/runs/impeller_run.py for the list). AERONC_IMPELLER_SPEC (JSON, ImpellerSpec's keys),
AERONC_ALLOWANCE (mm), AERONC_STATIONS and AERONC_CHANNELS (0: all) change the defaults.
AERONC_PART (a STEP file) runs it on that part instead (e.g. ../shared/data/impeller/
turbo3d_impeller.step: its 11 bodies are fused first).
Exit code 0 on success, 1 with the failed stage named.
"""
import os


def main():
    import json
    import sys

    from aeronc.errors import AeroNCError
    from aeronc.runs import impeller_run
    from aeronc.tests.parts import impeller_part

    try:
        part_file = os.environ.get("AERONC_PART")
        if part_file:  # a part made elsewhere: no truth; several bodies are fused first
            import Part
            shape, truth, source = Part.read(part_file), None, part_file
        else:
            spec = json.loads(os.environ.get("AERONC_IMPELLER_SPEC") or "{}")
            shape, truth = impeller_part.make_test_impeller(spec)
            source = "generated impeller, spec {}".format(json.dumps(spec) if spec else "default (2 x 9 blades)")
        impeller_run.run(os.environ.get("AERONC_OUT", "out/impeller"), shape, truth, source=source,
                         allowance=float(os.environ.get("AERONC_ALLOWANCE", "2.0")),
                         stations=int(os.environ.get("AERONC_STATIONS", "24")),
                         channels=int(os.environ.get("AERONC_CHANNELS", "0")))
    except AeroNCError as e:  # a stage failed for a reason the user can act on: one line, no traceback
        print("impeller run failed: {}".format(e), file=sys.stderr)
        sys.stderr.flush()
        os._exit(1)


from aeronc.tests.script import run  # noqa: E402  (on the path from the installed addon)

run(main)
