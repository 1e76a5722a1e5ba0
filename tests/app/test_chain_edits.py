"""The user's edits of a machining chain (reorder within a program, tool override, disabling),
applied to hand-made chains whose result is known; plain Python."""
import unittest

from aeronc.pipeline import chain_edits


def _chain():
    """Setup 0, one process, step r with two programs (EM-F20: units 0 1 2, EM-F10: unit 3),
    step fs with one program (EM-F10: units 4 5)."""
    units = [{"id": i, "setup": 0, "element": 10 + i, "step": "r" if i < 4 else "fs", "operation": "pocket",
              "tool": "EM-F20" if i < 3 else "EM-F10", "cutter": {"diameter": 20.0 if i < 3 else 10.0,
                                                                 "cornerRadius": 0.0, "type": "flat"},
              "enabled": True, "order": i} for i in range(6)]
    return {"setups": [{"id": 0, "processes": [{"id": 0, "steps": [
        {"code": "r", "programs": [{"tool": "EM-F20", "units": [0, 1, 2]}, {"tool": "EM-F10", "units": [3]}]},
        {"code": "fs", "programs": [{"tool": "EM-F10", "units": [4, 5]}]}]}]}],
        "units": units, "order": [0, 1, 2, 3, 4, 5],
        "tools": [{"id": "EM-F20", "diameter": 20.0, "cornerRadius": 0.0, "type": "flat", "number": 1},
                  {"id": "EM-F10", "diameter": 10.0, "cornerRadius": 0.0, "type": "flat", "number": 2,
                   "settings": {"roughing": {"spindleRpm": 6000.0, "feedMmMin": 900.0, "plungeFeedMmMin": 300.0},
                                "finishing": {"spindleRpm": 8000.0, "feedMmMin": 700.0, "plungeFeedMmMin": 200.0}}},
                  {"id": "EM-B10R1", "diameter": 10.0, "cornerRadius": 1.0, "type": "bull", "number": 3}]}


def _program_units(chain):
    return [p["units"] for _, _, _, p in chain_edits.programs(chain)]


class ChainEditsTest(unittest.TestCase):
    def test_no_edits_change_nothing(self):
        built = _chain()
        chain, notes = chain_edits.apply(built, None)
        self.assertEqual(chain, built)
        self.assertEqual(notes, [])

    def test_move_within_a_program_only(self):
        built = _chain()
        e = chain_edits.moved(built, {}, 2, -1)
        chain, _ = chain_edits.apply(built, e)
        self.assertEqual(_program_units(chain), [[0, 2, 1], [3], [4, 5]])
        self.assertEqual(chain["order"], [0, 2, 1, 3, 4, 5])
        self.assertEqual([u["order"] for u in sorted(chain["units"], key=lambda u: u["id"])], [0, 2, 1, 3, 4, 5])
        # The first unit of a program cannot go up, the last not down, a lone one not at all.
        self.assertIsNone(chain_edits.moved(chain, e, 0, -1))
        self.assertIsNone(chain_edits.moved(chain, e, 5, 1))
        self.assertIsNone(chain_edits.moved(chain, e, 3, 1))
        # Moves add up.
        e2 = chain_edits.moved(chain, e, 0, 1)
        chain2, _ = chain_edits.apply(built, e2)
        self.assertEqual(_program_units(chain2), [[2, 0, 1], [3], [4, 5]])
        self.assertEqual(built["order"], [0, 1, 2, 3, 4, 5])  # the built chain is left alone

    def test_tool_change_moves_the_unit_to_the_program_of_that_tool(self):
        built = _chain()
        chain, notes = chain_edits.apply(built, chain_edits.with_tool({}, built, 1, "EM-F10"))
        self.assertEqual(notes, [])
        self.assertEqual(_program_units(chain), [[0, 2], [1, 3], [4, 5]])
        unit = chain_edits.units_by_id(chain)[1]
        self.assertEqual(unit["tool"], "EM-F10")
        self.assertEqual(unit["cutter"]["diameter"], 10.0)
        self.assertEqual(unit["toolNumber"], 2)
        self.assertEqual(unit["setting"]["spindleRpm"], 6000.0)  # a rough-step unit takes the roughing data
        # A tool no program of the step has gets a program of its own, after the unit's old one.
        chain, _ = chain_edits.apply(built, chain_edits.with_tool({}, built, 5, "EM-B10R1"))
        self.assertEqual([p["tool"] for _, _, s, p in chain_edits.programs(chain) if s["code"] == "fs"],
                         ["EM-F10", "EM-B10R1"])
        self.assertEqual(chain_edits.units_by_id(chain)[5]["cutter"]["cornerRadius"], 1.0)
        # The last unit leaving a program removes the program.
        chain, _ = chain_edits.apply(built, chain_edits.with_tool({}, built, 3, "EM-F20"))
        self.assertEqual(_program_units(chain), [[0, 1, 2, 3], [4, 5]])
        # Back to the chain's own tool: the override goes.
        e = chain_edits.with_tool(chain_edits.with_tool({}, built, 3, "EM-F20"), built, 3, "EM-F10")
        self.assertTrue(chain_edits.is_empty(e))

    def test_unknown_tool_is_refused_with_a_note(self):
        built = _chain()
        chain, notes = chain_edits.apply(built, {"tools": {"2": "NO-SUCH"}})
        self.assertEqual(chain_edits.units_by_id(chain)[2]["tool"], "EM-F20")
        self.assertEqual(len(notes), 1)
        self.assertIn("NO-SUCH", notes[0])

    def test_disabled_units(self):
        built = _chain()
        e = chain_edits.with_enabled({}, 4, False)
        chain, _ = chain_edits.apply(built, e)
        self.assertEqual([u["id"] for u in chain["units"] if not u["enabled"]], [4])
        chain, _ = chain_edits.apply(built, chain_edits.with_enabled(e, 4, True))
        self.assertTrue(all(u["enabled"] for u in chain["units"]))

    def test_edits_of_units_gone_are_dropped_with_notes(self):
        built = _chain()
        edits = {"order": [1, 0, 99], "tools": {"98": "EM-F10"}, "disabled": [97, 2]}
        chain, notes = chain_edits.apply(built, edits)
        self.assertEqual(_program_units(chain)[0], [1, 0, 2])
        self.assertEqual([u["id"] for u in chain["units"] if not u["enabled"]], [2])
        self.assertEqual(len(notes), 3)
        self.assertTrue(any("99" in n for n in notes) and any("98" in n for n in notes)
                        and any("97" in n for n in notes))

    def test_edits_survive_json(self):
        import json
        built = _chain()
        e = chain_edits.with_tool(chain_edits.with_enabled(chain_edits.moved(built, {}, 1, 1), 0, False),
                                  built, 4, "EM-B10R1")
        again = json.loads(json.dumps(chain_edits.to_json_ready(e)))
        self.assertEqual(chain_edits.apply(built, again), chain_edits.apply(built, e))


if __name__ == "__main__":
    unittest.main()
