"""The Path Job of one setup of the machining chain.

Its Model is the part placed by the setup frame: the frame's u, v, w become the Job's X, Y, Z,
so the setup's tool axis is the Job's +Z and the units' geometry (u, v, h) is in Job
coordinates. For -Z that is a rotation of 180 degrees about X. Its Stock is the recognition
blank box in the same frame. Its ToolControllers are the ones the setup's units need, one per
knowledge-base tool and cutting operation, tagged by the tool plan ("<tool id>/<operation>"):
a Job keeps the controllers it has (with the speeds and feeds they were given or optimised
to); a missing one is made from the unit's tool and cutting data (the knowledge base's n and
feeds), then given the optimiser's speeds and feeds for its tool and operation.
"""
import FreeCAD

from aeronc import pathcompat
from aeronc.pipeline.tool_planning import TC_TAG

SETUP_TAG = "AeroNCSetup"  # property on the Jobs of a chain: the setup id



def frame_rotation(frame):
    """The rotation taking world coordinates to the setup frame (rows u, v, w)."""
    u, v, w = (frame[k] for k in ("u", "v", "w"))
    m = FreeCAD.Matrix(u[0], u[1], u[2], 0, v[0], v[1], v[2], 0, w[0], w[1], w[2], 0, 0, 0, 0, 1)
    return FreeCAD.Rotation(m)


def frame_placement(frame):
    return FreeCAD.Placement(FreeCAD.Vector(), frame_rotation(frame))


def box_in_frame(box, frame):
    """The box (xmin, ymin, zmin, xmax, ymax, zmax) bounding a world box seen in the frame."""
    rot = frame_rotation(frame)
    corners = [rot.multVec(FreeCAD.Vector(x, y, z))
               for x in (box[0], box[3]) for y in (box[1], box[4]) for z in (box[2], box[5])]
    xs, ys, zs = [c.x for c in corners], [c.y for c in corners], [c.z for c in corners]
    clean = [round(c, 9) + 0.0 for c in (min(xs), min(ys), min(zs), max(xs), max(ys), max(zs))]
    return tuple(clean)


def part_box(shape, deflection=1e-3, fine=1e-6):
    """(xmin, ymin, zmin, xmax, ymax, zmax) through the points of the shape's edges, as
    recognition measures the part: FreeCAD's BoundBox can stand most of a millimetre off a part
    with curved edges (0.74 mm on NIST FTC-10), which would put phantom stock round it.
    Chords fall inside an arc's extreme by up to the deflection: the edges that come that close
    to a side are walked again at the fine one."""
    def extent(pts):
        return [min(p[k] for p in pts) for k in range(3)], [max(p[k] for p in pts) for k in range(3)]

    edges = [(edge, edge.discretize(Deflection=deflection)) for edge in shape.Edges]
    if not edges:  # no edge: a closed surface
        bb = shape.BoundBox
        return (bb.XMin, bb.YMin, bb.ZMin, bb.XMax, bb.YMax, bb.ZMax)
    boxes = [extent(pts) for _, pts in edges]
    lo = [min(b[0][k] for b in boxes) for k in range(3)]
    hi = [max(b[1][k] for b in boxes) for k in range(3)]
    for (edge, pts), (elo, ehi) in zip(edges, boxes):
        curved = len(pts) > 2  # a straight edge's ends are exact
        # Only an axis the edge curves in can gain from the fine walk: an arc in the plane of a
        # side (a pocket's corner on the top face) keeps that coordinate exactly.
        if curved and any(elo[k] != ehi[k] and (elo[k] < lo[k] + deflection or ehi[k] > hi[k] - deflection)
                          for k in range(3)):
            flo, fhi = extent(edge.discretize(Deflection=fine))
            lo = [min(a, b) for a, b in zip(lo, flo)]
            hi = [max(a, b) for a, b in zip(hi, fhi)]
    return tuple(lo + hi)


def blank_box(group):
    """The recognition blank of a Machining Features group: its Blank, or the part's box
    (part_box) grown by its Allowance."""
    if len(group.Blank) == 6:
        return tuple(group.Blank)
    box = part_box(group.Source.Shape)
    a = group.Allowance.Value
    return tuple(c - a for c in box[:3]) + tuple(c + a for c in box[3:])


def cutting_operation(unit):
    """The knowledge base's cutting operation whose data a unit uses: drilling for the drill
    step, roughing for rough, corner, hole-milling and cut-off steps, finishing otherwise."""
    from aeronc.pipeline.chain_edits import setting_operation
    return setting_operation(unit.get("step", ""))


def tag_of(unit):
    return "{}/{}".format(unit["tool"], cutting_operation(unit))


def setup_label(setup, part):
    return "Job {} ({})".format(setup.get("name") or setup["id"], part.Label)


def make_job(doc, part, setup):
    job = pathcompat.create_job(doc, [part], "Job")
    job.addProperty("App::PropertyInteger", SETUP_TAG, "AeroNC", "Setup of the machining chain this Job machines",
                    0, True)
    setattr(job, SETUP_TAG, int(setup["id"]))
    # The Job's default ToolController is not one the chain uses.
    for tc in pathcompat.tool_controllers(job):
        pathcompat.remove_tool_controller(doc, tc)
    return job


