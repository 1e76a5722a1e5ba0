"""The NC machining chain of a Machining Features group, and the Path Jobs made from it.

compute() asks the core for the chain (the process template of the part family fused with the
domain tree: setups, processes, steps, programs, tools and units, sequenced) without touching
the document. build() records it on a MachiningChain object and makes one Path Job per setup
with an operation per unit in chain order; update() applies the user's edits (unit order, tool
overrides, disabled units) and brings the Jobs in line. Each is one undo step, and a failure
leaves the document as it was.

Rebuilding never silently overwrites a manual edit: the user's edits of the chain are applied
to the new chain, and a parameter changed by hand on an operation keeps its value; what was
kept, or could not be kept, is listed in the chain's Messages.
"""
import json

from aeronc.pipeline import chain_edits, cutting_optimisation, knowledge_base, setup_job
from aeronc import operations, pathcompat
from aeronc.errors import AeroNCError, MachiningChainError, from_core
from aeronc.objects import machining_chain as chain_object
from aeronc.objects import machining_features
from aeronc.objects.base import attach_views
from aeronc.objects.transaction import in_transaction


def _core():
    from aeronc import _core as core
    return core


def _check_group(group):
    if not machining_features.is_machining_features(group):
        raise MachiningChainError("{} is not a Machining Features group".format(getattr(group, "Label", group)))
    part = group.Source
    if part is None:
        raise MachiningChainError("{}: no source part".format(group.Label))
    group.recompute()
    if group.Outdated:
        raise MachiningChainError("{}: {} changed since its features were recognised; recognise again first"
                                  .format(group.Label, part.Label))
    if not machining_features.result_of(group).get("elements"):
        raise MachiningChainError("{}: no domain element to machine; recognise the part's features first "
                                  "(or choose other setup directions)".format(group.Label))
    return part


def part_families(kb):
    """Part families with a process template in the knowledge base (an open KnowledgeBase)."""
    try:
        return [row[0] for row in kb.table("part_family")["rows"]]
    except RuntimeError:  # a knowledge base without process planning
        return []


def compute(group, family, material, machine="", kb_path=None):
    """The chain the core builds for the group (dict); the document is not touched."""
    _check_group(group)
    kb = _open_kb(kb_path)
    if not machine:
        names = kb.machine_names()
        machine = names[0] if names else ""
    # The tools Select tools planned for this material and machine are taken as they are.
    plan = getattr(group, "ToolPlan", "") if (group.Material, group.Machine) == (material, machine) else ""
    with from_core(MachiningChainError, group.Label):
        text = _core().build_chain(group.Result, kb.path, material, knowledge_base.sql_folder(), machine, family,
                                   plan)
    return json.loads(text)


def _open_kb(kb_path):
    try:
        return knowledge_base.open_kb(kb_path)
    except AeroNCError as e:
        raise MachiningChainError(str(e)) from None


def check(chain):
    """The chain with the construction rules checked again (its "checks" replaced)."""
    with from_core(MachiningChainError, "checking the chain"):
        return json.loads(_core().check_chain(json.dumps(chain)))


def edited(built, edits):
    """(the built chain with the edits applied and checked, notes on dropped edits)."""
    chain, notes = chain_edits.apply(built, edits)
    return check(chain), notes


def failed_checks(chain):
    return [c for c in chain.get("checks", []) if not c.get("ok", True)]


def build(group, family, material, machine="", kb_path=None, edits=None, built=None, progress=None):
    """Build (or rebuild) the chain of a Machining Features group and its Jobs, one undo step.

    built: a chain compute() returned (the panel computes it first); else it is computed.
    edits: the user's edits; None keeps those of the group's existing chain.
    Returns the MachiningChain object; its Jobs and Messages say what was made and kept."""
    part = _check_group(group)
    if built is None:
        built = compute(group, family, material, machine, kb_path)
    existing = chain_object.chains_of_features(group)
    obj = existing[0] if existing else None
    if edits is None:
        edits = chain_object.edits_of(obj) if obj is not None else chain_edits.EMPTY
    chain, notes = edited(built, edits)
    kb = _open_kb(kb_path)
    doc = group.Document
    settings = dict(Family=family, Material=material, Machine=built.get("machine") or machine,
                    KnowledgeBase=kb_path or "")

    def work():
        target = obj
        if target is None:
            target = doc.addObject("App::FeaturePython", "MachiningChain")
            chain_object.MachiningChain(target)
            target.Label = "Machining chain ({})".format(part.Label)
            target.Visibility = True
            attach_views([target])
        target.Features = group
        for k, v in settings.items():
            setattr(target, k, v)
        _store(target, built, edits, chain)
        messages = notes + _sync_jobs(target, chain, part, setup_job.blank_box(group), kb, progress)
        target.Messages = messages
        target.purgeTouched()  # its execute computes nothing: the Jobs are made here
        return target

    return in_transaction(doc, "Machining chain", work)


