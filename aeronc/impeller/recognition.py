"""App-side wrapper of the C++ impeller core: recognition by rules and dimension analysis
(impeller paper, docs/impeller.md).

The shape crosses to `aeronc._core` as BREP text, unchanged, so the face numbers in the result
are the source's FaceN. Every failure becomes `RecognitionError` with the core's message (not an
impeller, unequal blade groups, missing hub, ...).
"""
import json

from aeronc.errors import RecognitionError, from_core
from aeronc.pipeline.recognition import _core, check_solid, shape_of


def recognise(source):
    """Recognise and measure the impeller in a Part shape or a document object.

    Returns the core's JSON as a dict: axis, bladeCount, splitterCount, hub, bore, holes, planes,
    turned, blades (each: kind, pressure, suction, leading, trailing, walls, fillets, shroud,
    angleDeg), closestPair and dimensions (boreDiameter, boreDepth, minChannelWidth,
    channelBlades, filletRadius, bladeHeight, splitterHeight, outerRadius, axialLength), in mm.
    """
    shape, label = shape_of(source)
    if not shape.isNull() and len(shape.Solids) > 1:
        raise RecognitionError(
            "{}: holds {} solids (bodies exported separately, e.g. a hub and its blades); impeller "
            "recognition needs one solid: fuse them first (Program impeller offers it; "
            "aeronc.impeller.body_fusion.fuse_bodies)".format(label, len(shape.Solids)))
    check_solid(shape, label)
    core = _core()
    with from_core(RecognitionError, label):
        return json.loads(core.recognise_impeller(shape.exportBrepToString()))


def program_data(source, allowance=2.0, kb_path=None, route="impeller"):
    """Recognition, dimensions, blank and process route of an impeller: (result dict, blank
    shape). The result is `recognise`'s with "blank" (allowance, axial stations and radii of the
    revolved outer profile, along the axis from its point) and "route" (steps: position,
    operation, strategy, faces, tool with its id, type, diameter, taper, reach, and the limits it
    met; skipped: rules that do not apply) added. kb_path: the knowledge base (default: the
    user's, made from the shipped SQL when missing)."""
    import Part
    from aeronc.pipeline import knowledge_base
    shape, label = shape_of(source)
    check_solid(shape, label)
    if not allowance >= 0:
        raise RecognitionError("{}: the blank allowance must be zero or more, not {}".format(label, allowance))
    import os
    kb_path = kb_path or knowledge_base.user_kb_path()
    os.makedirs(os.path.dirname(kb_path) or ".", exist_ok=True)  # the user's folder on first use
    core = _core()
    with from_core(RecognitionError, label):
        text, blank_brep = core.impeller_program_data(
            shape.exportBrepToString(), float(allowance), kb_path,
            knowledge_base.sql_folder(), route)
    blank = Part.Shape()
    blank.importBrepFromString(blank_brep)
    return json.loads(text), blank


def face_roles(result):
    """{FaceN: role} of a recognition result: hub, bore, hole, plane, turned, and per blade
    "main 3 pressure", "splitter 3 fillet", ... (blade numbers from 0 in angular order)."""
    roles = {f: "hub" for f in hub_faces(result)}
    if result.get("bore"):
        roles[result["bore"]] = "bore"
    for key, name in (("holes", "hole"), ("planes", "plane"), ("turned", "turned")):
        for f in result.get(key, []):
            roles[f] = name
    for i, b in enumerate(result["blades"]):
        tag = "{} {}".format(b["kind"], i)
        for f in b["walls"]:
            roles[f] = tag + " wall"
        for f in shroud_faces(b):
            roles[f] = tag + " shroud"
        for key in ("pressure", "suction", "leading", "trailing", "shroud"):
            if b.get(key):
                roles[b[key]] = "{} {}".format(tag, key)
        for f in b["fillets"]:
            roles[f] = tag + " fillet"
    return roles


def face_role_names(result):
    """The colour role of every face, FaceN order (index N-1): hub, bore, hole_wall, plane,
    turned, main_blade, splitter_blade, root_fillet, shroud (aeronc.feature_colours)."""
    roles = ["unclaimed"] * int(result["faceCount"])

    def put(faces, role):
        for f in faces:
            if 1 <= f <= len(roles):
                roles[f - 1] = role

    put(hub_faces(result), "hub")
    if result.get("bore"):
        put([result["bore"]], "bore")
    put(result.get("holes", []), "hole_wall")
    put(result.get("planes", []), "plane")
    put(result.get("turned", []), "turned")
    for b in result["blades"]:
        put(blade_wall_faces(b), b["kind"] + "_blade")
        put(b["fillets"], "root_fillet")
        put(shroud_faces(b), "shroud")
    return roles


def blade_wall_faces(blade):
    """The wall faces of one blade of the result: pressure, suction, leading, trailing and
    any other walls (edge rounds), each once."""
    faces = [blade[k] for k in ("pressure", "suction", "leading", "trailing") if blade.get(k)]
    return faces + [f for f in blade.get("walls", []) if f not in faces]


def hub_faces(result):
    """Every hub face of the result: one face of revolution, or a piece per channel as exporters
    write it (results stored before the hub had several faces name only "hub")."""
    return list(result.get("hubFaces") or [result["hub"]])


def shroud_faces(blade):
    """Every shroud (tip) face of one blade of the result."""
    return list(blade.get("shroudFaces") or [blade["shroud"]])
