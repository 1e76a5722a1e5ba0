"""The gate's dependents: what a left-out operation takes with it. An element's later operations
go with it, and, when it is a roughing, those of the elements inside it; a roughing that stops short of its element's
floor (deeper than every end mill reaches) takes nothing with it, and left out alone it leaves
the programs incomplete, not unready."""
import json
import unittest

from aeronc.pipeline import gate


class _Op:
    def __init__(self, label, element, unit=None):
        self.Label = label
        self.ElementId = element
        self.Unit = json.dumps(unit or {})
        self.Step = (unit or {}).get("step", "")  # as the operation carries its unit's step


# Element 1 holds element 2; element 3 stands apart.
RESULT = {"elements": [{"id": 1, "parent": -1}, {"id": 2, "parent": 1}, {"id": 3, "parent": -1}]}


class DependentsTest(unittest.TestCase):
    def ops(self, short_of_floor):
        return [_Op("Pocket E1 r U0", 1, {"step": "r", "shortOfFloor": True} if short_of_floor else {"step": "r"}),
                _Op("Pocket E2 r U1", 2), _Op("Profile E2 fs U2", 2), _Op("Pocket E3 r U3", 3)]

    def test_a_left_out_roughing_takes_the_elements_inside_with_it(self):
        out = gate.dependents(self.ops(False), {"Pocket E1 r U0": "gouges"}, RESULT)
        self.assertEqual(sorted(out), ["Pocket E2 r U1", "Profile E2 fs U2"])
        self.assertIn("left out with Pocket E1 r U0", out["Pocket E2 r U1"])

    def test_a_roughing_short_of_its_floor_takes_nothing_with_it(self):
        self.assertEqual(gate.dependents(self.ops(True), {"Pocket E1 r U0": "gouges"}, RESULT), {})

    def test_a_left_out_finishing_takes_its_own_elements_later_operations_only(self):
        ops = [_Op("Pocket E1 r U0", 1, {"step": "r"}), _Op("Profile E1 sf U1", 1, {"step": "sf"}),
               _Op("Pocket E2 r U2", 2, {"step": "r"}), _Op("Profile E1 ff U3", 1, {"step": "ff"}),
               _Op("Profile E2 fs U4", 2, {"step": "fs"})]
        out = gate.dependents(ops, {"Profile E1 sf U1": "no toolpath"}, RESULT)
        self.assertEqual(sorted(out), ["Profile E1 ff U3"])
        # The roughing left out takes the element inside, and that element's later operations.
        out = gate.dependents(ops, {"Pocket E1 r U0": "gouges"}, RESULT)
        self.assertEqual(sorted(out), ["Pocket E2 r U2", "Profile E1 ff U3", "Profile E1 sf U1", "Profile E2 fs U4"])

    def test_an_element_apart_is_not_taken(self):
        out = gate.dependents(self.ops(False), {"Pocket E2 r U1": "gouges"}, RESULT)
        self.assertEqual(sorted(out), ["Profile E2 fs U2"])


class VerdictTest(unittest.TestCase):
    """A roughing short of its floor left out alone leaves the programs incomplete, not unready;
    any other operation left out makes them not ready."""

    def data(self, kinds):
        return {"part": "p", "programs": [{"path": "p.mpf"}],
                "leftOut": [{"label": "Pocket E{} r U{}".format(k, k), "kind": kind, "reason": "gouges"}
                            for k, kind in enumerate(kinds)],
                "materialLeft": [{"element": 0, "faces": [3], "area": 100.0, "maxLeft": 30.0, "reason": "x"}]}

    def test_short_of_floor_alone_is_incomplete(self):
        from aeronc.runs.main_job import SHORT_OF_FLOOR, verdict_of
        v = verdict_of(self.data([SHORT_OF_FLOOR]))
        self.assertEqual(v["status"], "INCOMPLETE")
        self.assertIn("1 operation left out of the programs (1 is a roughing short of its floor)", v["text"])
        self.assertIn("the programs neither gouge nor rapid through material", v["text"])

    def test_any_other_left_out_is_not_ready(self):
        from aeronc.runs.main_job import SHORT_OF_FLOOR, verdict_of
        self.assertEqual(verdict_of(self.data([SHORT_OF_FLOOR, "gouge"]))["status"], "NOT READY")
        self.assertEqual(verdict_of(self.data(["dependent"]))["status"], "NOT READY")


if __name__ == "__main__":
    unittest.main()


class _Length:
    def __init__(self, value):
        self.Value = value


class _Roughing:
    """A roughing operation whose toolpath exists only while its allowances leave at least
    `room` mm less than the pocket allows (what recompute() of a real operation decides)."""

    def __init__(self, step="r", radial=0.5, axial=0.3, room=10.0):
        self.Step, self.room, self.recomputed = step, room, 0
        self.UserEdited = ["Note"]
        self._radial, self._axial = _Length(radial), _Length(axial)
        self.Check, self.Path = "", type("P", (), {"Commands": ["G1"]})()

    @property
    def RadialAllowance(self):
        return self._radial

    @RadialAllowance.setter
    def RadialAllowance(self, v):
        self._radial = _Length(float(v))

    @property
    def AxialAllowance(self):
        return self._axial

    @AxialAllowance.setter
    def AxialAllowance(self, v):
        self._axial = _Length(float(v))

    def recompute(self):
        from aeronc.post import readiness
        self.recomputed += 1
        ok = self._radial.Value <= self.room
        self.Check = "" if ok else readiness.NO_TOOLPATH
        self.Path.Commands = ["G1"] if ok else []


class RegrowTest(unittest.TestCase):
    """A roughing that gouges is re-made once with its allowances grown by the gouge and a margin;
    the allowances it was planned with are what its simulation then checks it against."""

    def test_a_gouging_roughing_is_re_made_with_grown_allowances(self):
        op = _Roughing()
        planned = gate.regrow(op, 0.63)
        self.assertEqual(planned, {"radial": 0.5, "axial": 0.3})
        grow = 0.63 + gate.REGROW_MARGIN
        self.assertAlmostEqual(op.RadialAllowance.Value, 0.5 + grow)
        self.assertAlmostEqual(op.AxialAllowance.Value, 0.3 + grow)
        self.assertEqual(op.UserEdited, ["Note"])  # the gate's choice, not an edit by hand
        note = gate.regrown_note(op, planned, 0.63)
        self.assertIn("planned 0.50, 0.30", note)
        self.assertIn("gouged 0.63 mm", note)

    def test_what_is_not_re_made(self):
        for op, depth in ((_Roughing(step="fs"), 0.1),          # a finishing
                          (_Roughing(), gate.REGROW_MAX),        # a growth beyond REGROW_MAX
                          (_Roughing(room=0.6), 0.3)):           # no toolpath with the grown allowances
            self.assertIsNone(gate.regrow(op, depth))
            self.assertEqual((op.RadialAllowance.Value, op.AxialAllowance.Value), (0.5, 0.3))
            self.assertTrue(op.Path.Commands)

    def test_the_operations_after_a_re_made_roughing_are_measured_from_the_new_simulation(self):
        first = {"ops": [{"label": "a", "removedVolume": 10.0}, {"label": "b", "removedVolume": 200.0}]}
        report = {"ops": [{"label": "a", "removedVolume": 8.0}, {"label": "b", "removedVolume": 350.0}]}
        self.assertEqual(sorted(gate.grown(first, report, ["x"])), ["b"])
        self.assertEqual(gate.grown(gate.rebased(first, report, {"b"}), report, ["x"]), {})
