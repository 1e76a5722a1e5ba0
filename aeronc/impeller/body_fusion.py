"""A part exported as several bodies (an impeller's hub and each blade a body of its own) made
one solid, so that recognition can run on it.

A plain multi-argument fuse of the shared 11-body impeller gives two solids and an invalid
B-rep in 17 s: its blades touch the hub only to the exporter's tolerance. Here each body is
fused to the growing solid alone (a copy) with a fuzzy value, the faces of one surface merged again
(Part's removeSplitter), and the step kept only when it leaves one valid solid. Bodies of almost
no volume (slivers an exporter leaves) are dropped.
"""
from aeronc.errors import RecognitionError

FUZZY_VALUES = (1e-3, 1e-2, 5e-2)  # mm: the first that gives one valid solid
SLIVER_SHARE = 1e-4          # of the largest body's volume
MAX_ORDERS = 4               # orders of the bodies tried before giving up


def fuse_bodies(shape, label="shape", progress=None):
    """One valid solid from the solids of `shape`: (solid, summary text).

    Raises RecognitionError when the shape holds no solid or a body does not fuse with the
    others into one valid solid at any fuzzy value, in any of the orders tried."""
    bodies = sorted(shape.Solids, key=lambda s: -abs(s.Volume))
    if not bodies:
        raise RecognitionError("{}: holds no solid to fuse".format(label))
    largest = abs(bodies[0].Volume)
    kept = [b for b in bodies[1:] if abs(b.Volume) >= SLIVER_SHARE * largest]
    dropped = len(bodies) - 1 - len(kept)
    # Whether a blade fuses validly depends on what is fused already (the exporter's gaps are
    # closed by the fuzzy value one neighbour at a time): the largest first, then the others
    # by volume, in reverse, or starting further round.
    orders = [kept, kept[::-1]] + [kept[k:] + kept[:k] for k in range(1, min(len(kept), MAX_ORDERS))]
    failure = None
    for order in orders:
        try:
            solid, fuzzy = _fuse_in_order(bodies[0], order, label, len(bodies), dropped, progress)
        except RecognitionError as e:
            failure = failure or e
            continue
        summary = "{} bodies: {} fused into one solid".format(len(bodies), len(order) + 1)
        if dropped:
            summary += ", {} degenerate (no volume) left out".format(dropped)
        return solid, summary + " (fuzzy value {:g} mm)".format(fuzzy)
    raise failure


def _fuse_in_order(first, order, label, total, dropped, progress):
    # Copies: a fuse raises the tolerances of its arguments' edges and vertices in place, which
    # would change the caller's shape and the next attempt.
    solid, fused, fuzzy_used = first.copy(), 1, 0.0
    pending = list(enumerate(order, start=2))
    while pending:
        if progress:
            progress(fused + dropped + 1, total)
        # A body that does not fuse yet may once its neighbours have (they bridge the gap).
        for k, (i, body) in enumerate(pending):
            step = None
            for fuzzy in FUZZY_VALUES:
                result = solid.fuse(body.copy(), fuzzy).removeSplitter()
                if len(result.Solids) == 1 and result.Solids[0].isValid():
                    step = result.Solids[0]
                    fuzzy_used = max(fuzzy_used, fuzzy)
                    break
            if step is not None:
                solid = step
                fused += 1
                del pending[k]
                break
        else:
            raise RecognitionError(
                "{}: body {} of {} (by volume) does not fuse with the others into one valid solid; "
                "it may not touch them".format(label, pending[0][0], total))
    return solid, fuzzy_used
