"""The main job end to end on a generated double-sided panel, headless."""
import contextlib
import json
import os
import shutil
import tempfile
import unittest

import FreeCAD
import Part

from aeronc import _core, pathcompat
from aeronc.pipeline.verification import VerificationError
from aeronc.post import PostError, nc_post
from aeronc.runs import main_job

PANEL = {"pocketsX": 2, "pocketsY": 1, "islands": False, "openings": False, "lighteningHoles": False,
         "joggles": False, "lowerRibs": False, "flange": False, "bottomPockets": True, "boltHoles": True}


def _write_panel(folder):
    brep, truth = _core.make_panel(json.dumps(PANEL))
    shape = Part.Shape()
    shape.importBrepFromString(brep)
    path = os.path.join(folder, "panel.brep")
    shape.exportBrep(path)
    return path, json.loads(truth)


class MainJobTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="aeronc_mainjob_")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def test_panel_to_programs_report_and_verification(self):
        part, _ = _write_panel(self.tmp)
        out = os.path.join(self.tmp, "out")
        lines = []
        run = main_job.run(part, out, say=lines.append)
        chain = run["chain"]
        setups = [s["name"] for s in chain["setups"]]
        self.assertEqual(sorted(setups), ["+Z", "-Z"])
        # One 840D and one LinuxCNC program per setup, each with moves.
        for k in range(1, len(setups) + 1):
            for ext in ("mpf", "ngc"):
                with open(os.path.join(out, "panel_setup{}.{}".format(k, ext))) as f:
                    text = f.read()
                self.assertIn("G1", text)
        # Every enabled unit is in the report's tables, and every operation was re-read and simulated.
        with open(os.path.join(out, "report.html")) as f:
            html = f.read()
        for u in chain["units"]:
            self.assertIn("<td class='n'>{}</td>".format(u["id"]), html)
        with open(os.path.join(out, "verification.json")) as f:
            report = json.load(f)
        self.assertEqual(len(report["ops"]), len([u for u in chain["units"] if u.get("enabled", True)]))
        self.assertGreater(report["stock"]["blankVolume"], report["stock"]["finalVolume"])
        self.assertTrue(all(op["removedVolume"] >= 0 for op in report["ops"]))
        # The program neither gouges nor rapids through material, and finishes what the plan finishes.
        self.assertEqual(report["gouges"]["count"], 0, report["gouges"].get("worst"))
        self.assertEqual(report["collisions"]["count"], 0, report["collisions"].get("worst"))
        # The bolt hole's 90 degree countersink (12 mm on the 6.6 mm hole) is cut by the crib's
        # 90 degree chamfer mill after the hole is drilled: its tip 0.2 mm under the countersink's
        # lower line, and the verification, which sees the mill's cone, finds the countersink
        # finished (before, 95 mm2 of it stood up to 1.9 mm) and nothing gouged.
        chamfers = [u for u in chain["units"] if u["operation"] == "chamfer"]
        self.assertEqual(len(chamfers), 1)
        unit = chamfers[0]
        self.assertEqual((unit["step"], unit["tool"]), ("e", "CM-90-D10"))
        self.assertAlmostEqual(unit["top"], 20.0, places=6)
        self.assertAlmostEqual(unit["bottom"], 20.0 - 2.7 - 0.2, places=6)
        drill = next(u for u in chain["units"] if u["element"] == unit["element"] and u["step"] in ("d", "h"))
        self.assertGreater(unit["order"], drill["order"])
        hole = next(e for e in run["recognition"]["elements"] if e["id"] == unit["element"])
        cone = {f for a in hole["attached"] if a["kind"] == "countersink" for f in a["faces"]}
        countersink = {f["face"]: f for f in report["coverage"]["faces"] if f["face"] in cone}
        self.assertTrue(countersink)
        for f in countersink.values():
            self.assertTrue(f["measured"])
            self.assertLess(f["maxLeftover"], 0.05, f)
        self.assertFalse(any("countersink" in g["reason"] for g in chain["unmachined"]))
        self.assertEqual([v["check"] for v in run["verification"] if not v["ok"]], [])
        self.assertEqual(run["verdict"]["status"], "READY")
        self.assertEqual(run["materialLeft"], [])
        self.assertEqual(run["leftOut"], [])
        # One progress line per stage, then the total and the verdict.
        self.assertTrue(lines[0].startswith("AeroNC main job"))
        self.assertIn("total", lines[-2])
        self.assertTrue(lines[-1].strip().startswith("READY"), lines[-1])
        # A second run replaces the first's outputs: the same files, no backup.
        first = sorted(os.listdir(out))
        main_job.run(part, out, say=lambda _: None)
        self.assertEqual(sorted(os.listdir(out)), first)
        self.assertFalse([n for n in first if n.endswith(".FCStd1") or ".part" in n])

    def test_part_modelled_far_from_its_origin_stands_centred_on_the_table(self):
        # 700 mm off in X and -500 mm in Y: with the part's origin as the table's centre every move
        # would leave the AC-5AX's +-325 mm; the blank stands centred instead (the post's part zero).
        part, _ = _write_panel(self.tmp)
        shape = Part.read(part)
        shape.translate(FreeCAD.Vector(700, -500, 40))
        far = os.path.join(self.tmp, "far.brep")
        shape.exportBrep(far)
        blank = shape.BoundBox
        self.assertEqual(main_job.part_zero((blank.XMin, blank.YMin, blank.ZMin, blank.XMax, blank.YMax, blank.ZMax),
                                            {"u": (1, 0, 0), "v": (0, 1, 0), "w": (0, 0, 1)}),
                         [-(blank.XMin + blank.XMax) / 2, -(blank.YMin + blank.YMax) / 2, -blank.ZMin])
        out = os.path.join(self.tmp, "far")
        run = main_job.run(far, out, say=lambda _: None)
        self.assertEqual(len(run["programs"]), 4)
        with open(os.path.join(out, "verification.json")) as f:
            report = json.load(f)
        self.assertEqual(report["gouges"]["count"], 0, report["gouges"].get("worst"))
        self.assertEqual(report["collisions"]["count"], 0, report["collisions"].get("worst"))

    def test_part_without_elements_names_the_stage_and_still_has_its_report(self):
        box = os.path.join(self.tmp, "box.brep")
        Part.makeBox(50, 40, 10).exportBrep(box)
        out = os.path.join(self.tmp, "out")
        lines = []
        with self.assertRaises(main_job.MainJobError) as ctx:
            main_job.run(box, out, say=lines.append)
        self.assertIn("recognise", str(ctx.exception))
        self.assertEqual(_programs_in(out), [])
        self.assertIn("FAILED at recognise", _banner(out))
        with open(os.path.join(out, "run.json")) as f:
            summary = json.load(f)
        self.assertEqual(summary["failed"]["stage"], "recognise")
        self.assertEqual(summary["programs"], [])
        self.assertIn("FAILED", lines[-1])

    def test_a_run_failing_after_the_post_leaves_no_program(self):
        # The programs are posted, then the verification fails: nothing that looks finished stays.
        part = _write_tslot(self.tmp)
        out = os.path.join(self.tmp, "out")

        def verify(job):
            raise VerificationError("rs274 reported: a made-up failure")
        with _stages_replaced(verify=verify):
            with self.assertRaises(main_job.MainJobError) as ctx:
                main_job.run(part, out, say=lambda _: None)
        self.assertIn("verify: rs274 reported", str(ctx.exception))
        self.assertEqual(_programs_in(out), [])
        self.assertIn("FAILED at verify", _banner(out))

    def test_part_nothing_of_which_can_be_machined_gets_no_program_and_its_report(self):
        part = _write_tslot(self.tmp)
        out = os.path.join(self.tmp, "out")

        def refuse_all(job):  # every unit with a radial allowance no cutter fits in
            for _, op in job.ops_by_label.values():
                op.RadialAllowance = 500
                op.recompute()
            return "all refused"
        lines = []
        with _stages_inserted_after("machining chain", refuse_all):
            with self.assertRaises(main_job.MainJobError) as ctx:
                main_job.run(part, out, say=lines.append)
        self.assertIn("NO PROGRAM", str(ctx.exception))
        self.assertIn("no toolpath", str(ctx.exception))
        self.assertEqual(_programs_in(out), [])
        self.assertTrue(_banner(out).startswith("NO PROGRAM"))
        self.assertTrue(any(l.strip().startswith("NO PROGRAM") for l in lines))

    def test_material_under_an_overhang_makes_the_verdict_incomplete_and_names_it(self):
        # A plate with a T-slot: the undercut either side of the slot is no element's (nothing
        # machines it along +Z); 10 mm of material stays over its floors. Nothing may read pass.
        part = _write_tslot(self.tmp)
        out = os.path.join(self.tmp, "out")
        lines = []
        run = main_job.run(part, out, say=lines.append)
        self.assertEqual(len(run["recognition"]["unclaimedFaces"]), 8)
        self.assertFalse(run["verdict"]["ready"])
        self.assertIn("8 unclaimed faces", run["verdict"]["text"])
        unclaimed = [e for e in run["materialLeft"] if e["element"] is None]
        self.assertEqual(len(unclaimed), 1)
        self.assertEqual(sorted(unclaimed[0]["faces"]), sorted(run["recognition"]["unclaimedFaces"]))
        self.assertGreaterEqual(unclaimed[0]["area"], 2 * 100 * 10)  # the two undercut floors at least
        self.assertGreaterEqual(unclaimed[0]["maxLeft"], 10 - 0.5)  # the overhang's 10 mm, to a cell
        # The checks table, the leftover picture's caption, the report's first line and the console.
        against = [v for v in run["verification"] if v["check"] == "coverage against the part"]
        self.assertEqual(len(against), 1)
        self.assertFalse(against[0]["ok"])
        self.assertIn("8 unclaimed faces", against[0]["detail"])
        captions = [c for c, _ in run["pictures"] if c.startswith("Material left")]
        self.assertTrue(captions and "8 unclaimed faces" in captions[0], captions)
        self.assertIn("8 unclaimed faces", _banner(out))
        self.assertNotIn("READY:", lines[-1].replace("NOT READY", ""))
        self.assertIn("8 unclaimed faces", lines[-1])

    def test_gate_leaves_out_a_gouging_operation_and_one_without_toolpath(self):
        part, _ = _write_panel(self.tmp)
        out = os.path.join(self.tmp, "out")
        picked = {}

        def sabotage(job):
            # A finishing pocket 0.6 mm too deep (a toolpath bug), and the roughing of another
            # element with an allowance no cutter fits in (the toolpath core refuses it).
            ops = [op for _, op in job.ops_by_label.values()]
            deep = next(op for op in ops if op.Step == "w" and op.Operation == "pocket")
            refused = next(op for op in ops if op.Step == "r" and op.ElementId != deep.ElementId)
            deep.Path = _lowered(deep.Path, 0.6)
            refused.RadialAllowance = 500
            refused.recompute()
            picked.update(deep=deep.Label, refused=refused.Label, element=refused.ElementId,
                          followers=[op.Label for op in ops if op.ElementId == refused.ElementId and op is not refused])
            return "sabotaged"
        lines = []
        with _stages_inserted_after("machining chain", sabotage):
            run = main_job.run(part, out, say=lines.append)
        kinds = {e["label"]: e["kind"] for e in run["leftOut"]}
        self.assertEqual(kinds.get(picked["deep"]), "gouge")
        self.assertEqual(kinds.get(picked["refused"]), "no toolpath")
        for label in picked["followers"]:  # the element's later units would cut what the roughing leaves
            self.assertEqual(kinds.get(label), "dependent", label)
        self.assertEqual(run["verdict"]["status"], "NOT READY")
        self.assertIn("left out", run["verdict"]["text"])
        self.assertIn(picked["deep"], run["verdict"]["text"])
        # The run's summary counts an element whose operation was left out as not machined.
        with open(os.path.join(out, "run.json")) as f:
            summary = json.load(f)
        why = summary["notMachined"].get(str(picked["element"]), "")
        self.assertIn("{} left out of the programs".format(picked["refused"]), why)
        self.assertTrue(_banner(out).startswith("NOT READY"))
        self.assertTrue(lines[-1].strip().startswith("NOT READY"), lines[-1])
        # What is delivered is safe: re-verified, and every left-out operation named in it.
        with open(os.path.join(out, "verification.json")) as f:
            report = json.load(f)
        self.assertEqual(report["gouges"]["count"], 0, report["gouges"].get("worst"))
        self.assertEqual(report["collisions"]["count"], 0, report["collisions"].get("worst"))
        texts = ""
        for name in _programs_in(out):
            with open(os.path.join(out, name)) as f:
                texts += f.read()
        for label in (picked["deep"], picked["refused"]):
            self.assertNotIn("operation: {})".format(label), texts)
            self.assertIn("(left out: {}: ".format(label), texts)
        self.assertIn("(left out: {}: gouges the part".format(picked["deep"]), texts)
        self.assertNotIn(".FAILED.", " ".join(_programs_in(out)))
        # The operations carry their mark in the saved document, and the post refuses them.
        doc = FreeCAD.openDocument(os.path.join(out, "panel.FCStd"))
        try:
            ops = {o.Label: o for o in doc.Objects if hasattr(o, "Check")}
            self.assertEqual(ops[picked["deep"]].Check, "Failed")
            self.assertIn("gouges the part", ops[picked["deep"]].Note)
            self.assertEqual(ops[picked["refused"]].Check, "No toolpath")
            self.assertIn("does not fit", ops[picked["refused"]].Note)
            self.assertTrue(all(o.Check == "Passed" for label, o in ops.items() if label not in kinds and o.Active))
            job = next(j for j in pathcompat.find_jobs(doc) if ops[picked["deep"]] in j.Operations.Group)
            with self.assertRaises(PostError) as ctx:
                nc_post.export(pathcompat.job_post_objects(job), "-", "", "840d")
            self.assertIn("is not ready to post", str(ctx.exception))
        finally:
            FreeCAD.closeDocument(doc.Name)


