"""MachiningOperation: a Path operation that machines one unit of the NC machining chain.

The unit, as the chain gave it (geometry in the setup frame, which is the Job's frame: top,
bottom, contour and island loops, open edges, holes; tool; cutting data), is kept in a hidden
JSON property. The parameters a programmer changes are properties of their own (step-down,
step-over, allowances, heights, Active, the ToolController). execute() computes the Path with
the core's toolpath generator, the feeds from the ToolController.

A parameter whose value differs from the chain's is listed in UserEdited, so that rebuilding
the chain keeps it (machining_chain.update reports what it kept). The proxy keeps no state:
everything is in properties and survives save and reopen.
"""
import json
import re


from aeronc import pathcompat
from aeronc.objects.base import BaseProxy, declare_property
from aeronc.operations import moves
from aeronc.post import readiness

COOLANT_MODES = ["None", "Flood", "Mist"]


def declare_path_properties(obj):
    """The properties FreeCAD's Path Job and posts read of any operation."""
    g = "Path"
    declare_property(obj, "App::PropertyBool", "Active", g, "Make False to leave the operation out of the program")
    declare_property(obj, "App::PropertyLink", "ToolController", g, "The tool controller the operation uses")
    if "CoolantMode" not in obj.PropertiesList:
        declare_property(obj, "App::PropertyEnumeration", "CoolantMode", g, "Coolant of the operation", COOLANT_MODES)
        obj.CoolantMode = "Flood"
    declare_property(obj, "App::PropertyString", "CycleTime", g, "Estimated machining time (HH:MM:SS)",
                     read_only=True)


class Parameter:
    """An editable parameter: a property standing for one field of the toolpath input."""

    def __init__(self, name, prop_type, key, doc, default=0.0):
        self.name, self.prop_type, self.key, self.doc, self.default = name, prop_type, key, doc, default

    def chain_value(self, unit):
        """The property's value as the chain (and the Job's defaults) give it."""
        v = unit.get(self.key)
        return float(self.default if v is None else v)

    def current(self, obj):
        v = getattr(obj, self.name)
        return float(getattr(v, "Value", v))

    def input_value(self, obj, unit):
        """(key, value) of the parameter in the toolpath generator's input."""
        return self.key, self.current(obj)


def reference_top(unit):
    """The top the relative clearance is measured from: the unit's, or its highest hole's, or the
    material earlier units leave standing over it (stockTop) when that is higher."""
    tops = [float(h["top"]) for h in unit.get("holes") or [] if "top" in h]
    top = max(tops) if tops else float(unit.get("top", 0.0))
    if unit.get("stockTop") is not None:
        top = max(top, float(unit["stockTop"]))
    return top


class SafeHeight(Parameter):
    """FreeCAD's SafeHeight, absolute; the generator takes it as "clearance" above the top."""

    def chain_value(self, unit):
        return reference_top(unit) + float(unit.get(self.key, self.default))

    def input_value(self, obj, unit):
        above = self.current(obj) - reference_top(unit)
        if above <= 0:
            raise ValueError("{}: the safe height {:g} is not above the top {:g}".format(
                obj.Label, self.current(obj), reference_top(unit)))
        return self.key, above


STEP_DOWN = Parameter("StepDown", "App::PropertyLength", "stepDown", "Depth of cut of each level (a_p)")
STEP_OVER = Parameter("StepOver", "App::PropertyLength", "stepOver", "Distance between neighbouring passes (a_e)")
RADIAL = Parameter("RadialAllowance", "App::PropertyDistance", "radialAllowance", "Material left on the walls")
AXIAL = Parameter("AxialAllowance", "App::PropertyDistance", "axialAllowance", "Material left on the floor")
SAFE = SafeHeight("SafeHeight", "App::PropertyDistance", "clearance",
                  "Height of the rapid moves between cuts (Job frame)", 3.0)
CLEARANCE = Parameter("ClearanceHeight", "App::PropertyDistance", "safeHeight",
                      "Height where the operation starts and ends (Job frame)")
RAMP = Parameter("RampAngle", "App::PropertyAngle", "rampAngle", "Angle of ramping entries, degrees", 3.0)
PECK = Parameter("PeckDepth", "App::PropertyLength", "peck", "Depth of each peck (G83); 0: no pecking")
DWELL = Parameter("DwellTime", "App::PropertyFloat", "dwell", "Dwell at the bottom, s (G82); 0: none")


