"""AeroNC's own Path operations, one per operation type of the machining chain's units.

  base                   MachiningOperation: unit JSON, parameters, user edits, execute()
  moves                  the toolpath generator's moves as Path commands
  generalised_pocket     pocket clearing of contour and island loops; rest machining of corners
  profile                passes along a drive loop (walls, outer contours, open edges)
  drilling               G81/G82/G83 drill cycles
  helical_interpolation  holes milled down a helix with an end mill
  chamfer                a chamfer mill's pass along an edge (countersinks, chamfers along outlines)

They are Path::FeaturePython objects with a Path, in a Job's Operations group: FreeCAD's post
framework, the Job's commands and the 3-D view treat them like Path's own operations.
"""
from aeronc import pathcompat
from aeronc.objects.base import attach_views, proxy_type


def _classes():
    from aeronc.operations.drilling import Drilling
    from aeronc.operations.generalised_pocket import GeneralisedPocket
    from aeronc.operations.helical_interpolation import HelicalInterpolation
    from aeronc.operations.profile import Profile
    from aeronc.operations.chamfer import Chamfer
    return {"pocket": GeneralisedPocket, "rest": GeneralisedPocket, "profile": Profile,
            "drilling": Drilling, "helix": HelicalInterpolation, "chamfer": Chamfer}


# The chain's operation names, and the words a template may use for the same operation.
ALIASES = {"pocket": "pocket", "pocketing": "pocket", "clearing": "pocket",
           "rest": "rest", "corner": "rest", "corners": "rest", "rest_machining": "rest",
           "profile": "profile", "contour": "profile", "wall": "profile",
           "drilling": "drilling", "drill": "drilling",
           "helix": "helix", "helical": "helix", "interpolation": "helix", "helical_interpolation": "helix",
           "circular_interpolation": "helix", "chamfer": "chamfer", "countersink": "chamfer"}


def operation_class(operation):
    """The class of an operation name of the chain; ValueError for a name no class machines."""
    kind = ALIASES.get(str(operation).lower())
    if kind is None:
        raise ValueError("no Path operation for the unit operation '{}'".format(operation))
    return _classes()[kind]


TYPES = {"AeroNC::GeneralisedPocket", "AeroNC::Profile", "AeroNC::Drilling", "AeroNC::HelicalInterpolation",
         "AeroNC::Chamfer"}


def is_machining_operation(obj):
    return proxy_type(obj) in TYPES


def create(doc, unit, label):
    """A new operation (not yet in a Job, no unit yet) of the unit's operation type."""
    cls = operation_class(unit.get("operation", ""))
    obj = pathcompat.create_path_object(doc, cls.__name__)
    cls(obj)
    obj.Active = True
    obj.Label = label
    attach_views([obj])
    return obj
