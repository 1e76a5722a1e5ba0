"""Commands of datum (photo) holes and compensated drilling:

  AeroNC_DefineDatumHoles      right-click on holes (cylindrical faces or their circular edges, in
                               the 3-D view or the tree): Define as datum (photo) hole
  AeroNC_CameraProgram         the camera program of a photo-hole set (APT and NC)
  AeroNC_ImportMeasurements    a measurement file for a photo-hole set (or again for a measured set)
  AeroNC_CompensatedDrilling   the compensated drilling operation in the part's Job
"""
import FreeCAD
import FreeCADGui

import aeronc


def selected_holes():
    """(part, hole faces or edges) when everything selected is a hole of one part: faces or
    circular edges picked in the 3-D view, or hole elements of a Machining Features tree;
    else None."""
    from aeronc import hole_geometry
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


def _idle():
    return FreeCADGui.ActiveDocument is not None and not FreeCADGui.Control.activeDialog()


def _error(title, e):
    from PySide import QtGui
    FreeCAD.Console.PrintError("AeroNC: {}\n".format(e))
    QtGui.QMessageBox.critical(FreeCADGui.getMainWindow(), "AeroNC: " + title, str(e))


class DefineDatumHoles:
    def GetResources(self):
        return {"Pixmap": aeronc.icon("PhotoHoleSet"),
                "MenuText": "Define as datum (photo) hole",
                "ToolTip": "Add the selected holes (cylindrical faces or their circular edges) to the part's "
                           "photo-hole set, in the order selected: drilled in advance, measured by the camera, "
                           "left out of the drilling"}

    def IsActive(self):
        return _idle() and selected_holes() is not None

    def Activated(self):
        picked = selected_holes()
        if picked is None:
            return
        from aeronc.objects import photo_hole_set
        try:
            obj = photo_hole_set.define_datum_holes(FreeCAD.ActiveDocument, *picked)
        except Exception as e:
            _error("datum holes", e)
            return
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(obj)


class CameraProgram:
    def GetResources(self):
        return {"Pixmap": aeronc.icon("CameraProgram"),
                "MenuText": "Camera program...",
                "ToolTip": "Write the camera program of the selected photo-hole set: an APT CL file "
                           "(GOTO/x,y,z,i,j,k normal to the surface, approach and safe height) and the NC program "
                           "posted for the camera's machine"}

    def IsActive(self):
        return _idle() and selected_photo_set() is not None

    def Activated(self):
        from aeronc.panels.photo_hole_set_panel import PhotoHoleSetPanel
        obj = selected_photo_set()
        if obj is not None:
            PhotoHoleSetPanel(obj).write_camera_program()
            PhotoHoleSetPanel.current = None


class ImportMeasurements:
    def GetResources(self):
        return {"Pixmap": aeronc.icon("MeasuredHoleSet"),
                "MenuText": "Import measurements...",
                "ToolTip": "Import the camera's measurement file (hole,u,v,height[,quality]) of the selected "
                           "photo-hole set through the machine's transform chain, and show each datum hole's "
                           "deviation"}

    def IsActive(self):
        return _idle() and (selected_photo_set() is not None or selected_measured_set() is not None)

    def Activated(self):
        ms = selected_measured_set()
        if ms is not None:
            from aeronc.panels.measured_hole_set_panel import MeasuredHoleSetPanel
            panel = MeasuredHoleSetPanel(ms)
            FreeCADGui.Control.showDialog(panel)
            panel.reimport()
            return
        obj = selected_photo_set()
        if obj is not None:
            from aeronc.panels.photo_hole_set_panel import PhotoHoleSetPanel
            panel = PhotoHoleSetPanel(obj)
            FreeCADGui.Control.showDialog(panel)
            panel.import_file()


class CompensatedDrilling:
    def GetResources(self):
        return {"Pixmap": aeronc.icon("CompensatedDrilling"),
                "MenuText": "Compensated drilling",
                "ToolTip": "Drill the part's holes (not the datum holes) at their compensated positions along "
                           "the surface normals: a Path operation in the part's Job, updated when new "
                           "measurements are imported"}

    def IsActive(self):
        return _idle() and (selected_photo_set() is not None or selected_measured_set() is not None)

    def Activated(self):
        from aeronc.objects import compensated_drilling
        ms = selected_measured_set()
        ps = ms.PhotoHoleSet if ms is not None else selected_photo_set()
        try:
            op = compensated_drilling.create_for_photo_set(ps, ms)
        except Exception as e:
            _error("compensated drilling", e)
            return
        FreeCADGui.Selection.clearSelection()
        FreeCADGui.Selection.addSelection(op)
