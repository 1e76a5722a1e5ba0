"""Optimise cutting parameters: the spindle speed and feeds of a Job's ToolControllers from
the core's cutting-parameter optimiser (impeller paper, section 3).

For each ToolController the cut is taken from the operations that use it:
- a_p, the largest step between the cutting levels of their paths (the first one measured
  from the operation's start depth);
- a_e, the operation's step-over times the tool diameter; a slot cuts the full diameter;
  a profile, which has no step-over, takes the knowledge base's a_e/D for the operation;
- L, the length of their cutting moves.
The cutter (diameter, teeth, corner radius, tool material) comes from the ToolBit, the
coefficients and limits from the knowledge base (workpiece material x tool material x
operation, and the machine). A ToolController that no operation uses is optimised for the
knowledge base's a_p and a_e.

propose() computes without touching the document; apply() writes SpindleSpeed, HorizFeed and
VertFeed of every ToolController that has an answer, as one undo step. A ToolController whose
problem is infeasible or incomplete gets a message and is never written.
"""
import json
import math
import os

import FreeCAD

from aeronc.pipeline import knowledge_base
from aeronc import pathcompat
from aeronc.objects.base import add_property
from aeronc.errors import CuttingOptimisationError, from_core
from aeronc.objects.transaction import in_transaction

TC_TAG = "AeroNCTool"  # set by Select tools: "<tool id>/<operation>"
RESULT_PROPERTY = "CuttingOptimum"
METHODS = {"nlopt": "deterministic (scan + NLopt SLSQP)", "ga": "genetic algorithm", "both": "both, side by side"}

# Assumed shop figures (docs/cutting-optimisation.md); the panel lets the user change them.
DEFAULT_ECONOMICS = {"t_0_min": 1.0, "c_0_per_min": 1.0, "c_t_per_tool_life": 40.0, "w_time": 0.5, "w_cost": 0.5}
# Roughing leaves stock for finishing: its surface only has to be a roughing class (ISO 1302
# N10). Finishing uses the knowledge base's threshold ra_max_um.
ROUGHING_RA_MAX_UM = 12.5
# Without the tool maker's chip load (the bit's Chipload attribute), the largest f_z is the
# knowledge base's recommended f_z times this: the upper end of handbook chip-load ranges.
CHIP_LOAD_FACTOR = 1.5
# A ToolController no operation uses yet: the cut is priced over this feed length.
NOMINAL_LENGTH_MM = 1000.0
_CUTTING_MOVES = {"G1", "G01", "G2", "G02", "G3", "G03"}


class OperationCut:
    """The engagement of one operation, with where each figure came from."""

    def __init__(self, op, a_p, a_e, length, a_p_from, a_e_from):
        self.op, self.a_p, self.a_e, self.length = op, a_p, a_e, length
        self.a_p_from, self.a_e_from = a_p_from, a_e_from


class Proposal:
    """The optimiser's answer for one ToolController; nothing is written until apply()."""

    def __init__(self, tc):
        self.tc = tc
        self.operation = ""      # knowledge-base operation: roughing or finishing
        self.tool_material = ""
        self.cuts = []           # OperationCut of every operation using tc
        self.params = None       # the parameter file sent to the core
        self.result = None       # the core's JSON answer (dict)
        self.text = ""           # the core's comparison table
        self.error = ""          # why there is no answer
        self.skipped = False     # not a milling cut (drilling, probing): left as it is
        self.spindle_rpm = self.horiz_feed = self.vert_feed = None
        self.current = (float(tc.SpindleSpeed), _mm_min(tc.HorizFeed), _mm_min(tc.VertFeed))

    @property
    def ok(self):
        return not self.error and not self.skipped and self.spindle_rpm is not None

    @property
    def optimum(self):
        return self.result["deterministic" if "deterministic" in self.result else "genetic"]["optimum"]

    def summary(self):
        o = self.optimum
        return "n {:.1f} r/min, f_z {:.4f} mm, v_f {:.1f} mm/min; active: {}; {} / {} / {}".format(
            o["n_rpm"], o["f_z_mm"], o["v_f_mm_min"], ", ".join(o["active"]) or "none",
            self.params["kb"]["workpiece_material"], self.tool_material, self.operation)


def _mm_min(quantity):
    """A FreeCAD speed (mm/s internally) in mm/min."""
    return float(FreeCAD.Units.Quantity(quantity).getValueAs("mm/min"))


# --- The cut, from the operations' paths ------------------------------------------------------

