"""The machining-domain tree in the document: build, save/reopen, undo, bad input."""
import math
import unittest

import FreeCAD
import Part

from aeronc import makers, objects
from aeronc.pipeline import recognition
from aeronc.objects.domain_element import DomainElement
from aeronc.objects.machining_features import MachiningFeatures
from aeronc.objects.setup_direction import SetupDirection
from aeronc.tests.app import support

BOTH_SIDES = [(0, 0, 1), (0, 0, -1)]


def num(v):
    return float(v) if v is not None else 0.0  # the core writes null where a measure does not apply


def aeronc_objects(doc):
    return [o for o in doc.Objects if (objects.proxy_type(o) or "").startswith("AeroNC::")]


class TestMachiningFeatures(unittest.TestCase):
    def setUp(self):
        self.doc = support.new_document("AeroNCFeatures")
        self.part, self.truth = support.make_panel_object(self.doc)

    def tearDown(self):
        FreeCAD.closeDocument(self.doc.Name)

    def assertTreeMatches(self, group, part):
        """The document tree under group is exactly the stored result's domain tree."""
        result = objects.result_of(group)
        elements = {el["id"]: el for el in result["elements"]}
        self.assertIsInstance(group.Proxy, MachiningFeatures)
        self.assertEqual(group.Source, part)
        self.assertEqual(group.SetupCount, len(result["setups"]))
        self.assertEqual(group.ElementCount, len(elements))
        self.assertEqual(group.HoleCount, sum(1 for e in elements.values() if e["type"] == "hole"))
        self.assertEqual(group.FaceCount, len(part.Shape.Faces))
        self.assertFalse(group.Outdated)
        self.assertEqual(len(group.Group), len(result["setups"]))
        seen = []

        def walk(obj, el_id, parent):
            el = elements[el_id]
            self.assertIsInstance(obj.Proxy, DomainElement)
            self.assertEqual((obj.ElementId, obj.ParentId, obj.ElementType), (el_id, parent, el["type"]))
            self.assertAlmostEqual(obj.Level.Value, num(el["level"]), places=6)
            self.assertAlmostEqual(obj.Depth.Value, max(0.0, num(el["depth"])), places=6)
            self.assertAlmostEqual(obj.FloorArea.Value, num(el["floorArea"]), places=3)
            self.assertAlmostEqual(obj.MinWidth.Value, num(el["minWidth"]), places=6)
            self.assertAlmostEqual(obj.MinCornerRadius.Value, num(el["minCornerRadius"]), places=6)
            if el.get("hole"):
                self.assertAlmostEqual(obj.HoleDiameter.Value, num(el["hole"]["diameter"]), places=6)
                self.assertEqual(obj.Through, el["hole"]["through"])
            else:
                self.assertNotIn("HoleDiameter", obj.PropertiesList)
            linked = obj.Faces[0][1] if obj.Faces else ()
            for sub in linked:
                self.assertEqual(obj.Faces[0][0], part)
                self.assertLessEqual(int(sub[4:]), len(part.Shape.Faces))
            for f in el["floorFaces"] + el["contourFaces"]:
                self.assertIn("Face{}".format(f), linked)
            self.assertEqual([c.ElementId for c in obj.Group], el["children"])
            seen.append(el_id)
            for child, child_id in zip(obj.Group, el["children"]):
                walk(child, child_id, el_id)

        for sobj, setup in zip(group.Group, result["setups"]):
            self.assertIsInstance(sobj.Proxy, SetupDirection)
            self.assertEqual(sobj.SetupId, setup["id"])
            self.assertEqual(list(sobj.Direction), [float(c) for c in setup["direction"]])
            self.assertEqual([o.ElementId for o in sobj.Group], setup["elements"])
            for obj, el_id in zip(sobj.Group, setup["elements"]):
                walk(obj, el_id, -1)
        self.assertEqual(sorted(seen), sorted(elements))
        self.assertEqual(len([o for o in aeronc_objects(group.Document)
                              if objects.proxy_type(o) == objects.DOMAIN_ELEMENT]), len(elements))

    def test_build_save_reopen(self):
        group = makers.create_machining_features(self.doc, self.part, directions=BOTH_SIDES, allowance=2.0)
        self.assertTrue(objects.is_machining_features(group))
        self.assertGreater(group.ElementCount, 0)
        self.assertTreeMatches(group, self.part)
        self.assertEqual(group.Allowance.Value, 2.0)
        self.assertAlmostEqual(group.AngularTolerance.Value,
                               math.degrees(recognition.DEFAULT_ANGULAR_TOLERANCE))
        self.assertEqual([tuple(v) for v in group.Directions], [tuple(map(float, d)) for d in BOTH_SIDES])
        result, name = group.Result, group.Name

        path = support.temp_fcstd("panel")
        self.doc.saveAs(path)
        FreeCAD.closeDocument(self.doc.Name)
        self.doc = FreeCAD.openDocument(path)
        group = self.doc.getObject(name)
        part = self.doc.getObject("Panel")
        self.assertEqual(group.Result, result)
        self.assertTreeMatches(group, part)
        for obj in aeronc_objects(self.doc):
            obj.touch()
        self.doc.recompute()
        self.assertTrue(all("Invalid" not in o.State and "Error" not in o.State for o in self.doc.Objects),
                        [(o.Name, o.State) for o in self.doc.Objects])
        self.assertTreeMatches(group, part)
        self.assertEqual(objects.settings_of(group)["allowance"], 2.0)

    def test_a_document_of_an_older_version_gets_the_properties_it_lacks(self):
        group = makers.create_machining_features(self.doc, self.part, directions=BOTH_SIDES)
        elements = [o for o in aeronc_objects(self.doc) if objects.proxy_type(o) == objects.DOMAIN_ELEMENT]
        holes = [o for o in elements if o.ElementType == "hole"]
        milled = [o for o in elements if o.ElementType != "hole"]
        self.assertTrue(holes and milled)
        # Before Select tools kept its plan in the proxies' properties, a tree had none of them.
        plan_props = ["Material", "Machine", "ToolChangesBefore", "ToolChangesAfter", "RoughingMinutesBefore",
                      "RoughingMinutesAfter", "ToolPlan"]
        for name in plan_props:
            group.removeProperty(name)
        for o in milled:
            for name in ("FinishingTool", "RoughingTool", "MachinableRatio", "NarrowPassages", "ToolError",
                         "FloorFilletRadius"):
                o.removeProperty(name)
        for o in holes:
            for name in ("Drill", "ToolError"):
                o.removeProperty(name)
        self.assertNotIn("Material", group.PropertiesList)
        depths = {o.Name: o.Depth.Value for o in elements}
        name, path = group.Name, support.temp_fcstd("older")
        self.doc.saveAs(path)
        FreeCAD.closeDocument(self.doc.Name)
        self.doc = FreeCAD.openDocument(path)
        group = self.doc.getObject(name)
        for name in plan_props:
            self.assertIn(name, group.PropertiesList)
        self.assertEqual((group.Material, group.ToolPlan, group.ToolChangesAfter), ("", "", 0))
        for name, depth in depths.items():
            o = self.doc.getObject(name)
            self.assertAlmostEqual(o.Depth.Value, depth, places=9)  # restored values stay
            self.assertEqual(o.ToolError, "")
            if o.ElementType == "hole":
                self.assertEqual(o.Drill, "")
                self.assertNotIn("RoughingTool", o.PropertiesList)
            else:
                self.assertEqual((o.RoughingTool, o.MachinableRatio, o.FloorFilletRadius.Value), ("", 0.0, 0.0))
                self.assertNotIn("HoleDiameter", o.PropertiesList)
        self.assertTreeMatches(group, self.doc.getObject("Panel"))

    def test_undo_removes_the_whole_tree_in_one_step(self):
        before = self.doc.UndoCount
        makers.create_machining_features(self.doc, self.part, directions=BOTH_SIDES)
        self.assertEqual(self.doc.UndoCount, before + 1)
        self.assertTrue(aeronc_objects(self.doc))
        self.doc.undo()
        self.assertEqual(aeronc_objects(self.doc), [])
        self.doc.redo()
        group = [o for o in self.doc.Objects if objects.is_machining_features(o)][0]
        self.assertTreeMatches(group, self.part)

    def test_not_a_solid_leaves_the_document_unchanged(self):
        face = self.doc.addObject("Part::Feature", "Face")
        face.Shape = Part.makePlane(10, 10)
        self.doc.recompute()
        names, undo = [o.Name for o in self.doc.Objects], self.doc.UndoCount
        with self.assertRaises(recognition.RecognitionError) as ctx:
            makers.create_machining_features(self.doc, face)
        self.assertIn("Face", str(ctx.exception))  # names the object
        self.assertIn("not a solid", str(ctx.exception))
        self.assertEqual([o.Name for o in self.doc.Objects], names)
        self.assertEqual(self.doc.UndoCount, undo)

    def test_failure_while_building_rolls_back(self):
        # A failure after recognition, while objects are being made, must not leave half a tree.
        names, undo = [o.Name for o in self.doc.Objects], self.doc.UndoCount

        def boom(objs):
            raise RuntimeError("boom")
        from aeronc.makers import machining_features as maker
        saved = maker.attach_views
        maker.attach_views = boom
        try:
            with self.assertRaisesRegex(RuntimeError, "boom"):
                makers.create_machining_features(self.doc, self.part, directions=BOTH_SIDES)
        finally:
            maker.attach_views = saved
        self.assertEqual([o.Name for o in self.doc.Objects], names)
        self.assertEqual(self.doc.UndoCount, undo)

    def test_cancel_leaves_the_document_unchanged(self):
        names = [o.Name for o in self.doc.Objects]
        with self.assertRaises(recognition.RecognitionCancelled):
            makers.create_machining_features(self.doc, self.part, progress=lambda f, s: False)
        self.assertEqual([o.Name for o in self.doc.Objects], names)

    def test_update_and_remove(self):
        group = makers.create_machining_features(self.doc, self.part, directions=[(0, 0, 1)])
        self.assertEqual(group.SetupCount, 1)
        undo = self.doc.UndoCount
        makers.update_machining_features(group, directions=BOTH_SIDES)
        self.assertEqual(self.doc.UndoCount, undo + 1)
        self.assertEqual(group.SetupCount, 2)
        self.assertTreeMatches(group, self.part)
        makers.remove_machining_features(group)
        self.assertEqual(aeronc_objects(self.doc), [])

    def test_outdated_when_the_part_changes(self):
        group = makers.create_machining_features(self.doc, self.part, directions=[(0, 0, 1)])
        self.part.Shape = Part.makeBox(10, 10, 10)
        group.touch()
        self.doc.recompute()
        self.assertTrue(group.Outdated)

    def test_blank_from_a_path_job(self):
        from aeronc import pathcompat
        job = pathcompat.create_job(self.doc, [self.part])
        self.doc.recompute()
        self.assertTrue(pathcompat.is_job(job))
        self.assertEqual(pathcompat.find_jobs(self.doc), [job])
        self.assertFalse(pathcompat.is_job(self.part))
        box = pathcompat.job_stock_box(job)
        bb = self.part.Shape.BoundBox
        self.assertEqual(len(box), 6)
        self.assertLessEqual(box[0], bb.XMin)
        self.assertGreaterEqual(box[5], bb.ZMax)
        group = makers.create_machining_features(self.doc, self.part, directions=[(0, 0, 1)], blank=box)
        self.assertEqual(tuple(group.Blank), tuple(box))
        self.assertEqual(objects.settings_of(group)["blank"], tuple(box))
        self.assertTreeMatches(group, self.part)


if __name__ == "__main__":
    unittest.main()