def update(obj, edits=None, progress=None):
    """Apply edits (default: the stored ones) to the chain and bring its Jobs in line, one undo
    step. Returns the MachiningChain object."""
    if not chain_object.is_machining_chain(obj):
        raise MachiningChainError("{} is not a Machining chain".format(getattr(obj, "Label", obj)))
    group = obj.Features
    if group is None:
        raise MachiningChainError("{}: its Machining Features group is gone; build the chain again".format(obj.Label))
    part = _check_group(group)
    built = chain_object.built_of(obj)
    if edits is None:
        edits = chain_object.edits_of(obj)
    chain, notes = edited(built, edits)
    kb = _open_kb(obj.KnowledgeBase or None)
    doc = obj.Document

    def work():
        _store(obj, built, edits, chain)
        obj.Messages = notes + _sync_jobs(obj, chain, part, setup_job.blank_box(group), kb, progress)
        obj.purgeTouched()
        return obj

    return in_transaction(doc, "Update machining chain", work)


def remove(obj):
    """Remove a chain and its Jobs (one undo step)."""
    doc = obj.Document

    def work():
        for job in list(obj.Jobs):
            pathcompat.remove_job(job)
        doc.removeObject(obj.Name)

    in_transaction(doc, "Remove machining chain", work)


def _store(obj, built, edits, chain):
    obj.Built = json.dumps(built, separators=(",", ":"))
    obj.Edits = json.dumps(chain_edits.to_json_ready(edits), separators=(",", ":"))
    obj.Chain = json.dumps(chain, separators=(",", ":"))
    units = chain.get("units", [])
    obj.UnitCount = len(units)
    obj.DisabledCount = sum(1 for u in units if not u.get("enabled", True))
    obj.TravelSavedPercent = float((chain.get("travel") or {}).get("savedPercent") or 0.0)
    obj.FailedChecks = len(failed_checks(chain))
    obj.Unmachined = [unmachined_text(u) for u in chain.get("unmachined", [])]


def unmachined_text(entry):
    """"element 7: reason", or "element 7, step fs: reason" when one step could not machine it."""
    step = ", step {}".format(entry["step"]) if entry.get("step") else ""
    return "element {}{}: {}".format(entry.get("element"), step, entry.get("reason", ""))


# --- the Jobs ------------------------------------------------------------------------------------

OPERATION_LABELS = {"GeneralisedPocket": "Pocket", "Profile": "Profile", "Drilling": "Drilling",
                    "HelicalInterpolation": "Helix", "Chamfer": "Chamfer"}


def operation_label(unit):
    cls = operations.operation_class(unit.get("operation", ""))
    kind = OPERATION_LABELS.get(cls.__name__, cls.__name__)
    if str(unit.get("operation", "")).lower() in ("rest", "corner", "corners", "rest_machining"):
        kind = "Corners"
    return "{} E{} {} U{}".format(kind, unit.get("element"), unit.get("step", ""), unit["id"])


def _unit_defaults(unit, job):
    """The unit with the heights and cycle parameters the chain leaves to the Job: rapids
    between cuts the setup sheet's safe offset above the top, the start and end of the
    operation its clearance offset above the stock."""
    from aeronc.operations.base import reference_top
    u = dict(unit)
    safe_offset, clearance_offset = pathcompat.job_height_offsets(job)
    stock_top = job.Stock.Shape.BoundBox.ZMax
    u.setdefault("clearance", safe_offset)
    u.setdefault("safeHeight", stock_top + clearance_offset)
    u["safeHeight"] = max(float(u["safeHeight"]), reference_top(u) + float(u["clearance"]))
    u.setdefault("rampAngle", 3.0)
    u.setdefault("peck", 0.0)
    u.setdefault("dwell", 0.0)
    return u