class MachiningOperation(BaseProxy):
    Type = "AeroNC::MachiningOperation"
    PARAMETERS = [STEP_DOWN, STEP_OVER, RADIAL, AXIAL, SAFE, CLEARANCE, RAMP]
    # The unit's fields the toolpath generator takes as they are (the operation's geometry).
    GEOMETRY_KEYS = ("top", "bottom", "contour", "islands", "openEdges")
    ICON = "MachiningOperation"

    def __init__(self, obj):
        super().__init__(obj)
        self.declare(obj)

    def declare(self, obj):
        cls = type(self)
        declare_path_properties(obj)
        g = "Machining unit"
        declare_property(obj, "App::PropertyInteger", "UnitId", g, "Unit of the machining chain", read_only=True)
        declare_property(obj, "App::PropertyInteger", "ElementId", g, "Domain element the unit machines", read_only=True)
        declare_property(obj, "App::PropertyInteger", "SetupId", g, "Setup of the unit", read_only=True)
        declare_property(obj, "App::PropertyString", "Operation", g, "Operation type of the unit", read_only=True)
        declare_property(obj, "App::PropertyString", "Step", g, "Step of the process (r, w, c, ss, sf, fs, ff)",
                         read_only=True)
        declare_property(obj, "App::PropertyString", "Tool", g, "Tool of the unit in the knowledge base", read_only=True)
        declare_property(obj, "App::PropertyDistance", "Top", g, "Top of the unit (Job frame)", read_only=True)
        declare_property(obj, "App::PropertyDistance", "Bottom", g, "Bottom of the unit (Job frame)", read_only=True)
        declare_property(obj, "App::PropertyString", "Unit", g, "The unit as the chain gave it (JSON)", hidden=True)
        declare_property(obj, "App::PropertyStringList", "UserEdited", g,
                         "Parameters changed by hand: rebuilding the chain keeps them", read_only=True)
        g = "Parameters"
        for p in cls.PARAMETERS:
            declare_property(obj, p.prop_type, p.name, g, p.doc)
        g = "Result"
        declare_property(obj, "App::PropertyLength", "CutLength", g, "Length of the feed moves", read_only=True)
        declare_property(obj, "App::PropertyLength", "RapidLength", g, "Length of the rapid moves", read_only=True)
        declare_check_properties(obj)

    # --- user edits --------------------------------------------------------------------------

    def onChanged(self, obj, prop):
        if prop in ("Unit", "UserEdited") or "Restore" in obj.State or not getattr(obj, "Unit", ""):
            return
        if prop == "Active" or prop == "ToolController" or any(p.name == prop for p in self.PARAMETERS):
            edited = self.edited_parameters(obj)
            if edited != list(obj.UserEdited):
                obj.UserEdited = edited

    def edited_parameters(self, obj):
        """Names of the properties whose value is not the chain's."""
        unit = unit_of(obj)
        out = [p.name for p in self.PARAMETERS if abs(p.current(obj) - p.chain_value(unit)) > 1e-9]
        if bool(obj.Active) != bool(unit.get("enabled", True)):
            out.append("Active")
        tc = obj.ToolController
        if tc is not None and unit.get("tool") and tool_of_controller(tc) not in ("", unit["tool"]):
            out.append("ToolController")
        return out

    # --- the unit ----------------------------------------------------------------------------

    def assign(self, obj, unit, tc):
        """Give the operation its unit and ToolController. What the user edited keeps its value;
        returns the edits kept against a different chain value: [(property, kept, chain's)]."""
        edited = set(obj.UserEdited)
        kept = []
        # Only what changes is set: an operation whose unit is the same is not recomputed.
        _set(obj, "Unit", json.dumps(unit, separators=(",", ":"), sort_keys=True))  # first: onChanged compares with it
        _set(obj, "UnitId", int(unit["id"]))
        _set(obj, "ElementId", int(unit.get("element", -1)))
        _set(obj, "SetupId", int(unit.get("setup", 0)))
        _set(obj, "Operation", str(unit.get("operation", "")))
        _set(obj, "Step", str(unit.get("step", "")))
        _set(obj, "Tool", str(unit.get("tool", "")))
        _set(obj, "Top", float(unit.get("top", 0.0)))
        _set(obj, "Bottom", float(unit.get("bottom", 0.0)))
        for p in self.PARAMETERS:
            value = p.chain_value(unit)
            if p.name in edited:
                if abs(p.current(obj) - value) > 1e-9:
                    kept.append((p.name, p.current(obj), value))
                continue
            if abs(p.current(obj) - value) > 1e-12:
                setattr(obj, p.name, value)
        enabled = bool(unit.get("enabled", True))
        if "Active" in edited:
            if bool(obj.Active) != enabled:
                kept.append(("Active", bool(obj.Active), enabled))
        else:
            _set(obj, "Active", enabled)
        if "ToolController" in edited and obj.ToolController is not None:
            if obj.ToolController is not tc:
                kept.append(("ToolController", obj.ToolController.Label, tc.Label if tc is not None else ""))
        elif obj.ToolController is not tc:
            obj.ToolController = tc
        _set(obj, "UserEdited", self.edited_parameters(obj))
        return kept

    # --- the path ----------------------------------------------------------------------------

    def toolpath_input(self, obj):
        """The toolpath generator's input: the unit's geometry, the operation's parameters and
        the cutter of its ToolController."""
        unit = unit_of(obj)
        data = {"operation": unit["operation"], "name": obj.Label}
        data.update({k: unit[k] for k in self.GEOMETRY_KEYS if unit.get(k) is not None})
        if unit.get("stockTop") is not None:
            data["stockTop"] = unit["stockTop"]
        for p in self.PARAMETERS:
            key, value = p.input_value(obj, unit)
            data[key] = value
        cutter = {k: v for k, v in (unit.get("cutter") or {}).items() if k in ("diameter", "cornerRadius")}
        cutter.update({k: v for k, v in cutter_of(obj.ToolController).items() if k in ("diameter", "cornerRadius")})
        data["cutter"] = cutter
        return data

    def toolpath_inputs(self, obj):
        """The generator's inputs whose toolpaths, one after the other, make the operation's."""
        return [self.toolpath_input(obj)]

    def execute(self, obj):
        if not obj.Unit:
            return
        tc = obj.ToolController
        try:
            if tc is None:
                raise RuntimeError("{}: no tool controller; choose one for the operation".format(obj.Label))
            from aeronc import _core
            # The core writes the Path's G-code and the time estimate: no Python work per move.
            program = _core.toolpath_program([json.dumps(i) for i in self.toolpath_inputs(obj)], obj.Label,
                                             tc.HorizFeed.Value, tc.VertFeed.Value,  # mm/s
                                             tc.HorizRapid.Value, tc.VertRapid.Value)
        except Exception as e:
            # No path rather than the last one computed for other parameters; the mark keeps the
            # posts from writing the operation as a tool change with no moves.
            obj.Path = pathcompat.path_of([])
            obj.CutLength = obj.RapidLength = 0.0
            obj.CycleTime = ""
            mark(obj, readiness.NO_TOOLPATH, re.sub(r"^unit \d+: ", "", str(e)))  # the batch's index: not the user's
            raise
        obj.Path = pathcompat.path_from_gcode(program["gcode"])
        obj.CutLength = float(program["cutLength"])
        obj.RapidLength = float(program["rapidLength"])
        obj.CycleTime = moves.clock_text(program["seconds"])
        mark(obj, readiness.NOT_CHECKED, "")