def part_zero(blank, frame):
    """Where the program zero (the part's origin, in the setup's frame) sits from the table's
    reference point when the blank stands centred on the table: minus the middle of the blank's
    underside in the frame. Parts modelled far from their origin then stay within the travel."""
    box = box_in_frame(blank, frame)
    return [0.0 - (box[0] + box[3]) / 2, 0.0 - (box[1] + box[4]) / 2, 0.0 - box[2]]  # no -0.0


def post_arguments(machine, blank, frame):
    """The arguments of AeroNC's posts for a setup: the machine, and the part zero with the blank
    centred on the table."""
    zero = part_zero(blank, frame)
    return "--machine {} --part-zero={}".format(machine, ",".join("{:.6f}".format(v) for v in zero))


def place(job, part, setup, blank, machine=None):
    """Model and stock of the Job in the setup's frame; with a machine, the Job posts with
    AeroNC's post for it (FreeCAD's Post command then writes what the main job writes)."""
    if machine:
        from aeronc.post import machines
        pathcompat.set_job_post(job, machines.post_of(machine), post_arguments(machine, blank, setup["frame"]))
    job.Label = setup_label(setup, part)
    pathcompat.set_model_placement(job, frame_placement(setup["frame"]))
    stock = job.Stock
    box = box_in_frame(blank, setup["frame"])
    bb = stock.Shape.BoundBox if stock is not None and not stock.Shape.isNull() else None
    if bb is None or any(abs(a - b) > 1e-6 for a, b in zip((bb.XMin, bb.YMin, bb.ZMin, bb.XMax, bb.YMax, bb.ZMax), box)):
        pathcompat.set_job_stock_box(job, box)


def tool_controllers(job, units, kb, cutting_data=None):
    """{tag: ToolController} for the units, made in the Job where missing (see module doc);
    cutting_data (a ChainCuttingData) writes the optimiser's speeds and feeds into each new one."""
    doc = job.Document
    have = {getattr(tc, TC_TAG): tc for tc in pathcompat.tool_controllers(job) if hasattr(tc, TC_TAG)}
    used = [tc.ToolNumber for tc in pathcompat.tool_controllers(job)]
    out = {}
    for unit in units:
        tag = tag_of(unit)
        if tag in out:
            continue
        tc = have.get(tag)
        if tc is None:
            number = unit.get("toolNumber")
            if not number or number in used:
                number = max(used + [0]) + 1
            s = unit.get("setting") or {}
            chamfer_mill = (unit.get("cutter") or {}).get("type") == "chamfer"
            tc = _make_tool_controller(doc, job, unit["tool"], tag, number, float(s.get("spindleRpm") or 0.0),
                                       float(s.get("feedMmMin") or 0.0), float(s.get("plungeFeedMmMin") or 0.0), kb,
                                       unit["cutter"] if chamfer_mill else None)
            # The optimiser's model is an end mill's: a chamfer mill keeps the knowledge base's data.
            if cutting_data is not None and not chamfer_mill:
                cutting_data.write(tc)
            used.append(number)
        out[tag] = tc
    return out


def unused_tool_controllers(job, wanted):
    """The Job's chain ToolControllers (tagged) that no unit needs and no operation uses."""
    return [tc for tc in pathcompat.tool_controllers(job)
            if hasattr(tc, TC_TAG) and tc not in wanted and not pathcompat.tool_controller_in_use(tc)]


def chamfer_bit(tool_id, cutter):
    """The .fctb document of a chamfer mill of the knowledge base's edge_tool table (FreeCAD's
    chamfer shape: CuttingEdgeAngle is the included angle)."""
    import math
    d, tip, angle = float(cutter["diameter"]), float(cutter["tipDiameter"]), float(cutter["includedAngle"])
    height = (d - tip) / 2 / math.tan(math.radians(angle / 2))
    mm = "{:.4f} mm".format
    return {"version": 2, "name": tool_id, "shape": "chamfer.fcstd", "attribute": {},
            "parameter": {"CuttingEdgeAngle": "{:.4f} \u00b0".format(angle), "CuttingEdgeHeight": mm(height),
                          "Diameter": mm(d), "TipDiameter": mm(tip), "Length": mm(max(50.0, 3 * d)),
                          "ShankDiameter": mm(d)}}


def _make_tool_controller(doc, job, tool_id, tag, number, rpm, hfeed, vfeed, kb, chamfer=None):
    import json
    from aeronc.errors import MachiningChainError, from_core
    if chamfer is not None:
        bit = chamfer_bit(tool_id, chamfer)
    else:
        with from_core(MachiningChainError, "tool {} of the chain".format(tool_id)):
            _, document = kb.bit_document(tool_id)
        bit = json.loads(document)
    tc = pathcompat.create_tool_controller(doc, job, "TC: {} {}".format(*tag.split("/")), bit,
                                           number, rpm, hfeed, vfeed)
    tc.addProperty("App::PropertyString", TC_TAG, "AeroNC", "Tool and operation of the AeroNC tool plan", 0, True)
    setattr(tc, TC_TAG, tag)
    return tc
