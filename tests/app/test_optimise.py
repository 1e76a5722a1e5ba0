"""The cutting-parameter optimiser through the Python module, headless."""
import json
import os
import tempfile
import unittest

import aeronc
from aeronc import _core


def _example():
    path = os.path.join(aeronc.PACKAGE_DIR, "resources", "optimise", "xa5032_face_mill_45_steel.json")
    with open(path) as f:
        return json.load(f)


class OptimiseTest(unittest.TestCase):
    def test_paper_example_through_python(self):
        text, result = _core.optimise_cutting(json.dumps(_example()), "both")
        result = json.loads(result)
        best = result["deterministic"]["optimum"]
        # The paper's MATLAB GA found n = 396.1 r/min, f_z = 0.169 mm (tolerance: docs/cutting-optimisation.md).
        self.assertAlmostEqual(best["n_rpm"], 396.1, delta=0.033 * 396.1)
        self.assertAlmostEqual(best["f_z_mm"], 0.169, delta=0.012 * 0.169)
        self.assertTrue(best["feasible"])
        self.assertEqual(len(best["active"]), 2)
        self.assertIn("genetic", result)
        self.assertIn("ours: scan+SLSQP", text)

    def test_knowledge_base_names(self):
        path = os.path.join(aeronc.PACKAGE_DIR, "resources", "optimise", "kb_45_steel_face_mill.json")
        with open(path) as f:
            params = f.read()
        with tempfile.TemporaryDirectory() as d:
            _, result = _core.optimise_cutting(params, kb_path=os.path.join(d, "kb.sqlite"),
                                               sql_folder=os.path.join(aeronc.PACKAGE_DIR, "resources", "kb"))
        self.assertTrue(json.loads(result)["deterministic"]["optimum"]["feasible"])

    def test_bad_input_is_the_module_error(self):
        p = _example()
        del p["force"]["C_F"]
        with self.assertRaisesRegex(_core.RecognitionError, "force.C_F"):
            _core.optimise_cutting(json.dumps(p))
        p = _example()
        p["machine"]["power_kw"] = 0.01
        with self.assertRaisesRegex(_core.RecognitionError, "raise P_max"):
            _core.optimise_cutting(json.dumps(p))
        with self.assertRaisesRegex(_core.RecognitionError, "not valid JSON"):
            _core.optimise_cutting("{")
        with self.assertRaisesRegex(_core.RecognitionError, "nlopt, ga or both"):
            _core.optimise_cutting(json.dumps(_example()), "simplex")

    def test_an_open_knowledge_base_gives_the_same_answer(self):
        path = os.path.join(aeronc.PACKAGE_DIR, "resources", "optimise", "kb_45_steel_face_mill.json")
        with open(path) as f:
            params = f.read()
        with tempfile.TemporaryDirectory() as d:
            kb_path = os.path.join(d, "kb.sqlite")
            sql = os.path.join(aeronc.PACKAGE_DIR, "resources", "kb")
            by_path = _core.optimise_cutting(params, "nlopt", 1, kb_path, sql, 11)
            kb = _core.KnowledgeBase(kb_path, sql)
            self.assertEqual(_core.optimise_cutting_in(kb, params, "nlopt", 1, 11), by_path)
            result = json.loads(by_path[1])
            self.assertEqual(len(result["map"]["n_rpm"]), 11)
            self.assertEqual(result["parameters"]["force"]["C_F"], 825)
            with self.assertRaisesRegex(_core.RecognitionError, "unknown key kb.colour"):
                _core.optimise_cutting_in(kb, json.dumps({"kb": {"colour": "red"}}))