def _sync_jobs(obj, chain, part, blank, kb, progress):
    """Make, update or remove the chain's Jobs and their operations; returns messages."""
    doc = obj.Document
    messages = []
    units = chain_edits.units_by_id(chain)
    order = [int(u) for u in chain.get("order", [])] or sorted(units)
    jobs = {getattr(j, setup_job.SETUP_TAG): j for j in obj.Jobs if hasattr(j, setup_job.SETUP_TAG)}
    # Jobs first, then ToolControllers, then operations: making a Job or a ToolController
    # recomputes the document, which would compute every operation made before it again.
    kept = []
    for setup in chain.get("setups", []):
        job = jobs.pop(int(setup["id"]), None) or setup_job.make_job(doc, part, setup)
        setup_job.place(job, part, setup, blank, obj.Machine)
        doc.recompute([job.Stock] + pathcompat.job_models(job))
        setup_units = [units[u] for u in order if u in units and int(units[u].get("setup", 0)) == int(setup["id"])]
        kept.append((job, setup_units))
    cutting_data = cutting_optimisation.ChainCuttingData(kb, obj.Material, obj.Machine)
    tcs = [setup_job.tool_controllers(job, setup_units, kb, cutting_data) for job, setup_units in kept]
    messages += cutting_data.messages
    for (job, setup_units), job_tcs in zip(kept, tcs):
        messages += _sync_operations(job, setup_units, job_tcs)
        for tc in setup_job.unused_tool_controllers(job, list(job_tcs.values())):
            pathcompat.remove_tool_controller(doc, tc)
    for job in jobs.values():
        messages.append("{}: its setup is no longer in the chain; removed".format(job.Label))
        pathcompat.remove_job(job)
    obj.Jobs = [job for job, _ in kept]
    return messages + _compute_paths(obj.Jobs, progress)


def _sync_operations(job, units, tcs):
    doc = job.Document
    ours = {}
    foreign = []
    for op in pathcompat.job_operations(job):
        if operations.is_machining_operation(op) and op.Unit:
            ours[op.UnitId] = op
        else:
            foreign.append(op)
    messages = []
    ordered = []
    for unit in units:
        op = ours.pop(int(unit["id"]), None)
        cls = operations.operation_class(unit.get("operation", ""))
        if op is not None and type(op.Proxy) is not cls:
            doc.removeObject(op.Name)  # the unit changed its operation type: a new operation
            op = None
        if op is None:  # into the Job's Operations with the others below: adding one by one is quadratic
            op = operations.create(doc, unit, operation_label(unit))
        full = _unit_defaults(unit, job)
        for prop, kept, chains in op.Proxy.assign(op, full, tcs[setup_job.tag_of(unit)]):
            messages.append("{}: {} kept at {} (edited by hand; the chain has {})".format(op.Label, prop, kept, chains))
        ordered.append(op)
    for op in ours.values():
        messages.append("{}: its unit is no longer in the chain; removed".format(op.Label))
        doc.removeObject(op.Name)
    pathcompat.set_job_operations(job, ordered + foreign)
    return messages


def _compute_paths(jobs, progress):
    """Compute every operation's path; returns a message for each that has none (the
    operation stays, marked with the toolpath generator's error, for the user to change)."""
    ops = [op for job in jobs for op in pathcompat.job_operations(job) if operations.is_machining_operation(op)]
    stale = [op for op in ops if {"Touched", "Invalid"} & set(op.State) or not op.Path.Commands]
    for i, op in enumerate(stale):
        if progress is not None and progress(i / max(1, len(stale)), "Toolpath of {}".format(op.Label)) is False:
            raise MachiningChainError("cancelled")
        op.recompute()
        op.purgeTouched()  # computed: the document's recompute below need not do it again
    if jobs:
        jobs[0].Document.recompute()
    return ["{}: no toolpath: {}".format(op.Label, getattr(op, "Note", "") or op.getStatusString())
            for op in ops if "Invalid" in op.State]


class _DraftOperation:
    """A unit as its operation would hold it, before the Jobs exist: the chain's parameter
    values, the unit's cutter, heights a clearance above its top (heights do not decide whether
    the toolpath core can machine a unit)."""

    def __init__(self, unit, label, parameters):
        from aeronc.operations.base import reference_top
        u = dict(unit)
        u.setdefault("clearance", 3.0)
        u.setdefault("safeHeight", reference_top(u) + 2 * float(u["clearance"]))
        u.setdefault("rampAngle", 3.0)
        u.setdefault("peck", 0.0)
        u.setdefault("dwell", 0.0)
        self.Label, self.Unit, self.ToolController = label, json.dumps(u), None
        for p in parameters:
            setattr(self, p.name, p.chain_value(u))


def draft_refusals(chain):
    """{unit id: the toolpath core's reason} for the enabled units of a chain (edited or not)
    that would get no toolpath: what the chain panel shows before OK makes the operations."""
    core = _core()
    out = {}
    for unit in chain.get("units", []):
        if not unit.get("enabled", True):
            continue
        try:
            cls = operations.operation_class(unit.get("operation", ""))
            proxy = cls.__new__(cls)  # its methods only: no document object behind it
            draft = _DraftOperation(unit, operation_label(unit), cls.PARAMETERS)
            for data in proxy.toolpath_inputs(draft):
                core.toolpath(json.dumps(data))
        except Exception as e:  # the core's ToolpathError, or an input it cannot take
            out[int(unit["id"])] = str(e)
    return out


def chain_operations(obj):
    """The chain's operations in chain order, over all its Jobs."""
    return [op for job in obj.Jobs for op in pathcompat.job_operations(job) if operations.is_machining_operation(op)]