def _path_geometry(path):
    """(cutting levels, cutting length) of a Path: the Z of every horizontal cutting move and
    the length of all cutting moves (lines and arcs, helices included)."""
    levels, length = set(), 0.0
    x = y = z = None
    for cmd in path.Commands:
        p = cmd.Parameters
        nx, ny, nz = p.get("X", x), p.get("Y", y), p.get("Z", z)
        if cmd.Name in _CUTTING_MOVES and None not in (x, y, z, nx, ny, nz):
            dz = nz - z
            if cmd.Name in ("G1", "G01"):
                seg = math.sqrt((nx - x) ** 2 + (ny - y) ** 2 + dz ** 2)
            else:
                cx, cy = x + p.get("I", 0.0), y + p.get("J", 0.0)
                r = math.hypot(x - cx, y - cy)
                a0, a1 = math.atan2(y - cy, x - cx), math.atan2(ny - cy, nx - cx)
                sweep = (a0 - a1) if cmd.Name in ("G2", "G02") else (a1 - a0)
                sweep %= 2 * math.pi
                if sweep < 1e-9:
                    sweep = 2 * math.pi  # a full circle ends where it starts
                seg = math.hypot(r * sweep, dz)
            length += seg
            if abs(dz) < 1e-6 and seg > 1e-9:
                levels.add(round(nz, 4))
        x, y, z = nx, ny, nz
    return sorted(levels, reverse=True), length


def _operation_kind(op):
    """'slot', 'stepover' (clearing with a step-over), or 'contour' (no step-over)."""
    if type(getattr(op, "Proxy", None)).__name__ == "ObjectSlot":
        return "slot"
    return "stepover" if pathcompat.op_property(op, "StepOver") is not None else "contour"


def operation_cut(op, diameter, ae_ratio):
    """The OperationCut of op for a tool of this diameter; ae_ratio (a_e/D of the knowledge
    base) is used where the operation has no step-over. Raises CuttingOptimisationError for an
    operation whose path has no cutting moves."""
    levels, length = _path_geometry(op.Path)
    if not levels or length <= 0:
        raise CuttingOptimisationError(
            "{}: its path has no cutting moves; recompute it (or check its depths)".format(op.Label))
    start = pathcompat.op_property(op, "StartDepth")
    top = start.Value if start is not None else None
    steps = [a - b for a, b in zip(levels, levels[1:])]
    if top is not None and top - levels[0] > 1e-6:
        steps.insert(0, top - levels[0])
    if steps:
        a_p, a_p_from = max(steps), "largest step between the path's cutting levels"
    else:
        step_down = pathcompat.op_property(op, "StepDown")
        if step_down is None or step_down.Value <= 0:
            raise CuttingOptimisationError("{}: one cutting level and no start depth or step-down to measure a_p "
                                           "from".format(op.Label))
        a_p, a_p_from = step_down.Value, "step-down (one cutting level)"
    kind = _operation_kind(op)
    if kind == "slot":
        a_e, a_e_from = diameter, "slot: the full diameter"
    elif kind == "stepover":
        percent = float(pathcompat.op_property(op, "StepOver"))
        a_e, a_e_from = min(1.0, percent / 100.0) * diameter, "step-over {:g} % of D".format(percent)
    else:
        a_e, a_e_from = ae_ratio * diameter, "knowledge base a_e/D = {:g} (no step-over)".format(ae_ratio)
    return OperationCut(op, a_p, a_e, length, a_p_from, a_e_from)


# --- The cutter, from the ToolBit --------------------------------------------------------------

def _length(bit, name):
    v = getattr(bit, name, None)
    return None if v is None else float(getattr(v, "Value", v))


