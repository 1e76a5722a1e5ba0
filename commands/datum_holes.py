"""Commands of datum (photo) holes and compensated drilling:

  AeroNC_DefineDatumHoles      right-click on holes (cylindrical faces or their circular edges, in
                               the 3-D view or the tree): Define as datum (photo) hole
  AeroNC_CameraProgram         the camera program of a photo-hole set (APT and NC)
  AeroNC_ImportMeasurements    a measurement file for a photo-hole set (or again for a measured set)
  AeroNC_CompensatedDrilling   the compensated drilling operation in the part's Job
"""
import FreeCADGui

from aeronc.commands.base import Command


def selected_holes():
    """(part, hole faces or edges) when everything selected is a hole of one part: faces or
    circular edges picked in the 3-D view, or hole elements of a Machining Features tree;
    else None."""
    from aeronc.drilling import hole_geometry
    part, subs = None, []
    selection = FreeCADGui.Selection.getSelectionEx()
    # Picking an element in the tree also selects its faces on the part (face_highlight): those
    # faces (a countersink's cone, a counterbore's floor) stand for the element, not for holes.
    mirrored = set()
    for s in selection:
        if getattr(s.Object, "ElementType", None) == "hole":
            for linked, names in getattr(s.Object, "Faces", None) or []:
                mirrored.update((linked.Name, n) for n in names)
    for s in selection:
        obj = s.Object
        if getattr(obj, "ElementType", None) == "hole":
            try:
                linked, name = hole_geometry.element_hole_face(obj)
            except hole_geometry.HoleError:
                return None
            if part not in (None, linked):
                return None
            part = linked
            subs.append(name)
            continue
        names = [n for n in s.SubElementNames if (obj.Name, n) not in mirrored]
        if mirrored and not names and s.SubElementNames:
            continue
        if not names or not hasattr(obj, "Shape") or part not in (None, obj):
            return None
        part = obj
        subs += names
    if part is None or not subs:
        return None
    try:
        hole_geometry.selected_hole_faces(part.Shape, subs)
    except (hole_geometry.HoleError, Exception):
        return None
    return part, subs


def _selected(kind):
    sel = FreeCADGui.Selection.getSelection()
    if len(sel) != 1:
        return None
    from aeronc.objects.base import proxy_type
    return sel[0] if proxy_type(sel[0]) == kind else None


def selected_photo_set():
    from aeronc.objects import photo_hole_set
    return _selected(photo_hole_set.TYPE)


def selected_measured_set():
    from aeronc.objects import measured_hole_set
    return _selected(measured_hole_set.TYPE)


class DefineDatumHoles(Command):
    ICON = "PhotoHoleSet"
    MENU_TEXT = "Define as datum (photo) hole"
    TOOLTIP = ("Add the selected holes (cylindrical faces or their circular edges) to the part's photo-hole set, "
               "in the order selected: drilled in advance, measured by the camera, left out of the drilling")

    def target(self):
        return selected_holes()

    def run(self, picked):
        from aeronc.makers import datum_holes
        obj = datum_holes.define_datum_holes(FreeCADGui.ActiveDocument.Document, *picked)
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(obj)


class CameraProgram(Command):
    ICON = "CameraProgram"
    MENU_TEXT = "Camera program..."
    TOOLTIP = ("Write the camera program of the selected photo-hole set: an APT CL file (GOTO/x,y,z,i,j,k normal "
               "to the surface, approach and safe height) and the NC program posted for the camera's machine")

    def target(self):
        return selected_photo_set()

    def run(self, obj):
        from aeronc.panels.photo_hole_set_panel import PhotoHoleSetPanel
        PhotoHoleSetPanel(obj).write_camera_program()
        PhotoHoleSetPanel.current = None


class ImportMeasurements(Command):
    ICON = "MeasuredHoleSet"
    MENU_TEXT = "Import measurements..."
    TOOLTIP = ("Import the camera's measurement file (hole,u,v,height[,quality]) of the selected photo-hole set "
               "through the machine's transform chain, and show each datum hole's deviation")

    def target(self):
        return selected_measured_set() or selected_photo_set()

    def run(self, obj):
        from aeronc.objects import measured_hole_set
        if measured_hole_set.is_measured_hole_set(obj):
            from aeronc.panels.measured_hole_set_panel import MeasuredHoleSetPanel
            panel = MeasuredHoleSetPanel(obj)
            FreeCADGui.Control.showDialog(panel)
            panel.reimport()
            return
        from aeronc.panels.photo_hole_set_panel import PhotoHoleSetPanel
        panel = PhotoHoleSetPanel(obj)
        FreeCADGui.Control.showDialog(panel)
        panel.import_file()


class CompensatedDrilling(Command):
    ICON = "CompensatedDrilling"
    MENU_TEXT = "Compensated drilling"
    TOOLTIP = ("Drill the part's holes (not the datum holes) at their compensated positions along the surface "
               "normals: a Path operation in the part's Job, updated when new measurements are imported")

    def target(self):
        return selected_measured_set() or selected_photo_set()

    def run(self, obj):
        from aeronc.makers import datum_holes
        from aeronc.objects import measured_hole_set
        ms = obj if measured_hole_set.is_measured_hole_set(obj) else None
        op = datum_holes.create_for_photo_set(ms.PhotoHoleSet if ms is not None else obj, ms)
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(op)
