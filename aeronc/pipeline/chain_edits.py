"""The user's edits of a machining chain, applied to the chain the core built.

An edit set is a dict (kept as JSON on the MachiningChain object):
  order     unit ids in the order the user wants them; it reorders units only within their
            program (units it does not name stay where the chain put them)
  tools     {unit id: tool id}: the unit is machined with this tool instead (it moves to the
            program of that tool in its step, or to a new one)
  disabled  unit ids the user switched off (their operations stay, inactive)
Edits name units by id; an edit of a unit the chain no longer has is dropped, with a note.
Plain Python, no FreeCAD: the panel and the App functions share it.
"""
import copy

EMPTY = {"order": [], "tools": {}, "disabled": []}
_ROUGHING_STEPS = {"r", "c", "h", "t"}


def setting_operation(step):
    """The cutting operation whose data a unit of this step uses (as the core has it):
    drilling for d, roughing for r, c, h and t, finishing otherwise."""
    return "drilling" if step == "d" else "roughing" if step in _ROUGHING_STEPS else "finishing"


def normalised(edits):
    """A complete edit set (missing keys empty; unit ids as ints)."""
    e = edits or {}
    return {"order": [int(u) for u in e.get("order", [])],
            "tools": {int(k): str(v) for k, v in (e.get("tools") or {}).items()},
            "disabled": sorted({int(u) for u in e.get("disabled", [])})}


def to_json_ready(edits):
    """The edit set with string keys, as JSON needs them."""
    e = normalised(edits)
    return {"order": e["order"], "tools": {str(k): v for k, v in e["tools"].items()}, "disabled": e["disabled"]}


def is_empty(edits):
    e = normalised(edits)
    return not (e["order"] or e["tools"] or e["disabled"])


def programs(chain):
    """Every program of the chain with where it sits: (setup, process, step, program)."""
    for setup in chain.get("setups", []):
        for process in setup.get("processes", []):
            for step in process.get("steps", []):
                for program in step.get("programs", []):
                    yield setup, process, step, program


def units_by_id(chain):
    return {int(u["id"]): u for u in chain.get("units", [])}


def program_of(chain, unit_id):
    """(setup, process, step, program) holding the unit, or None."""
    for where in programs(chain):
        if unit_id in [int(u) for u in where[3].get("units", [])]:
            return where
    return None


def _slot_fill(sequence, members, new_order):
    """sequence with the positions of `members` refilled in new_order."""
    it = iter(new_order)
    return [next(it) if u in members else u for u in sequence]


def _reorder(chain, user_order):
    pos = {u: i for i, u in enumerate(user_order)}
    order = [int(u) for u in chain.get("order", [])]
    for _, _, _, program in programs(chain):
        ids = [int(u) for u in program.get("units", [])]
        named = [u for u in ids if u in pos]
        if len(named) < 2:
            continue
        wanted = sorted(named, key=lambda u: pos[u])
        if wanted == named:
            continue
        program["units"] = _slot_fill(ids, set(named), wanted)
        in_order = [u for u in order if u in set(named)]
        order = _slot_fill(order, set(in_order), [u for u in sorted(in_order, key=lambda u: pos[u])])
    chain["order"] = order


def _tool_data(chain, tool_id):
    tools = chain.get("tools") or {}
    if isinstance(tools, dict):
        return tools.get(tool_id)
    return next((t for t in tools if t.get("id") == tool_id), None)


def _change_tool(chain, unit, tool_id, notes):
    data = _tool_data(chain, tool_id)
    if data is None:
        notes.append("unit {}: tool {} is not among the chain's tools; kept {}".format(unit["id"], tool_id,
                                                                                    unit.get("tool")))
        return
    where = program_of(chain, int(unit["id"]))
    unit["tool"] = tool_id
    cutter = dict(unit.get("cutter") or {})
    for key in ("diameter", "cornerRadius", "type"):
        if key in data:
            cutter[key] = data[key]
    unit["cutter"] = cutter
    number = data.get("toolNumber", data.get("number"))
    if number is not None:
        unit["toolNumber"] = number
    setting = (data.get("settings") or {}).get(setting_operation(unit.get("step", "")))
    if setting:
        unit["setting"] = {k: setting[k] for k in ("spindleRpm", "feedMmMin", "plungeFeedMmMin") if k in setting}
    if where is None:
        return
    _, _, step, program = where
    if program.get("tool") == tool_id:
        return
    uid = int(unit["id"])
    program["units"] = [u for u in program["units"] if int(u) != uid]
    target = next((p for p in step["programs"] if p.get("tool") == tool_id), None)
    if target is None:
        target = {"tool": tool_id, "units": []}
        step["programs"].insert(step["programs"].index(program) + 1, target)
    pos = {int(u): i for i, u in enumerate(chain.get("order", []))}
    target["units"] = sorted([int(u) for u in target["units"]] + [uid], key=lambda u: pos.get(u, 1 << 30))
    if not program["units"]:
        step["programs"].remove(program)


def apply(built, edits):
    """(chain with the edits applied, notes on edits that could not be applied). `built` is
    not changed. Each unit's "enabled" and "order" fields follow the edits."""
    chain = copy.deepcopy(built)
    e = normalised(edits)
    notes = []
    units = units_by_id(chain)
    for uid, tool in sorted(e["tools"].items()):
        if uid not in units:
            notes.append("unit {} no longer exists: its tool change to {} was dropped".format(uid, tool))
            continue
        if units[uid].get("tool") != tool:
            _change_tool(chain, units[uid], tool, notes)
    missing = [u for u in e["order"] if u not in units]
    if missing:
        notes.append("units {} no longer exist: left out of the order".format(", ".join(map(str, missing))))
    _reorder(chain, [u for u in e["order"] if u in units])
    disabled = set(e["disabled"])
    for uid in sorted(disabled - set(units)):
        notes.append("unit {} no longer exists: its disabling was dropped".format(uid))
    built_units = units_by_id(built)  # once: a lookup per unit would be quadratic on a large panel
    for uid, u in units.items():
        was = built_units.get(uid)
        u["enabled"] = uid not in disabled and bool(True if was is None else was.get("enabled", True))
    for i, uid in enumerate(int(u) for u in chain.get("order", [])):
        if uid in units:
            units[uid]["order"] = i
    return chain, notes


def moved(chain, edits, unit_id, delta):
    """The edits with the unit moved delta places within its program (None if it cannot)."""
    where = program_of(chain, unit_id)
    if where is None:
        return None
    ids = [int(u) for u in where[3]["units"]]
    i = ids.index(unit_id)
    j = i + delta
    if j < 0 or j >= len(ids):
        return None
    ids[i], ids[j] = ids[j], ids[i]
    e = normalised(edits)
    order = [int(u) for u in chain.get("order", [])]
    in_order = [u for u in order if u in set(ids)]
    e["order"] = _slot_fill(order, set(in_order), [u for u in ids if u in set(in_order)])
    return e


def with_tool(edits, built, unit_id, tool_id):
    """The edits with the unit's tool set (back to the chain's tool: the override goes)."""
    e = normalised(edits)
    original = units_by_id(built).get(unit_id, {}).get("tool")
    if tool_id == original:
        e["tools"].pop(unit_id, None)
    else:
        e["tools"][unit_id] = tool_id
    return e


def with_enabled(edits, unit_id, enabled):
    e = normalised(edits)
    d = set(e["disabled"])
    if enabled:
        d.discard(unit_id)
    else:
        d.add(unit_id)
    e["disabled"] = sorted(d)
    return e