def cutter_of(tc):
    """(diameter, teeth, corner radius, tool material, note) of the ToolController's bit.

    The corner radius sets the feed marks: a bull nose's torus radius, a ball's radius; a flat
    end mill leaves the peripheral-milling scallop f_z^2/(8 R) on the wall, the same formula
    with r = D/2. Raises CuttingOptimisationError naming what is missing."""
    bit = getattr(tc, "Tool", None)
    if bit is None:
        raise CuttingOptimisationError("{}: no tool bit".format(tc.Label))
    d = _length(bit, "Diameter")
    if d is None or d <= 0:
        raise CuttingOptimisationError("{}: tool {} has no positive Diameter".format(tc.Label, bit.Label))
    teeth = int(getattr(bit, "Flutes", 0) or 0)
    if teeth < 1:
        raise CuttingOptimisationError(
            "{}: tool {} has no number of teeth; set Flutes in the tool bit's attributes".format(tc.Label, bit.Label))
    shape = os.path.basename(str(getattr(bit, "BitShape", "") or getattr(bit, "ShapeName", ""))).lower()
    flat = _length(bit, "FlatRadius")
    corner = _length(bit, "CornerRadius")
    if flat is not None and d / 2 - flat > 1e-9:
        r, note = d / 2 - flat, "torus radius"
    elif corner is not None and corner > 0:
        r, note = corner, "corner radius"
    elif "ball" in shape:
        r, note = d / 2, "ball radius"
    else:
        r, note = d / 2, "flat end: wall scallop, r = D/2"
    material = str(getattr(bit, "Material", "") or "").strip()
    if not material:
        raise CuttingOptimisationError(
            "{}: tool {} has no material; set Material (HSS or Carbide) in its attributes".format(tc.Label, bit.Label))
    material = {"carbide": "carbide", "hss": "HSS"}.get(material.lower(), material)
    return d, teeth, r, material, note


# --- Where the names come from ------------------------------------------------------------------

def _is_drill(tc):
    bit = getattr(tc, "Tool", None)
    shape = str(getattr(bit, "BitShape", "") or getattr(bit, "ShapeName", "")) if bit is not None else ""
    return "drill" in os.path.basename(shape).lower()


def _tag(tc):
    tag = getattr(tc, TC_TAG, "") or ""
    return tag.split("/", 1) if "/" in tag else None


def long_reach_fz_factor(kb, tool_id):
    """The knowledge base's f_z reduction for a necked tool reaching more than long_reach_ratio
    diameters (kb::LongReach, docs/tool-crib.md); 1 for any other tool or without the thresholds."""
    tool = next((t for t in kb.tools() if t["id"] == tool_id), None)
    if not tool or not tool.get("neckDiameter"):
        return 1.0
    try:
        ratio, factor = kb.threshold("long_reach_ratio"), kb.threshold("long_reach_fz_factor")
    except RuntimeError:  # a knowledge base without them reduces nothing
        return 1.0
    return factor if tool["reach"] > ratio * tool["diameter"] + 1e-9 else 1.0


def _features_groups_of(job):
    """The AeroNC Machining Features groups whose part is a model of job."""
    from aeronc.objects import machining_features
    doc = job.Document
    return [g for g in doc.Objects if machining_features.is_machining_features(g) and g.Source is not None
            and job in pathcompat.jobs_of_part(doc, g.Source)]


def defaults_for(job):
    """(material, machine) recorded by Select tools for the Job's part, or ('', '')."""
    for g in _features_groups_of(job):
        material, machine = getattr(g, "Material", ""), getattr(g, "Machine", "")
        if material:
            return material, machine
    return "", ""


def tool_controllers_of(target):
    """(Job, ToolControllers) for a ToolController or a Job; raises for anything else."""
    if pathcompat.is_tool_controller(target):
        job = pathcompat.job_of(target)
        if job is None:
            raise CuttingOptimisationError("{} is not in a Job".format(target.Label))
        return job, [target]
    if pathcompat.is_job(target):
        tcs = pathcompat.tool_controllers(target)
        if not tcs:
            raise CuttingOptimisationError("{} has no ToolControllers".format(target.Label))
        return target, tcs
    raise CuttingOptimisationError("{} is neither a ToolController nor a Job".format(target.Label))


# --- Propose and apply ---------------------------------------------------------------------------

