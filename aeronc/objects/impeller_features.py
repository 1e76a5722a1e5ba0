"""ImpellerFeatures: the recognised impeller of a part in the document, and its nodes.

The group holds the core's recognition and dimensions (Result, JSON with every face's colour
role added as faceRoles, so the 3D view and the pictures colour it the same way) and one
ImpellerFeature node per blade (main or splitter, in angular order), and for the hub, the
root fillets, the shroud faces, the bore, the planes and the turned faces. Each node lists the
FaceN of the source solid it stands for. Made by aeronc.impeller.programming.
"""
import json

from aeronc.objects.base import BaseProxy, declare_property, proxy_type

TYPE = "AeroNC::ImpellerFeatures"
NODE_TYPE = "AeroNC::ImpellerFeature"
ROLES = ["main_blade", "splitter_blade", "hub", "root_fillets", "shroud", "bore", "planes", "turned", "holes"]
DIMENSIONS = [("BoreDiameter", "boreDiameter", "Diameter of the centre bore"),
              ("BoreDepth", "boreDepth", "Length of the bore along the axis"),
              ("MinChannelWidth", "minChannelWidth", "Narrowest distance between two adjacent blades"),
              ("FilletRadius", "filletRadius", "Root fillet radius"),
              ("BladeHeight", "bladeHeight", "Main blade height above the hub"),
              ("SplitterHeight", "splitterHeight", "Splitter blade height above the hub"),
              ("OuterRadius", "outerRadius", "Largest radius of the part about its axis"),
              ("AxialLength", "axialLength", "Extent of the part along its axis")]


class ImpellerFeatures(BaseProxy):
    Type = TYPE

    def __init__(self, obj):
        super().__init__(obj)
        self.declare(obj)

    def declare(self, obj):
        g = "Impeller"
        declare_property(obj, "App::PropertyLinkGlobal", "Source", g, "The solid recognised as an impeller")
        declare_property(obj, "App::PropertyInteger", "BladeCount", g, "Main blades", read_only=True)
        declare_property(obj, "App::PropertyInteger", "SplitterCount", g, "Splitter blades", read_only=True)
        declare_property(obj, "App::PropertyVector", "AxisPoint", g, "A point of the axis", read_only=True)
        declare_property(obj, "App::PropertyVector", "AxisDirection", g, "Axis, from the hub towards the shroud",
                         read_only=True)
        declare_property(obj, "App::PropertyIntegerList", "ClosestPair", g,
                         "The adjacent pair of blades whose shroud faces are closest", read_only=True)
        g = "Dimensions"
        for prop, _, doc in DIMENSIONS:
            declare_property(obj, "App::PropertyLength", prop, g, doc, read_only=True)
        g = "Result"
        declare_property(obj, "App::PropertyString", "Result", g, "Recognition and dimensions (JSON)", hidden=True)

    def execute(self, obj):
        pass


class ImpellerFeature(BaseProxy):
    """One node: a blade, or the hub, fillets, shroud, bore, planes, turned faces or holes."""
    Type = NODE_TYPE

    def __init__(self, obj):
        super().__init__(obj)
        self.declare(obj)

    def declare(self, obj):
        g = "Feature"
        if "Role" not in obj.PropertiesList:
            declare_property(obj, "App::PropertyEnumeration", "Role", g, "What the faces are", ROLES)
            obj.setEditorMode("Role", 1)
        declare_property(obj, "App::PropertyInteger", "BladeIndex", g, "Blade number in angular order (-1: no blade)",
                         -1, read_only=True)
        declare_property(obj, "App::PropertyFloat", "AngleDeg", g, "Angle of the blade about the axis",
                         read_only=True)
        declare_property(obj, "App::PropertyIntegerList", "FaceNumbers", g, "FaceN of the source solid",
                         read_only=True)
        declare_property(obj, "App::PropertyLinkSubListGlobal", "Faces", g, "The faces of the source solid")
        g = "Blade"
        for name, doc in (("PressureFace", "Pressure side (faces the turning direction)"),
                          ("SuctionFace", "Suction side"), ("LeadingFace", "Leading edge (nearer the axis)"),
                          ("TrailingFace", "Trailing edge"), ("ShroudFace", "Blade tip")):
            declare_property(obj, "App::PropertyInteger", name, g, doc, 0, read_only=True)
        declare_property(obj, "App::PropertyIntegerList", "FilletFaces", g, "Root fillets of the blade",
                         read_only=True)

    def execute(self, obj):
        pass


def is_impeller_features(obj):
    return proxy_type(obj) == TYPE


def is_impeller_feature(obj):
    return proxy_type(obj) == NODE_TYPE


def result_of(obj):
    return json.loads(obj.Result) if obj.Result else {}
