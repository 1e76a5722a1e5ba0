"""Generated impellers with their known truth (the core's testparts generator), for the tests
and the impeller run's script; not part of a user's install."""
import json

from aeronc.errors import RecognitionError, from_core


def make_test_impeller(spec=None):
    """A generated impeller: (Part shape, truth dict). spec: ImpellerSpec fields as a dict
    (bladeCount, splitters, filletRadius, ...); unknown keys are refused."""
    import Part
    from aeronc import _core as core
    with from_core(RecognitionError, "generated impeller"):
        brep, truth = core.make_impeller(json.dumps(spec or {}))
    shape = Part.Shape()
    shape.importBrepFromString(brep)
    return shape, json.loads(truth)