def propose_one(tc, ops, kb, material, machine, method="nlopt", ra_max=None, economics=None, map_points=0):
    """The Proposal for one ToolController used by operations ops. Never raises for the
    ToolController's own problems: they end up in Proposal.error (or Proposal.skipped for hole
    operations)."""
    from aeronc import _core
    prop = Proposal(tc)
    if ops and all(pathcompat.is_hole_operation(op) for op in ops):
        prop.skipped = True
        prop.error = "used by hole operations only ({}); the milling model does not describe them".format(
            ", ".join(op.Label for op in ops))
        return prop
    ops = [op for op in ops if not pathcompat.is_hole_operation(op)]
    if _is_drill(tc) or (_tag(tc) or ["", ""])[1] == "drilling":
        prop.skipped = True
        prop.error = "a drill; the milling model does not describe it"
        return prop
    try:
        d, teeth, r, tool_material, r_note = cutter_of(tc)
        tag = _tag(tc)
        if tag:
            operation = tag[1]
        else:
            operation = "roughing" if any(_operation_kind(op) != "contour" for op in ops) else "finishing"
        if operation not in ("roughing", "finishing"):
            prop.skipped = True
            prop.error = "a {} tool; the milling model does not describe it".format(operation)
            return prop
        prop.operation, prop.tool_material = operation, tool_material
        try:
            with from_core(CuttingOptimisationError):
                condition = kb.cutting_condition(material, tool_material, operation, d)
        except ValueError as e:  # an argument the binding refuses
            raise CuttingOptimisationError(str(e)) from None
        chip_load = _length(tc.Tool, "Chipload") or 0.0
        chip_note = "from the bit"
        if chip_load <= 0:
            chip_load = CHIP_LOAD_FACTOR * condition["fz"]
            chip_note = "{:g} x the knowledge base's f_z".format(CHIP_LOAD_FACTOR)
            reduce = long_reach_fz_factor(kb, tag[0]) if tag else 1.0
            if reduce != 1.0:
                chip_load *= reduce
                chip_note += ", x {:g} for the long reach".format(reduce)
        if ops:
            prop.cuts = [operation_cut(op, d, condition["aeRatio"]) for op in ops]
            # One set of speeds serves every operation: force and power grow with a_p and a_e,
            # so the deepest and widest engagement is the one to meet the limits with.
            deepest = max(prop.cuts, key=lambda c: c.a_p)
            widest = max(prop.cuts, key=lambda c: c.a_e)
            cut = {"length_mm": sum(c.length for c in prop.cuts), "a_p_mm": deepest.a_p, "a_e_mm": widest.a_e,
                   "source": "a_p from {} ({}), a_e from {} ({}); L = cutting moves of {}".format(
                       deepest.op.Label, deepest.a_p_from, widest.op.Label, widest.a_e_from,
                       ", ".join(c.op.Label for c in prop.cuts))}
        else:
            cut = {"length_mm": NOMINAL_LENGTH_MM, "a_e_mm": condition["aeRatio"] * d,
                   "source": "no operation uses this ToolController: the knowledge base's a_p and a_e/D, "
                             "over a nominal {:g} mm".format(NOMINAL_LENGTH_MM)}
        params = {
            "name": tc.Label,
            "kb": {"workpiece_material": material, "tool_material": tool_material, "operation": operation,
                   "machine": machine},
            "cutter": {"diameter_mm": d, "teeth": teeth, "corner_radius_mm": r, "max_chip_load_mm": chip_load,
                       "source": "tool bit {} ({}; chip load {})".format(tc.Tool.Label, r_note, chip_note)},
            "cut": cut,
            "economics": dict(economics or DEFAULT_ECONOMICS),
        }
        limit = (ra_max or {}).get(operation)
        if limit is None and operation == "roughing":
            limit = ROUGHING_RA_MAX_UM
        if limit is not None:
            params["quality"] = {"ra_max_um": limit}
        rpm, feed, _ = prop.current
        if rpm > 0 and feed > 0:
            params["references"] = [{"label": "now: " + tc.Label, "n_rpm": rpm, "f_z_mm": feed / (teeth * rpm)}]
        prop.params = params
        with from_core(CuttingOptimisationError):
            text, result = _core.optimise_cutting_in(kb, json.dumps(params), method, 1, map_points)
        prop.text, prop.result = text, json.loads(result)
        best = prop.optimum
        ratio = kb.threshold("plunge_feed_ratio")
        prop.spindle_rpm = best["n_rpm"]
        prop.horiz_feed = best["v_f_mm_min"]
        prop.vert_feed = best["v_f_mm_min"] * ratio
    except CuttingOptimisationError as e:
        prop.error = str(e)
    return prop