def declare_check_properties(obj):
    """Check and Note: whether the operation may reach a program (aeronc.post.readiness). Output
    properties: marking an operation does not make it compute its path again."""
    g = "Result"
    declare_property(obj, "App::PropertyEnumeration", "Check", g,
                     "Not checked, Passed (the posted program's simulation found nothing), No toolpath, "
                     "Failed (gouges the part or rapids through material): the posts refuse the last two",
                     readiness.CHECK_STATES, read_only=True, output=True)
    declare_property(obj, "App::PropertyString", "Note", g, "Why the operation has no toolpath or failed its check",
                     read_only=True, output=True)


def mark(obj, state, note):
    """Set an operation's check state and note (only what changes)."""
    if "Check" not in obj.PropertiesList:
        declare_check_properties(obj)
    if obj.Check != state:
        obj.Check = state
    if obj.Note != note:
        obj.Note = note


def _set(obj, prop, value):
    current = getattr(obj, prop)
    if getattr(current, "Value", current) != value:
        setattr(obj, prop, value)


def unit_of(obj):
    """The unit an operation machines, as the chain gave it (dict)."""
    return json.loads(obj.Unit) if obj.Unit else {}


def tool_of_controller(tc):
    """The knowledge-base tool id of a ToolController made for the chain, or ''."""
    tag = getattr(tc, "AeroNCTool", "")
    return tag.split("/")[0] if tag else ""


def cutter_of(tc):
    """Diameter, corner radius and type of the ToolController's bit ({} without a bit)."""
    bit = getattr(tc, "Tool", None) if tc is not None else None
    if bit is None or not hasattr(bit, "Diameter"):
        return {}
    d = float(bit.Diameter.Value)
    shape = str(getattr(bit, "BitShape", "")).lower()
    if ("chamfer" in shape or "v-bit" in shape) and hasattr(bit, "CuttingEdgeAngle"):
        # A cone: its included angle (FreeCAD's CuttingEdgeAngle) and flat tip.
        tip = float(bit.TipDiameter.Value) if hasattr(bit, "TipDiameter") else 0.0
        return {"diameter": d, "cornerRadius": 0.0, "type": "chamfer", "tipDiameter": tip,
                "includedAngle": float(getattr(bit.CuttingEdgeAngle, "Value", bit.CuttingEdgeAngle))}
    if "drill" in shape:
        return {"diameter": d, "cornerRadius": 0.0, "type": "drill"}
    if "ball" in shape:
        return {"diameter": d, "cornerRadius": d / 2, "type": "ball"}
    if hasattr(bit, "FlatRadius"):
        return {"diameter": d, "cornerRadius": max(0.0, d / 2 - float(bit.FlatRadius.Value)), "type": "bull"}
    if hasattr(bit, "CornerRadius"):
        r = float(bit.CornerRadius.Value)
        return {"diameter": d, "cornerRadius": r, "type": "bull" if r > 0 else "flat"}
    return {"diameter": d, "cornerRadius": 0.0, "type": "flat"}
