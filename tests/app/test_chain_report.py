"""The machining-chain report and its pictures, headless."""
import os
import re
import tempfile
import unittest

from aeronc.reports import chain_report, toolpath_picture


def _run():
    chain = {
        "family": "integral_panel", "material": "7050-T7451", "machine": "AC-5AX",
        "setups": [{"id": 0, "name": "+Z", "direction": [0, 0, 1], "processes": [
            {"id": 1, "machine": "AC-5AX", "tool": "EM-B16R2", "steps": [
                {"code": "r", "programs": [{"tool": "EM-B16R2", "units": [10, 11]}]}]},
            {"id": 2, "machine": "AC-5AX", "tool": "DR-6.6", "steps": [
                {"code": "d", "programs": [{"tool": "DR-6.6", "units": [12]}]}]}]}],
        "units": [
            {"id": 10, "element": 3, "operation": "pocket", "tool": "EM-B16R2", "top": 30, "bottom": 4,
             "radialAllowance": 1, "axialAllowance": 0.5, "setting": {"spindleRpm": 15000, "feedMmMin": 4800},
             "enabled": True, "order": 1},
            {"id": 11, "element": 4, "operation": "pocket", "tool": "EM-B16R2", "top": 30, "bottom": 4,
             "radialAllowance": 1, "axialAllowance": 0.5, "setting": {"spindleRpm": 15000, "feedMmMin": 4800},
             "enabled": False, "order": 2},
            {"id": 12, "element": 9, "operation": "drill", "tool": "DR-6.6", "top": 4, "bottom": 0,
             "radialAllowance": 0, "axialAllowance": 0, "setting": {"spindleRpm": 7000, "feedMmMin": 900},
             "enabled": True, "order": 3}],
        "travel": {"rulesOnly": 2400.0, "optimised": 1800.0, "savedPercent": 25.0},
        "checks": [{"rule": "priority", "node": "setup +Z", "ok": True, "message": "r < d"},
                   {"rule": "removal", "node": "tool <T&1>", "ok": False, "message": "removes nothing"}],
        "unmachined": [{"element": 7, "reason": "no tool reaches 80 mm"}],
    }
    return {"part": "panel", "source": "/tmp/panel.step", "recognition": {"elements": [{}] * 5}, "chain": chain,
            "operations": [{"unit": 10, "cutLength": 5000.0, "minutes": 1.5},
                           {"unit": 12, "cutLength": 20.0, "minutes": 0.25}],
            "programs": [{"setup": "+Z", "dialect": "Sinumerik 840D", "path": "/x/panel_+Z.mpf", "lines": 1234}],
            "verification": [{"check": "gouge", "node": "+Z", "ok": True, "detail": "0 moves"}],
            "stages": [("recognise", 1.0), ("chain", 0.5)]}


class ChainReportTest(unittest.TestCase):
    def test_tables_follow_the_chain(self):
        text = chain_report.render(_run())
        # One row per unit, in the setup table, with its step and tool.
        for uid in ("10", "11", "12"):
            self.assertRegex(text, r"<td class='n'>{}</td>".format(uid))
        self.assertIn("(disabled)", text)                     # unit 11
        self.assertIn("1 min 30 s", text)                     # unit 10's time
        self.assertIn("1 min 45 s", text)                     # the total
        self.assertIn("2,400 mm in rule order", text)
        self.assertIn("no tool reaches 80 mm", text)
        self.assertEqual(text.count('class="fail"'), 1)      # the removal check
        self.assertIn("tool &lt;T&amp;1&gt;", text)          # escaped
        self.assertNotIn("<T&1>", text)
        self.assertIn('<a href="panel_+Z.mpf">', text)

    def test_elements_not_machined_are_counted_once_faces_apart(self):
        run = _run()
        run["chain"]["unmachined"] += [
            {"element": 7, "reason": "its walls need a finishing tool", "step": "fs"},
            {"element": 8, "reason": "a chamfer needs a chamfer tool", "faces": [41, 42]}]
        text = chain_report.render(run)
        self.assertIn("<td>1, 1 more with faces left</td>", text)
        self.assertIn("<td>41, 42</td>", text)
        self.assertIn("<td>all</td>", text)

    def test_a_roughing_the_gate_re_made_is_named_with_its_allowances(self):
        run = _run()
        run["regrown"] = [{"label": "Pocket E6 r U0", "note": "re-made with allowances 1.21 mm radial, 0.71 mm "
                           "axial (planned 1.00, 0.50): with the planned ones it gouged 0.01 mm"}]
        text = chain_report.render(run)
        self.assertIn("<td>Re-made by the gate</td><td>Pocket E6 r U0: re-made with allowances 1.21 mm radial", text)
        self.assertNotIn("Re-made by the gate", chain_report.render(_run()))

    def test_every_element_machined_says_so(self):
        run = _run()
        run["chain"]["unmachined"] = []
        self.assertIn("Every recognised element is machined", chain_report.render(run))

    def test_write_replaces_the_file_whole(self):
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "report.html")
            with open(path, "w") as f:
                f.write("old")
            chain_report.write(path, _run())
            with open(path) as f:
                self.assertTrue(f.read().startswith("<!DOCTYPE html>"))
            self.assertEqual(sorted(os.listdir(d)), ["report.html"])

    def test_pictures_are_written(self):
        with tempfile.TemporaryDirectory() as d:
            square = [(0, 0), (100, 0), (100, 60), (0, 60), (0, 0)]
            moves = [[0, 10, 10, 40], [2, 10, 10, 20], [1, 90, 10, 20], [1, 90, 50, 20], [3, 50, 30, 0, 33, 0, 0]]
            png = toolpath_picture.draw([{"name": "+Z", "edges": [square],
                                          "toolpaths": [{"tool": "EM-B16R2", "moves": moves}]}],
                                        os.path.join(d, "tp.png"), "test")
            self.assertGreater(os.path.getsize(png), 5000)
            left = {"nx": 4, "ny": 3, "x0": 0.0, "y0": 0.0, "cell": 1.0,
                    "top": [0.0, 0.0, 0.5, None, 0.0, 0.1, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]}
            png = toolpath_picture.draw_leftover(left, os.path.join(d, "left.png"))
            self.assertGreater(os.path.getsize(png), 5000)
            self.assertFalse([n for n in os.listdir(d) if re.search(r"\.part", n)])


if __name__ == "__main__":
    unittest.main()