def propose(target, material="", machine="", kb_path=None, method="nlopt", ra_max=None, economics=None,
            map_points=0, progress=None):
    """Proposals for a ToolController or for every ToolController of a Job.

    material and machine default to what Select tools recorded for the Job's part (and the
    machine to the knowledge base's first). ra_max: {"roughing": um, "finishing": um} to
    override the roughness limits. progress(done, total, label) is called per ToolController.
    Raises CuttingOptimisationError when the target, the knowledge base or the names are wrong."""
    if method not in METHODS:
        raise CuttingOptimisationError("method must be one of {}, got {!r}".format(", ".join(METHODS), method))
    job, tcs = tool_controllers_of(target)
    kb = knowledge_base.open_kb(kb_path)
    rec_material, rec_machine = defaults_for(job)
    material = material or rec_material
    if not material:
        raise CuttingOptimisationError("no workpiece material: choose one ({})".format(
            ", ".join(kb.workpiece_materials())))
    if material not in kb.workpiece_materials():
        raise CuttingOptimisationError("unknown workpiece material {!r}; the knowledge base has {}".format(
            material, ", ".join(kb.workpiece_materials())))
    machine = machine or rec_machine or (kb.machine_names() or [""])[0]
    if machine not in kb.machine_names():
        raise CuttingOptimisationError("unknown machine {!r}; the knowledge base has {}".format(
            machine, ", ".join(kb.machine_names())))
    ops_of = {tc.Name: [] for tc in tcs}
    for op in pathcompat.tooled_operations(job):
        tc = pathcompat.tool_controller_of(op)
        if tc.Name in ops_of:
            ops_of[tc.Name].append(op)
    out = []
    for i, tc in enumerate(tcs):
        if progress:
            progress(i, len(tcs), tc.Label)
        out.append(propose_one(tc, ops_of[tc.Name], kb, material, machine, method, ra_max, economics, map_points))
    if progress:
        progress(len(tcs), len(tcs), "")
    return out


def write(proposal, tc):
    """The proposal's speeds and feeds, and the optimiser's record, into a ToolController."""
    tc.SpindleSpeed = float(proposal.spindle_rpm)
    tc.HorizFeed = "{!r} mm/min".format(float(proposal.horiz_feed))
    tc.VertFeed = "{!r} mm/min".format(float(proposal.vert_feed))
    add_property(tc, "App::PropertyString", RESULT_PROPERTY, "AeroNC",
                 "What the cutting-parameter optimiser chose, and why", proposal.summary(), True)


class ChainCuttingData:
    """Speeds and feeds for the ToolControllers the machining chain makes in its Jobs.

    A controller is made before the operations that will use it, so the optimiser is asked at
    the knowledge base's a_p and a_e for the tool and operation (as for a controller no
    operation uses); the answer is computed once per tool and operation and written into every
    new controller of that tag. A controller the optimiser cannot answer for (a drill, a bit
    without teeth or material) keeps the knowledge base's speeds and feeds, and says why in
    messages. Optimising a Job afterwards (Optimise cutting parameters) takes the cut from its
    operations' paths instead."""

    def __init__(self, kb, material, machine):
        self.kb, self.material, self.machine = kb, material, machine
        self.answers = {}  # tag -> Proposal
        self.messages = []

    def write(self, tc):
        """Write the optimum into tc (tagged by the chain); True when it had one."""
        tag = getattr(tc, TC_TAG)
        proposal = self.answers.get(tag)
        if proposal is None:
            proposal = self.answers[tag] = propose_one(tc, [], self.kb, self.material, self.machine)
            if proposal.error and not proposal.skipped:
                self.messages.append("{}: the knowledge base's speeds and feeds kept ({})".format(tag, proposal.error))
        if proposal.ok:
            write(proposal, tc)
        return proposal.ok


def apply(proposals):
    """Write every proposal that has an answer into its ToolController, as one undo step, and
    recompute the operations that use them. Returns the ToolControllers written. Raises
    CuttingOptimisationError, writing nothing, when no proposal has an answer."""
    good = [p for p in proposals if p.ok]
    if not good:
        reasons = "; ".join("{}: {}".format(p.tc.Label, p.error) for p in proposals if p.error)
        raise CuttingOptimisationError("nothing to write" + (": " + reasons if reasons else ""))
    doc = good[0].tc.Document
    before = [(p.tc, p.tc.SpindleSpeed, p.tc.HorizFeed, p.tc.VertFeed) for p in good]

    def work():
        try:
            for p in good:
                write(p, p.tc)
            written = set(p.tc.Name for p in good)
            jobs = {job.Name: job for job in (pathcompat.job_of(p.tc) for p in good)}
            ops = [op for job in jobs.values() for op in pathcompat.tooled_operations(job)
                   if pathcompat.tool_controller_of(op).Name in written]
            if ops:
                doc.recompute(ops)
        except BaseException:
            # freecadcmd documents do not record undo: put the old values back by hand.
            for tc, rpm, hf, vf in before:
                tc.SpindleSpeed, tc.HorizFeed, tc.VertFeed = rpm, hf, vf
            raise
        return [p.tc for p in good]

    return in_transaction(doc, "Optimise cutting parameters", work)


def optimise(target, material="", machine="", kb_path=None, method="nlopt", ra_max=None, economics=None):
    """propose() and apply() in one call, for scripts. Returns the proposals."""
    proposals = propose(target, material, machine, kb_path, method, ra_max, economics)
    apply(proposals)
    return proposals
