"""GUI side of AeroNC's document objects, imported as aeronc.viewproviders. GUI only: no App
module imports it; install() (at GUI start-up) registers attach() with the App side, which
calls it for the objects the makers create and for objects restored without view providers.
"""
from aeronc.objects.base import proxy_type, set_view_attacher


def install():
    """Give AeroNC's objects their view providers from now on (called once at GUI start-up)."""
    set_view_attacher(attach)


def attach(obj, restoring=False):
    """Give obj the view provider of its AeroNC type (no-op if it already has one).
    restoring: called while the document is being opened."""
    vobj = getattr(obj, "ViewObject", None)
    if vobj is None or getattr(vobj, "Proxy", None) is not None:
        return
    from aeronc.objects import DOMAIN_ELEMENT, MACHINING_FEATURES, SETUP_DIRECTION
    from aeronc.objects import measured_hole_set, photo_hole_set
    from aeronc.operations import compensated_drilling
    from aeronc.objects.machining_chain import TYPE as MACHINING_CHAIN
    from aeronc.objects import impeller_features, impeller_program
    from aeronc.operations import TYPES as OPERATIONS
    from aeronc.operations.impeller_operation import TYPE as IMPELLER_OPERATION
    t = proxy_type(obj)
    if t == impeller_features.TYPE:
        from aeronc.viewproviders.view_impeller import ViewImpellerFeatures as cls
    elif t == impeller_features.NODE_TYPE:
        from aeronc.viewproviders.view_impeller import ViewImpellerFeature as cls
    elif t == impeller_program.TYPE:
        from aeronc.viewproviders.view_impeller import ViewImpellerProgram as cls
    elif t == photo_hole_set.TYPE:
        from aeronc.viewproviders.view_photo_hole_set import ViewPhotoHoleSet as cls
    elif t == measured_hole_set.TYPE:
        from aeronc.viewproviders.view_measured_hole_set import ViewMeasuredHoleSet as cls
    elif t == compensated_drilling.TYPE:
        from aeronc.viewproviders.view_compensated_drilling import ViewCompensatedDrilling as cls
    elif t == MACHINING_FEATURES:
        from aeronc.viewproviders.view_machining_features import ViewMachiningFeatures as cls
    elif t == SETUP_DIRECTION:
        from aeronc.viewproviders.view_setup_direction import ViewSetupDirection as cls
    elif t == DOMAIN_ELEMENT:
        from aeronc.viewproviders.view_domain_element import ViewDomainElement as cls
    elif t == MACHINING_CHAIN:
        from aeronc.viewproviders.view_machining_chain import ViewMachiningChain as cls
    elif t in OPERATIONS or t == IMPELLER_OPERATION:
        from aeronc.viewproviders.view_operation import ViewOperation as cls
    else:
        return
    cls(vobj)
    if restoring:
        # The object has no view state: the document was made under freecadcmd. Its objects
        # come in hidden; show the tree and colour the part once the document is open (the
        # part's view provider resets its colours when it gets its shape during opening).
        vobj.Visibility = True
        if t in (MACHINING_FEATURES, impeller_features.TYPE) and obj.Result:
            from PySide import QtCore
            name, doc = obj.Name, obj.Document
            QtCore.QTimer.singleShot(0, lambda: _colour_later(doc, name))
    elif t in (MACHINING_FEATURES, impeller_features.TYPE) and obj.Result and vobj.Visibility:
        vobj.Proxy.colour_source(obj)


def _colour_later(doc, name):
    try:
        obj = doc.getObject(name)
    except Exception:  # document closed meanwhile
        return
    if obj is not None and getattr(obj.ViewObject, "Proxy", None) is not None:
        obj.ViewObject.Proxy.colour_source(obj)
