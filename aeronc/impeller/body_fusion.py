"""A part exported as several bodies (an impeller's hub and each blade a body of its own) made
one solid, so that recognition can run on it.

A plain multi-argument fuse of the shared 11-body impeller gives two solids and an invalid
B-rep in 17 s: its blades touch the hub only to the exporter's tolerance. Here each body is
fused to the growing solid alone with a fuzzy value, the faces of one surface merged again
(Part's removeSplitter), and the step kept only when it leaves one valid solid. Bodies of almost
no volume (slivers an exporter leaves) are dropped.
"""
from aeronc.errors import RecognitionError

FUZZY_VALUES = (1e-3, 1e-2)  # mm: the first that gives one valid solid
SLIVER_SHARE = 1e-4          # of the largest body's volume


def fuse_bodies(shape, label="shape", progress=None):
    """One valid solid from the solids of `shape`: (solid, summary text).

    Raises RecognitionError when the shape holds no solid or a body does not fuse with the
    others into one valid solid at any fuzzy value."""
    bodies = sorted(shape.Solids, key=lambda s: -abs(s.Volume))
    if not bodies:
        raise RecognitionError("{}: holds no solid to fuse".format(label))
    largest = abs(bodies[0].Volume)
    solid, fused, dropped, fuzzy_used = bodies[0], 1, 0, 0.0
    for i, body in enumerate(bodies[1:], start=2):
        if abs(body.Volume) < SLIVER_SHARE * largest:
            dropped += 1
            continue
        if progress:
            progress(i, len(bodies))
        step = None
        for fuzzy in FUZZY_VALUES:
            result = solid.fuse(body, fuzzy).removeSplitter()
            if len(result.Solids) == 1 and result.Solids[0].isValid():
                step = result.Solids[0]
                fuzzy_used = max(fuzzy_used, fuzzy)
                break
        if step is None:
            raise RecognitionError(
                "{}: body {} of {} (by volume) does not fuse with the others into one valid solid; "
                "it may not touch them".format(label, i, len(bodies)))
        solid = step
        fused += 1
    summary = "{} bodies: {} fused into one solid".format(len(bodies), fused)
    if dropped:
        summary += ", {} degenerate (no volume) left out".format(dropped)
    return solid, summary + " (fuzzy value {:g} mm)".format(fuzzy_used)
