"""Select tools for a Machining Features tree: the plan of the core written into the document.

The plan is made from the tree the group stored when its features were recognised, so the
tools belong to exactly the elements the document shows; the part is not recognised again.
Each milled DomainElement gets its finishing tool, roughing tool and machinable ratio eta,
each hole its drill, and the MachiningFeatures group the tool changes and roughing time
before and after merging, and the plan itself (ToolPlan), which the machining chain takes as
it is. No Path Job is made here: the chain's Jobs get the ToolControllers their units need,
with the optimiser's speeds and feeds (chain_building). Everything is one undo step; a failure
leaves the document as it was.
"""
import json

from aeronc.pipeline import knowledge_base
from aeronc.objects import machining_features
from aeronc.objects.base import descendants, proxy_type
from aeronc.objects.transaction import in_transaction
from aeronc.objects.domain_element import TYPE as ELEMENT_TYPE

TC_TAG = "AeroNCTool"  # property on the chain's ToolControllers: "<tool id>/<operation>" of the plan


def _element_objects(group):
    return {o.ElementId: o for o in descendants(group) if proxy_type(o) == ELEMENT_TYPE}


def _set_plan_properties(group, plan, material, machine):
    """Write the plan into the properties the proxies declare (group "Tools")."""
    group.Material, group.Machine = material, machine
    group.ToolChangesBefore, group.ToolChangesAfter = plan["toolChanges"]["before"], plan["toolChanges"]["after"]
    group.RoughingMinutesBefore = plan["timeMin"]["before"] or 0.0
    group.RoughingMinutesAfter = plan["timeMin"]["after"] or 0.0
    group.ToolPlan = json.dumps(plan, separators=(",", ":"))

    objs = _element_objects(group)
    for e in plan["elements"]:
        obj = objs.get(e["id"])
        if obj is None:
            continue
        obj.FinishingTool, obj.RoughingTool = e["finishingTool"] or "", e["roughingTool"] or ""
        obj.MachinableRatio = e["eta"] if e["eta"] is not None else 0.0
        obj.NarrowPassages = e["narrowPassages"] or 0
        obj.ToolError = e["error"] or ""
    for h in plan["holes"]:
        obj = objs.get(h["id"])
        if obj is None:
            continue
        obj.Drill, obj.ToolError = h["drill"] or "", h["error"] or ""


def select_tools(group, material, machine="", kb_path=None, progress=None):
    """Plan the tools of a MachiningFeatures group from its stored tree and record them (one
    undo step).

    progress, if given, is called as progress(fraction, stage) when planning starts and when
    the plan is about to be recorded; returning False cancels, leaving the document as it was.
    Returns the plan (dict). Raises KnowledgeBaseError with a clear message
    for a group without a source or a stored recognition, a source changed since recognition,
    a stored tree the core cannot read, an unknown material or machine, a knowledge base that
    cannot be opened, or a cancel."""
    if not machining_features.is_machining_features(group):
        raise knowledge_base.KnowledgeBaseError("{} is not a Machining Features group".format(group.Label))
    part = group.Source
    if part is None:
        raise knowledge_base.KnowledgeBaseError("{}: no source part".format(group.Label))
    group.recompute()
    if group.Outdated:
        raise knowledge_base.KnowledgeBaseError(
            "{}: {} changed since its features were recognised; recognise again first".format(group.Label, part.Label))
    try:
        tree = machining_features.result_of(group)
    except ValueError as e:
        raise knowledge_base.KnowledgeBaseError(
            "{}: the stored recognition is not valid JSON ({}); recognise again".format(group.Label, e))
    if not tree:
        raise knowledge_base.KnowledgeBaseError("{}: no stored recognition; recognise first".format(group.Label))

    def going_on(fraction, stage):
        if progress is not None and progress(fraction, stage) is False:
            raise knowledge_base.KnowledgeBaseError("{}: tool selection cancelled".format(group.Label))

    going_on(0.0, "Planning tools")
    kb = knowledge_base.open_kb(kb_path)
    if not machine:
        names = kb.machine_names()
        machine = names[0] if names else ""
    try:
        plan = knowledge_base.plan_tools(tree, material, machine=machine, kb_path=kb.path)
    except knowledge_base.KnowledgeBaseError as e:
        raise knowledge_base.KnowledgeBaseError("{}: {}".format(group.Label, e))
    going_on(0.9, "Recording the plan")
    doc = group.Document

    def work():
        _set_plan_properties(group, plan, material, machine)
        doc.recompute()

    in_transaction(doc, "Select tools", work)
    return plan
