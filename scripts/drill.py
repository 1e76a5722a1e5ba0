"""The drilling run on a generated wing skin, headless, against the installed addon:

    HOME=<a FreeCAD home with AeroNC installed> AERONC_OUT=out/drill freecadcmd scripts/drill.py

(`scripts/run.sh drill` does this.) A generated wing-skin panel (curved chordwise, radius
1.2 m) with four rows of fifteen 4.8 mm holes (aeronc.tests.parts.wing_skin); its datum holes
(the first, middle and last hole of every row, twelve); then aeronc.runs.drilling_run: the
camera program, a measurement file from a simulated camera (the part moved, scaled and bent as
an assembly would leave it, plus 10 um of camera noise), the import through the transform
chain, the compensation of the 48 other holes, the drilling program and the report, all in
AERONC_OUT (see aeronc/runs/drilling_run.py for the list). Prints how far the drilled holes
land from where assembly put them, compensated and nominal. Exit code 0 on success, 1 with the
failed stage named.
"""
import math
import os
import random


def assembled(p):
    """Where assembly put a point p of the nominal skin (part frame, mm): a rigid offset and a
    small turn, a 0.3 per mille scale, and a sag of the skin between its ends."""
    x, y, z = p
    turn = math.radians(0.03)
    x, y = x * math.cos(turn) - y * math.sin(turn), x * math.sin(turn) + y * math.cos(turn)
    sag = 0.6 * math.sin(math.pi * (x + 200.0) / 400.0) * (0.5 + y / 720.0)
    return (1.0003 * x + 0.42, 1.0003 * y - 0.25 + 0.1 * math.sin(x / 150.0), z + 0.15 + sag)


def main():
    import sys

    import FreeCAD

    from aeronc.drilling import compensation, hole_geometry
    from aeronc.errors import AeroNCError
    from aeronc.runs import drilling_run
    from aeronc.tests.parts import wing_skin

    solid, truth = wing_skin.make_wing_skin()
    last = truth["spec"]["holes_per_row"] - 1

    def place(h):  # (row, index) of a found hole, from the generator's truth
        t = min(truth["holes"], key=lambda t: (t["entry"] - h["entry"]).Length)
        return t["row"], t["index"]
    # Datum holes in camera order: each row's first, middle and last hole, rows in turn.
    holes = hole_geometry.find_holes(solid, 20.0)
    datum = sorted((h for h in holes if place(h)[1] in (0, last // 2, last)), key=place)
    rng = random.Random(3)

    def camera(photo_set, _program):
        return compensation.synthetic_measurements(
            photo_set, lambda p: tuple(c + rng.gauss(0.0, 0.01) for c in assembled(p)))

    try:
        data = drilling_run.run(os.environ.get("AERONC_OUT", "out/drill"), solid, [h["faces"][0] for h in datum],
                                camera, name="wing_skin", tolerance=0.7)
    except AeroNCError as e:  # a stage failed for a reason the user can act on: one line, no traceback
        print("drilling run failed: {}".format(e), file=sys.stderr)
        sys.stderr.flush()
        os._exit(1)

    def rms(pairs):
        return math.sqrt(sum((FreeCAD.Vector(*assembled(n)) - FreeCAD.Vector(*c)).Length ** 2
                             for n, c in pairs) / len(pairs))
    print("  RMS distance of the {} drilled holes from where assembly put them: {:.3f} mm compensated, "
          "{:.3f} mm nominal".format(len(data["nominal"]), rms(list(zip(data["nominal"], data["compensated"]))),
                                     rms([(n, n) for n in data["nominal"]])))


from aeronc.tests.script import run  # noqa: E402  (on the path from the installed addon)

run(main)
