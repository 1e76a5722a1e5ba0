"""The machining chain through the Python binding, headless: built from a stored recognition
of the sample panel, the same chain the command line makes from the part; re-checked after the
edits a panel makes (order, tool, enabled); bad input raised as the core's error, turned into
KnowledgeBaseError by errors.from_core."""
import json
import os
import shutil
import subprocess
import tempfile
import unittest

import aeronc
from aeronc import _core
from aeronc.pipeline import knowledge_base
from aeronc.errors import KnowledgeBaseError, from_core

SAMPLE = os.path.join(aeronc.PACKAGE_DIR, "resources", "samples", "sample_panel.step")


def failures(chain, rule):
    return [c for c in chain["checks"] if c["rule"] == rule and not c["ok"]]


class ChainBindingTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tree_json = _core.recognise_file(SAMPLE)

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="aeronc_chain_")
        self.kb_path = os.path.join(self.tmp, "kb.sqlite")

    def tearDown(self):
        shutil.rmtree(self.tmp, ignore_errors=True)

    def build(self, **kw):
        return json.loads(_core.build_chain(self.tree_json, self.kb_path, "7050-T7451",
                                            knowledge_base.sql_folder(), **kw))

    def test_chain_of_the_sample_panel(self):
        chain = self.build()
        tree = json.loads(self.tree_json)
        self.assertEqual(chain["family"], "integral_panel")
        self.assertEqual([s["name"] for s in chain["setups"]], ["+Z", "-Z"])
        # Every element machined or listed with its reason; every rule holds.
        machined = {u["element"] for u in chain["units"]}
        listed = {m["element"] for m in chain["unmachined"]}
        for e in tree["elements"]:
            self.assertTrue(e["id"] in machined or e["id"] in listed, e["id"])
        self.assertEqual([c for c in chain["checks"] if not c["ok"]], [])
        self.assertEqual(sorted(chain["order"]), list(range(len(chain["units"]))))
        self.assertLessEqual(chain["travel"]["optimised"], chain["travel"]["rulesOnly"])
        # The toolpath generator's fields.
        pocket = next(u for u in chain["units"] if u["operation"] == "pocket")
        for key in ("contour", "islands", "openEdges", "top", "bottom", "radialAllowance", "axialAllowance",
                    "stepDown", "stepOver", "cutter", "holes", "setting", "toolNumber", "enabled", "order"):
            self.assertIn(key, pocket)
        rest = next(u for u in chain["units"] if u["operation"] == "rest")
        self.assertLess(rest["cutter"]["diameter"], rest["previousCutter"]["diameter"])
        drills = {u["tool"] for u in chain["units"] if u["operation"] == "drill"}
        self.assertIn("DR-6.6", drills)

        # The same chain as the command line's from the part.
        cli = os.path.join(os.path.dirname(aeronc.PACKAGE_DIR), "bin", "aeronc")
        if os.path.exists(cli):
            out = os.path.join(self.tmp, "chain.json")
            subprocess.run([cli, "chain", SAMPLE, "--kb", self.kb_path, "--material", "7050-T7451",
                            "--json", out], check=True, capture_output=True)
            with open(out) as f:
                self.assertEqual(json.load(f), chain)

    def test_edits_are_checked_again(self):
        chain = self.build()
        checked = json.loads(_core.check_chain(json.dumps(chain)))
        self.assertEqual(checked, chain)  # nothing edited, nothing changed

        # Disable a finishing unit: its element lacks a must-step.
        fs = next(u for u in chain["units"] if u["step"] == "fs")
        fs["enabled"] = False
        checked = json.loads(_core.check_chain(json.dumps(chain)))
        self.assertEqual(len(failures(checked, "existence")), 1)
        self.assertIn("element {}".format(fs["element"]), failures(checked, "existence")[0]["node"])
        fs["enabled"] = True

        # Move it first: priority names it; the tree follows the order.
        chain["order"].remove(fs["id"])
        chain["order"].insert(0, fs["id"])
        checked = json.loads(_core.check_chain(json.dumps(chain)))
        self.assertTrue(failures(checked, "priority"))
        first = checked["setups"][0]["processes"][0]
        self.assertEqual(first["steps"][0]["programs"][0]["units"], [fs["id"]])

    def test_bad_input_is_named(self):
        with self.assertRaises(KnowledgeBaseError) as ctx, from_core(KnowledgeBaseError):
            self.build(family="impeller")
        self.assertIn("no process template or part family 'impeller'", str(ctx.exception))
        with self.assertRaises(KnowledgeBaseError) as ctx, from_core(KnowledgeBaseError):
            _core.check_chain('{"family": "integral_panel"}')
        self.assertIn("missing field", str(ctx.exception))
        with self.assertRaises(RuntimeError):
            _core.build_chain("{", self.kb_path, "7050-T7451", knowledge_base.sql_folder())


if __name__ == "__main__":
    unittest.main()