T_SLOT = "T-slot plate: 174 x 174 x 30, a 20 mm slot through along X, 40 mm wide between z 8 and 18 over 100 mm"


def _write_tslot(folder):
    """A plate with a T-slot, by plain boolean cuts (Part): the undercut is no element's."""
    plate = Part.makeBox(174, 174, 30)
    slot = Part.makeBox(176, 20, 25, FreeCAD.Vector(-1, 77, 8))
    under = Part.makeBox(100, 40, 10, FreeCAD.Vector(37, 67, 8))
    shape = plate.cut(slot.fuse(under)).removeSplitter()
    path = os.path.join(folder, "tslot.brep")
    shape.exportBrep(path)
    return path


def _lowered(path, dz):
    import Path
    out = []
    for c in path.Commands:
        p = dict(c.Parameters)
        if "Z" in p and c.Name not in ("G0", "G00"):
            p["Z"] = p["Z"] - dz
        out.append(Path.Command(c.Name, p))
    return Path.Path(out)


def _programs_in(out):
    return sorted(n for n in os.listdir(out) if n.endswith((".mpf", ".ngc")))


def _banner(out):
    """The report's first line (the text of its first paragraph)."""
    import re
    with open(os.path.join(out, "report.html")) as f:
        html = f.read()
    body = html[html.index("<body>") + len("<body>"):].lstrip()
    m = re.match(r"<p class='banner [a-z]+'>(.*?)</p>", body)
    return __import__("html").unescape(m.group(1)) if m else body[:200]


@contextlib.contextmanager
def _stages_replaced(**stages):
    saved = main_job.STAGES
    main_job.STAGES = tuple((n, stages.get(n, f)) for n, f in saved)
    try:
        yield
    finally:
        main_job.STAGES = saved


@contextlib.contextmanager
def _stages_inserted_after(name, stage):
    saved = main_job.STAGES
    k = [n for n, _ in saved].index(name) + 1
    main_job.STAGES = saved[:k] + (("test hook", stage),) + saved[k:]
    try:
        yield
    finally:
        main_job.STAGES = saved


if __name__ == "__main__":
    unittest.main()
